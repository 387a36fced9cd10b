#!/usr/bin/env bash
# Before/after check for changes that must leave every pixel as it was
# (first made for the map technique as modules). Builds the pinned BASE commit
# beside the work tree, renders every case below with both builds, and
# compares every file each writes: the frame, the techniques' debug images
# (shadow maps, cube crosses, texel density, cascade colours), and for
# `compare` rows the technique, reference, error, visibility and reach
# images and metrics.json (its timing fields, *Ms, left out).
#
# Usage: scripts/refactor-check.sh [--base COMMIT] [--only REGEX] [--list] [--bench | --bench-all | --bench-scene NAME]
#   --base COMMIT  the "before" build (default: the commit the map module's inside refactor started from)
#   --only REGEX   only the cases whose name matches (grep -E)
#   --list         print the cases and exit
#   --bench        also time both builds side by side (bench, interleaved rounds)
#                  on six scenes with the map technique's main variants
#   --bench-all    the same over every bundled scene (scenes/, scenes/lecture/)
#                  at its own settings
#   --bench-scene NAME  the same for one bundled scene (e.g. learnopengl-point-shadows,
#                  lecture/peter-panning): to time one again with more rounds
# Environment: REFCHECK_WIDTH, REFCHECK_HEIGHT (400x300), REFCHECK_ROUNDS (3) and
# REFCHECK_FRAMES (40 timed frames a round) for the timing. The table gives
# the ratio of the fastest rounds and of the rounds' medians: on a shared
# machine a single fast round of one build moves the first, not the second.
#
# Writes build-refcheck/{base-src,base}/ (the BASE build, kept between runs),
# build-refcheck/out/{base,head}/CASE/ and build-refcheck/out/table.md: one
# row per case with the files compared, the files that differ and the
# pixels that differ. Exit 0 only when nothing differs (and every case ran).
# The "after" build is the work tree's, in build/ (preset default).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

# The commit the map module's inside refactor starts from (the one before
# its first landing): every landing of it is measured against this.
base=48fd5a681ba65b6dd686b98382158905c58cce53
only=""
list=false
bench=false
bench_scene=""
while (($#)); do
  case $1 in
    --base) base=$(git rev-parse --verify "$2^{commit}"); shift 2 ;;
    --only) only=$2; shift 2 ;;
    --list) list=true; shift ;;
    --bench) bench=true; shift ;;
    --bench-all) bench=all; shift ;;
    --bench-scene) bench=one; bench_scene=$2; shift 2 ;;
    *) echo "refactor-check: unknown argument '$1' (see the usage at the top of $0)" >&2; exit 2 ;;
  esac
done
width=${REFCHECK_WIDTH:-400}
height=${REFCHECK_HEIGHT:-300}

# ---------------------------------------------------------------- the cases
# case NAME render|compare SCENE [--set K=V ...]: every row names its
# technique and the option it varies explicitly, so a change of defaults
# cannot hide in a row.
names=() commands=()
case_() {
  local name=$1
  shift
  names+=("$name")
  commands+=("$(printf '%q ' "$@")")  # shell-quoted: values with spaces survive
}
S=scenes
T=lights[0].shadow.technique
M=lights[0].shadow.map

# Every bundled scene with the technique it names (or none) and with a map.
for f in "$S"/*.json; do
  s=$(basename "$f" .json)
  # A scene whose lights are all generated (lightGrid: many-lights.json) has
  # no lights[0] to set; its light list is tested by LightListGLTest.
  own=$(python3 -c 'import json,sys; l=json.load(open(sys.argv[1])).get("lights") or [None]; print("" if l[0] is None else l[0].get("shadow",{}).get("technique","none"))' "$f")
  [[ -n $own ]] || continue
  case_ "scene-$s-$own" render "$f" --set "$T=$own"
  [[ $own == map ]] || case_ "scene-$s-map" render "$f" --set "$T=map"
  [[ $own == none ]] || case_ "scene-$s-none" render "$f" --set "$T=none"
  case_ "compare-$s-$own" compare "$f" --set "$T=$own"
done

# The map technique, one option at a time from the defaults, per light type.
dir=$S/two-boxes-sun.json spot=$S/spot-objects.json point=$S/four-spheres-point.json
for light in dir spot; do
  f=${!light}
  for filter in none hardware grid dither4 poisson; do case_ "map-$light-filter-$filter" render "$f" --set "$T=map" "$M.filter=$filter"; done
  case_ "map-$light-filter-pcss" render "$f" --set "$T=map" "$M.filter=pcss" "lights[0].size=$([[ $light == dir ]] && echo 2 || echo 0.3)"
  case_ "map-$light-grid-kernel5" render "$f" --set "$T=map" "$M.filter=grid" "$M.kernel=5"
  for taps in bilinear nearest; do case_ "map-$light-grid-taps-$taps" render "$f" --set "$T=map" "$M.filter=grid" "$M.gridTaps=$taps"; done
  case_ "map-$light-poisson-32-r3" render "$f" --set "$T=map" "$M.filter=poisson" "$M.samples=32" "$M.radius=3"
  for format in depth16 depth24 depth32f rgba8 r8; do
    case_ "map-$light-format-$format" render "$f" --set "$T=map" "$M.format=$format"
    case_ "map-$light-format-$format-grid" render "$f" --set "$T=map" "$M.format=$format" "$M.filter=grid"
  done
  case_ "map-$light-fit-scene" render "$f" --set "$T=map" "$M.fit=scene"
  case_ "map-$light-size-512" render "$f" --set "$T=map" "$M.size=512"
  case_ "map-$light-normalBias-0" render "$f" --set "$T=map" "$M.normalBias=0"
  case_ "map-$light-constantBias" render "$f" --set "$T=map" "$M.constantBias=0.002"
  case_ "map-$light-slopeBias" render "$f" --set "$T=map" "$M.slopeBias=4" "$M.offsetUnits=8"
  case_ "map-$light-cullFront" render "$f" --set "$T=map" "$M.cullFront=true"
  case_ "map-$light-shadowedLight" render "$f" --set "$T=map" "$M.shadowedLight=0.5"
  for filter in none hardware; do case_ "map-$light-mipmaps-$filter" render "$f" --set "$T=map" "$M.mipmaps=true" "$M.filter=$filter"; done
  case_ "map-$light-mipmaps-rgba8" render "$f" --set "$T=map" "$M.mipmaps=true" "$M.format=rgba8"
  for preset in lecture learnopengl; do case_ "map-$light-preset-$preset" render "$f" --set "$T=map" "$M.preset=$preset"; done
  for rep in vsm evsm2 evsm4 msm; do case_ "map-$light-moments-$rep" render "$f" --set "$T=map" "$M.representation=$rep"; done
  case_ "map-$light-moments-evsm4-half" render "$f" --set "$T=map" "$M.representation=evsm4" "$M.momentFormat=rgba16f"
  case_ "map-$light-moments-vsm-half" render "$f" --set "$T=map" "$M.representation=vsm" "$M.momentFormat=rgba16f"
  case_ "map-$light-moments-msm-blur0" render "$f" --set "$T=map" "$M.representation=msm" "$M.blur=0"
  case_ "map-$light-moments-msm-blur6" render "$f" --set "$T=map" "$M.representation=msm" "$M.blur=6"
  case_ "map-$light-moments-vsm-bleed" render "$f" --set "$T=map" "$M.representation=vsm" "$M.bleedReduction=0.3"
  case_ "map-$light-moments-evsm2-mipmaps" render "$f" --set "$T=map" "$M.representation=evsm2" "$M.mipmaps=true"
done
# Cascades (directional only).
field=$S/cascades-field.json
for n in 1 2 4 8; do case_ "map-cascades-$n" render "$field" --set "$T=map" "$M.cascades=$n"; done
case_ "map-cascades-4-tight" render "$field" --set "$T=map" "$M.cascades=4" "$M.stabilize=false"
case_ "map-cascades-4-blend" render "$field" --set "$T=map" "$M.cascades=4" "$M.cascadeBlend=0.2"
case_ "map-cascades-4-lambda" render "$field" --set "$T=map" "$M.cascades=4" "$M.cascadeLambda=0.3"
case_ "map-cascades-4-splits" render "$field" --set "$T=map" "$M.cascades=4" "$M.cascadeSplits=8 30 100"
case_ "map-cascades-4-grid" render "$field" --set "$T=map" "$M.cascades=4" "$M.filter=grid"
case_ "map-cascades-4-pcss" render "$field" --set "$T=map" "$M.cascades=4" "$M.filter=pcss" "lights[0].size=1"
case_ "map-cascades-4-rgba8" render "$field" --set "$T=map" "$M.cascades=4" "$M.format=rgba8"
case_ "map-cascades-4-evsm4" render "$field" --set "$T=map" "$M.cascades=4" "$M.representation=evsm4"
case_ "map-cascades-4-msm-mipmaps" render "$field" --set "$T=map" "$M.cascades=4" "$M.representation=msm" "$M.mipmaps=true"
case_ "map-cascades-2-small" render "$dir" --set "$T=map" "$M.cascades=2"
# Fit sdsm (fitted on the GPU): one map, warped, and cascades, stabilised or each slice fitted to its own samples, warped or not.
long=$S/long-view.json
for f in long field; do
  case_ "sdsm-$f-one" render "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=1"
  case_ "compare-sdsm-$f-one" compare "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=1"
  case_ "sdsm-$f-one-lispsm" render "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=1" "$M.warp=lispsm"
  case_ "sdsm-$f-cascades" render "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=4"
  case_ "sdsm-$f-cascades-tight" render "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=4" "$M.stabilize=false"
  case_ "sdsm-$f-cascades-tight-lispsm" render "${!f}" --set "$T=map" "$M.fit=sdsm" "$M.cascades=4" "$M.stabilize=false" "$M.warp=lispsm"
done
case_ "sdsm-dir-pcss" render "$dir" --set "$T=map" "$M.fit=sdsm" "$M.filter=pcss" "lights[0].size=2"
# Point lights: cube maps.
for filter in none hardware grid poisson pcf20; do case_ "map-point-filter-$filter" render "$point" --set "$T=map" "$M.filter=$filter"; done
case_ "map-point-filter-pcss" render "$point" --set "$T=map" "$M.filter=pcss" "lights[0].size=0.2"
case_ "map-point-grid-kernel4" render "$point" --set "$T=map" "$M.filter=grid" "$M.kernel=4"
for format in depth16 depth24 depth32f rgba8 r8; do case_ "map-point-format-$format" render "$point" --set "$T=map" "$M.format=$format"; done
case_ "map-point-fit-scene" render "$point" --set "$T=map" "$M.fit=scene"
case_ "map-point-size-512" render "$point" --set "$T=map" "$M.size=512"
case_ "map-point-cubePasses-six" render "$point" --set "$T=map" "$M.cubePasses=six"
case_ "map-point-faceCulling-off" render "$point" --set "$T=map" "$M.faceCulling=false"
case_ "map-point-six-faceCulling-off" render "$point" --set "$T=map" "$M.cubePasses=six" "$M.faceCulling=false"
case_ "map-point-diskRadius" render "$point" --set "$T=map" "$M.filter=poisson" "$M.diskRadius=0.1" "$M.diskGrowth=2"
case_ "map-point-normalBias-0" render "$point" --set "$T=map" "$M.normalBias=0"
case_ "map-point-slopeBias" render "$point" --set "$T=map" "$M.slopeBias=4" "$M.offsetUnits=8"
case_ "map-point-constantBias" render "$point" --set "$T=map" "$M.constantBias=0.002"
case_ "map-point-cullFront" render "$point" --set "$T=map" "$M.cullFront=true"
for filter in none grid pcf20; do case_ "map-point-preset-lecture-$filter" render "$point" --set "$T=map" "$M.preset=lecture" "$M.filter=$filter"; done
case_ "map-point-preset-learnopengl" render "$point" --set "$T=map" "$M.preset=learnopengl"
case_ "map-point-preset-lecture-000" render "$S/torus-pyramid.json" --set "$T=map" "$M.preset=lecture-000"
case_ "map-room-point-t2" render "$S/room-point.json" --set "$T=map" --time 2
# The shadow atlas: one spot or point light's tiles through the map's own
# pass, and the generated lights of many-lights.json through the light list.
for light in spot point; do
  for filter in none hardware; do case_ "map-$light-atlas-$filter" render "${!light}" --set "$T=map" "$M.atlas=true" "$M.filter=$filter"; done
done
for count in 16 64 256; do case_ "atlas-many-lights-$count" render "$S/many-lights.json" --set "lightGrid.count=$count"; done
case_ "list-many-lights-64-unshadowed" render "$S/many-lights.json" --set 'lightGrid.light.shadow.technique=none'
case_ "atlas-many-lights-64-hardware" render "$S/many-lights.json" --set 'lightGrid.light.shadow.map.filter=hardware'
# Translucent and alpha-tested casters with every light type.
glass=$S/glass-panel.json
case_ "map-glass-spot" render "$glass" --set "$T=map"
case_ "map-glass-spot-rgba8" render "$glass" --set "$T=map" "$M.format=rgba8"
glassPoint='lights[0]={"type":"point","position":[0,1.3,4],"intensity":1,"shadow":{"technique":"map"}}'
glassSun='lights[0]={"type":"directional","direction":[0.1,-0.3,-1],"intensity":1,"shadow":{"technique":"map"}}'
case_ "map-glass-point" render "$glass" --set "$glassPoint"
case_ "map-glass-dir" render "$glass" --set "$glassSun"
case_ "map-glass-dir-cascades" render "$glass" --set "$glassSun" "$M.cascades=2"
case_ "sdsm-glass-dir" render "$glass" --set "$glassSun" "$M.fit=sdsm"
# The other techniques' options.
for style in stencil lecture; do case_ "planar-$style" render "$S/torus-floating.json" --set "$T=planar" "lights[0].shadow.planar.style=$style"; done
case_ "planar-geometry" render "$S/torus-floating.json" --set "$T=planar" "lights[0].shadow.planar.projection=geometry"
case_ "planar-spot" render "$spot" --set "$T=planar"
case_ "planar-point" render "$point" --set "$T=planar"
for method in depth-fail depth-pass book; do
  case_ "volume-$method" render "$S/two-boxes-sun.json" --set "$T=volume" "lights[0].shadow.volume.method=$method"
  case_ "volume-$method-point" render "$point" --set "$T=volume" "lights[0].shadow.volume.method=$method"
done
case_ "volume-cpu" render "$spot" --set "$T=volume" "lights[0].shadow.volume.extrusion=cpu"
case_ "volume-open-triangles" render "$glass" --set "$T=volume" "lights[0].shadow.volume.openMeshes=triangles" 'materials.glass.alphaMode="opaque"'  # volumes refuse alpha-tested casters
case_ "disc-spot" render "$S/discs.json" --set 'lights[0]={"type":"spot","position":[0.5,4,0.5],"direction":[0,-1,0],"outerCone":50,"shadow":{"technique":"disc"}}'
case_ "disc-point" render "$S/discs.json" --set 'lights[0]={"type":"point","position":[0.5,4,0.5],"shadow":{"technique":"disc"}}'

# Against the reference: one row per light type and family, soft ones included.
for light in dir spot point; do
  f=${!light}
  case_ "compare-map-$light" compare "$f" --set "$T=map"
  case_ "compare-map-$light-grid" compare "$f" --set "$T=map" "$M.filter=grid"
  case_ "compare-map-$light-rgba8" compare "$f" --set "$T=map" "$M.format=rgba8"
  case_ "compare-map-$light-pcss" compare "$f" --set "$T=map" "$M.filter=pcss" "lights[0].size=$([[ $light == dir ]] && echo 2 || echo 0.3)"
  case_ "compare-planar-$light" compare "$f" --set "$T=planar"
  case_ "compare-volume-$light" compare "$f" --set "$T=volume"
done
case_ "compare-map-dir-evsm4" compare "$dir" --set "$T=map" "$M.representation=evsm4"
case_ "compare-map-spot-msm" compare "$spot" --set "$T=map" "$M.representation=msm"
case_ "compare-map-cascades-4" compare "$field" --set "$T=map" "$M.cascades=4"
case_ "compare-glass-point" compare "$glass" --set "$glassPoint"
case_ "compare-glass-dir" compare "$glass" --set "$glassSun"

if $list; then
  for i in "${!names[@]}"; do [[ -z $only || ${names[i]} =~ $only ]] && printf '%-44s %s\n' "${names[i]}" "${commands[i]//\\/}"; done
  exit 0
fi

# ---------------------------------------------------------------- the builds
bash scripts/install-deps.sh --no-browser >/dev/null
work=$root/build-refcheck
mkdir -p "$work"
if [[ "$(cat "$work/base-src/.commit" 2>/dev/null)" != "$base" ]]; then
  echo "refactor-check: extracting $base into $work/base-src"
  rm -rf "$work/base-src" "$work/base"
  mkdir -p "$work/base-src"
  git archive "$base" | tar -x -C "$work/base-src"
  echo "$base" > "$work/base-src/.commit"
fi
echo "refactor-check: building the base ($base) in $work/base"
cmake -S "$work/base-src" -B "$work/base" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHADOWLAB_BUILD_TESTS=OFF -DSHADOWLAB_BUILD_VIEWER=OFF >/dev/null
cmake --build "$work/base" --target shadowlab_tool >/dev/null
echo "refactor-check: building the work tree in build/"
cmake --preset default >/dev/null
cmake --build --preset default --target shadowlab_tool imagediff >/dev/null
base_tool=$work/base/apps/shadowlab/shadowlab
head_tool=$root/build/apps/shadowlab/shadowlab
imagediff=$root/build/tests/imagediff

# ---------------------------------------------------------------- the runs
out=$work/out
rm -rf "$out"
mkdir -p "$out/base" "$out/head"
run() {  # run TOOL DIR COMMAND SCENE ARGS...: one case into DIR
  local tool=$1 dir=$2 command=$3
  shift 3
  mkdir -p "$dir"
  if [[ $command == render ]]; then
    "$tool" render "$@" --width "$width" --height "$height" -o "$dir/frame.png" --debug-images "$dir" > "$dir/stdout.txt" 2> "$dir/stderr.txt"
  else
    "$tool" compare "$@" --width "$width" --height "$height" --samples 16 -o "$dir" > "$dir/stdout.txt" 2> "$dir/stderr.txt"
  fi
}
# metrics.json without its timing fields (*Ms), keys sorted.
normalise_json() {
  python3 -c '
import json, sys
def strip(v):
    if isinstance(v, dict): return {k: strip(x) for k, x in v.items() if not k.endswith("Ms")}
    if isinstance(v, list): return [strip(x) for x in v]
    return v
print(json.dumps(strip(json.load(open(sys.argv[1]))), sort_keys=True, indent=1))' "$1"
}

table=$out/table.md
{
  echo "# refactor-check: $(git rev-parse --short "$base") (before) against the work tree at $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src shaders apps include || echo ' with uncommitted changes') (after)"
  echo
  echo "${width}x${height}; every file each case writes, compared byte for byte (PNG pixels counted where they differ; metrics.json without its *Ms timing fields)."
  echo
  echo "| case | command | files | files changed | pixels changed |"
  echo "|---|---|---:|---:|---:|"
} > "$table"
cases=0 files_total=0 changed_total=0 pixels_total=0 failed=0
for i in "${!names[@]}"; do
  name=${names[i]}
  [[ -z $only || $name =~ $only ]] || continue
  eval "argv=(${commands[i]})"
  status_base=0 status_head=0
  run "$base_tool" "$out/base/$name" "${argv[@]}" || status_base=$?
  run "$head_tool" "$out/head/$name" "${argv[@]}" || status_head=$?
  cases=$((cases + 1))
  files=0 changed=0 pixels=0 notes=""
  if ((status_base != status_head)); then
    notes=" (exit $status_base before, $status_head after)"
    changed=$((changed + 1))
  elif ((status_base != 0)); then
    notes=" (both exit $status_base: $(head -c 120 "$out/head/$name/stderr.txt" | tr '\n|' '  '))"
    failed=$((failed + 1))
  fi
  while IFS= read -r rel; do
    files=$((files + 1))
    a=$out/base/$name/$rel b=$out/head/$name/$rel
    if [[ ! -f $a || ! -f $b ]]; then
      changed=$((changed + 1))
      notes+=" $rel only $([[ -f $a ]] && echo before || echo after);"
      continue
    fi
    case $rel in
      *.png)
        if ! cmp -s "$a" "$b"; then
          changed=$((changed + 1))
          n=$("$imagediff" "$a" "$b" 2>/dev/null || echo "?")
          if [[ $n =~ ^[0-9]+$ ]]; then pixels=$((pixels + n)); fi
          notes+=" $rel: $n px;"
        fi ;;
      *.json)
        if ! cmp -s <(normalise_json "$a") <(normalise_json "$b"); then
          changed=$((changed + 1))
          notes+=" $rel differs;"
        fi ;;
    esac
  done < <(cd "$out" && { (cd base/"$name" && find . -type f \( -name '*.png' -o -name '*.json' \)); (cd head/"$name" && find . -type f \( -name '*.png' -o -name '*.json' \)); } | sed 's|^\./||' | sort -u)
  files_total=$((files_total + files)) changed_total=$((changed_total + changed)) pixels_total=$((pixels_total + pixels))
  printf '| %s | `%s` | %d | %d | %d%s |\n' "$name" "${commands[i]//\\/}" "$files" "$changed" "$pixels" "$notes" >> "$table"
  printf '%-44s %3d files, %d changed, %d pixels%s\n' "$name" "$files" "$changed" "$pixels" "$notes"
done
{
  echo
  echo "**$cases cases, $files_total files compared, $changed_total changed, $pixels_total pixels changed; $failed cases failed in both builds.**"
} >> "$table"
echo "refactor-check: $cases cases, $files_total files, $changed_total changed, $pixels_total pixels changed, $failed failed in both (table: $table)"

# ---------------------------------------------------------------- timing
if [[ $bench != false ]]; then
  rounds=${REFCHECK_ROUNDS:-3}
  frames=${REFCHECK_FRAMES:-40}
  rows=("learnopengl-shadow-mapping|--set $T=map" "learnopengl-point-shadows|--set $T=map" "two-boxes-sun|--set $T=map --set $M.filter=grid"
        "spot-objects|--set $T=map" "cascades-field|--set $T=map --set $M.cascades=4" "light-leak|--set $T=map")
  if [[ $bench == all ]]; then
    rows=()
    for f in "$S"/*.json "$S"/lecture/*.json; do
      f=${f#"$S"/}
      rows+=("${f%.json}|")
    done
  elif [[ $bench == one ]]; then
    [[ -f "$S/$bench_scene.json" ]] || { echo "refactor-check: --bench-scene: no scene $S/$bench_scene.json" >&2; exit 2; }
    rows=("$bench_scene|")
  fi
  echo
  echo "| scene | settings | before ms (per round) | after ms (per round) | after / before (fastest rounds) | after / before (medians of the rounds) |" | tee "$out/bench.md"
  echo "|---|---|---|---|---:|---:|" | tee -a "$out/bench.md"
  for row in "${rows[@]}"; do
    scene=${row%%|*} sets=${row#*|}
    before=() after=()
    for ((r = 0; r < rounds; ++r)); do
      for which in base head; do
        tool=$base_tool
        [[ $which == head ]] && tool=$head_tool
        # shellcheck disable=SC2086
        "$tool" bench "$S/$scene.json" $sets --width 800 --height 600 --frames "$frames" -o "$out/bench-$which" > /dev/null 2> "$out/bench-$which.log"
        ms=$(python3 -c 'import json,sys; print("%.2f" % json.load(open(sys.argv[1]))["results"][0]["frameMs"]["median"])' "$out/bench-$which/results.json")
        if [[ $which == base ]]; then before+=("$ms"); else after+=("$ms"); fi
      done
    done
    ratio=$(python3 -c 'import sys, statistics as s; a=[float(x) for x in sys.argv[1].split()]; b=[float(x) for x in sys.argv[2].split()]; print("%.3f | %.3f" % (min(b) / min(a), s.median(b) / s.median(a)))' "${before[*]}" "${after[*]}")
    echo "| $scene | \`$sets\` | ${before[*]} | ${after[*]} | $ratio |" | tee -a "$out/bench.md"
  done
fi

((changed_total == 0 && failed == 0))

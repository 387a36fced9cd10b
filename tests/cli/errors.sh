#!/usr/bin/env bash
# Every bad input to the tool: a one-line error naming the file or flag,
# a non-zero exit, no crash (exit code < 128) and no output file.
# Usage: errors.sh SHADOWLAB_BINARY SOURCE_DIR
set -u
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passed=0

# expect_error NAME EXPECTED_SUBSTRING ARGS...
expect_error() {
  local name=$1 expected=$2
  shift 2
  local out="$work/out.png"
  rm -f "$out" "$out.partial"
  local stderr
  stderr=$(cd "$work" && env ${TOOL_ENV:-} "$tool" "$@" 2>&1 >/dev/null)
  local code=$?
  # bench's progress lines (a bar per step) are not error output.
  if [[ -n "${PROGRESS_OK:-}" ]]; then stderr=$(printf '%s\n' "$stderr" | grep -v '^\[[#.]*\] \|^bench: [0-9]* runs\?$'); fi
  local lines
  lines=$(printf '%s' "$stderr" | grep -c '')
  if [[ $code -eq 0 || $code -ge 128 ]]; then
    echo "FAIL $name: exit code $code (expected 1..127)"; failures=$((failures + 1)); return
  fi
  if [[ "$stderr" != *"$expected"* ]]; then
    echo "FAIL $name: stderr does not contain '$expected':"; echo "  $stderr"; failures=$((failures + 1)); return
  fi
  if [[ $lines -ne 1 ]]; then
    echo "FAIL $name: $lines lines of error output (expected 1):"; echo "$stderr"; failures=$((failures + 1)); return
  fi
  if [[ -e "$out" || -e "$out.partial" ]]; then
    echo "FAIL $name: an output file was written"; failures=$((failures + 1)); return
  fi
  echo "ok   $name: $stderr"
  passed=$((passed + 1))
}

printf '{ "nodes": [ \n' > "$work/malformed.json"
printf '{"lights": [{"type":"directional"}, {"type":"directional","direction":[1,2]}]}' > "$work/direction.json"
printf '{"nodes": [{"mesh": "missing.obj"}]}' > "$work/missing-mesh.json"
printf 'not a glb' > "$work/fake.glb"
printf '{"nodes": [{"mesh": "fake.glb"}]}' > "$work/fake-glb.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$work/bad.obj"
printf '{"nodes": [{"mesh": "bad.obj"}]}' > "$work/bad-obj.json"
printf '{"lights": [{"type":"directional","intensity":1e999}]}' > "$work/inf.json"
printf '{"nodes": [{"shape": {"type":"box","size":[1,-1,1]}}]}' > "$work/negative.json"
printf '{"lihgts": []}' > "$work/unknown-key.json"
printf 'P3 not json' > "$work/notjson.json"
printf '{"lights": [{"type":"directional","shadow":{"technique":"planar","planar":{"receivers":"nope"}}}], "nodes": [{"name":"ground","shape":{"type":"plane","size":[4,4]}}]}' > "$work/planar-nope.json"

expect_error malformed-json "malformed.json: invalid JSON" render malformed.json -o out.png
expect_error direction-count "direction.json: lights[1].direction: expected 3 numbers, got 2" render direction.json -o out.png
expect_error missing-mesh "missing-mesh.json: nodes[0].mesh: " render missing-mesh.json -o out.png
expect_error glb-not-gltf "fake.glb" render fake-glb.json -o out.png
expect_error obj-bad-index "bad.obj" render bad-obj.json -o out.png
expect_error infinite-number "inf.json: invalid JSON: number overflow parsing '1e999' (numbers must be finite)" render inf.json -o out.png
expect_error negative-size "negative.json: nodes[0].shape.size: expected 3 numbers > 0" render negative.json -o out.png
expect_error unknown-key "unknown-key.json: lihgts: unknown key" render unknown-key.json -o out.png
expect_error not-json "notjson.json: invalid JSON" render notjson.json -o out.png
expect_error missing-scene "nope.json: file not found" render nope.json -o out.png
expect_error set-bad-path "--set lights[3].intensity=2: index 3 out of range" render -o out.png --set 'lights[3].intensity=2'
expect_error set-bad-value "--set lights[0].intensity=bright: lights[0].intensity: expected a number, got a string" render -o out.png --set 'lights[0].intensity=bright'
expect_error set-unknown-key "--set camera.fov=30: camera.fov: unknown key" render -o out.png --set camera.fov=30
# Two --set of one path: the earlier (here a bad) value would be replaced unchecked.
expect_error set-twice "--set lights[0].intensity=2: lights[0].intensity is already set by --set lights[0].intensity=-1 (give each path once)" render -o out.png --set 'lights[0].intensity=-1' --set 'lights[0].intensity=2'
expect_error set-twice-written-apart "--set lights[00].intensity=2: lights[00].intensity is already set by --set lights[0].intensity=1" bench -o b --set 'lights[0].intensity=1' --set 'lights[00].intensity=2'
# A block set after a path inside it would drop that path's value unread.
expect_error set-block-after-inner "--set lights[0].shadow.map={\"filter\":\"none\"}: replaces lights[0].shadow.map.size, set by --set lights[0].shadow.map.size=7 before it" render -o out.png --set 'lights[0].shadow.map.size=7' --set 'lights[0].shadow.map={"filter":"none"}'
expect_error set-light-after-intensity "--set lights[0]={\"type\":\"directional\"}: replaces lights[0].intensity, set by --set lights[0].intensity=-1 before it" compare -o c --set 'lights[0].intensity=-1' --set 'lights[0]={"type":"directional"}'
# The other way round a path inside a block refines it: allowed, and it applies.
(cd "$work" && "$tool" render -o refined.png --width 32 --height 24 --set 'lights[0].shadow.map={"filter":"none"}' --set 'lights[0].shadow.map.size=7' 2>refined.txt) \
  && { echo "FAIL set-inner-after-block: the refined size 7 (under 16) was not checked"; failures=$((failures + 1)); } \
  || { grep -q "lights\[0\]\.shadow\.map\.size=7" "$work/refined.txt" && passed=$((passed + 1)) \
       || { echo "FAIL set-inner-after-block: $(cat "$work/refined.txt")"; failures=$((failures + 1)); }; }
expect_error set-no-value "--set camera: expected key=value" render -o out.png --set camera
expect_error map-past-budget "lights[0].shadow.map: the shadow maps of 1 light(s) need 2.00 GiB, more than the budget of 1 GiB" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.size=16384 --set 'lights[0].shadow.map.format="rgba8"'
expect_error map-size-range "--set lights[0].shadow.map.size=16385: lights[0].shadow.map.size: expected an integer in 0..16384, got 16385" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.size=16385
# The names come from the filters' table (src/techniques/map/options/Filters.cpp): the list's start, and what was given.
expect_error map-bad-filter "--set lights[0].shadow.map.filter=pcff: lights[0].shadow.map.filter: expected one of \"none\", \"hardware\", \"grid\"" render -o out.png --set lights[0].shadow.map.filter=pcff
expect_error map-bad-filter-names-it "), got \"pcff\"" render -o out.png --set lights[0].shadow.map.filter=pcff
expect_error map-point-dither "--set lights[0].shadow.map.filter=dither4: lights[0].shadow.map.filter: map: filter \"dither4\" is for 2D maps" render "$src/scenes/room-point.json" -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.filter=dither4
expect_error map-spot-pcf20 "--set lights[0].shadow.map.filter=pcf20: lights[0].shadow.map.filter: map: filter \"pcf20\" (the lecture's 20 directions) is for point lights' cube maps" render "$src/scenes/spot-objects.json" -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.filter=pcf20
expect_error planar-unknown-receiver "lights[0].shadow.planar.receivers: no node named 'nowhere'" render "$src/scenes/two-boxes-sun.json" -o out.png --set lights[0].shadow.technique=planar --set lights[0].shadow.planar.receivers=nowhere
expect_error planar-receiver-type "--set lights[0].shadow.planar.receivers=5: lights[0].shadow.planar.receivers: expected a string" render "$src/scenes/two-boxes-sun.json" -o out.png --set lights[0].shadow.planar.receivers=5
expect_error width-zero "--width" render -o out.png --width 0
expect_error width-text "--width" render -o out.png --width wide
expect_error width-past-gpu-limit "--width 100000: exceeds this GPU's limit" render -o out.png --width 100000
expect_error output-not-png "-o out.jpg: expected a .png file name" render -o out.jpg
expect_error output-missing-dir "directory" render -o no/such/dir/out.png
expect_error unknown-subcommand "shadowlab: error:" frobnicate
expect_error unknown-flag "shadowlab: error:" render --frobnicate
# Animated lights and frame sequences.
expect_error frames-without-field "-o out.png: --frames 3 needs a frame number field in the name, e.g. frame_%03d.png" render -o out.png --frames 3
expect_error frames-zero "--frames" render -o out.png --frames 0
expect_error frames-bad-field "-o out%s.png: '%' starts a frame number field such as %d or %03d" render -o 'out%s.png' --frames 2
expect_error frames-two-fields "-o out%d%d.png: more than one frame number field" render -o 'out%d%d.png' --frames 2
expect_error time-nan "--time nan: expected a finite number of seconds" render -o out.png --time nan
expect_error time-inf "--time inf: expected a finite number of seconds" render -o out.png --time inf
expect_error time-text "--time" render -o out.png --time soon
expect_error time-empty "--time: expected a value, got an empty string" render -o out.png --time ''
expect_error fps-empty "--fps: expected a value, got an empty string" render -o out.png --fps ''
expect_error debug-images-empty "--debug-images: expected a value, got an empty string" render -o out.png --debug-images ''
expect_error set-empty "--set: expected a value, got an empty string" render -o out.png --set ''
expect_error vary-empty "--vary: expected a value, got an empty string" bench -o out.png --vary ''
expect_error vary-same-key-twice "--vary lights[0].intensity=3: lights[0].intensity is already varied by --vary lights[0].intensity=1,2" bench -o out.png --vary lights[0].intensity=1,2 --vary lights[0].intensity=3
expect_error frame-width-999 "-o f%999d.png: the frame number's width is 999 (at most 20)" render -o 'f%999d.png' --frames 2
expect_error frame-width-left-999 "-o f%-999d.png: the frame number's width is 999 (at most 20)" render -o 'f%-999d.png' --frames 2
if compgen -G "$work/f*.png" >/dev/null; then echo "FAIL frame-width: left $(cd "$work" && echo f*.png)"; failures=$((failures + 1)); fi
# Render-time errors name where the value came from: the --set, else the scene file.
expect_error budget-from-set "--set lights[0].shadow.map.cascades=8: lights[0].shadow.map: the shadow maps of 1 light(s) need 8.00 GiB" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.size=16384 --set lights[0].shadow.map.cascades=8
expect_error planar-receivers-from-set "--set lights[0].shadow.planar.receivers=nope: lights[0].shadow.planar.receivers: no node named 'nope'" render -o out.png --set lights[0].shadow.technique=planar --set lights[0].shadow.planar.receivers=nope
expect_error planar-receivers-from-file "planar-nope.json: lights[0].shadow.planar.receivers: no node named 'nope'" render planar-nope.json -o out.png
expect_error splits-beyond-far "--set lights[0].shadow.map.cascadeSplits=\"500\": lights[0].shadow.map.cascadeSplits: \"500\": the last split must lie before the camera's far plane (camera.far 100)" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.cascades=2 --set 'lights[0].shadow.map.cascadeSplits="500"'
expect_error splits-inside-near "the first split must lie beyond the camera's near plane (camera.near 0.1)" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.cascades=2 --set 'lights[0].shadow.map.cascadeSplits="0.01"'
expect_error warp-spot "--set lights[0].shadow.map.warp=lispsm: lights[0].shadow.map.warp: map: warp \"lispsm\" is for directional lights" render "$src/scenes/spot-objects.json" -o out.png --set lights[0].shadow.map.warp=lispsm
expect_error warp-cascades "lights[0].shadow.map.warp: map: warp \"lispsm\" with cascades takes stabilize false (a warped map cannot be snapped to whole texels); or use warp \"none\"" render -o out.png --set lights[0].shadow.map.warp=lispsm --set lights[0].shadow.map.cascades=3
expect_error outside-repeat-cube "--set lights[0].shadow.map.outside=repeat: lights[0].shadow.map.outside: map: outside \"repeat\" is for one 2D map" render "$src/scenes/room-point.json" -o out.png --set lights[0].shadow.map.outside=repeat
expect_error warp-near-zero "--set lights[0].shadow.map.warpNear=0: lights[0].shadow.map.warpNear: expected a number in 0.01..1000, got 0" render -o out.png --set lights[0].shadow.map.warpNear=0
# The map budget counts translucent casters' transmittance and mip chains, and names the light that holds the memory.
# The file's size alone fits; a --set of cascades takes it past the budget: the --set is named, not the file.
printf '{"lights":[{"type":"directional","shadow":{"technique":"map","map":{"size":8192,"cascades":2}}}],"nodes":[{"shape":{"type":"box"}}]}' > "$work/fits.json"
expect_error budget-from-set-over-file "--set lights[0].shadow.map.cascades=8: lights[0].shadow.map: the shadow maps of 1 light(s) need 2.00 GiB" render fits.json -o out.png --set lights[0].shadow.map.cascades=8
expect_error budget-translucent "lights[0].shadow.map: the shadow maps of 1 light(s) need 3.00 GiB" render "$src/scenes/glass-panel.json" -o out.png --set 'materials.glass.alphaMode="blend"' --set lights[0].shadow.map.size=16384
expect_error budget-mipmaps "lights[0].shadow.map: the shadow maps of 1 light(s) need 2.58 GiB" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.representation=evsm4 --set lights[0].shadow.map.mipmaps=true --set lights[0].shadow.map.size=8192
expect_error budget-names-the-light "lights[1].shadow.map: the shadow maps of 2 light(s) need 2.00 GiB" render -o out.png --set 'lights=[{"type":"directional","direction":[0,-1,0.3],"shadow":{"technique":"map","map":{"size":512}}},{"type":"directional","direction":[0,-1,0.2],"shadow":{"technique":"map","map":{"size":16384,"cascades":2}}}]'
# A combination check names the option at fault and the --set that set it, not the technique.
expect_error splits-order-blames-splits "--set lights[0].shadow.map.cascadeSplits=\"5 3\": lights[0].shadow.map.cascadeSplits: map: cascadeSplits \"5 3\": expected increasing distances > 0" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.cascades=3 --set 'lights[0].shadow.map.cascadeSplits="5 3"'
expect_error moments-filter-blames-filter "--set lights[0].shadow.map.filter=pcss: lights[0].shadow.map.filter: map: filter \"pcss\": a moment map" render -o out.png --set lights[0].shadow.technique=map --set lights[0].shadow.map.representation=vsm --set lights[0].shadow.map.filter=pcss
# A huge value is not echoed whole: the message is cut in the middle and keeps its reason.
huge=$(head -c 110000 /dev/zero | tr '\0' 'x')
expect_error huge-value-cut "bytes cut) ...xxxx" render -o out.png --set "lights[0].intensity=$huge"
msg=$(cd "$work" && "$tool" render -o out.png --set "lights[0].intensity=$huge" 2>&1 >/dev/null)
if [[ ${#msg} -gt 800 || "$msg" != *"lights[0].intensity: expected a number, got a string" ]]; then echo "FAIL huge-value-cut: ${#msg} bytes"; failures=$((failures + 1)); fi
# The frame-memory guard with a small injected budget (no multi-GB allocation): render, and the viewer's window before it opens.
TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=1000000 expect_error memory-injected-render "--width 640 --height 360: the frame needs about 14.1 MiB (estimated 64 bytes per pixel), more than the budget of 1.0 MiB (SHADOWLAB_MEMORY_LIMIT_BYTES)" render -o out.png --width 640 --height 360
if "$tool" view --help >/dev/null 2>&1; then  # built with the viewer
  TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=1000000 expect_error memory-injected-view "--width 1024 --height 768: the frame needs about 48.0 MiB" view --width 1024 --height 768
fi
# Names the system refuses (too long, a loop of links): the flag or file and the reason, never raw "filesystem error:" text.
long=$(printf 'x%.0s' $(seq 300))
ln -s loop-b "$work/loop-a"; ln -s loop-a "$work/loop-b"
expect_error output-name-too-long "-o $long.png: File name too long" render -o "$long.png"
expect_error output-in-link-loop "-o loop-a/x.png: Too many levels of symbolic links" render -o loop-a/x.png
expect_error compare-output-in-link-loop "-o loop-a/d: Too many levels of symbolic links" compare -o loop-a/d
expect_error bench-output-name-too-long "-o $long: File name too long" bench -o "$long"
expect_error scene-name-too-long "$long.json: File name too long" render "$long.json" -o out.png
expect_error scene-in-link-loop "loop-a/s.json: Too many levels of symbolic links" render loop-a/s.json -o out.png
expect_error bench-scene-in-link-loop "loop-a/s.json: Too many levels of symbolic links" bench loop-a/s.json -o outdir
if "$tool" view --help >/dev/null 2>&1; then
  # A NUL byte in a script line is shown, not where the message stops.
  printf 'bogus\0tail\n' > "$work/nul.txt"
  expect_error script-nul-byte "nul.txt:1: a NUL byte in the line (expected text)" view --script nul.txt
  printf 'set lights[0].intensity=1\0x\n' > "$work/nul-set.txt"
  expect_error script-nul-in-value "nul-set.txt:1: a NUL byte in the line" view --script nul-set.txt
  # A resize is held to the frame-memory guard as --width and --height are.
  printf 'resize 1024 768\n' > "$work/resize.txt"
  TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=1000000 expect_error script-resize-past-memory "resize.txt:1: resize 1024 768: --width 1024 --height 768: the frame needs about 48.0 MiB" view --width 64 --height 64 --script resize.txt
  expect_error script-in-link-loop "--script loop-a/s.txt: Too many levels of symbolic links" view --script loop-a/s.txt
  printf 'save loop-a/x.json\n' > "$work/save-loop.txt"
  expect_error script-save-in-link-loop "save-loop.txt:1: save loop-a/x.json: Too many levels of symbolic links" view --script save-loop.txt
  printf 'compare loop-a/d\n' > "$work/compare-loop.txt"
  expect_error script-compare-in-link-loop "compare-loop.txt:1: compare loop-a/d: Too many levels of symbolic links" view --script compare-loop.txt
fi
# The device-memory guard, with a driver that reports 1 MiB free (injected: llvmpipe reports none).
TOOL_ENV=SHADOWLAB_DEVICE_MEMORY_KIB=1024 expect_error memory-device "--width 640 --height 360: the frame needs about 14.1 MiB (estimated 64 bytes per pixel), more than the budget of 1.0 MiB (the device's free memory, as SHADOWLAB_DEVICE_MEMORY_KIB reports it)" render -o out.png --width 640 --height 360
if ! env SHADOWLAB_DEVICE_MEMORY_KIB=1024 "$tool" info | grep -q '^device memory free: 1 MiB (SHADOWLAB_DEVICE_MEMORY_KIB)$'; then echo "FAIL info-device-memory"; failures=$((failures + 1)); fi
TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=lots expect_error memory-limit-bad "SHADOWLAB_MEMORY_LIMIT_BYTES=lots: expected a finite decimal number of bytes, at least 1024" render -o out.png
TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=1e400 expect_error memory-limit-infinite "SHADOWLAB_MEMORY_LIMIT_BYTES=1e400: expected a finite decimal number of bytes" render -o out.png
TOOL_ENV=SHADOWLAB_MEMORY_LIMIT_BYTES=0x10 expect_error memory-limit-hex "SHADOWLAB_MEMORY_LIMIT_BYTES=0x10: expected a finite decimal number of bytes" render -o out.png
TOOL_ENV=SHADOWLAB_DEVICE_MEMORY_KIB=abc expect_error device-memory-bad "SHADOWLAB_DEVICE_MEMORY_KIB=abc: expected a whole number of KiB" render -o out.png
TOOL_ENV=SHADOWLAB_DEVICE_MEMORY_KIB=-5 expect_error device-memory-negative "SHADOWLAB_DEVICE_MEMORY_KIB=-5: expected a whole number of KiB" render -o out.png
# --debug-images names itself when its directory cannot be (was a raw "filesystem error"), and nothing is written.
touch "$work/plainfile"
expect_error debug-images-is-a-file "--debug-images plainfile: exists and is not a directory" render -o out.png --debug-images plainfile
expect_error debug-images-under-a-file "--debug-images plainfile/sub: cannot create the directory (Not a directory)" render -o out.png --debug-images plainfile/sub
expect_error number-past-float "--set lights[0].intensity=1e300: lights[0].intensity: expected a finite number of magnitude at most 3e38 (a float's range), got 1e+300" render -o out.png --set 'lights[0].intensity=1e300'
expect_error unknown-command "paint: not a command (expected one of render compare bench export techniques info" paint
# export: a name that is not .gltf or .glb, --camera for a scene file or the default scene.
expect_error export-not-gltf "-o out.png: expected a .gltf or .glb file name" export -o out.png
expect_error export-camera-default "--camera 1: needs a glTF file (the default scene has one camera)" export --camera 1 -o out.gltf
expect_error render-camera-json "two-boxes-sun.json: a camera index is for glTF files" render "$src/scenes/two-boxes-sun.json" --camera 0 -o out.png
expect_error view-from-light-range "--view-from-light: Value -1 not in range 0 to 255" render -o out.png --view-from-light -1
expect_error fps-zero "--fps 0: expected a finite number of frames per second > 0" render -o out.png --fps 0 --frames 2
expect_error fps-negative "--fps -30: expected a finite number of frames per second > 0" render -o out.png --fps -30
expect_error frame-time-overflows "--time 1.7e+308 --fps 1e-308: frame 1's time is not a finite number of seconds" render -o 'out%d.png' --frames 2 --time 1.7e308 --fps 1e-308
expect_error compare-time-nan "--time nan: expected a finite number of seconds" compare -o out.png --time nan
expect_error bench-fps-inf "--fps inf: expected a finite number of frames per second > 0" bench -o out.png --fps inf
expect_error path-on-directional "--set lights[0].path.type=sine: lights[0].path: a directional light has no position to move" render -o out.png --set lights[0].path.type=sine
expect_error path-unknown-type "--set lights[0].path.type=circle: lights[0].path.type: unknown path type 'circle' (expected sine or keyframes)" render "$src/scenes/room-point.json" -o out.png --set lights[0].path.type=circle
expect_error path-times-decreasing "lights[0].path.times[1]: expected times strictly increasing, got 1 after 2" render "$src/scenes/room-point.json" -o out.png --set 'lights[0].path={"type":"keyframes","times":[2,1],"positions":[[0,1,0],[0,2,0]]}'

# No OpenGL 4.5 core: Mesa can be told to offer only 4.1 (other drivers ignore this).
if "$tool" info | grep -q "Mesa"; then
  TOOL_ENV="MESA_GL_VERSION_OVERRIDE=4.1" expect_error no-gl45 "OpenGL 4.5 core is required, found '4.1" render -o out.png
fi

# compare and bench: the same rules; the output here is a directory.
expect_dir_error() {
  local name=$1 expected=$2
  shift 2
  rm -rf "$work/outdir"
  expect_error "$name" "$expected" "$@"
  if [[ -e "$work/outdir" ]]; then echo "FAIL $name: output directory was created"; failures=$((failures + 1)); passed=$((passed - 1)); fi
}
expect_dir_error compare-missing-scene "nope.json: file not found" compare nope.json -o outdir
expect_dir_error compare-bad-set "--set lights[0].intensity=x: lights[0].intensity: expected a number" compare -o outdir --set 'lights[0].intensity=x'
expect_dir_error compare-samples-zero "--samples" compare -o outdir --samples 0
expect_dir_error compare-output-is-file "-o malformed.json: exists and is not a directory" compare -o malformed.json
expect_dir_error bench-missing-scene "nope.json: file not found" bench nope.json -o outdir
expect_dir_error bench-bad-vary "--vary lights[0].intensity: expected key=value1,value2" bench -o outdir --vary 'lights[0].intensity'
# A run that fails mid-bench names its scene and combination (its maps pass the load, not the memory budget).
PROGRESS_OK=1 expect_dir_error bench-run-names-combination "bench run 2/2 ($src/scenes/two-boxes-sun.json, --vary lights[0].shadow.map.size=16384): --vary lights[0].shadow.map.size=16384: lights[0].shadow.map: the shadow maps of 1 light(s) need" \
  bench "$src/scenes/two-boxes-sun.json" -o outdir --frames 1 --warmup 0 --width 32 --height 32 --set lights[0].shadow.technique=map --set 'lights[0].shadow.map.format="rgba8"' --vary lights[0].shadow.map.size=64,16384
expect_dir_error bench-vary-bad-value "--vary lights[0].intensity=abc: lights[0].intensity: expected a number" bench -o outdir --vary 'lights[0].intensity=1,abc'
expect_dir_error bench-vary-empty-value "--vary lights[0].intensity=1,,2: empty value" bench -o outdir --vary 'lights[0].intensity=1,,2'
expect_dir_error bench-frames-zero "--frames" bench -o outdir --frames 0
expect_dir_error bench-bad-scene "direction.json: lights[1].direction" bench direction.json -o outdir

# --- Hostile input (issue 12): the reproducers, through the tool. -----------
corpus="$src/fuzz/corpus"
cp "$corpus"/files/* "$work/"
cp "$corpus"/gltf/repro-*.gltf "$corpus"/scene/repro-*.json "$work/"
scene_of() { printf '{"nodes": [{"mesh": "%s"}]}' "$1" > "$work/$2"; }
scene_of repro-accessor-offset-wraps.gltf gltf-offset.json
scene_of repro-accessor-count-huge.gltf gltf-count.json
scene_of repro-node-cycle.gltf gltf-cycle.json
scene_of repro-translation-1e300.gltf gltf-inf.json
scene_of repro-texture-16385x1.gltf gltf-wide-texture.json
printf '{"materials": {"m": {"baseColorTexture": "wide-16385x1.png"}}, "nodes": [{"shape": {"type": "box"}, "material": "m"}]}' > "$work/wide-texture.json"
printf '{"lights": [{"type": "directional", "direction": [1e30, 1e30, 1e30]}], "nodes": [{"shape": {"type": "box"}}]}' > "$work/huge-direction.json"
printf '{"nodes": [{"mesh": "a\\nb.obj"}]}' > "$work/newline-mesh.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1\v\f\r 2\nf 1 2 3\n' > "$work/control.obj"
printf '{"nodes": [{"mesh": "control.obj"}]}' > "$work/control-obj.json"
mkdir -p "$work/dir.png" "$work/scenedir"

expect_error gltf-offset-wraps "gltf-offset.json: nodes[0].mesh: repro-accessor-offset-wraps.gltf: accessor 0 (POSITION): byteOffset 18446744073709551604" render gltf-offset.json -o out.png
expect_error gltf-count-huge "count 1537228672809129301 exceeds the limit of 16777216 elements" render gltf-count.json -o out.png
expect_error gltf-cycle "repro-node-cycle.gltf: node 0 is referenced more than once (a cycle" render gltf-cycle.json -o out.png
expect_error cli-parse-newline '--width: Value 1\n2 not in range' render -o out.png --width $'1\n2'
expect_error gltf-translation-1e300 "repro-translation-1e300.gltf: node 0: transform values must be finite" render gltf-inf.json -o out.png
expect_error gltf-texture-past-gpu-limit "gltf-wide-texture.json: nodes[0].mesh: " render gltf-wide-texture.json -o out.png
expect_error texture-past-gpu-limit "wide-texture.json: materials.m.baseColorTexture (" render wide-texture.json -o out.png
expect_error children-nested-10000 "repro-children-nested-10000.json: JSON nested deeper than 200 levels" render repro-children-nested-10000.json -o out.png
expect_error lights-past-limit "repro-lights-300.json: lights: expected at most 256 lights, got 300" render repro-lights-300.json -o out.png
expect_error segments-2-64 "majorSegments: expected an integer in 3..1024, got 18446744073709551615" render 'repro-segments-2^64-1.json' -o out.png
expect_error camera-3e38 "camera: camera position and target are too far apart" render repro-camera-3e38.json -o out.png
expect_error texture-is-directory "materials.m.baseColorTexture: texture . is not a regular file" render repro-texture-is-directory.json -o out.png
expect_error transform-overflows "nodes[0].children[0]: world transform is not finite" render repro-translation-overflows-composed.json -o out.png
expect_error newline-in-key 'repro-newline-in-key.json: na\nme: unknown key' render repro-newline-in-key.json -o out.png
expect_error newline-in-mesh-path 'a\nb.obj: file not found' render newline-mesh.json -o out.png
expect_error obj-control-bytes "control.obj:3: bad number '1\\v\\f\\r' after 'v'" render control-obj.json -o out.png
expect_error set-index-past-2-64 "index 99999999999999999999 is too large" render -o out.png --set 'lights[99999999999999999999].intensity=1'
expect_error set-newline-in-value '--set camera.fovY=1\n2: camera.fovY: expected a number' render -o out.png --set $'camera.fovY=1\n2'
expect_error set-invalid-utf8 "name: invalid UTF-8 in the string 'a\\xffb'" render -o out.png --set $'name=a\xffb'
expect_error render-empty-scene "render: scene: empty path" render "" -o out.png
expect_error render-empty-output "-o: empty path" render -o ""
expect_error output-is-directory "-o dir.png: is a directory" render -o dir.png
# The frame-memory estimate: 16384x16384 is 16 GiB at 64 bytes per pixel,
# refused on any machine with less than 32 GiB (and 65536^2 on any machine).
if (( $(awk '/MemTotal/ {print $2}' /proc/meminfo) < 32 * 1024 * 1024 )); then side=16384; else side=65536; fi
expect_error frame-memory "--width $side --height $side: the frame needs about" render -o out.png --width $side --height $side
expect_dir_error compare-frame-memory "--width 65536 --height 65536: the frame needs about" compare -o outdir --width 65536 --height 65536
# A directional light of [1e30, 1e30, 1e30] is normalised, not zeroed: it renders.
if (cd "$work" && "$tool" render huge-direction.json -o huge.png --width 32 --height 18 >/dev/null 2>&1) && [[ -s "$work/huge.png" ]]; then
  echo "ok   huge-direction renders"; passed=$((passed + 1))
else
  echo "FAIL huge-direction: did not render"; failures=$((failures + 1))
fi

# bench: count first, and leave nothing behind on any failure.
expect_no_leftovers() {
  local name=$1
  if compgen -G "$work/outdir*" >/dev/null; then
    echo "FAIL $name: left $(cd "$work" && echo outdir*)"; failures=$((failures + 1)); passed=$((passed - 1))
  fi
}
vary=()
for k in 0 1 2 3 4 5 6; do vary+=(--vary "lights[$k].intensity=1,2,3,4,5,6,7,8,9,10"); done
expect_dir_error bench-too-many-runs "--vary: 1 scene x 10 x 10 x 10 x 10 x 10 x 10 x 10 values make more than 10000 runs" bench -o outdir "${vary[@]}"
expect_no_leftovers bench-too-many-runs
expect_dir_error bench-empty-scene "bench: empty scene path" bench "" -o outdir
expect_dir_error bench-scene-is-directory "scenedir: not a regular file (expected a scene file)" bench scenedir -o outdir
expect_dir_error bench-invalid-utf8-name "name: invalid UTF-8" bench -o outdir --set $'name=a\xffb'
expect_no_leftovers bench-invalid-utf8-name
printf '{}' > "$work/bad"$'\xff'".json"
expect_dir_error bench-invalid-utf8-path "file name is not valid UTF-8" bench "bad"$'\xff'".json" -o outdir
# The first scene renders and writes its images, the second fails at upload:
# nothing of the first may remain.
bench_small=(--frames 1 --warmup 0 --width 16 --height 16 --samples 1)
PROGRESS_OK=1 expect_dir_error bench-texture-past-gpu-limit "wide-texture.json: materials.m.baseColorTexture (" bench huge-direction.json wide-texture.json -o outdir "${bench_small[@]}"
expect_no_leftovers bench-texture-past-gpu-limit
# An existing output directory keeps its other files and gets no partial results.
mkdir -p "$work/keep" && echo mine > "$work/keep/notes.txt"
(cd "$work" && "$tool" bench huge-direction.json wide-texture.json -o keep "${bench_small[@]}" >/dev/null 2>&1)
if [[ "$(cd "$work/keep" && ls)" == "notes.txt" ]] && ! compgen -G "$work/keep.partial*" >/dev/null; then
  echo "ok   bench-existing-output-untouched"; passed=$((passed + 1))
else
  echo "FAIL bench-existing-output-untouched: $(cd "$work" && ls keep keep.partial* 2>&1)"; failures=$((failures + 1))
fi
# A 300-character scene name: file names are shortened, the run succeeds.
long=$(printf 'n%.0s' $(seq 300))
if (cd "$work" && "$tool" bench huge-direction.json -o longname --set "name=$long" "${bench_small[@]}" >/dev/null 2>&1) &&
   [[ -s "$work/longname/results.json" ]] && ! compgen -G "$work/longname.partial*" >/dev/null; then
  echo "ok   bench-300-character-name"; passed=$((passed + 1))
else
  echo "FAIL bench-300-character-name"; failures=$((failures + 1))
fi

# Outputs renamed into place all or none (OutputFiles.h): a directory in the
# way of one of them fails the command in one line naming that file, and
# leaves none of the others, no temporary, and earlier files as they were.
# expect_all_or_nothing NAME EXPECTED DIR BLOCKING_DIRECTORY EXISTING_FILE ARGS...
expect_all_or_nothing() {
  local name=$1 expected=$2 dir=$3 blocker=$4 existing=$5
  shift 5
  local stderr code
  stderr=$(cd "$work" && "$tool" "$@" 2>&1 >/dev/null)
  code=$?
  local left
  left=$(cd "$work/$dir" && ls -A | grep -v -x -e "$blocker" -e "$existing")
  if [[ $code -ne 0 && $code -lt 128 && $(printf '%s' "$stderr" | grep -c '') -eq 1 && "$stderr" == *"$expected"* && -z "$left" &&
        "$(cat "$work/$dir/$existing")" == "earlier" ]]; then
    echo "ok   $name: $stderr"; passed=$((passed + 1))
  else
    echo "FAIL $name (exit $code): $stderr; left: $left; $existing: $(cat "$work/$dir/$existing" 2>&1)"; failures=$((failures + 1))
  fi
}
mkdir -p "$work/cmpblocked/technique.png" && echo earlier > "$work/cmpblocked/reference.png"
expect_all_or_nothing compare-output-blocked-by-directory "cmpblocked/technique.png: cannot write (a directory of that name is in the way)" \
  cmpblocked technique.png reference.png compare -o cmpblocked --width 32 --height 18 --samples 1
mkdir -p "$work/seq" "$work/seq/shot-0002.png" && echo earlier > "$work/seq/shot-0000.png"
expect_all_or_nothing render-sequence-blocked-by-directory "-o seq/shot-0002.png: is a directory (expected a .png file name)" \
  seq shot-0002.png shot-0000.png render -o seq/shot-%04d.png --frames 3 --width 32 --height 18
mkdir -p "$work/dbg" "$work/dbg/blocker-light0-map.png" && echo earlier > "$work/dbg/blocker.png"
expect_all_or_nothing render-debug-image-blocked-by-directory "dbg/blocker-light0-map.png: cannot write (a directory of that name is in the way)" \
  dbg blocker-light0-map.png blocker.png render --set lights[0].shadow.technique=map -o dbg/blocker.png --debug shadow-maps --width 32 --height 18

# bench's --vary and --set: one key (or a key and what holds it) set twice is refused, as is a value given twice.
PROGRESS_OK=1 expect_error vary-holding-key "--vary lights[0].shadow.technique=planar,map: lights[0].shadow.technique is already varied by --vary lights[0].shadow={\"technique\":\"none\"},{\"technique\":\"map\"} (one holds the other)" bench -o outdir --vary 'lights[0].shadow={"technique":"none"},{"technique":"map"}' --vary lights[0].shadow.technique=planar,map
PROGRESS_OK=1 expect_error vary-value-twice "--vary lights[0].intensity=1,1: the value 1 is given twice" bench -o outdir --vary lights[0].intensity=1,1
PROGRESS_OK=1 expect_error vary-and-set "--vary lights[0].intensity=1,2: lights[0].intensity is also set by --set lights[0].intensity=5" bench -o outdir --set lights[0].intensity=5 --vary lights[0].intensity=1,2
PROGRESS_OK=1 expect_error bench-check-names-scene "cascades are for directional lights; a spot or point light takes one map (cascades 1) (bench: $src/scenes/spot-objects.json, --vary lights[0].shadow.map.cascades=4; --skip-unsupported leaves such runs out)" bench "$src/scenes/two-boxes-sun.json" "$src/scenes/spot-objects.json" -o outdir --set lights[0].shadow.technique=map --vary lights[0].shadow.map.cascades=1,4
# Cascade splits: what is wrong with them, in the numbers as written and as the 32-bit floats they become.
expect_error splits-past-float "cascadeSplits \"1e39\": expected increasing distances > 0; 1e39 is not finite or past a 32-bit float's range" render -o out.png --set lights[0].shadow.map.cascades=2 --set 'lights[0].shadow.map.cascadeSplits="1e39"'
expect_error splits-equal-as-floats "5.0000001 does not follow 5 (it is 5 as a 32-bit float)" render -o out.png --set lights[0].shadow.map.cascades=3 --set 'lights[0].shadow.map.cascadeSplits="5, 5.0000001"'
printf '{"camera":{"far":50},"lights":[{"type":"directional","shadow":{"technique":"map","map":{"cascades":2,"cascadeSplits":"49.99999999"}}}]}' > "$work/split-far.json"
expect_error splits-round-onto-far "split-far.json: lights[0].shadow.map.cascadeSplits: \"49.99999999\": the last split must lie before the camera's far plane (camera.far 50); as a 32-bit float it is 50" render split-far.json -o out.png
# The reference's rays are bounded: --samples 65536 at 1920x1080 traced for many minutes.
expect_error compare-too-many-rays "--samples 65536 at 1920x1080: 1.36e+11 rays for each soft light's reference, more than the limit of 2^31" compare -o cmpdir --samples 65536 --width 1920 --height 1080
# And the scene's: each of 5 soft lights within the limit, together past 2^32 (issue 59: 64 lights at 65536 traced 6e10 rays).
expect_error compare-scene-too-many-rays "--samples 16384 at 256x256: 5.37e+09 rays for the reference of 5 soft lights, more than the limit of 2^32 for a scene" compare -o cmpdir --samples 16384 --width 256 --height 256 --set 'lights=[{"type":"point","position":[0,3,0],"size":0.2},{"type":"point","position":[0,3,0],"size":0.2},{"type":"point","position":[0,3,0],"size":0.2},{"type":"point","position":[0,3,0],"size":0.2},{"type":"point","position":[0,3,0],"size":0.2}]'
expect_error bench-too-many-rays "--samples 65536 at 512x512: 1.72e+10 rays" bench -o outdir --samples 65536 --width 512 --height 512
expect_error bench-output-cannot-be-made "-o /proc/shadowlab-bench: cannot create the directory" bench -o /proc/shadowlab-bench "${bench_small[@]}"
# bench says what the techniques noticed (a planar light with nothing planar to fall on) and keeps it in the row.
printf '{"lights":[{"type":"directional","shadow":{"technique":"planar"}}],"nodes":[{"name":"ball","shape":{"type":"sphere"},"translation":[0,2,0]}]}' > "$work/planar-none.json"
if (cd "$work" && "$tool" bench planar-none.json -o planar-bench "${bench_small[@]}" 2>planar-bench.err >/dev/null) &&
   grep -q "^shadowlab: note: bench run 1/1 (.*): lights\[0\].shadow.planar" "$work/planar-bench.err" && grep -q '"notes": \[' "$work/planar-bench/results.json" &&
   ! grep -q '"notes": \[\]' "$work/planar-bench/results.json"; then
  echo "ok   bench-notes"; passed=$((passed + 1))
else
  echo "FAIL bench-notes: $(cat "$work/planar-bench.err")"; failures=$((failures + 1))
fi

PROGRESS_OK=1 expect_error vary-index-spelled-twice "--vary lights[00].intensity=3,4: lights[00].intensity is already varied by --vary lights[0].intensity=1,2 (give all its values in one --vary)" bench -o outdir --vary lights[0].intensity=1,2 --vary lights[00].intensity=3,4
PROGRESS_OK=1 expect_error vary-and-set-index-spelled "is also set by --set lights[00].intensity=5" bench -o outdir --set lights[00].intensity=5 --vary lights[0].intensity=1,2
# 20,000 values: refused for the 10,000-run limit, naming the key, before
# the values are compared (issue 59: every pair was compared first, a
# minute and more, and then the product was refused without the key).
PROGRESS_OK=1 expect_error vary-20000-values "--vary lights[0].intensity=...: 20000 values make more than 10000 runs (the limit)" bench -o outdir --vary "lights[0].intensity=$(seq -s, 0 19999)"
PROGRESS_OK=1 expect_error vary-value-twice-spelled "--vary lights[0].intensity=1,1.0: the value 1.0 (1) is given twice" bench -o outdir --vary lights[0].intensity=1,1.0
PROGRESS_OK=1 expect_error bench-budget-from-set "bench run 1/1 (fits.json): --set lights[0].shadow.map.cascades=8: lights[0].shadow.map: the shadow maps of 1 light(s) need 2.00 GiB" bench fits.json -o outdir --set lights[0].shadow.map.cascades=8 "${bench_small[@]}"
# A write that fails part way (a full disk; here the file-size limit, which
# fails the same write calls) is an error naming the file and its reason,
# with nothing left: no truncated image, no temporary, no directory made.
# expect_clean_failure NAME EXPECTED ARGS...: run in a fresh directory, which must stay empty.
expect_clean_failure() {
  local name=$1 expected=$2
  shift 2
  local dir="$work/clean-$name"
  mkdir -p "$dir"
  local stderr code
  stderr=$(cd "$dir" && "$@" 2>&1 >/dev/null)
  code=$?
  stderr=$(printf '%s\n' "$stderr" | grep -v '^\[[#.]*\] \|^bench: [0-9]* runs\?$')  # bench's progress is not error output
  local left
  left=$(ls -A "$dir")
  if [[ $code -ne 0 && $code -lt 128 && $(printf '%s' "$stderr" | grep -c '') -eq 1 && "$stderr" == *"$expected"* && -z "$left" ]]; then
    echo "ok   $name: $stderr"; passed=$((passed + 1))
  else
    echo "FAIL $name (exit $code): $stderr; left: $left"; failures=$((failures + 1))
  fi
}
limited() { (ulimit -f 4; "$tool" "$@"); }  # 4 KiB a file: the images written here are larger
expect_clean_failure render-disk-full "out.png: cannot write (File too large)" limited render -o out.png --width 320 --height 240
expect_clean_failure render-sequence-disk-full "cannot write (File too large)" limited render -o 'f%d.png' --frames 3 --width 320 --height 240
expect_clean_failure compare-disk-full "cannot write (File too large)" limited compare -o cmp --width 320 --height 240 --samples 1
expect_clean_failure render-debug-images-disk-full "dbg/sub/" limited render -o out.png --width 32 --height 24 --set lights[0].shadow.technique=map --debug-images dbg/sub
expect_clean_failure bench-disk-full "cannot write (File too large)" limited bench -o b --frames 1 --warmup 0 --width 160 --height 120 --samples 1

# expect_interrupted NAME WAIT SIGNALS MESSAGE MAX_MS -- ARGS...: runs the
# tool with ARGS in $work/NAME, waits (WAIT: "pending", until a frame's
# .pending file is there; "bench", until bench's "1 run" line and half a
# second; or seconds), sends SIGNALS (comma-separated, 1 ms apart), and
# expects a non-zero exit under 128, one error line (bench's progress lines
# aside) holding MESSAGE, nothing left in $work/NAME, and with MAX_MS the end
# within MAX_MS of the signal.
expect_interrupted() {
  local name=$1 wait=$2 signals=$3 message=$4 max=$5
  shift 6
  local dir="$work/$name" err="$work/$name.err" first=1 s
  (mkdir -p "$dir" && cd "$dir" && exec "$tool" "$@") 2> "$err" >/dev/null &
  local pid=$!
  case $wait in
    pending) for _ in $(seq 100); do compgen -G "$dir/*.pending-*" >/dev/null && break; sleep 0.1; done ;;
    bench) for _ in $(seq 100); do grep -q '^bench: 1 run' "$err" 2>/dev/null && break; sleep 0.1; done; sleep 0.5 ;;
    *) sleep "$wait" ;;
  esac
  for s in ${signals//,/ }; do
    ((first)) || sleep 0.001
    first=0
    kill -"$s" "$pid" 2>/dev/null
  done
  local signalled
  signalled=$(date +%s%N)
  wait "$pid"
  local code=$?
  local took=$((($(date +%s%N) - signalled) / 1000000))
  local errors
  errors=$(grep -v '^\[[#.]*\] \|^bench: [0-9]* runs\?$' "$err")
  if [[ $code -ne 0 && $code -lt 128 && $(grep -c '' <<<"$errors") -eq 1 && "$errors" == *"$message"* && -z "$(ls -A "$dir")" && (-z "$max" || $took -lt $max) ]]; then
    echo "ok   $name (${took} ms after the signal): $errors"; passed=$((passed + 1))
  else
    echo "FAIL $name (exit $code, ${took} ms after the signal): $(cat "$err"); left: $(ls -A "$dir" | head -3)"; failures=$((failures + 1))
  fi
}
sequence=(render -o 'f%05d.png' --frames 100000 --width 32 --height 24)
# An interrupt stops a run at its next frame as an error: the frames written
# so far under temporary names are removed. SIGQUIT is one too.
expect_interrupted render-interrupted 3 TERM "interrupted (SIGTERM)" "" -- "${sequence[@]}"
expect_interrupted render-interrupted-quit pending QUIT "interrupted (SIGQUIT)" "" -- "${sequence[@]}"
# Two SIGTERMs 1 ms apart (an impatient double Ctrl-C): the second waits
# for the clean stop the first asked for; nothing is left (the second one
# used to end the process at once, leaving its frames' .pending files).
expect_interrupted render-interrupted-twice pending TERM,TERM "interrupted (SIGTERM)" "" -- "${sequence[@]}"
# bench stops for an interrupt that comes while the reference is traced:
# 320x240 at 4096 rays a pixel, a trace of seconds, long after the signal,
# which comes once the run has begun.
expect_interrupted bench-interrupted bench TERM "interrupted (SIGTERM)" "" -- bench -o b --frames 1 --warmup 0 --width 320 --height 240 --samples 4096 --set lights[0].size=1
# compare stops for an interrupt in the middle of its trace, not at its end:
# 960x540 at 4096 rays a pixel is 10-29 s of tracing on a 2-core llvmpipe
# machine; the run must end within 5 s of the signal (the trace stops within
# a chunk of 16 pixels' rays). The technique's frame takes about a second,
# so at 3 s the trace has begun. SIGUSR1 is one of the interrupts too.
expect_interrupted compare-interrupted-in-trace 3 USR1 "interrupted (SIGUSR1)" 5000 -- compare -o c --samples 4096 --set lights[0].size=1

# A second interrupt more than a second after the first ends the run at
# once (killed by the signal, exit 128+15), removing this run's frames'
# temporaries first. To hold the run between the two without racing its
# checks: the first comes just after frame 0's temporary appears (frame 1's
# render has begun, with no check in it: penumbra-step at 3000x3000 with
# 64 + 64 PCSS taps, about 2 s a frame here, so that a loaded machine's
# delays in this script's sleeps and kills cannot let it reach its next
# check; a 0.5 s frame once did), the process is then stopped for 1.2 s,
# and the second is delivered as it continues.
forced="$work/forced-end"
mkdir -p "$forced"
(cd "$forced" && exec "$tool" render "$src/scenes/penumbra-step.json" -o 'z%03d.png' --frames 5 --width 3000 --height 3000 \
   --set lights[0].shadow.map.samples=64 --set lights[0].shadow.map.blockerSamples=64 --set lights[0].shadow.map.earlyOut=false) 2>"$forced.err" >/dev/null &
pid=$!
for _ in $(seq 3000); do compgen -G "$forced/z000.png.pending-$pid" >/dev/null && break; sleep 0.01; done
kill -TERM "$pid"; sleep 0.01; kill -STOP "$pid"; sleep 1.2; kill -TERM "$pid"; kill -CONT "$pid"
wait "$pid"
code=$?
if [[ $code -eq 143 && -z "$(ls -A "$forced")" ]]; then
  echo "ok   render-interrupted-twice-apart (exit $code, nothing left)"; passed=$((passed + 1))
else
  echo "FAIL render-interrupted-twice-apart (exit $code): $(cat "$forced.err"); left: $(ls -A "$forced" | head -3)"; failures=$((failures + 1))
fi

# What a killed run left (its process is gone) is removed by the next run
# writing into that directory (the frames of a sequence it does not write
# again too), even a bench that then fails; a live process's stays.
true & dead=$!
wait "$dead"
mkdir -p "$work/stale" "$work/stale/b.partial-$dead"
touch "$work/stale/out.png.pending-$dead" "$work/stale/out.png.pending-$dead.partial" "$work/stale/f000002.png.pending-$dead" "$work/stale/out.png.pending-$$"
(cd "$work/stale" && "$tool" render -o out.png --width 32 --height 24 >/dev/null 2>&1)
(cd "$work/stale" && "$tool" bench nope.json -o b >/dev/null 2>&1)
left=$(cd "$work/stale" && ls -A | sort | tr '\n' ' ')
if [[ "$left" == "out.png out.png.pending-$$ " ]]; then
  echo "ok   stale-temporaries-removed"; passed=$((passed + 1))
else
  echo "FAIL stale-temporaries-removed: left $left"; failures=$((failures + 1))
fi

echo "$passed passed, $failures failed"
[[ $failures -eq 0 ]]

#!/usr/bin/env bash
# Re-renders every PNG in docs/images/ from the command that makes it, so the
# pictures can be remade after a default changes.
#
#   bash scripts/doc-images.sh [OUTDIR]     # default OUTDIR: docs/images
#
# Each image is one line below, with the doc that shows it. `compare` writes
# technique.png, reference.png and error-<i>.png into a directory; `--debug-images`
# writes light<i>-map.png, light<i>-cube.png, light<i>-texel-density.png,
# light<i>-cascades.png; the wanted file is copied to the image's name.
# The default technique is `map` and the default map size 1024^2: an image
# of no shadows says technique=none, and one the docs measured at 2048^2
# says size=2048. Needs the built tool (SHADOWLAB=path to use another) and,
# for viewer.png, a display or xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/.."

tool=${SHADOWLAB:-build/apps/shadowlab/shadowlab}
out=${1:-docs/images}
mkdir -p "$out"
[[ -x $tool ]] || { echo "doc-images: no tool at $tool (build it: bash scripts/build.sh)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

L='lights[0]'
MAP="$L.shadow.map"

# render NAME [render args...]: the frame itself.
render() {
    local name=$1; shift
    "$tool" render "$@" -o "$out/$name.png" >/dev/null
    echo "$out/$name.png"
}
# compare NAME FILE [compare args...]: one of compare's images (technique.png,
# reference.png, error-0.png).
compare() {
    local name=$1 file=$2; shift 2
    local dir="$scratch/$name"
    "$tool" compare "$@" -o "$dir" >/dev/null
    cp "$dir/$file" "$out/$name.png"
    echo "$out/$name.png"
}
# debug NAME FILE [render args...]: one of render's --debug-images.
debug() {
    local name=$1 file=$2; shift 2
    local dir="$scratch/$name"
    mkdir -p "$dir"
    "$tool" render "$@" -o "$dir/frame.png" --debug-images "$dir/debug" >/dev/null
    cp "$dir/debug/$file" "$out/$name.png"
    echo "$out/$name.png"
}
# view NAME [view args...]: a screenshot of the viewer, panel included.
view() {
    local name=$1; shift
    local run=()
    if [[ -z ${DISPLAY:-} ]]; then
        if ! command -v xvfb-run >/dev/null; then
            echo "doc-images: skipped $name.png (no display and no xvfb-run)" >&2
            return 0
        fi
        run=(xvfb-run -a -s "-screen 0 1280x800x24")
    fi
    "${run[@]}" "$tool" view "$@" --screenshot "$out/$name.png" >/dev/null
    echo "$out/$name.png"
}

# README.md
render  default                 --width 960 --height 540   # README: the default scene at its defaults (a light with no technique gets `map`, 768^2)
# (the unshadowed baseline instead, as README said before the default changed: add --set "$L.shadow.technique=none")
view    viewer                  scenes/room-point.json --width 1280 --height 720 --frames 60   # README "The viewer": room-point's cube map at its defaults; times and graph vary per run

# README "The lecture's shadows": each scene in scenes/lecture/ at 400x225, as it ships and with its fix
render  lecture-acne            scenes/lecture/acne.json --width 400 --height 225
render  lecture-acne-fixed      scenes/lecture/acne.json --width 400 --height 225 --set "$MAP"'={"filter": "none"}'
render  lecture-peter-panning   scenes/lecture/peter-panning.json --width 400 --height 225
render  lecture-aliasing        scenes/lecture/aliasing.json --width 400 --height 225
render  lecture-outside-map     scenes/lecture/outside-map.json --width 400 --height 225
render  lecture-pcf             scenes/lecture/pcf.json --width 400 --height 225
debug   lecture-point-cube light0-cube.png scenes/lecture/point-cube.json --width 400 --height 225
render  lecture-planar          scenes/lecture/planar-double-blending.json --width 400 --height 225
render  lecture-volume          scenes/lecture/volume-camera-in-shadow.json --width 400 --height 225
render  lecture-rgba8           scenes/lecture/rgba8-packing.json --width 400 --height 225
debug   lecture-cascades light0-cascades.png scenes/cascades-field.json --width 400 --height 225
compare lecture-pcss technique.png scenes/penumbra-step.json --width 400 --height 225

# docs/techniques/map.md "Bias": each bias key alone on the acne scene
for key in slopeBias=1.5 offsetUnits=8 normalBias=1 constantBias=0.002; do
    render "bias-${key%%=*}" scenes/lecture/acne.json --width 400 --height 225 --set "$MAP.$key"
done

# docs/exercises.md (960x540 unless said; 2048^2 maps)
compare exercise-camera-at-light technique.png scenes/spot-objects.json --width 960 --height 540 --set "$L.shadow.technique=map" --set "$MAP.size=2048" --set 'camera.position=[1.5,5.0,1.0]' --set 'camera.target=[1.2,4.0,0.8]'   # exercises 8.6.1-1
compare exercise-fit-scene-error error-0.png scenes/learnopengl-shadow-mapping.json --width 800 --height 600 --set "$L.shadow.technique=map" --set "$MAP.filter=none" --set "$MAP.size=1024" --set "$MAP.fit=scene"   # exercises 8.6.1-2
compare exercise-fit-tight-error error-0.png scenes/learnopengl-shadow-mapping.json --width 800 --height 600 --set "$L.shadow.technique=map" --set "$MAP.filter=none" --set "$MAP.size=1024" --set "$MAP.fit=tight"   # exercises 8.6.1-2
compare discs-spot technique.png scenes/discs.json --width 960 --height 540 --set "$L"'={"type": "spot", "position": [1, 7, 1], "direction": [0, -1, 0], "outerCone": 60, "shadow": {"technique": "disc"}}'   # exercises 8.6.2-1
compare glass-panel-red technique.png scenes/glass-panel.json --width 960 --height 540 --set materials.glass.alphaMode=blend --set 'materials.glass.baseColor=[1,0,0]' --set "$MAP.size=2048"   # exercises 8.6.2-2 and techniques "Translucent casters"

# docs/techniques/map.md
debug   map-texel-density light0-texel-density.png scenes/learnopengl-shadow-mapping.json --width 800 --height 600 --set "$L.shadow.technique=map"   # techniques "Debug"
render  slide-projector         scenes/slide-projector.json --width 640 --height 400   # techniques, slide projector
compare map-learnopengl technique.png scenes/learnopengl-shadow-mapping.json --width 640 --height 480 --set "$L.shadow.technique=map"   # techniques "Accuracy": defaults
compare map-learnopengl-error error-0.png scenes/learnopengl-shadow-mapping.json --width 640 --height 480 --set "$L.shadow.technique=map"   # techniques "Accuracy": its error image
compare map-lecture-error error-0.png scenes/learnopengl-shadow-mapping.json --width 640 --height 480 --set "$L.shadow.technique=map" --set "$MAP.preset=lecture"   # techniques "Accuracy": preset lecture
render  map-spot                scenes/spot-objects.json --width 640 --height 360 --set "$L.shadow.technique=map"   # techniques "Accuracy": a spot's map
render  map-filter-none         --width 480 --height 270 --set "$L.shadow.technique=map" --set "$MAP.size=256" --set "$MAP.filter=none"   # techniques "Filters": none
render  map-filter-hardware     --width 480 --height 270 --set "$L.shadow.technique=map" --set "$MAP.size=256" --set "$MAP.filter=hardware"   # techniques "Filters": hardware
render  map-filter-dither4      --width 480 --height 270 --set "$L.shadow.technique=map" --set "$MAP.size=256" --set "$MAP.filter=dither4"   # techniques "Filters": dither4
render  map-filter-poisson      --width 480 --height 270 --set "$L.shadow.technique=map" --set "$MAP.size=256" --set "$MAP.filter=poisson"   # techniques "Filters": poisson (16 samples, the default)
render  map-filter-grid         --width 480 --height 270 --set "$L.shadow.technique=map" --set "$MAP.size=256" --set "$MAP.filter=grid" --set "$MAP.kernel=5"   # techniques "Filters": grid 5x5
compare map-mipmaps-error error-0.png scenes/learnopengl-shadow-mapping.json --width 800 --height 600 --set "$L.shadow.technique=map" --set "$MAP.size=2048" --set "$MAP.mipmaps=true"   # techniques "Every option in bench" (2048^2)

# docs/techniques/map-point.md
render  point-learnopengl       scenes/learnopengl-point-shadows.json --width 800 --height 600 --set "$L.shadow.technique=map"   # techniques, cube maps: defaults
debug   point-cube-cross light0-cube.png scenes/learnopengl-point-shadows.json --width 800 --height 600 --set "$L.shadow.technique=map" --set "$MAP.size=256"   # techniques, cube maps: the cross at 256^2
compare point-learnopengl-preset-error error-0.png scenes/learnopengl-point-shadows.json --width 800 --height 600 --set "$L.shadow.technique=map" --set "$MAP.preset=learnopengl"   # techniques, cube maps: preset learnopengl
render  point-room              scenes/room-point.json --width 960 --height 540 --set "$L.shadow.technique=map"   # techniques, cube maps: room-point

# docs/techniques/cascades.md, pcss.md, moments.md
render  cascades-field          scenes/cascades-field.json --width 640 --height 360 --set "$MAP.cascades=4" --set "$MAP.size=2048"   # techniques "Cascaded shadow maps" (2048^2 per cascade)
debug   cascades-field-cascades light0-cascades.png scenes/cascades-field.json --width 640 --height 360 --set "$MAP.cascades=4" --set "$MAP.size=2048"   # techniques "Cascaded shadow maps": by cascade
compare pcss-spot-objects technique.png scenes/spot-objects.json --width 480 --height 270 --samples 1024 --set "$L.size=0.3" --set "$L.shadow.technique=map" --set "$MAP.filter=pcss"   # techniques "Soft shadows"
compare pcss-spot-objects-reference reference.png scenes/spot-objects.json --width 480 --height 270 --samples 1024 --set "$L.size=0.3" --set "$L.shadow.technique=map" --set "$MAP.filter=pcss"   # techniques "Soft shadows": the reference
render  light-leak-vsm          scenes/light-leak.json --width 480 --height 270 --set "$MAP.size=2048" --set "$MAP.representation=vsm" --set "$MAP.blur=6"   # techniques "Filterable maps" (2048^2)
render  light-leak-evsm4        scenes/light-leak.json --width 480 --height 270 --set "$MAP.size=2048" --set "$MAP.representation=evsm4" --set "$MAP.blur=6"   # techniques "Filterable maps" (2048^2)
debug   atlas-many-lights       light0-atlas.png scenes/many-lights.json --width 800 --height 600   # techniques "shadow atlas": its tiles (the first light's debug images hold the atlas)

compare long-view-tight-error error-0.png scenes/long-view.json --width 480 --height 270 --set "$MAP.cascades=1" --set "$MAP.warp=none"   # techniques "Warped maps": one 2048^2 map, unwarped, its errors
compare long-view-lispsm-error error-0.png scenes/long-view.json --width 480 --height 270 --set "$MAP.cascades=1" --set "$MAP.warp=lispsm"   # techniques "Warped maps": the same map warped
# docs/techniques/planar.md
render  planar-room             scenes/room-point.json --width 960 --height 540 --set "$L.shadow.technique=planar"   # techniques `planar`
render  planar-room-lecture     scenes/room-point.json --width 1280 --height 720 --set "$L.shadow.technique=planar" --set "$L.shadow.planar.style=lecture"   # techniques `planar`: style lecture
compare planar-spot-error error-0.png scenes/spot-objects.json --width 960 --height 540 --set "$L.shadow.technique=planar"   # techniques `planar`: the spot scene's error image

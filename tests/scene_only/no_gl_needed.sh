#!/bin/bash
# The scene floor links no OpenGL: the program built from shadowlab_scene
# alone (check_scenes.cpp) needs no GL, EGL or libepoxy library at run time
# (readelf's NEEDED entries), and reads every bundled scene.
# usage: no_gl_needed.sh CHECK_SCENES_BINARY SOURCE_DIR
set -euo pipefail
bin=$1; src=$2
needed=$(readelf -d "$bin" | grep NEEDED || true)
if grep -Ei 'epoxy|libEGL|libGL|libgbm|glfw' <<<"$needed"; then
    echo "FAIL: $bin needs a GL library (above); the scene floor must not"; exit 1
fi
shopt -s nullglob
scenes=("$src"/scenes/*.json "$src"/scenes/lecture/*.json)
(( ${#scenes[@]} > 10 )) || { echo "FAIL: found only ${#scenes[@]} bundled scenes"; exit 1; }
out=$("$bin" "${scenes[@]}")
lines=$(grep -c 'lights\[' <<<"$out")
echo "$out" | tail -1
echo "PASS: ${#scenes[@]} scenes, $lines lights read without GL"

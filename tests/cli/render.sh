#!/usr/bin/env bash
# `shadowlab render` writes the image it names, for the default scene and
# a scene file with --set, and `shadowlab info` reports OpenGL 4.5.
set -eu
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
out=$("$tool" render --width 96 --height 54)
[[ "$out" == "default.png" && -s default.png ]] || { echo "default render wrote '$out'"; exit 1; }
out=$("$tool" render "$src/scenes/torus-resting.json" -o t.png --width 64 --height 48 --set lights[0].intensity=0.5)
[[ "$out" == "t.png" && -s t.png ]] || { echo "scene render wrote '$out'"; exit 1; }
# PNG signature and size from the IHDR chunk.
[[ "$(head -c 8 t.png | od -An -tx1 | tr -d ' \n')" == "89504e470d0a1a0a" ]] || { echo "not a PNG"; exit 1; }
[[ "$(od -An -tu1 -j16 -N8 t.png | tr -s ' ')" == " 0 0 0 64 0 0 0 48" ]] || { echo "wrong size"; exit 1; }
"$tool" info | grep -q "GL version: *4\.[5-9]" || { echo "info does not report GL 4.5+"; "$tool" info; exit 1; }
# The registered techniques and their generated option tables.
"$tool" techniques | grep -q "^none: " || { echo "techniques does not list none"; exit 1; }
"$tool" techniques --markdown | grep -q '^#### `lights\[i\].shadow.none`' || { echo "techniques --markdown"; exit 1; }
# --debug-images: "none" has no images, so the directory stays empty; the
# render itself is unchanged.
out=$("$tool" render "$src/scenes/torus-resting.json" -o d.png --width 64 --height 48 --set lights[0].intensity=0.5 --debug-images dbg)
[[ "$out" == "d.png" && -d dbg && -z "$(ls dbg)" ]] || { echo "debug images: '$out'"; exit 1; }
cmp -s d.png t.png || { echo "--debug-images changed the image"; exit 1; }
# --view-from-light: the light's own view; a point light or a missing light is a one-line error.
out=$("$tool" render "$src/scenes/spot-objects.json" -o v.png --width 64 --height 48 --view-from-light 0)
[[ "$out" == "v.png" && -s v.png ]] || { echo "view from light wrote '$out'"; exit 1; }
cmp -s v.png d.png && { echo "--view-from-light changed nothing"; exit 1; }
if "$tool" render "$src/scenes/room-point.json" -o p.png --view-from-light 0 2>err.txt; then echo "point light view accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q -- "--view-from-light 0: light" err.txt && [[ ! -e p.png ]] || { echo "point light view: $(cat err.txt)"; exit 1; }
if "$tool" render "$src/scenes/spot-objects.json" -o p.png --view-from-light 7 2>err.txt; then echo "light 7 accepted"; exit 1; fi
grep -q -- "--view-from-light 7: the scene has 1 light" err.txt && [[ ! -e p.png ]] || { echo "missing light: $(cat err.txt)"; exit 1; }
# --debug shadow-maps: the map beside the image; a kind it does not know is a one-line error.
out=$("$tool" render "$src/scenes/spot-objects.json" -o s.png --width 64 --height 48 --set lights[0].shadow.technique=map --set lights[0].shadow.map.size=64 --debug shadow-maps)
[[ -s s.png && -s s-light0-map.png && ! -e s-light0-texel-density.png ]] || { echo "--debug shadow-maps wrote: $out"; exit 1; }
if "$tool" render -o q.png --debug everything 2>err.txt; then echo "--debug everything accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 && ! -e q.png ]] && grep -q -- "--debug" err.txt || { echo "--debug everything: $(cat err.txt)"; exit 1; }
echo "7 passed, 0 failed"

#!/usr/bin/env bash
# `shadowlab render` writes the image it names, for the default scene and
# a scene file with --set, and sequences of frames of an animated light and camera;
# `shadowlab info` reports OpenGL 4.5.
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
"$tool" techniques | grep -q "^map (the default): " || { echo "techniques does not name map the default"; exit 1; }
"$tool" techniques --markdown | grep -q '^#### `lights\[i\].shadow.none`' || { echo "techniques --markdown"; exit 1; }
# --debug-images: the scene sets no technique, so its light gets a shadow
# map (the default) and the directory holds the map and its texel density;
# the render itself is unchanged. "none" has no images: the directory stays empty.
out=$("$tool" render "$src/scenes/torus-resting.json" -o d.png --width 64 --height 48 --set lights[0].intensity=0.5 --debug-images dbg)
[[ "$out" == $'d.png\ndbg/light0-map.png\ndbg/light0-texel-density.png' ]] || { echo "debug images: '$out'"; exit 1; }
cmp -s d.png t.png || { echo "--debug-images changed the image"; exit 1; }
out=$("$tool" render "$src/scenes/torus-resting.json" -o n.png --width 64 --height 48 --set lights[0].shadow.technique=none --debug-images none-dbg)
[[ "$out" == "n.png" && -d none-dbg && -z "$(ls none-dbg)" ]] || { echo "debug images of none: '$out'"; exit 1; }
cmp -s n.png d.png && { echo "the default technique drew no shadow"; exit 1; }
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
# --debug texel-density of lights in the shadow atlas (no density image of a
# tile): a note names them, rather than writing nothing silently (issue 59).
"$tool" render "$src/scenes/many-lights.json" -o a.png --width 64 --height 48 --set lightGrid.count=2 --debug texel-density 2>err.txt >/dev/null \
  || { echo "--debug texel-density on atlas lights failed: $(cat err.txt)"; exit 1; }
grep -qx "shadowlab: note: --debug texel-density: no texel-density image of lights 0 'spot 0', 1 'point 1': the technique makes none of its map (a tile of the shadow atlas)" err.txt \
  || { echo "atlas lights' missing density unsaid: $(cat err.txt)"; exit 1; }
"$tool" render "$src/scenes/torus-resting.json" -o td.png --width 64 --height 48 --debug texel-density 2>err.txt >/dev/null
[[ -s td-light0-texel-density.png && ! -s err.txt ]] || { echo "--debug texel-density of a map light: $(cat err.txt)"; exit 1; }
# A point light's cube: its six faces as one cross, 4 x 3 faces of 64 texels.
out=$("$tool" render "$src/scenes/room-point.json" -o c.png --width 64 --height 48 --set lights[0].shadow.technique=map --set lights[0].shadow.map.size=64 --debug shadow-maps)
[[ -s c-light0-cube.png ]] || { echo "--debug shadow-maps on a point light wrote: $out"; exit 1; }
[[ "$(head -c 24 c-light0-cube.png | tail -c 8 | od -An -tu1 | tr -s ' ')" == " 0 0 1 0 0 0 0 192" ]] || { echo "the cube cross is not 256x192"; exit 1; }
if "$tool" render -o q.png --debug everything 2>err.txt; then echo "--debug everything accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 && ! -e q.png ]] && grep -q -- "--debug" err.txt || { echo "--debug everything: $(cat err.txt)"; exit 1; }
# --frames: the room's point light follows Lawonn's path (z = 3 sin(0.5 t));
# at 1 frame per second, frames 0, 1 and 2 see it at z = 0, 1.44 and 2.52.
mkdir seq
out=$("$tool" render "$src/scenes/room-point.json" --frames 3 --fps 1 -o 'seq/frame_%03d.png' --width 64 --height 48)
[[ "$out" == $'seq/frame_000.png\nseq/frame_001.png\nseq/frame_002.png' ]] || { echo "--frames 3 printed '$out'"; exit 1; }
[[ "$(ls seq)" == $'frame_000.png\nframe_001.png\nframe_002.png' ]] || { echo "--frames 3 wrote: $(ls -a seq)"; exit 1; }
for pair in "000 001" "001 002" "000 002"; do
  set -- $pair
  cmp -s "seq/frame_$1.png" "seq/frame_$2.png" && { echo "frames $1 and $2 are the same: the light did not move"; exit 1; }
done
# Frame k is --time + k / --fps: a single frame at --time 2 is frame 2 of the sequence.
"$tool" render "$src/scenes/room-point.json" --time 2 -o at2.png --width 64 --height 48 >/dev/null
cmp -s at2.png seq/frame_002.png || { echo "--time 2 differs from frame 2 at 1 fps"; exit 1; }
# Without a frame number field: a one-line error before anything is rendered, no file.
mkdir noseq
if "$tool" render "$src/scenes/room-point.json" --frames 3 -o noseq/frame.png --width 64 --height 48 2>err.txt; then echo "--frames 3 without %d accepted"; exit 1; fi
[[ $(wc -l <err.txt) -eq 1 && -z "$(ls -A noseq)" ]] && grep -q -- "-o noseq/frame.png: --frames 3 needs a frame number field" err.txt \
  || { echo "--frames without %d: $(cat err.txt); wrote: $(ls -A noseq)"; exit 1; }
# One bad frame name (frame 1's is a directory) fails before frame 0 is written.
mkdir -p bad/f1.png
if "$tool" render "$src/scenes/room-point.json" --frames 3 -o 'bad/f%d.png' --width 64 --height 48 2>err.txt; then echo "a directory as frame 1 accepted"; exit 1; fi
[[ "$(ls -A bad)" == "f1.png" ]] && grep -q -- "-o bad/f1.png: is a directory" err.txt || { echo "bad frame name: $(cat err.txt); wrote: $(ls -A bad)"; exit 1; }
# Without -o, a sequence is named <scene>-%03d.png; %% is a percent sign.
out=$("$tool" render "$src/scenes/room-point.json" --frames 2 --width 32 --height 24)
[[ "$out" == $'room-point-000.png\nroom-point-001.png' && -s room-point-001.png ]] || { echo "default sequence names: '$out'"; exit 1; }
out=$("$tool" render --frames 2 -o 'p%%-%d.png' --width 32 --height 24)
[[ "$out" == $'p%-0.png\np%-1.png' ]] || { echo "%% in a name: '$out'"; exit 1; }
# A scene without a path renders the same at every time.
"$tool" render "$src/scenes/torus-resting.json" -o t5.png --width 64 --height 48 --set lights[0].intensity=0.5 --time 5 >/dev/null
cmp -s t5.png t.png || { echo "--time moved a static scene"; exit 1; }
# A camera path: the frames move with it, and at a key's time the camera is
# where that key puts it, exactly as a static camera written there.
walk='camera.path={"type": "keyframes", "times": [0, 1], "positions": [[4, 3, 5], [5, 3, 4]], "targets": [[0, 0.5, 0], [0, 1, 0]]}'
"$tool" render "$src/scenes/torus-resting.json" --set "$walk" --frames 2 --fps 1 -o 'walk_%d.png' --width 64 --height 48 >/dev/null
cmp -s walk_0.png walk_1.png && { echo "frames 0 and 1 of a camera path are the same: the camera did not move"; exit 1; }
"$tool" render "$src/scenes/torus-resting.json" --set 'camera.position=[5, 3, 4]' --set 'camera.target=[0, 1, 0]' -o key1.png --width 64 --height 48 >/dev/null
cmp -s walk_1.png key1.png || { echo "frame 1 of the camera path differs from a static camera at its key"; exit 1; }
"$tool" render "$src/scenes/torus-resting.json" --set "$walk" -o walk_static.png --width 64 --height 48 --time 7 >/dev/null
cmp -s walk_static.png key1.png || { echo "--time 7 (past the last key) differs from the last key"; exit 1; }
[[ -z "$(find . -name '*.pending*' -o -name '*.partial*')" ]] || { echo "temporaries left: $(find . -name '*.pending*' -o -name '*.partial*')"; exit 1; }
echo "9 passed, 0 failed"

#!/usr/bin/env bash
# glTF files as whole scenes (issue 63's acceptance): three bundled scenes
# exported by scripts/export-gltf.sh (a directional, a spot and a point
# light, each with its camera) render as the scene JSON they came from and
# hold the 0.05 % bar against the ray-traced reference.
# Usage: gltf.sh SHADOWLAB_BINARY SOURCE_DIR
set -eu
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
scenes="two-boxes-sun spot-objects four-spheres-point"

for s in $scenes; do set -- "$@" "$src/scenes/$s.json"; done
shift 2
bash "$src/scripts/export-gltf.sh" -t "$tool" -o gltf "$@" > export.txt || fail "export-gltf.sh failed: $(cat export.txt)"

for s in $scenes; do
  [[ -s gltf/$s.gltf ]] || fail "export-gltf.sh wrote no gltf/$s.gltf"
  # The export renders as its scene JSON. Tolerance: at most 0.01 % of the
  # pixels may differ, by at most one 8-bit step: a direction written as a
  # unit vector is normalised again when read, and a node's rotation as a
  # normalised quaternion, which moves a float's last bit (measured: at most
  # 2 pixels of 120,000 differ, by 1).
  "$tool" render "gltf/$s.gltf" -o "$s-gltf.png" --width 400 --height 300 > "$s-render.txt" 2>&1 || fail "render gltf/$s.gltf: $(cat "$s-render.txt")"
  ! grep -q "note:" "$s-render.txt" || fail "render gltf/$s.gltf printed a note for a file with its lights and camera: $(cat "$s-render.txt")"
  "$tool" render "$src/scenes/$s.json" -o "$s-json.png" --width 400 --height 300 > /dev/null || fail "render $s.json failed"
  python3 - "$s-gltf.png" "$s-json.png" <<'PY' || fail "$s: the glTF render differs from the scene's"
import struct, sys, zlib
def pixels(path):
    data = open(path, "rb").read()
    at, idat = 8, b""
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR": w, h, depth, colour = struct.unpack(">IIBB", body[:10])
        if kind == b"IDAT": idat += body
        at += 12 + n
    assert depth == 8 and colour in (2, 6), (depth, colour)
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev, p = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for y in range(h):
        f, line = raw[p], bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                q = a + b - c
                pa, pb, pc = abs(q - a), abs(q - b), abs(q - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, bpp, b"".join(rows)
wa, ha, bpp, a = pixels(sys.argv[1])
wb, hb, _, b = pixels(sys.argv[2])
assert (wa, ha) == (wb, hb)
differ = worst = 0
for i in range(0, len(a), bpp):
    d = max(abs(a[i + k] - b[i + k]) for k in range(3))
    differ += d > 0
    worst = max(worst, d)
print("%s: %d of %d pixels differ, by at most %d" % (sys.argv[1], differ, wa * ha, worst))
sys.exit(0 if differ <= 0.0001 * wa * ha and worst <= 1 else 1)
PY
  # The glTF scene against the exact reference: the bundled scenes' bar.
  "$tool" compare "gltf/$s.gltf" -o "compare-$s" --width 800 --height 600 > /dev/null || fail "compare gltf/$s.gltf failed"
  python3 - "compare-$s/metrics.json" <<'PY' || fail "compare gltf/$s.gltf: over the 0.05 % bar"
import json, sys
light = json.load(open(sys.argv[1]))["lights"][0]
away = light["falseShadowAwayFromEdges"] + light["falseLitAwayFromEdges"]
print("%s: %.4f %% misclassified away from edges" % (sys.argv[1], 100 * away))
sys.exit(0 if away <= 0.0005 else 1)
PY
done
# --camera N past the file's cameras: one line naming the file and the index, no image.
if "$tool" render gltf/spot-objects.gltf --camera 3 -o camera3.png 2> camera3.txt; then fail "--camera 3 of a one-camera file succeeded"; fi
[[ $(wc -l < camera3.txt) -eq 1 ]] && grep -q "spot-objects.gltf: cameras: camera 3: the scene places 1 camera" camera3.txt || fail "--camera 3: $(cat camera3.txt)"
[[ ! -e camera3.png ]] || fail "--camera 3 left camera3.png"

# An orthographic camera (camera.orthoHeight; glTF's orthographic cameras)
# holds the same bar against the reference, exported and read back.
"$tool" export "$src/scenes/spheres-sun.json" --set camera.orthoHeight=7 -o ortho.glb > /dev/null || fail "export with an orthographic camera failed"
"$tool" compare ortho.glb -o compare-ortho --width 320 --height 240 > /dev/null || fail "compare ortho.glb failed"
python3 - compare-ortho/metrics.json <<'PY' || fail "compare ortho.glb: over the 0.05 % bar"
import json, sys
light = json.load(open(sys.argv[1]))["lights"][0]
away = light["falseShadowAwayFromEdges"] + light["falseLitAwayFromEdges"]
print("%s: %.4f %% misclassified away from edges, %d shadowed" % (sys.argv[1], 100 * away, light["referenceShadowedPixels"]))
sys.exit(0 if away <= 0.0005 and light["referenceShadowedPixels"] > 1000 else 1)
PY
echo "PASS: gltf (3 scenes exported, rendered and compared; --camera; an orthographic camera)"

#!/usr/bin/env bash
# `shadowlab compare` writes metrics.json (atomically) with the numbers it
# printed, the bench record's per-light fields, and reach-<i>.png beside
# visibility-<i>.png.
# Usage: compare.sh SHADOWLAB_BINARY SOURCE_DIR
set -eu
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
passed=0

for scene in torus-floating spot-objects; do
  "$tool" compare "$src/scenes/$scene.json" -o "$scene" --width 160 --height 90 > "$scene.txt" || fail "compare $scene failed"
  [[ -s $scene/metrics.json ]] || fail "compare $scene did not write metrics.json"
  [[ ! -e $scene/metrics.json.partial ]] || fail "compare $scene left metrics.json.partial behind"
  [[ -s $scene/reach-0.png ]] || fail "compare $scene did not write reach-0.png"
  # reach-0.png is 8-bit greyscale: IHDR bit depth 8, colour type 0.
  [[ "$(od -An -tu1 -j24 -N2 "$scene/reach-0.png" | tr -s ' ')" == " 8 0" ]] || fail "$scene/reach-0.png is not 8-bit grey"
  # metrics.json parses, has every field, and says what compare printed.
  python3 - "$scene/metrics.json" "$scene.txt" <<'PY' || fail "compare $scene: metrics.json does not match its output"
import json, os, re, sys
metrics = json.load(open(sys.argv[1]))
printed = open(sys.argv[2]).read()
top = ["scene", "sceneFile", "width", "height", "softSamples", "referenceMs", "techniqueImage", "referenceImage", "lights"]
fields = ["name", "type", "technique", "soft", "receiverPixels", "referenceShadowedPixels", "edgePixels", "falseShadow",
          "falseLit", "falseShadowAwayFromEdges", "falseLitAwayFromEdges", "meanAbsError", "rmse",
          "errorImage", "visibilityImage", "reachImage"]
def check(ok, what):
    if not ok:
        print(what); sys.exit(1)
for key in top: check(key in metrics, "metrics.json: no '%s'" % key)
check(len(metrics["lights"]) >= 1, "metrics.json: no lights")
head = re.search(r"scene (\S+), (\d+)x(\d+), reference traced in (\d+) ms", printed)
check(head is not None, "no header line in: " + printed)
check((metrics["scene"], metrics["width"], metrics["height"]) == (head[1], int(head[2]), int(head[3])), "scene/size differ")
check(int(metrics["referenceMs"]) == int(head[4]), "referenceMs %s, printed %s" % (metrics["referenceMs"], head[4]))
pct = lambda share: "%.3f%%" % (100.0 * share)
for i, l in enumerate(metrics["lights"]):
    for key in fields: check(key in l, "light %d: no '%s'" % (i, key))
    for key in ("errorImage", "visibilityImage", "reachImage"):
        check(os.path.isfile(os.path.join(os.path.dirname(sys.argv[1]), l[key])), "light %d: %s missing" % (i, l[key]))
    shadowed = l["referenceShadowedPixels"] / l["receiverPixels"] if l["receiverPixels"] else 0.0
    expected = [
        "light %d '%s' (%s, %s, technique %s): %d receiver pixels, %s shadowed in truth"
        % (i, l["name"], l["type"], "soft" if l["soft"] else "hard", l["technique"], l["receiverPixels"], pct(shadowed)),
        "false shadow %s, false lit %s\n" % (pct(l["falseShadow"]), pct(l["falseLit"])),
        "false shadow %s, false lit %s (%d pixels in the 1-pixel edge band)"
        % (pct(l["falseShadowAwayFromEdges"]), pct(l["falseLitAwayFromEdges"]), l["edgePixels"]),
        "MAE %g, RMSE %g" % (l["meanAbsError"], l["rmse"]),
    ]
    for line in expected: check(line in printed, "not printed: %r" % line)
PY
done
passed=$((passed + 1))

# --time moves the camera along its path for both sides: at a key's time the
# numbers and images are those of a static camera at that key.
walk='camera.path={"type": "keyframes", "times": [0, 2], "positions": [[-4, 3, 5], [5, 4, 4]], "targets": [[0, 0.5, 0], [0, 1, 0]]}'
"$tool" compare "$src/scenes/torus-floating.json" --set "$walk" --time 2 -o walk --width 96 --height 54 >/dev/null || fail "compare --time with a camera path failed"
"$tool" compare "$src/scenes/torus-floating.json" --set 'camera.position=[5, 4, 4]' --set 'camera.target=[0, 1, 0]' -o key --width 96 --height 54 >/dev/null \
  || fail "compare with the key's static camera failed"
for f in technique.png reference.png error-0.png; do cmp -s walk/$f key/$f || fail "compare --time 2: $f differs from the static camera at the key"; done
"$tool" compare "$src/scenes/torus-floating.json" --set "$walk" -o walk0 --width 96 --height 54 >/dev/null || fail "compare at time 0 failed"
cmp -s walk0/technique.png walk/technique.png && fail "compare at times 0 and 2 of a camera path gave the same image"
passed=$((passed + 1))

# The error image's colours are said with the files (a user opening
# error-0.png should not need docs/metrics.md to read it).
"$tool" compare "$src/scenes/torus-resting.json" -o legend --width 48 --height 27 > legend.txt || fail "compare for the legend failed"
grep -qx "error-<i>.png: red = lit where truth is shadowed (false lit), blue = shadowed where truth is lit (false shadow), paler in the 1-pixel edge band; grey = agrees, darker grey = not a receiver" legend.txt \
  || fail "no legend of the error image: $(cat legend.txt)"
passed=$((passed + 1))

# A light in the shadow atlas has no texel footprint measured, and compare
# says so rather than leave the line out (issue 59).
"$tool" compare "$src/scenes/many-lights.json" --set lightGrid.count=2 -o atlas --width 96 --height 72 > atlas.txt || fail "compare of the atlas's lights failed"
[[ $(grep -c "texel footprint (pixels a texel):  not measured (the technique makes no texel-density image of this light's map)" atlas.txt) -eq 2 ]] || fail "the atlas's lights' footprint unsaid: $(cat atlas.txt)"
passed=$((passed + 1))

# An output directory that cannot be made is one error line, and no metrics.json.
touch blocker
if "$tool" compare "$src/scenes/torus-floating.json" -o blocker/out --width 32 --height 18 > out.txt 2> err.txt; then
  fail "compare into a file's subdirectory succeeded"
fi
[[ $(wc -l < err.txt) -eq 1 ]] && grep -q '^shadowlab: error: ' err.txt || fail "expected one error line: $(cat err.txt)"
passed=$((passed + 1))
echo "$passed passed, 0 failed"

#!/usr/bin/env bash
# bench --flips over cascades-field's whole camera walk (60 s, sampled at 60
# evenly spaced frames: --frames 60 --fps 1), 4 cascades of 1024^2, filter
# none, stabilised and fitted tightly. For a light that stays put, a flip is
# a receiver pixel whose shadow changes at the same world point between two
# frames' maps (docs/metrics.md), edges included: a tight fit slides its
# texel grid under the world as the view moves, so its edges crawl; a
# stabilised one stays put. The issue's bar: tight at least 5x stabilised
# (mean share per pair of frames; measured at 480x270: 0.26 % and
# 0.00014 %). About two minutes (60 traced references a row).
# Usage: flips.sh SHADOWLAB_BINARY SOURCE_DIR
set -eu
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$tool" bench "$src/scenes/cascades-field.json" --set lights[0].shadow.map.cascades=4 --set lights[0].shadow.map.size=1024 \
  --set 'lights[0].shadow.map.filter="none"' --vary lights[0].shadow.map.stabilize=true,false \
  --flips --frames 60 --fps 1 --warmup 0 --width 320 --height 180 -o walk >/dev/null 2>&1 || fail "bench --flips over the walk failed"
python3 - walk/results.json <<'PY' || fail "tight cascades do not flip 5x more than stabilised ones"
import json, sys
rows = json.load(open(sys.argv[1]))["results"]
stable, tight = (r["lights"][0]["flips"] for r in rows)
assert len(stable["perPair"]) == 59 and len(tight["perPair"]) == 59, (len(stable["perPair"]), len(tight["perPair"]))
print(f"flips, mean share per pair: stabilised {100 * stable['mean']:.5f} %, tight {100 * tight['mean']:.5f} %")
assert tight["mean"] > 0.0001, tight["mean"]  # the tight fit's edges crawl: at least 0.01 % of the receivers a pair
assert tight["mean"] >= 5 * stable["mean"], (tight["mean"], stable["mean"])
PY
# Fit sdsm with stabilised cascades: the first slice starts at the nearest
# depth the camera sees and the last ends at the farthest, both kept while
# the walk stays within them (MapCameras: sampledRange), so it flips no more than today's stabilised cascades (the
# issue's bar), within one receiver pixel a pair of frames on average (a
# split that moved each time the nearest depth crossed a step flipped
# 0.014 % a pair, 0.39 % at a jump).
"$tool" bench "$src/scenes/cascades-field.json" --set lights[0].shadow.map.cascades=4 --set lights[0].shadow.map.size=1024 \
  --set 'lights[0].shadow.map.filter="none"' --set 'lights[0].shadow.map.fit="sdsm"' \
  --flips --frames 60 --fps 1 --warmup 0 --width 320 --height 180 -o sdsm >/dev/null 2>&1 || fail "bench --flips with fit sdsm failed"
python3 - walk/results.json sdsm/results.json <<'PY' || fail "sdsm's stabilised cascades flip more than the tight fit's"
import json, sys
stable = json.load(open(sys.argv[1]))["results"][0]["lights"][0]
sdsm = json.load(open(sys.argv[2]))["results"][0]["lights"][0]
pixel = 1.0 / stable["receiverPixels"]
print(f"flips, mean share per pair: stabilised tight {100 * stable['flips']['mean']:.5f} %, sdsm {100 * sdsm['flips']['mean']:.5f} %")
assert sdsm["flips"]["mean"] <= stable["flips"]["mean"] + pixel, (sdsm["flips"]["mean"], stable["flips"]["mean"], pixel)
PY
echo "2 passed, 0 failed"

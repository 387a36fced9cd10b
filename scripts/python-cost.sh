#!/usr/bin/env bash
# The Python module's render() against the same render through the library
# in C++ (tests/tools/rendercost.cpp: one Renderer with the scene uploaded
# once, as the module keeps it for calls with the same Scene; each call the
# scene at time 0, the frame and the pixels read back into a new image),
# interleaved in one run: ROUNDS rounds of COUNT calls each side, the
# median call of each round, then the median over rounds and their ratio.
# Issue 28's bar: Python at most 1.1x C++.
#
#   bash scripts/python-cost.sh [SCENE] [WIDTH] [HEIGHT] [COUNT] [ROUNDS]
#
# From the source tree after a build (build/python, build/tests/rendercost).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-scenes/two-boxes-sun.json}
width=${2:-800}
height=${3:-600}
count=${4:-30}
rounds=${5:-7}
python=/usr/bin/python3
[ -x build/tests/rendercost ] || { echo "python-cost.sh: build/tests/rendercost missing: build first (bash scripts/build.sh)" >&2; exit 1; }
[ -e build/python ] || { echo "python-cost.sh: build/python missing: the module was not built (pybind11-dev, python3-dev)" >&2; exit 1; }
cpp=() py=()
for ((r = 0; r < rounds; r++)); do
  cpp+=("$(build/tests/rendercost "$scene" "$width" "$height" "$count")")
  py+=("$(PYTHONPATH=build/python "$python" - "$scene" "$width" "$height" "$count" <<'PY'
import statistics, sys, time
import shadowlab
scene = shadowlab.load_scene(sys.argv[1])
width, height, count = (int(a) for a in sys.argv[2:5])
times = []
for _ in range(count):
    start = time.perf_counter()
    shadowlab.render(scene, width, height)
    times.append((time.perf_counter() - start) * 1000.0)
print("%.3f" % statistics.median(times))
PY
)")
  echo "round $((r + 1))/$rounds: C++ ${cpp[-1]} ms, Python ${py[-1]} ms" >&2
done
"$python" - "${cpp[*]}" "${py[*]}" "$scene" "$width" "$height" "$count" "$rounds" <<'PY'
import statistics, sys
cpp = [float(v) for v in sys.argv[1].split()]
py = [float(v) for v in sys.argv[2].split()]
c, p = statistics.median(cpp), statistics.median(py)
print("%s %sx%s, %s calls x %s rounds: C++ %.2f ms, Python %.2f ms a render (medians); Python / C++ = %.3f; per round: %s"
      % (sys.argv[3], sys.argv[4], sys.argv[5], sys.argv[6], sys.argv[7], c, p, p / c,
         " ".join("%.2f" % (b / a) for a, b in zip(cpp, py))))
PY

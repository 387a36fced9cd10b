#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (preset `fuzz`, build-fuzz/) and
# fuzzes each loader (scene JSON with --set overrides, OBJ, glTF and .glb,
# two at a time), either
#   --runs N [--seed S]  exactly N inputs per target from libFuzzer seed S
#                        (default 1): repeatable, what scripts/test.sh and CI run;
#   --seconds S          S seconds per target from a random seed: a longer,
#                        different search each time (the default: 30 s, or
#                        SHADOWLAB_FUZZ_SECONDS).
# A finding (crash, sanitizer report, leak, 10 s timeout, 2 GB memory) fails
# the run and its input is kept in build-fuzz/fuzz-artifacts/<target>/;
# replay it with build-fuzz/fuzz/shadowlab_fuzz_<target> FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SHADOWLAB_FUZZ_SECONDS:-30}
runs=0
seed=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=${2:?--runs needs a number}; shift 2 ;;
    --seed) seed=${2:?--seed needs a number}; shift 2 ;;
    --seconds) seconds=${2:?--seconds needs a number}; runs=0; shift 2 ;;
    *) echo "fuzz.sh: unknown option $1 (expected --runs N, --seed S or --seconds S)" >&2; exit 2 ;;
  esac
done
for v in "$runs" "$seed" "$seconds"; do
  [[ $v =~ ^[0-9]+$ ]] || { echo "fuzz.sh: $v: expected a whole number" >&2; exit 2; }
done
cmake --preset fuzz -DSHADOWLAB_FUZZ_SECONDS="$seconds" -DSHADOWLAB_FUZZ_RUNS="$runs" -DSHADOWLAB_FUZZ_SEED="$seed" >/dev/null
cmake --build --preset fuzz -j2
ctest --preset fuzz -j2

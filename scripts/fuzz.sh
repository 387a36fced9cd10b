#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (preset `fuzz`, build-fuzz/) and
# fuzzes each loader for SHADOWLAB_FUZZ_SECONDS (default 30) seconds:
# scene JSON with --set overrides, OBJ, glTF and .glb, two at a time.
# A finding (crash, sanitizer report, leak, 10 s timeout, 2 GB memory) fails
# the run and its input is kept in build-fuzz/fuzz-artifacts/<target>/;
# replay it with build-fuzz/fuzz/shadowlab_fuzz_<target> FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SHADOWLAB_FUZZ_SECONDS:-30}
cmake --preset fuzz -DSHADOWLAB_FUZZ_SECONDS="$seconds" >/dev/null
cmake --build --preset fuzz -j2
ctest --preset fuzz -j2

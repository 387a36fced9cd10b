#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, GL on the
# headless context, command line, installed package), then, where clang and
# its libFuzzer runtime are present (scripts/install-deps.sh installs them),
# a bounded fuzz run of every loader (scripts/fuzz.sh: 30 s per target).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --preset default -j2
if command -v clang++ >/dev/null && [[ -f "$(clang++ -print-runtime-dir)/libclang_rt.fuzzer-x86_64.a" ]]; then
  bash scripts/fuzz.sh
else
  echo "test.sh: clang++ or its libFuzzer runtime is missing; skipping the fuzz run (scripts/install-deps.sh installs them)"
fi

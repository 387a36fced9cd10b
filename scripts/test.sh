#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, GL on the
# headless context, command line, installed package), then, where clang and
# its libFuzzer runtime are present (scripts/install-deps.sh installs them),
# a bounded, repeatable fuzz run of every loader (scripts/fuzz.sh --runs:
# 200,000 inputs per target from seed 1, whatever the machine's speed, so a
# clone passes or fails the same way every time; about 30 s here).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --preset default -j2
if command -v clang++ >/dev/null && [[ -f "$(clang++ -print-runtime-dir)/libclang_rt.fuzzer-x86_64.a" ]]; then
  bash scripts/fuzz.sh --runs 200000 --seed 1
else
  echo "test.sh: clang++ or its libFuzzer runtime is missing; skipping the fuzz run (scripts/install-deps.sh installs them)"
fi

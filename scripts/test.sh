#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, GL on the
# headless context, command line, installed package).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --preset default -j2

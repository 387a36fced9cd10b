#!/usr/bin/env bash
# Installs missing Debian packages, configures and builds shadowlab in build/.
# Extra arguments go to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset default "$@" >/dev/null
cmake --build --preset default

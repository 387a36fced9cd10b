#!/usr/bin/env bash
# Installs what is missing, builds, and renders the default scene to default.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/apps/shadowlab/shadowlab render -o default.png

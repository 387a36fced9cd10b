#!/usr/bin/env bash
# Installs the Debian packages shadowlab needs to build, test and render
# (clang and its libFuzzer runtime build the fuzz targets, scripts/fuzz.sh;
# pybind11 and Python 3's headers, numpy, pytest and matplotlib the Python
# module and its tests; Universal Ctags the functions' lengths,
# tests/code/lengths.py; Chart.js, inlined into bench's report at build time).
# Skips packages that are already installed; uses sudo when not root.
# Usage: scripts/install-deps.sh [--no-browser]
#   --no-browser  skip Chromium (only the report screenshot test needs it)
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libepoxy-dev libegl-dev libegl1-mesa-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0 libgbm1
  libglfw3-dev libglm-dev libstb-dev libpng-dev
  libtinygltf-dev nlohmann-json3-dev libcli11-dev
  libimgui-dev libembree-dev libjs-chart.js
  googletest libgtest-dev
  clang libclang-rt-14-dev universal-ctags
  glmark2-data xvfb xauth
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
)
if [[ "${1:-}" != "--no-browser" ]]; then
  packages+=(chromium)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"

#!/usr/bin/env bash
# Exports scenes to glTF, each with its camera and lights (KHR_lights_punctual),
# as starting files and for the tests: `shadowlab export` on each.
# Usage: scripts/export-gltf.sh [-t SHADOWLAB_BINARY] [-o DIR] [SCENE.json ...]
#   default binary build/apps/shadowlab/shadowlab, default DIR gltf/,
#   default scenes: every scenes/*.json.
# Each scene becomes DIR/<name>.gltf, which `shadowlab render DIR/<name>.gltf`
# renders as the scene it came from (docs/scene-format.md, "glTF files as scenes").
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tool=$root/build/apps/shadowlab/shadowlab
out=gltf
while getopts "t:o:" flag; do
  case $flag in
    t) tool=$OPTARG ;;
    o) out=$OPTARG ;;
    *) echo "usage: $0 [-t SHADOWLAB_BINARY] [-o DIR] [SCENE.json ...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[[ -x $tool ]] || { echo "export-gltf: $tool: no shadowlab binary (build first: bash scripts/build.sh, or give -t)" >&2; exit 1; }
if [[ $# -eq 0 ]]; then set -- "$root"/scenes/*.json; fi
mkdir -p "$out"
for scene in "$@"; do
  "$tool" export "$scene" -o "$out/$(basename "${scene%.*}").gltf"
done

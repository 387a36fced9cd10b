#!/usr/bin/env bash
# The hostile-input battery (tests/hostile/run.py, issue 24): about 950
# inputs a user can give (every option of every technique through --set,
# --vary, scene JSON, broken glTF/OBJ and textures, output paths, sizes past
# the limits, viewer scripts under Xvfb, the Python module's arguments),
# each checked for one line of error naming the option and its source, a
# non-zero exit, no crash, nothing left behind, bounded time and memory;
# valid ones must succeed. It runs on a copy of the build (the tool, the
# library and the Python module), so a rebuild meanwhile does not disturb
# it. About a minute on 2 cores; not part of the test suite (it starts an
# X server and takes up to 3 GB in one case).
#
#   bash scripts/hostile.sh [run.py's options: --only REGEX, --jobs N, --list]
#
# From the source tree after a build; the report is DIR/report.md (printed).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/apps/shadowlab/shadowlab ] || { echo "hostile.sh: build/apps/shadowlab/shadowlab missing: build first (bash scripts/build.sh)" >&2; exit 1; }
dir=$(mktemp -d /tmp/shadowlab-hostile-XXXXXX)
mkdir -p "$dir/bin" "$dir/python"
cp build/apps/shadowlab/shadowlab "$dir/bin/"
cp -P build/src/libshadowlab.so* "$dir/bin/"
if compgen -G 'build/python/*.so' >/dev/null; then cp build/python/*.so "$dir/python/"; fi
cp -r scenes "$dir/scenes"
/usr/bin/python3 tests/hostile/run.py --snapshot "$dir" "$@"
echo "report: $dir/report.md"

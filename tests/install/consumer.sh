#!/usr/bin/env bash
# Installs the built tree into a temporary prefix and builds a separate CMake
# project against it with find_package(shadowlab); runs the result.
# Usage: consumer.sh BUILD_DIR CONSUMER_SOURCE_DIR
set -eu
build=$1
consumer=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib:$work/prefix/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}" "$work/build/consumer" "$work/consumer.png"
[[ -s "$work/consumer.png" ]]
passed=1
# The Python module, when built, installs beside the library and imports
# from there (it finds the library through its RPATH).
module=$(find "$work/prefix" -name 'shadowlab.cpython-*.so' | head -1)
if [[ -n "$module" ]]; then
  PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c 'import shadowlab; a = shadowlab.render(shadowlab.default_scene(), 32, 24); assert a.shape == (24, 32, 4)'
  passed=2
fi
echo "$passed passed, 0 failed"

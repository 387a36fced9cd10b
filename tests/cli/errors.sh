#!/usr/bin/env bash
# Every bad input to the tool: a one-line error naming the file or flag,
# a non-zero exit, no crash (exit code < 128) and no output file.
# Usage: errors.sh SHADOWLAB_BINARY SOURCE_DIR
set -u
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passed=0

# expect_error NAME EXPECTED_SUBSTRING ARGS...
expect_error() {
  local name=$1 expected=$2
  shift 2
  local out="$work/out.png"
  rm -f "$out" "$out.partial"
  local stderr
  stderr=$(cd "$work" && env ${TOOL_ENV:-} "$tool" "$@" 2>&1 >/dev/null)
  local code=$?
  local lines
  lines=$(printf '%s' "$stderr" | grep -c '')
  if [[ $code -eq 0 || $code -ge 128 ]]; then
    echo "FAIL $name: exit code $code (expected 1..127)"; failures=$((failures + 1)); return
  fi
  if [[ "$stderr" != *"$expected"* ]]; then
    echo "FAIL $name: stderr does not contain '$expected':"; echo "  $stderr"; failures=$((failures + 1)); return
  fi
  if [[ $lines -ne 1 ]]; then
    echo "FAIL $name: $lines lines of error output (expected 1):"; echo "$stderr"; failures=$((failures + 1)); return
  fi
  if [[ -e "$out" || -e "$out.partial" ]]; then
    echo "FAIL $name: an output file was written"; failures=$((failures + 1)); return
  fi
  echo "ok   $name: $stderr"
  passed=$((passed + 1))
}

printf '{ "nodes": [ \n' > "$work/malformed.json"
printf '{"lights": [{"type":"directional"}, {"type":"directional","direction":[1,2]}]}' > "$work/direction.json"
printf '{"nodes": [{"mesh": "missing.obj"}]}' > "$work/missing-mesh.json"
printf 'not a glb' > "$work/fake.glb"
printf '{"nodes": [{"mesh": "fake.glb"}]}' > "$work/fake-glb.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$work/bad.obj"
printf '{"nodes": [{"mesh": "bad.obj"}]}' > "$work/bad-obj.json"
printf '{"lights": [{"type":"directional","intensity":1e999}]}' > "$work/inf.json"
printf '{"nodes": [{"shape": {"type":"box","size":[1,-1,1]}}]}' > "$work/negative.json"
printf '{"lihgts": []}' > "$work/unknown-key.json"
printf 'P3 not json' > "$work/notjson.json"

expect_error malformed-json "malformed.json: invalid JSON" render malformed.json -o out.png
expect_error direction-count "direction.json: lights[1].direction: expected 3 numbers, got 2" render direction.json -o out.png
expect_error missing-mesh "missing-mesh.json: nodes[0].mesh: " render missing-mesh.json -o out.png
expect_error glb-not-gltf "fake.glb" render fake-glb.json -o out.png
expect_error obj-bad-index "bad.obj" render bad-obj.json -o out.png
expect_error infinite-number "inf.json: invalid JSON: number overflow parsing '1e999' (numbers must be finite)" render inf.json -o out.png
expect_error negative-size "negative.json: nodes[0].shape.size: expected 3 numbers > 0" render negative.json -o out.png
expect_error unknown-key "unknown-key.json: lihgts: unknown key" render unknown-key.json -o out.png
expect_error not-json "notjson.json: invalid JSON" render notjson.json -o out.png
expect_error missing-scene "nope.json: file not found" render nope.json -o out.png
expect_error set-bad-path "--set lights[3].intensity=2: index 3 out of range" render -o out.png --set 'lights[3].intensity=2'
expect_error set-bad-value "--set lights[0].intensity=bright: lights[0].intensity: expected a number, got a string" render -o out.png --set 'lights[0].intensity=bright'
expect_error set-unknown-key "--set camera.fov=30: camera.fov: unknown key" render -o out.png --set camera.fov=30
expect_error set-no-value "--set camera: expected key=value" render -o out.png --set camera
expect_error width-zero "--width" render -o out.png --width 0
expect_error width-text "--width" render -o out.png --width wide
expect_error width-past-gpu-limit "--width 100000: exceeds this GPU's limit" render -o out.png --width 100000
expect_error output-not-png "-o out.jpg: expected a .png file name" render -o out.jpg
expect_error output-missing-dir "directory" render -o no/such/dir/out.png
expect_error unknown-subcommand "shadowlab: error:" frobnicate
expect_error unknown-flag "shadowlab: error:" render --frobnicate

# No OpenGL 4.5 core: Mesa can be told to offer only 4.1 (other drivers ignore this).
if "$tool" info | grep -q "Mesa"; then
  TOOL_ENV="MESA_GL_VERSION_OVERRIDE=4.1" expect_error no-gl45 "OpenGL 4.5 core is required, found '4.1" render -o out.png
fi

# compare and bench: the same rules; the output here is a directory.
expect_dir_error() {
  local name=$1 expected=$2
  shift 2
  rm -rf "$work/outdir"
  expect_error "$name" "$expected" "$@"
  if [[ -e "$work/outdir" ]]; then echo "FAIL $name: output directory was created"; failures=$((failures + 1)); passed=$((passed - 1)); fi
}
expect_dir_error compare-missing-scene "nope.json: file not found" compare nope.json -o outdir
expect_dir_error compare-bad-set "--set lights[0].intensity=x: lights[0].intensity: expected a number" compare -o outdir --set 'lights[0].intensity=x'
expect_dir_error compare-samples-zero "--samples" compare -o outdir --samples 0
expect_dir_error compare-output-is-file "-o malformed.json: exists and is not a directory" compare -o malformed.json
expect_dir_error bench-missing-scene "nope.json: file not found" bench nope.json -o outdir
expect_dir_error bench-bad-vary "--vary lights[0].intensity: expected key=value1,value2" bench -o outdir --vary 'lights[0].intensity'
expect_dir_error bench-vary-bad-value "--vary lights[0].intensity=abc: lights[0].intensity: expected a number" bench -o outdir --vary 'lights[0].intensity=1,abc'
expect_dir_error bench-vary-empty-value "--vary lights[0].intensity=1,,2: empty value" bench -o outdir --vary 'lights[0].intensity=1,,2'
expect_dir_error bench-frames-zero "--frames" bench -o outdir --frames 0
expect_dir_error bench-bad-scene "direction.json: lights[1].direction" bench direction.json -o outdir

echo "$passed passed, $failures failed"
[[ $failures -eq 0 ]]

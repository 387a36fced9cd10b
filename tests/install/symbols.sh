#!/usr/bin/env bash
# The shared library exports its public API and nothing else: every dynamic
# symbol it defines is in namespace shadowlab (or is the vtable or type
# information of a shadowlab class), names a declaration of the public
# headers (include/shadowlab/*.h: the first name after `shadowlab::` must
# be declared there), and shadowlab::Error's type information is among them
# so that users can catch it.
# Usage: symbols.sh LIBRARY INCLUDE_DIR
set -eu
lib=$1
include=$2
symbols=$(nm -DC --defined-only "$lib" | cut -d' ' -f3- | grep -v '^\(_edata\|_end\|__bss_start\)$' || true)
[[ -n "$symbols" ]] || { echo "FAIL: $lib exports nothing"; exit 1; }
fail=0
count=0
while IFS= read -r s; do
    count=$((count + 1))
    name=${s#typeinfo name for }
    name=${name#typeinfo for }
    name=${name#vtable for }
    if [[ "$name" != shadowlab::* ]]; then
        echo "FAIL: exported outside namespace shadowlab: $s"; fail=1; continue
    fi
    first=${name#shadowlab::}
    first=${first%%[^A-Za-z0-9_]*}
    if ! grep -qw -- "$first" "$include"/shadowlab/*.h; then
        echo "FAIL: exported but not declared in include/shadowlab: $s"; fail=1
    fi
    case "$name" in *::Impl::*|*::gl::*|*::map::*) echo "FAIL: internal symbol exported: $s"; fail=1 ;; esac
done <<< "$symbols"
grep -qx 'typeinfo for shadowlab::Error' <<< "$symbols" || { echo "FAIL: typeinfo for shadowlab::Error is not exported"; fail=1; }
[[ $fail == 0 ]] || exit 1
echo "$count exported symbols, all public API"

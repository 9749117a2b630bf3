#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst header --sealed --codes 0,4095` writes today the header the library's
# tests (tests/test_sealed.c, on the host and on the Cortex-M4F) and the
# flash images (bench/flash) compile: tests/support/eq20.h, byte for byte.
#   header_sealed.sh <hyst> <tests/support> <work dir>
set -euo pipefail
tool=$1 support=$2 work=$3
mkdir -p "$work"
cd "$work"
cp "$support/eq20.hyst" .
"$tool" header --model eq20.hyst --sealed --codes 0,4095 eq20 2> err.txt ||
    { echo "FAIL: header: $(cat err.txt)" >&2; exit 1; }
if ! cmp -s eq20.h "$support/eq20.h"; then
    diff "$support/eq20.h" eq20.h | head -20 >&2 || true
    echo "FAIL: tests/support/eq20.h is not what 'hyst header --model eq20.hyst --sealed" \
         "--codes 0,4095 eq20' writes now: regenerate it (in tests/support)" >&2
    exit 1
fi
echo "tests/support/eq20.h is hyst header's, byte for byte"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst header --sealed --codes 0,4095 --compensator` writes today the header the library's
# tests (tests/test_sealed.c, on the host and on the Cortex-M4F) and the
# flash images (bench/flash) compile: tests/data/eq20.h, byte for byte.
#   header_sealed.sh <hyst> <model file> <checked-in header> <work dir>
set -euo pipefail
tool=$1 model=$2 header=$3 work=$4
mkdir -p "$work"
cd "$work"
cp "$model" .
"$tool" header --model "$(basename "$model")" --sealed --codes 0,4095 --compensator eq20 2> err.txt ||
    { echo "FAIL: header: $(cat err.txt)" >&2; exit 1; }
if ! cmp -s eq20.h "$header"; then
    diff "$header" eq20.h | head -20 >&2 || true
    echo "FAIL: $header is not what 'hyst header --model $(basename "$model") --sealed" \
         "--codes 0,4095 --compensator eq20' writes now: regenerate it there" >&2
    exit 1
fi
echo "$header is hyst header's, byte for byte"

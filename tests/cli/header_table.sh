#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst header --compensator`: the compensator's table built on the host and
# taken from the header as firmware takes it from flash
# (hyst_curve_inverse_table_const(), hyst_curve_everett_inverse_table_const()),
# for a model file of each kind:
#  - the header compiles with the project's warnings as errors in float and
#    double builds, and the library accepts its table and seal in both;
#  - the double build's drives are, bit for bit, those of `hyst inv
#    --intervals N [--rows R]` (the table built at init); the float build's
#    agree with them within 2e-5 of the drive range (each within 1e-5 of the
#    exact compensator);
#  - one number of the float table changed in the header: refused (checksum
#    mismatch), nothing run;
#  - --rows without kind everett, --intervals without --compensator: refused.
#   header_table.sh <hyst> <cc> <include dir> <library> <C flags and layout defines> <work dir>
set -euo pipefail
tool=$1 cc=$2 inc=$3 lib=$4 defs=$5 work=$6
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

printf 'hyst-model-text 1\nkind poly\nlo 0\nhi 40\ndelay 0\ncoeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1\n' > poly.hyst
printf 'hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 0\ndegree 3\nterms 3 1 0 2 -0.5 0.4\n' > ev.hyst
awk 'BEGIN { for (k = 0; k < 3000; k++)
               printf "%.9g\n", 40 * (1 - cos(0.05 * k)) / 2 * (0.6 + 0.4 * cos(0.0131 * k));
             s = 1; for (k = 0; k < 2000; k++) { s = (s * 16807) % 2147483647;
               printf "%.9g\n", 40 * s / 2147483647 } }' > x.txt

# build <label>: comp.h in this directory into run_f32, run_f64
build() {
    local def out
    for def in "" "-DHYST_USE_DOUBLE"; do
        out=run_f32
        [ -z "$def" ] || out=run_f64
        # shellcheck disable=SC2086 # the layout defines are separate words
        "$cc" -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror $def $defs \
            -I. -I"$inc" "$here/header_table_run.c" "$lib" -lm -o $out 2> cc_err.txt ||
            fail "$1: the header does not compile ($def): $(head -5 cc_err.txt)"
    done
}

# check <model> <label> <header args...> -- <inv args...>
check() {
    local model=$1 label=$2 hargs=() iargs=()
    shift 2
    while [ "$1" != -- ]; do hargs+=("$1"); shift; done
    shift
    iargs=("$@")
    "$tool" header --model "$model" --compensator "${hargs[@]}" comp 2> h_err.txt ||
        fail "$label: header: $(cat h_err.txt)"
    grep -q '^static const hyst_table_seal_t comp_seal = {0x[0-9A-F]\{8\}ul, ' comp.h ||
        fail "$label: no seal in comp.h"
    build "$label"
    "$tool" sim --model "$model" --digits 17 x.txt > y.txt || fail "$label: sim"
    "$tool" inv --model "$model" --digits 17 "${iargs[@]}" y.txt > cli.txt 2> /dev/null ||
        fail "$label: inv"
    ./run_f64 < y.txt > d64.txt 2> r_err.txt || fail "$label: double build: $(cat r_err.txt)"
    ./run_f32 < y.txt > d32.txt 2> r_err.txt || fail "$label: float build: $(cat r_err.txt)"
    cmp -s cli.txt d64.txt || fail "$label: the double build's drives are not hyst inv's"
    paste -d, d64.txt d32.txt | awk -F, '{ d = $2 - $1; if (d < 0) d = -d; if (d / 40 > w) w = d / 40 }
        END { printf "float vs double: %.3g of the drive range", w; exit !(w <= 2e-5) }' > cmp.txt ||
        fail "$label: $(cat cmp.txt)"
    echo "$label: double build = hyst inv bit for bit; $(cat cmp.txt)"
}

check poly.hyst "poly, default table" -- --intervals default
check poly.hyst "poly, 64 intervals" --intervals 64 -- --intervals 64
check ev.hyst "everett, default table" -- --intervals default
check ev.hyst "everett, 8 rows of 16 intervals" --rows 8 --intervals 16 -- --rows 8 --intervals 16

# a damaged table: one number of the float table one digit off
awk '/^#else/ { f = 1 } f && /^    [0-9]/ && !done { sub(/^    [0-9.e+-]+f/, "    0.123456791f"); done = 1 } { print }' \
    comp.h > damaged.h
! cmp -s comp.h damaged.h || fail "the damaged header is not changed"
mv damaged.h comp.h
build "damaged"
rc=0
./run_f32 < y.txt > /dev/null 2> r_err.txt || rc=$?
[ $rc -eq 3 ] && grep -q 'checksum mismatch' r_err.txt ||
    fail "a damaged table: exit $rc, $(cat r_err.txt)"
./run_f64 < y.txt > /dev/null 2> /dev/null || fail "the double table was not damaged"
echo "damaged float table: refused ($(cat r_err.txt))"

# refusals
rc=0
"$tool" header --model poly.hyst --compensator --rows 8 comp 2> e.txt || rc=$?
[ $rc -ne 0 ] && grep -q 'option --rows applies to kind everett only' e.txt || fail "--rows, kind poly: $(cat e.txt)"
rc=0
"$tool" header --model ev.hyst --intervals 8 comp 2> e.txt || rc=$?
[ $rc -ne 0 ] && grep -q 'option --intervals needs --compensator' e.txt || fail "--intervals alone: $(cat e.txt)"
echo "refusals: ok"

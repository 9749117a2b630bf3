#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Round trip: `hyst sim` through the paper's Eq. 20 cubic, then `hyst fit`
# must return the coefficients (both estimators), and the generated header
# must compile cleanly in float and double builds.
#   roundtrip.sh <hyst> <C compiler> <include dir> <work dir>
set -euo pipefail
tool=$1 cc=$2 inc=$3 work=$4
mkdir -p "$work"
cd "$work"
poly="-6.1876e-6,1.1949e-3,8.6444e-2,5.8517e-1"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Triangle 0..40 V in 0.05 V steps, 3 cycles; a second, unused column, semicolons.
awk 'BEGIN { for (c = 0; c < 3; c++) { for (i = 0; i <= 800; i++) print i * 0.05 "; 7";
             for (i = 799; i > 0; i--) print i * 0.05 "; 7" } print 0 "; 7" }' > x.csv
"$tool" sim --poly "$poly" --range 0,40 --tp x.csv > y.csv
[ "$(wc -l < y.csv)" -eq "$(wc -l < x.csv)" ] || fail "sim: one output per input"
grep -qvE '^-?[0-9.e+-]+,[0-9]+$' y.csv && fail "sim --tp: lines are y,tp"
# with memory wiped at each extreme, a triangle keeps at most one turning point
awk -F, '$2 > 1 { exit 1 }' y.csv || fail "sim --tp: count above 1 on a full-range triangle"
paste -d, <(cut -d';' -f1 x.csv) <(cut -d, -f1 y.csv) > xy.csv

check() { # check <fit output> <tolerance>: coefficients within relative tolerance
    awk -F, -v want="$poly" -v tol="$2" 'NR == 1 {
        n = split(want, w, ",");
        if (NF != n) { print "coefficient count " NF " != " n; exit 1 }
        for (k = 1; k <= n; k++) {
            e = ($k - w[k]) / w[k]; if (e < 0) e = -e;
            if (e > tol) { print "coefficient " k ": " $k " vs " w[k] " (rel " e ")"; exit 1 }
        } }
        NR == 2 && $0 != "0,40" { print "domain " $0; exit 1 }' "$1"
}
for method in joint reflect; do
    "$tool" fit --degree 3 --method "$method" xy.csv > fit_$method.txt || fail "fit $method"
    check fit_$method.txt 1e-6 || fail "fit $method: $(head -2 fit_$method.txt)"
done
# the same through standard input and --xcol/--ycol on a reordered file
paste -d' ' <(cut -d, -f2 xy.csv) <(cut -d, -f1 xy.csv) |
    "$tool" fit --degree 3 --xcol 2 --ycol 1 - > fit_stdin.txt || fail "fit from stdin"
check fit_stdin.txt 1e-6 || fail "fit from stdin: $(head -1 fit_stdin.txt)"

"$tool" fit --degree 3 --header f0_roundtrip xy.csv > /dev/null 2>&1 || fail "fit --header"
grep -q 'static const hyst_poly_t f0_roundtrip = {' f0_roundtrip.h || fail "header content"
printf '#include "f0_roundtrip.h"\nint main(void) { return f0_roundtrip.degree == 3u ? 0 : 1; }\n' > use.c
for def in "" "-DHYST_USE_DOUBLE"; do
    "$cc" -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror $def \
        -I. -I"$inc" use.c -o use || fail "header does not compile ($def)"
    ./use || fail "header degree ($def)"
done

# a fit that does not increase: exit 2, reported with the turn, no header
awk 'BEGIN { for (c = 0; c < 3; c++) { for (i = 0; i <= 100; i++) { x = i / 10; print x, (x - 3) ^ 2 }
             for (i = 99; i > 0; i--) { x = i / 10; print x, 9 + 49 - (7 - x) ^ 2 } } }' > dip.txt
set +e
"$tool" fit --degree 2 --header f0_dip dip.txt > dip_fit.txt 2> dip_err.txt
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "non-increasing fit: exit $rc, expected 2"
grep -q 'NOT increasing: slope negative at x = ' dip_fit.txt || fail "turn not reported"
[ ! -e f0_dip.h ] || fail "header written for a non-increasing fit"
echo "round trip ok: $(head -1 fit_joint.txt)"

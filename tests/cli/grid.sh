#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Model files of kind everett_grid (the asymmetric kind on a grid) in `hyst`:
#  - sim --model runs one: one cell of mass 8 on [0, 2] gives E(a, b) =
#    8 ((a - b) / 2)^2, exact at these inputs;
#  - malformed files are refused, naming line and field; inv --model gives
#    the drives of sim's outputs back; inv --intervals refuses the kind (no
#    tabulated compensator); header --compensator says how firmware builds
#    it (compiled and run: inv's drives), --sealed, --intervals refused;
#  - header --model writes its hyst_everett_grid_t, which compiles (float and
#    double) and which the library's constructor accepts;
#  - fit --kind everett_grid on a record of a grid plant with minor loops
#    saves a model whose sim follows the plant within 1 % of its range (its
#    knots found within 0.02 of the plant's), also from a record that
#    starts inside a loop (its samples before the first extreme not fitted),
#    and the default fit, with the other kinds, chooses a grid for it.
#   grid.sh <hyst> <C compiler> <include dir> <library sources dir> <work dir>
set -euo pipefail
tool=$1 cc=$2 inc=$3 src=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

cat > one.hyst <<'EOF'
hyst-model-text 1
kind everett_grid
lo 0
hi 2
y_lo 1
knots 0 2
weights 8
EOF
printf '1\n2\n1.5\n1.75\n' > x.txt
"$tool" sim --model one.hyst x.txt > y.txt || fail "sim of a grid model"
[ "$(tr '\n' ' ' < y.txt)" = "3 9 8.5 8.625 " ] || fail "sim: $(tr '\n' ' ' < y.txt)"

refused() { # <file> <expected message part>
    if "$tool" sim --model "$1" x.txt > /dev/null 2> err.txt; then fail "$1 accepted"; fi
    grep -q -- "$2" err.txt || fail "$1: $(cat err.txt)"
}
sed 's/^weights 8$/weights 8 1/' one.hyst > bad1.hyst
refused bad1.hyst "bad1.hyst:7: field 3: one too many: weights needs 1 numbers for 2 knots"
sed 's/^knots 0 2$/knots 0.5 2/' one.hyst > bad2.hyst
refused bad2.hyst "bad2.hyst:6: field 2: knots must run from lo to hi"
sed 's/^weights 8$/weights -8/' one.hyst > bad3.hyst
refused bad3.hyst "model file bad3.hyst: "
sed 's/^y_lo 1$/degree 2/' one.hyst > bad4.hyst
refused bad4.hyst "bad4.hyst:5: field 1: degree is not a key of kind everett_grid"
# inv --model: the compensator, in closed form: the drives of sim's outputs back
"$tool" inv --model one.hyst y.txt > xi.txt || fail "inv of a grid model"
[ "$(tr '\n' ' ' < xi.txt)" = "1 2 1.5 1.75 " ] || fail "inv: $(tr '\n' ' ' < xi.txt)"
if "$tool" inv --model one.hyst --intervals 32 y.txt > /dev/null 2> err.txt; then
    fail "inv --intervals accepted a grid"
fi
grep -q "no tabulated compensator" err.txt || fail "inv --intervals: $(cat err.txt)"

# the header as firmware uses it (header_run.c, in float and in double)
"$tool" header --model one.hyst grid_model 2> /dev/null || fail "header"
bash "$here/header_run.sh" "$cc" "$inc" "$src" grid_model 1 || fail "header"
for d in "" -DHYST_USE_DOUBLE; do
    "./run$d" || fail "the header's grid refused ($d)"
done
# a rate term on a grid: sim --model adds it, so the header declares it as for
# the other kinds (it was dropped, the header including hyst/rate.h for nothing)
{ cat one.hyst; printf 'rate_tau 4\nrate_weight 0.25\n'; } > rate.hyst
"$tool" header --model rate.hyst grid_rate 2> /dev/null || fail "header of a grid with a rate term"
grep -q 'static const hyst_wide_t grid_rate_rate_tau = HYST_REAL_C(4\.0);' grid_rate.h &&
    grep -q 'static const hyst_wide_t grid_rate_rate_weight = HYST_REAL_C(0\.25);' grid_rate.h ||
    fail "header of a grid with a rate term: $(grep -c rate grid_rate.h) lines name it, no declaration"
# header --compensator: the same grid, the compensator built from it in firmware gives
# inv --model's drives; no table of its own (--intervals, --sealed refused)
"$tool" header --model one.hyst --compensator grid_comp 2> /dev/null || fail "header --compensator"
grep -q "hyst_curve_everett_grid_inverse()" grid_comp.h || fail "header --compensator: no inverse named"
bash "$here/header_run.sh" "$cc" "$inc" "$src" grid_comp 1 -DWANT="$(paste -s -d, y.txt)" ||
    fail "header --compensator"
for d in "" -DHYST_USE_DOUBLE; do
    "./run$d" > xc.txt || fail "the header's compensator refused ($d)"
    [ "$(tr '\n' ' ' < xc.txt)" = "$(tr '\n' ' ' < xi.txt)" ] ||
        fail "header --compensator drives ($d): $(tr '\n' ' ' < xc.txt), inv: $(tr '\n' ' ' < xi.txt)"
done
for opt in --sealed "--intervals 32" "--rows 8"; do
    # shellcheck disable=SC2086
    if "$tool" header --model one.hyst --compensator $opt g2 2> err.txt; then
        fail "header --compensator $opt accepted a grid"
    fi
    grep -q "closed form" err.txt || fail "header --compensator $opt: $(cat err.txt)"
done
# ---- a grid plant: a near step between 1 and 1.4 of 0..3, minor loops of decreasing size ----
cat > plant.hyst <<'EOF'
hyst-model-text 1
kind everett_grid
lo 0
hi 3
y_lo 0
knots 0 1 1.4 3
weights 1 0.5 8 0.2 0.5 1
EOF
awk 'BEGIN { for (c = 0; c < 12; c++) { a = 3 - c * 0.2; b = c * 0.2;
             for (x = b; x < a; x += 0.01) print x; for (x = a; x > b; x -= 0.01) print x } }' > px.txt
"$tool" sim --model plant.hyst px.txt > py.txt || fail "sim of the plant"
paste -d ' ' px.txt py.txt > rec.txt
"$tool" fit --kind everett_grid --degree 3 --delay 0 --creep none --save fitted.hyst rec.txt > fit.txt ||
    fail "fit --kind everett_grid: $(cat fit.txt)"
"$tool" sim --model fitted.hyst px.txt > fy.txt || fail "sim of the fitted grid"
paste -d ' ' py.txt fy.txt | awk '{ d = $1 - $2; s += d * d; n++; lo = n == 1 || $1 < lo ? $1 : lo;
                                   hi = n == 1 || $1 > hi ? $1 : hi }
                                 END { r = 100 * sqrt(s / n) / (hi - lo); print "grid fit: " r " %";
                                       exit !(r < 1) }' || fail "the fitted grid misses the plant"
awk '/knots 0 [0-9.]+ [0-9.]+ [0-9.]+$/ { k1 = $(NF - 2); k2 = $(NF - 1);
     exit !(k1 > 0.98 && k1 < 1.02 && k2 > 1.38 && k2 < 1.42) }' fit.txt ||
    fail "the knots found: $(grep -o 'knots.*' fit.txt)"
# the same plant's record from inside a loop (falling from 3 at 2.51), with a
# last major loop: the masses fitted on the samples from the first extreme
# on (before it the model's state, from rest, is not the plant's)
awk 'BEGIN { for (c = 0; c < 12; c++) { a = 3 - c * 0.2; b = c * 0.2;
             for (x = b; x < a; x += 0.01) print x; for (x = a; x > b; x -= 0.01) print x }
             for (x = 2.2; x > 0; x -= 0.01) print x; for (x = 0; x < 3; x += 0.01) print x
             for (x = 3; x > 0; x -= 0.01) print x }' > mx.txt
"$tool" sim --model plant.hyst mx.txt > my.txt || fail "sim of the plant (from inside a loop)"
paste -d ' ' mx.txt my.txt | tail -n +351 > mid.txt
"$tool" fit --kind everett_grid --degree 3 --delay 0 --creep none --save mid.hyst mid.txt > mid_fit.txt ||
    fail "fit --kind everett_grid from inside a loop: $(cat mid_fit.txt)"
head_n=$(awk '$1 <= 0.03 || $1 >= 2.97 { print NR - 1; exit }' mid.txt)
n=$(wc -l < mid.txt)
grep -q "run over the record, $((n - head_n)) of $n samples used" mid_fit.txt ||
    fail "from inside a loop, $head_n samples before the first extreme: $(grep -o '[0-9]* of [0-9]* samples used' mid_fit.txt)"
"$tool" sim --model mid.hyst mx.txt > mfy.txt 2> /dev/null || fail "sim of the grid fitted from inside a loop"
paste -d ' ' my.txt mfy.txt | awk '{ d = $1 - $2; s += d * d; n++; lo = n == 1 || $1 < lo ? $1 : lo;
                                    hi = n == 1 || $1 > hi ? $1 : hi }
                                  END { exit !(100 * sqrt(s / n) / (hi - lo) < 1) }' ||
    fail "the grid fitted from inside a loop misses the plant"
# major loops alone determine every mass of 3 intervals, not how the inner
# cells of 4 share theirs: the fit says so (stdout and a warning), not silently
awk 'BEGIN { for (c = 0; c < 3; c++) { for (x = 0; x < 3; x += 0.01) print x
             for (x = 3; x > 0; x -= 0.01) print x } }' > major_x.txt
"$tool" sim --model plant.hyst major_x.txt > major_y.txt || fail "sim of the plant (major loops)"
paste -d ' ' major_x.txt major_y.txt > major.txt
"$tool" fit --kind everett_grid --degree 3 --delay 0 --creep none major.txt > m3.txt 2> m3.err ||
    fail "fit of 3 intervals on major loops: $(cat m3.err)"
! grep -q "do not determine" m3.txt m3.err || fail "3 intervals on major loops said undetermined"
"$tool" fit --kind everett_grid --degree 4 --delay 0 --creep none major.txt > m4.txt 2> m4.err ||
    fail "fit of 4 intervals on major loops: $(cat m4.err)"
grep -q "^# the record's turning points do not determine every mass of this grid" m4.txt ||
    fail "4 intervals on major loops, the report: $(grep residual m4.txt)"
grep -q "^hyst fit: warning: major.txt: the record's turning points do not determine every mass" m4.err ||
    fail "4 intervals on major loops, no warning: $(cat m4.err)"
! grep -q "do not determine" fit.txt || fail "the record with minor loops said undetermined"
# the grid's most intervals (above f0's highest degree) are accepted
"$tool" fit --kind everett_grid --degree 12 --delay 0 --creep none rec.txt > fit12.txt ||
    fail "fit --kind everett_grid --degree 12: $(cat fit12.txt)"
grep -q "kind everett_grid, 12 intervals" fit12.txt || fail "--degree 12: $(grep residual fit12.txt)"
"$tool" fit --creep none rec.txt > auto.txt || fail "default fit"
grep -q '^# chosen by hold-out: degree [46], delay 0 (kind everett_grid' auto.txt ||
    fail "default fit on a grid plant: $(grep chosen auto.txt)"
echo "grid.sh: OK"

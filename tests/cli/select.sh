#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst fit` without --degree: degree and delay chosen by hold-out. A record
# made by the model itself (Eq. 20, degree 3) on its major loop, the output
# lagging by 3 samples, plus noise: the choice must be degree 3 and delay 3,
# without a creep term, every candidate reported, the parameter count printed.
#   select.sh <hyst> <work dir>
set -euo pipefail
tool=$1 work=$2
mkdir -p "$work"
cd "$work"
poly="-6.1876e-6,1.1949e-3,8.6444e-2,5.8517e-1"
fail() { echo "FAIL: $*" >&2; exit 1; }

# A major-loop record: full-range triangles 0..40..0 V, 0.25 V steps, 9 cycles.
awk 'BEGIN { for (c = 0; c < 9; c++) { for (x = 0; x < 40; x += 0.25) print x;
             for (x = 40; x > 0; x -= 0.25) print x } print 0 }' > x.txt
"$tool" sim --poly "$poly" --range 0,40 x.txt > y.txt
# line k: x[k] and the output for x[k - 3] (a sensor 3 samples late), with
# +-A/2 um of deterministic noise (an LCG): late_record A
late_record() {
    awk -v amp="$1" 'NR == FNR { x[NR] = $1; n = NR; next } { y[FNR] = $1 }
         END { s = 12345; for (k = 4; k <= n; k++) {
                   s = (s * 1103515245 + 12345) % 2147483648; e = (s / 2147483648 - 0.5) * amp;
                   printf "%s %.9g\n", x[k], y[k - 3] + e } }' x.txt y.txt
}
late_record 0.02 > rec.txt
"$tool" fit rec.txt > fit.txt || fail "fit without --degree: $(cat fit.txt)"
grep -q '^# chosen by hold-out: degree 3, delay 3 ' fit.txt || fail "choice: $(grep chosen fit.txt)"
grep -q '^# parameters 4$' fit.txt || fail "parameter count: $(grep parameters fit.txt)"
# no creep in the record: the creep term tried, not chosen
grep -q '^# creep: none (hold-out rms ' fit.txt || fail "creep: $(grep creep fit.txt)"
grep -q '^# delay 3 samples$' fit.txt || fail "delay line"
[ "$(grep -c '^# candidate degree' fit.txt)" -eq 81 ] || fail "candidates: $(grep -c candidate fit.txt)"
grep -q '^# candidate degree 3 delay 3: .*(chosen)$' fit.txt || fail "chosen mark"
# a given delay is kept: only models are compared (at the wrong delay a
# flexible one may take the misalignment in as loop shape)
"$tool" fit --delay 2 rec.txt > fit2.txt || fail "fit --delay 2"
grep -q '^# chosen by hold-out: degree [0-9]*, delay 2 ' fit2.txt || fail "fixed delay: $(grep chosen fit2.txt)"
grep -q '^# candidate .* delay [013-9]' fit2.txt && fail "a candidate at another delay than 2"
[ "$(grep -c '^# candidate degree' fit2.txt)" -eq 9 ] || fail "candidates with --delay"
# the model file: what fit chose, read back by sim (the delay applied) and inv
"$tool" fit --save m.hyst rec.txt > /dev/null 2>&1 || fail "fit --save"
head -n 1 m.hyst | grep -qx 'hyst-model-text 1' || fail "model file magic"
grep -qx 'delay 3' m.hyst || fail "model file delay"
coeffs="$(sed -n 's/^coeffs //p' m.hyst | tr ' ' ',')"
"$tool" sim --model m.hyst x.txt > sim_model.txt || fail "sim --model"
"$tool" sim --poly "$coeffs" --range 0,40 x.txt > sim_poly.txt || fail "sim --poly"
# line k of sim --model is line k - 3 of sim --poly; the first 3 are f0(0)
[ "$(tail -n +4 sim_model.txt | wc -l)" -eq "$(($(wc -l < sim_poly.txt) - 3))" ] || fail "sim --model: line count"
cmp <(tail -n +4 sim_model.txt) <(head -n -3 sim_poly.txt) || fail "sim --model: not the delayed sim --poly"
[ "$(head -n 3 sim_model.txt | sort -u | wc -l)" -eq 1 ] || fail "sim --model: the first lines at rest"
"$tool" inv --model m.hyst y.txt > inv_model.txt 2> inv_err.txt || fail "inv --model"
grep -q 'delay of 3 samples is not compensated' inv_err.txt || fail "inv --model: the delay note"
cmp inv_model.txt <("$tool" inv --poly "$coeffs" --range 0,40 y.txt) || fail "inv --model differs from inv --poly"
# the firmware header of the model file: f0 as saved, compiled with the library's header
"$tool" header --model m.hyst --dir . f0_sel 2> /dev/null || fail "header --model"
grep -q 'static const hyst_poly_t f0_sel = {' f0_sel.h || fail "header content"
grep -q 'follows its input$' f0_sel.h && grep -q '^ \* 3 samples later' f0_sel.h || fail "header: the delay comment"
for c in $(sed -n 's/^coeffs //p' m.hyst); do grep -q "HYST_REAL_C($c)" f0_sel.h || fail "header: coefficient $c"; done
"$tool" header --model m.hyst '9x' 2> err.txt && fail "header: a bad NAME accepted"
grep -q "NAME '9x' is not a C identifier" err.txt || fail "header: message $(cat err.txt)"
# The same record without noise (a simulated plant, fitted to its own nine
# printed digits): every candidate of degree 3 and more is exact there, and
# the plant's own degree, delay and no creep term must win, not the one whose
# rounding happens to be 1 % lower.
late_record 0 > exact.txt
"$tool" fit exact.txt > fit_exact.txt || fail "fit of an exact record: $(cat fit_exact.txt)"
grep -q '^# chosen by hold-out: degree 3, delay 3 (kind poly, 4 parameters' fit_exact.txt ||
    fail "exact record: $(grep chosen fit_exact.txt)"
grep -q '^# creep: none ' fit_exact.txt || fail "exact record: $(grep creep: fit_exact.txt)"
grep -q '^# delay 3 samples$' fit_exact.txt || fail "exact record: $(grep '^# delay' fit_exact.txt)"
grep -q '^# hold-out rms [0-9.e+-]* is the record.s resolution' fit_exact.txt ||
    fail "exact record: no resolution line"
grep -q 'resolution' fit.txt && fail "noisy record: a resolution line"
# The plant driven with minor loops (0.005 um of noise): f0's estimator is
# biased there, E of the width alone (t-degree 0) is not and wins; it is the
# symmetric model, so the model file is kind poly, whose compensator is a
# table, and predicts as that E does.
awk 'BEGIN { for (c = 0; c < 4; c++) { for (x = 0; x < 40; x += 0.25) print x;
             for (x = 40; x > 0; x -= 0.25) print x; for (x = 0; x < 30; x += 0.25) print x;
             for (x = 30; x > 10; x -= 0.25) print x; for (x = 10; x < 25; x += 0.25) print x;
             for (x = 25; x > 15; x -= 0.25) print x; for (x = 15; x > 0; x -= 0.25) print x }
           print 0 }' > xm.txt
"$tool" sim --poly "$poly" --range 0,40 xm.txt > ym.txt
awk 'NR == FNR { x[NR] = $1; n = NR; next } { y[FNR] = $1 }
     END { s = 12345; for (k = 1; k <= n; k++) {
               s = (s * 1103515245 + 12345) % 2147483648; e = (s / 2147483648 - 0.5) * 0.005;
               printf "%s %.9g\n", x[k], y[k] + e } }' xm.txt ym.txt > minor.txt
"$tool" fit --save minor.hyst minor.txt > fit_minor.txt 2> fit_minor_err.txt ||
    fail "fit of the minor-loop record: $(cat fit_minor_err.txt)"
grep -q '^# chosen by hold-out: degree 3, delay 0 (kind everett, t-degree 0, 4 parameters' \
    fit_minor.txt || fail "minor loops: $(grep chosen fit_minor.txt)"
grep -q '^# written as kind poly: E of t-degree 0 is the symmetric model' fit_minor.txt ||
    fail "minor loops: no line saying E was written as f0"
grep -qx 'kind poly' minor.hyst || fail "minor loops: the model file is not kind poly: $(cat minor.hyst)"
grep -q 'the symmetric model (kind poly, degree 3) run over the record' fit_minor.txt ||
    fail "minor loops: the residual line: $(sed -n 4p fit_minor.txt)"
! grep -q 'minor loops' fit_minor_err.txt || fail "minor loops: f0 warned of: $(cat fit_minor_err.txt)"
# the plant's f0 within the noise
awk '/^coeffs / { want[2] = -6.1876e-6; want[3] = 1.1949e-3; want[4] = 8.6444e-2; want[5] = 0.58517;
                  for (k = 2; k <= 5; k++) { d = ($k - want[k]) / want[k]; if (d < 0) d = -d;
                      if (d > 0.02) { print "coefficient " k - 1 ": " $k; bad = 1 } } }
     END { exit bad }' minor.hyst || fail "minor loops: f0 is not the plant's"
# the same E kept as E when asked for by kind: sim of the two agree
"$tool" fit --kind everett --degree 3 --t-degree 0 --delay 0 --creep none --save minor_e.hyst \
    minor.txt > /dev/null 2>&1 || fail "fit --kind everett of the minor-loop record"
grep -qx 'kind everett' minor_e.hyst || fail "--kind everett written as another kind"
"$tool" sim --model minor.hyst xm.txt > sim_minor.txt || fail "sim of the f0 written"
"$tool" sim --model minor_e.hyst xm.txt > sim_minor_e.txt || fail "sim of the E"
paste sim_minor.txt sim_minor_e.txt | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1e-9) bad = 1 }
    END { exit bad }' || fail "minor loops: f0 written and E predict differently"
# its compensator is the table (kind poly's): inv undoes sim
"$tool" inv --model minor.hyst sim_minor.txt > inv_minor.txt 2> inv_minor_err.txt ||
    fail "inv of the f0 written: $(cat inv_minor_err.txt)"
paste inv_minor.txt xm.txt | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1e-6) bad = 1 }
    END { exit bad }' || fail "minor loops: inv does not undo sim"
# --kind everett without a degree: E of t-degree 0 stays kind everett
"$tool" fit --kind everett --save minor_k.hyst minor.txt > fit_minor_k.txt 2>&1 ||
    fail "fit --kind everett"
grep -qx 'kind everett' minor_k.hyst || fail "--kind everett: written as $(grep kind minor_k.hyst)"
! grep -q 'written as kind poly' fit_minor_k.txt || fail "--kind everett: said written as poly"
# --method branches: that fit of kind poly at a given degree, its delay and creep option
# chosen alike: the same model file, and no warning of minor loops; the joint estimator of
# the same degree warns and points to it
"$tool" fit --degree 3 --method branches --save minor_b.hyst minor.txt > fit_minor_b.txt \
    2> minor_b_err.txt || fail "fit --method branches: $(cat minor_b_err.txt)"
cmp minor_b.hyst minor.hyst || fail "--method branches: not the f0 the choice wrote"
! grep -q 'minor loops' minor_b_err.txt || fail "--method branches warned: $(cat minor_b_err.txt)"
grep -q 'f0 fitted as E of t-degree 0 along every branch' fit_minor_b.txt ||
    fail "--method branches: the residual line: $(sed -n 4p fit_minor_b.txt)"
"$tool" fit --degree 3 minor.txt > /dev/null 2> minor_j_err.txt || fail "fit --degree 3"
grep -q 'f0 of --degree 3 is biased.*or fit --method branches (f0 along every branch)$' \
    minor_j_err.txt || fail "--degree 3 on minor loops: $(cat minor_j_err.txt)"
"$tool" fit --method branches --creep none minor.txt > fit_minor_bc.txt ||
    fail "fit --method branches without --degree"
grep -q 'kinds compared: poly, f0 fitted along every branch' fit_minor_bc.txt ||
    fail "--method branches: $(grep chosen fit_minor_bc.txt)"
! grep -q '^# candidate degree\|everett_grid\|t-degree [1-3] ' fit_minor_bc.txt ||
    fail "--method branches compared another kind"
"$tool" fit --degree 5 --method branches minor.txt 2> err.txt && fail "--method branches of degree 5"
grep -q 'option --degree: 5 is above 4, the highest degree --method branches fits' err.txt ||
    fail "degree 5: $(cat err.txt)"
"$tool" fit --kind everett --method branches minor.txt 2> err.txt && fail "--kind everett --method branches"
# inputs far from 0: the powers of x cancel; refused, nothing written
awk '{ printf "%.17g %s\n", $1 + 1e6, $2 }' minor.txt > far.txt
"$tool" fit --degree 3 --method branches --save far.hyst far.txt > /dev/null 2> err.txt &&
    fail "--method branches far from 0"
grep -q 'gives no f0 in powers of x on \[1000000, 1000040\]' err.txt || fail "far: $(cat err.txt)"
[ ! -e far.hyst ] || fail "far: a model file written"
echo "select: degree 3, delay 3 recovered; $(grep -c '^# candidate' fit.txt) candidates;" \
     "E of t-degree 0 on minor loops written as f0"

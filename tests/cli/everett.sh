#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The asymmetric kind (kind everett) in `hyst`:
#  - fit without --kind on the measured record compares both kinds (E of
#    each degree and t-degree), reports every candidate and chooses by the
#    rule (the fewest parameters within 1 % of the lowest hold-out RMS, the
#    symmetric kind between as many); the
#    asymmetric kind, linear in t, wins there;
#  - a record made by a hand-written asymmetric model (delay 2, noise): fit
#    chooses kind everett, degree 2, delay 2 and returns its terms;
#  - fit --save, then sim --model prints what the library gives for the
#    saved model (everett_run), the delay applied, bit for bit;
#  - the headers of fit --header and header --model compile (float and
#    double) and hold the saved numbers; inv --model gives back the inputs
#    of the model's outputs (the asymmetric compensator, to 1e-9 of the span);
#  - the same plant's record from inside a loop: only the samples after the
#    first extreme are fitted (before it the model's state, from rest, is
#    not the plant's): E recovered, its class chosen; a record whose first
#    extreme comes late (excursions growing from a rest in the middle) has
#    every output fitted;
#  - a fit the library refuses (E falling) exits 2 and writes nothing;
#  - major loops alone of a plant whose E is of degree 3, linear in t: E of
#    full degree 3 is singular there, t-degree 1 is chosen and recovered.
#   everett.sh <hyst> <everett_run> <C compiler> <include dir> <work dir> <measured record>
set -euo pipefail
tool=$1 run=$2 cc=$3 inc=$4 work=$5 data=$6
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
# line 1 of a fit's output FILE: the plant's three terms 3,1,2, each within TOL
plant_terms_within() {
    awk -F, -v tol="$1" 'NR == 1 { if (NF != 3) exit 1; split("3,1,2", w, ",");
        for (k = 1; k <= 3; k++) { d = $k - w[k]; if (d < 0) d = -d; if (d > tol) exit 1 } }' "$2"
}

# ---- the measured record: both kinds compared, every candidate reported (the
# hysteresis models alone: creep.sh checks the creep term) ----
"$tool" fit --skip 350 --ycol 5 --creep none "$data" > meas.txt || fail "fit on the measured record"
[ "$(grep -c '^# candidate degree' meas.txt)" -eq 81 ] || fail "poly candidates: $(grep -c '^# candidate degree' meas.txt)"
# everett: degree d = 1..4, t-degree 0..d - 1 (10), at each delay 0..8
[ "$(grep -c '^# candidate everett degree [1-4] t-degree [0-3] delay' meas.txt)" -eq 90 ] || fail "everett candidates"
[ "$(grep -c '(chosen)$' meas.txt)" -eq 1 ] || fail "one candidate chosen"
grep -q '^# chosen by hold-out: degree 4, delay 4 (kind everett, t-degree 1, 8 parameters: .*kinds compared: poly, everett, everett_grid, spline)$' meas.txt ||
    fail "choice on the measured record: $(grep chosen meas.txt)"
grep -qx '# parameters 8' meas.txt || fail "parameter count: $(grep parameters meas.txt)"
# the rule, recomputed from the printed table: params = degree + 1 (poly),
# 1 + the sum over i = 1..d of min(d - i, k) + 1 (everett degree d, t-degree k),
# K + 3 (spline of K intervals), one more for a sub-sample delay
awk '/^# candidate .*hold-out rms/ {
         ev = $3 == "everett"; gr = $3 == "everett_grid"; sp = $3 == "spline";
         d = ev || gr || sp ? $5 : $4; rms = ev ? $12 : gr || sp ? $10 : $9; sub(/,$/, "", rms);
         if (ev) { if ($6 != "t-degree" || $8 != "delay") { print "columns: " $0; exit 1 }
                   p = 1; for (i = 1; i <= d; i++) p += (d - i < $7 ? d - i : $7) + 1 }
         else if (gr || sp) { if ($4 != "intervals" || $6 != "delay") { print "columns: " $0; exit 1 }
                              p = gr ? 1 + d * (d + 1) / 2 + d - 1 : d + 3 }
         else p = d + 1;
         if ((ev ? $9 : gr || sp ? $7 : $6) ~ /\./) p++;
         n++; P[n] = p; K[n] = ev || gr || sp; R[n] = rms + 0; C[n] = /\(chosen\)$/;
         if (best == "" || rms + 0 < best) best = rms + 0 }
     END { for (i = 1; i <= n; i++) if (R[i] <= best * 1.01 && (w == "" || P[i] < P[w] ||
               (P[i] == P[w] && (K[i] < K[w] || (K[i] == K[w] && R[i] < R[w]))))) w = i;
           if (!C[w]) { print "rule picks candidate " w; exit 1 } }' meas.txt || fail "the chosen candidate is not the rule's"
# major loops alone determine E linear in t, not E of full degree 3
grep -q '^# candidate everett degree 3 t-degree 2 delay 4: not scored (the record.s turning points do not determine E' meas.txt ||
    fail "degree 3 on major loops: $(grep 'everett degree 3 t-degree 2 delay 4' meas.txt)"
grep -q '^# candidate everett degree 3 t-degree 1 delay 4: hold-out rms' meas.txt ||
    fail "degree 3, t-degree 1 on major loops: $(grep 'everett degree 3 t-degree 1 delay 4' meas.txt)"
# --kind tcm: the symmetric kind only, as before
"$tool" fit --kind tcm --skip 350 --ycol 5 --creep none "$data" > tcm.txt || fail "fit --kind tcm"
grep -q '^# chosen by hold-out: degree 4, delay 4 (kind poly, 5 parameters' tcm.txt || fail "--kind tcm: $(grep chosen tcm.txt)"
! grep -q 'candidate everett' tcm.txt || fail "--kind tcm scored everett candidates"
# --compare-pi names the chosen kind
"$tool" fit --skip 350 --ycol 5 --creep none --compare-pi 10 "$data" > cmp.txt || fail "--compare-pi"
grep -q '^# compare on the last third .*hold-out rms asymmetric (everett) TCM degree 4 t-degree 1 (8 parameters) [0-9.]*, PI 10 operators' cmp.txt ||
    fail "compare line: $(grep compare cmp.txt)"

# ---- a simulated asymmetric plant: E = 3 w + w t + 2 w^2 on [0, 40] ----
printf 'hyst-model-text 1\n# a hand-written plant\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 0\ndegree 2\nterms 3 1 2\n' > plant.hyst
# three times: a major loop, then nested minor loops, 0.25 V steps
awk 'function ramp(a, b,   k, n) { n = int((b > a ? b - a : a - b) / 0.25 + 0.5);
                                 for (k = 1; k <= n; k++) printf "%.2f\n", a + (b - a) * k / n }
     BEGIN { print 0; for (c = 0; c < 3; c++) { ramp(0, 40); ramp(40, 10); ramp(10, 30); ramp(30, 5);
             ramp(5, 35); ramp(35, 20); ramp(20, 25); ramp(25, 0); ramp(0, 40); ramp(40, 0) } }' > x.txt
"$tool" sim --model plant.hyst --digits 17 x.txt > y.txt || fail "sim of the plant"
# line k: x[k] and the output for x[k - 2] (a sensor 2 samples late), +-0.005 of noise (an LCG)
awk 'NR == FNR { x[NR] = $1; n = NR; next } { y[FNR] = $1 }
     END { s = 4242; for (k = 3; k <= n; k++) {
               s = (s * 1103515245 + 12345) % 2147483648; e = (s / 2147483648 - 0.5) * 0.01;
               printf "%s %.9g\n", x[k], y[k - 2] + e } }' x.txt y.txt > rec.txt
"$tool" fit --save m.hyst --header f0_asym rec.txt > fit.txt 2> fit_err.txt || fail "fit: $(cat fit_err.txt)"
grep -q '^# chosen by hold-out: degree 2, delay 2 (kind everett, t-degree 1, 4 parameters' fit.txt || fail "plant: $(grep chosen fit.txt)"
plant_terms_within 0.01 fit.txt ||
    fail "plant terms: $(head -1 fit.txt)"
# the model file as docs/cli.md gives it
[ "$(sed -n 1p m.hyst)" = 'hyst-model-text 1' ] && [ "$(grep -v '^#' m.hyst | cut -d' ' -f1 | paste -sd' ')" = "hyst-model-text kind lo hi y_lo delay degree terms" ] ||
    fail "model file keys: $(cat m.hyst)"
grep -qx 'kind everett' m.hyst && grep -qx 'delay 2' m.hyst && grep -qx 'degree 2' m.hyst || fail "model file: $(cat m.hyst)"
val() { sed -n "s/^$1 //p" m.hyst; }
# sim --model: the library's outputs for the saved model, 2 lines late
"$tool" sim --model m.hyst --digits 17 x.txt > sim_model.txt || fail "sim --model"
# shellcheck disable=SC2046 # the terms are separate arguments
"$run" "$(val lo)" "$(val hi)" "$(val y_lo)" "$(val degree)" $(val terms) < x.txt > lib.txt || fail "everett_run"
[ "$(wc -l < sim_model.txt)" -eq "$(wc -l < x.txt)" ] || fail "sim --model: line count"
cmp <(tail -n +3 sim_model.txt) <(head -n -2 lib.txt) || fail "sim --model differs from the library's outputs"
[ "$(head -n 2 sim_model.txt | sort -u)" = "$(head -n 1 lib.txt)" ] || fail "sim --model: the first lines are not y_lo"
# written again by fit, the same text: numbers read back bit for bit
"$tool" fit --save m2.hyst rec.txt > /dev/null 2>&1 && cmp -s m.hyst m2.hyst || fail "second --save differs"

# ---- the plant's record from inside a loop (its first 199 samples dropped:
# it starts falling from 40 at 30.25): the model runs from rest, so the
# samples before the first extreme are not fitted; E recovered, the plant's
# class chosen ----
"$tool" sim --model plant.hyst --digits 17 x.txt > y_plant.txt || fail "sim of the plant"
paste -d' ' x.txt y_plant.txt | tail -n +200 > mid.txt
"$tool" fit --kind everett --degree 2 --t-degree 1 --delay 0 --creep none mid.txt > mid_fit.txt ||
    fail "fit of the record from inside a loop"
plant_terms_within 1e-3 mid_fit.txt ||
    fail "terms from inside a loop: $(head -1 mid_fit.txt)"
"$tool" fit --creep none mid.txt > mid_choice.txt || fail "fit from inside a loop, chosen"
grep -q '^# chosen by hold-out: degree 2, delay 0 (kind everett, t-degree 1, 4 parameters' mid_choice.txt ||
    fail "choice from inside a loop: $(grep chosen mid_choice.txt)"

# ---- the plant's record of excursions growing from a rest at 20: the first
# extreme comes in the last third, so every output is fitted (from rest, as
# the plant ran), not only the tail after it; E recovered ----
awk 'BEGIN { for (i = 0; i < 50; i++) print 20; for (c = 1; c <= 10; c++) { a = 2 * c;
             for (x = 20; x < 20 + a; x += 0.25) print x; for (x = 20 + a; x > 20 - a; x -= 0.25) print x;
             for (x = 20 - a; x < 20; x += 0.25) print x } }' > gx.txt
"$tool" sim --model plant.hyst --digits 17 gx.txt > gy.txt || fail "sim of the plant (growing)"
paste -d' ' gx.txt gy.txt > grow.txt
"$tool" fit --kind everett --degree 2 --t-degree 1 --delay 0 --creep none grow.txt > grow_fit.txt ||
    fail "fit of the growing record"
n=$(wc -l < grow.txt)
grep -q "run over the record, $n of $n samples used" grow_fit.txt ||
    fail "growing record: $(grep -o '[0-9]* of [0-9]* samples used' grow_fit.txt), not $n of $n"
plant_terms_within 1e-3 grow_fit.txt ||
    fail "terms of the growing record: $(head -1 grow_fit.txt)"

# ---- headers: compile in float and double, hold the saved numbers ----
"$tool" header --model m.hyst --dir . f0_hdr 2> /dev/null || fail "header --model"
for h in f0_asym f0_hdr; do
    grep -q "static const hyst_everett_t $h = {" $h.h || fail "$h.h: $(cat $h.h)"
    for t in $(val terms) $(val y_lo); do grep -q "HYST_REAL_C($t)" $h.h || fail "$h.h: number $t"; done
    t2=$(val terms | cut -d' ' -f2)
    printf '#include "%s.h"\nint main(void) { return %s.degree == 2u && %s.e[0][1] == HYST_REAL_C(%s) && %s.e[1][1] == 0 ? 0 : 1; }\n' \
        $h $h $h "$t2" $h > use_$h.c
    for def in "" "-DHYST_USE_DOUBLE"; do
        "$cc" -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror $def \
            -I. -I"$inc" use_$h.c -o use_$h || fail "$h.h does not compile ($def)"
        ./use_$h || fail "$h.h: degree or terms ($def)"
    done
done
grep -q '^ \* output follows its input 2 samples later' f0_hdr.h || fail "header --model: the delay comment"

# ---- inv: the compensator gives back the inputs of the model's outputs ----
"$tool" inv --model m.hyst --digits 17 lib.txt > inv.txt 2> inv_err.txt || fail "inv --model: $(cat inv_err.txt)"
grep -q 'delay of 2 samples is not compensated' inv_err.txt || fail "inv: the delay note: $(cat inv_err.txt)"
paste -d' ' inv.txt x.txt | awk -v lo="$(val lo)" -v hi="$(val hi)" '
    { d = $1 - $2; if (d < 0) d = -d; if (d > worst) worst = d; n++ }
    END { if (n == 0 || worst > 1e-9 * (hi - lo)) { print "worst", worst, "of", n; exit 1 } }' ||
    fail "inv --model does not give back the inputs"

# ---- a fit the library refuses: the output falls as the input rises ----
# clearly falling (correlation below -0.5, a sensor of the opposite sign): refused
# before fitting, nothing printed; falling less, with an uncorrelated ripple 5.5
# times the output's deviation (correlation about -0.3): fitted, then refused
awk '{ print $1, -$2 }' rec.txt > negated.txt
rc=0
"$tool" fit --kind everett --degree 1 negated.txt > neg.txt 2> neg_err.txt || rc=$?
[ "$rc" -eq 1 ] && [ ! -s neg.txt ] &&
    grep -qF 'negated.txt: the output (column 2) falls as the input (column 1) rises (correlation -0.9' neg_err.txt ||
    fail "a negated output: exit $rc, $(cat neg_err.txt)"
awk 'NR == FNR { s += $2; ss += $2 * $2; n++; next }
     FNR == 1 { a = 5.5 * sqrt(ss / n - (s / n) ^ 2) }
     { print $1, -$2 + a * (((FNR * 7919) % 101) - 50) / 50 }' rec.txt rec.txt > falling.txt
rc=0
"$tool" fit --kind everett --degree 1 --save fall.hyst --header f0_fall falling.txt > fall.txt 2> fall_err.txt || rc=$?
[ "$rc" -eq 2 ] || fail "refused E: exit $rc"
grep -q '^# E NOT accepted by the library: branch function E not increasing in a and decreasing in b' fall.txt ||
    fail "refused E: $(tail -1 fall.txt)"
grep -q 'the fitted E is refused by the library: .*; no header or model file written' fall_err.txt || fail "refused E: $(cat fall_err.txt)"
[ ! -e fall.hyst ] && [ ! -e f0_fall.h ] || fail "files written for a refused E"
# ---- major loops alone of a plant with E of degree 3, linear in t ----
# E = 3 w + w t + 2 w^2 - 0.5 w^2 t + 0.4 w^3 on [0, 40]: four major loops,
# the sensor 1 sample late, +-0.005 of noise
printf 'hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 0\ndegree 3\nterms 3 1 0 2 -0.5 0.4\n' > plant3.hyst
awk 'function ramp(a, b,   k, n) { n = int((b > a ? b - a : a - b) / 0.25 + 0.5);
                                 for (k = 1; k <= n; k++) printf "%.2f\n", a + (b - a) * k / n }
     BEGIN { print 0; for (c = 0; c < 4; c++) { ramp(0, 40); ramp(40, 0) } }' > x3.txt
"$tool" sim --model plant3.hyst --digits 17 x3.txt > y3.txt || fail "sim of the degree 3 plant"
awk 'NR == FNR { x[NR] = $1; n = NR; next } { y[FNR] = $1 }
     END { s = 4343; for (k = 2; k <= n; k++) {
               s = (s * 1103515245 + 12345) % 2147483648; e = (s / 2147483648 - 0.5) * 0.01;
               printf "%s %.9g\n", x[k], y[k - 1] + e } }' x3.txt y3.txt > rec3.txt
# E of full degree 3 is singular on major loops
rc=0
"$tool" fit --kind everett --degree 3 --delay 1 rec3.txt > full3.txt 2> full3_err.txt || rc=$?
[ "$rc" -eq 1 ] && grep -q 'everett degree 3 t-degree 2: the record.s turning points do not determine E of this degree' full3_err.txt ||
    fail "degree 3 in full on major loops: exit $rc, $(cat full3_err.txt)"
# chosen by hold-out: degree 3, t-degree 1, its terms recovered (w t^2 not fitted: 0)
"$tool" fit rec3.txt > fit3.txt || fail "fit of the degree 3 plant"
grep -q '^# chosen by hold-out: degree 3, delay 1 (kind everett, t-degree 1, 6 parameters' fit3.txt ||
    fail "degree 3 plant: $(grep chosen fit3.txt)"
grep -qx '# parameters 6' fit3.txt || fail "degree 3 plant: $(grep parameters fit3.txt)"
grep -q '^# candidate everett degree 3 t-degree 2 delay 1: not scored (the record.s turning points' fit3.txt ||
    fail "degree 3 plant, t-degree 2: $(grep 'degree 3 t-degree 2 delay 1' fit3.txt)"
check_terms3() {
    awk -F, 'NR == 1 { if (NF != 6 || $3 != 0) exit 1; split("3,1,0,2,-0.5,0.4", w, ",");
                       for (k = 1; k <= 6; k++) { d = $k - w[k]; if (d < 0) d = -d; if (d > 0.03) exit 1 } }' "$1"
}
check_terms3 fit3.txt || fail "degree 3 plant terms: $(head -1 fit3.txt)"
# the same with degree and t-degree given
"$tool" fit --kind everett --degree 3 --t-degree 1 --delay 1 rec3.txt > given3.txt || fail "--t-degree 1"
check_terms3 given3.txt && grep -qx '# parameters 6' given3.txt || fail "--degree 3 --t-degree 1: $(head -1 given3.txt)"
# --t-degree without --degree: that t-degree only, each degree above it
"$tool" fit --kind everett --t-degree 1 --delay 1 rec3.txt > only1.txt || fail "--t-degree 1 alone"
[ "$(grep -c '^# candidate' only1.txt)" -eq 3 ] && [ "$(grep -c '^# candidate everett degree [234] t-degree 1 delay 1' only1.txt)" -eq 3 ] ||
    fail "--t-degree 1 alone: $(grep '^# candidate' only1.txt)"

echo "everett: measured record $(grep '^# chosen' meas.txt | cut -d'(' -f1); plant terms $(head -1 fit.txt)"

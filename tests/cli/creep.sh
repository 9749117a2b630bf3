#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The creep term (hyst/creep.h, docs/creep.md) in `hyst`:
#  - a record made by sim from a model file with a known creep term (Eq. 20,
#    delay 3, one lag of 2000 samples, weight 0.05 um/V) plus noise: fit
#    chooses degree 3, delay 3 and the creep term, tau 2000, and recovers its
#    weight; --creep none and --creep TAU do as they say;
#  - the saved model: sim --model adds the weighted lag of the (delayed)
#    input to the hysteresis output (checked against a lag computed here),
#    inv --model gives back the inputs of sim's outputs, header --model holds
#    the creep term and compiles (float and double);
#  - model files with a broken creep term are refused, naming line and field;
#  - the measured record: the automatic choice has a creep term, by the rule
#    recomputed from the printed table over both options of every candidate
#    (without creep, and with it: one parameter more), and predicts the last
#    third at least twice as well as PI-10.
#   creep.sh <hyst> <C compiler> <include dir> <library sources dir> <work dir> <measured record>
set -euo pipefail
tool=$1 cc=$2 inc=$3 src=$4 work=$5 data=$6
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# ---- a plant with creep: Eq. 20 on 0..40 V, 30 triangles of 320 samples ----
cat > plant.hyst <<'EOF'
hyst-model-text 1
kind poly
lo 0
hi 40
delay 3
coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1
creep_tau 2000
creep_weight 0.05
EOF
awk 'BEGIN { for (c = 0; c < 30; c++) { for (x = 0; x < 40; x += 0.25) print x;
             for (x = 40; x > 0; x -= 0.25) print x } print 0 }' > x.txt
"$tool" sim --model plant.hyst x.txt > y.txt || fail "sim of the plant"
# +-0.01 um of deterministic noise (an LCG)
paste -d ' ' x.txt y.txt | awk '{ s = (NR == 1) ? 12345 : s; s = (s * 1103515245 + 12345) % 2147483648;
                                  printf "%s %.9g\n", $1, $2 + (s / 2147483648 - 0.5) * 0.02 }' > rec.txt
"$tool" fit --save m.hyst rec.txt > fit.txt || fail "fit: $(cat fit.txt)"
grep -q '^# chosen by hold-out: degree 3, delay 3 (kind poly, creep, 6 parameters' fit.txt ||
    fail "choice: $(grep chosen fit.txt)"
grep -qx '# parameters 6' fit.txt || fail "parameter count: $(grep parameters fit.txt)"
line=$(grep '^# creep: tau' fit.txt) || fail "no creep line: $(grep creep fit.txt)"
[[ $line =~ ^#\ creep:\ tau\ 2000\ samples,\ weight\ ([0-9.e-]+)\  ]] || fail "creep line: $line"
awk -v w="${BASH_REMATCH[1]}" 'BEGIN { exit !(w > 0.049 && w < 0.051) }' || fail "creep weight ${BASH_REMATCH[1]}"
grep -qx 'creep_tau 2000' m.hyst || fail "model file: $(grep creep m.hyst)"
grep -q '^creep_weight 0.0' m.hyst || fail "model file: $(grep creep m.hyst)"
grep -q ' (chosen, with creep)$' fit.txt || fail "chosen mark: $(grep chosen fit.txt)"
# --creep none: the hysteresis model alone; --creep TAU: that lag, always
"$tool" fit --creep none --save none.hyst rec.txt > none.txt || fail "--creep none"
! grep -q creep none.hyst || fail "--creep none wrote a creep term"
! grep -q '^# creep' none.txt || fail "--creep none: $(grep '^# creep' none.txt)"
grep -q '^# chosen by hold-out: degree [0-9], delay 3 (kind [a-z]*, [0-9]' none.txt ||
    fail "--creep none: $(grep chosen none.txt)"
"$tool" fit --creep 500 --degree 3 --delay 3 --save forced.hyst rec.txt > forced.txt || fail "--creep 500"
grep -qx 'creep_tau 500' forced.hyst || fail "--creep 500: $(grep creep forced.hyst)"
"$tool" fit --creep 0.5 rec.txt > bad.txt 2> bad_err.txt && fail "--creep 0.5 accepted"
grep -q "option --creep: '0.5' is not none, auto or a time constant" bad_err.txt || fail "--creep 0.5: $(cat bad_err.txt)"

# ---- sim --model: the hysteresis output plus w times the lag of the input ----
"$tool" sim --model m.hyst x.txt > sim.txt || fail "sim --model"
grep -v '^creep_' m.hyst > bare.hyst
"$tool" sim --model bare.hyst --digits 17 x.txt > bare.txt || fail "sim of the model without creep"
tau=$(awk '$1 == "creep_tau" { print $2 }' m.hyst)
w=$(awk '$1 == "creep_weight" { print $2 }' m.hyst)
# the model's delay: 3 samples and a fraction f of a sample (fit may choose
# one): its input is the drive interpolated, (1 - f) x[k] + f x[k - 1]
f=$(awk '$1 == "delay" { print $2 - 3 }' m.hyst)
awk -v f="$f" 'BEGIN { exit !(f >= 0 && f < 1) }' || fail "delay: $(grep delay m.hyst)"
awk -v f="$f" 'NR == 1 { p = $1 } { printf "%.17g\n", (1 - f) * $1 + f * p; p = $1 }' x.txt > u.txt
# the lag from lo = 0 at rest, of the model's input 3 samples back (the
# delay), its state before each sample
paste -d ' ' u.txt bare.txt sim.txt |
    awk -v tau="$tau" -v w="$w" '{ x[NR] = $1; h = $2; got = $3;
        c = (NR > 3) ? w * s : 0; if (NR > 3) s += (x[NR - 3] - s) / tau;
        d = got - (h + c); if (d < 0) d = -d; if (d > worst) worst = d }
        END { if (worst > 1e-6) { print "sim differs by " worst; exit 1 } }' ||
    fail "sim --model with creep"
# ---- inv --model: the drive of each desired output (the delay not compensated) ----
"$tool" inv --model m.hyst sim.txt > drive.txt 2> inv_err.txt || fail "inv --model: $(cat inv_err.txt)"
paste -d ' ' u.txt drive.txt |
    awk '{ x[NR] = $1; if (NR > 3) { d = $2 - x[NR - 3]; if (d < 0) d = -d; if (d > worst) worst = d } }
         END { if (worst > 1e-6 * 40) { print "inv misses by " worst; exit 1 } }' || fail "inv --model with creep"
grep -q 'clamped' inv_err.txt && fail "inv clamped sim's own outputs: $(cat inv_err.txt)"
# ---- header --model: the creep term for hyst_creep_init() ----
"$tool" header --model m.hyst plant_model > /dev/null || fail "header --model"
grep -q '^#define plant_model_CREEP_TERMS 1u$' plant_model.h || fail "header: $(grep CREEP plant_model.h)"
cat > use.c <<'EOF'
#include "plant_model.h"
#include "hyst/hyst.h"
int main(void)
{
    hyst_creep_t c;
    return hyst_creep_init(&c, plant_model_CREEP_TERMS, plant_model_creep_tau,
                           plant_model_creep_weight, plant_model.lo) != HYST_OK ||
           plant_model_creep_tau[0] != 2000;
}
EOF
for def in -DHYST_USE_DOUBLE -UHYST_USE_DOUBLE; do
    "$cc" -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror $def -I"$inc" -I. use.c \
        "$src"/*.c -lm -o use || fail "the header does not compile ($def)"
    ./use || fail "the header's creep term refused ($def)"
done

# ---- model files with a broken creep term ----
bad() { # name, the lines after coeffs, the message expected
    printf 'hyst-model-text 1\nkind poly\nlo 0\nhi 1\ncoeffs 1 0\n%b' "$2" > "$1.hyst"
    echo 0.5 | "$tool" sim --model "$1.hyst" > /dev/null 2> "$1.err" && fail "$1 accepted"
    grep -qF "$3" "$1.err" || fail "$1: $(cat "$1.err")"
}
bad tau_alone 'creep_tau 100\n' "tau_alone.hyst:6: field 1: creep_tau needs creep_weight too"
bad lengths 'creep_tau 100 1000\ncreep_weight 0.5\n' "lengths.hyst:7: field 3 is missing: creep_weight needs 2 numbers, one per creep_tau"
bad lengths_many 'creep_tau 100\ncreep_weight 0.5 0.1\n' "lengths_many.hyst:7: field 3: one too many: creep_weight needs 1 numbers"
bad short_tau 'creep_tau 0.5\ncreep_weight 0.5\n' "short_tau.hyst:6: field 2: '0.5' is not a time constant of at least 1 sample"
bad many 'creep_tau 1 2 3 4 5\ncreep_weight 1 1 1 1 1\n' "many.hyst:6: field 6: one too many: creep_tau needs 1 to 4 numbers"

# ---- the measured record ----
"$tool" fit --skip 350 --ycol 5 --compare-pi 10 "$data" > meas.txt || fail "fit on the measured record"
grep -q '^# chosen by hold-out: degree 4, delay 4 (kind everett, t-degree 1, creep, 10 parameters' meas.txt ||
    fail "choice on the measured record: $(grep chosen meas.txt)"
# the rule from the printed table: each candidate with p parameters (as in
# everett.sh) and its creep option with p + 2 (weight and time constant); the fewest within 1 % of the
# lowest, then the polynomial f0, then the lower error
awk '/^# candidate .*hold-out rms/ {
         ev = $3 == "everett"; gr = $3 == "everett_grid"; sp = $3 == "spline";
         d = ev || gr || sp ? $5 : $4; rms = ev ? $12 : gr || sp ? $10 : $9; sub(/,$/, "", rms);
         if (ev) { p = 1; for (i = 1; i <= d; i++) p += (d - i < $7 ? d - i : $7) + 1 }
         else if (gr) p = 1 + d * (d + 1) / 2 + d - 1; else if (sp) p = d + 3; else p = d + 1;
         if ((ev ? $9 : gr || sp ? $7 : $6) ~ /\./) p++;
         n++; P[n] = p; K[n] = ev || gr || sp; R[n] = rms + 0; C[n] = / \(chosen\)$/;
         if (match($0, /with creep tau [0-9.e+]+: [0-9.e+-]+/)) {
             split(substr($0, RSTART, RLENGTH), f, " "); n++; P[n] = p + 2; K[n] = ev || gr; R[n] = f[5] + 0;
             C[n] = /\(chosen, with creep\)$/ }
         if (best == "" || R[n - 1] < best) best = R[n - 1]; if (best == "" || R[n] < best) best = R[n] }
     END { for (i = 1; i <= n; i++) if (R[i] <= best * 1.01 && (w == "" || P[i] < P[w] ||
               (P[i] == P[w] && (K[i] < K[w] || (K[i] == K[w] && R[i] < R[w]))))) w = i;
           if (!C[w]) { print "rule picks option " w; exit 1 } }' meas.txt || fail "the chosen option is not the rule's"
line=$(grep '^# compare' meas.txt) || fail "no compare line"
[[ $line =~ with\ creep\ \(10\ parameters\)\ ([0-9.e-]+),\ PI\ 10\ operators\ \(11\ parameters\)\ ([0-9.e-]+)\;\ PI/TCM\ ([0-9.e-]+)$ ]] ||
    fail "compare line: $line"
awk -v r="${BASH_REMATCH[3]}" 'BEGIN { exit !(r >= 2) }' || fail "PI-10 / model ${BASH_REMATCH[3]} below 2"
echo "creep: measured record PI-10 / model ${BASH_REMATCH[3]}"

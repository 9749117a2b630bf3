#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst fit --kind pi`: a record made by `hyst pi` itself (known weights, one
# of them 0, and an offset) over minor loops gives those weights back, and the
# '# hyst pi' line it prints reproduces the record; a falling output gives
# w1 = 0 (exit 2); --compare-pi prints both hold-out scores.
#   pi_fit.sh <hyst> <work dir> <measured record>
set -euo pipefail
tool=$1 work=$2 data=$3
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
# |a_i - b_i| <= tol for the comma-separated lists a, b
close() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { n = split(a, p, ","); m = split(b, q, ",");
          if (n != m) exit 1; for (i = 1; i <= n; i++) { d = p[i] - q[i]; if (d < 0) d = -d;
          if (d > tol) exit 1 } }'; }

# minor loops inside 0..2 V: peaks 2, 1.5, 1.8, valleys 0, 0.6, 0.2, 0.01 V steps, twice
awk 'function ramp(a, b,   k, n) { n = int((b > a ? b - a : a - b) / 0.01 + 0.5);
                                 for (k = 1; k <= n; k++) printf "%.2f\n", a + (b - a) * k / n }
     BEGIN { print 0; for (c = 0; c < 2; c++) { ramp(0, 2); ramp(2, 0.6); ramp(0.6, 1.5);
             ramp(1.5, 0.2); ramp(0.2, 1.8); ramp(1.8, 0) } }' > x.txt
w=0.5,0,0.3,0.2 r=0,0.5,1,1.5
"$tool" pi --weights $w --thresholds $r --offset 3 x.txt > y.txt
paste -d' ' x.txt y.txt > rec.txt
"$tool" fit --kind pi --operators 4 rec.txt > fit.txt || fail "fit --kind pi: $(cat fit.txt)"
close "$(sed -n 1p fit.txt)" "$w" 1e-6 || fail "weights $(sed -n 1p fit.txt), made with $w"
[ "$(sed -n 2p fit.txt)" = "$r" ] || fail "thresholds $(sed -n 2p fit.txt), made with $r"
close "$(sed -n 3p fit.txt)" 3 1e-6 || fail "offset $(sed -n 3p fit.txt)"
grep -qx '# parameters 5 (4 weights and the offset; the thresholds are fixed)' fit.txt ||
    fail "parameter count: $(grep parameters fit.txt)"
grep -qx '# 1 of the 4 weights are 0' fit.txt || fail "zero weights: $(grep 'weights are' fit.txt)"
grep -q '^# hold-out rms ' fit.txt || fail "hold-out line"
# the printed options run the fitted model: the record again
read -r -a opts <<< "$(sed -n 's/^# hyst pi //p' fit.txt)"
"$tool" pi "${opts[@]}" x.txt > again.txt || fail "hyst pi with the printed options"
paste -d' ' y.txt again.txt | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1e-6) bad++ }
    END { exit bad > 0 }' || fail "the printed model does not reproduce the record"
# the output falls as the input rises: every weight 0, w1 = 0 refused by 'hyst pi'
# (a clearly falling one is refused before fitting: cli_fit_falling_pi); this
# one falls less, an uncorrelated ripple added (correlation about -0.3)
awk 'NR == FNR { s += $2; ss += $2 * $2; n++; next }
     FNR == 1 { a = 5.5 * sqrt(ss / n - (s / n) ^ 2) }
     { print $1, -$2 + a * (((FNR * 7919) % 101) - 50) / 50 }' rec.txt rec.txt > falling.txt
set +e
"$tool" fit --kind pi --operators 4 falling.txt > fall.txt 2> fall_err.txt
rc=$?
set -e
[ $rc -eq 2 ] || fail "w1 = 0: exit status $rc"
[ "$(sed -n 1p fall.txt)" = "0,0,0,0" ] || fail "falling output: weights $(sed -n 1p fall.txt)"
grep -q 'the fitted w1 is 0' fall_err.txt || fail "w1 = 0 message: $(cat fall_err.txt)"
# the comparison on the measured record: the same split, delay and skip for both
"$tool" fit --skip 350 --ycol 5 --degree 3 --delay 1 --creep none --compare-pi 10 "$data" > cmp.txt ||
    fail "--compare-pi"
line=$(grep '^# compare' cmp.txt) || fail "no compare line"
[[ $line =~ delay\ 1\):\ hold-out\ rms\ TCM\ degree\ 3\ \(4\ parameters\)\ ([0-9.e-]+),\ PI\ 10\ operators\ \(11\ parameters\)\ ([0-9.e-]+)\;\ PI/TCM\ ([0-9.e-]+)$ ]] ||
    fail "compare line: $line"
# the PI figure is what --kind pi reports as its hold-out on the same options
"$tool" fit --kind pi --operators 10 --skip 350 --ycol 5 --delay 1 "$data" > pi10.txt ||
    fail "fit --kind pi on the measured record"
grep -qx "# hold-out rms ${BASH_REMATCH[2]} (fitted on the first two thirds, predicting the last third)" pi10.txt ||
    fail "PI-10 hold-out differs: $(grep hold-out pi10.txt) vs ${BASH_REMATCH[2]}"
echo "pi_fit: weights $(sed -n 1p fit.txt) recovered; measured record: $line"

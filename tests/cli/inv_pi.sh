#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst inv` and `hyst pi` against things known independently of them:
#  - inv undoes sim: sim of an input sequence, then inv of its outputs, gives
#    the inputs back (relative 1e-6), on smooth nested loops and random jumps;
#  - unreachable targets: clamped, warned with count and first line, exit 0;
#  - pi equals hand-computed values of Eq. 15 (docs/theory.md, the PI section)
#    for two operators, and the closed-form branches for the paper's Table 1
#    model;
#  - 6000 nested turning points are all kept (the engine's memory grows).
#   inv_pi.sh <hyst> <work dir>
set -euo pipefail
tool=$1 work=$2
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
poly="-6.1876e-6,1.1949e-3,8.6444e-2,5.8517e-1" # paper Eq. 20, increasing on [0, 40]

# ---- (1) sim -> inv round trip, from lo (where both start) ----
# nested loops shrinking and growing in [2, 40], then Park-Miller random jumps in it
awk 'BEGIN { for (k = 0; k < 3000; k++)
               printf "%.9g\n", 2 + 38 * (1 - cos(0.05 * k)) / 2 * (0.6 + 0.4 * cos(0.0131 * k));
             s = 1; for (k = 0; k < 2000; k++) { s = (s * 16807) % 2147483647;
               printf "%.9g\n", 2 + 38 * s / 2147483647 } }' > x.txt
[ "$(head -1 x.txt)" = 2 ] || fail "sequence must start at lo"
"$tool" sim --poly "$poly" --range 2,40 x.txt > y.txt
"$tool" inv --poly "$poly" --range 2,40 y.txt > xi.txt 2> inv_err.txt
[ ! -s inv_err.txt ] || fail "inv warned on reachable targets: $(cat inv_err.txt)"
[ "$(wc -l < xi.txt)" -eq 5000 ] || fail "inv: one input per desired output"
paste x.txt xi.txt | awk '{ e = ($2 - $1) / $1; if (e < 0) e = -e; if (e > m) { m = e; at = NR } }
    END { printf "max relative error %.3g at line %d\n", m, at; exit !(m <= 1e-6) }' > rt.txt ||
    fail "inv(sim(x)) != x: $(cat rt.txt)"
# and sim undoes inv: the drive found for each target reproduces it
"$tool" sim --poly "$poly" --range 2,40 xi.txt > yi.txt
paste y.txt yi.txt | awk '{ e = ($2 - $1) / $1; if (e < 0) e = -e; if (e > m) m = e }
    END { printf "%.3g", m; exit !(m <= 1e-6) }' > rt2.txt || fail "sim(inv(y)) != y: $(cat rt2.txt)"
# the same through standard input, second column, --tp
paste -d';' x.txt y.txt | "$tool" inv --poly "$poly" --range 2,40 --xcol 2 --tp - > xt.txt
cmp -s <(cut -d, -f1 xt.txt) xi.txt || fail "inv from stdin --xcol 2 differs"
grep -qvE '^[0-9.e+-]+,[0-9]+$' xt.txt && fail "inv --tp: lines are x,tp"

# ---- (2) unreachable targets: f0(2) = 0.762788099, f0(40) = 5.5587636 ----
# 0.762788099 is f0(2) rounded to 9 digits (as sim prints it): not warned;
# 0.76278 is 1e-5 below it: warned.
printf '# targets\n1\n9\n3\n0.1\n0.762788099\n0.76278\n' > far.txt
"$tool" inv --poly "$poly" --range 2,40 far.txt > far_x.txt 2> far_err.txt ||
    fail "inv: clamping must keep exit status 0"
grep -q '^hyst inv: warning: far.txt: 3 desired outputs outside \[0.762788099, 5.5587636\] were clamped to it (first at line 3)$' far_err.txt ||
    fail "inv clamp warning: $(cat far_err.txt)"
[ "$(sed -n 2p far_x.txt)" = 40 ] || fail "target above f0(hi) must give hi: $(sed -n 2p far_x.txt)"
[ "$(sed -n 4p far_x.txt)" = 2 ] || fail "target below f0(lo) must give lo: $(sed -n 4p far_x.txt)"
[ "$(sed -n 5,6p far_x.txt | tr '\n' ' ')" = "2 2 " ] || fail "targets at f0(lo): $(sed -n 5,6p far_x.txt)"
printf '2\n41\n1\n' | "$tool" sim --poly "$poly" --range 2,40 > /dev/null 2> sim_err.txt ||
    fail "sim: clamping must keep exit status 0"
grep -q '^hyst sim: warning: <stdin>: 2 inputs outside \[2, 40\] were clamped to it (first at line 2)$' sim_err.txt ||
    fail "sim clamp warning: $(cat sim_err.txt)"

# ---- (3) pi, two operators r = 0, 1: Eq. 15 by hand ----
# x:      2     0.5    1.5    3     -1     0
# z1:     2     0.5    1.5    3     -1     0      (r1 = 0: z1 = x)
# z2:     1     0.5    0.5    2     -1    -1      max(x - 1, min(x, z2))
# w 1,.5: 2.5   0.75   1.75   4     -1.5  -0.5
# w 1,-.5:1.5   0.25   1.25   2     -0.5   0.5
printf '2\n0.5\n1.5\n3\n-1\n0\n' > p.txt
[ "$("$tool" pi --weights 1,0.5 --thresholds 0,1 p.txt | tr '\n' ' ')" = "2.5 0.75 1.75 4 -1.5 -0.5 " ] ||
    fail "pi 2 operators: $("$tool" pi --weights 1,0.5 --thresholds 0,1 p.txt | tr '\n' ' ')"
awk '{ print "7, " $0 }' p.txt | "$tool" pi --weights=1,-0.5 --thresholds=0,1 --xcol 2 > pn.txt
[ "$(tr '\n' ' ' < pn.txt)" = "1.5 0.25 1.25 2 -0.5 0.5 " ] || fail "pi negative weight: $(tr '\n' ' ' < pn.txt)"

# ---- (4) pi, paper Table 1: ramp 0 -> 1 -> 0 -> 1 ----
# Rising from rest, z_i = max(0, x - r_i): y = f_PI(x) = sum w_i max(0, x - r_i).
# Falling from x = 1, z_i = min(x, 1 - r_i): y = f_PI(1) - f_PI(1 - x). At x = 0
# every z_i is 0 again, so the second rise is f_PI(x) once more.
w="0.0789,0.2268,0.1928,0.2019,0.1995,0.2001,0.2000,0.2000,0.1999,0.2005"
r="0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9"
awk 'BEGIN { for (i = 0; i <= 100; i++) print i / 100; for (i = 99; i >= 0; i--) print i / 100;
             for (i = 1; i <= 100; i++) print i / 100 }' > ramp.txt
"$tool" pi --weights "$w" --thresholds "$r" ramp.txt > pi.txt
paste ramp.txt pi.txt | awk -v w="$w" -v r="$r" '
    function f(x,   i, s) { s = 0; for (i = 1; i <= n; i++) if (x > R[i]) s += W[i] * (x - R[i]); return s }
    BEGIN { n = split(w, W, ","); split(r, R, ",") }
    { want = (NR > 101 && NR <= 201) ? f(1) - f(1 - $1) : f($1); e = $2 - want; if (e < 0) e = -e;
      if (e > m) { m = e; at = NR } }
    END { printf "max abs error %.3g at line %d (%d lines)\n", m, at, NR; exit !(m <= 1e-8 && NR == 301) }' > pi_err.txt ||
    fail "pi Table 1: $(cat pi_err.txt)"
# ---- (5) deep nesting: every sample a turning point inside the last ----
# 0, then 6000 reversals of shrinking amplitude around 20: the stored turning
# points grow by one per sample (the engine's memory must grow with them, never
# merge loops), and inv still undoes sim exactly.
awk 'BEGIN { n = 6000; print 0; for (k = 1; k <= n; k++) printf "%.9g\n", 20 + 20 * (k % 2 ? 1 : -1) * (1 - k / (n + 1)) }' > deep.txt
"$tool" sim --poly "$poly" --range 0,40 --tp deep.txt > deep_y.txt
awk -F, 'NR > 2 && $2 != NR - 2 { print "line " NR ": tp " $2; bad = 1; exit } END { exit bad }' deep_y.txt ||
    fail "sim --tp on nested reversals: $(tail -1 deep_y.txt)"
cut -d, -f1 deep_y.txt | "$tool" inv --poly "$poly" --range 0,40 --tp > deep_x.txt
[ "$(tail -1 deep_x.txt | cut -d, -f2)" = 5999 ] || fail "inv --tp on nested reversals: $(tail -1 deep_x.txt)"
paste -d, deep.txt deep_x.txt | awk -F, '{ e = $2 - $1; if (e < 0) e = -e; if (e > m) m = e }
    END { exit !(m <= 1e-6) }' || fail "inv(sim(x)) != x on nested reversals"

echo "inv round trip: $(cat rt.txt), sim(inv(y)) max relative error $(cat rt2.txt); pi Table 1: $(cat pi_err.txt)"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# What `hyst fit` does for records unlike its first one:
#  - a delay scaled to the drive: a plant (Eq. 20, delay 20 samples) driven
#    by triangles of 4000 samples: the delays searched reach about 1/64 of
#    the period (over 40), past the 0..8 of a fast drive, and fit chooses 20;
#  - a sub-sample delay: the same plant 20.5 samples late (a model file's
#    fractional delay: sim runs the drive interpolated half a sample, checked
#    here against sim of that drive at delay 20), driven by a sine: fit
#    chooses 20.5 and writes it to the model file, also with --degree; the
#    model at the fraction chosen by the whole delays' rule (the plant's
#    kind, the symmetric one, between models of as many parameters);
#  - inputs beyond the range fitted: an asymmetric plant driven by triangles
#    of growing amplitude, whose last third goes past the first two thirds'
#    peaks: fit counts the hold-out inputs outside the range fitted, the
#    model file records the range it was identified on (key identified), and
#    sim --model says how many inputs left it (the count computed here) and
#    predicts them instead of clamping them (outputs beyond its value at the
#    range's end);
#  - the same for the symmetric kinds (a polynomial f0 plant, the same
#    drive): f0 a polynomial (--kind tcm) and a spline (--kind spline) are
#    widened too, their branches continued beyond the range fitted;
#  - the choice's report: the runner-up (another model) and PI-10 on the same
#    split, the ratio as printed; a warning when the last third holds no
#    minor loop (major loops only) or spans under half the inputs' range, none
#    when it has both;
#  - f0 of a given degree fitted on a drive with minor loops: a warning (the
#    joint estimator takes every sample for a major branch's), none on major
#    loops only, for --kind everett or without --degree;
#  - a model file with an identified range outside its domain is refused.
#   fidelity.sh <hyst> <work dir>
set -euo pipefail
tool=$1 work=$2
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# ---- delay search scaled to the drive's period ----
cat > plant.hyst <<'MODEL'
hyst-model-text 1
kind poly
lo 0
hi 40
delay 20
coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1
MODEL
awk 'BEGIN { for (c = 0; c < 8; c++) { for (k = 0; k < 2000; k++) print k * 0.02;
             for (k = 2000; k > 0; k--) print k * 0.02 } print 0 }' > x.txt
"$tool" sim --model plant.hyst x.txt > y.txt || fail "sim of the plant"
paste -d ' ' x.txt y.txt | awk '{ s = (NR == 1) ? 4242 : s; s = (s * 1103515245 + 12345) % 2147483648;
                                  printf "%s %.9g\n", $1, $2 + (s / 2147483648 - 0.5) * 0.004 }' > rec.txt
"$tool" fit --creep none rec.txt > fit.txt 2> fit_err.txt || fail "fit: $(cat fit.txt)"
searched=$(sed -n 's/^# delays searched 0\.\.\([0-9]*\) .*/\1/p' fit.txt)
[ "${searched:-0}" -ge 40 ] || fail "delays searched: $(grep '^# delays' fit.txt)"
grep -qx '# delay 20 samples' fit.txt || fail "delay: $(grep '^# delay' fit.txt)"

# ---- a sub-sample delay ----
sed 's/^delay 20$/delay 20.5/' plant.hyst > half.hyst
"$tool" sim --model half.hyst --digits 17 x.txt > yh.txt || fail "sim of a fractional delay"
awk 'NR == 1 { p = $1 } { print 0.5 * $1 + 0.5 * p; p = $1 }' x.txt > xh.txt
"$tool" sim --model plant.hyst --digits 17 xh.txt > yh_ref.txt || fail "sim of the interpolated drive"
paste -d ' ' yh.txt yh_ref.txt | awk '{ d = $1 - $2; if (d > 1e-12 || d < -1e-12) { print "line " NR ": " $0; exit 1 } }' ||
    fail "delay 20.5 is not the drive interpolated half a sample at delay 20"
# a sine drive (a delay on a triangle's constant slope looks like a loop's
# width, which the models take), 0.0002 um of noise
awk 'BEGIN { for (k = 0; k <= 32000; k++) printf "%.9g\n", 20 - 20 * cos(2 * 3.141592653589793 * k / 4000) }' > xs.txt
"$tool" sim --model half.hyst xs.txt | paste -d ' ' xs.txt - |
    awk '{ s = (NR == 1) ? 4242 : s; s = (s * 1103515245 + 12345) % 2147483648;
           printf "%s %.9g\n", $1, $2 + (s / 2147483648 - 0.5) * 0.0004 }' > rech.txt
"$tool" fit --creep none --save mh.hyst rech.txt > fith.txt || fail "fit: $(cat fith.txt)"
grep -q '^# delay 20.5 samples (sub-sample' fith.txt || fail "sub-sample delay: $(grep '^# delay' fith.txt)"
grep -qx 'delay 20.5' mh.hyst || fail "model file: $(grep delay mh.hyst)"
# chosen at the fraction by the whole delays' rule: between as many
# parameters (f0 of degree 3 and E of degree 3, t-degree 0, the same model in
# two bases) the symmetric kind, whose compensator is a table
grep -qx 'kind poly' mh.hyst || fail "the kind at 20.5: $(grep '(chosen)' fith.txt)"
# with --degree too (no --delay): the delay chosen for that model
"$tool" fit --degree 3 --creep none rech.txt > fitd.txt 2> fitd_err.txt || fail "fit --degree: $(cat fitd.txt)"
grep -q '^# delay 20.5 samples (sub-sample' fitd.txt || fail "--degree 3: $(grep '^# delay' fitd.txt)"

# ---- the choice's report ----
chosen=$(grep '(chosen)$' fit.txt | sed 's/^# candidate \(.*\) delay \([0-9]*\): hold-out rms \([^,]*\),.*/\1|\2|\3/')
runner=$(grep '^# runner-up: ' fit.txt) || fail "no runner-up line"
[[ $runner =~ ^#\ runner-up:\ (.*)\ delay\ ([0-9]+)\ \(([0-9]+)\ parameters\):\ hold-out\ rms\ ([0-9.e-]+),\ the\ chosen\ ([0-9.e-]+)$ ]] ||
    fail "runner-up line: $runner"
[ "${BASH_REMATCH[1]}" != "${chosen%%|*}" ] || fail "the runner-up is the chosen model: $runner"
[ "${BASH_REMATCH[5]}" = "${chosen##*|}" ] || fail "runner-up line's chosen figure: $runner ($chosen)"
# the runner-up is the best of the other models in the candidate table
best_other=$(awk -v c="${chosen%%|*}" '/^# candidate .*hold-out rms/ {
        name = $0; sub(/^# candidate /, "", name); sub(/ delay [0-9]+:.*/, "", name);
        r = $0; sub(/.*hold-out rms /, "", r); sub(/,.*/, "", r);
        if (name != c && (b == "" || r + 0 < b + 0)) b = r } END { print b }' fit.txt)
[ "$best_other" = "${BASH_REMATCH[4]}" ] || fail "runner-up $runner, best other $best_other"
pi=$(grep '^# PI-10 on the same split' fit.txt) || fail "no PI-10 line"
[[ $pi =~ hold-out\ rms\ ([0-9.e-]+),\ the\ chosen\ ([0-9.e-]+)\;\ PI-10\ /\ chosen\ ([0-9.e-]+)$ ]] ||
    fail "PI-10 line: $pi"
awk -v p="${BASH_REMATCH[1]}" -v c="${BASH_REMATCH[2]}" -v q="${BASH_REMATCH[3]}" \
    'BEGIN { exit !(q > 0 && (p / c) / q > 0.995 && (p / c) / q < 1.005) }' || fail "PI-10 ratio: $pi"
grep -q 'warning: rec.txt: the last third holds no minor loop' fit_err.txt ||
    fail "no warning of major loops only: $(cat fit_err.txt)"
# the last third in a corner of the range: triangles 0..40, then 10..16
awk 'BEGIN { for (c = 0; c < 4; c++) { for (x = 0; x < 40; x += 0.25) print x; for (x = 40; x > 0; x -= 0.25) print x }
             for (c = 0; c < 30; c++) { for (x = 10; x < 16; x += 0.25) print x; for (x = 16; x > 10; x -= 0.25) print x } print 10 }' > xc.txt
"$tool" sim --model plant.hyst xc.txt | paste -d ' ' xc.txt - > recc.txt
"$tool" fit --creep none recc.txt > /dev/null 2> corner_err.txt || fail "fit of the corner record"
grep -q 'warning: recc.txt: the last third.s inputs span 1[45][.0-9]* % of the record.s range' corner_err.txt ||
    fail "no warning of a narrow last third: $(cat corner_err.txt)"

# ---- f0 of a given degree on minor loops ----
# recc.txt's drive reverses inside its range 59 times (30 peaks at 15.75 V, 29
# valleys at 10 V); rech.txt's (a sine 0..40) never
"$tool" fit --degree 2 --delay 0 --creep none recc.txt > /dev/null 2> minor_err.txt || fail "fit --degree 2 of the corner record"
grep -q '^hyst fit: warning: recc.txt: the drive has 59 reversals inside its range (minor loops): f0 of --degree 2 is biased,.* leave out --degree to let fit choose, or fit --method branches (f0 along every branch)$' minor_err.txt ||
    fail "no warning of f0 fitted on minor loops: $(cat minor_err.txt)"
! grep -q 'minor loops): f0' fitd_err.txt || fail "warned of minor loops on major loops only: $(cat fitd_err.txt)"
# the degree chosen among f0 alone (--kind tcm) is as biased
"$tool" fit --kind tcm --creep none recc.txt > /dev/null 2> minor_tcm_err.txt || fail "fit --kind tcm of the corner record"
grep -q '^hyst fit: warning: recc.txt: the drive has 59 reversals inside its range (minor loops): f0 of every degree is biased,.* leave out --kind tcm to let fit compare E too, or fit --method branches (f0 along every branch)$' minor_tcm_err.txt ||
    fail "no warning of f0 chosen on minor loops: $(cat minor_tcm_err.txt)"
"$tool" fit --kind tcm --creep none rech.txt > /dev/null 2> major_tcm_err.txt || fail "fit --kind tcm of the sine record"
! grep -q 'minor loops): f0' major_tcm_err.txt || fail "warned of minor loops on major loops only: $(cat major_tcm_err.txt)"
"$tool" fit --kind everett --degree 2 --delay 0 --creep none recc.txt > /dev/null 2> minor_ev_err.txt || fail "fit --kind everett of the corner record"
! grep -q 'minor loops): f0' minor_ev_err.txt corner_err.txt || fail "warned of f0 on minor loops for another kind or the choice"

# ---- inputs beyond the range fitted ----
cat > asym.hyst <<'MODEL'
hyst-model-text 1
kind everett
lo 0
hi 40
y_lo 0
delay 1
degree 2
terms 3 -0.5 1
MODEL
# triangles from 0 to 8, 12, ..., 40 V, 0.1 V a sample
awk 'BEGIN { for (p = 8; p <= 40; p += 4) { for (x = 0; x < p; x += 0.1) print x;
             for (x = p; x > 0; x -= 0.1) print x } print 0 }' > xg.txt
"$tool" sim --model asym.hyst xg.txt > yg.txt || fail "sim of the asymmetric plant"
paste -d ' ' xg.txt yg.txt > recg.txt
n=$(wc -l < recg.txt)
head -n $((2 * n / 3)) recg.txt > train.txt
"$tool" fit --creep none --save m.hyst train.txt > fitg.txt || fail "fit: $(cat fitg.txt)"
# the whole record's last third: reversals at 32 and 36 V inside 0..40, the whole range
"$tool" fit --creep none recg.txt > /dev/null 2> whole_err.txt || fail "fit of the whole record"
! grep -q 'warning' whole_err.txt || fail "warned of a last third with minor loops and range: $(cat whole_err.txt)"
grep -q '^# hold-out: [1-9][0-9]* of its [0-9]* inputs outside \[' fitg.txt ||
    fail "hold-out count: $(grep '^# hold-out' fitg.txt)"
read -r id_lo id_hi < <(awk '$1 == "identified" { print $2, $3 }' m.hyst)
[ -n "${id_hi:-}" ] || fail "no identified range in the model file: $(cat m.hyst)"
lo=$(awk '$1 == "lo" { print $2 }' m.hyst)
hi=$(awk '$1 == "hi" { print $2 }' m.hyst)
awk -v a="$id_hi" -v b="$hi" -v c="$lo" -v d="$id_lo" 'BEGIN { exit !(b > a && c <= d) }' ||
    fail "domain [$lo, $hi] does not extend the identified [$id_lo, $id_hi]"
beyond=$(awk -v h="$id_hi" -v l="$id_lo" '$1 > h + 0 || $1 < l + 0 { c++ } END { print c + 0 }' xg.txt)
[ "$beyond" -gt 0 ] || fail "the test record never leaves the range fitted"
"$tool" sim --model m.hyst xg.txt > pred.txt 2> sim_err.txt || fail "sim --model: $(cat sim_err.txt)"
grep -q "note: xg.txt: $beyond of $n inputs outside \[" sim_err.txt || fail "sim note ($beyond): $(cat sim_err.txt)"
! grep -q 'clamped' sim_err.txt || fail "inputs clamped: $(cat sim_err.txt)"
# predicted past the range: the largest output exceeds the model's output at
# the range's end, and tracks the plant's (within 2 % of its range)
paste -d ' ' yg.txt pred.txt | awk '{ e = $1 - $2; s += e * e; if ($1 > m) m = $1; if ($1 < l) l = $1 }
    END { exit !(sqrt(s / NR) < 0.02 * (m - l)) }' || fail "prediction beyond the range fitted"

# the symmetric kinds, widened as E is: a polynomial f0 plant on the same drive
cat > sym.hyst <<'MODEL'
hyst-model-text 1
kind poly
lo 0
hi 40
delay 1
coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1
MODEL
"$tool" sim --model sym.hyst xg.txt > ys.txt || fail "sim of the symmetric plant"
paste -d ' ' xg.txt ys.txt > recs.txt
head -n $((2 * n / 3)) recs.txt > train_sym.txt
# the error bound of each: 2 % of the range for f0 by the joint estimator
# (biased by the minor loops, as fit warns), 0.5 % for the spline (2.9 %
# when it clamped the inputs beyond the range fitted)
for kind in tcm:0.02 spline:0.005; do
    k=${kind%%:*} bound=${kind#*:}
    "$tool" fit --kind "$k" --creep none --save "m_$k.hyst" train_sym.txt > "fit_$k.txt" 2> /dev/null ||
        fail "fit --kind $k: $(cat "fit_$k.txt")"
    grep -q "^# hold-out: [1-9][0-9]* of its [0-9]* inputs outside \[.*poly, everett and spline widened" "fit_$k.txt" ||
        fail "--kind $k hold-out count: $(grep '^# hold-out' "fit_$k.txt")"
    read -r id_lo id_hi < <(awk '$1 == "identified" { print $2, $3 }' "m_$k.hyst")
    [ -n "${id_hi:-}" ] || fail "--kind $k: no identified range in the model file: $(cat "m_$k.hyst")"
    hi=$(awk '$1 == "hi" { print $2 }' "m_$k.hyst")
    awk -v a="$id_hi" -v b="$hi" 'BEGIN { exit !(b > a) }' ||
        fail "--kind $k: domain up to $hi does not extend the identified [$id_lo, $id_hi]"
    "$tool" sim --model "m_$k.hyst" xg.txt > "pred_$k.txt" 2> "sim_$k.txt" || fail "sim --model m_$k.hyst"
    grep -q 'predicted by its branches continued beyond it' "sim_$k.txt" || fail "--kind $k sim note: $(cat "sim_$k.txt")"
    ! grep -q 'clamped' "sim_$k.txt" || fail "--kind $k: inputs clamped: $(cat "sim_$k.txt")"
    paste -d ' ' ys.txt "pred_$k.txt" | awk -v b="$bound" '{ e = $1 - $2; s += e * e; if ($1 > m) m = $1;
        if (NR == 1 || $1 < l) l = $1 } END { exit !(sqrt(s / NR) < b * (m - l)) }' ||
        fail "--kind $k: prediction beyond the range fitted above $bound of the range"
done

# ---- a model file whose identified range is not within its domain ----
sed 's/^identified .*/identified -1000 50/' m.hyst > bad.hyst
"$tool" sim --model bad.hyst xg.txt > /dev/null 2> bad_err.txt && fail "identified outside the domain accepted"
grep -q 'identified -1000 50 is not a range within \[lo, hi\]' bad_err.txt || fail "refusal: $(cat bad_err.txt)"
echo "fidelity: ok"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst fit --validate OTHER`: the choice scored on a second record of the
# same plant instead of the hold-out splits of the first.
# 1. A plant outside every kind fit chooses among (a Prandtl-Ishlinskii
#    model of 6 operators) behind a dead time of 1 sample, driven by
#    reversal curves at 0.1 and at 1 V per sample: on the slow record alone
#    the hold-out of the asymmetric kind (--kind everett) takes a longer
#    delay, one that imitates the loop's shape at that rate; scored on the
#    fast record, the choice is the dead time, and its model predicts the
#    fast record better. (Among every kind, a spline follows the operators'
#    corners and the hold-out alone takes the dead time.) The validation RMS
#    printed is the error of the model saved, run by `hyst sim --model`,
#    with a creep or a rate term too.
# 2. A plant of the kinds compared (f0 of degree 3, which the everett kind
#    of t-degree 0 holds, 3 samples late): the degree and the delay found on
#    a record at another speed; with --degree, the delay.
# 3. --skip drops the rows of both records.
# 4. A missing, empty, one-column, constant, falling or one-row OTHER, both
#    records on standard input, --compare-pi and --kind pi: refused, nothing
#    printed or written.
#   validate.sh <hyst> <work dir>
set -euo pipefail
tool=$1 work=$2
mkdir -p "$work"
cd "$work"
rm -f ./*.hyst
fail() { echo "FAIL: $*" >&2; exit 1; }

# reversal curves from 40 V down to 32, 24, 16, 8 and back, twice, at s V per sample
drive() {
    awk -v s="$1" 'function go(a, b) { if (a < b) for (x = a; x < b; x += s) print x;
                                       else for (x = a; x > b; x -= s) print x }
        BEGIN { for (r = 0; r < 2; r++) { go(0, 40); for (t = 32; t >= 4; t -= 8) { go(40, t); go(t, 40) }
                go(40, 0) } print 0 }'
}
# line k: x[k] and the output of x[k - d] with +-0.01 of deterministic noise (an LCG)
record() { # <drive> <outputs> <d>
    awk -v d="$3" 'NR == FNR { x[NR] = $1; n = NR; next } { y[FNR] = $1 }
        END { for (k = d + 1; k <= n; k++) { s = (k * 1103515245 + 12345) % 2147483648;
                  printf "%s %.9g\n", x[k], y[k - d] + (s / 2147483648 - 0.5) * 0.02 } }' "$1" "$2"
}
# the RMS of the model file's run by sim over a record against its outputs,
# the first `delay` rows (the model's rest output) left out as fit leaves them
sim_rms() { # <model> <record>
    awk '{ print $1 }' "$2" > sim_x.txt
    "$tool" sim --model "$1" sim_x.txt > sim_y.txt
    local d
    d=$(sed -n 's/^delay \([0-9]*\).*/\1/p' "$1")
    paste -d ' ' sim_y.txt "$2" | awk -v d="${d:-0}" 'NR > d { e = $1 - $3; s += e * e; n++ }
        END { printf "%.6g\n", sqrt(s / n) }'
}

# ---- 1. the dead time of a plant outside the kinds ----
drive 0.1 > slow_x.txt
drive 1 > fast_x.txt
for r in slow fast; do
    "$tool" pi --weights 1,1,1,0.5,0.2,0.1 --thresholds 0,2,5,9,14,20 ${r}_x.txt > ${r}_pi.txt
    record ${r}_x.txt ${r}_pi.txt 1 > $r.txt
done
"$tool" fit --creep none --save every.hyst slow.txt > every.txt 2> /dev/null || fail "fit, every kind"
grep -qx 'delay 1' every.hyst || fail "every kind, the hold-out alone: $(grep chosen every.txt)"
"$tool" fit --kind everett --creep none --save alone.hyst slow.txt > alone.txt 2> /dev/null ||
    fail "fit alone"
grep -q '^# chosen by hold-out: ' alone.txt || fail "the hold-out line: $(grep chosen alone.txt)"
alone_delay=$(sed -n 's/^delay //p' alone.hyst)
[ "$alone_delay" != 1 ] || fail "the hold-out alone took the dead time: the case tests nothing"
"$tool" fit --kind everett --creep none --validate fast.txt --save validated.hyst slow.txt \
    > validated.txt 2> /dev/null || fail "fit --validate: $(cat validated.txt)"
grep -q '^# chosen on fast.txt: degree [0-9]*, delay 1 (kind .*: validation rms [0-9.e-]*$' \
    validated.txt || fail "the choice: $(grep chosen validated.txt)"
grep -qx 'delay 1' validated.hyst || fail "the model file's delay: $(grep delay validated.hyst)"
grep -q '^# chosen by hold-out' validated.txt && fail "a hold-out line with --validate"
grep -q '^# validation: 0 of its [0-9]* inputs outside \[0, 40\], the range of the record fitted$' \
    validated.txt || fail "the validation line: $(grep '^# validation' validated.txt)"
grep -q '^# validation excitation: its inputs span 100 % of the record.s range, [1-9][0-9]* reversals' \
    validated.txt || fail "the excitation line"
grep -q '^# candidate .*: validation rms .*(chosen)$' validated.txt || fail "the candidates' lines"
grep -q 'hold-out' validated.txt && fail "hold-out named with --validate: $(grep hold-out validated.txt)"
grep -q '^# PI-10' validated.txt && fail "PI-10's last third against a choice on another record"
printed=$(sed -n 's/^# chosen on .*validation rms \([0-9.e-]*\)$/\1/p' validated.txt)
[ "$(sim_rms validated.hyst fast.txt)" = "$printed" ] ||
    fail "validation rms $printed is not sim's $(sim_rms validated.hyst fast.txt)"
awk -v a="$(sim_rms alone.hyst fast.txt)" -v b="$printed" 'BEGIN { exit !(b < a) }' ||
    fail "the validated model predicts the fast record no better: $printed, alone $(sim_rms alone.hyst fast.txt)"
# a creep or a rate term given: fitted on the slow record, scored on the fast
# one with the model, and the score the model file's error there
for term in "--creep 500:creep_tau 500" "--creep none --rate 1:rate_tau 1"; do
    "$tool" fit ${term%:*} --validate fast.txt --save terms.hyst slow.txt > terms.txt 2> /dev/null ||
        fail "fit ${term%:*} --validate"
    grep -qx "${term#*:}" terms.hyst || fail "${term%:*}: no ${term#*:} in the model file"
    printed=$(sed -n 's/^# chosen on .*validation rms \([0-9.e-]*\)$/\1/p' terms.txt)
    [ "$(sim_rms terms.hyst fast.txt)" = "$printed" ] ||
        fail "$term: validation rms $printed is not sim's $(sim_rms terms.hyst fast.txt)"
done
# with the creep option compared too (the default), the same dead time
"$tool" fit --validate fast.txt slow.txt > validated_creep.txt 2> /dev/null || fail "--creep auto"
grep -q '^# delay 1 samples$' validated_creep.txt || fail "creep auto: $(grep '^# delay' validated_creep.txt)"

# ---- 2. a plant of the kinds compared, 3 samples late ----
cat > plant.txt << 'EOF'
hyst-model-text 1
kind poly
lo 0
hi 40
delay 3
coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1
EOF
drive 0.25 > a_x.txt
drive 0.5 > b_x.txt
for r in a b; do
    "$tool" sim --model plant.txt ${r}_x.txt > ${r}_y.txt
    record ${r}_x.txt ${r}_y.txt 0 > $r.txt
done
"$tool" fit --validate b.txt a.txt > same.txt 2> /dev/null || fail "fit --validate (same plant)"
grep -q '^# chosen on b.txt: degree 3, delay 3 (kind everett, t-degree 0, 4 parameters' same.txt ||
    fail "same plant: $(grep chosen same.txt)"
grep -q '^# creep: none (validation rms ' same.txt || fail "same plant, creep: $(grep creep same.txt)"
"$tool" fit --kind everett --degree 3 --t-degree 0 --validate b.txt a.txt > given.txt 2> /dev/null ||
    fail "fit --degree --validate"
grep -q '^# delay 3 samples$' given.txt || fail "--degree: $(grep '^# delay' given.txt)"
grep -q '^# delay chosen on the validation record among 0..8 samples (without --delay)$' given.txt ||
    fail "--degree: the delay line"
grep -q '^# validation on b.txt: rms [0-9.e-]* (the model fitted on the whole record, run from rest over its [0-9]* samples)$' \
    given.txt || fail "--degree: the validation line"
# --degree and --delay: nothing chosen but the creep option, the model still scored on OTHER
"$tool" fit --kind everett --degree 3 --t-degree 0 --delay 3 --creep none --validate b.txt a.txt \
    > fixed.txt 2> /dev/null || fail "fit --degree --delay --validate"
grep -q '^# validation on b.txt: rms ' fixed.txt || fail "--delay: the validation line"

# ---- 3. --skip drops the first rows of both records ----
for r in a b; do
    { for i in 1 2 3 4 5 6 7 8 9 10; do echo "20 $((i * 7 % 5))"; done; cat $r.txt; } > skip_$r.txt
done
"$tool" fit --skip 10 --validate skip_b.txt --save skip.hyst skip_a.txt > skip.txt 2> /dev/null ||
    fail "fit --skip --validate"
"$tool" fit --validate b.txt --save noskip.hyst a.txt > noskip.txt 2> /dev/null || fail "fit (no skip)"
cmp <(grep -v '^#' skip.hyst) <(grep -v '^#' noskip.hyst) || fail "--skip: another model"
cmp <(grep '^# candidate' skip.txt) <(grep '^# candidate' noskip.txt) || fail "--skip: other scores"

# ---- 4. refusals: exit 1, the reason, nothing printed, no model file ----
: > empty.txt
awk '{ print $1 }' b.txt > one_column.txt
awk '{ print $1, 5 }' b.txt > constant_y.txt
awk '{ print 3, $2 }' b.txt > constant_x.txt
awk '{ print $1, -$2 }' b.txt > falling.txt
head -n 1 b.txt > one_row.txt
refused() { # <expected message> <fit arguments...>
    local msg=$1
    shift
    if "$tool" fit "$@" > out.txt 2> err.txt; then fail "accepted: fit $*"; fi
    grep -q -- "$msg" err.txt || fail "fit $*: message $(cat err.txt)"
    [ ! -s out.txt ] || fail "fit $*: printed $(cat out.txt)"
    [ ! -e refused.hyst ] || fail "fit $*: wrote a model file"
}
refused 'nosuch.txt: cannot open' --validate nosuch.txt --save refused.hyst a.txt
refused 'empty.txt: no data' --validate empty.txt --save refused.hyst a.txt
refused 'one_column.txt:1: field 2 is missing' --validate one_column.txt --save refused.hyst a.txt
refused 'constant_y.txt: column 2 is constant' --validate constant_y.txt --save refused.hyst a.txt
refused 'constant_x.txt: column 1 is constant' --validate constant_x.txt --save refused.hyst a.txt
refused 'falling.txt: the output (column 2) falls' --validate falling.txt --save refused.hyst a.txt
refused 'one_row.txt: 1 rows after --skip 0' --validate one_row.txt --save refused.hyst a.txt
refused 'one_row.txt: 0 rows after --skip 5' --skip 5 --validate one_row.txt --save refused.hyst a.txt
refused "'-' and FILE '-' both name standard input" --validate - --save refused.hyst - < a.txt
refused 'does not combine with --validate' --validate b.txt --compare-pi 10 a.txt
refused 'option --validate does not apply to --kind pi' --kind pi --validate b.txt a.txt
refused 'the model file would replace it' --validate b.txt --save b.txt a.txt
echo "validate: delay 1 on the fast record (the hold-out alone: $alone_delay); degree 3 delay 3; refusals"

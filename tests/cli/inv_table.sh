#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst inv --intervals N [--rows R]`: the firmware's tabulated compensator,
# for a model file of each kind (poly: Eq. 20; everett: E of degree 3):
#  - it prints, bit for bit, what the library prints run as firmware runs it
#    (inv_table_run: hyst_f64_init_inverse_table(), or
#    hyst_f64_curve_everett_inverse_table() and hyst_f64_init_curve()), and
#    on stderr the error init measured, as hyst_curve_inverse_error() gives it;
#  - on nested loops and random jumps it agrees with the exact compensator
#    (`hyst inv` without --intervals) within that error, 1.01 times it (init
#    measures at points of each interval, the library's tests allow 1 %),
#    plus the exact compensator's own tolerance; kind everett: a turning
#    point's drive carries the table's error into the branches that start
#    there, so (tp + 1) times it, tp the stored turning points (--tp);
#  - with the default table, within 1e-5 of the drive range;
#  - a coarse table is really used (its error and its drive differences are
#    not 0), `--intervals default` is the library's default size, and
#    standard output stays one drive per line (the note is on stderr);
#  - 2000 nested reversals: the turning-point memory grows from 256 entries
#    (a snapshot carried over) and the drives stay the library's, bit for bit;
#    kind everett: the model driven by them gives the desired outputs back
#    within 1e-5 of its output range at every depth.
#   inv_table.sh <hyst> <inv_table_run> <work dir>
set -euo pipefail
tool=$1 run=$2 work=$3
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

printf 'hyst-model-text 1\nkind poly\nlo 0\nhi 40\ndelay 0\ncoeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1\n' > poly.hyst
printf 'hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 1\ndegree 3\nterms 3 1 0 2 -0.5 0.4\n' > ev.hyst
val() { sed -n "s/^$2 //p" "$1"; }

# drives from lo (where both compensators start): nested loops shrinking and
# growing over [0, 40], then Park-Miller random jumps in it; the desired
# outputs are what sim --model prints for them (17 digits; kind everett's
# first line is the model at rest, its delay)
awk 'BEGIN { for (k = 0; k < 3000; k++)
               printf "%.9g\n", 40 * (1 - cos(0.05 * k)) / 2 * (0.6 + 0.4 * cos(0.0131 * k));
             s = 1; for (k = 0; k < 2000; k++) { s = (s * 16807) % 2147483647;
               printf "%.9g\n", 40 * s / 2147483647 } }' > x.txt
n=$(wc -l < x.txt)

note_re="^hyst inv: tabulated compensator, .*: init's worst measured error ([0-9.e+-]+) of the drive range \[([0-9.e+-]+), ([0-9.e+-]+)\], ([0-9.e+-]+)$"

# check <model> <label> <tp factor 0|1> <slack> <default 0|1> <coarse 0|1> <run args...> -- <inv args...>
check() {
    local model=$1 label=$2 per_tp=$3 slack=$4 dflt=$5 coarse=$6
    shift 6
    local runargs=() invargs=()
    while [ "$1" != -- ]; do runargs+=("$1"); shift; done
    shift
    invargs=("$@")
    "$tool" inv --model "$model" --digits 17 --tp "${invargs[@]}" y_$model.txt > tab.txt 2> tab_err.txt ||
        fail "$label: exit status: $(cat tab_err.txt)"
    [ "$(wc -l < tab.txt)" -eq "$n" ] || fail "$label: $(wc -l < tab.txt) lines for $n desired outputs"
    ! grep -qvE '^[0-9.e+-]+,[0-9]+$' tab.txt || fail "$label: a line is not drive,tp: $(grep -vE '^[0-9.e+-]+,[0-9]+$' tab.txt | head -1)"
    [ "$(grep -c 'tabulated compensator' tab_err.txt)" -eq 1 ] || fail "$label: the note: $(cat tab_err.txt)"
    local note err lo hi abs
    note=$(grep 'tabulated compensator' tab_err.txt)
    [[ $note =~ $note_re ]] || fail "$label: note format: $note"
    err=${BASH_REMATCH[1]} lo=${BASH_REMATCH[2]} hi=${BASH_REMATCH[3]} abs=${BASH_REMATCH[4]}
    [ "$lo" = "$(val "$model" lo)" ] && [ "$hi" = "$(val "$model" hi)" ] || fail "$label: drive range [$lo, $hi]"
    awk -v e="$err" -v a="$abs" -v lo="$lo" -v hi="$hi" 'BEGIN { d = a - e * (hi - lo); if (d < 0) d = -d;
        exit !(d <= 1e-8 * (a > 0 ? a : 1)) }' || fail "$label: $abs is not $err of the range"
    # the library's own run, as firmware: the same drives bit for bit, the same error
    "$run" "${runargs[@]}" < y_$model.txt > lib.txt 2> lib_err.txt || fail "$label: inv_table_run: $(cat lib_err.txt)"
    [ "$(cat lib_err.txt)" = "$err" ] || fail "$label: note says $err, the library $(cat lib_err.txt)"
    cmp -s <(cut -d, -f1 tab.txt) lib.txt || fail "$label: the drives differ from the library's tabulated compensator"
    # against the exact compensator
    paste -d, exact_$model.txt tab.txt | awk -F, -v e="$err" -v lo="$lo" -v hi="$hi" \
        -v per_tp="$per_tp" -v slack="$slack" -v dflt="$dflt" -v coarse="$coarse" '
        { d = $2 - $1; if (d < 0) d = -d; s = hi - lo;
          k = per_tp ? $3 + 1 : 1; allowed = k * (1.01 * e + slack) * s;
          if (d > allowed) { printf "line %d: |%s - %s| = %.3g above %.3g (tp %d)\n", NR, $2, $1, d, allowed, $3; bad = 1; exit }
          if (dflt && d > 1e-5 * s) { printf "line %d: %.3g above 1e-5 of the drive range\n", NR, d / s; bad = 1; exit }
          if (d / s > worst) worst = d / s }
        END { if (bad) exit 1;
              if (coarse && !(e > 0 && worst > 0)) { print "the table was not used (error " e ", worst " worst ")"; exit 1 }
              printf "worst %.3g of the drive range, init measured %s", worst, e }' > cmp.txt ||
        fail "$label: $(cat cmp.txt)"
    echo "$label: $(cat cmp.txt)"
}

for m in poly.hyst ev.hyst; do
    "$tool" sim --model "$m" --digits 17 x.txt > y_$m.txt || fail "sim --model $m"
    "$tool" inv --model "$m" --digits 17 y_$m.txt > exact_$m.txt 2> exact_err.txt || fail "exact inv $m"
    ! grep -q 'tabulated' exact_err.txt || fail "exact inv $m: a table note without --intervals"
done

# the models' numbers, for inv_table_run
# shellcheck disable=SC2207 # numbers as separate words
p_args=($(val poly.hyst lo) $(val poly.hyst hi))
# shellcheck disable=SC2207
c=($(val poly.hyst coeffs))
# shellcheck disable=SC2207
e_args=($(val ev.hyst lo) $(val ev.hyst hi) $(val ev.hyst y_lo) $(val ev.hyst degree))
# shellcheck disable=SC2207
terms=($(val ev.hyst terms))
# "default": inv_table_run takes the library's HYST_INV_TABLE, HYST_EVERETT_INV_ROWS and
# HYST_EVERETT_INV_INTERVALS. Slack: poly, the bisection's rounding (about 1e-15 of the
# range); everett, Newton's tolerance in double (2^-40 of the span per solve, for both
# compensators), with margin: 8 times it
check poly.hyst "poly, default table" 0 1e-13 1 0 poly "${p_args[@]}" default "${c[@]}" -- --intervals default
check poly.hyst "poly, 16 intervals" 0 1e-13 0 1 poly "${p_args[@]}" 16 "${c[@]}" -- --intervals 16
tol=$(awk 'BEGIN { printf "%.17g", 8 / 2^40 }')
check ev.hyst "everett, default table" 1 "$tol" 1 0 everett "${e_args[@]}" default default "${terms[@]}" -- --intervals default
check ev.hyst "everett, 8 rows of 16 intervals" 1 "$tol" 0 1 everett "${e_args[@]}" 8 16 "${terms[@]}" -- --rows 8 --intervals 16
grep -q "delay of 1 samples is not compensated" tab_err.txt || fail "the delay note: $(cat tab_err.txt)"
# --rows default is what no --rows gives
"$tool" inv --model ev.hyst --intervals 16 y_ev.hyst.txt > a.txt 2> /dev/null
"$tool" inv --model ev.hyst --intervals 16 --rows default y_ev.hyst.txt > b.txt 2> /dev/null
cmp -s a.txt b.txt || fail "everett: --rows default is not the rows without --rows"

# 2000 nested reversals around 20 V: the engine's memory grows (256, 512, ...,
# 4096 entries: inv_table_run's capacity), each time through a snapshot
awk 'BEGIN { n = 2000; print 0; for (k = 1; k <= n; k++) printf "%.9g\n", 20 + 20 * (k % 2 ? 1 : -1) * (1 - k / (n + 1)) }' > deep.txt
for m in poly.hyst ev.hyst; do
    "$tool" sim --model "$m" --digits 17 deep.txt > deep_y.txt 2> /dev/null || fail "sim --model $m, nested"
    "$tool" inv --model "$m" --digits 17 --tp --intervals default deep_y.txt > deep_x.txt 2> /dev/null ||
        fail "inv --intervals, nested, $m"
    [ "$(tail -1 deep_x.txt | cut -d, -f2)" -ge 1990 ] || fail "nested, $m: $(tail -1 deep_x.txt) turning points"
    if [ $m = poly.hyst ]; then
        "$run" poly "${p_args[@]}" default "${c[@]}" < deep_y.txt > deep_lib.txt 2> /dev/null ||
            fail "inv_table_run, nested, $m"
    else
        "$run" everett "${e_args[@]}" default default "${terms[@]}" < deep_y.txt > deep_lib.txt 2> /dev/null ||
            fail "inv_table_run, nested, $m"
    fi
    cmp -s <(cut -d, -f1 deep_x.txt) deep_lib.txt || fail "nested, $m: the drives differ from the library's"
done
echo "nested reversals: $(tail -1 deep_x.txt | cut -d, -f2) turning points, the library's drives"
# kind everett, the same 2000 nested reversals without the delay: the model driven by the
# tabulated compensator gives the desired outputs back within 1e-5 of its output range at every
# depth (a new turning point is stored at the model's output for its drive: the table's errors
# do not add up over nested loops)
grep -v '^delay ' ev.hyst > ev0.hyst
"$tool" sim --model ev0.hyst --digits 17 deep.txt > deep_y0.txt 2> /dev/null || fail "sim --model ev0.hyst"
"$tool" inv --model ev0.hyst --digits 17 --intervals default deep_y0.txt > deep_x0.txt 2> /dev/null ||
    fail "inv --intervals, nested, ev0.hyst"
"$tool" sim --model ev0.hyst --digits 17 deep_x0.txt > deep_back.txt 2> /dev/null || fail "sim of the drives"
span=$(printf '0\n40\n' | "$tool" sim --model ev0.hyst --digits 17 2> /dev/null | awk 'NR == 1 { a = $1 } END { print $1 - a }')
paste -d, deep_y0.txt deep_back.txt | awk -F, -v s="$span" '
    { d = $2 - $1; if (d < 0) d = -d; if (d / s > worst) { worst = d / s; at = NR } }
    END { printf "round trip over nested loops: worst %.3g of the output range (line %d)\n", worst, at;
          exit !(worst <= 1e-5) }' > rt.txt || fail "$(cat rt.txt)"
cat rt.txt

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Model files of kind spline (the symmetric TCM, f0 a monotone cubic spline on
# uniform knots) in `hyst`:
#  - sim --model runs one: f0 = x^3 + x on [0, 1] in two pieces (a cubic is
#    its own Hermite spline), exact at these inputs, rising and falling;
#  - malformed files are refused, naming line and field (the reader), or
#    with the library's reason (a piece that falls); inv --model gives the
#    drives of sim's outputs back; header --compensator says how firmware
#    builds it (compiled and run: inv's drives), --sealed, --rows refused;
#  - header --model writes its hyst_spline_t, which compiles (float and
#    double) and which the library's constructor accepts;
#  - a plant whose f0 is a C2 spline of 5 intervals (written from its
#    I-spline weights, the fit's own class), 2 samples late, driven with
#    minor loops, +-0.005 of noise: fit --kind spline chooses 5 intervals and
#    delay 2, its hold-out error the noise's; the model saved predicts the
#    plant within a fraction of the noise; sim --model of it prints what the
#    library gives for its header's hyst_spline_t (compiled here), bit for
#    bit; fit's line 1 is the model file's values; inv --model undoes sim
#    --model on the minor loops; a creep term and the identified range are
#    saved and read back; a domain above the inputs fitted continues f0 as a
#    straight line at its slope there, by whole knot intervals;
#  - inv --intervals N (the tabulated compensator, hyst_curve_spline_inverse_table())
#    on the plant's minor loops: within the error init measured (printed on
#    stderr, 1.01 times it) of inv --model's drives, times the turning points
#    each drive's branch stands on (each carries the table's error); header
#    --compensator --intervals N, compiled and run as firmware builds it,
#    prints those drives bit for bit (double build); --rows, --sealed and
#    a bad N refused, nothing on standard output.
#   spline.sh <hyst> <C compiler> <include dir> <library sources dir> <work dir>
set -euo pipefail
tool=$1 cc=$2 inc=$3 src=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# ---- a hand-written spline: f0 = x^3 + x on [0, 1], f0' = 3 x^2 + 1 ----
cat > one.hyst <<'EOF'
hyst-model-text 1
kind spline
lo 0
hi 1
values 0 0.625 2
slopes 1 1.75 4
EOF
printf '0\n0.25\n0.5\n1\n0.5\n0.75\n0\n' > x.txt
"$tool" sim --model one.hyst x.txt > y.txt || fail "sim of a spline model"
# rising f0(x); from (1, 2) falling 2 - g(1 - x); from (0.5, 1.375) rising 1.375 + g(x - 0.5),
# g(d) = f0(d) - f0(0): 0.265625 at 0.25, 0.625 at 0.5
[ "$(tr '\n' ' ' < y.txt)" = "0 0.265625 0.625 2 1.375 1.640625 0 " ] || fail "sim: $(tr '\n' ' ' < y.txt)"

# one.hyst edited by a sed expression, refused by sim and header in these words (one a line);
# the last: the reader takes it (slopes >= 0), the library refuses a piece that falls
n=0
while IFS='|' read -r edit message; do
    n=$((n + 1))
    sed "$edit" one.hyst > "bad$n.hyst"
    for cmd in "sim --model bad$n.hyst x.txt" "header --model bad$n.hyst bad"; do
        # shellcheck disable=SC2086
        if "$tool" $cmd > /dev/null 2> err.txt; then fail "$cmd accepted ($edit)"; fi
        grep -qF -- "${message//@/bad$n.hyst}" err.txt || fail "$cmd ($edit): $(cat err.txt)"
    done
done <<'EOF'
s/^slopes 1 1.75 4$/slopes 1 1.75/|@:6: field 4 is missing: slopes needs 3 numbers, one per value
s/^slopes 1 1.75 4$/slopes 1 1.75 4 5/|@:6: field 5: one too many: slopes needs 3 numbers, one per value
s/^slopes 1 1.75 4$/slopes 1 -1.75 4/|@:6: field 3: '-1.75' is not a slope >= 0 (f0 increases)
s/^values 0 0.625 2$/values 0/|@:5: field 3 is missing: values needs 2 to 33 numbers (f0 at the knots)
s/^lo 0$/y_lo 0\nlo 0/|@:3: field 1: y_lo is not a key of kind spline (f0 is given by values and slopes)
/^slopes/d|@: the key slopes is missing
s/^kind spline$/kind poly\ncoeffs 1 0/|@:6: field 1: values is not a key of kind poly
s/^values 0 0.625 2$/values 0 1.9 2/|model file @: f0 not increasing
EOF
[ "$n" -eq 8 ] || fail "$n refusals tried"

# inv --model: the compensator (hyst_curve_spline_inverse()): the drives of sim's outputs back
"$tool" inv --model one.hyst y.txt > xi.txt || fail "inv of a spline model"
[ "$(tr '\n' ' ' < xi.txt)" = "$(tr '\n' ' ' < x.txt)" ] || fail "inv: $(tr '\n' ' ' < xi.txt)"

# header --model: the hyst_spline_t, accepted by the library's constructor (header_run.c, in
# float and in double)
"$tool" header --model one.hyst spline_model 2> /dev/null || fail "header"
grep -q "hyst_curve_from_spline(&curve, &spline_model, table, HYST_SPLINE_TABLE_LEN(2u))" \
    spline_model.h || fail "header: the constructor's call: $(cat spline_model.h)"
bash "$here/header_run.sh" "$cc" "$inc" "$src" spline_model 2 -DKIND_SPLINE || fail "header"
for d in "" -DHYST_USE_DOUBLE; do
    "./run$d" || fail "the header's spline refused ($d)"
done
# header --compensator: the curve's compensator built in firmware gives inv --model's
# drives; no table of its own without --intervals
"$tool" header --model one.hyst --compensator spline_comp 2> /dev/null || fail "header --compensator"
grep -q "hyst_curve_spline_inverse()" spline_comp.h || fail "header --compensator: no inverse named"
# (6 digits: the float build's bisection ends within its rounding of the drive)
bash "$here/header_run.sh" "$cc" "$inc" "$src" spline_comp 2 -DKIND_SPLINE -DDIGITS=6 \
    -DWANT="$(paste -s -d, y.txt)" || fail "header --compensator"
for d in "" -DHYST_USE_DOUBLE; do
    "./run$d" > xc.txt || fail "the header's compensator refused ($d)"
    [ "$(tr '\n' ' ' < xc.txt)" = "$(tr '\n' ' ' < xi.txt)" ] ||
        fail "header --compensator drives ($d): $(tr '\n' ' ' < xc.txt), inv: $(tr '\n' ' ' < xi.txt)"
done
! grep -q "_INTERVALS" spline_comp.h || fail "header --compensator: a table without --intervals"

# ---- a plant of the fit's class: f0' = (K / (hi - lo)) sum w_j B_j (quadratic B-splines on
# the uniform knots), K = 5 on [0, 3]: f0(x_k) = the sum over intervals i < k of
# (w_i + 4 w_(i+1) + w_(i+2)) / 6, f0'(x_k) = (w_k + w_(k+1)) / 2 K / (hi - lo); a near step ----
awk 'BEGIN { split("0.3 0.2 0.2 2.5 2.5 0.2 0.1", w); K = 5; lo = 0; hi = 3; y = 0.5;
             printf "hyst-model-text 1\n# the C2 spline of I-spline weights %s\n", "0.3 0.2 0.2 2.5 2.5 0.2 0.1";
             printf "kind spline\nlo %g\nhi %g\ndelay 2\nvalues %.17g", lo, hi, y;
             for (i = 1; i <= K; i++) { y += (w[i] + 4 * w[i + 1] + w[i + 2]) / 6; printf " %.17g", y }
             printf "\nslopes";
             for (k = 1; k <= K + 1; k++) printf " %.17g", (w[k] + w[k + 1]) / 2 * K / (hi - lo);
             printf "\n" }' > plant.hyst
sed 's/^delay 2$/delay 0/' plant.hyst > plant0.hyst
# minor loops of decreasing size, then a major loop
awk 'BEGIN { for (c = 0; c < 12; c++) { a = 3 - c * 0.2; b = c * 0.2;
             for (x = b; x < a; x += 0.01) printf "%.2f\n", x; for (x = a; x > b; x -= 0.01) printf "%.2f\n", x }
             for (x = 0; x < 3; x += 0.01) printf "%.2f\n", x; for (x = 3; x >= 0; x -= 0.01) printf "%.2f\n", x }' > px.txt
"$tool" sim --model plant.hyst --digits 17 px.txt > py.txt || fail "sim of the plant"
"$tool" sim --model plant0.hyst --digits 17 px.txt > py0.txt || fail "sim of the plant without its delay"
# +-0.005 of noise (an LCG): rms 0.005 / sqrt(3) = 0.00289
paste -d ' ' px.txt py.txt | awk 'BEGIN { s = 4242 } { s = (s * 1103515245 + 12345) % 2147483648
                                    printf "%s %.9g\n", $1, $2 + (s / 2147483648 - 0.5) * 0.01 }' > rec.txt
"$tool" fit --kind spline --creep none --save fitted.hyst rec.txt > fit.txt 2> fit.err ||
    fail "fit --kind spline: $(cat fit.err)"
grep -q '^# chosen by hold-out: degree 5, delay 2 (kind spline, 8 parameters: .*kinds compared: spline)$' fit.txt ||
    fail "the plant's class: $(grep chosen fit.txt)"
[ "$(grep -c '^# candidate spline intervals [0-9]* delay 2: hold-out rms' fit.txt)" -eq 15 ] ||
    fail "candidates 2..16 at delay 2: $(grep -c 'candidate spline intervals [0-9]* delay 2:' fit.txt)"
! grep -q 'candidate \(degree\|everett\)' fit.txt || fail "--kind spline scored other kinds"
# the chosen candidate's hold-out error is the noise's
awk '/^# candidate spline intervals 5 delay 2: .*\(chosen\)$/ { r = $10; sub(/,$/, "", r)
                                                                    ok = r > 0.0025 && r < 0.0033 }
     END { exit !ok }' fit.txt ||
    fail "hold-out of the chosen: $(grep '(chosen)' fit.txt)"
grep -qx '# parameters 8' fit.txt || fail "parameters: $(grep parameters fit.txt)"
grep -q '^delay 2$' fitted.hyst && grep -q '^kind spline$' fitted.hyst || fail "the model file: $(cat fitted.hyst)"
# line 1 (15 digits) is the model file's values (17)
awk 'NR == FNR { if (FNR == 1) n = split($0, a, ","); next }
     /^values / { ok = NF - 1 == n; for (i = 2; i <= NF; i++) ok = ok && ($i - a[i - 1]) ^ 2 < 1e-24 }
     END { exit !ok }' fit.txt fitted.hyst || fail "line 1: $(head -1 fit.txt), the file: $(grep values fitted.hyst)"
# the saved model predicts the plant (delay included) within a fraction of the noise
"$tool" sim --model fitted.hyst --digits 17 px.txt > fy.txt || fail "sim of the fitted model"
paste -d ' ' py.txt fy.txt | awk '{ d = $1 - $2; s += d * d; n++ }
                                 END { r = sqrt(s / n); print "spline fit: rms " r; exit !(r < 0.001) }' ||
    fail "the fitted spline misses the plant"

# ---- sim --model is the library's run of the header's hyst_spline_t, bit for bit ----
sed 's/^delay 2$/delay 0/' fitted.hyst > fitted0.hyst
"$tool" header --model fitted0.hyst fitted 2> /dev/null || fail "header of the fitted model"
bash "$here/header_run.sh" "$cc" "$inc" "$src" fitted 32 -DKIND_SPLINE -DSIM ||
    fail "the fitted model's header"
./run-DHYST_USE_DOUBLE < px.txt > ly.txt || fail "the library refused the fitted model's header"
"$tool" sim --model fitted0.hyst --digits 17 px.txt > sy.txt || fail "sim of the fitted model, delay 0"
[ "$(wc -l < ly.txt)" -eq "$(wc -l < px.txt)" ] || fail "the library's run: $(wc -l < ly.txt) outputs"
cmp -s ly.txt sy.txt || fail "sim --model differs from the library: $(paste -d ' ' ly.txt sy.txt | awk '$1 != $2' | head -3)"
./run < px.txt > /dev/null || fail "a float build refused the fitted model's header"

# ---- inv --model undoes sim --model, minor loops included ----
"$tool" sim --model plant0.hyst px.txt > p9.txt || fail "sim of the plant (9 digits)"
"$tool" inv --model plant0.hyst p9.txt > pxi.txt || fail "inv of the plant"
paste -d ' ' px.txt pxi.txt | awk '{ d = $1 - $2; d = d < 0 ? -d : d; m = d > m ? d : m }
                                  END { print "inv: max " m; exit !(m < 1e-6) }' ||
    fail "inv --model does not undo sim --model"

# ---- fit --degree K: the spline's intervals, 1..32; a creep term and the identified range ----
"$tool" fit --kind spline --degree 32 --delay 2 --creep none rec.txt > f32.txt || fail "--degree 32"
grep -q "kind spline, 32 intervals" f32.txt || fail "--degree 32: $(grep residual f32.txt)"
if "$tool" fit --kind spline --degree 33 rec.txt > /dev/null 2> err.txt; then fail "--degree 33 accepted"; fi
grep -qF "option --degree: '33' is not an integer in 1..32" err.txt || fail "--degree 33: $(cat err.txt)"
"$tool" fit --kind spline --degree 5 --delay 2 --creep 500 --domain -1,3 --save creep.hyst \
    --header creep_h rec.txt > creep.txt || fail "fit with creep and a domain"
grep -q '^creep_tau 500$' creep.hyst && grep -q '^identified 0 3$' creep.hyst ||
    fail "creep and identified range: $(cat creep.hyst)"
grep -q 'static const hyst_wide_t creep_h_creep_tau\[creep_h_CREEP_TERMS\]' creep_h.h ||
    fail "the header's creep term: $(cat creep_h.h)"
printf -- '-0.5\n0\n1\n' | "$tool" sim --model creep.hyst > /dev/null 2> note.txt || fail "sim of creep.hyst"
grep -q "1 of 3 inputs outside \[0, 3\], the range the model was identified on" note.txt ||
    fail "sim's note: $(cat note.txt)"
# a domain above the inputs fitted: the knots from lo to the largest input (5 intervals of
# 0.6 on [0, 3]), then whole intervals to cover [0, 4], f0 a straight line there at its slope
# at 3 (predicted, not held: the output keeps rising above the inputs fitted); below them the
# knots start at the domain's lo, where the model rests
"$tool" fit --kind spline --degree 5 --delay 2 --creep none --domain 0,4 --save wide.hyst \
    rec.txt > wide.txt || fail "fit with a wider domain"
awk '/^lo / { lo = $2 } /^hi / { hi = $2 } /^values / { for (i = 2; i <= NF; i++) v[i - 1] = $i; n = NF - 1 }
     /^slopes / { for (i = 2; i <= NF; i++) m[i - 1] = $i }
     END { d = (v[7] - v[6]) - 0.6 * m[6]; d2 = (v[8] - v[7]) - 0.6 * m[6]
           exit !(lo == 0 && (hi - 4.2) ^ 2 < 1e-24 && n == 8 && m[6] == m[7] && m[6] == m[8] &&
                  d * d < 1e-24 && d2 * d2 < 1e-24 && m[6] > 0) }' wide.hyst ||
    fail "the domain's continuation: $(grep -v '^#' wide.hyst)"
grep -q '^identified 0 3$' wide.hyst || fail "identified range: $(cat wide.hyst)"
sed 's/^delay 2$/delay 0/' wide.hyst > wide0.hyst
printf '3\n3.5\n' | "$tool" sim --model wide0.hyst --digits 17 > wy.txt 2> /dev/null ||
    fail "sim of wide.hyst"
awk 'NR == 1 { a = $1 } NR == 2 { b = $1 } END { exit !(b > a) }' wy.txt ||
    fail "held beyond the inputs fitted: $(cat wy.txt)"
# and within them it predicts the plant as the fit on the inputs' range alone does
"$tool" sim --model wide.hyst --digits 17 px.txt > wfy.txt 2> /dev/null || fail "sim of wide.hyst"
paste -d ' ' py.txt wfy.txt | awk '{ d = $1 - $2; s += d * d; n++ } END { exit !(sqrt(s / n) < 0.001) }' ||
    fail "the wider domain's model misses the plant"
# ---- inv --intervals N: the tabulated compensator, on the plant's minor loops ----
"$tool" sim --model plant0.hyst --digits 17 px.txt > p17.txt || fail "sim of the plant (17 digits)"
"$tool" inv --model plant0.hyst --digits 17 p17.txt > exact.txt || fail "inv of the plant (17 digits)"
note_re="^hyst inv: tabulated compensator, ([0-9]+) intervals \(([0-9]+) of them evaluated exactly\): init's worst measured error ([0-9.e+-]+) of the drive range \[0, 3\], ([0-9.e+-]+)$"
for n in 8 64 default; do
    "$tool" inv --model plant0.hyst --digits 17 --tp --intervals $n p17.txt > tab.txt 2> err.txt ||
        fail "inv --intervals $n: $(cat err.txt)"
    [[ "$(cat err.txt)" =~ $note_re ]] || fail "inv --intervals $n: the note: $(cat err.txt)"
    [ "$n" != default ] || [ "${BASH_REMATCH[1]}" -eq 256 ] || fail "default: ${BASH_REMATCH[1]} intervals"
    [ "$(wc -l < tab.txt)" -eq "$(wc -l < px.txt)" ] || fail "inv --intervals $n: $(wc -l < tab.txt) lines"
    paste -d, exact.txt tab.txt | awk -F, -v e="${BASH_REMATCH[3]}" '
        { d = $2 - $1; d = d < 0 ? -d : d; allowed = ($3 + 1) * (1.01 * e + 1e-15) * 3
          if (d > allowed) { printf "line %d: |%s - %s| above %.3g (tp %d)", NR, $2, $1, allowed, $3; exit 1 }
          if (d / 3 > w) w = d / 3 }
        END { if (!(w > 0)) { print "the table was not used"; exit 1 } }' > cmp.txt ||
        fail "inv --intervals $n against the exact compensator: $(cat cmp.txt)"
done
# header --compensator --intervals N: what firmware builds at init, its drives those of inv
"$tool" header --model plant0.hyst --compensator --intervals 64 plant_comp 2> /dev/null ||
    fail "header --compensator --intervals"
grep -q "^#define plant_comp_INTERVALS 64u$" plant_comp.h &&
    grep -q "hyst_curve_spline_inverse_table(&comp, &fwd, comp_table, plant_comp_INTERVALS)" plant_comp.h ||
    fail "header --compensator --intervals: $(cat plant_comp.h)"
"$tool" inv --model plant0.hyst --digits 17 --intervals 64 p17.txt > tab.txt 2> /dev/null || fail "inv --intervals 64"
head -400 p17.txt > want.txt
bash "$here/header_run.sh" "$cc" "$inc" "$src" plant_comp 5 -DKIND_SPLINE -DTABLED -DDIGITS=17 \
    -DWANT="$(paste -s -d, want.txt)" || fail "header --compensator --intervals"
./run-DHYST_USE_DOUBLE > hc.txt || fail "the header's tabulated compensator refused (double)"
cmp -s hc.txt <(head -400 tab.txt) || fail "the header's drives differ from inv --intervals 64"
./run > /dev/null || fail "the header's tabulated compensator refused (float)"
# refusals: exit 1, nothing on standard output
for cmd in "inv --model plant0.hyst --intervals 64 --rows 8 p17.txt" \
           "inv --model plant0.hyst --intervals 0 p17.txt" \
           "inv --model plant0.hyst --intervals 1048577 p17.txt" \
           "header --model plant0.hyst --compensator --sealed --intervals 64 s2" \
           "header --model plant0.hyst --compensator --rows 8 --intervals 64 s2" \
           "header --model plant0.hyst --compensator --intervals 0 s2"; do
    rc=0
    # shellcheck disable=SC2086
    "$tool" $cmd > out.txt 2> err.txt || rc=$?
    [ "$rc" -eq 1 ] && [ ! -s out.txt ] && [ -s err.txt ] && [ ! -e s2.h ] ||
        fail "$cmd: exit $rc, $(head -c 200 out.txt) $(cat err.txt)"
done
echo "spline.sh: OK"

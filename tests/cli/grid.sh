#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Model files of kind everett_grid (the asymmetric kind on a grid) in `hyst`:
#  - sim --model runs one: one cell of mass 8 on [0, 2] gives E(a, b) =
#    8 ((a - b) / 2)^2, exact at these inputs;
#  - malformed files are refused, naming line and field; inv and header
#    --compensator refuse the kind (no compensator yet);
#  - header --model writes its hyst_everett_grid_t, which compiles (float and
#    double) and which the library's constructor accepts.
#   grid.sh <hyst> <C compiler> <include dir> <library sources dir> <work dir>
set -euo pipefail
tool=$1 cc=$2 inc=$3 src=$4 work=$5
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
if "$tool" inv --model one.hyst x.txt > /dev/null 2> err.txt; then fail "inv accepted a grid"; fi
grep -q "no compensator yet" err.txt || fail "inv: $(cat err.txt)"

"$tool" header --model one.hyst grid_model 2> /dev/null || fail "header"
cat > use.c <<'EOF'
#include "hyst/hyst.h"
#include "grid_model.h"
int main(void)
{
    static hyst_real_t table[HYST_EVERETT_GRID_TABLE_LEN(1u)];
    hyst_curve_t c;
    return hyst_curve_from_everett_grid(&c, &grid_model, table, HYST_EVERETT_GRID_TABLE_LEN(1u)) != HYST_OK;
}
EOF
for d in "" -DHYST_USE_DOUBLE; do
    "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror $d -I"$inc" -I. use.c "$src"/*.c -lm -o use \
        || fail "header does not compile ($d)"
    ./use || fail "the header's grid refused ($d)"
done
if "$tool" header --model one.hyst --compensator g2 2> err.txt; then fail "header --compensator"; fi
echo "grid.sh: OK"

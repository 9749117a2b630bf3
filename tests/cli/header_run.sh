#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds header_run.c for the header NAME.h in the current directory (kind
# everett_grid, or kind spline with -DKIND_SPLINE; K its intervals), in float
# (./run) and in double (./run-DHYST_USE_DOUBLE), with the library's sources;
# more -D options pass through (-DWANT=..., -DSIM, -DDIGITS=N: header_run.c).
#   header_run.sh <C compiler> <include dir> <library sources dir> <NAME> <K> [-D...]
set -euo pipefail
cc=$1 inc=$2 src=$3 model=$4 k=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
for d in "" -DHYST_USE_DOUBLE; do
    # shellcheck disable=SC2086
    "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror $d -DMODEL_H="\"$model.h\"" -DMODEL="$model" \
        -DINTERVALS="$k" "$@" -I"$inc" -I. "$here/header_run.c" "$src"/*.c -lm -o "run$d" || {
        echo "FAIL: $model.h does not compile (${d:-float})" >&2
        exit 1
    }
done

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# sim, inv and pi read one line at a time, in constant memory: one million
# samples (a whole-file reader needs 16 bytes per sample, and an engine sized
# for the sample count 16 more) go through with 24 MB of address space, from
# a file and from a pipe, one output per input. The results wait in a
# temporary file (in $TMPDIR, here the work dir) until the input is checked.
#   stream.sh <hyst> <work dir>
set -euo pipefail
tool=$1 work=$2
mkdir -p "$work"
cd "$work"
export TMPDIR=$PWD
fail() { echo "FAIL: $*" >&2; exit 1; }
rows=1000000 limit_kb=24000
poly="-6.1876e-6,1.1949e-3,8.6444e-2,5.8517e-1" # paper Eq. 20, increasing on [0, 40]

# triangles 0..40 V with shrinking and growing amplitude: nested loops
awk -v n=$rows 'BEGIN { for (k = 0; k < n; k++) { p = k % 2000; a = 0.5 + 0.5 * cos(k / 50000);
                         printf "%.6g\n", 40 * a * (p <= 1000 ? p : 2000 - p) / 1000 } }' > x.txt

limited() { ( ulimit -v $limit_kb && exec "$tool" "$@" ); }
check() { # check <what> <output file>
    [ "$(wc -l < "$2")" -eq $rows ] || fail "$1: $(wc -l < "$2") lines out for $rows in"
}
limited sim --poly "$poly" --range 0,40 x.txt > y.txt || fail "sim from a file (exit $?)"
check sim y.txt
limited inv --poly "$poly" --range 0,40 - < y.txt > xi.txt || fail "inv from standard input (exit $?)"
check inv xi.txt
paste x.txt xi.txt | awk '{ e = $2 - $1; if (e < 0) e = -e; if (e > m) m = e }
    END { printf "inv(sim(x)) - x: max %.3g\n", m; exit !(m <= 1e-5) }' || fail "inv(sim(x)) != x"
cat x.txt | limited pi --weights 1,0.5 --thresholds 0,1 > p.txt || fail "pi from a pipe (exit $?)"
check pi p.txt
[ -z "$(ls "$TMPDIR" | grep -v -e '^x.txt$' -e '^y.txt$' -e '^xi.txt$' -e '^p.txt$')" ] ||
    fail "temporary files left: $(ls "$TMPDIR")"
echo "sim, inv, pi: $rows samples each within $limit_kb KB of address space"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Right or refused at the edges of the tool's files: `fit` never writes its
# model file or header over the record it reads, nor the one over the other
# (the record and the first file written are kept byte for byte); a model
# file whose domain is empty is refused by its reader, naming its lines, not
# an option that was not given; a record of inputs spanning 1e-300 is called
# too small, not too large; a UTF-8 byte-order mark before a record's first
# line is skipped (it is not a bad number); the crafted model files of
# tests/model_files are read or refused as their names say.
#   outputs.sh <hyst> <work dir> <model files dir>
set -euo pipefail
tool=$1 work=$2 crafted=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
# refused <text> <cmd>...: exit status 1, nothing on stdout, <text> in the message
refused() {
    local text=$1 rc=0
    shift
    "$tool" "$@" > out.txt 2> err.txt || rc=$?
    [ "$rc" -eq 1 ] || fail "exit status $rc (expected 1): $*"
    [ ! -s out.txt ] || fail "output printed: $*"
    grep -qF -- "$text" err.txt || fail "message '$(cat err.txt)' lacks '$text': $*"
}

# a major loop of f0(x) = x^2 + x on [0, 2], twice
awk 'BEGIN { for (c = 0; c < 2; c++) { for (i = 0; i <= 20; i++) { x = i / 10; print x, x * x + x }
             for (i = 19; i > 0; i--) { x = i / 10; print x, 6 - (2 - x) ^ 2 - (2 - x) } } print 0, 0 }' > rec.csv
cp rec.csv rec.orig
refused "option --save: rec.csv is the record being read" fit --degree 2 --save rec.csv rec.csv
refused "is the record being read" fit --degree 2 --save ./rec.csv rec.csv
cmp -s rec.csv rec.orig || fail "--save over the record changed it"
cp rec.csv loop.h
refused "option --header: loop.h is the record being read" fit --degree 2 --header loop loop.h
cmp -s loop.h rec.orig || fail "--header over the record changed it"
refused "options --header and --save both name f0.h" fit --degree 2 --save f0.h --header f0 rec.csv
[ ! -e f0.h ] || fail "f0.h written"
"$tool" fit --degree 2 --header f0 rec.csv > /dev/null 2>&1 || fail "fit --header"
cp f0.h f0.orig
refused "options --header and --save both name" fit --degree 2 --save ./f0.h --header f0 rec.csv
cmp -s f0.h f0.orig || fail "an existing header was replaced"
"$tool" fit --degree 2 --save m.hyst --header f1 rec.csv > /dev/null 2>&1 || fail "distinct outputs"
[ -s m.hyst ] && [ -s f1.h ] || fail "distinct outputs not written"

# a target that is not a regular file: a pipe (or a device: as root, --save /dev/null
# replaced the system's /dev/null with the model's text) is refused, left as it was;
# a symbolic link is written through: the file it names replaced, the link kept
mkfifo pipe.hyst
refused "pipe.hyst: not a regular file (a device, pipe or socket): cannot write the model file" \
    fit --degree 2 --save pipe.hyst rec.csv
[ -p pipe.hyst ] || fail "the pipe was replaced"
mkfifo pipe.h
refused "pipe.h: not a regular file (a device, pipe or socket): cannot write the header" \
    fit --degree 2 --header pipe rec.csv
[ -p pipe.h ] || fail "the pipe was replaced"
refused "pipe.h: not a regular file" header --model m.hyst pipe
[ -p pipe.h ] || fail "the pipe was replaced by header"
mkdir -p models
cp m.hyst models/v1.hyst
ln -s models/v1.hyst link.hyst
"$tool" fit --degree 1 --save link.hyst rec.csv > /dev/null 2>&1 || fail "--save through a link"
[ -L link.hyst ] || fail "--save replaced the symbolic link by a file"
grep -q '^coeffs [^ ]* [^ ]*$' models/v1.hyst || fail "--save did not write the file the link names"
ln -s nowhere/m.hyst dangling.hyst
refused "dangling.hyst: a symbolic link to nothing" fit --degree 1 --save dangling.hyst rec.csv
[ -L dangling.hyst ] || fail "the dangling link was replaced"

# a model file with lo > hi: its reader's refusal, naming file, line and field
printf 'hyst-model-text 1\nkind poly\nhi 1\nlo 2\ncoeffs 1 0\n' > inverted.hyst
echo 1.5 > x.txt
for cmd in sim inv; do
    refused "inverted.hyst:4: field 2: the domain is empty: hi '1' is not above lo '2'" \
        $cmd --model inverted.hyst x.txt
    grep -q -- "--range" err.txt && fail "$cmd blames --range: $(cat err.txt)"
done

# inputs spanning 1e-300: coefficients of x^k overflow because the inputs are small
awk 'BEGIN { for (i = 0; i < 200; i++) { x = (i % 50) / 50; print x * 1e-300, (x + 0.1 * x * x) * 1e-300 } }' > tiny.txt
refused "the inputs span only 9.8e-301: the numbers are too small, rescale them" fit --degree 3 tiny.txt
grep -q "too large" err.txt && fail "tiny inputs called too large"

# a UTF-8 byte-order mark before the first line: skipped, the same numbers
printf '\xef\xbb\xbf0;1\n1;2\n2;3.5\n' > bom.csv
printf '0;1\n1;2\n2;3.5\n' > plain.csv
"$tool" sim --poly 1,0 --range 0,4 --xcol 2 bom.csv > bom.out 2>&1 || fail "bom: $(cat bom.out)"
"$tool" sim --poly 1,0 --range 0,4 --xcol 2 plain.csv > plain.out 2>&1
cmp -s bom.out plain.out || fail "bom: $(cat bom.out) differs from $(cat plain.out)"
# not elsewhere: a mark inside the record is a bad number, quoted
printf '0;1\n\xef\xbb\xbf1;2\n' > bom2.csv
refused "bom2.csv:2: field 1: '\\xef\\xbb\\xbf1'" sim --poly 1,0 --range 0,3 bom2.csv

# the crafted model files: ok_* read, bad_* refused naming the file
n=0
for f in "$crafted"/*.hyst; do
    name=$(basename "$f")
    rc=0
    "$tool" header --model "$f" --dir . m > /dev/null 2> err.txt || rc=$?
    case $name in
    ok_*) [ "$rc" -eq 0 ] || fail "$name refused: $(cat err.txt)" ;;
    *) [ "$rc" -eq 1 ] && grep -qF "hyst header: $f" err.txt || fail "$name: rc $rc, $(cat err.txt)" ;;
    esac
    n=$((n + 1))
done
[ "$n" -ge 45 ] || fail "only $n crafted model files"
echo "outputs.sh: ok ($n crafted model files)"

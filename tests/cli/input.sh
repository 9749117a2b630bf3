#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Input that cannot be a committed text file (raw bytes, NUL, 1 MB lines, ...):
# generated here, then `hyst` must fail as expect_fail.cmake checks (exit
# status != 0, nothing on standard output, the expected message on standard
# error), or succeed as stated.
#   input.sh <hyst> <work dir> <case>
set -euo pipefail
tool=$1 work=$2/$3 case=$3
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_fail <text> <arg>...: `hyst <arg>...` fails, prints nothing on
# stdout, and its message on stderr contains <text> (a fixed string).
expect_fail() {
    local text=$1 rc=0
    shift
    "$tool" "$@" > out.txt 2> err.txt || rc=$?
    [ "$rc" -ne 0 ] || fail "exit status 0 for: hyst $*"
    [ ! -s out.txt ] || fail "something printed as a result: $(head -c 200 out.txt | cat -v)"
    grep -qF -- "$text" err.txt || fail "message does not contain '$text': $(head -c 400 err.txt | cat -v)"
    echo "exit $rc: $(head -c 400 err.txt | cat -v)"
}
# no_raw_bytes: the message holds printable ASCII only (no ESC, CR, NUL, 0xff...)
no_raw_bytes() {
    if LC_ALL=C grep -q '[^ -~]' err.txt; then
        fail "raw bytes in the message: $(cat -v err.txt)"
    fi
}

case $case in
escape_bytes) # terminal escape sequences and non-ASCII bytes are quoted as \xNN
    printf '0 1\n1 \033[31m\377A\033[0m\r\n' > esc.txt
    expect_fail "esc.txt:2: field 2: '\\x1b[31m\\xffA\\x1b[0m' is not a finite number" fit --degree 1 esc.txt
    no_raw_bytes
    expect_fail "option --method: '\\x1b]0;title\\x07' is not joint, reflect or branches" \
        fit --degree 1 --method $'\033]0;title\007' esc.txt
    no_raw_bytes
    expect_fail "bad\\x1bname.txt: cannot open" sim --poly 1,0 --range 0,1 $'bad\033name.txt'
    no_raw_bytes
    ;;
long_field) # a 1 MB field: its first 40 characters, "..." and its length
    { printf '0\n'; head -c 1048576 /dev/zero | tr '\0' 7; printf 'x\n'; } > long.txt
    expect_fail "long.txt:2: field 1: '7777777777777777777777777777777777777777...' (1048577 bytes) is not a finite number" \
        pi --weights 1 --thresholds 0 long.txt
    [ "$(wc -c < err.txt)" -lt 300 ] || fail "message of $(wc -c < err.txt) bytes"
    expect_fail "option --weights: item 1 '7777777777777777777777777777777777777777...' (1001 bytes) is not a finite number" \
        pi --weights "$(head -c 1000 /dev/zero | tr '\0' 7)x" --thresholds 0 long.txt
    [ "$(wc -c < err.txt)" -lt 300 ] || fail "message of $(wc -c < err.txt) bytes"
    # a line of 16 MB or more (a binary file without newlines): refused, memory bounded
    head -c 17000000 /dev/zero | tr '\0' 7 > huge.txt
    expect_fail "<stdin>:1: line of 16 MB or more" sim --poly 1,0 --range 0,1 - < huge.txt
    rm huge.txt
    ;;
nul_byte) # a NUL byte would end the line early, silently: refused with its place
    printf '0 1\n1 2\0 junk\n2 3\n' > nul.txt
    expect_fail "nul.txt:2: NUL byte at column 4" fit --degree 1 nul.txt
    printf '0\n\0\n1\n' | expect_fail "<stdin>:2: NUL byte at column 1" sim --poly 1,0 --range 0,1
    printf 'hyst-model-text 1\nkind poly\nlo 0\nhi 4\0\ncoeffs 1 0\n' > nul.hyst
    expect_fail "nul.hyst:4: field 2: NUL byte at column 5" sim --model nul.hyst nul.txt
    ;;
stdin_directory) # a directory as standard input: named as such, not "read error"
    expect_fail "<stdin>: is a directory" inv --poly 1,0 --range 0,1 < .
    expect_fail "<stdin>: is a directory" fit --degree 1 - < .
    ;;
cr_line_ends) # lines ended by CR alone (an old Mac export): read as lines, as model files
    printf '# x\r0\r1\r\r2\r' > cr.txt
    "$tool" pi --weights 1 --thresholds 0 cr.txt > out.txt 2> err.txt || fail "CR: $(cat err.txt)"
    [ "$(tr '\n' ' ' < out.txt)" = "0 1 2 " ] || fail "CR: $(cat -v out.txt)"
    printf '0 1\r\n1 x\r2 3\r' > crmix.txt # CR LF and CR: line 2 named
    expect_fail "crmix.txt:2: field 2: 'x' is not a finite number" fit --degree 1 crmix.txt
    ;;
*)
    fail "unknown case '$case'"
    ;;
esac

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hyst fit --header NAME` replaces NAME.h only when the whole command
# succeeds: the header goes to a temporary file in the same directory,
# synced, then renamed over NAME.h. A failure (header write error, file-size
# limit, standard output error) leaves an existing NAME.h byte for byte, no
# new one, no temporary file, and a message with the reason.
#   header.sh <hyst> <work dir> <case>
set -euo pipefail
tool=$1 work=$2/$3 case=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# a major loop of f0(x) = x^2 + x on [0, 2], twice
awk 'BEGIN { for (c = 0; c < 2; c++) { for (i = 0; i <= 20; i++) { x = i / 10; print x, x * x + x }
             for (i = 19; i > 0; i--) { x = i / 10; print x, 6 - (2 - x) ^ 2 - (2 - x) } } print 0, 0 }' > loop.txt
"$tool" fit --degree 2 --header f0 loop.txt > /dev/null 2>&1 || fail "fit --header on good input"
cp f0.h good.h
# only_files <name>...: the directory holds exactly these files
only_files() {
    local want have
    want=$(printf '%s\n' loop.txt good.h "$@" | sort)
    have=$(ls -A | sort)
    [ "$have" = "$want" ] || fail "files: $(echo $have) (expected $(echo $want))"
}
# failing <text> <cmd>...: the command fails, its message contains <text>
failing() {
    local text=$1 rc=0
    shift
    "$@" 2> err.txt || rc=$?
    [ "$rc" -ne 0 ] || fail "exit status 0 for: $*"
    grep -qF -- "$text" err.txt || fail "message does not contain '$text': $(cat err.txt)"
    echo "exit $rc: $(cat err.txt)" >&2
    rm -f err.txt
}

case $case in
header_mode) # a new header is an ordinary file (0666 less the umask), not 0600
    rm f0.h
    (umask 022 && "$tool" fit --degree 2 --header f0 loop.txt > /dev/null 2>&1)
    [ "$(stat -c %a f0.h)" = 644 ] || fail "mode $(stat -c %a f0.h), expected 644"
    cmp -s f0.h good.h || fail "header differs from the first run"
    ;;
header_size_limit) # ulimit -f: the header cannot be written; the old one stays whole
    # limited <KB> <arg>...: hyst under a file-size limit; its message reaches
    # err.txt through a pipe (the limit would stop a write to the file)
    limited() {
        local kb=$1
        shift
        bash -c 'ulimit -f "$1" && shift && exec "$0" "$@"' "$tool" "$kb" "$@" 2>&1 > /dev/null | cat >&2
        return "${PIPESTATUS[0]}"
    }
    failing "f0.h: cannot write the header: File too large" limited 0 fit --degree 2 --header f0 loop.txt
    cmp -s f0.h good.h || fail "the existing header was changed (limit 0)"
    only_files f0.h
    # 1 KB and a longer header (a long input path in its comment): cut mid-token before
    long=$(printf 'd%.0s' {1..250})/$(printf 'e%.0s' {1..250})
    mkdir -p "$long"
    cp loop.txt "$long/"
    failing "f0.h: cannot write the header: File too large" \
        limited 1 fit --degree 2 --header f0 "$long/loop.txt"
    cmp -s f0.h good.h || fail "the existing header was changed (limit 1 KB)"
    rm -r "${long%%/*}"
    only_files f0.h
    failing "f1.h: cannot write the header: File too large" limited 0 fit --degree 2 --header f1 loop.txt
    only_files f0.h
    ;;
header_stdout_full) # the results cannot be printed: no header is written or replaced
    printf '/* an older header */\n' > f0.h
    cp f0.h old.h
    failing "write error on standard output: No space left on device" \
        "$tool" fit --degree 2 --header f0 loop.txt > /dev/full
    cmp -s f0.h old.h || fail "the existing header was replaced"
    failing "write error on standard output" "$tool" fit --degree 2 --header f1 loop.txt > /dev/full
    only_files f0.h old.h
    ;;
header_is_directory) # NAME.h is a directory: said before anything is printed
    mkdir f1.h
    failing "f1.h: is a directory" "$tool" fit --degree 2 --header f1 loop.txt > out.txt
    [ ! -s out.txt ] || fail "results printed: $(cat out.txt)"
    rm out.txt
    only_files f0.h f1.h
    ;;
header_dir) # --header-dir DIR: DIR/NAME.h, the same text; nothing in the current directory
    "$tool" fit --degree 2 --header f1 loop.txt > /dev/null 2>&1 || fail "fit --header f1"
    mv f1.h want.h
    mkdir out
    "$tool" fit --degree 2 --header f1 --header-dir out loop.txt > /dev/null 2> err.txt ||
        fail "fit --header-dir: $(cat err.txt)"
    grep -qF "wrote out/f1.h" err.txt || fail "message: $(cat err.txt)"
    rm err.txt
    cmp -s out/f1.h want.h || fail "out/f1.h differs from the header written without --header-dir"
    [ "$(ls -A out)" = f1.h ] || fail "files in out: $(ls -A out)"
    "$tool" fit --degree 2 --header f0 --header-dir "$PWD/out/" loop.txt > /dev/null 2>&1 ||
        fail "fit --header-dir with an absolute path and a trailing /"
    cmp -s out/f0.h good.h || fail "out/f0.h differs from ./f0.h"
    rm -r out want.h
    only_files f0.h
    ;;
header_dir_errors) # a missing directory, a file, no --header: refused before anything is printed
    failing "option --header-dir: 'nodir': No such file or directory" \
        "$tool" fit --degree 2 --header f1 --header-dir nodir loop.txt > out.txt
    failing "option --header-dir: 'loop.txt': not a directory" \
        "$tool" fit --degree 2 --header f1 --header-dir loop.txt loop.txt >> out.txt
    failing "option --header-dir needs --header NAME" \
        "$tool" fit --degree 2 --header-dir . loop.txt >> out.txt
    [ ! -s out.txt ] || fail "results printed: $(cat out.txt)"
    rm out.txt
    only_files f0.h
    ;;
*)
    fail "unknown case '$case'"
    ;;
esac

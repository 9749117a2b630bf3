#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's firmware example, compiled as written (its first C block,
# with the board's prototypes included before it) and run on a board that
# checks what it publishes, writes to flash and does on a reset request.
#   readme_c.sh <README.md> <C compiler> <include dir> <libhyst.a> <work dir> [flags]
# flags: the build's own C flags (sanitizers), for compiling and linking.
set -euo pipefail
readme=$1 cc=$2 inc=$3 lib=$4 work=$5
read -r -a flags <<<"${6:-}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mkdir -p "$work"
awk '/^```c$/ && !done { inside = 1; next } /^```$/ && inside { inside = 0; done = 1 } inside' \
    "$readme" > "$work/readme_example.c"
[ -s "$work/readme_example.c" ] || { echo "FAIL: no C block in $readme"; exit 1; }
"$cc" "${flags[@]}" -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror -I"$inc" -I"$here" \
    -include "$here/board.h" -c "$work/readme_example.c" -o "$work/readme_example.o"
"$cc" "${flags[@]}" -std=c99 -Wall -Wextra -Werror -I"$inc" -I"$here" -c "$here/board.c" \
    -o "$work/board.o"
"$cc" "${flags[@]}" "$work/readme_example.o" "$work/board.o" "$lib" -lm -o "$work/readme_example"
"$work/readme_example"

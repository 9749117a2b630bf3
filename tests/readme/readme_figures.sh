#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The figures the README states next to its firmware example, checked: the
# example (its first C block) built for a Cortex-M4F as written, with the
# library at -Os, sections and --gc-sections, newlib-nano.
#   RAM   = the sizes of the example's own data and bss objects (nm);
#   flash = text + data of the linked image minus the same board linked
#           with empty example functions (tests/readme/board_m4.c);
#           again with -DHYST_NO_DOUBLE (library and example).
# The README writes them as "**N bytes of RAM**", "**N bytes of flash**" and
# "**N bytes** with `HYST_NO_DOUBLE`" (digits, optionally grouped by spaces).
# (Warnings are readme_c's: the example's double literals would warn in a
# HYST_NO_DOUBLE build, where a firmware writes float ones.)
# RAM is fixed by the ABI and always compared; flash depends on the compiler,
# so it is compared when arm-none-eabi-gcc is the version the README names
# ("arm-none-eabi-gcc X.Y"), and only printed otherwise.
#   readme_figures.sh <README.md> <source root> <work dir>
# Exit 77 (skipped) without arm-none-eabi-gcc.
set -euo pipefail
shopt -s inherit_errexit # a failed build inside $(image ...) fails the test
readme=$1 root=$2 work=$3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cc=arm-none-eabi-gcc
command -v "$cc" >/dev/null 2>&1 || { echo "SKIP: no $cc"; exit 77; }
mkdir -p "$work"
F=(-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -ffunction-sections -fdata-sections
   -std=c99 -Wall -Wextra -Werror -I"$root/include" -I"$here")
L=(--specs=nosys.specs --specs=nano.specs -Wl,--gc-sections)

awk '/^```c$/ && !done { inside = 1; next } /^```$/ && inside { inside = 0; done = 1 } inside' \
    "$readme" > "$work/example.c"
[ -s "$work/example.c" ] || { echo "FAIL: no C block in $readme"; exit 1; }

stated() { # <pattern with one group of digits and spaces>: the README's figure, digits only
    sed -n "s/.*$1.*/\1/p" "$readme" | head -n 1 | tr -d ' '
}
want_ram=$(stated '\*\*\([0-9][0-9 ]*\) bytes of RAM\*\*')
want_flash=$(stated '\*\*\([0-9][0-9 ]*\) bytes of flash\*\*')
want_nd=$(stated '\*\*\([0-9][0-9 ]*\) bytes\*\* with `HYST_NO_DOUBLE`')
want_cc=$(sed -n 's/.*arm-none-eabi-gcc \([0-9][0-9]*\.[0-9][0-9]*\).*/\1/p' "$readme" | head -n 1)
for v in want_ram want_flash want_nd want_cc; do
    [ -n "${!v}" ] || { echo "FAIL: README.md states no ${v#want_} figure next to the example"; exit 1; }
done

image() { # <name> <sources file> [defines...]: the library, the example and the two images; prints the flash
    local name=$1 sources=$2; shift 2
    local dir="$work/$name"
    rm -rf "$dir/lib"
    mkdir -p "$dir/lib"
    xargs -P 2 -I{} sh -c \
        'f={}; exec "$0" "$@" -I"'"$root"'/src" -c "$f" -o "'"$dir"'/lib/$(basename "$f" .c).o"' \
        "$cc" "${F[@]}" "$@" <"$sources"
    rm -f "$dir/libhyst.a"
    arm-none-eabi-ar rcs "$dir/libhyst.a" "$dir"/lib/*.o
    "$cc" "${F[@]}" "$@" -include "$here/board.h" -c "$work/example.c" -o "$dir/example.o"
    "$cc" "${F[@]}" "$@" -c "$here/board_m4.c" -o "$dir/board.o"
    "$cc" "${F[@]}" "$@" -DREADME_EMPTY_EXAMPLE -c "$here/board_m4.c" -o "$dir/board_empty.o"
    "$cc" "${F[@]}" "$dir/example.o" "$dir/board.o" "$dir/libhyst.a" "${L[@]}" -Wl,-Map="$dir/example.map" \
        -lm -o "$dir/example.elf"
    "$cc" "${F[@]}" "$dir/board_empty.o" "${L[@]}" -lm -o "$dir/empty.elf"
    local with without
    with=$(arm-none-eabi-size "$dir/example.elf" | awk 'NR == 2 { print $1 + $2 }')
    without=$(arm-none-eabi-size "$dir/empty.elf" | awk 'NR == 2 { print $1 + $2 }')
    echo $((with - without))
}

ls "$root"/src/*.c >"$work/all_sources"
flash=$(image default "$work/all_sources")
# The HYST_NO_DOUBLE image links the same members: compile only those (a missing one fails the link).
sed -n 's/.*libhyst\.a(\([a-z0-9_]*\)\.o).*/\1/p' "$work/default/example.map" | sort -u |
    sed "s|.*|$root/src/&.c|" >"$work/linked_sources"
flash_nd=$(image no_double "$work/linked_sources" -DHYST_NO_DOUBLE)
# RAM: the example's own objects (data and bss, any binding), as laid out for the M4F.
ram=$(arm-none-eabi-nm -S --radix=d "$work/default/example.o" |
      awk 'NF == 4 && $3 ~ /^[bBdD]$/ { s += $2 } END { print s + 0 }')
have_cc=$("$cc" -dumpversion | cut -d. -f1,2)

fail=0
echo "RAM: README $want_ram bytes, measured $ram"
[ "$ram" -eq "$want_ram" ] || { echo "FAIL: the example's RAM is $ram bytes, README.md says $want_ram"; fail=1; }
echo "flash: README $want_flash bytes, measured $flash (arm-none-eabi-gcc $have_cc)"
echo "flash with HYST_NO_DOUBLE: README $want_nd bytes, measured $flash_nd"
if [ "$have_cc" = "$want_cc" ]; then
    [ "$flash" -eq "$want_flash" ] ||
        { echo "FAIL: the example's flash is $flash bytes, README.md says $want_flash"; fail=1; }
    [ "$flash_nd" -eq "$want_nd" ] ||
        { echo "FAIL: with HYST_NO_DOUBLE the example's flash is $flash_nd bytes, README.md says $want_nd"; fail=1; }
else
    echo "flash not compared: README.md states arm-none-eabi-gcc $want_cc, this is $have_cc"
fi
[ "$fail" -eq 0 ] && echo "readme figures: as stated"
exit $fail

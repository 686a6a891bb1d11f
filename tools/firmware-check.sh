#!/bin/sh
# firmware-check: build csrc/ for bare-metal targets and prove it needs no
# floating point, no heap and no stdio.  For each compiler found it compiles
# every core file freestanding, lists the undefined symbols each object
# needs (nm -u), fails on any that is not an integer-arithmetic helper or
# memset/memcpy/memmove, and prints the .text bytes of each file and of the
# whole core; then the code typical applications link (tools/firmware/apps.sh).
# Cortex-M0 (arm-none-eabi-gcc) is required: the size budgets are its.  rv32
# (riscv64-unknown-elf-gcc) is checked where that compiler is installed, and
# said to be skipped where it is not.
#
#   tools/firmware-check.sh [OUTDIR]      (make firmware-check)
set -eu
out=${1:-build/fw}
common="-std=c99 -pedantic -Wall -Wextra -Werror -Os -ffreestanding -ffunction-sections -fdata-sections -Icsrc/include -Icsrc/src"

# name | compiler | flags | nm | size
targets="cortex-m0|arm-none-eabi-gcc|-mcpu=cortex-m0 -mthumb|arm-none-eabi-nm|arm-none-eabi-size
rv32imac|riscv64-unknown-elf-gcc|-march=rv32imac -mabi=ilp32 --specs=picolibc.specs|riscv64-unknown-elf-nm|riscv64-unknown-elf-size"

# Symbols a core object may need: the string.h trio and the compiler's
# integer helpers (64-bit division and shifts on 32-bit machines).
allowed='^(memset|memcpy|memmove|__aeabi_(l|ul)divmod|__aeabi_(i|ui)divmod|__aeabi_(i|ui)div|__aeabi_l(lsl|lsr|asr)|__aeabi_lmul|__aeabi_lcmp|__aeabi_ulcmp|__(u)?(div|mod|mul)di3|__(a|l)shrdi3|__ashldi3|__(u)?cmpdi2|__clzsi2|__clzdi2|__ctzsi2|__ctzdi2)$'
status=0
built=0
for t in $(printf '%s\n' "$targets" | tr ' ' '~'); do
  t=$(printf '%s' "$t" | tr '~' ' ')
  name=$(echo "$t" | cut -d'|' -f1); cc=$(echo "$t" | cut -d'|' -f2)
  flags=$(echo "$t" | cut -d'|' -f3); nm=$(echo "$t" | cut -d'|' -f4); sz=$(echo "$t" | cut -d'|' -f5)
  if ! command -v "$cc" >/dev/null 2>&1; then
    if [ "$name" = cortex-m0 ]; then
      echo "firmware-check: $name: $cc not installed (required; on Debian: apt-get install gcc-arm-none-eabi)"
      status=1
    else
      printf '\n%s: skipped: %s not installed\n' "$name" "$cc"
    fi
    continue
  fi
  rm -rf "$out/$name"; mkdir -p "$out/$name"
  total=0
  printf '\n%s (%s %s -Os)\n' "$name" "$cc" "$flags"
  printf '  %-14s %8s\n' file ".text B"
  for src in csrc/src/*/*.c; do
    obj="$out/$name/$(basename "$src" .c).o"
    # shellcheck disable=SC2086
    $cc $common $flags -c "$src" -o "$obj"
    text=$($sz -A "$obj" | awk '$1 ~ /^\.text/ {s += $2} END {print s + 0}')
    total=$((total + text))
    printf '  %-14s %8d\n' "$(basename "$src")" "$text"
  done
  printf '  %-14s %8d\n' "core" "$total"
  # The same core as one file (make single), as a firmware build drops it in.
  if [ -f build/single/rastrum.c ]; then
    # shellcheck disable=SC2086
    $cc $common $flags -Ibuild/single -c build/single/rastrum.c -o "$out/$name/single.o"
    whole=$($sz -A "$out/$name/single.o" | awk '$1 ~ /^\.text/ {s += $2} END {print s + 0}')
    printf '  %-14s %8d\n' "single file" "$whole"
    printf 'whole core %s: %d B\n' "$name" "$whole"
  fi
  # What the core as a whole needs from outside: undefined in some object,
  # defined in none.
  $nm --defined-only "$out/$name"/*.o | awk 'NF == 3 {print $3}' | sort -u > "$out/$name/defined"
  $nm -u "$out/$name"/*.o | awk 'NF >= 2 {print $NF}' | sort -u > "$out/$name/undefined"
  needs=$(comm -23 "$out/$name/undefined" "$out/$name/defined")
  bad=$(printf '%s\n' $needs | grep -Ev "$allowed" || true)
  echo "  needs from outside: $(echo $needs)"
  if [ -n "$bad" ]; then
    echo "  FORBIDDEN: $(echo $bad)"; status=1
  fi
  built=$((built + 1))
done
# What typical applications link, from the one-file build (tools/firmware/apps.sh).
if [ -f build/single/rastrum.c ] && command -v arm-none-eabi-gcc >/dev/null 2>&1; then
  echo
  tools/firmware/apps.sh "$out/apps" || status=1
fi
[ "$built" -gt 0 ] || status=1
[ "$status" -eq 0 ] && echo "firmware-check: ok" || echo "firmware-check: FAILED"
exit "$status"

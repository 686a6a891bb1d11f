#!/bin/sh
# cross-check: the C tests on other machines, and the same pixels there.
# Builds tests/c/test_*.c and tests/c/hash_scenes.c natively and for 32-bit
# ARM (arm-linux-gnueabihf) and big-endian MIPS (mips-linux-gnu), runs the
# foreign ones under qemu-user, and compares the scene hashes byte for byte
# with the native run.  The tests run their quick count of random cases
# (RAST_TEST_QUICK) under qemu; the scene hashes are all computed.
#
#   tools/cross-check.sh [OUTDIR]        (make cross-check)
set -eu
out=${1:-build/cross}
flags="-std=c99 -pedantic -Wall -Wextra -Werror -O2 -Icsrc/include -Icsrc/src -Itests/c"
src=$(ls csrc/src/*/*.c)
rm -rf "$out"; mkdir -p "$out"

# shellcheck disable=SC2086
${CC:-cc} $flags tests/c/hash_scenes.c $src -o "$out/hash-native"
"$out/hash-native" > "$out/native.txt"
echo "native: $(wc -l < "$out/native.txt") scene hashes"

status=0
for m in "arm|arm-linux-gnueabihf-gcc|qemu-arm" "mips|mips-linux-gnu-gcc|qemu-mips"; do
  name=${m%%|*}; rest=${m#*|}; cc=${rest%%|*}; qemu=${rest#*|}
  if ! command -v "$cc" >/dev/null 2>&1 || ! command -v "$qemu" >/dev/null 2>&1; then
    echo "cross-check: $cc or $qemu not installed"; status=1; continue
  fi
  # The core once per machine (a static library), then each test links it:
  # compiling the whole core again for every test was most of this stage.
  mkdir -p "$out/obj-$name"
  for f in $src; do
    # shellcheck disable=SC2086
    $cc $flags -c "$f" -o "$out/obj-$name/$(basename "$f" .c).o"
  done
  ${cc%gcc}ar rcs "$out/librastrum-$name.a" "$out/obj-$name"/*.o
  for t in tests/c/test_*.c; do
    exe="$out/$(basename "$t" .c)-$name"
    # shellcheck disable=SC2086
    # (-lm: test_glue_rings compiles the binding's glue in, whose snap uses
    # floor; the core never does)
    $cc $flags -static "$t" "$out/librastrum-$name.a" -lm -o "$exe"
    printf '%s on %s: ' "$(basename "$t" .c)" "$name"
    if RAST_TEST_QUICK=1 "$qemu" "$exe" > "$exe.log" 2>&1; then tail -1 "$exe.log"; else
      echo "FAILED"; tail -5 "$exe.log"; status=1
    fi
  done
  # shellcheck disable=SC2086
  $cc $flags -static tests/c/hash_scenes.c "$out/librastrum-$name.a" -o "$out/hash-$name"
  "$qemu" "$out/hash-$name" > "$out/$name.txt"
  if cmp -s "$out/native.txt" "$out/$name.txt"; then
    echo "$name: $(wc -l < "$out/$name.txt") scene hashes, identical to native"
  else
    echo "$name: scene hashes DIFFER from native:"; diff "$out/native.txt" "$out/$name.txt" | head -5
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "cross-check: ok" || echo "cross-check: FAILED"
exit "$status"

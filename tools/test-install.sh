#!/usr/bin/env bash
# test-install.sh - the C packaging as a user meets it (make test-install):
#  1. the README's C example and its install-and-build commands, copied from
#     README.md, run as written (HOME is a scratch folder; `make` is this
#     tree's Makefile), and the CMake project the README shows builds the
#     same example through find_package(rastrum);
#  2. two installs with different PREFIXes each get a .pc and a CMake
#     package naming their own PREFIX;
#  3. examples/draw_ppm.c builds through pkg-config against a staged
#     install, by hand and by `make example` (whose binary must run without
#     LD_LIBRARY_PATH); DESTDIR is honoured (LICENSE and CHANGELOG.md go to
#     share/doc/rastrum) and uninstall removes what install put.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$root/build/test-install
rm -rf "$work"
mkdir -p "$work/home" "$work/readme"
passed=0
ok() { passed=$((passed + 1)); }
fail() { echo "test-install: FAILED: $*" >&2; echo "test-install: $passed passed, 1 failed"; exit 1; }

# The first ```c block of README.md, or the first ```sh or ```cmake block
# after it.
extract() {
  python3 - "$root/README.md" "$1" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
blocks = re.findall(r"^```(\w*)\n(.*?)^```$", text, re.S | re.M)
start = next(i for i, (lang, _) in enumerate(blocks) if lang == "c")
want = sys.argv[2]
for lang, body in blocks[start:]:
    if lang == want:
        sys.stdout.write(body)
        break
else:
    sys.exit("README.md has no ```%s block after its first ```c block" % want)
PY
}

# 1. The README, as written.
cd "$work/readme"
extract c > quad.c
extract sh > steps.sh
extract cmake > CMakeLists.txt
grep -q 'int main' quad.c || fail "the README's C example has no main()"
(
  export HOME=$work/home
  make() { command make --no-print-directory -C "$root" "$@" >/dev/null; }
  set -e
  # shellcheck disable=SC1091
  . ./steps.sh
) > steps.log 2>&1 || { cat steps.log; fail "the README's install-and-build steps"; }
test -s quad.pgm && head -c 15 quad.pgm | grep -q '^P5 320 240 255' || fail "quad.pgm not written"
ok
if command -v cmake >/dev/null 2>&1; then
  cmake -S . -B build -DCMAKE_PREFIX_PATH="$work/home/.local" -DCMAKE_C_FLAGS="-Wall -Wextra -Werror" \
    > cmake.log 2>&1 && cmake --build build >> cmake.log 2>&1 || { cat cmake.log; fail "the README's CMake project"; }
  ./build/quad cmake.pgm && cmp -s quad.pgm cmake.pgm || fail "the CMake build draws another image"
  ok
else
  fail "cmake is not installed"
fi

# 2. Each install's .pc and CMake package name its own PREFIX.
for p in a b; do
  command make --no-print-directory -C "$root" install PREFIX="$work/prefix-$p" >/dev/null
done
for p in a b; do
  pc=$work/prefix-$p/lib/pkgconfig/rastrum.pc
  grep -qx "prefix=$work/prefix-$p" "$pc" || fail "$pc does not name prefix-$p"
  [ "$(PKG_CONFIG_PATH=$work/prefix-$p/lib/pkgconfig pkg-config --variable=libdir rastrum)" = "$work/prefix-$p/lib" ] \
    || fail "pkg-config --variable=libdir for prefix-$p"
  grep -q "$work/prefix-$p/lib" "$work/prefix-$p/lib/cmake/rastrum/rastrum-config.cmake" \
    || fail "the CMake package of prefix-$p"
  ok
done

# 3. draw_ppm through pkg-config; DESTDIR; uninstall.
cc -std=c99 -pedantic -Wall -Wextra -Werror "$root/examples/draw_ppm.c" \
  $(PKG_CONFIG_PATH=$work/prefix-b/lib/pkgconfig pkg-config --cflags --libs rastrum) \
  -Wl,-rpath,"$work/prefix-b/lib" -o "$work/draw_ppm"
"$work/draw_ppm" "$work/draw_ppm.ppm"
ok
# make example against that PREFIX (not one the loader searches): the binary
# it builds must run with no LD_LIBRARY_PATH, and draw what the one above drew.
(unset LD_LIBRARY_PATH; PKG_CONFIG_PATH=$work/prefix-b/lib/pkgconfig \
  command make --no-print-directory -C "$root" example >"$work/example.log" 2>&1) \
  || { cat "$work/example.log"; fail "make example under PREFIX=prefix-b"; }
(unset LD_LIBRARY_PATH; "$root/build/draw_ppm" "$work/example.ppm") || fail "make example's binary does not run"
cmp -s "$work/draw_ppm.ppm" "$work/example.ppm" || fail "make example's binary draws another image"
ok
command make --no-print-directory -C "$root" install DESTDIR="$work/destdir" PREFIX=/usr >/dev/null
for f in include/rastrum.h lib/pkgconfig/rastrum.pc lib/librastrum.a lib/cmake/rastrum/rastrum-config.cmake \
         share/doc/rastrum/LICENSE share/doc/rastrum/CHANGELOG.md; do
  test -f "$work/destdir/usr/$f" || fail "DESTDIR install lacks usr/$f"
done
grep -qx 'prefix=/usr' "$work/destdir/usr/lib/pkgconfig/rastrum.pc" || fail "the staged .pc names the stage"
ok
command make --no-print-directory -C "$root" uninstall DESTDIR="$work/destdir" PREFIX=/usr >/dev/null
left=$(find "$work/destdir" -type f | wc -l)
[ "$left" -eq 0 ] || fail "uninstall left $left files"
ok
echo "test-install: $passed passed, 0 failed"

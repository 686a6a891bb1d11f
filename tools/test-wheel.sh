#!/usr/bin/env bash
# test-wheel.sh - the wheel as a user installs it (make test-wheel):
#  1. builds the wheel once, as pip does for a user (an isolated build),
#     from a copy of the tree;
#  2. checks its name says cp39-abi3 (one wheel for CPython 3.9 and later),
#     that both extension modules are *.abi3.so, and that it carries the
#     licence (License-Expression: MIT, the LICENSE file);
#  3. installs it into fresh virtualenvs of two Python versions, the oldest
#     and the newest found, and runs a few test files there against the
#     installed package (never the source tree): a 6x7 mask known by hand,
#     then the release's numbers and files (tests/test_release.py), the API
#     and error tests and the polygon fillers against the exact oracle.
#
#   tools/test-wheel.sh BUILD_PYTHON [OUTDIR]
#
# The Pythons: WHEEL_PYTHONS="/path/python3.9 /path/python3.13" when given;
# else every pyenv version (PYENV_ROOT, else ~/.pyenv) and every python3.N
# on PATH, 3.9 or newer, able to make a virtualenv.  Fewer than two found is
# a failure with the reason, never a skip.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_python=${1:?usage: tools/test-wheel.sh BUILD_PYTHON [OUTDIR]}
out=${2:-$root/build/test-wheel}
tests=${WHEEL_TESTS:-tests/test_release.py tests/test_api.py tests/test_errors.py tests/test_polygon_exact.py}
# the polygon tests but their thousand-vertex rings, at hypothesis's quick profile: a minute a Python
select=${WHEEL_K:-not thousands}
fail() { echo "test-wheel: FAILED: $*" >&2; exit 1; }

# --- the Pythons ------------------------------------------------------------
declare -A by_minor=()
consider() {
  local py=$1 v
  [ -x "$py" ] || return 0
  v=$("$py" -c 'import sys, venv, ensurepip; print("%d.%d" % sys.version_info[:2]) if sys.version_info >= (3, 9) else None' \
      2>/dev/null) || return 0
  [ -n "$v" ] && [ "$v" != None ] || return 0
  [ -n "${by_minor[$v]:-}" ] || by_minor[$v]=$py
}
if [ -n "${WHEEL_PYTHONS:-}" ]; then
  for py in $WHEEL_PYTHONS; do
    consider "$(command -v "$py" || echo "$py")"
    [ "${#by_minor[@]}" -gt 0 ] || fail "WHEEL_PYTHONS: $py is not a Python 3.9+ able to make a virtualenv"
  done
else
  for py in "${PYENV_ROOT:-$HOME/.pyenv}"/versions/3.*/bin/python3; do consider "$py"; done
  for n in $(seq 9 20); do
    p=$(command -v "python3.$n" 2>/dev/null) || continue
    # a pyenv shim answers for a version it may not have: ask for the real binary
    consider "$("$p" -c 'import sys; print(sys.executable)' 2>/dev/null || true)"
  done
  consider "$(command -v python3 2>/dev/null || true)"
fi
minors=$(printf '%s\n' "${!by_minor[@]}" | sort -t. -k1,1n -k2,2n)
count=$(printf '%s\n' $minors | grep -c . || true)
if [ "$count" -lt 2 ]; then
  fail "found ${count} Python version(s) able to make a virtualenv (${minors:-none}); the wheel must be" \
       "tried on two. Install a second (apt-get install python3.N-venv, or pyenv install 3.N) or name" \
       "two with WHEEL_PYTHONS=\"/path/python3.X /path/python3.Y\""
fi
oldest=$(printf '%s\n' $minors | head -1)
newest=$(printf '%s\n' $minors | tail -1)
echo "test-wheel: Pythons found: $(echo $minors); trying $oldest (${by_minor[$oldest]}) and $newest (${by_minor[$newest]})"

# --- 1. the wheel, built once -----------------------------------------------------
# From a copy of the tree (what is there, committed or not; without build/,
# .venv and .git): setuptools builds in the source folder, and the copy
# leaves the tree's build/ (the extension other targets built there) as
# it was.
rm -rf "$out"; mkdir -p "$out/dist" "$out/src"
tar -C "$root" --exclude=./build --exclude=./.venv --exclude=./.git --exclude=__pycache__ \
  --exclude=./.hypothesis -cf - . | tar -C "$out/src" -xf - || fail "copying the tree"
(cd "$out/src" &&
  "$build_python" -m pip wheel --quiet --disable-pip-version-check --no-deps -w "$out/dist" .) \
  > "$out/build.log" 2>&1 || { tail -30 "$out/build.log"; fail "building the wheel"; }
wheel=$(ls "$out"/dist/rastrum-*.whl)
echo "test-wheel: built $(basename "$wheel")"

# --- 2. what it says and carries -----------------------------------------------
case $(basename "$wheel") in
  rastrum-*-cp39-abi3-*.whl) ;;
  *) fail "$(basename "$wheel") is not tagged cp39-abi3" ;;
esac
"$build_python" - "$wheel" <<'PY' || fail "the wheel's contents"
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
exts = sorted(n for n in names if n.endswith(".so"))
assert exts == ["rastrum/_native.abi3.so", "rastrum/_seq.abi3.so"], exts
meta = next(n for n in names if n.endswith(".dist-info/METADATA"))
text = zipfile.ZipFile(sys.argv[1]).read(meta).decode()
assert "License-Expression: MIT" in text.splitlines(), "no License-Expression: MIT"
assert "License-File: LICENSE" in text.splitlines(), "no License-File"
assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names), "no LICENSE file"
assert "rastrum/py.typed" in names, "no py.typed"
print("test-wheel: %s and %s, License-Expression: MIT, LICENSE, py.typed" % tuple(exts))
PY

# --- 3. installed into two Pythons ------------------------------------------------
for v in "$oldest" "$newest"; do
  env_dir=$out/venv-$v
  "${by_minor[$v]}" -m venv "$env_dir" || fail "python $v: making a virtualenv"
  "$env_dir/bin/python" -m pip install --quiet --disable-pip-version-check "$wheel" pytest hypothesis \
    > "$out/install-$v.log" 2>&1 || { tail -20 "$out/install-$v.log"; fail "python $v: pip install of the wheel"; }
  # From a folder outside the tree, so that only the installed package can be imported.
  (cd "$out" && "$env_dir/bin/python" - "$env_dir" <<'PY') || fail "python $v: importing the installed wheel"
import os, sys
import numpy as np
import rastrum
where = os.path.realpath(rastrum.__file__)
assert where.startswith(os.path.realpath(sys.argv[1])), "rastrum imported from %s, not the virtualenv" % where
m = rastrum.polygon_mask([(1, 1), (5, 1), (5, 4), (1, 4)], (6, 7))
want = np.zeros((6, 7), bool); want[1:4, 1:5] = True  # pixel centres (x + 1/2, y + 1/2) inside
assert m.dtype == bool and m.shape == (6, 7) and (m == want).all(), m
print("test-wheel: python %d.%d: rastrum %s from %s" % (sys.version_info[:2] + (rastrum.__version__, where)))
PY
  # shellcheck disable=SC2086
  (cd "$out" && RASTRUM_HYPOTHESIS_PROFILE=quick "$env_dir/bin/python" -m pytest -q -p no:cacheprovider \
     --rootdir "$root" -k "$select" $(for t in $tests; do echo "$root/$t"; done)) > "$out/pytest-$v.log" 2>&1 \
    || { tail -30 "$out/pytest-$v.log"; fail "python $v: the tests against the installed wheel"; }
  echo "test-wheel: python $v: $(tail -1 "$out/pytest-$v.log")"
done
echo "test-wheel: ok"

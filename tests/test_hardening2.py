"""Issue 18 (Hardening II) at the Python level: the reproducers an outside
tester found, as tests.

- Canvas.depth was a plain attribute handed to C unchecked: a (1, 4) array
  overflowed the heap (a segfault from pure Python), an int64 one drew
  wrong pixels.  Now a checked property, checked again at each fill.
- Exact snapping of Fraction, Decimal and longdouble coordinates (they
  were rounded to float64 first: 0.5 - 2**-60 at S = 0 filled column 0).
- Depths that are not integers are refused (0.4 and 0.2 tied when
  rounded), never rounded.
- A seed fill racing a writer thread stays in its clip and returns.
- read_obj and line_pixels: memory bounded by the input, not by what a
  line of it asks for.
The bad-input rows for each are in test_bad_input.py.
"""

from __future__ import annotations

import decimal
import io
import math
import os
import subprocess
import sys
import threading
import time
import tracemalloc
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import _core
from rastrum._native import lib

from oracle import snap


def test_depth_heap_overflow_reproducer():
    """The issue's script, in a child process (on the old code it died of
    SIGSEGV): now the assignment raises InputError and nothing is drawn."""
    script = (
        "import numpy as np, rastrum\n"
        "c = rastrum.Canvas((512, 512), format='gray8')\n"
        "try:\n"
        "    c.depth = np.full((1, 4), 2**31 - 1, np.int32)\n"
        "except rastrum.InputError as e:\n"
        "    print('InputError', e)\n"
        "c.fill_triangles([[(0, 0), (512, 0), (0, 512)]], 255, depth=[[0, 0, 0]])\n"
        "print('filled', int(c.array.sum() // 255), c.depth.shape)\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ))
    assert out.returncode == 0, out.stderr
    assert "InputError depth must have the canvas's shape" in out.stdout
    assert "(512, 512)" in out.stdout.splitlines()[-1]


def test_depth_int64_of_the_right_shape_is_refused():
    c = rastrum.Canvas((6, 8), format="gray8")
    with pytest.raises(rastrum.InputError, match="int32"):
        c.depth = np.zeros((6, 8), np.int64)
    assert c.depth is None


def test_depth_reshaped_in_place_is_caught_at_the_fill():
    """An accepted buffer can change shape in place; the fill checks it
    again and writes nothing."""
    c = rastrum.Canvas((6, 8), format="gray8")
    c.fill_triangles([[(0, 0), (8, 0), (0, 6)]], 5, depth=[[3, 3, 3]])
    d = c.depth
    before = c.array.copy()
    d.shape = (8, 6)
    with pytest.raises(rastrum.InputError, match="shape"):
        c.fill_triangles([[(0, 0), (8, 0), (0, 6)]], 9, depth=[[1, 1, 1]])
    assert np.array_equal(c.array, before)
    d.shape = (6, 8)
    c.fill_triangles([[(0, 0), (8, 0), (0, 6)]], 9, depth=[[1, 1, 1]])
    assert (c.array == 9).sum() == (before == 5).sum()


def test_depth_set_by_hand_is_used():
    """A buffer set by the user takes part in the test: a far buffer lets
    the triangle draw, a near one stops it."""
    c = rastrum.Canvas((6, 8), format="gray8")
    c.depth = np.full((6, 8), -100, np.int32)
    c.fill_triangles([[(0, 0), (8, 0), (0, 6)]], 9, depth=[[0, 0, 0]])
    assert not c.array.any()
    c.depth = np.full((6, 8), 100, np.int32)
    c.fill_triangles([[(0, 0), (8, 0), (0, 6)]], 9, depth=[[0, 0, 0]])
    assert c.array.any() and (c.depth[c.array == 9] == 0).all()


def test_public_attributes_refuse_being_set():
    """Every other public attribute of a Canvas is read-only."""
    c = rastrum.Canvas((4, 4), format="gray8")
    for name in ("array", "packed", "width", "height", "format"):
        with pytest.raises(AttributeError):
            setattr(c, name, np.zeros((4, 4), np.uint8))
    settable = [n for n in dir(rastrum.Canvas) if not n.startswith("_")
                and isinstance(getattr(rastrum.Canvas, n), property)
                and getattr(rastrum.Canvas, n).fset is not None]
    assert settable == ["depth"]


# ---- exact snapping ---------------------------------------------------------------

HALF_MINUS = Fraction(1, 2) - Fraction(1, 2 ** 60)


def _column0(x1, s=0):
    """Does a rectangle from x = 0 to x1 (rows 0..1) fill column 0?"""
    c = rastrum.Canvas((1, 3), format="gray8")
    c.fill_polygon([(0, 0), (x1, 0), (x1, 1), (0, 1)], 9, subpixel_bits=s)
    return bool(c.array[0, 0])


def test_half_minus_tiny_does_not_fill_column_0():
    """0.5 - 2**-60 snaps to 0 at S = 0 (floor(v + 1/2) = 0): the rectangle
    [0, v] is empty.  Rounded to float64 first it became 0.5, which snaps
    to 1 and filled column 0."""
    assert snap(HALF_MINUS, 0) == 0
    assert not _column0(HALF_MINUS)
    assert not _column0(decimal.Decimal(1) / 2 - decimal.Decimal(2) ** -60)
    assert _column0(Fraction(1, 2)) and _column0(decimal.Decimal("0.5"))
    ld = np.longdouble(0.5) - np.longdouble(2.0) ** -60
    if ld == np.longdouble(0.5):
        pytest.skip("longdouble is float64 here")
    assert not _column0(ld)


@given(st.fractions(min_value=-(2 ** 27), max_value=2 ** 27, max_denominator=2 ** 70),
       st.integers(0, 16))
def test_exact_double_snaps_as_the_exact_value(v, s):
    """The float64 handed to C snaps as the exact value does, at every S;
    also right at the boundaries and a hair either side of them."""
    for w in (v, Fraction(math.floor(v * 2 ** s)) / 2 ** s + Fraction(1, 2 ** (s + 1)),
              Fraction(math.floor(v * 2 ** s)) / 2 ** s + Fraction(1, 2 ** (s + 1)) - Fraction(1, 2 ** 80)):
        d = _core.exact_double(w)
        assert type(d) is float
        assert math.floor(Fraction(d) * 2 ** s + Fraction(1, 2)) == snap(w, s)


@given(st.lists(st.tuples(st.fractions(-12, 12, max_denominator=2 ** 40),
                          st.fractions(-12, 12, max_denominator=2 ** 40)), min_size=3, max_size=7),
       st.integers(0, 16))
def test_fraction_polygon_equals_its_exactly_snapped_copy(ring, s):
    """A polygon of Fractions fills the pixels of the same polygon with
    its vertices snapped exactly (the oracle's snap) and given as floats."""
    snapped = [(snap(x, s) / 2 ** s, snap(y, s) / 2 ** s) for x, y in ring]
    got = rastrum.polygon_mask(np.array(ring, dtype=object), (12, 12), subpixel_bits=s)
    want = rastrum.polygon_mask(snapped, (12, 12), subpixel_bits=s)
    assert np.array_equal(got, want)


def test_range_message_prints_the_limit_exactly():
    """At S = 10 the 32-bit range is +-131071.9990234375 pixels; %g printed
    131072, a value that is itself outside it.  (xscan: the 32-bit path;
    aet takes the 64-bit path past it, tests/test_precision.py.)"""
    with pytest.raises(rastrum.InputError) as info:
        rastrum.polygon_mask([(0, 0), (131072, 0), (0, 1)], (4, 4), subpixel_bits=10, algorithm="xscan")
    assert "131071.9990234375" in str(info.value)
    assert "131072 " not in str(info.value).split("range")[1]


# ---- a seed fill racing a writer ----------------------------------------------------

def test_flood_fill_racing_a_writer_thread():
    """A thread toggles pixels of the region (the seed too) while fills
    run; each call returns (RAST_E_WORK is RastrumError) and writes only
    inside the canvas: the guard around it is never written, and every
    pixel holds one of the values anyone wrote."""
    big = np.full((40, 50), 200, np.uint8)
    view = big[5:35, 5:45]
    view[...] = 0
    view[::4, 1:] = 3  # walls with gaps: corridors
    view[2::4, :-1] = 3
    canvas = rastrum.Canvas.wrap(view)
    stop = threading.Event()

    def writer():
        rng = np.random.default_rng(7)
        while not stop.is_set():
            y, x = int(rng.integers(0, 30)), int(rng.integers(0, 40))
            view[1, 0] = 0
            view[y, x] = 0
            view[1, 0] = 1
            view[y, x] = 1

    t = threading.Thread(target=writer)
    t.start()
    calls = 0
    try:
        deadline = time.monotonic() + 1.5
        while time.monotonic() < deadline:
            try:
                canvas.flood_fill((0, 1), 7, connectivity=4 + 4 * (calls % 2))
            except rastrum.RastrumError as e:
                assert "work limit" in str(e) or "changed" in str(e)
            view[view == 7] = 0
            calls += 1
    finally:
        stop.set()
        t.join()
    assert calls > 10
    assert (big[:5] == 200).all() and (big[35:] == 200).all()
    assert (big[:, :5] == 200).all() and (big[:, 45:] == 200).all()
    assert set(np.unique(view)) <= {0, 1, 3, 7}


# ---- memory limits ------------------------------------------------------------------

def test_read_obj_one_huge_face_is_refused_in_memory_of_the_file():
    """One face of 15M corners (30 MB) used to take 4.4 GiB and 45 s; it
    is refused (max_face_corners) with memory a small multiple of the
    file's."""
    from rastrum.scene import read_obj
    text = "v 0 0 0\nf" + " 1" * 15_000_000 + "\n"
    source = io.StringIO(text)
    tracemalloc.start()
    try:
        with pytest.raises(rastrum.InputError, match="max_face_corners"):
            read_obj(source)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 4 * len(text), peak
    # the limit is a keyword: a face of 70000 corners reads with a larger one
    v, f, n = read_obj(io.StringIO("v 0 0 0\nv 1 0 0\nf" + " 1 2" * 35000 + "\n"), max_face_corners=70000)
    assert f.shape == (69998, 3)
    for bad in (2, -1, 1.5, True, "9"):
        with pytest.raises(rastrum.InputError, match="max_face_corners"):
            read_obj(io.StringIO("v 0 0 0\n"), max_face_corners=bad)


def test_line_pixels_refuses_before_allocating():
    """A 2-point call that would return 2**27 pixels (1 GiB) is refused
    before the output is made; with max_pixels=None it is allowed (tried
    on a smaller one)."""
    tracemalloc.start()
    try:
        with pytest.raises(rastrum.InputError, match="max_pixels"):
            rastrum.line_pixels((0, 0), (2 ** 27 - 1, 0), subpixel_bits=0)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1 << 20
    px = rastrum.line_pixels((0, 0), (2 ** 24 + 5, 0), subpixel_bits=0, sample_offset=0, max_pixels=None)
    assert len(px) == 2 ** 24 + 6
    assert len(rastrum.line_pixels((0, 0), (2 ** 24 - 1, 0), subpixel_bits=0, sample_offset=0)) == 2 ** 24

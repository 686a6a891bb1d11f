"""A Path filled through the scratch block the caller lends
(python/glue/pathfill.c, rastpy_path_lent): the path flattened in one
pass straight into the block, with no count first, when the block holds
its vertices, its ring sizes (at the block's end) and the filler's
scratch; else the counted way.  Blocks of every size are tried, from
none to more than the call wants, byte by byte about each threshold.

What is checked, for each size: the canvas (and polygon_coverage's
array) is pixel for pixel what filling the rings of ``path.flatten()``
paints (a separate way: the rings go through Python and the polygon
filler, tests/test_path_fill.py's equality), nothing is written past the
block's end (guard bytes after it), and the size the call says it wants
is one that the next call fills in (a block that large then wants no
more).
"""

import numpy as np
import pytest

import rastrum
from rastrum._coverage import _tls
from rastrum._native import ffi
from rastrum._path import Path

GUARD = 64
SHAPE = (12, 16)

PATHS = {
    # curves of both degrees, a ring inside another, subpaths of 1 and 2
    # vertices (left out of the fill), a drawing verb after a close (a new
    # subpath at the closed one's start)
    "mixed": "M1 10 Q1 1 8 1 T15 10 Z M4 9 C4 4 12 4 12 9 Z M3 3 M5 5 L9 9 M2 2 L6 2 L4 6 Z L1 7 L2 11 Z",
    # as many subpaths as verbs (the ring sizes' room is for that many)
    "moves": "M1 1 M2 2 M3 3 M4 4 M5 5 M6 6 M7 7",
    # many vertices from few verbs (a fine tolerance)
    "curves": "M0.5 11 C0.5 -4 15.5 -4 15.5 11 Q8 5 0.5 11 Z M3 9 Q8 -1 13 9 Z",
}


def _sc():
    """This thread's rastpy_scratch (made by a first call that lends it)."""
    if not hasattr(_tls, "sc"):
        rastrum.polygon_coverage([[(1, 1), (5, 1), (3, 4)]], (6, 6))
    return _tls.sc


def _lend(size):
    """A block of `size` bytes lent to the next call, GUARD bytes after it;
    returns the cffi array (kept alive by the caller)."""
    sc = _sc()
    buf = ffi.new("char[]", size + GUARD)
    ffi.buffer(buf)[size:] = b"\xa5" * GUARD
    sc.buf, sc.size, sc.want = (buf if size else ffi.NULL), size, 0
    return buf


def _draw(p, how, aa, tol):
    if how == "canvas":
        c = rastrum.Canvas(SHAPE, format="gray8")
        c.array[...] = 7
        c.fill_polygon(p, 200, aa=aa, rule="nonzero", tolerance=tol)
        return c.array.copy()
    return rastrum.polygon_coverage(p, SHAPE, method=aa, rule="nonzero", tolerance=tol)


def _expected(p, how, aa, tol):
    rings = p.flatten(8, tol)
    if how == "canvas":
        c = rastrum.Canvas(SHAPE, format="gray8")
        c.array[...] = 7
        if rings:
            c.fill_polygon(rings, 200, aa=aa, rule="nonzero")
        return c.array.copy()
    if not rings:
        return np.zeros(SHAPE, np.uint8)
    return rastrum.polygon_coverage(rings, SHAPE, method=aa, rule="nonzero")


def _wanted(p, how, aa, tol):
    """The block the call wants, asked with none lent."""
    _lend(0)
    _draw(p, how, aa, tol)
    return _sc().want


@pytest.mark.parametrize("name", sorted(PATHS))
@pytest.mark.parametrize("how", ["canvas", "coverage"])
@pytest.mark.parametrize("aa,tol", [("area", None), ("accumulate", 1 / 64)])
def test_path_fill_every_lent_size(name, how, aa, tol):
    p = Path.from_svg(PATHS[name])
    want = _expected(p, how, aa, tol)
    full = _wanted(p, how, aa, tol)
    assert full > 0
    # room for the vertices and ring sizes alone below ~2 KB; for the
    # filler's scratch too just below `full` (the one pass wants no more
    # than the counted way says); a coarse stride between
    sizes = sorted(set(range(0, min(full, 2048), 4)) | set(range(2048, full, 509)) |
                   set(range(max(0, full - 160), full + 48)) | {2 * full + 3})
    for size in sizes:
        buf = _lend(size)
        got = _draw(p, how, aa, tol)
        assert np.array_equal(got, want), (name, how, aa, size, full)
        assert ffi.buffer(buf)[size:] == b"\xa5" * GUARD, ("written past the block", name, how, size)
        asked = _sc().want
        if asked > size:  # the next call, lent what this one wanted, wants no more
            buf = _lend(asked)
            assert np.array_equal(_draw(p, how, aa, tol), want), (name, how, aa, size, asked)
            assert ffi.buffer(buf)[asked:] == b"\xa5" * GUARD
            assert _sc().want <= asked, (name, how, size, asked, _sc().want)
    _lend(0)

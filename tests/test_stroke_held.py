"""rastrum.stroke's outline held as the stroker made it (Path._lines,
python/rastrum/_path.py): a Path (type Path, so that polygon_coverage and
Canvas.fill_polygon flatten it in C straight into the filler) whose points
are the stroker's int32 on its 1/2**b grid, with no float64 copy and no
Python list until something asks for one.

Checked here: the grid points a fill at subpixel_bits s takes from the held
integers (Path._fixed) are floor(x 2**s + 1/2) of the outline's points x,
computed in exact fractions (not by numpy, not by C); the outline behaves
as the Path built point by point from those points (verbs, points, len,
flatten, copy, building on after it) and every fill of it (polygon_mask,
polygon_coverage's methods, Canvas.fill_polygon and Canvas.stroke, binary
and anti-aliased) draws what that list-built Path draws.  Cheap: small
polylines, examples as the hypothesis profile says (tests/conftest.py).
"""

from fractions import Fraction
import math

import numpy as np
from hypothesis import given, strategies as st

import rastrum
from rastrum._path import CLOSE, LINE, MOVE


@st.composite
def polylines(draw):
    nlines = draw(st.integers(1, 3))
    lines = []
    for _ in range(nlines):
        n = draw(st.integers(1, 8))
        lines.append([(draw(st.integers(0, 4 * 40)) / 4.0 + draw(st.sampled_from([0, 1 / 3.0, 1e-6])),
                       draw(st.integers(0, 4 * 30)) / 4.0) for _ in range(n)])
    style = dict(join=draw(st.sampled_from(["miter", "round", "bevel"])),
                 cap=draw(st.sampled_from(["butt", "round", "square"])))
    if draw(st.booleans()):
        style.update(dash=[draw(st.integers(1, 12)), draw(st.integers(0, 6))])
    width = draw(st.sampled_from([0.5, 1, 3, 4.75]))
    tol = draw(st.sampled_from([None, 1 / 64.0, 0.2]))
    return lines, width, style, tol


def listed(outline):
    """The same outline built point by point (a Path held as lists)."""
    p = rastrum.Path(tolerance=outline.tolerance)
    pts = iter(outline.points.tolist())
    for v in outline.verbs.tolist():
        if v == MOVE:
            p.move_to(*next(pts))
        elif v == LINE:
            p.line_to(*next(pts))
        else:
            assert v == CLOSE
            p.close()
    return p


def grid(x, s):
    """floor(x 2**s + 1/2), exactly."""
    return math.floor(Fraction(x) * (1 << s) + Fraction(1, 2))


@given(polylines())
def test_held_outline_is_the_listed_path(case):
    lines, width, style, tol = case
    outline = rastrum.stroke(lines, width, tolerance=tol, **style)
    assert type(outline) is rastrum.Path
    if not len(outline):
        return
    ref = listed(outline)
    assert len(outline) == len(ref) and np.array_equal(outline.verbs, ref.verbs)
    assert np.array_equal(outline.points, ref.points)
    # the held integers rounded to every grid a fill takes, against fractions
    for s in (0, 5, 8, 16):
        fixed, verbs = outline._fixed(s)
        want = [[grid(x, s), grid(y, s)] for x, y in outline.points.tolist()]
        assert fixed.dtype == np.int32 and fixed.tolist() == want
        assert np.array_equal(verbs, ref.verbs)
        rings, want_rings = outline.flatten(s, tolerance=1.0), ref.flatten(s, tolerance=1.0)  # lines: any
        assert len(rings) == len(want_rings) and all(np.array_equal(a, b) for a, b in zip(rings, want_rings))
    shape = (34, 44)
    assert np.array_equal(rastrum.polygon_mask(outline, shape, rule="nonzero"),
                          rastrum.polygon_mask(ref, shape, rule="nonzero"))
    for method in ("area", "ss4", "accumulate"):
        for bits in (8, 4) if tol != 1 / 64.0 else (8,):  # (1/64 px is below a 1/16 px grid's step)
            got = rastrum.polygon_coverage(outline, shape, rule="nonzero", method=method, subpixel_bits=bits)
            assert np.array_equal(got, rastrum.polygon_coverage(ref, shape, rule="nonzero", method=method,
                                                                subpixel_bits=bits))
    for aa in (None, "area", "ss4"):
        a = rastrum.Canvas(shape, format="gray8")
        b = rastrum.Canvas(shape, format="gray8")
        a.fill_polygon(outline, 200, rule="nonzero", aa=aa)
        b.fill_polygon(ref, 200, rule="nonzero", aa=aa)
        assert np.array_equal(a.array, b.array)
        c = rastrum.Canvas(shape, format="gray8")
        c.stroke(lines, 200, width=width, tolerance=tol, aa=aa, **style)
        if tol is None:  # Canvas.stroke: the fill takes the stroke's tolerance too
            assert np.array_equal(c.array, a.array)


def test_held_outline_builds_on_as_lists():
    """Reading or extending the outline's lists makes them once, from the
    held points; after that it is an ordinary Path."""
    outline = rastrum.stroke([(2, 3), (10, 3), (10, 9)], 2, join="round")
    n, pts = len(outline), outline.points
    c = outline.copy()
    assert type(c) is rastrum.Path and np.array_equal(c.points, pts) and np.array_equal(c.verbs, outline.verbs)
    outline.move_to(20, 20).line_to(24, 20).line_to(24, 24).close()
    assert len(outline) == n + 4
    assert np.array_equal(outline.points[:len(pts)], pts)
    assert outline.points[len(pts):].tolist() == [[20, 20], [24, 20], [24, 24]]
    assert len(c) == n  # the copy is independent
    cov = rastrum.polygon_coverage(outline, (30, 30), rule="nonzero", method="area", dtype=np.float64)
    assert cov[20:24, 20:24].sum() == 8.0  # the triangle added after the stroke
    assert "Path(%d verbs" % (n + 4) in repr(outline)

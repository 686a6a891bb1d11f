"""Canvas.fill_polygon of a Path with ``aa=``, and polygon_coverage of a
Path: the path flattened in C
straight into the anti-aliased filler (python/glue/pathfill.c), without
its rings going back through Python (docs/paths.md, "Speed").

What is checked: the canvas is pixel for pixel what filling the rings of
``path.flatten(subpixel_bits, tolerance)`` paints (the flattening's bound
is checked exactly in tests/test_path.py, the fill of rings against the
oracles in the coverage tests), and for "area" also the exact rational
coverage of those rings (tests/oracle_coverage.py) rounded to the level;
the Path's cached arrays follow every edit; bad input leaves the canvas
untouched.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import InputError
from rastrum._path import Path

import oracle_coverage
from test_coverage import _n_m, check_area

coord = st.integers(-64, 64 * 16).map(lambda v: v / 64)  # pixels, on a 1/64 grid, some outside
TOLS = [None, 1.0, 1 / 4, 1 / 16, 1 / 256]


@st.composite
def paths(draw):
    p = Path()
    for _ in range(draw(st.integers(1, 3))):
        p.move_to(draw(coord), draw(coord))
        for _ in range(draw(st.integers(0, 4))):
            kind = draw(st.sampled_from("lqc"))
            if kind == "l":
                p.line_to(draw(coord), draw(coord))
            elif kind == "q":
                p.quad_to(draw(coord), draw(coord), draw(coord), draw(coord))
            else:
                p.cubic_to(*(draw(coord) for _ in range(6)))
        if draw(st.booleans()):
            p.close()
    return p


def paint(p, how, aa, rule, bits, tol, fmt="gray8", color=255):
    c = rastrum.Canvas((12, 16), format=fmt)
    c.array[...] = 7
    if how == "path":
        c.fill_polygon(p, color, aa=aa, rule=rule, subpixel_bits=bits, tolerance=tol)
    else:
        rings = p.flatten(bits, tol)
        if rings:
            c.fill_polygon(rings, color, aa=aa, rule=rule, subpixel_bits=bits)
    return c.array.copy()


@settings(max_examples=max(5, settings().max_examples // 2))
@given(paths(), st.sampled_from(["area", "accumulate", "ss4"]), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([4, 8, 12]), st.sampled_from(TOLS))
def test_path_fill_equals_its_rings_filled(p, aa, rule, bits, tol):
    if tol is not None and tol * (1 << bits) < 1:
        tol = None
    assert np.array_equal(paint(p, "path", aa, rule, bits, tol), paint(p, "rings", aa, rule, bits, tol))


small = st.integers(-16, 8 * 16 + 16).map(lambda v: v / 16)


@settings(max_examples=max(5, settings().max_examples // 4))  # the rational oracle is slow
@given(st.lists(small, min_size=8, max_size=8), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([1.0, 1 / 4]))
def test_path_fill_area_is_the_exact_coverage(v, rule, tol):
    """On a clear canvas, colour 255: the level floor(255 a + 1/2) of the
    exact area a of each pixel inside the flattened rings, except at a tie
    within the documented bound (docs/coverage.md, "The bound of area"),
    where the next level is allowed and only there: check_area, as for
    every "area" fill of rings."""
    p = Path().move_to(v[0], v[1]).cubic_to(*v[2:]).quad_to(v[1], v[6], v[0], v[7]).close()
    c = rastrum.Canvas((8, 8), format="gray8")
    c.fill_polygon(p, 255, aa="area", rule=rule, tolerance=tol)
    rings = p.flatten(8, tol)
    exact = oracle_coverage.coverage_exact([r.tolist() for r in rings], (8, 8), rule=rule)
    n, m = _n_m([r.tolist() for r in rings], 8)
    check_area(c.array, exact, 255, n, m, "path %s %s" % (rule, tol))


def test_path_fill_area_at_an_exact_half():
    """A pixel covered exactly half by slanted edges of slope 5/6 (whose
    pieces are not on the engine's grid): 127 or 128 are both within the
    bound at this tie; hypothesis found it (the exact-floor check above
    wrongly refused 127 until it took the tie rule of the other tests)."""
    v = [6.0, 5.75, 0.625, 1.0625, 3.4375, 4.875, 1.6875, -7 / 16]
    p = Path().move_to(v[0], v[1]).cubic_to(*v[2:]).quad_to(v[1], v[6], v[0], v[7]).close()
    rings = p.flatten(8, 0.25)
    exact = oracle_coverage.coverage_exact([r.tolist() for r in rings], (8, 8), rule="nonzero")
    assert exact[4][4] == oracle_coverage.F(1, 2)
    c = rastrum.Canvas((8, 8), format="gray8")
    c.fill_polygon(p, 255, aa="area", tolerance=0.25)
    assert c.array[4, 4] in (127, 128)
    n, m = _n_m([r.tolist() for r in rings], 8)
    check_area(c.array, exact, 255, n, m, "half")


@settings(max_examples=max(5, settings().max_examples // 2))
@given(paths(), st.sampled_from(["area", "accumulate", "ss2"]), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([4, 8]), st.sampled_from(TOLS), st.sampled_from([np.uint8, np.uint16, np.float64]))
def test_path_coverage_equals_its_rings_coverage(p, method, rule, bits, tol, dtype):
    """polygon_coverage of a Path: flattened in C into the filler once its
    options are known (the second call), the same as of its rings."""
    if tol is not None and tol * (1 << bits) < 1:
        tol = None
    kw = dict(method=method, rule=rule, subpixel_bits=bits, dtype=dtype)
    rings = p.flatten(bits, tol)
    want = rastrum.polygon_coverage(rings, (12, 16), **kw) if rings else None
    for _ in range(2):
        got = rastrum.polygon_coverage(p, (12, 16), tolerance=tol, **kw)
        if want is None:
            assert not got.any()
        else:
            assert got.dtype == want.dtype and np.array_equal(got, want)


def _same_in_every_format(p):
    for fmt, color in (("rgb888", 77), ("gray8", 200), ("rgb565", 140), ("mono1", 1)):
        for aa in ("area", "accumulate"):
            assert np.array_equal(paint(p, "path", aa, "nonzero", 8, None, fmt, color),
                                  paint(p, "rings", aa, "nonzero", 8, None, fmt, color))


def test_path_fill_other_formats():
    # quadratic and cubic curves, a ring inside another, a triangle across both
    _same_in_every_format(Path.from_svg("M1 10 Q1 1 8 1 T15 10 Z M4 9 C4 4 12 4 12 9 Z M2 2 L6 2 L4 6 Z"))


def test_path_fill_glyph_text():
    # matplotlib is an optional input (Path.from_matplotlib), not a test extra
    textpath = pytest.importorskip("matplotlib.textpath")
    _same_in_every_format(Path.from_matplotlib(textpath.TextPath((0, 0), "ag&S", size=11))
                          .transformed((1, 0, 1, 0, -1, 10)))


def test_path_arrays_follow_every_edit():
    p = Path(tolerance=1 / 16).move_to(1, 1).quad_to(14, 0, 12, 11)
    a = paint(p, "path", "area", "nonzero", 8, None)  # arrays and the 8-bit points cached
    assert p.verbs.tolist() == [0, 1 + 1] and p.points.shape == (3, 2)
    for edit in (lambda q: q.line_to(2, 10),
                 lambda q: q.close().line_to(15, 2).line_to(15, 6),  # a new subpath at the closed one's start
                 lambda q: q.cubic_to(3, 3, 9, 1, 15, 11),
                 lambda q: setattr(q, "_pts", [(x + 1, y) for x, y in q._pts]),
                 lambda q: q.move_to(0, 0).line_to(5, 11).line_to(0, 11)):
        edit(p)
        fresh = Path(tolerance=1 / 16)
        fresh._verbs, fresh._pts = list(p._verbs), list(p._pts)
        b = paint(p, "path", "area", "nonzero", 8, None)
        assert np.array_equal(b, paint(fresh, "path", "area", "nonzero", 8, None))
        assert np.array_equal(p.points, np.array(p._pts, float).reshape(-1, 2))
        assert not np.array_equal(a, b)
        a = b
    whole = Path()
    whole._verbs += p._verbs  # as bench/paths_scene.py joins paths
    whole._pts += p._pts
    assert np.array_equal(paint(whole, "path", "area", "nonzero", 8, 1 / 16), a)
    q = p.points
    q[0, 0] = 3.0  # a copy: the path is not changed
    assert p.points[0, 0] != 3.0
    with pytest.raises(ValueError):  # the cached arrays are read-only
        p._as_arrays()[1][0, 0] = 3.0
    assert not p._fixed(8)[0].flags.writeable


def test_path_fill_bad_input_leaves_the_canvas():
    c = rastrum.Canvas((8, 8), format="gray8")
    c.array[...] = 9
    far = Path().move_to(0, 0).line_to(1e7, 0).line_to(0, 5)
    with pytest.raises(InputError, match="outside the range"):
        c.fill_polygon(far, 255, aa="area")
    with pytest.raises(InputError, match="below one grid step"):
        c.fill_polygon(Path().move_to(0, 0).quad_to(8, 0, 8, 8), 255, aa="area", tolerance=1 / 512)
    assert (c.array == 9).all()
    for p in (far, Path().move_to(0, 0).line_to(1e7, 0).line_to(0, 5)):
        for _ in range(2):
            with pytest.raises(InputError, match="outside the range"):
                rastrum.polygon_coverage(p, (8, 8), rule="nonzero")
    c.fill_polygon(Path(), 255, aa="area")  # nothing to paint
    c.fill_polygon(Path().move_to(1, 1).line_to(5, 5), 255, aa="area")  # encloses nothing
    assert (c.array == 9).all()


def test_path_fill_subpixel_bits_past_16_refused_as_for_rings():
    p = Path(tolerance=1 / 8).move_to(1, 1).cubic_to(20, -3, -4, 20, 11, 7).close()
    c = rastrum.Canvas((8, 8), format="gray8")
    for geometry in (p, p.flatten(16)):
        with pytest.raises(InputError, match="subpixel_bits"):
            c.fill_polygon(geometry, 255, aa="area", subpixel_bits=20)
    assert not c.array.any()

"""A translucent fill is computed and blended over the geometry's pixel box
only (issue 34: python/glue/blend.c, Canvas._blend): its pixels must be
those of the whole canvas's blend, computed here the old way from public
calls -- polygon_mask / triangles_mask (times 255) or polygon_coverage /
triangles_coverage of the WHOLE canvas -- then blended by the integer
oracle of tests/test_opacity.py (exact fractions, docs/opacity.md), or,
with gamma=, by rast_blend_coverage_linear over the whole canvas.  Every
format, method, rule, algorithm, rounding, boundary, S and sample offset;
shapes inside, over the canvas's edge and wholly outside; bad input raises
what the whole-canvas path raises, and writes nothing.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from rastrum import _canvas
from rastrum._core import InputError
from test_opacity import canvas_expected

FORMATS = ["gray8", "rgb888", "rgb565", "rgba8888"]
METHODS = [None, "area", "accumulate", "ss2", "ss4", "ss16"]
POLY_ALGOS = sorted(rastrum.ALGORITHMS["polygon_mask"])
TRI_ALGOS = sorted(rastrum.ALGORITHMS["triangles_mask"])


def fresh(fmt, h, w, seed):
    rng = np.random.default_rng(seed)
    c = rastrum.Canvas((h, w), format=fmt)
    hi = 65536 if fmt == "rgb565" else 256
    c.array[...] = rng.integers(0, hi, c.array.shape)
    return c


@st.composite
def coords(draw, lo, hi, n):
    # quarter pixels (ties on samples and cell edges) or any float
    grid = draw(st.booleans())
    v = st.integers(int(lo * 4), int(hi * 4)).map(lambda k: k / 4) if grid else \
        st.floats(lo, hi, allow_nan=False)
    return [(draw(v), draw(v)) for _ in range(n)]


def colour(draw, fmt):
    """(an RGBA colour for fmt, opacity, gamma) that make a blend, not the
    value's own fill (docs/opacity.md)."""
    n = 1 if fmt == "gray8" else 3
    alpha = draw(st.integers(0, 255))
    color = tuple(draw(st.integers(0, 255)) for _ in range(n)) + (alpha,)
    opacity = draw(st.sampled_from([None, 0.0, 0.3, 0.5, 1.0]))
    gamma = draw(st.sampled_from([None, None, None, "srgb", 2.2]))
    if opacity is None and gamma is None and (fmt == "rgba8888" or alpha == 255):
        opacity = 0.5  # else a stored value, not a blend
    if opacity == 1.0 and gamma is None and fmt != "rgba8888" and alpha == 255:
        opacity = 0.5  # the same: an opaque colour at full opacity is the value's fill
    return color, opacity, gamma


@st.composite
def cases(draw):
    fmt = draw(st.sampled_from(FORMATS))
    h, w = draw(st.integers(1, 20)), draw(st.integers(1, 20))
    tris = draw(st.booleans())
    aa = draw(st.sampled_from(METHODS))
    # near the canvas, over its edges, or wholly outside it
    where = draw(st.sampled_from(["near", "near", "out"]))
    lo, hi = (-5.0, max(h, w) + 5.0) if where == "near" else (max(h, w) + 3.0, max(h, w) + 12.0)
    if draw(st.booleans()) and where == "out":
        lo, hi = -12.0, -3.0
    if tris:
        geom = np.array(draw(coords(lo, hi, 3 * draw(st.integers(1, 4)))), float).reshape(-1, 3, 2)
    else:
        geom = np.array(draw(coords(lo, hi, draw(st.integers(3, 8)))), float)
        form = draw(st.sampled_from(["array", "tuples", "two"]))
        if form == "tuples":
            geom = [tuple(p) for p in geom.tolist()]
        elif form == "two":  # a list of rings (a hole, or two pieces)
            geom = [geom, np.array(draw(coords(lo, hi, 4)), float)]
    kw = dict(subpixel_bits=draw(st.sampled_from([0, 2, 8, 16])),
              sample_offset=draw(st.sampled_from([0.5, 0.0])))
    if not tris:
        kw["rule"] = draw(st.sampled_from(["evenodd", "nonzero"]))
    if aa is None:
        kw["algorithm"] = draw(st.sampled_from(TRI_ALGOS if tris else POLY_ALGOS))
        kw["rounding"] = draw(st.sampled_from(["exact", "exact", "textbook"]))
        kw["boundary"] = draw(st.sampled_from(["exact", "exact", "closed", "conservative"]))
    color, opacity, gamma = colour(draw, fmt)
    return fmt, (h, w), tris, geom, aa, kw, color, opacity, gamma, draw(st.integers(0, 2 ** 16))


def whole_canvas_cov(tris, geom, shape, aa, kw):
    """The old way: the mask (255 inside) or uint8 coverage of the whole canvas."""
    if aa is None:
        f = rastrum.triangles_mask if tris else rastrum.polygon_mask
        return f(geom, shape, **kw).astype(np.uint8) * np.uint8(255)
    kw = {k: v for k, v in kw.items() if k in ("rule", "subpixel_bits", "sample_offset")}
    if tris:
        return rastrum.triangles_coverage(geom, shape, method=aa, **kw)
    return rastrum.polygon_coverage(geom, shape, method=aa, **kw)


def draw_call(c, tris, geom, aa, kw, color, opacity, gamma):
    if tris:
        kw = dict(kw, aa=aa)
        kw.pop("rule", None)
        if len(geom) == 1 and aa is None:
            return c.fill_triangle(geom[0], color, opacity=opacity, gamma=gamma, **kw)
        return c.fill_triangles(geom, color, opacity=opacity, gamma=gamma, **kw)
    return c.fill_polygon(geom, color, aa=aa, opacity=opacity, gamma=gamma, **kw)


def whole_canvas_path(monkeypatch):
    """Canvas._blend as it was: the whole canvas's mask or coverage, blended whole."""
    monkeypatch.setattr(_canvas, "_blend_box", lambda *a: False)


@settings(max_examples=S_.examples(150), deadline=None)
@given(cases())
def test_box_blend_is_the_whole_canvas_blend(case):
    fmt, shape, tris, geom, aa, kw, color, opacity, gamma, seed = case
    c = fresh(fmt, *shape, seed)
    before = c.array.copy()
    try:
        cov = whole_canvas_cov(tris, geom, shape, aa, kw)
        blend, _ = _canvas._blend_args(color, opacity, fmt, "test", gamma)
    except InputError:
        with pytest.raises(InputError):
            draw_call(c, tris, geom, aa, kw, color, opacity, gamma)
        np.testing.assert_array_equal(c.array, before)
        return
    draw_call(c, tris, geom, aa, kw, color, opacity, gamma)
    if gamma is None:  # the integer oracle
        rgba = tuple(blend[0])
        want = canvas_expected(fmt, before, cov, rgba, blend[1].opacity)
    else:  # rast_blend_coverage_linear over the whole canvas
        old = rastrum.Canvas.wrap(before.copy(), format=fmt)
        _canvas._blend_mask(old._target, np.ascontiguousarray(cov), blend)
        want = old.array
    np.testing.assert_array_equal(c.array, want)
    if not cov.any():
        np.testing.assert_array_equal(c.array, before)  # (the oracle's A = 0: nothing drawn)


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("aa", METHODS)
def test_outside_draws_nothing(fmt, aa):
    """A shape wholly off the canvas (every side): no pixel, no error."""
    for dx, dy in ((-40, 0), (40, 0), (0, -40), (0, 40), (-40, -40)):
        c = fresh(fmt, 9, 11, 5)
        before = c.array.copy()
        ring = np.array([[1.5, 1.5], [8.2, 2.0], [5.0, 7.5]]) + [dx, dy]
        c.fill_polygon(ring, (10, 200, 30, 140) if fmt != "gray8" else (10, 140), aa=aa, opacity=0.5)
        c.fill_triangles(ring.reshape(1, 3, 2), (10, 200, 30, 140) if fmt != "gray8" else (10, 140), aa=aa,
                         opacity=0.5)
        np.testing.assert_array_equal(c.array, before)


def outcome(call, fmt="rgb888"):
    """(the error's message or None, the canvas after the call)."""
    c = fresh(fmt, 6, 7, 1)
    before = c.array.copy()
    try:
        call(c)
    except InputError as e:
        np.testing.assert_array_equal(c.array, before)  # nothing written
        return str(e), c.array
    return None, c.array


@pytest.mark.parametrize("call", [
    # far off the canvas at ss16 (its range is the fine grid's)
    lambda c: c.fill_polygon([(40000, 1), (40001, 1), (40000, 3)], (1, 2, 3, 100), aa="ss16"),
    lambda c: c.fill_triangles([[(4e6, 1), (40001, 1), (40000, 3)]], (1, 2, 3, 100), aa="ss16"),
    lambda c: c.fill_polygon([(4e6, 1), (2, 1), (2, 3)], (1, 2, 3, 100), aa="ss16", subpixel_bits=4),
    # past the 32-bit range
    lambda c: c.fill_polygon([(1e9, 1), (2, 1), (2, 3)], (1, 2, 3, 100)),
    lambda c: c.fill_triangles([[(1e9, 1), (2, 1), (2, 3)]], (1, 2, 3, 100), aa="area"),
    lambda c: c.fill_triangles([[(1e9, 1), (2, 1), (2, 3)]], (1, 2, 3, 100)),
    lambda c: c.fill_polygon([(np.nan, 1), (2, 1), (2, 3)], (1, 2, 3, 100), aa="area"),
    lambda c: c.fill_polygon([(1, 1), (2, 1)], (1, 2, 3, 100)),
    lambda c: c.fill_polygon([[(1, 1), (6, 1), (2, 3)], [(1, 1), (2, 2)]], (1, 2, 3, 100), aa="area"),
    lambda c: c.fill_polygon([(1, 1), (6, 1), (2, 3)], (1, 2, 3, 100), algorithm="fence", rule="nonzero"),
    lambda c: c.fill_polygon([(1, 1), (6, 1), (2, 3)], (1, 2, 3, 100), aa="area", subpixel_bits=17),
    lambda c: c.fill_polygon([(1, 1), (6, 1), (2, 3)], (1, 2, 3, 100), aa="ss4", subpixel_bits=17),
    lambda c: c.fill_polygon([(1, 1), (6, 1), (2, 3)], (1, 2, 3, 100), rounding="textbook"),
    lambda c: c.fill_triangles([[(1, 1), (6, 1), (2, 3)]], (1, 2, 3, 100), boundary="closed", aa="area"),
])
def test_errors_are_the_whole_canvas_paths(call, monkeypatch):
    """The same message (or none) as the whole-canvas path, the same
    pixels, and nothing written on error."""
    new = outcome(call)
    whole_canvas_path(monkeypatch)
    old = outcome(call)
    assert new[0] == old[0]
    np.testing.assert_array_equal(new[1], old[1])


def test_forms_the_box_does_not_take():
    """A mask at S = 20 (the 64-bit path) and rings the box call does not
    read (int32, a Path) still draw, through the whole-canvas path, with
    the same pixels."""
    ring = np.array([[1.25, 0.5], [6.75, 2.0], [3.0, 5.5]])
    i32 = np.array([[1, 0], [7, 2], [3, 6]], np.int32)
    path = rastrum.Path().move_to(1.25, 0.5).line_to(6.75, 2.0).line_to(3.0, 5.5).close()
    for geom, kw, cov in (
            (ring, dict(subpixel_bits=20), rastrum.polygon_mask(ring, (7, 8), subpixel_bits=20)),
            (i32, dict(aa="area"), rastrum.polygon_coverage(i32, (7, 8))),
            (path, dict(aa="area"), rastrum.polygon_coverage(path, (7, 8))),
            (path, {}, rastrum.polygon_mask(path, (7, 8)))):
        c = fresh("gray8", 7, 8, 3)
        before = c.array.copy()
        c.fill_polygon(geom, (90, 128), **kw)
        cov = cov.astype(np.uint8) * np.uint8(255) if cov.dtype == np.bool_ else cov
        np.testing.assert_array_equal(c.array, canvas_expected("gray8", before, cov, (90, 90, 90, 128), 255))

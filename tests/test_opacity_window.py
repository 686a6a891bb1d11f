"""The translucent calls that blended the WHOLE canvas before (issue 34) now
compute and blend their shape's box only: rings the box call did not read
(int32 arrays, tuples, lists of them), the 64-bit path (subpixel_bits above
16, a vertex past the 32-bit range, with "area" too), Canvas.line and
polyline (python/glue/blend.c, rastpy_blend_polyline) and the seed fills
(the region's box); Paths (flattened to rings the box call already read)
are checked with them.  Each is checked against the whole canvas's blend
computed here from public calls: the whole canvas's mask (polygon_mask,
an opaque line / polyline on a gray8 canvas, an opaque flood fill of the
region on a gray8 copy) or coverage (polygon_coverage) blended by the
integer oracle of tests/test_opacity.py (exact fractions,
docs/opacity.md), or with gamma= by rast_blend_coverage_linear over the
whole canvas.  Shapes inside, over the canvas's edge and wholly outside.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from rastrum import _canvas
from rastrum._core import InputError
from test_opacity import canvas_expected
from test_opacity_box import FORMATS, colour, coords, fresh

POLY_ALGOS = sorted(rastrum.ALGORITHMS["polygon_mask"])


def span(draw, h, w):
    """(lo, hi) of coordinates near the canvas, over its edges, or wholly outside."""
    where = draw(st.sampled_from(["near", "near", "out", "out-"]))
    if where == "near":
        return -5.0, max(h, w) + 5.0
    return (max(h, w) + 3.0, max(h, w) + 12.0) if where == "out" else (-12.0, -3.0)


def expect(fmt, before, cov, color, opacity, gamma):
    """The whole canvas's blend of `cov` (uint8, the canvas's shape)."""
    blend, _ = _canvas._blend_args(color, opacity, fmt, "test", gamma)
    if gamma is None:  # the integer oracle
        return canvas_expected(fmt, before, cov, tuple(blend[0]), blend[1].opacity)
    old = rastrum.Canvas.wrap(before.copy(), format=fmt)
    _canvas._blend_mask(old._target, np.ascontiguousarray(cov), blend)
    return old.array


def check(c, before, fmt, cov, color, opacity, gamma):
    cov = cov.astype(np.uint8) * np.uint8(255) if cov.dtype == np.bool_ else np.asarray(cov, np.uint8)
    np.testing.assert_array_equal(c.array, expect(fmt, before, cov, color, opacity, gamma))
    if not cov.any():
        np.testing.assert_array_equal(c.array, before)  # an empty box: nothing drawn


@st.composite
def polygon_cases(draw):
    fmt = draw(st.sampled_from(FORMATS))
    h, w = draw(st.integers(1, 16)), draw(st.integers(1, 16))
    lo, hi = span(draw, h, w)
    aa = draw(st.sampled_from([None, None, "area", "ss4", "accumulate"]))
    ring = np.array(draw(coords(lo, hi, draw(st.integers(3, 7)))), float)
    form = draw(st.sampled_from(["int32", "int32 list", "tuples", "tuple of tuples", "two", "path", "far"]))
    if form == "far":  # a vertex past the 32-bit range at S = 8: the 64-bit path (binary, "area")
        ring[draw(st.integers(0, len(ring) - 1))] = (draw(st.sampled_from([-1, 1])) * 3e6, draw(st.floats(lo, hi)))
        aa = draw(st.sampled_from([None, "area"]))
    if form == "int32":
        geom = np.round(ring).astype(np.int32)
    elif form == "int32 list":
        geom = [np.round(ring).astype(np.int32), np.round(ring[::-1] / 2).astype(np.int32)]
    elif form == "tuples":
        geom = [tuple(p) for p in ring.tolist()]
    elif form == "tuple of tuples":
        geom = tuple(tuple(p) for p in ring.tolist())
    elif form == "two":  # rings of pairs
        geom = [[tuple(p) for p in ring.tolist()], [tuple(p) for p in ring[::-1].tolist()[:3]]]
    elif form == "path":
        path = rastrum.Path().move_to(*ring[0])
        for k in range(1, len(ring) - 1, 2):
            path = path.quad_to(*ring[k], *ring[k + 1])
        geom = path.close()
    else:
        geom = ring
    kw = dict(rule=draw(st.sampled_from(["evenodd", "nonzero"])),
              sample_offset=draw(st.sampled_from([0.5, 0.0])))
    if aa is None:
        kw["subpixel_bits"] = draw(st.sampled_from([0, 8, 16, 17, 24, 32]))
        wide = kw["subpixel_bits"] > 16 or form == "far"
        kw["algorithm"] = "aet" if wide else draw(st.sampled_from(POLY_ALGOS))
        kw["boundary"] = draw(st.sampled_from(["exact", "exact", "conservative"] + ([] if wide else ["closed"])))
    else:
        kw["subpixel_bits"] = draw(st.sampled_from([0, 2, 8, 16]))
    return fmt, (h, w), geom, aa, kw, colour(draw, fmt), draw(st.integers(0, 2 ** 16))


@settings(max_examples=S_.examples(60), deadline=None)
@given(polygon_cases())
def test_polygon_forms_blend_their_box(case):
    """int32 rings, tuples, lists of rings, Paths, S 17..32 and vertices
    past the 32-bit range: the whole canvas's mask or coverage, blended."""
    fmt, shape, geom, aa, kw, (color, opacity, gamma), seed = case
    c = fresh(fmt, *shape, seed)
    before = c.array.copy()
    try:
        if aa is None:
            cov = rastrum.polygon_mask(geom, shape, **kw)
        else:
            cov = rastrum.polygon_coverage(geom, shape, method=aa, rule=kw["rule"],
                                           subpixel_bits=kw["subpixel_bits"], sample_offset=kw["sample_offset"])
    except InputError:  # (a rule the algorithm lacks): the same error, nothing written
        with pytest.raises(InputError):
            c.fill_polygon(geom, color, aa=aa, opacity=opacity, gamma=gamma, **kw)
        np.testing.assert_array_equal(c.array, before)
        return
    c.fill_polygon(geom, color, aa=aa, opacity=opacity, gamma=gamma, **kw)
    check(c, before, fmt, cov, color, opacity, gamma)


def test_polygon_forms_take_the_box_call(monkeypatch):
    """Each of those forms is drawn by the box call (Canvas._blend_box),
    and lines by rastpy_blend_polyline, not by the whole canvas's blend."""
    def whole(*a):
        raise AssertionError("the whole canvas blended")

    monkeypatch.setattr(_canvas, "_blend_mask", whole)
    ring = np.array([[1.25, 0.5], [6.75, 2.0], [3.0, 5.5]])
    path = rastrum.Path().move_to(1.25, 0.5).line_to(6.75, 2.0).line_to(3.0, 5.5).close()
    far = np.array([[1.25, 0.5], [3e6, 2.0], [3.0, 5.5]])
    c = fresh("rgb888", 7, 8, 3)
    for geom, kw in ((ring.astype(np.int32), {}), (ring.astype(np.int32), dict(aa="area")),
                     ((tuple(ring[0]), tuple(ring[1]), tuple(ring[2])), {}), (path, {}), (path, dict(aa="ss4")),
                     (ring, dict(subpixel_bits=24)), (far, {}), (far, dict(aa="area")), ([], {})):
        c.fill_polygon(geom, (9, 99, 199, 100), **kw)
    c.line((1.5, 1.5), (6.5, 4.0), (9, 99, 199), opacity=0.5)
    c.polyline(ring, (9, 99, 199), closed=True, opacity=0.5, algorithm="dda")


@st.composite
def line_cases(draw):
    fmt = draw(st.sampled_from(FORMATS))
    h, w = draw(st.integers(1, 16)), draw(st.integers(1, 16))
    lo, hi = span(draw, h, w)
    if draw(st.integers(0, 7)) == 0:  # long lines across the canvas (DDA's error grows with the length)
        lo, hi = -1500.0, 1500.0  # (inside +-2047 px, the range at S = 16)
    pts = draw(coords(lo, hi, draw(st.integers(2, 5))))
    kw = dict(algorithm=draw(st.sampled_from(["bresenham", "dda"])),
              subpixel_bits=draw(st.sampled_from([0, 4, 8, 16])),
              sample_offset=draw(st.sampled_from([0.5, 0.0])))
    closed = draw(st.booleans())
    return fmt, (h, w), pts, closed, kw, colour(draw, fmt), draw(st.integers(0, 2 ** 16))


@settings(max_examples=S_.examples(60), deadline=None)
@given(line_cases())
def test_lines_blend_their_box(case):
    """Canvas.line and polyline with a blend: the pixels of the opaque line
    (polyline) drawn on a gray8 canvas of the same shape, blended."""
    fmt, shape, pts, closed, kw, (color, opacity, gamma), seed = case
    mask = rastrum.Canvas(shape, format="gray8")
    c = fresh(fmt, *shape, seed)
    before = c.array.copy()
    mask.line(pts[0], pts[1], 255, **kw)
    c.line(pts[0], pts[1], color, opacity=opacity, gamma=gamma, **kw)
    check(c, before, fmt, mask.array, color, opacity, gamma)
    mask = rastrum.Canvas(shape, format="gray8")
    c = fresh(fmt, *shape, seed)
    mask.polyline(pts, 255, closed=closed, **kw)
    c.polyline(pts, color, closed=closed, opacity=opacity, gamma=gamma, **kw)
    check(c, before, fmt, mask.array, color, opacity, gamma)


@st.composite
def seed_cases(draw):
    fmt = draw(st.sampled_from(FORMATS))
    h, w = draw(st.integers(1, 12)), draw(st.integers(1, 12))
    levels = draw(st.integers(1, 3))  # few values: regions of every shape
    picture = np.array(draw(st.lists(st.integers(0, levels - 1), min_size=h * w, max_size=h * w)),
                       np.uint8).reshape(h, w)
    seed = (draw(st.integers(0, w - 1)), draw(st.integers(0, h - 1)))
    return fmt, picture, seed, draw(st.sampled_from([4, 8])), draw(st.booleans()), colour(draw, fmt)


def painted(fmt, picture):
    """A canvas whose pixel values are those of `picture`'s levels."""
    c = rastrum.Canvas(picture.shape, format=fmt)
    palette = {"gray8": [3, 90, 200], "rgb565": [0x0000, 0xF800, 0x001F]}.get(
        fmt, [(3, 4, 5), (90, 1, 200), (200, 200, 0)] if fmt == "rgb888" else
        [(3, 4, 5, 6), (90, 1, 200, 7), (200, 200, 0, 255)])
    for k, v in enumerate(palette):
        c.array[picture == k] = v
    return c


@settings(max_examples=S_.examples(60), deadline=None)
@given(seed_cases())
def test_seed_fills_blend_their_region(case):
    """flood_fill and boundary_fill with a blend: the region found by an
    opaque flood fill of a gray8 picture of the levels, blended."""
    fmt, picture, seed, connectivity, boundary, (color, opacity, gamma) = case
    c = painted(fmt, picture)
    before = c.array.copy()
    x, y = seed
    if boundary:  # the boundary: the level 0 (a seed on it paints nothing)
        region = (picture != 0).astype(np.uint8)
        if region[y, x]:
            rastrum.Canvas.wrap(region).flood_fill(seed, 2, connectivity=connectivity)
        edge = {"gray8": 3, "rgb565": (0, 0, 0), "rgb888": (3, 4, 5), "rgba8888": (3, 4, 5, 6)}[fmt]  # level 0
        c.boundary_fill(seed, color, edge,
                        connectivity=connectivity, opacity=opacity, gamma=gamma)
    else:
        region = picture.copy() + 1
        rastrum.Canvas.wrap(region).flood_fill(seed, 0, connectivity=connectivity)
        region = np.where(region == 0, 2, 0).astype(np.uint8)
        c.flood_fill(seed, color, connectivity=connectivity, opacity=opacity, gamma=gamma)
    check(c, before, fmt, np.where(region == 2, 255, 0).astype(np.uint8), color, opacity, gamma)


@pytest.mark.parametrize("fmt", FORMATS)
def test_lines_outside_draw_nothing(fmt):
    """Lines wholly off the canvas (every side): no pixel, no error."""
    color = (10, 140) if fmt == "gray8" else (10, 200, 30, 140)
    for dx, dy in ((-40, 0), (40, 0), (0, -40), (0, 40), (-40, -40)):
        c = fresh(fmt, 9, 11, 5)
        before = c.array.copy()
        pts = np.array([[1.5, 1.5], [8.2, 2.0], [5.0, 7.5]]) + [dx, dy]
        c.line(tuple(pts[0]), tuple(pts[1]), color, opacity=0.5)
        c.polyline(pts, color, closed=True, opacity=0.5, algorithm="dda")
        np.testing.assert_array_equal(c.array, before)

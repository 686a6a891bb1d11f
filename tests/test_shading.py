"""Gouraud rectangles (and, below, colour polygons) against the exact
references of oracle_shading.py."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from oracle_shading import rect_gouraud
from strategies import examples

coord = st.one_of(
    st.integers(-4, 24).map(float),
    st.floats(-6, 26, allow_nan=False, width=32).map(float),
    st.integers(-24, 100).map(lambda k: k / 4.0),
)
color = st.integers(0, 255)
corner_colors = st.lists(st.tuples(color, color, color, color), min_size=4, max_size=4)


def spell(precision):
    """The current spelling of a precision (flat is shading="flat")."""
    return {"shading": "flat"} if precision == "flat" else {"precision": precision}


@settings(max_examples=examples(200))
@given(rect=st.tuples(coord, coord, coord, coord), cols=corner_colors,
       S=st.sampled_from([0, 1, 4, 8]), offset=st.sampled_from([0.5, 0.0]),
       precision=st.sampled_from(["exact", "fixed", "flat"]), F=st.sampled_from([1, 4, 8, 16]))
def test_rect_gouraud_matches_oracle(rect, cols, S, offset, precision, F):
    c = rastrum.Canvas((17, 20), format="rgba8888", background=7)
    c.fill_rect_gouraud(rect, cols, **spell(precision), fraction_bits=F, subpixel_bits=S,
                        sample_offset=offset)
    want = rect_gouraud(rect, cols, (17, 20), precision=precision, fraction_bits=F, subpixel_bits=S,
                        sample_offset=offset, background=7)
    np.testing.assert_array_equal(c.array, want)


@settings(max_examples=examples(100))
@given(rect=st.tuples(coord, coord, coord, coord), cols=corner_colors, S=st.sampled_from([0, 8]))
def test_rect_pixels_are_the_polygon_fill(rect, cols, S):
    """Whatever the colours, the pixels written are the ring's polygon fill
    (a background the colours never take shows which)."""
    x0, y0, x1, y1 = rect
    c = rastrum.Canvas((17, 20), format="rgb888", background=0)
    cols3 = [(1 + a % 255, b, cc) for a, b, cc, _ in cols]  # red >= 1: never the background
    c.fill_rect_gouraud(rect, cols3, subpixel_bits=S)
    want = rastrum.polygon_mask([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], (17, 20), subpixel_bits=S)
    np.testing.assert_array_equal(c.array[..., 0] != 0, want)


def test_rect_clip_does_not_change_values():
    """A sub-view (clipped drawing) gets the same colours as the whole."""
    cols = [(255, 0, 0), (0, 255, 0), (255, 255, 0), (0, 0, 255)]
    for precision in ("exact", "fixed"):
        whole = rastrum.Canvas((30, 40))
        whole.fill_rect_gouraud((-3.3, -2.2, 41.7, 33.1), cols, precision=precision, fraction_bits=6)
        big = np.zeros((30, 40, 3), np.uint8)
        part = rastrum.Canvas.wrap(big[5:20, 7:33])
        part.fill_rect_gouraud((-3.3 - 7, -2.2 - 5, 41.7 - 7, 33.1 - 5), cols, precision=precision,
                               fraction_bits=6)
        np.testing.assert_array_equal(big[5:20, 7:33], whole.array[5:20, 7:33])


def test_rect_corner_order_and_gray():
    """p0 may be any corner: a colour stays with its corner."""
    a = rastrum.Canvas((9, 12), format="gray8")
    b = rastrum.Canvas((9, 12), format="gray8")
    a.fill_rect_gouraud((1, 1, 11, 8), [0, 100, 200, 50])
    b.fill_rect_gouraud((11, 8, 1, 1), [200, 50, 0, 100])
    np.testing.assert_array_equal(a.array, b.array)
    want = rect_gouraud((1, 1, 11, 8), [[0], [100], [200], [50]], (9, 12), channels=1)[..., 0]
    np.testing.assert_array_equal(a.array, want)


def test_rect_errors():
    c = rastrum.Canvas((4, 4))
    cols = [(0, 0, 0)] * 4
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4), cols)
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4, 4), [(0, 0, 0)] * 3)
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4, 4), [(0, 0, 256)] * 4)
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4, 4), cols, precision="fast")
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4, 4), cols, precision="fixed", fraction_bits=17)
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 4, 4), cols, method="quads")
    # a side longer than RAST_GOURAUD_RECT_MAX_SIZE units
    with pytest.raises(ValueError):
        c.fill_rect_gouraud((0, 0, 2 ** 26 / 256 + 1, 4), cols)
    assert not c.array.any()


def test_rect_largest_size_exact():
    """The largest side allowed: exact values at the corners of the view."""
    n = rastrum._native.lib.RAST_GOURAUD_RECT_MAX_SIZE
    c = rastrum.Canvas((3, 3), format="gray8")
    c.fill_rect_gouraud((0, 0, n, n), [0, 255, 255, 255], subpixel_bits=0)
    want = rect_gouraud((0, 0, n, n), [[0], [255], [255], [255]], (3, 3), subpixel_bits=0, channels=1)
    np.testing.assert_array_equal(c.array, want[..., 0])


# ---- polygons with vertex colours (the AET, edge then span) -----------------------

from oracle_shading import polygon_gouraud, triangle_barycentric  # noqa: E402

pcoord = st.one_of(st.integers(-3, 22).map(float), st.floats(-4, 23, allow_nan=False, width=32).map(float),
                   st.integers(-8, 90).map(lambda k: k / 4.0))


@st.composite
def colour_rings(draw, max_rings=3):
    rings = draw(st.lists(st.lists(st.tuples(pcoord, pcoord), min_size=3, max_size=8), min_size=1,
                          max_size=max_rings))
    n = sum(len(r) for r in rings)
    cols = draw(st.lists(st.tuples(color, color, color), min_size=n, max_size=n))
    return rings, cols


@settings(max_examples=examples(200))
@given(rc=colour_rings(), rule=st.sampled_from(["evenodd", "nonzero"]), S=st.sampled_from([0, 2, 8]),
       offset=st.sampled_from([0.5, 0.0]))
def test_polygon_gouraud_matches_oracle(rc, rule, S, offset):
    rings, cols = rc
    c = rastrum.Canvas((19, 21), background=3)
    c.fill_polygon(rings, vertex_colors=cols, rule=rule, subpixel_bits=S, sample_offset=offset)
    want = polygon_gouraud(rings, cols, (19, 21), rule=rule, subpixel_bits=S, sample_offset=offset,
                           channels=3, background=3)
    np.testing.assert_array_equal(c.array, want)


@settings(max_examples=examples(150))
@given(rc=colour_rings(), rule=st.sampled_from(["evenodd", "nonzero"]), S=st.sampled_from([0, 8]),
       precision=st.sampled_from(["exact", "flat"]))
def test_polygon_gouraud_pixels_are_the_fill(rc, rule, S, precision):
    """The pixels written are exactly the plain fill's (holes, both rules)."""
    rings, cols = rc
    cols = [(1 + r % 255, g, b) for r, g, b in cols]  # red >= 1: never the background
    c = rastrum.Canvas((19, 21))
    c.fill_polygon(rings, vertex_colors=cols, rule=rule, subpixel_bits=S, **spell(precision))
    want = rastrum.polygon_mask(rings, (19, 21), rule=rule, subpixel_bits=S)
    np.testing.assert_array_equal(c.array[..., 0] != 0, want)
    if precision == "flat":
        assert (c.array[want] == cols[0]).all()


@settings(max_examples=examples(150))
@given(tri=st.lists(st.tuples(pcoord, pcoord), min_size=3, max_size=3),
       cols=st.lists(st.tuples(color, color, color), min_size=3, max_size=3),
       S=st.sampled_from([0, 4, 8]))
def test_polygon_gouraud_triangle_is_barycentric(tri, cols, S):
    """For a triangle, edge-then-span equals the barycentric interpolation
    exactly (both are the affine function through the vertex colours)."""
    c = rastrum.Canvas((19, 21))
    c.fill_polygon(tri, vertex_colors=cols, subpixel_bits=S)
    np.testing.assert_array_equal(c.array, triangle_barycentric(tri, cols, (19, 21), subpixel_bits=S,
                                                                channels=3))


def test_polygon_gouraud_far_coordinates():
    """Edges near the ends of the coordinate range: the 128-bit products."""
    lim = rastrum._native.lib.RAST_COORD_MAX / 256.0
    ring = [(-lim, -lim), (lim, -lim * 0.999), (lim * 0.3, lim), (0.7, 10.3)]
    cols = [(255, 0, 10), (0, 255, 200), (30, 60, 255), (255, 255, 255)]
    c = rastrum.Canvas((12, 16))
    c.fill_polygon(ring, vertex_colors=cols)
    np.testing.assert_array_equal(c.array, polygon_gouraud([ring], cols, (12, 16), channels=3))


def test_polygon_gouraud_errors():
    c = rastrum.Canvas((8, 8))
    ring = [(0, 0), (8, 0), (4, 8)]
    with pytest.raises(ValueError):
        c.fill_polygon(ring, vertex_colors=[(0, 0, 0)] * 2)
    with pytest.raises(ValueError):
        c.fill_polygon(ring, vertex_colors=[(0, 0, 0)] * 3, algorithm="xscan")
    with pytest.raises(ValueError):
        c.fill_polygon(ring, vertex_colors=[(0, 0, 0)] * 3, precision="fixed")
    with pytest.raises(ValueError):
        c.fill_polygon(ring, vertex_colors=[(0, 0, 0)] * 3, boundary="closed")
    with pytest.raises(ValueError):
        c.fill_polygon(ring)
    assert not c.array.any()

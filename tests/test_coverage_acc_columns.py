""""accumulate" into a painter (Canvas.fill_polygon, aa="accumulate"), whose
walk is narrowed to the columns the edges reach (rast__acc_narrow in
csrc/src/coverage/coverage_acc.c: [floor(min x), floor(max x) + 1) of the
clip), and meshes of rings whose edges span eight rows or more on the mean
(walked a band of rows at a time), against the accumulation's definition
from the exact oracle.

The rings lie inside the canvas, so the walk is narrowed: their leftmost
and rightmost vertices on a pixel's side, 1/256 px either side of it or
between, so that the last column reached holds a sliver or nothing, and
the first and last columns of the clip are reached or not.  A range cut by
one column on either side leaves a sliver's pixels 0."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import _accumulated, _n_m, check_area

# offsets from a pixel's side, in 1/256 px: on it, a subpixel either side,
# half a pixel
_NUDGE = [0, 1, -1, 128]


def _paint(rings, shape, rule):
    """rings painted in one call (the walk narrowed to the columns they
    reach), 255 over 0: the coverage levels"""
    canvas = rastrum.Canvas.wrap(np.zeros(shape, np.uint8))
    canvas.fill_polygon(rings, 255, rule=rule, aa="accumulate")
    return canvas.array


@st.composite
def _column_rings(draw):
    """A convex ring of 3-6 vertices inside a canvas of width w: its
    leftmost vertex at column c0's left side nudged, its rightmost at
    column c1's, c0 and c1 anywhere from the clip's first column to its
    last (the ring may touch the canvas' left and right sides); vertical
    and horizontal edges where vertices share a coordinate."""
    w = draw(st.integers(2, 12), label="width")
    h = draw(st.integers(2, 8), label="height")
    c0 = draw(st.integers(0, w - 1), label="c0")
    c1 = draw(st.integers(c0 + 1, w), label="c1")
    n0, n1 = draw(st.sampled_from(_NUDGE)), draw(st.sampled_from(_NUDGE))
    x0 = max(0, c0 * 256 + n0)
    x1 = min(w * 256, c1 * 256 - abs(n1) if n1 != 128 else c1 * 256 - 128)
    if x1 <= x0:
        x1 = x0 + 1
    ys = draw(st.lists(st.sampled_from([0, 1, 128, 255, 256]), min_size=2, max_size=2))
    ya, yb = ys[0], h * 256 - ys[1]
    if yb <= ya:
        yb = ya + 1
    shape = draw(st.sampled_from(["triangle", "box", "diamond", "trapezoid"]))
    mid_y = (ya + yb) // 2
    xm = draw(st.integers(x0, x1))
    if shape == "triangle":  # leftmost and rightmost on its base: a horizontal edge
        pts = [(x0, yb), (xm, ya), (x1, yb)]
    elif shape == "box":  # vertical edges on the nudged sides
        pts = [(x0, ya), (x1, ya), (x1, yb), (x0, yb)]
    elif shape == "diamond":  # the extreme columns reached at one point each
        pts = [(xm, ya), (x1, mid_y), (xm, yb), (x0, mid_y)]
    else:
        xa, xb = sorted(draw(st.lists(st.integers(x0, x1), min_size=2, max_size=2)))
        pts = [(xa, ya), (xb, ya), (x1, yb), (x0, yb)]
    if draw(st.booleans()):
        pts = pts[::-1]
    ring = [(x / 256.0, y / 256.0) for x, y in pts]
    return ring, (h, w)


@settings(max_examples=S_.examples(40), deadline=None)
@given(_column_rings(), st.sampled_from(["nonzero", "evenodd"]))
def test_painter_columns_reached(scene, rule):
    """Each column the ring reaches is painted, the first and the last
    among them, where a sliver of 1/256 px falls in it: against the oracle
    (check_area's bound: no pixel off by more than a tie allows)."""
    ring, shape = scene
    want = _accumulated([ring], shape, rule, 8)
    n, m = _n_m([ring], 8)
    check_area(_paint([np.array(ring)], shape, rule), want, 255, n, m, S_.lit([ring]))


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(2, 3), st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 2, 256]),
       st.sampled_from(["nonzero", "evenodd"]), st.booleans())
def test_mesh_of_tall_cells(cols, seed, snap, rule, paint):
    """A mesh of cols x 1 cells about 3 px wide and 14 px tall, each cell
    two triangles given as two rings (edges of 8 rows or more on the mean:
    the band walk), inner vertices on a grid of 1/snap px (pixel corners,
    half pixels: edges ending on them, levels on a tie), the mesh's sides
    on the clip's first and last columns, into an array in one call or a
    painter a ring a call; against the oracle."""
    rnd = np.random.default_rng(seed)
    h, w = 16, 3 * cols
    gx = np.linspace(0, w, cols + 1)
    xs_top = gx.copy()
    xs_bot = gx.copy()
    xs_top[1:-1] += rnd.uniform(-1, 1, cols - 1)
    xs_bot[1:-1] += rnd.uniform(-1, 1, cols - 1)
    xs_top, xs_bot = np.round(xs_top * snap) / snap, np.round(xs_bot * snap) / snap
    y0, y1 = np.round(rnd.uniform(0, 1.5) * snap) / snap, np.round(rnd.uniform(14.5, 16) * snap) / snap
    rings = []
    for c in range(cols):
        a, b = (xs_top[c], y0), (xs_top[c + 1], y0)
        d, e = (xs_bot[c + 1], y1), (xs_bot[c], y1)
        rings += [[a, b, d], [a, d, e]]
    shape = (h, w)
    want = _accumulated(rings, shape, rule, 8)
    n, m = _n_m(rings, 8)
    if paint:
        out = _paint([np.array(r) for r in rings], shape, rule)
    else:
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate")
    check_area(out, want, 255, n, m, S_.lit(rings))

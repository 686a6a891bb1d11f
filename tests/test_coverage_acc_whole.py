""""accumulate"'s whole-edge walk of a pile (csrc/src/coverage/
coverage_acc.c, rast__acc_whole_in, session 20): its edges that lie in one
column (a piece a row, no column stepper), its edges in one row (no row
stepper; from the edge's top to its bottom end in the one row, in one
column or across verticals), and the first, middle and last rows of the
others, for both directions and both signs of edge.  Piles of triangles
with a flat side inside one pixel row, or a steep side inside one pixel
column, or both, among taller ones (every edge 32 rows high or less, the
rows dense: the piles' walk, docs/coverage.md), vertices on grids of 1/4
and 1/256 pixel, as rings either way round (polygon_coverage, uint8 and
uint16, both rules) and as a triangle batch; against the accumulation's own
definition from the exact oracle (test_coverage._accumulated: each ring's
exact signed area over each pixel, summed, the rule applied)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage import check_accumulate as _check, check_accumulate_batch


def _snap(p, snap):
    return (round(p[0] * snap) / snap, round(p[1] * snap) / snap)


def _tri(rnd, shape, snap, kind):
    """A triangle 12 to 20 rows high inside the canvas, of one kind: 0, a
    side inside one pixel row (1 to 6 columns long, or inside one column);
    1, a side inside one pixel column; 2, both (a side in one pixel)."""
    h, w = shape
    ht = rnd.uniform(12.0, 20.0)
    while True:
        y0 = np.floor(rnd.uniform(0.0, h - ht - 1.0)) + rnd.uniform(0.05, 0.45)
        if kind == 0:
            x0 = rnd.uniform(8.0, w - 8.0)
            b = (x0 + rnd.choice([-1, 1]) * rnd.uniform(0.0, 6.0), y0 + rnd.uniform(0.1, 0.5))
            a = (x0, y0)
        elif kind == 1:
            c = np.floor(rnd.uniform(8.0, w - 8.0))
            a = (c + rnd.uniform(0.05, 0.95), y0)
            b = (c + rnd.uniform(0.05, 0.95), y0 + rnd.uniform(2.0, ht))
        else:
            c = np.floor(rnd.uniform(8.0, w - 8.0))
            a = (c + rnd.uniform(0.05, 0.95), y0)
            b = (c + rnd.uniform(0.05, 0.95), y0 + rnd.uniform(0.1, 0.5))
        far = (a[0] + rnd.uniform(-7.0, 7.0), y0 + ht)
        tri = [_snap(a, snap), _snap(b, snap), _snap(far, snap)]
        area = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[2][0] - tri[0][0]) * (tri[1][1] - tri[0][1])
        if area != 0 and all(0 < x < w and 0 <= y < h for x, y in tri):
            return tri if rnd.integers(2) else tri[::-1]


def _pile(rnd, k, shape, snap):
    return [_tri(rnd, shape, snap, i % 3) for i in range(k)]


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_whole_edges_in_one_row_or_column(seed, snap, rule):
    """60 triangles, each with a side in one pixel row, in one pixel
    column, or in one pixel, on a canvas 48 x 40 (the ring's rows used
    again below row 32)."""
    rnd = np.random.default_rng(seed)
    shape = (48, 40)
    _check(_pile(rnd, 60, shape, snap), shape, rule)


def test_whole_edges_triangle_batch():
    """triangles_coverage(method="accumulate") of such piles is the
    accumulation of the same triangles, each turned counter-clockwise."""
    rnd = np.random.default_rng(20)
    shape = (48, 40)
    for snap in (4, 256, 4, 256):
        rings = _pile(rnd, 60, shape, snap)
        check_accumulate_batch(rings, shape)

""""accumulate"'s band walk on piles of small triangles (csrc/src/coverage/
coverage_acc.c, rast__acc_short_in): an edge that lies in the clip's
columns and meets a band in two rows or more, its first or last among them,
is walked there in one loop, its row and column steppers in registers, its
parts' columns between the first and last vertical crossed deposited whole
(docs/coverage.md, the accumulation's band walk).  Triangles 12 to 20 rows
high (every edge long enough on the mean for the band walk), shallow and
steep sides, vertices on grids of 1, 1/4 and 1/256 pixel (sides that start
and end on row boundaries among them), in bands whose rows are read whole
(many parts for the width: no cell marked) and in bands whose touched cells
are marked (few parts on a wide canvas); against the accumulation's own
definition from the exact oracle (tests/oracle.py through test_coverage):
each ring's exact signed area over each pixel, summed, the rule applied."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage import check_accumulate as _check, check_accumulate_batch


def _triangles(rnd, k, shape, snap, slope):
    """k triangles, apex above, 12 to 20 rows high, every vertex inside
    the canvas's columns (the edges in the clip), sides up to `slope`
    columns a row; each turned either way round."""
    h, w = shape
    rings = []
    while len(rings) < k:
        x0, y0 = rnd.uniform(1.0, w - 1.0), rnd.uniform(0.0, h - 13.0)
        tri = [(x0, y0)]
        for _ in range(2):
            dy = rnd.uniform(12.0, min(20.0, h - 0.5 - y0))
            dx = rnd.uniform(-slope, slope) * dy
            tri.append((min(max(x0 + dx, 0.5), w - 0.5), y0 + dy))
        tri = [(round(x * snap) / snap, round(y * snap) / snap) for x, y in tri]
        a = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[2][0] - tri[0][0]) * (tri[1][1] - tri[0][1])
        if a == 0:
            continue
        rings.append(tri if rnd.integers(2) else tri[::-1])
    return rings


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 4, 256]), st.sampled_from([0.3, 1.5]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_small_triangles_dense_bands(seed, snap, slope, rule):
    """10 triangles on a canvas 36 pixels wide: several parts for every 32
    columns in each row (the band's rows read whole, its span of columns
    standing for the marks); steep sides (a vertical now and then) or
    shallow ones (several a row, the whole columns between)."""
    rnd = np.random.default_rng(seed)
    shape = (30, 36)
    _check(_triangles(rnd, 10, shape, snap, slope), shape, rule)


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 4, 256]), st.sampled_from([0.3, 1.5]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_small_triangles_marked_bands(seed, snap, slope, rule):
    """One or two triangles on a canvas 160 pixels wide: few parts for the
    width, so that each part marks the cells it touches."""
    rnd = np.random.default_rng(seed)
    shape = (30, 160)
    rings = _triangles(rnd, 1 + int(rnd.integers(2)), (30, 40), snap, slope)
    off = rnd.uniform(0.0, 110.0)
    rings = [[(x + round(off), y) for x, y in r] for r in rings]
    _check(rings, shape, rule)


def test_triangle_batch_equals_rings():
    """triangles_coverage(method="accumulate") of a pile of small
    triangles is the accumulation of the same triangles, each turned
    counter-clockwise (the batch's own turning), as rings."""
    rnd = np.random.default_rng(18)
    shape = (30, 36)
    for snap in (1, 4, 256):
        rings = _triangles(rnd, 10, shape, snap, 1.0)
        check_accumulate_batch(rings, shape)

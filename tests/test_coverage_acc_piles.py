""""accumulate"'s walk of piles of small triangles (csrc/src/coverage/
coverage_acc.c, rast__acc_by_piles): when every edge is 32 rows high or
less and the rows are dense on the mean, each edge is walked whole, once,
into a ring of 64 rows of cells (rast__acc_whole_in: both steppers set by
a division each, the same pieces as the bands' walk), the rows read out a
window at a time; edges that leave the clip go row by row the general way;
a row with a level near a tie is counted again per 16 columns or goes to
the exact sweep (docs/coverage.md, the accumulation's piles).  Piles of 60
to 90 triangles 9 to 30 rows high on canvases 40 to 72 rows tall (windows
of 32 rows and more, edges that start in one window and end in the next,
rows of the ring used again), steep and shallow sides, vertices on grids
of 1, 1/4 and 1/256 pixel, some triangles past each side of the canvas;
against the accumulation's own definition from the exact oracle
(tests/oracle.py through test_coverage): each ring's exact signed area over
each pixel, summed, the rule applied."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage import check_accumulate as _check, check_accumulate_batch


def _pile(rnd, k, shape, snap, slope, hmin, hmax, out):
    """k triangles, hmin to hmax rows high, sides up to `slope` columns a
    row; with out, about one in five reaching past a side of the canvas
    (above, below, left or right); each turned either way round."""
    h, w = shape
    rings = []
    while len(rings) < k:
        ht = rnd.uniform(hmin, hmax)
        x0, y0 = rnd.uniform(1.0, w - 1.0), rnd.uniform(0.0, h - ht)
        if out and rnd.integers(5) == 0:
            side = rnd.integers(4)
            if side == 0:
                y0 = -rnd.uniform(0.5, ht / 2)
            elif side == 1:
                y0 = h - ht / 2
            elif side == 2:
                x0 = -rnd.uniform(0.5, 4.0)
            else:
                x0 = w + rnd.uniform(0.5, 4.0)
        tri = [(x0, y0)]
        for q in range(2):
            dy = ht if q == 0 else rnd.uniform(ht / 3, ht)
            dx = rnd.uniform(-slope, slope) * dy
            tri.append((x0 + dx, y0 + dy))
        tri = [(round(x * snap) / snap, round(y * snap) / snap) for x, y in tri]
        a = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[2][0] - tri[0][0]) * (tri[1][1] - tri[0][1])
        if a == 0:
            continue
        rings.append(tri if rnd.integers(2) else tri[::-1])
    return rings


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 4, 256]), st.sampled_from([0.3, 1.5]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_piles_in_the_canvas(seed, snap, slope, rule):
    """60 triangles 9 to 16 rows high inside a canvas 44 x 40: every edge
    walked whole; the ring's rows used again below row 32."""
    rnd = np.random.default_rng(seed)
    shape = (44, 40)
    _check(_pile(rnd, 60, shape, snap, slope, 9.0, 16.0, False), shape, rule)


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 4, 256]), st.sampled_from([0.3, 1.5]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_piles_past_the_sides(seed, snap, slope, rule):
    """60 triangles 9 to 16 rows high, about one in five past a side of a
    canvas 40 x 44 (those edges row by row, the general way)."""
    rnd = np.random.default_rng(seed)
    shape = (40, 44)
    _check(_pile(rnd, 60, shape, snap, slope, 9.0, 16.0, True), shape, rule)


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_tall_piles(seed, snap, rule):
    """Triangles up to 30 rows high on a canvas 72 rows tall (windows of 34
    rows or more: an edge that starts in one window ends in the next)."""
    rnd = np.random.default_rng(seed)
    shape = (72, 36)
    _check(_pile(rnd, 40, shape, snap, 0.6, 14.0, 30.0, True), shape, rule)


def test_triangle_batch_equals_rings():
    """triangles_coverage(method="accumulate") of a pile is the
    accumulation of the same triangles, each turned counter-clockwise, as
    rings."""
    rnd = np.random.default_rng(19)
    shape = (40, 44)
    for snap in (1, 4, 256):
        rings = _pile(rnd, 60, shape, snap, 1.0, 9.0, 16.0, True)
        check_accumulate_batch(rings, shape)

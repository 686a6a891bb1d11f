""""accumulate"'s steppers made lazily (csrc/src/coverage/coverage_acc.c,
rast__acc_t_at, rast__acc_t_next, rast__acc_qxs): in the rows' walk an
edge's column stepper is set at the first vertical it crosses without its
step (qX RAST__ACC_LAZYX), and its row stepper at its second row's top
without the row step (qxsr RAST__ACC_UNMADE); an edge that goes on has
the step made where it is first stepped: at the next vertical (in the
one-crossing way or in rast__acc_part's), at its third row's top, in the
tie passes' step back (rast__acc_top_back), and across an exact row that
rebuilds every record (rast__acc_load sets the lazy stepper again).
Small triangles (edges of one to four rows, crossing up to five
verticals: the rows' walk), their vertices on a fine grid or on a 1/6
pixel grid (ties, exact rows), against the exact oracle
(test_coverage._accumulated) with check_area's allowance at a tie."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage_acc_compact import _check, _tie_triangle


def _triangles(rnd, k, grid, width, rows):
    """k triangles, vertices on the 1/grid pixel grid, each in a box
    `width` px wide and `rows` tall at a random place in the 6 x 12 canvas
    (or a little out of it), either orientation."""
    out = []
    for _ in range(k):
        x0, y0 = rnd.integers(-1, 12 - width + 2), rnd.integers(-1, 6 - rows + 2)
        xs = rnd.integers(0, width * grid + 1, 3) / grid + x0
        ys = rnd.integers(0, rows * grid + 1, 3) / grid + y0
        out.append([(float(x), float(y)) for x, y in zip(xs, ys)])
    return out


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 8), st.sampled_from([6, 256]), st.integers(1, 5),
       st.integers(1, 4), st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_short_edges_stepped_on_after_a_lazy_start(seed, k, grid, width, rows, rule, dtype):
    _check(_triangles(np.random.default_rng(seed), k, grid, width, rows), rule, dtype)


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(1, 3), st.integers(0, 3), st.booleans(), st.booleans(), st.booleans(),
       st.sampled_from(["evenodd", "nonzero"]))
def test_a_lazy_stepper_across_a_row_that_rebuilds_every_record(y, dx, mirror, reverse, tie_reverse, rule):
    """A slanted edge crosses one vertical in row y - 1 (its stepper set
    without the step) and one a row below it, where a tie in a row of
    five of the call's six edges sends the row to the exact sweep with
    every record rebuilt; below, the edge crosses the next verticals."""
    ring = [(5.5 + dx, y - 0.5), (9.5 + dx, y + 2.5), (5.2 + dx, y + 2.9)]
    if mirror:
        ring = [(17.0 - a, b) for a, b in ring]
    if reverse:
        ring = ring[::-1]
    rings = [_tie_triangle(0 if not mirror else 8, y, mirror, False, tie_reverse), ring]
    for dtype in (np.uint8, np.uint16):
        _check(rings, rule, dtype)


def test_one_edge_through_five_verticals_in_four_rows():
    """(2.5, 0.5) to (7.5, 4.25): x = 3 in its first row (a lazy stepper),
    then 4, 5, 6, 7 a row or so apart, each way round and mirrored."""
    for mirror in (False, True):
        for rev in (False, True):
            ring = [(2.5, 0.5), (7.5, 4.25), (2.0, 5.0)]
            if mirror:
                ring = [(12.0 - a, b) for a, b in ring]
            if rev:
                ring = ring[::-1]
            _check([ring], "nonzero", np.uint16)

""""accumulate"'s band walk in dense bands (csrc/src/coverage/coverage_acc.c,
rast__acc_by_bands): long shallow edges, each crossing several columns in
every row of a band whose four rows all hold enough parts to be read whole,
so that no cell is marked (the band's span of columns stands for the marks)
and each row's columns between its ends are deposited by the column
stepper's loop (rast__acc_cols_in: each column's height from the stepper's
carry, the stepper itself brought up to date after the loop), in both
directions and both orientations, against the accumulation's definition
from the exact oracle (tests/oracle.py through test_coverage)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _accumulated, _n_m, check_area

SHAPE = (40, 72)


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(2, 4), st.integers(0, 2 ** 32 - 1), st.sampled_from([4, 256]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_shallow_triangles_in_dense_bands(k, seed, snap, rule):
    """k triangles across the image, each with two edges from near its left
    side to near its right side over 10 to 30 rows (2 to 7 columns a row)
    and one steep edge at one side: every edge long (the band walk), the
    rows' parts many for the width (dense), vertices on a grid of 1/snap."""
    rnd = np.random.default_rng(seed)
    h, w = SHAPE
    rings = []
    for _ in range(k):
        xl, xr = rnd.uniform(-3.0, 6.0), rnd.uniform(w - 6.0, w + 3.0)
        y0 = rnd.uniform(-2.0, h - 12.0)
        ya, yb = y0 + rnd.uniform(10.0, 30.0), y0 + rnd.uniform(10.0, 30.0)
        tri = [(xl, y0), (xr, ya), (xl if rnd.integers(2) else xr, yb)] if rnd.integers(2) else \
              [(xr, y0), (xl, ya), (xr if rnd.integers(2) else xl, yb)]
        tri = [(round(x * snap) / snap, round(y * snap) / snap) for x, y in tri]
        a = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[2][0] - tri[0][0]) * (tri[1][1] - tri[0][1])
        if a == 0:
            continue
        rings.append(tri if rnd.integers(2) else tri[::-1])
    if not rings:
        return
    want = _accumulated(rings, SHAPE, rule, 8)
    n, m = _n_m(rings, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=dtype)
        check_area(out, want, M_OF[dtype], n, m, S_.lit(rings))

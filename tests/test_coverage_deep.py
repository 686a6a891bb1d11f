""""area" where shapes overlap deeply (issue 33): in a row taken group by
group (coverage_area.c, rast__cov_row_groups; rows of more than 32 edges),
a group whose winding numbers cannot reach 0 under non-zero adds nothing,
and a group of edges that all span the row is cut into blocks that do
not meet (rast__grp_blocks): one edge alone added whole with the sign its
winding numbers give, several (crossing or coincident) swept alone.  Many
overlapping rings, coincident edges, crossings on pixel corners, against
the exact oracle of tests/oracle_coverage.py within the bound of
rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _check(rl, shape, rule, dtype, what):
    out = rastrum.polygon_coverage(rl, shape, rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, shape, rule, 8), M_OF[dtype], n, m, what)


def _slanted(rnd, h, w, count, grid):
    """`count` long quads and triangles from above the strip to below it
    (their edges span its rows and cross each other inside them), either
    orientation, some of them twice (coincident edges); vertices on the
    quarter-pixel grid, or on pixel corners when `grid`."""
    rings = []
    q = 1.0 if grid else 0.25
    for _ in range(count):
        xa, xb = (np.round(rnd.uniform(-2, w + 2, 2) / q) * q).tolist()
        wa, wb = (np.round(rnd.uniform(q, 3, 2) / q) * q).tolist()
        if rnd.integers(0, 3):
            r = [(xa, -1.0), (xa + wa, -1.0), (xb + wb, h + 1.0), (xb, h + 1.0)]
        else:
            r = [(xa, -1.0), (xb + wb, h + 1.0), (xb, h + 1.0)]
        if rnd.integers(0, 2):
            r = r[::-1]
        rings.append(r)
        if rnd.integers(0, 5) == 0:  # the same ring again, either way round
            rings.append(r if rnd.integers(0, 2) else r[::-1])
    return rings


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 2), st.just(17),
       st.booleans(), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_deep_overlaps_equal_oracle(seed, h, count, grid, rule, dtype):
    rnd = np.random.default_rng(seed)
    w = 12
    rl = _slanted(rnd, h, w, count, grid)
    if rnd.integers(0, 2):  # and a ring with vertices inside the rows
        rl.append([(0.5, 0.25), (w - 0.5, h - 0.75), (w * 0.5, h - 0.25)])
    _check(rl, (h, w), rule, dtype, repr((seed, h, count, grid)))


def test_crossings_on_pixel_corners():
    # X shapes: two edges from corner to corner crossing on a pixel corner
    # (and on a row's top or bottom), 9 pairs of them deep in one wide box
    rl = [[(-1.0, -1.0), (40.0, -1.0), (40.0, 5.0), (-1.0, 5.0)]]
    for k in range(9):
        x = 2.0 * k
        rl.append([(x, 0.0), (x + 2, 2.0), (x + 2, 0.0), (x, 2.0)])  # a bow tie
        rl.append([(x + 1, 1.0), (x + 3, 3.0), (x + 3, 1.0), (x + 1, 3.0)][::(-1) ** k])
    for rule in ("evenodd", "nonzero"):
        _check(rl, (3, 20), rule, np.uint8, "corners " + rule)


def test_coincident_edges_deep_inside():
    # 12 copies of one slanted band inside a box (winding up to 9: under
    # non-zero nothing to add inside), two of them turned the other way
    # (cancelled in pairs), a band crossing them all, 8 upright strips
    band = [(3.0, -1.0), (5.5, -1.0), (30.25, 4.0), (27.75, 4.0)]
    rl = [[(-1.0, -1.0), (40.0, -1.0), (40.0, 4.0), (-1.0, 4.0)]]
    rl += [band if k % 6 else band[::-1] for k in range(12)]
    rl.append([(30.0, -1.0), (31.5, -1.0), (1.5, 4.0), (0.0, 4.0)])
    rl += [[(x, -1.0), (x + 0.5, -1.0), (x + 0.5, 4.0), (x, 4.0)] for x in range(4, 36, 4)]
    for rule in ("evenodd", "nonzero"):
        _check(rl, (3, 36), rule, np.uint8, "coincident " + rule)

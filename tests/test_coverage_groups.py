""""area" on rows of many rings (issue 33): a row that is not fast as a
whole is taken group by group (coverage_area.c, rast__cov_row_groups), each
group of edges whose columns meet added whole or swept alone from the
winding number on its left.  Rows of more than 32 edges go that way: small
rings side by side, overlapping or nested, with horizontal edges inside the
rows (which join groups), against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _scene(seed, h, w, count):
    """`count` small rings along a strip h rows tall: triangles, boxes
    with their tops and bottoms inside rows, boxes with holes, either
    orientation, some overlapping their neighbours, one long ring across."""
    rnd = np.random.default_rng(seed)
    rings = []
    for k in range(count):
        x, y = rnd.uniform(-0.5, w - 1.5), rnd.uniform(-0.5, h - 1.5)
        kind = rnd.integers(0, 4)
        if kind == 0:
            r = (np.array([x, y]) + rnd.uniform(0, 2.5, (3, 2))).tolist()
        else:
            x0, y0 = round(x * 4) / 4, round(y * 4) / 4 + 0.5
            x1, y1 = x0 + rnd.choice([0.75, 1.25, 2.5]), y0 + rnd.choice([0.5, 1.25, 2.0])
            r = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            if kind == 3:  # a hole, turned the other way
                rings.append(r)
                r = [(x0 + 0.25, y0 + 0.25), (x0 + 0.25, y1 - 0.25), (x1 - 0.25, y1 - 0.25),
                     (x1 - 0.25, y0 + 0.25)]
        if rnd.integers(0, 2):
            r = r[::-1]
        rings.append(r)
    if rnd.integers(0, 2):
        rings.append([(-1, 0.3), (w + 1, h * 0.6), (w * 0.5, h * 0.8)])
    return rings


@settings(max_examples=S_.examples(25), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 4), st.sampled_from([16, 24, 40]),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_many_rings_in_a_row_equal_oracle(seed, h, count, rule, dtype):
    w = 2 * count
    rl = _scene(seed, h, w, count)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m, repr((seed, h, count)))


def test_side_by_side_rings_apart_and_overlapping():
    # 40 boxes with tops and bottoms inside the row, apart, then each
    # overlapped by the next (a row of 80 edges: no fast row, groups)
    for step in (1.5, 0.75):
        rl = [[(0.25 + step * k, 0.5), (1.25 + step * k, 0.5), (1.25 + step * k, 1.75),
               (0.25 + step * k, 1.75)] for k in range(40)]
        shape = (3, 64)
        for rule in ("evenodd", "nonzero"):
            out = rastrum.polygon_coverage(rl, shape, rule=rule)
            n, m = _n_m(rl, 8)
            check_area(out, exact_area(rl, shape, rule, 8), 255, n, m, "boxes %s" % step)

""""area"'s sweep (coverage_area.c, rast__cov_row_area) sets each edge's
line at the bottom of the row (xT + rT/dy: the order of neighbours there,
whether they cross inside the row); for an edge that starts inside the
row, rast__sweep_x_bottom computes it by 64-bit divisions, |dx| rel / dy
then the rest's bits a step at a time, or rast__cov_x_at's 128-bit way
when the quotient would pass 2^62 (shallow edges: |dx| / dy of 4 and more
at S = 8, of 1/4 and more at S = 0).  Stroke-like self-crossing rings
(a zig-zag of steep and shallow edges, both ways, and the same zig-zag
shifted back along it: winding numbers of 2 where they overlap), their
vertices inside the rows (or on the grid of 1/4 px), at S = 0, 4 and 8,
against the exact oracle of tests/oracle_coverage.py within the bound of
rastrum.h (docs/coverage.md)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _zigzag(rnd, h, w, count, grid):
    """A ring of `count` points forward along a zig-zag across an h x w
    canvas and back along the same zig-zag shifted by a fraction of a
    pixel: steep and shallow edges (dx up to the width, dy down to 1/20
    px), every vertex inside a row or on the grid of 1/4 px."""
    pts = []
    y = rnd.uniform(0.05, h - 0.05)
    for _ in range(count):
        x = rnd.uniform(-1.0, w + 1.0)
        if rnd.integers(0, 3):  # shallow: a small step in y
            y = min(max(y + rnd.uniform(-0.6, 0.6), 0.05), h - 0.05)
        else:
            y = rnd.uniform(0.05, h - 0.05)
        if grid:
            x, y = round(x * 4) / 4, round(y * 4) / 4
        pts.append((x, y))
    ox, oy = rnd.uniform(-0.6, 0.6), rnd.uniform(0.1, 0.5)
    back = [(x + ox, y + oy) for (x, y) in pts[::-1]]
    return [pts + back]


@settings(max_examples=S_.examples(60), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([0, 4, 8]), st.booleans(),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_zigzag_rings_equal_oracle(seed, s, grid, rule, dtype):
    rnd = np.random.default_rng(seed)
    h, w = 3, 10
    rl = _zigzag(rnd, h, w, int(rnd.integers(4, 9)), grid)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, subpixel_bits=s, dtype=dtype)
    n, m = _n_m(rl, s)
    check_area(out, exact_area(rl, (h, w), rule, s), M_OF[dtype], n, m, repr((seed, s, grid)))

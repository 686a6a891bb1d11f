""""area" where many edges cross in a row and some of them start or end
inside it (issue 33): such a group of a row (coverage_area.c,
rast__cov_row_groups) is cut into blocks by its edges' lines across the
whole strip (rast__grp_lines, rast__grp_blocks with `lines`), each block
swept alone, or added whole when it is one edge, or skipped when its
winding numbers cannot reach 0 under non-zero.  The winding number left
of a block is the one just below the row's top.  Groups of more than 128
edges with vertices inside the rows, no horizontal edge inside them:
triangles and quads piled on a narrow canvas (cusps and chains inside the
rows, vertices on pixel corners, coincident edges), against the exact
oracle of tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _check(rl, shape, rule, dtype, what):
    out = rastrum.polygon_coverage(rl, shape, rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, shape, rule, 8), M_OF[dtype], n, m, what)


def _slivers(rnd, w, count, grid):
    """`count` thin slanted triangles side by side across a one-row canvas
    of width w, each with one vertex inside the row (its base above or
    below the row: a cusp inside it, two edges that start or end there),
    every third one a band bent inside the row instead (chains: one edge
    ends where the next starts), leaning one way so that their columns
    overlap (one group of the row);
    every fifth one wider, across its neighbours (crossings: blocks of
    several edges), a few twice (coincident edges).  Apices anywhere in
    the row, or on the quarter-pixel grid when `grid` (on the row's top
    too).  Few crossings, so that the oracle stays quick."""
    rings = []
    lean = rnd.uniform(1.0, 2.5) * (1 if rnd.integers(0, 2) else -1)
    for k in range(count):
        x = -1.0 + (w + 2.0) * k / count + rnd.uniform(0, 0.05)
        y = rnd.uniform(0.02, 0.98)
        if grid:
            y = float(rnd.integers(0, 4)) / 4
        d = 1.2 if k % 5 == 0 else 0.1
        if k % 3 == 1:  # a band from above the row to below it, bent inside it (chains),
            # wide: its sides in blocks apart, others between them
            y2 = rnd.uniform(0.02, 0.98) if not grid else y
            d = rnd.uniform(1.5, 2.5)
            b = x - lean * (y + 0.5)
            r = [(b, -0.5), (x, y), (x + 0.9 * lean * (1.5 - y), 1.5),
                 (x + 0.9 * lean * (1.5 - y2) + d, 1.5), (x + d, y2), (b + d, -0.5)]
        else:  # a sliver whose base is below the row, or above it (a cusp)
            yb = 1.5 if rnd.integers(0, 2) else -0.5
            xb = x + lean * (yb - y)
            r = [(x, y), (xb, yb), (xb + d, yb)]
        if rnd.integers(0, 2):
            r = r[::-1]
        rings.append(r)
        if rnd.integers(0, 12) == 0:  # the same ring again, either way round
            rings.append(r if rnd.integers(0, 2) else r[::-1])
    return rings


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.booleans(), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]), st.booleans())
def test_slivers_equal_oracle(seed, grid, rule, dtype, box):
    rnd = np.random.default_rng(seed)
    w = 6
    rl = _slivers(rnd, w, 56, grid)
    if box:  # a box round them: winding numbers of 2 and more inside
        rl.append([(-3.5, -1.0), (w + 3.5, -1.0), (w + 3.5, 2.0), (-3.5, 2.0)][::1 if rnd.integers(0, 2) else -1])
    _check(rl, (1, w), rule, dtype, repr((seed, grid, box)))

""""area" where a swept row's events are a ring's vertices (issue 34's
stroke): an edge ends at a vertex inside the row and the next edge of its
ring, of the same direction, starts there (coverage_area.c,
rast__cov_replace, and the other vertex events), the vertex's abscissa
taken as the edges' own end (rast__cov_at_top, rast__cov_end_at), and
pieces that begin at a crossing or a vertex and reach the row's bottom,
ended at the line's abscissa the sweep set there (xT).  Rings that walk
down the rows and back up, zigzagging so that they cross themselves and
each other on and between the vertices' ordinates, with long quads across
the rows so that the rows are swept; against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _zigzag(rnd, h, w, steps, q):
    """Down the rows through `steps` vertices (ordinates on the grid of q
    px, strictly increasing: every edge of the way down points down), then
    back up through as many: a ring whose two sides cross each other."""
    ys = np.sort(rnd.choice(np.arange(1, int(h / q)), size=steps, replace=False)) * q
    down = [(float(np.round(rnd.uniform(-1, w + 1), 2)), float(y)) for y in ys]
    up = [(float(np.round(rnd.uniform(-1, w + 1), 2)), float(y)) for y in ys[::-1]]
    ring = [(float(rnd.uniform(0, w)), -0.5)] + down + [(float(rnd.uniform(0, w)), h + 0.5)] + up
    return ring if rnd.integers(0, 2) else ring[::-1]


def _scene(rnd, h, w, rings, steps, q):
    out = []
    for _ in range(3):  # long slanted quads across every row: the rows are swept
        xa, xb = rnd.uniform(-2, w + 2, 2).round(2).tolist()
        r = [(xa, -1.0), (xa + 1.25, -1.0), (xb + 1.25, h + 1.0), (xb, h + 1.0)]
        out.append(r if rnd.integers(0, 2) else r[::-1])
    for _ in range(rings):
        out.append(_zigzag(rnd, h, w, steps, q))
    return out


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 4), st.sampled_from([0.5, 0.25, 0.125]),
       st.integers(1, 3), st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_vertex_chains_equal_oracle(seed, h, q, rings, rule, dtype):
    rnd = np.random.default_rng(seed)
    w = 8
    steps = min(int(h / q) - 1, 6)
    rl = _scene(rnd, h, w, rings, steps, q)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype, method="area")
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m, repr((seed, h, q, rings, rule)))


def test_vertex_chains_one_ring_many_rows():
    """A fixed long zigzag (seed 0): one ring, 12 vertices a side."""
    rnd = np.random.default_rng(0)
    rl = [_zigzag(rnd, 6, 10, 10, 0.5), _zigzag(rnd, 6, 10, 10, 0.5)]
    for rule in ("nonzero", "evenodd"):
        out = rastrum.polygon_coverage(rl, (6, 10), rule=rule, dtype=np.uint8, method="area")
        n, m = _n_m(rl, 8)
        check_area(out, exact_area(rl, (6, 10), rule, 8), 255, n, m, rule)

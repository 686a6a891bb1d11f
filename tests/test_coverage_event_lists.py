""""area" on rows of many vertex events (issue 34): a swept row whose edges
start or end inside it 24 times or more finds each event's edges by
walking two lists of them, by start and by end (coverage_area.c,
rast__cov_ev_lists), not by scanning them all; an edge starting at an event
goes into the order without its neighbours' exact abscissae where the
neighbour's piece start and its line's bottom both lie on one side of it
(rast__cov_apart); and the sweep's first pass steps an edge's abscissa at
the row's top a row down for its line's bottom.  A closed random walk that
crosses itself everywhere (a stroke's outline, short edges, many vertices
in every row, on a grid of q px: vertices on one ordinate, on other edges,
repeated), alone or over triangles, against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _walk(rnd, h, w, n, q):
    """n vertices of a closed walk inside (h, w), steps of up to 2 px, on
    the grid of q px."""
    pts, x, y = [], rnd.uniform(0, w), rnd.uniform(0, h)
    for _ in range(n):
        x = min(max(x + rnd.uniform(-2, 2), 0.0), float(w))
        y = min(max(y + rnd.uniform(-1, 1), 0.0), float(h))
        pts.append((float(np.round(x / q) * q), float(np.round(y / q) * q)))
    return pts


def _scene(rnd, h, w, n, q, tris):
    rings = [_walk(rnd, h, w, n, q)]
    for _ in range(tris):
        r = _walk(rnd, h, w, 3, q)
        rings.append(r if rnd.integers(0, 2) else r[::-1])
    return rings


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 2), st.sampled_from([0.5, 0.25, 1 / 16]),
       st.sampled_from([0, 6]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_many_events_a_row_equal_oracle(seed, h, q, tris, rule, dtype):
    rnd = np.random.default_rng(seed)
    w = 4  # (narrow: the walk crosses itself in every row, 24 events and more)
    rl = _scene(rnd, h, w, 50 * h + 20, q, tris)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m, repr((seed, h, q, tris)))


def test_a_dense_walk_equals_oracle():
    """Fixed seeds, so that the cases run on every profile: two rows of 140
    vertices, whose sweeps list 32 to 75 events each (and list them again
    after a vertex where neighbours meet)."""
    for seed, q, rule in ((0, 1 / 16, "nonzero"), (1, 0.5, "evenodd")):
        rnd = np.random.default_rng(seed)
        rl = _scene(rnd, 2, 4, 140, q, 0)
        out = rastrum.polygon_coverage(rl, (2, 4), rule=rule, dtype=np.uint8)
        n, m = _n_m(rl, 8)
        check_area(out, exact_area(rl, (2, 4), rule, 8), 255, n, m, repr((seed, q, rule)))

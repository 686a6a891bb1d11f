""""area" at a ring's vertices inside swept rows (issue 34): where one edge
ends and the next edge of its ring, of its direction, starts from its bottom
vertex, the new edge takes the old one's place in the sweep's order
without the exact side tests against the neighbours whose lines are not
parallel to the old edge's (coverage_area.c, rast__cov_apart_at_vertex:
with no crossing at or before the vertex the vertex is strictly on its
side); parallel neighbours (the same line, or apart) take the tests.  And
in rows of many events the ending edges are found from their slots' hints
(rast__cov_find), not by a scan.  Rings whose two sides are chains going
down and up (every vertex a continuation), crossing each other, beside
"rails" laid along a chain's edges (a thin quad on the edge's own line
and one a grid step beside it), vertices on a grid of q px (crossings on
the vertices' ordinates, at the vertices themselves), against the exact
oracle of tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _grid(v, q):
    return float(np.round(v / q) * q)


def _chains(rnd, h, w, n, q):
    """A ring: a chain of n vertices going down (ordinates increasing, some
    repeated: a level edge between two), then one going up; abscissae at
    random."""
    down = np.sort(rnd.uniform(-0.5, h + 0.5, n))
    up = np.sort(rnd.uniform(-0.5, h + 0.5, n))[::-1]
    left = [(_grid(rnd.uniform(0, w), q), _grid(y, q)) for y in down]
    right = [(_grid(rnd.uniform(0, w), q), _grid(y, q)) for y in up]
    return left + right


def _rails(ring, rnd, k, q):
    """k thin quads, each along one of the ring's edges: one long side on
    the edge's line (beyond both its ends), the other q px to its right."""
    out = []
    for _ in range(k):
        i = int(rnd.integers(0, len(ring)))
        (x0, y0), (x1, y1) = ring[i], ring[(i + 1) % len(ring)]
        if y0 == y1:
            continue
        ax, ay = x0 - (x1 - x0), y0 - (y1 - y0)
        bx, by = x1 + (x1 - x0), y1 + (y1 - y0)
        r = [(ax, ay), (bx, by), (bx + q, by), (ax + q, ay)]
        out.append(r if rnd.integers(0, 2) else r[::-1])
    return out


def _scene(rnd, h, w, n, q, rings, rails):
    rl = [_chains(rnd, h, w, n, q) for _ in range(rings)]
    for r in list(rl):
        rl += _rails(r, rnd, rails, q)
    return rl


def _check(rl, shape, rule, dtype, what):
    out = rastrum.polygon_coverage(rl, shape, rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, shape, rule, 8), M_OF[dtype], n, m, what)


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 3), st.sampled_from([0.5, 0.25, 1 / 16]),
       st.sampled_from([6, 30]), st.sampled_from([0, 3]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_chains_and_rails_equal_oracle(seed, h, q, n, rails, rule, dtype):
    rnd = np.random.default_rng(seed)
    w = 6
    rl = _scene(rnd, h, w, n * h, q, 2, rails)
    _check(rl, (h, w), rule, dtype, repr((seed, h, q, n, rails)))


def test_chain_beside_its_own_line():
    """Fixed cases on every profile: a zigzag chain whose every other edge
    has a rail on its line (the neighbour's line is the old edge's: the
    exact tests decide) or a grid step beside it (parallel, apart), and a
    chain crossing it at its vertices' ordinates; a level edge between
    the ending edge and the starting one; and two dense chains, many
    events a row (their ending edges found by the hints)."""
    left = [(1.0 + (k % 2) * 2.0, 0.5 * k - 0.25) for k in range(9)]
    right = [(5.0 - (k % 3), 4.25 - 0.5 * k) for k in range(9)]
    ring = left + right
    rl = [ring]
    for i in range(0, 8, 2):
        (x0, y0), (x1, y1) = ring[i], ring[i + 1]
        dx, dy = x1 - x0, y1 - y0
        off = 0.0625 if i % 4 else 0.0
        rl.append([(x0 - dx + off, y0 - dy), (x1 + dx + off, y1 + dy), (x1 + dx + off + 0.5, y1 + dy),
                   (x0 - dx + off + 0.5, y0 - dy)])
    rl.append([(0.0, 0.25), (6.0, 0.75), (6.0, 2.25), (0.0, 2.75)])  # crossing on the vertices' ordinates
    for rule in ("evenodd", "nonzero"):
        _check(rl, (4, 6), rule, np.uint8, "rails " + rule)
    # one edge ends at (0, 0.5), a level edge, the next starts at (4, 0.5):
    # not a continuation (its place is past the quad's two edges, which
    # cross neither edge inside the row): the tests decide
    rl = [[(0.0, -1.0), (0.0, 0.5), (4.0, 0.5), (4.0, 2.0), (5.0, 2.0), (5.0, -1.0)],
          [(3.0, -1.0), (1.0, 2.0), (1.5, 2.0), (3.5, -1.0)]]
    for rule in ("evenodd", "nonzero"):
        _check(rl, (1, 6), rule, np.uint8, "level " + rule)
    for seed, q, rule in ((0, 1 / 16, "nonzero"), (1, 0.25, "evenodd")):
        rnd = np.random.default_rng(seed)
        rl = _scene(rnd, 2, 6, 70, q, 2, 2)
        _check(rl, (2, 6), rule, np.uint8, repr((seed, q, rule)))

""""area" at vertex events deep inside overlaps (issue 33): in a swept row,
an event where a few edges end and start is mended where it happens
(coverage_area.c, rast__cov_event_local: the ending edges leave the
order, the starting ones go in by a binary search, the heap of the
neighbours' crossings relabelled, windings recomputed only as far as they
change); more edits at one ordinate, or neighbours meeting right at it,
take the passes over the whole order (rast__cov_event).  Fans of many
edges through one vertex, vertices lying on other edges, crossings on the
vertices' ordinates and on pixel corners, against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _check(rl, shape, rule, dtype, what):
    out = rastrum.polygon_coverage(rl, shape, rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, shape, rule, 8), M_OF[dtype], n, m, what)


def _scene(rnd, h, w, count, q, fan):
    """Long slanted quads spanning the rows (so that the rows are swept,
    edges crossing inside them), and `count` small triangles with vertices
    inside the rows on the grid of q px (coincident vertices, vertices on
    other edges and crossings on their ordinates are common there); with
    `fan`, a fan of triangles sharing one vertex (many edges ending and
    starting at one point: more than one event mends locally)."""
    rings = []
    for _ in range(6):
        xa, xb = rnd.uniform(-2, w + 2, 2).round(2).tolist()
        r = [(xa, -1.0), (xa + 1.5, -1.0), (xb + 1.5, h + 1.0), (xb, h + 1.0)]
        rings.append(r if rnd.integers(0, 2) else r[::-1])

    def pt():
        return (float(np.round(rnd.uniform(0, w) / q) * q), float(np.round(rnd.uniform(0, h) / q) * q))
    for _ in range(count):
        r = [pt(), pt(), pt()]
        rings.append(r if rnd.integers(0, 2) else r[::-1])
    if fan:
        c = pt()
        for _ in range(fan):
            r = [c, pt(), pt()]
            rings.append(r if rnd.integers(0, 2) else r[::-1])
    return rings


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 4), st.sampled_from([1.0, 0.5, 0.25]),
       st.sampled_from([0, 3, 10]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_events_in_deep_overlaps_equal_oracle(seed, h, q, fan, rule, dtype):
    rnd = np.random.default_rng(seed)
    w = 8
    rl = _scene(rnd, h, w, 8, q, fan)
    _check(rl, (h, w), rule, dtype, repr((seed, h, q, fan)))


def test_events_on_crossings_and_corners():
    # bow ties whose crossing is a pixel corner and whose vertices are on
    # the ordinate of other bow ties' crossings, inside slanted bands that
    # cross them all; a fan of 10 triangles round (5, 2)
    rl = [[(x0, -1.0), (x0 + 2.0, -1.0), (x0 - 3.0, 5.0), (x0 - 5.0, 5.0)] for x0 in (4.0, 9.0, 14.0)]
    for k in range(6):
        x = 2.0 * k
        rl.append([(x, 1.0), (x + 2, 3.0), (x + 2, 1.0), (x, 3.0)])
        rl.append([(x + 1, 0.0), (x + 3, 2.0), (x + 3, 0.0), (x + 1, 2.0)][::(-1) ** k])
    for a in range(10):
        rl.append([(5.0, 2.0), (1.0 + a, 0.0 if a % 2 else 4.0), (2.0 + a, 4.0 if a % 3 else 0.5)])
    for rule in ("evenodd", "nonzero"):
        _check(rl, (4, 14), rule, np.uint8, "events " + rule)

"""The flattened vertices themselves, point for point (issue 34): each
curve's vertex i of n is its exact point B(i/n) rounded, floor(v + 1/2)
per coordinate (rastrum.h, "Paths"), and n is the documented count
n = ceil(sqrt(ceil(c m / (4T - 3)))).  The C code steps the points by
exact forward differences and finds n without a square root
(csrc/src/path/flatten.c); the oracle here is the Bernstein form in
Python integers and math.isqrt, nothing shared with it.  Where n is large
only some vertices are checked (both ends, a stride): an error of the
stepping carries on to the later vertices.
"""

import math

import numpy as np
from hypothesis import assume, example, given, strategies as st

from rastrum._native import lib
from rastrum._path import MOVE, LINE, CLOSE, _flatten_fixed

LIM = lib.RAST_COORD_MAX


def wang(q, tol):
    """rastrum.h's count: ceil(sqrt(ceil(c m / (4T - 3)))), at least 1."""
    dd = max((q[k][0] - 2 * q[k + 1][0] + q[k + 2][0]) ** 2 + (q[k][1] - 2 * q[k + 1][1] + q[k + 2][1]) ** 2
             for k in range(len(q) - 2))
    m = math.isqrt(dd) + (math.isqrt(dd) ** 2 < dd)
    need = -(-(3 if len(q) == 4 else 1) * m // (4 * tol - 3))
    return max(1, math.isqrt(need) + (math.isqrt(need) ** 2 < need))


def vertex(q, i, n):
    """B(i/n) rounded: floor((2 N + n^d) / (2 n^d)) per coordinate, N the
    Bernstein numerator sum binom(d, k) (n - i)^(d-k) i^k P_k."""
    d = len(q) - 1
    w = [math.comb(d, k) * (n - i) ** (d - k) * i ** k for k in range(d + 1)]
    den = n ** d
    return tuple((2 * sum(a * p[c] for a, p in zip(w, q)) + den) // (2 * den) for c in (0, 1))


def check(q, tol):
    rings = _flatten_fixed(np.array([MOVE, len(q) - 1], np.uint8), np.array(q, np.int32), tol)
    assert len(rings) == 1
    got = rings[0]
    n = wang(q, tol)
    assert len(got) == n + 1, (q, tol)
    idx = range(n + 1) if n <= 600 else sorted(set(range(100)) | set(range(n - 100, n + 1)) |
                                               set(range(0, n + 1, n // 97)))
    for i in idx:
        assert tuple(map(int, got[i])) == vertex(q, i, n), (q, tol, i, n)
    return n


coord = st.one_of(st.integers(-3000, 3000), st.integers(-LIM, LIM),
                  st.sampled_from([LIM, -LIM, LIM - 1, -LIM + 1, 0]))
tol = st.one_of(st.integers(1, 8), st.integers(1, LIM))


@given(st.lists(st.tuples(coord, coord), min_size=3, max_size=4), tol)
@example([(-LIM, -LIM), (LIM, LIM), (-LIM, -LIM), (LIM, LIM)], 1)  # n = 47,726, the largest
@example([(-LIM, -LIM), (LIM, LIM), (-LIM, -LIM)], 1)  # a quadratic's largest n
@example([(LIM, -LIM), (-LIM, LIM), (LIM, -LIM), (-LIM, LIM)], 2)
@example([(0, 0), (1, 1), (2, 2)], 1)  # straight: one edge
def test_vertices_are_the_rounded_curve(q, t):
    check(q, t)


@given(st.integers(1, 200), st.sampled_from([1, 2, 3, 5, 1000]), st.sampled_from([2, 3]),
       st.integers(-1, 1), st.integers(0, 1))
def test_count_at_its_thresholds(n, t, d, off, dy):
    """Curves whose second difference (dx, dy) puts m at the largest value
    n edges take (c m <= n^2 (4T - 3)), one past it, one below: the count
    must be the formula's on both sides of each threshold."""
    c, qq = (3 if d == 3 else 1), 4 * t - 3
    m = max(1, n * n * qq // c + off)  # m = ceil(sqrt(dx^2 + dy^2))
    dx = m - dy  # dy = 1: dx^2 + 1 is not a square, its ceiling root is dx + 1 = m
    assume(1 <= dx and (3 if d == 3 else 1) * dx <= LIM)
    # P0 - 2 P1 + P2 = (dx, dy) (a cubic's second difference repeated)
    q = [(0, 0), (0, 0), (dx, dy)] if d == 2 else [(0, 0), (0, 0), (dx, dy), (3 * dx, 3 * dy)]
    assert check(q, t) == wang(q, t)


def test_paragraph_shapes():
    """Lines, closes and curves of both degrees in one path: every curve's
    vertices as above, in order, in the right rings."""
    q1 = [(0, 0), (4000, 9000), (9000, 1000)]
    q2 = [(9000, 1000), (-3000, 5000), (7000, 8000), (100, 200)]
    verbs = np.array([MOVE, 2, 3, LINE, CLOSE, MOVE, LINE, 2, CLOSE], np.uint8)
    pts = np.array(q1 + q2[1:] + [(5, 5), (77, 77), (300, 900), (2000, -51), (10, 700)], np.int32)
    rings = _flatten_fixed(verbs, pts, 3)
    n1, n2, n3 = wang(q1, 3), wang(q2, 3), wang([(300, 900), (2000, -51), (10, 700)], 3)
    want0 = [q1[0]] + [vertex(q1, i, n1) for i in range(1, n1 + 1)] + \
        [vertex(q2, i, n2) for i in range(1, n2 + 1)] + [(5, 5)]
    q3 = [(300, 900), (2000, -51), (10, 700)]
    want1 = [(77, 77), (300, 900)] + [vertex(q3, i, n3) for i in range(1, n3 + 1)]
    assert [tuple(map(int, v)) for v in rings[0]] == want0
    assert [tuple(map(int, v)) for v in rings[1]] == want1

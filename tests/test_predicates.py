"""Point-in-triangle predicates against exact references: every method
against oracle_lines (points on edges and vertices, degenerate triangles,
coordinates at the range limit), and OWNER against the fill oracle
(tests/oracle.py): a sample is in the oracle's mask iff the predicate says
so of the sample point."""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_lines as ref
import rastrum
from oracle import oracle_mask, snap
from strategies import COORD_MAX, examples, rings

METHODS = ("sameside", "cross", "area", "barycentric", "owner")


def on_edge_points(a, b):
    """Lattice points of the closed segment ab: a, b and those between."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    d = math.gcd(dx, dy)
    if d == 0:
        return [a]
    step = (dx // d, dy // d)
    ks = sorted(k for k in {0, d, d // 2, 1, d - 1} if 0 <= k <= d)
    return [(a[0] + k * step[0], a[1] + k * step[1]) for k in ks]


@st.composite
def triangle_and_point(draw, lim):
    """An integer triangle (maybe degenerate) and a point on it, near it or
    anywhere, coordinates within +-lim."""
    c = st.integers(-lim, lim)
    kind = draw(st.sampled_from(["random", "random", "collinear", "repeated", "flat"]))
    a = (draw(c), draw(c))
    b = (draw(c), draw(c))
    if kind == "collinear":
        k = draw(st.integers(-3, 3))
        cc = (a[0] + k * (b[0] - a[0]), a[1] + k * (b[1] - a[1]))
        if not all(-lim <= v <= lim for v in cc):
            cc = b
    elif kind == "repeated":
        cc = draw(st.sampled_from([a, b]))
    elif kind == "flat":  # a horizontal or vertical edge: top, bottom, left, right
        cc = (draw(c), a[1]) if draw(st.booleans()) else (a[0], draw(c))
    else:
        cc = (draw(c), draw(c))
    t = [a, b, cc]
    where = draw(st.sampled_from(["vertex", "edge", "edge", "near", "anywhere"]))
    if where == "vertex":
        p = draw(st.sampled_from(t))
    elif where == "edge":
        k = draw(st.integers(0, 2))
        p = draw(st.sampled_from(on_edge_points(t[k], t[(k + 1) % 3])))
    elif where == "near":
        q = draw(st.sampled_from(t))
        d = st.integers(-2, 2)
        p = (max(-lim, min(lim, q[0] + draw(d))), max(-lim, min(lim, q[1] + draw(d))))
    else:
        p = (draw(c), draw(c))
    return p, t


def check_all(p, t):
    for method in METHODS:
        want = ref.point_in_triangle(p, t, method)
        got = rastrum.point_in_triangle(p, t, method=method, subpixel_bits=0)
        assert got is want, (method, p, t)
        # the other winding order, and a rotation of the vertices
        assert rastrum.point_in_triangle(p, t[::-1], method=method, subpixel_bits=0) is want
        assert rastrum.point_in_triangle(p, t[1:] + t[:1], method=method, subpixel_bits=0) is want


@settings(max_examples=examples(300))
@given(triangle_and_point(12))
def test_small_triangles(tp):
    check_all(*tp)


@settings(max_examples=examples(300))
@given(triangle_and_point(COORD_MAX))
def test_at_the_range_limit(tp):
    check_all(*tp)


def test_extreme_triangle():
    M = COORD_MAX
    t = [(-M, -M), (M, -M), (-M, M)]
    for p in [(-M, -M), (M, -M), (-M, M), (0, 0), (0, -1), (1, 0), (-M, 0), (0, -M), (M, M), (M - 1, -M + 1)]:
        check_all(p, t)


def test_degenerate_triangles_contain_nothing():
    # Literal seed formulas would accept: same side, every point; cross and
    # area, the line through the vertices; all three equal, the plane.
    for t in ([(0, 0), (2, 2), (4, 4)], [(0, 0), (0, 0), (4, 4)], [(1, 1)] * 3, [(0, 3), (5, 3), (2, 3)]):
        for p in [(0, 0), (1, 1), (3, 3), (7, 7), (1, 2), (1, 3), (9, -4)]:
            for method in METHODS:
                assert rastrum.point_in_triangle(p, t, method=method, subpixel_bits=0) is False


def test_boundary_semantics_table():
    """The README's table: t = (0,0), (4,0), (0,4), y down."""
    t = [(0, 0), (4, 0), (0, 4)]
    table = {  # point: (closed tests, owner)
        (1, 1): (True, True),    # inside
        (0, 2): (True, True),    # left edge
        (2, 0): (True, True),    # top edge (horizontal)
        (2, 2): (True, False),   # right edge (the hypotenuse)
        (0, 0): (True, True),    # top-left vertex
        (4, 0): (True, False),   # top-right vertex
        (0, 4): (True, False),   # bottom vertex
        (3, 3): (False, False),  # outside
    }
    for p, (closed, owner) in table.items():
        for method in METHODS:
            want = owner if method == "owner" else closed
            assert rastrum.point_in_triangle(p, t, method=method, subpixel_bits=0) is want, (p, method)


@pytest.mark.parametrize("o", (0, 0.5))
@settings(max_examples=examples(100))
@given(data=st.data())
def test_owner_is_the_fill_rule(o, data):
    """OWNER at each sample point equals the exact fill oracle's mask of the
    triangle (tests/oracle.py), with the triangles' awkward vertices from
    strategies.rings (slivers, repeats, collinear, horizontal, far away)."""
    S = data.draw(st.integers(1 if o else 0, 8))
    h, w = data.draw(st.integers(1, 10)), data.draw(st.integers(1, 10))
    tri = data.draw(rings(S, o, (h, w), min_size=3, max_size=3))
    mask = oracle_mask([tri], (h, w), subpixel_bits=S, sample_offset=o)
    for j in range(h):
        for i in range(w):
            got = rastrum.point_in_triangle((i + o, j + o), tri, method="owner", subpixel_bits=S)
            assert got == mask[j, i], (tri, S, o, i, j)


@settings(max_examples=examples(100))
@given(data=st.data())
def test_fractional_coordinates_are_snapped_as_fills_snap(data):
    S = data.draw(st.integers(0, 8))
    f = st.floats(-20, 20)
    t = [(data.draw(f), data.draw(f)) for _ in range(3)]
    p = (data.draw(f), data.draw(f))
    ts = [(snap(x, S), snap(y, S)) for x, y in t]
    ps = (snap(p[0], S), snap(p[1], S))
    for method in METHODS:
        assert rastrum.point_in_triangle(p, t, method=method, subpixel_bits=S) is ref.point_in_triangle(ps, ts, method)


@pytest.mark.parametrize(
    "kwargs",
    [
        dict(p=(0, 0), tri=[(0, 0), (1, 0)]),
        dict(p=(0, 0), tri=[(0, 0), (1, 0), (0, 1)], method="winding"),
        dict(p=(0, np.nan), tri=[(0, 0), (1, 0), (0, 1)]),
        dict(p=(0, 0), tri=[(0, 0), (1e9, 0), (0, 1)]),
        dict(p=(0, 0, 0), tri=[(0, 0), (1, 0), (0, 1)]),
        dict(p=(0, 0), tri=[(0, 0), (1, 0), (0, 1)], subpixel_bits=-1),
    ],
)
def test_bad_input(kwargs):
    with pytest.raises(rastrum.InputError):
        rastrum.point_in_triangle(**kwargs)


def test_reference_self_check():
    """The reference's closed test against a third formulation: p is in the
    closed, non-degenerate triangle iff no edge has p strictly outside."""
    rng = np.random.default_rng(7)
    for _ in range(2000):
        t = [tuple(int(v) for v in rng.integers(-4, 5, 2)) for _ in range(3)]
        p = tuple(int(v) for v in rng.integers(-5, 6, 2))
        area = ref._cross(t[0], t[1], t[2])
        if area == 0:
            assert not ref.in_closed_triangle(p, t)
            continue
        s = 1 if area > 0 else -1
        inside = all(s * ref._cross(t[k], t[(k + 1) % 3], p) >= 0 for k in range(3))
        assert ref.in_closed_triangle(p, t) == inside

"""Paths: the flattening bound checked in exact rational arithmetic, the
SVG path grammar, arcs, and Paths accepted by the fills.

The bound (rastrum.h, "Paths"; proven in csrc/src/path/flatten.c): the
Hausdorff distance between a Bezier curve (its control points on the
grid) and its flattened polyline is at most the tolerance, the rounding
of the vertices included.  Checked here without trusting the C code's
parametrisation: every sampled exact curve point B(t) (fractions.Fraction)
must be within the tolerance of the polyline, and every sampled polyline
point within the tolerance of some exact curve point.
"""

from fractions import Fraction as F
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings, strategies as st

import rastrum
from rastrum._native import lib
from rastrum._path import Path, _flatten_fixed, MOVE, CUBIC, CLOSE, LINE

LIM = lib.RAST_COORD_MAX


def bez(q, t):
    """The exact point of the Bezier curve with control points q at t."""
    s = 1 - t
    if len(q) == 3:
        w = (s * s, 2 * s * t, t * t)
    else:
        w = (s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t)
    return (sum(a * p[0] for a, p in zip(w, q)), sum(a * p[1] for a, p in zip(w, q)))


def d2_seg(p, a, b):
    """Squared distance from p to segment ab, exactly."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    l2 = dx * dx + dy * dy
    t = F(0)
    if l2:
        t = min(F(1), max(F(0), F((p[0] - a[0]) * dx + (p[1] - a[1]) * dy, 1) / l2))
    ex, ey = a[0] + t * dx - p[0], a[1] + t * dy - p[1]
    return ex * ex + ey * ey


def flatten_one(q, tol):
    verbs = np.array([MOVE, len(q) - 1], np.uint8)
    rings = _flatten_fixed(verbs, np.array(q, np.int32), tol)
    assert len(rings) == 1
    return [tuple(map(int, v)) for v in rings[0]]


def check_bound(q, tol, samples=64):
    """Both directions of the Hausdorff bound, exactly, on samples: every
    edge when there are at most 512, else the first and last 64 edges
    (where a curve's second derivative is often largest) and every
    (n // samples)-th one."""
    w = flatten_one(q, tol)
    n = len(w) - 1
    assert n >= 1 and w[0] == tuple(q[0]) and w[-1] == tuple(q[-1])
    t2 = tol * tol
    edges = range(n) if n <= 512 else sorted(set(range(64)) | set(range(n - 64, n)) |
                                              set(range(0, n, max(1, n // samples))))
    # curve -> polyline: B(t) near the polyline (its own edge first; all
    # edges before declaring a failure)
    ts = sorted({F(j, samples) for j in range(samples + 1)} |
                {F(4 * i + k, 4 * n) for i in edges for k in (1, 2, 3)})
    for t in ts:
        p = bez(q, t)
        i = min(int(t * n), n - 1)
        if d2_seg(p, w[i], w[i + 1]) > t2:
            assert min(d2_seg(p, w[k], w[k + 1]) for k in range(n)) <= t2, (q, tol, t)
    # polyline -> curve: points of the edges near the curve point at the
    # same parameter, else near some finely sampled curve point
    fine = None
    for i in edges:
        for s in (F(0), F(1, 4), F(1, 2), F(3, 4)):
            m = (w[i][0] + s * (w[i + 1][0] - w[i][0]), w[i][1] + s * (w[i + 1][1] - w[i][1]))
            b = bez(q, (i + s) / n)
            if (b[0] - m[0]) ** 2 + (b[1] - m[1]) ** 2 > t2:
                if fine is None:
                    fine = [bez(q, F(j, 4096)) for j in range(4097)]
                assert min((c[0] - m[0]) ** 2 + (c[1] - m[1]) ** 2 for c in fine) <= t2, (q, tol, i, s)
    return n


coord_small = st.integers(-4096, 4096)
coord_any = st.one_of(st.integers(-LIM, LIM), st.sampled_from([LIM, -LIM, LIM - 1, -LIM + 1, 0]))
# tolerances from 1 px down to 1/256 px at subpixel_bits = 8
tol_s8 = st.sampled_from([256, 128, 64, 32, 16, 8, 4, 2, 1]) | st.integers(1, 256)


@st.composite
def curves(draw, coord=coord_small):
    d = draw(st.sampled_from([2, 3]))
    q = [(draw(coord), draw(coord)) for _ in range(d + 1)]
    kind = draw(st.sampled_from(["plain", "coincident", "loop", "cusp", "collinear", "closed", "point"]))
    if kind == "coincident":
        i, j = draw(st.integers(0, d)), draw(st.integers(0, d))
        q[i] = q[j]
    elif kind == "loop" and d == 3:  # controls crossed far out: a loop
        (x0, y0), (x3, y3) = q[0], q[3]
        q[1], q[2] = (x3 + (x3 - x0), y3 + (y0 - y3)), (x0 - (x3 - x0), y0 + (y0 - y3))
    elif kind == "cusp" and d == 3:  # P0 P1 P2 P3 with P1 - P0 = P3 - P2 reversed: a cusp
        (x0, y0), (x1, y1) = q[0], q[1]
        q[2], q[3] = (x0, y1), (x1, y0)
    elif kind == "collinear":
        a, b = q[0], q[-1]
        ks = [draw(st.integers(-3, 4)) for _ in range(d - 1)]
        for i, k in enumerate(ks):
            q[i + 1] = (a[0] + k * (b[0] - a[0]), a[1] + k * (b[1] - a[1]))
    elif kind == "closed":
        q[-1] = q[0]
    elif kind == "point":
        q = [q[0]] * (d + 1)
    q = [(max(-LIM, min(LIM, x)), max(-LIM, min(LIM, y))) for x, y in q]
    return q


@settings(deadline=None, max_examples=150, suppress_health_check=[HealthCheck.too_slow])
@given(curves(), tol_s8)
@example([(0, 0), (0, 3074), (0, 3074), (0, 0)], 256)  # found with a cubic's c = 2 instead of 3
def test_bound_exact(q, tol):
    check_bound(q, tol)


@settings(deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow])
@given(curves(coord_any), st.sampled_from([1, 2, 3, 256, 4096]) | st.integers(1, LIM))
def test_bound_exact_range_limits(q, tol):
    check_bound(q, tol, samples=24)


def test_bound_extremes():
    """The largest curves at tolerance 1 (128-bit evaluation, n near its
    maximum of 47,726) and at tolerance RAST_COORD_MAX (one edge)."""
    for q in ([(-LIM, -LIM), (LIM, LIM), (-LIM, -LIM), (LIM, LIM)],
              [(-LIM, LIM), (LIM, -LIM), (-LIM, LIM), (LIM, -LIM)],
              [(-LIM, -LIM), (LIM, LIM), (-LIM, -LIM)]):
        n = check_bound(q, 1, samples=16)
        assert 1024 < n <= 47726
        check_bound(q, LIM, samples=16)


def wang(q, tol):
    """rastrum.h's count, from the formula: ceil(sqrt(ceil(c m / (4T - 3))))."""
    dd = max((q[k][0] - 2 * q[k + 1][0] + q[k + 2][0]) ** 2 + (q[k][1] - 2 * q[k + 1][1] + q[k + 2][1]) ** 2
             for k in range(len(q) - 2))
    m = math.isqrt(dd) + (math.isqrt(dd) ** 2 < dd)
    need = -(-(3 if len(q) == 4 else 1) * m // (4 * tol - 3))
    n = math.isqrt(need) + (math.isqrt(need) ** 2 < need)
    return max(n, 1)


@settings(deadline=None, max_examples=300)
@given(curves(coord_any), st.integers(1, LIM))
def test_count_is_the_formula(q, tol):
    assert len(flatten_one(q, tol)) - 1 == wang(q, tol)


def test_count_follows_flatness():
    """Quartering the tolerance doubles the count (away from the rounding
    budget: (4T - 3) for T = 1 is 1); a straight curve is one edge; the
    count does not depend on translation."""
    q = [(0, 0), (300000, 900000), (900000, -400000), (1200000, 0)]
    ns = [len(flatten_one(q, t)) - 1 for t in (1024, 256, 64, 16)]
    for a, b in zip(ns, ns[1:]):
        assert 1.9 < b / a < 2.1
    assert len(flatten_one([(0, 0), (10, 10), (20, 20), (30, 30)], 1)) == 2
    assert len(flatten_one([(0, 0), (5, 7), (10, 14)], 1)) == 2
    moved = [(x + 123457, y - 98765) for x, y in q]
    assert len(flatten_one(moved, 3)) == len(flatten_one(q, 3))


def test_bad_paths():
    with pytest.raises(rastrum.InputError):
        _flatten_fixed(np.array([LINE], np.uint8), np.array([[0, 0]], np.int32), 4)
    with pytest.raises(rastrum.InputError):
        _flatten_fixed(np.array([MOVE, 9], np.uint8), np.array([[0, 0]], np.int32), 4)
    with pytest.raises(rastrum.InputError):
        _flatten_fixed(np.array([MOVE, CUBIC], np.uint8), np.array([[0, 0]] * 3, np.int32), 4)
    with pytest.raises(rastrum.InputError):
        _flatten_fixed(np.array([MOVE], np.uint8), np.array([[LIM + 1, 0]], np.int32), 4)
    with pytest.raises(rastrum.InputError):
        _flatten_fixed(np.array([MOVE], np.uint8), np.array([[0, 0]], np.int32), 0)
    with pytest.raises(rastrum.InputError, match="tolerance"):
        Path(tolerance=0)
    with pytest.raises(rastrum.InputError, match="tolerance"):
        Path(tolerance=float("nan"))
    with pytest.raises(rastrum.InputError, match="move_to"):
        Path().line_to(1, 2)
    with pytest.raises(rastrum.InputError, match="x"):
        Path().move_to("a", 2)
    with pytest.raises(rastrum.InputError, match="below one grid step"):
        Path(tolerance=1 / 1024).move_to(0, 0).quad_to(1, 1, 2, 0).flatten(8)
    with pytest.raises(rastrum.InputError, match="range"):
        Path().move_to(1e9, 0).line_to(0, 0).line_to(0, 1).flatten(8)


# ---- the Python Path -----------------------------------------------------------------------

def test_path_flatten_matches_fixed_call():
    p = Path(tolerance=1 / 16).move_to(1.5, 2).cubic_to(10, -3, 20, 25, 30.25, 2).line_to(30, 30).close()
    rings = p.flatten(8)
    q = [(384, 512), (2560, -768), (5120, 6400), (7744, 512)]
    w = flatten_one(q, 16)
    assert np.array_equal(rings[0][:len(w)] * 256, np.array(w, float))
    assert rings[0][-1].tolist() == [30.0, 30.0]


def test_fills_take_a_path():
    p = Path(tolerance=1 / 32).move_to(2, 2).cubic_to(20, -5, 30, 30, 4, 28).close()
    rings = p.flatten(8)
    assert np.array_equal(rastrum.polygon_mask(p, (32, 32)), rastrum.polygon_mask(rings, (32, 32)))
    for method in ("area", "ss4"):
        a = rastrum.polygon_coverage(p, (32, 32), method=method, rule="nonzero")
        b = rastrum.polygon_coverage(rings, (32, 32), method=method, rule="nonzero")
        assert np.array_equal(a, b)
    # subpixel_bits above 16: flattened at 16 bits, taken exactly by the 64-bit path
    assert rastrum.polygon_mask(p, (32, 32), subpixel_bits=24).sum() == \
        rastrum.polygon_mask(p.flatten(24), (32, 32), subpixel_bits=24).sum()


def test_circle_area_within_tolerance_band():
    """A circle of four arcs: its flattened area between the areas of the
    circles of radius r - tol - arc error and r + arc error."""
    r = 40.0
    for tol in (1 / 4, 1 / 16, 1 / 64, 1 / 256):
        p = Path.from_svg("M 90 50 A 40 40 0 0 1 50 90 A 40 40 0 0 1 10 50 A 40 40 0 0 1 50 10 "
                          "A 40 40 0 0 1 90 50 Z", tolerance=tol)
        a = rastrum.polygon_coverage(p, (100, 100), dtype=np.float64).sum()
        err = rastrum._path.ARC_ERROR + 2 ** -9  # the snapped control points
        assert math.pi * (r - tol - err) ** 2 <= a <= math.pi * (r + err) ** 2


def test_svg_grammar():
    ref = Path().move_to(10, 20).line_to(30, 20).line_to(30, 40).line_to(10, 40).close()
    for d in ("M10 20 L30 20 L30 40 L10 40 Z", "m10,20 h20 v20 h-20 z", "M10 20 30 20 30 40 10 40z",
              "m10 20 20 0 0 20-20 0Z", "M10,20H30V40H10Z", "  M 1e1 2E1 l 2e1 0 0 20 -20 0 z  "):
        p = Path.from_svg(d)
        assert p.verbs.tolist() == ref.verbs.tolist(), d
        assert p.points.tolist() == ref.points.tolist(), d
    # S and T reflect the previous control point, only after C/S and Q/T
    p = Path.from_svg("M0 0 C 1 2 3 4 5 6 S 9 10 11 12 T 20 20 Q 1 1 2 2 T 4 4 s 1 1 2 2")
    pts = p.points.tolist()
    assert pts[4] == [7.0, 8.0]             # S: 2*(5,6) - (3,4)
    assert pts[7] == [11.0, 12.0]           # T after S: no reflection, control = current
    assert pts[11] == [3.0, 3.0]            # T after Q: 2*(2,2) - (1,1)
    assert pts[13] == [4.0, 4.0]            # s after T: first control = current point
    # relative commands after Z start from the subpath's start
    p = Path.from_svg("M 5 5 l 1 0 l 0 1 z l 2 2")
    assert p.verbs.tolist() == [MOVE, LINE, LINE, CLOSE, MOVE, LINE]
    assert p.points.tolist()[-2:] == [[5.0, 5.0], [7.0, 7.0]]
    # arc flags without separators
    a = Path.from_svg("M0 0a5 5 0 1010 0")
    b = Path.from_svg("M0 0 a 5 5 0 1 0 10 0")
    assert a.points.tolist() == b.points.tolist()
    assert a.points.tolist()[-1] == [10.0, 0.0]
    for bad in ("L 1 2", "M 1", "M 1 2 X 3", "M 0 0 A 1 1 0 2 0 3 3", "M 0 0 L 1 2 3", "1 2"):
        with pytest.raises(rastrum.InputError, match="d:|move_to"):
            Path.from_svg(bad)


@settings(deadline=None, max_examples=60)
@given(st.floats(0.5, 60), st.floats(0.5, 60), st.floats(-360, 360), st.booleans(), st.booleans(),
       st.floats(-50, 50), st.floats(-50, 50))
def test_arc_on_the_ellipse(rx, ry, rot, large, sweep, x, y):
    assume(abs(x) + abs(y) > 1e-3)
    p = Path().move_to(0, 0).arc_to(rx, ry, rot, large, sweep, x, y)
    pts = p.points
    assert pts[-1].tolist() == [x, y]
    # every cubic end point is on one ellipse of the arc's axes and
    # rotation (radii scaled up when too small, SVG F.6.6)
    ends = pts[0::3] if len(pts) > 1 else pts
    phi = math.radians(rot)
    c, s = math.cos(phi), math.sin(phi)
    # the centre: from the first three ends (solve generally by fitting)
    u = np.array([[c * px + s * py, -s * px + c * py] for px, py in ends])
    # all ends satisfy ((u - cu)/RX)^2 + ((v - cv)/RY)^2 = 1 with RX/RY = rx/ry
    k = rx / ry
    A = np.column_stack([u[:, 0] * 2, u[:, 1] * 2 * k * k, np.ones(len(u))])
    b = u[:, 0] ** 2 + (k * u[:, 1]) ** 2
    if len(u) >= 3:
        sol, *_ = np.linalg.lstsq(A, b, rcond=None)
        assert np.allclose(A @ sol, b, atol=1e-6 * max(1.0, float(np.abs(b).max())))


def test_path_as_polygon_mask_docstring_example():
    p = rastrum.Path().move_to(1, 1).quad_to(4, 7, 7, 1).close()
    assert rastrum.polygon_mask(p, (4, 8)).sum() == 12


def test_arc_flags_checked():
    """arc_to's large_arc and sweep: True/False or 0/1 (numpy's too); anything
    else an InputError naming the flag, the path unchanged."""
    p = Path().move_to(0, 0).line_to(4, 0).close()
    for bad in (2, -1, 0.5, "1", None, np.zeros((4, 5), np.int32)):
        for k in (3, 4):
            args = [5, 5, 0, 1, 0, 10, 0]
            args[k] = bad
            with pytest.raises(rastrum.InputError, match="large_arc|sweep"):
                p.arc_to(*args)
            assert len(p) == 3 and p.points.shape == (2, 2)
    for good in (True, 1, np.bool_(True), np.int64(1)):
        q = Path().move_to(0, 0).arc_to(5, 5, 0, good, good, 10, 0)
        assert np.array_equal(q.points, Path().move_to(0, 0).arc_to(5, 5, 0, True, True, 10, 0).points)

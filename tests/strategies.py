"""Hypothesis strategies for nasty polygon scenes.

Coordinates are bounded by the C library's documented range
(``lib.RAST_COORD_MAX``, in 1/2**S pixel after snapping).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from hypothesis import settings, strategies as st

from rastrum._native import lib

COORD_MAX = int(lib.RAST_COORD_MAX)

RULES = ("evenodd", "nonzero")


def examples(base: int) -> int:
    """Scale an example count by the active profile (default = 100)."""
    return max(1, round(base * settings.default.max_examples / 100))


def limit_px(S: int) -> float:
    """Largest |v| in pixels whose snapped value is in range, as a float.

    COORD_MAX / 2**S is exact in binary floating point.
    """
    return COORD_MAX / (1 << S)


def is_in_range(v: float, S: int) -> bool:
    """Exact check of the documented range: |floor(v*2^S + 1/2)| <= max."""
    q = Fraction(v) * (1 << S) + Fraction(1, 2)
    f = q.numerator // q.denominator
    return -COORD_MAX <= f <= COORD_MAX


# --- coordinates -----------------------------------------------------------

def coordinates(S: int, o: float, dim: int):
    """One coordinate (pixels) along an axis of a target of size ``dim``."""
    g = 1 << S
    lim = limit_px(S)
    near = st.floats(-6.0, dim + 6.0, allow_nan=False, allow_infinity=False)
    on_sample = st.integers(-3, dim + 3).map(lambda k: k + o)
    on_grid = st.integers(-3 * g, (dim + 3) * g).map(lambda k: k / g)
    # exact snapping ties (k + 1/2) / 2^S and values a hair either side
    tie = st.integers(-3 * g, (dim + 3) * g).map(lambda k: (k + 0.5) / g)
    near_tie = st.one_of(
        st.tuples(tie, st.sampled_from([-1, 1]), st.integers(10, 40)).map(
            lambda t: t[0] + t[1] * 2.0 ** (-S - t[2])),
        # the adjacent floats: v*2^S + 1/2 rounds in float arithmetic
        st.tuples(tie, st.sampled_from([-math.inf, math.inf])).map(
            lambda t: math.nextafter(*t)))
    outside = st.one_of(st.floats(-1000.0, -6.0), st.floats(dim + 6.0, 1000.0))
    far = st.floats(-lim, lim)
    at_limit = st.sampled_from([lim, -lim,
                                (COORD_MAX + 0.25) / g,   # still snaps to max
                                -(COORD_MAX + 0.5) / g,   # tie -> -max
                                lim - 1.0 / g, -lim + 1.0 / g])
    return st.one_of(
        near, near, near, on_sample, on_sample, on_grid, tie, near_tie,
        outside, far, at_limit)


# --- rings -----------------------------------------------------------------

@st.composite
def rings(draw, S: int, o: float, shape, min_size=3, max_size=12):
    """A closed ring with awkward vertices, as a list of (x, y) floats."""
    H, W = shape
    cx = coordinates(S, o, W)
    cy = coordinates(S, o, H)
    n = draw(st.integers(min_size, max_size))
    pts = [(draw(cx), draw(cy))]
    tiny = 2.0 ** -(S + 1)
    while len(pts) < n:
        kind = draw(st.sampled_from(
            ["new", "new", "new", "new", "repeat", "horizontal", "vertical",
             "collinear", "sliver"]))
        px, py = pts[-1]
        if kind == "new":
            p = (draw(cx), draw(cy))
        elif kind == "repeat":
            p = (px, py)
        elif kind == "horizontal":
            p = (draw(cx), py)
        elif kind == "vertical":
            p = (px, draw(cy))
        elif kind == "collinear" and len(pts) >= 2:
            qx, qy = pts[-2]
            t = draw(st.sampled_from([-1.0, 0.5, 2.0, 3.0]))
            p = (px + t * (px - qx), py + t * (py - qy))
        else:  # sliver: within less than one grid step of the last vertex
            d = st.floats(-tiny, tiny)
            p = (px + draw(d), py + draw(d))
        if not (np.isfinite(p[0]) and np.isfinite(p[1])
                and is_in_range(p[0], S) and is_in_range(p[1], S)):
            p = (draw(cx), draw(cy))
        pts.append(p)
    return pts


@st.composite
def ring_with_hole(draw, S: int, o: float, shape):
    """An outer ring and a hole inside it, each in either orientation."""
    H, W = shape
    g = 1 << S
    x0 = draw(st.integers(-2 * g, W * g)) / g
    y0 = draw(st.integers(-2 * g, H * g)) / g
    w = draw(st.integers(3 * g, (W + 4) * g)) / g
    h = draw(st.integers(3 * g, (H + 4) * g)) / g
    outer = [(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)]
    if draw(st.booleans()):
        # a random polygon for the hole, shrunk into the outer box
        k = draw(st.integers(3, 8))
        fx = st.floats(0.1, 0.9)
        hole = [(x0 + draw(fx) * w, y0 + draw(fx) * h) for _ in range(k)]
    else:
        a = draw(st.floats(0.05, 0.45))
        b = draw(st.floats(0.55, 0.95))
        hole = [(x0 + a * w, y0 + a * h), (x0 + b * w, y0 + a * h),
                (x0 + b * w, y0 + b * h), (x0 + a * w, y0 + b * h)]
    if draw(st.booleans()):
        outer = outer[::-1]
    if draw(st.booleans()):
        hole = hole[::-1]
    res = [outer, hole]
    if draw(st.booleans()):
        res = res[::-1]
    return res


def shapes(max_h=40, max_w=40):
    return st.tuples(st.integers(1, max_h), st.integers(1, max_w))


@st.composite
def scenes(draw, S: int, o: float, max_h=40, max_w=40, max_rings=3):
    """(rings, shape): rings is a list of (N, 2) float64 arrays."""
    shape = draw(shapes(max_h, max_w))
    kind = draw(st.sampled_from(["random", "random", "random", "hole"]))
    if kind == "hole":
        rl = draw(ring_with_hole(S, o, shape))
        if draw(st.booleans()):
            rl.append(draw(rings(S, o, shape)))
    else:
        rl = draw(st.lists(rings(S, o, shape), min_size=1,
                           max_size=max_rings))
    return [np.asarray(r, dtype=np.float64) for r in rl], shape


@st.composite
def rings_from_few_points(draw, xs, ys, max_size=6, max_rings=4):
    """Rings drawn from a pool of 3 to 7 points, integer coordinates in the
    ranges xs and ys, some moved by 0.5 or 0.3 of a pixel (on pixel
    corners, on pixel sides, inside pixels): they share vertices and sides,
    touch tip to tip, run back along themselves and meet at vertices of
    four or six edges."""
    pool = draw(st.lists(st.tuples(st.integers(*xs), st.integers(*ys), st.sampled_from([0, 0.5, 0.3])),
                         min_size=3, max_size=7, unique=True))
    picks = draw(st.lists(st.lists(st.integers(0, 6), min_size=3, max_size=max_size), min_size=1,
                          max_size=max_rings))
    pts = [(x + f, y + f / 2) for x, y, f in pool]
    return [[pts[i % len(pts)] for i in pick] for pick in picks]


def as_input_form(rl, form):
    """Present a list of (N,2) arrays in one of the accepted input forms."""
    if form == "arrays":
        return rl
    if form == "lists":
        return [r.tolist() for r in rl]
    if form == "tuples":
        return [[tuple(p) for p in r.tolist()] for r in rl]
    if form == "single" and len(rl) == 1:
        return rl[0]
    return rl


input_forms = st.sampled_from(["arrays", "lists", "tuples", "single"])


# --- helpers for failure messages ---------------------------------------------

def lit(rl):
    """Rings as plain lists of floats: a reproducer to paste."""
    return [np.asarray(r, dtype=np.float64).tolist() for r in rl]


def assert_same(a, b, msg):
    """a equals b element for element, or an error naming the first cells."""
    if not np.array_equal(a, b):
        d = np.argwhere(a != b)
        raise AssertionError(f"{msg}\n{len(d)} cell(s) differ, first "
                             f"(row, col[, channel]): {d[:10].tolist()}")


def zigzag_ring(rnd, xlo: float, xhi: float, ys) -> np.ndarray:
    """A ring down the rows ys (sorted) and back up them, its x drawn in
    [xlo, xhi) by the numpy Generator rnd: an edge on every stretch of
    rows, crossing the others at random (the supersampling delta tests)."""
    n = len(ys)
    return np.concatenate([np.stack([rnd.uniform(xlo, xhi, n), ys], -1),
                           np.stack([rnd.uniform(xlo, xhi, n), ys[::-1]], -1)])


def tiny_triangle(rnd, cx: float, cy: float, rmax: float) -> list:
    """A triangle around (cx, cy), its corners a random turn and a radius
    in [0.2, rmax) away, either way round (drawn by rnd, in that order)."""
    t = rnd.uniform(0, 2 * np.pi) + np.array([0, 2.1, 4.2])
    r = rnd.uniform(0.2, rmax)
    tri = [[float(cx + r * np.cos(a)), float(cy + r * np.sin(a))] for a in t]
    return tri[::-1] if rnd.random() < 0.5 else tri


def assert_ss_oracle(rings, shape, k, rule, dtype):
    """polygon_coverage(method="ssK") of rings equals the binary rule on
    the K-times grid (oracle_coverage.coverage_ss), levels of dtype."""
    import oracle_coverage as oc
    import rastrum
    out = rastrum.polygon_coverage(rings, shape, rule=rule, method="ss%d" % k, dtype=dtype)
    want = oc.coverage_ss(rings, shape, k, rule=rule, M=int(np.iinfo(dtype).max))
    assert_same(out.astype(np.int64), want, "%s ss%d %s %r" % (rule, k, dtype.__name__, rings))

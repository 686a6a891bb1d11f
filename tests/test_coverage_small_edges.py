"""The one-small-convex-ring path of the Canvas (csrc/src/coverage/
coverage_small.c; its convexity test rast__cov_convex in
csrc/src/entry/coverage.c), at the edges of what it takes (issue 33):

- its tie routing: a level whose 64-bit sum is within the rounding bound
  of a tie goes to the engines.  Each ring of NEAR_TIES (a trapezoid: one
  steep edge E and a vertical side on a whole column) has a pixel whose
  exact value x = a 255 + 1/2 lies just below a level boundary, by less
  than the floors of E's abscissae to the 2^-26 px grid move it up (the
  small path's one rounding; _claims checks the scene).  Without the
  routing (no window, only exact ties declined) that pixel is one level
  high.  (A window 4 times narrower, or of one edge, is still wide
  enough: a steep piece's floors are at most 2^(K+1) of its 2^(K+4), and
  only the pixel's own edges of one direction add up: harmless.);
- rings that are not convex though every turn is one way (a pentagram:
  its dx changes sign four times) or whose dx flips only twice (a bowtie:
  its turns change sign): the accumulation of their edges is not their
  coverage, so the convexity test must send them to the engines (which
  read it too: its mutations show in polygon_coverage's levels as well);
- rings of 17 to 24 vertices (past RAST__CS_EDGES = 16: the engines') and
  boxes of 25 x 25 pixels (past RAST__CS_DIM = 24), whose small path
  would overrun its arrays on the stack: the levels stay right there, but
  the sanitizers' build (make asan-py) stops on it;
- rings partly off every side of the canvas (the box's rows and columns
  clipped as they are handed on).

Every ring is painted with Canvas.fill_polygon (aa="area", "accumulate",
"ss2", "ss4") on gray8 and rgba8888 canvases of random pixels, and each
channel must be the documented blend (test_coverage_paint.expected) of
the oracle's levels: floor(a' 255 + 1/2) of the exact area
(tests/oracle_coverage.py; for "accumulate" the rule applied to the
integral of the winding number, test_coverage._accumulated of the
ring's fan of triangles), or for "ssK" the binary rule's samples on the
k-times grid counted (test_coverage_small._samples); for the rings that
are not plain the engines' levels, held to the exact ones within the
documented bound (test_coverage.check_area), are the ones painted."""

import math
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import M_OF, _accumulated, _n_m, check_area, exact_area
from test_coverage_paint import expected
from test_coverage_small import SHAPE, _samples

T26 = 1 << 26

# (E (X0, Y0, X1, Y1) in 1/256 px from its top vertex, column C of the
# pixel (J, C) near a tie), the ring E, then right to column 8, up and
# back, moved by (ox, oy) whole pixels on the canvas
J = 4
NEAR_TIES = [
    ((885, 0, 1368, 2339), 4),
    ((973, 0, 1202, 2299), 4),
    ((959, 0, 367, 2369), 2),
    ((825, 0, 980, 2551), 3),
]


def _trapezoid(e, ox=0, oy=0):
    X0, Y0, X1, Y1 = e
    return [(X0 / 256 + ox, Y0 / 256 + oy), (X1 / 256 + ox, Y1 / 256 + oy), (8.0 + ox, Y1 / 256 + oy),
            (8.0 + ox, Y0 / 256 + oy)]


def _claims(e, c):
    """The pixel (J, c)'s exact area a right of E, and the scene as claimed:
    x = a 255 + 1/2 below a boundary by d > 0, and E's two abscissae at
    the pixel's row lines floored to 2^-26 px raise its area by e/2^27
    px (e their two floors' sum, in 2^-26 px) with 255 e/2^27 > d."""
    X0, Y0, X1, Y1 = e
    xt, xb = (F(X0, 256) + F((256 * y - Y0) * (X1 - X0), 256 * (Y1 - Y0)) for y in (J, J + 1))
    assert math.floor(xt) == math.floor(xb) == c
    a = c + 1 - (xt + xb) / 2
    x = a * 255 + F(1, 2)
    d = math.ceil(x) - x
    lift = sum(v * T26 - math.floor(v * T26) for v in (xt, xb)) * 255 / 2 ** 27
    assert 0 < d < lift, (e, float(d), float(lift))
    return a


def _paint(ring, rule, method, fmt, seed, cov):
    """ring painted with aa=method on a random canvas of fmt, against the
    documented blend of the levels cov."""
    rng = np.random.default_rng(seed)
    n = 4 if fmt == "rgba8888" else 1
    canvas = rastrum.Canvas(SHAPE, format=fmt)
    canvas.array[...] = rng.integers(0, 256, canvas.array.shape, dtype=np.uint8)
    color = tuple(int(v) for v in rng.integers(0, 256, n)) if n > 1 else int(rng.integers(0, 256))
    before = canvas.array.copy()
    canvas.fill_polygon(np.asarray(ring, np.float64), color, rule=rule, aa=method, subpixel_bits=8)
    S_.assert_same(canvas.array, expected(fmt, before, color, cov),
                   "fill_polygon(aa=%r, rule=%r) on %s: %s" % (method, rule, fmt, S_.lit([ring])))


_MEMO = {}


def _levels(ring, rule, method, plain):
    """The levels to paint: the oracle's (exact when plain; else the
    engines', held to it within the bound), or the samples counted.  (A
    plain ring's are the same under either rule, and "accumulate"'s are
    "area"'s there: computed once.)"""
    key = (tuple(ring), None if plain else rule, "area" if plain and method == "accumulate" else method)
    if key in _MEMO:
        return _MEMO[key]
    if method.startswith("ss"):
        out = _samples(ring, rule, int(method[2:]), 8 + int(method[2:]).bit_length() - 1, 0.5)
    elif plain:
        out = np.vectorize(lambda a: oc.level(a, 255), otypes=[np.int64])(exact_area([ring], SHAPE, rule, 8))
    else:
        if method == "accumulate":  # (the winding's integral: the signed fan triangles' areas summed)
            exact = _accumulated([[ring[0], p, q] for p, q in zip(ring[1:], ring[2:])], SHAPE, rule, 8)
        else:
            exact = exact_area([ring], SHAPE, rule, 8)
        out = rastrum.polygon_coverage([ring], SHAPE, rule=rule, method=method, dtype=np.uint8)
        n, m = _n_m([ring], 8)
        check_area(out, exact, M_OF[np.uint8], n, m, S_.lit([ring]))
    _MEMO[key] = out
    return out


FORMATS = ["gray8", "rgba8888"]
METHODS = ["area", "accumulate", "ss2", "ss4"]


@pytest.mark.parametrize("case", NEAR_TIES, ids=lambda k: "%s-col%d" % ("_".join(map(str, k[0])), k[1]))
def test_near_a_tie_goes_to_the_engines(case):
    e, c = case
    a = _claims(e, c)
    ring = _trapezoid(e, 3, 5)
    for rule in ("nonzero", "evenodd"):
        want = _levels(ring, rule, "area", True)
        assert want[J + 5, c + 3] == math.floor(a * 255 + F(1, 2))
        for method in ("area", "accumulate"):
            for fmt in FORMATS:
                _paint(ring, rule, method, fmt, 1, want)


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.sampled_from(NEAR_TIES), st.integers(-3, 30), st.integers(-4, 25), st.booleans(),
       st.integers(0, 2 ** 32 - 1))
def test_near_a_tie_moved(case, ox, oy, flip, seed):
    """The same rings moved by whole pixels (partly off the canvas too),
    or mirrored top to bottom about a whole row (the same areas, E's
    floors at its other ends: the pixel's level exact either way)."""
    ring = _trapezoid(case[0], ox, oy)
    if flip:
        ring = [(x, 2 * oy + 10 - y) for x, y in ring]
    for method in ("area", "accumulate"):
        _paint(ring, "nonzero", method, FORMATS[seed & 1], seed, _levels(ring, "nonzero", method, True))


def _star(n, k, cx, cy, r, turn):
    """A regular star polygon {n/k}: vertex i at angle turn + 2 pi i k / n,
    on the 1/256 px grid."""
    t = turn + 2 * np.pi * k * np.arange(n) / n
    return [(round((cx + r * math.cos(v)) * 256) / 256, round((cy + r * math.sin(v)) * 256) / 256) for v in t]


def _paint_all(ring, seed, plain):
    """_paint of ring with both rules, every method and format, against the
    oracle's levels (plain: as _levels takes it)."""
    for rule in ("nonzero", "evenodd"):
        for method in METHODS:
            for fmt in FORMATS:
                _paint(ring, rule, method, fmt, seed, _levels(ring, rule, method, plain))


# rings every vertex of which turns the same way but which wind twice, or
# whose dx flips sign only twice but which cross themselves
NOT_CONVEX = {
    "pentagram": _star(5, 2, 10.3, 9.6, 5.7, 0.3),
    "small pentagram": _star(5, 2, 4.6, 5.3, 2.35, 1.0),
    "bowtie": [(2.3, 3.1), (9.6, 7.7), (9.9, 2.2), (2.1, 8.4)],
    "thin bowtie": [(3.3, 4.05), (13.7, 6.6), (13.2, 3.9), (3.6, 6.8)],
}


@pytest.mark.parametrize("name", sorted(NOT_CONVEX))
def test_not_convex_goes_to_the_engines(name):
    _paint_all(NOT_CONVEX[name], 2, False)


@pytest.mark.parametrize("n", [15, 16, 17, 18, 20, 24])
def test_many_vertices(n):
    """Regular rings of 15 to 24 vertices, 5 to 17 px across (the small
    path's bound: 16 vertices; past it, its room for edges would overrun:
    make asan-py sees that)."""
    rnd = np.random.default_rng(n)
    rad = rnd.uniform(2.5, 8.5)
    c = rnd.uniform(rad + 1, 36 - rad, 2)
    t = rnd.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(n) / n
    ring = [(round((c[0] + rad * math.cos(v)) * 256) / 256, round((c[1] + rad * math.sin(v)) * 256) / 256)
            for v in t]
    for method in METHODS:
        _paint(ring, "nonzero", method, FORMATS[n & 1], n, _levels(ring, "nonzero", method, True))


# boxes round the bound both ways at once (pixel boxes of 24 x 24 px: the
# small path's; 25 x 25: the engines'), and rings partly off each side of
# the canvas
BOXES = {
    "24 x 24 octagon": [(3.5, 1.0), (20.5, 1.0), (25.0, 5.5), (25.0, 20.5), (20.5, 25.0), (3.5, 25.0),
                        (1.0, 20.5), (1.0, 5.5)],
    "25 x 25 octagon": [(3.5, 0.6), (20.5, 0.6), (24.6, 5.5), (24.6, 20.5), (20.5, 24.4), (3.5, 24.4),
                        (0.9, 20.5), (0.9, 5.5)],
    "25 x 25 diamond": [(12.7, 0.3), (24.5, 12.6), (12.7, 24.8), (0.3, 12.6)],
    "off the left": [(-5.3, 4.2), (6.6, 2.9), (9.1, 12.7), (-3.2, 15.4)],
    "off the top": [(4.2, -5.3), (16.1, -2.2), (13.3, 9.7), (2.9, 6.6)],
    "off the right": [(38.7, 4.2), (50.6, 2.9), (53.1, 12.7), (40.8, 15.4)],
    "off the bottom": [(6.2, 33.7), (18.1, 36.8), (15.3, 49.7), (4.9, 46.6)],
    "off the bottom right": [(39.6, 35.3), (47.2, 36.1), (45.4, 44.8), (41.1, 43.9)],
}


@pytest.mark.parametrize("name", sorted(BOXES))
def test_box_bounds_and_clip(name):
    _paint_all(BOXES[name], 3, True)

""""area"'s sweep of a group of two or three edges that all span the row
(csrc/src/coverage/coverage_area.c, "sweeps of two or three edges that
span the row": rast__area_two, rast__area_few): the edges in their exact
order at the row's top, their signs from the winding number left of them,
the neighbours' crossings inside the row in the order of their times, each
swapping its pair and resigning it, then every piece to the row's bottom,
as rast__cov_row_area would do it.  Against the exact oracles:
tests/oracle_nonzero.py (non-zero) and tests/oracle_coverage.py's
coverage_exact (even-odd), within the bound of rastrum.h, uint8 and uint16.

Rows here: bundles of two or three quadrilaterals from above the strip to
below it, each with one slanted side near the bundle's column and the
other upright a few pixels away, so that the slanted sides cross each
other inside the strip in every order (winding 2 or 3, or 0 where one is
wound the other way, between them), each bundle its own group of two or
three edges (rast__area_two, rast__area_few), alone or inside a wide ring
(winding 1 or -1 left of them); vertices on the 1/256 px grid, crossings
off it."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle_nonzero import nonzero_area
from test_coverage import check_area, exact_area

Q = 256  # vertices on the 1/256 px grid (S = 8): exact as given


def _snap(pts):
    return [(round(x * Q) / Q, round(y * Q) / Q) for x, y in pts]


def _ccw(pts):
    a, b, c = pts[:3]
    turn = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return pts if turn > 0 else pts[::-1]


def _bundle(rnd, x, h, n):
    """n (2 or 3) quadrilaterals from above the strip to below it, each
    with one slanted side near column x (from x + u at the top to x + v at
    the bottom, |u|, |v| < 1.6: the n sides cross each other inside the
    strip in some order; half the time through nearly one point, so that
    every pair crosses in one row) and the other upright 4 to 8 px away,
    left or right; each wound either way."""
    top, bot = -rnd.uniform(0.3, 2), h + rnd.uniform(0.3, 2)
    near = rnd.random() < 0.5  # the sides through nearly one point: every pair crossing in one row
    yc = rnd.uniform(0.3, h - 0.3)
    out = []
    for i in range(n):
        if near:
            sl, o = rnd.uniform(-0.45, 0.45), rnd.uniform(-0.12, 0.12)
            u, v = o + sl * (top - yc), o + sl * (bot - yc)
        else:
            u, v = rnd.uniform(-1.6, 1.6), rnd.uniform(-1.6, 1.6)
        if i % 2 == 0:
            X = x - 4 - 2 * i
            q = [(X, top), (x + u, top), (x + v, bot), (X, bot)]
        else:
            X = x + 4 + 2 * i
            q = [(x + u, top), (X, top), (X, bot), (x + v, bot)]
        q = _ccw(_snap(q))
        out.append(q if rnd.random() < 0.7 else q[::-1])
    return out


def _scene(rnd, w, h, nb, ring):
    """nb bundles of two or three crossing sides, 16 px apart, in a wide
    ring (either way round) or alone."""
    rings = []
    if ring:
        r = _ccw(_snap([(0.5, -3), (w - 0.5, -3), (w - 0.5, h + 3), (0.5, h + 3)]))
        rings.append(r if rnd.random() < 0.7 else r[::-1])
    for i in range(nb):
        x = 9 + 16 * i + rnd.uniform(-0.5, 0.5)
        rings.extend(_bundle(rnd, x, h, 2 + (rnd.random() < 0.5)))
    return rings


def _check(rings, shape, what, evenodd=True):
    n = sum(len(r) for r in rings)
    m = n * (n - 1) // 2
    nz = nonzero_area(rings, shape)
    eo = exact_area(rings, shape, "evenodd", 8) if evenodd else None
    for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
        out = rastrum.polygon_coverage(rings, shape, rule="nonzero", dtype=dtype, method="area")
        check_area(out, nz, M, n, m, "%s nonzero %s" % (what, np.dtype(dtype).name))
        if evenodd:
            out = rastrum.polygon_coverage(rings, shape, rule="evenodd", dtype=dtype, method="area")
            check_area(out, eo, M, n, m, "%s evenodd %s" % (what, np.dtype(dtype).name))


@pytest.mark.parametrize("seed", range(8))
def test_crossing_sides(seed):
    """Bundles of two and three crossing sides, alone and in a ring
    (winding 1 or -1 left of each bundle), both rules."""
    rnd = np.random.default_rng(400 + seed)
    w = (34, 50, 66, 82)[seed % 4]
    _check(_scene(rnd, w, 6, (w - 2) // 16, seed % 2 == 1), (6, w), "sides seed %d" % seed)


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([34, 50, 66]), st.booleans())
def test_crossing_sides_random(seed, w, ring):
    rnd = np.random.default_rng(seed)
    _check(_scene(rnd, w, 5, (w - 2) // 16, ring), (5, w), "random %d %d %d" % (seed, w, ring),
           evenodd=False)

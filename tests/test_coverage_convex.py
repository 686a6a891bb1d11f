""""area" of one convex ring by the accumulation (csrc/src/entry/coverage.c,
rast__cov_convex): a ring whose edges (those of length 0 skipped) all turn
one way or go straight on, and whose direction goes round once, is convex
and simple, so the accumulation is its exact coverage at any size (the
tiny polygons drawn one call each, where the general test of a plain
polygon does not pay).  Convex rings -- with repeated vertices, vertices
on a side, either way round, from any vertex, on pixel corners and off
them -- and rings that turn one way without being convex (a pentagram, a
convex ring wound twice, a side that turns back) are held to the exact
oracle (tests/oracle_coverage.py) under both rules, as polygon_coverage's
uint8 and uint16 levels and as Canvas.fill_polygon(aa="area")'s pixels."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check

SHAPE = (12, 12)


def _hull(pts):
    """The convex hull of integer points (Andrew's monotone chain), counter-
    clockwise in (x, y), no three on a line; fewer than 3 when degenerate."""
    pts = sorted(set(pts))
    if len(pts) < 3:
        return pts

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]
    return half(pts) + half(pts[::-1])


def _paint_check(rings, rule):
    """Canvas.fill_polygon(aa="area") of 255 on 0 writes each pixel's
    level: the same as polygon_coverage's uint8 (itself held to the oracle)."""
    want = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="area", dtype=np.uint8)
    for src in (np.asarray(rings[0], np.float64), rings[0]):
        c = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
        c.fill_polygon(np.zeros((3, 2)), 255, rule=rule, aa="area")  # the next call: the quick path
        c.fill_polygon(src, 255, rule=rule, aa="area")
        assert np.array_equal(c.array, want), "Canvas.fill_polygon(aa='area') differs: %s" % S_.lit(rings)


@settings(max_examples=S_.examples(60), deadline=None)
@given(st.lists(st.tuples(st.integers(-128, 896), st.integers(-128, 896)), min_size=3, max_size=9),
       st.sampled_from([1, 2, 4, 64]), st.integers(0, 8), st.booleans(), st.integers(0, 3),
       st.sampled_from(["nonzero", "evenodd"]))
def test_convex_rings(pts, grid, start, reverse, extra, rule):
    """Hulls of random points (in 1/64 px) on a grid of 1/grid px (grid 1:
    pixel corners), started anywhere, either way round, with a vertex
    repeated or a vertex put on a side's midpoint (on the line exactly: a
    side of even differences) `extra` times."""
    q = 64 // grid
    h = _hull([(x // q * q, y // q * q) for x, y in pts])
    if len(h) < 3:
        return
    ring = h[start % len(h):] + h[:start % len(h)]
    for k in range(extra):
        i = (3 * k) % len(ring)
        a, b = ring[i], ring[(i + 1) % len(ring)]
        if (a[0] - b[0]) % 2 == 0 and (a[1] - b[1]) % 2 == 0 and k % 2 == 0:
            ring.insert(i + 1, ((a[0] + b[0]) // 2, (a[1] + b[1]) // 2))
        else:
            ring.insert(i + 1, a)  # a side of length 0
    if reverse:
        ring = ring[::-1]
    rings = [[(x / 64, y / 64) for x, y in ring]]
    _check(rings, rule, shape=SHAPE)
    _paint_check(rings, rule)


def _pentagon(r=5.0, c=(6.0, 6.0), turns=1, step=1, n=5):
    return [(c[0] + r * np.cos(2 * np.pi * step * k / n + 0.3), c[1] + r * np.sin(2 * np.pi * step * k / n + 0.3))
            for k in range(n * turns)]


NOT_CONVEX = {
    # every turn the same way, the direction round twice: winding 2 inside the pentagon
    "pentagram": [_pentagon(step=2)],
    # a convex ring wound twice: winding 2 everywhere inside
    "a pentagon twice round": [_pentagon(turns=2)],
    # a side that turns back along itself: a spike out of a square
    "a spike back along a side": [[(1.5, 1.5), (9.5, 1.5), (11.5, 1.5), (9.5, 1.5), (9.5, 9.5), (1.5, 9.5)]],
}


@pytest.mark.parametrize("name", sorted(NOT_CONVEX))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_one_way_but_not_convex(name, rule):
    rings = NOT_CONVEX[name]
    exact = _check(rings, rule, shape=SHAPE)
    _paint_check(rings, rule)
    if name != "a spike back along a side":  # (the spike has no area: accumulation and area agree)
        acc = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_tiny_convex_ring_far_out_and_off_canvas(rule):
    """A convex ring partly off the canvas, and one wholly off it."""
    for ring in ([(-3.3, -2.1), (4.2, -1.7), (5.1, 3.9), (-1.2, 5.5)],
                 [(20.25, 3.5), (30.5, 4.0), (25.0, 9.75)]):
        _check([ring], rule, shape=SHAPE)
        _paint_check([ring], rule)

""""accumulate" on deep rows (csrc/src/coverage/coverage_acc.c, the bands'
walk, session 21): a row of 4,096 parts or more used to go whole to the
exact sweep; now it is accumulated, even-odd always, non-zero where the
bound from the band's edges (rast__acc_deep_add, rast__acc_deep_fits)
keeps every pixel's |winding integral| <= 4,095, and to the exact sweep
when it does not.  Piles of a few tall triangles (34 to 46 rows of a 48-row
canvas: the bands' walk, not the piles' nor the rows') each repeated
hundreds or thousands of times, some one way round and some the other, so
that rows hold 4,200 to 16,400 parts and the winding integral reaches
+-1,400 (under the bound) or +-8,192 (past it, where a 64-bit running sum
read as signed wraps to 0); as rings (polygon_coverage, uint8 and uint16,
both rules) and as a triangle batch.  The oracle: the accumulation's own
definition (test_coverage._accumulated's: each ring's exact signed area
over each pixel, here once a distinct triangle times its count, summed,
the rule applied)."""

import numpy as np
import pytest

import oracle_coverage as oc
import rastrum
from test_coverage import M_OF, check_area, exact_area, rule_applied, F

SHAPE = (48, 24)


def _tri(rnd, shape):
    """A triangle 34 to 46 rows high, vertices on a 1/4 px grid."""
    h, w = shape
    while True:
        top = rnd.uniform(0.0, 10.0)
        bot = rnd.uniform(top + 34.0, min(h - 0.25, top + 46.0))
        pts = [(rnd.uniform(0.5, w - 0.5), top), (rnd.uniform(0.5, w - 0.5), bot),
               (rnd.uniform(0.5, w - 0.5), rnd.uniform(top, bot))]
        tri = [(round(x * 4) / 4, round(y * 4) / 4) for x, y in pts]
        if _area2(tri) != 0:
            return tri


def _area2(t):
    return (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])


def _turned(t, sign):
    """t with the sign of its (doubled) area: +1 or -1."""
    return t if (_area2(t) > 0) == (sign > 0) else t[::-1]


def _want(pile, shape, rule):
    """The rule applied to sum(count * signed exact area): pile is a list
    of (triangle, count), each triangle as it is drawn."""
    total = None
    for t, c in pile:
        a = exact_area([t], shape, "nonzero", 8) * (c if _area2(t) > 0 else -c)
        total = a if total is None else total + a
    return rule_applied(total, rule)


def _n_m(pile):
    """The scene's edges and crossing pairs (test_coverage._n_m's, of the
    distinct triangles' edges times their counts)."""
    edges = []
    for t, c in pile:
        for e in oc._edges(oc.oracle.snapped_rings([t], 8)):
            edges.append((e, c))
    m = 0
    for p in range(len(edges)):
        for q in range(p + 1, len(edges)):
            a, b = edges[p][0], edges[q][0]
            y = oc._crossing_y(a, b)
            if y is not None and max(a[1], b[1]) < y < min(a[3], b[3]):
                m += edges[p][1] * edges[q][1]
    return sum(c for _, c in edges), m


def _rings(pile):
    return [np.asarray(t, dtype=np.float64) for t, c in pile for _ in range(c)]


def _piles(seed):
    """(name, pile): windings under the bound both ways, and past it (one
    triangle 8,192 times) either way round."""
    rnd = np.random.default_rng(seed)
    t = [_tri(rnd, SHAPE) for _ in range(5)]
    return [
        ("mixed", [(_turned(t[0], 1), 1100), (_turned(t[1], -1), 1100), (_turned(t[2], 1), 300)]),
        ("up", [(_turned(t[0], 1), 700), (_turned(t[1], 1), 700), (_turned(t[3], 1), 700)]),
        ("down", [(_turned(t[2], -1), 1400), (_turned(t[4], -1), 800)]),
        ("past up", [(_turned(t[3], 1), 8192), (_turned(t[4], -1), 3)]),
        ("past down", [(_turned(t[1], -1), 8192), (_turned(t[0], 1), 5)]),
    ]


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_deep_rows_rings(seed, rule):
    for name, pile in _piles(seed):
        want = _want(pile, SHAPE, rule)
        n, m = _n_m(pile)
        rings = _rings(pile)
        for dtype in (np.uint8, np.uint16):
            out = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=dtype)
            check_area(out, want, M_OF[dtype], n, m, "%s seed %d %s %s: %s" % (
                name, seed, rule, np.dtype(dtype).name, [(t, c) for t, c in pile]))


@pytest.mark.parametrize("seed", [3, 4])
def test_deep_rows_triangle_batch(seed):
    """triangles_coverage(method="accumulate"): each triangle turned
    counter-clockwise, so the winding integral is the count of them over
    the pixel: 2,400 (under the bound) and 8,197 (past it)."""
    rnd = np.random.default_rng(seed)
    t = [_turned(_tri(rnd, SHAPE), 1) for _ in range(4)]
    for pile in ([(t[0], 800), (t[1], 800), (t[2], 800)], [(t[3], 8192), (t[0], 5)]):
        want = _want(pile, SHAPE, "nonzero")
        n, m = _n_m(pile)
        tris = np.asarray([tt for tt, c in pile for _ in range(c)], dtype=np.float64)
        # (each given either way round: the batch turns them)
        tris[1::2] = tris[1::2, ::-1]
        out = rastrum.triangles_coverage(tris, SHAPE, method="accumulate")
        check_area(out, want, M_OF[np.uint8], n, m, "batch seed %d: %s" % (seed, pile))

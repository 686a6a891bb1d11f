""""accumulate" of a map whose countries share their borders
(csrc/src/coverage/coverage_acc.c, rast__acc_many_pairs and
rast__acc_cancel): a polygon of 2 rings or more and 1,024 edges or more
that is not a mesh's has a sample of its edges looked at (about one in s,
s = max(4, floor(sqrt(n / 64))), pseudo-random gaps), and when the pairs
of equal and opposite edges found there stand for an eighth of the edges
or more, every such pair is dropped before the walk (two such edges add
nothing to the winding number anywhere: the same accumulation, docs/
coverage.md).  When the sample finds pairs but too few, nothing may be
dropped, not even the pairs it found.

The scenes: maps on a jittered grid (test_coverage_borders._map: each
border cut at points both neighbours share) of 10 x 10 countries, the
same way round each, with a lake, with a country drawn twice (its coast
and its borders the same way twice: winding 2, a border three times, one
of them the other way) or wound the other way (its borders the same way
as its neighbours': nothing cancels there); and a 3 x 3 map among 60
rings that share nothing (the sample finds some of the map's pairs, too
few).  Against the accumulation's own definition in exact arithmetic
(test_coverage._accumulated's: the rule applied to the sum of each
ring's signed exact area, each ring's taken over its own box here), with
check_area's allowance at a tie, uint8 and uint16."""

from fractions import Fraction as F

import numpy as np
import pytest

import rastrum
import oracle_coverage as oc
from test_coverage import check_area, exact_area, rule_applied
from test_coverage_borders import _map, _shape

M_OF = {np.uint8: 255, np.uint16: 65535}


def _accumulated(rings, shape, rule, s=8):
    """test_coverage._accumulated, each ring's exact area computed over its
    own box of pixels (moved there by whole pixels: the same snapped
    points, moved) and added into the whole."""
    total = np.empty(shape, object)
    total.fill(F(0))
    for ring in rings:
        snapped = oc.oracle.snapped_rings([ring], s)[0]
        area2 = sum(F(x0) * F(y1) - F(x1) * F(y0)
                    for (x0, y0), (x1, y1) in zip(snapped, snapped[1:] + snapped[:1]))
        r = np.asarray(ring, float)
        x0, y0 = int(np.floor(r[:, 0].min())) - 1, int(np.floor(r[:, 1].min())) - 1
        x1, y1 = int(np.ceil(r[:, 0].max())) + 1, int(np.ceil(r[:, 1].max())) + 1
        moved = (r - [x0, y0]).tolist()
        a = exact_area([moved], (y1 - y0, x1 - x0), "nonzero", s) * (1 if area2 > 0 else -1)
        for (j, i), v in np.ndenumerate(a):
            if 0 <= y0 + j < shape[0] and 0 <= x0 + i < shape[1]:
                total[y0 + j, x0 + i] += v
            else:
                assert v == 0, "the shape must hold every ring"
    return rule_applied(total, rule)


def _n_m(rings, s=8):
    """test_coverage._n_m (edges; pairs that cross strictly inside both),
    the pairs tried only where their boxes meet."""
    edges = oc._edges(oc.oracle.snapped_rings(rings, s))
    box = np.array([[min(e[0], e[2]), e[1], max(e[0], e[2]), e[3]] for e in edges], float)
    m = 0
    for p in range(len(edges)):
        near = np.nonzero((box[p + 1:, 0] <= box[p, 2]) & (box[p + 1:, 2] >= box[p, 0])
                          & (box[p + 1:, 1] <= box[p, 3]) & (box[p + 1:, 3] >= box[p, 1]))[0] + p + 1
        for q in near:
            y = oc._crossing_y(edges[p], edges[q])
            if y is not None and max(edges[p][1], edges[q][1]) < y < min(edges[p][3], edges[q][3]):
                m += 1
    return len(edges), m


def _edges_not_horizontal(rings):
    return sum(sum(1 for a, b in zip(r, r[1:] + r[:1]) if a[1] != b[1]) for r in rings)


def _check(rings, shape, rule, what):
    exact = _accumulated(rings, shape, rule)
    n, m = _n_m(rings)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
        check_area(out, exact, M_OF[dtype], n, m, "%s %s" % (what, np.dtype(dtype).name))
    return exact


def _scene(kind, seed):
    m = _map(seed, 10, 10, 8)
    if kind == "same way":
        return list(m.values())
    if kind == "a lake":
        return [r for c, r in m.items() if c != (4, 5)]
    if kind == "an inland one twice":  # winding 2 inside it; its borders three times
        return list(m.values()) + [m[4, 4]]
    if kind == "a coastal one twice":  # winding 2 next to 0
        return list(m.values()) + [m[0, 3]]
    if kind == "one the other way":  # its borders the same way as its neighbours'
        return [r[::-1] if c == (5, 5) else r for c, r in m.items()]
    raise ValueError(kind)


KINDS = ["same way", "a lake", "an inland one twice", "a coastal one twice", "one the other way"]
# What a wrong drop would draw instead: the country's copies dropped with
# each other (a lake there), or its borders with its neighbours' the same
# way (the map the same way round everywhere).
WRONG = {"an inland one twice": ("a lake at", (4, 4)), "a coastal one twice": ("a lake at", (0, 3)),
         "one the other way": ("same way", None)}


@pytest.mark.parametrize("kind,rule,seed", [("same way", "nonzero", 11), ("same way", "evenodd", 5),
                                            ("a lake", "evenodd", 12), ("an inland one twice", "nonzero", 13),
                                            ("an inland one twice", "nonzero", 6),
                                            ("a coastal one twice", "nonzero", 14),
                                            ("one the other way", "nonzero", 15),
                                            ("one the other way", "evenodd", 16)])
def test_maps_cancelled(kind, rule, seed):
    rings = _scene(kind, seed)
    n = _edges_not_horizontal(rings)
    assert n >= 1024  # (the sample's threshold, RAST__ACC_LOOK_MIN)
    exact = _check(rings, _shape(10, 10), rule, kind)
    if kind in WRONG:  # the scene means something: the wrong drop would be seen
        how, c = WRONG[kind]
        other = (_scene("same way", seed) if how == "same way"
                 else [r for k, r in _map(seed, 10, 10, 8).items() if k != c])
        wrong = _accumulated(other, _shape(10, 10), rule)
        assert any(a != b for a, b in zip(exact.flat, wrong.flat)), "the scene tests nothing"


def _blob(rnd, c, k, r):
    """A simple ring: k vertices by increasing angle round c, none more than
    pi/4 after the last, radii between r/2 and r (1/64 px)."""
    ang = (np.arange(k) + rnd.uniform(0, 0.45, k)) * 2 * np.pi / k
    rad = rnd.uniform(0.5 * r, r, k)
    return (np.round(np.stack([c[0] + rad * np.cos(ang), c[1] + rad * np.sin(ang)], 1) * 64) / 64).tolist()


@pytest.mark.parametrize("seed,rule", [(1, "nonzero"), (2, "evenodd"), (3, "nonzero"), (4, "evenodd")])
def test_few_pairs_among_many(seed, rule):
    """A 3 x 3 map (36 pairs of shared edges) among 60 rings of 16 to 20
    vertices that share nothing: the sample finds a few of the pairs, too
    few for the whole to be looked at; what it found stays."""
    rnd = np.random.default_rng(seed)
    rings = list(_map(seed, 3, 3, 4).values())
    for q in range(60):
        rings.append(_blob(rnd, (7.5 + 2.2 * (q % 10), 1.5 + 2.2 * (q // 10)), int(rnd.integers(16, 21)), 1.0))
    n = _edges_not_horizontal(rings)
    assert 1024 <= n < 1300
    _check(rings, (16, 30), rule, "few pairs %d" % seed)

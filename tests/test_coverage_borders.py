""""area" of rings that share their borders, a map's countries
(csrc/src/coverage/coverage_plain.c, rast__cov_borders): two edges equal
and opposite add nothing to the winding number, so the polygon without
them has the coverage of the original, and when it is plain "area" takes
its accumulation (issue 33).  The scenes are maps on a jittered grid
whose neighbours run along the same border points the opposite ways
(64 points or more: the test's threshold), the same way round each, with
a lake (a country left out), or with what must not go that way: a
country wound the other way (its borders do not cancel), one drawn twice
(winding 2 inside it, next to 0 on the coast), a ring inside a coastal
country (winding 2 a fraction of a pixel from 0: the rings are apart,
condition 3 in the sweep must see it), a ring across the others; or two
lakes that touch at a corner (the coast passes one point twice: not
joined into rings).
Each is held to the exact oracle
(tests/oracle_coverage.py) under one rule or the other (the oracle is
slow on a map), in uint8 and uint16; where
the accumulation alone is wrong, the scene says so (else it would test
nothing)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check


def _map(seed, nx, ny, k, cell=1.6):
    """Countries on an nx by ny grid: corners jittered, each border cut in
    k pieces at points both neighbours share (1/64 px), every ring
    counter-clockwise; the rings by (row, column)."""
    rnd = np.random.default_rng(seed)
    cx = 1.0 + cell * np.arange(nx + 1)[None, :] + rnd.uniform(-0.35, 0.35, (ny + 1, nx + 1))
    cy = 1.0 + cell * np.arange(ny + 1)[:, None] + rnd.uniform(-0.35, 0.35, (ny + 1, nx + 1))
    cut = {}

    def border(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in cut:
            pa = np.array([cx[key[0]], cy[key[0]]])
            pb = np.array([cx[key[1]], cy[key[1]]])
            t = np.arange(1, k) / k
            d = pb - pa
            off = rnd.uniform(-0.12, 0.12, (k - 1, 1)) * np.array([-d[1], d[0]]) / np.hypot(*d)
            cut[key] = np.round((pa + t[:, None] * d + off) * 64) / 64
        pts = cut[key]
        return pts if (a, b) == key else pts[::-1]

    def corner(c):
        return np.round(np.array([[cx[c], cy[c]]]) * 64) / 64

    rings = {}
    for i in range(ny):
        for j in range(nx):
            cs = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]  # (every ring the same way round)
            parts = []
            for q in range(4):
                parts += [corner(cs[q]), border(cs[q], cs[(q + 1) % 4])]
            rings[i, j] = np.concatenate(parts).tolist()
    return rings


def _shape(nx, ny, cell=1.6):
    return (int(np.ceil(ny * cell + 2.5)), int(np.ceil(nx * cell + 2.5)))


def _scene(kind, seed, nx, ny, k):
    m = _map(seed, nx, ny, k)
    if kind == "same way":
        return list(m.values())
    if kind == "a lake":
        return [r for c, r in m.items() if c != (1, 1)]
    if kind == "one the other way":
        return [r[::-1] if c == (1, 1) else r for c, r in m.items()]
    if kind == "a coastal one twice":  # winding 2 next to 0
        return list(m.values()) + [m[0, 0]]
    if kind == "an inland one twice":  # winding 2 inside the coast
        return list(m.values()) + [m[1, 1]]
    if kind == "a country within one":  # a ring inside a coastal country, a fraction of a pixel from the coast
        r = np.array(m[0, 0])
        c = r.mean(0)
        return list(m.values()) + [(np.round((c + 0.85 * (r - c)) * 64) / 64).tolist()]
    if kind == "a ring across":
        return list(m.values()) + [[(0.5, 2.3), (nx * 1.6 + 1.5, 2.1), (nx * 1.6 + 1.4, 2.9), (0.6, 3.2)]]
    if kind == "two lakes corner to corner":  # the coast through one point twice: two edges start there
        return [r for c, r in m.items() if c not in ((1, 1), (2, 2))]
    raise ValueError(kind)


KINDS = ["same way", "a lake", "two lakes corner to corner", "one the other way", "a coastal one twice",
         "an inland one twice", "a country within one", "a ring across"]
# (where the accumulation alone is wrong)
NOT_PLAIN = {"one the other way", "a coastal one twice", "a country within one", "a ring across"}


@pytest.mark.parametrize("kind,rule", [(kind, ("nonzero", "evenodd")[i % 2]) for i, kind in enumerate(KINDS)])
def test_maps(kind, rule):
    nx, ny, k = 3, 3, 3
    rings = _scene(kind, 7, nx, ny, k)
    assert sum(len(r) for r in rings) >= 64
    exact = _check(rings, rule, shape=_shape(nx, ny))
    if kind in NOT_PLAIN:  # the accumulation alone is wrong there: the fallback is needed
        acc = rastrum.polygon_coverage(rings, _shape(nx, ny), rule=rule, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.just(3), st.integers(3, 4), st.integers(2, 3),
       st.sampled_from(KINDS), st.sampled_from(["nonzero", "evenodd"]), st.booleans())
def test_random_maps(seed, nx, ny, k, kind, rule, flip):
    """Maps of 3 by 3 or 4 countries, borders of 2 or 3 pieces, any
    kind, wound either way as a whole; the oracle decides."""
    rings = _scene(kind, seed, nx, ny, k)
    if flip:
        rings = [r[::-1] for r in rings]
    _check(rings, rule, shape=_shape(nx, ny))

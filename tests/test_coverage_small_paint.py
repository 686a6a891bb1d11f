"""The small path's rows handed to the painter (coverage_small.c, issue 33)
and gray8's blend of a run (formats.c, eight pixels at a time where SSE2
is), over a background that is not 0: Canvas.fill_polygon(aa=...) of one
small ring must leave every pixel at (s*c + d*(255 - c) + 127) // 255 of
its background d, the colour s and the ring's level c as polygon_coverage
gives it (an array: the engines' levels, never the painter's), written
here from the docs (docs/coverage.md).  The rings: slivers whose rows have
levels 0 between levels not 0 (a row that is not one run), rings 16 to 24
pixels wide (stretches of 255 for the painter's full entry), rings partly
off the canvas (the run cut to the clip), and runs of every length round
the blend's eight pixels."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_

SHAPE = (36, 40)


def _mix(s, d, c):
    s, d, c = (np.asarray(v, np.int64) for v in (s, d, c))
    return (s * c + d * (255 - c) + 127) // 255


def _check(ring, method, color, seed, rule="nonzero"):
    ring = np.ascontiguousarray(np.asarray(ring, np.float64))
    cov = rastrum.polygon_coverage([ring], SHAPE, rule=rule, method=method, dtype=np.uint8)
    bg = np.random.default_rng(seed).integers(0, 256, SHAPE, dtype=np.uint8)
    c = rastrum.Canvas.wrap(bg.copy())
    c.fill_polygon(ring, color, rule=rule, aa=method)
    want = _mix(color, bg, cov).astype(np.uint8)
    S_.assert_same(c.array, want, "Canvas.fill_polygon(aa=%r, color=%d) off the blend of its levels: %s"
                   % (method, color, S_.lit([ring])))
    return cov


RINGS = {
    # thin and slanted: rows whose supersampled levels have a 0 between
    # levels not 0, the line missing every sample of a pixel ("area" of a
    # convex ring is one run a row: a concave height's integrals)
    "sliver 1": [(1.3, 5.02), (22.7, 10.31), (22.7, 10.34), (1.3, 5.05)],
    "sliver 2": [(1.3, 5.1), (22.7, 7.9), (22.7, 7.93), (1.3, 5.13)],
    # wide rows: stretches of 255 of 16 pixels and more (the full entry)
    "box 22 wide": [(1.3, 2.6), (23.2, 2.6), (23.2, 9.4), (1.3, 9.4)],
    "hexagon 23 wide": [(1.4, 12.0), (7.0, 2.3), (18.9, 2.2), (24.3, 12.1), (18.8, 21.7), (7.1, 21.9)],
    # partly off the canvas, each side
    "off left": [(-5.3, 3.2), (6.6, 2.9), (7.4, 11.3), (-4.1, 12.8)],
    "off right and bottom": [(31.2, 28.4), (45.1, 29.0), (44.0, 41.5), (33.3, 40.2)],
}


@pytest.mark.parametrize("name", sorted(RINGS))
def test_rings_over_a_background(name):
    for method in ("area", "accumulate", "ss2", "ss4"):
        for color in (0, 1, 128, 200, 255):
            cov = _check(RINGS[name], method, color, seed=len(name) + color)
    if name.startswith("sliver") or name.startswith("off"):
        return
    full = (cov == 255).astype(np.int8)
    run = max(max((len(r) for r in "".join(map(str, row)).split("0")), default=0) for row in full)
    assert run >= 16, "no stretch of 16 levels 255 in %s: the full entry is not reached" % name


def test_sliver_rows_are_not_one_run():
    """The slivers are what they are for: some row's levels not 0 have a 0
    between them (else the test above would not reach the row machinery)."""
    for method in ("ss2", "ss4"):
        gaps = 0
        for name in ("sliver 1", "sliver 2"):
            cov = rastrum.polygon_coverage([np.asarray(RINGS[name])], SHAPE, rule="nonzero", method=method,
                                           dtype=np.uint8)
            for row in cov:
                nz = np.flatnonzero(row)
                gaps += len(nz) > 0 and nz[-1] - nz[0] + 1 != len(nz)
        assert gaps > 0, method


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(3, 12), st.integers(0, 2 ** 32 - 1), st.floats(0.3, 12.0), st.floats(0.05, 1.0),
       st.sampled_from(["area", "accumulate", "ss2", "ss4"]), st.integers(0, 255))
def test_random_rings_over_a_background(n, seed, rad, squash, method, color):
    """Regular rings squashed to slivers or not, turned at random, anywhere
    (partly off the canvas too): runs of every length from 1 to 24."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(-rad, np.array(SHAPE[::-1]) + rad, 2)
    t = 2 * np.pi * np.arange(n) / n
    x, y = rad * np.cos(t), rad * squash * np.sin(t)
    a = rnd.uniform(0, 2 * np.pi)
    ring = np.stack([c[0] + x * np.cos(a) - y * np.sin(a), c[1] + x * np.sin(a) + y * np.cos(a)], 1)
    _check(ring, method, color, seed)

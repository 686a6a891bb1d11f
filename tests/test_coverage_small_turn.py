"""One small convex ring painted by "area" and "accumulate" into gray8
(coverage_small.c), either way round: its levels are taken from its
running sums without their magnitude, each edge's sign being minus the
ring's turn (entry/coverage.c's rast__cov_convex) times its direction, so
that the sums are the pixels' areas inside whichever way the ring goes
(docs/coverage.md: a convex ring's winding number is +1 or -1 inside, and
its accumulation its exact coverage).  Each ring is drawn as given and
reversed, from each of its vertices, and every pixel is held to the blend
of the exact levels (tests/oracle_coverage.py through
test_coverage_small_box's check, written from the docs): regular and
jittered rings, rectangles whose sides lie on pixel lines (sums exactly 0
right of them and between), and slivers a fraction of a pixel wide
(sums near 0, which the rounding of the crossings may leave a little
below it)."""

import numpy as np
import pytest

from test_coverage_small_box import _check, _ring

RINGS = {
    "triangle": [(3.3, 2.1), (11.7, 5.4), (5.2, 10.9)],
    "rectangle on pixel lines": [(2.0, 3.0), (9.0, 3.0), (9.0, 6.0), (2.0, 6.0)],
    "square on half pixels": [(4.5, 4.5), (8.5, 4.5), (8.5, 8.5), (4.5, 8.5)],
    "steep sliver": [(6.0, 1.0), (6.25, 1.0), (6.1, 12.0)],
    "flat sliver": [(1.0, 6.0), (13.0, 6.1), (1.0, 6.3)],
    "hexagon": _ring(8.2, 7.1, 4.6, 6, 5),
    "octagon": _ring(7.4, 6.6, 5.8, 8, 11),
    "pentagon past the left": _ring(1.3, 7.2, 4.1, 5, 3),
    "quad past the bottom right": _ring(15.1, 12.8, 3.7, 4, 8),
}


@pytest.mark.parametrize("name", sorted(RINGS))
@pytest.mark.parametrize("method", ["area", "accumulate"])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_either_way_round(name, method, rule):
    ring = RINGS[name]
    for way in (ring, ring[::-1]):
        for k in range(len(way)):
            _check(way[k:] + way[:k], method, 200, 7 * k + len(way), rule)


@pytest.mark.parametrize("seed", range(12))
def test_random_rings_either_way(seed):
    g = np.random.default_rng(seed)
    for _ in range(6):
        ring = _ring(g.uniform(1, 16), g.uniform(1, 13), g.uniform(0.4, 6.5), int(g.integers(3, 9)),
                     int(g.integers(1 << 30)))
        for way in (ring, ring[::-1]):
            _check(way, "area" if seed % 2 else "accumulate", int(g.integers(0, 256)), seed)

""""area"'s quick groups in a swept row where a quick level is not certain
(csrc/src/coverage/coverage_area.c, "quick groups in a swept row"): when
rast__grp_emit finds a quick column whose value lies within the window of
a tie between two levels, it returns 0 with the quick cells cleared and the
exact ones kept, and rast__cov_row_groups adds the quick groups again the
exact way (rast__area_exact), rast__cells_emit then writing the row.  The
scenes of tests/test_coverage_group_quick.py never reach that fallback: on
the 1/256 px grid a pixel's coverage lies within the window of a tie only
by chance.  Here the fast groups (holes in a wide ring, lone triangles and
quadrilaterals beside it) have their vertices on the half-pixel grid, so
that many of their pixels are covered by exactly 1/2 (or 1/4, 3/4): in
uint8 and uint16 alike, 1/2 M is a tie (M odd), which the quick value
cannot decide.  The rows are swept by two overlapping triangles across
each side of the ring (winding 2 there).  Against the exact oracle of
tests/oracle_nonzero.py, within the bound of rastrum.h (at a tie, one
level either way), uint8 and uint16."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from test_coverage_group_keys import _check

Q = 256  # the swept triangles' vertices on the 1/256 px grid (S = 8)


def _snap(pts, q):
    return [(round(x * q) / q, round(y * q) / q) for x, y in pts]


def _ccw(pts):
    a, b, c = pts[:3]
    turn = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return pts if turn > 0 else pts[::-1]


def _half(rnd, x, y, size):
    """A triangle or an axis-aligned quadrilateral with vertices on the
    half-pixel grid near (x, y), up to size px across: sides through
    pixels' diagonals and verticals at x + 1/2 (pixels covered 1/2)."""
    if rnd.random() < 0.5:
        w, h = max(0.5, round(rnd.uniform(0.5, size) * 2) / 2), max(0.5, round(rnd.uniform(0.5, size) * 2) / 2)
        pts = _snap([(x, y), (x + w, y), (x + w, y + h), (x, y + h)], 2)
    else:
        d = max(0.5, round(rnd.uniform(0.5, size) * 2) / 2)
        pts = _snap([(x, y), (x + d, y), (x + d, y + d)] if rnd.random() < 0.5 else
                    [(x, y), (x + d, y + d), (x, y + d)], 2)
    return _ccw(pts)


def _scene(rnd, w, h, nholes, nout):
    """A ring from x0 to x1 over the whole strip; two overlapping
    triangles (1/256 px grid) across each of its sides; nholes holes
    inside it (wound the other way) and nout shapes outside it, a share
    past either end of the clip, on the half-pixel grid."""
    x0, x1 = round(rnd.uniform(0.2, 0.3) * w * 2) / 2, round(rnd.uniform(0.7, 0.8) * w * 2) / 2
    ring = _ccw([(x0, -1.5), (x1, -1.5), (x1 + 0.5, h + 1.5), (x0 - 0.5, h + 1.5)])
    rings = [ring]
    for xs in (x0, x1):
        for _ in range(2):
            rings.append(_ccw(_snap([(xs - 2.5 + rnd.uniform(0, 4.5), rnd.uniform(-1.5, 0.5) + k * h / 3)
                                     for k in range(3)], Q)))
    for _ in range(nholes):
        xh = round(rnd.uniform(x0 + 3.5, x1 - 5.5) * 2) / 2
        rings.append(_half(rnd, xh, round(rnd.uniform(-1, h - 1) * 2) / 2, 2.5)[::-1])
    for _ in range(nout):
        if rnd.random() < 0.5:
            xo = rnd.uniform(-3, x0 - 6) if rnd.random() < 0.7 else rnd.uniform(-4, -1)
        else:
            xo = rnd.uniform(x1 + 4, w) if rnd.random() < 0.7 else rnd.uniform(w - 1, w + 2)
        rings.append(_half(rnd, round(xo * 2) / 2, round(rnd.uniform(-1, h - 1) * 2) / 2, 2.5))
    return rings


@pytest.mark.parametrize("seed", range(8))
def test_half_pixel_shapes_beside_swept_sides(seed):
    """Holes and lone shapes on the half-pixel grid in rows swept across
    both sides of the ring: quick columns of 1/2, 1/4 and 3/4 coverage."""
    rnd = np.random.default_rng(300 + seed)
    w = (40, 56, 72, 90)[seed % 4]
    _check(_scene(rnd, w, 7, 3 + seed, 3 + seed % 4), (7, w), "ties seed %d" % seed)


@settings(max_examples=12, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 8), st.integers(0, 8), st.sampled_from([36, 57, 80]))
def test_half_pixel_shapes_random(seed, nholes, nout, w):
    rnd = np.random.default_rng(seed)
    _check(_scene(rnd, w, 5, nholes, nout), (5, w), "ties random %d %d %d %d" % (seed, nholes, nout, w))

""""area"'s rows by groups where one group is swept and others are fast
(csrc/src/coverage/coverage_area.c, "quick groups in a swept row"): the
fast groups go to the quick cells (64-bit, 2^-30 px) beside the swept
groups' exact cells, and rast__grp_emit writes each column the way its
group was added: an exact column from the exact cover plus the quick
cover so far, a quick column from the quick cover plus the exact cover so
far (whole rows there), and where a quick level is not certain the quick
groups are added again the exact way.  Against the exact oracle of
tests/oracle_nonzero.py (checked against tests/oracle_coverage.py in
tests/test_coverage_few_live.py), within the bound of rastrum.h, uint8 and
uint16.

Rows here: a wide ring (winding 1) whose left and right sides are each
crossed by two overlapping triangles (winding 2 there: those groups are
swept), with holes (rings wound the other way) inside it, fast groups whose
pixels lie on the inside, and lone triangles outside it, some reaching
past either end of the clip; rows with several holes between two swept
groups; and scenes of the same kind in rows where the swept group lies
right of the fast ones (the swept flag carried from the row above)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from test_coverage_group_keys import _check

Q = 256  # the vertices on the 1/256 px grid (S = 8): exact as given


def _snap(pts):
    return [(round(x * Q) / Q, round(y * Q) / Q) for x, y in pts]


def _ccw(pts):
    a, b, c = pts[:3]
    turn = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return pts if turn > 0 else pts[::-1]


def _tri(rnd, x, y, size):
    return _snap([(x + rnd.uniform(0, size), y + rnd.uniform(0, size)) for _ in range(3)])


def _scene(rnd, w, h, nholes, nout, swept_left=True):
    """A ring from x0 to x1 over the whole strip (and past it), the same
    way round as the triangles; two overlapping triangles across its left
    side and two across its right (the swept groups; only the right pair
    when not swept_left); nholes holes inside it, wound the other way;
    nout lone triangles left and right of it, a share past the clip."""
    x0, x1 = rnd.uniform(0.2, 0.35) * w, rnd.uniform(0.65, 0.8) * w
    ring = _ccw(_snap([(x0, -1.5), (x1 + rnd.uniform(-1, 1), -1.5), (x1, h + 1.5), (x0 + rnd.uniform(-1, 1), h + 1.5)]))
    rings = [ring]
    sides = [x0, x1] if swept_left else [x1]
    for xs in sides:
        for _ in range(2):
            rings.append(_ccw(_tri(rnd, xs - 2.5, rnd.uniform(-1, h - 2), 4.5)))
    for _ in range(nholes):
        xh = rnd.uniform(x0 + 3.5, x1 - 5.5)
        rings.append(_ccw(_tri(rnd, xh, rnd.uniform(-1, h - 1.5), rnd.uniform(1.2, 2.2)))[::-1])
    for _ in range(nout):
        if rnd.random() < 0.5:
            xo = rnd.uniform(-3, x0 - 5) if rnd.random() < 0.7 else rnd.uniform(-5, -1)
        else:
            xo = rnd.uniform(x1 + 3, w) if rnd.random() < 0.7 else rnd.uniform(w - 1, w + 3)
        rings.append(_ccw(_tri(rnd, xo, rnd.uniform(-1, h - 1.5), rnd.uniform(1.2, 2.5))))
    return rings


@pytest.mark.parametrize("seed", range(6))
def test_holes_between_swept_sides(seed):
    """Holes inside the ring between its two swept sides: their quick
    columns lie right of a swept group whose cover is a whole row."""
    rnd = np.random.default_rng(seed)
    w = (40, 64, 90)[seed % 3]
    _check(_scene(rnd, w, 6, 3 + seed, 4), (6, w), "holes seed %d" % seed)


@pytest.mark.parametrize("seed", range(4))
def test_swept_right_of_fast(seed):
    """The swept pair across the ring's right side only: in its rows the
    fast groups left of it (lone triangles, the ring's left side, holes)
    are kept and flushed when the sweep comes, in the rows below quick
    beside it from the start."""
    rnd = np.random.default_rng(100 + seed)
    w = (48, 72)[seed % 2]
    _check(_scene(rnd, w, 8, 2 + seed, 5, swept_left=False), (8, w), "right seed %d" % seed)


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 8), st.integers(0, 8), st.sampled_from([36, 57, 80]),
       st.booleans())
def test_swept_and_quick_random(seed, nholes, nout, w, left):
    rnd = np.random.default_rng(seed)
    _check(_scene(rnd, w, 5, nholes, nout, left), (5, w), "random %d %d %d %d %d" % (seed, nholes, nout, w, left))


def _wide(rnd, ntri, w, h):
    """ntri triangles 1.5 to 5 px across in a strip h rows high and w px
    wide, each starting in some row (new edges for that row's sort), a share
    of them long and slanted (edges whose columns pass their neighbours'
    from row to row), a few past the clip."""
    rings = []
    for _ in range(ntri):
        x, y = rnd.uniform(-3, w + 2), rnd.uniform(-1, h - 1)
        if rnd.random() < 0.3:
            d = rnd.uniform(-6, 6)
            pts = [(x, y), (x + d, y + h), (x + d + rnd.uniform(0.5, 2), y + h)]
        else:
            s = rnd.uniform(1.5, 5)
            pts = [(x + rnd.uniform(0, s), y + rnd.uniform(0, s)) for _ in range(3)]
        rings.append(_ccw(_snap(pts)))
    return rings


@pytest.mark.parametrize("seed", range(4))
def test_wide_rows_sorted_from_the_last(seed):
    """Rows of 49 to 170 parts on a canvas three times as wide as that
    (rast__grp_merge: the last row's order kept, the new edges merged in),
    the triangles overlapping (swept groups beside quick ones)."""
    rnd = np.random.default_rng(200 + seed)
    w = (300, 420)[seed % 2]
    _check(_wide(rnd, (70, 110)[seed % 2], w, 10), (10, w), "wide seed %d" % seed)

""""area"'s rows by groups where a row holds many parts for its columns
(csrc/src/coverage/coverage_area.c, rast__cov_row_groups): the parts are
sorted by their first column in one counting pass (rast__grp_count) when
they are at least one in RAST__GRP_COUNT (3) of the clip's columns, with
the counts in the sweep's room (two counts a polygon edge: the pass is
taken only when the columns fit); a part joins a group by its column
against the group's greatest, clamped to the clip (rast__grp_col_le: both
left of it, or both at or right of its right end, join); and a group's
windings come from its parts' ends (a part that starts at the row's top
adds its direction; one that starts or ends inside the row makes the group
not full).  Against the exact oracle of tests/oracle_nonzero.py (checked
against tests/oracle_coverage.py in tests/test_coverage_few_live.py),
within the bound of rastrum.h, uint8 and uint16.

Rows here: dozens of triangles across a narrow strip, many of them
reaching past the clip on both sides (parts whose columns clamp to one
key, in no order among them), and a zigzag ring and its mirror, all of
whose edges cross the one row, on a canvas of 2n - 1 to 3n - 1 columns for
n edges: the counts would not fit the room there (the pass must not be
taken)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle_nonzero import nonzero_area
from test_coverage import check_area

Q = 256  # the vertices on the 1/256 px grid (S = 8): exact as given


def _check(rings, shape, what):
    a = nonzero_area(rings, shape)
    n = sum(len(r) for r in rings)
    m = n * (n - 1) // 2
    for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
        out = rastrum.polygon_coverage(rings, shape, rule="nonzero", dtype=dtype, method="area")
        check_area(out, a, M, n, m, "%s %s" % (what, np.dtype(dtype).name))


def _strip(rnd, ntri, w, h, out):
    """ntri triangles each from above the strip to below it, across it by
    up to 3 px, a vertex inside it one time in two; a share of them
    (`out`) from 1 to 6 px past the left or the right end of the clip."""
    rings = []
    for _ in range(ntri):
        if rnd.random() < out:
            x = rnd.uniform(-6, -0.5) if rnd.random() < 0.5 else rnd.uniform(w + 0.5, w + 6)
        else:
            x = rnd.uniform(0, w)
        mid = rnd.uniform(0.2, h - 0.2) if rnd.random() < 0.5 else h + 1.0
        pts = [(x, -1.0), (x + rnd.uniform(-3, 3), h + 1.0), (x + rnd.uniform(-3, 3), mid)]
        pts = [(round(px * Q) / Q, round(py * Q) / Q) for px, py in pts]
        rings.append(pts if rnd.random() < 0.5 else pts[::-1])
    return rings


@pytest.mark.parametrize("seed", range(4))
def test_dense_strip(seed):
    """60 to 90 triangles across a strip 24 or 40 px wide: every row holds
    more than 48 parts (the counting pass), a third of them past the clip."""
    rnd = np.random.default_rng(seed)
    w = (24, 40)[seed % 2]
    rings = _strip(rnd, 60 + 10 * seed, w, 3, 1 / 3)
    _check(rings, (3, w), "strip seed %d" % seed)


@settings(max_examples=12, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(50, 80), st.sampled_from([16, 30, 48]),
       st.sampled_from([0.0, 0.2, 0.6]))
def test_dense_strip_random(seed, ntri, w, out):
    rnd = np.random.default_rng(seed)
    _check(_strip(rnd, ntri, w, 2, out), (2, w), "random strip %d %d %d %.1f" % (seed, ntri, w, out))


def _zigzag(n, w, shift):
    """A ring of n edges, each across row 0 (y from -1/2 to 3/2), its
    vertices spread over x in [-2, w + 2], moved by `shift`."""
    xs = np.linspace(-2, w + 2, n)
    return [(round((float(x) + shift) * Q) / Q, -0.5 if k % 2 == 0 else 1.5) for k, x in enumerate(xs)]


@pytest.mark.parametrize("n, w", [(30, 119), (30, 150), (30, 179), (24, 100), (40, 230)])
def test_counts_past_the_room(n, w):
    """Two zigzag rings of n edges each (2n edges: room for 4n counts), one
    reversed and moved by 0.7 px, so that they cross inside row 0, on a
    canvas of w columns, between 4n - 1 and 6n - 1 (keys 0 to w + 1: the
    pass's condition, 3 (2n) >= w + 1, holds): its w + 2 counts would
    overrun the room."""
    a = _zigzag(n, w, 0.0)
    b = _zigzag(n, w, 0.7)[::-1]
    _check([a, b], (1, w), "zigzag n=%d w=%d" % (n, w))

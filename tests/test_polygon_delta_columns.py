"""The winding-delta walk's shortcuts for edges that need no DDA.

When the "aet" fill adds each edge's winding deltas as it sets the edge
up (csrc/src/fillers/aet.c, rast__delta_now_walk: many small rings on
few rows), an edge whose two ends count at one column is added at that
column on every row it crosses, with no DDA, and one that crosses a single
row takes only its first column.  The scenes here are made of such edges:
thin rings whose vertices lie within a pixel column, on its sample column
(which counts there), a subpixel past it (which counts at the next), on
and between sample rows; edges from one column to the next crossing one
row or several; rings cut by the canvas' four sides (rows cut to the
clip, columns counted at its first column or past its last); non-zero
past 511 vertices (the rows' crossings counted).  Checked bit for bit
against the exact oracle (tests/oracle.py), in polygon_mask (the counters
in the mask itself) and on a gray8 Canvas (a buffer of their own), under
both rules, both samples and both roundings.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from strategies import RULES, examples
from test_polygon_delta import OFFSETS
from test_polygon_delta_bytes import check_canvas
from test_polygon_exact import check_equal


@st.composite
def column_rings(draw, S, o, rings=(12, 30)):
    """Rings of vertices whose abscissas are a sample column i + o, or a
    step either side of it, tall (several rows) or short (one), some
    wider (one column to the next), some past the canvas' sides."""
    h = draw(st.integers(1, 6), label="height")
    w = draw(st.integers(3, 40), label="width")
    step = 1 / (1 << min(S, 3))  # on sample points, and a subpixel either side

    def near(c):  # c, or a step or two either side of it
        return c + draw(st.integers(-2, 2)) * step

    out = []
    for _ in range(draw(st.integers(*rings), label="rings")):
        col = draw(st.integers(-2, w + 1)) + o
        cy = draw(st.integers(-2 * 4, (h + 2) * 4)) / 4 + o
        tall = draw(st.integers(0, 4)) * 0.75 + step
        wide = draw(st.sampled_from([0, 0, 1, 2]))  # columns the ring may span
        ring = []
        for _ in range(draw(st.integers(3, 6))):
            x = near(col + draw(st.integers(0, wide)))
            y = cy + draw(st.sampled_from([-1, 1])) * draw(st.integers(0, 4)) * tall / 4
            ring.append((x, near(y)))
        if draw(st.booleans()):
            ring.reverse()  # a hole where it overlaps another ring
        out.append(ring)
    return out, (h, w)


@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(20), deadline=None)
@given(data=st.data())
def test_column_edges_match_oracle(o, data):
    """polygon_mask (any rounding), or a gray8 Canvas (exact)."""
    S, rule, rounding = (data.draw(st.sampled_from(v), label=k)
                         for k, v in (("S", [0, 2, 8]), ("rule", RULES), ("rounding", ["exact", "textbook"])))
    rings, shape = data.draw(column_rings(S, o), label="scene")
    if rounding == "exact" and data.draw(st.booleans(), label="canvas"):
        check_canvas(rings, shape, rule=rule, subpixel_bits=S, sample_offset=o)
    else:
        check_equal(rings, shape, algorithms="aet", rule=rule, subpixel_bits=S, sample_offset=o,
                    rounding=rounding)


@pytest.mark.parametrize("seed", range(3))
def test_column_edges_nonzero_past_511_vertices(seed):
    """Over 511 vertices: the non-zero fill counts the rows' crossings as
    the edges go (at most 510 a row, else another way); the column edges
    count there too.  (Seeded: a scene this size is too large a draw for
    hypothesis.)"""
    rng = np.random.default_rng(seed)
    rings = []
    for _ in range(140):
        x = rng.integers(-1, 30) + 0.5
        y = rng.integers(-4, 28) / 4
        ring = [(x + rng.integers(-2, 3) / 256 + rng.integers(0, 2) * rng.integers(0, 2),
                 y + rng.integers(-8, 9) / 4 + rng.integers(-2, 3) / 256) for _ in range(4)]
        rings.append(ring if rng.integers(2) else ring[::-1])
    assert sum(map(len, rings)) > 511
    check_equal(rings, (6, 28), algorithms="aet", rule="nonzero", subpixel_bits=8)


@pytest.mark.parametrize("rule", RULES)
def test_one_column_on_its_sample_and_past_it(rule):
    """Slivers with both ends on the sample column x = i + 1/2 (counted at
    column i: the pixel is inside from there) and a 1/256 past it (counted
    at i + 1), down one row and several, each beside its mirror image."""
    e = 1 / 256
    rings = []
    for k in range(10):
        x = 1.5 + 2 * k
        for dx in (0.0, e):
            rings.append([(x + dx, 0.2), (x + dx, 2.9 + k % 3), (x + 1 + dx, 2.9 + k % 3), (x + 1 + dx, 0.2)])
            rings.append([(x - dx, 0.7), (x + 0.5 - dx, 1.4), (x + 1 - dx, 0.7)])
    for o in OFFSETS:
        check_equal(rings, (5, 24), algorithms="aet", rule=rule, subpixel_bits=8, sample_offset=o)

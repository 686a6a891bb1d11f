"""Many small rings on few rows: the AET filler's winding-delta way.

The "aet" polygon fill takes the winding deltas summed along each row
(csrc/src/fillers/aet.c) when a polygon has many edges for its rows: at
least 8 edges a row on average, the sweep's word tests at most 8 a crossing,
and (non-zero) at most 510 crossings a row.  The scenes here are built to
meet that rule (checked below from the counts the rule reads), so every
example is the delta way, checked bit for bit against the exact oracle
(tests/oracle.py) and against every other algorithm: overlapping rings,
holes (rings turned the other way), vertices on sample points and on sample
rows, collinear vertices, horizontal edges, rings past the canvas' sides,
both rules, both sample offsets, both roundings.  The sweep's own way is
what test_polygon_exact.py's scenes (a few rings on up to 40 rows) take,
and tests/c/test_delta.c compares the two ways directly.
"""

import math

import pytest
from hypothesis import assume, given, settings, strategies as st

from strategies import RULES, examples
from test_polygon_exact import check_equal

OFFSETS = [0.5, 0.0]


def crossing_edges(rings, shape, o):
    """Edges crossing at least one sample row of the canvas (the rule's edge
    count, which counts only those)."""
    n = 0
    for ring in rings:
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            lo, hi = min(y0, y1), max(y0, y1)
            # sample rows j + o with lo <= j + o < hi, 0 <= j < height
            first = max(0, math.ceil(lo - o))
            if first < shape[0] and first + o < hi:
                n += 1
    return n


@st.composite
def many_rings(draw, S, o):
    h = draw(st.integers(1, 5), label="height")
    w = draw(st.integers(4, 48), label="width")
    step = 1 / (1 << min(S, 2))  # on sample points and rows, and between them

    def coord(lo, hi):
        return draw(st.integers(round(lo / step), round(hi / step))) * step

    rings = []
    for _ in range(draw(st.integers(12, 30), label="rings")):
        cx, cy = coord(-2, w + 2), coord(-1, h + 1)
        ring = [(cx + coord(-3, 3), cy + coord(-2, 2))
                for _ in range(draw(st.integers(3, 6)))]
        if draw(st.booleans()):
            ring.reverse()  # a hole where it overlaps another ring
        if len(ring) < 6 and draw(st.booleans()):  # a collinear vertex
            (ax, ay), (bx, by) = ring[0], ring[1]
            ring.insert(1, ((ax + bx) / 2, (ay + by) / 2))
        rings.append(ring)
    shape = (h, w)
    # the rule's conditions, from its counts (8 edges a row; one band and
    # at most 7 words a row against as many crossings as edges; under 512
    # edges)
    assume(crossing_edges(rings, shape, o) >= 8 * h)
    return rings, shape


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(15), deadline=None)
@given(data=st.data())
def test_many_small_rings_match_oracle(rule, o, data):
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    rings, shape = data.draw(many_rings(S, o), label="scene")
    rounding = data.draw(st.sampled_from(["exact", "textbook"]), label="rounding")
    check_equal(rings, shape, rule=rule, subpixel_bits=S, sample_offset=o,
                rounding=rounding)


@pytest.mark.parametrize("rule", RULES)
def test_rings_stacked_on_one_row(rule):
    """Forty triangles overlapping on one row, half of them turned the other
    way, all on sample points: windings from -20 to 20 on the row."""
    rings = []
    for k in range(40):
        tri = [(k * 0.5, 0.5), (k * 0.5 + 6, 0.5), (k * 0.5 + 3, 1.5)]
        rings.append(tri if k % 2 else tri[::-1])
    assert crossing_edges(rings, (2, 30), 0.5) >= 8 * 2
    check_equal(rings, (2, 30), rule=rule, subpixel_bits=4, sample_offset=0.5)

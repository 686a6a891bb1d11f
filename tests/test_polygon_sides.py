"""The AET filler's way for one ring that every row crosses twice
(csrc/src/fillers/aet.c, rast__aet_sides): a ring of at most 16 vertices
whose vertices' rows, taken round it, go down once and up once (a
y-monotone ring, every convex one among them) is filled by walking its
two sides, each row's run between their two crossings.  Against the exact
oracle (tests/oracle.py), bit for bit, on a gray8 canvas (the runs written
into the rows), an RGB one (through the sink) and in polygon_mask (the
opaque painter): rings down one side and up the other with plateaus at
the top, the bottom and on the way, sides that cross each other (a
twisted ring: under either rule the run between the two crossings),
vertices that zigzag between two sample rows (rows still down once and
up once) or across one (not such a ring: the other way fills it), every
vertex in turn as the ring's first, both directions, rings cut by the
canvas' four sides, 3 to 17 vertices (17 keeps the AET).
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from strategies import RULES, examples
from test_polygon_few import _check_canvas


@st.composite
def monotone_rings(draw, S, o, shape):
    """A ring down one side and up the other (ys non-decreasing along each
    side: plateaus), on the 1/2^S grid, reaching past the canvas."""
    h, w = shape
    q = 1 << min(S, 4)
    n = draw(st.integers(3, 17), label="vertices")
    k = draw(st.integers(1, n - 2), label="left side's inner vertices")
    y = st.integers((-3) * q, (h + 3) * q)
    x = st.integers((-3) * q, (w + 3) * q)
    ys = sorted(draw(st.lists(y, min_size=n, max_size=n)))
    top, bottom, inner = ys[0], ys[-1], ys[1:-1]
    order = draw(st.permutations(range(n - 2)))
    left = sorted(inner[i] for i in order[:k])
    right = sorted((inner[i] for i in order[k:]), reverse=True)
    if draw(st.booleans(), label="flat top"):
        top = left[0] if left else top
    path = [top] + left + [bottom] + right
    ring = [(draw(x) / q + o * 0, yv / q) for yv in path]
    if draw(st.booleans(), label="zigzag within a row"):
        # a vertex nudged up by less than its row's share on the left side:
        # its row unchanged when it stays between the same sample rows
        i = draw(st.integers(1, len(ring) - 1))
        ring[i] = (ring[i][0], ring[i][1] - draw(st.integers(0, 2)) / (1 << S))
    start = draw(st.integers(0, len(ring) - 1), label="first vertex")
    ring = ring[start:] + ring[:start]
    if draw(st.booleans(), label="reversed"):
        ring = ring[::-1]
    return np.asarray(ring, np.float64)


@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(60), deadline=None)
@given(data=st.data())
def test_monotone_rings(rule, data):
    S = data.draw(st.sampled_from([0, 2, 4, 8]), label="S")
    o = data.draw(st.sampled_from([0.5, 0.0]), label="offset")
    shape = data.draw(st.tuples(st.integers(1, 20), st.integers(1, 24)), label="shape")
    ring = data.draw(monotone_rings(S, o, shape), label="ring")
    _check_canvas([ring], shape, rule, S, o)


@pytest.mark.parametrize("rule", RULES)
@pytest.mark.parametrize("o", [0.5, 0.0])
def test_shapes_by_hand(rule, o):
    """Convex rings of every start, a twisted quadrilateral (its sides
    cross), plateaus, a zigzag inside a row gap and one across a sample
    row, a ring on one row, each cut by each side of the canvas."""
    hexagon = [(2.2, 0.3), (9.1, 0.8), (13.4, 3.2), (10.2, 6.6), (3.3, 6.1), (0.6, 3.4)]
    bowtie = [(1.0, 0.4), (11.0, 0.4), (1.5, 6.6), (11.5, 6.6)]  # down, across, up
    plateaus = [(1.0, 1.0), (5.0, 1.0), (7.0, 2.5), (9.0, 2.5), (10.0, 6.2), (4.0, 6.2), (0.5, 4.0),
                (0.5, 3.0), (2.0, 2.5)]
    zig = [(1.0, 0.2), (4.0, 2.6), (5.0, 2.52), (6.0, 2.7), (8.0, 6.0), (2.0, 5.0)]  # within rows 2..3
    across = [(1.0, 0.2), (4.0, 2.6), (5.0, 2.4), (6.0, 2.7), (8.0, 6.0), (2.0, 5.0)]  # 2.4: back over 2.5
    flat = [(1.0, 2.1), (9.0, 2.2), (5.0, 2.4)]
    for base in (hexagon, bowtie, plateaus, zig, across, flat):
        for start in range(len(base)):
            ring = base[start:] + base[:start]
            for dx, dy in ((0, 0), (-5, 0), (5, 0), (0, -3), (0, 3)):
                moved = np.asarray([(x + dx, y + dy) for x, y in ring], np.float64)
                _check_canvas([moved], (7, 12), rule, 8, o)
                _check_canvas([moved[::-1]], (7, 12), rule, 8, o)

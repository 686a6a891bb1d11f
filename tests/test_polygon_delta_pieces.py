"""The winding-delta walk's count of a row's crossings, and its rows and
columns of vertices by shifts.

When the "aet" fill adds each edge's winding deltas as it sets the edge
up (csrc/src/fillers/aet.c, rast__delta_now_walk), its byte counters are
exact under non-zero only while no row has more than 510 crossings
(docs/semantics.md: a pixel is inside when its winding number is not 0;
the counters keep it modulo 2^8).  Past 511 vertices the walk counts each
row's crossings and, past 510 on a row, leaves the fill to the sweep.  It
counts them a piece of a ring at a time: consecutive crossing edges of
one direction cross each row between their ends exactly once.  The scenes
here are k copies of one zigzag ring (six pieces) or of a convex one
(two), the ring starting at each of its vertices in turn (at a peak, a
valley, mid-piece, on the clipped bottom), so that a row has 6k or 2k
crossings and the winding number reaches k: at k = 256 a count that
missed a piece lets the counters wrap to 0 inside.  And rows and columns of vertices as one shift
of a biased 32-bit value: S = 16 with vertices near the input range's
ends (+-2047 px), both samples, both roundings.  Checked bit for bit
against the exact oracle (tests/oracle.py), in polygon_mask (the
counters in the mask itself) and on a gray8 Canvas (a buffer of their
own).
"""

import numpy as np
import pytest

import rastrum

from oracle import oracle_mask
from test_polygon_delta import OFFSETS
from test_polygon_delta_bytes import check_canvas

# A "W" over a bar: y goes down, up, down, up, down, along the bottom, up.
ZIGZAG = [(1.0, 0.3), (4.0, 5.6), (7.0, 1.2), (10.0, 5.4), (13.0, 0.4), (14.5, 7.7), (0.5, 7.7)]
# Two pieces (a row crosses it twice: 256 copies, 512 crossings, a winding
# number of 256; a count that missed either piece would take the deltas).
CONVEX = [(2.0, 0.3), (9.0, 0.8), (13.0, 3.2), (10.0, 6.6), (3.0, 6.1), (0.6, 3.4)]


def rotated(ring, k):
    return ring[k:] + ring[:k]


@pytest.mark.parametrize("copies", [85, 86, 255, 256, 257])
@pytest.mark.parametrize("start", range(7))
@pytest.mark.parametrize("base", ["zigzag", "convex"])
def test_copies_at_the_counters_reach(base, copies, start):
    """k copies of the zigzag (rows of 6k crossings, k = 85: 510, the
    counters' reach, and of 2k; the bottom cut by the canvas) or of the
    convex ring (2k), non-zero (the only rule that counts).  At k = 257
    some copies turned the other way round (a winding number of 1 there:
    no wrap, but the counts are the same)."""
    ring = ZIGZAG if base == "zigzag" else CONVEX
    ring = rotated(ring, start % len(ring))
    rings = [ring] * copies
    if copies == 257:
        rings = [ring] * 129 + [ring[::-1]] * 128
    shape = (7, 16)
    assert sum(map(len, rings)) > 511 or base == "convex"  # (510 vertices: at most 510 crossings)
    exp = oracle_mask(rings, shape, rule="nonzero", subpixel_bits=4)
    assert exp.any()
    got = rastrum.polygon_mask(rings, shape, rule="nonzero", subpixel_bits=4)
    assert np.array_equal(got, exp), np.argwhere(got != exp)[:10].tolist()
    check_canvas(rings, shape, rule="nonzero", subpixel_bits=4)


@pytest.mark.parametrize("shift", [0, 3])
def test_copies_cut_at_the_top(shift):
    """256 copies of the zigzag moved up so that its top pieces start
    above the canvas (their rows cut to the clip's), the last turned
    round at the start (a hole's pieces)."""
    ring = [(x, y - shift) for x, y in ZIGZAG]
    for start in (0, 2, 5):
        rings = [rotated(ring, start)] * 256 + [rotated(ring, start)[::-1]] * (start % 2)
        shape = (5, 16)
        exp = oracle_mask(rings, shape, rule="nonzero", subpixel_bits=4)
        got = rastrum.polygon_mask(rings, shape, rule="nonzero", subpixel_bits=4)
        assert np.array_equal(got, exp), (start, np.argwhere(got != exp)[:10].tolist())
        check_canvas(rings, shape, rule="nonzero", subpixel_bits=4)


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("rounding", ["exact", "textbook"])
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_extreme_coordinates_fine_grid(o, rounding, rule):
    """S = 16: vertices up to +-2047.99 px (2^27 - 1 at 1/2^16 px, the
    input range's ends) in rings reaching into the canvas from far
    outside, with slivers on and a subpixel either side of the sample
    columns and rows (the rows and columns by shifts must floor there
    exactly), many of them, so that the deltas take the fill."""
    far = (2 ** 27 - 1) / 2 ** 16
    e = 2.0 ** -16
    rng = np.random.default_rng(16)
    rings = [[(-far, -far), (far, 3.5 + o), (5.0 + o, far)],
             [(far, -far), (-far, 4.0 + e), (2.0 + o - e, far)],
             [(-far, far), (far, far - e), (6.5, -far)]]
    for _ in range(60):
        x = int(rng.integers(-1, 12)) + o + float(rng.choice([-e, 0.0, e]))
        y = int(rng.integers(-1, 8)) + o + float(rng.choice([-e, 0.0, e]))
        h = float(rng.choice([e, 1.0, 1.0 + e, 2.0]))
        w = float(rng.choice([0.0, e, 1.0]))
        ring = [(x, y), (x + w, y + h), (x + w + e, y + h), (x + e, y)]
        rings.append(ring if rng.integers(2) else ring[::-1])
    shape = (8, 12)
    kw = dict(rule=rule, subpixel_bits=16, sample_offset=o, rounding=rounding)
    exp = oracle_mask(rings, shape, **kw)
    got = rastrum.polygon_mask(rings, shape, **kw)
    assert np.array_equal(got, exp), np.argwhere(got != exp)[:10].tolist()
    if rounding == "exact":
        check_canvas(rings, shape, rule=rule, subpixel_bits=16, sample_offset=o)


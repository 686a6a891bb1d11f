""""accumulate"'s rows' walk on edges that lie in one pixel row (csrc/src/
coverage/coverage_acc.c, rast__acc_by_rows and rast__acc_ones): the edges
whose first and last row is the row are taken apart from those that go on
below it, put without the list of the edges going on, their ends from their
vertices where they lie strictly inside the row (else as rast__acc_ends
makes them: a vertex on the row's top or bottom), and handed back to the
row's list for its readout and the passes at a tie.  Scenes of many small
rings (glyph-sized blobs of 5 to 14 vertices, a pixel or a few across: most
of their edges in one row), vertices on grids of 1/2, 1/4 and 1/256 pixel
(ends on row boundaries among them), some past the canvas's top, left or
right (keys clamped, parts left and right of the clip), in rows of few
parts (cells marked) and of many (read whole, counted per 16 columns);
bars one row high and half a pixel wide (each pixel's level at an exact tie:
the tie passes, which read the row's whole list); against the
accumulation's own definition from the exact oracle (tests/oracle.py
through test_coverage): each ring's exact signed area over each pixel,
summed, the rule applied."""

import math

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage import check_accumulate as _check


def _blobs(rnd, k, shape, snap, margin):
    """k small rings (5 to 14 vertices round a centre, radii 0.4 to 2.5
    pixels), centres up to `margin` pixels past the canvas's top, left and
    right; each turned either way round, snapped to 1/snap pixel."""
    h, w = shape
    rings = []
    while len(rings) < k:
        cx, cy = rnd.uniform(-margin, w + margin), rnd.uniform(-margin, h - 1.0)
        nv = int(rnd.integers(5, 15))
        r = rnd.uniform(0.4, 2.5)
        ring = []
        for t in range(nv):
            a = 2 * math.pi * (t + rnd.uniform(-0.3, 0.3)) / nv
            rr = r * rnd.uniform(0.6, 1.0)
            ring.append((round((cx + rr * math.cos(a)) * snap) / snap, round((cy + rr * math.sin(a)) * snap) / snap))
        ring = [p for i, p in enumerate(ring) if p != ring[i - 1]]
        if len(ring) < 3:
            continue
        area2 = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))
        if area2 == 0:
            continue
        rings.append(ring if rnd.integers(2) else ring[::-1])
    return rings


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([2, 4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_many_blobs_rows_read_whole(seed, snap, rule):
    """40 blobs on a canvas 8 x 60: tens of parts a row (64 and more in
    some: counted per 16 columns), many for the width (read whole)."""
    rnd = np.random.default_rng(seed)
    shape = (8, 60)
    _check(_blobs(rnd, 40, shape, snap, 2.0), shape, rule)


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([2, 4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_few_blobs_cells_marked(seed, snap, rule):
    """3 blobs on a canvas 8 x 150: few parts for the width, each marking
    the cells it touches; one may reach past an edge of the canvas."""
    rnd = np.random.default_rng(seed)
    shape = (8, 150)
    _check(_blobs(rnd, 3, shape, snap, 2.0), shape, rule)


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 40), st.sampled_from(["evenodd", "nonzero"]))
def test_half_pixel_bars_at_ties(seed, nbars, rule):
    """Bars one row high (top and bottom on row boundaries: every edge in
    one row, its ends on the row's top and bottom) and half a pixel wide,
    on a quarter-pixel grid (pixels half covered: each level at an exact
    tie), with blobs on the same rows: the tie passes read every edge of
    the row, those in one row among them."""
    rnd = np.random.default_rng(seed)
    shape = (6, 70)
    rings = _blobs(rnd, int(rnd.integers(0, 30)), shape, 4, 1.0)
    for _ in range(nbars):
        x = int(rnd.integers(-1, 70)) + 0.25 * int(rnd.integers(0, 3))
        y = int(rnd.integers(-1, 6))
        bar = [(x, y), (x + 0.5, y), (x + 0.5, y + 1), (x, y + 1)]
        rings.append(bar if rnd.integers(2) else bar[::-1])
    _check(rings, shape, rule)

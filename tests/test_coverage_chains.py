""""area" on groups whose parts tile a row (coverage_area.c,
rast__fast_chain): a chain of a ring's edges through the row, each slab
between its vertices holding one edge, is tested by one walk of its edges'
windings, not slab by slab; and on tops shared by many edges (a glyph's
vertices on a coarse grid: rast__cov_cancel keeps runs of one top without
coincident edges in their order without the block pass, and cancels the
coincident ones).  Rows of more than 32 edges that are not simple (slivers
narrower than a pixel put two pieces in one column), so that the rows go
group by group: many small many-sided rings on a quarter-pixel grid, apart,
nested with either orientation (windings 2 and 0 inside chains: not fast,
swept), overlapping, and sharing sides.  Against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _glyphs(seed, h, w, count, mode):
    """`count` rings of 6-14 vertices snapped to a quarter pixel (tall
    enough that their sides are chains through whole rows), a sliver
    beside every third; mode "apart", "nested" (a smaller ring inside,
    same or other orientation), "overlap" or "shared" (boxes sharing a
    side, coincident edges of opposite directions)."""
    rnd = np.random.default_rng(seed)
    rings = []
    for k in range(count):
        cx = (rnd.uniform(1, w - 1) if mode == "overlap" else 2.5 * k + 1.25)
        cy = rnd.uniform(h * 0.35, h * 0.65)
        if mode == "shared":
            x0, y0 = round((2.5 * k + 0.25) * 4) / 4, round(rnd.uniform(0, 1) * 4) / 4
            y1 = y0 + round(rnd.uniform(1.5, h - 1) * 4) / 4
            for a, b in ((x0, x0 + 1.0), (x0 + 1.0, x0 + 2.0)):
                r = [(a, y0), (b, y0), (b, y1), (a, y1)]
                rings.append(r if rnd.integers(0, 2) else r[::-1])
            continue
        n = int(rnd.integers(6, 15))
        rx, ry = rnd.uniform(0.6, 1.1), rnd.uniform(1.0, h * 0.45)
        t = 2 * np.pi * np.arange(n) / n + rnd.uniform(0, 0.3)
        ring = np.round(np.stack([cx + rx * np.cos(t), cy + ry * np.sin(t)], 1) * 4) / 4
        if rnd.integers(0, 2):
            ring = ring[::-1]
        rings.append(np.ascontiguousarray(ring))
        if mode == "nested":
            inner = np.round(np.stack([cx + rx * 0.5 * np.cos(t), cy + ry * 0.6 * np.sin(t)], 1) * 4) / 4
            rings.append(np.ascontiguousarray(inner if rnd.integers(0, 2) else inner[::-1]))
        if k % 3 == 0:  # a sliver: its two sides in one column
            sx = cx + 1.1
            rings.append([(sx, 0.25), (sx + 0.2, 0.25), (sx + 0.25, h - 0.25), (sx + 0.05, h - 0.25)])
    return rings


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 5),
       st.sampled_from(["apart", "nested", "overlap", "shared"]),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_chains_through_rows_equal_oracle(seed, h, mode, rule, dtype):
    count = 8
    w = 21
    rl = _glyphs(seed, h, w, count, mode)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m, repr((seed, h, mode)))


def test_chain_of_one_direction_twice_is_swept():
    # two copies of one zig-zag ring, the second shifted by a quarter
    # pixel: between their chains the winding number is 2 under one
    # orientation (not fast: swept) and their sides lie in one column;
    # with 12 slivers the rows hold more than 32 edges
    zig = [(1.0, 0.0), (1.5, 1.25), (1.0, 2.5), (1.5, 3.75), (1.0, 5.0),
           (3.0, 5.0), (3.5, 3.75), (3.0, 2.5), (3.5, 1.25), (3.0, 0.0)]
    shifted = [(x + 0.25, y) for x, y in zig]
    slivers = [[(5.0 + k, 0.25), (5.2 + k, 0.25), (5.25 + k, 4.75), (5.05 + k, 4.75)] for k in range(12)]
    shape = (5, 18)
    for rl in ([zig, shifted] + slivers, [zig, shifted[::-1]] + slivers):
        for rule in ("evenodd", "nonzero"):
            out = rastrum.polygon_coverage(rl, shape, rule=rule)
            n, m = _n_m(rl, 8)
            check_area(out, exact_area(rl, shape, rule, 8), 255, n, m, rule)

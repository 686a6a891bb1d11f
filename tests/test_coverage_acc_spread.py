""""accumulate" on rows of 64 parts or more walked row by row, where the
parts put in one column or two are counted per 16 columns but leave the
row's first and last cell touched as they are, and the cells read are
those from the first counted 16 columns to the last's and the cell after
(csrc/src/coverage/coverage_acc.c, rast__acc_spread), against the exact
oracle: the rule applied to the integral of the winding number over each
pixel.

The scene: many small triangles and thin quadrilaterals, a row or two
tall (short edges: the row walk), their columns drawn near the verticals
between one 16 columns and the next (a part in the last column of one,
whose cell after is the first of the next), in the first and the last
columns of the clip, and rings that reach past its left side (whose parts
add to the first cell, counted nowhere) and past its right side; on a
narrow clip (every cell read) and on one wider than 16 columns a part
(only the cells marked read)."""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import check_area, exact_area, rule_applied


def _area2(ring):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))


def _integral(rings, shape, rule):
    """The rule applied to each pixel's integral of the winding number: the
    sum of the rings' own (each simple: winding 1 or -1 inside), signed by
    their orientations."""
    total = np.zeros(shape, object)
    total[...] = F(0)
    for ring in rings:
        if not _area2(ring):
            continue
        # (over the columns it reaches only, moved left by a whole number
        # of pixels: the same values)
        c0 = max(0, int(np.floor(min(x for x, _ in ring))))
        c1 = min(shape[1], int(np.floor(max(x for x, _ in ring))) + 1)
        if c0 >= c1:
            continue
        part = exact_area([[(x - c0, y) for x, y in ring]], (shape[0], c1 - c0), "nonzero", 8)
        total[:, c0:c1] = total[:, c0:c1] + part * (1 if _area2(ring) > 0 else -1)
    return rule_applied(total, rule)


def _shapes(rnd, w, h, snap, count):
    """count small rings, each near a multiple of 16 columns (or a side of
    the clip), a row or two tall; both orientations."""
    rings = []
    for k in range(count):
        kind = rnd.integers(0, 4)
        if kind == 0:  # at a vertical between two 16 columns
            x = 16 * rnd.integers(1, max(2, w // 16 + 1)) + rnd.uniform(-1.5, 1.5)
        elif kind == 1:  # at the left side, or past it
            x = rnd.uniform(-3.0, 1.5)
        elif kind == 2:  # at the right side, or past it
            x = w + rnd.uniform(-2.0, 2.0)
        else:
            x = rnd.uniform(0.0, w)
        y = rnd.uniform(0.0, h - 1.0)
        dx, dy = rnd.uniform(0.05, 1.6), rnd.uniform(0.3, 1.0)
        if rnd.integers(0, 2):
            ring = [(x, y), (x + dx, y + dy), (x - 0.5 * dx, y + dy)]
        else:  # a thin quadrilateral, sloped: one vertical crossed or none
            ring = [(x, y), (x + 0.2, y), (x + dx, y + dy), (x + dx - 0.2, y + dy)]
        ring = [(round(a * snap) / snap, round(b * snap) / snap) for a, b in ring]
        rings.append(ring[::-1] if k % 3 == 0 else ring)
    return rings


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([(2, 40), (2, 1200)]), st.sampled_from([4, 256]),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([np.uint8, np.uint16]))
def test_rows_of_many_counted_parts_read_where_they_are(seed, shape, snap, rule, dtype):
    rnd = np.random.default_rng(seed)
    h, w = shape
    rings = _shapes(rnd, w, h, snap, 100)  # (over 64 parts a row: counted)
    n = sum(len(r) for r in rings)
    m = 255 if dtype == np.uint8 else 65535
    want = _integral(rings, shape, rule)
    out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
    check_area(out, want, m, n, n * (n - 1) // 2, "seed %d, shape %s, snap %d, %s" % (seed, shape, snap, rule))


def test_a_part_in_the_last_column_of_16_touches_the_next_16():
    """Rows of 82 parts or more, all in columns 15 and 47 (the last of
    their 16 columns, counted there) but one ring's, in 32 .. 33: the cells
    after 15 and 47 (16 and 48) are read though no part is counted in their
    16 columns; so is what lies left of the clip."""
    rings = []
    for k in range(40):
        x = 15.25 if k % 2 else 47.25
        y = 0.125 + 0.0625 * (k % 4)
        tri = [(x, y), (x + 0.5, y + 1.5), (x + 0.125, y + 2.5)]
        rings.append(tri if k % 4 < 2 else tri[::-1])
    rings.append([(-4.0, 0.5), (32.5, 0.5), (33.25, 2.75), (-4.0, 2.75)])
    shape = (4, 64)
    n = sum(len(r) for r in rings)
    for rule in ("nonzero", "evenodd"):
        want = _integral(rings, shape, rule)
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=np.uint8)
        check_area(out, want, 255, n, n * (n - 1) // 2, rule)
        assert out[1, 16] == out[1, 17] and out[1, 48] == 0 and out[1, 0] == 255

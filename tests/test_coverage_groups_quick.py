""""area" on rows whose groups all pass the fast tests (coverage_area.c,
rast__cov_row_groups): such a row is added the quick way (in builds for
speed, the accumulation's 64-bit cells, rast__cov_acc_area_parts; where
those refuse it, or built for size, this file's quick cells, rast__q_piece),
and again the exact way only where a level is not certain;
a row with a group to sweep is added the exact way throughout.  Rows of more
than 32 edges, where the simple rows of the accumulation do not apply
(three short edges of a flattened curve in one column): many small
many-sided rings side by side, apart or overlapping; rings sharing sides
(coincident edges, which cancel); triangles whose edges cross on pixel
corners.  Against the exact oracle of tests/oracle_coverage.py within the
bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _blobs(seed, h, w, count, overlap):
    """`count` small rings of 8-12 vertices (flattened curves: several
    short edges to a pixel column) along a strip h rows tall, either
    orientation; apart (centres 2 px apart) or overlapping."""
    rnd = np.random.default_rng(seed)
    rings = []
    for k in range(count):
        cx = (rnd.uniform(0, w - 2) if overlap else 2.0 * k + 1.0) + rnd.uniform(-0.1, 0.1)
        cy = rnd.uniform(0.45, h - 0.45)
        n = int(rnd.integers(8, 13))
        r = rnd.uniform(0.3, 0.45 if h == 1 else 0.8) * (2 if overlap else 1)
        t = rnd.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(n) / n
        ring = np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], 1)
        if rnd.integers(0, 2):
            ring = ring[::-1]
        rings.append(np.ascontiguousarray(ring))
    return rings


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 2), st.sampled_from([5, 6]),
       st.booleans(), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_many_small_curved_rings_equal_oracle(seed, h, count, overlap, rule, dtype):
    w = 2 * count + 1
    rl = _blobs(seed, h, w, count, overlap)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m,
               repr((seed, h, count, overlap)))


@settings(max_examples=S_.examples(5), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]))
def test_shared_sides_and_corner_crossings_equal_oracle(seed, rule):
    # boxes side by side sharing their vertical sides (coincident edges of
    # opposite directions, cancelled), with a few of them doubled (the same
    # direction: not cancelled, winding 2), and triangles with vertices on
    # pixel corners whose edges cross on pixel corners
    rnd = np.random.default_rng(seed)
    h, w = 3, 40
    rl = []
    for k in range(12):
        y0 = rnd.choice([0.25, 0.5, 1.0])
        y1 = y0 + rnd.choice([0.75, 1.5, 2.0])
        box = [(1.0 + 1.5 * k, y0), (2.5 + 1.5 * k, y0), (2.5 + 1.5 * k, y1), (1.0 + 1.5 * k, y1)]
        rl.append(box if rnd.integers(0, 2) else box[::-1])
        if rnd.integers(0, 4) == 0:
            rl.append(box)
    for k in range(int(rnd.integers(0, 4))):
        x = float(rnd.integers(0, w - 4))
        # (x, 0)-(x + 2, 2) and (x + 2, 0)-(x, 2) cross at the corner (x + 1, 1)
        rl.append([(x, 0.0), (x + 2, 2.0), (x + 2, 0.0)])
        rl.append([(x + 2, 0.0), (x, 2.0), (x, 0.0)][::1 if rnd.integers(0, 2) else -1])
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), 255, n, m, repr(seed))

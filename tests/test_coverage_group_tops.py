""""area" on rows of many small overlapping triangles (coverage_area.c,
rast__cov_row_area with qtops): a group that is swept alone starts with
each edge's exact abscissa at the row's top taken from its part's quick
start (2^-30 pixel and a remainder over dy, rast__fast_range), not by a
128-bit division.  Piles of small triangles (most of a row's edges in swept
groups, vertices inside the rows, tops reached from rows that were not
swept), as a triangle batch and as rings, some past the canvas's left and
top (negative abscissae), vertices on grids of 1/256 and 1/3 pixel (the
snapped slopes leave remainders), against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h.  Small canvases:
the oracle is exact rational arithmetic."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _pile(seed, h, w, count, grid):
    """`count` triangles 0.6 to 4 px across, centred anywhere on a strip
    h x w and a pixel past its left and top, on a grid of 1/grid px."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform([-1.0, -1.0], [w, h], (count, 1, 2))
    r = rnd.uniform(0.3, 2.0, (count, 1, 1))
    t = rnd.uniform(0, 2 * np.pi, (count, 3, 1))
    tri = c + r * np.concatenate([np.cos(t), np.sin(t)], 2)
    return np.round(tri * grid) / grid


@settings(max_examples=S_.examples(16), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 3), st.sampled_from([8, 12]),
       st.sampled_from([256, 3]), st.sampled_from([np.uint8, np.uint16]))
def test_piles_of_small_triangles_equal_oracle(seed, h, w, grid, dtype):
    tris = _pile(seed, h, w, w + 2, grid)
    out = rastrum.triangles_coverage(tris, (h, w), dtype=dtype)
    n, m = _n_m(list(tris), 8)
    check_area(out, exact_area(list(tris), (h, w), "nonzero", 8, triangles=True), M_OF[dtype], n, m,
               repr((seed, h, w, grid)))


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 3), st.sampled_from(["nonzero", "evenodd"]))
def test_piles_as_rings_equal_oracle(seed, h, rule):
    w = 10
    rings = [t.tolist()[::-1] if k % 3 == 0 else t.tolist()
             for k, t in enumerate(_pile(seed, h, w, w + 2, 256))]
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule)
    n, m = _n_m(rings, 8)
    check_area(out, exact_area(rings, (h, w), rule, 8), 255, n, m, repr((seed, h, rule)))

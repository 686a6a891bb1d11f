""""area" on grouped rows whose groups all pass the fast tests, in uint8 and
uint16 (coverage_area.c, rast__cov_row_groups): such a row is added by the
accumulation's cells (rast__cov_acc_area_parts, coverage_acc.c), every part
with its direction and the rule applied per pixel, which is the coverage
because each pixel meets one group, whose winding takes 0 and its own s
(+1 or -1: both in one row here).  Text-like rows of more than 32 edges,
where most rows fail the simple-row test (two sides of a stroke in one
column) and are not tried again but every fourth; and a wide canvas whose
rows hold many edges in a few columns, where the groups' sort (a counting
pass by the key's top bits, then an insertion) runs past its moves and
the radix sort finishes.  Against the exact oracle of
tests/oracle_coverage.py within the bound of rastrum.h (issue 33)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _ring(cx, cy, rx, ry, n, phase, cw):
    t = phase + 2 * np.pi * np.arange(n) / n
    ring = np.stack([cx + rx * np.cos(t), cy + ry * np.sin(t)], 1)
    return np.ascontiguousarray(ring[::-1] if cw else ring)


def _letters(seed, h, count, overlap):
    """`count` "o"s of 18-22 vertices a ring (an outer ring and a hole
    wound the other way: a stroke 0.5-0.8 px wide, both of its sides in
    one column where it runs flat), side by side 3 px apart, each wound
    either way; a few shifted onto the next one when `overlap`."""
    rnd = np.random.default_rng(seed)
    rings = []
    for k in range(count):
        cx = 2.0 + 3.0 * k + rnd.uniform(-0.2, 0.2)
        if overlap and rnd.integers(0, 3) == 0:
            cx += 1.5
        cy = h / 2 + rnd.uniform(-0.3, 0.3)
        rx, ry = rnd.uniform(1.1, 1.4), rnd.uniform(h / 2 - 0.4, h / 2 - 0.2)
        wd = rnd.uniform(0.5, 0.8)
        n = int(rnd.integers(18, 23))
        ph = rnd.uniform(0, 2 * np.pi)
        cw = bool(rnd.integers(0, 2))
        rings.append(_ring(cx, cy, rx, ry, n, ph, cw))
        rings.append(_ring(cx, cy, rx - wd, ry - wd, n, ph + 0.1, not cw))
    return rings


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([3, 4]), st.booleans(),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_text_like_rows_equal_oracle(seed, h, overlap, rule, dtype):
    # two "o"s: some 35-45 edges in the middle rows
    count = 2
    w = 3 * count + 3
    rl = _letters(seed, h, count, overlap)
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m,
               repr((seed, h, overlap)))


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]))
def test_many_edges_in_few_columns_of_a_wide_row_equal_oracle(seed, rule):
    # 1,100 columns: the sort's buckets are 16 columns wide; eight rings of
    # 12 vertices 2 px apart in columns 500-516 put some 50 edges in a row
    # into two or three buckets, in the order of their tops
    rnd = np.random.default_rng(seed)
    h, w = 2, 1100
    rl = []
    for k in range(8):
        cx = 501.0 + 2.0 * k + rnd.uniform(-0.05, 0.05)
        rl.append(_ring(cx, 1.0 + rnd.uniform(-0.1, 0.1), 0.45, 0.9, 12, rnd.uniform(0, 2 * np.pi),
                        bool(rnd.integers(0, 2))))
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), 255, n, m, repr(seed))

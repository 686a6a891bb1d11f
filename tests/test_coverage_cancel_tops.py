""""area" where many edges share one top (coverage_area.c, rast__cov_cancel):
each run of one top is put in order by insertion first
(rast__cov_tops_insert) and goes to the Shell sort when it holds coincident
edges or is far from in order; coincident edges of opposite directions
cancel, of one direction stay.  Boxes with one top along a strip, in ring
order left to right (the runs nearly in order), shuffled (far from it), some
sharing sides (coincident, cancelled) or doubled (one direction: winding 2),
the tie-free runs before and after the shared ones.  Against the exact
oracle of tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _boxes(seed, count, shuffle, shared, doubled):
    """`count` boxes 1.5 px wide, their tops at y 0.25 (or 1.25: two tops),
    apart, or every third pair sharing a side when `shared`; a few drawn
    twice when `doubled`; either orientation."""
    rnd = np.random.default_rng(seed)
    rings, x = [], 0.3
    for k in range(count):
        top = 0.25 if k % 4 else 1.25
        bot = top + rnd.choice([1.5, 2.0, 2.75])
        x1 = x + 1.5
        ring = np.array([[x, top], [x1, top], [x1, bot], [x, bot]])
        if rnd.integers(0, 2):
            ring = ring[::-1]
        rings.append(np.ascontiguousarray(ring))
        if doubled and k % 5 == 2:
            rings.append(ring.copy())
        x = x1 if shared and k % 3 == 1 else x1 + 0.5
    if shuffle:
        rings = [rings[i] for i in rnd.permutation(len(rings))]
    return rings, int(np.ceil(x)) + 1


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([9, 24]), st.booleans(), st.booleans(),
       st.booleans(), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_boxes_of_one_top_equal_oracle(seed, count, shuffle, shared, doubled, rule, dtype):
    rl, w = _boxes(seed, count, shuffle, shared, doubled)
    h = 5
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    n, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), M_OF[dtype], n, m,
               repr((seed, count, shuffle, shared, doubled)))

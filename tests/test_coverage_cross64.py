""""area"'s crossing times at the edge of their 64-bit way (issue 33): a
pair of edges whose crossing's numerator has all seven factors in
[-2^20, 2^20) fixed units (the offsets of the tops, the rise and run of
both edges) takes 64-bit products and divisions (coverage_area.c, rast__cov_cross;
rast__shl_div64 in base/wide.h), any other pair the 128-bit way.  Long
slanted quads whose sides rise and run 2^20 units give or take a few (the
tops 2^19 units above the canvas), crossing each other inside it, put pairs
just inside and just outside that bound in the same rows; every level is
checked against the exact oracle of tests/oracle_coverage.py within the
bound of rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area

LIM = 2 ** 20  # the 64-bit way's bound on each factor (-LIM <= v < LIM), in fixed units
NEAR = st.sampled_from([LIM - 2, LIM - 1, LIM, LIM + 1])


def _quad(top, dy, cx, dx, wd, s, flip):
    """A quad from ordinate `top` down `dy` (units of 2^-s px), its left
    side through (cx, top + dy / 2) with run dx, `wd` units wide."""
    u = 2.0 ** -s
    x0 = cx - dx // 2
    r = [(x0 * u, top * u), ((x0 + wd) * u, top * u), ((x0 + dx + wd) * u, (top + dy) * u),
         ((x0 + dx) * u, (top + dy) * u)]
    return r[::-1] if flip else r


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([4, 8]),
       st.lists(st.tuples(NEAR, NEAR, st.booleans(), st.booleans()), min_size=2, max_size=4),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_crossings_at_the_64_bit_bound_equal_oracle(seed, s, sides, rule, dtype):
    rnd = np.random.default_rng(seed)
    h, w = 3, 5
    rings = []
    for dy, run, neg, flip in sides:
        # the top 2^19 units (give or take) above the canvas: |top - Yj|
        # near 2^19, the tops' offsets up to about 2^20 apart
        top = -(dy // 2) + int(rnd.integers(-3, 4)) * 2 ** s
        cx = int(rnd.integers(1, w)) * 2 ** s + int(rnd.integers(-2 ** (s - 1), 2 ** (s - 1)))
        wd = int(rnd.integers(1, 3)) * 2 ** s
        rings.append(_quad(top, dy, cx, -run if neg else run, wd, s, flip))
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, subpixel_bits=s, dtype=dtype)
    n, m = _n_m(rings, s)
    check_area(out, exact_area(rings, (h, w), rule, s), M_OF[dtype], n, m, repr((seed, s, sides)))

""""area"'s quick rows (coverage_area.c, the quick accumulation): the window
round a tie in which a level sends the row to the exact way is the largest
group's parts (the parts meeting one column), and none in a column no part
meets, whose value is exact.  Rows of many small flattened rings (the
groups' way, as in test_coverage_groups_quick.py) beside boxes whose
horizontal sides lie on half pixels: the columns between a box's sides are
half covered, an exact tie (level 128 of 255), met by no part.  Against
the exact oracle of tests/oracle_coverage.py: every pixel within the bound
of rastrum.h, and the ties exactly."""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area
from test_coverage_groups_quick import _blobs


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(0, 3), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_half_covered_runs_beside_groups_equal_oracle(seed, nbox, rule, dtype):
    h, count = 2, 8
    rnd = np.random.default_rng(seed)
    rl = _blobs(seed, h, 2 * count + 1, count, False)
    w = 2 * count + 2 + 7 * nbox
    for b in range(nbox):  # a box 4-6 px wide, sides anywhere on the 1/256 grid, top and bottom on halves
        x0 = 2 * count + 2 + 7 * b + int(rnd.integers(0, 256)) / 256
        x1 = x0 + 4 + int(rnd.integers(0, 512)) / 256
        y0 = 0.5 if rnd.integers(0, 2) else 1.5
        ring = [(x0, y0), (x1, y0), (x1, y0 + 1), (x0, y0 + 1)]
        if rnd.integers(0, 2):
            ring = ring[::-1]
        rl.append(np.array(ring, np.float64))
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, dtype=dtype)
    exact = exact_area(rl, (h, w), rule, 8)
    n, m = _n_m(rl, 8)
    what = repr((seed, nbox, rule))
    check_area(out, exact, M_OF[dtype], n, m, what)
    ties = [(j, i) for (j, i), a in np.ndenumerate(exact) if a == F(1, 2)]
    assert len(ties) >= 3 * nbox, what  # the columns inside each box, in one row or two
    for j, i in ties:
        assert int(out[j, i]) == oc.level(F(1, 2), M_OF[dtype]), (what, j, i)

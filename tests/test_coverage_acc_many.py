""""accumulate" into uint8 on rows of 256 parts or more under the non-zero
rule, where the running sum's winding reaches past 2^7 either way
(csrc/src/coverage/coverage_acc.c: such rows are read the quick way with
the rule applied on 64 bits, rast__acc_sum24's big, and a band's four
rows together with AVX2), against the definition from the exact oracle:
the rule applied to the integral of the winding number over each pixel.

The scene: c1 copies of one triangle and c2 copies of another turned the
other way, overlapping, so that the winding runs from -c2 to c1 along a
row and every pixel where the two meet takes a value in (0, 1) from the
difference of large sums (c1 - c2 in -2..2).  Short triangles go the row
walk, tall ones the band walk; vertices on half pixels put levels on
ties, which go to the exact sweep.  The oracle: the copies' integral is
c1 times one's, less c2 times the other's."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import check_area, exact_area, rule_applied


def _area2(ring):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))


def _triangle(rnd, w, h, snap):
    pts = np.round(rnd.uniform([0.5, 0.5], [w - 0.5, h - 0.5], (3, 2)) * snap) / snap
    return [(float(x), float(y)) for x, y in pts]


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(130, 180), st.integers(-2, 2),
       st.sampled_from([2, 256]), st.sampled_from([(6, 40), (48, 24)]))
def test_rows_of_many_parts_with_a_deep_winding(seed, c1, d, snap, shape):
    rnd = np.random.default_rng(seed)
    h, w = shape
    a, b = _triangle(rnd, w, h, snap), _triangle(rnd, w, h, snap)
    if _area2(a) == 0 or _area2(b) == 0:
        return
    if (_area2(a) > 0) == (_area2(b) > 0):
        b = b[::-1]
    c2 = c1 - d
    ea = exact_area([a], shape, "nonzero", 8) * (1 if _area2(a) > 0 else -1)
    eb = exact_area([b], shape, "nonzero", 8) * (1 if _area2(b) > 0 else -1)
    want = rule_applied(ea * c1 + eb * c2, "nonzero")
    rings = [a] * c1 + [b] * c2
    n = 3 * len(rings)
    out = rastrum.polygon_coverage(rings, shape, rule="nonzero", method="accumulate", dtype=np.uint8)
    check_area(out, want, 255, n, n * (n - 1) // 2, "seed %d, %d - %d copies, shape %s" % (seed, c1, c2, shape))

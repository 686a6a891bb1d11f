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

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
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


def _near_tie(d, hole):
    """A quadrilateral whose pixel (1, 2) is 83/170 covered, a level on a
    tie (124.5 of 255, 31996.5 of 65535), and a right triangle of legs d
    beside it in that pixel, which moves the pixel 255 d^2 / 2 of a level
    past the tie (below it when `hole`: the triangle inside the
    quadrilateral, turning the other way)."""
    quad = [(2, 0), (2.125, 0), (3.08984375, 3.984375), (2, 3.984375)]
    tri = [(2.875, 1.5), (2.875, 1.5 + d), (2.875 + d, 1.5)]
    if hole:
        tri = [(x - 0.625, y) for x, y in tri]
    tri = tri if ((_area2(tri) > 0) == (_area2(quad) > 0)) != hole else tri[::-1]
    return quad, tri


@pytest.mark.parametrize("d, hole", [(2.0 ** -10, False), (2.0 ** -10, True), (2.0 ** -16, False)])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_a_level_near_a_tie_in_a_band_row_of_many_parts(d, hole, rule):
    """The pixel above beside 150 tall thin triangles (300 parts on each
    row, walked a band at a time), none in its 16 columns.  By the window
    of all the row's parts the level is not certain; by the parts that
    touch its 16 columns (5) it is when the triangle moves it 255 d^2 / 2 =
    2^-13.0 of a level (d = 2^-10; 2^-5 of a uint16 level), and the row is
    read out of its cells again, counted (coverage_acc.c, rast__acc_again);
    at 2^-25 (d = 2^-16) it is not, and the row goes to the exact sweep.
    Either way the level is the one past the tie."""
    quad, tri = _near_tie(d, hole)
    tall = [[(x, 0.5), (x + 1.5, 0.5), (x + 0.75, 11.5)] for x in np.arange(20.0, 20.0 + 3 * 150, 3)]
    rings = [quad, tri] + [[(float(x), float(y)) for x, y in t] for t in tall]
    shape = (12, 480)
    exact = exact_area([quad, tri], (4, 16), rule, 16)
    assert exact[1, 2] == F(83, 170) + F(-1 if hole else 1, 1) * F(d) ** 2 / 2
    for dtype, M, want in ((np.uint8, 255, 124 if hole else 125), (np.uint16, 65535, 31996 if hole else 31997)):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype, subpixel_bits=16)
        assert out[1, 2] == want, (dtype.__name__, int(out[1, 2]), want)
        assert (out[:4, :16] == [[oc.level(a, M) for a in r] for r in exact]).all()

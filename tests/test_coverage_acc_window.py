""""accumulate"'s window (csrc/src/coverage/coverage_acc.c, rast__acc_win):
the quick sums are within (n + 1) 2^-29 of the exact integral a of the
winding number over a pixel, n the row's parts (or the most of them in
16 columns), so a pixel whose level floor(a' M + 1/2) is not certain by
that margin sends its row to the exact sweep.  No earlier test made the
quick sums' error large enough to matter: a window 4 times too narrow
(the 24-bit paths' `win >> 27` made `>> 29`, or rast__acc_win's `<< 22`
made `<< 20`) passed them all (issue 34).

The scenes here make it matter.  A steep edge through pixel (J, 2) from
its top row to its bottom one is cut at the pixel's top and bottom lines;
the quick sums floor those two abscissae to the 2^-30 px grid, which
moves the pixel's quick value by the mean of the two floors.  Each edge
below was chosen (tests/test_coverage_acc_window.py's _floors checks it)
with both floors at least 0.97 of 2^-30, so that n1 copies of edge A and
n2 of edge B (every copy the same way round: the errors add) move the
quick value by about n 2^-30, half the bound; the copies' exact value a
(even-odd) is just below a level boundary, by less than that error minus
a quarter of the window.  The return edges lie right of the canvas, the
canvas 40 columns wide (the row's parts counted per 16 columns: the
window is that of the n edges through the pixel).  A window a quarter of
the right one lets the quick value's level through: one level too high.
Short edges (3 rows: the row walk) and long ones (20 rows: the band
walk), uint8 (the 24-bit sums: rast__acc_levels24, rast__acc_quad) and
uint16 (rast__acc_level), n = 400 and 200.  Against the definition from
the exact oracle (tests/oracle_coverage.py): floor(a' M + 1/2), a' the
even-odd rule applied to the sum of the rings' signed areas."""

import math
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import exact_area, rule_applied

W = 40
Q = F(1, 2 ** 30)

# (J, dtype, canvas rows): [(edge A, n1, edge B, n2)], an edge (X0, Y0, X1, Y1)
# in 1/256 px from its top vertex to its bottom one
CASES = {
    (1, np.uint8, 3): [((706, 205, 742, 704), 46, (667, 128, 631, 522), 354),
                       ((608, 211, 587, 633), 161, (648, 56, 688, 743), 239),
                       ((645, 60, 685, 569), 118, (583, 73, 577, 629), 282)],
    (1, np.uint16, 3): [((633, 187, 641, 640), 151, (645, 124, 647, 640), 49),
                        ((633, 187, 641, 640), 23, (614, 32, 636, 575), 177),
                        ((633, 187, 641, 640), 188, (673, 225, 696, 644), 12)],
    (12, np.uint8, 26): [((687, 126, 603, 5456), 293, (577, 165, 540, 5766), 107),
                         ((512, 365, 598, 6005), 330, (789, 529, 695, 5523), 70),
                         ((573, 88, 571, 5558), 68, (780, 625, 683, 5861), 332)],
    (12, np.uint16, 26): [((542, 581, 641, 6139), 197, (708, 294, 699, 5811), 3),
                          ((711, 311, 671, 5506), 192, (512, 213, 564, 5649), 8),
                          ((626, 762, 697, 5745), 119, (663, 244, 781, 5679), 81)],
}


def _ring(e, dx=0, dy=0):
    """The edge, shifted by (dx, dy) px, and back along the right of the canvas."""
    X0, Y0, X1, Y1 = e
    a, b = (X0 / 256 + dx, Y0 / 256 + dy), (X1 / 256 + dx, Y1 / 256 + dy)
    return [a, b, (W + 2.0, b[1]), (W + 2.0, a[1])]


def _floors(e, j):
    """The floors of the edge's abscissae at y = j and j + 1 to the 2^-30 px
    grid, in units of 2^-30 px (exact), and where it is there (px)."""
    X0, Y0, X1, Y1 = e
    out = []
    for t in (256 * j, 256 * (j + 1)):
        x = F(X0) / 256 + F((t - Y0) * (X1 - X0), 256 * (Y1 - Y0))
        out.append((x / Q - math.floor(x / Q), x))
    return out


def _signed(r, shape):
    a2 = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(r, r[1:] + r[:1]))
    return exact_area([r], shape, "nonzero", 8) * (1 if a2 > 0 else -1)


def _check(j, dtype, h, case, dx=0, dy=0):
    A, n1, B, n2 = case
    shape = (h + dy, W)
    M = 255 if dtype == np.uint8 else 65535
    rA, rB = _ring(A, dx, dy), _ring(B, dx, dy)
    want = rule_applied(_signed(rA, shape) * n1 + _signed(rB, shape) * n2, "evenodd")
    out = rastrum.polygon_coverage([rA] * n1 + [rB] * n2, shape, rule="evenodd", method="accumulate", dtype=dtype)
    bad = [(p, int(out[p]), oc.level(a, M)) for p, a in np.ndenumerate(want)
           if int(out[p]) != oc.level(a, M) and (a * M + F(1, 2)).denominator != 1]
    assert not bad, "%s: %d pixel(s) off (pixel, level, exact): %s" % (case, len(bad), bad[:4])
    return want[j + dy, 2 + dx], M


@pytest.mark.parametrize("key", list(CASES), ids=lambda k: "row%d-%s" % (k[0], np.dtype(k[1]).name))
def test_quick_error_near_a_level_boundary(key):
    j, dtype, h = key
    for case in CASES[key]:
        _near_boundary(case, j, dtype, h)


def _near_boundary(case, j, dtype, h, edge_ok=lambda e: True):
    """Check case's pixels (_check) and that the scene is what it claims:
    its two edges' floors in row j near 1 in pixel column 2, and the
    exact value just below a level boundary, by less than the quick sums'
    modelled error."""
    A, n1, B, n2 = case
    err = 0
    for e, k in ((A, n1), (B, n2)):
        assert edge_ok(e), e
        (f0, x0), (f1, x1) = _floors(e, j)
        assert f0 >= F(97, 100) and f1 >= F(97, 100) and 2 <= x0 < 3 and 2 <= x1 < 3
        err += k * (f0 + f1) / 2 * Q
    a, M = _check(j, dtype, h, case)
    x = a * M + F(1, 2)
    assert 0 < math.ceil(x) - x < err * M, case


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.sampled_from(list(CASES)), st.integers(0, 2), st.integers(0, 30),
       st.integers(0, 3))
def test_shifted_by_whole_pixels(key, which, dx, dy):
    """The same scenes moved by whole pixels (the floors do not change): the
    pixel in another column of its 16, or in the next block of 16 columns."""
    j, dtype, h = key
    _check(j, dtype, h, CASES[key][which], dx, dy)


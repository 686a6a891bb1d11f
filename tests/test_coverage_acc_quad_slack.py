""""accumulate"'s band of four uint8 rows read out together
(csrc/src/coverage/coverage_acc.c, rast__acc_quad): the tie window it
gives each row, `(rast__acc_win(cnt, 255) >> 27) + 256` in 2^-24 levels,
is the quick sums' error bound (the `>> 27` part) plus the floor of the
running sum to 24 bits (z = v >> 27: the `+ 256` part, 255 times under
one unit of z).  No test made the second part matter: the quad's `+ 256`
dropped (or halved) passed every earlier test (issue 34).

The scenes here make it matter.  One ring: a steep edge E from the
canvas's top row to its 16th (dy not a power of two: the pixels' areas
are not multiples of 2^-24) and back along the right of the canvas, so
each row has two parts (the quad's window: 23 + 256); the canvas 8
columns wide (every row dense), the edges 15 rows long (the band walk).
Each E was chosen (_claims checks it) so that pixel (9, C)'s exact value
x = a 255 + 1/2 lies just past a level boundary (by under 17 / 2^24),
on the side the 24-bit floor leaves: its positive sum's floor lowers it,
a negative sum's (the ring reversed) raises its magnitude, by more than
that plus the quick part of the window (over 200 / 2^24 past it).  The
right window sends the row to the exact sweep; a window without the
floor's part keeps the floor's level, one off.  Against the exact
oracle (tests/oracle_coverage.py): floor(a' M + 1/2), a' the rule
applied to the ring's signed area, no tie among them (the exact values
are that far from one).

The same rings painted (Canvas.fill_polygon, aa="accumulate", 255 on a
gray8 canvas of 0: the pixel is the level) take no quad: their rows are
read one at a time into the painter's row (rast__acc_row's 24-bit way,
rast__acc_levels24), whose window has the same `+ 256`; dropped there,
each ring's pixel is one level off the same way.  (The return side 40
columns right of the canvas: a pixel box past the small path's 24.)"""

import math
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import rule_applied
from test_coverage_acc_window import _signed

W, H, J = 8, 16, 9
T = 1 << 24

# (edge E (X0, Y0, X1, Y1) in 1/256 px, top vertex first, column C of the
# pixel (J, C), reversed): reversed = False: the ring's sums are positive
# there, the exact value just above a boundary; True: negative, just below
CASES = [
    ((1347, 0, 1068, 3947), 4, False),
    ((1411, 0, 624, 3883), 3, False),
    ((1515, 0, 977, 3907), 4, False),
    ((1461, 0, 1423, 3869), 5, False),
    ((957, 0, 1236, 3947), 4, True),
    ((637, 0, 1424, 3883), 4, True),
]


def _ring(e, rev, dx=0, dy=0, back=W + 2.0):
    """E shifted by (dx, dy) px and back along the right of the canvas (at
    x = back)."""
    X0, Y0, X1, Y1 = e
    a, b = (X0 / 256 + dx, Y0 / 256 + dy), (X1 / 256 + dx, Y1 / 256 + dy)
    r = [a, b, (back, b[1]), (back, a[1])]
    return r[::-1] if rev else r


def _claims(e, c, rev):
    """The pixel's exact area a (from E's abscissae at its row lines), and
    the scene as claimed: x = a 255 + 1/2 past a boundary by d, the
    24-bit floor moving x the other way by more than d + 24 / 2^24."""
    X0, Y0, X1, Y1 = e
    xt, xb = (F(X0, 256) + F((256 * y - Y0) * (X1 - X0), 256 * (Y1 - Y0)) for y in (J, J + 1))
    assert math.floor(xt) == math.floor(xb) == c
    a = c + 1 - (xt + xb) / 2
    x = a * 255 + F(1, 2)
    f = a * T - math.floor(a * T)  # the floor's loss, in units of z (of a positive sum)
    if rev:  # (a negative sum floored: its magnitude up by 1 - f)
        d, move = math.ceil(x) - x, 1 - f
    else:
        d, move = x - math.floor(x), f
    assert 0 < d * T < 17 and move * 255 - d * T > 200, (e, float(d * T), float(move))
    return a


def _off(out, want, what):
    """out's pixels against the exact levels of want: none off."""
    bad = [(p, int(out[p]), oc.level(a, 255)) for p, a in np.ndenumerate(want) if int(out[p]) != oc.level(a, 255)]
    assert not bad, "%s: %d pixel(s) off (pixel, level, exact): %s" % (what, len(bad), bad[:4])


def _check(e, c, rev, rule, dx=0, dy=0, h=H):
    shape = (h, W)
    r = _ring(e, rev, dx, dy)
    want = rule_applied(_signed(r, shape), rule)
    out = rastrum.polygon_coverage([r], shape, rule=rule, method="accumulate", dtype=np.uint8)
    _off(out, want, "%s %s" % (S_.lit([r]), rule))
    return want


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("case", CASES, ids=lambda k: "%s-col%d%s" % ("_".join(map(str, k[0])), k[1],
                                                                       "-rev" if k[2] else ""))
def test_floor_near_a_level_boundary(case, rule):
    e, c, rev = case
    a = _claims(e, c, rev)
    want = _check(e, c, rev, rule)
    assert want[J, c] == a  # (the oracle's value is the one claimed)


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.sampled_from(CASES), st.sampled_from(["nonzero", "evenodd"]), st.integers(-4, 3), st.integers(-8, 8))
def test_shifted_by_whole_pixels(case, rule, dx, dy):
    """The same scenes moved by whole pixels (the fractions do not change):
    the pixel in another column, its row in another band or at another
    row of one, the edges cut at the canvas's top."""
    e, c, rev = case
    _check(e, c, rev, rule, dx, dy, h=24)


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("case", CASES, ids=lambda k: "%s-col%d%s" % ("_".join(map(str, k[0])), k[1],
                                                                       "-rev" if k[2] else ""))
def test_painted_rows(case, rule):
    e, c, rev = case
    r = _ring(e, rev, back=W + 40.0)
    want = rule_applied(_signed(r, (H, W)), rule)
    canvas = rastrum.Canvas.wrap(np.zeros((H, W), np.uint8))
    canvas.fill_polygon(np.asarray(r), 255, rule=rule, aa="accumulate")
    _off(canvas.array, want, "%s %s painted" % (S_.lit([r]), rule))

""""accumulate"'s rows that the tie pass of a row of many parts cannot
decide (csrc/src/coverage/coverage_acc.c, rast__acc_ties_z, then
rast__acc_exact_cols): such a row is added again the exact way over the
span of the columns left undecided only, with the edges that meet those
columns, those wholly left of them given as the cover they carry, those
wholly right left out; the row's other pixels keep the levels the quick
passes gave them.  Scenes: one row of 64 parts or more (diamonds in one
pixel row: counted per 16 columns, the uint8 tie pass that keeps the
row's sums), a wide ring round the middle of the row whose slanted left
side lies wholly left of the undecided columns (its cover carried), and
holes (or, for even-odd, overlaps) whose slanted side crosses a pixel's
centre at a slope of 1/3 or 1/5: that pixel is covered exactly 1/2 (a tie)
by parts whose column crossings (1/3, 2/3 of the row; 2/5, 3/5) are not on
the 2^-30 grid, so no quick window decides it.  Against the accumulation's
own definition from the exact oracle (test_coverage._accumulated), uint8
and uint16 (which takes the whole row the exact way), both rules."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage import check_accumulate as _check


def _diamond(cx, cy, rx, ry):
    return [(cx - rx, cy), (cx, cy - ry), (cx + rx, cy), (cx, cy + ry)]


def _tie(c, q, up):
    """A triangle in pixel row 1 whose slanted side (slope 1/q, rising or
    falling) crosses the centre of pixel (c, 1): the triangle covers that
    pixel exactly 1/2."""
    h = q // 2  # the side runs from column c - h to c + 1 + h
    if up:
        return [(c - h, 1), (c + 1 + h, 2), (c - h, 2)]
    return [(c - h, 2), (c + 1 + h, 1), (c + 1 + h, 2)]


def _scene(rnd, width, nties, rule):
    rings = []
    ccw = bool(rnd.integers(2))
    # 34 to 40 diamonds in row 1, left of the wide ring (144 parts and more)
    nd = int(rnd.integers(34, 41))
    for i in range(nd):
        d = _diamond(2 + 1.6 * i + rnd.integers(0, 64) / 256, 1.5, 0.6, 0.45)
        rings.append(d if rnd.integers(2) else d[::-1])
    # the wide ring round the middle: its left side slanted, past the
    # right of the canvas sometimes
    x0 = 66 + rnd.integers(0, 256) / 64
    x1 = width - 5 + int(rnd.integers(0, 12))
    wide = [(x0 + 3, 0.25), (x1, 0.25), (x1 + 2, 2.75), (x0, 2.75)]
    rings.append(wide if ccw else wide[::-1])
    cols = sorted(rnd.choice(np.arange(78, width - 12, 7), size=nties, replace=False))
    for c in cols:
        t = _tie(int(c), int(rnd.choice([3, 5])), bool(rnd.integers(2)))
        if rule == "nonzero":
            # a hole in the wide ring: winding 1 - 1/2
            rings.append(t[::-1] if _area2(t) * _area2(wide if ccw else wide[::-1]) > 0 else t)
        else:
            # an overlap: 1 + 1/2, folded to 1/2
            rings.append(t if rnd.integers(2) else t[::-1])
    # a few diamonds right of the ties too
    for i in range(int(rnd.integers(0, 6))):
        d = _diamond(width - 3.5 + 1.2 * i, 1.5, 0.5, 0.4)
        rings.append(d if rnd.integers(2) else d[::-1])
    return rings


def _area2(r):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(r, r[1:] + r[:1]))


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 4), st.sampled_from(["evenodd", "nonzero"]))
def test_ties_left_undecided_exact_cols(seed, nties, rule):
    """One to four pixels at exact ties spread along a row of 150 parts
    and more, inside a wide ring: the undecided span from the first to the
    last of them, the wide ring's left side and the diamonds left of it
    carried, the diamonds right of it left out."""
    rnd = np.random.default_rng(seed)
    shape = (3, 150)
    _check(_scene(rnd, 150, nties, rule), shape, rule)


"""The small path's rows in stretches (coverage_small.c, rast__cov_small:
boxes wider than RAST__CS_NARROW = 12 pixels): each row's levels are made
column by column only over the cells the two directions' pieces wrote
(lo .. hi + 1 of each), and once for each run of columns between them
(the running sum is the same there), filled by words of 8 bytes; each
row's levels not 0 are noted as bits.  Canvas.fill_polygon(aa=...) of 255
on 0 (so each pixel is its level) must give the exact oracle's level
floor(255 a + 1/2) (tests/oracle_coverage.py, exact rationals; one level
off only within the documented bound of a tie) and polygon_coverage's
levels (the engines'), on rings 13 to 24 pixels wide: rows whose middle
run is whole (255) or partial (the top and bottom rows of a box whose
sides are not on pixel lines), rows where the two directions' cells meet
or overlap (thin and slanted rings), rows one direction crosses from side
to side (a shallow edge), either orientation, both rules, partly off the
canvas, and random convex rings."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area
from test_coverage_convex import _hull

SHAPE = (34, 40)


def _check(ring, method="area", rule="nonzero", s=8):
    ring = np.ascontiguousarray(np.asarray(ring, np.float64))
    c = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
    c.fill_polygon(ring, 255, rule=rule, aa=method, subpixel_bits=s)
    n, m = _n_m([ring], s)
    check_area(c.array, exact_area([ring], SHAPE, rule, s), M_OF[np.uint8], n, m, S_.lit([ring]))
    want = rastrum.polygon_coverage([ring], SHAPE, rule=rule, method=method, subpixel_bits=s, dtype=np.uint8)
    S_.assert_same(c.array, want, "Canvas.fill_polygon(aa=%r) differs from polygon_coverage: %s"
                   % (method, S_.lit([ring])))
    return c.array


RINGS = {
    # a middle run of 255 between the sides' cells; partial top and bottom rows
    "box 13 wide": [(2.3, 2.6), (15.2, 2.6), (15.2, 9.4), (2.3, 9.4)],
    "box 22 wide": [(1.3, 3.35), (23.7, 3.35), (23.7, 12.8), (1.3, 12.8)],
    "hexagon 23 wide": [(1.4, 12.0), (7.0, 2.3), (18.9, 2.2), (24.3, 12.1), (18.8, 21.7), (7.1, 21.9)],
    "octagon 20 wide": [(5.2, 1.7), (15.9, 1.4), (21.6, 7.3), (21.8, 16.1), (16.2, 21.4), (5.4, 21.6),
                        (0.6, 16.4), (0.9, 7.2)],
    # the two directions' cells meeting and overlapping in every row
    "sliver": [(1.3, 5.02), (22.7, 10.31), (22.7, 10.84), (1.3, 5.55)],
    "thin steep": [(3.2, 1.1), (18.6, 30.2), (19.9, 30.1), (4.4, 1.0)],
    # a shallow side across the whole box in a row or two
    "shallow triangle": [(0.7, 6.3), (23.9, 8.1), (11.2, 20.6)],
    "wedge": [(0.4, 2.2), (24.1, 2.9), (24.3, 4.7)],
    # clipped: off the left, off the right and bottom
    "off left": [(-9.3, 3.2), (8.6, 2.9), (9.4, 13.3), (-8.1, 14.8)],
    "off right": [(27.2, 22.4), (45.1, 23.0), (44.0, 40.5), (29.3, 39.2)],
}


@pytest.mark.parametrize("name", sorted(RINGS))
@pytest.mark.parametrize("method", ["area", "accumulate"])
def test_wide_rings(name, method):
    ring = np.asarray(RINGS[name])
    for reverse in (False, True):
        for rule in ("nonzero", "evenodd"):
            _check(ring[::-1] if reverse else ring, method, rule)


def test_partial_middle_runs():
    """The boxes' top and bottom rows have a middle run neither 0 nor 255
    (made once for the run), their other rows a run of 255: both kinds are
    reached."""
    out = _check(RINGS["box 22 wide"])
    for j in (3, 12):  # (0.648 and 0.801 of a pixel high, snapped to 1/256)
        assert 0 < out[j, 5:20].min() == out[j, 5:20].max() < 255, out[j]
    assert (out[4:12, 5:20] == 255).all()


@pytest.mark.parametrize("dx", [0.0, 0.125, 0.37, 0.5, 0.93])
def test_widths_round_the_bound(dx):
    """Rings 11 to 24 pixels wide (the narrow pass to 12, stretches past
    it), at sub-pixel offsets."""
    for w in range(11, 25):
        x0 = 0.6 + dx
        _check([(x0, 2.45 + dx), (x0 + w - 1.3, 1.8), (x0 + w - 1.1, 9.7 + dx), (x0 + 0.4, 10.2)])


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.lists(st.tuples(st.integers(0, 23 * 64), st.integers(0, 23 * 64)), min_size=3, max_size=12),
       st.integers(-64, 14 * 64), st.integers(-64, 10 * 64), st.sampled_from(["area", "accumulate"]),
       st.sampled_from(["nonzero", "evenodd"]), st.booleans())
def test_random_wide_convex_rings(pts, ox, oy, method, rule, reverse):
    hull = _hull([((x + ox) / 64.0, (y + oy) / 64.0) for x, y in pts])
    if len(hull) < 3:
        return
    _check(hull[::-1] if reverse else hull, method, rule)

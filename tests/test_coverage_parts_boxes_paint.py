""""area" painted (a Canvas: the solid painter, gray8) of a polygon some
of whose parts are not plain, by the parts' boxes
(csrc/src/entry/coverage.c, rast__cov_boxes_paint): the boxes' levels
found first, then the accumulation of the rings outside them handed row
by row to the painter, a row that meets a box gathered and the box's row
put in, a box's rows that the accumulation leaves empty handed on in
their place (docs/coverage.md, plain parts by the accumulation).  Every
pixel of the canvas must be (s c + d (255 - c) + 127) // 255 of its
background d, the colour s and the level c of the exact coverage
(tests/oracle_coverage.py; one level off only at a tie within the
documented bound), and the same as the blend of the uint8 array
polygon_coverage gives.  The scenes: those of
tests/test_coverage_parts_boxes.py (an L that is not plain, plain glyphs
beside it), moved past each side of the canvas, and a wide one where a
row meets a box, a long plain bar (stretches of level 255, the painter's
full entry) and glyphs, rows that meet the box alone, and rows that
meet no box."""
import numpy as np
import pytest

import oracle_coverage as oc
import rastrum
from test_coverage import _n_m, blend, blended, levels_near_ties
from test_coverage_parts_boxes import SCENES, SHAPE, L, _moved
from test_coverage_plain_parts import _ring

S = 8


def _bar(x0, x1, y0, y1, n):
    """A plain bar [x0, x1] x [y0, y1], its long sides cut in n edges each
    (short edges: the test part by part runs), counter-clockwise."""
    xs = np.linspace(x0, x1, n + 1)
    top = [(x, y0) for x in xs]
    bottom = [(x, y1) for x in xs[::-1]]
    return (np.round(np.array(top + bottom) * 64) / 64).tolist()


WIDE_SHAPE = (20, 56)
# the L (rows 1-15, columns 0-9), a bar in its rows 3-6 (columns 14.3 to
# 49.6: runs of 255 far longer than 16), glyphs in rows 12-18 on the right
WIDE = L + [_bar(14.3, 49.6, 3.25, 6.5, 40)] + [
    _ring(20 + 5 * k, 15, 1.2, 2.2, 16, 0.1 * k, k % 2 == 0) for k in range(6)]


def _exact_levels(rings, shape, rule):
    return levels_near_ties(oc.coverage_exact(rings, shape, rule=rule, subpixel_bits=S), 255, sum(_n_m(rings, S)))


def _paint_check(rings, shape, rule, color, seed):
    bg = np.random.default_rng(seed).integers(0, 256, shape, dtype=np.uint8)
    img = bg.copy()
    rastrum.Canvas.wrap(img).fill_polygon([np.asarray(r, np.float64) for r in rings], color, rule=rule,
                                          aa="area", subpixel_bits=S)
    got = img.astype(np.int64)
    arr = rastrum.polygon_coverage(rings, shape, rule=rule, subpixel_bits=S, dtype=np.uint8)
    diff = np.argwhere(got != blend(color, bg, arr))
    assert not len(diff), "%d pixel(s) unlike the array's levels blended, first %s: got %d, the array's level %d" % (
        len(diff), tuple(diff[0]), got[tuple(diff[0])], arr[tuple(diff[0])])
    want, near = _exact_levels(rings, shape, rule)
    bad = np.argwhere(~blended(got, color, bg, want, near))
    assert not len(bad), "%d pixel(s) off the blend of the exact levels, first %s: got %d want level %d" % (
        len(bad), tuple(bad[0]), got[tuple(bad[0])], want[tuple(bad[0])])
    return want


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_boxes_painted(name, rule):
    _paint_check(SCENES[name], SHAPE, rule, 200, 1)


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("dx, dy", [(-3.375, -2.5), (-1.125, -4.0), (11.0, 3.25), (10.625, 5.875),
                                    (0.5, 0.125), (-0.25, 2.0), (0.0, 9.5), (0.0, -9.25)])
def test_boxes_painted_past_the_edges(name, dx, dy):
    """The boxes cut by the canvas on each side, the glyphs past it."""
    rule = ("nonzero", "evenodd")[int(dx * 8 + dy * 8) % 2]
    _paint_check(_moved(SCENES[name], dx, dy), SHAPE, rule, 77, 2)


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("color", [255, 131])
@pytest.mark.parametrize("dy", [0.0, 0.375, -2.0, 4.5])
def test_boxes_painted_wide(rule, color, dy):
    want = _paint_check(_moved(WIDE, 0, dy), WIDE_SHAPE, rule, color, 3)
    # (the scene holds what it should: a row with the L's and the bar's
    # pixels, the bar's 255s, rows with the L's alone)
    assert (want == 255).sum(axis=1).max() >= 30
    assert ((want[:, :10] > 0) & (want[:, 10:] == 0).all(axis=1)[:, None]).any()

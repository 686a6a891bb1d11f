""""accumulate" of polygons into uint8 and uint16 (csrc/src/coverage/coverage_acc.c:
one row of 64-bit cells, two deposits per column, a row sent to the exact
sweep when a level lies near a tie) against its definition from the exact
oracle: the rule applied to the integral of the winding number over each
pixel, within the documented bound.  The scenes reach the engine's cases:
rings past every side of the clip (cover carried in from the left, parts
right of it dropped, edges walking into and out of the clip), vertices on
pixel corners and half pixels (levels on a tie: those rows go to the exact
sweep), slivers, collinear vertices, both orientations overlapping, far
coordinates, both rules."""

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _accumulated, _n_m, check_area, exact_area, rule_applied
from test_coverage_fast import _star_shaped

SHAPE = (7, 9)


def _check(rings, rule, shape=SHAPE):
    want = _accumulated(rings, shape, rule, 8)
    n, m = _n_m(rings, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
        check_area(out, want, M_OF[dtype], n, m, S_.lit(rings))


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(1, 3), st.integers(3, 12), st.integers(0, 2 ** 32 - 1),
       st.sampled_from([1, 2, 4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_rings_across_the_clip(k, n, seed, snap, rule):
    """Up to three simple rings of either orientation, overlapping, each
    anywhere from well left of the image to well right of it (and above,
    below), vertices on a grid of 1/snap pixel."""
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(k):
        c = rnd.uniform([-4, -4], [SHAPE[1] + 4, SHAPE[0] + 4])
        ring = _star_shaped(rnd, n, c, 0.5, rnd.uniform(1.0, 9.0), snap).tolist()
        rings.append(ring if rnd.integers(2) else ring[::-1])
    _check(rings, rule)


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("name", [
    "half pixels",          # levels at a = 1/2: ties, rows to the exact sweep
    "corners",              # every vertex on a pixel corner, diagonals through corners
    "slivers",              # 1/256 pixel wide, long, steep and shallow
    "collinear",            # vertices in the middle of straight sides
    "left of the clip",     # cover carried in from x < 0 through every row
    "right of the clip",    # parts dropped past the last column
    "far",                  # a ring reaching the range limit (2^27 / 2^8 pixels) on both sides
    "deep",                 # the same square 5 times: winding 5, folded or clamped
])
def test_scenes(name, rule):
    scenes = {
        "half pixels": [[(0.5, 0.5), (8.5, 0.5), (8.5, 6.5), (0.5, 6.5)],
                        [(2, 1.5), (2, 5.5), (6.5, 5.5), (6.5, 1.5)]],
        "corners": [[(0, 0), (9, 0), (9, 7), (0, 7)], [(1, 1), (4, 6), (8, 1)],
                    [(2, 2), (2, 6), (6, 6)]],
        "slivers": [[(1, 0.5), (1 + 1 / 256, 0.5), (8, 6.5)], [(0, 3), (9, 3 + 1 / 256), (9, 3)],
                    [(4, -2), (4 + 1 / 256, -2), (4 + 1 / 256, 9)]],
        "collinear": [[(1, 1), (3, 1), (5, 1), (7, 1), (7, 3.5), (7, 6), (4, 6), (1, 6), (1, 3)]],
        "left of the clip": [[(-50, 0.3), (3.7, 0.9), (2.2, 6.6), (-80, 6.1)]],
        "right of the clip": [[(4.3, 0.2), (90, 1.7), (70, 6.8), (5.1, 5.9)]],
        "far": [[(-524287.5, 1.25), (524287.5, 2.5), (524287.5, 5.75), (-524287.5, 4.125)]],
        "deep": [[(1.3, 1.1), (7.6, 1.4), (7.2, 5.8), (1.1, 6.3)]] * 5,
    }
    _check(scenes[name], rule)


def test_a_level_on_a_tie_is_the_exact_ones():
    """A square covering half of each pixel of a column: a = 1/2, exactly
    halfway between two levels; floor(a M + 1/2) = (M + 1) / 2 is what the
    exact sweep gives, and the engine's own cells cannot tell."""
    ring = [[(2.5, 0), (3.5, 0), (3.5, 7), (2.5, 7)]]
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(ring, SHAPE, method="accumulate", dtype=dtype)
        M = M_OF[dtype]
        assert (out[:, 2] == (M + 1) // 2).all() and (out[:, 3] == (M + 1) // 2).all()
        assert out[:, [0, 1, 4, 5, 6, 7, 8]].sum() == 0


def _area2(ring):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))


@pytest.mark.parametrize("method", ["accumulate", "area"])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("orient", [1, -1])
@pytest.mark.parametrize("mirror", [False, True])
@pytest.mark.parametrize("wide", [0, 30, 62])
@pytest.mark.parametrize("hole", [False, True])
def test_a_level_just_past_a_tie_is_exact(method, rule, orient, mirror, wide, hole):
    """Pixel (2, 1) of the quadrilateral is covered 83/170, a tie in both
    formats (83/170 * 255 = 124.5, * 65535 = 31996.5) that is not a dyadic
    number: the 64-bit cells, which floor each column crossing to 2^-30
    pixel, land below it.  A triangle of area 2^-33 (legs of 2^-16 pixel)
    in the same pixel, apart, lifts the exact value just past the tie, so
    the level is the upper one, 2^-25 of a level from the tie: far outside
    the documented bound, well inside the cells' error.  Only the exact
    redo of the row gets it right (without it, 124 and 31996).  Mirrored
    (the quadrilateral x -> 5 - x, the pixel the same; the triangle one
    that leans the same way, outside it): every slanted edge leans left
    instead of one each way, and the row must still be redone (its edges
    are not all vertical).  Wide: a thin box at x = 30 makes the rows 29
    cells long, so that the pixel is read with 15 others at a time (SSE2);
    at x = 62, 61 cells, the pixel read with 31 others (AVX2, where the
    processor has it).  Hole:
    the triangle inside the quadrilateral, turning the other way, takes
    2^-33 off instead: the level is the lower one (the cells' error now
    lands on the other side of the tie in some of these scenes)."""
    quad = [(2, 0), (2.125, 0), (3.08984375, 3.984375), (2, 3.984375)]
    d = 2 ** -16
    tri = [(2.875, 1.5), (2.875, 1.5 + d), (2.875 + d, 1.5)]
    if hole:  # inside the quadrilateral (its slanted side is at x = 2.488 at y = 1.5)
        tri = [(x - 0.625, y) for x, y in tri]
    if mirror:
        quad = [(5 - x, y) for x, y in quad]
        tri = [(2.125 - d, 1.5), (2.125, 1.5), (2.125 - d, 1.5 + d)]
        if hole:
            tri = [(x + 0.625, y) for x, y in tri]
    quad = quad if orient > 0 else quad[::-1]
    tri = tri if ((_area2(tri) > 0) == (_area2(quad) > 0)) != hole else tri[::-1]
    rings = [quad, tri] + ([[(wide, 0), (wide + 0.25, 0), (wide + 0.25, 3.984375), (wide, 3.984375)]] if wide else [])
    shape = (5, wide + 10) if wide else (5, 5)
    exact = exact_area(rings, shape, rule, 16)
    assert exact[1, 2] == F(83, 170) + F(-1 if hole else 1, 2 ** 33)
    n, m = _n_m(rings, 16)
    for dtype, want in ((np.uint8, 124 if hole else 125), (np.uint16, 31996 if hole else 31997)):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method=method, dtype=dtype, subpixel_bits=16)
        assert out[1, 2] == want
        check_area(out, exact, M_OF[dtype], n, m, "%s %s" % (method, rule))


def _near_tie(hole):
    """The quadrilateral and the tiny triangle of
    test_a_level_just_past_a_tie_is_exact: the triangle inside the
    quadrilateral turning the other way when `hole` (its pixel's level
    then the lower one)."""
    quad = [(2, 0), (2.125, 0), (3.08984375, 3.984375), (2, 3.984375)]
    d = 2 ** -16
    tri = [(2.875, 1.5), (2.875, 1.5 + d), (2.875 + d, 1.5)]
    if hole:
        tri = [(x - 0.625, y) for x, y in tri]
    tri = tri if ((_area2(tri) > 0) == (_area2(quad) > 0)) != hole else tri[::-1]
    return quad, tri


@pytest.mark.parametrize("rule, hole", [("nonzero", False), ("evenodd", True)])
def test_a_level_just_past_a_tie_in_a_row_of_many_parts(rule, hole):
    """The pixel of test_a_level_just_past_a_tie_is_exact, 2^-25 of a level
    past a tie, in rows of 266 parts or more: 130 slanted quadrilaterals to
    its right (two parts a row each).  Such a row bounds its cells' error
    by the most parts that touch any 16 columns (coverage_acc.c,
    rast__acc_count), not by all 266, and the pixel must still send the row
    to the exact sweep (a window of 0 gives 124 / 125 the other way)."""
    quad, tri = _near_tie(hole)
    many = [[(x0 + 0.5, 0.25), (x0 + 1.75, 0.25), (x0 + 3.25, 3.75), (x0 + 2.0, 3.75)]
            for x0 in range(10, 10 + 4 * 130, 4)]
    rings = [quad, tri] + many
    shape = (5, 10 + 4 * 130 + 4)
    exact = exact_area(rings, shape, rule, 16)
    assert exact[1, 2] == F(83, 170) + F(-1 if hole else 1, 2 ** 33)
    n1, m1 = _n_m([quad, tri] + many[:1], 16)
    n2, m2 = _n_m([quad, tri] + many[:2], 16)
    n, m = n1 + (len(many) - 1) * (n2 - n1), m1 + (len(many) - 1) * (m2 - m1)
    for dtype, want in ((np.uint8, 124 if hole else 125), (np.uint16, 31996 if hole else 31997)):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype,
                                       subpixel_bits=16)
        assert out[1, 2] == want
        check_area(out, exact, M_OF[dtype], n, m, "%s %s" % (rule, dtype.__name__))


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_long_shallow_parts_in_sparse_rows(rule):
    """Rows with few parts mark the cells each part touches; a shallow
    edge's part in a row spans hundreds of columns (several 64-bit words of
    marks), and the marks of a part reaching into the last column stop
    short of the cell past the clip.  Against the oracle, both formats."""
    quad = [(1.3, 0.2), (299.7, 1.1), (299.1, 2.9), (2.2, 1.7)]
    wedge = [(-40.5, 3.1), (330.25, 3.4), (-40.5, 3.9)]  # past both sides of the clip
    _check([quad, wedge], rule, shape=(5, 300))


@settings(max_examples=S_.examples(25), deadline=None)
@given(st.integers(1, 2), st.integers(3, 4), st.integers(0, 2 ** 32 - 1),
       st.sampled_from([1, 4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_sparse_rows_across_a_wide_clip(k, n, seed, snap, rule):
    """At most 8 parts a row in 140 columns: every row takes the marked
    (sparse) scan; rings stretched 20 times wider than tall, from left of
    the clip to right of it."""
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(k):
        c = rnd.uniform([-20, -2], [160, 8])
        ring = _star_shaped(rnd, n, c, 0.5, rnd.uniform(1.0, 4.0), snap)
        ring[:, 0] = c[0] + (ring[:, 0] - c[0]) * 20
        ring = np.round(ring * snap) / snap
        rings.append(ring.tolist() if rnd.integers(2) else ring.tolist()[::-1])
    _check(rings, rule, shape=(6, 140))


# ---- long edges: the walk a band of rows at a time ---------------------------
#
# When the edges cross 32 rows or more each on the mean, each is walked over
# a band of 4 rows at a time (its steppers held from row to row), into four
# rows of cells; the rows are then read out in order, a row whose level is
# near a tie (or whose parts are too many for the cells' bound) going to the
# exact sweep while the rows below it in the band wait.

TALL = (80, 7)


def _tall_ring(rnd, n, c, rx, ry, snap):
    """A ring star-shaped round c, stretched (rx across, ry down) so that its
    edges are long and steep, snapped to multiples of 1/snap; None when the
    snapping broke it (the vertices no longer turn round c in order, less
    than half a turn apart: then it may not be simple, and the oracle below
    assumes simple rings)."""
    ang = (np.arange(n) + rnd.uniform(0, 0.45, n)) * 2 * np.pi / n
    r = rnd.uniform(0.6, 1.0, n)
    pts = np.round(np.stack([c[0] + rx * r * np.cos(ang), c[1] + ry * r * np.sin(ang)], 1) * snap) / snap
    turn = np.diff(np.unwrap(np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0])), append=np.nan)
    turn[-1] = 2 * np.pi - np.nansum(turn[:-1])
    if not ((turn > 1e-9) & (turn < np.pi - 1e-9)).all():
        return None
    return pts.tolist()


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(1, 3), st.integers(3, 5), st.integers(0, 2 ** 32 - 1),
       st.sampled_from([2, 4, 256]), st.sampled_from(["evenodd", "nonzero"]))
def test_long_edges_walked_a_band_at_a_time(k, n, seed, snap, rule):
    """Rings of few vertices over a tall image (the band walk): edges that
    start and end inside a band and pass band boundaries, rings reaching
    past the top and bottom and past the left and right sides (an edge that
    leaves the clip goes part by part), vertices on a grid of 1/snap pixel
    (levels on a tie: rows to the exact sweep in the middle of a band),
    overlapping, both orientations; against the oracle, both formats."""
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(k):
        c = rnd.uniform([-1, 10], [TALL[1] + 1, TALL[0] - 10])
        ring = _tall_ring(rnd, n, c, rnd.uniform(2.5, 6.0), rnd.uniform(30.0, 60.0), snap)
        if ring is not None:
            rings.append(ring if rnd.integers(2) else ring[::-1])
    if rings:
        _check(rings, rule, shape=TALL)


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_rows_of_many_parts_inside_a_band(rule):
    """300 copies of a tall triangle and a lone thin one: 602 parts in each
    row they share, more than the cells' bound holds (512), so those rows
    go to the exact sweep while the band's other rows are read out of its
    cells (the rows above and below hold the thin triangle alone; the band
    of rows 8 to 11 has row 8 of the thin one alone and three of 602
    parts, so it is not walked as a whole band).  The oracle: the copies'
    integral is 300 times one's."""
    tri = [(1.25, 9.5), (5.5, 40.25), (2.125, 71.75)]
    thin = [(6.0, 0.5), (6.5, 79.5), (6.25, 0.5)]
    a1 = exact_area([tri], TALL, "nonzero", 8)
    a2 = exact_area([thin], TALL, "nonzero", 8)
    sign = (1 if _area2(tri) > 0 else -1) * (1 if _area2(thin) > 0 else -1)
    want = rule_applied(a1 * 300 + a2 * sign, rule)
    rings = [tri] * 300 + [thin]
    n, m = _n_m(rings, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, TALL, rule=rule, method="accumulate", dtype=dtype)
        check_area(out, want, M_OF[dtype], n, m, "%s %s" % (rule, dtype.__name__))


@pytest.mark.parametrize("copies", [2046, 8192])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_rows_of_thousands_of_parts(copies, rule):
    """A row of a paragraph of text holds ~700 parts: uint8 rows take up
    to 4,095 (coverage_acc.c, RAST__ACC_MAXN), where the winding is at
    most 2,047 and the 64-bit sums hold it.  2,046 copies of a tall
    triangle and a thin one: 4,094 parts, a winding of 2,046 or 2,047,
    accumulated; 8,192 copies: 24,579 parts, a winding of 2^13, which a
    64-bit sum of 2^51 a pixel would wrap to 0, so those rows go to the
    exact sweep.
    The oracle: the copies' integral is `copies` times one's."""
    tri = [(1.25, 9.5), (5.5, 40.25), (2.125, 71.75)]
    thin = [(6.0, 0.5), (6.5, 79.5), (6.25, 0.5)]
    a1 = exact_area([tri], TALL, "nonzero", 8)
    a2 = exact_area([thin], TALL, "nonzero", 8)
    sign = (1 if _area2(tri) > 0 else -1) * (1 if _area2(thin) > 0 else -1)
    want = rule_applied(a1 * copies + a2 * sign, rule)
    rings = [tri] * copies + [thin]
    # n and m counted on one and two copies (O(n^2) pairs on all): a copy
    # adds the same edges and crossings as the second does
    n1, m1 = _n_m([tri, thin], 8)
    n2, m2 = _n_m([tri, tri, thin], 8)
    n, m = n1 + (copies - 1) * (n2 - n1), m1 + (copies - 1) * (m2 - m1)
    out = rastrum.polygon_coverage(rings, TALL, rule=rule, method="accumulate", dtype=np.uint8)
    check_area(out, want, 255, n, m, "%d copies, %s" % (copies, rule))


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(1, 2), st.integers(0, 2 ** 32 - 1), st.sampled_from([4, 256]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_long_shallow_edges_in_band_rows(k, seed, snap, rule):
    """Long edges across a wide image: parts that cross tens of columns in
    a row (the columns between deposited in one pass), rows with few parts
    (their cells marked a bit each) beside rows with many, in one band."""
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(k):
        c = rnd.uniform([20, 40], [100, 50])
        ring = _tall_ring(rnd, 4, c, rnd.uniform(20.0, 60.0), rnd.uniform(40.0, 50.0), snap)
        if ring is not None:
            rings.append(ring if rnd.integers(2) else ring[::-1])
    if rings:
        _check(rings, rule, shape=(90, 120))


@pytest.mark.parametrize("method", ["accumulate", "area"])
def test_long_edges_painted_as_written(method):
    """A Canvas fill hands each row on as it is read out of the band (one
    row buffer): gray8 painted with 255 equals the coverage levels."""
    rings = [[(0.3, -4.0), (6.6, 30.25), (1.5, 83.0)], [(5.2, 2.5), (6.9, 77.75), (3.0, 40.125)]]
    cov = rastrum.polygon_coverage(rings, TALL, method=method)
    canvas = rastrum.Canvas((TALL[0], TALL[1]), "gray8")
    canvas.fill_polygon(rings, 255, aa=method)
    np.testing.assert_array_equal(canvas.array, cov)
    _check(rings, "evenodd", shape=TALL)


@pytest.mark.parametrize("method", ["accumulate", "area"])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("wide", [False, True])
@pytest.mark.parametrize("hole", [False, True])
def test_a_level_just_past_a_tie_is_exact_in_a_band(method, rule, wide, hole):
    """The scene of test_a_level_just_past_a_tie_is_exact beside two tall
    triangles in columns of their own, whose long edges make the call walk
    a band at a time: the row with the near-tie pixel is redone by the exact
    sweep inside its band (without it, 124 and 31996), the band's other
    rows read out of the cells.  Wide: a tall box at x = 62 makes the rows
    61 cells long (read 32 at a time with AVX2, or the band's four rows 8
    columns at a time).  Hole: the triangle inside the quadrilateral,
    turning the other way (the level the lower one), as there."""
    quad, tri = _near_tie(hole)
    tall = [[(6.25, 0.5), (8.5, 199.75), (7.125, 1.0)], [(9.5, 2.0), (11.75, 3.0), (10.25, 198.5)]]
    if wide:
        tall.append([(62, 0.25), (62.5, 0.25), (62.5, 199.5), (62, 199.5)])
    rings = [quad, tri] + tall
    shape = (200, 70) if wide else (200, 12)
    exact = exact_area(rings, shape, rule, 16)
    assert exact[1, 2] == F(83, 170) + F(-1 if hole else 1, 2 ** 33)
    n, m = _n_m(rings, 16)
    for dtype, want in ((np.uint8, 124 if hole else 125), (np.uint16, 31996 if hole else 31997)):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method=method, dtype=dtype, subpixel_bits=16)
        assert out[1, 2] == want
        check_area(out, exact, M_OF[dtype], n, m, "%s %s" % (method, rule))


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_steppers_exact_over_a_thousand_crossings(rule):
    """Edges of 1,100 rows that cross a vertical in most rows, and one that
    crosses several a row: each crossing's ordinate comes from the last by
    a quotient and a remainder, so an error in a carry would add up over a
    thousand crossings to a hundredth of a uint16 level near the bottom,
    where the oracle checks the last rows (the rings moved up, the same
    cells at the same fractions)."""
    # (no vertical on a half pixel: its pixels would be ties, their rows
    # all redone by the exact sweep)
    rings = [[(0.25, -0.3), (1090.37109375, 1099.609375), (0.25, 1099.90625)],
             [(1099.75, 0.25), (16.12890625, 1099.8125), (1099.75, 1099.5)],
             [(300.0, 20.0), (700.3359375, 5.0), (1099.0, 1098.65625)]]
    shape = (1100, 1100)
    n, m = _n_m(rings, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
        for x0 in (0, 980):  # the columns the edges cross in the last rows
            moved = [[(x - x0, y - 1080) for x, y in r] for r in rings]
            want = _accumulated(moved, (20, 120), rule, 8)
            check_area(out[1080:, x0:x0 + 120], want, M_OF[dtype], n, m, "%s %s" % (rule, dtype.__name__))

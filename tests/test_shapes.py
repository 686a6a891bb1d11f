"""Shapes as Paths, Pillow's shape methods on Canvas, Canvas.stroke, and
Paths (rastrum's and matplotlib's) accepted by every fill (docs/paths.md).

Referees: the exact rational oracle (tests/oracle.py) for the binary
fill of the flattened path; the true ellipse (closed-form distance
bounds) for the shapes' geometry; Pillow's ImageDraw for its
conventions (pixel boxes, vertices, angles).
"""

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import Canvas, InputError, Path
from rastrum._path import ARC_ERROR
from oracle import oracle_mask

PIL = pytest.importorskip("PIL.ImageDraw")
from PIL import Image, ImageDraw  # noqa: E402

# How far the filled region may be from the true curve: the flattening
# tolerance, the cubics' own distance from the ellipse (ARC_ERROR) and the
# snapping of the control points to 1/256 px (the curve is a convex
# combination of them: it moves at most sqrt(2)/512).
SNAP = math.sqrt(2) / 512


def _bound(tol):
    return tol + ARC_ERROR + SNAP


@given(cx=st.floats(4, 28), cy=st.floats(4, 20), rx=st.floats(0.5, 12), ry=st.floats(0.5, 12),
       rot=st.floats(-180, 180), tol=st.sampled_from([1.0, 0.25, 1 / 16, 1 / 256]))
def test_ellipse_mask_within_tolerance_of_the_true_ellipse(cx, cy, rx, ry, rot, tol):
    """Every pixel centre farther than the bound from the true ellipse is
    classified as the true ellipse classifies it; and the fill is the
    exact oracle's fill of the flattened rings."""
    p = Path.ellipse(cx, cy, rx, ry, rotation=rot)
    shape = (26, 34)
    m = rastrum.polygon_mask(p, shape, tolerance=tol)
    assert (m == oracle_mask(p.flatten(8, tol), shape)).all()
    ys, xs = np.mgrid[0:shape[0], 0:shape[1]] + 0.5
    c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
    u = (xs - cx) * c + (ys - cy) * s  # in the ellipse's own axes
    v = -(xs - cx) * s + (ys - cy) * c
    q = np.hypot(u / rx, v / ry)
    # the map to the unit circle is 1/min(rx, ry)-Lipschitz: the distance to
    # the boundary is at least min(rx, ry) * |q - 1|
    sure = min(rx, ry) * np.abs(q - 1) > _bound(tol)
    assert (m[sure] == (q < 1)[sure]).all()


@given(r=st.floats(1, 14), tol=st.sampled_from([1.0, 1 / 16, 1 / 256]), dx=st.floats(0, 1), dy=st.floats(0, 1))
def test_circle_area_coverage_within_tolerance(r, tol, dx, dy):
    """'area' coverage (exact for the flattened path) sums to the circle's
    area within perimeter x bound."""
    cx, cy = 16 + dx, 16 + dy
    cov = rastrum.polygon_coverage(Path.circle(cx, cy, r), (33, 33), dtype=np.float64, tolerance=tol)
    assert abs(cov.sum() - math.pi * r * r) <= 2 * math.pi * r * _bound(tol)


def test_a_tighter_tolerance_gives_more_vertices_and_a_closer_area():
    p = Path.circle(50, 50, 40)
    coarse, fine = p.flatten(8, 1.0), p.flatten(8, 1 / 256)
    assert len(coarse[0]) < len(fine[0])
    a = [rastrum.polygon_coverage(p, (100, 100), dtype=np.float64, tolerance=t).sum() for t in (1.0, 1 / 256)]
    assert abs(a[1] - math.pi * 1600) < abs(a[0] - math.pi * 1600)


def test_shapes_run_clockwise_on_screen_and_close():
    for p in (Path.circle(5, 5, 3), Path.ellipse(5, 5, 3, 2, rotation=30), Path.rounded_rectangle(1, 1, 9, 6, 2),
              Path.pieslice(5, 5, 4, 3, 10, 200), Path.chord(5, 5, 4, 3, 200, 10), Path.regular_polygon(5, 5, 4, 5),
              Path.rounded_rectangle(1, 1, 9, 6, 2, corners=(True, False, True, False))):
        for ring in p.flatten():
            x, y = ring[:, 0], ring[:, 1]
            assert np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y) > 0
        assert p.verbs[-1] == 4  # closed


def test_arc_angles_are_pillows():
    """Degrees clockwise from 3 o'clock (y down), the parametric angle."""
    p = Path.arc(10, 20, 8, 4, 30, 120)
    assert np.allclose(p.points[0], (10 + 8 * math.cos(math.radians(30)), 20 + 4 * math.sin(math.radians(30))))
    assert np.allclose(p.points[-1], (10 + 8 * math.cos(math.radians(120)), 20 + 4 * math.sin(math.radians(120))))
    assert len(Path.arc(0, 0, 1, 1, 30, 30)) == 0  # nothing
    full = Path.pieslice(10, 10, 5, 5, 0, 360)
    assert rastrum.polygon_mask(full, (20, 20)).sum() == rastrum.polygon_mask(Path.circle(10, 10, 5), (20, 20)).sum()
    # end < start wraps: 300 -> 60 is the 120 degrees through 3 o'clock
    m = rastrum.polygon_mask(Path.pieslice(10, 10, 8, 8, 300, 60), (20, 20))
    assert m[10, 17] and not m[10, 3]


@pytest.mark.parametrize("box", [(0, 0, 9, 9), (2, 3, 20, 11), (1, 1, 2, 2), (0, 0, 30, 7), (5, 5, 5, 12),
                                 (3, 1, 40, 40)])
def test_pixel_box_as_pillow(box):
    """Axis-aligned: the same pixel box as ImageDraw (inclusive boxes); a
    rectangle (radius 0) the very same pixels."""
    def drawn(f):
        im = Image.new("L", (48, 48))
        f(ImageDraw.Draw(im))
        return np.array(im)

    def bbox(m):
        ys, xs = np.nonzero(m)
        return (xs.min(), ys.min(), xs.max(), ys.max())

    c = Canvas((48, 48), format="gray8")
    c.ellipse(box, fill=1)
    assert bbox(c.array) == bbox(drawn(lambda d: d.ellipse(box, fill=1)))
    for r in (0, 3, 5):
        c = Canvas((48, 48), format="gray8")
        c.rounded_rectangle(box, r, fill=1)
        pil = drawn(lambda d: d.rounded_rectangle(box, r, fill=1))
        assert bbox(c.array) == bbox(pil)
        if r == 0:
            assert (c.array == pil).all()


def test_regular_polygon_vertices_are_pillows():
    from PIL.ImageDraw import _compute_regular_polygon_vertices as pil_vertices

    for n, rot in ((3, 0), (5, 17.5), (6, -40), (12, 90)):
        ours = Path.regular_polygon(20, 30, 10, n, rotation=rot).points
        theirs = np.array(pil_vertices((20, 30, 10), n, rot))
        # the same vertices (Pillow rounds to 2 decimals), ours the other way round
        assert np.allclose(ours[::-1], theirs, atol=0.006)


def test_pillow_pieslice_uses_the_parametric_angle():
    """On a flat ellipse, 45 degrees is the parametric angle (polar 11.3)."""
    im = Image.new("L", (201, 41))
    ImageDraw.Draw(im).pieslice((0, 0, 200, 40), 0, 45, fill=1)
    c = Canvas((41, 201), format="gray8")
    c.pieslice((0, 0, 200, 40), 0, 45, fill=1)
    for m in (np.array(im), c.array):
        ys, xs = np.nonzero(m)
        top = np.degrees(np.arctan2(ys + 0.5 - 20.5, xs + 0.5 - 100.5)).max()
        assert 10 < top < 12.5


def test_canvas_shapes_are_fills_of_the_shape_paths():
    c = Canvas((30, 40), format="gray8")
    c.chord((2, 3, 30, 25), 20, 250, fill=200, aa="area")
    p = Path.chord(16.5, 14.5, 14.5, 11.5, 20, 250)  # the box's continuous extent [2, 31] x [3, 26]
    assert (c.array == _blend(rastrum.polygon_coverage(p, (30, 40), rule="nonzero"), 200)).all()


def _blend(cov, s):
    """Canvas's documented blend over 0: (s*c + 127) // 255."""
    return ((s * cov.astype(np.int64) + 127) // 255).astype(np.uint8)


def test_outline_is_the_ring_inside_the_box():
    c = Canvas((24, 24), format="gray8")
    c.ellipse((2, 2, 21, 21), outline=255, width=3, aa="area")
    outer, inner = Path.circle(12, 12, 10), Path.circle(12, 12, 7)
    exact = rastrum.polygon_coverage(outer, (24, 24), dtype=np.float64) - \
        rastrum.polygon_coverage(inner, (24, 24), dtype=np.float64)
    assert abs(c.array.sum() / 255 - exact.sum()) < 0.5
    assert c.array[12, 12] == 0 and c.array[12, 3] == 255


def test_arc_on_a_circle_is_the_annular_sector():
    c = Canvas((40, 40), format="gray8")
    c.arc((0, 0, 39, 39), 0, 90, fill=255, width=4, aa="area")
    area = math.pi * (20 ** 2 - 16 ** 2) / 4
    assert abs(c.array.sum() / 255 - area) < 0.5
    assert c.array[37, 21] == 255 and c.array[2, 21] == 0  # the bottom right quarter (clockwise from 3)


def test_line_width_1_is_the_old_bresenham_line():
    a, b = Canvas((12, 16), format="gray8"), Canvas((12, 16), format="gray8")
    a.line((1.2, 0.7), (14.9, 10.1), 7)
    b._line((1.2, 0.7), (14.9, 10.1), 7)
    assert (a.array == b.array).all() and a.array.any()
    im = Image.new("L", (16, 12))
    ImageDraw.Draw(im).line([(1, 2), (14, 2), (14, 9)], fill=7)
    c = Canvas((12, 16), format="gray8")
    c.line([(1, 2), (14, 2), (14, 9)], fill=7)
    assert (c.array == np.array(im)).all()


def test_wide_line_is_the_stroke():
    c = Canvas((20, 30), format="gray8")
    c.line([(2, 3), (25, 12), (4, 17)], 255, width=3, joint="curve", aa="area")
    s = rastrum.stroke(np.array([(2, 3), (25, 12), (4, 17)]) + 0.5, 3, join="round", cap="butt")
    assert (c.array == rastrum.polygon_coverage(s, (20, 30), rule="nonzero")).all()
    d = Canvas((20, 30), format="gray8")
    d.line((2, 3), (25, 12), 255, width=2)  # binary, wide: the pixel centres inside the stroke
    s = rastrum.stroke([(2, 3), (25, 12)], 2)
    assert (d.array.astype(bool) == rastrum.polygon_mask(s, (20, 30), rule="nonzero")).all()


def test_canvas_stroke_is_the_nonzero_fill_of_rastrum_stroke():
    pts = [(2, 2), (20, 14), (4, 14), (18, 3)]  # crosses itself
    for join, cap in (("miter", "butt"), ("round", "round"), ("bevel", "square")):
        c = Canvas((18, 24), format="gray8")
        c.stroke(pts, 255, 2.5, join=join, cap=cap, aa="area")
        s = rastrum.stroke(pts, 2.5, join=join, cap=cap)
        assert (c.array == rastrum.polygon_coverage(s, (18, 24), rule="nonzero")).all()
    shapely = pytest.importorskip("shapely")
    c, d = Canvas((18, 24), format="gray8"), Canvas((18, 24), format="gray8")
    c.stroke(shapely.LineString(pts), 255, 2, aa="area")
    d.stroke(pts, 255, 2, aa="area")
    assert (c.array == d.array).all()


def test_matplotlib_paths_are_accepted_everywhere():
    pytest.importorskip("matplotlib")
    from matplotlib.textpath import TextPath
    from matplotlib.transforms import Affine2D

    tp = TextPath((0, 0), "g@8", size=18).transformed(Affine2D().scale(1, -1).translate(1, 20))
    p = Path.from_matplotlib(tp)
    shape = (26, 40)
    want = rastrum.polygon_mask(p, shape, rule="nonzero")
    assert want.sum() > 50
    assert (want == oracle_mask(p.flatten(), shape, rule="nonzero")).all()
    assert (rastrum.polygon_mask(tp, shape, rule="nonzero") == want).all()
    assert (rastrum.masks([tp], shape)[0] == want).all()  # union: non-zero as the glyphs run
    assert (rastrum.labels([tp, p], shape) == np.where(want, 2, 0)).all()
    assert (rastrum.rasterize([(tp, 5)], out_shape=shape, rule="nonzero") == np.where(want, 5, 0)).all()
    c = Canvas(shape, format="gray8")
    c.fill_polygon(tp, 3, rule="nonzero")
    assert (c.array == np.where(want, 3, 0)).all()
    assert (rastrum.polygon_coverage(tp, shape, rule="nonzero") ==
            rastrum.polygon_coverage(p, shape, rule="nonzero")).all()


def test_rasterize_takes_paths_in_world_coordinates():
    affine = pytest.importorskip("affine")
    t = affine.Affine(0.5, 0, 100, 0, -0.5, 50)
    p = Path.circle(10.3, 9.1, 6.2)
    got = rastrum.rasterize([(p.transformed(t), 3)], out_shape=(20, 20), transform=t)
    assert ((got == 3) == rastrum.polygon_mask(p, (20, 20))).all()


def test_tolerance_keyword():
    p = Path.circle(20, 20, 15)
    coarse = rastrum.polygon_coverage(p, (40, 40), tolerance=1.0)
    assert (coarse != rastrum.polygon_coverage(p, (40, 40))).any()
    assert (rastrum.polygon_coverage(p, (40, 40), tolerance=Path.DEFAULT_TOLERANCE) ==
            rastrum.polygon_coverage(p, (40, 40))).all()
    for bad in (0, -1.0, float("nan"), "x"):
        with pytest.raises(InputError, match="tolerance"):
            rastrum.polygon_mask(p, (40, 40), tolerance=bad)
        with pytest.raises(InputError, match="tolerance"):
            rastrum.masks([p], (40, 40), tolerance=bad)
        c = Canvas((40, 40), format="gray8")
        with pytest.raises(InputError, match="tolerance"):
            c.fill_polygon(p, 1, tolerance=bad)
        assert not c.array.any()


def test_bad_input_draws_nothing():
    c = Canvas((10, 10), format="rgb888")
    for call, words in ((lambda: c.ellipse((5, 5, 2, 8), fill=1), "x1 >= x0"),
                        (lambda: c.ellipse((1, 1, 5, 5)), "fill or outline"),
                        (lambda: c.ellipse((1, 1, 5, 5), fill=(1, 2, 3), outline=(1, 2)), "colour"),
                        (lambda: c.rounded_rectangle((1, 1, 5, 5), -2, fill=1), "radius"),
                        (lambda: c.regular_polygon((5, 5, 3), 2, fill=1), "n_sides"),
                        (lambda: c.regular_polygon((5, 5), 4, fill=1), "bounding_circle"),
                        (lambda: c.arc((1, 1, 5, 5), 0, float("nan"), fill=1), "end"),
                        (lambda: c.line([(1, 1), (4, 4)], 1, width=-1), "width"),
                        (lambda: c.line([(1, 1), (4, 4)], 1, joint="round"), "joint"),
                        (lambda: c.stroke([(1, 1), (4, 4)], 1, 0), "width"),
                        (lambda: c.stroke([(1, 1), (4, 4)], 1, 2, join="sharp"), "join")):
        with pytest.raises(InputError, match=words):
            call()
        assert not c.array.any()


def test_shapely_polygons_are_accepted_by_every_fill():
    shapely = pytest.importorskip("shapely")
    ring = shapely.Point(10, 10).buffer(6).difference(shapely.Point(10, 10).buffer(3))
    g = shapely.MultiPolygon([ring, shapely.box(0, 0, 2, 2)])
    rings = [np.asarray(r.coords) for p in g.geoms for r in [p.exterior, *p.interiors]]
    shape = (20, 20)
    want = oracle_mask(rings, shape)
    assert (rastrum.polygon_mask(g, shape) == want).all()
    assert (rastrum.masks([g], shape)[0] == want).all()
    assert (rastrum.labels([g], shape) == want).all()
    cov = rastrum.polygon_coverage(rings, shape)
    assert (rastrum.polygon_coverage(g, shape) == cov).all()
    c = Canvas(shape, format="gray8")
    c.fill_polygon(g, 255, aa="area")
    assert (c.array == cov).all()


@given(x0=st.floats(1, 5), y0=st.floats(1, 5), w=st.floats(2, 20), h=st.floats(2, 14), r=st.floats(0, 8),
       start=st.floats(-360, 360), sweep=st.floats(1, 359))
def test_areas_of_rounded_rectangles_and_pie_slices(x0, y0, w, h, r, start, sweep):
    """'area' coverage (exact for the flattened path) against the closed
    forms: w h - (4 - pi) r^2 (r clamped), and sweep/2 r^2, within the
    perimeter x bound."""
    tol = Path.DEFAULT_TOLERANCE
    rr = min(r, w / 2, h / 2)
    cov = rastrum.polygon_coverage(Path.rounded_rectangle(x0, y0, x0 + w, y0 + h, r), (22, 28), dtype=np.float64)
    assert abs(cov.sum() - (w * h - (4 - math.pi) * rr * rr)) <= 2 * (w + h) * _bound(tol)
    rad = 9.0
    cov = rastrum.polygon_coverage(Path.pieslice(12, 12, rad, rad, start, start + sweep), (24, 24), dtype=np.float64)
    assert abs(cov.sum() - math.radians(sweep) / 2 * rad * rad) <= (2 * rad + math.radians(sweep) * rad) * _bound(tol)

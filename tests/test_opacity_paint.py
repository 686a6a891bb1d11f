"""The loose ends of issue 34 (docs/opacity.md, docs/paths.md):

* Canvas.stroke and the Pillow shapes take `opacity=` and `gamma=` (and a
  colour's alpha): a stroke's outline is one non-zero fill, each pixel
  blended once where its pieces overlap; a shape's fill and outline are
  two layers, each blended once; against the exact blend oracle of
  test_opacity.py applied to the opaque calls' coverage;
* the blended seed fills find their region in a window grown around the
  seed (Canvas._seed_blend): the breadth-first region of test_opacity_more,
  with windows far smaller than the region;
* Canvas.composite takes `gamma=` as the fills do (linear light).
"""

from fractions import Fraction as Q

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from rastrum import _canvas
from test_opacity import canvas, canvas_expected, level, nearest
from test_opacity_more import colour_for, linear_pixel, region, same_as

KINDS = ["gray8", "rgb888", "rgb565", "rgba8888"]
SHAPE = (7, 9)


def coverage_of(draw):
    """The coverage level c of each pixel an opaque call paints: value 255
    on a zero gray8 canvas ((255 c + 127) // 255 = c; binary: 255)."""
    m = rastrum.Canvas(SHAPE, format="gray8")
    draw(m, 255)
    return m.array.copy()


# a path crossing itself, a dash whose pieces overlap at the turn, a tight
# round join: places where two pieces of the outline cover the same pixel
STROKES = [([(0.5, 0.5), (8.5, 6.5), (8.5, 0.5), (0.5, 6.5)], 2.0, dict(join="round")),
           ([(1.0, 3.5), (8.0, 3.5), (4.0, 0.5), (4.0, 6.5)], 1.5, dict(dash=[3, 1], cap="square")),
           ([(1.2, 5.8), (4.5, 0.7), (7.6, 5.9)], 3.0, dict(join="miter", miter_limit=10))]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("aa", [None, "area", "ss4"])
def test_stroke_blends_each_pixel_once(kind, aa):
    rng = np.random.default_rng(14)
    color, rgba = colour_for(kind)
    for opacity in (None, 0.6) if kind != "rgba8888" else (0.6,):  # rgba8888 stores a value without opacity
        lv = 255 if opacity is None else nearest(Q(opacity) * 255)
        for pts, width, kw in STROKES:
            c = canvas(kind, rng)
            before = c.array.copy()
            c.stroke(pts, color, width, aa=aa, opacity=opacity, **kw)
            outline = rastrum.stroke(pts, width, **kw)
            cov = (rastrum.polygon_mask(outline, SHAPE, rule="nonzero").astype(np.uint8) * 255 if aa is None
                   else rastrum.polygon_coverage(outline, SHAPE, rule="nonzero", method=aa))
            np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, lv), err_msg=str(pts))


def test_stroke_and_arc_linear_light():
    rng = np.random.default_rng(5)
    for draw in (lambda c, col, **k: c.stroke(STROKES[0][0], col, 2.0, aa="area", **k),
                 lambda c, col, **k: c.arc((0, 0, 8, 6), 30, 300, col, 2, aa="area", **k)):
        c = canvas("rgb888", rng)
        before = c.array.copy()
        draw(c, (255, 255, 255, 140), gamma="srgb")
        cov = coverage_of(lambda m, v: draw(m, v))
        assert cov.any()
        for y, x in np.ndindex(*SHAPE):
            want = linear_pixel("rgb888", "srgb", (255, 255, 255, 140), tuple(int(v) for v in before[y, x]),
                                level(140, 255, int(cov[y, x]), 255))
            assert tuple(c.array[y, x]) == want


SHAPES = [
    lambda c, fill, outline, **k: c.ellipse((0, 0, 7, 5), fill, outline, 2, **k),
    lambda c, fill, outline, **k: c.circle((4, 3), 2.6, fill, outline, 1, **k),
    lambda c, fill, outline, **k: c.rounded_rectangle((1, 0, 7, 6), 2, fill, outline, 2, **k),
    lambda c, fill, outline, **k: c.pieslice((0, 0, 8, 6), 20, 250, fill, outline, 2, **k),
    lambda c, fill, outline, **k: c.chord((0, 0, 8, 6), 200, 30, fill, outline, 1, **k),
    lambda c, fill, outline, **k: c.regular_polygon((4, 3, 3.2), 5, 10, fill, outline, 2, **k),
]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("aa", [None, "area"])
def test_shapes_blend_fill_then_outline(kind, aa):
    """The fill blended once, then the outline over it (two layers)."""
    rng = np.random.default_rng(21)
    color, rgba = colour_for(kind)
    other = (30, 220) if kind == "gray8" else (10, 250, 90, 200)
    other_rgba = (30, 30, 30, 220) if kind == "gray8" else other
    for draw in SHAPES:
        c = canvas(kind, rng)
        before = c.array.copy()
        draw(c, color, other, aa=aa, opacity=0.75)
        lv = nearest(Q(0.75) * 255)
        cov_fill = coverage_of(lambda m, v: draw(m, v, None, aa=aa))
        cov_line = coverage_of(lambda m, v: draw(m, None, v, aa=aa))
        assert cov_fill.any() and cov_line.any()
        want = canvas_expected(kind, before, cov_fill, rgba, lv)
        want = canvas_expected(kind, want, cov_line, other_rgba, lv)
        np.testing.assert_array_equal(c.array, want)


def test_shapes_alpha_without_opacity():
    """An RGBA colour on rgb888 blends at its alpha (it was refused)."""
    c = canvas("rgb888", np.random.default_rng(2))
    before = c.array.copy()
    c.ellipse((0, 0, 8, 6), fill=(200, 40, 250, 150), aa="area")
    cov = coverage_of(lambda m, v: m.ellipse((0, 0, 8, 6), fill=v, aa="area"))
    np.testing.assert_array_equal(c.array, canvas_expected("rgb888", before, cov, (200, 40, 250, 150), 255))


def test_opaque_and_opacity_one_unchanged():
    """No opacity, or opacity 1 with alpha 255: the value's pixels."""
    calls = [lambda c, col, **k: c.stroke(STROKES[1][0], col, 1.5, aa="area", **k)]
    calls += [lambda c, col, draw=draw, **k: draw(c, col, col, aa="area", **k) for draw in SHAPES]
    for draw in calls:
        a, b = (canvas("rgb888", np.random.default_rng(4)) for _ in range(2))
        draw(a, (9, 200, 40))
        draw(b, (9, 200, 40, 255), opacity=1.0)
        np.testing.assert_array_equal(a.array, b.array)


@pytest.mark.parametrize("call, word", [
    (lambda c: c.stroke([(0, 0), (5, 3)], (1, 2, 3), 2, opacity=1.5), "opacity"),
    (lambda c: c.stroke([(0, 0), (5, 3)], (1, 2, 3), 2, aa="area", gamma="lab"), "gamma"),
    (lambda c: c.stroke([(0, 0), (5, 3)], (1, 2, 3, 300), 2), "alpha"),
    (lambda c: c.ellipse((0, 0, 4, 4), (1, 2, 3), (4, 5, 6), opacity=-0.1), "opacity"),
    (lambda c: c.ellipse((0, 0, 4, 4), (1, 2, 3), (4, 5, 6, 256), opacity=0.5), "alpha"),
    (lambda c: c.pieslice((0, 0, 4, 4), 0, 90, (1, 2, 3), gamma=9.0), "gamma"),
    (lambda c: c.arc((0, 0, 4, 4), 0, 90, (1, 2, 3), 0, opacity="x"), "opacity"),
    (lambda c: c.arc((0, 0, 4, 4), 0, 90, (1, 2, 3), 2, opacity=2), "opacity"),
    (lambda c: c.line([(0, 0), (4, 4)], fill=(1, 2, 3), width=0, opacity=2), "opacity"),
    (lambda c: c.regular_polygon((2, 2, 2), 4, fill=(1, 2, 3), outline=(1, 2, 3), gamma=0.1), "gamma"),
])
def test_bad_input_names_it_and_writes_nothing(call, word):
    c = rastrum.Canvas((5, 5), format="rgb888", background=7)
    before = c.array.copy()
    with pytest.raises(rastrum.InputError, match=word):
        call(c)
    np.testing.assert_array_equal(c.array, before)


@pytest.mark.parametrize("fmt", ["mono1", "label"])
def test_no_blend_on_mono1_and_labels(fmt):
    c = rastrum.Canvas.wrap(np.zeros((5, 5), np.int32), format="label") if fmt == "label" else rastrum.Canvas((5, 5), format=fmt)
    for call in (lambda: c.stroke([(0, 0), (5, 3)], 1, 2, opacity=0.5),
                 lambda: c.ellipse((0, 0, 4, 4), 1, opacity=0.5),
                 lambda: c.circle((2, 2), 2, 1, gamma="srgb")):
        with pytest.raises(rastrum.InputError):
            call()
    assert not c.array.any()


# ---- the blended seed fills' window -------------------------------------------------

@settings(max_examples=S_.examples(60), deadline=None)
@given(data=st.data(), kind=st.sampled_from(KINDS), connectivity=st.sampled_from([4, 8]),
       window=st.integers(0, 3), h=st.integers(1, 24), w=st.integers(1, 30))
def test_seed_blend_window_grows_to_the_region(data, kind, connectivity, window, h, w):
    keep = _canvas._SEED_WINDOW
    _canvas._SEED_WINDOW = window  # 0..3 pixels each side of the seed: grown on almost every call
    try:
        seed_fills_match_the_walk(data, kind, connectivity, h, w)
    finally:
        _canvas._SEED_WINDOW = keep


def seed_fills_match_the_walk(data, kind, connectivity, h, w):
    color, rgba = colour_for(kind)
    rng = np.random.default_rng(data.draw(st.integers(0, 2 ** 16)))
    c = rastrum.Canvas((h, w), format=kind)
    two = (np.uint16(0x1234), np.uint16(0xBEEF)) if kind == "rgb565" else \
        ((7,) * c.array.shape[-1] if c.array.ndim == 3 else 7, (90,) * c.array.shape[-1] if c.array.ndim == 3 else 90)
    pick = rng.random((h, w)) < data.draw(st.sampled_from([0.3, 0.55, 0.7]))
    c.array[pick] = two[0]
    c.array[~pick] = two[1]
    before = c.array.copy()
    seed = (data.draw(st.integers(0, w - 1)), data.draw(st.integers(0, h - 1)))
    c.flood_fill(seed, color, connectivity=connectivity, opacity=0.8)
    cov = region(before, seed, same_as(before, before[seed[1], seed[0]]), connectivity).astype(np.uint8) * 255
    np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, nearest(Q(0.8) * 255)))
    c.array[...] = before
    edge = 0x1234 if kind == "rgb565" else two[0]
    if kind == "rgb565":  # a colour whose packed pixel is 0x1234
        edge = ((0x1234 >> 11) << 3, ((0x1234 >> 5) & 63) << 2, (0x1234 & 31) << 3)
    c.boundary_fill(seed, color, edge, connectivity=connectivity, opacity=0.5)
    cov = region(before, seed, ~same_as(before, two[0]), connectivity).astype(np.uint8) * 255
    np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, nearest(Q(0.5) * 255)))


def test_seed_blend_serpentine_past_the_first_window():
    """A corridor that leaves the first window and comes back into it (a
    serpentine on 130 x 150, its turns at the far ends): one region."""
    h, w = 130, 150
    wall = np.zeros((h, w), bool)
    for k, y in enumerate(range(1, h - 1, 2)):  # a wall row every other row, its gap at alternate ends
        wall[y] = True
        wall[y, (w - 1) if k % 2 else 0] = False
    c = rastrum.Canvas((h, w), format="gray8")
    c.array[wall] = 255
    before = c.array.copy()
    seed = (w // 2, h // 2 - (h // 2) % 2)
    assert not wall[seed[1], seed[0]]
    c.flood_fill(seed, (100, 128), opacity=1.0)
    cov = region(before, seed, before == 0, 4).astype(np.uint8) * 255
    assert (cov[~wall] == 255).all()
    np.testing.assert_array_equal(c.array, canvas_expected("gray8", before, cov, (100, 100, 100, 128), 255))


# ---- Canvas.composite's gamma= ----------------------------------------------------------

@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("wide", [False, True])
def test_composite_linear_light(kind, wide):
    """composite(..., gamma=) is the fills' linear-light blend (the exact
    nearest level of the linear mix, test_opacity_more's oracle), uint8 or
    uint16 coverage."""
    rng = np.random.default_rng(8)
    c = canvas(kind, rng)
    before = c.array.copy()
    cov = rng.integers(0, 65536 if wide else 256, SHAPE).astype(np.uint16 if wide else np.uint8)
    cov[0, :3] = 0
    color, rgba = colour_for(kind)
    c.composite(cov, color, opacity=0.7, gamma=2.2)
    lv = nearest(Q(0.7) * 255)
    flat = before.reshape(SHAPE[0] * SHAPE[1], -1)
    for i, (y, x) in enumerate(np.ndindex(*SHAPE)):
        if kind == "rgb565":
            p = int(before[y, x])
            d = (p >> 11, (p >> 5) & 63, p & 31)
            r, g, b = linear_pixel(kind, 2.2, rgba, d, level(rgba[3], lv, int(cov[y, x]), 65535 if wide else 255))
            assert int(c.array[y, x]) == (r << 11) | (g << 5) | b
        else:
            d = tuple(int(v) for v in flat[i])
            want = linear_pixel(kind, 2.2, rgba, d, level(rgba[3], lv, int(cov[y, x]), 65535 if wide else 255))
            assert tuple(int(v) for v in np.atleast_1d(c.array[y, x])) == want


def test_composite_gamma_bad_input():
    c = rastrum.Canvas(SHAPE, format="rgba8888", background=(1, 2, 3, 4))
    before = c.array.copy()
    cov = np.full(SHAPE, 200, np.uint8)
    for kw in (dict(gamma="lab"), dict(gamma=0.1), dict(gamma="srgb", premultiplied=True)):
        with pytest.raises(rastrum.InputError, match="gamma"):
            c.composite(cov, (1, 2, 3, 4), **kw)
    np.testing.assert_array_equal(c.array, before)
    with pytest.raises(rastrum.InputError, match="not mono1"):
        rastrum.Canvas(SHAPE, format="mono1").composite(cov, 1, gamma="srgb")

"""Opacity: an RGBA colour's alpha times an opacity level, applied
source-over (docs/opacity.md; rastrum.h "opacity"), held against an oracle
written here from the docs in exact rational arithmetic (fractions), then
the stated rounding:

- the alpha level A = the product (alpha/255)(opacity/255)(c/C) times 255
  to the nearest integer, c a coverage level out of C (255: binary fills
  and uint8 coverage; 65535: uint16 coverage); A = 0 leaves the pixel;
- gray8, rgb888, rgb565 (its 5/6/5-bit fields) and premultiplied rgba8888
  (alpha mixed with 255): each channel the nearest integer to
  s A/255 + d (1 - A/255);
- straight rgba8888: alpha the nearest integer to 255 (a_s + a_d (1 - a_s)),
  colour the exact straight colour of the exact source-over,
  (s a_s + d a_d (1 - a_s)) / (a_s + a_d (1 - a_s)), rounded half up.

The core (rast_blend_coverage) exhaustively over small level sets of alpha,
opacity, source, destination and coverage, for every format and both
coverage widths, plus hypothesis; the Canvas fills (binary and
anti-aliased) against the oracle applied to polygon_mask /
polygon_coverage / triangles_*; opaque calls unchanged; bad input.
"""

import functools
import itertools
import math
from fractions import Fraction as Q

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from rastrum import _core
from rastrum._native import ffi, lib

HALF = Q(1, 2)


def nearest(q):
    return math.floor(q + HALF)


@functools.lru_cache(maxsize=None)
def level(alpha, opacity, c, full):
    return nearest(Q(alpha, 255) * Q(opacity, 255) * Q(c, full) * 255)


@functools.lru_cache(maxsize=None)
def mix(s, d, a):
    w = Q(a, 255)
    return nearest(s * w + d * (1 - w))


@functools.lru_cache(maxsize=None)
def pixel(kind, rgba, d, a):
    """Pixel d (a tuple of the format's channels: gray8 (L,), rgb888
    (R, G, B), rgb565 its three fields, rgba8888 (R, G, B, A)) after the
    colour rgba at alpha level a."""
    if a == 0:
        return d
    if kind == "gray8":
        return (mix(rgba[0], d[0], a),)
    if kind == "rgb888":
        return tuple(mix(rgba[k], d[k], a) for k in range(3))
    if kind == "rgb565":
        src = (rgba[0] >> 3, rgba[1] >> 2, rgba[2] >> 3)
        return tuple(mix(src[k], d[k], a) for k in range(3))
    if kind == "rgba8888p":
        return tuple(mix(rgba[k], d[k], a) for k in range(3)) + (mix(255, d[3], a),)
    a_s, a_d = Q(a, 255), Q(d[3], 255)
    out = a_s + a_d * (1 - a_s)
    return tuple(nearest((rgba[k] * a_s + d[k] * a_d * (1 - a_s)) / out) for k in range(3)) + (nearest(out * 255),)


FORMAT = {"gray8": "gray8", "rgb888": "rgb888", "rgb565": "rgb565", "rgba8888": "rgba8888", "rgba8888p": "rgba8888"}
KINDS = list(FORMAT)


def to_channels(kind, arr):
    """The (N,) pixels of a (1, N[, C]) array as channel tuples."""
    if kind == "gray8":
        return [(int(v),) for v in arr[0]]
    if kind == "rgb565":
        return [(int(v) >> 11, (int(v) >> 5) & 63, int(v) & 31) for v in arr[0]]
    return [tuple(int(x) for x in p) for p in arr[0]]


def from_channels(kind, pixels):
    if kind == "gray8":
        return np.array([[p[0] for p in pixels]], np.uint8)
    if kind == "rgb565":
        return np.array([[(p[0] << 11) | (p[1] << 5) | p[2] for p in pixels]], np.uint16)
    return np.array([pixels], np.uint8)


def core_blend(kind, dest, cov, rgba, opacity):
    """rast_blend_coverage of rgba at `opacity` through the (1, N) coverage
    (uint8 or uint16) over the (1, N) pixels `dest` (channel tuples)."""
    arr = from_channels(kind, dest)
    target = _core.make_target(arr, _core.FORMATS[FORMAT[kind]])
    cov = np.ascontiguousarray(cov)
    opts = ffi.new("rast_blend_opts *", {"opacity": opacity, "premultiplied": int(kind == "rgba8888p")})
    fmt = lib.RAST_COVERAGE_U16 if cov.dtype == np.uint16 else lib.RAST_COVERAGE_U8
    st_ = lib.rast_blend_coverage(target, ffi.from_buffer(cov), fmt, cov.shape[1] * cov.itemsize, bytes(rgba), opts)
    assert st_ == lib.RAST_OK
    return to_channels(kind, arr)


def expected(kind, dest, cov, rgba, opacity):
    full = 65535 if cov.dtype == np.uint16 else 255
    return [pixel(kind, tuple(rgba), d, level(rgba[3], opacity, int(c), full)) for d, c in zip(dest, cov[0])]


LEVELS = [0, 1, 127, 128, 254, 255]
ALPHAS = [0, 1, 128, 254, 255]
OPACITIES = [0, 1, 127, 255]
COV = {np.uint8: [0, 1, 2, 127, 128, 254, 255],
       np.uint16: [0, 1, 128, 129, 256, 257, 32767, 32768, 65279, 65534, 65535]}
SOURCES = [(0, 0, 0), (255, 255, 255), (1, 128, 254), (200, 17, 90)]


def dests(kind):
    if kind == "gray8":
        return [(d,) for d in LEVELS]
    if kind == "rgb565":
        return [(r, g, b) for r, g, b in zip([0, 1, 15, 16, 30, 31], [0, 1, 31, 32, 62, 63], [31, 30, 16, 15, 1, 0])]
    if kind == "rgb888":
        return [(d, LEVELS[(i + 2) % 6], LEVELS[(i + 4) % 6]) for i, d in enumerate(LEVELS)]
    return [(d, LEVELS[(i + 3) % 6], 255 - d, a) for i, d in enumerate(LEVELS) for a in LEVELS
            if kind == "rgba8888" or d <= a]  # premultiplied: colour <= alpha


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16], ids=["u8", "u16"])
@pytest.mark.parametrize("kind", KINDS)
def test_core_exhaustive(kind, dtype):
    """Every alpha x opacity x source x destination x coverage of the sets
    (under the quick and valgrind profiles: every destination and coverage,
    fewer alphas, opacities and sources)."""
    pairs = list(itertools.product(dests(kind), COV[dtype]))
    dest = [p[0] for p in pairs]
    cov = np.array([[p[1] for p in pairs]], dtype)
    full = settings.default.max_examples >= 100  # the quick and valgrind profiles: a subset
    sets = (ALPHAS, OPACITIES, SOURCES) if full else ((0, 128, 255), (127, 255), SOURCES[2:])
    for alpha, opacity, src in itertools.product(*sets):
        rgba = src + (alpha,)
        assert core_blend(kind, dest, cov, rgba, opacity) == expected(kind, dest, cov, rgba, opacity), (rgba, opacity)


@settings(max_examples=S_.examples(60))
@given(data=st.data(), kind=st.sampled_from(KINDS), wide=st.booleans(),
       rgba=st.tuples(*[st.integers(0, 255)] * 4), opacity=st.integers(0, 255))
def test_core_random(data, kind, wide, rgba, opacity):
    n = data.draw(st.integers(1, 24))
    top = {"gray8": [255], "rgb888": [255] * 3, "rgb565": [31, 63, 31]}.get(kind, [255] * 4)
    dest = [tuple(data.draw(st.integers(0, t)) for t in top) for _ in range(n)]
    if kind == "rgba8888p":
        dest = [tuple(min(v, p[3]) for v in p[:3]) + (p[3],) for p in dest]
    dtype = np.uint16 if wide else np.uint8
    cov = np.array([data.draw(st.lists(st.integers(0, 65535 if wide else 255), min_size=n, max_size=n))], dtype)
    assert core_blend(kind, dest, cov, rgba, opacity) == expected(kind, dest, cov, rgba, opacity)


def test_core_opaque_is_the_aa_blend():
    """Alpha 255, opacity 255, uint8 coverage: A = c, the anti-aliased fill's
    own blend (s c + d (255 - c) + 127) // 255 (straight rgba8888 over an
    opaque pixel too)."""
    cov = np.arange(256, dtype=np.uint8)[None]
    for kind, d in (("gray8", (77,)), ("rgb888", (3, 130, 250)), ("rgba8888", (3, 130, 250, 255))):
        got = core_blend(kind, [d] * 256, cov, (200, 10, 99, 255), 255)
        s = (200, 10, 99, 255)
        assert got == [tuple((s[k] * c + d[k] * (255 - c) + 127) // 255 for k in range(len(d))) for c in range(256)]


def test_core_errors_write_nothing():
    arr = np.full((2, 3), 9, np.uint8)
    target = _core.make_target(arr, _core.FORMATS["gray8"])
    cov = np.full((2, 3), 255, np.uint8)
    c = ffi.from_buffer(cov)
    rgba = bytes((1, 2, 3, 255))
    bad = [
        (c, lib.RAST_COVERAGE_U8, 3, rgba, {"opacity": 256}, lib.RAST_E_ARG),
        (c, lib.RAST_COVERAGE_U8, 3, rgba, {"opacity": -1}, lib.RAST_E_ARG),
        (c, lib.RAST_COVERAGE_U8, 3, rgba, {"opacity": 255, "premultiplied": 2}, lib.RAST_E_ARG),
        (c, lib.RAST_COVERAGE_U8, 2, rgba, None, lib.RAST_E_ARG),
        (c, lib.RAST_COVERAGE_FIX62, 24, rgba, None, lib.RAST_E_ARG),
        (c, lib.RAST_COVERAGE_U8, 3, ffi.NULL, None, lib.RAST_E_NULL),
        (ffi.NULL, lib.RAST_COVERAGE_U8, 3, rgba, None, lib.RAST_E_NULL),
        (ffi.cast("uint8_t *", c) + 1, lib.RAST_COVERAGE_U16, 6, rgba, None, lib.RAST_E_ALIGN),
        (c, lib.RAST_COVERAGE_U16, 5, rgba, None, lib.RAST_E_ARG),
    ]
    for cov_p, fmt, stride, col, opts, status in bad:
        o = ffi.new("rast_blend_opts *", opts) if opts else ffi.NULL
        assert lib.rast_blend_coverage(target, cov_p, fmt, stride, col, o) == status
    for fmt in ("mono1", "count16"):
        a = np.zeros((2, 1 if fmt == "mono1" else 3), np.uint8 if fmt == "mono1" else np.uint16)
        t = _core.make_target(a, _core.FORMATS[fmt] if fmt == "mono1" else lib.RAST_FORMAT_COUNT16,
                              3 if fmt == "mono1" else None)
        assert lib.rast_blend_coverage(t, c, lib.RAST_COVERAGE_U8, 3, rgba, ffi.NULL) == lib.RAST_E_FORMAT
    assert (arr == 9).all()


@pytest.mark.parametrize("value, level", [(0, 0), (1, 255), (0.5, 128), (1 / 255, 1), (0.001, 0), (0.002, 1),
                                          (127.5 / 255, 128), (np.float32(0.25), 64), (0.99, 252)])
def test_opacity_level(value, level):
    """floor(opacity * 255 + 1/2) of the float's exact value."""
    assert rastrum._canvas._opacity_level(value, "x") == level == nearest(Q(float(value)) * 255)


# ---- Canvas ------------------------------------------------------------------

RING = [(0.3, 0.6), (7.7, 1.2), (5.1, 6.9), (1.4, 5.2)]
TRIS = [[(0.2, 0.1), (7.9, 0.4), (3.3, 6.8)], [(3.3, 6.8), (7.9, 0.4), (7.6, 6.6)]]
CANVAS = {"gray8": 1, "rgb888": 3, "rgb565": 3, "rgba8888": 4}


def canvas(kind, rng):
    h, w = 7, 9
    c = rastrum.Canvas((h, w), format=kind)
    if kind == "rgb565":
        c.array[...] = rng.integers(0, 65536, (h, w), dtype=np.uint16)
    else:
        c.array[...] = rng.integers(0, 256, c.array.shape, dtype=np.uint8)
    return c


def canvas_expected(kind, before, cov, rgba, opacity):
    flat = before.reshape(1, -1) if kind in ("gray8", "rgb565") else before.reshape(1, -1, before.shape[-1])
    dest = to_channels(kind, flat)
    out = expected(kind, dest, cov.reshape(1, -1), rgba, opacity)
    return from_channels(kind, out).reshape(before.shape)


@pytest.mark.parametrize("kind", list(CANVAS))
@pytest.mark.parametrize("aa", [None, "area", "ss4"])
def test_canvas_fills(kind, aa):
    rng = np.random.default_rng(34)
    shape = (7, 9)
    if aa is None:
        cov_p = rastrum.polygon_mask(RING, shape, rule="nonzero").astype(np.uint8) * 255
        cov_t = rastrum.triangles_mask(TRIS, shape).astype(np.uint8) * 255
    else:
        cov_p = rastrum.polygon_coverage(RING, shape, rule="nonzero", method=aa)
        cov_t = rastrum.triangles_coverage(TRIS, shape, method=aa)
    n = CANVAS[kind]
    for color, rgba, opacity in [((90, 200, 31, 128), (90, 200, 31, 128), None),
                                 ("#40e0d0c0", (0x40, 0xE0, 0xD0, 0xC0), 0.3),
                                 ("turquoise", (0x40, 0xE0, 0xD0, 255), 0.7)]:
        if kind == "gray8" and not isinstance(color, str):
            color, rgba = (90, 128), (90, 90, 90, 128)
        if kind == "gray8" and isinstance(color, str):
            from PIL import ImageColor
            la = ImageColor.getcolor(color, "LA")
            rgba = (la[0],) * 3 + (la[1],)
        if kind == "rgba8888" and opacity is None:
            continue  # a pixel value there: stored (test_canvas_rgba_stores)
        level = 255 if opacity is None else nearest(Q(opacity) * 255)
        for draw, cov in ((lambda c: c.fill_polygon(RING, color, rule="nonzero", aa=aa, opacity=opacity), cov_p),
                          (lambda c: c.fill_triangles(TRIS, color, aa=aa, opacity=opacity), cov_t),
                          (lambda c: c.fill_triangle(TRIS[0], color, aa=aa, opacity=opacity),
                           rastrum.triangles_mask(TRIS[:1], shape).astype(np.uint8) * 255 if aa is None
                           else rastrum.triangles_coverage(TRIS[:1], shape, method=aa))):
            c = canvas(kind, rng)
            before = c.array.copy()
            draw(c)
            np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, level))


@pytest.mark.parametrize("kind", list(CANVAS))
@pytest.mark.parametrize("aa", [None, "area"])
def test_canvas_opaque_unchanged(kind, aa):
    """No opacity (or 1.0) and alpha 255: the value's fill, bit for bit."""
    rng = np.random.default_rng(7)
    plain = canvas(kind, rng)
    color = {"gray8": 200, "rgba8888": (9, 200, 40, 255)}.get(kind, (9, 200, 40))
    others = [canvas(kind, np.random.default_rng(7)) for _ in range(3)]
    plain.fill_polygon(RING, color, aa=aa)
    others[0].fill_polygon(RING, color, aa=aa, opacity=None)
    if kind != "rgba8888":
        others[1].fill_polygon(RING, color, aa=aa, opacity=1.0)
        others[2].fill_polygon(RING, (200, 255) if kind == "gray8" else (9, 200, 40, 255), aa=aa)
    else:
        others[1].fill_polygon(RING, color, aa=aa)
        others[2].fill_polygon(RING, color, aa=aa)
    for o in others:
        np.testing.assert_array_equal(o.array, plain.array)


def test_canvas_rgba_stores():
    """rgba8888 without opacity: the colour is a pixel value, stored (as
    Pillow's ImageDraw on an RGBA image)."""
    c = rastrum.Canvas((4, 4), format="rgba8888", background=(1, 2, 3, 4))
    c.fill_polygon([(0, 0), (4, 0), (4, 4), (0, 4)], (200, 100, 50, 60))
    assert (c.array == (200, 100, 50, 60)).all()
    c.fill_polygon([(0, 0), (4, 0), (4, 4), (0, 4)], (0, 0, 0, 255), opacity=0.0)
    assert (c.array == (200, 100, 50, 60)).all()


@pytest.mark.parametrize("kwargs, color, fmt", [
    (dict(opacity=1.5), (1, 2, 3), "rgb888"), (dict(opacity=-0.01), (1, 2, 3), "rgb888"),
    (dict(opacity=float("nan")), (1, 2, 3), "rgb888"), (dict(opacity="half"), (1, 2, 3), "rgb888"),
    (dict(opacity=True), (1, 2, 3), "rgb888"), (dict(opacity=0.5), 1, "mono1"),
    (dict(), (1, 2, 3, 256), "rgb888"), (dict(), (1, 2, 3, -1), "rgb888"), (dict(), (1, 2.5, 3, 9), "rgb888"),
    (dict(), "#12345", "rgb888"), (dict(opacity=0.5), "nocolour", "gray8"),
    (dict(gamma=2.2, vertex_colors=[[1, 2, 3]] * 4), None, "rgb888"),  # opacity: test_opacity_shaded.py
])
def test_canvas_bad_input(kwargs, color, fmt):
    c = rastrum.Canvas((5, 5), format=fmt, background=0 if fmt == "mono1" else 7)
    before = c.packed.copy() if fmt == "mono1" else c.array.copy()
    with pytest.raises(rastrum.InputError):
        c.fill_polygon([(0, 0), (5, 0), (5, 5), (0, 5)], color, **kwargs)
    np.testing.assert_array_equal(c.packed if fmt == "mono1" else c.array, before)


def test_canvas_per_triangle_colours_refuse_opacity():
    c = rastrum.Canvas((5, 5), format="rgb888")
    with pytest.raises(rastrum.InputError, match="one colour"):
        c.fill_triangles(TRIS, [(1, 2, 3), (4, 5, 6)], opacity=0.5)
    assert not c.array.any()


# ---- linear light (gamma=) -----------------------------------------------------

def linear_table(gamma):
    """round(2^24 decode(k / 255)) for every level k: the stated tables."""
    if gamma == "srgb":
        f = [v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4 for v in (k / 255 for k in range(256))]
    else:
        f = [(k / 255) ** gamma for k in range(256)]
    return [math.floor((1 << 24) * v + 0.5) for v in f]


def linear_expected(dec, s, d, a):
    """The level whose table value is nearest the exact mix
    (dec[s] a + dec[d] (255 - a)) / 255, ties to the lower: a scan of all
    256 levels, in integers scaled by 255 (exact)."""
    if a == 0:
        return d
    x = dec[s] * a + dec[d] * (255 - a)
    return min(range(256), key=lambda k: (abs(255 * dec[k] - x), k))


@pytest.mark.parametrize("gamma", ["srgb", 2.2, 0.5])
def test_linear_light_gray8_exhaustive(gamma):
    """Every destination level, several sources and alpha levels."""
    dec = linear_table(gamma)
    assert all(p < q for p, q in zip(dec, dec[1:]))
    rows = [(s, a) for s in (0, 1, 128, 254, 255) for a in (1, 2, 64, 128, 200, 254, 255)]
    c = rastrum.Canvas((len(rows), 256), format="gray8")
    c.array[...] = np.arange(256, dtype=np.uint8)
    for j, (s, a) in enumerate(rows):
        c.fill_polygon([(0, j), (256, j), (256, j + 1), (0, j + 1)], (s, a), gamma=gamma)
    table = np.array(dec, np.int64)
    d = np.arange(256)
    want = np.array([np.abs(255 * table[None, :] - (table[s] * a + table[d] * (255 - a))[:, None]).argmin(axis=1)
                     for s, a in rows], np.uint8)  # linear_expected for every d (argmin: the lowest on a tie)
    assert [linear_expected(dec, s, 77, a) for s, a in rows] == list(want[:, 77])
    np.testing.assert_array_equal(c.array, want)


def test_linear_light_rgb888_aa():
    """Anti-aliased, with opacity: A from the coverage as the core's, each
    channel mixed in linear light."""
    rng = np.random.default_rng(2)
    dec = linear_table("srgb")
    c = rastrum.Canvas((7, 9), format="rgb888")
    c.array[...] = rng.integers(0, 256, c.array.shape, dtype=np.uint8)
    before = c.array.copy()
    c.fill_polygon(RING, "#ff8000c0", aa="area", opacity=0.8, gamma="srgb")
    cov = rastrum.polygon_coverage(RING, (7, 9), method="area")
    lv = nearest(Q(0.8) * 255)
    for y, x in np.ndindex(7, 9):
        a = level(0xC0, lv, int(cov[y, x]), 255)
        for k, s in enumerate((0xFF, 0x80, 0x00)):
            assert c.array[y, x, k] == linear_expected(dec, s, int(before[y, x, k]), a), (y, x, k)


@pytest.mark.parametrize("fmt, gamma", [("mono1", "srgb"), ("gray8", "linear"),
                                        ("gray8", 5.0), ("gray8", 0.1), ("gray8", True), ("gray8", float("nan"))])
def test_linear_light_bad_input(fmt, gamma):
    c = rastrum.Canvas((4, 4), format=fmt, background=1 if fmt == "mono1" else 3)
    before = c.packed.copy()
    with pytest.raises(rastrum.InputError, match="gamma"):
        c.fill_polygon([(0, 0), (4, 0), (4, 4)], 1 if fmt == "mono1" else 200, gamma=gamma)
    np.testing.assert_array_equal(c.packed, before)


def test_docs_examples_run():
    """docs/opacity.md's Python examples run as written."""
    import os
    import re

    text = open(os.path.join(os.path.dirname(__file__), "..", "docs", "opacity.md"), encoding="utf-8").read()
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)
    assert blocks
    for k, block in enumerate(blocks):
        exec(compile(block, "docs/opacity.md block %d" % k, "exec"), {})


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16], ids=["u8", "u16"])
def test_canvas_composite(kind, dtype):
    """Canvas.composite: a coverage image of either width, every format,
    premultiplied rgba8888 too, against the oracle."""
    rng = np.random.default_rng(11)
    fmt = FORMAT[kind]
    c = canvas(fmt, rng)
    if kind == "rgba8888p":
        c.array[..., :3] = np.minimum(c.array[..., :3], c.array[..., 3:])
    before = c.array.copy()
    top = 65535 if dtype == np.uint16 else 255
    cov = rng.integers(0, top + 1, (7, 9)).astype(dtype)
    cov[0, :3] = (0, top, 1)
    rgba = (200, 30, 99, 170)
    color = rgba if fmt in ("rgb888", "rgb565", "rgba8888") else (200, 170)
    want_rgba = rgba if fmt != "gray8" else (200, 200, 200, 170)
    c.composite(cov, color, opacity=0.6, premultiplied=kind == "rgba8888p")
    flat = before.reshape(1, -1) if fmt in ("gray8", "rgb565") else before.reshape(1, -1, before.shape[-1])
    want = expected(kind, to_channels(kind, flat), cov.reshape(1, -1), want_rgba, nearest(Q(0.6) * 255))
    np.testing.assert_array_equal(c.array, from_channels(kind, want).reshape(before.shape))


@pytest.mark.parametrize("fmt, kwargs", [
    ("rgb888", dict(coverage=np.zeros((7, 8), np.uint8))), ("rgb888", dict(coverage=np.zeros((7, 9), np.int32))),
    ("rgb888", dict(premultiplied=True)), ("rgba8888", dict(premultiplied=1)), ("mono1", dict()),
    ("rgb888", dict(opacity=2)),
])
def test_canvas_composite_bad_input(fmt, kwargs):
    c = rastrum.Canvas((7, 9), format=fmt, background=0 if fmt == "mono1" else 5)
    before = (c.packed if fmt == "mono1" else c.array).copy()
    args = dict(coverage=np.full((7, 9), 255, np.uint8))
    args.update(kwargs)
    with pytest.raises(rastrum.InputError, match="Canvas.composite"):
        c.composite(args.pop("coverage"), (1, 2, 3, 4)[:4 if fmt == "rgba8888" else 3] if fmt != "mono1" else 1,
                    **args)
    np.testing.assert_array_equal(c.packed if fmt == "mono1" else c.array, before)

"""Opacity on shaded fills (docs/opacity.md "Shaded fills"):
``fill_triangles(..., vertex_colors=..., opacity=...)`` binary and with
``aa``, rast_fill_triangles_shaded_blend / rast_fill_triangles_shaded_aa_blend.

The expected pixels come from references written here and in the shaded
oracles, in rational arithmetic, independently of the C code:

- the colour each pixel gets: oracle_shade.shade (binary: ownership from
  the binary oracle, the barycentric value at the sample, floor(v + 1/2),
  every channel, alpha too), test_shaded_aa.reference_colors (aa: the
  binary colour where a triangle owns the sample, else the last touching
  triangle's plane) with the coverage held against the exact oracles;
- source-over (`over` below, from docs/opacity.md): the alpha level
  A = round(alpha o c / 255^2) of the exact product, then each channel the
  nearest level to the exact mix (s A + d (255 - A)) / 255 (rgb565 on its
  5/6/5 fields with s's top bits), straight rgba8888 the exact straight
  colour of the mix rounded half up and alpha (255 A + a (255 - A)) / 255
  rounded; A = 0 leaves the pixel.  Binary fills blend triangle by
  triangle in batch order (c = 255); aa fills blend each pixel once at its
  union coverage c.
"""

import math
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_shade
import rastrum
import strategies as S_
from test_shaded_aa import checked_coverage, reference_colors

FORMATS = ["gray8", "rgb888", "rgb565", "rgba8888"]
METHODS = ["area", "ss4", "accumulate"]


def _near(q):
    """floor(q + 1/2) of a Fraction."""
    return math.floor(q + F(1, 2))


def over(fmt, d, s, o, c):
    """Pixel value d (gray8 int, rgb888 (3,), rgb565 int, rgba8888 (4,))
    after the straight colour s = (R, G, B, A) at opacity level o and
    coverage level c (0..255), as docs/opacity.md states it."""
    A = _near(F(int(s[3]) * o * c, 255 * 255))
    if A == 0:
        return d

    def mix(sv, dv):
        return _near(F(sv * A + dv * (255 - A), 255))

    if fmt == "gray8":
        return mix(int(s[0]), int(d))
    if fmt == "rgb888":
        return [mix(int(s[k]), int(d[k])) for k in range(3)]
    if fmt == "rgb565":
        d = int(d)
        return (mix(int(s[0]) >> 3, d >> 11) << 11) | (mix(int(s[1]) >> 2, (d >> 5) & 63) << 5) \
            | mix(int(s[2]) >> 3, d & 31)
    a = int(d[3])
    m = 255 * A + a * (255 - A)  # 255 x the exact alpha of the mix
    rgb = [_near(F(int(s[k]) * A * 255 + int(d[k]) * a * (255 - A), m)) for k in range(3)]
    return rgb + [_near(F(255 * A + a * (255 - A), 255))]


def blend_image(fmt, before, rgba, o, cov):
    """`before` (the canvas array) with per-pixel colours rgba (H, W, 4;
    -1: not painted) blended at coverage cov (H, W)."""
    out = before.astype(np.int64).copy()
    h, w = cov.shape
    for j in range(h):
        for i in range(w):
            if rgba[j, i, 0] < 0 or cov[j, i] == 0:
                continue
            out[j, i] = over(fmt, out[j, i], rgba[j, i], o, int(cov[j, i]))
    return out.astype(before.dtype)


def vertex_rgba(fmt, vc):
    """The RGBA each vertex colour of `vc` (N, 3, C) stands for."""
    vc = np.asarray(vc, np.int64)
    out = np.empty(vc.shape[:-1] + (4,), np.int64)
    c = vc.shape[-1]
    out[..., :3] = vc[..., :1] if c in (1, 2) else vc[..., :3]
    out[..., 3] = vc[..., -1] if c in (2, 4) else 255
    return out


def random_canvas(fmt, shape, rng):
    c = rastrum.Canvas(shape, format=fmt)
    a = c.array
    hi = 0xFFFF if fmt == "rgb565" else 255
    a[...] = rng.integers(0, hi + 1, a.shape)
    if fmt == "rgba8888" and rng.integers(0, 2):  # opaque and transparent pixels too
        a[..., 3] = rng.choice([0, 255, 128], a.shape[:2])
    return c


def level_of(opacity):
    return _near(F(opacity) * 255)


def scene(data, n_max=2, size=7):
    shape = data.draw(S_.shapes(size, size), label="shape")
    h, w = shape
    n = data.draw(st.integers(1, n_max), label="n")
    coord = st.one_of(st.floats(-2, max(h, w) + 2, allow_nan=False),
                      st.integers(-1, max(h, w) + 1).map(float))
    tris = np.array(data.draw(st.lists(st.tuples(coord, coord), min_size=3 * n, max_size=3 * n),
                              label="v"), np.float64).reshape(n, 3, 2)
    return shape, tris


def vertex_colours(data, fmt, n):
    """(N, 3, C) vertex colours in one of the spellings fmt takes: with
    alpha ((L, A) on gray8, (R, G, B, A)) or without."""
    with_alpha = data.draw(st.booleans(), label="alpha")
    c = (2 if with_alpha else 1) if fmt == "gray8" else (4 if with_alpha or fmt == "rgba8888" else 3)
    alpha = st.sampled_from([0, 1, 127, 128, 254, 255]) | st.integers(0, 255)
    vals = []
    for _ in range(3 * n):
        v = data.draw(st.lists(st.integers(0, 255), min_size=c, max_size=c), label="vc")
        if c in (2, 4):
            v[-1] = data.draw(alpha, label="a")
        vals.append(v)
    return np.array(vals, np.int64).reshape(n, 3, c)


OPACITY = st.sampled_from([0.0, 1 / 255, 0.5, 0.999, 1.0]) | st.floats(0, 1)


@settings(max_examples=S_.examples(40), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), opacity=st.none() | OPACITY,
       S=st.sampled_from([0, 2, 8]), shading=st.sampled_from(["gouraud", "gouraud", "flat"]),
       seed=st.integers(0, 2 ** 32 - 1))
def test_binary_equals_reference(data, fmt, opacity, S, shading, seed):
    shape, tris = scene(data)
    vc = vertex_colours(data, fmt, len(tris))
    canvas = random_canvas(fmt, shape, np.random.default_rng(seed))
    before = canvas.array.copy()
    canvas.fill_triangles(tris, vertex_colors=vc, opacity=opacity, shading=shading, subpixel_bits=S)
    rgba = vertex_rgba(fmt, vc)
    if opacity is None and fmt == "rgba8888":  # no opacity: rgba8888 stores the colour, alpha too
        want = before.copy()
        for k in range(len(tris)):
            ref, _ = oracle_shade.shade(tris[k:k + 1], rgba[k:k + 1], shape, subpixel_bits=S,
                                        precision="flat" if shading == "flat" else "exact")
            want = np.where(ref >= 0, ref, want)
        np.testing.assert_array_equal(canvas.array, want)
        return
    o = 255 if opacity is None else level_of(opacity)
    want = before
    for k in range(len(tris)):  # triangle by triangle, in batch order
        ref, _ = oracle_shade.shade(tris[k:k + 1], rgba[k:k + 1], shape, subpixel_bits=S,
                                    precision="flat" if shading == "flat" else "exact")
        want = blend_image(fmt, want, ref, o, np.full(shape, 255))
    np.testing.assert_array_equal(canvas.array, want)


@settings(max_examples=S_.examples(25), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       opacity=OPACITY, S=st.sampled_from([2, 8]), shading=st.sampled_from(["gouraud", "flat"]),
       seed=st.integers(0, 2 ** 32 - 1))
def test_aa_equals_reference(data, fmt, method, opacity, S, shading, seed):
    shape, tris = scene(data, size=6)
    vc = vertex_colours(data, fmt, len(tris))
    canvas = random_canvas(fmt, shape, np.random.default_rng(seed))
    before = canvas.array.copy()
    canvas.fill_triangles(tris, vertex_colors=vc, opacity=opacity, shading=shading, subpixel_bits=S,
                          aa=method)
    cov = checked_coverage(tris, shape, method, S, 0.5)
    ref = reference_colors(tris, vertex_rgba(fmt, vc), shape, S, 0.5, shading, cov)
    np.testing.assert_array_equal(canvas.array, blend_image(fmt, before, ref, level_of(opacity), cov))


@settings(max_examples=S_.examples(20), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), aa=st.sampled_from([None, "area"]),
       precision=st.sampled_from(["exact", "fixed"]), seed=st.integers(0, 2 ** 32 - 1))
def test_opacity_one_is_todays_fill(data, fmt, aa, precision, seed):
    """opacity=1 with opaque vertex colours: bit for bit the fill without
    opacity (rgba8888: over opaque pixels, where source-over is a copy)."""
    if aa is not None and precision == "fixed":
        precision = "exact"
    shape, tris = scene(data, n_max=3, size=9)
    n = len(tris)
    c = 1 if fmt == "gray8" else 3
    vc = np.array(data.draw(st.lists(st.integers(0, 255), min_size=3 * n * c, max_size=3 * n * c),
                            label="vc")).reshape(n, 3, c)
    a = random_canvas(fmt, shape, np.random.default_rng(seed))
    if fmt == "rgba8888":
        a.array[..., 3] = 255
    b = rastrum.Canvas.wrap(a.array.copy(), fmt)
    a.fill_triangles(tris, vertex_colors=vc, precision=precision, aa=aa)
    b.fill_triangles(tris, vertex_colors=vc, precision=precision, aa=aa, opacity=1.0)
    np.testing.assert_array_equal(a.array, b.array)


def test_fixed_precision_blends_the_fixed_colours():
    """precision="fixed": the colours the stored fixed-point fill gives
    (on an rgba8888 canvas), blended by the reference."""
    tris = np.array([[(0.3, 0.2), (30.6, 4.1), (9.2, 17.9)], [(31, 18), (2.5, 16.5), (28.0, 0.5)]])
    vc = np.array([[(255, 0, 9, 255), (0, 200, 60, 40), (30, 90, 255, 180)],
                   [(10, 250, 4, 0), (120, 0, 255, 255), (90, 90, 90, 128)]])
    for F_ in (4, 9):
        colours = []
        for k in range(2):
            s = rastrum.Canvas((18, 32), format="rgba8888")
            s.array[...] = 0
            s.fill_triangles(tris[k:k + 1], vertex_colors=vc[k:k + 1], precision="fixed", fraction_bits=F_)
            owned = rastrum.triangles_mask(tris[k:k + 1], (18, 32))
            colours.append(np.where(owned[..., None], s.array.astype(np.int64), -1))
        c = random_canvas("rgb888", (18, 32), np.random.default_rng(F_))
        want = c.array.copy()
        c.fill_triangles(tris, vertex_colors=vc[..., [0, 1, 2, 3]], precision="fixed", fraction_bits=F_,
                         opacity=0.75)
        for k in range(2):
            want = blend_image("rgb888", want, colours[k], level_of(0.75), np.full((18, 32), 255))
        np.testing.assert_array_equal(c.array, want)


def test_fill_triangle_takes_opacity():
    tri = [(0.5, 0.25), (7.75, 2.0), (1.0, 5.5)]
    vc = [(255, 0, 0, 200), (0, 255, 0, 100), (0, 0, 255, 255)]
    for aa in (None, "area"):
        a = rastrum.Canvas((6, 8), format="rgb888", background=(40, 50, 60))
        b = rastrum.Canvas((6, 8), format="rgb888", background=(40, 50, 60))
        a.fill_triangle(tri, vertex_colors=vc, opacity=0.6, aa=aa)
        b.fill_triangles([tri], vertex_colors=[vc], opacity=0.6, aa=aa)
        np.testing.assert_array_equal(a.array, b.array)
        assert (a.array != 40).any()


@pytest.mark.parametrize("fmt,kwargs,message", [
    ("rgb888", {"opacity": 1.5}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": -0.1}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": float("nan")}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": True}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": "half"}, "opacity must be a number in 0..1"),
    ("mono1", {"opacity": 0.5}, "opacity is for gray8, rgb888, rgb565 and rgba8888"),
    ("rgb888", {"opacity": 0.5, "depth": [[1, 2, 3]]}, "depth"),
    ("rgb888", {"opacity": 0.5, "vertex_colors": [[(1, 2, 3, 4, 5)] * 3]}, "channels"),
    ("rgb888", {"opacity": 0.5, "vertex_colors": [[(1, 2, 300)] * 3]}, "0..255"),
    ("gray8", {"vertex_colors": [[(1, 256)] * 3]}, "0..255"),
    ("rgb888", {"opacity": 0.5, "aa": "area", "precision": "fixed"}, "precision"),
    ("rgb888", {"opacity": 0.5, "gamma": 2.2}, "opacity and gamma are for one colour"),
])
def test_bad_input_writes_nothing(fmt, kwargs, message):
    c = rastrum.Canvas((5, 6), format=fmt)
    if fmt != "mono1":
        c.array[...] = 7
    before = c.array.copy()
    kw = {"vertex_colors": [[(255, 0, 0), (0, 255, 0), (0, 0, 255)]] if fmt != "gray8" else [[(9, 3)] * 3]}
    kw.update(kwargs)
    with pytest.raises(rastrum.InputError, match=message):
        c.fill_triangles([[(0, 0), (6, 0), (0, 5)]], **kw)
    np.testing.assert_array_equal(c.array, before)


def test_c_errors_before_writing():
    """The C entries refuse a format without the blend, a bad opacity and
    a bad premultiplied flag before writing anything (rastrum.h)."""
    from rastrum._native import ffi, lib

    buf = np.full((4, 4), 9, np.uint8)
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": 4, "height": 4, "stride": 4,
                                  "format": lib.RAST_FORMAT_GRAY8, "clip": {"x0": 0, "y0": 0, "x1": 4, "y1": 4}})
    tris = ffi.new("rast_point[3]", [{"x": 0, "y": 0}, {"x": 4 << 8, "y": 0}, {"x": 0, "y": 4 << 8}])
    cols = ffi.new("uint8_t[12]", [200] * 12)
    topts = ffi.new("rast_tri_opts *", {"algorithm": lib.RAST_TRI_EDGE, "subpixel_bits": 8, "sample": lib.RAST_SAMPLE_CENTER})
    copts = ffi.new("rast_coverage_opts *", {"method": lib.RAST_AA_AREA, "subpixel_bits": 8,
                                             "sample": lib.RAST_SAMPLE_CENTER})
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    need = ffi.new("size_t *")
    assert lib.rast_shaded_aa_scratch_size(copts, 1, 4, 4, need) == lib.RAST_OK
    scratch = ffi.new("unsigned char[]", max(need[0], 1 << 16))
    for opacity, premul, status in ((256, 0, lib.RAST_E_ARG), (-1, 0, lib.RAST_E_ARG), (128, 2, lib.RAST_E_ARG)):
        b = ffi.new("rast_blend_opts *", {"opacity": opacity, "premultiplied": premul})
        assert lib.rast_fill_triangles_shaded_blend(t, tris, 1, cols, topts, sh, b, scratch,
                                                    len(scratch)) == status
        assert lib.rast_fill_triangles_shaded_aa_blend(t, tris, 1, cols, copts, sh, b, scratch,
                                                       len(scratch)) == status
    assert (buf == 9).all()
    b = ffi.new("rast_blend_opts *", {"opacity": 128, "premultiplied": 0})
    t.format = lib.RAST_FORMAT_MONO1
    assert lib.rast_fill_triangles_shaded_blend(t, tris, 1, cols, topts, sh, b, scratch,
                                                len(scratch)) == lib.RAST_E_FORMAT
    assert (buf == 9).all()
    t.format = lib.RAST_FORMAT_GRAY8
    assert lib.rast_fill_triangles_shaded_blend(t, tris, 1, cols, topts, sh, b, scratch,
                                                len(scratch)) == lib.RAST_OK
    assert buf[0, 0] == over("gray8", 9, (200, 200, 200, 200), 128, 255)


def over_premultiplied(d, s, o, c):
    """Premultiplied rgba8888 pixel d after the colour s (straight R, G, B,
    A) at opacity o, coverage c (rastrum.h rast_blend_opts): each channel
    the nearest level to (v A + d (255 - A)) / 255 with v the straight
    colour channel, alpha with v = 255."""
    A = _near(F(int(s[3]) * o * c, 255 * 255))
    if A == 0:
        return d
    src = [int(s[0]), int(s[1]), int(s[2]), 255]
    return [_near(F(src[k] * A + int(d[k]) * (255 - A), 255)) for k in range(4)]


@settings(max_examples=S_.examples(15), deadline=None)
@given(data=st.data(), o=st.integers(0, 255), aa=st.booleans(), seed=st.integers(0, 2 ** 32 - 1))
def test_c_premultiplied_rgba8888(data, o, aa, seed):
    """The C entries with premultiplied = 1 (the Canvas composites
    straight): the reference colours, blended premultiplied."""
    from rastrum._native import ffi, lib

    h, w = 5, 6
    pts = data.draw(st.lists(st.tuples(st.integers(-256, 7 * 256), st.integers(-256, 6 * 256)),
                             min_size=3, max_size=3), label="pts")
    vc = np.array(data.draw(st.lists(st.integers(0, 255), min_size=12, max_size=12), label="vc"),
                  np.int64).reshape(1, 3, 4)
    rng = np.random.default_rng(seed)
    buf = rng.integers(0, 256, (h, w, 4), dtype=np.uint8)
    before = buf.copy()
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": w, "height": h, "stride": 4 * w,
                                  "format": lib.RAST_FORMAT_RGBA8888,
                                  "clip": {"x0": 0, "y0": 0, "x1": w, "y1": h}})
    tris = ffi.new("rast_point[3]", [{"x": x, "y": y} for x, y in pts])
    cols = ffi.new("uint8_t[12]", [int(v) for v in vc.ravel()])
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    b = ffi.new("rast_blend_opts *", {"opacity": o, "premultiplied": 1})
    scratch = ffi.new("unsigned char[]", 1 << 16)
    tri = np.array([[(x / 256, y / 256) for x, y in pts]])
    if aa:
        copts = ffi.new("rast_coverage_opts *", {"method": lib.RAST_AA_AREA, "subpixel_bits": 8,
                                                 "sample": lib.RAST_SAMPLE_CENTER})
        assert lib.rast_fill_triangles_shaded_aa_blend(t, tris, 1, cols, copts, sh, b, scratch,
                                                       len(scratch)) == lib.RAST_OK
        cov = checked_coverage(tri, (h, w), "area", 8, 0.5)
        ref = reference_colors(tri, vc, (h, w), 8, 0.5, "gouraud", cov)
    else:
        topts = ffi.new("rast_tri_opts *", {"algorithm": lib.RAST_TRI_EDGE, "subpixel_bits": 8,
                                            "sample": lib.RAST_SAMPLE_CENTER})
        assert lib.rast_fill_triangles_shaded_blend(t, tris, 1, cols, topts, sh, b, scratch,
                                                    len(scratch)) == lib.RAST_OK
        cov = np.full((h, w), 255)
        ref, _ = oracle_shade.shade(tri, vc, (h, w))
    want = before.astype(np.int64)
    for j in range(h):
        for i in range(w):
            if ref[j, i, 0] >= 0 and cov[j, i]:
                want[j, i] = over_premultiplied(want[j, i], ref[j, i], o, int(cov[j, i]))
    np.testing.assert_array_equal(buf, want)


# ---- Gouraud rectangles and colour polygons (fill_rect_gouraud, -------------
# ---- fill_polygon(vertex_colors=)): rast_fill_rect_gouraud_blend, -----------
# ---- rast_fill_polygon_gouraud_blend -----------------------------------------

import oracle_shading
from oracle import oracle_mask


def colours_2d(data, fmt, n, with_alpha=None):
    """(n, C) colours in one of the spellings fmt takes, with alpha ((L, A)
    on gray8, (R, G, B, A)) or without (with_alpha None: either), as
    vertex_colours draws them."""
    if with_alpha is None:
        with_alpha = data.draw(st.booleans(), label="alpha")
    c = (2 if with_alpha else 1) if fmt == "gray8" else (4 if with_alpha or fmt == "rgba8888" else 3)
    alpha = st.sampled_from([0, 1, 127, 128, 254, 255]) | st.integers(0, 255)
    vals = []
    for _ in range(n):
        v = data.draw(st.lists(st.integers(0, 255), min_size=c, max_size=c), label="vc")
        if c in (2, 4):
            v[-1] = data.draw(alpha, label="a")
        vals.append(v)
    return np.array(vals, np.int64).reshape(n, c)


def rgba_2d(vc):
    """The RGBA (n, 4) each (n, C) colour stands for."""
    return vertex_rgba(None, np.asarray(vc)[None])[0]


def expected(fmt, before, ref, painted, opacity, stored):
    """`before` with the pixels `painted` (H, W) given the RGBA ref (H, W, 4):
    stored as rgba8888 stores them, or blended by the reference."""
    if stored:  # rgba8888 without opacity: the colour, alpha too
        return np.where(painted[..., None], ref, before).astype(before.dtype)
    rgba = np.where(painted[..., None], ref.astype(np.int64), -1)
    o = 255 if opacity is None else level_of(opacity)
    return blend_image(fmt, before, rgba, o, np.full(painted.shape, 255))


@settings(max_examples=S_.examples(20), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), opacity=st.none() | OPACITY,
       precision=st.sampled_from(["exact", "exact", "fixed", "flat"]), S=st.sampled_from([0, 2, 8]),
       seed=st.integers(0, 2 ** 32 - 1))
def test_rect_equals_reference(data, fmt, opacity, precision, S, seed):
    h, w = data.draw(S_.shapes(7, 8), label="shape")
    coord = st.one_of(st.floats(-2, 10, allow_nan=False), st.integers(-1, 9).map(float))
    rect = data.draw(st.tuples(coord, coord, coord, coord), label="rect")
    F_ = data.draw(st.integers(1, 16), label="F")
    vc = colours_2d(data, fmt, 4)
    canvas = random_canvas(fmt, (h, w), np.random.default_rng(seed))
    before = canvas.array.copy()
    shading = {"shading": "flat"} if precision == "flat" else {"precision": precision}
    canvas.fill_rect_gouraud(rect, vc, fraction_bits=F_, subpixel_bits=S, opacity=opacity, **shading)
    x0, y0, x1, y1 = rect
    painted = oracle_mask([[(x0, y0), (x1, y0), (x1, y1), (x0, y1)]], (h, w), subpixel_bits=S)
    ref = oracle_shading.rect_gouraud(rect, rgba_2d(vc), (h, w), precision=precision, fraction_bits=F_,
                                      subpixel_bits=S)
    np.testing.assert_array_equal(
        canvas.array, expected(fmt, before, ref, painted, opacity, opacity is None and fmt == "rgba8888"))


@settings(max_examples=S_.examples(20), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), opacity=st.none() | OPACITY,
       rule=st.sampled_from(["evenodd", "nonzero"]), shading=st.sampled_from(["gouraud", "gouraud", "flat"]),
       S=st.sampled_from([0, 2, 8]), seed=st.integers(0, 2 ** 32 - 1))
def test_polygon_equals_reference(data, fmt, opacity, rule, shading, S, seed):
    h, w = data.draw(S_.shapes(7, 8), label="shape")
    coord = st.one_of(st.floats(-2, 10, allow_nan=False), st.integers(-1, 9).map(float))
    nrings = data.draw(st.integers(1, 2), label="nrings")
    rings = [data.draw(st.lists(st.tuples(coord, coord), min_size=3, max_size=6), label="ring")
             for _ in range(nrings)]
    n = sum(len(r) for r in rings)
    # with opacity, alpha too: A = round(alpha o / 255) is rounded only when
    # neither is 255 (opacity without alpha: test_rect_equals_reference)
    vc = colours_2d(data, fmt, n, True if opacity is not None else None)
    canvas = random_canvas(fmt, (h, w), np.random.default_rng(seed))
    before = canvas.array.copy()
    canvas.fill_polygon([np.array(r, np.float64) for r in rings], vertex_colors=vc, rule=rule, shading=shading,
                        subpixel_bits=S, opacity=opacity)
    painted = oracle_mask(rings, (h, w), rule=rule, subpixel_bits=S)
    rgba = rgba_2d(vc)
    if shading == "flat":
        ref = np.broadcast_to(rgba[0], (h, w, 4))
    else:
        ref = oracle_shading.polygon_gouraud(rings, rgba, (h, w), rule=rule, subpixel_bits=S)
    np.testing.assert_array_equal(
        canvas.array, expected(fmt, before, ref, painted, opacity, opacity is None and fmt == "rgba8888"))


@settings(max_examples=S_.examples(15), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), which=st.sampled_from(["rect", "tris", "polygon"]),
       precision=st.sampled_from(["exact", "fixed"]), seed=st.integers(0, 2 ** 32 - 1))
def test_rect_polygon_opacity_one_is_todays_fill(data, fmt, which, precision, seed):
    """opacity=1 with opaque colours: bit for bit the fill without opacity
    (rgba8888: over opaque pixels)."""
    c = 1 if fmt == "gray8" else 3
    n = 4 if which != "polygon" else data.draw(st.integers(3, 7), label="n")
    vc = np.array(data.draw(st.lists(st.integers(0, 255), min_size=n * c, max_size=n * c), label="vc")).reshape(n, c)
    pts = data.draw(st.lists(st.tuples(st.floats(-1, 10, allow_nan=False), st.floats(-1, 9, allow_nan=False)),
                             min_size=n, max_size=n), label="pts")
    a = random_canvas(fmt, (8, 9), np.random.default_rng(seed))
    if fmt == "rgba8888":
        a.array[..., 3] = 255
    b = rastrum.Canvas.wrap(a.array.copy(), fmt)
    for canvas, kw in ((a, {}), (b, {"opacity": 1.0})):
        if which == "polygon":
            canvas.fill_polygon(np.array(pts), vertex_colors=vc, **kw)
        else:
            canvas.fill_rect_gouraud(pts[0] + pts[1], vc, precision=precision,
                                     method="bilinear" if which == "rect" else "triangles", **kw)
    np.testing.assert_array_equal(a.array, b.array)


def test_rect_triangles_method_blends_its_triangles():
    """method="triangles" with opacity: the two triangles' shaded blend."""
    vc = [(255, 0, 0, 200), (0, 255, 0, 100), (0, 0, 255, 255), (90, 90, 9, 0)]
    for fmt, corner in (("rgb888", vc), ("gray8", [(v[0], v[3]) for v in vc])):
        a = rastrum.Canvas((6, 8), format=fmt, background=(40, 50, 60) if fmt == "rgb888" else 40)
        b = rastrum.Canvas((6, 8), format=fmt, background=(40, 50, 60) if fmt == "rgb888" else 40)
        a.fill_rect_gouraud((0.5, 0.25, 7.5, 5.75), corner, method="triangles", opacity=0.6)
        quad = np.array([(0.5, 0.25), (7.5, 0.25), (7.5, 5.75), (0.5, 5.75)])
        split = [(0, 1, 2), (0, 2, 3)]
        b.fill_triangles(quad[split], vertex_colors=np.array(corner)[split], opacity=0.6)
        np.testing.assert_array_equal(a.array, b.array)
        assert (a.array != 40).any()


@pytest.mark.parametrize("which", ["rect", "polygon"])
@pytest.mark.parametrize("fmt,kwargs,message", [
    ("rgb888", {"opacity": 1.5}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": float("nan")}, "opacity must be a number in 0..1"),
    ("rgb888", {"opacity": "half"}, "opacity must be a number in 0..1"),
    ("mono1", {"opacity": 0.5}, "opacity is for gray8, rgb888, rgb565 and rgba8888"),
    ("rgb888", {"opacity": 0.5, "colors": [(1, 2, 3, 4, 5)] * 4}, "C in|channels"),
    ("rgb888", {"opacity": 0.5, "colors": [(1, 2, 300)] * 4}, "0..255"),
    ("rgb888", {"colors": [(1, 2, 3, -1)] * 4}, "0..255"),
    ("gray8", {"colors": [(1, 256)] * 4}, "0..255"),
    ("rgb888", {"opacity": 0.5, "colors": [(1, 2, 3, 4)] * 3}, "4|vertices|colour"),
])
def test_rect_polygon_bad_input_writes_nothing(which, fmt, kwargs, message):
    c = rastrum.Canvas((5, 6), format=fmt)
    if fmt != "mono1":
        c.array[...] = 7
    before = c.array.copy()
    kw = dict(kwargs)
    colors = kw.pop("colors", [(255, 0, 0), (0, 255, 0), (0, 0, 255), (9, 9, 9)] if fmt != "gray8"
                    else [(9, 3)] * 4)
    with pytest.raises(rastrum.InputError, match=message):
        if which == "rect":
            c.fill_rect_gouraud((0, 0, 6, 5), colors, **kw)
        else:
            c.fill_polygon([(0, 0), (6, 0), (6, 5), (0, 5)], vertex_colors=colors, **kw)
    np.testing.assert_array_equal(c.array, before)


def test_c_rect_polygon_errors_before_writing():
    """rast_fill_rect_gouraud_blend and rast_fill_polygon_gouraud_blend
    refuse a format without the blend, a bad opacity and a bad
    premultiplied flag before writing anything (rastrum.h)."""
    from rastrum._native import ffi, lib

    buf = np.full((4, 4), 9, np.uint8)
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": 4, "height": 4, "stride": 4,
                                  "format": lib.RAST_FORMAT_GRAY8, "clip": {"x0": 0, "y0": 0, "x1": 4, "y1": 4}})
    pts = ffi.new("rast_point[4]", [{"x": 0, "y": 0}, {"x": 4 << 8, "y": 0}, {"x": 4 << 8, "y": 4 << 8},
                                    {"x": 0, "y": 4 << 8}])
    sizes = ffi.new("uint32_t[1]", [4])
    poly = ffi.new("rast_polygon *", {"points": pts, "ring_sizes": sizes, "nrings": 1})
    cols = ffi.new("uint8_t[16]", [200] * 16)
    topts = ffi.new("rast_tri_opts *", {"algorithm": lib.RAST_TRI_EDGE, "subpixel_bits": 8,
                                        "sample": lib.RAST_SAMPLE_CENTER})
    fopts = ffi.new("rast_fill_opts *", {"algorithm": lib.RAST_ALGO_AET, "subpixel_bits": 8,
                                         "sample": lib.RAST_SAMPLE_CENTER})
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    scratch = ffi.new("unsigned char[]", 1 << 16)

    def both(b):
        return (lib.rast_fill_rect_gouraud_blend(t, pts[0], pts[2], cols, topts, sh, b),
                lib.rast_fill_polygon_gouraud_blend(t, poly, cols, fopts, sh, b, scratch, len(scratch)))

    for opacity, premul in ((256, 0), (-1, 0), (128, 2)):
        assert both(ffi.new("rast_blend_opts *", {"opacity": opacity, "premultiplied": premul})) == \
            (lib.RAST_E_ARG, lib.RAST_E_ARG)
    b = ffi.new("rast_blend_opts *", {"opacity": 128, "premultiplied": 0})
    t.format = lib.RAST_FORMAT_MONO1
    assert both(b) == (lib.RAST_E_FORMAT, lib.RAST_E_FORMAT)
    t.format = lib.RAST_FORMAT_GRAY8
    sh.precision = 99
    assert both(b) == (lib.RAST_E_ARG, lib.RAST_E_ARG)
    assert (buf == 9).all()
    sh.precision = lib.RAST_PRECISION_EXACT
    assert both(b) == (lib.RAST_OK, lib.RAST_OK)  # the polygon over the rectangle's pixels
    once = over("gray8", 9, (200, 200, 200, 200), 128, 255)
    assert (buf == over("gray8", once, (200, 200, 200, 200), 128, 255)).all()


@settings(max_examples=S_.examples(10), deadline=None)
@given(data=st.data(), o=st.integers(0, 255), which=st.sampled_from(["rect", "polygon"]),
       seed=st.integers(0, 2 ** 32 - 1))
def test_c_rect_polygon_premultiplied(data, o, which, seed):
    """premultiplied = 1 (the Canvas composites straight): the reference
    colours blended premultiplied."""
    from rastrum._native import ffi, lib

    h, w = 5, 6
    n = 2 if which == "rect" else 4
    xy = data.draw(st.lists(st.tuples(st.integers(-256, 7 * 256), st.integers(-256, 6 * 256)),
                            min_size=n, max_size=n), label="pts")
    vc = np.array(data.draw(st.lists(st.integers(0, 255), min_size=16, max_size=16), label="vc"),
                  np.int64).reshape(4, 4)
    buf = np.random.default_rng(seed).integers(0, 256, (h, w, 4), dtype=np.uint8)
    before = buf.copy()
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": w, "height": h, "stride": 4 * w,
                                  "format": lib.RAST_FORMAT_RGBA8888,
                                  "clip": {"x0": 0, "y0": 0, "x1": w, "y1": h}})
    pts = ffi.new("rast_point[]", [{"x": x, "y": y} for x, y in xy])
    cols = ffi.new("uint8_t[16]", [int(v) for v in vc.ravel()])
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    b = ffi.new("rast_blend_opts *", {"opacity": o, "premultiplied": 1})
    px = [(F(x, 256), F(y, 256)) for x, y in xy]
    if which == "rect":
        topts = ffi.new("rast_tri_opts *", {"algorithm": lib.RAST_TRI_EDGE, "subpixel_bits": 8,
                                            "sample": lib.RAST_SAMPLE_CENTER})
        assert lib.rast_fill_rect_gouraud_blend(t, pts[0], pts[1], cols, topts, sh, b) == lib.RAST_OK
        rect = (px[0][0], px[0][1], px[1][0], px[1][1])
        ring = [(rect[0], rect[1]), (rect[2], rect[1]), (rect[2], rect[3]), (rect[0], rect[3])]
        ref = oracle_shading.rect_gouraud(rect, vc, (h, w))
    else:
        fopts = ffi.new("rast_fill_opts *", {"algorithm": lib.RAST_ALGO_AET, "subpixel_bits": 8,
                                             "sample": lib.RAST_SAMPLE_CENTER})
        sizes = ffi.new("uint32_t[1]", [4])
        poly = ffi.new("rast_polygon *", {"points": pts, "ring_sizes": sizes, "nrings": 1})
        scratch = ffi.new("unsigned char[]", 1 << 16)
        assert lib.rast_fill_polygon_gouraud_blend(t, poly, cols, fopts, sh, b, scratch,
                                                   len(scratch)) == lib.RAST_OK
        ring = px
        ref = oracle_shading.polygon_gouraud([ring], vc, (h, w))
    painted = oracle_mask([[(float(x), float(y)) for x, y in ring]], (h, w))
    want = before.astype(np.int64)
    for j, i in zip(*np.nonzero(painted)):
        want[j, i] = over_premultiplied(want[j, i], ref[j, i], o, 255)
    np.testing.assert_array_equal(buf, want)

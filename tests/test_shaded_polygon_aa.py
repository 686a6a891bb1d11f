"""Anti-aliased Gouraud rectangles and polygons (issue 34):
``fill_rect_gouraud(rect, corner_colors, aa=...)`` and
rast_fill_polygon_gouraud_aa(_blend) (through the binding's call,
_shading.fill_polygon_gouraud_aa), against references written here from
docs/coverage.md "Shaded rectangles and polygons, anti-aliased" in
rational arithmetic, independent of the C code:

- coverage c: rastrum's polygon_coverage levels (those the fill blends
  with), first held against the exact oracles (oracle_coverage: area within
  half a level of 255 a, ssK bit for bit);
- the colour of a pixel the binary fill paints (oracle_mask): the binary
  shaded polygon's (oracle_shading.polygon_gouraud: edge, then span; a
  rectangle: oracle_shading.rect_gouraud, bilinear at the sample);
- elsewhere (c > 0): over the edges of non-zero length whose closed
  segment meets the closed pixel square (a separating-axis test), the
  point nearest the sample (exact squared distances; the first edge in
  ring order on a tie), the edge's colour there, floor(v + 1/2);
- the blend: test_shaded_aa.blended (a colour stored, as the aa fills
  store one) or test_opacity_shaded.blend_image (alpha and opacity,
  docs/opacity.md), premultiplied rgba8888 by over_premultiplied.
"""

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage
import oracle_shade
import oracle_shading
import rastrum
import strategies as S_
from oracle import oracle_mask, snap
from test_opacity_shaded import (blend_image, colours_2d, level_of, over_premultiplied, random_canvas,
                                 rgba_2d, OPACITY)
from test_shaded_aa import blended

METHODS = ["area", "ss2", "ss4", "accumulate"]
FORMATS = ["gray8", "rgb888", "rgba8888", "rgb565"]


def checked_coverage(rings, shape, method, rule, S, o):
    """rastrum's polygon coverage levels, held against the exact oracles."""
    cov = rastrum.polygon_coverage(rings, shape, rule=rule, method=method, subpixel_bits=S, sample_offset=o)
    if method == "area":
        a = oracle_coverage.coverage_exact(rings, shape, rule=rule, subpixel_bits=S)
        err = np.abs(cov.astype(object) - a * 255)
        assert all(e <= F(1, 2) + F(1, 2 ** 20) for e in err.ravel())
    elif method.startswith("ss"):
        k = int(method[2:])
        want = oracle_coverage.coverage_ss(rings, shape, k, rule=rule, subpixel_bits=S, sample_offset=o)
        np.testing.assert_array_equal(cov, want)
    return cov.astype(np.int64)


def _meets(a, b, i, j):
    """Do the closed segment ab and the closed square [i, i+1] x [j, j+1]
    meet?  Both convex: disjoint iff their projections on x, y or the
    segment's normal are disjoint."""
    sq = [(F(i), F(j)), (F(i + 1), F(j)), (F(i + 1), F(j + 1)), (F(i), F(j + 1))]
    for ax, ay in ((1, 0), (0, 1), (a[1] - b[1], b[0] - a[0])):
        ps = [ax * x + ay * y for x, y in (a, b)]
        qs = [ax * x + ay * y for x, y in sq]
        if max(ps) < min(qs) or max(qs) < min(ps):
            return False
    return True


def rim_colour(pts, edges, cols, i, j, o):
    """The documented colour of a pixel the binary fill does not paint."""
    p = (i + o, j + o)
    best = None
    for ia, ib in edges:
        a, b = pts[ia], pts[ib]
        if a == b or not _meets(a, b, i, j):
            continue
        d = (b[0] - a[0], b[1] - a[1])
        t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] ** 2 + d[1] ** 2)
        t = min(max(t, F(0)), F(1))
        q = (a[0] + t * d[0], a[1] + t * d[1])
        dist = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
        if best is None or dist < best[0]:
            best = (dist, [oracle_shade._round(cols[ia][c] + t * (cols[ib][c] - cols[ia][c])) for c in range(4)])
    assert best is not None, "coverage at (%d, %d) with no edge meeting its square" % (i, j)
    return best[1]


def reference(rings, rgba, shape, rule, S, o, shading, cov, rect=None):
    """(H, W, 4) ints: each pixel's documented colour where cov > 0, -1
    elsewhere.  rect: the binary colours from the rectangle's oracle."""
    h, w = shape
    o = F(o)
    if shading == "flat":
        out = np.broadcast_to(np.asarray(rgba[0], np.int64), (h, w, 4)).copy()
        out[cov == 0] = -1
        return out
    painted = oracle_mask(rings, shape, rule=rule, subpixel_bits=S, sample_offset=float(o))
    if rect is not None:
        binary = oracle_shading.rect_gouraud(rect, rgba, shape, subpixel_bits=S, sample_offset=float(o))
    else:
        binary = oracle_shading.polygon_gouraud(rings, rgba, shape, rule=rule, subpixel_bits=S,
                                                sample_offset=float(o))
    pts, edges = [], []
    for ring in rings:
        base = len(pts)
        pts.extend((F(snap(x, S), 1 << S), F(snap(y, S), 1 << S)) for x, y in ring)
        edges.extend((base + k, base + (k + 1) % len(ring)) for k in range(len(ring)))
    cols = [[int(c) for c in col] for col in rgba]
    out = np.full((h, w, 4), -1, np.int64)
    for j in range(h):
        for i in range(w):
            if cov[j, i] == 0:
                continue
            out[j, i] = binary[j, i] if painted[j, i] else rim_colour(pts, edges, cols, i, j, o)
    return out


def expected(fmt, before, ref, cov, opacity, stored):
    """The documented blend: stored colours as the aa fills blend a value
    (rgba8888 without opacity: every channel, alpha too), else source-over
    at alpha times opacity times coverage."""
    if stored:
        return blended(fmt, before, ref, cov)
    o = 255 if opacity is None else level_of(opacity)
    return blend_image(fmt, before, ref, o, cov)


def fill_polygon_aa(canvas, rings, vc, method, *, rule="evenodd", shading="gouraud", S=8, o=0.5,
                    opacity=None):
    """rast_fill_polygon_gouraud_aa(_blend) of `rings` with the (N, C)
    vertex colours `vc` on `canvas`, through the binding's one call, the
    colours and blend made as Canvas makes a shaded fill's."""
    from rastrum import _core, _shading

    sb = canvas._vertex_blend(vc, opacity, "test", "vertex_colors")
    colors, blend = sb if sb is not None else (_shading.vertex_rgba(vc, canvas.format), None)
    _shading.fill_polygon_gouraud_aa(canvas, rings, colors, method, rule, S, o,
                                     _core.shading_precision(shading, "exact"), blend, "test", {})


def rings_strategy(data, h, w, max_rings=2):
    coord_x = st.one_of(st.floats(-2, w + 2, allow_nan=False), st.integers(-1, w + 1).map(float))
    coord_y = st.one_of(st.floats(-2, h + 2, allow_nan=False), st.integers(-1, h + 1).map(float))
    nrings = data.draw(st.integers(1, max_rings), label="nrings")
    return [data.draw(st.lists(st.tuples(coord_x, coord_y), min_size=3, max_size=6), label="ring")
            for _ in range(nrings)]


@settings(max_examples=S_.examples(40), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       opacity=st.none() | OPACITY, rule=st.sampled_from(["evenodd", "nonzero"]),
       shading=st.sampled_from(["gouraud", "gouraud", "flat"]), S=st.sampled_from([0, 2, 8]),
       o=st.sampled_from([0.5, 0.5, 0.0]), seed=st.integers(0, 2 ** 32 - 1))
def test_polygon_equals_reference(data, fmt, method, opacity, rule, shading, S, o, seed):
    h, w = data.draw(S_.shapes(7, 8), label="shape")
    rings = rings_strategy(data, h, w)
    n = sum(len(r) for r in rings)
    vc = colours_2d(data, fmt, n)
    canvas = random_canvas(fmt, (h, w), np.random.default_rng(seed))
    before = canvas.array.copy()
    fill_polygon_aa(canvas, [np.array(r, np.float64) for r in rings], vc, method, rule=rule, shading=shading,
                    S=S, o=o, opacity=opacity)
    cov = checked_coverage(rings, (h, w), method, rule, S, o)
    ref = reference(rings, rgba_2d(vc), (h, w), rule, S, o, shading, cov)
    stored = opacity is None and (fmt == "rgba8888" or vc.shape[1] in (1, 3))
    np.testing.assert_array_equal(canvas.array, expected(fmt, before, ref, cov, opacity, stored))


@settings(max_examples=S_.examples(30), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       opacity=st.none() | OPACITY, shading=st.sampled_from(["gouraud", "gouraud", "flat"]),
       S=st.sampled_from([0, 2, 8]), seed=st.integers(0, 2 ** 32 - 1))
def test_rect_equals_reference(data, fmt, method, opacity, shading, S, seed):
    """The rectangle: the binary fill's bilinear colour where it paints,
    the bilinear colour at the rectangle's point nearest the sample on the
    rim (its four sides' nearest point is that point)."""
    h, w = data.draw(S_.shapes(7, 8), label="shape")
    cx = st.one_of(st.floats(-2, w + 2, allow_nan=False), st.integers(-1, w + 1).map(float))
    cy = st.one_of(st.floats(-2, h + 2, allow_nan=False), st.integers(-1, h + 1).map(float))
    x0, y0, x1, y1 = rect = data.draw(st.tuples(cx, cy, cx, cy), label="rect")
    vc = colours_2d(data, fmt, 4)
    canvas = random_canvas(fmt, (h, w), np.random.default_rng(seed))
    before = canvas.array.copy()
    canvas.fill_rect_gouraud(rect, vc, shading=shading, subpixel_bits=S, opacity=opacity, aa=method)
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    cov = checked_coverage([ring], (h, w), method, "nonzero", S, 0.5)
    rgba = rgba_2d(vc)
    ref = reference([ring], rgba, (h, w), "nonzero", S, 0.5, shading, cov, rect=rect)
    if shading != "flat":  # on the rim: bilinear at the sample clamped into the rectangle
        g = 1 << S
        X0, Y0, X1, Y1 = (F(snap(v, S), g) for v in rect)
        painted = oracle_mask([ring], (h, w), subpixel_bits=S)
        for j, i in zip(*np.nonzero((cov > 0) & ~painted)):
            if X0 == X1 or Y0 == Y1:
                continue
            u = (min(max(i + F(1, 2), min(X0, X1)), max(X0, X1)) - X0) / (X1 - X0)
            v = (min(max(j + F(1, 2), min(Y0, Y1)), max(Y0, Y1)) - Y0) / (Y1 - Y0)
            want = [oracle_shade._round((1 - u) * (1 - v) * int(rgba[0][c]) + u * (1 - v) * int(rgba[1][c])
                                        + u * v * int(rgba[2][c]) + (1 - u) * v * int(rgba[3][c]))
                    for c in range(4)]
            assert list(ref[j, i]) == want
    stored = opacity is None and (fmt == "rgba8888" or vc.shape[1] in (1, 3))
    np.testing.assert_array_equal(canvas.array, expected(fmt, before, ref, cov, opacity, stored))


def test_rect_interior_is_the_binary_fill_and_bands_join():
    """A 40-row rectangle (three bands of colour): every fully covered
    pixel has the binary fill's colour exactly; fill_rect_gouraud(aa=) is
    the aa colour polygon of the ring;
    method "triangles" is fill_triangles(aa=) of the two triangles."""
    shape = (40, 23)
    rect = (1.25, 0.75, 21.6, 38.3)
    corners = [(250, 10, 30), (10, 240, 30), (0, 20, 250), (200, 200, 200)]
    a = rastrum.Canvas(shape, format="rgb888")
    a.fill_rect_gouraud(rect, corners, aa="area")
    b = rastrum.Canvas(shape, format="rgb888")
    b.fill_rect_gouraud(rect, corners)
    x0, y0, x1, y1 = rect
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    cov = rastrum.polygon_coverage([ring], shape, method="area")
    full = cov == 255
    assert full.sum() > 600
    np.testing.assert_array_equal(a.array[full], b.array[full])
    c = rastrum.Canvas(shape, format="rgb888")
    fill_polygon_aa(c, ring, np.array(corners), "area")
    np.testing.assert_array_equal(a.array, c.array)
    d = rastrum.Canvas(shape, format="rgb888")
    d.fill_rect_gouraud(rect, corners, aa="ss4", method="triangles")
    e = rastrum.Canvas(shape, format="rgb888")
    quad = np.array(ring)
    e.fill_triangles(quad[[(0, 1, 2), (0, 2, 3)]], vertex_colors=np.array(corners)[[(0, 1, 2), (0, 2, 3)]],
                     aa="ss4")
    np.testing.assert_array_equal(d.array, e.array)
    assert d.array.any()


def test_triangle_ring_is_the_triangle():
    """A ring of three vertices owns the pixels and colours of the
    Gouraud triangle (its edge-then-span value is the plane's), so where
    the triangle's silhouette rule and the polygon's agree, so do they:
    every pixel painted by the binary fill."""
    tri = [(0.7, 0.4), (9.3, 2.2), (3.1, 8.6)]
    vc = [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    a = rastrum.Canvas((9, 10), format="rgb888")
    fill_polygon_aa(a, tri, np.array(vc), "area", rule="nonzero")
    b = rastrum.Canvas((9, 10), format="rgb888")
    b.fill_triangle(tri, vertex_colors=vc, aa="area")
    painted = oracle_mask([tri], (9, 10), rule="nonzero")
    np.testing.assert_array_equal(a.array[painted], b.array[painted])
    assert painted.sum() > 20


@settings(max_examples=S_.examples(10), deadline=None)
@given(data=st.data(), o=st.integers(0, 255), seed=st.integers(0, 2 ** 32 - 1))
def test_c_premultiplied_rgba8888(data, o, seed):
    """rast_fill_polygon_gouraud_aa_blend with premultiplied = 1 (the
    Canvas composites straight): the reference colours, blended
    premultiplied at each pixel's coverage."""
    from rastrum._native import ffi, lib

    h, w = 5, 6
    n = data.draw(st.integers(3, 5), label="n")
    pts = data.draw(st.lists(st.tuples(st.integers(-256, 7 * 256), st.integers(-256, 6 * 256)),
                             min_size=n, max_size=n), label="pts")
    vc = np.array(data.draw(st.lists(st.integers(0, 255), min_size=4 * n, max_size=4 * n), label="vc"),
                  np.int64).reshape(n, 4)
    buf = np.random.default_rng(seed).integers(0, 256, (h, w, 4), dtype=np.uint8)
    before = buf.copy()
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": w, "height": h, "stride": 4 * w,
                                  "format": lib.RAST_FORMAT_RGBA8888,
                                  "clip": {"x0": 0, "y0": 0, "x1": w, "y1": h}})
    cpts = ffi.new("rast_point[]", [{"x": x, "y": y} for x, y in pts])
    sizes = ffi.new("uint32_t[1]", [n])
    poly = ffi.new("rast_polygon *", {"points": cpts, "ring_sizes": sizes, "nrings": 1})
    cols = ffi.new("uint8_t[]", [int(v) for v in vc.ravel()])
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    b = ffi.new("rast_blend_opts *", {"opacity": o, "premultiplied": 1})
    copts = ffi.new("rast_coverage_opts *", {"method": lib.RAST_AA_AREA, "rule": lib.RAST_RULE_EVENODD,
                                             "subpixel_bits": 8, "sample": lib.RAST_SAMPLE_CENTER})
    need = ffi.new("size_t *")
    assert lib.rast_polygon_gouraud_aa_scratch_size(copts, n, w, h, need) == lib.RAST_OK
    scratch = ffi.new("unsigned char[]", need[0])
    assert lib.rast_fill_polygon_gouraud_aa_blend(t, poly, cols, copts, sh, b, scratch, need[0]) == lib.RAST_OK
    ring = [(x / 256, y / 256) for x, y in pts]
    cov = checked_coverage([ring], (h, w), "area", "evenodd", 8, 0.5)
    ref = reference([ring], vc, (h, w), "evenodd", 8, 0.5, "gouraud", cov)
    want = before.astype(np.int64)
    for j in range(h):
        for i in range(w):
            if cov[j, i]:
                want[j, i] = over_premultiplied(want[j, i], ref[j, i], o, int(cov[j, i]))
    np.testing.assert_array_equal(buf, want)


def test_c_errors_before_writing():
    """The C entries check everything before writing: a NULL polygon or
    colours, a format without colour (COUNT16) or without the blend
    (MONO1, blended), a fixed precision, too little scratch."""
    from rastrum._native import ffi, lib

    buf = np.full((4, 4), 9, np.uint8)
    t = ffi.new("rast_target *", {"pixels": ffi.from_buffer(buf), "width": 4, "height": 4, "stride": 4,
                                  "format": lib.RAST_FORMAT_GRAY8, "clip": {"x0": 0, "y0": 0, "x1": 4, "y1": 4}})
    pts = ffi.new("rast_point[3]", [{"x": 0, "y": 0}, {"x": 900, "y": 100}, {"x": 100, "y": 900}])
    sizes = ffi.new("uint32_t[1]", [3])
    poly = ffi.new("rast_polygon *", {"points": pts, "ring_sizes": sizes, "nrings": 1})
    cols = ffi.new("uint8_t[12]", [200] * 12)
    copts = ffi.new("rast_coverage_opts *", {"method": lib.RAST_AA_AREA, "subpixel_bits": 8,
                                             "sample": lib.RAST_SAMPLE_CENTER})
    sh = ffi.new("rast_shade_opts *", {"precision": lib.RAST_PRECISION_EXACT})
    need = ffi.new("size_t *")
    assert lib.rast_polygon_gouraud_aa_scratch_size(copts, 3, 4, 4, need) == lib.RAST_OK
    scratch = ffi.new("unsigned char[]", need[0])
    b = ffi.new("rast_blend_opts *", {"opacity": 128, "premultiplied": 0})
    fill = lib.rast_fill_polygon_gouraud_aa
    assert fill(t, ffi.NULL, cols, copts, sh, scratch, need[0]) == lib.RAST_E_NULL
    assert fill(t, poly, ffi.NULL, copts, sh, scratch, need[0]) == lib.RAST_E_NULL
    assert fill(t, poly, cols, copts, sh, scratch, need[0] - 1) == lib.RAST_E_SCRATCH
    sh.precision = lib.RAST_PRECISION_FIXED
    assert fill(t, poly, cols, copts, sh, scratch, need[0]) == lib.RAST_E_ARG
    sh.precision = lib.RAST_PRECISION_EXACT
    pts[1].x = lib.RAST_COORD_MAX + 1
    assert fill(t, poly, cols, copts, sh, scratch, need[0]) == lib.RAST_E_RANGE
    pts[1].x = 900
    assert lib.rast_fill_polygon_gouraud_aa_blend(t, poly, cols, copts, sh, ffi.new(
        "rast_blend_opts *", {"opacity": 256}), scratch, need[0]) == lib.RAST_E_ARG
    t.format = lib.RAST_FORMAT_MONO1
    assert lib.rast_fill_polygon_gouraud_aa_blend(t, poly, cols, copts, sh, b, scratch, need[0]) == \
        lib.RAST_E_FORMAT
    t.format = lib.RAST_FORMAT_COUNT16
    t.stride = 8
    assert fill(t, poly, cols, copts, sh, scratch, need[0]) == lib.RAST_E_FORMAT
    assert (buf == 9).all()
    t.format, t.stride = lib.RAST_FORMAT_GRAY8, 4
    assert fill(t, poly, cols, copts, sh, scratch, need[0]) == lib.RAST_OK
    assert (buf != 9).any()


@pytest.mark.parametrize("fmt,kwargs,message", [
    ("rgb888", {"aa": "ss3"}, "aa='ss3'"),
    ("rgb888", {"aa": "area", "precision": "fixed"}, "precision"),
    ("rgb888", {"aa": "area", "opacity": 1.5}, "opacity must be a number in 0..1"),
    ("rgb888", {"aa": "area", "colors": [(1, 2, 3, 4, 5)] * 4}, "C in|channels"),
    ("rgb888", {"aa": "area", "colors": [(1, 2, 300)] * 4}, "0..255"),
    ("gray8", {"aa": "area", "colors": [(1, 256)] * 4}, "0..255"),
    ("rgb888", {"aa": "area", "colors": [(1, 2, 3)] * 3}, "4 colours|corner_colors"),
    ("rgb888", {"aa": "area", "subpixel_bits": 17}, "subpixel_bits"),
    ("mono1", {"aa": "area", "opacity": 0.5}, "opacity is for gray8, rgb888, rgb565 and rgba8888"),
])
def test_bad_input_writes_nothing(fmt, kwargs, message):
    c = rastrum.Canvas((5, 6), format=fmt)
    if fmt != "mono1":
        c.array[...] = 7
    before = c.array.copy()
    kw = dict(kwargs)
    colors = kw.pop("colors", [(255, 0, 0), (0, 255, 0), (0, 0, 255), (9, 9, 9)] if fmt != "gray8"
                    else [(9, 3)] * 4)
    with pytest.raises(rastrum.InputError, match=message):
        c.fill_rect_gouraud((0.5, 0.5, 5.5, 4.5), colors, **kw)
    np.testing.assert_array_equal(c.array, before)


def test_polygon_count_and_options_checked_before_writing():
    c = rastrum.Canvas((5, 6), format="rgb888", background=7)
    before = c.array.copy()
    with pytest.raises(rastrum.InputError, match="3 colours for 4 vertices"):
        fill_polygon_aa(c, [(0.5, 0.5), (5.5, 0.5), (5.5, 4.5), (0.5, 4.5)], np.array([(1, 2, 3)] * 3), "area")
    with pytest.raises(rastrum.InputError, match="aa='ss3'"):
        fill_polygon_aa(c, [(0.5, 0.5), (5.5, 0.5), (3, 4.5)], np.array([(1, 2, 3)] * 3), "ss3")
    with pytest.raises(rastrum.InputError, match="rings"):
        fill_polygon_aa(c, [(0.5, 0.5), (5.5, float("nan")), (3, 4.5)], np.array([(1, 2, 3)] * 3), "area")
    np.testing.assert_array_equal(c.array, before)

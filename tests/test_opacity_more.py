"""Opacity, continued (docs/opacity.md): the linear-light blend in the core
(rast_blend_coverage_linear) for every format, and `opacity=` / a
colour's alpha on the Canvas calls beyond the polygon and triangle fills:
lines (binary, wide, anti-aliased, polylines), seed fills and shaded fills.

Every result is held against an oracle written here from docs/opacity.md:
the alpha level and the stored-level mix from test_opacity.py's exact
rational oracle; the linear-light mix by a scan of every level for the one
whose table value is nearest the exact mix (integers scaled by the
denominator, so exact), ties to the lower; the pixels a call covers from
the opaque call's own footprint (line_pixels, polygon_mask, the seed's
connected region computed here by a breadth-first walk).
"""

import functools
import itertools
import math
from collections import deque
from fractions import Fraction as Q

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from rastrum import _core
from rastrum._native import ffi, lib
from test_opacity import (FORMAT, canvas, canvas_expected, from_channels, level, nearest,
                          to_channels)

TOPS = {"gray8": [255], "rgb888": [255] * 3, "rgb565": [31, 63, 31], "rgba8888": [255] * 4}


# ---- linear light in the core --------------------------------------------------

@functools.lru_cache(maxsize=None)
def table(gamma, n):
    """round(2^24 decode(k / n)) for k = 0..n: the stated tables."""
    def decode(v):
        if gamma == "srgb":
            return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4
        return v ** gamma
    return tuple(math.floor((1 << 24) * decode(k / n) + 0.5) for k in range(n + 1))


@functools.lru_cache(maxsize=None)
def as_array(dec):
    return np.array(dec, np.int64)


def nearest_level(dec, num, den):
    """The level k whose dec[k] is nearest num / den, the lower on a tie (a
    scan of every level, exact in integers: den dec[k] and num < 2^62;
    argmin gives the first of equal distances)."""
    assert 0 <= num < 1 << 62 and 0 < den < 1 << 30
    return int(np.abs(den * as_array(dec) - num).argmin())


def linear_pixel(kind, gamma, rgba, d, a):
    if a == 0:
        return d
    if kind == "rgb565":
        src = (rgba[0] >> 3, rgba[1] >> 2, rgba[2] >> 3)
        decs = (table(gamma, 31), table(gamma, 63), table(gamma, 31))
        return tuple(nearest_level(decs[k], decs[k][src[k]] * a + decs[k][d[k]] * (255 - a), 255)
                     for k in range(3))
    dec = table(gamma, 255)
    if kind in ("gray8", "rgb888"):
        return tuple(nearest_level(dec, dec[rgba[k]] * a + dec[d[k]] * (255 - a), 255) for k in range(len(d)))
    # straight rgba8888: the linear colour of the exact source-over; alpha in stored levels
    a_s, a_d = Q(a, 255), Q(d[3], 255)
    out = a_s + a_d * (1 - a_s)
    colour = tuple(nearest_level(dec, *(lambda q: (q.numerator, q.denominator))(
        (dec[rgba[k]] * a_s + dec[d[k]] * a_d * (1 - a_s)) / out)) for k in range(3))
    return colour + (nearest(out * 255),)


def gamma_cdata(gamma):
    g = ffi.new("rast_gamma *")
    g.dec8, g.dec6, g.dec5 = table(gamma, 255), table(gamma, 63), table(gamma, 31)
    return g


def core_linear(kind, dest, cov, rgba, opacity, g, premultiplied=0):
    arr = from_channels(kind, dest)
    target = _core.make_target(arr, _core.FORMATS[FORMAT[kind]])
    opts = ffi.new("rast_blend_opts *", {"opacity": opacity, "premultiplied": premultiplied})
    fmt = lib.RAST_COVERAGE_U16 if cov.dtype == np.uint16 else lib.RAST_COVERAGE_U8
    status = lib.rast_blend_coverage_linear(target, ffi.from_buffer(cov), fmt, cov.shape[1] * cov.itemsize,
                                            bytes(rgba), opts, g)
    return status, to_channels(kind, arr)


GAMMAS = ["srgb", 2.2, 0.5]
KINDS = ["gray8", "rgb888", "rgb565", "rgba8888"]


@pytest.mark.parametrize("kind", KINDS)
def test_linear_core_every_destination(kind):
    """Every destination level of each channel (rgba8888: with several
    alphas), several sources, alphas and coverage levels of both widths."""
    top = TOPS[kind]
    n = max(top) + 1
    dest = [tuple(min(k, t) for t in top[:3]) + ((0, 1, 128, 255)[k % 4],) * (kind == "rgba8888") for k in range(n)]
    full = settings.default.max_examples >= 100
    for gamma in GAMMAS[:1 + full + (kind != "rgba8888")]:
        g = gamma_cdata(gamma)
        for (src, alpha, opacity), (dtype, c) in itertools.product(
                [((0, 0, 0), 255, 255), ((255, 255, 255), 128, 255), ((200, 17, 90), 254, 127), ((1, 128, 254), 60, 200)],
                [(np.uint8, 255), (np.uint8, 77), (np.uint16, 30001)]):
            rgba = src + (alpha,)
            cov = np.full((1, n), c, dtype)
            status, got = core_linear(kind, dest, cov, rgba, opacity, g)
            assert status == lib.RAST_OK
            a = level(alpha, opacity, c, 65535 if dtype == np.uint16 else 255)
            rgba_k = rgba if kind != "gray8" else (src[0],) * 3 + (alpha,)
            assert got == [linear_pixel(kind, gamma, rgba_k, d, a) for d in dest], (gamma, rgba, c)


@settings(max_examples=S_.examples(40))
@given(data=st.data(), kind=st.sampled_from(KINDS), wide=st.booleans(), gamma=st.sampled_from(GAMMAS),
       rgba=st.tuples(*[st.integers(0, 255)] * 4), opacity=st.integers(0, 255))
def test_linear_core_random(data, kind, wide, gamma, rgba, opacity):
    n = data.draw(st.integers(1, 12))
    dest = [tuple(data.draw(st.integers(0, t)) for t in TOPS[kind]) for _ in range(n)]
    dtype = np.uint16 if wide else np.uint8
    cov = np.array([data.draw(st.lists(st.integers(0, 65535 if wide else 255), min_size=n, max_size=n))], dtype)
    status, got = core_linear(kind, dest, cov, rgba, opacity, gamma_cdata(gamma))
    assert status == lib.RAST_OK
    full = 65535 if wide else 255
    rgba_k = rgba if kind != "gray8" else (rgba[0],) * 3 + (rgba[3],)
    assert got == [linear_pixel(kind, gamma, rgba_k, d, level(rgba[3], opacity, int(c), full))
                   for d, c in zip(dest, cov[0])]


def test_linear_core_identities():
    """s = d keeps d, A = 255 gives s (gray8, every level, every table)."""
    for gamma in GAMMAS:
        g = gamma_cdata(gamma)
        for s in (0, 3, 128, 255):
            for a in (255, 1, 100):
                _, got = core_linear("gray8", [(s,)] * 3 + [(k,) for k in range(256)],
                                          np.full((1, 259), a, np.uint8), (s, s, s, 255), 255, g)
                assert got[:3] == [(s,)] * 3
                if a == 255:
                    assert got[3:] == [(s,)] * 256


def test_linear_core_errors_write_nothing():
    arr = np.full((2, 3, 4), 9, np.uint8)
    target = _core.make_target(arr, _core.FORMATS["rgba8888"])
    cov = np.full((2, 3), 255, np.uint8)
    c = ffi.from_buffer(cov)
    rgba = bytes((1, 2, 3, 200))
    good = gamma_cdata("srgb")
    flat = gamma_cdata("srgb")
    flat.dec8[7] = flat.dec8[6]  # not strictly increasing
    big = gamma_cdata("srgb")
    big.dec5[31] = (1 << 24) + 1
    pre = ffi.new("rast_blend_opts *", {"opacity": 255, "premultiplied": 1})
    for g, opts, status in [(ffi.NULL, ffi.NULL, lib.RAST_E_NULL), (flat, ffi.NULL, lib.RAST_E_ARG),
                            (big, ffi.NULL, lib.RAST_E_ARG), (good, pre, lib.RAST_E_ARG)]:
        assert lib.rast_blend_coverage_linear(target, c, lib.RAST_COVERAGE_U8, 3, rgba, opts, g) == status
    assert (arr == 9).all()
    assert lib.rast_blend_coverage_linear(target, c, lib.RAST_COVERAGE_U8, 3, rgba, ffi.NULL, good) == lib.RAST_OK
    assert not (arr == 9).all()


def test_linear_python_tables_are_the_stated_ones():
    """The Canvas's tables are the docs' formula, strictly increasing."""
    for gamma in ("srgb", 2.2, 0.3, 3.0):
        g = rastrum._canvas._gamma_tables(gamma, "x")
        for name, n in (("dec8", 255), ("dec6", 63), ("dec5", 31)):
            got = list(getattr(g, name))
            assert got == list(table(gamma, n))
            assert all(p < q for p, q in zip(got, got[1:]))


@pytest.mark.parametrize("kind", KINDS)
def test_linear_canvas_every_format(kind):
    """Canvas.fill_polygon(..., gamma=) on every blend format, binary and
    anti-aliased, against the oracle on polygon_mask / polygon_coverage."""
    rng = np.random.default_rng(5)
    ring = [(0.3, 0.6), (7.7, 1.2), (5.1, 6.9), (1.4, 5.2)]
    for aa in (None, "area"):
        c = canvas(kind, rng)
        before = c.array.copy()
        color = (40, 200) if kind == "gray8" else (250, 128, 3, 200)
        c.fill_polygon(ring, color, aa=aa, opacity=0.9, gamma=2.2)
        cov = (rastrum.polygon_mask(ring, (7, 9)).astype(np.uint8) * 255 if aa is None
               else rastrum.polygon_coverage(ring, (7, 9), method="area"))
        rgba = (40, 40, 40, 200) if kind == "gray8" else color
        flat = before.reshape(1, -1) if kind in ("gray8", "rgb565") else before.reshape(1, -1, before.shape[-1])
        want = [linear_pixel(kind, 2.2, rgba, d, level(rgba[3], nearest(Q(0.9) * 255), int(cv), 255))
                for d, cv in zip(to_channels(kind, flat), cov.reshape(-1))]
        np.testing.assert_array_equal(c.array, from_channels(kind, want).reshape(before.shape))


# ---- lines, polylines, seed fills ------------------------------------------------

SHAPE = (7, 9)
CANVAS_KINDS = ["gray8", "rgb888", "rgb565", "rgba8888"]


def colour_for(kind):
    """(the colour as given, its straight RGBA)."""
    if kind == "gray8":
        return (90, 150), (90, 90, 90, 150)
    return (200, 40, 250, 150), (200, 40, 250, 150)


def footprint(draw):
    """The pixels the opaque call paints: value 1 on a zero gray8 canvas,
    as 255."""
    m = rastrum.Canvas(SHAPE, format="gray8")
    draw(m, 1)
    return (m.array != 0).astype(np.uint8) * 255


LINES = [
    (lambda c, col, **k: c.line((0.5, 0.5), (8.2, 5.9), col, **k), None),
    (lambda c, col, **k: c.polyline([(0.5, 6.5), (8.5, 0.5), (8.5, 6.5), (0.5, 0.5)], col, closed=True, **k), None),
    (lambda c, col, **k: c.line([(1, 1), (7, 5), (2, 5)], fill=col, **k), None),
]
WIDE = [([(0.7, 1.2), (8.1, 5.3), (2.2, 6.1)], 2.5, "round", "area"), ([(0.5, 3.5), (8.5, 3.5)], 3, "bevel", "ss4"),
        ([(1.2, 0.8), (6.6, 6.1)], 1, "bevel", "area")]


@pytest.mark.parametrize("kind", CANVAS_KINDS)
def test_lines_blend(kind):
    """Binary lines and polylines: their pixels (self-crossing and shared
    vertices too) blended once each; wide and anti-aliased lines: the
    stroke's coverage, blended."""
    rng = np.random.default_rng(34)
    color, rgba = colour_for(kind)
    for opacity in (None, 0.4) if kind != "rgba8888" else (0.4,):  # rgba8888 stores a value without opacity
        lv = 255 if opacity is None else nearest(Q(opacity) * 255)
        for draw, _ in LINES:
            c = canvas(kind, rng)
            before = c.array.copy()
            draw(c, color, opacity=opacity)
            cov = footprint(lambda m, v: draw(m, v))
            np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, lv))
        for pts, width, join, aa in WIDE:
            c = canvas(kind, rng)
            before = c.array.copy()
            c.line([(x - 0.5, y - 0.5) for x, y in pts], fill=color, width=width, aa=aa,
                   joint="curve" if join == "round" else None, opacity=opacity)
            outline = rastrum.stroke(pts, width, join=join, cap="butt")
            cov = rastrum.polygon_coverage(outline, SHAPE, rule="nonzero", method=aa)
            np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, lv), err_msg=str(pts))


def test_lines_linear_light():
    rng = np.random.default_rng(3)
    c = canvas("rgb888", rng)
    before = c.array.copy()
    c.polyline([(0.5, 0.5), (8.5, 6.5), (0.5, 6.5)], (255, 255, 255, 140), gamma="srgb")
    cov = footprint(lambda m, v: m.polyline([(0.5, 0.5), (8.5, 6.5), (0.5, 6.5)], v))
    for y, x in np.ndindex(*SHAPE):
        want = linear_pixel("rgb888", "srgb", (255, 255, 255, 140), tuple(int(v) for v in before[y, x]),
                            level(140, 255, int(cov[y, x]), 255))
        assert tuple(c.array[y, x]) == want


@pytest.mark.parametrize("kind", CANVAS_KINDS)
def test_lines_opaque_unchanged(kind):
    """Alpha 255 (or opacity 1): the value's line, bit for bit."""
    color = {"gray8": 200, "rgba8888": (9, 200, 40, 255)}.get(kind, (9, 200, 40))
    alpha = {"gray8": (200, 255), "rgba8888": (9, 200, 40, 255)}.get(kind, (9, 200, 40, 255))
    plain = canvas(kind, np.random.default_rng(1))
    plain.polyline([(0.5, 0.5), (8.5, 6.5), (0.5, 6.5)], color)
    other = canvas(kind, np.random.default_rng(1))
    other.polyline([(0.5, 0.5), (8.5, 6.5), (0.5, 6.5)], alpha, opacity=None if kind == "rgba8888" else 1.0)
    np.testing.assert_array_equal(other.array, plain.array)


def region(arr, seed, inside, connectivity):
    """The pixels connected to seed through pixels where inside[y, x]: a
    breadth-first walk."""
    h, w = inside.shape
    out = np.zeros((h, w), bool)
    x, y = seed
    if not inside[y, x]:
        return out
    steps = [(1, 0), (-1, 0), (0, 1), (0, -1)] + ([(1, 1), (1, -1), (-1, 1), (-1, -1)] if connectivity == 8 else [])
    todo = deque([(x, y)])
    out[y, x] = True
    while todo:
        x, y = todo.popleft()
        for dx, dy in steps:
            u, v = x + dx, y + dy
            if 0 <= u < w and 0 <= v < h and inside[v, u] and not out[v, u]:
                out[v, u] = True
                todo.append((u, v))
    return out


def same_as(arr, value):
    eq = arr == value
    return eq.all(axis=2) if eq.ndim == 3 else eq


@pytest.mark.parametrize("kind", CANVAS_KINDS)
@pytest.mark.parametrize("connectivity", [4, 8])
def test_seed_fills_blend(kind, connectivity):
    """flood_fill: the seed's connected region of its value; boundary_fill:
    the region connected through pixels not of the boundary; each blended
    once (a gray8 (L, A), an RGBA colour, opacity)."""
    rng = np.random.default_rng(connectivity)
    color, rgba = colour_for(kind)
    for _ in range(3):
        c = canvas(kind, rng)
        two = c.array[0, 0].copy(), c.array[0, 1].copy()
        edge = two[0] if kind in ("gray8", "rgb565") else tuple(int(v) for v in two[0])
        if kind == "rgb565":  # the boundary as a colour, its pixel the packed top bits
            edge = (96, 200, 8)
            two = (np.uint16((96 >> 3) << 11 | (200 >> 2) << 5 | 8 >> 3), np.uint16(0x1234))
        pick = rng.integers(0, 2, SHAPE).astype(bool)
        c.array[pick] = two[0]
        c.array[~pick] = two[1]
        before = c.array.copy()
        seed = (int(rng.integers(0, 9)), int(rng.integers(0, 7)))
        c.flood_fill(seed, color, connectivity=connectivity, opacity=0.8)
        cov = region(before, seed, same_as(before, before[seed[1], seed[0]]), connectivity).astype(np.uint8) * 255
        lv = nearest(Q(0.8) * 255)
        np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, lv))
        c.array[...] = before
        c.boundary_fill(seed, color, edge, connectivity=connectivity, opacity=1.0 if kind == "rgba8888" else None)
        cov = region(before, seed, ~same_as(before, two[0]), connectivity).astype(np.uint8) * 255
        np.testing.assert_array_equal(c.array, canvas_expected(kind, before, cov, rgba, 255))


@pytest.mark.parametrize("call", [
    lambda c: c.line((0, 0), (5, 3), (1, 2, 3), opacity=1.5),
    lambda c: c.line((0, 0), (5, 3), (1, 2, 3, 256)),
    lambda c: c.line([(0, 0), (5, 3)], fill=(1, 2, 3), width=3, aa="area", opacity="x"),
    lambda c: c.line([(0, 0), (5, 3)], fill=(1, 2, 3), width=3, gamma="lab"),
    lambda c: c.polyline([(0, 0), (5, 3)], (1, 2, 3), opacity=-0.5),
    lambda c: c.polyline([(0, 0), (5, 3)], "#12345", gamma="srgb"),
    lambda c: c.flood_fill((0, 0), (1, 2, 3), opacity=2),
    lambda c: c.flood_fill((9, 0), (1, 2, 3), opacity=0.5),
    lambda c: c.boundary_fill((0, 0), (1, 2, 3, 4), (1, 2), opacity=0.5),
    lambda c: c.flood_fill((0, 0), (1, 2, 3), gamma=9.0),
])
def test_lines_seed_bad_input(call):
    c = rastrum.Canvas((5, 5), format="rgb888", background=7)
    before = c.array.copy()
    with pytest.raises(rastrum.InputError):
        call(c)
    np.testing.assert_array_equal(c.array, before)


@pytest.mark.parametrize("fmt", ["mono1", "label"])
def test_lines_seed_refuse_opacity_without_colours(fmt):
    c = rastrum.Canvas((5, 5), format=fmt) if fmt == "mono1" else rastrum.Canvas.wrap(np.zeros((5, 5), np.int64),
                                                                                       "label")
    before = (c.packed if fmt == "mono1" else c.array).copy()
    for call in (lambda: c.line((0, 0), (4, 4), 1, opacity=0.5), lambda: c.polyline([(0, 0), (4, 4)], 1, gamma=2.2),
                 lambda: c.flood_fill((0, 0), 1, opacity=0.5), lambda: c.line([(0, 0), (4, 4)], fill=1, width=2,
                                                                              opacity=0.5)):
        with pytest.raises(rastrum.InputError):
            call()
    np.testing.assert_array_equal(c.packed if fmt == "mono1" else c.array, before)


def test_linear_core_ties_go_down():
    """A table of the caller's (any strictly increasing one is taken) with
    exact ties between two levels: the lower level wins (the sRGB and power
    tables almost never tie)."""
    dec = tuple(16 * k * (k + 1) for k in range(256))
    g = ffi.new("rast_gamma *")
    g.dec8, g.dec6, g.dec5 = dec, dec[:64], dec[:32]
    mids = {255 * (dec[k] + dec[k + 1]) for k in range(255)}
    cases = [(s, d, a) for s in range(0, 256, 5) for d in range(256) for a in (1, 3, 17, 51, 85, 170)
             if 2 * (dec[s] * a + dec[d] * (255 - a)) in mids]
    assert len(cases) > 20
    for s, d, a in cases:
        status, got = core_linear("gray8", [(d,)], np.array([[a]], np.uint8), (s, s, s, 255), 255, g)
        want = nearest_level(dec, dec[s] * a + dec[d] * (255 - a), 255)
        assert 2 * 255 * dec[want] < 2 * (dec[s] * a + dec[d] * (255 - a))  # the lower of the two
        assert got == [(want,)], (s, d, a)

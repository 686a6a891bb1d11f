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
from test_opacity import (FORMAT, canvas, canvas_expected, from_channels, level, nearest, pixel,
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
                status, got = core_linear("gray8", [(s,)] * 3 + [(k,) for k in range(256)],
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

"""The whole-array calls' fixed cost (issue 33): polygon_mask of a list of
several rings goes to C in one call (rastrum._core.packed_call, no numpy
form of the points, no scan for the 64-bit path), and polygon_coverage's
float32 output is converted from the 2^-62 integers in one pass
(rastpy_fix62_to_float).  Each must give what the exact oracle gives, take
the 64-bit path when a point needs it, and raise what the general path
raises; and the quick path must really be taken."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core
from rastrum._native import ffi, lib
from oracle import oracle_mask
from strategies import examples


def _no_general_mask(monkeypatch):
    def boom(*a, **k):
        raise AssertionError("general path taken")
    monkeypatch.setattr(_core, "mask_polygon", boom)


_coord = st.integers(-24, 24 * 8 + 24).map(lambda v: v / 8.0)  # some off the 12 x 14 mask
_ring = st.lists(st.tuples(_coord, _coord), min_size=3, max_size=7)


def _form(ring, how):
    a = np.array(ring, np.float64)
    if how == "f64":
        return a
    if how == "i32":
        return np.round(a).astype(np.int32)
    if how == "strided":
        return np.repeat(a, 2, axis=0)[::2]  # float64, strides (32, 8)
    return [tuple(p) for p in ring]  # (x, y) pairs


@settings(max_examples=examples(40), deadline=None)
@given(st.lists(_ring, min_size=2, max_size=4), st.sampled_from(["f64", "i32", "strided", "pairs"]),
       st.sampled_from([{}, {"rule": "nonzero"}, {"sample_offset": 0.0}, {"subpixel_bits": 2},
                        {"algorithm": "edgeflag"}]))
def test_several_rings_quick_mask_is_exact(rings, how, kw):
    rings = [_form(r, how) for r in rings]
    got = rastrum.polygon_mask(rings, (12, 14), **kw)
    assert got.dtype == np.bool_ and got.shape == (12, 14)
    want = oracle_mask([np.asarray(r, np.float64) for r in rings], (12, 14), rule=kw.get("rule", "evenodd"),
                       subpixel_bits=kw.get("subpixel_bits", 8), sample_offset=kw.get("sample_offset", 0.5))
    np.testing.assert_array_equal(got, want)


def test_several_rings_take_the_quick_path(monkeypatch):
    square = np.array([(1, 1), (9, 1), (9, 8), (1, 8)], np.float64)
    hole = np.array([(3, 3), (3, 6), (6, 6), (6, 3)], np.float64)
    want = rastrum.polygon_mask([square, hole], (10, 11))
    _no_general_mask(monkeypatch)
    np.testing.assert_array_equal(rastrum.polygon_mask([square, hole], (10, 11)), want)
    np.testing.assert_array_equal(rastrum.polygon_mask([square, hole.astype(np.int32)], (10, 11)), want)
    np.testing.assert_array_equal(want, oracle_mask([square, hole], (10, 11)))


def test_several_rings_past_the_32bit_range_take_the_64bit_path():
    # at S = 8 the 32-bit path holds |v| < 2^19 px; a far vertex needs the
    # 64-bit one, which the quick call leaves to the general path
    far = np.array([(1.5, 1.0), (2.0e6, 3.0), (1.5, 6.0)])
    box = np.array([(6, 7), (9, 7), (9, 9), (6, 9)], np.float64)
    got = rastrum.polygon_mask([far, box], (10, 12))
    np.testing.assert_array_equal(got, oracle_mask([far, box], (10, 12)))
    assert got.any()
    # subpixel_bits above 16: the 64-bit path as well
    got20 = rastrum.polygon_mask([far, box], (10, 12), subpixel_bits=20)
    np.testing.assert_array_equal(got20, oracle_mask([far, box], (10, 12), subpixel_bits=20))


@pytest.mark.parametrize("bad, where", [(float("nan"), "ring 1"), (float("inf"), "ring 1")])
def test_several_rings_bad_point_named_as_before(bad, where):
    square = [(1.0, 1.0), (9.0, 1.0), (9.0, 8.0)]
    other = np.array([(3.0, 3.0), (3.0, bad), (6.0, 6.0)])
    with pytest.raises(rastrum.InputError, match=where):
        rastrum.polygon_mask([np.array(square), other], (10, 11))
    with pytest.raises(rastrum.InputError, match="shape"):
        rastrum.polygon_mask([np.array(square), np.array(square)], (10, -1))


def _fix62_values():
    rnd = np.random.default_rng(5)
    # ties of the float32 rounding: a float64 halfway between two float32
    ties = [(2 ** 24 + 1) << 37, (2 ** 24 + 3) << 37, ((2 ** 23 + 1) << 38) + (1 << 13)]
    edge = [0, 1, 2 ** 52 + 1, 2 ** 53 + 1, 2 ** 61 + 12345, 2 ** 62 - 1, 2 ** 62,
            2 ** 63 - 1, 2 ** 63, 2 ** 63 + 2 ** 11 + 1, 2 ** 64 - 1]  # (above 2^62: never written)
    return edge + ties + [int(v) for v in rnd.integers(0, 2 ** 62, 300, dtype=np.uint64)]


def test_fix62_to_float_rounds_as_documented():
    """float32 output: a = u / 2^62 rounded to the nearest float64, then to
    the nearest float32 (ties to even), from the exact fraction."""
    u = _fix62_values()
    buf = np.array(u, np.uint64)
    out = np.full(len(u), np.nan, np.float32)
    lib.rastpy_fix62_to_float(ffi.from_buffer(buf), ffi.from_buffer(out), len(u))
    want = np.array([np.float32(float(Fraction(v, 2 ** 62))) for v in u], np.float32)
    np.testing.assert_array_equal(out, want)
    assert buf.tolist() == u  # the integers left as they were
    # and the float64 conversion on the same values
    lib.rastpy_fix62_to_double(ffi.from_buffer(buf), len(u))
    np.testing.assert_array_equal(buf.view(np.float64), [float(Fraction(v, 2 ** 62)) for v in u])


@pytest.mark.parametrize("method", ["area", "accumulate", "ss4"])
def test_float32_coverage_is_float32_of_float64(method):
    t = np.linspace(0, 2 * np.pi, 19, endpoint=False)
    ring = np.stack([8.3 + 6.1 * np.cos(t), 7.6 + 5.4 * np.sin(t)], 1)
    f64 = rastrum.polygon_coverage([ring], (16, 17), method=method, dtype=np.float64)
    f32 = rastrum.polygon_coverage([ring], (16, 17), method=method, dtype=np.float32)
    assert f32.dtype == np.float32 and f32.shape == (16, 17) and f32.flags.c_contiguous
    np.testing.assert_array_equal(f32, f64.astype(np.float32))
    assert ((f64 > 0) & (f64 < 1)).sum() > 20
    assert rastrum.polygon_coverage([], (3, 0), dtype=np.float32).shape == (3, 0)

"""The whole-array calls' fixed cost (issue 33): polygon_mask of a list of
several rings goes to C in one call (rastrum._core.packed_call, no numpy
form of the points, no scan for the 64-bit path).  It must give what the
exact oracle gives, take the 64-bit path when a point needs it, and raise
what the general path raises; and the quick path must really be taken."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core
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

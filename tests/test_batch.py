"""The batch engine (rastrum._batch.burn over rast_fill_polygons_spans):
many polygons, each with its value, burnt in order into one array of any
supported dtype, against the exact oracle applied polygon by polygon."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from oracle import oracle_mask
from rastrum import InputError, _batch, _core
from strategies import examples

H, W = 13, 17
DTYPES = [np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32, np.int64, np.uint64,
          np.float32, np.float64]


def _ring(draw, n):
    # vertices on the 1/4 grid, on sample points and past the edges
    c = st.integers(-12, 4 * W + 12).map(lambda k: k / 4)
    r = st.integers(-12, 4 * H + 12).map(lambda k: k / 4)
    return np.array([(draw(c), draw(r)) for _ in range(n)], float)


@st.composite
def batches(draw):
    polys = []
    for _ in range(draw(st.integers(1, 6))):
        rings = [_ring(draw, draw(st.integers(3, 7))) for _ in range(draw(st.integers(1, 2)))]
        polys.append(rings)
    return polys


def _expected(polys, values, dtype, merge, rule, s):
    out = np.full((H, W), 7, dtype)
    for rings, v in zip(polys, values):
        m = oracle_mask(rings, (H, W), rule=rule, subpixel_bits=s)
        with np.errstate(over="ignore"):
            if merge == "replace":
                out[m] = v
            else:
                out[m] = out[m] + np.asarray(v, dtype)  # wraps as the glue does
    return out


@settings(max_examples=examples(60))
@given(batches(), st.sampled_from(DTYPES), st.sampled_from(["replace", "add"]),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([0, 2, 8]), st.data())
def test_burn_equals_oracle_in_order(polys, dtype, merge, rule, s, data):
    info = np.iinfo(dtype) if np.issubdtype(dtype, np.integer) else None
    lo, hi = (int(info.min), int(info.max)) if info else (-1e6, 1e6)
    values = np.array([data.draw(st.integers(int(max(lo, -10**6)), int(min(hi, 10**6))))
                       for _ in polys]).astype(dtype)
    out = np.full((H, W), 7, dtype)
    _batch.burn(out, polys, _core.fill_opts("aet", rule, s, 0.5), values=values, merge=merge)
    np.testing.assert_array_equal(out, _expected(polys, values, dtype, merge, rule, s))


@settings(max_examples=examples(30))
@given(batches(), st.sampled_from(["aet", "edgeflag", "xscan"]))
def test_planes_are_each_polygons_mask(polys, algorithm):
    out = np.zeros((len(polys), H, W), bool)
    _batch.burn(out, polys, _core.fill_opts(algorithm, "evenodd", 8, 0.5), planes=True)
    for k, rings in enumerate(polys):
        np.testing.assert_array_equal(out[k], oracle_mask(rings, (H, W)))


def test_strided_and_sub_views():
    big = np.zeros((H + 4, W + 6), np.int32)
    view = big[2:2 + H, 3:3 + W]
    sq = [np.array([(-2, -2), (W + 2, -2), (W + 2, H + 2), (-2, H + 2)], float)]
    _batch.burn(view, [sq], _core.fill_opts("aet", "evenodd", 8, 0.5), values=np.array([5]))
    assert (view == 5).all() and big.sum() == 5 * H * W


def test_bad_polygon_is_named_and_nothing_written():
    out = np.full((H, W), 3, np.uint16)
    good = [np.array([(1, 1), (9, 1), (9, 9)], float)]
    opts = _core.fill_opts("aet", "evenodd", 8, 0.5)
    with pytest.raises(InputError, match=r"polygon 2: ring 1, point 1 \(nan, 2.0\) is NaN"):
        _batch.burn(out, [good, good, good + [np.array([(0, 0), (np.nan, 2), (3, 1)])]], opts)
    with pytest.raises(InputError, match=r"polygon 1: ring 0, point 2 .* outside the range"):
        _batch.burn(out, [good, [np.array([(0, 0), (1, 0), (1e9, 1)])]], opts)
    assert (out == 3).all()
    with pytest.raises(InputError, match="2 values for 1 polygon$"):
        _batch.burn(out, [good], opts, values=[1, 2])
    with pytest.raises(InputError, match="dtype complex128"):
        _batch.burn(np.zeros((H, W), complex), [good], opts)
    with pytest.raises(InputError, match="read-only"):
        ro = np.zeros((H, W), np.uint8)
        ro.flags.writeable = False
        _batch.burn(ro, [good], opts)
    assert (out == 3).all()

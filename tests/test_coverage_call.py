"""The direct path of polygon_coverage / triangles_coverage (the call's own
cost): options checked once and remembered, float64 rings handed straight
to C.  It must give what the general path gives, bit for bit, raise what
the general path raises, and still refuse what the general path refuses;
and it must really be taken (else these tests would only test the general
path twice)."""

import math

import numpy as np
import pytest

import rastrum
from rastrum import _coverage as cov
import oracle_coverage as oc

METHODS = list(rastrum._coverage.METHODS)
DTYPES = [np.uint8, np.uint16, np.float32, np.float64]


def _scene():
    t = np.linspace(0, 2 * np.pi, 23, endpoint=False)
    outer = np.stack([9.3 + 7.1 * np.cos(t), 8.6 + 6.4 * np.sin(t)], 1)
    hole = np.stack([9.0 + 2.6 * np.cos(t), 8.1 + 2.9 * np.sin(t)], 1)[::-1]  # strides (-16, 8)
    star = np.array([(3.2, 1.1), (12.7, 14.3), (0.4, 9.6), (17.5, 5.2), (1.9, 15.8)])
    return outer, hole, star


def _no_general_path(monkeypatch):
    """Make the general path's ring conversion fail loudly."""
    def boom(rings):
        raise AssertionError("general path taken")
    monkeypatch.setattr(rastrum._core, "_points", boom)
    monkeypatch.setattr(cov, "tris_f64", boom)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
@pytest.mark.parametrize("dtype", DTYPES)
def test_direct_path_equals_general_path(method, rule, dtype, monkeypatch):
    outer, hole, star = _scene()
    shape = (17, 19)
    for rings in ([outer, hole], [star], star, [outer, hole, star]):
        as_lists = [r.tolist() for r in rings] if isinstance(rings, list) else rings.tolist()
        # lists of Python floats: the general path (and it remembers the options)
        want = rastrum.polygon_coverage(as_lists, shape, rule=rule, method=method, dtype=dtype)
        with monkeypatch.context() as m:
            _no_general_path(m)
            got = rastrum.polygon_coverage(rings, shape, rule=rule, method=method, dtype=dtype)
        assert got.dtype == want.dtype == np.dtype(dtype) and got.shape == shape
        np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("dtype", DTYPES)
def test_direct_triangles_equal_general_path(method, dtype, monkeypatch):
    rnd = np.random.default_rng(5)
    tris = rnd.uniform(-2, 21, (12, 3, 2))
    want = rastrum.triangles_coverage(tris.tolist(), (18, 16), method=method, dtype=dtype)
    with monkeypatch.context() as m:
        _no_general_path(m)
        got = rastrum.triangles_coverage(tris, (18, 16), method=method, dtype=dtype)
    assert got.dtype == want.dtype
    np.testing.assert_array_equal(got, want)


def test_direct_path_against_the_oracle(monkeypatch):
    outer, hole, star = _scene()
    rastrum.polygon_coverage([[0, 0], [1, 0], [1, 1]], (1, 1), rule="nonzero")  # remember
    for rings in ([outer, hole], [star]):
        with monkeypatch.context() as m:
            _no_general_path(m)
            got = rastrum.polygon_coverage(rings, (17, 19), rule="nonzero")
        a = oc.coverage_exact([r.tolist() for r in rings], (17, 19), rule="nonzero")
        want = np.vectorize(lambda v: oc.level(v, 255))(a)
        np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("bad", [math.nan, math.inf, 1e9])
@pytest.mark.parametrize("several", [False, True])
def test_direct_path_errors_are_the_general_paths(bad, several):
    outer, hole, star = _scene()
    broken = star.copy()
    broken[3, 1] = bad
    rings = [outer, broken] if several else [broken]
    rastrum.polygon_coverage([outer], (9, 9))  # the options remembered
    with pytest.raises(rastrum.InputError) as general:
        rastrum.polygon_coverage([r.tolist() for r in rings], (9, 9))
    with pytest.raises(rastrum.InputError) as direct:
        rastrum.polygon_coverage(rings, (9, 9))
    assert str(direct.value) == str(general.value)
    assert ("ring 1, point 3" if several else "point 3") in str(direct.value)
    tris = np.stack([star[:3], broken[2:5]])
    with pytest.raises(rastrum.InputError) as general:
        rastrum.triangles_coverage(tris.tolist(), (9, 9))
    with pytest.raises(rastrum.InputError) as direct:
        rastrum.triangles_coverage(tris, (9, 9))
    assert str(direct.value) == str(general.value) and "triangle 1, vertex 1" in str(direct.value)


def test_remembered_options_do_not_let_other_types_through():
    star = _scene()[2]
    rastrum.polygon_coverage(star, (4, 4), subpixel_bits=8, sample_offset=0.5)
    for kwargs, words in (({"subpixel_bits": 8.0}, "subpixel_bits must be an int"),
                          ({"subpixel_bits": True}, "subpixel_bits must be an int"),
                          ({"sample_offset": True}, "sample_offset must be 0.5"),
                          ({"method": ["area"]}, "unknown or unsupported method"),
                          ({"dtype": [np.uint8]}, "dtype must be one of"),
                          ({"dtype": np.int8}, "dtype must be one of")):
        with pytest.raises(rastrum.InputError, match=words):
            rastrum.polygon_coverage(star, (4, 4), **kwargs)
    for shape in ((4, -1), (4, 4.0), (True, 4), [4, 4.5]):
        with pytest.raises(rastrum.InputError, match="shape"):
            rastrum.polygon_coverage(star, shape)


def test_empty_and_odd_input_still_take_the_general_path():
    star = _scene()[2]
    rastrum.polygon_coverage(star, (4, 4))
    assert rastrum.polygon_coverage([], (2, 3)).tolist() == [[0] * 3] * 2
    assert rastrum.polygon_coverage(star, (0, 3)).shape == (0, 3)
    assert rastrum.polygon_coverage([star[:2]], (2, 2)).tolist() == [[0, 0], [0, 0]]
    f32 = rastrum.polygon_coverage(star.astype(np.float32), (17, 19))
    np.testing.assert_array_equal(f32, rastrum.polygon_coverage(star.astype(np.float32).tolist(), (17, 19)))
    assert rastrum.triangles_coverage(np.zeros((0, 3, 2)), (2, 2)).tolist() == [[0, 0], [0, 0]]


def _fix62_values():
    ties = [2 ** 53 + 1, 2 ** 53 + 3, 2 ** 54 + 2, 2 ** 54 + 6, 2 ** 62 - 1, 2 ** 61 + 2 ** 8 + 1]
    rnd = np.random.default_rng(3)
    return [0, 1, 2, 3, 2 ** 62] + ties + [int(v) for v in rnd.integers(0, 2 ** 62, 300, dtype=np.uint64)]


def test_fix62_to_float_in_place_rounds_once_to_nearest():
    """The float outputs: a = u / 2^62 rounded to the nearest float64 (ties
    to even, as float(Fraction) does), float32 the nearest float32 of that."""
    from fractions import Fraction
    from rastrum._native import ffi, lib
    u = _fix62_values()
    buf = np.array(u, np.uint64)
    lib.rastpy_fix62_to_double(ffi.from_buffer(buf), len(u))
    want = np.array([float(Fraction(v, 2 ** 62)) for v in u])
    np.testing.assert_array_equal(buf.view(np.float64), want)
    # and through polygon_coverage: the float32 output is float32(float64 output)
    star = _scene()[2]
    f64 = rastrum.polygon_coverage(star, (17, 19), dtype=np.float64)
    f32 = rastrum.polygon_coverage(star, (17, 19), dtype=np.float32)
    np.testing.assert_array_equal(f32, f64.astype(np.float32))
    assert f64.min() == 0 and f64.max() == 1 and ((f64 > 0) & (f64 < 1)).sum() > 20


def test_canvas_aa_remembered_options_do_not_let_other_types_through():
    c = rastrum.Canvas((8, 8), format="gray8")
    tri = np.array([(1.0, 1.0), (6.5, 1.0), (2.0, 6.5)])
    c.fill_polygon(tri, 200, aa="area")
    before = c.array.copy()
    for kwargs, words in (({"subpixel_bits": 8.0}, "subpixel_bits must be an int"),
                          ({"sample_offset": True}, "sample_offset must be 0.5"),
                          ({"rule": ["evenodd"]}, "rule")):
        with pytest.raises(rastrum.InputError, match=words):
            c.fill_polygon(tri, 200, aa="area", **kwargs)
    np.testing.assert_array_equal(c.array, before)
    assert before.max() > 0

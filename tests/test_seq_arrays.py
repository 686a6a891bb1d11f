"""A list of ring arrays read in one C pass (rastrum._seq.rings, issue 33):
every array's points as numpy's float64 conversion gives them, whatever its
strides (C, Fortran, a strided or reversed view), through the array's own
head and through numpy's __array_struct__ capsule alike; anything but exact
ndarrays of shape (N >= 1, 2) and numpy's float64 or int32 dtype answers
None (the general path then checks it).  The oracle is numpy: the arrays
converted one by one and concatenated."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core, _seq
from strategies import examples

_DTYPES = [np.float64, np.int32, np.float32, np.int64, ">f8", ">i4", bool]


def _view(a, how):
    """The points of `a` (m, 2) in another memory layout, same values."""
    if how == "fortran":
        return np.asfortranarray(a)
    if how == "strided":  # every other row of a bigger array
        b = np.zeros((2 * len(a), 3), a.dtype)
        b[::2, :2] = a
        return b[::2, :2]
    if how == "reversed":  # negative strides
        return np.ascontiguousarray(a[::-1])[::-1]
    if how == "columns":  # x and y stored as a (2, m) array, transposed
        return np.ascontiguousarray(a.T).T
    return a


def _expect(rings):
    """What packed_rings must give: None unless every item is an exact
    ndarray of numpy's float64 or int32 dtype and shape (m >= 1, 2)."""
    ok = all(type(r) is np.ndarray and r.dtype in (np.dtype(np.float64), np.dtype(np.int32))
             and r.dtype.isnative and r.ndim == 2 and r.shape[1] == 2 and len(r) >= 1 for r in rings)
    if not rings or not ok:
        return None
    return np.concatenate([r.astype(np.float64) for r in rings]), [len(r) for r in rings]


@st.composite
def _ring_lists(draw):
    n = draw(st.integers(1, 6))
    out = []
    for _ in range(n):
        m = draw(st.integers(1, 9))
        dt = draw(st.sampled_from(_DTYPES if draw(st.integers(0, 3)) == 0 else [np.float64, np.int32]))
        vals = draw(st.lists(st.integers(-2 ** 31, 2 ** 31 - 1) | st.floats(-1e6, 1e6, allow_nan=False),
                             min_size=2 * m, max_size=2 * m))
        a = np.array(vals, np.float64).reshape(m, 2)
        if np.dtype(dt).kind in "iub":
            a = np.clip(np.round(a), -2 ** 31, 2 ** 31 - 1)
        a = a.astype(dt)
        out.append(_view(a, draw(st.sampled_from(["c", "fortran", "strided", "reversed", "columns"]))))
    return out


@pytest.fixture(params=[True, False], ids=["head", "capsule"])
def route(request):
    prev = _seq.use_head(request.param)
    yield request.param
    _seq.use_head(prev)


@settings(max_examples=examples(60), deadline=None)
@given(rings=_ring_lists(), head=st.booleans())
def test_arrays_read_as_numpy_converts_them(rings, head):
    prev = _seq.use_head(head)
    try:
        got = _core.packed_rings(rings)
    finally:
        _seq.use_head(prev)
    want = _expect(rings)
    if want is None:
        assert got is None
        return
    pts, sizes, n = got
    assert pts.dtype == np.float64 and np.array_equal(pts, want[0])
    assert n == len(rings) and list(sizes) == want[1]


@pytest.mark.parametrize("bad", [
    np.zeros((0, 2)), np.ones((3, 3)), np.ones((3, 1, 2)), np.ones(4), np.float64(3.0) * np.ones(()),
    np.ones((3, 2), np.float32), np.ones((3, 2), ">f8"), np.ones((3, 2), np.int64), np.ones((3, 2), bool),
    np.ones((3, 2)).view(np.matrix), np.ma.masked_array(np.ones((3, 2))), np.ones((3, 2), object),
    np.zeros(6, np.uint8)[1:].view(np.int8)[:4].reshape(2, 2),
])
def test_anything_else_is_left_to_the_general_path(bad, route):
    good = np.array([[0.5, 0.5], [4.0, 1.0], [2.0, 3.0]])
    assert _core.packed_rings([good, bad]) is None
    assert _core.packed_rings([bad]) is None


def test_unaligned_float64_is_left_to_the_general_path(route):
    raw = np.zeros(6 * 8 + 1, np.uint8)
    a = np.frombuffer(raw.data, np.float64, 6, 1).reshape(3, 2)  # at an odd address
    assert not a.flags.aligned
    assert _core.packed_rings([a]) is None
    assert np.array_equal(rastrum.polygon_mask([a], (4, 4)), rastrum.polygon_mask([a.copy()], (4, 4)))
    assert np.array_equal(rastrum.polygon_mask(a, (4, 4)), rastrum.polygon_mask(a.copy(), (4, 4)))
    for aa in (None, "area"):  # Canvas.fill_polygon's quick paths take the copy too
        c, d = rastrum.Canvas((4, 4)), rastrum.Canvas((4, 4))
        c.fill_polygon(a, 255, aa=aa)
        d.fill_polygon(a.copy(), 255, aa=aa)
        assert np.array_equal(c.array, d.array)


def test_head_route_is_the_default_and_checked():
    # the array head is trusted once it agreed with __array_struct__:
    # use_head answers the previous setting (True: on, or not yet checked)
    assert _seq.use_head(True) is True
    _core.packed_rings([np.ones((3, 2))])
    assert _seq.use_head(True) is True


def test_many_rings_mask_and_bad_point_as_the_general_path(route):
    rng = np.random.default_rng(3)
    rings = [_view(rng.uniform(0, 60, (int(rng.integers(3, 9)), 2)), h)
             for h in ["c", "fortran", "strided", "columns"] * 30]
    rings[7] = np.round(rings[7]).astype(np.int32)
    lists = [r.tolist() for r in rings]  # the general path: lists of lists
    assert np.array_equal(rastrum.polygon_mask(rings, (64, 64)), rastrum.polygon_mask(lists, (64, 64)))
    rings[5] = rings[5].copy()
    rings[5][1, 0] = np.nan
    lists[5][1][0] = float("nan")
    canvas = rastrum.Canvas.wrap(np.zeros((64, 64), np.uint8))
    msgs = []
    for src in (rings, lists):
        with pytest.raises(rastrum.InputError) as e:
            canvas.fill_polygon(src, 255)
        msgs.append(str(e.value))
    assert not canvas.array.any() and msgs[0] == msgs[1] and "ring 5, point 1" in msgs[0]

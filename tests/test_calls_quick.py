"""The quick paths of issue 33 (the Python call): Canvas.fill_polygon's
common call straight to C, and rings read in one C pass
(_core.packed_rings, rastrum._seq.rings), give what the general path gives,
pixel for pixel, and refuse what it refuses with its messages."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core
from rastrum._core import InputError
from strategies import examples


def _general(a):
    """The same points as a non-contiguous view: the general path."""
    b = np.empty((len(a), 4))
    b[:, ::2] = a
    return b[:, ::2]


def _flat(rings):
    return np.concatenate([np.asarray(r, np.float64).reshape(-1, 2) for r in rings])


@pytest.mark.parametrize("rings", [
    [np.array([[0.5, 0.25], [9.0, 1.0], [4.0, 7.5]])],
    [np.array([[0.5, 0.25], [9.0, 1.0], [4.0, 7.5]]), np.array([[1, 1], [3, 1], [2, 2]], np.int32)],
    [np.array([[0.5, 0.25], [9.0, 1.0]]), np.array([[1.0, 1.0]])],  # 2 and 1 points: kept
    [(0.5, 0.25), (9, 1), [4.0, 7.5]],  # one ring of pairs
    [[(0.5, 0.25), (9, 1), (4.0, 7.5)], ((1, 1), (3.5, 1), (2, 2))],  # rings of pairs
])
def test_packed_rings_as_the_general_path(rings):
    pts, sizes, n = _core.packed_rings(rings)
    arrays = _core.rings_f64(rings)
    assert n == len(arrays) and pts.dtype == np.float64
    assert np.array_equal(pts, np.concatenate(arrays))
    if n > 1:
        assert list(sizes) == [len(a) for a in arrays]


@pytest.mark.parametrize("rings", [
    [], [np.zeros((0, 2))], [np.ones((3, 2), bool)], [np.ones((3, 3))], [np.ones((3, 1, 2))],
    [np.ones((3, 2), np.float32)], [np.ones((3, 2)).view(np.matrix)], [(2 ** 60, 1.0), (1, 2), (3, 4)],
    [(True, 1.0), (1, 2), (3, 4)], [(np.float64(1), 1.0), (1, 2), (3, 4)], [(1, 2, 3), (1, 2), (3, 4)],
    [[]], [1.0, 2.0, 3.0, 4.0], ((1, 2), (3, 4), (5, 6)), [{"type": "Polygon", "coordinates": []}],
])
def test_packed_rings_leaves_the_rest_to_the_general_path(rings):
    assert _core.packed_rings(rings) is None


def _hexagons():
    c = st.floats(-20, 60, allow_nan=False)
    return st.lists(st.tuples(c, c), min_size=3, max_size=12)


@settings(max_examples=150, deadline=None)
@given(_hexagons(), st.sampled_from([{}, {"rule": "nonzero"}, {"subpixel_bits": 20}, {"sample_offset": 0},
                                     {"algorithm": "edgeflag"}, {"boundary": "closed"},
                                     {"boundary": "conservative", "subpixel_bits": 3}]),
       st.sampled_from(["gray8", "rgb888", "rgb565", "mono1"]))
def test_canvas_quick_path_as_the_general_path(pts, kw, fmt):
    a = np.array(pts, np.float64)
    color = 200 if fmt in ("gray8", "mono1") else (10, 200, 30)
    c1, c2, c3 = (rastrum.Canvas((40, 44), format=fmt, background=0) for _ in range(3))
    c1.fill_polygon(a, color, **kw)
    c2.fill_polygon(_general(a), color, **kw)
    c3.fill_polygon(pts, color, **kw)  # a list of (x, y) tuples
    assert np.array_equal(c1.array, c2.array) and np.array_equal(c3.array, c2.array)


@pytest.mark.parametrize("bad", [np.nan, np.inf, 1e9])
def test_canvas_quick_path_refuses_as_the_general_path(bad):
    a = np.array([[1.0, 1.0], [9.0, 2.0], [4.0, bad]])
    c = rastrum.Canvas.wrap(np.zeros((10, 10), np.uint8))
    msgs = []
    for src in (a, _general(a), [tuple(p) for p in a.tolist()]):
        with pytest.raises(InputError) as e:
            c.fill_polygon(src, 255)
        msgs.append(str(e.value))
        assert not c.array.any()
    assert len(msgs) == 3 and len(set(msgs)) == 1
    c.fill_polygon(np.array([[3e5, 1.0], [3e5 + 9, 2.0], [3e5, 6.0]]), 255)  # past the 32-bit range: 64-bit path


def test_canvas_quick_path_read_only_and_labels():
    arr = np.zeros((8, 8), np.uint8)
    c = rastrum.Canvas.wrap(arr)
    arr.flags.writeable = False
    with pytest.raises(InputError, match="read-only"):
        c.fill_polygon(np.array([[1.0, 1.0], [7.0, 1.0], [4.0, 6.0]]), 255)
    lab = np.zeros((8, 8), np.int32)
    rastrum.Canvas.wrap(lab, format="label").fill_polygon(np.array([[1.0, 1.0], [7.0, 1.0], [4.0, 6.0]]), 70000)
    assert set(np.unique(lab)) == {0, 70000}
    assert np.array_equal(lab != 0, rastrum.polygon_mask(np.array([[1.0, 1.0], [7.0, 1.0], [4.0, 6.0]]), (8, 8)))


def test_polygon_mask_int32_ring():
    a = np.array([[1, 1], [30, 3], [12, 25]], np.int32)
    assert np.array_equal(rastrum.polygon_mask(a, (32, 32)), rastrum.polygon_mask(_general(a.astype(float)), (32, 32)))


def test_many_rings_one_call_as_the_general_path():
    rng = np.random.default_rng(5)
    rings = [rng.uniform(0, 60, (int(rng.integers(3, 9)), 2)) for _ in range(200)]
    slow = [_general(r) for r in rings]
    assert np.array_equal(rastrum.polygon_mask(rings, (64, 64)), rastrum.polygon_mask(slow, (64, 64)))
    assert np.array_equal(rastrum.polygon_coverage(rings, (64, 64), rule="nonzero"),
                          rastrum.polygon_coverage(slow, (64, 64), rule="nonzero"))


# ---- Canvas.fill_polygon(aa=...)'s quick path (an int colour, the binary
# options at their defaults) against the general one (_fill_aa: the same
# colour as a numpy int), and both against the documented blend of
# polygon_coverage's levels, (s*c + d*(255 - c) + 127) // 255.

@settings(max_examples=examples(60), deadline=None)
@given(_hexagons(), st.sampled_from(["accumulate", "area", "ss4"]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([{}, {"subpixel_bits": 4}, {"sample_offset": 0.0}]))
def test_canvas_aa_quick_path_as_the_general_path(pts, aa, rule, kw):
    a = np.array(pts, np.float64)
    back = (np.arange(40 * 44).reshape(40, 44) * 7 % 256).astype(np.uint8)
    quick, general = rastrum.Canvas.wrap(back.copy()), rastrum.Canvas.wrap(back.copy())
    quick.fill_polygon(a, 200, aa=aa, rule=rule, **kw)
    general.fill_polygon(a, np.int64(200), aa=aa, rule=rule, **kw)
    assert np.array_equal(quick.array, general.array)
    c = rastrum.polygon_coverage(a, (40, 44), method=aa, rule=rule, **kw).astype(np.int64)
    want = np.where(c > 0, (200 * c + back.astype(np.int64) * (255 - c) + 127) // 255, back)
    assert np.array_equal(quick.array, want)


def test_canvas_aa_quick_path_refuses_as_the_general_path():
    tri = np.array([[1.0, 1.0], [7.0, 1.0], [4.0, 6.0]])
    cases = [(dict(aa="ss3"), "aa="), (dict(aa="area", rule="winding"), "rule"),
             (dict(aa="area", subpixel_bits=17), "subpixel_bits"), (dict(aa="area", sample_offset=0.25), "sample_offset"),
             (dict(aa="area", subpixel_bits=True), "subpixel_bits"), (dict(aa="area", algorithm="edgeflag"), "algorithm")]
    for kw, word in cases:
        msgs = []
        for color in (255, np.int64(255)):  # quick, general
            c = rastrum.Canvas.wrap(np.zeros((8, 8), np.uint8))
            with pytest.raises(InputError, match=word) as e:
                c.fill_polygon(tri, color, **kw)
            assert not c.array.any()
            msgs.append(str(e.value))
        assert msgs[0] == msgs[1]
    c = rastrum.Canvas.wrap(np.zeros((8, 8), np.uint8))
    c.fill_polygon(tri, 255, aa="area")  # now cached: the quick path's own lookup
    with pytest.raises(InputError, match="nan"):
        c.fill_polygon(np.array([[1.0, 1.0], [7.0, np.nan], [4.0, 6.0]]), 7, aa="area")
    arr = np.zeros((8, 8), np.uint8)
    ro = rastrum.Canvas.wrap(arr)
    arr.flags.writeable = False
    with pytest.raises(InputError, match="read-only"):
        ro.fill_polygon(tri, 255, aa="area")
    for dtype in (np.int32, np.int64):  # a label canvas never blends
        with pytest.raises(InputError, match="label"):
            rastrum.Canvas.wrap(np.zeros((8, 8), dtype), format="label").fill_polygon(tri, 3, aa="area")

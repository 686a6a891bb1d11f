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


# ---- Canvas.fill_polygon's call done in C (rastrum._seq.fill): once a
# canvas has drawn with an int colour object, the next call with the same
# target and colour (a float64 ring array or a list of pairs, no keyword,
# or the keyword options' checked rast_fill_opts) goes to C in one call.
# It must give the general path's pixels, decline what that path alone
# takes, and leave errors to it.

_FORMATS = {"gray8": 200, "rgb888": 77, "rgb565": 140, "rgba8888": 17, "mono1": 1}
_EMPTY = np.zeros((3, 2))  # a degenerate ring: no pixel, but the call is remembered


def _canvas(fmt):
    if fmt.startswith("label"):
        return rastrum.Canvas.wrap(np.zeros((40, 44), np.int32 if fmt == "label32" else np.uint16), format="label")
    return rastrum.Canvas((40, 44), format=fmt, background=0)


class _Only:
    """Within: the named fallbacks raise, so that only the C call can draw."""

    def __init__(self, kw):
        import rastrum._canvas as m
        self.m, self.kw = m, kw

    def __enter__(self):
        def boom(*a, **k):
            raise AssertionError("the C call declined")
        self.saved = (self.m._fill_polygon, self.m._fill_ring)
        if self.kw:
            self.m._fill_ring = boom  # the full method is entered; its cffi call must not be
        else:
            self.m._fill_polygon = boom

    def __exit__(self, *exc):
        self.m._fill_polygon, self.m._fill_ring = self.saved


@settings(max_examples=examples(40), deadline=None)
@given(_hexagons(), st.sampled_from([{}, {"rule": "nonzero"}, {"sample_offset": 0.0}, {"subpixel_bits": 4},
                                     {"algorithm": "edgeflag", "boundary": "closed"}]),
       st.sampled_from(list(_FORMATS) + ["label32", "label16"]), st.booleans())
def test_canvas_c_call_as_the_general_path(pts, kw, fmt, tuples):
    color = _FORMATS.get(fmt, 1000)
    src = [tuple(p) for p in pts] if tuples else np.array(pts, np.float64)
    general, quick = _canvas(fmt), _canvas(fmt)
    general.fill_polygon(_general(np.array(pts, np.float64)), color, **kw)
    quick.fill_polygon(_EMPTY, color, **kw)  # remembered
    assert quick._fpq[0] is quick._target and quick._fpq[1] is color
    with _Only(kw):
        quick.fill_polygon(src, color, **kw)
    assert np.array_equal(quick.array, general.array)


def test_canvas_c_call_declines_what_the_general_path_takes():
    pts = [(0.5, 0.25), (30.0, 3.0), (25.5, 31.0), (2.0, 20.0)]
    a = np.array(pts)
    f = np.empty((4, 2), order="F")
    f[:] = a
    odd = np.frombuffer(np.zeros(8 * 9, np.uint8).data, np.float64, 8, 1).reshape(4, 2)  # unaligned
    odd[:] = a
    others = [_general(a), f, odd, a.astype(np.float32), a.astype(np.int32), [list(p) for p in pts],
              tuple(pts), [(np.float64(x), y) for x, y in pts], [pts, pts[:3]], [a], a.reshape(1, 4, 2),
              rastrum.Path().move_to(*pts[0]).line_to(*pts[1]).line_to(*pts[2]).close()]
    for src in others:
        for color in (200, 7, np.uint8(200), np.int64(7)):
            want = _canvas("gray8")
            want.fill_polygon(src, color)
            got = _canvas("gray8")
            got.fill_polygon(_EMPTY, 200)
            got.fill_polygon(src, color)
            got.fill_polygon(src, color)  # and again, remembered if it may be
            assert np.array_equal(got.array, want.array), (src, color)
    big = _canvas("label32")  # an int not cached by CPython: equal but not the same object
    big.fill_polygon(_EMPTY, int("70000"))
    big.fill_polygon(a, int("70001"))
    assert set(np.unique(big.array)) == {0, 70001}


@pytest.mark.parametrize("kw", [{}, {"rule": "nonzero"}])
def test_canvas_c_call_leaves_errors_to_the_general_path(kw):
    tri = np.array([[1.0, 1.0], [9.0, 2.0], [4.0, 6.0]])
    for bad in (np.nan, np.inf, 1e9, 3e5):
        a = tri.copy()
        a[2, 1] = bad
        msgs = []
        for src in (a, [tuple(p) for p in a.tolist()]):
            fresh, primed = (rastrum.Canvas.wrap(np.zeros((10, 10), np.uint8)) for _ in range(2))
            primed.fill_polygon(_EMPTY, 255, **kw)
            for c in (fresh, primed):
                if bad == 3e5:  # past the 32-bit range: C declines, the 64-bit path draws
                    c.fill_polygon(src, 255, **kw)
                    continue
                with pytest.raises(InputError) as e:
                    c.fill_polygon(src, 255, **kw)
                msgs.append(str(e.value))
                assert not c.array.any()
            assert np.array_equal(fresh.array, primed.array)
        assert len(set(msgs)) <= 1
    for short in (tri[:2], [(1.0, 1.0), (2.0, 2.0)], np.zeros((0, 2)), []):
        fresh, primed = (rastrum.Canvas.wrap(np.zeros((10, 10), np.uint8)) for _ in range(2))
        primed.fill_polygon(_EMPTY, 255, **kw)
        for c in (fresh, primed):
            try:
                c.fill_polygon(short, 255, **kw)
                out = None
            except InputError as e:
                out = str(e)
            assert not c.array.any()
            if c is fresh:
                first = out
        assert out == first
    arr = np.zeros((8, 8), np.uint8)
    ro = rastrum.Canvas.wrap(arr)
    ro.fill_polygon(_EMPTY, 255, **kw)
    arr.flags.writeable = False
    with pytest.raises(InputError, match="read-only"):
        ro.fill_polygon(tri, 255, **kw)
    with pytest.raises(InputError, match="read-only"):
        ro.fill_polygon([tuple(p) for p in tri.tolist()], 255, **kw)


def test_canvas_fill_polygon_reads_as_its_signature():
    import inspect
    sig = inspect.signature(rastrum.Canvas.fill_polygon)
    assert list(sig.parameters)[:3] == ["self", "rings", "color"] and "opacity" in sig.parameters
    assert sig.parameters["rule"].kind is inspect.Parameter.KEYWORD_ONLY
    assert "Paint `color`" in rastrum.Canvas.fill_polygon.__doc__
    c = rastrum.Canvas.wrap(np.zeros((8, 8), np.uint8))
    with pytest.raises(TypeError, match=r"fill_polygon\(\) got an unexpected keyword argument 'rul'"):
        c.fill_polygon(_EMPTY, 1, rul="nonzero")
    with pytest.raises(TypeError):
        c.fill_polygon(_EMPTY, 1, "nonzero")


@pytest.mark.parametrize("kw", [dict(algorithm=["aet"]), dict(rule={"evenodd"}), dict(rounding=[1]),
                                dict(boundary={}), dict(algorithm=["aet"], subpixel_bits=4),
                                dict(rule=[], sample_offset=0.25)])
def test_polygon_mask_options_of_unhashable_types_are_input_errors(kw):
    # The options cache looks a key up by value: a list or a dict given as a
    # name must still be refused by the checks, with an InputError (a
    # ValueError), not a TypeError out of the cache's dict.
    ring = np.array([[1.0, 1.0], [6.0, 1.5], [3.0, 5.0]])
    with pytest.raises(InputError):
        rastrum.polygon_mask(ring, (8, 8), **kw)
    canvas = rastrum.Canvas((8, 8), format="gray8", background=0)
    with pytest.raises(InputError):
        canvas.fill_polygon(ring, 255, **kw)
    assert not canvas.array.any()

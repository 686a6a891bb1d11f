"""Bad input raises ValueError (rastrum.InputError) with a message naming
the problem, and leaves a canvas untouched."""

import re

import numpy as np
import pytest

import rastrum
from strategies import COORD_MAX

TRI = [(0.5, 0.5), (6.0, 1.0), (2.0, 5.5)]
SHAPE = (6, 7)
INF = float("inf")
NAN = float("nan")


def test_exception_hierarchy():
    assert issubclass(rastrum.RastrumError, Exception)
    assert issubclass(rastrum.InputError, rastrum.RastrumError)
    assert issubclass(rastrum.InputError, ValueError)


def raises_input_error(pattern):
    """pytest.raises for InputError whose message matches ``pattern``
    (case-insensitive regex naming the problem)."""
    return pytest.raises(rastrum.InputError, match=re.compile(pattern, re.I))


BAD_RINGS = [
    # (rings, regex the message must match)
    ([(0, 0), (NAN, 1), (2, 0)], r"finite|nan"),
    ([(0, 0), (1, INF), (2, 0)], r"finite|inf"),
    ([(0, 0), (1, 1), (-INF, 0)], r"finite|inf"),
    ([np.array([[0, 0, 0], [1, 1, 1], [2, 0, 0]], float)], r"shape|\(N, ?2\)"),
    ([np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])], r"shape|\(N, ?2\)|dim"),
    ([np.zeros((3, 2, 1))], r"shape|\(N, ?2\)|dim"),
    # polygon_mask's "aet" takes the 64-bit path past the 32-bit range:
    # +-2**28 pixels at every subpixel_bits (tests/test_precision.py); 1- and
    # 2-point rings draw nothing (tests/test_ml.py), they are not errors
    ([(0, 0), (2.0 ** 28, 0), (0, 3)], r"range|limit|large"),
    ([(0, 0), (3, 0), (0, -2.0 ** 28)], r"range|limit|large"),
    ([(0, 0), (1e300, 0), (0, 3)], r"range|limit|large"),
]


@pytest.mark.parametrize("rings,pattern", BAD_RINGS)
def test_bad_rings(rings, pattern):
    with raises_input_error(pattern):
        rastrum.polygon_mask(rings, SHAPE)


def test_short_rings_are_nothing():
    # Issue 14: a ring of 1 or 2 points encloses nothing and draws nothing,
    # as in C (and rasterio, cv2, skia, skimage); these two rows raised
    # before ("a ring needs at least 3").
    assert not rastrum.polygon_mask([(0, 0), (1, 1)], SHAPE).any()
    full = rastrum.polygon_mask(TRI, SHAPE)
    assert np.array_equal(rastrum.polygon_mask([TRI, [(1, 1), (2, 2)]], SHAPE), full)


def test_empty_rings_are_nothing():
    # Defined in issue 5: empty input draws nothing; it is not an error.
    # See test_bad_input.py.
    full = rastrum.polygon_mask(TRI, SHAPE)
    assert not rastrum.polygon_mask([np.zeros((0, 2))], SHAPE).any()
    assert np.array_equal(rastrum.polygon_mask([TRI, np.zeros((0, 2))], SHAPE), full)


def test_range_depends_on_subpixel_bits():
    # The 32-bit path (every algorithm but "aet", which goes on to the
    # 64-bit path): |v| * 2**S below 2**27.
    v = 2.0 ** 27 / 2 ** 4              # fine at S=0, past the limit at S=4
    ring = [(0, 0), (v, 0), (0, 3)]
    rastrum.polygon_mask(ring, SHAPE, subpixel_bits=0, algorithm="xscan")
    with raises_input_error(r"range|limit|large"):
        rastrum.polygon_mask(ring, SHAPE, subpixel_bits=4, algorithm="xscan")
    with raises_input_error(r"range|limit|large"):
        rastrum.polygon_mask([(0, 0), ((COORD_MAX + 1) / 256, 0), (0, 3)], SHAPE, algorithm="xscan")
    # "aet" goes on to 2**28 pixels whatever S is
    rastrum.polygon_mask([(0, 0), ((COORD_MAX + 1) / 256, 0), (0, 3)], SHAPE, subpixel_bits=20)
    with raises_input_error(r"range|limit|large"):
        rastrum.polygon_mask([(0, 0), (2.0 ** 28, 0), (0, 3)], SHAPE, subpixel_bits=0)
    # "aet" at S = 4 is the 64-bit path: the same pixels as at S = 0 here
    assert np.array_equal(rastrum.polygon_mask(ring, SHAPE, subpixel_bits=4),
                          rastrum.polygon_mask(ring, SHAPE, subpixel_bits=0))


@pytest.mark.parametrize("shape", [
    (-1, 5), (5, -1), (5,), (1, 2, 3), (2.5, 3), (3, 2.0), "ab", None, 7,
    (None, 3),
])
def test_bad_shape(shape):
    with raises_input_error(r"shape"):
        rastrum.polygon_mask(TRI, shape)


def test_numpy_int_shape_accepted():
    m = rastrum.polygon_mask(TRI, (np.int64(6), np.int32(7)))
    assert m.shape == (6, 7)
    assert rastrum.polygon_mask(TRI, np.array([6, 7])).shape == (6, 7)


@pytest.mark.parametrize("rule", ["even-odd", "winding", "", None, 1,
                                  "EVENODD "])
def test_unknown_rule(rule):
    with raises_input_error(r"rule"):
        rastrum.polygon_mask(TRI, SHAPE, rule=rule)


@pytest.mark.parametrize("alg", ["bogus", "", None, 3, "AET "])
def test_unknown_algorithm(alg):
    with raises_input_error(r"algorithm"):
        rastrum.polygon_mask(TRI, SHAPE, algorithm=alg)


@pytest.mark.parametrize("bits", [-1, 33, 100, 2.5, 8.0, "8", None])
def test_bad_subpixel_bits(bits):
    with raises_input_error(r"subpixel"):
        rastrum.polygon_mask(TRI, SHAPE, subpixel_bits=bits)


def test_numpy_int_subpixel_bits_accepted():
    assert rastrum.polygon_mask(TRI, SHAPE, subpixel_bits=np.int64(4)
                                ).shape == SHAPE


@pytest.mark.parametrize("o", [0.25, 1, -0.5, 1.0, 0.4999, NAN, None, "0.5"])
def test_bad_sample_offset(o):
    with raises_input_error(r"offset"):
        rastrum.polygon_mask(TRI, SHAPE, sample_offset=o)


def test_good_sample_offsets():
    for o in (0, 0.0, 0.5, np.float64(0.5)):
        assert rastrum.polygon_mask(TRI, SHAPE, sample_offset=o).shape == SHAPE


# --- canvas ------------------------------------------------------------------

FORMATS = {"gray8": 1, "rgb888": 3, "rgba8888": 4}

BAD_COLORS = {
    "gray8": [256, -1, 1.5, "redd", "#12", None, (1, 2, 3), [300]],
    "rgb888": [256, -1, (1, 2), (1, 2, 3, 4, 5), (0, 0, 256), (0, -1, 0),
               (1.5, 2, 3), "no such colour", "#ff00zz", None],
    "rgba8888": [256, -1, (1, 2), (1, 2, 3, 4, 5), (0, 0, 0, 256),
                 (0, 0, 0, -1), (1, 2, 3.5, 4), "#fffff", "", None],
}


def _canvas(fmt):
    c = rastrum.Canvas((6, 7), format=fmt, background=17)
    c.array[...] = np.arange(c.array.size, dtype=np.uint8).reshape(
        c.array.shape)
    return c


@pytest.mark.parametrize("fmt,color", [(f, c) for f, cs in BAD_COLORS.items()
                                       for c in cs])
def test_bad_color(fmt, color):
    c = _canvas(fmt)
    before = c.array.copy()
    with raises_input_error(r"colou?r"):
        c.fill_polygon(TRI, color)
    assert np.array_equal(c.array, before)


BAD_FILL_KWARGS = [
    (dict(rule="bogus"), r"rule"),
    (dict(algorithm="bogus"), r"algorithm"),
    (dict(subpixel_bits=33), r"subpixel"),
    (dict(subpixel_bits=17, algorithm="xscan"), r"subpixel"),
    (dict(subpixel_bits=-1), r"subpixel"),
    (dict(sample_offset=0.25), r"offset"),
]


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("rings,pattern", BAD_RINGS)
def test_canvas_bad_rings_untouched(fmt, rings, pattern):
    c = _canvas(fmt)
    before = c.array.copy()
    with raises_input_error(pattern):
        c.fill_polygon(rings, 255)
    assert np.array_equal(c.array, before)


@pytest.mark.parametrize("kw,pattern", BAD_FILL_KWARGS)
def test_canvas_bad_options_untouched(kw, pattern):
    c = _canvas("rgb888")
    before = c.array.copy()
    with raises_input_error(pattern):
        c.fill_polygon(TRI, (1, 2, 3), **kw)
    assert np.array_equal(c.array, before)


def test_canvas_multi_ring_error_is_atomic():
    # the bad ring comes last: nothing of the good rings may be painted
    c = _canvas("gray8")
    before = c.array.copy()
    rings = [TRI, [(0, 0), (7, 0), (7, 6), (0, 6)], [(0, 0), (NAN, 1), (2, 0)]]
    with raises_input_error(r"finite|nan"):
        c.fill_polygon(rings, 255)
    assert np.array_equal(c.array, before)


@pytest.mark.parametrize("args,pattern", [
    (((5, -1),), r"width|size|shape"),
    (((-1, 5),), r"height|size|shape"),
    (((5, 2.5),), r"width|size|shape"),
    (((5, 5), "rgb565x"), r"format"),
    (((5, 5), "rgb888", 256), r"background|colou?r"),
    (((5, 5), "rgb888", -1), r"background|colou?r"),
])
def test_canvas_bad_construction(args, pattern):
    with raises_input_error(pattern):
        rastrum.Canvas(*args)


@pytest.mark.parametrize("make,pattern", [
    (lambda: np.zeros((4, 5, 3), np.float32), r"uint8|dtype"),
    (lambda: np.zeros((4, 5, 3), np.uint16), r"uint8|dtype"),  # (H, W) uint16 is rgb565
    (lambda: np.zeros((4, 5, 3), np.int8), r"uint8|dtype"),
    (lambda: np.zeros((4, 5, 2), np.uint8), r"shape|channel|format"),
    (lambda: np.zeros((4, 5, 5), np.uint8), r"shape|channel|format"),
    (lambda: np.zeros(20, np.uint8), r"shape|dim|format"),
    (lambda: np.zeros((2, 4, 5, 3), np.uint8), r"shape|dim|format"),
    (lambda: [[0, 0], [0, 0]], r"array|uint8|dtype"),
])
def test_wrap_bad_array(make, pattern):
    with raises_input_error(pattern):
        rastrum.Canvas.wrap(make())


def test_wrap_read_only():
    a = np.zeros((4, 5, 3), np.uint8)
    a.setflags(write=False)
    with raises_input_error(r"writ|read.?only"):
        rastrum.Canvas.wrap(a)
    b = np.broadcast_to(np.zeros(3, np.uint8), (4, 5, 3))
    with pytest.raises(ValueError):
        rastrum.Canvas.wrap(b)


@pytest.mark.parametrize("shape,fmt", [
    ((4, 5), "rgb888"), ((4, 5, 3), "gray8"), ((4, 5, 3), "rgba8888"),
    ((4, 5, 4), "rgb888"), ((4, 5, 1), "rgb888"),
])
def test_wrap_format_mismatch(shape, fmt):
    with raises_input_error(r"shape|channel|format"):
        rastrum.Canvas.wrap(np.zeros(shape, np.uint8), format=fmt)


VIEWS = [
    lambda a: a[:, :, :3],           # rgb888 view of rgba memory
    lambda a: a[:, ::2],             # every other pixel
    lambda a: a[:, :, ::-1][:, :, :3],
    lambda a: a[::-1],               # negative row stride
]


@pytest.mark.parametrize("k", range(len(VIEWS)))
def test_wrap_unusual_strides_rejected_or_correct(k):
    """Views whose pixels are not plain rows (a channel subset, a column
    stride, reversed channels, reversed rows) must be rejected with
    ValueError, or painted exactly with no stray writes."""
    big = np.full((6, 8, 4), 0xA5, np.uint8)
    view = VIEWS[k](big)
    before = big.copy()
    try:
        c = rastrum.Canvas.wrap(view)
    except ValueError:
        assert np.array_equal(big, before)
        return
    n = view.shape[2]
    color = (1, 2, 3, 4)[:n]
    c.fill_polygon([(-1, -1), (20, -1), (20, 20), (-1, 20)], color)
    assert (view == np.array(color, np.uint8)).all()
    probe = np.zeros(big.shape, np.uint8)
    VIEWS[k](probe)[...] = 1
    assert not ((big != before) & (probe == 0)).any(), "write outside view"

"""Lines against the exact reference (tests/oracle_lines.py, written from the
header): Bresenham equal pixel for pixel and in order, symmetric, exactly
clipped, never a write outside; the DDA measured for what it is."""

import doctest
import time
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_lines as ref
import rastrum
import rastrum._canvas
import rastrum._lines
from oracle import snap
from rastrum._native import ffi, lib
from strategies import COORD_MAX, coordinates, examples

OFFSETS = (0, 0.5)
HALF = Fraction(1, 2)


def c_line(a, b, S, o, algorithm="bresenham", clip=None):
    """rast_line_pixels on fixed-point endpoints, as a list of (x, y)."""
    opts = rastrum._lines.line_opts(algorithm, S, o)
    pa = ffi.new("rast_point *", list(a))[0]
    pb = ffi.new("rast_point *", list(b))[0]
    rect = rastrum._lines._clip_rect(clip)
    count = ffi.new("size_t *")
    st_ = lib.rast_line_pixels(pa, pb, opts, rect, ffi.NULL, 0, count)
    assert st_ in (lib.RAST_OK, lib.RAST_E_SCRATCH)
    out = np.empty((count[0], 2), np.int32)
    if count[0]:
        assert lib.rast_line_pixels(pa, pb, opts, rect, ffi.from_buffer("int32_t[]", out), count[0], count) == 0
    return [tuple(p) for p in out.tolist()]


# ---- fixed-point endpoints -------------------------------------------------------

@st.composite
def endpoints(draw, S, o, span=40):
    """Fixed-point a, b (units 1/2**S): random, on the pixel grid, on samples,
    zero length, lines that meet exact ties, long lines, every octant."""
    g = 1 << S
    half = g // 2 if o else 0  # a sample offset in fixed point (S >= 1 for o = 1/2)
    anywhere = st.integers(-span * g, span * g)
    on_grid = st.integers(-span, span).map(lambda k: k * g)
    on_sample = st.integers(-span, span).map(lambda k: k * g + half)
    coord = st.one_of(anywhere, anywhere, on_grid, on_sample)
    a = (draw(coord), draw(coord))
    kind = draw(st.sampled_from(["random", "random", "zero", "tie", "long", "axis", "diagonal"]))
    if kind == "zero":
        b = a
    elif kind == "tie":
        # slope +-1/2, +-2, +-1/4 ...: the line passes halfway between samples
        m = draw(st.sampled_from([2, 4, 6]))
        k = draw(st.integers(-8, 8))
        sx, sy = draw(st.sampled_from([1, -1])), draw(st.sampled_from([1, -1]))
        d = (sx * m * k * g, sy * k * g)
        b = (a[0] + d[0], a[1] + d[1]) if draw(st.booleans()) else (a[0] + d[1], a[1] + d[0])
    elif kind == "long":
        big = st.integers(-2000 * g, 2000 * g)
        b = (draw(big), draw(big))
    elif kind == "axis":
        b = (draw(coord), a[1]) if draw(st.booleans()) else (a[0], draw(coord))
    elif kind == "diagonal":
        k = draw(st.integers(-30 * g, 30 * g))
        b = (a[0] + k, a[1] + draw(st.sampled_from([k, -k])))
    else:
        b = (draw(coord), draw(coord))
    return a, b


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("S", range(9))
@settings(max_examples=examples(100))
@given(data=st.data())
def test_bresenham_equals_reference(S, o, data):
    a, b = data.draw(endpoints(S, o))
    want = ref.line_pixels(a, b, S, Fraction(o))
    got = c_line(a, b, S, o)
    assert got == want, (a, b, S, o)
    # symmetric: b -> a lists the same pixels in the reverse order
    assert c_line(b, a, S, o) == want[::-1], (a, b, S, o)


def test_ties_go_down_and_right():
    # (0,0) -> (4,2) at integer samples: y = 1/2 at x = 1 -> row 1 (down);
    # (0,0) -> (2,4): x = 1/2 at y = 1 -> column 1 (right); either direction.
    assert c_line((0, 0), (4, 2), 0, 0) == [(0, 0), (1, 1), (2, 1), (3, 2), (4, 2)]
    assert c_line((4, 2), (0, 0), 0, 0) == [(4, 2), (3, 2), (2, 1), (1, 1), (0, 0)]
    assert c_line((0, 0), (2, 4), 0, 0) == [(0, 0), (1, 1), (1, 2), (2, 3), (2, 4)]
    assert c_line((0, 0), (4, -2), 0, 0) == [(0, 0), (1, 0), (2, -1), (3, -1), (4, -2)]
    # pixel centres: y = x/2 + 1/4 is 1 at x = 1.5 and 2 at x = 3.5, on the
    # border between two rows: the lower row, whose pixel contains the point
    assert c_line((0, 1), (16, 9), 2, 0.5) == [(0, 0), (1, 1), (2, 1), (3, 2)]
    assert c_line((16, 9), (0, 1), 2, 0.5) == [(3, 2), (2, 1), (1, 1), (0, 0)]


@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_limits_and_clips(o, data):
    """Endpoints anywhere in the range, up to +-RAST_COORD_MAX, for every S
    up to 16, seen through a clip: exactly the reference's pixels there."""
    S = data.draw(st.integers(0, 16))
    M = COORD_MAX
    extreme = st.one_of(st.sampled_from([M, -M, M - 1, -M + 1, 0]), st.integers(-M, M))
    a = (data.draw(extreme), data.draw(extreme))
    b = (data.draw(extreme), data.draw(extreme))
    if data.draw(st.booleans()):
        # a window on the line (around a point of it), so that it is not empty
        t = Fraction(data.draw(st.integers(0, 1000)), 1000)
        cx = int((a[0] + t * (b[0] - a[0])) / (1 << S))
        cy = int((a[1] + t * (b[1] - a[1])) / (1 << S))
    else:
        cx, cy = data.draw(st.integers(-50, 50)), data.draw(st.integers(-50, 50))
    w, h = data.draw(st.integers(0, 40)), data.draw(st.integers(0, 40))
    clip = (cx - w // 2, cy - h // 2, cx - w // 2 + w, cy - h // 2 + h)
    want = ref.line_pixels(a, b, S, Fraction(o), clip)
    assert c_line(a, b, S, o, clip=clip) == want, (a, b, S, o, clip)
    assert c_line(b, a, S, o, clip=clip) == want[::-1]


def guarded_canvas(h, w, fmt="gray8", pad=3, guard=0xA5):
    """A Canvas over the middle of a bigger array whose border is guard bytes."""
    channels = {"gray8": (), "rgb888": (3,), "rgba8888": (4,)}[fmt]
    big = np.full((h + 2 * pad, w + 2 * pad) + channels, guard, np.uint8)
    view = big[pad:pad + h, pad:pad + w]
    view[...] = 0
    return big, rastrum.Canvas.wrap(view, fmt), (slice(pad, pad + h), slice(pad, pad + w))


def border_intact(big, inner, guard=0xA5):
    mask = np.ones(big.shape[:2], bool)
    mask[inner] = False
    return bool(np.all(big[mask] == guard))


@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(50))
@given(data=st.data())
def test_huge_lines_through_a_canvas(o, data):
    """Lines 2^28 pixels long crossing a small canvas: the pixels the
    reference puts on the canvas, nothing in the guard border, and quickly
    (the walk jumps to the clip instead of stepping to it)."""
    S = data.draw(st.integers(0, 16))
    M = COORD_MAX
    g = 1 << S
    h, w = data.draw(st.integers(1, 30)), data.draw(st.integers(1, 30))
    a = (data.draw(st.sampled_from([M, -M])), data.draw(st.integers(-M, M)))
    if data.draw(st.booleans()):
        a = a[::-1]
    # b: a point of the canvas (in fixed point), so the line crosses it
    b = (data.draw(st.integers(0, w * g - 1)), data.draw(st.integers(0, h * g - 1)))
    if data.draw(st.booleans()):  # and on through to the other side of the range
        b = (max(-M, min(M, 2 * b[0] - a[0])), max(-M, min(M, 2 * b[1] - a[1])))
    big, canvas, inner = guarded_canvas(h, w, "rgb888")
    t0 = time.perf_counter()
    for _ in range(20):
        lib.rast_draw_line(canvas._target, ffi.new("rast_point *", list(a))[0],
                           ffi.new("rast_point *", list(b))[0],
                           rastrum._lines.line_opts("bresenham", S, o), canvas._pixel((1, 2, 3)))
    elapsed = time.perf_counter() - t0
    assert border_intact(big, inner)
    want = np.zeros((h, w), bool)
    for x, y in ref.line_pixels(a, b, S, Fraction(o), (0, 0, w, h)):
        want[y, x] = True
    got = np.all(canvas.array == (1, 2, 3), axis=2)
    assert np.array_equal(got, want), (a, b, S, o)
    assert np.all(canvas.array[~want] == 0)
    # stepping 2^28 pixels 20 times would take seconds; the jump takes microseconds
    assert elapsed < 0.5, elapsed


# ---- the Python API on float input ------------------------------------------------

@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_line_pixels_and_canvas_line(o, data):
    S = data.draw(st.integers(0, 8))
    h, w = data.draw(st.integers(1, 24)), data.draw(st.integers(1, 24))
    cx, cy = coordinates(S, o, w), coordinates(S, o, h)
    p0 = (data.draw(cx), data.draw(cy))
    p1 = (data.draw(cx), data.draw(cy))
    a = (snap(p0[0], S), snap(p0[1], S))
    b = (snap(p1[0], S), snap(p1[1], S))
    clip = (0, 0, w, h)
    want = ref.line_pixels(a, b, S, Fraction(o), clip)
    got = rastrum.line_pixels(p0, p1, subpixel_bits=S, sample_offset=o, clip=clip)
    assert got.dtype == np.int32 and got.shape == (len(want), 2)
    assert [tuple(p) for p in got.tolist()] == want
    # Canvas.line writes exactly those pixels, whole, and nothing else
    fmt = data.draw(st.sampled_from(["gray8", "rgb888", "rgba8888"]))
    big, canvas, inner = guarded_canvas(h, w, fmt)
    color = {"gray8": 200, "rgb888": (9, 8, 7), "rgba8888": (1, 2, 3, 4)}[fmt]
    canvas.line(p0, p1, color, subpixel_bits=S, sample_offset=o)
    assert border_intact(big, inner)
    mask = np.zeros((h, w), bool)
    for x, y in want:
        mask[y, x] = True
    painted = canvas.array if fmt == "gray8" else canvas.array
    expect = np.zeros_like(painted)
    expect[mask] = color
    assert np.array_equal(painted, expect)


def test_line_pixels_unclipped_and_order():
    got = rastrum.line_pixels((10.25, -3.5), (-7.75, 4.0), subpixel_bits=2)
    want = ref.line_pixels((41, -14), (-31, 16), 2, HALF)
    assert [tuple(p) for p in got.tolist()] == want
    assert tuple(got[0]) == (9, -4)  # starts at p0's end
    empty = rastrum.line_pixels((0.2, 0.2), (0.3, 0.3))  # no sample on it
    assert empty.shape == (0, 2)


# ---- the DDA ------------------------------------------------------------------------

@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("S", [0, 4, 8])
@settings(max_examples=examples(100))
@given(data=st.data())
def test_dda(S, o, data):
    """What is true of the DDA: it is its documented rounding (the
    reference), it has the exact line's major pixels (one per step), and on
    lines shorter than 2^16 steps each pixel is at most one off."""
    a, b = data.draw(endpoints(S, o))
    dda = c_line(a, b, S, o, "dda")
    assert dda == ref.dda_pixels(a, b, S, Fraction(o)), (a, b, S, o)
    exact = c_line(a, b, S, o)
    assert len(dda) == len(exact)
    ymajor = abs(b[1] - a[1]) > abs(b[0] - a[0])
    for (x, y), (ex, ey) in zip(dda, exact):
        if ymajor:
            assert y == ey and abs(x - ex) <= 1
        else:
            assert x == ex and abs(y - ey) <= 1
    clip = (-5, -5, 7, 9)
    assert c_line(a, b, S, o, "dda", clip) == [p for p in dda if -5 <= p[0] < 7 and -5 <= p[1] < 9]


def test_dda_is_not_the_exact_line():
    # slope 1/3 rounds to 21845/65536: the DDA falls behind by x/196608
    # pixel, so after a few thousand steps it puts some pixels a row too high
    a, b = (0, 0), (3 * 40000, 40000)
    dda, exact = c_line(a, b, 0, 0, "dda"), c_line(a, b, 0, 0)
    assert len(dda) == len(exact) == 120001
    assert dda != exact
    assert max(abs(p[1] - q[1]) for p, q in zip(dda, exact)) == 1


def dda_difference_rate(n=2000, span=100, seed=1):
    """Fraction of random lines (S = 8, centres, endpoints within +-span
    pixels) where the DDA's pixels are not the exact line's."""
    rng = np.random.default_rng(seed)
    differ = 0
    for _ in range(n):
        a, b = (tuple(int(v) for v in rng.integers(-span << 8, span << 8, 2)) for _ in range(2))
        differ += c_line(a, b, 8, 0.5, "dda") != c_line(a, b, 8, 0.5)
    return differ / n


def test_dda_differs_on_some_random_lines():
    rate = dda_difference_rate(500)
    assert 0 < rate < 0.5


# ---- polylines and outlines ------------------------------------------------------------

@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(50))
@given(data=st.data())
def test_outline_is_the_union_of_its_lines(o, data):
    S = data.draw(st.integers(0, 8))
    h, w = data.draw(st.integers(1, 20)), data.draw(st.integers(1, 20))
    cx, cy = coordinates(S, o, w), coordinates(S, o, h)
    n = data.draw(st.integers(2, 6))
    pts = [(data.draw(cx), data.draw(cy)) for _ in range(n)]
    closed = data.draw(st.booleans())
    big, canvas, inner = guarded_canvas(h, w, "gray8")
    canvas.polyline(pts, 1, closed=closed, subpixel_bits=S, sample_offset=o)
    assert border_intact(big, inner)
    want = np.zeros((h, w), np.uint8)
    segments = list(zip(pts, pts[1:])) + ([(pts[-1], pts[0])] if closed else [])
    for p0, p1 in segments:
        for x, y in rastrum.line_pixels(p0, p1, subpixel_bits=S, sample_offset=o, clip=(0, 0, w, h)).tolist():
            want[y, x] = 1
    assert np.array_equal(canvas.array, want)


def test_three_lines_make_a_triangle():
    # seed 002: line(t0, t1); line(t1, t2); line(t2, t0)
    tri = [(1, 1), (10, 4), (3, 9)]
    c = rastrum.Canvas((12, 12), format="gray8")
    c.polyline(tri, 255, closed=True, subpixel_bits=0, sample_offset=0)
    d = rastrum.Canvas((12, 12), format="gray8")
    for k in range(3):
        d.line(tri[k], tri[(k + 1) % 3], 255, subpixel_bits=0, sample_offset=0)
    assert np.array_equal(c.array, d.array)
    assert c.array[1, 1] == c.array[4, 10] == c.array[9, 3] == 255


# ---- bad input: InputError, nothing written ---------------------------------------------

@pytest.mark.parametrize(
    "call",
    [
        lambda c: c.line((0, 0), (5, 5), 1, algorithm="wu"),
        lambda c: c.line((0, 0), (5, np.nan), 1),
        lambda c: c.line((0, 0), (5, 1e9), 1),
        lambda c: c.line((0, 0), (5,), 1),
        lambda c: c.line((0, 0), (5, 5), 1, subpixel_bits=17),
        lambda c: c.line((0, 0), (5, 5), 1, sample_offset=0.25),
        lambda c: c.line((0, 0), (5, 5), 256),
        lambda c: c.polyline([(0, 0)], 1),
        lambda c: c.polyline([(0, 0), (3, 3), (4, np.inf)], 1, closed=True),
        lambda c: c.polyline("abc", 1),
        lambda c: rastrum.line_pixels((0, 0), (1, 1), clip=(0, 0, 5)),
        lambda c: rastrum.line_pixels((0, 0), (1, 1), clip=(0, 0, 5, 2 ** 31)),
        lambda c: rastrum.line_pixels((0, 0), (1, 1), algorithm=None),
    ],
)
def test_bad_input_writes_nothing(call):
    c = rastrum.Canvas((8, 8), format="gray8", background=3)
    before = c.array.copy()
    with pytest.raises(rastrum.InputError):
        call(c)
    assert np.array_equal(c.array, before)


def test_registry_and_names():
    assert rastrum.ALGORITHMS["Canvas.line"] == {"bresenham": (), "dda": ()}
    for name in ("line_pixels", "point_in_triangle"):
        assert name in rastrum.__all__ and callable(getattr(rastrum, name))


def test_docstring_examples_run():
    for mod in (rastrum._lines, rastrum._canvas):
        failed, attempted = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
        assert attempted and not failed


@pytest.mark.parametrize("o", OFFSETS)
@settings(max_examples=examples(50))
@given(data=st.data())
def test_closed_boundary_mode_adds_these_lines(o, data):
    """boundary="closed" (boundary.c, through linerun.c) is the exact fill
    plus the pixels line_pixels gives for every edge: the two files agree."""
    S = data.draw(st.integers(0, 8))
    h, w = data.draw(st.integers(1, 16)), data.draw(st.integers(1, 16))
    cx, cy = coordinates(S, o, w), coordinates(S, o, h)
    ring = [(data.draw(cx), data.draw(cy)) for _ in range(data.draw(st.integers(3, 6)))]
    want = rastrum.polygon_mask(ring, (h, w), subpixel_bits=S, sample_offset=o)
    for p0, p1 in zip(ring, ring[1:] + ring[:1]):
        for x, y in rastrum.line_pixels(p0, p1, subpixel_bits=S, sample_offset=o, clip=(0, 0, w, h)).tolist():
            want[y, x] = True
    got = rastrum.polygon_mask(ring, (h, w), subpixel_bits=S, sample_offset=o, boundary="closed")
    assert np.array_equal(got, want), (ring, S, o)

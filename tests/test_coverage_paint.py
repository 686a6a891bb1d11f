"""Anti-aliased Canvas fills (``aa=``): the painted pixels equal the
documented blend applied to the coverage levels that
``rastrum.polygon_coverage`` / ``triangles_coverage`` give for the same
input (those levels are held against the exact rational oracle in
test_coverage.py).  The blend, written here on its own from the docs:

- gray8, rgb888, rgba8888 (alpha too): each channel d becomes
  (s*c + d*(255 - c) + 127) // 255, s the colour's channel, c the level;
- rgb565: the same on the 5/6/5-bit fields, s the colour's top bits;
- mono1: the colour where c >= 128, else unchanged.

Every format, both rules, every method, overlapping rings, opaque and
partial colours, guard pixels around a wrapped sub-view, mono1's padding
bits, and the canvas untouched when an argument is bad.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_

METHODS = ["area", "ss2", "ss4", "ss8", "ss16", "accumulate"]
FORMATS = ["gray8", "rgb888", "rgba8888", "rgb565", "mono1"]
CHANNELS = {"gray8": 1, "rgb888": 3, "rgba8888": 4}
MARGIN = 2  # guard pixels around a wrapped canvas


def mix(s, d, c):
    s, d, c = (np.asarray(v, np.int64) for v in (s, d, c))
    return (s * c + d * (255 - c) + 127) // 255


def expected(fmt, before, color, cov):
    """The documented blend of `color` with coverage levels `cov` (H, W)
    over the pixels `before` (as the canvas's ``array`` shows them)."""
    if fmt in CHANNELS:
        n = CHANNELS[fmt]
        s = np.broadcast_to(np.asarray(color, np.int64), (n,))
        c = cov[..., None] if n > 1 else cov
        return mix(s if n > 1 else s[0], before, c).astype(np.uint8)
    if fmt == "rgb565":
        r, g, b = (int(v) for v in color)
        d = before.astype(np.int64)
        out = (mix(r >> 3, d >> 11, cov) << 11) | (mix(g >> 2, (d >> 5) & 63, cov) << 5) | mix(b >> 3, d & 31, cov)
        return out.astype(np.uint16)
    on = 1 if color else 0
    return np.where(cov >= 128, on, before).astype(np.uint8)


def random_canvas(fmt, shape, rng):
    """A canvas of `shape` with random pixels, and what to compare outside it:
    (canvas, guard) where guard() is True iff nothing outside was written."""
    h, w = shape
    if fmt == "mono1":
        c = rastrum.Canvas((h, w), format="mono1")
        c.packed[...] = rng.integers(0, 256, c.packed.shape, dtype=np.uint8)
        pad = (w % 8) and c.packed[:, -1] & (0xFF >> (w % 8))
        before = c.packed.copy()

        def guard():
            if not w % 8:
                return True
            return np.array_equal(c.packed[:, -1] & (0xFF >> (w % 8)), before[:, -1] & (0xFF >> (w % 8)))
        del pad
        return c, guard
    full = (h + 2 * MARGIN, w + 2 * MARGIN)
    if fmt == "rgb565":
        big = rng.integers(0, 65536, full, dtype=np.uint16)
    elif fmt == "gray8":
        big = rng.integers(0, 256, full, dtype=np.uint8)
    else:
        big = rng.integers(0, 256, full + (CHANNELS[fmt],), dtype=np.uint8)
    keep = big.copy()
    inner = big[MARGIN:-MARGIN, MARGIN:-MARGIN]
    c = rastrum.Canvas.wrap(inner, format=fmt if fmt == "rgb565" else None)

    def guard():
        outside = np.ones(full, bool)
        outside[MARGIN:-MARGIN, MARGIN:-MARGIN] = False
        return np.array_equal(big[outside], keep[outside])
    return c, guard


def random_color(fmt, rng, opaque):
    if fmt == "mono1":
        return int(rng.integers(0, 2))
    if fmt == "gray8":
        return 255 if opaque else int(rng.integers(0, 256))
    n = 3 if fmt == "rgb565" else CHANNELS[fmt]
    if opaque:
        return tuple([255] * n)
    col = [int(v) for v in rng.integers(0, 256, n)]
    if n == 4:
        col[3] = 128  # a partial alpha: mixed like the other channels
    return tuple(col)


@settings(max_examples=S_.examples(60), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       rule=st.sampled_from(["evenodd", "nonzero"]), S=st.sampled_from([0, 2, 4, 8]),
       o=st.sampled_from([0.5, 0.0]), opaque=st.booleans(), seed=st.integers(0, 2 ** 32 - 1))
def test_polygon_blend_equals_formula_on_coverage(data, fmt, method, rule, S, o, opaque, seed):
    rl, shape = data.draw(S_.scenes(S, o, max_h=20, max_w=20), label="scene")
    rng = np.random.default_rng(seed)
    canvas, guard = random_canvas(fmt, shape, rng)
    color = random_color(fmt, rng, opaque)
    before = canvas.array.copy()
    try:
        cov = rastrum.polygon_coverage(rl, shape, rule=rule, method=method, subpixel_bits=S, sample_offset=o)
    except rastrum.InputError as e:  # ssK at the range limit: refused alike, nothing written
        with pytest.raises(rastrum.InputError, match=str(e).split(":")[0]):
            canvas.fill_polygon(rl, color, rule=rule, subpixel_bits=S, sample_offset=o, aa=method)
        np.testing.assert_array_equal(canvas.array, before)
        assert guard()
        return
    canvas.fill_polygon(rl, color, rule=rule, subpixel_bits=S, sample_offset=o, aa=method)
    np.testing.assert_array_equal(canvas.array, expected(fmt, before, color, cov))
    assert guard()


@settings(max_examples=S_.examples(40), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       S=st.sampled_from([0, 3, 8]), seed=st.integers(0, 2 ** 32 - 1))
def test_triangles_blend_equals_formula_on_coverage(data, fmt, method, S, seed):
    """A batch is one region: overlapping triangles blend once, as its
    union's coverage says."""
    shape = data.draw(S_.shapes(16, 16), label="shape")
    h, w = shape
    n = data.draw(st.integers(0, 6), label="n")
    coord = st.floats(-2, max(h, w) + 2, allow_nan=False)
    tris = np.array(data.draw(st.lists(st.tuples(coord, coord), min_size=3 * n, max_size=3 * n), label="v"),
                    np.float64).reshape(n, 3, 2)
    rng = np.random.default_rng(seed)
    canvas, guard = random_canvas(fmt, shape, rng)
    color = random_color(fmt, rng, False)
    before = canvas.array.copy()
    cov = rastrum.triangles_coverage(tris, shape, method=method, subpixel_bits=S)
    canvas.fill_triangles(tris, color, subpixel_bits=S, aa=method)
    np.testing.assert_array_equal(canvas.array, expected(fmt, before, color, cov))
    assert guard()
    if n:
        one = random_canvas(fmt, shape, np.random.default_rng(seed))[0]
        c1 = rastrum.triangles_coverage(tris[:1], shape, method=method, subpixel_bits=S)
        b1 = one.array.copy()
        one.fill_triangle(tris[0], color, subpixel_bits=S, aa=method)
        np.testing.assert_array_equal(one.array, expected(fmt, b1, color, c1))


def test_overlap_blends_once():
    """A square drawn twice in one call (non-zero: winding 2) is blended by
    its coverage once: the result is one fill's, not two."""
    sq = np.array([(1.25, 1.25), (5.5, 1.25), (5.5, 4.75), (1.25, 4.75)])
    for method in ["area", "ss4"]:
        once = rastrum.Canvas((6, 7), format="gray8", background=40)
        twice = rastrum.Canvas((6, 7), format="gray8", background=40)
        once.fill_polygon([sq], 200, rule="nonzero", aa=method)
        twice.fill_polygon([sq, sq], 200, rule="nonzero", aa=method)
        np.testing.assert_array_equal(once.array, twice.array)
        assert once.array[2, 2] == 200 and once.array[1, 1] == mix(200, 40, 144)  # 3/4 * 3/4 -> 143.4


def test_mesh_has_no_seams():
    """A triangulated square in one call: every interior pixel gets the
    colour exactly, every outside pixel keeps the background."""
    v = np.array([[1, 1], [4.4, 1], [9, 1], [1, 5.2], [5.1, 4.7], [9, 5.6], [1, 9], [4.8, 9], [9, 9]])
    tris = []
    for r in range(2):
        for c in range(2):
            a, b, d, e = v[3 * r + c], v[3 * r + c + 1], v[3 * r + c + 4], v[3 * r + c + 3]
            tris += [[a, b, d], [a, d, e]]
    for method in METHODS:
        canvas = rastrum.Canvas((11, 11), format="rgb888", background=(9, 8, 7))
        canvas.fill_triangles(tris, (250, 100, 3), aa=method)
        want = np.empty((11, 11, 3), np.uint8)
        want[...] = (9, 8, 7)
        want[1:9, 1:9] = (250, 100, 3)
        np.testing.assert_array_equal(canvas.array, want, err_msg=method)


def test_mono1_threshold():
    """mono1 is on where the level is >= 128, off-pixels elsewhere stay."""
    c = rastrum.Canvas((1, 4), format="mono1")
    # coverage of columns 0..3: 0.5 (128), 127/255 (127 -> off), 1 (255), 0
    c.fill_polygon([(0.5, 0), (1, 0), (1, 1), (0.5, 1)], 1, aa="area")
    c.fill_polygon([(1 + 128 / 255, 0), (3, 0), (3, 1), (1 + 128 / 255, 1)], 1, aa="area", subpixel_bits=16)
    assert rastrum.polygon_coverage([(1 + 128 / 255, 0), (2, 0), (2, 1), (1 + 128 / 255, 1)], (1, 3),
                                    subpixel_bits=16)[0, 1] == 127
    assert c.array.tolist() == [[1, 0, 1, 0]]


def test_binary_is_unchanged():
    """aa=None is the binary fill, the same pixels as without the keyword."""
    ring = [(0.3, 0.7), (7.9, 1.2), (3.3, 6.6)]
    a = rastrum.Canvas((8, 9), format="rgb888")
    b = rastrum.Canvas((8, 9), format="rgb888")
    a.fill_polygon(ring, (1, 2, 3))
    b.fill_polygon(ring, (1, 2, 3), aa=None)
    np.testing.assert_array_equal(a.array, b.array)


BAD = [
    ("fill_polygon", dict(aa="ss3"), r"aa='ss3'.*None.*area, ss2, ss4, ss8, ss16, accumulate"),
    ("fill_polygon", dict(aa=True), r"aa=True"),
    ("fill_polygon", dict(aa="area", algorithm="xscan"), r"algorithm='xscan' is for binary fills"),
    ("fill_polygon", dict(aa="area", boundary="closed"), r"boundary='closed' is for binary fills"),
    ("fill_polygon", dict(aa="area", rounding="textbook"), r"rounding"),
    ("fill_polygon", dict(aa="area", rule="bogus"), r"rule"),
    ("fill_polygon", dict(aa="ss4", subpixel_bits=17), r"subpixel_bits"),
    ("fill_polygon", dict(aa="area", color=(1, 2, 3, 4, 5)), r"colour"),
    # (vertex_colors with aa was refused until the anti-aliased colour
    # polygon came; colours that do not match the vertices still are)
    ("fill_polygon", dict(aa="area", color=None, vertex_colors=[(1, 2, 3)] * 2), r"vertex_colors"),
    ("fill_polygon", dict(aa="area", vertex_colors=[(1, 2, 3)] * 3), r"one of color and vertex_colors"),
    ("fill_polygon", dict(aa="area", rings=[(0, 0), (float("nan"), 1), (2, 2)]), r"rings"),
    ("fill_triangles", dict(aa="area", color=[(1, 2, 3)]), r"one colour"),
    ("fill_triangles", dict(aa="area", depth=[(1, 2, 3)]), r"depth"),
    ("fill_triangles", dict(aa="area", algorithm="sweep"), r"algorithm='sweep' is for binary fills"),
    ("fill_triangles", dict(aa="area", shading="flat"), r"shading='flat'"),
    ("fill_triangles", dict(aa="area", tris=[[(0, 0), (1e12, 0), (0, 1)]]), r"tris"),
    ("fill_triangles", dict(aa="ss16", tris=[[(0, 0), (2 ** 24, 0), (0, 1)]], subpixel_bits=0),
     r"times 16"),
    ("fill_triangle", dict(aa="bogus"), r"aa='bogus'"),
]


@pytest.mark.parametrize("method,kwargs,match", BAD, ids=[str(i) for i in range(len(BAD))])
def test_bad_input_writes_nothing(method, kwargs, match):
    canvas = rastrum.Canvas((6, 6), format="rgb888", background=(5, 6, 7))
    before = canvas.array.copy()
    kw = dict(kwargs)
    if method == "fill_polygon":
        geometry = kw.pop("rings", [(0, 0), (5, 1), (2, 5)])
    elif method == "fill_triangles":
        geometry = kw.pop("tris", [[(0, 0), (5, 1), (2, 5)]])
    else:
        geometry = [(0, 0), (5, 1), (2, 5)]
    color = kw.pop("color", (200, 100, 0))
    with pytest.raises(rastrum.InputError, match=match):
        getattr(canvas, method)(geometry, color, **kw)
    np.testing.assert_array_equal(canvas.array, before)


def test_label_canvas_refuses_aa():
    for dtype in (np.int32, np.int64):
        a = np.zeros((4, 4), dtype)
        c = rastrum.Canvas.wrap(a, format="label")
        with pytest.raises(rastrum.InputError, match="labels.*aa=None"):
            c.fill_polygon([(0, 0), (3, 0), (0, 3)], 7, aa="area")
        assert not a.any()


def test_aa_methods_table():
    assert set(rastrum.AA_METHODS) == {"Canvas.fill_polygon", "Canvas.fill_triangle", "Canvas.fill_triangles"}
    for entry, methods in rastrum.AA_METHODS.items():
        assert list(methods) == METHODS, entry
        assert all(rules == ("evenodd", "nonzero") for rules in methods.values())

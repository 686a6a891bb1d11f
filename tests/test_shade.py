"""Shading and pixel formats: painters decide what is written, fillers which
pixels.  Exact Gouraud colours and depths equal the fraction oracle
(oracle_shade.py) bit for bit; a shaded call writes exactly the pixels the
unshaded one writes, for every filler and format; rgb565 and mono1 take
every existing entry point."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from oracle_shade import INT32_MAX, pack, shade
from strategies import assert_same, examples, rings, shapes
from test_triangles import ALGOS, OFFSETS, ROUNDINGS, lit, triangles

FORMATS = ["gray8", "rgb888", "rgba8888", "rgb565", "mono1"]
CHANNELS = {"gray8": 1, "mono1": 1, "rgb888": 3, "rgb565": 3, "rgba8888": 4}
# two backgrounds that differ in every bit a pixel has
BACKGROUNDS = {"gray8": (0, 255), "mono1": (0, 1), "rgb888": (0, 255),
               "rgba8888": (0, 255), "rgb565": (0, 255)}


def spell(precision):
    """The current spelling of a precision (flat is shading="flat")."""
    return {"shading": "flat"} if precision == "flat" else {"precision": precision}


def vertex_colors_for(fmt, rgba):
    """The (N, 3, C) array a user of `fmt` gives for (N, 3, 4) colours."""
    c = CHANNELS[fmt]
    return rgba[..., :1] if c == 1 else rgba[..., :c]


def effective_rgba(fmt, rgba):
    """The RGBA the library interpolates for those: C = 1 is R = G = B."""
    out = rgba.copy()
    if CHANNELS[fmt] == 1:
        out[..., 1] = out[..., 2] = out[..., 0]
    if CHANNELS[fmt] != 4:
        out[..., 3] = 255
    return out


def expected_canvas(fmt, shape, background, rgba_out):
    c = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=background)
    want = c.array.copy()
    written = rgba_out[..., 0] >= 0
    want[written] = pack(np.where(rgba_out < 0, 0, rgba_out), fmt)[written]
    return want


@st.composite
def colour_batches(draw, S, o, max_h=20, max_w=20, max_n=4, with_depth=False):
    shape = draw(shapes(max_h, max_w))
    tris = draw(st.lists(triangles(S, o, shape), min_size=0, max_size=max_n))
    n = len(tris)
    level = st.one_of(st.integers(0, 255), st.sampled_from([0, 1, 127, 128, 254, 255]))
    cols = np.array(draw(st.lists(st.lists(st.lists(level, min_size=4, max_size=4),
                                           min_size=3, max_size=3), min_size=n, max_size=n)),
                    dtype=np.int64).reshape(n, 3, 4)
    depth = None
    if with_depth:
        zval = st.one_of(st.integers(-3, 3), st.integers(-2 ** 31, 2 ** 31 - 1),
                         st.sampled_from([-2 ** 31, 2 ** 31 - 1]))
        depth = np.array(draw(st.lists(st.lists(zval, min_size=3, max_size=3),
                                       min_size=n, max_size=n)), dtype=np.int64).reshape(n, 3)
    return tris, shape, cols, depth


# --- exact colours against the fraction oracle ----------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
@settings(max_examples=examples(40))
@given(data=st.data())
def test_exact_matches_oracle(fmt, data):
    S = data.draw(st.sampled_from([0, 1, 4, 8, 16]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    alg = data.draw(st.sampled_from(ALGOS), label="alg")
    tris, shape, cols, depth = data.draw(colour_batches(S, o, with_depth=data.draw(st.booleans())),
                                         label="batch")
    kw = dict(subpixel_bits=S, sample_offset=o, rounding=rounding)
    want, zwant = shade(tris, effective_rgba(fmt, cols), shape, depth=depth, **kw)
    bg = BACKGROUNDS[fmt][0]
    c = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=bg)
    c.fill_triangles(np.asarray(tris, dtype=np.float64).reshape(-1, 3, 2),
                     vertex_colors=vertex_colors_for(fmt, cols), depth=depth, algorithm=alg, **kw)
    msg = f"{fmt} {alg} {lit(tris)} {shape} {cols.tolist()} depth={depth} {kw}"
    assert_same(c.array, expected_canvas(fmt, shape, bg, want), msg)
    if depth is not None and len(tris):
        assert_same(c.depth, zwant, "depth " + msg)


@settings(max_examples=examples(60))
@given(data=st.data())
def test_exact_ties_on_sample_grid(data):
    """Vertices on sample points of a small grid make exact halves common:
    they must round up, in every filler."""
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    shape = (8, 8)
    # far coordinates (up to the range at S = 1) and depths of 2^28 steps
    # send the products past int64_t: the 128-bit path, with ties too
    far = st.sampled_from([2 ** 12, 2 ** 20, 2 ** 25, 2 ** 26 - 1])
    near = st.integers(-1, 8)
    coord = st.one_of(near, near, near, far, far.map(lambda v: -v))
    pt = st.tuples(coord, coord).map(lambda p: (p[0] + o, p[1] + o))
    n = data.draw(st.integers(1, 3), label="n")
    tris = [[data.draw(pt, label="p") for _ in range(3)] for _ in range(n)]
    cols = np.array(data.draw(st.lists(st.integers(0, 255), min_size=12 * n, max_size=12 * n),
                              label="cols")).reshape(n, 3, 4)
    zval = st.integers(-8, 7).map(lambda k: k * 2 ** 28).flatmap(
        lambda z: st.integers(max(z - 3, -2 ** 31), min(z + 3, 2 ** 31 - 1)))
    depth = None
    if data.draw(st.booleans(), label="with depth"):
        depth = np.array(data.draw(st.lists(zval, min_size=3 * n, max_size=3 * n))).reshape(n, 3)
    want, zwant = shade(tris, cols, shape, subpixel_bits=1, sample_offset=o, depth=depth)
    for alg in ALGOS:
        c = rastrum.Canvas((8, 8), format="rgba8888")
        c.fill_triangles(tris, vertex_colors=cols, algorithm=alg, subpixel_bits=1, sample_offset=o,
                         depth=depth)
        msg = f"{alg} {tris} {cols.tolist()} depth={depth}"
        assert_same(c.array, expected_canvas("rgba8888", shape, 0, want), msg)
        if depth is not None:
            assert_same(c.depth, zwant, "depth " + msg)


@settings(max_examples=examples(40))
@given(data=st.data())
def test_flat_matches_oracle(data):
    """precision="flat" and per-triangle colours: vertex 0's colour; depth
    still interpolated exactly."""
    S = data.draw(st.sampled_from([0, 4, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    fmt = data.draw(st.sampled_from(FORMATS), label="fmt")
    tris, shape, cols, depth = data.draw(colour_batches(S, o, with_depth=data.draw(st.booleans())),
                                         label="batch")
    kw = dict(subpixel_bits=S, sample_offset=o)
    rgba = effective_rgba(fmt, cols)
    want, _ = shade(tris, rgba, shape, depth=depth, precision="flat", **kw)
    batch = np.asarray(tris, dtype=np.float64).reshape(-1, 3, 2)
    for how in ("vertex", "per_triangle"):
        c = rastrum.Canvas((shape[0], shape[1]), format=fmt)
        if how == "vertex":
            c.fill_triangles(batch, vertex_colors=vertex_colors_for(fmt, cols), shading="flat",
                             depth=depth, **kw)
        else:
            c.fill_triangles(batch, vertex_colors_for(fmt, cols)[:, 0], depth=depth, **kw)
        assert_same(c.array, expected_canvas(fmt, shape, 0, want), f"{how} {fmt} {lit(tris)} {kw}")


def test_exact_on_sample_points_and_ties():
    """Vertices on sample points: the vertex pixel gets the vertex colour;
    a value exactly halfway rounds up."""
    c = rastrum.Canvas((3, 5), format="gray8")
    # x from 0.5 to 4.5 on row 0's samples: 0 at x=0.5, 1 at x=4.5 -> 0.25 per pixel
    c.fill_triangles([[(0.5, 0.5), (4.5, 0.5), (0.5, 2.5)]], vertex_colors=[[[0], [1], [0]]])
    # row 0: 0, .25, .5 -> 1 (half up), .75 -> 1; (4.5, .5) is a right vertex: not owned
    assert c.array[0].tolist() == [0, 0, 1, 1, 0]
    c = rastrum.Canvas((3, 3), format="gray8")
    c.fill_triangles([[(0.5, 0.5), (2.5, 0.5), (0.5, 2.5)]], vertex_colors=[[[200], [10], [90]]])
    assert c.array[0, 0] == 200 and c.array[0, 1] == 105 and c.array[1, 0] == 145


# --- painters decide what, fillers which: the same pixels -----------------------

def written(fmt, shape, paint):
    """The pixels a call writes: equal on two canvases of different
    backgrounds (every bit differs) iff written."""
    got = []
    for bg in BACKGROUNDS[fmt]:
        c = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=bg)
        paint(c)
        got.append(c.array)
    same = got[0] == got[1]
    return same.all(axis=-1) if same.ndim == 3 else same


@pytest.mark.parametrize("precision", ["exact", "fixed", "flat"])
@settings(max_examples=examples(40))
@given(data=st.data())
def test_shaded_pixels_equal_unshaded(precision, data):
    S = data.draw(st.sampled_from([0, 3, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    boundary = data.draw(st.sampled_from(["exact", "exact", "closed", "conservative"]), label="boundary")
    fmt = data.draw(st.sampled_from(FORMATS), label="fmt")
    F = data.draw(st.integers(1, 16), label="F")
    tris, shape, cols, _ = data.draw(colour_batches(S, o, 16, 16), label="batch")
    batch = np.asarray(tris, dtype=np.float64).reshape(-1, 3, 2)
    kw = dict(subpixel_bits=S, sample_offset=o, rounding=rounding, boundary=boundary)
    for alg in ALGOS:
        want = rastrum.triangles_mask(batch, shape, algorithm=alg, **kw)
        got = written(fmt, shape, lambda c: c.fill_triangles(
            batch, vertex_colors=vertex_colors_for(fmt, cols), **spell(precision),
            fraction_bits=F, algorithm=alg, **kw))
        assert_same(got, want, f"{precision} F={F} {fmt} {alg} {lit(tris)} {shape} {kw}")


# --- fixed point: close to exact --------------------------------------------------

@settings(max_examples=examples(60))
@given(data=st.data())
def test_fixed_16_within_one_level(data):
    """With F = 16 the stepped value is off by far less than half a level on
    these small targets, so a pixel is at most one level from exact."""
    S = data.draw(st.sampled_from([0, 4, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    tris, shape, cols, _ = data.draw(colour_batches(S, o, 24, 24), label="batch")
    batch = np.asarray(tris, dtype=np.float64).reshape(-1, 3, 2)
    out = []
    for precision in ("exact", "fixed"):
        c = rastrum.Canvas((shape[0], shape[1]), format="rgba8888")
        c.fill_triangles(batch, vertex_colors=cols, precision=precision, fraction_bits=16,
                         subpixel_bits=S, sample_offset=o)
        out.append(c.array.astype(int))
    assert np.abs(out[0] - out[1]).max(initial=0) <= 1, f"{lit(tris)} {shape} {cols.tolist()}"


def fixed_by_paths(batch, cols, shape, precision="fixed", **kw):
    """A fill on rgba8888 (the packed path where it applies: exact rounding
    and boundary, a small enough box) and the same colours through the
    general path: R, G, B on rgb888, A as the level of gray8."""
    out = {}
    for fmt, vc in (("rgba8888", cols), ("rgb888", cols[..., :3]), ("gray8", cols[..., 3:])):
        c = rastrum.Canvas((shape[0], shape[1]), format=fmt)
        c.fill_triangles(batch, vertex_colors=vc, precision=precision, **kw)
        out[fmt] = c.array.astype(int)
    return out["rgba8888"], np.dstack([out["rgb888"], out["gray8"]])


@settings(max_examples=examples(60))
@given(data=st.data())
def test_fixed_packed_equals_general(data):
    """The packed rgba8888 path (two channels a 64-bit word, no clamping)
    computes the documented fixed-point values: equal, pixel for pixel, to
    the general per-channel path that other formats take."""
    S = data.draw(st.sampled_from([0, 2, 8, 16]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    boundary = data.draw(st.sampled_from(["exact", "exact", "exact", "closed"]), label="boundary")
    F = data.draw(st.integers(1, 16), label="F")
    alg = data.draw(st.sampled_from(ALGOS), label="alg")
    tris, shape, cols, _ = data.draw(colour_batches(S, o, 24, 24, max_n=6), label="batch")
    batch = np.asarray(tris, dtype=np.float64).reshape(-1, 3, 2)
    got, want = fixed_by_paths(batch, cols, shape, fraction_bits=F, algorithm=alg,
                               subpixel_bits=S, sample_offset=o, rounding=rounding,
                               boundary=boundary)
    assert_same(got, want, f"F={F} {alg} {lit(tris)} {shape} {cols.tolist()}")


@pytest.mark.parametrize("F", [3, 6, 8, 12, 16, "exact"])
def test_fixed_packed_equals_general_many(F):
    """The same on 400 random triangles of up to ~300 px (boxes past 2^F
    for small F: both paths in one batch), slivers, vertices on sample
    points (exact halves) and vertex colours at the ends of the range;
    "exact": the exact packed path against the general one."""
    rng = np.random.default_rng(F if F != "exact" else 99)
    ctr = rng.uniform(0, 128, (400, 1, 2))
    batch = ctr + rng.normal(0, 6, (400, 3, 2)) * rng.uniform(0.2, 3, (400, 1, 1))
    batch[::7, 2] = batch[::7, 0] + (batch[::7, 1] - batch[::7, 0]) * 0.5 + 0.01  # slivers
    batch[1::5] = np.round(batch[1::5]) + 0.5  # on sample points
    cols = rng.choice([0, 1, 128, 254, 255, 17, 200], (400, 3, 4)).astype(np.int64)
    kw = dict(precision="exact") if F == "exact" else dict(fraction_bits=F)
    got, want = fixed_by_paths(batch, cols, (128, 128), **kw)
    assert_same(got, want, f"F={F}")


@pytest.mark.parametrize("S", [0, 4, 8, 12])
def test_exact_packed_equals_general_big(S):
    """Big triangles (2A past 2^31 at S >= 8: the packed exact path keeps
    its remainders in 64-bit registers instead of 32-bit lanes), vertices on
    sample points so that exact halves are everywhere."""
    rng = np.random.default_rng(S + 7)
    batch = np.round(rng.uniform(-20, 148, (60, 3, 2))) + 0.5
    cols = rng.integers(0, 256, (60, 3, 4)).astype(np.int64)
    got, want = fixed_by_paths(batch, cols, (128, 128), precision="exact", subpixel_bits=S)
    assert_same(got, want, f"S={S}")


def test_fixed_error_grows_as_f_shrinks():
    """Coarser F, larger error: F = 2 is visibly off somewhere on a big
    smooth triangle, F = 16 nowhere by more than one level."""
    tri = [[(0.3, 0.2), (250.7, 10.1), (30.2, 180.9)]]
    cols = [[[0, 255, 17, 255], [255, 3, 100, 255], [90, 180, 255, 255]]]
    ref = rastrum.Canvas((192, 256), format="rgba8888")
    ref.fill_triangles(tri, vertex_colors=cols)
    err = {}
    for F in (2, 16):
        c = rastrum.Canvas((192, 256), format="rgba8888")
        c.fill_triangles(tri, vertex_colors=cols, precision="fixed", fraction_bits=F)
        err[F] = np.abs(c.array.astype(int) - ref.array).max()
    assert err[16] <= 1 < err[2]


# --- depth ------------------------------------------------------------------------

def test_depth_nearer_wins_whatever_the_order():
    a = [(0, 0), (10, 0), (0, 10)]
    b = [(10, 10), (0, 10), (10, 0)]
    big = [(0, 0), (10, 0), (10, 10)]
    res = []
    for order in ([0, 1, 2], [2, 1, 0]):
        c = rastrum.Canvas((10, 10), format="gray8")
        tris = [a, b, big]
        colours = [[[10]] * 3, [[20]] * 3, [[30]] * 3]
        depths = [[5, 5, 5], [1, 1, 1], [3, 3, 3]]
        c.fill_triangles([tris[k] for k in order], vertex_colors=[colours[k] for k in order],
                         depth=[depths[k] for k in order])
        res.append(c.array.copy())
        assert c.depth.dtype == np.int32 and c.depth.shape == (10, 10)
    assert_same(res[0], res[1], "order")
    # a alone, a under big (nearer), big under b (nearer)
    assert (res[0][7, 1], res[0][1, 5], res[0][3, 8]) == (10, 30, 20)


def test_depth_buffer_kept_and_cleared():
    c = rastrum.Canvas((4, 4), format="gray8")
    assert c.depth is None
    c.fill_triangles([[(0, 0), (4, 0), (0, 4)]], 50)  # no depth: nothing made
    assert c.depth is None
    c.fill_triangles([[(0, 0), (4, 0), (0, 4)]], 100, depth=[[7, 7, 7]])
    assert c.depth[0, 0] == 7 and c.depth[3, 3] == INT32_MAX
    c.fill_triangles([[(0, 0), (4, 0), (0, 4)]], 200, depth=[[7, 7, 7]])  # equal fails
    assert c.array[0, 0] == 100
    c.clear_depth()
    assert c.depth is None
    c.fill_triangles([[(0, 0), (4, 0), (0, 4)]], 200, depth=[[7, 7, 7]])
    assert c.array[0, 0] == 200


# --- pixel formats through the existing entry points ---------------------------

@pytest.mark.parametrize("fmt", ["rgb565", "mono1"])
@settings(max_examples=examples(40))
@given(data=st.data())
def test_new_formats_fill_polygons_exactly(fmt, data):
    S = data.draw(st.sampled_from([0, 4, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    shape = data.draw(shapes(20, 37), label="shape")
    rl = [data.draw(rings(S, o, shape), label="ring")]
    alg = data.draw(st.sampled_from(sorted(rastrum.ALGORITHMS["polygon_mask"])), label="alg")
    kw = dict(subpixel_bits=S, sample_offset=o)
    want = oracle_mask(rl, shape, rule="evenodd", **kw)
    on, off = ((255, 0, 128), (0, 255, 7)) if fmt == "rgb565" else (1, 0)
    for bg, fg in ((off, on), (on, off)):
        c = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=bg)
        c.fill_polygon(rl, fg, algorithm=alg, **kw)
        ref = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=fg).array
        exp = rastrum.Canvas((shape[0], shape[1]), format=fmt, background=bg).array.copy()
        exp[want] = ref[want]
        assert_same(c.array, exp, f"{fmt} {alg} {rl} {shape} {kw}")
        if fmt == "mono1":  # padding bits after the last column untouched
            pad = (-shape[1]) % 8
            if pad and shape[0]:
                last = c.packed[:, -1] & ((1 << pad) - 1)
                assert (last == (((1 << pad) - 1) if bg == 1 else 0)).all()


def test_mono1_bit_order_and_lines():
    c = rastrum.Canvas((2, 19), format="mono1")
    c.line((0, 0), (18, 0), 1, subpixel_bits=0, sample_offset=0)
    assert c.packed[0].tolist() == [0xFF, 0xFF, 0xE0] and c.packed[1].tolist() == [0, 0, 0]
    c.fill_polygon([(3, 1), (10, 1), (10, 2), (3, 2)], 1, sample_offset=0)
    assert c.packed[1].tolist() == [0b00011111, 0b11000000, 0]
    assert c.array[1].tolist() == [0, 0, 0] + [1] * 7 + [0] * 9
    img = c.to_image()
    assert img.mode == "1" and np.array_equal(np.asarray(img), c.array.astype(bool))


def test_rgb565_packing_and_image():
    c = rastrum.Canvas((1, 3), format="rgb565", background=(8, 4, 8))
    assert c.array.dtype == np.uint16 and c.array.tolist() == [[(1 << 11) | (1 << 5) | 1] * 3]
    c.fill_triangles([[(0, 0), (3, 0), (0, 3)]], (255, 255, 255))
    assert c.array[0, 0] == 0xFFFF
    assert np.asarray(c.to_image())[0, 0].tolist() == [255, 255, 255]
    wrapped = rastrum.Canvas.wrap(np.zeros((2, 5), np.uint16), format="rgb565")
    assert wrapped.format == "rgb565"
    wrapped.fill_polygon([(0, 0), (5, 0), (5, 2)], (255, 0, 0), sample_offset=0)
    assert wrapped.array[0, 1] == 0xF800
    for fmt in ("mono1", "rgb565"):
        with pytest.raises(rastrum.InputError, match=fmt):
            rastrum.Canvas.wrap(np.zeros((2, 5), np.uint8), format=fmt)


# --- bad input ----------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, what", [
    (dict(), "color or vertex_colors"),
    (dict(color=1, vertex_colors=[[[1], [2], [3]]]), "exactly one"),
    (dict(vertex_colors=[[[1], [2]]]), "shape"),
    (dict(vertex_colors=[[[1, 2, 3], [1, 2, 3], [1, 2, 3]]]), "channels"),
    (dict(vertex_colors=[[[1], [2], [300]]]), "0..255"),
    (dict(vertex_colors=[[[1], [2], [3]]], precision="rough"), "precision"),
    (dict(vertex_colors=[[[1], [2], [3]]], precision="fixed", fraction_bits=0), "fraction_bits"),
    (dict(vertex_colors=[[[1], [2], [3]]], precision="fixed", fraction_bits=17), "fraction_bits"),
    (dict(color=1, depth=[[1, 2]]), "depth"),
    (dict(color=1, depth=[[1, 2, 2.0 ** 31]]), "int32"),
    (dict(color=1, depth=[[1, 2, float("nan")]]), "int32"),
])
def test_bad_shading_input(kwargs, what):
    c = rastrum.Canvas((4, 4), format="gray8")
    with pytest.raises(rastrum.InputError, match=what):
        c.fill_triangles([[(0, 0), (4, 0), (0, 4)]], **kwargs)
    assert not c.array.any() and c.depth is None


def test_readme_shading_example():
    """The docs' shading example (docs/python.md) runs as written
    (tests/test_readme.py runs every block; this one is named here)."""
    import os
    import re
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(root, "docs", "python.md"), encoding="utf-8") as f:
        (code,) = [c for c in re.findall(r"```python\n(.*?)```", f.read(), flags=re.S) if "vertex_colors=cols" in c]
    exec(compile(code, "docs/python.md", "exec"), {})

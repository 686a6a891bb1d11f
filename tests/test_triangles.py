"""Triangle batches equal the exact oracle bit for bit (docs/semantics.md): each
triangle owns what the polygon rule gives it as a one-ring polygon."""

import doctest
import itertools
import re

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import rastrum._canvas
import rastrum._triangles
from oracle import oracle_mask
from strategies import (COORD_MAX, assert_same, coordinates, examples,
                        is_in_range, limit_px, shapes)

ALGOS = list(rastrum.ALGORITHMS["triangles_mask"])
OFFSETS = [0.5, 0.0]
ROUNDINGS = ["exact", "textbook"]


def test_registry():
    assert ALGOS == ["edge", "sweep", "edgeflag"]
    for table in ("triangles_mask", "Canvas.fill_triangles"):
        assert rastrum.ALGORITHMS[table] == {a: ("evenodd", "nonzero") for a in ALGOS}


def test_docstrings_run():
    for mod in (rastrum._triangles, rastrum._canvas):
        res = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
        assert res.failed == 0 and res.attempted > 0, mod


# --- the reference ----------------------------------------------------------

def oracle_count(tris, shape, S, o, rounding):
    """Sum over the triangles of the oracle's mask of each as a ring."""
    out = np.zeros(shape, np.int64)
    for t in tris:
        out += oracle_mask([list(map(tuple, t))], shape, rule="evenodd",
                           subpixel_bits=S, sample_offset=o, rounding=rounding)
    return out


def lit(tris):
    return np.asarray(tris, dtype=np.float64).tolist()


def check_batch(tris, shape, S, o, rounding, algorithms=ALGOS):
    """Every algorithm's count equals the oracle's; set mode is count > 0."""
    exp = oracle_count(tris, shape, S, o, rounding)
    kw = dict(subpixel_bits=S, sample_offset=o, rounding=rounding)
    for alg in algorithms:
        got = rastrum.triangles_count(tris, shape, algorithm=alg, **kw)
        assert got.dtype == np.uint16 and got.shape == tuple(shape)
        msg = f"rastrum.triangles_mask({lit(tris)!r}, {tuple(shape)!r}, algorithm={alg!r}, mode='count', {kw})"
        assert_same(got, exp, msg)
        got = rastrum.triangles_mask(tris, shape, algorithm=alg, **kw)
        assert got.dtype == np.bool_
        assert_same(got, exp > 0, msg.replace("'count'", "'set'"))


# --- strategies -------------------------------------------------------------

@st.composite
def triangles(draw, S, o, shape):
    """One awkward triangle: random, a sliver thinner than 1/2^S, huge and
    mostly off-screen, on sample points, at the range limit, degenerate."""
    H, W = shape
    g = 1 << S
    cx, cy = coordinates(S, o, W), coordinates(S, o, H)
    kind = draw(st.sampled_from(["random", "random", "sliver", "huge", "on_sample",
                                 "limit", "degenerate", "horizontal"]))
    p = [(draw(cx), draw(cy)) for _ in range(3)]
    if kind == "sliver":
        # the third vertex off the first edge's midpoint by less than a grid
        # step: thinner than 1/2^S, snapped either onto the edge or just off
        t = draw(st.floats(-2.0 / g, 2.0 / g))
        (x0, y0), (x1, y1) = p[0], p[1]
        p[2] = ((x0 + x1) / 2 + t, (y0 + y1) / 2 - t)
    elif kind == "huge":
        lim = limit_px(S)
        far = st.floats(-lim, lim)
        p[0] = (draw(far), draw(far))
        p[1] = (draw(far), draw(cy))
    elif kind == "on_sample":
        p = [(draw(st.integers(-2, W + 2)) + o, draw(st.integers(-2, H + 2)) + o) for _ in range(3)]
    elif kind == "limit":
        lim = limit_px(S)
        edge = st.sampled_from([lim, -lim, (COORD_MAX + 0.25) / g, -(COORD_MAX + 0.5) / g])
        p[0] = (draw(edge), draw(edge))
        p[1] = (draw(edge), draw(cy))
    elif kind == "degenerate":
        (x0, y0), (x1, y1) = p[0], p[1]
        t = draw(st.sampled_from([-1.0, 0.0, 0.5, 2.0]))
        p[2] = (x0 + t * (x1 - x0), y0 + t * (y1 - y0))
    elif kind == "horizontal":
        p[1] = (p[1][0], p[0][1])
    p = [q if is_in_range(q[0], S) and is_in_range(q[1], S) else (draw(cx), draw(cy)) for q in p]
    return p


@st.composite
def batches(draw, S, o, max_h=32, max_w=32, max_n=6):
    shape = draw(shapes(max_h, max_w))
    tris = draw(st.lists(triangles(S, o, shape), min_size=0, max_size=max_n))
    return tris, shape


# --- against the oracle ---------------------------------------------------------

@pytest.mark.parametrize("S", range(9))
@settings(max_examples=examples(60))
@given(data=st.data())
def test_count_matches_oracle(S, data):
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    tris, shape = data.draw(batches(S, o), label="batch")
    check_batch(tris, shape, S, o, rounding)


@pytest.mark.parametrize("S", [12, 16])
@settings(max_examples=examples(20))
@given(data=st.data())
def test_count_matches_oracle_fine_subpixel(S, data):
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    tris, shape = data.draw(batches(S, o), label="batch")
    check_batch(tris, shape, S, o, rounding)


@pytest.mark.parametrize("boundary", ["closed", "conservative"])
@settings(max_examples=examples(40))
@given(data=st.data())
def test_boundary_modes_match_oracle(boundary, data):
    """Each triangle adds its outline as its one-ring polygon would; the
    count shows the shared outline pixels twice (not watertight, by
    definition)."""
    from oracle_boundary import ORACLES
    S = data.draw(st.sampled_from([0, 3, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    tris, shape = data.draw(batches(S, o, 16, 16, 4), label="batch")
    kw = dict(subpixel_bits=S, sample_offset=o, rounding=rounding)
    exp = np.zeros(shape, np.int64)
    for t in tris:
        exp += ORACLES[boundary]([list(map(tuple, t))], shape, **kw)
    for alg in ALGOS:
        got = rastrum.triangles_count(tris, shape, algorithm=alg, boundary=boundary, **kw)
        assert_same(got, exp, f"{alg} {boundary} {lit(tris)} {shape} {kw}")


@settings(max_examples=examples(100))
@given(data=st.data())
def test_vertex_order_never_matters(data):
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    shape = data.draw(shapes(24, 24), label="shape")
    tri = data.draw(triangles(S, o, shape), label="tri")
    kw = dict(subpixel_bits=S, sample_offset=o, rounding=rounding)
    first = rastrum.triangles_mask([tri], shape, **kw)
    for alg in ALGOS:
        for perm in itertools.permutations(tri):
            got = rastrum.triangles_mask([list(perm)], shape, algorithm=alg, **kw)
            assert_same(got, first, f"{alg} {lit(perm)} {kw} vs {lit(tri)}")


def test_textbook_example_3_1():
    """Seed 001, Example 3-1: the book's SpanLeft/SpanRight table, filled
    [SpanLeft, SpanRight) per row; the exact rule adds pixel (4, 6)."""
    tri = [[(1, 1), (5, 3), (4, 7)]]
    book = {1: (1, 1), 2: (2, 3), 3: (2, 5), 4: (3, 5), 5: (3, 5), 6: (4, 4)}
    want = np.zeros((9, 8), bool)
    for j, (a, b) in book.items():
        want[j, a:b] = True
    for alg in ALGOS:
        got = rastrum.triangles_mask(tri, (9, 8), algorithm=alg, subpixel_bits=0,
                                     sample_offset=0, rounding="textbook")
        assert_same(got, want, alg)
        want_exact = want.copy()
        want_exact[6, 4] = True
        got = rastrum.triangles_mask(tri, (9, 8), algorithm=alg, subpixel_bits=0, sample_offset=0)
        assert_same(got, want_exact, alg)


@pytest.mark.parametrize("alg", ALGOS)
def test_degenerate_draws_nothing(alg):
    degenerate = [
        [(0, 0), (2, 2), (4, 4)],            # collinear
        [(1.5, 1.5)] * 3,                    # one point
        [(0, 1.5), (6, 1.5), (3, 1.5)],      # horizontal only
        [(2.5, 0), (2.5, 7), (2.5, 3)],      # vertical only
        [(0.5, 0.5), (5.5, 5.5), (0.5, 0.5)],  # repeated vertex
        [(1.0, 1.0), (4.0, 5.0), (1.0 + 2 ** -10, 1.0)],  # snaps to a repeated vertex
    ]
    for tri in degenerate:
        for o in OFFSETS:
            for r in ROUNDINGS:
                m = rastrum.triangles_count([tri], (6, 7), algorithm=alg, sample_offset=o,
                                           rounding=r)
                assert not m.any(), (tri, o, r)
    assert rastrum.triangles_mask([], (5, 7), algorithm=alg).shape == (5, 7)
    assert rastrum.triangles_count(np.zeros((0, 3, 2)), (5, 7), algorithm=alg).dtype == np.uint16
    for shape in ((0, 5), (5, 0), (0, 0)):
        m = rastrum.triangles_mask([[(0, 0), (4, 0), (0, 4)]], shape, algorithm=alg)
        assert m.shape == shape and m.dtype == np.bool_


@pytest.mark.parametrize("S", [0, 4, 8, 16])
@pytest.mark.parametrize("alg", ALGOS)
def test_at_range_limit(alg, S):
    lim = limit_px(S)
    g = 1 << S
    tris = [
        [(-lim, -lim), (lim, -lim), (lim, lim)],
        [(-lim, -lim), (lim, lim), (-lim, lim)],
        [(-lim, -lim), (lim, 3.25), (2.5, lim)],
        [(lim, -lim), (-lim, 2.0), (lim, lim)],
        [((COORD_MAX + 0.25) / g, -(COORD_MAX + 0.5) / g), (1.5, 6.5), (-lim, lim)],
        [(0.5, -lim), (0.5 + 1.0 / g, lim), (3.5, lim)],
    ]
    for o in OFFSETS:
        for r in ROUNDINGS:
            # the first two cover everything once
            m = rastrum.triangles_count(tris[:2], (5, 6), algorithm=alg, subpixel_bits=S,
                                       sample_offset=o, rounding=r)
            assert (m == 1).all()
            check_batch(tris, (7, 9), S, o, r, algorithms=[alg])
    for v in ((COORD_MAX + 1) / g, -(COORD_MAX + 0.75) / g, 1e300):
        with pytest.raises(ValueError, match="range"):
            rastrum.triangles_mask([[(0, 0), (3, 0), (0, 3)], [(v, 0), (3, 0), (0, 3)]], (4, 4),
                                   algorithm=alg, subpixel_bits=S)


# --- a mesh is covered exactly once ------------------------------------------------

def jittered_mesh(n=100, size=1024.0, half_grid=False, seed=7):
    """2 n^2 triangles cutting the square [0, size]^2: a grid whose inner
    points move by up to 0.15 of a cell (so no triangle turns over) and
    whose border points slide along the border, each cell cut along a
    random diagonal, each triangle in a random winding."""
    rng = np.random.default_rng(seed)
    cell = size / n
    ij = np.arange(n + 1) * cell
    x, y = np.meshgrid(ij, ij)  # x[j, i], y[j, i]
    jx = rng.uniform(-0.15, 0.15, x.shape) * cell
    jy = rng.uniform(-0.15, 0.15, y.shape) * cell
    jx[:, [0, -1]] = 0
    jy[[0, -1], :] = 0
    x, y = x + jx, y + jy
    if half_grid:
        x, y = np.round(x * 2) / 2, np.round(y * 2) / 2
    p = np.stack([x, y], axis=-1)
    p00, p10, p01, p11 = p[:-1, :-1], p[:-1, 1:], p[1:, :-1], p[1:, 1:]
    diag = rng.random((n, n)) < 0.5
    t1 = np.where(diag[..., None, None], np.stack([p00, p10, p11], -2), np.stack([p00, p10, p01], -2))
    t2 = np.where(diag[..., None, None], np.stack([p00, p11, p01], -2), np.stack([p10, p11, p01], -2))
    tris = np.concatenate([t1.reshape(-1, 3, 2), t2.reshape(-1, 3, 2)])
    flip = rng.random(len(tris)) < 0.5
    tris[flip] = tris[flip][:, ::-1]
    return tris[rng.permutation(len(tris))]


@pytest.mark.parametrize("half_grid", [False, True])
def test_mesh_covered_exactly_once(half_grid):
    tris = jittered_mesh(half_grid=half_grid)
    assert tris.shape == (20000, 3, 2)
    for alg in ALGOS:
        for o in OFFSETS:
            for r in ROUNDINGS:
                cnt = rastrum.triangles_count(tris, (1024, 1024), algorithm=alg, sample_offset=o,
                                             rounding=r)
                holes, over = int((cnt == 0).sum()), int((cnt > 1).sum())
                assert holes == 0 and over == 0, (alg, o, r, holes, over)
    # the check can fail: drop one triangle and there are holes
    cnt = rastrum.triangles_count(tris[1:], (1024, 1024))
    assert (cnt == 0).sum() > 0


# --- the inline gray8 path --------------------------------------------------------
# A gray8 target painted one value (triangles_mask "set", Canvas gray8) has
# its runs written by the filler itself (rast__sink_direct8), and, when every
# run of a triangle lies inside the clip, without cutting each one
# (rast__rows_direct_uncut): one memset per row down a row pointer.  The
# batches above mostly reach past the target; these stay inside it, so
# that this path meets slivers, horizontal edges, triangles of one or two
# rows, vertices on samples and on the grid.

@st.composite
def inside_triangles(draw, S, o, shape):
    H, W = shape
    g = 1 << S

    def coord(dim):
        return st.one_of(
            st.floats(1.0, dim - 1.0),
            st.integers(g, (dim - 1) * g).map(lambda k: k / g),
            st.integers(1, dim - 2).map(lambda k: k + o))

    cx, cy = coord(W), coord(H)
    p = [(draw(cx), draw(cy)) for _ in range(3)]
    kind = draw(st.sampled_from(["random", "random", "sliver", "horizontal", "one_row", "small"]))
    if kind == "sliver":
        t = draw(st.floats(-2.0 / g, 2.0 / g))
        (x0, y0), (x1, y1) = p[0], p[1]
        p[2] = (min(max((x0 + x1) / 2 + t, 1.0), W - 1.0), min(max((y0 + y1) / 2 - t, 1.0), H - 1.0))
    elif kind == "horizontal":
        p[1] = (p[1][0], p[0][1])
    elif kind == "one_row":
        # all three within a pixel's height: one or two rows, or none
        y = draw(st.integers(1, H - 3))
        p = [(x, y + draw(st.floats(0.0, 1.5))) for x, _ in p]
    elif kind == "small":
        x, y = p[0]
        d = st.floats(-3.0, 3.0)
        p = [(min(max(x + draw(d), 1.0), W - 1.0), min(max(y + draw(d), 1.0), H - 1.0))
             for _ in range(3)]
    return p


@settings(max_examples=examples(150))
@given(data=st.data())
def test_inside_target_matches_oracle(data):
    S = data.draw(st.sampled_from([0, 2, 4, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rounding = data.draw(st.sampled_from(ROUNDINGS), label="rounding")
    shape = data.draw(st.tuples(st.integers(4, 40), st.integers(4, 40)), label="shape")
    tris = data.draw(st.lists(inside_triangles(S, o, shape), min_size=1, max_size=8), label="tris")
    check_batch(tris, shape, S, o, rounding)
    # the same through a gray8 Canvas over other pixels: only the covered
    # ones change
    exp_mask = oracle_count(tris, shape, S, o, rounding) > 0
    for alg in ALGOS:
        c = rastrum.Canvas((shape[0], shape[1]), format="gray8")
        c.array[...] = 7
        c.fill_triangles(tris, 200, algorithm=alg, subpixel_bits=S, sample_offset=o, rounding=rounding)
        assert_same(c.array, np.where(exp_mask, 200, 7).astype(np.uint8), f"{alg} gray8 {lit(tris)}")


# --- Canvas ----------------------------------------------------------------------------

@settings(max_examples=examples(30))
@given(data=st.data())
def test_canvas_writes_only_covered_pixels(data):
    S = data.draw(st.sampled_from([0, 3, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    tris, shape = data.draw(batches(S, o, 20, 20), label="batch")
    fmt = data.draw(st.sampled_from(["gray8", "rgb888", "rgba8888"]), label="format")
    alg = data.draw(st.sampled_from(ALGOS), label="alg")
    h, w = shape
    c = rastrum.Canvas((h, w), format=fmt)
    rng = np.random.default_rng(len(tris))
    c.array[...] = rng.integers(0, 200, c.array.shape, dtype=np.uint8)
    before = c.array.copy()
    color = {"gray8": 255, "rgb888": (255, 1, 2), "rgba8888": (255, 1, 2, 3)}[fmt]
    c.fill_triangles(tris, color, algorithm=alg, subpixel_bits=S, sample_offset=o)
    mask = oracle_count(tris, shape, S, o, "exact") > 0
    exp = before.copy()
    exp[mask] = color
    assert_same(c.array, exp, f"{alg} {fmt} {lit(tris)}")
    # fill_triangle, one at a time, paints the same
    d = rastrum.Canvas((h, w), format=fmt)
    d.array[...] = before
    for t in tris:
        d.fill_triangle(t, color, algorithm=alg, subpixel_bits=S, sample_offset=o)
    assert_same(d.array, exp, "fill_triangle")


def test_canvas_on_a_sub_view():
    big = np.zeros((20, 30), np.uint8)
    c = rastrum.Canvas.wrap(big[5:15, 10:20])
    c.fill_triangles([[(-5, -5), (50, -5), (-5, 50)]], 7)
    assert (big[5:15, 10:20] == 7).all() and big.sum() == 7 * 100


# --- errors: ValueError naming the problem, nothing written ----------------------

TRI = [(0.5, 0.5), (6.0, 1.0), (2.0, 5.5)]
NAN, INF = float("nan"), float("inf")
BAD = [
    # (tris, kwargs, regex the message must match)
    ([[(0, 0), (NAN, 1), (2, 0)]], {}, r"finite|nan"),
    ([TRI, [(0, 0), (1, INF), (2, 0)]], {}, r"finite|inf"),
    ([[(0, 0), (1, 1)]], {}, r"shape|\(N, 3, 2\)"),
    ([[(0, 0, 0), (1, 1, 1), (2, 0, 0)]], {}, r"shape|\(N, 3, 2\)"),
    (TRI, {}, r"shape|\(N, 3, 2\)"),
    ([[["a", 0], [1, 1], [2, 0]]], {}, r"number"),
    ([[(0, 0), (1e300, 0), (0, 3)]], {}, r"range"),
    ([[(0, 0), ((COORD_MAX + 1) / 256, 0), (0, 3)]], {}, r"range"),
    ([TRI], {"algorithm": "aet"}, r"algorithm"),
    ([TRI], {"algorithm": None}, r"algorithm"),
    ([TRI], {"mode": "union"}, r"mode"),
    ([TRI], {"mode": None}, r"mode"),
    ([TRI], {"subpixel_bits": 17}, r"subpixel"),
    ([TRI], {"subpixel_bits": 2.0}, r"subpixel"),
    ([TRI], {"subpixel_bits": True}, r"subpixel"),
    ([TRI], {"sample_offset": 0.25}, r"sample_offset"),
    ([TRI], {"rounding": "nearest"}, r"rounding"),
    ([TRI], {"boundary": "outline"}, r"boundary"),
]


@pytest.mark.parametrize("tris,kw,pattern", BAD)
def test_bad_input(tris, kw, pattern):
    with pytest.raises(rastrum.InputError, match=re.compile(pattern, re.I)):
        rastrum.triangles_mask(tris, (6, 7), **kw)
    if "mode" in kw:
        return  # Canvas has no mode
    c = rastrum.Canvas((6, 7), format="gray8", background=3)
    with pytest.raises(rastrum.InputError, match=re.compile(pattern, re.I)):
        c.fill_triangles(tris, 200, **kw)
    assert (c.array == 3).all()


@pytest.mark.parametrize("shape", [(-1, 5), (5,), (2.5, 3), None])
def test_bad_shape(shape):
    with pytest.raises(rastrum.InputError, match="shape"):
        rastrum.triangles_mask([TRI], shape)


def test_bad_canvas_arguments():
    c = rastrum.Canvas((6, 7), format="rgb888", background=3)
    for tri, color, pattern in [
        (TRI, (1, 2), r"colou?r"),
        (TRI, 300, r"colou?r"),
        ([TRI], 5, r"shape|\(3, 2\)"),
        ([(0, 0), (1, 1)], 5, r"shape|\(3, 2\)"),
        ([(0, 0), (NAN, 1), (2, 0)], 5, r"finite|nan"),
    ]:
        with pytest.raises(rastrum.InputError, match=re.compile(pattern, re.I)):
            c.fill_triangle(tri, color)
    with pytest.raises(rastrum.InputError, match="colou?r"):
        c.fill_triangles([TRI], (1, 2, 3, 4, 5))
    assert (c.array == 3).all()

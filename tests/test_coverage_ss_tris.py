"""Supersampling of triangle batches ("ss2" .. "ss16", triangles_coverage):
the binary rule on the k-times finer grid, counted per pixel
(docs/coverage.md), bit for bit as tests/oracle_coverage.py's coverage_ss
gives it.  The walk (csrc/src/coverage/coverage_ss.c) takes a band of up
to 8 output rows at once while few triangles are active (as many as the
scratch's room allows), an output row at a time while 256 or more are:
so canvases taller than a band, counts of triangles on both sides of 256
(the walk changes mode mid-canvas), triangles of either turn, some
reaching past the canvas (their runs clipped), some spanning it."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _scene(seed, h, w, n, wide):
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(-2, [w + 2, h + 2], (n, 1, 2))
    r = rnd.uniform(0.3, 4, (n, 1, 1))
    t = rnd.uniform(0, 2 * np.pi, (n, 1, 1)) + np.array([0, 2.1, 4.2])[None, :, None] \
        + rnd.uniform(-0.4, 0.4, (n, 3, 1))
    tris = c + r * np.concatenate([np.cos(t), np.sin(t)], 2)
    flip = rnd.random(n) < 0.5
    tris[flip] = tris[flip][:, ::-1]  # either turn
    if wide:  # a few across the canvas and past its sides
        big = rnd.uniform(-3, [w + 3, h + 3], (wide, 3, 2))
        tris = np.concatenate([tris, big])
        rnd.shuffle(tris)
    return tris


@settings(max_examples=S_.examples(14), deadline=None)
@given(st.integers(9, 30), st.integers(4, 24), st.integers(1, 320), st.integers(0, 3),
       st.integers(0, 2 ** 32 - 1), st.sampled_from(["ss2", "ss4", "ss8", "ss16"]))
def test_small_triangle_batches_equal_oracle(h, w, n, wide, seed, method):
    tris = _scene(seed, h, w, n, wide)
    out = rastrum.triangles_coverage(tris, (h, w), method=method)
    want = oc.coverage_ss(list(tris), (h, w), int(method[2:]), triangles=True)
    S_.assert_same(out.astype(np.int64), want, tris.tolist())


def test_dense_rows_change_mode_mid_canvas():
    # 600 small triangles in the middle rows of a tall canvas: the walk goes
    # by bands at the top and bottom and by output rows between
    rnd = np.random.default_rng(7)
    h, w = 40, 12
    c = np.concatenate([rnd.uniform([0, 0], [w, 8], (20, 1, 2)),
                        rnd.uniform([0, 14], [w, 22], (600, 1, 2)),
                        rnd.uniform([0, 30], [w, 40], (20, 1, 2))])
    tris = c + rnd.uniform(-2.5, 2.5, (len(c), 3, 2))
    for method in ("ss4", "ss8"):
        out = rastrum.triangles_coverage(tris, (h, w), method=method)
        want = oc.coverage_ss(list(tris), (h, w), int(method[2:]), triangles=True)
        S_.assert_same(out.astype(np.int64), want, method)


def _pile(seed, h, w, n, nlong):
    # n triangles piled in a band of rows (hundreds active on each: the
    # walk skips those inside the columns covered by the rest, their edges
    # moved k rows at once) and nlong ones that start in the pile and
    # leave it (walked again below it, from where the skips left them)
    rnd = np.random.default_rng(seed)
    y0 = rnd.uniform(-1, h / 3)
    y1 = y0 + rnd.uniform(3, h / 2)
    pile = rnd.uniform([-3, y0], [w + 3, y1], (n, 3, 2))
    pile[:, 0, 1], pile[:, 1, 1] = y0 - 1, y1 + 1  # each across the whole band
    long_ = np.concatenate([rnd.uniform([-2, y0], [w + 2, y1], (nlong, 1, 2)),
                            rnd.uniform([-2, y0], [w + 2, h + 2], (nlong, 2, 2))], 1)
    tris = np.concatenate([pile, long_])
    flip = rnd.random(len(tris)) < 0.5
    tris[flip] = tris[flip][:, ::-1]  # either turn
    rnd.shuffle(tris)
    return tris


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(12, 36), st.integers(4, 20), st.integers(260, 420), st.integers(1, 12),
       st.integers(0, 2 ** 32 - 1), st.sampled_from(["ss2", "ss4", "ss8"]))
def test_piles_then_triangles_leaving_them_equal_oracle(h, w, n, nlong, seed, method):
    tris = _pile(seed, h, w, n, nlong)
    out = rastrum.triangles_coverage(tris, (h, w), method=method)
    want = oc.coverage_ss(list(tris), (h, w), int(method[2:]), triangles=True)
    S_.assert_same(out.astype(np.int64), want, tris.tolist())

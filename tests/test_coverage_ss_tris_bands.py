"""Supersampled triangle batches walked in bands of up to 32 output rows
(csrc/src/coverage/coverage_ss.c, RAST__SS_BAND, session 16: 8 before),
as many as keep the band's rows of bits within 32 KiB (RAST__SS_BAND_BYTES)
and never fewer than 8: canvases taller than one band, so triangles cross
the bands' boundaries (rows 31, 32, 62, ... for a narrow canvas), and wide
canvases where the byte bound cuts the band (ss4 on 700 columns: 23 rows;
ss8: the floor of 8).  Each against the binary rule on the k-times finer
grid (tests/oracle_coverage.py's coverage_ss, docs/coverage.md)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _tall(seed, h, w, n):
    # triangles of every height up to the canvas's, some past its edges
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(-2, [w + 2, h + 2], (n, 1, 2))
    r = rnd.uniform(0.5, [w / 2 + 1, h / 2 + 1], (n, 1, 2))
    t = rnd.uniform(0, 2 * np.pi, (n, 1, 1)) + np.array([0, 2.1, 4.2])[None, :, None] \
        + rnd.uniform(-0.4, 0.4, (n, 3, 1))
    tris = c + r * np.concatenate([np.cos(t), np.sin(t)], 2)
    flip = rnd.random(n) < 0.5
    tris[flip] = tris[flip][:, ::-1]  # either turn
    return tris


def _check(tris, shape, method):
    out = rastrum.triangles_coverage(tris, shape, method=method)
    want = oc.coverage_ss(list(tris), shape, int(method[2:]), triangles=True)
    S_.assert_same(out.astype(np.int64), want, (method, shape, tris.tolist()))


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(33, 100), st.integers(3, 14), st.integers(1, 40),
       st.integers(0, 2 ** 32 - 1), st.sampled_from(["ss2", "ss4", "ss8"]))
def test_tall_canvases_across_bands_equal_oracle(h, w, n, seed, method):
    _check(_tall(seed, h, w, n), (h, w), method)


def test_band_boundaries_exactly():
    # vertices on the rows where bands of 32 (and 8) output rows meet, and
    # half a pixel either side of them
    h, w = 100, 9
    ys = [31, 31.5, 32, 32.5, 63.75, 64, 64.25, 95.5, 96]
    tris = []
    for k, y in enumerate(ys):
        tris.append([[1 + k % 3, 0.3], [w - 0.7, y], [0.2, y + 3.5]])
        tris.append([[w - 1.5, y], [0.5, y - 20.25], [w - 0.2, 99.9]])
    tris = np.array(tris, dtype=np.float64)
    for method in ("ss4", "ss8", "ss16"):
        _check(tris, (h, w), method)


def test_wide_canvas_band_cut_by_bytes():
    # 700 columns: ss4's band is 23 rows (1,408 bytes a row of bits), ss8's
    # the floor of 8; long thin triangles across many bands
    rnd = np.random.default_rng(16)
    h, w = 60, 700
    tris = _tall(5, h, w, 30)
    tris = np.concatenate([tris, rnd.uniform(-5, [w + 5, h + 5], (4, 3, 2))])
    for method in ("ss4", "ss8"):
        _check(tris, (h, w), method)

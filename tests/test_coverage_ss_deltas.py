"""Supersampling ("ssK", polygon_coverage) by winding deltas on the fine
grid (csrc/src/coverage/coverage_ss.c, rast__ss_delta, builds with
SSE2): where a polygon has many short edges (at least 2 a fine row, as
the keys' walk takes them) and dense crossings (at most 4 words of 64
fine columns a crossing), each edge adds its direction at its crossing's
column in byte counters, a band of 32 output rows at a time, and each
fine row is summed along into a row of bits.  The counts must stay the
binary rule on the k-times finer grid (docs/coverage.md), bit for bit as
tests/oracle_coverage.py's coverage_ss gives them: edges carried from
band to band (canvases taller than 32 rows), crossings left and right of
the clip (counted at its first column, or past its last), vertices on
sample rows and columns, both rules, k = 2 .. 16, uint8 and uint16; and
non-zero with more than 511 edges, where the counters (modulo 2^8) are
exact only when no row has more than 510 crossings: a winding number of
256 must not read as 0 (such a polygon goes the keyed sweep's way)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _zigzags(rnd, h, w, k, past, snap):
    """Rings zig-zagging down a stretch of a canvas h tall and w wide (past:
    up to that many pixels beyond it) and back up, a vertex every fine row
    or so (k fine rows a pixel), each ring's edges crossing its stretch's
    rows twice or more, a triangle as tall as the canvas, and small
    triangles down the canvas, 1.5 a fine row: over 2 edges a fine row in
    all."""
    rings = []
    for _ in range(int(rnd.integers(1, 4))):
        y0, y1 = np.sort(rnd.uniform(-past, h + past, 2))
        n = max(3, int((y1 - y0) * k * 1.5 / max(1, len(rings) + 1)) + 3)
        ys = np.sort(rnd.uniform(y0, y1, n))
        pts = S_.zigzag_ring(rnd, -past, w + past, ys)
        if snap:  # some vertices on sample rows and columns of the fine grid
            on = rnd.random(pts.shape) < 0.5
            pts = np.where(on, np.round(pts * snap) / snap, pts)
        rings.append([[float(x), float(y)] for x, y in pts])
    # (a triangle the canvas's height: edges through every band)
    x = rnd.uniform(0, w, 3)
    rings.append([[float(x[0]), -past - 0.3], [float(x[1]), h + past + 0.2], [float(x[2]), h / 2.0]])
    # (and small rings down the canvas: edges enough for every row)
    for i in range(int(h * k * 1.5) + 1):
        cx, cy = rnd.uniform(-past, w + past), (i * 2.0 / (3 * k)) % (h + 2 * past) - past
        rings.append(S_.tiny_triangle(rnd, cx, cy, 1.5))
    return rings


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(20, 72), st.integers(2, 9),
       st.sampled_from([0, 0, 1.5]), st.sampled_from([0, 8]),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([2, 4, 4, 8]),
       st.sampled_from([np.uint8, np.uint16]))
def test_tall_zigzags_equal_oracle(seed, h, w, past, snap, rule, k, dtype):
    # canvases up to 72 rows: up to three bands of 32 output rows, the
    # edges that go on past a band carried into the next
    poly = _zigzags(np.random.default_rng(seed), h, w, k, past, snap)
    S_.assert_ss_oracle(poly, (h, w), k, rule, dtype)


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["nonzero", "evenodd"]))
def test_zigzags_ss16_equal_oracle(seed, rule):
    # k = 16: 16 fine rows an output row
    poly = _zigzags(np.random.default_rng(seed), 4, 3, 16, 0.5, 16)
    out = rastrum.polygon_coverage(poly, (4, 3), rule=rule, method="ss16")
    want = oc.coverage_ss(poly, (4, 3), 16, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, poly))


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1))
def test_winding_past_255_nonzero(seed):
    # 255, 256 and 257 squares turned the same way, each a little apart
    # (no two edges equal: none cancel), twice as many crossings on their
    # rows: the winding number in their common part is their number, 256
    # of them 0 modulo 2^8, yet inside under non-zero
    rnd = np.random.default_rng(seed)
    for copies in (255, 256, 257):
        d = rnd.uniform(0.001, 0.004, copies)
        poly = [[[0.3 + e, 0.2 + e], [3.6 - e, 0.2 + e], [3.6 - e, 3.7 - e], [0.3 + e, 3.7 - e]]
                for e in np.cumsum(d)]
        out = rastrum.polygon_coverage(poly, (4, 4), rule="nonzero", method="ss4")
        want = oc.coverage_ss(poly, (4, 4), 4, rule="nonzero")
        S_.assert_same(out.astype(np.int64), want, "%d %r" % (copies, d.tolist()))
        assert out[1:3, 1:3].min() == 255


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["nonzero", "evenodd"]))
def test_many_small_rings_in_bands(seed, rule):
    # more than 511 edges, few on any row (a paragraph's glyphs, rows of
    # small triangles down a tall canvas): the most crossings on a row
    # counted and found below 511, the deltas taken
    rnd = np.random.default_rng(seed)
    h, w = 40, 6
    rings = []
    for i in range(180):
        cx, cy = (i % 6) + rnd.uniform(0.2, 0.8), (i // 6) * 1.3 + rnd.uniform(0.2, 0.8)
        r = rnd.uniform(0.3, 0.9)
        t = rnd.uniform(0, 2 * np.pi) + np.array([0, 2.1, 4.2])
        tri = [[float(cx + r * np.cos(a)), float(cy + r * np.sin(a))] for a in t]
        rings.append(tri[::-1] if rnd.random() < 0.5 else tri)
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss4")
    want = oc.coverage_ss(rings, (h, w), 4, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, rings))

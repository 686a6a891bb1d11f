"""Supersampling "ss4" into uint8 by winding deltas (coverage_ss.c,
rast__ss_delta_row4, builds with SSE2): an output row straight from its
four fine rows of byte counters, 64 fine columns (16 pixels) at a time,
the prefix sums and each pixel's count of its 4 x 4 samples in one pass.
Canvases wider than 16 pixels, so that a row has several such blocks:
blocks with no crossing left of the first one (nothing written yet), in
the middle outside (0) and inside (a rectangle under the zig-zags: the
running sums' constant, 4 samples a fine row inside), a last block cut
by the clip's right edge, crossings left and right of the clip, rows
with no crossing at all; both rules, into an array and through a gray8
canvas (a painter's row, narrowed to the polygon's columns).  The levels
must be tests/oracle_coverage.py's coverage_ss bit for bit
(docs/coverage.md: the binary rule on the 4 times finer grid)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _scene(rnd, h, w, x0, x1, past, box):
    """Up to two zig-zag rings down the canvas within columns [x0, x1]
    (past: up to that many pixels beyond the canvas), small triangles down
    it there, 3 a fine row (over 2 edges a fine row: the deltas' walk),
    and, with box, a rectangle spanning the columns on rows the triangles
    leave alone (whole blocks of 16 pixels inside, no crossing in them)."""
    rings = []
    ya, yb = np.sort(rnd.uniform(0, h, 2)) if box else (h + 9.0, h + 9.0)
    for _ in range(int(rnd.integers(0, 3))):
        y0, y1 = np.sort(rnd.uniform(-past, h + past, 2))
        n = max(3, int((y1 - y0) * 3) + 3)
        ys = np.sort(rnd.uniform(y0, y1, n))
        pts = S_.zigzag_ring(rnd, x0 - past, x1 + past, ys)
        on = rnd.random(pts.shape) < 0.3  # some vertices on sample rows and columns
        pts = np.where(on, np.round(pts * 8) / 8, pts)
        rings.append([[float(x), float(y)] for x, y in pts])
    if box:
        xa, xb = x0 + 0.3, x1 - 0.3
        rings.append([[xa, ya], [xb, ya], [xb, yb], [xa, yb]])
    for i in range(int(h * 12) + 1):
        cx, cy = rnd.uniform(x0, x1), (i / 6.0) % h
        if ya - 1.5 < cy < yb + 1.5:
            continue
        rings.append(S_.tiny_triangle(rnd, cx, cy, 1.2))
    return rings


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 14), st.integers(17, 70),
       st.floats(0, 1), st.floats(0, 1), st.sampled_from([0, 1.5]), st.booleans(),
       st.sampled_from(["nonzero", "evenodd"]))
def test_wide_rows_equal_oracle(seed, h, w, a, b, past, box, rule):
    # columns [x0, x1]: anywhere in the canvas, at least 4 pixels wide
    x0 = a * (w - 4)
    x1 = x0 + 4 + b * (w - 4 - x0)
    poly = _scene(np.random.default_rng(seed), h, w, x0, x1, past, box)
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss4")
    want = oc.coverage_ss(poly, (h, w), 4, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, poly))


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 10), st.integers(17, 60),
       st.floats(0, 1), st.booleans(), st.sampled_from(["nonzero", "evenodd"]))
def test_wide_rows_painted(seed, h, w, a, box, rule):
    # a gray8 canvas of 0 painted 255: each pixel its level,
    # (255 c + 127) // 255 = c; the painter's rows narrowed to the
    # polygon's columns
    x0 = a * (w - 4)
    x1 = x0 + 4 + 0.5 * (w - 4 - x0)
    poly = _scene(np.random.default_rng(seed), h, w, x0, x1, 0, box)
    canvas = rastrum.Canvas((h, w), format="gray8")
    canvas.fill_polygon(poly, 255, rule=rule, aa="ss4")
    want = oc.coverage_ss(poly, (h, w), 4, rule=rule)
    S_.assert_same(canvas.array.astype(np.int64), want, "%s %r" % (rule, poly))

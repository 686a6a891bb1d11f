"""Supersampling "ss4" of triangle batches into uint8, a word of 16 pixels
at a time (csrc/src/coverage/coverage_ss.c, rast__ss_bits_row_k: in SSE2
builds rast__ss_count4 counts a word's 4 x 16 samples and levels them;
the last, partial word and other dtypes take the scalar count).  Each
count 0 .. 16 of a pixel's samples must give floor((255 c + 8) / 16)
(docs/coverage.md), at every lane of a word: the counts are laid out by
rectangles whose sides lie between samples (overlapping triangles), so c is known without an
oracle; and random batches on canvases two words wide and more, against
tests/oracle_coverage.py."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _rect(x0, y0, x1, y1):
    # two triangles whose union holds the rectangle and lies within 1/16
    # of it (its samples, 1/8 from its sides, and no other), with no edge
    # in common (a shared edge would hand the batch to the polygon walk)
    e = 1 / 32
    return [[(x0 - e, y0 - e), (x1 + e, y0 - e), (x1 + e, y1 + e)],
            [(x0 - e, y0 - 2 * e), (x1 + 2 * e, y1 + e), (x0 - e, y1 + e)]]


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 31), st.integers(0, 1), st.booleans(), st.booleans())
def test_every_count_at_every_lane(offset, row, right, tall):
    # pixel offset + c (row `row`) gets c samples: c // 4 whole sample
    # rows from its top and c % 4 samples of the next (from its right
    # or left side); `tall` adds a pixel below each, all 16 inside
    h, w = 3, 48
    tris, want = [], np.zeros((h, w), dtype=np.int64)
    for c in range(17):
        x, q, r = offset + c, c // 4, c % 4
        if q:
            tris += _rect(x, row, x + 1, row + q / 4)
        if r:
            a = x + 1 - r / 4 if right else x
            tris += _rect(a, row + q / 4, a + r / 4, row + (q + 1) / 4)
        want[row, x] = (255 * c + 8) // 16
        if tall:
            tris += _rect(x, row + 1, x + 1, row + 2)
            want[row + 1, x] = 255
    tris = np.array(tris, dtype=np.float64)
    out = rastrum.triangles_coverage(tris, (h, w), method="ss4")
    S_.assert_same(out.astype(np.int64), want, (offset, row, right, tall))


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(2, 10), st.integers(33, 70), st.integers(1, 300), st.floats(0.3, 6),
       st.integers(0, 2 ** 32 - 1), st.sampled_from([np.uint8, np.uint16]))
def test_wide_batches_equal_oracle(h, w, n, size, seed, dtype):
    # n triangles of radius up to `size` (some past the canvas's sides);
    # 256 or more active on a row take the pile's walk
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(-2, [w + 2, h + 2], (n, 1, 2))
    tris = c + rnd.uniform(-size, size, (n, 3, 2))
    out = rastrum.triangles_coverage(tris, (h, w), method="ss4", dtype=dtype)
    M = 255 if dtype == np.uint8 else 65535
    want = oc.coverage_ss(list(tris), (h, w), 4, triangles=True, M=M)
    S_.assert_same(out.astype(np.int64), want, tris.tolist())

"""Supersampling ("ssK", polygon_coverage) of polygons of many short
edges: rows of small glyph-like rings, a few fine rows tall each, where
edges join and end on most fine rows.  There the walk keeps an AET of
keys (csrc/src/coverage/coverage_ss.c, rast__ss_sweep: an edge's column
over its index, its record left in the edge table; a row's new edges'
keys sorted in runs of 16 and merged), where long edges keep the AET of
records.  Either way the counts are the binary rule on the k-times finer
grid (docs/coverage.md), bit for bit as tests/oracle_coverage.py's
coverage_ss gives them: rings turned either way, overlapping or not,
self-intersecting (edges that cross: the keys re-sorted), vertices on
sample rows and columns (equal columns, edges ending on the row where
others start), rings reaching past the canvas (clipped runs), under both
rules, at k = 2 .. 16, uint8 and uint16."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _glyphs(seed, h, w, n, size, snap, past):
    """n rings of 3 to 9 vertices, each within `size` pixels of its centre
    (the centres on lines across the canvas, as text, or anywhere), some
    vertices on a grid of 1/snap pixel; with `past`, centres a pixel
    beyond the canvas too."""
    rnd = np.random.default_rng(seed)
    rings = []
    lines = rnd.random() < 0.5
    for i in range(n):
        if lines:
            cx = (i * 1.7) % (w + 2 * past) - past
            cy = (int(i * 1.7 // (w + 2 * past)) * (size + 0.3)) % (h + 2 * past) - past + size / 2
        else:
            cx, cy = rnd.uniform(-past, w + past), rnd.uniform(-past, h + past)
        m = int(rnd.integers(3, 10))
        if rnd.random() < 0.5:  # a convex-ish ring, turned either way
            t = np.sort(rnd.uniform(0, 2 * np.pi, m))
            if rnd.random() < 0.5:
                t = t[::-1]
            pts = np.stack([cx + size * np.cos(t) * rnd.uniform(0.3, 1, m),
                            cy + size * np.sin(t) * rnd.uniform(0.3, 1, m)], -1)
        else:  # any order: edges that cross
            pts = np.stack([cx + rnd.uniform(-size, size, m), cy + rnd.uniform(-size, size, m)], -1)
        if snap:
            on = rnd.random(pts.shape) < 0.5
            pts = np.where(on, np.round(pts * snap) / snap, pts)
        rings.append([[float(x), float(y)] for x, y in pts])
    return rings


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 6), st.integers(4, 40), st.integers(8, 60),
       st.sampled_from([0.4, 0.8, 1.5]), st.sampled_from([0, 2, 8]), st.sampled_from([0, 0, 1]),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([2, 4, 4, 8]),
       st.sampled_from([np.uint8, np.uint8, np.uint16]))
def test_glyph_rows_equal_oracle(seed, h, w, n, size, snap, past, rule, k, dtype):
    rings = _glyphs(seed, h, w, n, size, snap, past)
    S_.assert_ss_oracle(rings, (h, w), k, rule, dtype)


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["nonzero", "evenodd"]))
def test_glyph_rows_ss16_equal_oracle(seed, rule):
    # k = 16: 16 fine rows an output row, the fine rows' keys 16 bits of
    # a pixel's count each
    rings = _glyphs(seed, 3, 10, 40, 0.4, 8, 0)
    out = rastrum.polygon_coverage(rings, (3, 10), rule=rule, method="ss16")
    want = oc.coverage_ss(rings, (3, 10), 16, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, rings))


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(40, 300), st.sampled_from(["nonzero", "evenodd"]))
def test_many_new_edges_on_one_row(seed, n, rule):
    # n small triangles whose tops share one fine row (and some their
    # columns), in a shuffled order: n to 2n keys sorted at once, in runs
    # of 16 merged in pairs
    rnd = np.random.default_rng(seed)
    xs = np.round(rnd.uniform(0, 30, n) * 4) / 4
    rings = []
    for x in xs:
        d = rnd.uniform(0.3, 1.2)
        tri = [[float(x), 0.625], [float(x + d), 0.625 + d], [float(x - d), 0.625 + d]]
        rings.append(tri[::-1] if rnd.random() < 0.5 else tri)
    out = rastrum.polygon_coverage(rings, (2, 30), rule=rule, method="ss4")
    want = oc.coverage_ss(rings, (2, 30), 4, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, rings))

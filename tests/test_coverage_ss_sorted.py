"""Supersampling ("ssK", polygon_coverage) where the walk of keys sorts
every edge's key by first row and column at once (csrc/src/coverage/
coverage_ss.c, rast__ss_sweep: two passes of 8 bits on the column over
the least one the crossings can have, then the rows) and where it cannot
and sorts each row's new keys as before: a ring far to the left (more
than 65,536 fine columns between the crossings' bounds, not tried), and
a mesh given as rings whose cancelled outline reaches past the canvas
(the bounds were the clip's: a crossing outside them is found on the
way, and the keys are made again row by row).  Either way the counts
are the binary rule on the k-times finer grid (docs/coverage.md), bit
for bit as tests/oracle_coverage.py's coverage_ss gives them."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage_ss_keys import _glyphs


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 5), st.integers(8, 30),
       st.sampled_from([0, 17000, 40000]), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([2, 4, 8]))
def test_glyph_rows_far_ring_equal_oracle(seed, h, w, far, rule, k):
    # text-like rows of small rings (many short edges: the walk of keys);
    # with `far`, one more ring that many pixels to the left of the
    # canvas, so that the crossings' columns span more than 65,536 fine
    # columns at some k (then each row's keys are sorted on their own)
    rings = _glyphs(seed, h, w, 40, 0.8, 4, 0)
    if far:
        rings.append([[-far, 0.5], [-far + 1.0, 0.75], [-far + 0.5, h - 0.25]])
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(rings, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d far %d %r" % (rule, k, far, rings))


def _cells(seed, h, w, n, past):
    """An n x n mesh of quadrilateral cells given as rings (all turned
    one way, so that their shared edges cancel), its inner vertices
    moved, `past` pixels beyond the canvas left and right."""
    rnd = np.random.default_rng(seed)
    flip = rnd.random() < 0.5
    g = np.stack(np.meshgrid(np.linspace(-past, w + past, n + 1),
                             np.linspace(0.3, h - 0.3, n + 1)), -1)
    g[1:-1, 1:-1] += rnd.uniform(-0.25, 0.25, (n - 1, n - 1, 2)) * [(w + 2 * past) / n, h / n]
    rings = []
    for r in range(n):
        for q in range(n):
            cell = [g[r, q], g[r, q + 1], g[r + 1, q + 1], g[r + 1, q]]
            rings.append(cell[::-1] if flip else cell)
    return [np.array(c, dtype=np.float64).tolist() for c in rings]


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 4), st.integers(6, 20), st.integers(8, 14),
       st.sampled_from([0.0, 2.0, 7.5]), st.sampled_from(["nonzero", "evenodd"]))
def test_mesh_outline_past_canvas_equal_oracle(seed, h, w, n, past, rule):
    # the mesh's shared edges cancel and its outline (4n edges, more than
    # two a fine row) is walked with keys; reaching past the canvas, its
    # crossings lie outside the clip's columns that bounded them
    rings = _cells(seed, h, w, n, past)
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss4")
    want = oc.coverage_ss(rings, (h, w), 4, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s past %r %r" % (rule, past, rings))

"""Supersampling ("ssK", polygon_coverage) of polygons of long edges (fewer
than two a fine row: csrc/src/coverage/coverage_ss.c, rast__ss_sweep_rows):
where no edge joins or ends within some fine rows of an output row, one
pass over the AET takes every edge through all of them (rast__ss_multi),
the runs on each fine row read from the AET's order, which the pass
checks; where it is out of order on one of them (edges that cross, or
meet), the pass is undone (the edges stepped back, the same ends counted
with the opposite sign) and the fine rows walked one at a time, sorted.
k = 4 into uint8 with many runs' ends counts a byte a fine column
(rast__ss_flush_bytes: 16 pixels a step, those with no end at once, the
last ones of a row a pixel at a time).  The counts must stay the binary
rule on the k times finer grid (docs/coverage.md), bit for bit as
tests/oracle_coverage.py's coverage_ss gives them: stars of many spikes
(dense rows, and sparse), their vertices on fine rows at times (edges
joining and ending inside an output row, and two edges from one vertex
in one column for rows), stars whose spikes cross each other and
bow-ties (a pair's edges changing places within an output row), rings
over rings (non-zero winding numbers of 2: runs over more than two
edges), reaching past the canvas, both rules, k = 2 .. 16."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _star(rnd, h, w, n, twist, snap, k):
    """A star of n spikes about a point of the canvas, its tips out to
    `reach` times the canvas, its inner vertices near the middle; with
    `twist`, every inner vertex turned by up to that many spikes' angle
    (spikes then cross their neighbours); with `snap`, vertices moved
    onto fine rows (k a pixel) half of the time."""
    cx, cy = rnd.uniform(0.3, 0.7) * w, rnd.uniform(0.3, 0.7) * h
    a = 2 * np.pi / n
    t = np.arange(2 * n) * a / 2 + rnd.uniform(0, a)
    t[1::2] += rnd.uniform(-twist, twist, n) * a
    r = np.where(np.arange(2 * n) % 2 == 0, rnd.uniform(0.35, 0.75, 2 * n) * max(h, w),
                 rnd.uniform(0.02, 0.25, 2 * n) * min(h, w))
    pts = np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], 1)
    if snap:
        on = rnd.random(2 * n) < 0.5
        pts[on, 1] = (np.floor(pts[on, 1] * k) + 0.5) / k
    return [[float(x), float(y)] for x, y in pts]


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(6, 40), st.integers(9, 90),
       st.integers(5, 60), st.sampled_from([0.0, 0.0, 0.45, 1.6]), st.booleans(),
       st.sampled_from(["nonzero", "nonzero", "evenodd"]), st.sampled_from([4, 4, 4, 2, 8]))
def test_stars_equal_oracle(seed, h, w, n, twist, snap, rule, k):
    # stars of few and of many spikes (sparse rows, and rows with a run's
    # end every few columns: the bytes), canvases of 9 to 90 pixels (rows
    # of a few pixels past a multiple of 16)
    rnd = np.random.default_rng(seed)
    poly = [_star(rnd, h, w, n, twist, snap, k)]
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(poly, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, poly))


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([0.0, 0.45]), st.booleans(),
       st.sampled_from(["nonzero", "evenodd"]))
def test_stars_ss16_uint16_equal_oracle(seed, twist, snap, rule):
    rnd = np.random.default_rng(seed)
    poly = [_star(rnd, 5, 20, 16, twist, snap, 16)]
    out = rastrum.polygon_coverage(poly, (5, 20), rule=rule, method="ss16", dtype=np.uint16)
    want = oc.coverage_ss(poly, (5, 20), 16, rule=rule, M=65535)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, poly))


def _bowties(rnd, h, w, n, k):
    """n bow-ties (a ring of four vertices whose two long edges cross, so
    that the two edges of one run change places) and a wide quadrilateral
    whose left and right edges cross a third edge's column on the way,
    the crossings' rows within an output row (k fine rows) or on one."""
    rings = []
    for _ in range(n):
        x0, x1 = np.sort(rnd.uniform(-0.2 * w, 1.2 * w, 2))
        y0, y1 = np.sort(rnd.uniform(-0.2 * h, 1.2 * h, 2))
        if rnd.random() < 0.5:  # the crossing on a fine row's sample line
            ym, half = (np.floor((y0 + y1) / 2 * k) + 0.5) / k, (y1 - y0) / 2
            y0, y1 = ym - half, ym + half
        rings.append([[float(x0), float(y0)], [float(x1), float(y0)],
                      [float(x0), float(y1)], [float(x1), float(y1)]])
    return rings


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(4, 30), st.integers(6, 40), st.integers(1, 5),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([4, 4, 2, 8]))
def test_bowties_equal_oracle(seed, h, w, n, rule, k):
    poly = _bowties(np.random.default_rng(seed), h, w, n, k)
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(poly, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, poly))


def _fans(rnd, h, w, n, k):
    """Thin triangles from shared apexes on fine rows' sample lines, their
    two long edges in one column for several fine rows below it (which
    of them is left is told only further down), pointing down and up, and
    a few overlapping one another (winding numbers of 2)."""
    rings = []
    for _ in range(n):
        ax = (np.floor(rnd.uniform(0, w) * k) + rnd.choice([0.5, 0.25, 0.0])) / k
        ay = (np.floor(rnd.uniform(0, h) * k) + 0.5) / k
        down = 1 if rnd.random() < 0.5 else -1
        depth = rnd.uniform(0.5, 1.0) * h
        dx = rnd.uniform(-0.5, 0.5) * w
        spread = rnd.choice([1.0 / 256, 2.0 / 256, rnd.uniform(0.01, 0.5)])
        rings.append([[float(ax), float(ay)], [float(ax + dx), float(ay + down * depth)],
                      [float(ax + dx + spread), float(ay + down * depth)]])
    return rings


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(4, 24), st.integers(6, 40), st.integers(2, 12),
       st.sampled_from(["nonzero", "evenodd"]))
def test_fans_equal_oracle(seed, h, w, n, rule):
    poly = _fans(np.random.default_rng(seed), h, w, n, 4)
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss4")
    want = oc.coverage_ss(poly, (h, w), 4, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, poly))


def _inside(rnd, h, w, n, k):
    """Bow-ties and twisted quadrilaterals whose every vertex lies within
    the canvas's columns (the pass's check without clamping: a crossing
    left of the run before it on its row), some of them over each other,
    their crossings on a fine row's sample line half of the time."""
    rings = []
    for _ in range(n):
        x0, x1 = np.sort(rnd.uniform(0.05 * w, 0.95 * w, 2))
        y0, y1 = np.sort(rnd.uniform(-0.1 * h, 1.1 * h, 2))
        if rnd.random() < 0.5:
            ym, half = (np.floor((y0 + y1) / 2 * k) + 0.5) / k, (y1 - y0) / 2
            y0, y1 = ym - half, ym + half
        if rnd.random() < 0.5:
            rings.append([[float(x0), float(y0)], [float(x1), float(y0)],
                          [float(x0), float(y1)], [float(x1), float(y1)]])
        else:  # a long thin quadrilateral whose sides cross one another
            xm = float(rnd.uniform(x0, x1))
            rings.append([[float(x0), float(y0)], [xm, float(y0)],
                          [float(x1), float(y1)], [float(x0) + 0.25, float(y1)]])
    return rings


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(4, 30), st.integers(6, 40), st.integers(1, 4),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([4, 4, 2, 8]))
def test_crossings_within_the_columns_equal_oracle(seed, h, w, n, rule, k):
    # every vertex within the canvas's columns: the order checked on the
    # crossings as they are (no clamp), where edges change places
    poly = _inside(np.random.default_rng(seed), h, w, n, k)
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(poly, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, poly))

""""area" where parts overlap in a few places of a row (issues 33, 34): the
exact sweep of a group (coverage_area.c, rast__cov_row_area) mends its
order at each vertex inside the row (rast__cov_event: the edges ending
there out, those starting there in, only the edges whose sign changes cut
their pieces) and sorts again only where neighbours meet at the vertex.
Rows here hold quick groups beside groups that overlap: small many-vertex
rings (a stroke's round joins), rings touching at pixel corners,
coincident edges, a ring whose winding reaches 2 on one column only, edges
through other rings' vertices (ties at an event), against the exact oracle
of tests/oracle_coverage.py within the bound of rastrum.h.  Small canvases:
the oracle is exact rational arithmetic."""

import math

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area


def _check(rings, shape, rule, dtype=np.uint8, what=""):
    out = rastrum.polygon_coverage(rings, shape, rule=rule, dtype=dtype, method="area")
    n, m = _n_m(rings, 8)
    check_area(out, exact_area(rings, shape, rule, 8), M_OF[dtype], n, m, what)


def _blob(cx, cy, r, k, phase, cw):
    """A k-gon of radius r (vertices on a 1/16 px grid: many of them inside
    one row, as on a round join)."""
    pts = [(round((cx + r * math.cos(phase + 2 * math.pi * i / k)) * 16) / 16,
            round((cy + r * math.sin(phase + 2 * math.pi * i / k)) * 16) / 16) for i in range(k)]
    return pts[::-1] if cw else pts


@st.composite
def joins(draw):
    """A row of quick rings (boxes, apart) with, among them, clusters of
    overlapping many-vertex blobs (winding 2 and more where they overlap)."""
    w = draw(st.integers(6, 9))
    rings = []
    for x in range(0, w - 1, 3):
        kind = draw(st.integers(0, 2))
        if kind == 0:  # a quick box, its top and bottom inside rows
            y0 = draw(st.sampled_from([0.25, 0.5, 1.0]))
            rings.append([(x + 0.25, y0), (x + 1.75, y0), (x + 1.75, y0 + 1.5), (x + 0.25, y0 + 1.5)])
        elif kind == 1:  # overlapping blobs (a join's inner corner)
            for _ in range(2):
                rings.append(_blob(x + draw(st.floats(0.6, 1.4)), draw(st.floats(0.8, 2.2)),
                                   draw(st.floats(0.4, 1.2)), draw(st.integers(5, 10)),
                                   draw(st.floats(0, 6.3)), draw(st.booleans())))
        # kind 2: nothing here
    return w, rings


@settings(max_examples=S_.examples(8), deadline=None)
@given(joins(), st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([np.uint8, np.uint16]))
def test_overlapping_blobs_among_quick_groups_equal_oracle(sc, rule, dtype):
    w, rings = sc
    _check(rings, (4, w), rule, dtype, repr(rings))


@st.composite
def grid_rings(draw):
    """Rings on a 1/4 px grid: vertices of one ring on the edges of another,
    edges through vertices, coincident edges (ties at an event)."""
    q = st.integers(0, 16).map(lambda v: v / 4)
    rings = []
    for _ in range(draw(st.integers(2, 4))):
        k = draw(st.integers(3, 5))
        rings.append([(draw(q), draw(st.integers(0, 8).map(lambda v: v / 4))) for _ in range(k)])
    return rings


@settings(max_examples=S_.examples(15), deadline=None)
@given(grid_rings(), st.sampled_from(["nonzero", "evenodd"]))
def test_rings_on_a_quarter_pixel_grid_equal_oracle(rings, rule):
    _check(rings, (2, 4), rule, np.uint8, repr(rings))


@st.composite
def chains(draw):
    """Rings made of two y-monotone chains (down one side, up the other,
    with horizontal steps) with vertices on a 1/8 px grid, two or three overlapping in one group
    of the row, beside a quick box (a group of its own) and a box touching
    the group's box at a pixel corner: nearly every vertex inside a row is
    one edge ending where the next of its direction starts (the sweep puts
    the new edge in the old one's place, rast__cov_event), and the grid
    makes the new edge start on a neighbour, neighbours cross right at a
    vertex, chains of two rings coincide (the ways the sweep must not take
    that shortcut)."""
    e8 = st.integers(0, 16)
    rings, chain = [], []
    for _ in range(draw(st.integers(2, 3))):
        ys = sorted(set(draw(st.lists(st.integers(1, 15), min_size=1, max_size=5))))
        x0 = draw(st.integers(0, 12))
        # a vertex, or two joined by a horizontal edge: the next edge of
        # the chain starts away from where the last ended
        left = [((x0 + draw(e8)) / 8, y / 8) for y in ys for _ in range(draw(st.integers(1, 2)))]
        if chain and draw(st.booleans()):
            # along the last ring's chain to halfway down its first edge
            # (coincident), then off to either side of it
            left = [chain[0], ((chain[0][0] + chain[1][0]) / 2, (chain[0][1] + chain[1][1]) / 2)] + \
                [((x0 + draw(e8)) / 8, p[1]) for p in chain[1:]]
        chain = left if len(left) > 1 else chain
        right = [((x0 + draw(e8)) / 8, y / 8) for y in reversed(ys) for _ in range(draw(st.integers(1, 2)))]
        ring = [((x0 + draw(e8)) / 8, draw(st.integers(0, 1)) / 8)] + left + \
            [((x0 + draw(e8)) / 8, draw(st.integers(15, 16)) / 8)] + right
        rings.append(ring[::-1] if draw(st.booleans()) else ring)
    box = [(4.25, 0.5), (5.0, 0.5), (5.0, 1.5), (4.25, 1.5)]  # quick, apart
    corner = [(5.0, 1.5), (5.75, 1.5), (5.75, 2.0), (5.0, 2.0)]  # touches it at a corner
    return rings + [box, corner]


@settings(max_examples=S_.examples(12), deadline=None)
@given(chains(), st.sampled_from(["nonzero", "evenodd"]))
def test_overlapping_chains_among_quick_groups_equal_oracle(rings, rule):
    _check(rings, (3, 6), rule, np.uint8, repr(rings))


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 5), st.sampled_from([0.0, 0.25, 0.5]), st.booleans(),
       st.sampled_from(["nonzero", "evenodd"]))
def test_winding_two_on_one_column_only(col, dy, cw, rule):
    # a long quick strip and, on one column, a diamond of many vertices
    # inside it (winding 2 there only), with a box touching the strip at a
    # pixel corner
    strip = [(0.5, 0.5 + dy), (7.5, 0.5 + dy), (7.5, 2.5 + dy), (0.5, 2.5 + dy)]
    diamond = _blob(col + 1.5, 1.5 + dy, 0.45, 12, 0.3, cw)
    corner = [(7.5, 2.5 + dy), (8.0, 2.5 + dy), (8.0, 3.0 + dy), (7.5, 3.0 + dy)]
    _check([strip, diamond, corner], (4, 9), rule, np.uint8, repr((col, dy, cw)))


def test_coincident_edges_and_corner_touches():
    # two boxes sharing a side (cancelled), two sharing it the same way
    # round (winding 2 along it), two touching at a corner, and a blob
    # whose vertices sit on a box's side
    a = [(0.5, 0.25), (2.0, 0.25), (2.0, 2.75), (0.5, 2.75)]
    b = [(2.0, 0.25), (3.5, 0.25), (3.5, 2.75), (2.0, 2.75)]
    c = [(0.5, 0.25), (0.5, 2.75), (2.0, 2.75), (2.0, 0.25)]
    d = [(3.5, 2.75), (5.0, 2.75), (5.0, 3.5), (3.5, 3.5)]
    e = [(2.0, 1.0), (2.75, 1.25), (2.75, 1.75), (2.0, 2.0), (1.25, 1.75), (1.25, 1.25)]
    for rings in ([a, b], [a, a], [a, c, e], [a, b, d, e], [a, e, e]):
        for rule in ("nonzero", "evenodd"):
            _check(rings, (4, 6), rule, np.uint8, repr(rings))


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["round", "miter", "bevel"]))
def test_small_self_crossing_strokes_equal_oracle(seed, join):
    # a stroke's outline: round joins overlap at every inner corner
    rnd = np.random.default_rng(seed)
    pts = np.cumsum(rnd.normal(0, 1.2, (6, 2)), axis=0) + 4
    outline = rastrum.stroke(np.clip(pts, 1, 7), 1.5, join=join, cap="butt", tolerance=0.05)
    rings = [np.asarray(r, float).tolist() for r in outline.flatten()]
    _check(rings, (8, 8), "nonzero", np.uint8, repr((seed, join)))

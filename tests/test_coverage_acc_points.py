""""accumulate" straight from the vertices (csrc/src/coverage/coverage_acc.c,
rast__cov_acc_points): its edges are read from the rings or the triangles
into 20-byte records (no rast__cedge written), a mesh's or a triangle
batch's shared sides dropped on those, the walk's records made from them
in row order, and each record's quick steps made only when its steppers
are first set (an edge inside one row never steps from row to row, one
inside one column never from column to column).  Rings with horizontal
runs, repeated vertices and rings of one or two vertices (no edges),
edges above, below and beside the clip, a clip so tall for its width that
the rows are sorted by the radix sort, not counted; meshes as many small
rings and as triangle batches, with degenerate triangles; against the
exact oracle (test_coverage._accumulated: the rule applied to the
integral of the winding number), check_area's allowance at a tie."""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
import oracle_coverage as oc
from test_coverage import _accumulated, _n_m, check_area, exact_area, rule_applied

M_OF = {np.uint8: 255, np.uint16: 65535}


def _check(rings, shape, rule, dtype, what):
    out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
    n, m = _n_m(rings, 8)
    check_area(out, _accumulated(rings, shape, rule, 8), M_OF[dtype], n, m, what)


def _staircase(rnd, x0, y0, w, h):
    """A simple x-monotone ring on the 1/4 grid in the box (x0, y0, w, h):
    its top and bottom sides are staircases (horizontal runs of several
    vertices, vertical steps, some slanted ones), a vertex repeated here
    and there; either orientation."""
    k = int(rnd.integers(2, 6))
    xs = np.sort(rnd.choice(np.arange(1, 4 * w), k, replace=False)) / 4 + x0
    xs = [x0] + [float(x) for x in xs] + [x0 + w]
    mid = y0 + h / 2
    top, bot = [], []
    for a, b in zip(xs, xs[1:]):
        t = mid - float(rnd.integers(1, 2 * h + 1)) / 4
        u = mid + float(rnd.integers(1, 2 * h + 1)) / 4
        run = [a, (a + b) / 2, b] if rnd.integers(2) else [a, b]  # (a run of three vertices)
        slant = float(rnd.integers(0, 2)) / 4  # (a slanted step, or a vertical one)
        top += [(run[0] + (slant if len(top) else 0), t)] + [(x, t) for x in run[1:]]
        bot += [(x, u) for x in run]
    ring = top + bot[::-1]
    if rnd.integers(2):
        i = int(rnd.integers(len(ring)))
        ring.insert(i, ring[i])  # (an edge of length 0)
    return ring if rnd.integers(2) else ring[::-1]


@settings(max_examples=S_.examples(25), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_rings_with_runs_and_rings_without_edges(seed, rule, dtype):
    """Overlapping staircases (winding numbers up to 3 either way), some
    poking out of the clip on any side, with rings of one and two vertices
    and a ring all on one ordinate among them (no edges: nothing to add)."""
    rnd = np.random.default_rng(seed)
    shape = (8, 10)
    rings = []
    for _ in range(int(rnd.integers(1, 4))):
        x0, y0 = rnd.integers(-2, 8), rnd.integers(-2, 6)
        rings.append(_staircase(rnd, float(x0), float(y0), int(rnd.integers(2, 6)), int(rnd.integers(1, 5))))
    extra = [[(1.5, 2.5)], [(2.0, 1.0), (4.0, 3.0)], [(0.5, 6.25), (3.0, 6.25), (7.0, 6.25)]]
    for r in extra:
        rings.insert(int(rnd.integers(len(rings) + 1)), r)
    _check(rings, shape, rule, dtype, repr(rings))


@settings(max_examples=S_.examples(8), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 2, 3]), st.sampled_from(["evenodd", "nonzero"]))
def test_a_clip_tall_for_its_width(seed, width, rule):
    """A zigzag of 24 edges or more down 60 rows of a clip 1 to 3 pixels
    wide (more rows than four times the width: the walk's records placed
    by a radix sort's order, not by the rows' counts), from above the clip
    to below it, and a few small rings."""
    rnd = np.random.default_rng(seed)
    h = 60
    ys = np.linspace(-3, h + 3, 14)
    left = [(float(rnd.integers(-4, 2 * width)) / 4, float(y)) for y in ys]
    right = [(float(rnd.integers(2 * width, 4 * width + 4)) / 4, float(y)) for y in ys[::-1]]
    rings = [left + right]
    for _ in range(int(rnd.integers(0, 4))):
        x, y = rnd.integers(0, 4 * width, 2) / 4
        y = y + float(rnd.integers(0, h - 2))
        rings.append([(x, y), (x + 0.75, y + 0.5), (x + 0.25, y + 1.75)])
    _check(rings, (h, width), rule, np.uint8, repr(rings))


def _signed(groups, shape, rule):
    """_accumulated for groups of rings, each group's rings turned one way
    and apart (a mesh's cells: the group's winding number is 0 or that
    way's sign, its integral the exact area of the group under non-zero,
    signed): one oracle call a group, not a ring."""
    total = None
    for rings in groups:
        snapped = oc.oracle.snapped_rings([rings[0]], 8)[0]
        area2 = sum(F(x0) * F(y1) - F(x1) * F(y0)
                    for (x0, y0), (x1, y1) in zip(snapped, snapped[1:] + snapped[:1]))
        a = exact_area(rings, shape, "nonzero", 8) * (1 if area2 > 0 else -1)
        total = a if total is None else total + a
    return rule_applied(total, rule)


def _mesh(rnd, n, cell):
    """The vertices of an n x n grid of cells `cell` px wide from (0.5, 0.5),
    the inner ones moved by up to a quarter cell (on the 1/64 grid)."""
    g = np.array([[0.5 + c * cell, 0.5 + r * cell] for r in range(n + 1) for c in range(n + 1)])
    inner = np.array([[0 < i % (n + 1) < n and 0 < i // (n + 1) < n] for i in range((n + 1) ** 2)])
    return g + np.round(rnd.uniform(-cell / 4, cell / 4, g.shape) * 64) / 64 * inner


@settings(max_examples=S_.examples(5), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]), st.booleans())
def test_a_mesh_of_many_small_rings(seed, rule, flip):
    """A mesh of 16 quadrilateral cells given as 16 rings of one polygon (16
    rings or more of 8 vertices or fewer on the mean: the shared sides
    dropped first), all turned one way (or all the other), and a ring
    across it: the levels of the accumulation, whose sums the dropped
    sides do not change."""
    rnd = np.random.default_rng(seed)
    n, cell = 4, 1.75
    p = _mesh(rnd, n, cell)
    rings = []
    for r in range(n):
        for c in range(n):
            a = r * (n + 1) + c
            q = [p[a], p[a + 1], p[a + n + 2], p[a + n + 1]]
            q = [(float(x), float(y)) for x, y in (q[::-1] if flip else q)]
            rings.append(q)
    over = [(2.25, 0.0), (6.5, 4.75), (3.0, 8.5)]
    out = rastrum.polygon_coverage(rings + [over], (8, 8), rule=rule, method="accumulate")
    n_, m = _n_m(rings + [over], 8)
    check_area(out, _signed([rings, [over]], (8, 8), rule), 255, n_, m, "mesh seed %d" % seed)


def _positive(tri):
    """The triangle turned so that its signed area (y down) is positive,
    as the batch's accumulation turns each (degenerate ones as given)."""
    (x0, y0), (x1, y1), (x2, y2) = [(F(x), F(y)) for x, y in tri]
    cross = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    return [tuple(v) for v in (tri if cross >= 0 else tri[[0, 2, 1]])]


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(0, 3))
def test_a_triangle_batch_with_shared_sides(seed, extra):
    """A triangulated mesh in mixed orientations (its inner sides given both
    ways: dropped before the walk), degenerate triangles (a point, a
    segment: no edges), and up to three triangles laid over it: the
    non-zero accumulation of the triangles each turned one way, min(sum of
    their coverages, 1) on every pixel."""
    rnd = np.random.default_rng(seed)
    n, cell = 3, 2.5
    p = _mesh(rnd, n, cell)
    tris, mesh = [], []
    for r in range(n):
        for c in range(n):
            a, b, d, e = r * (n + 1) + c, r * (n + 1) + c + 1, (r + 1) * (n + 1) + c + 1, (r + 1) * (n + 1) + c
            t1, t2 = np.array([p[a], p[b], p[d]]), np.array([p[a], p[d], p[e]])
            tris += [t1 if rnd.integers(2) else t1[[0, 2, 1]], t2 if rnd.integers(2) else t2[[0, 2, 1]]]
            mesh += [_positive(t1), _positive(t2)]
    tris += [np.array([[3.0, 3.0]] * 3), np.array([[1.0, 1.0], [2.0, 2.0], [4.0, 4.0]])]
    over = [np.round(rnd.uniform(-1, 9, (3, 2)) * 16) / 16 for _ in range(extra)]
    tris += over
    order = rnd.permutation(len(tris))
    batch = np.array([tris[i] for i in order])
    out = rastrum.triangles_coverage(batch, (8, 8), method="accumulate")
    rings = [_positive(t) for t in batch]
    nn, m = _n_m(rings, 8)
    want = _signed([mesh] + [[_positive(t)] for t in over], (8, 8), "nonzero")
    check_area(out, want, 255, nn, m, "batch seed %d" % seed)

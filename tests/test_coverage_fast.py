""""area" coverage where its fast rows decide (csrc/src/coverage/coverage_area.c): a
row whose winding number takes only 0 and one sign of 1 is added edge by
edge without the sweep, and coincident edges of opposite directions cancel
before it.  These scenes are built so that the test for a fast row meets
its cases - cusps and chains with their vertex inside a row or on its
border, several vertices in one row, neighbours whose ranges overlap
without crossing (and crossing barely), rings sharing sides, meshes - and
each is held to the exact oracle (tests/oracle_coverage.py) within the
documented bound, under both rules; "accumulate" must agree with "area"
where nothing overlaps."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area

SHAPE = (9, 9)


def _check(rl, rule, s=8, triangles=False, shape=SHAPE):
    exact = exact_area(rl, shape, rule, s, triangles=triangles)
    n, m = _n_m(rl, s, triangles=triangles)
    for dtype in (np.uint8, np.uint16):
        if triangles:
            out = rastrum.triangles_coverage(np.asarray(rl, float), shape, subpixel_bits=s, dtype=dtype)
        else:
            out = rastrum.polygon_coverage(rl, shape, rule=rule, subpixel_bits=s, dtype=dtype)
        check_area(out, exact, M_OF[dtype], n, m, S_.lit(rl))
    return exact


def _star_shaped(rnd, n, c, rmin, rmax, snap):
    """A simple polygon: vertices by increasing angle round c, no two more
    than 0.97 pi apart (so c is inside and no edge crosses another), radii
    random; coordinates rounded to multiples of 1/snap (vertices on pixel
    corners and edges, shared ordinates; rounding keeps it simple at these
    sizes, and the oracle decides anyway)."""
    ang = (np.arange(n) + rnd.uniform(0, 0.45, n)) * 2 * np.pi / n
    r = rnd.uniform(rmin, rmax, n)
    pts = np.stack([c[0] + r * np.cos(ang), c[1] + r * np.sin(ang)], 1)
    return np.round(pts * snap) / snap


@settings(max_examples=S_.examples(80))
@given(st.integers(3, 24), st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 2, 4, 256]),
       st.sampled_from(["evenodd", "nonzero"]), st.booleans(), st.booleans())
def test_simple_polygons_with_and_without_holes(n, seed, snap, rule, hole, reverse):
    """Star-shaped polygons (simple, many vertices per row, cusps and
    chains), a smaller one inside as a hole (opposite direction) or as an
    island of the same direction (winding 2 under non-zero: the rows through
    it are swept)."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(3.5, 5.5, 2)
    outer = _star_shaped(rnd, n, c, 1.5, 4.0, snap)
    rl = [outer[::-1] if reverse else outer]
    if hole:
        inner = _star_shaped(rnd, max(3, n // 2), c, 0.3, 1.2, snap)
        rl.append(inner if reverse else inner[::-1])
        rl.append(inner) if seed % 3 == 0 else None  # and once more: cancels it
    _check([r.tolist() for r in rl], rule)


@settings(max_examples=S_.examples(60))
@given(st.integers(2, 5), st.integers(2, 5), st.integers(0, 2 ** 32 - 1), st.sampled_from([0.0, 0.3, 1.0]))
def test_mesh_in_one_call_and_as_rings(rows, cols, seed, jitter):
    """A jittered grid cut into triangles, mixed orientations: as one triangle
    batch (the union; inner edges cancel) and as one path of rings under
    non-zero with each triangle turned counter-clockwise (the same region)."""
    rnd = np.random.default_rng(seed)
    xs = np.linspace(0.5, 8.5, cols + 1)
    ys = np.linspace(0.5, 8.5, rows + 1)
    pts = np.array([[[x, y] for x in xs] for y in ys])
    pts[1:-1, 1:-1] += rnd.uniform(-jitter, jitter, (rows - 1, cols - 1, 2)) * 8 / max(rows, cols) / 3
    pts = np.round(pts * 64) / 64
    tris = []
    for r in range(rows):
        for q in range(cols):
            a, b, d, e = pts[r, q], pts[r, q + 1], pts[r + 1, q + 1], pts[r + 1, q]
            t1, t2 = [a, b, d], [a, d, e]
            if rnd.integers(2):
                t1 = t1[::-1]
            tris += [t1, t2]
    exact = _check([np.array(t).tolist() for t in tris], "nonzero", triangles=True)
    inner = exact[2:-2, 2:-2]
    assert (inner == 1).all()  # the grid covers [0.5, 8.5]^2: no seam inside
    ccw = []
    for t in tris:
        t = np.array(t)
        cross = (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[1, 1] - t[0, 1]) * (t[2, 0] - t[0, 0])
        ccw.append((t if cross > 0 else t[::-1]).tolist())
    _check(ccw, "nonzero")


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
@pytest.mark.parametrize("name", [
    "cusp on a row line", "cusp inside a row", "chain through a row", "two cusps in a row",
    "near-horizontal neighbours", "neighbours crossing inside a row", "shared side",
    "shared side, same direction", "sliver", "touching at a vertex", "horizontal edges inside rows",
    "hourglass", "hourglass crossing on a row line", "hourglass with a vertex in the crossing's row"])
def test_fast_row_cases(name, rule):
    scenes = {
        # apex exactly on the line y = 3 between rows 2 and 3; bottom vertex on y = 7
        "cusp on a row line": [[(4.5, 3), (7.25, 7), (1.5, 7)]],
        "cusp inside a row": [[(4.5, 2.5), (7.25, 6.75), (4.5, 6.375), (1.5, 6.75)]],
        "chain through a row": [[(1, 1), (5, 1), (6.5, 3.5), (7, 8), (2, 8), (2.5, 4.25)]],
        "two cusps in a row": [[(1, 2.25), (3, 5.5), (5, 2.75), (8, 5.25), (8, 8), (1, 8)]],
        # shallow edges whose ranges in a row overlap without crossing
        "near-horizontal neighbours": [[(0.5, 4), (8.5, 3.5), (8.5, 4.25), (0.5, 4.5)]],
        # and the same crossing inside a row (a bow tie)
        "neighbours crossing inside a row": [[(0.5, 4), (8.5, 4.6), (8.5, 3.9), (0.5, 4.5)]],
        "shared side": [[(1, 1), (5, 1.5), (4.5, 7.75)], [(4.5, 7.75), (5, 1.5), (8, 6)]],
        "shared side, same direction": [[(1, 1), (5, 1.5), (4.5, 7.75)], [(5, 1.5), (4.5, 7.75), (8, 6)]],
        "sliver": [[(1, 1), (8, 7.5), (8, 7.5 + 1 / 256)]],
        "touching at a vertex": [[(1, 1), (4.5, 4.5), (1, 8)], [(4.5, 4.5), (8, 1), (8, 8)]],
        # two edges of opposite directions crossing inside row 4: winding 0 and
        # 1 above the crossing, 0 and -1 below it (the order at the row's
        # bottom differs from its top: the row is swept)
        "hourglass": [[(1, 1), (8, 8), (1, 8), (8, 1)]],
        "hourglass crossing on a row line": [[(1, 1), (8, 7), (1, 7), (8, 1)]],
        # the same, one crossing edge cut by a vertex in that row (slabs)
        "hourglass with a vertex in the crossing's row": [[(1, 1), (4.25, 4.25), (8, 8), (1, 8), (8, 1)]],
        "horizontal edges inside rows": [[(1, 1.5), (3, 1.5), (3, 3.25), (6, 3.25), (6, 1.5),
                                          (8, 1.5), (8, 7.75), (1, 7.75)]],
    }
    _check(scenes[name], rule)


@settings(max_examples=S_.examples(40))
@given(st.integers(3, 16), st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]))
def test_accumulate_equals_area_on_simple_polygons(n, seed, rule):
    rnd = np.random.default_rng(seed)
    rl = [_star_shaped(rnd, n, rnd.uniform(3.5, 5.5, 2), 1.0, 4.0, 256).tolist()]
    area = rastrum.polygon_coverage(rl, SHAPE, rule=rule, dtype=np.uint16)
    acc = rastrum.polygon_coverage(rl, SHAPE, rule=rule, method="accumulate", dtype=np.uint16)
    assert np.abs(area.astype(int) - acc.astype(int)).max() <= 1


def test_big_circle_and_star_against_the_oracle():
    """The bench's shapes at 64x64 (long edges over many rows, the fast path
    throughout), each held to the oracle over the whole canvas."""
    c = 32
    t = np.linspace(0, 2 * math.pi, 64, endpoint=False)
    circle = np.stack([c + 25.6 * np.cos(t), c + 25.6 * np.sin(t)], 1)
    k = np.arange(40)
    r = np.where(k % 2, 12.8, 30.08)
    star = np.stack([c + r * np.cos(2 * math.pi * k / 40), c + r * np.sin(2 * math.pi * k / 40)], 1)
    for rl in ([circle.tolist()], [star.tolist()]):
        _check(rl, "nonzero", shape=(64, 64))


# ---- the 64-bit row stepper (abscissae in 2^-30 pixel plus a remainder) ------

def _near_parallel_bowtie(flip_x, flip_y):
    """Two edges, 32 pixels long at subpixel_bits=16, that cross 32/65536
    pixel below the top of row 20, where their abscissae differ by 2^-31
    pixel: the same 2^-30 floor, so only the remainders order them.  Taken
    as not crossing, the row's sliver above the crossing would be counted
    with the wrong sign (an error near 2^-42, far above the bound)."""
    u = 1.0 / 65536
    x0, y = 8.0, 20.0
    ring = [(x0, 2.0), (x0, 38.0), (x0 - u, y + 16 + 32 * u), (x0 + u, y - 16 + 32 * u)]
    return [[(16 - x if flip_x else x, 40 - y if flip_y else y) for x, y in ring]]


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("flip_x", [False, True])
@pytest.mark.parametrize("flip_y", [False, True])
def test_fast_row_orders_by_remainder_below_the_quick_grid(rule, flip_x, flip_y):
    from fractions import Fraction as F
    rl = _near_parallel_bowtie(flip_x, flip_y)
    exact = exact_area(rl, (40, 16), rule, 16)
    n, m = _n_m(rl, 16)
    f64 = rastrum.polygon_coverage(rl, (40, 16), rule=rule, subpixel_bits=16, dtype=np.float64)
    for (j, i), a in np.ndenumerate(exact):
        assert abs(F(float(f64[j, i])) - a) <= F(n + m + 2, 2 ** 58) + F(1, 2 ** 52), (j, i)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rl, (40, 16), rule=rule, subpixel_bits=16, dtype=dtype)
        check_area(out, exact, M_OF[dtype], n, m, "bowtie")


@settings(max_examples=S_.examples(15), deadline=None)
@given(st.integers(0, 16), st.integers(1, 3), st.integers(0, 2 ** 32 - 1),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from(["area", "accumulate"]))
def test_long_edges_stepped_row_to_row(s, k, seed, rule, method):
    """Long thin slanted quads over many rows, every subpixel_bits, vertices
    off the grid of the quick stepper: each row's abscissae come from the
    row above by the 64-bit step (remainder carried), and must give the
    exact area."""
    rng = np.random.default_rng(seed)
    h, w = 160, 6
    rings = []
    for _ in range(k):
        x0, x1 = rng.uniform(0.2, w - 0.2, 2)
        d = rng.uniform(0.3, 1.5)
        ring = [(x0, -0.7), (x0 + d, -0.7), (x1 + d, h + 0.3), (x1, h + 0.3)]
        rings.append(ring)
    if method == "accumulate":
        rings = rings[:1]  # nothing overlaps: accumulate is exact too
    exact = exact_area(rings, (h, w), rule, s)
    n, m = _n_m(rings, s)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method=method, subpixel_bits=s,
                                       dtype=dtype)
        check_area(out, exact, M_OF[dtype], n, m, "quads")

"""rastrum.stroke: "area" coverage of the outline, filled non-zero, against
the ideal stroke pixel by pixel.  Referee: shapely (GEOS), built apart
from rastrum's pieces: each segment's flat buffer, each vertex's join as
GEOS buffers the two-segment polyline around it (mitre when SVG's ratio
1/sin(theta/2) is within miter_limit, else bevel; round: GEOS's outer arc,
SVG's sector), caps as buffers of the end segments extended (square) or
half discs (round; a zero-length subpath: a whole disc); all unioned.
Dashes: the polyline cut in float along its length as SVG says (a dash
crossing a vertex keeps it; a closed subpath starting inside a dash joins
its last dash to its first), each dash stroked by the same referee.
Polygonal joins and caps: within 1/255 of the exact area per pixel;
round ones: within twice (the tolerance + the fill's snapping) per pixel.
The C stroker itself: tests/c/test_stroke.c, tests/fuzz/fuzz_stroke.c.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

import rastrum
from strategies import examples

shapely = pytest.importorskip("shapely")
from shapely.geometry import LineString, Point, Polygon, box  # noqa: E402

SIZE = 24


def referee(pts, width, join, cap, limit, closed=False, hint=None):
    h = width / 2
    p = [pts[0]]
    for q in pts[1:]:
        if q != p[-1]:
            p.append(q)
    if closed and len(p) > 1 and p[-1] == p[0]:
        p.pop()
    parts = []
    if len(p) == 1:
        if cap == "round":
            parts.append(Point(p[0]).buffer(h, quad_segs=QS))
        elif cap == "square":
            ux, uy = (1.0, 0.0) if hint is None else np.divide(hint, math.hypot(*hint))
            x, y = p[0]
            parts.append(Polygon([(x - ux * h + uy * h, y - uy * h - ux * h), (x + ux * h + uy * h, y + uy * h - ux * h),
                                  (x + ux * h - uy * h, y + uy * h + ux * h), (x - ux * h - uy * h, y - uy * h + ux * h)]))
        return union(parts) if parts else None
    ring = p + [p[0]] if closed else p
    for a, b in zip(ring, ring[1:]):
        parts.append(LineString([a, b]).buffer(h, cap_style="flat"))
    n = len(p)
    for i in (range(n) if closed else range(1, n - 1)):
        a, v, b = p[i - 1], p[i], p[(i + 1) % n]
        if join == "round":
            parts.append(LineString([a, v, b]).buffer(h, cap_style="flat", join_style="round", quad_segs=QS))
            continue
        u1 = np.subtract(v, a) / math.dist(v, a)
        u2 = np.subtract(b, v) / math.dist(b, v)
        cos_t = -float(np.dot(u1, u2))
        ratio = math.inf if cos_t >= 1 else math.sqrt(2 / (1 - cos_t))
        style = "mitre" if join == "miter" and ratio <= limit else "bevel"
        parts.append(LineString([a, v, b]).buffer(h, cap_style="flat", join_style=style,
                                                  mitre_limit=max(limit, ratio) * 1.0001 + 1))
    if not closed:
        for end, nxt in ((p[0], p[1]), (p[-1], p[-2])):
            u = np.subtract(end, nxt) / math.dist(end, nxt)
            beyond = LineString([end, tuple(np.add(end, u * h * 1.01))]).buffer(h * 1.01, cap_style="flat")
            if cap == "round":  # the half disc beyond the end
                parts.append(Point(end).buffer(h, quad_segs=QS).intersection(beyond))
            elif cap == "square":
                parts.append(LineString([end, tuple(np.add(end, u * h))]).buffer(h, cap_style="flat"))
    return union(parts)


QS = 256  # the referee's arcs: a 1024-gon, within r * 2e-5 px of the circle


def dashes(pts, closed, dash, offset):
    """SVG's dashing, in float: [(polyline, direction of its segment)],
    and whether a dash's end fell within 1e-4 px of a vertex (where the
    C stroker's rounded lengths may end it on either side)."""
    p = [pts[0]]
    for q in pts[1:]:
        if q != p[-1]:
            p.append(q)
    if closed and len(p) > 1 and p[-1] == p[0]:
        p.pop()
    pat = list(dash) * (2 if len(dash) % 2 else 1)
    period = sum(pat)
    off = offset % period
    i = 0
    while off > pat[i] or (off == pat[i] and off > 0):
        off -= pat[i]
        i = (i + 1) % len(pat)
    left, on = pat[i] - off, i % 2 == 0
    if len(p) == 1:
        return ([([p[0], p[0]], None)] if on else []), False
    segs = list(zip(p, p[1:])) + ([(p[-1], p[0])] if closed else [])
    out, near = [], False
    cur = [p[0]] if on else None
    held = closed and on  # the first dash, joined to the last one at the end
    first = None
    for a, b in segs:
        ln, pos = math.dist(a, b), 0.0
        d = (b[0] - a[0], b[1] - a[1])
        while True:
            if abs(left - (ln - pos)) < 1e-4:
                near = True
            if left > ln - pos:
                left -= ln - pos
                if on:
                    cur.append(b)
                break
            pos += left
            pt = (a[0] + d[0] * pos / ln, a[1] + d[1] * pos / ln) if pos < ln else b
            if on:
                cur.append(pt)
                if held and first is None:
                    first, first_d = cur, d
                else:
                    out.append((cur, d))
                cur = None
            else:
                cur = [pt]
            i = (i + 1) % len(pat)
            left, on = pat[i], not on
    if held and first is None:  # one dash all round
        return [(p, "closed")], near
    if on:
        cur = cur + first[1:] if held else cur
        out.append((cur, d))
    elif held:
        out.append((first, first_d))
    return out, near


def dashed_referee(pts, width, join, cap, limit, dash, offset, closed=False):
    parts, near = dashes(pts, closed, dash, offset)
    geoms = [referee(q, width, join, cap, limit, closed=(hint == "closed"), hint=None if hint == "closed" else hint)
             for q, hint in parts]
    geoms = [g for g in geoms if g is not None]
    return (union(geoms) if geoms else None), near


def union(parts):
    # GEOS's floating overlay has lost holes here (a pentagram stroked 1 px
    # wide came out with its centre filled); the snap-rounding overlay on
    # a 2^-30 px grid is robust, and moves nothing by a visible amount.
    return shapely.union_all(parts, grid_size=2 ** -30)


BOXES = np.array([box(x, y, x + 1, y + 1) for y in range(SIZE) for x in range(SIZE)])


def exact_coverage(geom):
    out = np.zeros(SIZE * SIZE)
    if geom is None or geom.is_empty:
        return out.reshape(SIZE, SIZE)
    x0, y0, x1, y1 = geom.bounds  # only the boxes it may touch
    xs, ys = np.arange(SIZE * SIZE) % SIZE, np.arange(SIZE * SIZE) // SIZE
    near = (xs + 1 > x0) & (xs < x1) & (ys + 1 > y0) & (ys < y1)
    out[near] = shapely.area(shapely.intersection(geom, BOXES[near]))
    return out.reshape(SIZE, SIZE)


def coverage(outline, bits=12):
    return rastrum.polygon_coverage(outline, (SIZE, SIZE), rule="nonzero", subpixel_bits=bits,
                                    dtype=np.float64)


coord = st.floats(3, SIZE - 3, allow_nan=False).map(lambda v: round(v * 64) / 64)


@st.composite
def polylines(draw):
    n = draw(st.integers(1, 7))
    pts = [(draw(coord), draw(coord)) for _ in range(n)]
    if draw(st.booleans()) and n > 1:  # a tiny segment
        i = draw(st.integers(0, n - 1))
        pts.insert(i + 1, (pts[i][0] + draw(st.sampled_from([0, 1 / 64, -1 / 32])), pts[i][1] + 1 / 64))
    return pts


def near_limit(pts, limit, closed):
    """Is some vertex's miter ratio within 1e-6 of the limit (where float
    rounding may pick either join)?"""
    p = [q for i, q in enumerate(pts) if i == 0 or q != pts[i - 1]]
    n = len(p)
    for i in (range(n) if closed else range(1, n - 1)):
        a, v, b = p[i - 1], p[i], p[(i + 1) % n]
        if a == v or v == b:
            continue
        u1 = np.subtract(v, a) / math.dist(v, a)
        u2 = np.subtract(b, v) / math.dist(b, v)
        c = -float(np.dot(u1, u2))
        if c < 1 and abs(math.sqrt(2 / (1 - c)) - limit) < 1e-6:
            return True
    return False


@settings(deadline=None, max_examples=examples(30), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([0.5, 1, 2.5, 4]), st.sampled_from(["miter", "bevel"]),
       st.sampled_from(["butt", "square"]), st.sampled_from([1.0, 1.5, 4.0, 10.0]))
def test_polygonal_strokes_exact(pts, width, join, cap, limit):
    assume(not near_limit(pts, limit, False))
    got = coverage(rastrum.stroke(pts, width, join=join, cap=cap, miter_limit=limit))
    want = exact_coverage(referee(pts, width, join, cap, limit))
    assert np.abs(got - want).max() <= 1 / 255, (pts, width, join, cap, limit)


@settings(deadline=None, max_examples=examples(20), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([1, 3]), st.sampled_from(["miter", "bevel"]),
       st.sampled_from([1.0, 4.0]))
def test_closed_subpaths_joined_all_round(pts, width, join, limit):
    assume(len(set(pts)) >= 3 and not near_limit(pts + [pts[0]], limit, True))
    path = rastrum.Path().move_to(*pts[0])
    for q in pts[1:]:
        path.line_to(*q)
    path.close()
    got = coverage(rastrum.stroke(path, width, join=join, cap="butt", miter_limit=limit))
    want = exact_coverage(referee(pts, width, join, "butt", limit, closed=True))
    assert np.abs(got - want).max() <= 1 / 255, (pts, width, join, limit)


@settings(deadline=None, max_examples=examples(20), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([1, 3]), st.sampled_from(["round", "miter", "bevel"]),
       st.sampled_from(["round", "butt", "square"]))
def test_round_parts_within_tolerance(pts, width, join, cap):
    assume("round" in (join, cap))
    tol = 1 / 1024
    got = coverage(rastrum.stroke(pts, width, join=join, cap=cap, tolerance=tol))
    assume(not near_limit(pts, 4.0, False))
    want = exact_coverage(referee(pts, width, join, cap, 4.0))
    # a band of width tol (rastrum.h: round parts within max(tolerance,
    # 2 grid steps of 2^-16 px)) + the fill's snapping (2^-13 px a
    # coordinate at subpixel_bits=12) + the referee's 1024-gon, along at
    # most 2 px of boundary in a pixel
    assert np.abs(got - want).max() <= 2 * (tol + 2 ** -12) + 1e-4, (pts, width, join, cap)


dash_arrays = st.lists(st.sampled_from([0, 0.5, 1, 2.5, 3.25]), min_size=1, max_size=3).filter(any)


def polyline_geometry(pts, closed):
    """The points as a stroke's geometry: a closed Path (one subpath) or
    the open polyline itself."""
    if not closed:
        return pts
    geom = rastrum.Path().move_to(*pts[0])
    for q in pts[1:]:
        geom.line_to(*q)
    return geom.close()


def stroke_bound(tol, join, cap):
    """The per-pixel bound on "area" coverage against the referee's exact
    area: 1/255 for polygonal joins and caps; round ones within the
    tolerance's band both ways plus the arcs' snapping (docs/paths.md)."""
    return 2 * (tol + 2 ** -12) + 1e-4 if "round" in (join, cap) else 1 / 255


@settings(deadline=None, max_examples=examples(30), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([0.5, 1, 2.5]), st.sampled_from(["miter", "bevel", "round"]),
       st.sampled_from(["butt", "square", "round"]), dash_arrays, st.sampled_from([-1.25, 0, 0.75, 2]),
       st.booleans())
def test_dashes(pts, width, join, cap, dash, offset, closed):
    """Every join x cap dashed, open and closed: polygonal ones within 1/255
    per pixel, round ones within the tolerance's band."""
    closed = closed and len(set(pts)) >= 3
    assume(not near_limit(pts + ([pts[0]] if closed else []), 4.0, closed))
    want, near = dashed_referee(pts, width, join, cap, 4.0, dash, offset, closed)
    assume(not near)
    tol = 1 / 1024
    geom = polyline_geometry(pts, closed)
    got = coverage(rastrum.stroke(geom, width, join=join, cap=cap, dash=dash, dash_offset=offset,
                                  tolerance=tol))
    assert np.abs(got - exact_coverage(want)).max() <= stroke_bound(tol, join, cap), \
        (pts, width, join, cap, dash, offset, closed)


def test_dash_crossing_a_vertex_keeps_the_join():
    """An L with one dash over its corner: the miter is there, exactly as
    the solid L's; a closed square starting mid-dash: one dash over the
    start vertex, mitred, no caps there."""
    solid = coverage(rastrum.stroke([(4, 4), (12, 4), (12, 12)], 2))
    dashed = coverage(rastrum.stroke([(4, 4), (12, 4), (12, 12)], 2, dash=[100, 1]))
    assert np.array_equal(solid, dashed)
    sq = rastrum.Path().move_to(4, 4).line_to(16, 4).line_to(16, 16).line_to(4, 16).close()
    # perimeter 48 = the period: on from 1 px before the start to 1 px after
    got = coverage(rastrum.stroke(sq, 2, dash=[2, 46], dash_offset=1))
    # two 1 x 2 legs overlapping by 1 px, and the corner's miter square
    assert got.sum() == 4 and got[3:5, 3:5].sum() == 4


def test_zero_length_subpaths():
    dot = coverage(rastrum.stroke([(10, 10), (10, 10)], 4, cap="round", tolerance=1 / 1024))
    assert abs(dot.sum() - math.pi * 4) < 0.01
    sq = coverage(rastrum.stroke([(10.5, 10.5)], 3, cap="square"))
    assert sq.sum() == 9.0
    assert coverage(rastrum.stroke([(10, 10)], 3, cap="butt")).sum() == 0


def test_self_crossing_counted_once():
    """An X: the crossing is covered once (non-zero union): exact per
    pixel, where an accumulator would count the crossing twice."""
    pts = [(2, 2), (20, 20), (20, 2), (2, 20)]
    outline = rastrum.stroke(pts, 2, join="bevel")
    got = coverage(outline)
    want = exact_coverage(referee(pts, 2, "bevel", "butt", 4.0))
    assert np.abs(got - want).max() <= 1 / 255
    # total: the snapping of the outline's irrational vertices (1/4096 px
    # grid) along its ~110 px of boundary, at most
    assert abs(got.sum() - want.sum()) < 110 * 2 ** -12
    acc = rastrum.polygon_coverage(outline, (SIZE, SIZE), rule="nonzero", method="accumulate",
                                   subpixel_bits=12, dtype=np.float64)
    assert np.abs(acc - want).max() > 10 / 255  # the signed-area accumulator adds overlaps (0.086 here)


def test_bad_arguments():
    for kw, msg in ((dict(width=0), "width"), (dict(width=1, join="mitre"), "join"),
                    (dict(width=1, cap="flat"), "cap"), (dict(width=1, miter_limit=0.5), "miter_limit"),
                    (dict(width=1, dash=[2, -1]), "dash"), (dict(width=1, dash=[0, 0]), "dash"),
                    (dict(width=1, dash=[]), "dash"), (dict(width=1, dash=[1, float("nan")]), "dash"),
                    (dict(width=1, dash=[1], dash_offset=float("inf")), "dash_offset")):
        with pytest.raises(rastrum.InputError, match=msg):
            rastrum.stroke([(0, 0), (4, 4)], **kw)
    with pytest.raises(rastrum.InputError, match="geometry"):
        rastrum.stroke([[(0, 0, 1)]], 1)


@settings(deadline=None, max_examples=examples(25), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([0.5, 3]), st.sampled_from(["miter", "round"]), st.sampled_from(["butt", "round"]),
       st.sampled_from([0, 4, 8, 16]))
def test_outline_arrays_equal_the_path_lists(pts, width, join, cap, bits):
    """stroke() hands its outline (and takes polylines) as arrays, the
    Path's lists made only when read: a Path rebuilt from those lists
    reads, flattens and fills the same, and extending the outline extends
    the lists."""
    out = rastrum.stroke(np.array(pts), width, join=join, cap=cap)
    again = rastrum.stroke([tuple(p) for p in pts], width, join=join, cap=cap)
    flat = out.flatten(bits)
    plain = rastrum.Path()
    plain._verbs, plain._pts = list(again._verbs), list(again._pts)  # the list-held Path
    want = plain.flatten(bits)
    assert len(flat) == len(want)
    for a, b in zip(flat, want):
        assert a.dtype == b.dtype and np.array_equal(a, b)
    assert np.array_equal(out.points, plain.points) and np.array_equal(out.verbs, plain.verbs)
    assert len(out) == len(plain)
    shape = (SIZE, SIZE)
    assert np.array_equal(rastrum.polygon_coverage(out, shape, rule="nonzero", subpixel_bits=bits),
                          rastrum.polygon_coverage(plain, shape, rule="nonzero", subpixel_bits=bits))
    copy = out.copy()
    copy.move_to(1, 1).line_to(5, 1).line_to(5, 5)
    assert len(copy) == len(plain) + 3 and copy.points[-1].tolist() == [5, 5]
    assert len(out) == len(plain)
    with pytest.raises(ValueError, match="tolerance"):
        out.flatten(8, tolerance=1e-9)

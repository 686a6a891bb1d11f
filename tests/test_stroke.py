"""rastrum.stroke: "area" coverage of the outline, filled non-zero, against
the ideal stroke pixel by pixel.  Referee: shapely (GEOS), built apart
from rastrum's pieces: each segment's flat buffer, each vertex's join as
GEOS buffers the two-segment polyline around it (mitre when SVG's ratio
1/sin(theta/2) is within miter_limit, else bevel), caps as buffers of the
end segments extended (square) or of the end points (round); all unioned.
Polygonal joins and caps: within 1/255 of the exact area per pixel;
round ones: within twice the Path's tolerance plus the arcs' error.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

import rastrum
from rastrum._path import ARC_ERROR

shapely = pytest.importorskip("shapely")
from shapely.geometry import LineString, Point, box  # noqa: E402

SIZE = 24


def referee(pts, width, join, cap, limit, closed=False):
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
            parts.append(Point(p[0]).buffer(h, quad_segs=512))
        elif cap == "square":
            parts.append(box(p[0][0] - h, p[0][1] - h, p[0][0] + h, p[0][1] + h))
        return union(parts) if parts else None
    ring = p + [p[0]] if closed else p
    for a, b in zip(ring, ring[1:]):
        parts.append(LineString([a, b]).buffer(h, cap_style="flat"))
    n = len(p)
    for i in (range(n) if closed else range(1, n - 1)):
        a, v, b = p[i - 1], p[i], p[(i + 1) % n]
        if join == "round":
            parts.append(Point(v).buffer(h, quad_segs=512))
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
            if cap == "round":
                parts.append(Point(end).buffer(h, quad_segs=512))
            elif cap == "square":
                u = np.subtract(end, nxt) / math.dist(end, nxt)
                parts.append(LineString([end, tuple(np.add(end, u * h))]).buffer(h, cap_style="flat"))
    return union(parts)


def union(parts):
    # GEOS's floating overlay has lost holes here (a pentagram stroked 1 px
    # wide came out with its centre filled); the snap-rounding overlay on
    # a 2^-30 px grid is robust, and moves nothing by a visible amount.
    return shapely.union_all(parts, grid_size=2 ** -30)


def exact_coverage(geom):
    boxes = [box(x, y, x + 1, y + 1) for y in range(SIZE) for x in range(SIZE)]
    if geom is None:
        return np.zeros((SIZE, SIZE))
    return shapely.area(shapely.intersection(geom, boxes)).reshape(SIZE, SIZE)


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


@settings(deadline=None, max_examples=60, suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([0.5, 1, 2.5, 4]), st.sampled_from(["miter", "bevel"]),
       st.sampled_from(["butt", "square"]), st.sampled_from([1.0, 1.5, 4.0, 10.0]))
def test_polygonal_strokes_exact(pts, width, join, cap, limit):
    assume(not near_limit(pts, limit, False))
    got = coverage(rastrum.stroke(pts, width, join=join, cap=cap, miter_limit=limit))
    want = exact_coverage(referee(pts, width, join, cap, limit))
    assert np.abs(got - want).max() <= 1 / 255, (pts, width, join, cap, limit)


@settings(deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow])
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


@settings(deadline=None, max_examples=25, suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([1, 3]), st.sampled_from(["round", "miter"]),
       st.sampled_from(["round", "butt"]))
def test_round_parts_within_tolerance(pts, width, join, cap):
    tol = 1 / 1024
    got = coverage(rastrum.stroke(pts, width, join=join, cap=cap, tolerance=tol))
    assume(not near_limit(pts, 4.0, False))
    want = exact_coverage(referee(pts, width, join, cap, 4.0))
    # a band of width tol + ARC_ERROR (+ the referee's 512-gon) along at
    # most 2 px of boundary in a pixel
    assert np.abs(got - want).max() <= 2 * (tol + ARC_ERROR) + 1e-4, (pts, width, join, cap)


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
                    (dict(width=1, dash=[2, 1]), "dash")):
        with pytest.raises(rastrum.InputError, match=msg):
            rastrum.stroke([(0, 0), (4, 4)], **kw)
    with pytest.raises(rastrum.InputError, match="geometry"):
        rastrum.stroke([[(0, 0, 1)]], 1)

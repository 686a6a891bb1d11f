"""rastrum.stroke(outline="compact"): the outline through each join's
inner meeting point (csrc/src/path/stroke.c, "Inner joins") and round
parts straddling the circle ("Round parts straddling the circle") against
the same referee as tests/test_stroke.py (shapely's union of each segment's flat
buffer, each vertex's join and each cap, built apart from rastrum's
pieces), pixel by pixel with the same bounds: polygonal joins and caps
within 1/255 of the exact area, round ones within twice (the tolerance +
the fill's snapping).  Then what the meeting point is for: at a plain turn
the ring has no loop (a simple polygon; "accumulate", which adds overlaps,
then equals "area"), and where the segments do not cover the corner the
outline keeps the pivot (the same outline as outline="exact"); round parts
take about 1/sqrt(2) as many points.  The C side at grid points, the
round parts' bound point by point, and the range limits:
tests/c/test_stroke_compact.c and tests/fuzz/fuzz_stroke_compact.c.
"""

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

import rastrum
from strategies import examples

shapely = pytest.importorskip("shapely")
from shapely.geometry import LinearRing  # noqa: E402
from test_stroke import (SIZE, coverage, dash_arrays, dashed_referee, exact_coverage, near_limit,  # noqa: E402
                         polyline_geometry, polylines, referee, stroke_bound)


@settings(deadline=None, max_examples=examples(30), suppress_health_check=[HealthCheck.too_slow])
@given(polylines(), st.sampled_from([0.5, 1, 2.5, 4]), st.sampled_from(["miter", "bevel", "round"]),
       st.sampled_from(["butt", "square", "round"]), st.sampled_from([1.0, 1.5, 4.0]), st.booleans(),
       st.none() | dash_arrays, st.sampled_from([0, 0.75]))
def test_compact_within_the_bound(pts, width, join, cap, limit, closed, dash, offset):
    closed = closed and len(set(pts)) >= 3
    assume(not near_limit(pts + ([pts[0]] if closed else []), limit, closed))
    tol = 1 / 1024
    geom = polyline_geometry(pts, closed)
    kw = dict(join=join, cap=cap, miter_limit=limit, tolerance=tol)
    if dash:
        want, near = dashed_referee(pts, width, join, cap, limit, dash, offset, closed)
        assume(not near)
    else:
        want = referee(pts, width, join, cap, limit, closed=closed)
    got = coverage(rastrum.stroke(geom, width, outline="compact", dash=dash, dash_offset=offset, **kw))
    assert np.abs(got - exact_coverage(want)).max() <= stroke_bound(tol, join, cap), \
        (pts, width, join, cap, limit, closed, dash)


def _rings(outline):
    """The outline's rings, its points as the stroker made them (not
    snapped as flatten() snaps)."""
    verbs, pts = outline.verbs, outline.points
    drawn = verbs[verbs != rastrum._path.CLOSE]
    starts = np.flatnonzero(drawn == rastrum._path.MOVE)
    return np.split(pts, starts[1:])


ZIGZAG = [(2, 3), (8, 20), (13, 4), (19, 21), (22, 5)]


@pytest.mark.parametrize("join", ["miter", "bevel", "round"])
def test_meet_plain_turns_make_no_loop(join):
    """A zigzag that does not cross itself, 2 px wide: "compact" makes one
    ring, a simple polygon (with polygonal joins two points fewer per join
    than "exact", which loops at each inner corner), and the signed-area
    accumulator gives what "area" gives; on "exact" it adds the loops."""
    piv = rastrum.stroke(ZIGZAG, 2, join=join, miter_limit=10)
    meet = rastrum.stroke(ZIGZAG, 2, join=join, miter_limit=10, outline="compact")
    (rp,), (rm,) = _rings(piv), _rings(meet)
    if join != "round":
        assert len(rm) == len(rp) - 2 * (len(ZIGZAG) - 2)
    assert LinearRing(rm).is_simple and not LinearRing(rp).is_simple
    kw = dict(rule="nonzero", subpixel_bits=12, dtype=np.float64)
    area = rastrum.polygon_coverage(meet, (SIZE, SIZE), method="area", **kw)
    acc = rastrum.polygon_coverage(meet, (SIZE, SIZE), method="accumulate", **kw)
    assert np.abs(acc - area).max() < 1e-6
    acc_piv = rastrum.polygon_coverage(piv, (SIZE, SIZE), method="accumulate", **kw)
    assert np.abs(acc_piv - area).max() > 1e-3  # the loops, counted twice


@pytest.mark.parametrize("pts", [
    [(2, 10), (20, 10), (2, 10.5)],                   # a turn of 178 degrees: the lines meet far off
    [(2, 10), (12, 10), (12, 10.25), (2, 10.5)],      # a middle segment shorter than the corner's reach
    [(2, 10), (20, 10), (20.3, 10.9)],                # the last segment shorter than the reach
    [(2, 10), (3.05, 10), (8.05, 18.66)],             # 60 degrees: the lines meet within the first
                                                      # segment (h tan 30 = 0.87 < 1.05) but the second
                                                      # one's parallelogram reaches h sin 60 = 1.3 back
])
def test_compact_keeps_the_pivot_where_the_segments_miss_the_corner(pts):
    for join in ("miter", "bevel"):  # (round joins: other arc points)
        piv = rastrum.stroke(pts, 3, join=join)
        meet = rastrum.stroke(pts, 3, join=join, outline="compact")
        assert np.array_equal(piv.points, meet.points) and np.array_equal(piv.verbs, meet.verbs), join


def test_compact_round_parts_fewer_points():
    """A dot 3 px wide at the default tolerance (1/256 px): 4m points on
    the circle, m = 14 exact (w <= m^2 (4T - 3) on the 2^-16 px grid),
    m = 10 compact (w (2m^2 + 1) <= 4 m^4 (4T - 3))."""
    exact = rastrum.stroke([(10, 10)], 3, cap="round")
    compact = rastrum.stroke([(10, 10)], 3, cap="round", outline="compact")
    (e,), (c,) = _rings(exact), _rings(compact)
    assert (len(e), len(c)) == (56, 40)
    c = c - 10
    r = np.hypot(c[:, 0], c[:, 1])
    # outside the circle by 1.5 / (4 m^2) = 0.00375 px, within the rounding
    assert np.abs(r - 1.5 * (1 + 1 / 400)).max() <= 2 ** -16


def test_compact_bad_argument():
    with pytest.raises(rastrum.InputError, match="outline"):
        rastrum.stroke([(1, 1), (5, 5)], 1, outline="meet")


@pytest.mark.parametrize("aa", [None, "area", "ss4"])
def test_canvas_stroke_passes_outline(aa):
    """Canvas.stroke(outline=) paints the fill of rastrum.stroke(outline=):
    the compact outline's pixels, which differ from the exact outline's
    somewhere on this zigzag of round joins (so a dropped keyword fails)."""
    pts = [(3.2, 4.1), (20.7, 18.3), (9.4, 27.9), (33.1, 30.2), (26.6, 6.5)]
    out = {}
    for kind in ("exact", "compact"):
        c = rastrum.Canvas((40, 40), format="gray8")
        c.stroke(pts, 255, width=5, join="round", cap="round", aa=aa, outline=kind)
        ref = rastrum.Canvas((40, 40), format="gray8")
        ref.fill_polygon(rastrum.stroke(pts, 5, join="round", cap="round", outline=kind), 255,
                         rule="nonzero", aa=aa)
        assert np.array_equal(c.array, ref.array)
        out[kind] = c.array.copy()
    if aa == "area":
        assert not np.array_equal(out["exact"], out["compact"])
    with pytest.raises(rastrum.InputError, match="outline"):
        rastrum.Canvas((4, 4), format="gray8").stroke(pts, 255, width=1, outline="tight")

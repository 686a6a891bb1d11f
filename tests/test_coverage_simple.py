""""area" coverage on its simple rows (csrc/src/coverage/coverage_acc.c): a
row is taken by the signed-area accumulation, without the sweep, when each
pixel of it is met by at most one edge, or by two that share an end as a
ring's chain (one ends where the other starts, one direction) or cusp (both
start or both end there, opposite directions), and no horizontal edge lies
inside the row.  Each scene below breaks one of those conditions where
the accumulation alone would be wrong (the winding number takes three
values in some pixel), so that "area" must send the row to the sweep; each
is held to the exact oracle (tests/oracle_coverage.py) under both rules,
and beside it the accumulation, to show that it differs there (else the
scene would test nothing)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check

SCENES = {
    # Two rings meet at V = (-1, 1.5), left of the image.  In row 1, ring A
    # comes down to V and ring B comes up to it: a chain of opposite
    # directions through pixels (0, 1) and (1, 1), with A's inside above
    # (winding +1) and B's below (-1) in each.
    "chain, opposite directions, vertex left of the image": [
        [(2.5, 0.5), (-1, 1.5), (-3, 0.5)],
        [(2.5, 2.5), (-1, 1.5), (-3, 2.5)]],
    # Two spikes whose tips touch at V = (5.5, 6): A's right side and B's
    # left side both come down to V and meet pixel column 5 of rows 2..4
    # alone, a cusp of one direction; A and B turn opposite ways (+1, -1).
    "cusp, one direction, tips touching below": [
        [(4.7, 0), (5.5, 6), (0, 2)],
        [(6.3, 0), (5.5, 6), (10, 2)]],
    # Three edges in pixel (0, 4), all from V = (-1, 4.6) left of the image:
    # ring A's spike (f down to V, then s up from it: a cusp) and ring B's
    # side t down from V (a chain with f, not with s); A and B turn
    # opposite ways, so the pixel holds windings -1, 0 and +1.
    "three edges in a pixel": [
        [(3, 3.0), (-1, 4.6), (3, 3.6)],
        [(-1, 4.6), (3, 5.6), (-3, 6.5)]],
    # A rectangle's bottom side (horizontal, inside row 4) under a
    # triangle's edge of the same turn: winding 2 above the side and right
    # of the edge, 1 and 0 elsewhere in pixel (3, 4); that edge is the only
    # one to meet the pixel.
    "horizontal edge inside a row": [
        [(0.5, 0.5), (8.5, 0.5), (8.5, 4.5), (0.5, 4.5)],
        [(3.2, 0.2), (8.8, 8.8), (3.8, 8.8)]],
}


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
@pytest.mark.parametrize("name", sorted(SCENES))
def test_rows_the_accumulation_cannot_take(name, rule):
    rings = SCENES[name]
    exact = _check(rings, rule, shape=(9, 9))
    acc = rastrum.polygon_coverage(rings, (9, 9), rule=rule, method="accumulate", dtype=np.float64)
    want = np.array(exact, dtype=np.float64)
    assert np.abs(acc - want).max() > 0.01, "the scene does not need the sweep"


@settings(max_examples=S_.examples(150), deadline=None)
@given(S_.rings_from_few_points((-3, 11), (-2, 10)), st.sampled_from(["nonzero", "evenodd"]))
def test_rings_sharing_vertices(rings, rule):
    """Rings drawn from a few points (some outside the image, some on
    pixel corners, some inside pixels): they share vertices and sides,
    touch tip to tip, run back along themselves and meet at vertices with
    four or six edges, the cases the test for a simple row must sort."""
    _check(rings, rule, shape=(9, 9))


def test_a_run_whose_edges_cancelled():
    """Triangles in one call: T1's horizontal side B-C lies inside row 4;
    the edge before it in T1, A-B, cancels with T2's B-A, so no live edge
    of the row owns the run; T3's left side crosses it in pixel (2, 4)
    (windings 2, 1, 1 and 0 there)."""
    tris = np.array([[(1, 1), (6, 4.5), (1, 4.5)], [(6, 4.5), (1, 1), (7, 1)],
                     [(2.3, 2), (9, 8.8), (2.6, 8.8)]])
    _check(tris.tolist(), "nonzero", triangles=True, shape=(9, 9))
    acc = rastrum.triangles_coverage(tris, (9, 9), method="accumulate", dtype=np.float64)
    exact = rastrum.triangles_coverage(tris, (9, 9), dtype=np.float64)
    assert abs(acc[4, 2] - exact[4, 2]) > 0.01

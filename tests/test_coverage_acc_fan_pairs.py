""""accumulate" of triangle batches whose sides meet at one top vertex
(csrc/src/coverage/coverage_acc.c, rast__acc_pairs and rast__acc_cancel):
a batch's sides shared by two triangles, equal and opposite, are dropped
before the walk; the match compares the whole edge, its top (xt, yt) and
its run (dx, dy), read as two 64-bit words.  Here 8 fans of 20 to 40 thin
triangles each round one centre, on sectors of a half disc below it with
gaps between them, all in shuffled order: hundreds of edges share their
top, half of them run the other way, not yet matched when the others
look, and 16 of them (each fan's first and last sides) have no partner.
An edge matched by its top alone drops two sides that do not cancel
(which goes unseen where the two partners left match each other in turn,
but not with a side that has none).  The fans' union is the polygons of
their rims and centre (the triangles meet side to side, no overlap), so
the coverage is theirs, against the exact oracle
(oracle_coverage.coverage_exact), check_area's allowance at a tie."""

import numpy as np
import pytest

import rastrum
import oracle_coverage as oc
from test_coverage import check_area


def _fans(rnd, k, g, cx, cy, r):
    """g fans of about k / g triangles (centre, rim i, rim i + 1) each, on
    g sectors of the lower half disc of radius r about (cx, cy) with gaps
    between them (each fan's first and last sides from the centre are
    shared with no other triangle), rim points at jittered angles on the
    1/256 grid, all the triangles shuffled; and the fans' polygons of
    centre and rim (meeting at the centre only)."""
    c = np.array([cx, cy])
    tris, polys = [], []
    edges = np.linspace(0.02, np.pi - 0.02, 2 * g + 1)
    for f in range(g):
        t = np.sort(rnd.uniform(edges[2 * f], edges[2 * f + 1], k // g + 1))
        rim = np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], axis=1)
        rim = np.round(rim * 256) / 256
        tris += [[c, rim[i], rim[i + 1]] for i in range(len(rim) - 1)]
        polys.append([tuple(c)] + [tuple(p) for p in rim])
    tris = np.array(tris)
    return tris[rnd.permutation(len(tris))], polys


@pytest.mark.parametrize("seed", range(6))
def test_fan_sides_cancel_by_whole_edges(seed):
    rnd = np.random.default_rng(seed)
    k = int(rnd.integers(160, 321))
    shape = (40, 64)
    tris, polys = _fans(rnd, k, 8, 31.5 + rnd.integers(0, 256) / 256, 3 + rnd.integers(0, 256) / 256, 30.0)
    out = rastrum.triangles_coverage(tris, shape, method="accumulate")
    exact = oc.coverage_exact(polys, shape, rule="nonzero")
    check_area(out, exact, 255, 3 * len(tris), 0, "fans seed %d (%d triangles)" % (seed, len(tris)))

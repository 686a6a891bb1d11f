""""area" of a map whose coasts, once its shared borders are dropped
(csrc/src/coverage/coverage_plain.c, rast__cov_borders), are more than 16
rings: the coast and its lakes.  That polygon is tested by its chains
(rast__pl_chains) as one part of all its rings, condition 3 (the winding
number of the other rings at each ring's least vertex) at every ring's
least vertex, however many rings there are (docs/coverage.md, "borders").
The scenes: countries on a jittered grid (tests/test_coverage_borders.py's
maps) with a lake at every other country of the inner rows and columns
(16 or 25 lakes), alone (plain) or with a ring inside one country (its
winding number 2 there: not plain, the rings apart, so only condition 3
sees it; a country next to a lake or the coast, the ring a fraction of a
pixel from its border: winding 2 next to 0), in turn in each of several
countries, because the kept rings come in the order of a hash table and
the ring inside must be one of the late ones for some scene.  Held to the
exact non-zero oracle (tests/oracle_nonzero.py, quick on a map); where the
accumulation alone is wrong, the scene says so."""
import numpy as np
import pytest

import rastrum
from test_coverage_borders import _map, _shape
from oracle_nonzero import nonzero_area
from test_coverage_few_live import _check


def _lakes(n):
    """The countries left out: every other one of the inner rows and
    columns, none touching another or the coast"""
    return {(i, j) for i in range(1, n - 1, 2) for j in range(1, n - 1, 2)}


def _scene(seed, n, inside=None):
    m = _map(seed, n, n, 2)
    lakes = _lakes(n)
    rings = [r for c, r in m.items() if c not in lakes]
    if inside is not None:  # a ring inside that country, the same way round: winding 2 inside it
        r = np.array(m[inside])
        c = r.mean(0)
        rings.append((np.round((c + 0.85 * (r - c)) * 64) / 64).tolist())
    return rings


@pytest.mark.parametrize("n,seed", [(9, 3), (9, 4), (11, 3)])
def test_many_lakes(n, seed):
    rings = _scene(seed, n)
    assert len(_lakes(n)) + 1 > 16
    _check(rings, _shape(n, n), "lakes %d %d" % (n, seed))


# countries next to a lake or on the coast (none a lake)
INSIDE = [(0, 0), (1, 2), (2, 3), (4, 5), (6, 3), (3, 6), (7, 2), (8, 4), (5, 8), (2, 7), (6, 5), (4, 1)]


@pytest.mark.parametrize("inside", INSIDE)
def test_a_ring_inside(inside):
    n = 9
    assert inside not in _lakes(n)
    rings = _scene(5, n, inside)
    _check(rings, _shape(n, n), "inside %s" % (inside,))
    exact = nonzero_area(rings, _shape(n, n))
    acc = rastrum.polygon_coverage(rings, _shape(n, n), rule="nonzero", method="accumulate", dtype=np.float64)
    assert max(abs(float(a) - float(e)) for a, e in zip(acc.ravel(), exact.ravel())) > 0.01, "the scene tests nothing"

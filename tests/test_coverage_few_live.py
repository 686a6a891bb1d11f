""""area"'s blocks of crossing edges where few edges may bound anything
(csrc/src/coverage/coverage_area.c): rast__grp_dead finds the block's
edges whose sign may not be 0 (live), stopping once they are more than
1 in RAST__FEW_PER (8) of the block; a block with at most that many
(nl * RAST__FEW_PER <= mb) has each live edge added alone
(rast__grp_few, rast__few_one), the others the sweep.  Two gaps of
issue 34, against the exact oracle of tests/oracle_nonzero.py (itself
checked here against tests/oracle_coverage.py), within the bound of
rastrum.h:

* blocks of more than 32 live edges taking rast__grp_few (a cap of 32
  once sent them to the sweep; only the benchmarks' image hashes covered
  them): a fan of 400 to 470 long edges across a 2-row strip, each
  leaning across 3 or 4 of its neighbours (one block a row), the first
  36 or 40 at winding 0 and 1 in turn (live), a climb of 4, the rest deep
  inside.  With a build that prints the blocks, seeds 0 and 1 have a
  block of 444 edges with 44 live ones in row 0 (352 <= 444: the few
  path) and one of 442 with 56 in row 1 (the sweep); seed 2 (80 wide,
  40 live) 468 with 48, and 466 with 59.
* the boundary nl * RAST__FEW_PER == mb and its neighbour: the chains of
  tests/test_coverage_few_many.py.  (2, 50, 4, 1) has a block of 16 edges
  with 3 live, (4, 50, 4, 2) one of 24 with 4: rast__grp_dead stopping at
  nl * 8 >= mb instead of > mb returns 2 (3) of them, and rast__grp_few,
  which then takes the block, leaves the others out (5 and 6 pixels off,
  by up to 51 levels of 255).  (6, 40, 8, 3) has a block of 24 with 3
  live, (1, 58, 8, 0) one of 24 with 3 and (1, 55, 3, 1) one of 64 with 8:
  there the caller's `<=` made `<` takes the sweep instead, which gives
  the same result bit for bit (19 such blocks compared, uint8, uint16 and
  float64): both are exact, so no test can tell them apart."""

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from oracle_nonzero import nonzero_area
from test_coverage import check_area
from test_coverage_deep import _slanted
from test_coverage_few_many import _chain


def _fan(rnd, w, nlive, up, ndead, lean, q=1 / 256, h=1):
    """Quads from y = -1 to h + 1 whose left sides lean across `lean`
    (a range, in steps between neighbours) of their neighbours, one way and
    the other in turn; directions: nlive at winding 0 and 1 in turn, a climb
    of `up`, ndead deep inside, the way down; the right sides on one line
    outside the canvas; vertices on the grid q."""
    turns = [(-1) ** k for k in range(max(nlive, ndead))]
    dirs = turns[:nlive] + [1] * up + turns[:ndead] + [-1] * up
    dirs += [-sum(dirs)] if sum(dirs) else []
    k = np.arange(len(dirs))
    step = (w - 1.0) / len(dirs)
    s = np.where(k % 2, 1, -1) * rnd.uniform(lean[0], lean[1], len(dirs)) * step
    top, bot = (np.round((0.5 + step * k + sg * s) / q) * q for sg in (1, -1))
    return [r if d > 0 else r[::-1] for d, r in
            zip(dirs, ([(float(a), -1.0), (float(b), h + 1.0), (w + 5.0, h + 1.0), (w + 5.0, -1.0)]
                       for a, b in zip(top, bot)))]


def _check(rl, shape, what):
    """uint8 and uint16 as check_area has them; float64 within the same
    bound (n edges, every pair of them counted as crossing)."""
    a = nonzero_area(rl, shape)
    n = sum(len(r) for r in rl)
    m = n * (n - 1) // 2
    for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
        out = rastrum.polygon_coverage(rl, shape, rule="nonzero", dtype=dtype)
        check_area(out, a, M, n, m, "%s %s" % (what, np.dtype(dtype).name))
    out = rastrum.polygon_coverage(rl, shape, rule="nonzero", dtype=np.float64)
    bound = F(n + m + 1, 2 ** 58)
    bad = [(p, float(v), float(a[p])) for p, v in np.ndenumerate(out) if abs(F(float(v)) - a[p]) > bound]
    assert not bad, "%s float64: %d pixel(s) off, first: %s" % (what, len(bad), bad[:4])


def test_oracle_equals_coverage_exact():
    """The quick oracle against tests/oracle_coverage.py on scenes it can
    take: small chains (spanning edges), and slanted quads and triangles,
    coincident edges, some on pixel corners."""
    for seed in range(2):
        rnd = np.random.default_rng(seed)
        rl = _chain(rnd, 1 / 256, 3, 12, 3)
        assert (nonzero_area(rl, (2, 16)) == oc.coverage_exact(rl, (2, 16), rule="nonzero")).all()
        rl = _slanted(rnd, 4, 10, 12, seed % 2)
        assert (nonzero_area(rl, (4, 10)) == oc.coverage_exact(rl, (4, 10), rule="nonzero")).all()
    rl = [[(0.5, 0.25), (3.75, 1.5), (1.0, 2.75)], [(0.5, 0.25), (3.75, 1.5), (1.0, 2.75)],
          [(2.0, 0.0), (2.0, 3.0), (0.0, 1.5)]]
    assert (nonzero_area(rl, (3, 4)) == oc.coverage_exact(rl, (3, 4), rule="nonzero")).all()


@pytest.mark.parametrize("w,nlive,ndead,seed", [(64, 36, 400, 0), (64, 36, 400, 1), (80, 40, 420, 2)])
def test_more_than_32_live_edges_in_a_block(w, nlive, ndead, seed):
    rl = _fan(np.random.default_rng(seed), w, nlive, 4, ndead, (3, 4))
    _check(rl, (2, w), "fan %s" % ((w, nlive, ndead, seed),))


@pytest.mark.parametrize("params", [(2, 50, 4, 1), (4, 50, 4, 2), (6, 40, 8, 3), (1, 58, 8, 0), (1, 55, 3, 1)])
def test_live_edges_at_one_in_eight(params):
    nlive, ndead, up, seed = params
    rl = _chain(np.random.default_rng(seed), 1 / 256, nlive, ndead, up)
    _check(rl, (2, 16), "chain %s" % (params,))


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(24, 72), st.integers(1, 44), st.integers(0, 6),
       st.integers(8, 160), st.sampled_from([(1, 2), (2, 3), (3, 4), (0.5, 4)]), st.sampled_from([1 / 256, 1 / 16]))
def test_fans_equal_oracle(seed, w, nlive, up, ndead, lean, q):
    rl = _fan(np.random.default_rng(seed), w, nlive, up, ndead, lean, q)
    _check(rl, (2, w), "fan %s" % ((seed, w, nlive, up, ndead, lean, q),))

""""area" where a block of crossing edges has a few edges that may bound
something (issue 33): rast__grp_dead tests blocks with the winding number
0 on their left too (the block at the edge of the shapes: on 10,000
canvas-spanning triangles, blocks of 15,000 edges were swept whole), and
keeps no cap on the live edges it lists (only one on their share of the
block); rast__grp_few looks, for each live edge, only at the block's
spanning edges whose lines may meet its own (the narrow ones, by their
lines' left ends) and at the wide ones and those that start or end inside
the strip, each (coverage_area.c).  A chain of quads across the canvas
whose left sides lean across several neighbours each (one block a row):
2 at winding 0 and 1 in turn, a climb of 8, 40 deep inside and the way
down; the right sides outside the canvas, on one line.  Then a quad whose
left side crosses the whole canvas (a wide line across the strip), and
in half the draws a triangle with its vertices inside row 0.  With a
build that prints rast__grp_few's calls, the seeds of test_w0_seeds took
it with w = 0 in row 0 (7 live edges of 59), the wide line looked at
alone, the others by the window.  Against the exact oracle of tests/oracle_coverage.py within the
bound of rastrum.h.  (Blocks of more than 32 live edges, which the cap
sent to the sweep, need some 300 edges: the oracle takes minutes there.
The 10,000 triangles of bench/bench_crossings.py have hundreds, and
build/cbench_scale's image hash of that scene did not change.)"""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage_deep import _check

H, W = 1, 16  # the chain from y = -1 to H + 1; the canvas 2 rows, W wide


def _chain(rnd, q, nlive=2, ndead=40, up=8):
    """The quads (see above): side k at 0.5 + k (W - 1) / n, leaning by
    0.4 .. 1 px one way or the other in turn, on the grid q."""
    def snap(v):
        return float(np.round(v / q) * q)

    dirs = [1 if k % 2 == 0 else -1 for k in range(nlive)]
    dirs += [1] * up + [-1 if k % 2 else 1 for k in range(ndead)] + [-1] * up
    if sum(dirs):
        dirs.append(-sum(dirs))
    step = (W - 1.0) / len(dirs)
    rl = []
    for k, d in enumerate(dirs):
        s = (1 if k % 2 else -1) * float(rnd.uniform(0.4, 1.0))
        lt, lb = snap(0.5 + step * k + s), snap(0.5 + step * k - s)
        r = [(lt, -1.0), (lb, H + 1.0), (W + 5.0, H + 1.0), (W + 5.0, -1.0)]
        rl.append(r if d > 0 else r[::-1])
    rl.append([(snap(W * 0.75), -1.0), (W + 5.0, -1.0), (W + 5.0, H + 1.0), (snap(W * 0.25), H + 1.0)])
    if rnd.integers(0, 2):
        rl.append([(0.25, 0.25), (snap(W * 0.4), H - 0.5), (snap(W * 0.2), H - 0.25)])
    return rl


@settings(max_examples=S_.examples(2), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1 / 256, 1 / 64]),
       st.sampled_from([np.uint8, np.uint16]))
def test_few_many_equal_oracle(seed, q, dtype):
    rnd = np.random.default_rng(seed)
    _check(_chain(rnd, q), (H + 1, W), "nonzero", dtype, repr((seed, q)))


def test_w0_seeds():
    """Seeds 5 and 11 of the chain (see above), on the 1/256 pixel grid."""
    for seed in (5, 11):
        rnd = np.random.default_rng(seed)
        _check(_chain(rnd, 1 / 256), (H + 1, W), "nonzero", np.uint16, "seed %d" % seed)

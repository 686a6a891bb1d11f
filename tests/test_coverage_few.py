""""area" where a block of crossing edges has few that bound anything
(issue 33): in a row cut into blocks (coverage_area.c, rast__grp_blocks),
when rast__grp_dead shows all but a few of a block's edges to bound
nothing under non-zero, the block is not swept: each of the few alone
takes the moments where another edge starts, ends or crosses it
(rast__grp_few).  A reversed box under everything (winding -1 left of
the blocks), then a chain of quads whose left sides lean across their
neighbours (one block: winding -1, 0, 1 at its left end, where its few
live edges are, deep further right) and whose right sides do the same on
the canvas's right; vertices on a fine grid or the 1/64 pixel one, and
all the left sides through one point (crossings that fall together).
Against the exact oracle of tests/oracle_coverage.py within the bound of
rastrum.h.  (With a build that counts rast__grp_few's calls, 8 of the
first 12 seeds of the chain took it.)"""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage_deep import _check


def _chain(rnd, h, w, n, q):
    """The reversed box and n quads: side k of each side's chain at
    0.1 k from its end of the canvas, leaning by 0.2 .. 0.7 px one way or
    the other in turn (so that it crosses its neighbours)."""
    rl = [[(-3.0, -1.0), (w + 3.0, -1.0), (w + 3.0, h + 1.0), (-3.0, h + 1.0)]]

    def snap(v):
        return float(np.round(v / q) * q)

    for k in range(n):
        s = (1 if k % 2 else -1) * float(rnd.uniform(0.2, 0.7))
        lt, lb = snap(0.5 + 0.1 * k + s), snap(0.5 + 0.1 * k - s)
        s = (1 if k % 2 else -1) * float(rnd.uniform(0.2, 0.7))
        rt, rb = snap(w - 0.5 - 0.1 * k + s), snap(w - 0.5 - 0.1 * k - s)
        rl.append([(lt, -1.0), (lb, h + 1.0), (rb, h + 1.0), (rt, -1.0)])
    return rl


@settings(max_examples=S_.examples(5), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 2), st.integers(28, 36),
       st.sampled_from([1 / 256, 1 / 64]), st.sampled_from([np.uint8, np.uint16]))
def test_few_live_equal_oracle(seed, h, n, q, dtype):
    rnd = np.random.default_rng(seed)
    _check(_chain(rnd, h, 12, n, q), (h, 12), "nonzero", dtype, repr((seed, h, n, q)))


def test_few_live_through_one_point():
    """The chain's left sides all through one point inside the row, the
    right sides as in the chain."""
    rnd = np.random.default_rng(3)
    rl = _chain(rnd, 2, 12, 32, 1 / 256)
    for k in range(1, len(rl)):
        d = 0.0625 * (k - 16)
        r = rl[k]
        rl[k] = [(3.0 - d, -1.0), (3.0 + d, 3.0), r[2], r[3]]
    _check(rl, (2, 12), "nonzero", np.uint16, "through one point")

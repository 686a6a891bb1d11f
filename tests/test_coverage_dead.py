""""area" at the edge of many overlapping shapes (issue 33): a block of a
row (coverage_area.c, rast__grp_blocks) whose every edge provably bounds
nothing under non-zero is left out, not swept (rast__grp_dead): each
edge's line lies in [lo, hi) across the strip, the spanning edges wholly
left of an edge are before it all the way, those wholly right never, the
others may be; when that bound keeps the winding numbers on both sides of
every edge from 0, the sweep would add nothing.  Piles of slanted shapes,
mostly of one orientation (deep inside: winding numbers of 2 and more),
under a box over part of the canvas or none (the pile's edge with 0 on its
left, deep further right), some reversed (winding numbers back to 0
inside), some with vertices inside the rows (blocks cut by lines), against
the exact oracle of tests/oracle_coverage.py within the bound of
rastrum.h."""

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage_deep import _check, _slanted
from test_coverage_deep_lines import _slivers


def _area2(r):
    x = np.array([p[0] for p in r])
    y = np.array([p[1] for p in r])
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _oriented(rnd, rings, reversed_share):
    """The rings turned one way round (so that their winding numbers add
    up), all but about `reversed_share` of them."""
    out = []
    for r in rings:
        r = list(r)
        if (_area2(r) < 0) != (rnd.uniform() < reversed_share):
            r = r[::-1]
        out.append(r)
    return out


def _box(rnd, h, w):
    """A box from above the rows to below them over the canvas's right
    part (or all of it), either way round."""
    x0 = float(rnd.choice([-2.0, rnd.uniform(0.5, w - 0.5)]))
    r = [(x0, -1.0), (w + 2.0, -1.0), (w + 2.0, h + 1.0), (x0, h + 1.0)]
    return r if rnd.integers(0, 2) else r[::-1]


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 2), st.booleans(),
       st.sampled_from([0.0, 0.1, 0.5]), st.booleans(), st.sampled_from([np.uint8, np.uint16]))
def test_piles_equal_oracle(seed, h, grid, reversed_share, box, dtype):
    rnd = np.random.default_rng(seed)
    w = 12
    rl = _oriented(rnd, _slanted(rnd, h, w, 24, grid), reversed_share)
    if box:
        rl.append(_box(rnd, h, w))
    _check(rl, (h, w), "nonzero", dtype, repr((seed, h, grid, reversed_share, box)))


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.booleans(), st.sampled_from([0.0, 0.1]), st.booleans())
def test_slivers_piled_equal_oracle(seed, grid, reversed_share, box):
    rnd = np.random.default_rng(seed)
    w = 6
    rl = _oriented(rnd, _slivers(rnd, w, 56, grid), reversed_share)
    if box:
        rl.append(_box(rnd, 1, w))
    _check(rl, (1, w), "nonzero", np.uint8, repr((seed, grid, reversed_share, box)))


def test_deep_pile_edge():
    """The pile's edge: 0 left of it, winding numbers of 20 and more a
    pixel further right, every edge leaning across its neighbours."""
    rnd = np.random.default_rng(7)
    rl = []
    for k in range(24):
        x = 1.0 + 0.2 * k
        rl.append([(x, -1.0), (x + 7.0, -1.0), (x + 3.0 + rnd.uniform(0, 2), 3.0), (x - 0.5, 3.0)])
    rl = _oriented(rnd, rl, 0.0)
    _check(rl, (2, 14), "nonzero", np.uint8, "deep pile edge")

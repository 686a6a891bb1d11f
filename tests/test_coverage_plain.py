""""area" of a plain polygon by the accumulation alone
(csrc/src/coverage/coverage_plain.c): when the rings are simple and apart
and every face's winding number is in {0, 1} (or every one in {0, -1}),
"area" skips the test of each row.  The scenes are tall, so that the plain
test runs (its edges cross at least six rows per vertex); each breaks one
condition where the accumulation alone would be wrong (that is checked
too, else the scene would test nothing), and each is held to the exact
oracle (tests/oracle_coverage.py) under both rules, in uint8 and uint16."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check

SHAPE = (32, 8)


def _rect(x0, y0, x1, y1, ccw=True):
    r = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return r if ccw else r[::-1]


NOT_PLAIN = {
    # pixel column 0 holds winding +1 (A) and -1 (B)
    "side by side, opposite ways": [_rect(0.2, 0.5, 0.4, 30.5), _rect(0.6, 0.5, 0.8, 30.5, False)],
    # a ring inside another, the same way, closer than a pixel: 0, 1, 2
    "nested, one way": [_rect(0.1, 0.2, 5.9, 30.8), _rect(0.3, 1.3, 5.7, 29.7)],
    # a bow tie: its lobes turn opposite ways and meet at (2.5, 15.25)
    "crossing": [[(0.5, 0.5), (4.5, 30), (4.5, 0.5), (0.5, 30)]],
    # tips touching at (2.5, 15.5), opposite ways
    "touching at a vertex": [[(0, 0.5), (2.5, 15.5), (0, 30.5)], [(5, 0.5), (2.5, 15.5), (5, 30.5)]],
    # B's vertex on A's side, opposite ways (all three inside pixel
    # column 2, not on its sides: else no pixel would hold both)
    "a vertex on an edge": [_rect(0.5, 0.5, 2.5, 30.5), [(2.5, 15.5), (4.5, 29.5), (4.5, 1.5)]],
    # one ring through one point twice: two lobes, opposite ways
    "a vertex visited twice": [[(0.5, 0.5), (2.5, 15.5), (4.5, 30.5), (4.5, 0.5), (2.5, 15.5), (0.5, 30.5)]],
}


@pytest.mark.parametrize("name", sorted(NOT_PLAIN))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_not_plain(name, rule):
    rings = NOT_PLAIN[name]
    exact = _check(rings, rule, shape=SHAPE)
    acc = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.float64)
    assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


PLAIN = {
    "a hole the other way, closer than a pixel": [_rect(0.1, 0.2, 5.9, 30.8),
                                                  _rect(0.3, 1.3, 5.7, 29.7, False)],
    "side by side, one way, in one pixel column": [_rect(0.2, 0.5, 0.4, 30.5), _rect(0.6, 0.5, 0.8, 30.5)],
    "an island in a hole": [_rect(0.1, 0.2, 5.9, 30.8), _rect(0.3, 1.3, 5.7, 29.7, False),
                            _rect(0.5, 2.5, 5.5, 28.5)],
    "clockwise, vertices on pixel corners": [_rect(1, 1, 5, 31, False)],
}


@pytest.mark.parametrize("name", sorted(PLAIN))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_plain(name, rule):
    _check(PLAIN[name], rule, shape=SHAPE)


@settings(max_examples=S_.examples(150), deadline=None)
@given(S_.rings_from_few_points((-1, 9), (-2, 34), max_size=5, max_rings=3),
       st.sampled_from(["nonzero", "evenodd"]))
def test_tall_rings_from_few_points(rings, rule):
    """Rings drawn from a few points over a tall image: plain or not, they
    share vertices, touch, cross and nest; the oracle decides."""
    _check(rings, rule, shape=SHAPE)


@settings(max_examples=S_.examples(100), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(1, 3), st.sampled_from(["nonzero", "evenodd"]))
def test_nested_star_shaped_rings(seed, nrings, rule):
    """Simple rings round one point, one inside the next, each way round at
    random: plain exactly when the directions alternate outwards."""
    rnd = np.random.default_rng(seed)
    rings = []
    for k in range(nrings):
        n = int(rnd.integers(3, 12))
        ang = (np.arange(n) + rnd.uniform(0, 0.45, n)) * 2 * np.pi / n
        r = (3 - k) * rnd.uniform(0.8, 1.0, n)
        ring = np.stack([4 + r * np.cos(ang), 16 + 5 * r * np.sin(ang)], 1)
        ring = np.round(ring * 4) / 4
        rings.append(ring if rnd.integers(2) else ring[::-1])
    _check([r.tolist() for r in rings], rule, shape=SHAPE)

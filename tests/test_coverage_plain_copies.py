""""area" of text whose parts repeat (csrc/src/coverage/coverage_plain.c,
rast__pl_again): a part that is a moved copy of a part tested before (as
many rings, of the same sizes, every point less the one at the same place
in the other the same) takes its answer without a test.  A paragraph's
words repeat so; here "o"s with holes, set again at moves of whole
snapped units, among copies that hash alike but are not copies: a hole
turned the other way (the same sizes and boxes: winding 2 a fraction of a
pixel from 0, where the accumulation alone is wrong, checked), a vertex
moved by 1/256 px.  Each is held to the exact oracle
(tests/oracle_coverage.py) under both rules, in uint8 and uint16 (issue
34)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check
from test_coverage_plain_parts import _o

SHAPE = (6, 26)


def _moved(rings, dx):
    return [(np.asarray(r) + [dx, 0.0]).tolist() for r in rings]


def _spoilt(rings, how):
    """The same sizes and boxes, not a moved copy: the hole turned the
    other way round (its first point too), or a vertex moved by 1/256 px
    (the box may change)."""
    outer, hole = rings
    if how == "hole turned":
        return [outer, hole[::-1]]
    hole = [list(p) for p in hole]
    hole[3][1] += 1 / 256
    return [outer, hole]


BASE = _o(2.0, 3.0, False)


@pytest.mark.parametrize("how", ["hole turned", "a vertex moved"])
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_copies(how, rule):
    rings = BASE + _moved(BASE, 4.25) + _spoilt(_moved(BASE, 8.5), how) + _moved(BASE, 12.75) + \
        _spoilt(_moved(BASE, 17.0), how)
    exact = _check(rings, rule, shape=SHAPE)
    if how == "hole turned":  # where the accumulation alone is wrong: a spoilt copy must be tested
        acc = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@settings(max_examples=S_.examples(6), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 5), st.sampled_from(["nonzero", "evenodd"]))
def test_random_copies(seed, count, rule):
    """An "o" of 8-13 vertices, set count times 4.25 px apart, each copy
    spoilt or not at random, either way; the oracle decides."""
    rnd = np.random.default_rng(seed)
    base = _o(2.0, 3.0, bool(rnd.integers(2)), n=int(rnd.integers(8, 14)), r=float(rnd.uniform(0.8, 1.3)))
    rings = []
    for k in range(count):
        copy = _moved(base, 4.25 * k)
        pick = int(rnd.integers(3))
        rings += copy if pick == 0 else _spoilt(copy, ["hole turned", "a vertex moved"][pick - 1])
    _check(rings, rule, shape=(6, int(4.25 * count) + 2))

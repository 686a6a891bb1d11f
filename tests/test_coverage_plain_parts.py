""""area" of a polygon that is plain part by part
(csrc/src/coverage/coverage_plain.c, rast__cov_plain_parts): rings whose
pixel boxes share no pixel are apart, and a part (the rings whose boxes
meet) whose rings are simple, apart and wind 0 and one sign is taken by
the accumulation: the whole polygon when every part is, else the rows whose
edges are all of such parts (coverage_area.c, rast__cov_row_plain).  The
scenes are glyph-like: rings of many short edges (so that the test of the
whole polygon, which needs tall edges, does not run), side by side, with
holes, wound either way per part, some overlapping, touching or sharing a
pixel column with a neighbour wound the other way (where the accumulation
alone is wrong: checked, else the scene would test nothing).  Each is held
to the exact oracle (tests/oracle_coverage.py) under both rules, in uint8
and uint16 (issues 33 and 34)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check

SHAPE = (6, 24)


def _ring(cx, cy, rx, ry, n, phase, cw):
    t = phase + 2 * np.pi * np.arange(n) / n
    ring = np.stack([cx + rx * np.cos(t), cy + ry * np.sin(t)], 1)
    ring = np.round(ring * 64) / 64
    return (ring[::-1] if cw else ring).tolist()


def _o(cx, cy, cw, n=14, hole=True, r=1.2):
    """An "o": a ring of n vertices and a hole wound the other way."""
    rings = [_ring(cx, cy, r, 2.2, n, 0.3, cw)]
    if hole:
        rings.append(_ring(cx, cy, r - 0.5, 1.6, n, 0.5, not cw))
    return rings


SCENES = {
    # every part plain, wound opposite ways (the whole is not: two signs)
    "apart, either way": _o(2, 3, False) + _o(6, 3, True) + _o(10, 3, False, hole=False),
    # one part overlapping another one way (winding 2 between them)
    "two overlapping, the rest apart": _o(2, 3, True) + _o(6.5, 3, False) + _o(7.5, 3, False, hole=False)
    + _o(13, 3, True),
    # a part wound -1 and one +1 a fraction of a pixel apart in one column
    "opposite ways in one pixel column": _o(2, 3, False) + [_ring(7.3, 3, 0.25, 2.2, 12, 0.2, False),
                                                            _ring(7.85, 3, 0.2, 2.2, 12, 0.2, True)]
    + _o(12, 3, True),
    # two rings wound opposite ways, touching at a vertex
    "touching at a vertex": _o(2, 3, False) + [[(6, 0.5), (7.5, 3), (6, 5.5), (5.5, 3)],
                                               [(9, 0.5), (7.5, 3), (9, 5.5), (9.5, 3)]],
}


NOT_PLAIN = {"two overlapping, the rest apart", "opposite ways in one pixel column", "touching at a vertex"}


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_parts(name, rule):
    rings = SCENES[name]
    exact = _check(rings, rule, shape=SHAPE)
    if name in NOT_PLAIN and rule == "nonzero":  # where a part is not plain, the accumulation alone is wrong
        acc = rastrum.polygon_coverage(rings, SHAPE, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 4), st.sampled_from(["nonzero", "evenodd"]))
def test_glyph_rows(seed, count, rule):
    """"o"s of 8-13 vertices a ring, each wound at random, with or without
    a hole, 2.6-4 px apart (some overlapping, touching or in one pixel
    column with the next), one row of them or two rows whose boxes may
    meet: plain or not, part by part; the oracle decides."""
    rnd = np.random.default_rng(seed)
    rings, x = [], 1.5
    rows = 1 + int(rnd.integers(0, 2))
    for k in range(count):
        cy = 3.0 if rows == 1 else (1.6 if k % 2 else 4.3)
        n = int(rnd.integers(8, 14))
        r = float(rnd.uniform(0.6, 1.3))
        rings += [_ring(x, cy, r, 1.3 if rows == 2 else 2.2, n, float(rnd.uniform(0, 6.3)), bool(rnd.integers(2)))]
        if rnd.integers(2):
            cw = not (np.asarray(rings[-1])[:, 0] @ np.roll(np.asarray(rings[-1])[:, 1], -1)
                      - np.asarray(rings[-1])[:, 1] @ np.roll(np.asarray(rings[-1])[:, 0], -1) < 0)
            rings.append(_ring(x, cy, r * 0.5, (1.3 if rows == 2 else 2.2) * 0.6, n,
                               float(rnd.uniform(0, 6.3)), cw if rnd.integers(4) else not cw))
        x += float(rnd.uniform(1.0, 4.0)) if rows == 1 else float(rnd.uniform(0.8, 2.5))
    _check(rings, rule, shape=(6, int(np.ceil(x)) + 2))

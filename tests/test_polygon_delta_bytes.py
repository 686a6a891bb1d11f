"""The winding-delta fill written straight to one-byte pixels.

When the "aet" fill takes its winding deltas (csrc/src/fillers/aet.c; the
rule and its scenes: test_polygon_delta.py) and the target is one byte a
pixel -- polygon_mask's own (every pixel written, 1 or 0) or a gray8
Canvas (inside set, the rest left as it was) -- each row's counters are
turned into pixels eight columns at a time instead of runs.  Checked here
bit for bit against the exact oracle (tests/oracle.py): the Canvas on a
pattern it must leave alone outside the polygon, widths that are no
multiple of 8 (the last word partial), windings that wrap the counters'
bytes (non-zero: 128 to 240 turns of a ring, up to 510 crossings a row), both rules and samples.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import RULES, examples
from test_polygon_delta import OFFSETS, crossing_edges, many_rings


def check_canvas(rings, shape, **kw):
    exp = oracle_mask(rings, shape, **kw)
    rng = np.random.default_rng(len(rings) * 7919 + shape[1])
    pattern = rng.integers(0, 256, shape, dtype=np.uint8)
    pattern[pattern == 201] = 0  # the fill's value marks exactly the inside
    canvas = rastrum.Canvas.wrap(pattern.copy())
    canvas.fill_polygon(rings, 201, **kw)
    want = np.where(exp, np.uint8(201), pattern)
    assert np.array_equal(canvas.array, want), np.argwhere(canvas.array != want)[:10].tolist()
    assert np.array_equal(rastrum.polygon_mask(rings, shape, **kw), exp)


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(6), deadline=None)
@given(data=st.data())
def test_canvas_and_mask_match_oracle(rule, o, data):
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    rings, shape = data.draw(many_rings(S, o), label="scene")
    check_canvas(rings, shape, rule=rule, subpixel_bits=S, sample_offset=o)


@pytest.mark.parametrize("turns", [128, 200, 240])
def test_windings_past_a_byte(turns):
    """A triangle walked round `turns` times (non-zero: a winding of 128 or
    more, the top bit of the counters' bytes), beside many small rings so
    that the rule takes the deltas (at most 510 crossings a row: 2 x turns
    and two a small ring)."""
    tri = [(1.5, 0.5), (37.5, 2.5), (3.5, 4.5)]
    rings = [tri * turns]
    rings += [[(x + 0.25, 0.75), (x + 1.75, 2.25), (x + 0.5, 4.25)] for x in range(2, 40, 3)]
    shape = (5, 43)
    assert crossing_edges(rings, shape, 0.5) >= 8 * shape[0]
    for rule in RULES:
        check_canvas(rings, shape, rule=rule, subpixel_bits=4)

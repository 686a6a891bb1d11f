"""One outline's rows written straight to one-byte pixels.

When the "aet" fill sweeps (few edges for the rows: a circle, a glyph, a
star; csrc/src/fillers/aet.c, rast__aet_sweep_bytes) into one-byte pixels --
polygon_mask's own mask (every pixel written once, the background between
the runs) or a gray8 Canvas (inside set, the rest left as it was) -- its
row hook writes each row itself, and polygon_mask's rows above and below
the outline are one memset (painters/paint.c).  Checked here bit for bit
against the exact oracle (tests/oracle.py): stars across and past the
mask's sides, two outlines far apart in y (blank rows between them), widths
that are no multiple of 8, both rules and samples.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import RULES, examples

OFFSETS = [0.5, 0.0]


def star(data, h, w, y0, y1):
    """A ring of 3..40 vertices round a centre in rows [y0, y1), radii at
    random (a star, often self-crossing), some vertices on sample rows."""
    m = data.draw(st.integers(3, 40))
    cx = data.draw(st.floats(-4, w + 4))
    cy = data.draw(st.floats(y0, y1))
    radii = data.draw(st.lists(st.floats(0.5, max(1.0, (y1 - y0) / 2)), min_size=m, max_size=m))
    t = np.arange(m) * (2 * np.pi / m)
    ring = np.stack([cx + np.cos(t) * radii, cy + np.sin(t) * radii], axis=1)
    if data.draw(st.booleans()):
        ring[:, 1] = np.floor(ring[:, 1]) + 0.5  # on sample rows (centre)
    return np.clip(ring, [-8, y0 - 2], [w + 8, y1 + 2])


def check(rings, shape, **kw):
    exp = oracle_mask(rings, shape, **kw)
    assert np.array_equal(rastrum.polygon_mask(rings, shape, **kw), exp)
    rng = np.random.default_rng(shape[0] * 7919 + shape[1])
    pattern = rng.integers(0, 256, shape, dtype=np.uint8)
    pattern[pattern == 77] = 0
    canvas = rastrum.Canvas.wrap(pattern.copy())
    canvas.fill_polygon(rings, 77, **kw)
    assert np.array_equal(canvas.array, np.where(exp, np.uint8(77), pattern))


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(8), deadline=None)
@given(data=st.data())
def test_one_outline_matches_oracle(rule, o, data):
    h = data.draw(st.integers(8, 60))
    w = data.draw(st.integers(9, 75))
    y0 = data.draw(st.integers(0, h // 2))
    ring = star(data, h, w, y0, data.draw(st.integers(y0 + 2, h + 3)))
    check([ring], (h, w), rule=rule, sample_offset=o)


@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(8), deadline=None)
@given(data=st.data())
def test_two_outlines_apart_match_oracle(rule, o, data):
    h = data.draw(st.integers(24, 70))
    w = data.draw(st.integers(9, 75))
    top = star(data, h, w, 1, 8)
    bottom = star(data, h, w, h - 8, h - 1)
    check([top, bottom], (h, w), rule=rule, sample_offset=o)

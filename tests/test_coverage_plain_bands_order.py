""""area" in bands (csrc/src/coverage/coverage_area.c, rast__cov_bands) with
the edges in any order: the bands are made once, a band ending only
between two rows that no edge reaches both of, and the edges are put in
band order before each band's call (a permutation, when the rings do not
come band by band).  The pages of tests/test_coverage_plain_bands.py
(lines of "o"s, some lines not plain), their rings listed bottom line
first or shuffled, and lines close enough (pitch 6: a row or two of
plain between) that a plain stretch between two lines that are not is
shorter than RAST__BAND_GAP and goes with them.  Each is held to the
exact oracle (tests/oracle_coverage.py) under both rules, uint8 and
uint16, and painted (a painter's rows, gray8) as the array's levels
(issues 33, 34)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
import test_coverage_plain_bands as B
from test_coverage_fast import _check


def _run(rings, rule, shape):
    _check(rings, rule, shape=shape)
    levels = rastrum.polygon_coverage(rings, shape, rule=rule, dtype=np.uint8)
    canvas = rastrum.Canvas(shape, format="gray8")
    canvas.fill_polygon(rings, 255, rule=rule, aa="area")
    assert np.array_equal(np.asarray(canvas.array), levels)


@pytest.mark.parametrize("pitch, rule", [(9.0, "nonzero"), (6.0, "evenodd")])
def test_bottom_line_first(pitch, rule, monkeypatch):
    """Bad lines 1 and 3 of 4, the rings listed last line first."""
    monkeypatch.setattr(B, "PITCH", pitch)
    bad = [0, 1, 0, 1]
    rings = B.page(bad, False, 0.0, [0, 1, 1, 0])[::-1]
    _run(rings, rule, B.shape_of(bad))


def test_plain_line_between_close_bad_lines(monkeypatch, rule="nonzero"):
    """Pitch 6: the plain line between two bad ones, and the rows round
    it, fewer than RAST__BAND_GAP: one band with them; the plain lines
    after them a band of their own."""
    monkeypatch.setattr(B, "PITCH", 6.0)
    bad = [1, 0, 1, 0, 0]
    rings = B.page(bad, False, 0.5, [0] * len(bad))
    _run(rings, rule, B.shape_of(bad))


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.lists(st.booleans(), min_size=2, max_size=4), st.booleans(), st.floats(-4, 4),
       st.integers(0, 2 ** 32 - 1), st.sampled_from([9.0, 6.0]), st.sampled_from(["nonzero", "evenodd"]))
def test_shuffled_pages(bad, tall, dy, seed, pitch, rule):
    """Any lines bad or not, the tall ring or not, the page anywhere, the
    rings in a random order: the oracle decides."""
    old = B.PITCH
    B.PITCH = pitch
    try:
        rings = B.page(bad, tall, round(dy * 8) / 8, [bool(seed >> k & 1) for k in range(len(bad))])
        shape = B.shape_of(bad)
    finally:
        B.PITCH = old
    order = np.random.default_rng(seed).permutation(len(rings))
    _run([rings[k] for k in order], rule, shape)

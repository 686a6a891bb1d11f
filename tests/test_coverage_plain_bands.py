""""area" of a polygon that is plain in some parts only, in bands of rows
(csrc/src/coverage/coverage_area.c, rast__cov_area_marked): the rows whose
edges all belong to plain parts (rast__cov_plain_parts) go to the
accumulation a band at a time, the rows that a part which is not plain
reaches to "area"'s rows, each band with the edges that reach it.  The
scenes are pages: lines of "o"s (tests/test_coverage_plain_parts.py's),
some lines with two overlapping (not plain: winding 2), far enough apart
that the rows between go in bands of their own; a tall ring down the left
side, which reaches every band (its edges carried from band to band); the
page moved up and down so that the clip cuts a line.  Each is held to the
exact oracle (tests/oracle_coverage.py) under both rules, in uint8 and
uint16, and painted (a painter's rows, gray8) as the array's levels
(issue 33)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage_fast import _check
from test_coverage_plain_parts import _o, _ring

PITCH = 9.0  # a line's height: "o"s 4.4 px tall, 4.6 px of rows between lines


def page(bad, tall, dy, flip):
    """Lines k = 0.. of two "o"s (8 vertices a ring) at y = 3 + PITCH k + dy;
    where bad[k] a third overlapping the second, wound the same way; a
    tall thin ring at x = 0.5 to 1.3 down every line when tall; the rings
    of line k wound the other way when flip[k]."""
    rings = []
    for k, b in enumerate(bad):
        cy = 3 + PITCH * k + dy
        rings += _o(3.5, cy, flip[k], n=8) + _o(7, cy, flip[k], n=8, hole=not b)
        if b:
            rings += _o(7.9, cy, flip[k], n=8, hole=False)
    if tall:
        h = PITCH * len(bad) + 2
        rings.append(_ring(0.9, dy + h / 2 - 1, 0.4, h / 2, 12, 0.1, False))
    return rings


def shape_of(bad):
    return (int(PITCH * len(bad)) - 2, 10)


SCENES = {
    "one bad line in the middle": ([0, 1, 0], True, 0.0, [0, 1, 0]),
    "bad first and last, cut by the clip": ([1, 0, 1], True, -2.5, [0, 1, 1]),
}


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_bands(name, rule):
    bad, tall, dy, flip = SCENES[name]
    rings = page(bad, tall, dy, flip)
    shape = shape_of(bad)
    exact = _check(rings, rule, shape=shape)
    if rule == "nonzero":  # where a line is not plain the accumulation alone is wrong
        acc = rastrum.polygon_coverage(rings, shape, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"
    levels = rastrum.polygon_coverage(rings, shape, rule=rule, dtype=np.uint8)
    canvas = rastrum.Canvas(shape, format="gray8")
    canvas.fill_polygon(rings, 255, rule=rule, aa="area")
    assert np.array_equal(np.asarray(canvas.array), levels)


@settings(max_examples=S_.examples(4), deadline=None)
@given(st.lists(st.booleans(), min_size=2, max_size=4), st.booleans(), st.floats(-4, 4),
       st.integers(0, 63), st.sampled_from(["nonzero", "evenodd"]))
def test_pages(bad, tall, dy, flips, rule):
    """Any lines bad or not, the tall ring or not, the page anywhere from
    a line cut at the top to one cut at the bottom: the oracle decides."""
    flip = [bool(flips >> k & 1) for k in range(len(bad))]
    _check(page(bad, tall, round(dy * 8) / 8, flip), rule, shape=shape_of(bad))

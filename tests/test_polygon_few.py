"""The AET filler's few-vertex way (csrc/src/fillers/aet.c: a polygon of at
most 16 vertices is walked edge by edge, small.h, its runs handed to the
sink or written straight into a gray8 target's rows), against the exact
oracle (tests/oracle.py), bit for bit.

polygon_mask takes it through the opaque painter (test_polygon_exact.py's
scenes do too); here the other two ends of it: Canvas.fill_polygon on a
gray8 canvas (the painter's fast kind: the runs written into the rows,
nothing else touched) and on an RGB one (the runs through the sink), with
the boundary modes, on canvases taller than the scratch's bands (the walk
takes its rows in bands: a 16-vertex ring over ~900 rows), across the
16/17-vertex line (17 keeps the AET), and in the glue's way of taking a
small polygon's clip whole (rastpy_poly: no cut to the polygon's box when
the AET's scratch fits the stack) and cut (a taller canvas).
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from oracle_boundary import oracle_closed, oracle_conservative
from strategies import RULES, examples, rings

ORACLES = {"exact": oracle_mask, "closed": oracle_closed, "conservative": oracle_conservative}


def _background(shape):
    """A gray8 canvas with a pattern, so that a pixel written outside the
    runs (or one left out) shows."""
    h, w = shape
    return ((np.arange(h)[:, None] * 7 + np.arange(w)[None, :] * 3) % 200 + 1).astype(np.uint8)


def _check_canvas(rl, shape, rule, S, o, boundary="exact"):
    exp = ORACLES[boundary](rl, shape, rule=rule, subpixel_bits=S, sample_offset=o)
    kw = dict(rule=rule, subpixel_bits=S, sample_offset=o, boundary=boundary)
    gray = _background(shape)
    c = rastrum.Canvas.wrap(gray)
    c.fill_polygon(rl if len(rl) > 1 else rl[0], 255, **kw)
    want = np.where(exp, np.uint8(255), _background(shape))
    assert np.array_equal(gray, want), (rl, shape, kw, np.argwhere(gray != want)[:8].tolist())
    rgb = np.repeat(_background(shape)[:, :, None], 3, axis=2)
    c = rastrum.Canvas.wrap(rgb)
    c.fill_polygon(rl, (9, 250, 77), **kw)
    want3 = np.where(exp[:, :, None], np.array([9, 250, 77], np.uint8), np.repeat(_background(shape)[:, :, None], 3, 2))
    assert np.array_equal(rgb, want3), (rl, shape, kw)
    # and the mask (the opaque painter, through the sink)
    got = rastrum.polygon_mask(rl, shape, **kw)
    assert np.array_equal(got, exp), (rl, shape, kw)


@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(20))
@given(data=st.data())
def test_few_vertices_on_canvases(rule, data):
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    o = data.draw(st.sampled_from([0.5, 0.0]), label="offset")
    shape = data.draw(st.tuples(st.integers(1, 24), st.integers(1, 32)), label="shape")
    n = data.draw(st.integers(3, 17), label="vertices")
    rl = [np.asarray(data.draw(rings(S, o, shape, min_size=n, max_size=n)), np.float64)]
    if n <= 10 and data.draw(st.booleans(), label="a second ring"):
        rl.append(np.asarray(data.draw(rings(S, o, shape, min_size=3, max_size=16 - n)), np.float64))
    boundary = data.draw(st.sampled_from(["exact", "exact", "closed", "conservative"]), label="boundary")
    _check_canvas(rl, shape, rule, S, o, boundary)


@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(10))
@given(data=st.data())
def test_few_vertices_tall(rule, data):
    """Rows in bands: 12-17 vertices over up to 900 rows (the AET's scratch
    for them holds ~60 rows of slots), some past the canvas' top, bottom
    and sides."""
    h = data.draw(st.sampled_from([300, 900, 1400]), label="height")
    w = 24
    n = data.draw(st.integers(12, 17), label="vertices")
    ys = sorted(data.draw(st.lists(st.floats(-20, h + 20), min_size=n, max_size=n), label="ys"))
    xs = data.draw(st.lists(st.floats(-4, w + 4), min_size=n, max_size=n), label="xs")
    # down one side and up the other: long edges, and some crossing
    left = [(xs[k], ys[k]) for k in range(0, n, 2)]
    right = [(xs[k], ys[k]) for k in range(1, n, 2)][::-1]
    rl = [np.asarray(left + right, np.float64)]
    _check_canvas(rl, (h, w), rule, 8, 0.5)


@pytest.mark.parametrize("n", [3, 4, 8, 15, 16, 17, 18])
@pytest.mark.parametrize("rule", RULES)
def test_star_either_side_of_the_line(n, rule):
    """A star polygon of n vertices (self-crossing: winding 2 at its
    centre), on a canvas the glue fills whole and one it cuts."""
    for shape in [(60, 70), (2000, 70)]:
        k = 2 if n % 2 else 3
        t = 2 * np.pi * (np.arange(n) * k % n) / n
        ring = np.stack([35.3 + 30 * np.cos(t), 30.2 + 28.7 * np.sin(t)], 1)
        _check_canvas([ring], shape, rule, 8, 0.5)
        _check_canvas([ring[::-1] + 0.5], shape, rule, 4, 0.0)

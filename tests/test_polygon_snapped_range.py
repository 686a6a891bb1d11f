"""The binding's binary fills skip the core's range pass (issue 33).

python/glue/fill.c hands its snapped points to rast__fill_snapped, which
trusts them to lie in +-RAST_COORD_MAX (rastpy_snap refuses any other
first: the call then returns the bad point and Python takes the general
path, the 64-bit fill or its error).  These tests hold that contract from
outside, against the exact oracle: vertices at the range's edge and just
past it, in the one-ring call, the packed call of several rings and
Canvas.fill_polygon, give the exact pixels; and a NaN, infinite or
non-number point gives the same error whichever path first saw it.
"""

import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import COORD_MAX, examples

from hypothesis import settings

SHAPE = (9, 11)


def _far(S, where):
    """A coordinate (pixels) at the 32-bit range's edge at S (0), one grid
    step past it (1, the 64-bit path's) or half a step inside the edge,
    which snaps onto it (2)."""
    unit = 2.0 ** -S
    return {0: COORD_MAX * unit, 1: (COORD_MAX + 1) * unit, 2: (COORD_MAX - 0.5) * unit}[where]


@st.composite
def scenes(draw):
    S = draw(st.sampled_from((0, 4, 8, 12, 16)))
    rings = []
    for _ in range(draw(st.integers(1, 3))):
        n = draw(st.integers(3, 6))
        pts = [[draw(st.integers(-2, 26)) / 2.0, draw(st.integers(-2, 20)) / 2.0] for _ in range(n)]
        # one vertex far out, on one axis, either sign: its edges cross the mask
        k, axis = draw(st.integers(0, n - 1)), draw(st.integers(0, 1))
        pts[k][axis] = draw(st.sampled_from((1, -1))) * _far(S, draw(st.integers(0, 2)))
        rings.append(np.array(pts, dtype=np.float64))
    return S, rings, draw(st.sampled_from(("evenodd", "nonzero")))


@settings(max_examples=examples(40), deadline=None)
@given(scenes())
def test_far_vertices_exact(scene):
    S, rings, rule = scene
    want = oracle_mask(rings, SHAPE, rule=rule, subpixel_bits=S)
    # the one-ring call, the packed call of several rings, the general path (a list of lists)
    got = rastrum.polygon_mask(rings if len(rings) > 1 else rings[0], SHAPE, rule=rule, subpixel_bits=S)
    np.testing.assert_array_equal(got, want)
    general = rastrum.polygon_mask([r.tolist() for r in rings], SHAPE, rule=rule, subpixel_bits=S)
    np.testing.assert_array_equal(general, want)
    canvas = rastrum.Canvas.wrap(np.full(SHAPE, 7, np.uint8))
    canvas.fill_polygon(rings, 200, rule=rule, subpixel_bits=S)
    np.testing.assert_array_equal(canvas.array, np.where(want, 200, 7).astype(np.uint8))


BAD = {"nan": float("nan"), "inf": float("inf"), "-inf": float("-inf")}


@pytest.mark.parametrize("bad", sorted(BAD))
@pytest.mark.parametrize("nrings", (1, 3))
def test_bad_point_same_error(bad, nrings):
    """The quick paths' refusal ends in the general path's error, word for word."""
    rings = [np.array([[1.0, 1.0], [6.0, 1.5], [4.0, 7.0], [2.0, 5.0]]) + i for i in range(nrings)]
    rings[-1][2, 1] = BAD[bad]
    quick = rings if nrings > 1 else rings[0]
    with pytest.raises(rastrum.InputError) as fast:
        rastrum.polygon_mask(quick, SHAPE)
    with pytest.raises(rastrum.InputError) as slow:
        rastrum.polygon_mask([r.tolist() for r in rings], SHAPE)
    assert str(fast.value) == str(slow.value)
    assert "point 2" in str(fast.value)
    canvas = rastrum.Canvas.wrap(np.full(SHAPE, 7, np.uint8))
    with pytest.raises(rastrum.InputError) as fill:
        canvas.fill_polygon(quick, 200)
    assert str(fill.value) == str(slow.value)
    assert (canvas.array == 7).all()

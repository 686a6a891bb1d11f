""""area" drawn by a painter (Canvas.fill_polygon(..., aa="area")): the
engine works only on the columns the polygon's edges reach
(coverage_area.c, rast__cov_narrow), not the canvas's whole width: left
and right of every edge the winding number is 0, so those pixels are 0
and no painter is handed them.  One small polygon a call on a wide canvas
(the cv2.fillPoly loop), polygons cut by the canvas's left or right side,
vertices on pixel corners (the last column an edge reaches is a column
boundary), horizontal spikes that reach past the other edges, and rings
that touch themselves.  Drawn in gray8 with colour 255 on black, each
pixel is its coverage level ((255 c + 127) // 255 = c): equal bit for bit
to polygon_coverage of the same ring (the whole width, no painter) and
within the bound of rastrum.h of the exact oracle
(tests/oracle_coverage.py)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import _n_m, check_area, exact_area

H, W = 8, 40


def _ring(rnd, corner, spike):
    """A small ring (3-7 vertices) anywhere on the canvas or partly off its
    left or right side; on pixel corners when `corner`; with a horizontal
    spike (out and back along one ordinate) when `spike`."""
    n = int(rnd.integers(3, 8))
    cx = rnd.uniform(-3, W + 3)
    cy = rnd.uniform(1, H - 1)
    r = rnd.uniform(0.3, 4.0)
    t = np.sort(rnd.uniform(0, 2 * np.pi, n))
    ring = np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], 1)
    if corner:
        ring = np.round(ring)
    if spike:
        k = int(rnd.integers(0, n))
        x, y = ring[k]
        reach = rnd.uniform(1, 8) * (1 if rnd.integers(0, 2) else -1)
        ring = np.concatenate([ring[:k + 1], [[x + reach, y], [x, y]], ring[k + 1:]])
    if rnd.integers(0, 2):
        ring = ring[::-1]
    return np.ascontiguousarray(ring)


@settings(max_examples=S_.examples(25), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.booleans(), st.booleans(),
       st.sampled_from(["evenodd", "nonzero"]))
def test_small_polygon_a_call_equals_array_and_oracle(seed, corner, spike, rule):
    rnd = np.random.default_rng(seed)
    ring = _ring(rnd, corner, spike)
    canvas = rastrum.Canvas((H, W), format="gray8")
    canvas.fill_polygon([ring], 255, rule=rule, aa="area")
    got = canvas.array
    whole = rastrum.polygon_coverage([ring], (H, W), rule=rule, dtype=np.uint8)
    what = repr((seed, corner, spike, rule, ring.tolist()))
    assert np.array_equal(got, whole), what
    n, m = _n_m([ring], 8)
    check_area(got, exact_area([ring], (H, W), rule, 8), 255, n, m, what)


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1))
def test_loop_of_polygons_on_one_canvas_equals_oracle(seed):
    # several calls on one canvas, each over what the others painted: the
    # pixels outside each call's columns keep what was there
    rnd = np.random.default_rng(seed)
    rings = [_ring(rnd, bool(rnd.integers(0, 2)), bool(rnd.integers(0, 2))) for _ in range(3)]
    canvas = rastrum.Canvas((H, W), format="gray8")
    want = np.zeros((H, W), np.int64)
    for ring in rings:
        canvas.fill_polygon([ring], 255, rule="nonzero", aa="area")
        c = rastrum.polygon_coverage([ring], (H, W), rule="nonzero", dtype=np.uint8).astype(np.int64)
        want = (255 * c + want * (255 - c) + 127) // 255
        n, m = _n_m([ring], 8)
        check_area(c, exact_area([ring], (H, W), "nonzero", 8), 255, n, m, repr((seed, ring.tolist())))
    assert np.array_equal(canvas.array, want.astype(np.uint8)), repr(seed)

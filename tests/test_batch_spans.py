"""The batch's span writers (python/glue/batch.c) for runs of every short
length, against the exact oracle.

A replace of four or more elements ends with one group of four that
overlaps the group before it; fewer than four are written one by one.  So
runs of 1..9 elements, starting at every column modulo 4, over a
background that must stay as it was on both sides, in every element type
(the bytes go through memset, the rest through those groups), and next to
runs of other polygons (later ones on top).
"""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from oracle import oracle_mask
from rastrum import _batch, _core
from strategies import examples

H, W = 3, 16
DTYPES = [np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32, np.int64, np.uint64,
          np.float32, np.float64]


def _rect(x0, x1, y0, y1):
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], float)


def _expected(polys, values, dtype, fill):
    out = np.full((H, W), fill, dtype)
    for rings, v in zip(polys, values):
        out[oracle_mask(rings, (H, W), rule="nonzero")] = v
    return out


@pytest.mark.parametrize("dtype", DTYPES)
def test_every_short_run_at_every_offset(dtype):
    opts = _core.fill_opts("aet", "nonzero", 8, 0.5)
    for x0 in range(4):
        for n in range(1, 10):
            polys = [[_rect(x0, x0 + n, 1, 2)]]
            out = np.full((H, W), 9, dtype)
            _batch.burn(out, polys, opts, values=np.array([3], dtype))
            want = _expected(polys, [3], dtype, 9)
            assert want[1].tolist().count(3) == n  # the oracle's run: n pixels
            np.testing.assert_array_equal(out, want, err_msg="run of %d at column %d" % (n, x0))


@settings(max_examples=examples(60))
@given(st.lists(st.tuples(st.integers(-2, W + 2), st.integers(0, 11), st.integers(-1, H),
                          st.integers(1, H + 1)), min_size=1, max_size=6),
       st.sampled_from(DTYPES))
def test_runs_side_by_side_later_on_top(boxes, dtype):
    """Rectangles of 0..11 columns (also past both edges, the runs clipped)
    and polygons drawn in order: each run's last group of four must not
    write past its end onto a neighbour's run or the background."""
    polys = [[_rect(x, x + w, y, y + h)] for x, w, y, h in boxes]
    values = np.arange(1, len(polys) + 1).astype(dtype)
    out = np.full((H, W), 100, dtype)
    _batch.burn(out, polys, _core.fill_opts("aet", "evenodd", 8, 0.5), values=values)
    np.testing.assert_array_equal(out, _expected(polys, values, dtype, 100))

"""Snapping to the 1/2^S grid is exact: floor(v * 2^S + 1/2) in rationals.

Regression: t + 0.5 in double rounds up for t = 1/2 - 2^-54, which snapped
0.49999999999999994 to 1 at S = 0 (found by the oracle comparison).
"""

import math
import re
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rastrum


def exact_snap(v, s):
    return math.floor(Fraction(v) * 2**s + Fraction(1, 2))


def snapped_column(x, s):
    """The column rastrum's snap puts x in: fill a tall thin triangle whose
    left edge is vertical at x and read the first set pixel of row 0
    (sample at the pixel's left corner, o = 0)."""
    h, w = 2, 64
    m = rastrum.polygon_mask([(x, -10.0), (70.0, -10.0), (x, 10.0)], (h, w), subpixel_bits=s, sample_offset=0)
    cols = np.flatnonzero(m[0])
    return cols[0] if len(cols) else w


def expected_column(x, s):
    # The edge sits at the snapped abscissa X = k / 2^s; the first corner
    # sample at or right of it is ceil(X).
    return max(0, math.ceil(Fraction(exact_snap(x, s), 2**s)))


BOUNDARY = [
    0.49999999999999994,  # 1/2 - 2^-54
    0.5,
    0.5000000000000001,
    1.4999999999999998,
    2.5,
    20.499999999999996,
]


@pytest.mark.parametrize("s", range(0, 9))
@pytest.mark.parametrize("x", BOUNDARY)
def test_half_way_values(x, s):
    x = x / 2**s  # the same tie on the 1/2^s grid (exact: a power of two)
    assert snapped_column(x, s) == expected_column(x, s)


@settings(max_examples=300, deadline=None)
@given(
    st.integers(0, 8),
    st.floats(0, 40, allow_nan=False, allow_infinity=False),
)
def test_random_values(s, x):
    assert snapped_column(x, s) == expected_column(x, s)


# --- the glue's vector snapping (AVX, then SSE2, then scalar) -------------------
# rastpy_snap takes the coordinates 4 at a time (AVX), then 2 (SSE2), then
# one by one, and on a bad coordinate hands the whole batch to the scalar
# loop to name the first bad point.  Batches of every length from 1 to 9
# points put each coordinate in each of those paths.

from rastrum import _core  # noqa: E402

LIM = 2**27 - 1  # RAST_COORD_MAX


def in_range_floats(s):
    lim = (LIM + 0.5) / 2**s
    return st.one_of(
        st.floats(-lim, lim, allow_nan=False, allow_infinity=False, exclude_max=True),
        st.sampled_from([0.49999999999999994, -0.5, 0.5, -0.49999999999999994, 2.5, -2.5,
                         1.4999999999999998, -1.5000000000000002]).map(lambda v: v / 2**s),
        st.integers(-LIM - 1, LIM - 1).map(lambda k: (k + 0.5) / 2**s),  # ties
    )


@settings(max_examples=200, deadline=None)
@given(st.data())
def test_vector_snap_matches_exact(data):
    s = data.draw(st.integers(0, 16), label="s")
    n = data.draw(st.integers(1, 9), label="points")
    xy = data.draw(st.lists(in_range_floats(s), min_size=2 * n, max_size=2 * n), label="xy")
    got = _core.snap_points(np.array(xy).reshape(n, 2), s)
    assert got.ravel().tolist() == [exact_snap(v, s) for v in xy]


@pytest.mark.parametrize("n", range(1, 10))
def test_vector_snap_names_the_first_bad_point(n):
    s = 8
    for bad in (float("nan"), float("inf"), -float("inf"), (LIM + 0.5) / 2**s,
                -(LIM + 0.5) / 2**s - 2.0**-30):
        for k in range(2 * n):
            xy = np.arange(2 * n, dtype=np.float64).reshape(n, 2)
            xy.flat[k] = bad
            with pytest.raises(rastrum.InputError, match=re.escape(str(tuple(xy[k // 2].tolist())))):
                _core.snap_points(xy, s)
    # just inside the range on both sides: no error, the exact values
    xy = np.array([[(LIM + 0.5) / 2**s - 2.0**-20, -(LIM + 0.5) / 2**s]] * n)
    assert _core.snap_points(xy, s).tolist() == [[LIM, -LIM]] * n

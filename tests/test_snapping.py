"""Snapping to the 1/2^S grid is exact: floor(v * 2^S + 1/2) in rationals.

Regression: t + 0.5 in double rounds up for t = 1/2 - 2^-54, which snapped
0.49999999999999994 to 1 at S = 0 (found by the oracle comparison).
"""

import math
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

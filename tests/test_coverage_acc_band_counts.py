""""accumulate"'s band walk counts each row's parts for its window
(csrc/src/coverage/coverage_acc.c, rast__acc_band_edges): an edge kept
from the bands above in one sum, one that starts in the band from its
first row on, each less from the row after its last.  A row counted short
gets a window too narrow for its quick sums' error (rast__acc_win).

tests/test_coverage_acc_window.py's band scenes (row 12, edges from row 0)
hold only edges kept from the bands above at the pixel's row.  Here every
edge starts in row 12, the first row the edges reach, so that the band
of rows 12 to 15 is the walk's first and the edges are all new in it:
their parts in row 13 are counted from their first row.  The scenes are
built the same way (the same helpers): two steep edges, each 21 rows
long (the band walk), through pixel (13, 2) from its top to its bottom,
both of their abscissae there floored by at least 0.97 of 2^-30 px, in
n1 and n2 copies (400 in all, the errors adding), the exact value just
below a level boundary by less than the quick sums' error.  The new
edges left uncounted (their `cnt[...]++` dropped) fails them all: the
quick value's level, one too high.  Against the exact oracle."""


import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import strategies as S_
from test_coverage_acc_window import _check, _near_boundary

J, H = 13, 36

# dtype: [(edge A, n1, edge B, n2)], an edge (X0, Y0, X1, Y1) in 1/256 px
# from its top vertex (row 12) to its bottom one (row 33)
CASES = {
    np.uint8: [((604, 3313, 706, 8478), 206, (642, 3312, 669, 8695), 194),
               ((664, 3256, 523, 8655), 165, (683, 3298, 511, 8529), 235),
               ((611, 3199, 651, 8484), 84, (732, 3240, 614, 8570), 316)],
    np.uint16: [((604, 3313, 706, 8478), 5, (664, 3256, 523, 8655), 395),
                ((604, 3313, 706, 8478), 26, (664, 3256, 523, 8655), 374),
                ((604, 3313, 706, 8478), 394, (664, 3256, 523, 8655), 6)],
}


@pytest.mark.parametrize("dtype", list(CASES), ids=lambda d: np.dtype(d).name)
def test_new_edges_counted_in_their_first_band(dtype):
    for case in CASES[dtype]:
        # each edge new in the band, and long
        _near_boundary(case, J, dtype, H, lambda e: 12 * 256 <= e[1] < 13 * 256 and e[3] - e[1] >= 20 * 256)


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.sampled_from(list(CASES)), st.integers(0, 2), st.integers(0, 30), st.integers(0, 3))
def test_new_edges_shifted_by_whole_pixels(dtype, which, dx, dy):
    """The same scenes moved by whole pixels: the band still starts at the
    edges' first row (the first the edges reach), the pixel in another
    column of its 16 or the next 16."""
    _check(J, dtype, H, CASES[dtype][which], dx, dy)

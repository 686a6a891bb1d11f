""""accumulate"'s exact rows on the walk's compact edge records
(csrc/src/coverage/coverage_acc.c, rast__acc_exact): a row whose levels
the quick sums cannot decide is swept the exact way on rast__cedge
records rebuilt from the walk's; when the row holds more than three in
four of the call's edges (a small shape inside one or two pixel rows),
every record is rebuilt in place and the walk's made again from them
after the row, with the steppers as they were, for the rows below.
Triangles on a 1/6 pixel grid (exact ties such as a pixel half covered,
slanted edges crossing verticals at rounded ordinates) inside one or two
rows, one or two, alone or above a ring that goes on below, and the same
among many others (the exact row's edges a few of the call's), against
the exact oracle (test_coverage._accumulated): every level floor(a' M +
1/2), a' the rule applied to the pixel's integral of the winding number,
with check_area's allowance at a tie."""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import _accumulated, check_area

SHAPE = (6, 12)


def _ring(rnd, x0, y0, rows):
    """A triangle (simple: the oracle's sum of rings), vertices on the 1/6
    grid in a box 4 px wide, `rows` tall, either orientation."""
    xs = rnd.integers(0, 4 * 6 + 1, 3) / 6 + x0
    ys = rnd.integers(0, rows * 6 + 1, 3) / 6 + y0
    return [(float(x), float(y)) for x, y in zip(xs, ys)]


def _check(rings, rule, dtype):
    M = 255 if dtype == np.uint8 else 65535
    out = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=dtype)
    want = _accumulated(rings, SHAPE, rule, 8)
    n = sum(len(r) for r in rings)
    check_area(out, want, M, n, n * (n - 1) // 2, repr(rings))


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 2]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]), st.booleans())
def test_a_small_shape_whose_row_holds_most_edges(seed, rows, rule, dtype, below):
    rnd = np.random.default_rng(seed)
    rings = [_ring(rnd, 1, 1, rows) for _ in range(int(rnd.integers(1, 3)))]
    if below:  # (a ring from the same rows on down: its steppers cross the exact row)
        rings.append([(6.0, 1.0), (9.5, 1 + 1 / 3), (7.0, 5.0)])
    _check(rings, rule, dtype)


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]))
def test_small_shapes_among_many_edges(seed, rule):
    rnd = np.random.default_rng(seed)
    rings = [_ring(rnd, 1 + 5 * (k % 2), (k // 2) % 5, 1) for k in range(12)]
    _check(rings, rule, np.uint8)


def _tie_triangle(x, y, mirror_x, mirror_y, reverse):
    """A triangle in row y whose slanted edge crosses two verticals at
    thirds of a pixel (rounded) and leaves the middle pixel of its three
    half covered (a tie), mirrored and turned as asked."""
    tri = [(0.0, 0.0), (3.0, 1.0), (0.0, 1.0)]
    tri = [(3.0 - a if mirror_x else a, 1.0 - b if mirror_y else b) for a, b in tri]
    tri = [(a + x, b + y) for a, b in tri]
    return tri[::-1] if reverse else tri


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.integers(0, 4), st.integers(0, 3), st.booleans(), st.booleans(), st.booleans(),
       st.sampled_from([0, 1, 2]), st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([np.uint8, np.uint16]))
def test_a_tie_in_a_row_of_most_edges(x, y, mirror_x, mirror_y, reverse, others, rule, dtype):
    """The tie goes to the exact sweep with every edge of the call in its
    row (others 0), or with a ring from that row on down (1: its steppers
    rebuilt and made again across the row), or among many other edges in
    other rows (2: the row's edges rebuilt in the free room)."""
    rings = [_tie_triangle(x, y, mirror_x, mirror_y, reverse)]
    if others == 1:
        rings.append([(6.0 + x, float(y)), (9.5 + x, y + 1 / 3), (7.0 + x, 5.0)])
    elif others == 2:
        rings += [[(0.5 + c, r + 0.25), (1.5 + c, r + 0.5), (0.75 + c, r + 0.9)]
                  for r in range(SHAPE[0]) if r != y for c in range(0, 12, 2)]
    _check(rings, rule, dtype)


def test_a_half_covered_pixel_under_a_slanted_edge():
    """Row 1: the triangle covers pixels 2, 3, 4 by 5/6, 1/2 (a tie), 1/6;
    its slanted edge crosses x = 3 and 4 at thirds of a pixel (rounded),
    so the tie goes to the exact sweep, with both of the call's edges."""
    tri = _tie_triangle(2, 1, False, False, False)
    for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
        out = rastrum.polygon_coverage([tri], SHAPE, method="accumulate", dtype=dtype)
        want = _accumulated([tri], SHAPE, "nonzero", 8)
        check_area(out, want, M, 3, 3, "triangle")
        assert [int(v) for v in out[1, 2:5]] == [(5 * M + 3) // 6, (M + 1) // 2, (M + 3) // 6]

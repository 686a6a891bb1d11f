"""Hand-computed checks of the reference oracle (no rastrum involved).

Every expected mask here was worked out by hand from the rule of docs/semantics.md
(crossings written as exact fractions in the comments), or follows from a
closed-form description that is independent of the oracle's algorithm.
"""

from fractions import Fraction
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle
from oracle import oracle_mask, oracle_mask_naive, oracle_winding, snap


def rows_to_mask(rows, shape):
    """{row: iterable of columns} -> bool mask."""
    m = np.zeros(shape, dtype=bool)
    for j, cols in rows.items():
        for i in cols:
            m[j, i] = True
    return m


def assert_mask(got, expected):
    if not np.array_equal(got, expected):
        diff = np.argwhere(got != expected)
        raise AssertionError(
            f"masks differ at (row, col) {diff.tolist()}\n"
            f"got:\n{got.astype(int)}\nexpected:\n{expected.astype(int)}")


# --- textbook figure 3-19 -------------------------------------------------

FIG_3_19 = [(7, 8), (3, 12), (1, 7), (3, 1), (6, 5), (8, 1), (12, 9)]

# Samples on integer coordinates (o = 0).  Edges and their y ranges:
#   E0 P0(7,8)->P1(3,12) [8,12) down   E1 P1->P2(1,7) [7,12) up
#   E2 P2->P3(3,1) [1,7) up            E3 P3->P4(6,5) [1,5) down
#   E4 P4->P5(8,1) [1,5) up            E5 P5->P6(12,9) [1,9) down
#   E6 P6->P0 [8,9) up
FIG_3_19_ROWS = {
    # y=1: crossings 3 (E2), 3 (E3), 8 (E4), 8 (E5): both spans empty
    1: [],
    # y=2: 8/3, 15/4, 15/2, 17/2  -> [8/3,15/4) = {3}, [7.5,8.5) = {8}
    2: [3, 8],
    # y=3: 7/3, 9/2, 7, 9 (the textbook rounds 7/3 to 2 and adds pixel 2)
    3: [3, 4, 7, 8],
    # y=4: 2, 21/4, 13/2, 19/2
    4: [2, 3, 4, 5, 7, 8, 9],
    # y=5: E3/E4 end at y=5 (bottom open): 5/3, 10
    5: list(range(2, 10)),
    # y=6: 4/3, 21/2
    6: list(range(2, 11)),
    # y=7: E1 starts (1), E2 ends; E5: 11
    7: list(range(1, 11)),
    # y=8: E1 7/5, E0 7 and E6 7 (local minimum P0, both count), E5 23/2
    8: list(range(2, 12)),
    # y=9: E1 9/5, E0 6 (E5 and E6 end at 9)
    9: [2, 3, 4, 5],
    # y=10: 11/5, 5
    10: [3, 4],
    # y=11: 13/5, 4
    11: [3],
    # y=12: everything ends
    12: [],
}


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
@pytest.mark.parametrize("S", [0, 3, 8, None])
def test_figure_3_19(rule, S):
    shape = (14, 14)
    got = oracle_mask(FIG_3_19, shape, rule=rule, subpixel_bits=S,
                      sample_offset=0)
    assert_mask(got, rows_to_mask(FIG_3_19_ROWS, shape))
    # also reversed orientation and all start vertices
    for k in range(len(FIG_3_19)):
        ring = FIG_3_19[k:] + FIG_3_19[:k]
        assert_mask(oracle_mask(ring[::-1], shape, rule=rule,
                                subpixel_bits=S, sample_offset=0),
                    rows_to_mask(FIG_3_19_ROWS, shape))


def test_figure_3_19_row3_crossings():
    # the row the brief quotes: crossings at 2+1/3, 4.5, 7, 9
    wind = oracle_winding(FIG_3_19, (14, 14), subpixel_bits=0,
                          sample_offset=0)
    # E2 is upward (-1), E3 downward (+1), E4 up (-1), E5 down (+1)
    assert wind[3].tolist() == [0, 0, 0, -1, -1, 0, 0, -1, -1, 0, 0, 0, 0, 0]


# --- textbook example 3-1: triangle P0(1,1) P1(5,3) P2(4,7), o = 0 -------

def test_example_3_1_triangle():
    tri = [(1, 1), (5, 3), (4, 7)]
    rows = {
        1: [],          # 1, 1: apex, empty span (book: pixel 1)
        2: [2],         # [3/2, 3)         (book: 2..3)
        3: [2, 3, 4],   # [2, 5)           (book: 2..5)
        4: [3, 4],      # [5/2, 19/4)      (book: 3..5)
        5: [3, 4],      # [3, 9/2)         (book: 3..5)
        6: [4],         # [7/2, 17/4)      (book: 4)
        7: [],          # bottom open
    }
    for S in (0, 8, None):
        got = oracle_mask(tri, (9, 8), subpixel_bits=S, sample_offset=0)
        assert_mask(got, rows_to_mask(rows, (9, 8)))


# --- simple shapes ------------------------------------------------------

def test_unit_square_both_offsets():
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    exp = np.zeros((3, 3), bool)
    exp[0, 0] = True
    for o in (0.5, 0):
        for S in (0, 8, None):
            assert_mask(oracle_mask(sq, (3, 3), subpixel_bits=S,
                                    sample_offset=o), exp)


def test_square_half_pixel_corners():
    # [0.5, 2.5]^2: o = 1/2 samples 0.5, 1.5 inside, 2.5 excluded (open)
    sq = [(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5)]
    exp = np.zeros((4, 4), bool)
    exp[0:2, 0:2] = True
    assert_mask(oracle_mask(sq, (4, 4), subpixel_bits=1), exp)
    # o = 0: samples 1, 2
    exp0 = np.zeros((4, 4), bool)
    exp0[1:3, 1:3] = True
    assert_mask(oracle_mask(sq, (4, 4), subpixel_bits=1, sample_offset=0),
                exp0)
    # S = 0 snaps 0.5 -> 1 and 2.5 -> 3: samples 1.5, 2.5 (o = 1/2)
    exp1 = np.zeros((4, 4), bool)
    exp1[1:3, 1:3] = True
    assert_mask(oracle_mask(sq, (4, 4), subpixel_bits=0), exp1)


def test_right_triangle():
    tri = [(0, 0), (4, 0), (0, 4)]
    ii, jj = np.meshgrid(np.arange(6), np.arange(6))
    # o = 1/2: inside iff (i + 1/2) + (j + 1/2) < 4 (hypotenuse open right)
    assert_mask(oracle_mask(tri, (6, 6)), (ii + jj <= 2))
    # o = 0: 0 <= j < 4 (top closed, bottom open), 0 <= i < 4 - j
    assert_mask(oracle_mask(tri, (6, 6), sample_offset=0),
                (ii + jj < 4) & (jj < 4))


def test_triangle_vertex_on_sample_right_open():
    # right-pointing tip exactly on sample (3.5, 1.5): the crossings there
    # are X = 3.5 twice -> span [3.5, 3.5) is empty
    tri = [(0.5, 0.5), (3.5, 1.5), (0.5, 2.5)]
    got = oracle_mask(tri, (4, 5))
    exp = np.zeros((4, 5), bool)
    # row yc=0.5: edge 1 (0.5,0.5)->(3.5,1.5) X=0.5, edge 3 X=0.5 -> empty
    # row yc=1.5: edge 2 X=3.5 (top closed), edge 3 X=0.5 -> [0.5, 3.5)
    exp[1, 0:3] = True
    # row yc=2.5: bottom open -> nothing
    assert_mask(got, exp)


OUTER_CW = [(1, 1), (9, 1), (9, 9), (1, 9)]      # clockwise on screen
INNER_CW = [(3, 3), (7, 3), (7, 7), (3, 7)]
INNER_CCW = INNER_CW[::-1]


@pytest.mark.parametrize("flip_outer", [False, True])
def test_ring_with_hole(flip_outer):
    outer = OUTER_CW[::-1] if flip_outer else OUTER_CW
    shape = (11, 11)
    full = np.zeros(shape, bool)
    full[1:9, 1:9] = True               # samples 1.5 .. 8.5
    holed = full.copy()
    holed[3:7, 3:7] = False             # samples 3.5 .. 6.5
    same = INNER_CCW if flip_outer else INNER_CW
    opposite = INNER_CW if flip_outer else INNER_CCW
    for hole in (same, opposite):
        assert_mask(oracle_mask([outer, hole], shape, rule="evenodd"), holed)
    assert_mask(oracle_mask([outer, opposite], shape, rule="nonzero"), holed)
    assert_mask(oracle_mask([outer, same], shape, rule="nonzero"), full)
    # ring order does not matter
    assert_mask(oracle_mask([same, outer], shape, rule="nonzero"), full)
    # screen-clockwise outer: its left edge goes up (direction -1) -> -1
    w = oracle_winding([outer, same], shape)
    assert set(np.unique(w[3:7, 3:7])) == {-2 if not flip_outer else 2}
    assert set(np.unique(w[1:9, 1:3])) == {-1 if not flip_outer else 1}


def test_doubled_ring_winding_two():
    sq = [(1, 1), (4, 1), (4, 4), (1, 4)]
    twice = sq + sq
    shape = (6, 6)
    assert not oracle_mask(twice, shape, rule="evenodd").any()
    exp = np.zeros(shape, bool)
    exp[1:4, 1:4] = True
    assert_mask(oracle_mask(twice, shape, rule="nonzero"), exp)


def test_pentagram():
    c = 20.5                            # centre on sample (20.5, 20.5)
    pts = [(c + 15 * math.sin(2 * math.pi * k * 2 / 5),
            c - 15 * math.cos(2 * math.pi * k * 2 / 5)) for k in range(5)]
    eo = oracle_mask(pts, (41, 41), rule="evenodd")
    nz = oracle_mask(pts, (41, 41), rule="nonzero")
    assert not eo[20, 20] and nz[20, 20]
    assert abs(oracle_winding(pts, (41, 41))[20, 20]) == 2
    # the top tip region (around y = 9) has winding 1 under both rules
    assert eo[9, 20] and nz[9, 20]
    assert (eo <= nz).all()


def test_empty_and_degenerate():
    assert not oracle_mask([], (5, 7)).any()
    assert oracle_mask([], (5, 7)).shape == (5, 7)
    assert oracle_mask([(0, 0), (5, 0), (0, 5)], (0, 4)).shape == (0, 4)
    assert oracle_mask([(0, 0), (5, 0), (0, 5)], (3, 0)).shape == (3, 0)
    # collinear ring
    assert not oracle_mask([(0, 0), (2, 2), (4, 4), (1, 1)], (6, 6),
                           rule="nonzero").any()
    # all points equal
    assert not oracle_mask([(1.5, 1.5)] * 5, (4, 4)).any()
    # horizontal-only ring
    assert not oracle_mask([(0, 1.5), (3, 1.5), (5, 1.5)], (4, 6)).any()
    # sliver thinner than the grid collapses after snapping
    sliver = [(0.5, 0.0), (0.5 + 2 ** -10, 0.0), (0.5 + 2 ** -10, 4.0),
              (0.5, 4.0)]
    assert not oracle_mask(sliver, (4, 2), subpixel_bits=8).any()
    # ... but not without snapping: it contains sample x = 0.5
    exp = np.zeros((4, 2), bool)
    exp[:, 0] = True
    assert_mask(oracle_mask(sliver, (4, 2), subpixel_bits=None), exp)


def test_huge_triangle_covers_target():
    tri = [(-1e6, -1e6), (3e6, -1e6), (-1e6, 3e6)]
    assert oracle_mask(tri, (7, 9)).all()
    assert oracle_mask(tri, (7, 9), subpixel_bits=16).all()
    # entirely outside
    assert not oracle_mask([(-1e6, -5), (1e6, -5), (0, -1)], (7, 9)).any()


def test_snap_round_half_up():
    assert snap(0.5, 0) == 1
    assert snap(1.5, 0) == 2
    assert snap(2.5, 0) == 3
    assert snap(-0.5, 0) == 0
    assert snap(-1.5, 0) == -1
    assert snap(-0.5000000001, 0) == -1
    assert snap(0.4999999999, 0) == 0
    assert snap(0.1, 8) == 26           # 25.6 -> 26
    assert snap(1 / 3, 1) == 1          # 0.666 -> 1
    assert snap(-1 / 3, 1) == -1        # -0.666 -> -1
    # exact: 0.1 as a float is slightly above 1/10; 0.1*5 = 0.5 + tiny
    assert snap(0.1, 0) == 0
    assert snap(2 ** -9, 8) == 1        # 0.5 exactly -> 1
    assert snap(-(2 ** -9), 8) == 0     # -0.5 exactly -> 0
    assert snap(np.float64(2.5), 0) == 3
    with pytest.raises(ValueError):
        snap(float("nan"), 8)
    with pytest.raises(ValueError):
        snap(float("inf"), 8)


def test_snapping_moves_edge_over_sample():
    # right edge at 1.5 + 2**-12: S=8 snaps to 1.5 -> sample 1.5 excluded
    sq = [(0, 0), (1.5 + 2 ** -12, 0), (1.5 + 2 ** -12, 1), (0, 1)]
    assert oracle_mask(sq, (1, 3), subpixel_bits=8).tolist() == \
        [[True, False, False]]
    assert oracle_mask(sq, (1, 3), subpixel_bits=12).tolist() == \
        [[True, True, False]]
    assert oracle_mask(sq, (1, 3), subpixel_bits=None).tolist() == \
        [[True, True, False]]
    # the tie 1.5 - 2**-9 snaps up at S=8 to 1.5 exactly (excluded)
    sq2 = [(0, 0), (1.5 - 2 ** -9, 0), (1.5 - 2 ** -9, 1), (0, 1)]
    assert oracle_mask(sq2, (1, 3), subpixel_bits=8).tolist() == \
        [[True, False, False]]
    sq3 = [(0, 0), (1.5 - 2 ** -9 - 2 ** -30, 0), (1.5 - 2 ** -9 - 2 ** -30, 1),
           (0, 1)]
    assert oracle_mask(sq3, (1, 3), subpixel_bits=8).tolist() == \
        [[True, False, False]]       # snaps down to 1.5 - 2**-8: excluded
    # left edge at 0.5 + 2**-9 (a tie) snaps up past sample 0.5; a hair
    # below the tie it snaps down onto 0.5 (left closed: included)
    sq4 = [(0.5 + 2 ** -9, 0), (3, 0), (3, 1), (0.5 + 2 ** -9, 1)]
    assert oracle_mask(sq4, (1, 3), subpixel_bits=8).tolist() == \
        [[False, True, True]]
    sq5 = [(0.5 + 2 ** -9 - 2 ** -40, 0), (3, 0), (3, 1),
           (0.5 + 2 ** -9 - 2 ** -40, 1)]
    assert oracle_mask(sq5, (1, 3), subpixel_bits=8).tolist() == \
        [[True, True, True]]


def test_input_forms():
    sq = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float64)
    a = oracle_mask(sq, (3, 3))
    assert_mask(oracle_mask([sq], (3, 3)), a)
    assert_mask(oracle_mask(sq.tolist(), (3, 3)), a)
    assert_mask(oracle_mask([sq.tolist()], (3, 3)), a)
    assert_mask(oracle_mask(sq[None], (3, 3)), a)
    assert_mask(oracle_mask(sq.astype(np.float32), (3, 3)), a)
    with pytest.raises(ValueError):
        oracle_mask(sq, (3, 3), rule="bogus")
    with pytest.raises(ValueError):
        oracle_mask(sq, (3, 3), sample_offset=0.25)


# --- closed forms and cross-checks (property based) ----------------------

coord = st.floats(-6, 16, allow_nan=False, allow_infinity=False)
snap_bits = st.one_of(st.none(), st.integers(0, 10))
offsets = st.sampled_from([0.5, 0.0])


def examples(base):
    # scaled by the active hypothesis profile (see conftest.py)
    return max(1, round(base * settings.default.max_examples / 100))


def _exact(v, S):
    if S is None:
        return Fraction(v)
    return Fraction(snap(v, S), 1 << S)


@settings(max_examples=examples(300), deadline=None)
@given(x0=coord, x1=coord, y0=coord, y1=coord, S=snap_bits, o=offsets,
       rule=st.sampled_from(["evenodd", "nonzero"]))
def test_axis_aligned_rectangle_closed_form(x0, x1, y0, y1, S, o, rule):
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    H, W = 11, 12
    ax0, ax1 = sorted((_exact(x0, S), _exact(x1, S)))
    ay0, ay1 = sorted((_exact(y0, S), _exact(y1, S)))
    oo = Fraction(o)
    cols = np.array([ax0 <= i + oo < ax1 for i in range(W)])
    rows = np.array([ay0 <= j + oo < ay1 for j in range(H)])
    exp = rows[:, None] & cols[None, :]
    assert_mask(oracle_mask(ring, (H, W), rule=rule, subpixel_bits=S,
                            sample_offset=o), exp)


ring_st = st.lists(st.tuples(coord, coord), min_size=3, max_size=9)


@settings(max_examples=examples(300), deadline=None)
@given(rings=st.lists(ring_st, min_size=1, max_size=3), S=snap_bits,
       o=offsets, rule=st.sampled_from(["evenodd", "nonzero"]))
def test_fast_equals_naive(rings, S, o, rule):
    shape = (9, 10)
    a = oracle_mask(rings, shape, rule=rule, subpixel_bits=S, sample_offset=o)
    b = oracle_mask_naive(rings, shape, rule=rule, subpixel_bits=S,
                          sample_offset=o)
    assert_mask(a, b)


grid_coord = st.integers(-12, 36).map(lambda k: k / 4)


@settings(max_examples=examples(200), deadline=None)
@given(rings=st.lists(st.lists(st.tuples(grid_coord, grid_coord),
                               min_size=3, max_size=8),
                      min_size=1, max_size=3),
       o=offsets, rule=st.sampled_from(["evenodd", "nonzero"]))
def test_fast_equals_naive_on_sample_grid(rings, o, rule):
    # vertices on quarter pixels: many vertices and edges exactly on samples
    shape = (8, 8)
    for S in (0, 1, 2):
        a = oracle_mask(rings, shape, rule=rule, subpixel_bits=S,
                        sample_offset=o)
        b = oracle_mask_naive(rings, shape, rule=rule, subpixel_bits=S,
                              sample_offset=o)
        assert_mask(a, b)


@settings(max_examples=examples(150), deadline=None)
@given(rings=st.lists(ring_st, min_size=1, max_size=3), S=snap_bits,
       o=offsets)
def test_int64_path_equals_bigint_path(rings, S, o):
    shape = (9, 10)
    a = oracle_winding(rings, shape, subpixel_bits=S, sample_offset=o)
    saved = oracle._INT64_SAFE
    oracle._INT64_SAFE = 0          # force the pure-Python integer path
    try:
        b = oracle_winding(rings, shape, subpixel_bits=S, sample_offset=o)
    finally:
        oracle._INT64_SAFE = saved
    assert np.array_equal(a, b)


def test_large_coordinates_bigint_path():
    # coordinates far beyond int64-safe magnitudes, no snapping
    big = 2.0 ** 70
    tri = [(-big, -big), (big, 0.25), (-big, big)]
    m = oracle_mask(tri, (6, 6), subpixel_bits=None)
    n = oracle_mask_naive(tri, (6, 6), subpixel_bits=None)
    assert_mask(m, n)
    assert m.all()
    tiny = [(0.5, 0.5), (0.5 + 2.0 ** -45, 0.5), (0.5, 3.5)]
    assert_mask(oracle_mask(tiny, (4, 2), subpixel_bits=None),
                oracle_mask_naive(tiny, (4, 2), subpixel_bits=None))
    assert oracle_mask(tiny, (4, 2), subpixel_bits=None)[:3, 0].all()


def test_big_scene_speed():
    # the benchmark's reference scene size: must stay quick
    import time
    rng = np.random.default_rng(1)
    rings = [rng.uniform(-50, 2100, size=(100, 2)) for _ in range(4)]
    t = time.perf_counter()
    m = oracle_mask(rings, (2048, 2048), rule="nonzero")
    assert m.shape == (2048, 2048)
    assert time.perf_counter() - t < 20

"""The non-default modes against their oracles, for every polygon algorithm:
textbook rounding (tests/oracle.py, rounding="textbook") and the closed and
conservative boundaries (tests/oracle_boundary.py)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from oracle_boundary import ORACLES, segment_meets_open_square
from strategies import RULES, assert_same, examples, lit, scenes

ALGOS = rastrum.ALGORITHMS["polygon_mask"]
OFFSETS = [0.5, 0.0]
FIG_3_19 = [(7, 8), (3, 12), (1, 7), (3, 1), (6, 5), (8, 1), (12, 9)]


def algorithms(rule):
    return [a for a, rules in ALGOS.items() if rule in rules]


def expected(rl, shape, rule, S, o, rounding, boundary):
    if boundary == "exact":
        return oracle_mask(rl, shape, rule=rule, subpixel_bits=S, sample_offset=o, rounding=rounding)
    return ORACLES[boundary](rl, shape, rule=rule, subpixel_bits=S, sample_offset=o, rounding=rounding)


@pytest.mark.parametrize("boundary", ["exact", "closed", "conservative"])
@pytest.mark.parametrize("rounding", ["exact", "textbook"])
@settings(max_examples=examples(60), deadline=None)
@given(data=st.data())
def test_modes_match_their_oracles(rounding, boundary, data):
    if rounding == "exact" and boundary == "exact":
        return  # test_polygon_exact.py covers it
    S = data.draw(st.integers(0, 8), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rule = data.draw(st.sampled_from(RULES), label="rule")
    rl, shape = data.draw(scenes(S, o, max_h=24, max_w=24), label="scene")
    exp = expected(rl, shape, rule, S, o, rounding, boundary)
    for alg in algorithms(rule):
        got = rastrum.polygon_mask(rl, shape, rule=rule, algorithm=alg, subpixel_bits=S,
                                   sample_offset=o, rounding=rounding, boundary=boundary)
        assert_same(got, exp, f"{alg} {rule} S={S} o={o} rounding={rounding} "
                              f"boundary={boundary}: polygon_mask({lit(rl)}, {shape})")


@pytest.mark.parametrize("boundary", ["closed", "conservative"])
def test_canvas_paints_the_same_pixels(boundary):
    ring = [(1.3, 0.7), (17.6, 4.2), (9.1, 13.9), (2.2, 9.5)]
    c = rastrum.Canvas((16, 20), "gray8")
    c.fill_polygon(ring, 7, boundary=boundary)
    assert_same(c.array == 7, rastrum.polygon_mask(ring, (16, 20), boundary=boundary), boundary)


def test_boundaries_contain_the_fill_and_closed_contains_the_outline():
    rng = np.random.default_rng(5)
    for _ in range(50):
        ring = rng.uniform(-3, 23, (int(rng.integers(3, 9)), 2))
        for o in OFFSETS:
            fill = rastrum.polygon_mask(ring, (20, 20), sample_offset=o)
            closed = rastrum.polygon_mask(ring, (20, 20), sample_offset=o, boundary="closed")
            cons = rastrum.polygon_mask(ring, (20, 20), sample_offset=o, boundary="conservative")
            assert (closed >= fill).all() and (cons >= fill).all()


def test_axis_aligned_rectangle():
    """On pixel borders the conservative fill adds nothing; with samples on
    the corners the closed fill is the (w+1) x (h+1) rectangle OpenCV fills."""
    sq = [(2, 1), (9, 1), (9, 6), (2, 6)]
    exact = rastrum.polygon_mask(sq, (10, 12))
    assert exact.sum() == 35
    assert_same(rastrum.polygon_mask(sq, (10, 12), boundary="conservative"), exact, "conservative")
    closed = rastrum.polygon_mask(sq, (10, 12), sample_offset=0, boundary="closed")
    exp = np.zeros((10, 12), bool)
    exp[1:7, 2:10] = True
    assert_same(closed, exp, "closed, corners")


def test_zero_area_spike_touches_its_pixels():
    """A ring walked there and back encloses nothing, but its edges cross
    pixels: conservative adds them (the closure), exact adds none."""
    spike = [(1.5, 1.5), (6.5, 3.5), (1.5, 1.5)]
    assert not rastrum.polygon_mask(spike, (6, 8)).any()
    cons = rastrum.polygon_mask(spike, (6, 8), boundary="conservative")
    exp = np.zeros((6, 8), bool)
    for j in range(6):
        for i in range(8):
            from fractions import Fraction as F
            exp[j, i] = segment_meets_open_square((F(3, 2), F(3, 2)), (F(13, 2), F(7, 2)), i, j)
    assert exp.sum() > 0
    assert_same(cons, exp, "spike")


# --- textbook rounding: the seed's worked examples ----------------------------

def test_textbook_figure_3_19_row_3():
    """Seed 001, 3.4.2: on scan line y = 3 the crossings (2.3, 4.5, 7, 9) round
    to (2, 5, 7, 9); left closed, right open fills [2, 4] and [7, 8]: 5 px."""
    for alg in algorithms("evenodd"):
        m = rastrum.polygon_mask(FIG_3_19, (14, 14), sample_offset=0, subpixel_bits=0,
                                 rounding="textbook", algorithm=alg)
        assert np.flatnonzero(m[3]).tolist() == [2, 3, 4, 7, 8], alg
        exact = rastrum.polygon_mask(FIG_3_19, (14, 14), sample_offset=0, subpixel_bits=0,
                                     algorithm=alg)
        # the exact rule starts at the first sample right of 2.33: column 3
        assert np.flatnonzero(exact[3]).tolist() == [3, 4, 7, 8], alg


def test_textbook_is_watertight():
    """Rounding depends on the edge and the row only: two triangles on either
    side of a shared edge never both own a pixel, and together own exactly
    the pixels of their union (a simple quadrilateral)."""
    rng = np.random.default_rng(3)

    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    checked = 0
    for _ in range(300):
        p = [tuple(v) for v in rng.integers(-8, 88, (4, 2)) / 4]
        if side(p[0], p[2], p[1]) * side(p[0], p[2], p[3]) >= 0:
            continue  # p1 and p3 must lie on opposite sides of p0-p2
        for o in OFFSETS:
            kw = dict(sample_offset=o, rounding="textbook", subpixel_bits=2)
            a = rastrum.polygon_mask([p[0], p[1], p[2]], (20, 20), **kw)
            b = rastrum.polygon_mask([p[0], p[2], p[3]], (20, 20), **kw)
            u = rastrum.polygon_mask(p, (20, 20), **kw)
            assert not (a & b).any(), p
            assert_same(a | b, u, f"union of {p}")
            checked += 1
    assert checked > 100


@pytest.mark.parametrize("bad", [("rounding", "nearest"), ("boundary", "touched"),
                                 ("rounding", None), ("boundary", 1)])
def test_unknown_mode_names(bad):
    with pytest.raises(ValueError, match=bad[0]):
        rastrum.polygon_mask([(0, 0), (4, 0), (0, 4)], (4, 4), **{bad[0]: bad[1]})

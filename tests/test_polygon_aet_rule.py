"""The AET filler's own ways (csrc/src/fillers/aet.c), against the exact
oracle (tests/oracle.py), bit for bit.

Meshes given as rings: the "aet" polygon fill of two rings or more of at
most 8 vertices on average first sums equal edges (an edge a->b of one
cell and b->a of the next cancel) and fills from what is left when at most
half of the edges are (rast__segs_cancel in csrc/src/base/edge.c).  The
meshes here meet that rule (checked below from the same counts), so every
example takes the cancelling: jittered grids of quads or triangles (either
diagonal), cells turned the other way (holes), cells given twice (winding
2 under non-zero, 0 under even-odd), vertices on sample points and sample
rows, meshes past the canvas' sides, both rules, both sample offsets, both
roundings.

Many vertices for the rows: the winding deltas are added as the edges are
set up (rast__aet_delta_now); test_polygon_delta.py's scenes take that way
now, and a ring wound round more times than the byte counters hold (past
510 crossings a row, non-zero) is filled by the sweep instead.
tests/c/test_aet_rule.c compares both ways with the AET's sweep of every
edge directly.
"""

from fractions import Fraction

import pytest
from hypothesis import given, settings, strategies as st, assume

from strategies import RULES, examples
from test_polygon_exact import check_equal


def edges_left(rings, rule, S):
    """The crossing edges the cancelling keeps (the rule's count): equal
    segments (snapped at S bits) summed, those of winding part 0 (even-odd:
    of even count) gone."""
    q = 1 << S
    count = {}
    for ring in rings:
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            a = (round(Fraction(y0) * q), round(Fraction(x0) * q))
            b = (round(Fraction(y1) * q), round(Fraction(x1) * q))
            if a[0] == b[0]:
                continue
            key, d = ((a, b), 1) if a < b else ((b, a), -1)
            count[key] = count.get(key, 0) + d
    if rule == "evenodd":
        return sum(n % 2 for n in count.values())
    return sum(abs(n) for n in count.values())


@st.composite
def meshes(draw, S):
    step = 1 / (1 << min(S, 2))  # on sample points and rows, and between them
    nx, ny = draw(st.integers(1, 6), label="nx"), draw(st.integers(1, 6), label="ny")
    cw, ch = draw(st.integers(1, 5), label="cell w"), draw(st.integers(1, 4), label="cell h")
    x0, y0 = draw(st.integers(-4, 4), label="x0") * step * 2, draw(st.integers(-3, 3), label="y0") * step * 2
    on_rows = draw(st.booleans(), label="jitter along rows only")
    grid = {}
    for r in range(ny + 1):
        for c in range(nx + 1):
            x, y = x0 + c * cw, y0 + r * ch
            if 0 < r < ny and 0 < c < nx:
                x += draw(st.integers(-1, 1)) * step
                if not on_rows:
                    y += draw(st.integers(-1, 1)) * step
            grid[r, c] = (x, y)
    rings = []
    for r in range(ny):
        for c in range(nx):
            a, b, d, e = grid[r, c], grid[r, c + 1], grid[r + 1, c + 1], grid[r + 1, c]
            kind = draw(st.sampled_from(["quad", "ad", "be"]))
            cell = {"quad": [[a, b, d, e]], "ad": [[a, b, d], [a, d, e]],
                    "be": [[a, b, e], [b, d, e]]}[kind]
            if draw(st.integers(0, 7)) == 0:  # turned the other way: a hole
                cell = [ring[::-1] for ring in cell]
            rings += cell
            if draw(st.integers(0, 9)) == 0:  # given twice, the same way
                rings += cell
    return rings


@pytest.mark.parametrize("o", [0.5, 0.0])
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(15), deadline=None)
@given(data=st.data())
def test_mesh_rings_match_oracle(rule, o, data):
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    rings = data.draw(meshes(S), label="rings")
    npoints = sum(len(r) for r in rings)
    # the rule's counts: two rings or more, 8 vertices a ring at most on
    # average, at most half of the edges left
    assume(len(rings) >= 2 and npoints <= 8 * len(rings))
    assume(2 * edges_left(rings, rule, S) <= npoints)
    shape = (data.draw(st.integers(1, 24), label="h"), data.draw(st.integers(1, 28), label="w"))
    rounding = data.draw(st.sampled_from(["exact", "textbook"]), label="rounding")
    check_equal(rings, shape, algorithms=["aet"], rule=rule, subpixel_bits=S,
                sample_offset=o, rounding=rounding)


@pytest.mark.parametrize("rule", RULES)
def test_mesh_of_triangles_cancels_to_its_outline(rule):
    """A 6 x 4 grid of triangle pairs with a vertex on every sample point
    of the grid: every inner edge cancels, the outline is what is filled,
    and a cell given twice and one turned round change what they should."""
    grid = {(r, c): (c * 3 + 0.5, r * 2 + 0.5) for r in range(5) for c in range(7)}
    rings = []
    for r in range(4):
        for c in range(6):
            a, b, d, e = grid[r, c], grid[r, c + 1], grid[r + 1, c + 1], grid[r + 1, c]
            rings += [[a, b, d], [a, d, e]]
    rings += [rings[0]]  # cell 0's first triangle twice: winding 2 (even-odd: out)
    rings[5] = rings[5][::-1]  # a triangle turned round: winding 0 there (even-odd: in)
    assert 2 * edges_left(rings, rule, 8) <= sum(len(r) for r in rings)
    check_equal(rings, (10, 20), algorithms=["aet"], rule=rule)


@pytest.mark.parametrize("turns", [200, 256])
def test_ring_wound_past_the_counters(turns):
    """A triangle walked round `turns` times (winding `turns` inside, 2 x
    turns crossings a row): 200 is read from the byte counters; 256 would
    wrap them to 0 (512 crossings a row), and the sweep fills."""
    tri = [(2.25, 0.5), (37.5, 3.25), (5.0, 5.75)]
    ring = tri * turns
    check_equal([ring], (6, 40), algorithms=["aet"], rule="nonzero")
    check_equal([tri[::-1] * turns], (6, 40), algorithms=["aet"], rule="nonzero")

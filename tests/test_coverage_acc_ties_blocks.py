""""accumulate"'s second pass over a row with a level near a tie decides
again only the blocks of 16 columns where a level was not certain
(csrc/src/coverage/coverage_acc.c, rast__acc_ties_z: a uint8 row of 64
parts or more, read by its 32-bit sums).  Every other part is put whole at
its first column, so the sums right of it must still be exact: a bar on
half pixels far right of a crowd of small slanted triangles (and of long
thin ones whose sides cross many blocks) has pixels on exact ties, which
only exact parts touch, and their levels must be floor(a M + 1/2) exactly,
with no allowance (128 of 255 where half covered).  The rest of the row is
checked against the exact oracle as tests/test_coverage.py does."""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import check_area, exact_area, rule_applied

SHAPE = (8, 320)
RIGHT = 112  # the bars' columns start here; nothing else reaches them


def _signed(ring):
    a2 = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))
    a = exact_area([ring], SHAPE, "nonzero", 8)
    return a if a2 > 0 else -a


BOX = [(4.0, 0.0), (316.0, 0.0), (316.0, 8.0), (4.0, 8.0)]


def _scene(seed, copies, long_sides):
    """A box over the rows from column 4 to 316 (its left side left of
    everything else: what it adds to the sums right of it must be there),
    two bars on half pixels right of column RIGHT (holes in the box: ties
    under either rule; one reaching past its right side), small slanted
    triangles left of column 100 (each `copies` times over: 64 parts a row
    or more), and long_sides thin triangles from column 0 to 110."""
    rnd = np.random.default_rng(seed)
    h, w = SHAPE
    bars = []
    for k in range(2):
        x0 = int(rnd.integers(RIGHT + 1, w - 40)) + 0.5
        x1 = w - 1.5 if k else x0 + int(rnd.integers(2, 30))
        y0 = int(rnd.integers(0, h - 3)) + 0.5
        y1 = y0 + int(rnd.integers(1, 3))
        bars.append([(x0, y0), (x0, y1), (x1, y1), (x1, y0)])  # (against the box)
    tris = []
    for _ in range(3):
        c = rnd.uniform([0.5, 0.5], [96.0, h - 3.5])
        pts = np.round((c + rnd.uniform(0, 3, (3, 2))) * 256) / 256
        t = [(float(x), float(y)) for x, y in pts]
        if sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(t, t[1:] + t[:1])) != 0:
            tris.append(t)
    longs = []
    for _ in range(long_sides):
        y = float(rnd.uniform(0.3, h - 1.3))
        longs.append([(0.25, y), (110.0, y + float(rnd.uniform(-0.6, 0.6))), (0.25, y + 0.75)])
    return bars, tris, longs


@settings(max_examples=S_.examples(12), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([24, 40]), st.integers(0, 2),
       st.sampled_from(["evenodd", "nonzero"]))
def test_ties_right_of_a_crowd_are_exact(seed, copies, long_sides, rule):
    bars, tris, longs = _scene(seed, copies, long_sides)
    total = _signed(BOX)
    for r in bars + longs:
        total = total + _signed(r)
    for t in tris:
        total = total + _signed(t) * copies
    want = rule_applied(total, rule)
    rings = [BOX] + bars + longs + [t for t in tris for _ in range(copies)]
    out = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.uint8)
    # the bars' side: only exact parts, every level as the definition has it
    strict = [[int(v) for v in r[RIGHT:]] for r in out]
    assert strict == [[oc.level(a, 255) for a in r[RIGHT:]] for r in want], "seed %d" % seed
    assert any(a == F(1, 2) for a in want[:, RIGHT:].flat)  # (ties there)
    n = sum(len(r) for r in rings)
    check_area(out, want, 255, n, n * (n - 1) // 2, "seed %d" % seed)


def test_a_tie_in_the_last_block_and_a_side_across_blocks():
    """Row 3: a bar's pixels half covered up to the last column touched,
    70 copies of a slanted triangle at the left, and a thin triangle whose
    long sides cross the blocks between them: the bar's levels 128, the
    fill right of it 0, the rest as the oracle has it."""
    bar = [(200.5, 3.5), (309.5, 3.5), (309.5, 5.0), (200.5, 5.0)]
    tri = [(10.125, 2.25), (12.875, 3.75), (11.0, 4.625)]
    thin = [(0.5, 3.2), (150.0, 3.9), (0.5, 3.6)]
    total = _signed(bar) + _signed(tri) * 70 + _signed(thin)
    for rule in ("evenodd", "nonzero"):
        want = rule_applied(total, rule)
        out = rastrum.polygon_coverage([bar, thin] + [tri] * 70, SHAPE, rule=rule, method="accumulate",
                                       dtype=np.uint8)
        assert [int(v) for v in out[3, 201:309]] == [128] * 108
        assert [int(v) for v in out[3, 310:]] == [0] * 10
        assert [[int(v) for v in r] for r in out[:, 160:]] == [[oc.level(a, 255) for a in r] for r in want[:, 160:]]
        n = 4 + 3 + 3 * 70
        check_area(out, want, 255, n, n * (n - 1) // 2, rule)

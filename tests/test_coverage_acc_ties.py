""""accumulate" on rows where a pixel sits on an exact tie among slanted
edges (csrc/src/coverage/coverage_acc.c, rast__acc_ties): a bar on half
pixels leaves the pixels under its long sides exactly half covered (127.5
of 255, 32767.5 of 65535), which no window around the quick sums can
decide, while short slanted triangles in the same rows keep the row from
being one of vertical edges only.  Such a row's parts are put again with
the pixels that only exact parts touch marked exact, and those levels
taken as they are; the rest of the row is decided as before, or goes to
the exact sweep.  Against the definition from the exact oracle: every
pixel's level is floor(a' M + 1/2), a' the rule applied to the integral
of the winding number over the pixel (each ring's signed area from the
oracle, summed), with check_area's allowance at a tie where the exact
sweep decides it (a tie at 7/30 is one too: 7/30 of 255 is 59.5), and
none at the bar's half-covered pixels beside a triangle, which only
exact parts touch."""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import check_area, exact_area, rule_applied


def _area2(ring):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))


def _signed(ring, shape):
    """The integral of ring's winding number over each pixel (exact)."""
    a = exact_area([ring], shape, "nonzero", 8)
    return a if _area2(ring) > 0 else -a


def _scene(seed, ntri, copies, snap, shape):
    """Two bars on half pixels (either orientation) and ntri short
    triangles (vertices on a 1/snap grid, each `copies` times over, so
    that a row holds 64 parts or more when copies is large)."""
    rnd = np.random.default_rng(seed)
    h, w = shape
    rings = []
    for _ in range(2):
        x0 = int(rnd.integers(0, w - 9)) + 0.5
        y0 = int(rnd.integers(0, h - 3)) + 0.5
        x1, y1 = x0 + int(rnd.integers(2, 8)), y0 + int(rnd.integers(1, 3))
        bar = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        rings.append(bar if rnd.integers(2) else bar[::-1])
    tris = []
    for _ in range(ntri):
        c = rnd.uniform([0.5, 0.5], [w - 3.5, h - 3.5])
        pts = np.round((c + rnd.uniform(0, 3, (3, 2))) * snap) / snap
        t = [(float(x), float(y)) for x, y in pts]
        if _area2(t) != 0:
            tris.append(t)
    return rings, tris


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([(1, 1), (4, 1), (2, 40)]),
       st.sampled_from([2, 256]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]), st.sampled_from([(10, 40), (10, 200)]))
def test_ties_among_slanted_edges_are_exact(seed, counts, snap, rule, dtype, shape):
    ntri, copies = counts
    bars, tris = _scene(seed, ntri, copies, snap, shape)
    total = sum((_signed(r, shape) for r in bars), np.zeros(shape, object) + F(0))
    for t in tris:
        total = total + _signed(t, shape) * copies
    want = rule_applied(total, rule)
    M = 255 if dtype == np.uint8 else 65535
    rings = bars + [t for t in tris for _ in range(copies)]
    out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
    n = sum(len(r) for r in rings)
    check_area(out, want, M, n, n * (n - 1) // 2, "seed %d, %s" % (seed, counts))


def test_a_bar_on_half_pixels_beside_a_slanted_triangle():
    """Row 2: the bar's pixels (3..8, 2) half covered, on ties, and a
    slanted triangle's parts in the same row; a level on each side of a
    tie, with no allowance (uint8 128, uint16 32768), the rest as the
    oracle has it."""
    shape = (6, 30)
    bar = [(3.5, 2.5), (9.5, 2.5), (9.5, 4.5), (3.5, 4.5)]
    tri = [(15.25, 1.125), (19.75, 2.875), (16.5, 4.0)]
    for rule in ("evenodd", "nonzero"):
        total = _signed(bar, shape) + _signed(tri, shape)
        want = rule_applied(total, rule)
        assert all(want[2, i] == F(1, 2) for i in range(4, 9))
        for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
            out = rastrum.polygon_coverage([bar, tri], shape, rule=rule, method="accumulate", dtype=dtype)
            assert [int(v) for v in out[2, 4:9]] == [(M + 1) // 2] * 5
            assert [[int(v) for v in r] for r in out] == [[oc.level(a, M) for a in r] for r in want]


@settings(max_examples=S_.examples(20), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([(1, 1), (4, 1), (2, 40)]), st.sampled_from([2, 256]),
       st.sampled_from(["evenodd", "nonzero"]))
def test_ties_as_the_exact_sweep_decides_them(seed, counts, snap, rule):
    """The same scene beside 256 copies of a tall box (512 parts in every
    row: a uint16 row of that many goes to the exact sweep whole), which
    moves no pixel left of it: the scene's pixels come out as the exact
    sweep has them, ties too (where the oracle's check allows a level
    either way, a tie whose pixel an inexact part touches must still go
    the sweep's way)."""
    ntri, copies = counts
    shape = (10, 40)
    bars, tris = _scene(seed, ntri, copies, snap, shape)
    rings = bars + [t for t in tris for _ in range(copies)]
    out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=np.uint16)
    box = [(44.5, 0.0), (50.0, 0.0), (50.0, 10.0), (44.5, 10.0)]
    ref = rastrum.polygon_coverage(rings + [box] * 256, (10, 52), rule=rule, method="accumulate",
                                   dtype=np.uint16)
    assert np.array_equal(out, ref[:, :40]), "seed %d, %s: %s" % (seed, counts, np.argwhere(out != ref[:, :40])[:5])

""""accumulate"'s ties' pass over a uint8 row of 64 parts or more
(csrc/src/coverage/coverage_acc.c, rast__acc_ties_z) reads the first
pass's cells again, kept, and looks only at the parts whose edges reach
the span from the first flagged block of 16 columns to the last: the
others are passed by their edges' ends.  So: ties at BOTH ends of the row
(a bar on half pixels at the left, in the first blocks, and one at the
right), the crowd of small slanted triangles between them (inside the
span, touching no flagged block), and long thin triangles whose sides
cross the left bar's columns in other rows than the bar's (their edges
reach the span, their parts in the bar's rows may not), or cross the bar
itself.  The bars' pixels that only exact parts touch must have the
definition's levels exactly (128 where half covered); the rest is checked
against the exact oracle as tests/test_coverage.py does."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_coverage import check_area, exact_area, rule_applied

SHAPE = (8, 256)


def _signed(ring):
    a2 = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]))
    a = exact_area([ring], SHAPE, "nonzero", 8)
    return a if a2 > 0 else -a


def _scene(seed, copies, longs):
    rnd = np.random.default_rng(seed)
    h, w = SHAPE
    y0 = int(rnd.integers(0, h - 3)) + 0.5
    y1 = y0 + int(rnd.integers(1, 3))
    xl = float(rnd.integers(4, 20)) + 0.5
    left = [(1.5, y0), (1.5, y1), (xl, y1), (xl, y0)]
    x0 = float(rnd.integers(200, 230)) + 0.5
    right = [(x0, y1), (x0, y0), (w - 1.5, y0), (w - 1.5, y1)]  # (either orientation: ties under both rules)
    tris = []
    for _ in range(3):
        c = rnd.uniform([40.5, 0.5], [180.0, h - 3.5])
        pts = np.round((c + rnd.uniform(0, 3, (3, 2))) * 256) / 256
        t = [(float(x), float(y)) for x, y in pts]
        if sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(t, t[1:] + t[:1])) != 0:
            tris.append(t)
    thin = []
    for _ in range(longs):  # from the left bar's columns to the crowd's, slanted, 1-4 rows tall
        ya = float(rnd.uniform(0.2, h - 4.5))
        thin.append([(float(rnd.uniform(0.0, 24.0)), ya), (float(rnd.uniform(60.0, 190.0)), ya + float(rnd.uniform(0.5, 4.0))),
                     (float(rnd.uniform(0.0, 24.0)), ya + 0.5)])
    return left, right, tris, thin


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([24, 40]), st.integers(0, 3),
       st.sampled_from(["evenodd", "nonzero"]))
def test_ties_at_both_ends_of_a_crowded_row(seed, copies, longs, rule):
    left, right, tris, thin = _scene(seed, copies, longs)
    rings = [left, right] + thin + [t for t in tris for _ in range(copies)]
    total = _signed(left) + _signed(right)
    for r in thin:
        total = total + _signed(r)
    for t in tris:
        total = total + _signed(t) * copies
    want = rule_applied(total, rule)
    out = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.uint8)
    # the bars' pixels on exact ties, where no slanted part reaches: the definition's level
    exact = want * 2 == 1
    touched = np.zeros(SHAPE, bool)
    for r in thin:  # (the columns and rows of the thin triangles, and the next ones: the parts' reach)
        xs, ys = [p[0] for p in r], [p[1] for p in r]
        touched[max(int(min(ys)), 0):int(max(ys)) + 1, max(int(min(xs)) - 1, 0):int(max(xs)) + 2] = True
    for i, j in zip(*np.nonzero(exact & ~touched)):
        assert int(out[i, j]) == oc.level(want[i, j], 255) == 128, "seed %d at %d,%d" % (seed, i, j)
    assert (exact & ~touched).any() or longs  # (ties checked, unless the thin ones cover them)
    n = sum(len(r) for r in rings)
    check_area(out, want, 255, n, n * (n - 1) // 2, "seed %d" % seed)

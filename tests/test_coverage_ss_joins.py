"""Supersampling ("ssK", polygon_coverage) of polygons whose fine rows
each take in many new edges at once: the binary rule on the k-times finer
grid, counted per pixel (docs/coverage.md), bit for bit as
tests/oracle_coverage.py's coverage_ss gives it.  The walk sorts a fine
row's new edges by a key an edge when there are 17 to 64 of them
(csrc/src/base/aet.h, rast__aet_join_keys), by the records otherwise: so
combs of 5 to 40 teeth (two edges a tooth starting on one row), in any
order across the row, teeth sharing columns (edges of equal column), on
and off the sample rows, under both rules, with teeth crossing each other
and reaching past the canvas (clipped runs)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _comb(seed, h, w, teeth, q, cross):
    """One ring: a bar along the top and `teeth` teeth hanging from the row
    y0, their columns drawn on a grid of 1/q pixel (q small: many equal
    columns), visited in a shuffled order (the edge table's order)."""
    rnd = np.random.default_rng(seed)
    y0 = rnd.choice([rnd.uniform(0.2, 1.5), 0.625, 0.5])  # on a sample row, or not
    xs = np.round(rnd.uniform(-1, w + 1, (teeth, 2)) * q) / q
    xs.sort(axis=1)
    xs[:, 1] += 1.0 / q
    bottoms = rnd.uniform(y0 + 0.3, h + 1, teeth)
    ring = [(-1.5, -0.5), (w + 1.5, -0.5), (w + 1.5, y0)]
    order = rnd.permutation(teeth)
    for t in order:
        a, b = xs[t]
        lean = rnd.uniform(-cross, cross)
        ring += [(b, y0), (b + lean, bottoms[t]), (a + lean, bottoms[t]), (a, y0)]
    ring.append((-1.5, y0))
    return [[[float(x), float(y)] for x, y in ring]]


@settings(max_examples=S_.examples(14), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 9), st.integers(3, 12), st.integers(5, 40),
       st.sampled_from([1, 2, 4, 16]), st.sampled_from([0.0, 0.0, 3.0]),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([2, 4, 8]))
def test_combs_equal_oracle(seed, h, w, teeth, q, cross, rule, k):
    rings = _comb(seed, h, w, teeth, q, cross)
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(rings, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, rings))

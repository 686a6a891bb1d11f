"""Supersampling ("ssK", polygon_coverage) of tangled polygons: the binary
rule on the k-times finer grid, counted per pixel (docs/coverage.md), bit
for bit as tests/oracle_coverage.py's coverage_ss gives it.  The walk
keeps a fine row's active edges in a list (csrc/src/coverage/coverage_ss.c,
rast__ss_list_walk): edges join it, end and are unlinked, and change
places (the list put back in order, edges moving back past one or many)
on the same rows.  So: random rings of short and long edges that cross
each other everywhere, several rings, vertices on the sample rows and
columns, some past the canvas (runs clipped), under both rules."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _tangle(seed, h, w, nrings, n, q):
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(nrings):
        if rnd.random() < 0.5:  # a random walk: short edges, crossing back
            p = np.cumsum(rnd.normal(0, 1.2, (n, 2)), 0) + rnd.uniform(0, [w, h])
        else:  # points anywhere: long edges crossing many others
            p = rnd.uniform(-1.5, [w + 1.5, h + 1.5], (n, 2))
        p = np.where(rnd.random(p.shape) < 0.3, np.round(p * q) / q, p)
        rings.append(p.tolist())
    return rings


@settings(max_examples=S_.examples(14), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 12), st.integers(3, 12), st.integers(1, 3),
       st.integers(3, 40), st.sampled_from([2, 4, 8]), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([2, 4, 8]))
def test_tangles_equal_oracle(seed, h, w, nrings, n, q, rule, k):
    rings = _tangle(seed, h, w, nrings, n, q)
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(rings, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, rings))

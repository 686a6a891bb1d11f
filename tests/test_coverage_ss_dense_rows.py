"""Supersampling ("ssK") into uint8 on the AET's walk, a row with many
runs' ends (one a column in 8 or more: rast__ss_flush_dense,
coverage_ss.c): the counts summed along the row, in builds with SSE2 16
columns a step (rast__ss_dense16: the levels worked out, for k = 4 from
the counts as bytes), the rest a column at a time.  Stars of long spikes
(few edges a fine row: not the deltas' walk) on canvases 16 to 70
pixels wide, so that a row has words of 64 columns summed in steps of 16
and a tail; both rules, k = 2 .. 16; the levels must be
tests/oracle_coverage.py's coverage_ss bit for bit (docs/coverage.md:
the binary rule on the k times finer grid)."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _star(rnd, h, w, n):
    """A star of n spikes about the canvas's middle, its tips past the
    edges at times, its inner vertices near the centre (a self-crossing
    ring under even-odd when the spikes are skewed)."""
    cx, cy = rnd.uniform(0.3, 0.7) * w, rnd.uniform(0.3, 0.7) * h
    t = np.sort(rnd.uniform(0, 2 * np.pi, 2 * n))
    r = np.where(np.arange(2 * n) % 2 == 0, rnd.uniform(0.5, 0.8, 2 * n) * max(h, w),
                 rnd.uniform(0.0, 0.2, 2 * n) * min(h, w))
    skew = rnd.uniform(-0.6, 0.6, 2 * n) * (np.arange(2 * n) % 2)
    return [[float(cx + ri * np.cos(ti + s)), float(cy + ri * np.sin(ti + s))]
            for ri, ti, s in zip(r, t, skew)]


@settings(max_examples=S_.examples(16), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(4, 12), st.integers(16, 70),
       st.integers(12, 40), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([2, 4, 4, 8]))
def test_dense_rows_equal_oracle(seed, h, w, n, rule, k):
    poly = [_star(np.random.default_rng(seed), h, w, n)]
    out = rastrum.polygon_coverage(poly, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(poly, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, poly))


@settings(max_examples=S_.examples(3), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["nonzero", "evenodd"]))
def test_dense_rows_ss16_equal_oracle(seed, rule):
    poly = [_star(np.random.default_rng(seed), 3, 18, 24)]
    out = rastrum.polygon_coverage(poly, (3, 18), rule=rule, method="ss16")
    want = oc.coverage_ss(poly, (3, 18), 16, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %r" % (rule, poly))

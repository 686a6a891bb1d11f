"""Supersampling ("ssK") of a mesh whose shared edges come late: a batch
(triangles_coverage) or a polygon of small rings (polygon_coverage) that
opens with unrelated triangles and then holds a mesh.  The cancelling of
shared edges (csrc/src/coverage/coverage_ss.c, rast__ss_cancel) is given
up a quarter of the way when fewer than one edge in 64 has met another
by then, though more than half of all would have cancelled: the
triangles are walked as they are.  Either way the counts are the binary
rule on the k-times finer grid (docs/coverage.md), bit for bit as
tests/oracle_coverage.py's coverage_ss gives them; the same scenes with
the mesh first (cancelled) check the other path against the same oracle."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _scene(seed, h, w, n, nrand, flip):
    rnd = np.random.default_rng(seed)
    g = np.stack(np.meshgrid(np.linspace(-1, w + 1, n + 1), np.linspace(-1, h + 1, n + 1)), -1)
    g[1:-1, 1:-1] += rnd.uniform(-0.3, 0.3, (n - 1, n - 1, 2)) * [w / n, h / n]
    g = np.where(rnd.random(g.shape) < 0.2, np.round(g * 4) / 4, g)  # some on sample rows
    mesh = []
    for r in range(n):
        for q in range(n):
            a, b, c, d = g[r, q], g[r, q + 1], g[r + 1, q + 1], g[r + 1, q]
            for t in ([a, b, c], [a, c, d]):
                mesh.append(t[::-1] if rnd.random() < flip else t)
    c = rnd.uniform(0, [w, h], (nrand, 1, 2))
    rand = c + rnd.uniform(-1.5, 1.5, (nrand, 3, 2))
    return np.array(mesh, dtype=np.float64), rand


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 9), st.integers(3, 9), st.integers(3, 5),
       st.sampled_from([0.0, 0.0, 0.3]), st.sampled_from(["nonzero", "evenodd"]),
       st.sampled_from([2, 4]), st.booleans())
def test_mesh_after_unrelated_triangles_equals_oracle(seed, h, w, n, flip, rule, k, mesh_first):
    mesh, rand = _scene(seed, h, w, n, n * n // 2 + 4, flip)
    tris = np.concatenate([mesh, rand] if mesh_first else [rand, mesh])
    m = "ss%d" % k
    if rule == "nonzero":  # (a batch: the union, non-zero)
        out = rastrum.triangles_coverage(tris, (h, w), method=m)
        want = oc.coverage_ss(list(tris), (h, w), k, triangles=True)
        S_.assert_same(out.astype(np.int64), want, "batch %s %r" % (m, tris.tolist()))
    rings = tris.tolist()
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method=m)
    want = oc.coverage_ss(rings, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s %s %r" % (rule, m, rings))

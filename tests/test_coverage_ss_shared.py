"""Supersampling ("ssK", polygon_coverage) of polygons made of many small
rings that share edges (a mesh given as rings, as the "mesh" family of
bench/families.py): the binary rule on the k-times finer grid, counted
per pixel (docs/coverage.md), bit for bit as tests/oracle_coverage.py's
coverage_ss gives it.  Such a polygon's shared edges may be cancelled
before the walk (csrc/src/coverage/coverage_ss.c, rast__ss_cancel): an
edge a->b and one b->a under both rules, and under even-odd also two
a->b.  So: cells turned both ways (their shared edges then run the same
way), cells repeated or reversed, rings of one or two vertices, meshes
reaching past the canvas (their runs clipped), holes where cells are
left out, and meshes with too few shared edges to cancel."""

import numpy as np
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_


def _mesh(seed, h, w, n, tris, flip, extra):
    rnd = np.random.default_rng(seed)
    x0, y0 = rnd.uniform(-2, 2, 2)
    g = np.stack(np.meshgrid(np.linspace(x0, x0 + w + rnd.uniform(-2, 2), n + 1),
                             np.linspace(y0, y0 + h + rnd.uniform(-2, 2), n + 1)), -1)
    g[1:-1, 1:-1] += rnd.uniform(-0.3, 0.3, (n - 1, n - 1, 2)) * [w / n, h / n]
    # a few vertices on the quarter-pixel grid (crossings on sample rows)
    g = np.where(rnd.random(g.shape) < 0.2, np.round(g * 4) / 4, g)
    rings = []
    for r in range(n):
        for q in range(n):
            a, b, c, d = g[r, q], g[r, q + 1], g[r + 1, q + 1], g[r + 1, q]
            cells = [[a, b, c], [a, c, d]] if tris else [[a, b, c, d]]
            for cell in cells:
                u = rnd.random()
                if u < 0.08:
                    continue  # a hole
                if rnd.random() < flip:
                    cell = cell[::-1]  # turned the other way
                rings.append(cell)
                if u > 1 - extra:  # repeated, either way
                    rings.append(cell[::-1] if rnd.random() < 0.5 else cell)
    if extra:
        rings.append([g[0, 0]])  # one vertex
        rings.append([g[0, 0], g[n, n]])  # two: a->b and b->a
    rnd.shuffle(rings)
    return [np.array(r, dtype=np.float64).tolist() for r in rings]


@settings(max_examples=S_.examples(14), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 10), st.integers(3, 10), st.integers(2, 5),
       st.booleans(), st.sampled_from([0.0, 0.0, 0.1, 0.5]), st.sampled_from([0.0, 0.1, 0.3]),
       st.sampled_from(["nonzero", "evenodd"]), st.sampled_from([2, 4, 8]))
def test_meshes_as_rings_equal_oracle(seed, h, w, n, tris, flip, extra, rule, k):
    rings = _mesh(seed, h, w, n, tris, flip, extra)
    out = rastrum.polygon_coverage(rings, (h, w), rule=rule, method="ss%d" % k)
    want = oc.coverage_ss(rings, (h, w), k, rule=rule)
    S_.assert_same(out.astype(np.int64), want, "%s ss%d %r" % (rule, k, rings))


def test_cells_that_cancel_whole():
    # a square of 2 x 2 cells drawn twice, the second time reversed: every
    # edge cancels (nothing under either rule); drawn twice the same way:
    # non-zero covers it once, even-odd not at all
    sq = [[(1.25 + 2 * i, 1.5 + 2 * j), (3.25 + 2 * i, 1.5 + 2 * j), (3.25 + 2 * i, 3.5 + 2 * j),
           (1.25 + 2 * i, 3.5 + 2 * j)] for i in range(2) for j in range(2)]
    rev = [r[::-1] for r in sq]
    for k in (2, 4):
        m = "ss%d" % k
        for rule in ("nonzero", "evenodd"):
            assert (rastrum.polygon_coverage(sq + rev, (7, 7), rule=rule, method=m) == 0).all()
        once = rastrum.polygon_coverage(sq, (7, 7), rule="nonzero", method=m)
        assert once.max() == 255
        S_.assert_same(once.astype(np.int64), oc.coverage_ss(sq, (7, 7), k, rule="nonzero"), m)
        assert (rastrum.polygon_coverage(sq + sq, (7, 7), rule="nonzero", method=m) == once).all()
        assert (rastrum.polygon_coverage(sq + sq, (7, 7), rule="evenodd", method=m) == 0).all()

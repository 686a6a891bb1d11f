""""area" of glyph-like polygons whose parts are tested from their points
alone (csrc/src/coverage/coverage_plain.c, rast__cov_parts_test: each
ring's chains built from its least vertex, found with its box, in one pass
round the ring; the edges marked afterwards from the rings' table,
rast__cov_parts_mark, and a polygon whose parts are all plain taken by
"accumulate"'s walk straight from the points, csrc/src/entry/coverage.c).
The rings come with their points rotated so that the least vertex (x, then
y) falls anywhere, the first and last points included; with edges of
length 0 (a point repeated, at the least vertex too, and round the end of
the ring); with horizontal edges at the ring's ends (the marks count the
edges that are not horizontal); with empty rings between; and with a ring
that passes twice through its least vertex (two lobes, apart or
overlapping: then not plain, and the accumulation alone is wrong). Each
is held to the exact oracle (tests/oracle_coverage.py) under both rules,
in uint8 and uint16 (issues 33 and 34)."""
import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area
from test_coverage_fast import _check


def _ring(cx, cy, rx, ry, n, phase, cw):
    t = phase + 2 * np.pi * np.arange(n) / n
    ring = np.round(np.stack([cx + rx * np.cos(t), cy + ry * np.sin(t)], 1) * 64) / 64
    return (ring[::-1] if cw else ring).tolist()


def _lobes(x, cy, overlap, cw):
    """A ring through its least vertex L twice: two triangles meeting at L,
    apart, or the second over the first (winding 2 there)."""
    L = (x, cy)
    a = [(x + 2.5, cy - 2.0), (x + 2.75, cy - 0.25)]
    b = [(x + 2.25, cy - 1.5), (x + 2.5, cy + 0.5)] if overlap else [(x + 2.5, cy + 0.25), (x + 2.75, cy + 2.0)]
    ring = [L] + a + [L] + b
    return ring[::-1] if cw else ring


def _dress(ring, rnd):
    """The ring's points rotated at random, a point repeated now and then
    (its least vertex at times), perhaps its last point its first again."""
    ring = [tuple(p) for p in ring]
    least = min(range(len(ring)), key=lambda i: ring[i])
    if rnd.integers(3) == 0:
        ring.insert(least, ring[least])
    for _ in range(int(rnd.integers(0, 3))):
        i = int(rnd.integers(len(ring)))
        ring.insert(i, ring[i])
    k = int(rnd.integers(len(ring)))
    ring = ring[k:] + ring[:k]
    if rnd.integers(4) == 0:
        ring.append(ring[0])
    return [list(p) for p in ring]


@settings(max_examples=S_.examples(10), deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.integers(2, 5), st.sampled_from(["nonzero", "evenodd"]))
def test_rotated_rings_equal_oracle(seed, count, rule):
    rnd = np.random.default_rng(seed)
    rings, x = [], 1.5
    for k in range(count):
        kind = int(rnd.integers(5))
        cw = bool(rnd.integers(2))
        cy = 3.0 if rnd.integers(2) else 9.0  # (rows of their own: some go by the accumulation, some not)
        if kind == 0:  # a ring through its least vertex twice
            rings.append(_lobes(x, cy, bool(rnd.integers(2)), cw))
            x += 3.5
        elif kind == 1:  # a box with horizontal edges at the ring's ends
            y0, y1 = cy - 3.0 + float(rnd.uniform(0.2, 1.5)), cy - 3.0 + float(rnd.uniform(4.0, 5.8))
            w = float(rnd.uniform(0.5, 2.0))
            box = [(x, y0), (x + w / 2, y0), (x + w, y0), (x + w, y1), (x, y1)]
            rings.append([(round(a * 64) / 64, round(b * 64) / 64) for a, b in (box[::-1] if cw else box)])
            x += w + float(rnd.uniform(0.5, 2.0))
        else:  # an "o", with a hole or not
            n = int(rnd.integers(6, 14))
            r = float(rnd.uniform(0.6, 1.3))
            rings.append(_ring(x, cy, r, 2.2, n, float(rnd.uniform(0, 6.3)), cw))
            if rnd.integers(2):
                rings.append(_ring(x, cy, r * 0.5, 1.3, n, float(rnd.uniform(0, 6.3)), not cw))
            x += float(rnd.uniform(1.0, 4.0))
        if rnd.integers(4) == 0:
            rings.append([])
    rings = [_dress(r, rnd) if r else r for r in rings]
    shape = (12, int(np.ceil(x)) + 2)
    full = [r for r in rings if r]  # (the oracle takes no empty ring)
    exact = exact_area(full, shape, rule, 8)
    n, m = _n_m(full, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, subpixel_bits=8, dtype=dtype)
        check_area(out, exact, M_OF[dtype], n, m, S_.lit(rings))


def test_lobes_over_one_another_are_not_plain():
    # the least vertex visited twice, the second lobe over the first: the
    # winding number 2 there, where the accumulation alone is wrong (the
    # scene tests something), among plain "o"s; the point order rotated
    # so that the least vertex is first, in the middle, and last
    o = _ring(8.0, 3.0, 1.2, 2.2, 12, 0.3, False)
    lobes = _lobes(1.0, 9.0, True, False)  # (in rows of their own)
    shape = (12, 12)
    for k in range(len(lobes)):
        rings = [lobes[k:] + lobes[:k], o]
        exact = _check(rings, "nonzero", shape=shape)
        acc = rastrum.polygon_coverage(rings, shape, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"

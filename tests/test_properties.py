"""Properties of the rule (docs/semantics.md) checked on rastrum directly:
watertightness, order-freedom, translation by whole pixels, and agreement
of all algorithms."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

import rastrum
from oracle import oracle_mask, snapped_rings
from strategies import RULES, assert_same, examples, lit, scenes

ALGOS = rastrum.ALGORITHMS["polygon_mask"]
CASES = [(alg, rule) for alg, rules in ALGOS.items() for rule in rules]
ALG_NAMES = list(ALGOS)
OFFSETS = [0.5, 0.0]




def draw_small_case(data):
    """S in 0..8, an offset, and a scene of at most 24 x 24 pixels."""
    S = data.draw(st.integers(0, 8), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rl, shape = data.draw(scenes(S, o, max_h=24, max_w=24), label="scene")
    return S, o, rl, shape


# --- watertightness -------------------------------------------------------

@st.composite
def triangulated_square(draw, half_grid: bool):
    """A square split into a jittered grid of cells, each cut along a random
    diagonal. Returns (triangles, square ring, shape)."""
    n = draw(st.integers(1, 6))
    if half_grid:
        g = draw(st.sampled_from([2.0, 2.5, 3.0, 3.5, 4.0]))
        x0 = draw(st.integers(-8, 30)) / 2
        y0 = draw(st.integers(-8, 30)) / 2
        jit = st.sampled_from([-0.5, 0.0, 0.5])
    else:
        g = draw(st.floats(1.0, 6.0))
        x0 = draw(st.floats(-5.0, 16.0))
        y0 = draw(st.floats(-5.0, 16.0))
        jit = st.floats(-g / 5, g / 5)
    xs = [x0 + k * g for k in range(n + 1)]
    ys = [y0 + k * g for k in range(n + 1)]
    P = {}
    for a in range(n + 1):
        for b in range(n + 1):
            x, y = xs[a], ys[b]
            # interior points move freely, boundary points along the boundary
            if 0 < a < n:
                x += draw(jit)
            if 0 < b < n:
                y += draw(jit)
            P[a, b] = (x, y)
    tris = []
    for a in range(n):
        for b in range(n):
            p00, p10, p11, p01 = P[a, b], P[a + 1, b], P[a + 1, b + 1], \
                P[a, b + 1]
            if draw(st.booleans()):
                tris += [[p00, p10, p11], [p00, p11, p01]]
            else:
                tris += [[p00, p10, p01], [p10, p11, p01]]
    square = [P[0, 0], P[n, 0], P[n, n], P[0, n]]
    shape = (draw(st.integers(1, 30)), draw(st.integers(1, 30)))
    return tris, square, shape


def signed_area2(tri):
    (ax, ay), (bx, by), (cx, cy) = tri
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@pytest.mark.parametrize("half_grid", [False, True])
@pytest.mark.parametrize("alg,rule", CASES)
@settings(max_examples=examples(60))
@given(data=st.data())
def test_watertight_triangulation(alg, rule, half_grid, data):
    tris, square, shape = data.draw(triangulated_square(half_grid),
                                    label="mesh")
    S = data.draw(st.sampled_from([0, 1, 2, 4, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    # after snapping no triangle may fold over (flip orientation)
    areas = [signed_area2(snapped_rings([t], S)[0]) for t in tris]
    assume(all(a >= 0 for a in areas))
    # random orientation per triangle: a single triangle's mask does not
    # depend on orientation under either rule
    flips = data.draw(st.lists(st.booleans(), min_size=len(tris),
                               max_size=len(tris)), label="flips")
    tris = [t[::-1] if f else t for t, f in zip(tris, flips)]
    total = np.zeros(shape, dtype=np.int64)
    for t in tris:
        total += rastrum.polygon_mask(t, shape, rule=rule, algorithm=alg,
                                      subpixel_bits=S, sample_offset=o)
    inside = oracle_mask(square, shape, subpixel_bits=S, sample_offset=o)
    assert_same(total, inside.astype(np.int64),
                f"triangles do not cover the square exactly once: "
                f"tris={tris!r} shape={shape} S={S} o={o} alg={alg} "
                f"rule={rule}")
    # the same triangles as rings of one polygon: even-odd gives the square
    if "evenodd" in ALGOS[alg]:
        m = rastrum.polygon_mask([np.asarray(t) for t in tris], shape,
                                 rule="evenodd", algorithm=alg,
                                 subpixel_bits=S, sample_offset=o)
        assert_same(m, inside, f"even-odd union of the mesh: tris={tris!r}")


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _weakly_convex(ring):
    n = len(ring)
    signs = {(_cross(ring[k], ring[(k + 1) % n], ring[(k + 2) % n]) > 0) -
             (_cross(ring[k], ring[(k + 1) % n], ring[(k + 2) % n]) < 0)
             for k in range(n)}
    return not ({1, -1} <= signs)


@pytest.mark.parametrize("alg,rule", CASES)
@settings(max_examples=examples(60))
@given(data=st.data())
def test_shared_edge_partition(alg, rule, data):
    """A convex polygon cut in two by a chord: the halves, which share the
    chord, never both own a sample and never both miss one."""
    S = data.draw(st.sampled_from([0, 2, 8]), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    c = st.floats(-3.0, 23.0)
    k = data.draw(st.integers(4, 9), label="k")
    cx, cy = data.draw(c, label="cx"), data.draw(c, label="cy")
    r = data.draw(st.floats(2.0, 14.0), label="r")
    angles = sorted(data.draw(st.lists(st.integers(0, 3599), min_size=k,
                                       max_size=k, unique=True),
                              label="tenths of degree"))
    angles = [a * np.pi / 1800 for a in angles]
    pts = [(cx + r * float(np.cos(a)), cy + r * float(np.sin(a)))
           for a in angles]
    i = data.draw(st.integers(0, k - 1), label="i")
    j = (i + data.draw(st.integers(2, k - 2), label="step")) % k
    if i > j:
        i, j = j, i
    a = pts[i:j + 1]
    b = pts[j:] + pts[:i + 1]
    # exact check after snapping: both halves convex, on opposite sides of
    # the chord, so they meet only along it
    sa, sb = snapped_rings([a, b], S)
    p, q = sa[0], sa[-1]
    assume(_weakly_convex(sa) and _weakly_convex(sb))
    side_a = {(_cross(p, q, v) > 0) - (_cross(p, q, v) < 0) for v in sa}
    side_b = {(_cross(p, q, v) > 0) - (_cross(p, q, v) < 0) for v in sb}
    assume(len(side_a - {0}) <= 1 and len(side_b - {0}) <= 1)
    assume(not ((side_a - {0}) & (side_b - {0})))
    shape = (24, 24)
    kw = dict(rule=rule, algorithm=alg, subpixel_bits=S, sample_offset=o)
    ma = rastrum.polygon_mask(a, shape, **kw)
    mb = rastrum.polygon_mask(b, shape, **kw)
    whole = oracle_mask(pts, shape, subpixel_bits=S, sample_offset=o)
    assert not (ma & mb).any(), f"overlap: a={a!r} b={b!r} {kw}"
    assert_same(ma | mb, whole, f"union is not the whole: a={a!r} b={b!r} "
                f"{kw}")


@pytest.mark.parametrize("alg", [a for a in ALG_NAMES
                                 if "evenodd" in ALGOS[a]])
@settings(max_examples=examples(60))
@given(data=st.data())
def test_evenodd_parity_is_additive(alg, data):
    """Under even-odd, mask(A + B) == mask(A) xor mask(B) for any rings."""
    S, o, rl, shape = draw_small_case(data)
    rl2, _ = data.draw(scenes(S, o, max_h=24, max_w=24), label="scene2")
    kw = dict(rule="evenodd", algorithm=alg, subpixel_bits=S, sample_offset=o)
    m1 = rastrum.polygon_mask(rl, shape, **kw)
    m2 = rastrum.polygon_mask(rl2, shape, **kw)
    m12 = rastrum.polygon_mask(rl + rl2, shape, **kw)
    assert_same(m12, m1 ^ m2, f"rings={lit(rl)!r} rings2={lit(rl2)!r} "
                f"shape={shape} {kw}")


# --- order freedom ---------------------------------------------------------

@pytest.mark.parametrize("alg,rule", CASES)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_order_free(alg, rule, data):
    S, o, rl, shape = draw_small_case(data)
    kw = dict(rule=rule, algorithm=alg, subpixel_bits=S, sample_offset=o)
    base = rastrum.polygon_mask(rl, shape, **kw)
    where = f"rings={lit(rl)!r} shape={shape} {kw}"
    # start vertex
    shifts = [data.draw(st.integers(0, len(r) - 1)) for r in rl]
    rot = [np.roll(r, -s, axis=0) for r, s in zip(rl, shifts)]
    assert_same(rastrum.polygon_mask(rot, shape, **kw), base,
                f"start vertex shifted by {shifts}: {where}")
    # ring order
    perm = data.draw(st.permutations(range(len(rl))))
    assert_same(rastrum.polygon_mask([rl[p] for p in perm], shape, **kw),
                base, f"rings permuted {perm}: {where}")
    # direction: every ring reversed (winding negated: both rules agree)
    rev = [r[::-1].copy() for r in rl]
    assert_same(rastrum.polygon_mask(rev, shape, **kw), base,
                f"all rings reversed: {where}")
    if rule == "evenodd":
        which = [data.draw(st.booleans()) for _ in rl]
        some = [r[::-1].copy() if w else r for r, w in zip(rl, which)]
        assert_same(rastrum.polygon_mask(some, shape, **kw), base,
                    f"rings reversed {which}: {where}")


# --- translation -------------------------------------------------------------

@pytest.mark.parametrize("alg,rule", CASES)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_translation_by_whole_pixels(alg, rule, data):
    S, o, rl, shape = draw_small_case(data)
    dx = data.draw(st.integers(-7, 7), label="dx")
    dy = data.draw(st.integers(-7, 7), label="dy")
    # the float addition must be exact for the property to apply: a
    # coordinate whose translate would round is first moved to 2**-24 units
    # (|v| < 2**28, so both it and its translate are exact floats)
    def exact_movable(v, d):
        if Fraction(v + d) == Fraction(v) + d:
            return v
        return float(np.round(v * 2.0 ** 24)) / 2.0 ** 24
    rl = [np.array([[exact_movable(x, dx), exact_movable(y, dy)]
                    for x, y in r.tolist()]) for r in rl]
    moved = [r + np.array([dx, dy], dtype=np.float64) for r in rl]
    for r, m in zip(rl, moved):
        for (x, y), (mx, my) in zip(r.tolist(), m.tolist()):
            assert Fraction(mx) == Fraction(x) + dx
            assert Fraction(my) == Fraction(y) + dy
    kw = dict(rule=rule, algorithm=alg, subpixel_bits=S, sample_offset=o)
    try:
        b = rastrum.polygon_mask(moved, shape, **kw)
    except ValueError:
        assume(False)           # translated past the coordinate range
    a = rastrum.polygon_mask(rl, shape, **kw)
    H, W = shape
    # a[y, x] == b[y + dy, x + dx] wherever both are in the target
    y_lo, y_hi = max(0, -dy), min(H, H - dy)
    x_lo, x_hi = max(0, -dx), min(W, W - dx)
    assume(y_lo < y_hi and x_lo < x_hi)
    assert_same(a[y_lo:y_hi, x_lo:x_hi],
                b[y_lo + dy:y_hi + dy, x_lo + dx:x_hi + dx],
                f"translation by ({dx}, {dy}): rings={lit(rl)!r} "
                f"shape={shape} {kw}")


# --- algorithms agree -------------------------------------------------------

@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_all_algorithms_agree(rule, data):
    algs = [a for a in ALG_NAMES if rule in ALGOS[a]]
    S = data.draw(st.integers(0, 16), label="S")
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rl, shape = data.draw(scenes(S, o), label="scene")
    kw = dict(rule=rule, subpixel_bits=S, sample_offset=o)
    ref = rastrum.polygon_mask(rl, shape, algorithm=algs[0], **kw)
    for alg in algs[1:]:
        assert_same(rastrum.polygon_mask(rl, shape, algorithm=alg, **kw), ref,
                    f"{alg} vs {algs[0]}: rings={lit(rl)!r} shape={shape} "
                    f"{kw}")


@pytest.mark.parametrize("alg,rule", CASES)
def test_deterministic_and_input_not_modified(alg, rule):
    rng = np.random.default_rng(3)
    rl = [rng.uniform(-5, 45, size=(12, 2)) for _ in range(3)]
    copies = [r.copy() for r in rl]
    a = rastrum.polygon_mask(rl, (40, 40), rule=rule, algorithm=alg)
    b = rastrum.polygon_mask(rl, (40, 40), rule=rule, algorithm=alg)
    assert np.array_equal(a, b)
    for r, c in zip(rl, copies):
        assert np.array_equal(r, c)
    # non-contiguous and other-dtype inputs give the same answer
    nc = [np.asfortranarray(r) for r in rl]
    assert np.array_equal(rastrum.polygon_mask(nc, (40, 40), rule=rule,
                                               algorithm=alg), a)
    strided = [np.repeat(r, 2, axis=0)[::2] for r in rl]
    assert np.array_equal(rastrum.polygon_mask(strided, (40, 40), rule=rule,
                                               algorithm=alg), a)
    ints = [np.round(r).astype(np.int32) for r in rl]
    assert np.array_equal(
        rastrum.polygon_mask(ints, (40, 40), rule=rule, algorithm=alg),
        oracle_mask([i.astype(np.float64) for i in ints], (40, 40),
                    rule=rule))
    f32 = [r.astype(np.float32) for r in rl]
    assert np.array_equal(
        rastrum.polygon_mask(f32, (40, 40), rule=rule, algorithm=alg),
        oracle_mask(f32, (40, 40), rule=rule))

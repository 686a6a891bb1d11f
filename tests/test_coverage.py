"""Anti-aliased coverage (docs/semantics.md, coverage) against the exact oracles of
tests/oracle_coverage.py: "area" within its documented bound of
floor(a*M + 1/2) (|out - M a| <= 1/2 everywhere), every "ssK" bit for bit,
"accumulate" where nothing overlaps, triangle batches as one region."""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

import oracle
import oracle_coverage as oc
import rastrum
import strategies as S_

F = Fraction
M_OF = {np.uint8: 255, np.uint16: 65535}


def _n_m(rings, subpixel_bits, triangles=False):
    """Edges and crossing pairs of the whole scene: at least the n and m of
    any row (the bound of rastrum.h is per row)."""
    rl = oc.oracle.snapped_rings(rings, subpixel_bits)
    edges = oc._edges(rl)
    m = 0
    for p in range(len(edges)):
        for q in range(p + 1, len(edges)):
            y = oc._crossing_y(edges[p], edges[q])
            if y is not None and max(edges[p][1], edges[q][1]) < y < min(edges[p][3], edges[q][3]):
                m += 1
    return len(edges), m


def check_area(out, exact, M, n, m, what):
    """out == floor(a M + 1/2), except at a tie within the bound, where it
    may be one level off; and always |out - M a| <= 1/2 + bound."""
    bound = F(n + m + 1, 2 ** 58) * M
    bad = []
    for (j, i), a in np.ndenumerate(exact):
        v = int(out[j, i])
        want = oc.level(a, M)
        if v == want:
            continue
        x = a * M + F(1, 2)
        near = abs(x - round(x)) <= bound
        if not (near and abs(v - want) == 1 and abs(v - a * M) <= F(1, 2) + bound):
            bad.append(((j, i), v, want, float(a)))
    assert not bad, "%s: %d pixel(s) off, first: %s" % (what, len(bad), bad[:5])


def levels_near_ties(exact, M, count):
    """The levels floor(a M + 1/2) of exact areas a, and where each is
    within check_area's bound (count: its n + m) of a tie, where the level
    may be one less or more."""
    bound = F(count + 1, 2 ** 58) * M
    want = np.zeros(exact.shape, np.int64)
    near = np.zeros(exact.shape, bool)
    for (j, i), a in np.ndenumerate(exact):
        want[j, i] = oc.level(a, M)
        x = a * M + F(1, 2)
        near[j, i] = abs(x - round(x)) <= bound
    return want, near


def blend(s, d, c):
    """gray8's blend of colour s over background d at level c (0 to 255):
    (s c + d (255 - c) + 127) // 255 (docs/coverage.md)."""
    s, d, c = (np.asarray(v, np.int64) for v in (s, d, c))
    return (s * c + d * (255 - c) + 127) // 255


def blended(got, color, bg, want, near):
    """Where got is the blend of colour over bg at the level want, or
    (where near, if not None) at one level less or more."""
    ok = got == blend(color, bg, want)
    if near is not None:
        ok |= near & ((got == blend(color, bg, np.clip(want - 1, 0, 255))) |
                      (got == blend(color, bg, np.clip(want + 1, 0, 255))))
    return ok


def exact_area(rings, shape, rule, s, triangles=False):
    return oc.coverage_exact(rings, shape, rule=rule, subpixel_bits=s, triangles=triangles)


# ---- the oracle checks itself ------------------------------------------------

def _simple(ring):
    """No two edges of the (exact) ring that are not neighbours meet,
    touching included (orientation tests in exact arithmetic)."""
    def turn(a, b, p):
        v = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        return (v > 0) - (v < 0)
    m = len(ring)
    edges = [(ring[k], ring[(k + 1) % m]) for k in range(m)]
    for i in range(m):
        for j in range(i + 2, m):
            if i == 0 and j == m - 1:
                continue
            (a, b), (c, d) = edges[i], edges[j]
            if turn(a, b, c) * turn(a, b, d) <= 0 and turn(c, d, a) * turn(c, d, b) <= 0:
                return False
    return True


@settings(max_examples=S_.examples(30))
@given(st.integers(1, 7), st.integers(1, 7), st.integers(3, 9), st.integers(0, 2 ** 32 - 1))
@example(4, 2, 5, 152919482)  # a hole that snapping makes cross itself
def test_oracle_slabs_equal_clipping_on_simple_polygons(h, w, n, seed):
    """Two independent exact references agree where both apply: a convex
    polygon (angles sorted around a centre) and a hole inside it."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(0, [w, h])
    ang = np.sort(rnd.uniform(0, 2 * np.pi, n))
    r = rnd.uniform(0.3, 3.0)
    outer = np.stack([c[0] + r * np.cos(ang), c[1] + r * np.sin(ang)], 1)
    g = outer.mean(axis=0)  # inside the convex polygon: the hole stays inside
    hole = (outer - g) * 0.4 + g
    cases = [[outer]]
    # ... unless snapping moves a vertex of a sliver's hole out of its
    # snapped outer ring (seed 5380 did): then the two references rightly
    # differ (that part of the hole has winding -1), and only the outer
    # ring is compared
    # (or snapping turns a sliver's hole round (seed 9511 did): then both
    # rings turn the same way, the hole has winding 2, and the clipping's
    # sum of signed areas is not a coverage)
    so, sh = oracle.snapped_rings([outer, hole[::-1]], 8)
    area2 = sum(so[k - 1][0] * so[k][1] - so[k][0] * so[k - 1][1] for k in range(len(so)))
    hole2 = sum(sh[k - 1][0] * sh[k][1] - sh[k][0] * sh[k - 1][1] for k in range(len(sh)))
    # (or snapping makes a sliver's hole cross itself (seed 152919482 did:
    # two of its vertices 1/256 apart): then the hole's winding is not of
    # one sign, and only the outer ring is compared)
    if area2 * hole2 < 0 and all(area2 * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) > 0
                                 for a, b in zip(so, so[1:] + so[:1]) for p in sh) and _simple(sh):
        cases.append([outer, hole[::-1]])
    for rl in cases:
        for rule in ("evenodd", "nonzero"):
            a = oc.coverage_exact(rl, (h, w), rule=rule)
            b = oc.coverage_clip(rl, (h, w))
            assert (a == b).all()


def test_oracle_overlaps():
    sq = [(1, 1), (3, 1), (3, 3), (1, 3)]
    once = oc.coverage_exact([sq], (4, 4))
    assert once[1, 1] == 1 and once[0, 0] == 0 and sum(once.ravel()) == 4
    assert (oc.coverage_exact([sq, sq], (4, 4), rule="nonzero") == once).all()
    assert (oc.coverage_exact([sq, sq], (4, 4), rule="evenodd") == 0).all()
    # a pentagram: its centre pentagon is winding 2 (in under non-zero only)
    star = [(10 + 8 * math.sin(k * 4 * math.pi / 5), 10 - 8 * math.cos(k * 4 * math.pi / 5))
            for k in range(5)]
    eo = oc.coverage_exact([star], (20, 20), rule="evenodd")
    nz = oc.coverage_exact([star], (20, 20), rule="nonzero")
    assert sum(nz.ravel()) > sum(eo.ravel())
    assert nz[9, 9] == 1 and eo[9, 9] == 0


# ---- area --------------------------------------------------------------------

DTYPES = [np.uint8, np.uint16]


@settings(max_examples=S_.examples(60))
@given(st.data(), st.sampled_from([0, 2, 8]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from(DTYPES))
def test_area_equals_oracle(data, s, rule, dtype):
    rl, shape = data.draw(S_.scenes(s, 0.5, max_h=10, max_w=10))
    out = rastrum.polygon_coverage(rl, shape, rule=rule, subpixel_bits=s, dtype=dtype)
    assert out.dtype == dtype and out.shape == shape
    n, m = _n_m(rl, s)
    check_area(out, exact_area(rl, shape, rule, s), M_OF[dtype], n, m, S_.lit(rl))


def overlap_scenes():
    sq = [(1.25, 1.5), (6.5, 1.5), (6.5, 5.75), (1.25, 5.75)]
    star = [(5 + 4.3 * math.sin(k * 4 * math.pi / 5), 5 - 4.3 * math.cos(k * 4 * math.pi / 5))
            for k in range(5)]
    rnd = np.random.default_rng(12)
    tris = [rnd.uniform(0, 10, (3, 2)) for _ in range(12)]
    circle = [(5 + 3.7 * math.cos(t), 5 + 3.7 * math.sin(t)) for t in np.linspace(0, 6.28, 40)]
    return {
        "square twice": [sq, sq],
        "square and its reverse": [sq, sq[::-1]],
        "pentagram": [star],
        "12 overlapping triangles in one path": tris,
        "circle with a coincident half": [circle, circle[:20]],
        "collinear overlapping edges": [[(1, 1), (8, 1), (8, 4), (1, 4)],
                                        [(3, 1), (9, 1), (9, 7), (3, 7)]],
    }


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
@pytest.mark.parametrize("name", sorted(overlap_scenes()))
def test_area_overlap_scenes(name, rule):
    rl = overlap_scenes()[name]
    for dtype in DTYPES:
        out = rastrum.polygon_coverage(rl, (10, 10), rule=rule, dtype=dtype)
        n, m = _n_m(rl, 8)
        check_area(out, exact_area(rl, (10, 10), rule, 8), M_OF[dtype], n, m, name)


def test_area_float_is_the_fixed_point_value():
    rl = overlap_scenes()["pentagram"]
    exact = exact_area(rl, (10, 10), "nonzero", 8)
    n, m = _n_m(rl, 8)
    f64 = rastrum.polygon_coverage(rl, (10, 10), rule="nonzero", dtype=np.float64)
    f32 = rastrum.polygon_coverage(rl, (10, 10), rule="nonzero", dtype=np.float32)
    assert f64.dtype == np.float64 and f32.dtype == np.float32
    for (j, i), a in np.ndenumerate(exact):
        assert abs(F(float(f64[j, i])) - a) <= F(n + m + 2, 2 ** 58) + F(1, 2 ** 52)
        assert abs(F(float(f32[j, i])) - a) <= F(1, 2 ** 23)


@settings(max_examples=S_.examples(30))
@given(st.integers(0, 4), st.integers(-3, 3), st.integers(-3, 3), st.integers(1, 3))
def test_area_corners_and_range_limit(s, dx, dy, k):
    """Vertices on pixel corners and edges, and rings reaching the range's
    ends (the visible part must still be exact)."""
    lim = S_.limit_px(s)
    rl = [[(-lim, -lim), (lim, 2 + dy * 0.5), (1 + dx * 0.5, lim)],
          [(1 + k, 1), (4, 1 + k * 0.5), (4, 5), (1, 4)]]
    for rule in ("evenodd", "nonzero"):
        out = rastrum.polygon_coverage(rl, (6, 6), rule=rule, subpixel_bits=s, dtype=np.uint16)
        n, m = _n_m(rl, s)
        check_area(out, exact_area(rl, (6, 6), rule, s), 65535, n, m, rl)


def test_area_examples():
    # half a pixel, a full one, none; a rectangle [0.5, 2) x [0, 1)
    assert rastrum.polygon_coverage([(0.5, 0), (2, 0), (2, 1), (0.5, 1)], (1, 3)).tolist() == \
        [[128, 255, 0]]
    # a triangle over one pixel: half of it
    assert rastrum.polygon_coverage([(0, 0), (1, 0), (0, 1)], (1, 1), dtype=np.float64)[0, 0] == 0.5
    # empty input, empty shape
    assert rastrum.polygon_coverage([], (2, 3)).tolist() == [[0] * 3] * 2
    assert rastrum.polygon_coverage([(0, 0), (1, 0), (0, 1)], (0, 4)).shape == (0, 4)


# ---- supersampling -------------------------------------------------------------

@settings(max_examples=S_.examples(60))
@given(st.data(), st.sampled_from([0, 1, 3, 8]), st.sampled_from([0.5, 0.0]),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([2, 4, 8, 16]),
       st.sampled_from(DTYPES))
def test_ss_equals_binary_oracle_on_finer_grid(data, s, o, rule, k, dtype):
    rl, shape = data.draw(S_.scenes(max(s, 4), o, max_h=8, max_w=8))
    if k == 16:
        shape = (min(shape[0], 4), min(shape[1], 4))
    try:
        out = rastrum.polygon_coverage(rl, shape, rule=rule, method="ss%d" % k, subpixel_bits=s,
                                       sample_offset=o, dtype=dtype)
    except rastrum.InputError:
        # scaled by k, a far vertex may leave the range (documented)
        lim = S_.COORD_MAX >> max(0, k.bit_length() - 1 - s)
        pts = [c for r in oc.oracle.snapped_rings(rl, s) for p in r for c in p]
        assert any(abs(c * (1 << s)) > lim for c in pts)
        return
    want = oc.coverage_ss(rl, shape, k, rule=rule, subpixel_bits=s, sample_offset=o,
                          M=M_OF[dtype])
    S_.assert_same(out.astype(np.int64), want, "ss%d %s" % (k, S_.lit(rl)))


def test_ss_float():
    rl = overlap_scenes()["pentagram"]
    f = rastrum.polygon_coverage(rl, (10, 10), method="ss4", rule="nonzero", dtype=np.float64)
    counts = oc.coverage_ss(rl, (10, 10), 4, rule="nonzero", M=16)  # count itself
    assert (f * 16 == counts).all()


# ---- accumulate ----------------------------------------------------------------

@settings(max_examples=S_.examples(30))
@given(st.integers(1, 9), st.integers(1, 9), st.integers(3, 9), st.integers(0, 2 ** 32 - 1),
       st.sampled_from(["evenodd", "nonzero"]), st.booleans())
def test_accumulate_exact_without_overlaps(h, w, n, seed, rule, hole):
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(0, [w, h])
    ang = np.sort(rnd.uniform(0, 2 * np.pi, n))
    outer = np.stack([c[0] + 3 * np.cos(ang), c[1] + 3 * np.sin(ang)], 1)
    g = outer.mean(axis=0)
    rl = [outer, ((outer - g) * 0.3 + g)[::-1]] if hole else [outer]
    out = rastrum.polygon_coverage(rl, (h, w), rule=rule, method="accumulate")
    nn, m = _n_m(rl, 8)
    check_area(out, exact_area(rl, (h, w), rule, 8), 255, nn, m, rl)


def test_accumulate_is_wrong_on_overlaps_as_documented():
    sc = overlap_scenes()
    twice = rastrum.polygon_coverage(sc["square twice"], (10, 10), rule="evenodd", method="accumulate")
    area = rastrum.polygon_coverage(sc["square twice"], (10, 10), rule="evenodd")
    assert (area == 0).all() and twice.max() > 0  # the ghost outline
    star_acc = rastrum.polygon_coverage(sc["pentagram"], (10, 10), rule="nonzero", method="accumulate")
    star = rastrum.polygon_coverage(sc["pentagram"], (10, 10), rule="nonzero")
    assert (star_acc != star).any()


def _accumulated(rings, shape, rule, s):
    """The accumulation's own definition, from the exact oracle: the
    integral of the winding number over each pixel is the sum, over the
    rings (each simple here), of the ring's exact area coverage signed by
    its orientation; non-zero takes min(|.|, 1), even-odd folds |.| mod 2."""
    total = None
    for ring in rings:
        snapped = oc.oracle.snapped_rings([ring], s)[0]
        area2 = sum(F(x0) * F(y1) - F(x1) * F(y0)
                    for (x0, y0), (x1, y1) in zip(snapped, snapped[1:] + snapped[:1]))
        a = exact_area([ring], shape, "nonzero", s) * (1 if area2 > 0 else -1)
        total = a if total is None else total + a
    return rule_applied(total, rule)


def check_accumulate(rings, shape, rule):
    """"accumulate" of rings, as uint8 and uint16, against the exact
    accumulation (_accumulated at 1/256 px) within check_area's bound."""
    want = _accumulated(rings, shape, rule, 8)
    n, m = _n_m(rings, 8)
    for dtype in (np.uint8, np.uint16):
        out = rastrum.polygon_coverage(rings, shape, rule=rule, method="accumulate", dtype=dtype)
        check_area(out, want, M_OF[dtype], n, m, S_.lit(rings))


def check_accumulate_batch(tris, shape):
    """triangles_coverage(method="accumulate") of triangles against the
    exact accumulation (_accumulated at 1/256 px, non-zero) of the same
    triangles, each turned counter-clockwise (the batch's own turning), as
    rings, within check_area's bound."""
    ccw = []
    for t in tris:
        a = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])
        ccw.append(t if a > 0 else t[::-1])
    want = _accumulated(ccw, shape, "nonzero", 8)
    n, m = _n_m(ccw, 8)
    out = rastrum.triangles_coverage(np.asarray(tris, dtype=np.float64), shape, method="accumulate")
    check_area(out, want, M_OF[np.uint8], n, m, S_.lit(tris))


def rule_applied(total, rule):
    """The rule applied to each pixel's integral of the winding number
    (exact): non-zero takes min(|.|, 1), even-odd folds |.| mod 2."""
    out = np.empty(total.shape, object)
    for idx, v in np.ndenumerate(total):
        v = abs(v)
        if rule == "nonzero":
            out[idx] = min(v, F(1))
        else:
            v -= 2 * (v.numerator // (2 * v.denominator))
            out[idx] = 2 - v if v > 1 else v
    return out


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(2, 4), st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_accumulate_on_overlaps_is_its_definition(k, seed, rule, dtype):
    """Overlapping squares of both orientations (winding numbers -k..k):
    "accumulate" gives the rule applied to the integral of the winding
    number, as documented: even-odd folds it, non-zero clamps it."""
    rnd = np.random.default_rng(seed)
    rings = []
    for _ in range(k):
        x, y = rnd.uniform(0.5, 3.5, 2)
        d = rnd.uniform(1.5, 4.0)
        sq = [(x, y), (x + d, y + 0.3), (x + d - 0.3, y + d), (x - 0.2, y + d - 0.4)]
        rings.append(sq if rnd.integers(2) else sq[::-1])
    out = rastrum.polygon_coverage(rings, (9, 9), rule=rule, method="accumulate", dtype=dtype)
    n, m = _n_m(rings, 8)
    check_area(out, _accumulated(rings, (9, 9), rule, 8), M_OF[dtype], n, m, rings)


# ---- triangle batches: one region ------------------------------------------------

def test_triangulated_square_has_no_seams():
    rnd = np.random.default_rng(5)
    g = np.linspace(1, 9, 7)
    pts = np.array([[x, y] for y in g for x in g]) + rnd.uniform(-0.3, 0.3, (49, 2)) * \
        np.array([[(0 < i % 7 < 6) and (0 < i // 7 < 6)] for i in range(49)])
    tris = []
    for r in range(6):
        for c in range(6):
            a, b, d, e = r * 7 + c, r * 7 + c + 1, r * 7 + c + 8, r * 7 + c + 7
            t1, t2 = [pts[a], pts[b], pts[d]], [pts[a], pts[d], pts[e]]
            tris += [t1, t2[::-1] if (r + c) % 2 else t2]  # mixed orientations
    for method in ("area", "ss4", "accumulate"):
        out = rastrum.triangles_coverage(np.array(tris), (10, 10), method=method)
        assert (out[1:9, 1:9] == 255).all(), method
        assert out[0].sum() == 0 and out[:, 0].sum() == 0
    exact = exact_area(tris, (10, 10), "nonzero", 8, triangles=True)
    assert sum(exact.ravel()) == 64


@settings(max_examples=S_.examples(40))
@given(st.integers(1, 8), st.integers(1, 8), st.integers(1, 6), st.integers(0, 2 ** 32 - 1),
       st.sampled_from(["area", "ss2", "ss8"]))
def test_triangles_union_equals_oracle(h, w, n, seed, method):
    rnd = np.random.default_rng(seed)
    tris = rnd.uniform(-1, 9, (n, 3, 2))
    if n > 1:
        tris[1] = tris[0][[0, 2, 1]]  # a triangle twice, reversed: still the union
    out = rastrum.triangles_coverage(tris, (h, w), method=method)
    if method == "area":
        nn, m = _n_m(list(tris), 8)
        check_area(out, exact_area(list(tris), (h, w), "nonzero", 8, triangles=True), 255, nn, m,
                   tris.tolist())
    else:
        k = int(method[2:])
        want = oc.coverage_ss(list(tris), (h, w), k, triangles=True)
        S_.assert_same(out.astype(np.int64), want, tris.tolist())


@settings(max_examples=S_.examples(12))
@given(st.integers(1, 6), st.integers(1, 8), st.integers(0, 2 ** 32 - 1),
       st.sampled_from(["ss2", "ss4", "ss8"]))
def test_many_overlapping_triangles_equal_oracle(h, w, seed, method):
    # hundreds active on a row (the walk then skips triangles inside columns
    # covered on every fine row): two wide ones across the rows, many drawn
    # in toward their centres (some poking out), slivers, one reversed
    rnd = np.random.default_rng(seed)
    big = rnd.uniform(-1, w + 1, (2, 3, 2))
    big[:, 0, 1], big[:, 1, 1] = -1, h + 1
    centre = big.mean(1)
    many = [centre[i % 2] + (big[i % 2] - centre[i % 2]) * rnd.uniform(0.05, 1.0)
            + rnd.uniform(-0.05, 0.05, (3, 2)) for i in range(280)]
    x = rnd.uniform(-1, w + 1, 20)
    slivers = [[(a, -1), (a + 0.1, h + 1), (a + rnd.uniform(-2, 2), rnd.uniform(-1, h + 1))] for a in x]
    tris = np.concatenate([big, np.array(many), np.array(slivers), big[:1, [0, 2, 1]]])
    rnd.shuffle(tris)
    out = rastrum.triangles_coverage(tris, (h, w), method=method)
    want = oc.coverage_ss(list(tris), (h, w), int(method[2:]), triangles=True)
    S_.assert_same(out.astype(np.int64), want, tris.tolist())


# ---- entry points and bad input ----------------------------------------------

def test_algorithms_table():
    for entry in ("polygon_coverage", "triangles_coverage"):
        assert set(rastrum.ALGORITHMS[entry]) == {"area", "ss2", "ss4", "ss8", "ss16", "accumulate"}


@pytest.mark.parametrize("kw, text", [
    (dict(method="ss3"), "area, ss2, ss4, ss8, ss16, accumulate"),
    (dict(method=None), "choose one of"),
    (dict(rule="odd"), "rule"),
    (dict(dtype=np.int32), "dtype"),
    (dict(subpixel_bits=33), "subpixel_bits"),  # ("area" takes 17..32: test_coverage64.py)
    (dict(sample_offset=0.25), "sample_offset"),
])
def test_bad_options(kw, text):
    with pytest.raises(ValueError, match=text):
        rastrum.polygon_coverage([(0, 0), (1, 0), (0, 1)], (2, 2), **kw)
    kw.pop("rule", None)
    if kw:
        with pytest.raises(ValueError, match=text):
            rastrum.triangles_coverage([[(0, 0), (1, 0), (0, 1)]], (2, 2), **kw)


def test_bad_geometry():
    with pytest.raises(ValueError, match="NaN"):
        rastrum.polygon_coverage([(0, 0), (1, float("nan")), (0, 1)], (2, 2))
    with pytest.raises(ValueError, match="outside the range"):
        rastrum.polygon_coverage([(0, 0), (1e9, 0), (0, 1)], (2, 2))
    with pytest.raises(ValueError, match="triangle 0, vertex 2"):
        rastrum.triangles_coverage([[(0, 0), (1, 0), (0, float("inf"))]], (2, 2))
    with pytest.raises(ValueError, match="shape"):
        rastrum.polygon_coverage([(0, 0), (1, 0), (0, 1)], (-1, 2))
    with pytest.raises(ValueError, match="shape"):
        rastrum.triangles_coverage(np.zeros((2, 3)), (2, 2))
    # ss16 with S = 0 scales the vertices by 16: the range shrinks by 16
    with pytest.raises(ValueError, match="range"):
        rastrum.polygon_coverage([(0, 0), (2 ** 26, 0), (0, 1)], (2, 2), method="ss16",
                                 subpixel_bits=0)

"""Exact-area coverage on 64-bit vertices (rast_polygon_coverage64; docs/coverage.md,
"64-bit vertices") against the exact rational oracle of tests/oracle_coverage.py:
S = 17..32, coordinates near +-2^28 pixels, vertices on pixel corners, slivers,
self-intersections, holes, both rules; within the documented bound
|a' - a| <= (n + m + 1) 2^-50 (n, m over the whole scene: at least any row's).
polygon_coverage switches to it by itself, and agrees with the 32-bit path where
both apply."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from rastrum._native import ffi, lib
from test_coverage import _n_m

F = Fraction
LIM = 2 ** 28  # |coordinate| < 2^28 pixels


def check_fix62(out, exact, n, m, what):
    """|a' - a| <= (n + m + 1) 2^-50 (+ the rounding to 2^-62) at every pixel."""
    bound = F(n + m + 1, 2 ** 50) + F(1, 2 ** 62)
    bad = [((j, i), float(a), int(out[j, i]) / 2 ** 62)
           for (j, i), a in np.ndenumerate(exact) if abs(F(int(out[j, i]), 2 ** 62) - a) > bound]
    assert not bad, "%s: %d pixel(s) off, first: %s" % (what, len(bad), bad[:5])


def check_levels(out, exact, M, n, m, what):
    """floor(a M + 1/2), or one level off within the bound of a tie."""
    bound = (F(n + m + 1, 2 ** 50) + F(1, 2 ** 62)) * M
    bad = []
    for (j, i), a in np.ndenumerate(exact):
        v, want = int(out[j, i]), oc.level(a, M)
        x = a * M + F(1, 2)
        if v != want and not (abs(x - round(x)) <= bound and abs(v - want) == 1):
            bad.append(((j, i), v, want))
    assert not bad, "%s: %d pixel(s) off, first: %s" % (what, len(bad), bad[:5])


@st.composite
def local_rings(draw, s, w, h, max_rings=3):
    """1..max_rings rings in local pixel coordinates around a w x h window:
    pixel corners, dyadic fractions at the full 2^-s, slivers (two vertices
    2^-s apart), repeated points (self-intersections come for free)."""
    def coord(extent):
        kind = draw(st.integers(0, 3))
        if kind == 0:  # a pixel corner
            return float(draw(st.integers(-1, extent + 1)))
        k = draw(st.integers(-(1 << s), (extent + 1) << s))
        if kind == 1:
            return k / float(1 << s) if s < 40 else 0.0
        if kind == 2:  # near a corner, by a few 2^-s
            return draw(st.integers(-1, extent + 1)) + draw(st.integers(-3, 3)) / float(1 << s)
        return draw(st.floats(-1.5, extent + 1.5, allow_nan=False))
    rings = []
    for _ in range(draw(st.integers(1, max_rings))):
        n = draw(st.integers(3, 7))
        ring = [(coord(w), coord(h)) for _ in range(n)]
        if draw(st.booleans()):  # a sliver: a vertex 2^-s from the previous one
            x, y = ring[-1]
            ring.append((x + draw(st.integers(-2, 2)) / float(1 << s), y + 1 / float(1 << s)))
        rings.append(ring)
    return rings


ORIGINS = st.sampled_from([(0, 0), (LIM - 8, LIM - 8), (-LIM + 2, -LIM + 2), (LIM - 8, -LIM + 2),
                           (123456789, -98765432)])


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.data(), st.integers(17, 32), ORIGINS, st.sampled_from(["evenodd", "nonzero"]))
def test_c_entry_matches_exact_area(data, s, origin, rule):
    """The C entry near +-2^28 (window moved there) against exact rationals."""
    w, h = data.draw(st.integers(1, 6)), data.draw(st.integers(1, 6))
    local = data.draw(local_rings(s, w, h))
    ox, oy = origin
    # snapped locally, then moved by the origin exactly (integers to C)
    shape = (h, w)
    rl = oc.oracle.snapped_rings(local, s)
    moved = [[(float(x), float(y)) for x, y in r] for r in rl]  # exact dyadics
    snapped_big = [[(x + ox, y + oy) for x, y in r] for r in rl]  # Fractions
    exact = oc.coverage_exact(moved, shape, rule=rule, subpixel_bits=s)
    n, m = _n_m(moved, s)
    out = c_coverage64_exact(snapped_big, shape, origin, rule, s)
    check_fix62(out, exact, n, m, "S=%d origin=%s %s" % (s, origin, rule))
    u8 = c_coverage64_exact(snapped_big, shape, origin, rule, s, lib.RAST_COVERAGE_U8)
    check_levels(u8, exact, 255, n, m, "uint8")
    u16 = c_coverage64_exact(snapped_big, shape, origin, rule, s, lib.RAST_COVERAGE_U16)
    check_levels(u16, exact, 65535, n, m, "uint16")


def c_coverage64_exact(rl, shape, origin, rule, s, fmt=lib.RAST_COVERAGE_FIX62):
    """c_coverage64 of rings given as exact Fractions on the 2^-s grid."""
    ints = [[(int(x * (1 << s)), int(y * (1 << s))) for x, y in r] for r in rl]
    return _c_ints(ints, shape, origin, rule, s, fmt)


def c_poly64(ints, shape, rule, s, fmt):
    """The arguments rast_polygon_coverage64 takes for integer rings on the
    2^-s grid and an output of `shape`: (poly, opts, scratch, need, dtype,
    keep), keep holding the buffers poly points into."""
    h, w = shape
    flat = np.array([v for r in ints for p in r for v in p], dtype=np.int64)
    sizes = ffi.new("uint32_t[]", [len(r) for r in ints])
    poly = ffi.new("rast_polygon64 *")
    pbuf = ffi.from_buffer("rast_point64[]", flat)
    poly.points, poly.ring_sizes, poly.nrings = pbuf, sizes, len(ints)
    opts = ffi.new("rast_coverage_opts *")
    opts.method, opts.subpixel_bits = lib.RAST_AA_AREA, s
    opts.rule = lib.RAST_RULE_EVENODD if rule == "evenodd" else lib.RAST_RULE_NONZERO
    need = ffi.new("size_t *")
    assert lib.rast_coverage64_scratch_size(opts, len(flat) // 2, w, h, need) == lib.RAST_OK
    scratch = np.empty(need[0] // 16 + 1, dtype=np.complex128)
    dt = {lib.RAST_COVERAGE_FIX62: np.uint64, lib.RAST_COVERAGE_U8: np.uint8,
          lib.RAST_COVERAGE_U16: np.uint16}[fmt]
    return poly, opts, scratch, need, dt, (flat, sizes, pbuf)


def _c_ints(ints, shape, origin, rule, s, fmt):
    h, w = shape
    poly, opts, scratch, need, dt, _keep = c_poly64(ints, shape, rule, s, fmt)
    clip = ffi.new("rast_rect *", {"x0": origin[0], "y0": origin[1],
                                   "x1": origin[0] + w, "y1": origin[1] + h})
    out = np.full(shape, 77, dtype=dt)
    r = lib.rast_polygon_coverage64(poly, opts, clip, fmt, ffi.from_buffer(out), w * out.itemsize,
                                    ffi.from_buffer(scratch), need[0])
    assert r == lib.RAST_OK, r
    return out


@settings(max_examples=S_.examples(25), deadline=None)
@given(st.data(), st.integers(17, 32), st.sampled_from(["evenodd", "nonzero"]))
def test_polygon_coverage_switches_to_wide(data, s, rule):
    """polygon_coverage takes S above 16 by itself (float64: the fraction)."""
    w, h = data.draw(st.integers(1, 6)), data.draw(st.integers(1, 6))
    rings = data.draw(local_rings(s, w, h))
    exact = oc.coverage_exact(rings, (h, w), rule=rule, subpixel_bits=s)
    n, m = _n_m(rings, s)
    f = rastrum.polygon_coverage(rings, (h, w), rule=rule, subpixel_bits=s, dtype=np.float64)
    bound = float(F(n + m + 1, 2 ** 50)) + 2.0 ** -52
    err = max(abs(float(a) - v) for a, v in zip(exact.ravel(), f.ravel()))
    assert err <= bound, (err, bound)
    u8 = rastrum.polygon_coverage(rings, (h, w), rule=rule, subpixel_bits=s)
    check_levels(u8, exact, 255, n, m, "uint8 S=%d" % s)


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.data(), st.integers(0, 16), st.sampled_from(["evenodd", "nonzero"]))
def test_same_as_32bit_path_where_both_apply(data, s, rule):
    """Where S <= 16 and the coordinates fit 32 bits both paths apply; they
    agree within the sum of their bounds (float64), and uint8 is the same
    level except within those bounds of a tie."""
    from rastrum._coverage import polygon_coverage64
    w, h = data.draw(st.integers(1, 8)), data.draw(st.integers(1, 8))
    rings = data.draw(local_rings(min(s, 12), w, h))
    n, m = _n_m(rings, s)
    a32 = rastrum.polygon_coverage(rings, (h, w), rule=rule, subpixel_bits=s, dtype=np.float64)
    a64 = polygon_coverage64(rings, (h, w), rule=rule, subpixel_bits=s)
    bound = (n + m + 1) * (2.0 ** -58 + 2.0 ** -50) + 2.0 ** -52
    assert np.abs(a32 - a64).max() <= bound
    l32 = rastrum.polygon_coverage(rings, (h, w), rule=rule, subpixel_bits=s)
    l64 = polygon_coverage64(rings, (h, w), rule=rule, subpixel_bits=s, dtype=np.uint8)
    x = a64 * 255 + 0.5
    tie = np.abs(x - np.round(x)) <= bound * 255 + 1e-12
    assert ((l32 == l64) | (tie & (np.abs(l32.astype(int) - l64) == 1))).all()


def test_far_coordinates_switch_at_low_s():
    """S = 8 with a vertex past 2^27 / 2^8 pixels: the 32-bit path cannot
    take it, the 64-bit one does (as polygon_mask switches)."""
    big = 2.0 ** 27
    ring = [(-big, -big), (3.5, -big), (3.5, big), (-big, big)]
    a = rastrum.polygon_coverage(ring, (2, 5), subpixel_bits=8, dtype=np.float64)
    assert a.tolist() == [[1.0, 1.0, 1.0, 0.5, 0.0]] * 2
    assert rastrum.polygon_coverage(ring, (2, 5), subpixel_bits=8).tolist() == [[255, 255, 255, 128, 0]] * 2
    assert rastrum.polygon_mask(ring, (2, 5), subpixel_bits=8).sum() == 6  # (its path switches too)


@pytest.mark.parametrize("s", [0, 8, 16])
@pytest.mark.parametrize("frac", [0.0, 0.25, 0.4375])
def test_path_choice_at_the_range_end_is_the_same_every_call(s, frac):
    """A coordinate that snaps to +-RAST_COORD_MAX itself (t = v 2^s in
    [M, M + 1/2)) is the 32-bit path's, whether the call comes the quick
    way (the 32-bit call first) or the general way (the range test first):
    the same call gives the same levels every time.  (Found by hypothesis
    in test_coverage_paint: a level at a tie came out 128, then 127, once
    the call was remembered, the first call having gone the 64-bit way.)"""
    import rastrum._coverage as C
    big = (lib.RAST_COORD_MAX + frac) / 2.0 ** s
    rings = [np.array([[big, 42.89], [-1.5, 3.17e7 / 2 ** s], [-1.0, 2.0], [8.5, 5.5], [8.5, 12.0],
                       [37.0, 11.0], [3.0, 489.1]]),
             np.array([[-1.9, -2.0], [-1.9, 10.5], [9.0, 10.5]]),
             np.array([[1.0, -569.5], [-big, 9.5], [7.5, 1.5]])]
    pts = C._points(rings)[0]
    assert not C._use_wide(C._opts("area", "nonzero", s, 0.5, "polygon_coverage"), pts)
    for dtype in (np.uint8, np.uint16, np.float64):
        C._QUICK.clear()
        outs = [rastrum.polygon_coverage(rings, (10, 7), rule="nonzero", subpixel_bits=s, dtype=dtype)
                for _ in range(3)]
        assert all((o == outs[0]).all() for o in outs[1:]), dtype
    over = [np.array([[(lib.RAST_COORD_MAX + 0.5) / 2.0 ** s, 1.0], [0.0, 0.0], [0.0, 3.0]])]
    assert C._use_wide(C._opts("area", "nonzero", s, 0.5, "polygon_coverage"), C._points(over)[0])


def test_known_values_at_s32():
    """Hand-computed areas at S = 32 near 2^28: a triangle of half a pixel,
    a bow tie (two triangles of 1/4 pixel each, even-odd and non-zero alike),
    a ring drawn twice (non-zero once, even-odd nothing), a hole."""
    o = 2 ** 28 - 4
    tri = [[(o, o), (o + 1, o), (o, o + 1)]]
    assert c_coverage64_exact(tri, (1, 1), (o, o), "evenodd", 32)[0, 0] == 2 ** 61
    bow = [[(o, o), (o + 1, o + 1), (o + 1, o), (o, o + 1)]]
    for rule in ("evenodd", "nonzero"):
        assert c_coverage64_exact(bow, (1, 1), (o, o), rule, 32)[0, 0] == 2 ** 61
    sq = [(o + F(1, 4), o), (o + 2, o), (o + 2, o + 1), (o + F(1, 4), o + 1)]
    twice = [sq, sq]
    assert c_coverage64_exact(twice, (1, 2), (o, o), "nonzero", 32).tolist() == [[3 * 2 ** 60, 2 ** 62]]
    assert c_coverage64_exact(twice, (1, 2), (o, o), "evenodd", 32).tolist() == [[0, 0]]
    outer = [(o, o), (o + 3, o), (o + 3, o + 3), (o, o + 3)]
    hole = [(o + 1, o + 1), (o + 1, o + 2), (o + 2, o + 2), (o + 2, o + 1)]
    got = c_coverage64_exact([outer, hole], (3, 3), (o, o), "nonzero", 32) >> 62
    assert got.tolist() == [[1, 1, 1], [1, 0, 1], [1, 1, 1]]


def test_bad_input():
    sq = [(0, 0), (1, 0), (1, 1)]
    with pytest.raises(rastrum.InputError, match="subpixel_bits"):
        rastrum.polygon_coverage(sq, (1, 1), subpixel_bits=33)
    with pytest.raises(rastrum.InputError, match="subpixel_bits"):
        rastrum.polygon_coverage(sq, (1, 1), method="ss4", subpixel_bits=17)
    with pytest.raises(rastrum.InputError, match="2\\*\\*28"):
        rastrum.polygon_coverage([(0, 0), (2.0 ** 28, 0), (1, 1)], (1, 1), subpixel_bits=20)
    with pytest.raises(rastrum.InputError, match="NaN"):
        rastrum.polygon_coverage([(0, 0), (float("nan"), 0), (1, 1)], (1, 1), subpixel_bits=20)


def test_c_errors_leave_out_untouched():
    poly = ffi.new("rast_polygon64 *")
    pts = ffi.new("rast_point64[3]", [(0, 0), (1 << 20, 0), (0, 1 << 20)])
    size = ffi.new("uint32_t *", 3)
    poly.points, poly.ring_sizes, poly.nrings = pts, size, 1
    opts = ffi.new("rast_coverage_opts *")
    opts.subpixel_bits = 20
    clip = ffi.new("rast_rect *", {"x0": 0, "y0": 0, "x1": 2, "y1": 2})
    out = np.full((2, 2), 7, np.uint8)
    need = ffi.new("size_t *")
    assert lib.rast_coverage64_scratch_size(opts, 3, 2, 2, need) == lib.RAST_OK
    sc = np.empty(need[0] // 16 + 1, np.complex128)
    buf = ffi.from_buffer(out)
    scb = ffi.from_buffer(sc)
    cases = []
    opts.method = lib.RAST_AA_SS4
    cases.append((lib.RAST_E_WIDE, lib.rast_polygon_coverage64(poly, opts, clip, 0, buf, 2, scb, need[0])))
    opts.method = lib.RAST_AA_AREA
    opts.subpixel_bits = 33
    cases.append((lib.RAST_E_SUBPIXEL, lib.rast_polygon_coverage64(poly, opts, clip, 0, buf, 2, scb, need[0])))
    opts.subpixel_bits = 20
    cases.append((lib.RAST_E_SCRATCH, lib.rast_polygon_coverage64(poly, opts, clip, 0, buf, 2, scb, need[0] - 1)))
    cases.append((lib.RAST_E_ARG, lib.rast_polygon_coverage64(poly, opts, clip, 0, buf, 1, scb, need[0])))
    cases.append((lib.RAST_E_ARG, lib.rast_polygon_coverage64(poly, opts, clip, 3, buf, 2, scb, need[0])))
    pts[1].x = 1 << 48
    cases.append((lib.RAST_E_RANGE, lib.rast_polygon_coverage64(poly, opts, clip, 0, buf, 2, scb, need[0])))
    assert [w for w, _ in cases] == [g for _, g in cases]
    assert (out == 7).all()

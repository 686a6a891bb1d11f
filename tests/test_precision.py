"""The 64-bit vertex path (issue 13): subpixel_bits up to 32, coordinates up
to 2**28 pixels, against the exact rational oracle (tests/oracle.py,
tests/oracle_boundary.py) written from DESIGN section 1 alone.

- hypothesis scenes at S = 17..32 (both rules, both sample offsets,
  holes): polygon_mask, Canvas.fill_polygon and the batch burn equal the
  oracle on the snapped input; the conservative boundary equals its oracle;
- at the ends of the range (vertices a float's step inside +-2**28 px, at
  S = 0 and S = 32, windows near the origin and near the far corner via a
  whole-pixel translation), vertices on sample points, slivers thinner than
  2**-S, collinear points;
- snapping: rastpy_snap64 is floor(v * 2**S + 1/2) exactly (Fractions),
  and the first bad point is named;
- below 17 bits both paths give the same bytes (the 64-bit path is chosen
  only when S or a coordinate needs it, so existing results do not move);
- on random GIS-like input (float64 vertices far from the grid) the mask
  at S = 32 differs from the exact rule on the UNSNAPPED input by 0 pixels,
  while S = 8 differs by some (the approximation this path removes);
- errors just past the limits, each naming the point, nothing written.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

import rastrum
from rastrum import _batch, _core
from rastrum._native import ffi, lib
from oracle import oracle_mask, snap
from oracle_boundary import oracle_conservative
from strategies import examples

PX = 2 ** lib.RAST_COORD64_PIXEL_BITS  # the 64-bit path's range, in pixels (exclusive)
RULES = ("evenodd", "nonzero")


def _below(v):
    """The largest float64 below v."""
    return float(np.nextafter(v, -np.inf))


def _last_in(S, sign=1):
    """The float64 furthest from 0 on the side `sign` whose snapped value
    at S is inside the 64-bit range, |floor(v * 2**S + 1/2)| <= 2**(S+28) - 1
    (the bounds are -(2**(S+28) - 3/2) / 2**S inclusive and
    (2**(S+28) - 1/2) / 2**S exclusive: rounding half up is not symmetric)."""
    lim = 2 ** (S + lib.RAST_COORD64_PIXEL_BITS) - 1
    v = sign * float(Fraction(2 * lim + 1, 2 ** (S + 1)))
    while abs(snap(v, S)) > lim:
        v = float(np.nextafter(v, -sign * np.inf))
    assert abs(snap(float(np.nextafter(v, sign * np.inf)), S)) > lim
    return v


# ---- strategies -------------------------------------------------------------------

def _coord(S, lo, hi):
    """Coordinates in [lo, hi] pixels: random floats, values on the 1/2**S
    grid (exactly representable), and sample points (k/2)."""
    grid = st.integers(int(lo * 2 ** S), int(hi * 2 ** S)).map(lambda k: k / 2 ** S)
    half = st.integers(int(2 * lo), int(2 * hi)).map(lambda k: k / 2)
    return st.one_of(st.floats(lo, hi, allow_nan=False), grid, half)


@st.composite
def scenes(draw, S, h=14, w=16, reach=6):
    """1..3 rings of 3..7 vertices within `reach` pixels of an h x w window."""
    c = _coord(S, -reach, max(h, w) + reach)
    rings = []
    for _ in range(draw(st.integers(1, 3))):
        rings.append(np.array(draw(st.lists(st.tuples(c, c), min_size=3, max_size=7)), float))
    return rings


# ---- the oracle at large S ----------------------------------------------------------

@settings(max_examples=examples(60))
@given(S=st.integers(17, 32), data=st.data(), rule=st.sampled_from(RULES),
       offset=st.sampled_from([0.5, 0.0]))
def test_mask_equals_oracle_large_s(S, data, rule, offset):
    rings = data.draw(scenes(S))
    got = rastrum.polygon_mask(rings, (14, 16), rule=rule, subpixel_bits=S, sample_offset=offset)
    want = oracle_mask(rings, (14, 16), rule=rule, subpixel_bits=S, sample_offset=offset)
    assert np.array_equal(got, want)


@settings(max_examples=examples(30))
@given(S=st.integers(17, 32), data=st.data(), rule=st.sampled_from(RULES))
def test_conservative_equals_oracle_large_s(S, data, rule):
    rings = data.draw(scenes(S, 10, 12, 3))
    got = rastrum.polygon_mask(rings, (10, 12), rule=rule, subpixel_bits=S, boundary="conservative")
    want = oracle_conservative(rings, (10, 12), rule=rule, subpixel_bits=S, sample_offset=0.5)
    assert np.array_equal(got, want)


@settings(max_examples=examples(30))
@given(S=st.integers(17, 32), data=st.data())
def test_canvas_fill_large_s(S, data):
    rings = data.draw(scenes(S))
    c = rastrum.Canvas((14, 16), "gray8")
    c.fill_polygon(rings, 200, subpixel_bits=S)
    want = oracle_mask(rings, (14, 16), subpixel_bits=S)
    assert np.array_equal(c.array == 200, want)
    assert np.array_equal(c.array[~want], np.zeros((~want).sum(), np.uint8))


@settings(max_examples=examples(30))
@given(S=st.sampled_from([8, 24, 32]), data=st.data(),
       dtype=st.sampled_from([np.uint8, np.int32, np.float64]), merge=st.sampled_from(["replace", "add"]))
def test_batch_burn_large_s(S, data, dtype, merge):
    """The batch burn on the 64-bit path (S > 16) against per-polygon oracle masks."""
    polys = [data.draw(scenes(S)) for _ in range(data.draw(st.integers(1, 4)))]
    values = np.arange(3, 3 + len(polys)).astype(dtype)
    out = np.full((14, 16), 1, dtype)
    opts = _core.fill_opts("aet", "evenodd", S, 0.5)
    _batch.burn(out, [[np.ascontiguousarray(r) for r in p] for p in polys], opts, values, merge)
    want = np.full((14, 16), 1, dtype)
    for p, v in zip(polys, values):
        m = oracle_mask(p, (14, 16), subpixel_bits=S)
        want[m] = v if merge == "replace" else want[m] + v
    assert np.array_equal(out, want)


# ---- the ends of the range -------------------------------------------------------

def _mask64_window(rings, S, x0, y0, h, w, rule="evenodd"):
    """The h x w window at pixel (x0, y0) of the 64-bit fill, through
    rast_fill_polygon64_spans with that clip (the window may sit anywhere
    in the plane)."""
    pts = np.ascontiguousarray(np.concatenate(rings), float)
    p64 = np.zeros(2 * len(pts), np.int64)
    assert lib.rastpy_snap64(ffi.from_buffer("double[]", pts), len(pts), S,
                             ffi.cast("int64_t *", p64.ctypes.data)) == -1
    sizes = ffi.new("uint32_t[]", [len(r) for r in rings])
    poly = ffi.new("rast_polygon64 *")
    poly.points = ffi.cast("rast_point64 *", p64.ctypes.data)
    poly.ring_sizes = sizes
    poly.nrings = len(rings)
    opts = _core.fill_opts("aet", rule, S, 0.5)
    clip = ffi.new("rast_rect *", (x0, y0, x0 + w, y0 + h))
    need = ffi.new("size_t *")
    assert lib.rast_scratch_size64(opts, len(pts), w, h, need) == 0
    scratch = np.zeros(need[0] // 8 + 1, np.uint64)
    mask = np.zeros((h, w), bool)

    @ffi.callback("void(void *, int32_t, int32_t, int32_t)")
    def span(user, y, a, b):
        mask[y - y0, a - x0:b - x0] = True

    assert lib.rast_fill_polygon64_spans(poly, opts, clip, span, ffi.NULL,
                                         ffi.cast("void *", scratch.ctypes.data), need[0]) == 0
    return mask


@pytest.mark.parametrize("S", [0, 8, 20, 32])
@pytest.mark.parametrize("rule", RULES)
def test_vertices_at_the_limits(S, rule):
    """Big polygons whose vertices sit a float's step inside +-2**28 px
    (the last float in range), seen through a window at the origin and
    through windows next to each corner of the range; there the oracle
    sees the polygon translated by whole pixels (which translates the
    pixels, and commutes with snapping)."""
    lim = _last_in(S)
    k = PX - 16  # a window [k, k + 14) x [k, k + 12) touches the far corner
    rng = np.random.default_rng(S + 7)
    drawn = 0
    for trial in range(6):
        ring = rng.choice([-lim, lim], size=(5, 2))
        ring[rng.random((5, 2)) < 0.4] = rng.uniform(-30, 30)
        got = rastrum.polygon_mask([ring], (12, 14), rule=rule, subpixel_bits=S)
        assert np.array_equal(got, oracle_mask([ring], (12, 14), rule=rule, subpixel_bits=S))
        for sx in (1, -1):
            for sy in (1, -1):
                # vertices near the corner (sx lim, sy lim), the window there
                near = np.c_[sx * (lim - rng.uniform(0, 40, 5)), sy * (lim - rng.uniform(0, 40, 5))]
                near[0] = (sx * lim, sy * lim)
                near[1] = (sx * lim, -sy * lim)  # an edge along the whole range
                x0 = k if sx > 0 else -k - 14
                y0 = k if sy > 0 else -k - 12
                got = _mask64_window([near], S, x0, y0, 12, 14, rule)
                want = oracle_mask([near - (x0, y0)], (12, 14), rule=rule, subpixel_bits=S)
                assert np.array_equal(got, want)
                drawn += bool(got.any())
    assert drawn >= 6  # the windows are not all empty


@pytest.mark.parametrize("S", [0, 16, 24, 32])
def test_just_past_the_limits(S):
    """The first float past the range either side (at S = 0 the half
    pixel below 2**28, which rounds up), 2**28, 1e300 and inf are refused,
    naming the point; nothing is written."""
    ring = np.array([(1.0, 1.0), (9.0, 2.0), (4.0, 8.0)])
    # the first floats past the range either side
    first_out = [float(np.nextafter(_last_in(S, sign), sign * np.inf)) for sign in (1, -1)]
    past = first_out + [PX, -PX, 1e300, np.inf]
    if S == 0:
        assert first_out == [PX - 0.5, -PX + 0.5 - 2.0 ** -25]  # half up: 2**28 - 1/2 is out
    for v in past:
        for axis in (0, 1):
            bad = ring.copy()
            bad[2, axis] = v
            c = rastrum.Canvas((10, 12), "gray8")
            with pytest.raises(rastrum.InputError, match=r"point 2.*(range|infinite)"):
                c.fill_polygon(bad, 9, subpixel_bits=S)
            assert not c.array.any()
            with pytest.raises(rastrum.InputError, match=r"point 2.*(range|infinite)"):
                rastrum.polygon_mask(bad, (10, 12), subpixel_bits=S)
    # and the last float inside is accepted
    for sign in (1, -1):
        ok = ring.copy()
        ok[2, 0] = _last_in(S, sign)
        assert np.array_equal(rastrum.polygon_mask(ok, (10, 12), subpixel_bits=S),
                              oracle_mask([ok], (10, 12), subpixel_bits=S))


def test_subpixel_bits_range_and_options():
    ring = np.array([(1.0, 1.0), (9.0, 2.0), (4.0, 8.0)])
    for S in (-1, 33, 64):
        with pytest.raises(rastrum.InputError, match=r"subpixel_bits must be in 0\.\.32"):
            rastrum.polygon_mask(ring, (10, 12), subpixel_bits=S)
    for kw in (dict(algorithm="xscan"), dict(algorithm="edgeflag"), dict(boundary="closed"),
               dict(rounding="textbook", sample_offset=0)):
        with pytest.raises(rastrum.InputError, match=r"subpixel_bits=20.*aet"):
            rastrum.polygon_mask(ring, (10, 12), subpixel_bits=20, **kw)
    # the other algorithms keep the 32-bit path (and its range) at S <= 16
    with pytest.raises(rastrum.InputError, match=r"range"):
        rastrum.polygon_mask(ring * 1e6, (10, 12), algorithm="xscan", subpixel_bits=8)
    # the C status for what the 64-bit path does not offer
    assert "64-bit" in ffi.string(lib.rast_status_str(lib.RAST_E_WIDE)).decode()


# ---- slivers, sample points, collinear points -------------------------------------

@pytest.mark.parametrize("S", [24, 32])
def test_slivers_and_sample_points(S):
    e = 2.0 ** -S  # one grid step
    cases = [
        # slivers one step wide, and thinner than a step (collapsing)
        [(0.5, -3.0), (0.5 + e, 20.0), (0.5, 20.0)],
        [(3.5, -3.0), (3.5 + e / 4, 20.0), (3.5 - e / 3, 20.0)],
        [(-2.0, 4.5), (30.0, 4.5 + e), (30.0, 4.5)],
        # vertices on sample points, and a step either side
        [(0.5, 0.5), (10.5, 0.5), (10.5, 7.5), (0.5, 7.5)],
        [(0.5 + e, 0.5 - e), (10.5 - e, 0.5 + e), (10.5, 7.5 + e), (0.5 - e, 7.5)],
        # collinear points, a spike and a repeated vertex
        [(1.0, 1.0), (4.0, 2.0), (7.0, 3.0), (10.0, 4.0), (2.0, 9.0)],
        [(2.0, 2.0), (9.0, 2.0), (9.0, 2.0), (12.0, 9.5), (9.0, 2.0), (2.0, 8.0)],
    ]
    for ring in cases:
        for rule in RULES:
            for off in (0.5, 0.0):
                got = rastrum.polygon_mask(ring, (10, 14), rule=rule, subpixel_bits=S, sample_offset=off)
                assert np.array_equal(got, oracle_mask([ring], (10, 14), rule=rule, subpixel_bits=S,
                                                       sample_offset=off)), (ring, rule, off)


# ---- snapping -----------------------------------------------------------------------

@settings(max_examples=examples(200))
@given(S=st.integers(0, 32), v=st.one_of(
    st.floats(-PX, PX, allow_nan=False),
    st.integers(-2 ** 40, 2 ** 40).map(lambda k: k / 2 ** 12),  # on and near halves
    st.floats(-1e-3, 1e-3)))
@example(S=0, v=0.5 - 2 ** -54)     # t + 1/2 rounds up in floats; the exact half does not
@example(S=32, v=2.0 ** -33)        # exactly half a step
@example(S=32, v=-(2.0 ** -33))
@example(S=0, v=_below(PX - 0.5))   # the last float in range at S = 0
@example(S=0, v=PX - 0.5)           # rounds to 2**28: out
@example(S=0, v=-PX + 0.5)          # rounds to -(2**28 - 1): in
@example(S=32, v=_below(PX))
@example(S=32, v=-_below(PX))
def test_snap64_is_exact(S, v):
    out = np.zeros(2, np.int64)
    xy = np.array([v, 0.0])
    bad = lib.rastpy_snap64(ffi.from_buffer("double[]", xy), 1, S, ffi.cast("int64_t *", out.ctypes.data))
    want = snap(v, S)
    if abs(want) <= 2 ** (S + lib.RAST_COORD64_PIXEL_BITS) - 1:
        assert bad == -1 and out[0] == want
    else:
        assert bad == 0


def test_snap64_names_the_first_bad_point():
    xy = np.array([1.0, 2.0, 3.0, np.nan, 5.0, np.inf], float)
    out = np.zeros(6, np.int64)
    assert lib.rastpy_snap64(ffi.from_buffer("double[]", xy), 3, 32, ffi.cast("int64_t *", out.ctypes.data)) == 1
    xy[3] = 4.0
    assert lib.rastpy_snap64(ffi.from_buffer("double[]", xy), 3, 32, ffi.cast("int64_t *", out.ctypes.data)) == 2


# ---- both paths below 17 bits -------------------------------------------------------

@settings(max_examples=examples(80))
@given(S=st.integers(0, 16), data=st.data(), rule=st.sampled_from(RULES),
       boundary=st.sampled_from(["exact", "conservative"]))
def test_both_paths_agree_below_17_bits(S, data, rule, boundary):
    """The same bytes from rastpy_mask_polygon and rastpy_mask_polygon64:
    switching paths (automatically, when a coordinate needs it) moves no
    pixel."""
    rings = data.draw(scenes(min(S, 10), 12, 13, 4))
    pts = np.ascontiguousarray(np.concatenate(rings))
    sizes = ffi.new("uint32_t[]", [len(r) for r in rings])
    opts = _core.fill_opts("aet", rule, S, 0.5, "exact", boundary)
    a, b = np.zeros((12, 13), np.uint8), np.zeros((12, 13), np.uint8)
    xy = ffi.from_buffer("double[]", pts)
    ra = lib.rastpy_mask_polygon(ffi.from_buffer(a), 12, 13, xy, len(pts), sizes, len(rings), opts)
    rb = lib.rastpy_mask_polygon64(ffi.from_buffer(b), 12, 13, xy, len(pts), sizes, len(rings), opts)
    assert ra == rb
    if ra == 0:
        assert np.array_equal(a, b)


def test_existing_results_unchanged_path():
    """At S <= 16 inside the 32-bit range the 32-bit path is used."""
    ring = np.array([(1.0, 1.0), (9.0, 2.0), (4.0, 8.0)])
    assert not _core.use_wide(_core.fill_opts("aet", "evenodd", 16, 0.5), ring)
    assert _core.use_wide(_core.fill_opts("aet", "evenodd", 17, 0.5), ring)
    assert _core.use_wide(_core.fill_opts("aet", "evenodd", 8, 0.5), ring * 1e6)
    assert not _core.use_wide(_core.fill_opts("xscan", "evenodd", 8, 0.5), ring * 1e6)


# ---- GIS scale: exact on the float input -------------------------------------------

def _gis_polygons(rng, n, w, h):
    """Random polygons with holes at GIS-like float coordinates (a rotated
    grid: nothing lands on the 1/256 grid)."""
    polys = []
    for _ in range(n):
        cx, cy = rng.uniform(0, w), rng.uniform(0, h)
        r = rng.uniform(3, 25)
        k = rng.integers(5, 12)
        t = np.sort(rng.uniform(0, 2 * np.pi, k))
        rr = r * rng.uniform(0.5, 1.0, k)
        outer = np.c_[cx + rr * np.cos(t), cy + rr * np.sin(t)]
        hole = np.c_[cx + 0.3 * r * np.cos(-t[:4]), cy + 0.3 * r * np.sin(-t[:4])]
        polys.append([outer, hole])
    return polys


def test_gis_scale_exact_on_float_input():
    """The issue's measurement, small: S = 32 gives 0 pixels off the exact
    rule on the unsnapped float64 input; S = 8 gives some off (so the
    comparison can fail)."""
    rng = np.random.default_rng(13)
    w, h = 120, 90
    off = {8: 0, 32: 0}
    for p in _gis_polygons(rng, 40, w, h):
        exact = oracle_mask(p, (h, w), subpixel_bits=None)
        for S in off:
            off[S] += int((rastrum.polygon_mask(p, (h, w), subpixel_bits=S) != exact).sum())
    assert off[32] == 0
    assert off[8] > 0


def test_exact_numbers_snap_exactly_on_the_64_bit_path():
    """A Fraction just below an S = 32 snapping boundary (0.5 + 2**-33,
    less 2**-60) snaps to 0.5, so the left edge keeps column 0's sample
    (0.5); its nearest float64 is the boundary itself, which snaps up and
    would lose the column.  Exact values are converted to a float64 on the
    same side of every boundary (within 2**19 pixels)."""
    x0 = Fraction(1, 2) + Fraction(1, 2 ** 33) - Fraction(1, 2 ** 60)
    assert float(x0) == 0.5 + 2.0 ** -33  # the float64 alone would round up
    values = [x0]
    if np.finfo(np.longdouble).nmant >= 60:  # x86's 80-bit long double holds it exactly
        values.append(np.longdouble(x0.numerator) / np.longdouble(x0.denominator))
    for v in values:
        ring = [(v, 0), (3, 0), (3, 2), (v, 2)]
        got = rastrum.polygon_mask(ring, (2, 4), subpixel_bits=32)
        # the oracle's snap of the exact value is 0.5 itself (its rings go
        # through float64, so it is given the snapped vertex)
        assert snap(x0, 32) == 2 ** 31
        want = oracle_mask([[(0.5, 0), (3, 0), (3, 2), (0.5, 2)]], (2, 4), subpixel_bits=32)
        np.testing.assert_array_equal(got, want)
        assert got[:, 0].all()
    float_only = rastrum.polygon_mask([(float(x0), 0), (3, 0), (3, 2), (float(x0), 2)], (2, 4), subpixel_bits=32)
    assert not float_only[:, 0].any()

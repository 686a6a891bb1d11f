"""zonal_stats' fractions in one C call (_zonal._all_fractions, through
python/glue/zonal.c's rastpy_window_fractions64) against:

* feature_fractions (one polygon_coverage call a feature, held to the
  exact oracle by test_zonal.py), BIT for bit: the same features, cells,
  order and float64 fractions, with features far outside the raster (their
  rings clipped first: feature_fractions' own path) among the others;
* the exact area of every cell of the snapped feature (oracle_coverage,
  rationals), within polygon_coverage's documented bound;
* the C function's bad input: a bad window or a full output is a status,
  never a write past the output.
"""

from fractions import Fraction as F

import numpy as np
from hypothesis import given, settings, strategies as st

import strategies as S_
from rastrum import _fractions, _zonal as zonal, gis
from rastrum._native import ffi, lib
from test_zonal import TRANSFORMS, exact_fractions, features, rings_of, world


def flat(geoms, t):
    xy, sizes, prings, kind, feat, _ = gis._flatten(geoms)
    px = gis._pixels(xy, gis._inverse(gis._transform6(t)), sizes, prings, feat)
    return px, sizes, prings, feat


def far(h, w, t, dx):
    """A square far outside the raster (x by dx raster widths) that still
    reaches into it: its window is the raster's, its own extent larger
    (feature_fractions clips its rings first)."""
    ring = [(-dx * w, -0.5), (w - 0.5, -0.5), (w - 0.5, h - 0.5), (-dx * w, h - 0.5), (-dx * w, -0.5)]
    return world({"type": "Polygon", "coordinates": [ring]}, t)


def assert_bits(got, want):
    for g, x in zip(got, want):
        assert g.dtype == x.dtype and g.shape == x.shape
        assert np.array_equal(g.view(np.uint8), x.view(np.uint8))


@settings(max_examples=S_.examples(30))
@given(st.integers(1, 40), st.integers(1, 40), st.data(), st.sampled_from(TRANSFORMS))
def test_same_bits_as_feature_fractions(h, w, data, t):
    geoms = [world(data.draw(features(h, w)), t) for _ in range(data.draw(st.integers(0, 6)))]
    for k in sorted(data.draw(st.lists(st.integers(0, len(geoms)), max_size=2))):
        geoms.insert(k, far(h, w, t, data.draw(st.sampled_from([3.0, 1e6]))))
    if not geoms:
        return
    px, sizes, prings, feat = flat(geoms, t)
    want = _fractions.feature_fractions(px, sizes, prings, feat, len(geoms), (h, w), "evenodd")[:3]
    rule = data.draw(st.sampled_from(["evenodd", "nonzero"]))
    if rule != "evenodd":
        want = _fractions.feature_fractions(px, sizes, prings, feat, len(geoms), (h, w), rule)[:3]
    seen = []
    # windows past the batch limit go to feature_fractions' sparse path,
    # the rest to the one C call: a small limit mixes both in one call
    limit, zonal._BATCH_CELLS = zonal._BATCH_CELLS, data.draw(st.sampled_from([zonal._BATCH_CELLS, 60]))
    try:
        got = zonal._all_fractions(px, sizes, prings, feat, len(geoms), (h, w), rule, seen.append)
    finally:
        zonal._BATCH_CELLS = limit
    assert_bits(got, want)
    assert seen and seen[-1] == len(geoms) and seen == sorted(seen)


@settings(max_examples=S_.examples(15))
@given(st.integers(1, 7), st.integers(1, 7), st.data(), st.sampled_from(TRANSFORMS))
def test_exact(h, w, data, t):
    """Each fraction the exact area of the snapped feature in the cell,
    rounded once to float64 (test_zonal.test_fractions_exact's bound)."""
    geoms = [world(data.draw(features(h, w)), t) for _ in range(data.draw(st.integers(1, 3)))]
    px, sizes, prings, feat = flat(geoms, t)
    f, cells, frac = zonal._all_fractions(px, sizes, prings, feat, len(geoms), (h, w), "evenodd")
    for k, g in enumerate(geoms):
        want, _ = exact_fractions(g, t, (h, w))
        mine = f == k
        got = {(int(c) // w, int(c) % w): v for c, v in zip(cells[mine], frac[mine])}
        e = sum(len(r) for r in rings_of(g))
        bound = F(e + e * (e - 1) // 2 + 1, 2 ** 58)
        assert set(got) <= set(want)
        for cell in set(got) | set(want):
            a, v = want.get(cell, F(0)), got.get(cell, 0.0)
            assert abs(F(v) - a) <= bound + abs(a) / 2 ** 53, (k, cell, v, float(a))


def test_c_bad_input_and_capacity():
    opts = ffi.new("rast_coverage_opts *")
    opts.method, opts.rule, opts.subpixel_bits = lib.RAST_AA_AREA, 0, 32
    xy = np.array([0.0, 0.0, 3.0, 0.0, 3.0, 2.0, 0.0, 2.0])  # a 3 x 2 rectangle: 6 full cells
    sizes = np.array([4], np.uint32)
    out_f, out_c, out_v = np.full(8, -7, np.int64), np.full(8, -7, np.int64), np.full(8, -7.0)
    failed = ffi.new("int64_t[2]")

    def call(win, cap):
        win = np.asarray(win, np.int64)
        return lib.rastpy_window_fractions64(len(win), ffi.from_buffer("int64_t[]", win),
                                             ffi.from_buffer("double[]", xy), len(xy) // 2,
                                             ffi.from_buffer("uint32_t[]", sizes), len(sizes), opts, 10, ffi.from_buffer("int64_t[]", out_f),
                                             ffi.from_buffer("int64_t[]", out_c), ffi.from_buffer("double[]", out_v),
                                             cap, failed)

    assert call([[5, 2, 3, 32, 0, 0, 1, 21]], 8) == 6
    assert out_f[:6].tolist() == [5] * 6 and out_c[:6].tolist() == [21, 22, 23, 31, 32, 33]
    assert out_v[:6].tolist() == [1.0] * 6 and out_f[6] == -7
    out_f[:] = -7
    assert call([[5, 2, 3, 32, 0, 0, 1, 0]], 5) == lib.RAST_E_ARG  # the 6th cell does not fit
    assert out_f[5] == -7
    assert call([[1, 2, 3, 32, 0, 0, 1, 0], [2, 0, 3, 32, 0, 0, 1, 0]], 8) == lib.RAST_E_ARG  # height 0
    assert failed[0] == 1
    assert call([[1, 2, 3, 32, 0, 0, 0, 0]], 8) == lib.RAST_E_ARG  # no ring
    # a window table running past the points or the rings given: refused before reading there
    out_f[:] = -7
    for bad in ([1, 2, 3, 32, 1, 0, 1, 0],  # its 4 points start at point 1 of 4
                [1, 2, 3, 32, 0, 1, 1, 0],  # its ring is ring 1 of 1
                [1, 2, 3, 32, 0, 0, 2, 0],  # two rings of 1
                [1, 2, 3, 32, -1, 0, 1, 0], [1, 2, 3, 32, 0, -1, 1, 0],
                [1, 2, 3, 32, 0, 2 ** 62, 1, 0], [1, 2, 3, 32, 2 ** 62, 0, 1, 0],
                [1, 2, 3, 32, 0, 0, 2 ** 33, 0]):
        assert call([[5, 2, 3, 32, 0, 0, 1, 21], bad], 8) == lib.RAST_E_ARG, bad
        assert failed[0] == 1
        assert out_f[:6].tolist() == [5] * 6 and (out_f[6:] == -7).all()  # the first window's cells only
    for bad_s in (33, 2 ** 32 + 5, -1):  # S past 32 (once read as S mod 2^32) or negative: refused
        got = call([[1, 2, 3, bad_s, 0, 0, 1, 0]], 8)
        assert got in (lib.RAST_E_SUBPIXEL, lib.RAST_E_ARG) and got != lib.RAST_OK and got < 0, (bad_s, got)
    assert call([[1, 2, 3, 2 ** 32 + 5, 0, 0, 1, 0]], 8) == call([[1, 2, 3, 33, 0, 0, 1, 0]], 8)
    xy[0] = np.nan
    assert call([[1, 2, 3, 32, 0, 0, 1, 0]], 8) == lib.RAST_E_ARG and failed[1] == 1  # point 0 bad

"""The quick accumulation of "area" and "accumulate" (csrc/src/coverage_area.c):
rows added whole are first summed in 64-bit arithmetic on a 2^-30 pixel grid,
and a row any of whose levels lies within that sum's error bound of a
rounding tie is added again the exact 128-bit way.  So the uint8 and uint16
levels must be, bit for bit, the levels of the exact way's own value: the
2^-62 fixed point the float outputs come from (which never takes the quick
way), rounded as floor(a62 M / 2^62 + 1/2).  Scenes with many exact ties
(vertices on halves and quarters, diagonals through pixel corners) make a
wrong tie test or a wrong quick sum show; the canvas is smaller than the
shapes, so edges cross the clip's sides too."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle
import oracle_coverage
import rastrum
import strategies as S_
from rastrum._native import ffi, lib


def _fix62(rings, shape, rule, method, s=8):
    """The exact way's a * 2^62 per pixel (uint64), as the float outputs get it."""
    h, w = shape
    pts, sizes, nrings = rastrum._core._points(rings)
    raw = np.zeros((h, w), np.uint64)
    opts = ffi.new("rast_coverage_opts *")
    opts.method = rastrum._coverage.METHODS[method]
    opts.rule = lib.RAST_RULE_NONZERO if rule == "nonzero" else lib.RAST_RULE_EVENODD
    opts.subpixel_bits = s
    opts.sample = lib.RAST_SAMPLE_CENTER
    res = lib.rastpy_polygon_coverage(ffi.from_buffer(raw), h, w, lib.RAST_COVERAGE_FIX62,
                                      ffi.from_buffer("double[]", pts), len(pts), sizes, nrings, opts,
                                      ffi.NULL)
    assert res == 0
    return raw


def _levels(raw, M):
    return np.array([[(int(v) * M + (1 << 61)) >> 62 for v in row] for row in raw], np.int64)


def _exact(rings, shape, rule, method, s):
    """Each pixel's exact value (Fractions, oracle_coverage): "area" the
    region's area; "accumulate" the integral of the winding number (each
    ring here is simple: its signed area), the rule applied to it."""
    if method == "area":
        return oracle_coverage.coverage_exact(rings, shape, rule=rule, subpixel_bits=s)
    a = np.empty(shape, dtype=object)
    a.fill(Fraction(0))
    for r in oracle.snapped_rings(rings, s):
        turn = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(r, r[1:] + r[:1]))
        if turn:
            a = a + (1 if turn > 0 else -1) * oracle_coverage.coverage_exact([r], shape, rule="nonzero",
                                                                                subpixel_bits=s)
    v = np.abs(a)
    if rule == "nonzero":
        return np.minimum(v, 1)
    v = np.vectorize(lambda t: t - 2 * (t // 2))(v)
    return np.vectorize(lambda t: 2 - t if t > 1 else t)(v)


def _check(rings, shape, rule, method, s=8):
    raw = _fix62(rings, shape, rule, method, s)
    exact = None
    for dtype, M in ((np.uint8, 255), (np.uint16, 65535)):
        got = rastrum.polygon_coverage(rings, shape, rule=rule, method=method, subpixel_bits=s,
                                       dtype=dtype).astype(np.int64)
        want = _levels(raw, M)
        # The 2^-62 fixed point is a's floor, so its level can be one
        # short where a level's boundary lies between raw and raw + 1 (the
        # levels of the two differ): there the exact value (oracle_coverage)
        # decides, and at an exact tie, a M + 1/2 an integer while a 2^62
        # is not (a = 1/30: 255/30 = 8.5; a = 9/10), either neighbour is the
        # documented level (docs/coverage.md, "The bound of \"area\"").
        near = np.argwhere(_levels(raw + np.uint64(1), M) != want)
        if len(near):
            if exact is None:
                exact = _exact(rings, shape, rule, method, s)
            for i, j in near:
                lv = oracle_coverage.level(exact[i, j], M)
                tie = (exact[i, j] * M + Fraction(1, 2)).denominator == 1
                want[i, j] = got[i, j] if tie and got[i, j] in (lv - 1, lv) else lv
        bad = np.argwhere(got != want)
        assert not len(bad), "%s %s %s: %d pixel(s) differ, first %s: %d, exact way %d; %s" % (
            method, rule, np.dtype(dtype).name, len(bad), tuple(bad[0]), got[tuple(bad[0])],
            want[tuple(bad[0])], S_.lit(rings))


def _star(rnd, n, c, rmin, rmax, snap):
    ang = (np.arange(n) + rnd.uniform(0, 0.45, n)) * 2 * np.pi / n
    r = rnd.uniform(rmin, rmax, n)
    pts = np.stack([c[0] + r * np.cos(ang), c[1] + r * np.sin(ang)], 1)
    return (np.round(pts * snap) / snap).tolist()


@settings(max_examples=S_.examples(60))
@given(st.integers(3, 40), st.integers(0, 2 ** 32 - 1), st.sampled_from([1, 2, 4, 256]),
       st.sampled_from(["evenodd", "nonzero"]), st.sampled_from(["area", "accumulate"]),
       st.booleans())
def test_quick_levels_are_the_exact_ways(n, seed, snap, rule, method, hole):
    """Star-shaped polygons (fast rows), with a hole or not, overhanging the
    canvas on every side."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(2, 10, 2)
    rl = [_star(rnd, n, c, 1.0, 9.0, snap)]
    if hole:
        rl.append(_star(rnd, max(3, n // 3), c, 0.2, 0.9, snap)[::-1])
    _check(rl, (12, 12), rule, method)


@pytest.mark.parametrize("method", ["area", "accumulate"])
@pytest.mark.parametrize("name, rings", [
    # diagonals through pixel corners and halves: many exact ties (a = 1/2)
    ("diamond", [[(6, 0.5), (11.5, 6), (6, 11.5), (0.5, 6)]]),
    ("thin diagonals", [[(0, 0), (12, 6), (12, 6.5), (0, 0.5)]]),
    ("half pixels", [[(0.5, 0.5), (10.5, 0.5), (10.5, 10.5), (0.5, 10.5)]]),
    ("spikes", [[(6 + (5.5 if k % 2 else 2) * np.cos(k * np.pi / 20),
                  6 + (5.5 if k % 2 else 2) * np.sin(k * np.pi / 20)) for k in range(40)]]),
    ("overhanging shallow edges", [[(-30, 2.25), (40, 3.75), (40, 9.5), (-30, 8)]]),
    # overlaps: the exact way sweeps ("area"), the quick way still sums ("accumulate")
    ("square twice", [[(1.5, 1.5), (9.5, 1.5), (9.5, 9.5), (1.5, 9.5)]] * 2),
])
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_quick_levels_on_ties(name, rings, method, rule):
    _check(rings, (12, 12), rule, method)

"""One small convex ring painted with aa="area" or "accumulate"
(csrc/src/coverage/coverage_small.c, the "loop" family's call, issue 33):
its levels summed in 64 bits on a 2^-26 pixel grid, the call declining to
the engines wherever a level is too near a tie to be sure of; with "ss2"
or "ss4", its samples' spans straight from the vertices.  Its pixels
must be the engines' bit for bit: Canvas.fill_polygon's pixels against
polygon_coverage's uint8 levels of the same ring (an array: the engines'
path, never the small one), and "area"'s against the exact oracle
(tests/oracle_coverage.py), the supersampled ones against the binary
rule's samples counted (polygon_mask on the k-times grid).  Rings of every size round the 24-pixel bound,
on and off pixel lines (exact ties: half pixels, 45-degree sides through
pixel corners), partly off the canvas, at S = 0..16, either rule."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_coverage import M_OF, _n_m, check_area, exact_area
from test_coverage_convex import _hull

SHAPE = (40, 44)


def _samples(ring, rule, k, s, offset):
    """k x k supersampling's uint8 levels from the binary rule alone: the
    ring snapped (half to even) to its own grid, scaled by k, filled by
    polygon_mask on the fine grid of S = s (its samples at (I + o) / k),
    counted per pixel, floor(255 c / k^2 + 1/2)."""
    snapped = np.rint(np.asarray(ring, np.float64) * (1 << (s - k.bit_length() + 1))) / (1 << (s - k.bit_length() + 1))
    fine = rastrum.polygon_mask([snapped * k], (SHAPE[0] * k, SHAPE[1] * k), rule=rule, subpixel_bits=s,
                                sample_offset=offset)
    c = fine.reshape(SHAPE[0], k, SHAPE[1], k).sum(axis=(1, 3)).astype(np.int64)
    return ((255 * c * 2 + k * k) // (2 * k * k)).astype(np.uint8)


def _same(ring, rule, method, s=8, oracle=True, offset=0.5):
    """Canvas.fill_polygon(aa=method) of 255 on 0 equals polygon_coverage's
    uint8 levels (the engines'), which the oracle bounds."""
    want = rastrum.polygon_coverage([ring], SHAPE, rule=rule, method=method, subpixel_bits=s, dtype=np.uint8,
                                    sample_offset=offset)
    c = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
    c.fill_polygon(np.asarray(ring, np.float64), 255, rule=rule, aa=method, subpixel_bits=s, sample_offset=offset)
    assert np.array_equal(c.array, want), "Canvas.fill_polygon(aa=%r) differs: %s" % (method, S_.lit([ring]))
    if oracle and method.startswith("ss"):
        k = int(method[2:])
        if s + k.bit_length() - 1 <= 16:  # (the fine grid's S: polygon_mask's bound)
            assert np.array_equal(want, _samples(ring, rule, k, s + k.bit_length() - 1, offset)), S_.lit([ring])
    elif oracle:
        n, m = _n_m([ring], s)
        check_area(want, exact_area([ring], SHAPE, rule, s), M_OF[np.uint8], n, m, S_.lit([ring]))


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.lists(st.tuples(st.integers(0, 2 ** 16), st.integers(0, 2 ** 16)), min_size=3, max_size=14),
       st.integers(1, 28 * 256), st.integers(-6 * 256, 30 * 256), st.integers(-6 * 256, 30 * 256),
       st.sampled_from([1, 16, 256]), st.sampled_from(["area", "accumulate", "ss2", "ss4", "ss8"]),
       st.sampled_from(["nonzero", "evenodd"]), st.booleans(), st.sampled_from([0.5, 0.0]))
def test_small_convex_rings(pts, size, ox, oy, grid, method, rule, reverse, offset):
    """Hulls of random points scaled to `size`/256 px (up to 28 px: past the
    bound of 24, where the engines take it), anywhere on the canvas or
    partly off it, on a grid of 1/grid px (grid 1: pixel corners, whose
    levels are exact ties or whole), either way round."""
    q = 256 // grid
    h = _hull([((x * size >> 16) // q * q + ox, (y * size >> 16) // q * q + oy) for x, y in pts])
    if len(h) < 3:
        return
    ring = [(x / 256, y / 256) for x, y in (h[::-1] if reverse else h)]
    _same(ring, rule, method, offset=offset)


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.integers(3, 16), st.integers(0, 2 ** 32 - 1), st.floats(0.2, 13.0), st.integers(0, 16),
       st.sampled_from(["area", "accumulate", "ss2", "ss4"]), st.sampled_from([0.5, 0.0]))
def test_regular_rings_every_s(n, seed, rad, s, method, offset):
    """The loop family's rings (a regular polygon of n sides, 0.4 to 26 px
    across, turned at random) at every S: the grid of 2^-26 pixel holds
    S = 16 and the box's products stay in 64 bits."""
    rnd = np.random.default_rng(seed)
    c = rnd.uniform(rad + 1, 40 - rad - 1, 2)
    t = rnd.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(n) / n
    ring = np.ascontiguousarray(np.stack([c[0] + rad * np.cos(t), c[1] + rad * np.sin(t)], 1))
    _same(ring, "nonzero", method, s=s, oracle=s <= 12, offset=offset)


TIES = {
    # sides on half pixels: every pixel along them exactly half covered (a tie)
    "box on half pixels": [(2.5, 3.5), (9.5, 3.5), (9.5, 8.5), (2.5, 8.5)],
    # a diamond whose sides run through pixel corners at 45 degrees: halves
    "diamond through corners": [(8.0, 2.0), (14.0, 8.0), (8.0, 14.0), (2.0, 8.0)],
    # a quarter and three quarters: levels 63.75 and 191.25, not ties, exact sums
    "box on quarter pixels": [(2.25, 3.75), (9.75, 3.75), (9.75, 8.25), (2.25, 8.25)],
    # a triangle of a pixel and a half: one level a tie, the others not
    "small triangle": [(1.0, 1.0), (4.0, 1.0), (1.0, 4.0)],
    # a sliver inside one pixel
    "sliver": [(5.1, 5.1), (5.9, 5.3), (5.2, 5.2)],
    # 24 pixels wide and tall exactly (the bound), and 25
    "24 wide": [(0.25, 1.25), (23.75, 1.25), (23.75, 3.75), (0.25, 3.75)],
    "25 wide": [(0.5, 1.25), (24.5, 1.25), (24.5, 3.75), (0.5, 3.75)],
    "24 tall": [(1.25, 0.25), (3.75, 0.25), (3.75, 23.75), (1.25, 23.75)],
    # a box reaching the canvas's right and bottom edges, and past them
    "at the corner": [(38.3, 35.2), (44.0, 35.2), (44.0, 40.0), (38.3, 40.0)],
    "past the corner": [(40.3, 36.2), (47.0, 36.6), (46.0, 43.0)],
}


@pytest.mark.parametrize("name", sorted(TIES))
def test_ties_and_bounds(name):
    """Both rules, every method of the small path, both sample offsets
    (for "ss2" and "ss4" the same rings put sides and vertices on sample
    rows and columns: top closed, bottom open, left closed, right open)."""
    for rule in ("nonzero", "evenodd"):
        for method in ("area", "accumulate", "ss2", "ss4"):
            for offset in (0.5, 0.0):
                _same(TIES[name], rule, method, offset=offset, oracle=rule == "nonzero" and offset == 0.5)


def test_blend_is_once():
    """A declined ring (ties) paints once: the engines' pixels over a
    background, not the small path's and then theirs (a blend twice)."""
    ring = np.array(TIES["box on half pixels"])
    want = rastrum.polygon_coverage([ring], SHAPE, method="area", dtype=np.uint8).astype(np.int64)
    c = rastrum.Canvas.wrap(np.full(SHAPE, 100, np.uint8))
    c.fill_polygon(ring, 255, aa="area")
    assert np.array_equal(c.array, ((255 * want + 100 * (255 - want) + 127) // 255).astype(np.uint8))

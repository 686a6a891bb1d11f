"""The batch's filler for polygons of few vertices (csrc/src/fillers/small.c)
against the exact oracle.

Batches (rastrum.masks, rastrum.labels, the batch engine with other
options) draw polygons of up to RAST__SMALL_POINTS vertices with the
small filler and larger ones with the AET; both must give the oracle's
pixels.  The cases aim at what the small filler does differently: crossings
clamped to the clip's columns (polygons past the edges), rows taken in
bands as tall as the scratch allows (tall polygons, and a batch whose
largest polygon is small), crossings of equal column (collinear and
repeated points, touching and overlapping rings), both rules, both
roundings, both sample offsets, coordinates near the range limit.
"""
import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _batch, _core
from oracle import oracle_mask

SMALL_POINTS = 256  # RAST__SMALL_POINTS (small.h)

grid = st.integers(-3, 12).map(float)  # few values: collinear, repeated, touching
fine = st.floats(-6, 18, allow_nan=False).map(lambda v: round(v, 3))
coord = st.one_of(grid, fine)
ring = st.lists(st.tuples(coord, coord), min_size=1, max_size=9).map(lambda r: np.array(r, float))
polygon = st.lists(ring, min_size=1, max_size=3)
SHAPE = (11, 13)


def burn(polys, shape, rule, sample_offset=0.5, rounding="exact", subpixel_bits=8):
    """One mask per polygon through the batch engine (no ring turned)."""
    opts = _core.fill_opts("aet", rule, subpixel_bits, sample_offset, rounding)
    out = np.zeros((len(polys),) + tuple(shape), np.uint8)
    _batch.burn(out, [[np.ascontiguousarray(r, float) for r in p] for p in polys], opts, planes=True)
    return out.astype(bool)


@given(st.lists(polygon, min_size=1, max_size=4), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([0, 0.5]), st.sampled_from(["exact", "textbook"]), st.sampled_from([0, 3, 8]))
def test_small_polygons_equal_the_oracle(polys, rule, offset, rounding, s):
    got = burn(polys, SHAPE, rule, offset, rounding, s)
    for k, p in enumerate(polys):
        want = oracle_mask(p, SHAPE, rule=rule, sample_offset=offset, rounding=rounding, subpixel_bits=s)
        assert np.array_equal(got[k], want), k


@settings(max_examples=40)
@given(st.integers(3, 40), st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]),
       st.integers(1, 2))
def test_tall_polygons_drawn_in_bands(n, seed, rule, nrings):
    # A tall polygon of few vertices in a batch of nothing larger: the
    # scratch (the AET's for the largest polygon) holds a band of a few
    # dozen rows, so its rows come in many bands.
    rng = np.random.default_rng(seed)
    rings = [np.stack([rng.uniform(-3, 9, n), rng.uniform(-5, 305, n)], 1) for _ in range(nrings)]
    shape = (300, 7)
    got = burn([rings], shape, rule)
    assert np.array_equal(got[0], oracle_mask(rings, shape, rule=rule))


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from(["evenodd", "nonzero"]))
def test_either_side_of_the_small_filler_s_limit(seed, rule):
    # SMALL_POINTS vertices: the small filler; one more: the AET; the same
    # region drawn both ways, and each equal to the oracle.
    rng = np.random.default_rng(seed)
    polys = []
    for n in (SMALL_POINTS, SMALL_POINTS + 1):
        t = np.sort(rng.uniform(0, 2 * np.pi, n))
        r = rng.uniform(3, 14, n)
        polys.append([np.stack([15 + r * np.cos(t), 15 + r * np.sin(t)], 1)])
    polys.append([polys[0][0][:-1]])  # the small one less a vertex
    shape = (30, 31)
    got = burn(polys, shape, rule)
    for k, p in enumerate(polys):
        assert np.array_equal(got[k], oracle_mask(p, shape, rule=rule)), k


@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=3, max_size=6),
       st.sampled_from([-1, 1]), st.sampled_from(["evenodd", "nonzero"]))
def test_near_the_range_limit(offsets, sign, rule):
    # Vertices far out (the snapped coordinates near RAST_COORD_MAX = 2^27 - 1
    # at S = 8: 524,287 pixels) with edges through the view: crossings far
    # left and right of the clip, clamped to its columns.
    far = sign * 524000.0
    ring = np.array([[far + 50 * dx, 5 + dy] if k % 2 else [5 + dx, 5 + 2 * dy]
                     for k, (dx, dy) in enumerate(offsets)], float)
    got = burn([[ring]], SHAPE, rule)
    assert np.array_equal(got[0], oracle_mask([ring], SHAPE, rule=rule))


@given(st.lists(polygon, min_size=1, max_size=6))
def test_labels_of_small_polygons_equal_the_oracle_in_order(polys):
    lab = rastrum.labels(polys, SHAPE, rule="nonzero", dtype=np.int32)
    want = np.zeros(SHAPE, np.int32)
    for k, p in enumerate(polys):
        want[oracle_mask(p, SHAPE, rule="nonzero")] = k + 1
    assert np.array_equal(lab, want)


# ---- masks into an uninitialised array (merge "fresh") -----------------------

@given(st.lists(polygon, min_size=1, max_size=5), st.sampled_from(["evenodd", "nonzero"]), st.booleans())
def test_fresh_masks_write_every_byte(polys, rule, chunked):
    # A dirty array: every byte must come out 0 or 1, the oracle's; polygons
    # out of view, empty and of 1 or 2 points included by the strategy.
    # `chunked` draws polygon by polygon (as with progress=), each call
    # into its own planes.
    from rastrum import _ml as ml
    polys = polys + [[np.array([[40.0, 40.0], [50.0, 40.0], [45.0, 48.0]])]]  # out of view
    out = np.full((len(polys),) + SHAPE, 0xAB, np.uint8)
    packed = ml._polygons(polys, "masks")
    opts = _core.fill_opts("aet", rule, 8, 0.5)
    ml._burn(out, packed, opts, rule, None, "fresh", True, "polygon", (lambda done: None) if chunked else None)
    for k, p in enumerate(polys):
        assert np.array_equal(out[k], oracle_mask(p, SHAPE, rule=rule).astype(np.uint8)), k


def test_fresh_needs_contiguous_uint8_planes():
    import pytest
    ring = [np.array([[1.0, 1.0], [6.0, 2.0], [3.0, 7.0]])]
    opts = _core.fill_opts("aet", "evenodd", 8, 0.5)
    base = np.full((2, 9, 12), 5, np.uint8)
    for out in (base[:, :, :10], np.full((2, 9, 10), 5, np.int32)):
        before = out.copy()
        with pytest.raises(rastrum.InputError):
            _batch.burn(out, [ring, ring], opts, merge="fresh", planes=True)
        assert np.array_equal(out, before)

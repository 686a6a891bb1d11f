"""Canvas.fill_polygon and the coverage calls on rings that came from a
pickle (or any other route that makes an equal dtype object of its own:
numpy.dtype(numpy.float64) == a.dtype, but not `is`) take the same quick
ways as rings made in the process, as polygon_mask's do
(tests/test_polygon_mask_pickled.py).  The dtype was compared by identity
only (python/rastrum/_canvas.py, _coverage.py, and the C calls of
python/ext/seq.c: _seq.fill, _seq.coverage), and such a ring went the
general way (the same pixels, about 20 times the time: 0.8 -> 12 us for
a Canvas's aa= call).

Here the slower ways are made to raise and the results are held to the
exact oracles: polygon_mask's (tests/oracle.py) for the binary fill, the
exact area's levels (tests/oracle_coverage.py, floor(255 a + 1/2)) blended
as documented (test_coverage_paint.expected) for aa="area" and
"accumulate" (a convex ring: the accumulation is its area).  A Canvas's
first call goes through the Python method (_canvas.py), the next ones
through the remembered C call (_seq.fill); polygon_coverage's and
triangles_coverage's first call with new options through Python
(_coverage.py), the next through _seq.coverage for polygon_coverage.  A
byte-swapped ring (not equal) still takes the general way, with the right
pixels."""

import pickle

import numpy as np
import pytest

import oracle_coverage as oc
import rastrum
from oracle import oracle_mask
from test_coverage_paint import expected

RING = np.array([(1.2, 0.7), (9.6, 2.1), (7.3, 8.8), (2.1, 6.4)], np.float64)
SHAPE = (10, 12)
COLOR = 200


def _boom(*args, **kw):
    raise AssertionError("the slow way was taken")


def _unpickled(a):
    b = pickle.loads(pickle.dumps(a))
    assert b.dtype == a.dtype and b.dtype is not np.dtype(a.dtype.type)  # (the trap itself)
    return b


def _levels(ring, rule="evenodd", s=8):
    cov = oc.coverage_exact([ring], SHAPE, rule=rule, subpixel_bits=s)
    return np.array([[oc.level(a, 255) for a in row] for row in cov], np.int64)


def _canvas():
    rng = np.random.default_rng(7)
    c = rastrum.Canvas(SHAPE, format="gray8")
    c.array[...] = rng.integers(0, 256, SHAPE, dtype=np.uint8)
    return c, c.array.copy()


@pytest.mark.parametrize("aa", ["area", "accumulate"])
def test_canvas_aa_unpickled(monkeypatch, aa):
    """The first call (Python's quick check), then the second (the
    remembered C call alone: the Python quick call made to raise too)."""
    import rastrum._canvas as cv
    monkeypatch.setattr(rastrum._coverage, "fill_polygon_aa", _boom)
    monkeypatch.setattr(rastrum._core, "_points", _boom)
    monkeypatch.setattr(rastrum.Canvas, "_fill_aa", _boom)
    ring = _unpickled(RING)
    lv = _levels(RING)
    c, before = _canvas()
    c.fill_polygon(ring, COLOR, aa=aa)
    once = expected("gray8", before, COLOR, lv)
    assert np.array_equal(c.array, once)
    monkeypatch.setattr(cv, "_lent", _boom)
    c.fill_polygon(ring, COLOR, aa=aa)
    assert np.array_equal(c.array, expected("gray8", once, COLOR, lv))


def test_canvas_binary_unpickled(monkeypatch):
    import rastrum._canvas as cv
    monkeypatch.setattr(rastrum._core, "fill_polygon", _boom)
    ring = _unpickled(RING)
    mask = oracle_mask([RING], SHAPE)
    c, before = _canvas()
    c.fill_polygon(ring, COLOR)
    assert np.array_equal(c.array, np.where(mask, COLOR, before))
    monkeypatch.setattr(cv, "_fill_ring", _boom)
    c.array[...] = before
    c.fill_polygon(ring, COLOR)
    assert np.array_equal(c.array, np.where(mask, COLOR, before))


@pytest.mark.parametrize("method", ["area", "accumulate"])
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_polygon_coverage_unpickled(monkeypatch, method, rule):
    """Options new to the process (subpixel_bits=7: the first call takes
    the Python path), then the remembered C call alone."""
    monkeypatch.setattr(rastrum._core, "_points", _boom)
    ring = _unpickled(RING)
    exp = _levels(RING, rule, 7)
    for rings in (ring, [ring]):
        got = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method=method, subpixel_bits=7)
        assert np.array_equal(got, exp)
    monkeypatch.setattr(rastrum._coverage, "_lent", _boom)
    for rings in (ring, [ring]):
        got = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method=method, subpixel_bits=7)
        assert np.array_equal(got, exp)


def test_triangles_coverage_unpickled(monkeypatch):
    """Its options remembered by a first call on a batch made here, then
    the unpickled batch with the general way's conversions made to raise."""
    made = np.array([RING[:3], RING[[0, 2, 3]]], np.float64)
    exp = _levels(RING)
    assert np.array_equal(rastrum.triangles_coverage(made, SHAPE), exp)
    monkeypatch.setattr(rastrum._coverage, "tris_f64", _boom)
    monkeypatch.setattr(rastrum._coverage, "_ntris", _boom)
    assert np.array_equal(rastrum.triangles_coverage(_unpickled(made), SHAPE), exp)


def test_byte_swapped_ring_right_pixels():
    """'>f8' is not numpy's native float64 (not equal): the general way,
    which reads it right."""
    ring = RING.astype(">f8")
    lv = _levels(RING)
    c, before = _canvas()
    c.fill_polygon(ring, COLOR, aa="area")
    assert np.array_equal(c.array, expected("gray8", before, COLOR, lv))
    assert np.array_equal(rastrum.polygon_coverage(ring, SHAPE), lv)
    assert np.array_equal(rastrum.polygon_coverage([ring], SHAPE), lv)

"""polygon_mask of rings that came from a pickle (or any other route that
makes an equal dtype object of its own: numpy.dtype(numpy.float64) ==
a.dtype, but not `is`) takes the same quick ways as rings made in the
process: one ring straight to C (python/rastrum/__init__.py), a list of
rings snapped from their own arrays (_seq.ring_ptrs, python/ext/seq.c) or
packed in one C pass (_seq.rings).  The dtype was compared by identity
only, and such rings went the general way (the same pixels, several times
the time).  Here the slower ways are made to raise, and the masks are
held to the exact oracle (tests/oracle.py).  A byte-swapped float64 ring
(not equal) still takes the general way, with the right pixels.
"""

import pickle

import numpy as np
import pytest

import rastrum
from oracle import oracle_mask

RING = np.array([(1.2, 0.7), (9.6, 2.1), (7.3, 8.8), (2.1, 6.4)], np.float64)
HOLE = np.array([(3.1, 3.2), (5.2, 5.9), (6.4, 3.3)], np.float64)
SHAPE = (10, 12)


def _boom(*args, **kw):
    raise AssertionError("the slow way was taken")


def _unpickled(a):
    if isinstance(a, list):
        return [_unpickled(r) for r in a]
    b = pickle.loads(pickle.dumps(a))
    assert b.dtype == a.dtype and b.dtype is not np.dtype(a.dtype.type)  # (the trap itself)
    return b


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_one_ring_unpickled(monkeypatch, rule):
    monkeypatch.setattr(rastrum._core, "mask_polygon", _boom)
    ring = _unpickled(RING)
    exp = oracle_mask([RING], SHAPE, rule=rule)
    assert np.array_equal(rastrum.polygon_mask(ring, SHAPE, rule=rule), exp)
    assert np.array_equal(rastrum.polygon_mask([ring], SHAPE, rule=rule), exp)


def test_one_int32_ring_unpickled(monkeypatch):
    monkeypatch.setattr(rastrum._core, "mask_polygon", _boom)
    ring = _unpickled(np.array([(1, 1), (9, 2), (7, 9), (2, 6)], np.int32))
    exp = oracle_mask([ring.astype(np.float64)], SHAPE)
    assert np.array_equal(rastrum.polygon_mask(ring, SHAPE), exp)


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_rings_unpickled(monkeypatch, rule):
    """Snapped from their own arrays: neither packed nor the general way."""
    monkeypatch.setattr(rastrum._core, "mask_polygon", _boom)
    monkeypatch.setattr(rastrum, "_seq_rings", _boom)
    rings = _unpickled([RING, HOLE, RING + 0.5])
    exp = oracle_mask([RING, HOLE, RING + 0.5], SHAPE, rule=rule)
    assert np.array_equal(rastrum.polygon_mask(rings, SHAPE, rule=rule), exp)


def test_rings_unpickled_packed(monkeypatch):
    """A list of float64 and int32 rings (not all float64: packed in one
    C pass), unpickled: packed, not the general way."""
    monkeypatch.setattr(rastrum._core, "mask_polygon", _boom)
    ring32 = np.array([(1, 1), (9, 2), (7, 9), (2, 6)], np.int32)
    rings = _unpickled([RING, ring32, HOLE])
    exp = oracle_mask([RING, ring32.astype(np.float64), HOLE], SHAPE, rule="nonzero")
    assert np.array_equal(rastrum.polygon_mask(rings, SHAPE, rule="nonzero"), exp)


def test_byte_swapped_ring_right_pixels():
    """'>f8' is not numpy's native float64 (not equal): the general way,
    which reads it right."""
    for ring in (RING.astype(">f8"), [RING.astype(">f8"), HOLE.astype(">f8")]):
        rings = ring if isinstance(ring, list) else [ring]
        exp = oracle_mask([np.asarray(r, np.float64) for r in rings], SHAPE)
        assert np.array_equal(rastrum.polygon_mask(ring, SHAPE), exp)

"""masks(..., rule="coco") and labels(..., rule="coco") against pycocotools
itself, bit for bit (skipped when pycocotools is missing): each object's
parts through pycocotools.mask.frPyObjects, united by mask.merge, decoded.
A random corpus of COCO-like objects (several parts, coordinates on the
1/5 grid where pycocotools' walk meets exact halves, and general floats),
then hypothesis on small ones."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import coco

M = pytest.importorskip("pycocotools.mask")


def pycocotools_mask(parts, h, w):
    return M.decode(M.merge(M.frPyObjects(parts, h, w))).astype(bool)


def random_objects(rng, n, h, w):
    objs = []
    for _ in range(n):
        parts = []
        for _ in range(rng.integers(1, 4)):
            k = int(rng.integers(3, 12))
            cx, cy = rng.uniform(-5, w + 5), rng.uniform(-5, h + 5)
            r = rng.uniform(0.5, min(h, w) / 2)
            xy = np.stack([cx + r * rng.uniform(-1, 1, k), cy + r * rng.uniform(-1, 1, k)], 1)
            if rng.random() < 0.5:
                xy = np.round(xy * 5) / 5  # the 1/5 grid: pycocotools' ties
            parts.append(xy.ravel().tolist())
        objs.append(parts)
    return objs


def test_masks_and_labels_equal_pycocotools_on_a_random_corpus():
    rng = np.random.default_rng(37)
    h, w = 61, 83
    objs = random_objects(rng, 200, h, w)
    want = np.stack([pycocotools_mask(o, h, w) for o in objs])
    for polys in (coco.polygons(objs), [coco.rings(o) for o in objs]):
        got = rastrum.masks(polys, (h, w), rule="coco")
        assert got.dtype == bool and got.shape == want.shape
        bad = np.flatnonzero((got != want).any(axis=(1, 2)))
        assert not len(bad), "objects differing from pycocotools: %s" % bad[:10].tolist()
    # the exact rule differs from pycocotools' (what rule="coco" is for)
    assert (rastrum.masks(coco.polygons(objs), (h, w)) != want).any()
    lab, count = rastrum.labels(coco.polygons(objs), (h, w), dtype=np.uint16, overlap=True, rule="coco")
    ref = np.zeros((h, w), np.uint16)
    for k, m in enumerate(want):
        ref[m] = k + 1
    assert np.array_equal(lab, ref) and np.array_equal(count, want.sum(axis=0))
    vals = rng.integers(1, 1000, len(objs))
    lab = rastrum.labels(coco.polygons(objs), (h, w), vals, rule="coco")
    ref = np.zeros((h, w), np.int32)
    for v, m in zip(vals, want):
        ref[m] = v
    assert np.array_equal(lab, ref)


coord = st.one_of(st.integers(-30, 130).map(lambda v: v / 5.0),
                  st.floats(-8, 30, allow_nan=False, allow_infinity=False))
part = st.lists(coord, min_size=6, max_size=16).map(lambda v: v[:len(v) // 2 * 2])


@settings(deadline=None, max_examples=150)
@given(st.lists(st.lists(part, min_size=1, max_size=3), min_size=1, max_size=4), st.integers(1, 24),
       st.integers(1, 24))
def test_masks_coco_matches_pycocotools(objs, h, w):
    got = rastrum.masks([coco.rings(o) for o in objs], (h, w), rule="coco")
    for k, o in enumerate(objs):
        assert np.array_equal(got[k], pycocotools_mask(o, h, w)), k


def test_coco_rule_edges():
    assert rastrum.masks([], (3, 4), rule="coco").shape == (0, 3, 4)
    assert not rastrum.masks([[]], (3, 4), rule="coco").any()
    assert rastrum.masks([[(0, 0), (2, 0), (2, 2)]], (0, 4), rule="coco").shape == (1, 0, 4)
    with pytest.raises(rastrum.InputError, match="rule=\"coco\".*subpixel_bits"):
        rastrum.masks([[(0, 0), (2, 0), (2, 2)]], (3, 4), rule="coco", subpixel_bits=4)
    with pytest.raises(rastrum.InputError, match=r"labels: polygon 1: point \(1e\+30, 0.0\)"):
        rastrum.labels([[(0, 0), (2, 0), (2, 2)], [(0, 0), (1e30, 0), (2, 2)]], (3, 4), rule="coco")

"""rastrum.coco.polygons: COCO segmentations read in one C pass
(rastrum._seq, python/ext/seq.c) into a packed batch.

The points are checked against numpy's own conversion of each part (the
reference: float64 of each number, the odd last one dropped), the masks
against the exact oracle (union of the parts), and every input the C pass
declines against coco.rings, which then judges it.
"""
import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import _seq, coco
from rastrum._core import InputError
from test_ml import union_oracle

SHAPE = (13, 17)

number = st.one_of(
    st.integers(-3, 20),
    st.floats(-3, 20, allow_nan=False).map(lambda v: round(v, 3)),
    st.integers(-2**70, 2**70),  # ints a double cannot hold exactly
    st.floats(allow_nan=False, allow_infinity=False, width=64),
)
part = st.lists(number, max_size=13)
segmentation = st.one_of(st.lists(part, max_size=4), part.filter(lambda p: len(p) > 0))


def reference(segs):
    """(points, ring sizes, rings per object) from numpy's conversion of
    each part, independently of the C pass."""
    pts, sizes, counts = [], [], []
    for s in segs:
        parts = [s] if s and not isinstance(s[0], list) else s
        n = 0
        for p in parts:
            a = np.array(p, np.float64)[: len(p) // 2 * 2].reshape(-1, 2)
            if len(a):
                pts.append(a)
                sizes.append(len(a))
                n += 1
        counts.append(n)
    return (np.concatenate(pts) if pts else np.zeros((0, 2)), np.array(sizes, np.uint32),
            np.array(counts, np.uint32))


@given(st.lists(segmentation, max_size=6))
def test_points_are_numpys_conversion(segs):
    b = coco.polygons(segs)
    pts, sizes, counts = reference(segs)
    assert b.points.dtype == np.float64 and b.points.shape == pts.shape
    assert b.points.tobytes() == pts.tobytes()  # bit for bit (-0.0 included)
    assert b.ring_sizes.tolist() == sizes.tolist()
    assert b.rings_per_polygon.tolist() == counts.tolist()
    assert len(b) == len(segs)
    for k, s in enumerate(segs):  # the same rings as coco.rings, empty parts left out
        want = [r for r in coco.rings(s) if len(r)]
        assert [r.tobytes() for r in b[k]] == [r.tobytes() for r in want]


small = st.one_of(st.integers(-3, 20), st.floats(-3, 20, allow_nan=False).map(lambda v: round(v, 2)))
small_seg = st.lists(st.lists(small, min_size=0, max_size=12), min_size=0, max_size=3)


@given(st.lists(small_seg, min_size=1, max_size=4))
def test_masks_and_labels_equal_the_oracle(segs):
    b = coco.polygons(segs)
    got = rastrum.masks(b, SHAPE)
    want = []
    for s in segs:  # the union rule: each part turned to positive area, non-zero
        rings = [np.array(p, float)[: len(p) // 2 * 2].reshape(-1, 2) for p in s]
        want.append(union_oracle([r for r in rings if len(r) >= 3], SHAPE))
    assert np.array_equal(got, np.array(want).reshape(got.shape))
    assert np.array_equal(got, rastrum.masks([coco.rings(s) for s in segs], SHAPE))
    lab = rastrum.labels(b, SHAPE, dtype=np.uint16)
    assert np.array_equal(lab, rastrum.labels([coco.rings(s) for s in segs], SHAPE, dtype=np.uint16))


def test_declined_inputs_take_the_python_path():
    """Whatever the C pass does not read (tuples, arrays, bools, numpy
    scalars, ints past a double) still works through coco.rings, or fails
    as coco.rings fails, naming the object."""
    seg = [[1, 1, 6, 1, 6, 5, 1, 5]]
    base = coco.polygons([seg])
    for other in ([(1, 1, 6, 1, 6, 5, 1, 5)], [np.array(seg[0], np.float32)], [[np.float64(v) for v in seg[0]]],
                  np.array(seg, float)):
        assert _seq.flat([other]) is None
        b = coco.polygons([other])
        assert b.points.tolist() == base.points.tolist()
        assert np.array_equal(rastrum.masks(b, SHAPE), rastrum.masks(base, SHAPE))
    assert _seq.flat((seg,)) is None and coco.polygons((seg,)).points.tolist() == base.points.tolist()
    assert _seq.flat([[[True, 1, 2, 3, 4, 5]]]) is None
    assert _seq.flat([[[2**1100, 1, 2, 3, 4, 5]]]) is None  # OverflowError in C: declined, not raised
    with pytest.raises(InputError, match=r"polygons: object 1: rings: part 0"):
        coco.polygons([seg, [["1", "2", "3", "4", "5", "6"]]])
    with pytest.raises(InputError, match=r"polygons: object 0: rings: an RLE segmentation"):
        coco.polygons([{"size": [4, 4], "counts": b"4"}])
    with pytest.raises(InputError, match=r"polygons: segmentations must be a list .* not dict"):
        coco.polygons({"size": [4, 4], "counts": b"4"})
    with pytest.raises(InputError, match=r"not int"):
        coco.polygons(3)


def test_the_batch_as_a_sequence():
    b = coco.polygons([[[0, 0, 4, 0, 4, 4]], [], [[1, 1, 2, 1, 2, 2], [5.5, 5, 7, 5, 7, 7, 9]]])
    assert len(b) == 3 and repr(b) == "<rastrum polygons: 3 polygons, 3 rings, 9 points>"
    assert [len(p) for p in b] == [1, 0, 2]
    assert b[-1][1].tolist() == [[5.5, 5.0], [7.0, 5.0], [7.0, 7.0]]
    assert [len(p) for p in b[1:]] == [0, 2]
    with pytest.raises(IndexError):
        b[3]
    with pytest.raises(ValueError):
        b.points[0, 0] = 1.0  # read-only: the batch is what the masks are drawn from
    m = rastrum.masks(b, (8, 10))
    assert m.shape == (3, 8, 10) and m[1].sum() == 0
    assert isinstance(b, rastrum.Polygons)


def test_no_segmentations():
    b = coco.polygons([])
    assert len(b) == 0 and b.points.shape == (0, 2)
    assert rastrum.masks(b, (3, 4)).shape == (0, 3, 4)


def test_made_from_tables():
    """rastrum.Polygons from the tables: checked, copied only when it must
    be, and the caller's arrays stay writable."""
    pts = np.array([[0, 0], [4, 0], [4, 4], [1, 1], [3, 1], [2, 3]], float)
    b = rastrum.Polygons(pts, [3, 3], [2])
    assert pts.flags.writeable and b.points.base is pts
    assert np.array_equal(rastrum.masks(b, (5, 5))[0], rastrum.masks([[pts[:3], pts[3:]]], (5, 5))[0])
    b32 = rastrum.Polygons(pts.astype(np.float32), np.array([3, 3], np.int64), (1, 1))
    assert b32.points.dtype == np.float64 and len(b32) == 2
    for args, msg in (((pts, [3, 2], [2]), "tables disagree: 6 points, ring sizes summing to 5"),
                      ((pts, [3, 3], [1]), "rings per polygon summing to 1"),
                      ((pts, [6, 0], [2]), r"each >= 1"),
                      ((pts.ravel(), [6], [1]), r"points must be \(P, 2\).*shapes \(12,\)")):
        with pytest.raises(InputError, match=msg):
            rastrum.Polygons(*args)

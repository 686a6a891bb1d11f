"""What rastrum.masks and rastrum.labels return: ordinary numpy arrays
that own their memory (writable, C-contiguous, no base), so they can be
written to, pickled and handed to frameworks without a copy; and each
plane is the exact oracle's mask of its polygon."""

import pickle

import numpy as np

import rastrum
from oracle import oracle_mask


def _polys():
    return [[np.array([[1.5, 1.0], [9.0, 2.5], [6.0, 8.5]])],
            [np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]),
             np.array([[3.0, 3.0], [7.0, 3.0], [7.0, 6.0]])]]


def _owned(a):
    assert a.flags.writeable and a.flags.c_contiguous and a.flags.owndata and a.base is None
    b = pickle.loads(pickle.dumps(a))
    assert b.dtype == a.dtype and np.array_equal(a, b)


def test_masks_output_is_an_owned_c_array_equal_to_the_oracle():
    m = rastrum.masks(_polys(), (10, 12))
    assert m.dtype == bool and m.shape == (2, 10, 12)
    _owned(m)
    for k, rings in enumerate(_polys()):
        want = np.zeros((10, 12), bool)
        for r in rings:
            want |= oracle_mask([r], (10, 12), rule="nonzero")
        np.testing.assert_array_equal(m[k], want)
    m[0, 0, 0] = True  # writable


def test_labels_output_is_an_owned_c_array():
    lab, count = rastrum.labels(_polys(), (10, 12), dtype=np.uint8, overlap=True)
    _owned(lab)
    _owned(count)

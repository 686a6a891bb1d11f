"""polygon_mask's list of float64 rings snapped straight from the arrays.

A list of several C-contiguous, aligned (m >= 1, 2) float64 arrays (a
paragraph's glyphs, a map's countries) goes to C as the arrays' addresses
and sizes (rastrum._seq.ring_ptrs, python/glue/fill.c rastpy_mask_rings),
each ring snapped from its own memory, not packed into one buffer first
(issue 33).  Checked here: ring_ptrs' answer against numpy (the addresses,
sizes, total, the arrays kept), None for every other form (which the
packing path then takes), the masks against the exact oracle
(tests/oracle.py) and against the same rings as lists, a bad point's
message the general path's, through the array head and the capsule route.
"""

import gc

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from rastrum import _seq
from strategies import RULES, examples
from test_seq_arrays import _view, route  # noqa: F401 (a fixture)

_F64 = np.dtype(np.float64)


def ptrs(rings):
    return _seq.ring_ptrs(rings, np.ndarray, _F64)


def test_addresses_sizes_and_the_arrays_kept():
    rings = [np.arange(2 * m, dtype=np.float64).reshape(m, 2) + m for m in (3, 1, 7)]
    ids = [id(r) for r in rings]
    got = ptrs(rings)
    assert got is not None
    addr, sizes, n, keep = got
    assert type(addr) is bytes and type(sizes) is bytes and type(keep) is tuple
    assert list(np.frombuffer(addr, np.uintp)) == [r.ctypes.data for r in rings]
    assert list(np.frombuffer(sizes, np.uint32)) == [3, 1, 7] and n == 11
    rings.clear()
    gc.collect()
    assert [id(r) for r in keep] == ids  # the arrays live as long as the tuple


@pytest.mark.parametrize("how", ["fortran", "strided", "reversed", "columns"])
def test_other_layouts_are_left_to_the_packing(how, route):  # noqa: F811
    good = np.array([[0.5, 0.5], [4.0, 1.0], [2.0, 3.0]])
    assert ptrs([good, _view(good * 2, how)]) is None
    assert ptrs([good, good.astype(np.int32)]) is None
    assert ptrs([good, np.zeros((0, 2))]) is None
    assert ptrs([good, [(0, 0), (1, 0), (0, 1)]]) is None
    assert ptrs([]) is None


def test_a_list_of_pairs_first_leaves_the_head_route_on():
    prev = _seq.use_head(True)
    try:
        assert ptrs([[(0.0, 0.0), (3.0, 0.0), (0.0, 3.0)], np.ones((3, 2))]) is None
        assert _seq.use_head(True) is True  # (not judged by a list's "head")
    finally:
        _seq.use_head(prev)


def test_unaligned_is_left_to_the_packing(route):  # noqa: F811
    raw = np.zeros(6 * 8 + 1, np.uint8)
    a = np.frombuffer(raw.data, np.float64, 6, 1).reshape(3, 2)
    b = np.array([[1.0, 1.0], [5.0, 1.0], [3.0, 4.0]])
    if route:
        assert ptrs([b, a]) is None
    assert np.array_equal(rastrum.polygon_mask([b, a], (6, 6)), rastrum.polygon_mask([b, a.copy()], (6, 6)))


@st.composite
def glyph_rings(draw):
    h, w = draw(st.integers(1, 24)), draw(st.integers(1, 24))
    rings = []
    for _ in range(draw(st.integers(2, 12))):
        m = draw(st.integers(3, 7))
        cx, cy = draw(st.floats(-4, w + 4)), draw(st.floats(-4, h + 4))
        pts = [(cx + draw(st.floats(-5, 5)), cy + draw(st.floats(-5, 5))) for _ in range(m)]
        rings.append(pts)
    return rings, (h, w)


@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(15), deadline=None)
@given(scene=glyph_rings(), head=st.booleans())
def test_masks_match_the_oracle_and_the_lists(rule, scene, head):
    rings, shape = scene
    arrays = [np.array(r, np.float64) for r in rings]
    prev = _seq.use_head(head)
    try:
        got = rastrum.polygon_mask(arrays, shape, rule=rule)
    finally:
        _seq.use_head(prev)
    assert np.array_equal(got, rastrum.polygon_mask(rings, shape, rule=rule))
    assert np.array_equal(got, oracle_mask(rings, shape, rule=rule))


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), 1e12])
def test_a_bad_point_says_what_the_general_path_says(bad, route):  # noqa: F811
    rng = np.random.default_rng(5)
    rings = [rng.uniform(0, 30, (int(rng.integers(3, 8)), 2)) for _ in range(9)]
    lists = [r.tolist() for r in rings]
    rings[6][2, 1] = lists[6][2][1] = bad
    msgs = []
    for src in (rings, lists):
        with pytest.raises(rastrum.InputError) as e:
            rastrum.polygon_mask(src, (32, 32))
        msgs.append(str(e.value))
    assert msgs[0] == msgs[1] and "ring 6, point 2" in msgs[0]

"""polygon_mask's list of rings packed as bytes (issue 33): _seq.rings with
as_bytes packs the same points and ring sizes as its bytearray form (or
refuses the same inputs), rastpy_mask_packed takes them as they are and
refuses memory not aligned for its items (RASTPY_E_ALIGN, then the general
path packs anew), and the masks of lists of rings in every form that path
takes are the exact ones (tests/oracle.py, rational arithmetic)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core, _seq
from oracle import oracle_mask
from strategies import examples

lib, ffi = _core.lib, _core.ffi


def _forms(rings):
    """The rings as a list of float64 arrays, of int32 arrays (rounded), of
    lists of (x, y) tuples, and as one ring of (x, y) pairs (the first)."""
    f64 = [np.ascontiguousarray(r, np.float64) for r in rings]
    return {
        "f64": f64,
        "i32": [np.round(r).astype(np.int32) for r in f64],
        "tuples": [[(float(x), float(y)) for x, y in r] for r in f64],
        "pairs": [(float(x), float(y)) for x, y in f64[0]],
    }


_ring = st.lists(st.tuples(st.integers(-8, 72), st.integers(-8, 72)), min_size=3, max_size=9)


@settings(max_examples=examples(40))
@given(rings=st.lists(_ring, min_size=2, max_size=4))
def test_bytes_form_packs_as_bytearray(rings):
    rings = [np.array(r, np.float64) / 4 for r in rings]
    for name, form in _forms(rings).items():
        a = _seq.rings(form, np.ndarray, _core._RING_DTYPES)
        b = _seq.rings(form, np.ndarray, _core._RING_DTYPES, 1)
        assert a is not None and b is not None, name
        assert type(b[0]) is bytes and bytes(a[0]) == b[0], name
        if a[1] is None:
            assert b[1] is None, name
        else:
            assert type(b[1]) is bytes and bytes(a[1]) == b[1], name


@pytest.mark.parametrize("form", [
    [np.zeros((3, 2), np.float32), np.zeros((3, 2))],   # a dtype it does not read
    [np.zeros((3, 2)), [(0, 0), (1, 1), (2, 0)]],       # arrays and pairs mixed
    [np.zeros((3, 3)), np.zeros((3, 2))],               # not (N, 2)
])
def test_bytes_form_refuses_as_bytearray(form):
    assert _seq.rings(form, np.ndarray, _core._RING_DTYPES) is None
    assert _seq.rings(form, np.ndarray, _core._RING_DTYPES, 1) is None


def test_misaligned_memory_refused():
    rings = [np.array([(1, 1), (9, 1), (9, 7), (1, 7)], np.float64), np.array([(3, 3), (3, 5), (6, 5)], np.float64)]
    raw, sizes = _seq.rings(rings, np.ndarray, _core._RING_DTYPES, 1)
    opts = _core.fill_opts("aet", "nonzero", 8, 0.5, "exact", "exact")
    want = rastrum.polygon_mask(rings, (10, 12), rule="nonzero")
    mask = np.zeros((10, 12), bool)
    assert lib.rastpy_mask_packed(ffi.from_buffer(mask), 10, 12, raw, 7, sizes, 2, opts) == 0
    assert (mask == want).all() and want.any()
    shifted = bytearray(len(raw) + 1)
    shifted[1:] = raw
    odd = ffi.from_buffer("char[]", shifted) + 1  # the same points one byte on: not aligned for a double
    assert lib.rastpy_mask_packed(ffi.from_buffer(mask), 10, 12, odd, 7, sizes, 2, opts) == lib.RASTPY_E_ALIGN
    odd_sizes = ffi.from_buffer("char[]", bytearray(b"\0" + sizes)) + 1
    assert lib.rastpy_mask_packed(ffi.from_buffer(mask), 10, 12, raw, 7, odd_sizes, 2,
                                  opts) == lib.RASTPY_E_ALIGN


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
@settings(max_examples=examples(40))
@given(rings=st.lists(_ring, min_size=2, max_size=4), offset=st.sampled_from([0.5, 0.0]))
def test_list_of_rings_matches_oracle(rule, rings, offset):
    rings = [np.array(r, np.float64) / 4 for r in rings]
    forms = _forms(rings)
    want = oracle_mask(forms["f64"], (16, 18), rule=rule, sample_offset=offset)
    for name in ("f64", "i32", "tuples"):
        got = rastrum.polygon_mask(forms[name], (16, 18), rule=rule, sample_offset=offset)
        exact = want if name != "i32" else oracle_mask(forms["i32"], (16, 18), rule=rule, sample_offset=offset)
        assert got.dtype == bool and got.shape == (16, 18)
        assert (got == exact).all(), name


def test_bad_point_still_named():
    """A bad point in a later ring: the packed call refuses it and the
    general path names it, as before."""
    rings = [np.array([(1, 1), (9, 1), (9, 7)], np.float64), np.array([(3, 3), (np.nan, 5), (6, 5)], np.float64)]
    with pytest.raises(rastrum.InputError, match="ring 1, point 1"):
        rastrum.polygon_mask(rings, (10, 12))


def test_list_of_rings_takes_the_packed_call(monkeypatch):
    """Lists of rings in the forms _seq.rings reads are filled by the packed
    call alone: the general path is not reached."""
    rings = [np.array([(1, 1), (9, 1), (9, 7), (1, 7)], np.float64), np.array([(3, 3), (3, 5), (6, 5)], np.float64)]
    want = rastrum.polygon_mask(rings, (10, 12))

    def general(*args):
        raise AssertionError("the general path")

    monkeypatch.setattr(_core, "mask_polygon", general)
    for form in _forms(rings).values():
        got = rastrum.polygon_mask(form if type(form[0]) is not tuple else [form, form[:3]], (10, 12))
        assert got.any()
    assert (rastrum.polygon_mask(rings, (10, 12)) == want).all()

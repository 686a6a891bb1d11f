"""polygon_coverage's common call made whole in C (rastrum._seq.coverage,
python/ext/seq.c; issue 33): one small float64 ring into a small uint8 or
uint16 array, its options those the general path has checked and
remembered.  Its levels are the exact ones (oracle_coverage: exact
rational area and sample counts, not the C code), the same bits as the
general path's; everything it declines (returns None for) takes the
general path, with its checks and messages; and it lends the calling
thread's scratch as _coverage._lent does."""

import threading
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage
import rastrum
import strategies as S_
from rastrum import _coverage as C
from rastrum._core import InputError

HEXA = np.array([[10.3, 5.2], [20.1, 8.7], [22.4, 18.2], [14.2, 24.9], [6.1, 19.3], [4.4, 11.1]])


def _quick(ring, shape, method="area", rule="evenodd", dtype=np.uint8):
    """The C call itself (None: declined), its key remembered first."""
    rastrum.polygon_coverage(ring, shape, rule=rule, method=method, dtype=dtype)
    return C._cov_quick(ring, shape, method, rule, 8, 0.5, dtype)


def _general(ring, shape, method, rule, dtype):
    """The same call by the general path (a list of (x, y) lists: not C's)."""
    return rastrum.polygon_coverage([ring.tolist()], shape, rule=rule, method=method, dtype=dtype)


@settings(max_examples=S_.examples(25))
@given(st.lists(st.tuples(st.floats(-2, 12), st.floats(-2, 12)), min_size=3, max_size=7),
       st.sampled_from(["area", "ss4"]), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([np.uint8, np.uint16]))
def test_the_c_call_gives_the_exact_levels(pts, method, rule, dtype):
    ring = np.array(pts, np.float64)
    shape = (9, 10)
    got = _quick(ring, shape, method, rule, dtype)
    assert got is not None and got.dtype == np.dtype(dtype) and got.shape == shape
    M = np.iinfo(dtype).max
    if method == "ss4":
        want = np.array(oracle_coverage.coverage_ss([pts], shape, 4, rule=rule, M=M), np.int64)
        assert np.array_equal(got.astype(np.int64), want)
    else:
        exact = oracle_coverage.coverage_exact([pts], shape, rule=rule)
        for (i, j), a in np.ndenumerate(exact):
            lv = oracle_coverage.level(a, M)
            tie = (a * M + Fraction(1, 2)).denominator == 1  # either neighbour (docs/coverage.md)
            assert got[i, j] == lv or (tie and got[i, j] == lv - 1), (i, j, a, got[i, j])
    assert np.array_equal(got, _general(ring, shape, method, rule, dtype))


@pytest.mark.parametrize("method", ["area", "accumulate", "ss2", "ss4", "ss16"])
@pytest.mark.parametrize("shape", [(32, 32), (1, 1), (512, 512), (3, 700)])
def test_the_c_call_is_the_general_path(method, shape):
    """The very bits of the general path, the ring overhanging or outside the
    array too (rows and columns cleared), the ring alone or in a list."""
    for ring in (HEXA, HEXA - 9.0, HEXA * 0.3 + 0.2):
        got = _quick(ring, shape, method, "nonzero")
        assert got is not None
        assert np.array_equal(got, _general(ring, shape, method, "nonzero", np.uint8))
        assert np.array_equal(C._cov_quick([ring], shape, method, "nonzero", 8, 0.5, np.uint8), got)
        assert np.array_equal(rastrum.polygon_coverage(ring, shape, rule="nonzero", method=method), got)


def test_what_the_c_call_declines():
    """None for all but its common call: the general path has it."""
    _quick(HEXA, (32, 32))
    ok = dict(rings=HEXA, shape=(32, 32), method="area", rule="evenodd", s=8, offset=0.5, dtype=np.uint8)

    def q(**kw):
        a = dict(ok, **kw)
        return C._cov_quick(a["rings"], a["shape"], a["method"], a["rule"], a["s"], a["offset"], a["dtype"])

    assert q() is not None
    big = np.ascontiguousarray(np.c_[np.cos(np.arange(257)), np.sin(np.arange(257))] * 5 + 9)
    for kw in (dict(shape=(513, 512)), dict(shape=(True, 32)), dict(shape=(np.int64(32), 32)),
               dict(shape=[32, 32]), dict(shape=(0, 32)), dict(shape=(32, -1)), dict(shape=(32, 32, 1)),
               dict(rings=np.asfortranarray(HEXA)), dict(rings=HEXA[::-1]), dict(rings=HEXA.astype(np.float32)),
               dict(rings=HEXA[:2]), dict(rings=big), dict(rings=[HEXA, HEXA]), dict(rings=HEXA.tolist()),
               dict(rings=HEXA.astype(">f8")), dict(s=8.0), dict(s=True), dict(offset=1), dict(method="Area"),
               dict(rule=None), dict(dtype=[("a", "u1")]), dict(dtype=np.float32)):
        assert q(**kw) is None, kw


@pytest.mark.parametrize("bad", [np.nan, np.inf, 1e12])
def test_a_bad_vertex_is_the_general_paths_error(bad):
    ring = HEXA.copy()
    _quick(ring, (32, 32))
    ring[2, 1] = bad
    assert C._cov_quick(ring, (32, 32), "area", "evenodd", 8, 0.5, np.uint8) is None
    with pytest.raises(InputError) as c_call:
        rastrum.polygon_coverage(ring, (32, 32))
    with pytest.raises(InputError) as general:
        rastrum.polygon_coverage([ring.tolist()], (32, 32))
    assert str(c_call.value) == str(general.value)


def test_the_c_call_lends_this_threads_scratch():
    """A fresh thread: its first call makes its block (the general path),
    a larger one through C grows it (_keep), kept for the next."""
    seen = {}

    def run():
        small = HEXA * 0.2
        seen["first"] = rastrum.polygon_coverage(small, (8, 8))
        sc = C._tls.sc
        seen["before"] = sc.size
        ring = np.ascontiguousarray(np.c_[np.cos(np.arange(200) * 0.1), np.sin(np.arange(200) * 0.1)] * 200 + 250)
        seen["got"] = C._cov_quick(ring, (500, 500), "area", "evenodd", 8, 0.5, np.uint8)
        seen["after"], seen["want"] = sc.size, sc.want
        seen["general"] = _general(ring, (500, 500), "area", "evenodd", np.uint8)

    t = threading.Thread(target=run)
    t.start()
    t.join()
    assert seen["got"] is not None and np.array_equal(seen["got"], seen["general"])
    assert seen["after"] >= seen["want"] > seen["before"]

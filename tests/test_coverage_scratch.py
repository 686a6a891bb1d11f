"""The coverage calls' scratch, kept between calls (one block per thread,
python/glue/coverage.h's rastpy_scratch): whether a call runs in the kept
block, in a block of its own (too large for the kept one, or past the cap)
or with none lent, its output is the same; the block grows to what a call
wanted, up to the cap; threads keep their own."""
import threading

import numpy as np
import pytest

import rastrum
from rastrum import _coverage as C
from rastrum._native import ffi, lib


def _ngon(n, r, c=(40.0, 30.0)):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t) * (1 + 0.3 * np.sin(5 * t))], 1)


SCENES = [[_ngon(n, r)] for n, r in ((5, 7.5), (400, 25.3), (7, 3.2), (3000, 28.9), (12, 20.1))]


def _unlent(rings, shape, method):
    """The same call with no scratch lent (the glue's own malloc)."""
    pts, sizes, nrings = rastrum._core._points(rings)
    opts = C._opts(method, "evenodd", 8, 0.5, "test")
    raw = np.zeros(shape, np.uint8)
    assert lib.rastpy_polygon_coverage(ffi.from_buffer(raw), shape[0], shape[1], lib.RAST_COVERAGE_U8,
                                       ffi.from_buffer("double[]", pts), len(pts), sizes, nrings, opts,
                                       ffi.NULL) == 0
    return raw


@pytest.mark.parametrize("method", ["area", "accumulate", "ss4"])
def test_kept_block_gives_the_same_output(method):
    shape = (60, 80)
    for rings in SCENES + SCENES[::-1]:  # growing, shrinking, growing again
        assert np.array_equal(rastrum.polygon_coverage(rings, shape, method=method), _unlent(rings, shape, method))
    sc = C._tls.sc
    assert sc.size >= sc.want > 0 and sc.buf != ffi.NULL


def test_the_block_grows_to_the_cap_and_no_further(monkeypatch):
    """Under a cap of 64 KB: the small scenes' wants are kept, the large
    ones (400 and 3000 edges) run in blocks of their own, leave the kept
    block as it was and still give the same output."""
    monkeypatch.setattr(C, "_SCRATCH_KEEP", 64 << 10)
    result = {}

    def run():  # a fresh thread: a fresh block
        shape, seen = (60, 80), []
        for r in SCENES:
            out = rastrum.polygon_coverage(r, shape, method="area")
            sc = C._tls.sc
            seen.append((sc.want, sc.size, np.array_equal(out, _unlent(r, shape, "area"))))
        result["seen"] = seen

    t = threading.Thread(target=run)
    t.start()
    t.join()
    seen = result["seen"]
    assert all(same for _, _, same in seen)
    big = [k for k, (want, _, _) in enumerate(seen) if want > 64 << 10]
    assert big == [1, 3]  # the 400- and 3000-gons
    for k, (want, size, _) in enumerate(seen):
        assert size <= 64 << 10
        assert (size == seen[k - 1][1]) if k in big else (size >= want)


def test_threads_keep_their_own_blocks():
    shape = (60, 80)
    want = [_unlent(r, shape, "area") for r in SCENES]
    bad, blocks, keep = [], set(), []

    def run(k):
        for i in range(30):
            j = (i + k) % len(SCENES)
            if not np.array_equal(rastrum.polygon_coverage(SCENES[j], shape, method="area"), want[j]):
                bad.append((k, j))
        blocks.add(int(ffi.cast("uintptr_t", C._tls.sc.buf)))
        keep.append(C._tls.buf)  # alive past the thread: a later thread's block cannot reuse its memory

    ts = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    assert not bad and len(blocks) == 4

"""python/glue/zonal.c checks each window's table, S and options before it
allocates the window's buffer (docs/bad-input.md): a window it refuses is
its status, never RASTPY_E_NOMEM for a buffer it would not have used."""

import numpy as np

from rastrum._native import ffi, lib


def test_zonal_checks_before_allocating():
    """A window of 2**30 - 1 squared cells (no such buffer can be had) with
    a bad S or method: its status, not RASTPY_E_NOMEM."""
    xy = np.array([0.0, 0.0, 3.0, 0.0, 3.0, 2.0])
    sizes = np.array([3], np.uint32)
    out = np.zeros(4, np.int64), np.zeros(4, np.int64), np.zeros(4)
    failed = ffi.new("int64_t[2]")
    big = (1 << 30) - 1
    for method, s, want in ((lib.RAST_AA_AREA, 33, lib.RAST_E_SUBPIXEL), (lib.RAST_AA_SS4, 8, lib.RAST_E_WIDE),
                            (lib.RAST_AA_AREA, 1 << 32, lib.RAST_E_SUBPIXEL)):
        opts = ffi.new("rast_coverage_opts *", {"method": method, "rule": 0, "subpixel_bits": 0})
        win = np.array([[4, big, big, s, 0, 0, 1, 0]], np.int64)
        got = lib.rastpy_window_fractions64(1, ffi.from_buffer("int64_t[]", win), ffi.from_buffer("double[]", xy), 3,
                                            ffi.from_buffer("uint32_t[]", sizes), 1, opts, 10,
                                            ffi.from_buffer("int64_t[]", out[0]), ffi.from_buffer("int64_t[]", out[1]),
                                            ffi.from_buffer("double[]", out[2]), 4, failed)
        assert got == want and failed[0] == 0 and failed[1] == 0

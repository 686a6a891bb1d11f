"""Anti-aliased coverage: ``polygon_coverage`` and ``triangles_coverage``.

The coverage of a pixel is the area of the part of its square that is
inside (docs/semantics.md, docs/coverage.md).  Thin, like the rest: check
the arguments, hand the float vertices to one C call (which snaps them
exactly and writes the whole array without the GIL), turn statuses into
exceptions.  Nothing is returned half-written.
"""

import threading

from typing import Any, Optional

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import InputError
from ._native import ffi, lib
from ._typing import CoverageMethod, PathRings, Rule, Shape
from ._triangles import tris_f64
from ._path import Path as _Path, c_form, path_rings


def _methods():
    """{name: code} as the C table lists them."""
    table = {}
    name = ffi.new("char **")
    for code in range(lib.RAST_AA_COUNT_):
        if lib.rast_aa_method_info(code, name) == lib.RAST_OK:
            table[ffi.string(name[0]).decode()] = code
    return table


#: The coverage methods by name ("area", "ss2", "ss4", "ss8", "ss16",
#: "accumulate").
METHODS = _methods()

# dtype -> (C output format, how to turn the C array into the result)
_U8, _U16, _F32, _F64 = (np.dtype(t) for t in (np.uint8, np.uint16, np.float32, np.float64))
_DTYPES = {_U8: lib.RAST_COVERAGE_U8, _U16: lib.RAST_COVERAGE_U16,
           _F32: lib.RAST_COVERAGE_FIX62, _F64: lib.RAST_COVERAGE_FIX62}
_C_DTYPE = {lib.RAST_COVERAGE_U8: _U8, lib.RAST_COVERAGE_U16: _U16,
            lib.RAST_COVERAGE_FIX62: np.dtype(np.uint64)}


def method_error(method, entry, supported):
    return InputError("unknown or unsupported method %r for %s; choose one of: %s"
                      % (method, entry, ", ".join(supported)))


def _opts(method, rule, subpixel_bits, sample_offset, entry):
    """A checked, read-only ``rast_coverage_opts *`` (cached: a hit skips the checks).

    str names, an int S and a float offset are looked up by value alone
    (a plain tuple: cheaper than the general cache's key, which adds the
    types); anything else takes the general cache, which checks them."""
    if type(subpixel_bits) is int and type(sample_offset) is float and type(method) is str \
            and type(rule) is str:
        key = (method, rule, subpixel_bits, sample_offset)
        opts = _OPTS.get(key)
        if opts is None:
            opts = _core.cached_opts("coverage", _make_opts, method, rule, subpixel_bits,
                                     sample_offset, entry)
            if len(_OPTS) < 256 and opts.subpixel_bits <= _MAX_S32:  # (S > 16: polygon_coverage only)
                _OPTS[key] = opts
        return opts
    return _core.cached_opts("coverage", _make_opts, method, rule, subpixel_bits, sample_offset, entry)


_OPTS = {}


def _make_opts(method, rule, subpixel_bits, sample_offset, entry):
    if not isinstance(method, str) or method not in METHODS:
        raise method_error(method, entry, list(METHODS))
    opts = ffi.new("rast_coverage_opts *")
    opts.method = METHODS[method]
    opts.rule = _core.RULES[_core._name(rule, "rule", _core.RULES)]
    # polygon_coverage's "area" takes S up to 32 (the 64-bit path below)
    wide = entry == "polygon_coverage" and method == "area"
    opts.subpixel_bits = _core._subpixel_bits(subpixel_bits, _MAX_S64 if wide else None)
    opts.sample = _core.sample_code(sample_offset)
    return opts


def _dtype(dtype):
    try:
        d = np.dtype(dtype)
    except TypeError:
        d = None
    if d not in _DTYPES:
        raise InputError("dtype must be one of uint8, uint16, float32, float64, not %r" % (dtype,))
    return d


# ---- the quick path -------------------------------------------------------------
# A call whose options were checked before (same values, same types) and
# whose rings need no conversion goes straight to C: a dict lookup for the
# options, a few comparisons for the arguments, one C call.  Anything else,
# and any error status, takes the general path, which checks everything and
# raises (so the messages are the general path's).

# (method, rule, subpixel_bits, sample_offset, dtype) -> (opts, C format,
# C array dtype, result dtype), filled by the general path once it has
# checked them; only for str names, an int S and a float offset (so that
# True, 8.0 or 0 still take the general path and its checks).
_QUICK = {}
_ndarray, _empty, _concatenate, _from_buffer, _NULL = np.ndarray, np.empty, np.concatenate, ffi.from_buffer, ffi.NULL
_DOUBLES = ffi.typeof("double[]")
_PACKED = (16, 8)          # strides of a C-contiguous float64 (N, 2) array
_PACKED_TRIS = (48, 16, 8)  # ... and of an (N, 3, 2) one
_MAX_DIM, _MAX_POINTS = lib.RAST_MAX_DIM, lib.RAST_MAX_POINTS

# Scratch kept between calls, one block per thread (rastpy_scratch in
# python/glue/coverage.h): a call that needs more than the block takes its
# own from malloc, and the block then grows to what it needed, up to this
# many bytes.  Without it a block of a few hundred KB taken and freed on
# every call could go back to the system each time and fault its pages in
# again on the next (79 page faults a call, 2.8 times the time, for
# "area" on four glyphs at 512 x 512).
_SCRATCH_KEEP = 32 << 20
_tls = threading.local()


def _lent(fn, *args):
    """fn(*args, this thread's scratch); after it, keep a block as large as
    the call wanted (within the cap)."""
    try:
        sc = _tls.sc
    except AttributeError:
        sc = _tls.sc = ffi.new("rastpy_scratch *")
        _tls.at = int(ffi.cast("uintptr_t", sc))  # (for _seq.coverage)
    result = fn(*args, sc)
    if sc.size < sc.want:
        _keep()
    return result


def _keep():
    """After a call that lent this thread's scratch and wanted more: a block
    as large as it wanted, kept (within the cap); _seq.coverage calls it too."""
    sc = _tls.sc
    if sc.size < sc.want <= _SCRATCH_KEEP:
        _tls.buf = ffi.new("char[]", sc.want)  # (malloc'd: 16-byte aligned)
        sc.buf, sc.size = _tls.buf, sc.want


def _quick(method, rule, subpixel_bits, sample_offset, dtype):
    """(the _QUICK key of these arguments, or None when they may not take
    it; what _QUICK holds under it, or None: nothing, or an unhashable
    dtype), in one call."""
    if type(subpixel_bits) is int and type(sample_offset) is float and type(method) is str \
            and type(rule) is str:
        key = (method, rule, subpixel_bits, sample_offset, dtype)
        try:
            return key, _QUICK.get(key)
        except TypeError:  # e.g. dtype=[...]
            return key, None
    return None, None


def _remember(key, opts, fmt, d):
    if key is not None and len(_QUICK) < 256 and opts.subpixel_bits <= _MAX_S32:
        try:
            _QUICK[key] = (opts, fmt, _C_DTYPE[fmt], d)
        except TypeError:
            return
        if fmt != _FIX62:  # uint8, uint16: the array C writes is the result
            _QUICK_C[key] = (int(ffi.cast("uintptr_t", opts)), fmt, _C_DTYPE[fmt], opts)


# polygon_coverage's common call (one small ring, a key _remember holds, a
# uint8 or uint16 result) made whole in C by _seq.coverage (python/ext/seq.c):
# no Python checks, no cffi conversions; this thread's scratch, as _lent
# lends it (once _lent has made it: _tls.at, its address), _keep after
# (issue 33).
# Anything it declines (None) is for the rest of polygon_coverage.
_QUICK_C: dict = {}
_cov_quick = _core._seq.coverage


def _plain_shape(shape):
    """(h, w) of a tuple of two ints in 1..RAST_MAX_DIM, else None."""
    if type(shape) is tuple and len(shape) == 2:
        h, w = shape
        if type(h) is int and type(w) is int and 0 < h <= _MAX_DIM and 0 < w <= _MAX_DIM:
            return shape
    return None


def _one_ring(rings):
    """The ring itself of one float64 (N, 2) array with N >= 3 (C-contiguous,
    at most RAST_MAX_POINTS), or of a list of one such array; else None."""
    r = rings[0] if type(rings) is list and len(rings) == 1 else rings
    # (the dtype equal, not only the same object: an unpickled array's is
    # a dtype of its own)
    if type(r) is _ndarray and (r.dtype is _F64 or r.dtype == _F64) and r.ndim == 2 and r.shape[1] == 2 \
            and r.strides == _PACKED and 3 <= len(r) <= _MAX_POINTS:
        return r
    return None


def _quick_points(rings):
    """(points as a ``double[]`` cdata, their number, ring sizes or NULL,
    number of rings) of rings that need no checking or conversion: one
    ring as _one_ring takes it, or a list of several in a form
    _core.packed_rings reads in one C pass (float64 or int32 arrays of any
    strides, or (x, y) pairs: no numpy array made of them, _core.packed_call);
    None for anything else, which _core._points checks."""
    if type(rings) is list and len(rings) != 1:
        return _core.packed_call(rings)  # checked and measured in one C pass
    ring = _one_ring(rings)
    return None if ring is None else (_from_buffer(_DOUBLES, ring), len(ring), _NULL, 1)


def _points(rings):
    """(float64 (N, 2) points, ring sizes or NULL, number of rings), as _core._points."""
    ring = _one_ring(rings)
    return (ring, _NULL, 1) if ring is not None else _core._points(rings)


def _check(result, pts, opts, what, sizes):
    if result == lib.RAST_E_RANGE:  # snapped in range, but not times k
        k = 1 << (opts.method - lib.RAST_AA_SS2 + 1)
        raise InputError(
            "%s: a vertex times %d (method ss%d scales the vertices to its finer grid) is "
            "outside the range +-%.6g pixels at subpixel_bits=%d"
            % (what, k, k, lib.RAST_COORD_MAX / float(max(k, 1 << opts.subpixel_bits)),
               opts.subpixel_bits))
    _core._check_glue(result, pts, opts.subpixel_bits, what, sizes)


def _ntris(batch):
    """The triangles of an (N, 3, 2) batch, at most what one call takes."""
    n = batch.shape[0]
    if 3 * n > lib.RAST_MAX_POINTS:
        raise InputError("%d triangles; at most %d per call" % (n, lib.RAST_MAX_POINTS // 3))
    return n


def _finish(raw, d):
    if d in (_U8, _U16):
        return raw
    # a in units of 2^-62: to float exactly (a power of two scales exactly;
    # the integer rounds to the nearest float64 once, or float32 once more).
    # In place, over the uint64 array's own memory (C): more arrays of that
    # size (astype, ldexp, or numpy's temporary for a ufunc whose output
    # overlaps its input) cost more than the arithmetic, in fresh pages.
    if d == _F32:  # float32 straight from the integers: one pass, no float64 array then a cast
        out = _empty(raw.shape, _F32)
        if raw.size:
            lib.rastpy_fix62_to_float(_from_buffer(raw), _from_buffer(out), raw.size)
        return out
    if raw.size:
        lib.rastpy_fix62_to_double(_from_buffer(raw), raw.size)
    return raw.view(np.float64)


def _path_coverage(path, shape, quick, tolerance):
    """The coverage of a Path, flattened in C straight into the filler
    (python/glue/pathfill.c; docs/paths.md), equal to that of its rings
    path.flatten(subpixel_bits, tolerance); None when the general path
    must take it (an error there says which)."""
    opts, fmt, c_dtype, d = quick
    c = c_form(path, opts.subpixel_bits, tolerance)
    if c is None or not c[1]:
        return None
    h, w = shape
    raw = _empty(shape, c_dtype)
    if _lent(lib.rastpy_path_coverage, _from_buffer(raw), h, w, fmt, *c, opts):
        return None
    return raw if fmt != _FIX62 else _finish(raw, d)


def polygon_coverage(rings: PathRings, shape: Shape, *, rule: Rule = "evenodd", method: CoverageMethod = "area",
                     subpixel_bits: int = 8, sample_offset: float = 0.5,
                     dtype: npt.DTypeLike = np.uint8, tolerance: Optional[float] = None) -> npt.NDArray[Any]:
    """How much of each pixel a polygon covers.

    Parameters
    ----------
    rings : (N, 2) array_like or list of them, or a Path
        The polygon's closed rings as (x, y) vertices in pixels, as for
        ``polygon_mask``; a ``rastrum.Path`` or a matplotlib ``Path`` is
        flattened within `tolerance`, a shapely polygon gives its rings.
    shape : (int, int)
        (height, width) of the result.
    rule : {"evenodd", "nonzero"}
        Fill rule; coverage is the area inside under it, right where
        contours overlap, cross or coincide.
    method : str
        One of ``ALGORITHMS["polygon_coverage"]``: "area" (the exact area,
        the default), "ss2", "ss4", "ss8", "ss16" (k x k sub-samples, the
        exact binary rule on each), "accumulate" (signed-area accumulation
        as FreeType does it: exact only where nothing overlaps).
    subpixel_bits : int
        Vertices are snapped to 1/2**subpixel_bits pixel (0..16; "area"
        takes 0..32 and coordinates up to 2**28 pixels, switching by itself
        to the 64-bit path when S or a coordinate needs it: docs/coverage.md).
    sample_offset : {0.5, 0}
        Where the sub-samples sit (the ssK methods only): (s + 0.5)/k or s/k.
    dtype : uint8, uint16, float32 or float64
        uint8 holds floor(a*255 + 1/2), uint16 floor(a*65535 + 1/2) (see
        docs/coverage.md for the bound on ties); the floats hold a (from a
        2^-62 fixed point): the cell's fraction inside.
    tolerance : float or None
        As ``polygon_mask``: a Path's flattening tolerance in pixels.

    Returns
    -------
    numpy.ndarray of `dtype`, shape (H, W)

    Raises
    ------
    InputError (a ValueError)
        As ``polygon_mask``; also an unknown method or dtype.

    Examples
    --------
    >>> import rastrum
    >>> rastrum.polygon_coverage([(0.5, 0), (2, 0), (2, 1), (0.5, 1)], (1, 3))
    array([[128, 255,   0]], dtype=uint8)
    """
    if tolerance is None:
        got = _cov_quick(rings, shape, method, rule, subpixel_bits, sample_offset, dtype)
        if got is not None:
            return got
    key, quick = _quick(method, rule, subpixel_bits, sample_offset, dtype)
    if type(rings) is _Path and quick is not None and _plain_shape(shape) is not None:
        got = _path_coverage(rings, shape, quick, tolerance)
        if got is not None:
            return got
    if tolerance is not None or not isinstance(rings, (list, tuple, np.ndarray)):  # docs/paths.md
        rings = path_rings(rings, subpixel_bits, tolerance)
    if quick is not None and _plain_shape(shape) is not None:
        points = _quick_points(rings)
        if points is not None:
            opts, fmt, c_dtype, d = quick
            xy, n, sizes, nrings = points
            h, w = shape
            raw = _empty(shape, c_dtype)
            if not _lent(_poly_call, _from_buffer(raw), h, w, fmt, xy, n, sizes, nrings, opts):
                return raw if fmt != _FIX62 else _finish(raw, d)
            # an error: the general path says which
    opts = _opts(method, rule, subpixel_bits, sample_offset, "polygon_coverage")
    d = _dtype(dtype)
    fmt = _DTYPES[d]
    _remember(key, opts, fmt, d)
    h, w = _core.shape2(shape)
    pts, sizes, nrings = _points(rings)
    raw = np.empty((h, w), _C_DTYPE[fmt])
    if not nrings:
        raw[...] = 0
        return _finish(raw, d)
    if _use_wide(opts, pts):
        result = lib.rastpy_polygon_coverage64(ffi.from_buffer(raw) if h and w else ffi.NULL, h, w, fmt,
                                               ffi.from_buffer("double[]", pts), len(pts), sizes, nrings,
                                               opts)
        if result:
            _core._check_glue(result, pts, opts.subpixel_bits, "rings",
                              [len(pts)] if nrings == 1 else sizes, True)
        return _finish(raw, d)
    result = _lent(lib.rastpy_polygon_coverage, ffi.from_buffer(raw) if h and w else ffi.NULL, h, w, fmt,
                   ffi.from_buffer("double[]", pts), len(pts), sizes, nrings, opts)
    if result:
        _check(result, pts, opts, "rings", [len(pts)] if nrings == 1 else sizes)
    return _finish(raw, d)


# ---- the 64-bit path (docs/coverage.md, "64-bit vertices") ------------------------
# "area" on rast_polygon64: subpixel_bits up to 32, coordinates up to 2**28
# pixels.  Taken only when S or a coordinate needs it, as polygon_mask does;
# where both apply they agree within their bounds (tests/test_coverage64.py).
_MAX_S32, _MAX_S64 = lib.RAST_MAX_SUBPIXEL_BITS, lib.RAST_MAX_SUBPIXEL_BITS64


def _use_wide(opts, pts):
    """Take rast_polygon_coverage64 for these options and float64 points?"""
    if opts.method != lib.RAST_AA_AREA:
        return False
    if opts.subpixel_bits > _MAX_S32:
        return True
    return bool(len(pts)) and bool(lib.rastpy_needs_wide(ffi.from_buffer("double[]", pts), len(pts),
                                                         opts.subpixel_bits))


def polygon_coverage64(rings: PathRings, shape: Shape, *, rule: Rule = "evenodd", subpixel_bits: int = 32,
                       dtype: npt.DTypeLike = np.float64) -> npt.NDArray[Any]:
    """``polygon_coverage(method="area")`` always on the 64-bit path (for
    callers that want it whatever the input: rastrum.rasterize's coverage,
    tests).  subpixel_bits 0..32, |coordinate| < 2**28 pixels."""
    rings = path_rings(rings, subpixel_bits, None)
    opts = _opts("area", rule, subpixel_bits, 0.5, "polygon_coverage")
    d = _dtype(dtype)
    fmt = _DTYPES[d]
    h, w = _core.shape2(shape)
    pts, sizes, nrings = _points(rings)
    raw = np.empty((h, w), _C_DTYPE[fmt])
    if not nrings:
        raw[...] = 0
        return _finish(raw, d)
    result = lib.rastpy_polygon_coverage64(ffi.from_buffer(raw) if h and w else ffi.NULL, h, w, fmt,
                                           ffi.from_buffer("double[]", pts), len(pts), sizes, nrings, opts)
    if result:
        _core._check_glue(result, pts, opts.subpixel_bits, "rings", [len(pts)] if nrings == 1 else sizes, True)
    return _finish(raw, d)


def triangles_coverage(tris: npt.ArrayLike, shape: Shape, *, method: CoverageMethod = "area",
                       subpixel_bits: int = 8, sample_offset: float = 0.5,
                       dtype: npt.DTypeLike = np.uint8) -> npt.NDArray[Any]:
    """How much of each pixel a batch of triangles covers, as ONE region.

    The batch is the union of its triangles (whatever their orientation):
    a mesh submitted in one call has no seams, and overlapping triangles
    are not counted twice (except by "accumulate", which adds them).
    Parameters as ``polygon_coverage``; `tris` is (N, 3, 2) as for
    ``triangles_mask``.

    Examples
    --------
    >>> import rastrum
    >>> sq = [[(0, 0), (2, 0), (2, 2)], [(0, 0), (2, 2), (0, 2)]]
    >>> rastrum.triangles_coverage(sq, (2, 2)).tolist()
    [[255, 255], [255, 255]]
    """
    key, quick = _quick(method, "nonzero", subpixel_bits, sample_offset, dtype)
    if quick is not None and _plain_shape(shape) is not None and type(tris) is _ndarray \
            and (tris.dtype is _F64 or tris.dtype == _F64) and tris.strides == _PACKED_TRIS \
            and tris.shape[1:] == (3, 2) \
            and 0 < 3 * len(tris) <= _MAX_POINTS:
        opts, fmt, c_dtype, d = quick
        h, w = shape
        raw = _empty(shape, c_dtype)
        if not _lent(_tris_call, _from_buffer(raw), h, w, fmt, _from_buffer(_DOUBLES, tris), len(tris), opts):
            return raw if fmt != _FIX62 else _finish(raw, d)
        # an error: the general path says which
    opts = _opts(method, "nonzero", subpixel_bits, sample_offset, "triangles_coverage")
    d = _dtype(dtype)
    fmt = _DTYPES[d]
    _remember(key, opts, fmt, d)
    h, w = _core.shape2(shape)
    t = tris_f64(tris)
    n = _ntris(t)
    raw = np.empty((h, w), _C_DTYPE[fmt])
    if n == 0:
        raw[...] = 0
        return _finish(raw, d)
    result = _lent(lib.rastpy_triangles_coverage, ffi.from_buffer(raw) if h and w else ffi.NULL, h, w, fmt,
                   ffi.from_buffer("double[]", t), n, opts)
    if result:
        _check(result, t.reshape(-1, 2), opts, "tris", 3)
    return _finish(raw, d)


_poly_call, _tris_call = lib.rastpy_polygon_coverage, lib.rastpy_triangles_coverage
_core._seq.coverage_setup(_QUICK_C, np.empty, int(ffi.cast("uintptr_t", ffi.addressof(lib, "rastpy_polygon_coverage"))),
                          _tls, _keep)
_FIX62 = lib.RAST_COVERAGE_FIX62


# ---- anti-aliased Canvas fills (aa=) -----------------------------------------------

#: Canvas fills that take ``aa=``, and for each the methods it accepts
#: (with the fill rules each takes; a triangle batch is one region, a union,
#: whatever the rule).  ``aa=None`` (the default) is the binary fill of
#: ``ALGORITHMS``.  The triangle fills take ``aa=`` with ``vertex_colors=``
#: too (Gouraud colour times coverage; shading "gouraud" or "flat",
#: precision "exact"); ``depth=``, per-triangle colours, fixed precision and
#: shaded polygons have no ``aa=``.
AA_ENTRIES = ("Canvas.fill_polygon", "Canvas.fill_triangle", "Canvas.fill_triangles")


def aa_opts(aa, rule, subpixel_bits, sample_offset, entry, binary_only):
    """The coverage options of ``aa=`` for `entry`, or InputError.

    `binary_only` maps the names of arguments that only binary fills take
    to (value given, default string): any not at its default is refused,
    naming the alternatives."""
    if not isinstance(aa, str) or aa not in METHODS:
        raise InputError("aa=%r for %s: choose None (binary, the default) or one of: %s"
                         % (aa, entry, ", ".join(METHODS)))
    for name, (value, default) in binary_only.items():
        if not (isinstance(value, str) and value == default):
            raise InputError("%s: %s=%r is for binary fills (aa=None); with aa=%r leave it out "
                             "(%s=%r)" % (entry, name, value, aa, name, default))
    return _opts(aa, rule, subpixel_bits, sample_offset, entry)


def aa_opts_quick(aa, rule, subpixel_bits, sample_offset, entry):
    """aa_opts for a call whose binary-only arguments are all at their
    defaults: checked options of str names, an int S and a float offset
    come from _OPTS in one lookup; anything else is checked by aa_opts."""
    if type(aa) is str and type(rule) is str and type(subpixel_bits) is int and type(sample_offset) is float:
        opts = _OPTS.get((aa, rule, subpixel_bits, sample_offset))
        if opts is not None:
            return opts
    return aa_opts(aa, rule, subpixel_bits, sample_offset, entry, {})


def fill_polygon_aa(target, rings, pixel, opts):
    """rast_fill_polygon_aa of `rings` (as polygon_mask takes them); with
    "area", a vertex past the 32-bit range takes the 64-bit path exactly
    where polygon_coverage takes it (_use_wide): its levels over the
    polygon's box, painted as the 32-bit fill paints them
    (rastpy_fill_polygon_aa64), as the translucent fills blend them."""
    pts, sizes, nrings = _points(rings)
    if not nrings:
        return
    xy = ffi.from_buffer("double[]", pts)
    result = _lent(lib.rastpy_fill_polygon_aa, target, xy, len(pts), sizes, nrings, opts, pixel)
    if result > 0 and opts.method == lib.RAST_AA_AREA and lib.rastpy_needs_wide(xy, len(pts), opts.subpixel_bits):
        result = lib.rastpy_fill_polygon_aa64(target, xy, len(pts), sizes, nrings, opts, pixel)
        if result:
            _core._check_glue(result, pts, opts.subpixel_bits, "rings", [len(pts)] if nrings == 1 else sizes, True)
        return
    if result:
        _check(result, pts, opts, "rings", [len(pts)] if nrings == 1 else sizes)


def fill_triangles_aa(target, batch, pixel, opts, what="tris"):
    """rast_fill_triangles_aa of the (N, 3, 2) float64 `batch`, one region."""
    n = _ntris(batch)
    if n == 0:
        return
    result = _lent(lib.rastpy_fill_triangles_aa, target, ffi.from_buffer("double[]", batch), n, opts, pixel)
    if result:
        _check(result, batch.reshape(-1, 2), opts, what, 3)


def fill_triangles_shaded_aa(target, batch, colors, opts, sopts, what="tris", blend=None):
    """rast_fill_triangles_shaded_aa of the (N, 3, 2) float64 `batch` with
    the (N, 3, 4) uint8 RGBA vertex `colors`: one region, a colour per pixel
    (blend: a ``rast_blend_opts *``, rast_fill_triangles_shaded_aa_blend)."""
    n = _ntris(batch)
    if n == 0:
        return
    if blend is not None:
        result = _lent(lib.rastpy_fill_triangles_shaded_aa_blend, target, ffi.from_buffer("double[]", batch),
                       n, ffi.from_buffer("uint8_t[]", colors), opts, sopts, blend)
    else:
        result = _lent(lib.rastpy_fill_triangles_shaded_aa, target, ffi.from_buffer("double[]", batch), n,
                       ffi.from_buffer("uint8_t[]", colors), opts, sopts)
    if result:
        _check(result, batch.reshape(-1, 2), opts, what, 3)

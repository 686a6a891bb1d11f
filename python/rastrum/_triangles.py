"""Triangle batches: ``triangles_mask`` and the helpers behind
``Canvas.fill_triangle(s)``.

Thin, like the rest: check the arguments, hand the float vertices to one C
call (which snaps them exactly and fills the whole batch without the GIL),
and turn statuses into exceptions.  Nothing is written when an argument is
bad.
"""

from typing import Literal

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import InputError
from ._native import ffi, lib
from ._typing import Boundary, Rounding, Shape, TriangleAlgorithm


def _triangle_algorithms():
    """{name: code} as the C table lists them."""
    table = {}
    name = ffi.new("char **")
    for code in range(lib.RAST_TRI_COUNT_):
        if lib.rast_tri_algorithm_info(code, name) == lib.RAST_OK:
            table[ffi.string(name[0]).decode()] = code
    return table


TRIANGLE_ALGORITHMS = _triangle_algorithms()
MODES = ("set", "count")

def _make_tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary):
    code = TRIANGLE_ALGORITHMS[_core._name(algorithm, "triangle algorithm", TRIANGLE_ALGORITHMS)]
    opts = ffi.new("rast_tri_opts *")
    opts.algorithm = code
    opts.subpixel_bits = _core._subpixel_bits(subpixel_bits)
    opts.sample = _core.sample_code(sample_offset)
    opts.rounding = _core.rounding_code(rounding)
    opts.boundary = _core.boundary_code(boundary)
    return opts


def tri_opts(algorithm, subpixel_bits, sample_offset, rounding="exact", boundary="exact"):
    """A checked, read-only ``rast_tri_opts *`` (cached as _core.fill_opts)."""
    return _core.cached_opts("triangles", _make_tri_opts, algorithm, subpixel_bits,
                             sample_offset, rounding, boundary)


def tris_f64(tris, single=False):
    """The batch as a checked, C-contiguous float64 (N, 3, 2) array (a copy
    when the input is not one already).

    With `single`, one triangle given as a (3, 2) array-like."""
    what = "tri" if single else "tris"
    a = _core.real_array(tris, what, "a (3, 2) array-like" if single else "an (N, 3, 2) array-like")
    if single:
        if a.shape != (3, 2):
            raise InputError("tri must have shape (3, 2): three (x, y) vertices, not %s" % (a.shape,))
        return a.reshape(1, 3, 2)
    if a.size == 0 and a.ndim < 3:
        return a.reshape(0, 3, 2)  # [] or np.zeros((0, 2)): an empty batch
    if a.ndim != 3 or a.shape[1:] != (3, 2):
        raise InputError("tris must have shape (N, 3, 2): N triangles of three (x, y) vertices, not %s"
                         % (a.shape,))
    if a.shape[0] >= 2 ** 32:
        raise InputError("%d triangles; at most 2**32 - 1 per call" % a.shape[0])
    return a


def fill_triangles(target, tris, pixel, opts, what="tris"):
    """Snap the checked (N, 3, 2) float64 batch and fill it into `target`."""
    n = tris.shape[0]
    if n == 0:
        return
    result = lib.rastpy_fill_triangles(target, ffi.from_buffer("double[]", tris), n, opts, pixel)
    if result:
        _core._check_glue(result, tris.reshape(-1, 2), opts.subpixel_bits, what, 3)


def _mode(mode):
    if not isinstance(mode, str) or mode not in MODES:
        raise InputError("unknown mode %r; choose one of: %s" % (mode, ", ".join(MODES)))
    return mode


def triangles_mask(tris: npt.ArrayLike, shape: Shape, *, algorithm: TriangleAlgorithm = "edge",
                   subpixel_bits: int = 8, sample_offset: float = 0.5, mode: Literal["set"] = "set",
                   rounding: Rounding = "exact", boundary: Boundary = "exact") -> npt.NDArray[np.bool_]:
    """Rasterise a batch of triangles into a mask, or count them per pixel.

    Each triangle owns exactly the pixels whose sample point the polygon
    rule gives it as a one-ring polygon (see :func:`rastrum.polygon_mask`):
    in either winding order, and nothing when it is degenerate.  Triangles
    that share an edge therefore never both own a pixel nor both miss one,
    so a triangulated region is counted exactly once everywhere.

    Parameters
    ----------
    tris : (N, 3, 2) array_like
        N triangles, each three (x, y) vertices in pixels.  N may be 0.
    shape : (int, int)
        (height, width) of the result, as numpy writes it.
    algorithm : str
        One of ``ALGORITHMS["triangles_mask"]`` ("edge", "sweep",
        "edgeflag"); all give the same pixels.
    subpixel_bits : int
        Vertices are snapped to 1/2**subpixel_bits pixel (0..16), the only
        approximation.  The coordinate range is +-(2**27 - 1) / 2**bits px.
    sample_offset : {0.5, 0}
        Where a pixel's sample point is: its centre (0.5) or its top-left
        corner (0, as OpenCV and the textbook).
    mode : {"set"}
        Deprecated: ``mode="count"`` (a uint16 count instead of the bool
        mask) is now :func:`triangles_count`; it still works for one
        release, with a DeprecationWarning.
    rounding : {"exact", "textbook"}
        "textbook" rounds each crossing to the nearest sample column,
        halves going right, as the textbook's Example 3-1 does (use it with
        ``sample_offset=0``).  Not exact; never the default.
    boundary : {"exact", "closed", "conservative"}
        Pixels of each triangle's outline to add, as in
        :func:`rastrum.polygon_mask`.  Only "exact" is watertight.

    Returns
    -------
    numpy.ndarray of bool, shape (H, W)
        True where a triangle owns the pixel.

    Raises
    ------
    InputError (a ValueError)
        Its message names the argument and the problem: a batch not of
        shape (N, 3, 2), a NaN, infinite or out-of-range coordinate (which
        triangle and vertex), coordinates that are not real numbers (bool,
        complex, str, None), a bad `shape`, an unknown name or option
        value.  An empty batch is not an error: the result is all 0.
    MemoryError
        When numpy cannot allocate the (H, W) result.

    Examples
    --------
    >>> import rastrum
    >>> square = [[(0, 0), (4, 0), (4, 4)], [(0, 0), (4, 4), (0, 4)]]
    >>> rastrum.triangles_mask(square, (5, 6)).astype(int)
    array([[1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [0, 0, 0, 0, 0, 0]])
    >>> rastrum.triangles_mask([[(1, 1), (5, 3), (4, 7)]], (8, 7),
    ...                        sample_offset=0).astype(int)[1:7]
    array([[0, 0, 0, 0, 0, 0, 0],
           [0, 0, 1, 0, 0, 0, 0],
           [0, 0, 1, 1, 1, 0, 0],
           [0, 0, 0, 1, 1, 0, 0],
           [0, 0, 0, 1, 1, 0, 0],
           [0, 0, 0, 0, 1, 0, 0]])
    """
    count = _mode(mode) == "count"
    if count:
        _core.deprecated('triangles_mask(mode="count") is now triangles_count(), which always returns uint16')
    return _mask(tris, shape, algorithm, subpixel_bits, sample_offset, rounding, boundary, count)


def triangles_count(tris: npt.ArrayLike, shape: Shape, *, algorithm: TriangleAlgorithm = "edge",
                    subpixel_bits: int = 8, sample_offset: float = 0.5, rounding: Rounding = "exact",
                    boundary: Boundary = "exact") -> npt.NDArray[np.uint16]:
    """Count, per pixel, the triangles of a batch that own it: overdraw
    made visible.

    Arguments as :func:`triangles_mask`, which gives the bool union of
    the same triangles (``triangles_count(...) > 0``).

    Returns
    -------
    numpy.ndarray of uint16, shape (H, W)
        The number of triangles owning each pixel, saturating at 65535.

    Examples
    --------
    >>> import rastrum
    >>> square = [[(0, 0), (4, 0), (4, 4)], [(0, 0), (4, 4), (0, 4)]]
    >>> rastrum.triangles_count(square, (5, 6))
    array([[1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 0, 0],
           [0, 0, 0, 0, 0, 0]], dtype=uint16)
    """
    return _mask(tris, shape, algorithm, subpixel_bits, sample_offset, rounding, boundary, True)


def _mask(tris, shape, algorithm, subpixel_bits, sample_offset, rounding, boundary, count):
    opts = tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
    h, w = _core.shape2(shape)
    batch = tris_f64(tris)
    out = np.zeros((h, w), np.uint16 if count else np.bool_)
    if not (h and w and batch.shape[0]):
        return out
    target = ffi.new("rast_target *")
    _core._check(lib.rast_target_init(target, ffi.from_buffer(out, require_writable=True), w, h,
                                      w * out.itemsize,
                                      lib.RAST_FORMAT_COUNT16 if count else lib.RAST_FORMAT_GRAY8))
    fill_triangles(target, batch, ffi.NULL if count else _ONE, opts)
    return out


_ONE = ffi.new("unsigned char[1]", [1])

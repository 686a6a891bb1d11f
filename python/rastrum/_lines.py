"""Lines and point-in-triangle predicates: the thin layer over line.c and
predicate.c.  Public names: :func:`line_pixels` and
:func:`point_in_triangle` (and ``Canvas.line`` / ``Canvas.polyline``, which
use the helpers here)."""

import numbers

from typing import Literal, Optional, Sequence

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import InputError
from ._native import ffi, lib
from ._typing import LineAlgorithm, Point

#: Line algorithm names and their C codes.
LINE_ALGORITHMS = {"bresenham": lib.RAST_LINE_BRESENHAM, "dda": lib.RAST_LINE_DDA}

#: Point-in-triangle methods and their C codes.
PREDICATES = {
    "sameside": lib.RAST_PRED_SAMESIDE,
    "cross": lib.RAST_PRED_CROSS,
    "area": lib.RAST_PRED_AREA,
    "barycentric": lib.RAST_PRED_BARYCENTRIC,
    "owner": lib.RAST_PRED_OWNER,
}


def line_opts(algorithm, subpixel_bits, sample_offset):
    """A checked ``rast_line_opts *``."""
    opts = ffi.new("rast_line_opts *")
    opts.algorithm = LINE_ALGORITHMS[_core._name(algorithm, "line algorithm", LINE_ALGORITHMS)]
    opts.subpixel_bits = _core._subpixel_bits(subpixel_bits)
    opts.sample = _core.sample_code(sample_offset)
    return opts


def snap_point(p, s, what="point"):
    """One (x, y) pair snapped to the 1/2^s grid, as a ``rast_point``."""
    try:
        shape = np.shape(p)
    except ValueError:  # ragged nesting
        shape = None
    if shape != (2,):
        raise InputError("%s must be a pair (x, y), not %r" % (what, p))
    p = _core.real_array(p, what, "a pair (x, y)")
    (x, y), = _core.snap_points(p.reshape(1, 2), s, what).tolist()
    return ffi.new("rast_point *", [x, y])[0]


def snap_polyline(points, s, minimum):
    """An (N, 2) array-like snapped to an int32 (N, 2) array, N >= minimum;
    no points at all ([] or an empty (0, 2) array) give an empty array."""
    try:
        empty = np.size(points) == 0 and _core.ndim(points) <= 2
    except ValueError:  # ragged nesting: snap_points says why
        empty = False
    if empty:
        return np.zeros((0, 2), np.int32)
    pts = _core.snap_points(points, s)
    if len(pts) < minimum:
        raise InputError("points: %s given; at least %d needed" % (_core.plural(len(pts), "point"), minimum))
    if len(pts) > lib.RAST_MAX_POINTS:
        raise InputError("%d points; at most %d per call" % (len(pts), lib.RAST_MAX_POINTS))
    return pts


def _clip_rect(clip):
    rect = ffi.new("rast_rect *")
    if clip is None:
        m = lib.RAST_MAX_DIM
        rect.x0, rect.y0, rect.x1, rect.y1 = -m, -m, m, m
        return rect
    try:
        values = [v for v in _core.as_numpy(clip)]
    except TypeError:
        values = None
    if (
        values is None
        or len(values) != 4
        or not all(isinstance(v, numbers.Integral) and not isinstance(v, (bool, np.bool_)) for v in values)
        or not all(-lib.RAST_MAX_DIM <= v <= lib.RAST_MAX_DIM for v in values)
    ):
        raise InputError(
            "clip must be (x0, y0, x1, y1), four ints in +-%d, not %r" % (lib.RAST_MAX_DIM, clip)
        )
    rect.x0, rect.y0, rect.x1, rect.y1 = (int(v) for v in values)
    return rect


MAX_LINE_PIXELS = 1 << 24


def line_pixels(p0: Point, p1: Point, *, algorithm: LineAlgorithm = "bresenham", subpixel_bits: int = 8,
                sample_offset: float = 0.5, clip: Optional[Sequence[int]] = None,
                max_pixels: int = MAX_LINE_PIXELS) -> npt.NDArray[np.int32]:
    """The pixels of the segment p0 -> p1, in order from p0.

    Under "bresenham" these are exactly the library's line (the one
    ``Canvas.line`` draws and the "closed" boundary mode adds): along the
    major axis (x when |dx| >= |dy|, else y) one pixel for each sample
    whose major coordinate lies on the segment, in the row (column) whose
    sample is nearest the line there; halfway, the lower row (the column
    to the right).  The set does not depend on the direction.  "dda" is the
    textbook DDA with 16 fraction bits, for comparison: same count, each
    pixel at most one off the exact line for lines shorter than 2**16
    pixels, and not always symmetric.

    Parameters
    ----------
    p0, p1 : (x, y)
        Endpoints in pixels, snapped to 1/2**subpixel_bits pixel.
    algorithm : {"bresenham", "dda"}
    subpixel_bits : int
        0..16; the range is +-(2**27 - 1) / 2**subpixel_bits pixels.
    sample_offset : {0.5, 0}
        Samples at pixel centres (0.5) or at integer points (0; with
        integer endpoints and ``subpixel_bits=0`` this is Bresenham's
        classic line, both endpoints included).
    clip : (x0, y0, x1, y1) or None
        Only the pixels with x0 <= x < x1 and y0 <= y < y1; None for all.
    max_pixels : int or None
        The most pixels returned (default 2**24, 128 MiB of output): a
        segment with more (in the clip) raises InputError before anything
        is allocated, since one call with far endpoints could ask for
        gigabytes.  None: no limit.

    Returns
    -------
    numpy.ndarray of int32, shape (N, 2)
        (x, y) of each pixel, from p0 to p1.

    Raises
    ------
    InputError (a ValueError)
        Naming the argument: p0 or p1 not a pair of real numbers, NaN,
        infinite or out of range; a bad clip; an unknown name or option
        value; more pixels than max_pixels.

    Examples
    --------
    >>> import rastrum
    >>> rastrum.line_pixels((0, 0), (5, 2), subpixel_bits=0, sample_offset=0).tolist()
    [[0, 0], [1, 0], [2, 1], [3, 1], [4, 2], [5, 2]]
    >>> rastrum.line_pixels((5, 2), (0, 0), subpixel_bits=0, sample_offset=0).tolist()
    [[5, 2], [4, 2], [3, 1], [2, 1], [1, 0], [0, 0]]
    """
    opts = line_opts(algorithm, subpixel_bits, sample_offset)
    s = opts.subpixel_bits
    a, b = snap_point(p0, s, "p0"), snap_point(p1, s, "p1")
    rect = _clip_rect(clip)
    if max_pixels is not None and (isinstance(max_pixels, (bool, np.bool_))
                                   or not isinstance(max_pixels, (int, np.integer)) or max_pixels < 0):
        raise InputError("max_pixels must be an int >= 0 or None, not %r" % (max_pixels,))
    count = ffi.new("size_t *")
    st = lib.rast_line_pixels(a, b, opts, rect, ffi.NULL, 0, count)
    if st != lib.RAST_E_SCRATCH:
        _core._check(st)
    if max_pixels is not None and count[0] > max_pixels:
        raise InputError("line_pixels: the segment has %d pixels, more than max_pixels=%d (pass "
                         "max_pixels=None, or a larger int, to get them)" % (count[0], max_pixels))
    out = np.empty((count[0], 2), np.int32)
    if count[0]:
        _core._check(lib.rast_line_pixels(a, b, opts, rect, ffi.from_buffer("int32_t[]", out), count[0], count))
    return out


def point_in_triangle(p: Point, tri: npt.ArrayLike, *,
                      method: Literal["owner", "sameside", "cross", "area", "barycentric"] = "owner",
                      subpixel_bits: int = 8) -> bool:
    """Is point p inside triangle tri?  Exact, after snapping.

    The four textbook tests ("sameside", "cross", "area", "barycentric")
    all decide the closed triangle: a point on an edge or a vertex is
    inside.  "owner" is the fills' own rule: p is inside iff a fill of the
    triangle owns a sample placed exactly at p (left and top edges in,
    right and bottom edges out, so triangles sharing an edge never both
    own a point).  A triangle of zero area contains no point, for every
    method.

    Parameters
    ----------
    p : (x, y)
    tri : (3, 2) array-like
        Vertices in either winding order.
    method : {"owner", "sameside", "cross", "area", "barycentric"}
    subpixel_bits : int
        Coordinates are snapped to 1/2**subpixel_bits (0..16), as the fills
        snap them.

    Returns
    -------
    bool

    Raises
    ------
    InputError (a ValueError)
        Naming the argument: p not a pair, tri not of shape (3, 2), a
        coordinate that is not a real number, NaN, infinite or out of
        range; an unknown method or a bad subpixel_bits.

    Examples
    --------
    >>> import rastrum
    >>> tri = [(0, 0), (4, 0), (0, 4)]
    >>> rastrum.point_in_triangle((2, 2), tri, method="sameside")  # on the hypotenuse
    True
    >>> rastrum.point_in_triangle((2, 2), tri)  # a right edge: not owned
    False
    >>> rastrum.point_in_triangle((0, 2), tri)  # a left edge: owned
    True
    """
    code = PREDICATES[_core._name(method, "method", PREDICATES)]
    s = _core._subpixel_bits(subpixel_bits)
    q = snap_point(p, s, "p")
    t = _core.snap_points(tri, s, "tri")
    if t.shape != (3, 2):
        raise InputError("tri must be three (x, y) vertices, shape (3, 2), not %s" % (t.shape,))
    t = ffi.new("rast_point[3]", t.tolist())
    inside = ffi.new("int *")
    _core._check(lib.rast_point_in_triangle(q, t, code, inside))
    return bool(inside[0])

"""rastrum: exact, integer-only polygon filling.

Every algorithm gives the same pixels: those whose sample point is inside
the polygon under one exact rule (pixel centres by default, spans left
closed and right open, rows top closed and bottom open; see docs/semantics.md).
Coordinates are (x, y) as in Pillow; arrays are (row, column) = (y, x) as in
numpy.
"""

from typing import Any, Optional

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import InputError, RastrumError
from ._typing import Boundary, PolygonAlgorithm, PathRings, Rounding, Rule, Shape
from ._native import lib as _lib
from ._canvas import Canvas, _fill_opts
from ._lines import line_pixels, point_in_triangle
from ._triangles import TRIANGLE_ALGORITHMS as _TRIANGLE_ALGORITHMS, triangles_count, triangles_mask
from . import scene
from . import coco
from ._batch import Polygons
from ._ml import labels, masks
from .scene import render_mesh
from .gis import rasterize, IDENTITY, geometry_mask, geometry_window, grid
from ._zonal import zonal_stats
from ._fractions import coverage_fractions
from ._coverage import AA_ENTRIES as _AA_ENTRIES, METHODS as _COVERAGE_METHODS, polygon_coverage, triangles_coverage
from ._coverage import _plain_shape
from ._path import Path, path_rings as _path_rings
from ._strokes import stroke

__all__ = ["polygon_mask", "triangles_mask", "triangles_count", "line_pixels", "point_in_triangle", "Canvas",
           "ALGORITHMS", "RastrumError", "InputError", "__version__", "render_mesh", "scene", "rasterize",
           "IDENTITY", "zonal_stats", "coverage_fractions", "geometry_mask", "geometry_window", "grid", "coco", "masks", "labels", "Polygons",
           "polygon_coverage", "triangles_coverage", "AA_METHODS", "Path", "stroke"]

_v = _lib.rast_version_number()
__version__ = "%d.%d.%d" % (_v // 10000, _v // 100 % 100, _v % 100)

#: The algorithm names each entry point accepts, and the fill rules each
#: algorithm supports.
ALGORITHMS = {
    "polygon_mask": {name: rules for name, (_, rules) in _core.POLYGON_ALGORITHMS.items()},
}
ALGORITHMS["Canvas.fill_polygon"] = ALGORITHMS["polygon_mask"]
# A triangle is the same under either rule.
ALGORITHMS["triangles_mask"] = {name: ("evenodd", "nonzero") for name in _TRIANGLE_ALGORITHMS}
ALGORITHMS["triangles_count"] = ALGORITHMS["triangles_mask"]
ALGORITHMS["Canvas.fill_triangles"] = ALGORITHMS["triangles_mask"]
# Lines have no fill rules.
ALGORITHMS["Canvas.line"] = {"bresenham": (), "dda": ()}
# Coverage: the methods (docs/semantics.md, coverage) and the rules each takes;
# a triangle batch is one region (a union), whatever the rule.
ALGORITHMS["polygon_coverage"] = {name: ("evenodd", "nonzero") for name in _COVERAGE_METHODS}
ALGORITHMS["triangles_coverage"] = {name: ("evenodd", "nonzero") for name in _COVERAGE_METHODS}

#: The Canvas fills that take ``aa=`` (anti-aliased: coverage blended into
#: the pixels), and for each the methods ``aa`` accepts with the fill rules
#: each takes.  ``aa=None`` (the default) is the binary fill of
#: ``ALGORITHMS``; shaded fills (vertex colours, depth, per-triangle colours)
#: have no ``aa=``.
AA_METHODS = {entry: {name: ("evenodd", "nonzero") for name in _COVERAGE_METHODS}
              for entry in _AA_ENTRIES}

_PLAIN_RINGS = (list, tuple, np.ndarray)  # no curves: polygon_mask's quick path


def polygon_mask(rings: PathRings, shape: Shape, *, rule: Rule = "evenodd", algorithm: PolygonAlgorithm = "aet",
                 subpixel_bits: int = 8, sample_offset: float = 0.5, rounding: Rounding = "exact",
                 boundary: Boundary = "exact", tolerance: Optional[float] = None) -> npt.NDArray[np.bool_]:
    """Rasterise a polygon into a boolean mask.

    Parameters
    ----------
    rings : (N, 2) array_like or list of them, or a Path
        The polygon's closed rings as (x, y) vertices in pixels; the last
        vertex joins the first.  Several rings make holes and islands.
        A ``rastrum.Path`` or a matplotlib ``Path`` (e.g. ``TextPath``: a
        font's glyphs) is flattened within `tolerance`; a shapely
        (Multi)Polygon or ``__geo_interface__`` polygon gives its rings.
    shape : (int, int)
        (height, width) of the mask, as numpy writes it.
    rule : {"evenodd", "nonzero"}
        Fill rule.  Under "nonzero", holes must run opposite to their outer
        ring.
    algorithm : str
        One of ``ALGORITHMS["polygon_mask"]``; all give the same pixels,
        so the choice is speed and memory: "aet" (the default) for smooth
        shapes and either rule; "edgeflag" is faster on dense real outlines
        under even-odd (coastlines, contours, text: 0.55-0.95x aet's time
        in the benchmarks) at the cost of a bit of scratch per pixel of
        the polygon's box.
    subpixel_bits : int
        Vertices are snapped to 1/2**subpixel_bits pixel (0..32), the only
        approximation.  The coordinate range is +-(2**27 - 1) / 2**bits px
        for the 32-bit vertex path; above 16 bits, or past that range, the
        fill takes the 64-bit path (algorithm "aet", rounding "exact",
        boundary "exact" or "conservative"), whose range is +-2**28 px at
        every subpixel_bits, with the same pixels where both apply
        (docs/precision.md).
    sample_offset : {0.5, 0}
        Where a pixel's sample point is: its centre (0.5) or its top-left
        corner (0, as OpenCV and the textbook).
    rounding : {"exact", "textbook"}
        "textbook" rounds each crossing to the nearest sample column,
        halves going right, as the textbook's worked examples do (use it
        with ``sample_offset=0``).  Not exact; never the default.
    boundary : {"exact", "closed", "conservative"}
        "closed" adds the library's outline of every edge (what OpenCV and
        Pillow draw), "conservative" every pixel an edge passes through
        (GDAL's ALL_TOUCHED).  The default is the exact partition.
    tolerance : float or None
        How far (pixels, > 0) a Path's flattened curves may be from the
        true ones; None: the Path's own ``tolerance``, else
        ``Path.DEFAULT_TOLERANCE`` (docs/paths.md).  Rings have no curves.

    Returns
    -------
    numpy.ndarray of bool, shape (H, W)
        True where the pixel's sample is inside.

    Raises
    ------
    InputError (a ValueError)
        Its message names the argument and the problem: a bad `shape`
        (negative, not two ints, past 2**30 - 1), a NaN, infinite or
        out-of-range coordinate (which ring and point), coordinates that
        are not real numbers (bool, complex, str, None), a ring of 1 or 2
        points or not of shape (N, 2), an unknown name or option value.
        Empty input (no rings, or rings of no points) is not an error: the
        mask is all False.  Non-contiguous or read-only arrays are fine.
    MemoryError
        When numpy cannot allocate the (H, W) mask.

    Examples
    --------
    >>> import rastrum
    >>> m = rastrum.polygon_mask([(1, 1), (5, 1), (5, 4), (1, 4)], (6, 7))
    >>> m.astype(int)
    array([[0, 0, 0, 0, 0, 0, 0],
           [0, 1, 1, 1, 1, 0, 0],
           [0, 1, 1, 1, 1, 0, 0],
           [0, 1, 1, 1, 1, 0, 0],
           [0, 0, 0, 0, 0, 0, 0],
           [0, 0, 0, 0, 0, 0, 0]])
    """
    if tolerance is not None or not isinstance(rings, _PLAIN_RINGS):  # curves flattened (docs/paths.md)
        rings = _path_rings(rings, subpixel_bits, tolerance)
    # The defaults themselves (the very objects): no key to build and hash;
    # other options through Canvas's cache of checked options (str names, an
    # int S and a float offset looked up by value; anything else checked).
    if algorithm is _AET and rule is _EVENODD and subpixel_bits is _S8 and sample_offset is _HALF \
            and rounding is _EXACT and boundary is _EXACT:
        opts = _DEFAULT_OPTS
    else:
        opts = _fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
    # One C-contiguous float64 ring and a plain (h, w): straight to C, every
    # check of the general path made here in a few comparisons (shape: two
    # ints in 1..RAST_MAX_DIM; ring: (N >= 3, 2) float64).  Anything else,
    # and any error status, takes the general path, which checks and raises.
    # (strides (16, 8): two float64 per row, rows packed: C-contiguous (N, 2))
    # A list of one such ring ([ring], as a loop over shapes passes it) is
    # that ring: the general path's packing and checks were two thirds of
    # a 64-gon's call on a 512 x 512 mask.
    ring = rings[0] if type(rings) is list and len(rings) == 1 else rings
    # (the dtypes by identity, else by equality: an unpickled array's dtype
    # is an equal object of its own, which the identity alone sent the
    # general way)
    if type(ring) is _ndarray and (ring.dtype is _I32 or ring.dtype == _I32) and ring.strides == _PACKED32:
        ring = ring.astype(_F64)  # an OpenCV-style int32 (N, 2) ring: exact as float64
    if type(ring) is _ndarray and (ring.dtype is _F64 or ring.dtype == _F64) and ring.strides == _PACKED \
            and type(shape) is tuple \
            and len(shape) == 2 and ring.shape[1] == 2 and ring.flags.aligned:
        h, w = shape
        n = len(ring)
        # (_plain_shape's test, inline: a call of its own was ~2% of a 64-gon's 512 x 512 mask)
        if type(h) is int and type(w) is int and 0 < h <= _MAX_DIM and 0 < w <= _MAX_DIM and n >= 3:
            mask = _empty(shape, _BOOL)
            if not _mask_call(_from_buffer(mask), h, w, _from_buffer(_DOUBLES, ring), n, opts):
                return mask
    # A list of several rings in a form _seq.rings packs in one C pass (holes,
    # glyphs) is one C call too, on the 32-bit path: the general path's
    # numpy form of the points, its scan of every point for the 64-bit path
    # (use_wide: a point past the 32-bit range is refused by this call, and
    # the general path then takes it) and its shape checks were ~2 us of a
    # 512 x 512 mask's call.
    # (The points and ring sizes packed as bytes, which the call takes as
    # they are: ffi.from_buffer of each, and a function to make them, were
    # ~1.5 us of a glyph's 16 us call.)
    # C-contiguous float64 rings (a paragraph's glyphs, a map's countries)
    # are snapped by the call straight from their arrays (_seq.ring_ptrs:
    # their addresses, and a tuple that keeps them alive), not packed first.
    if type(rings) is list and len(rings) > 1:
        if _plain_shape(shape) is not None:
            got = _seq_ptrs(rings, _ndarray, _F64)
            if got is not None:
                ptrs, sizes, npts, keep = got
                if npts <= _MAX_POINTS:
                    h, w = shape
                    mask = _empty(shape, _BOOL)
                    if not _mask_rings(_from_buffer(mask), h, w, ptrs, npts, sizes, len(sizes) >> 2, opts):
                        return mask
            else:
                got = _seq_rings(rings, _ndarray, _RING_DTYPES, 1)
                if got is not None and len(got[0]) <= _MAX_POINTS_BYTES:
                    raw, sizes = got
                    h, w = shape
                    mask = _empty(shape, _BOOL)
                    if not _mask_packed(_from_buffer(mask), h, w, raw, len(raw) >> 4,
                                        _NULL if sizes is None else sizes, 1 if sizes is None else len(sizes) >> 2,
                                        opts):
                        return mask
    return _core.mask_polygon(_core.shape2(shape), rings, opts, opts.subpixel_bits)


_AET, _EVENODD, _S8, _HALF, _EXACT = (polygon_mask.__kwdefaults__[k] for k in (
    "algorithm", "rule", "subpixel_bits", "sample_offset", "rounding"))
assert polygon_mask.__kwdefaults__["boundary"] is _EXACT
_DEFAULT_OPTS = _core.fill_opts(_AET, _EVENODD, _S8, _HALF, _EXACT, _EXACT)
_ndarray, _empty = _core.np.ndarray, _core.np.empty
_F64, _BOOL = _core.np.dtype(_core.np.float64), _core.np.dtype(bool)
_MAX_DIM = _lib.RAST_MAX_DIM
_PACKED, _I32, _PACKED32 = (16, 8), _core.np.dtype(_core.np.int32), (8, 4)
_DOUBLES = _core.ffi.typeof("double[]")
_mask_call, _from_buffer = _lib.rastpy_mask_ring, _core.ffi.from_buffer
_mask_packed, _NULL = _lib.rastpy_mask_packed, _core.ffi.NULL
_seq_rings, _RING_DTYPES, _MAX_POINTS_BYTES = _core._seq.rings, _core._RING_DTYPES, _core._MAX_POINTS_BYTES
_seq_ptrs, _mask_rings, _MAX_POINTS = _core._seq.ring_ptrs, _lib.rastpy_mask_rings, _lib.RAST_MAX_POINTS


def __getattr__(name: str) -> Any:
    # rastrum.lib was the raw cffi library, never meant to be public: every
    # drawing call has a checked Python entry point above.
    if name == "lib":
        import warnings
        warnings.warn("rastrum.lib (the raw cffi library) is not public (deprecated: it will be removed in the "
                      "next release); use the functions of the rastrum namespace", DeprecationWarning, stacklevel=2)
        return _lib
    raise AttributeError("module 'rastrum' has no attribute %r" % (name,))

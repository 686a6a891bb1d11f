"""rastrum: exact, integer-only polygon filling.

Every algorithm gives the same pixels: those whose sample point is inside
the polygon under one exact rule (pixel centres by default, spans left
closed and right open, rows top closed and bottom open; see the README).
Coordinates are (x, y) as in Pillow; arrays are (row, column) = (y, x) as in
numpy.
"""

from . import _core
from ._core import InputError, RastrumError
from ._native import lib
from .canvas import Canvas
from .lines import line_pixels, point_in_triangle
from .triangles import TRIANGLE_ALGORITHMS as _TRIANGLE_ALGORITHMS, triangles_mask
from . import scene
from .scene import render_mesh
from .coverage import METHODS as _COVERAGE_METHODS, polygon_coverage, triangles_coverage

__all__ = ["polygon_mask", "triangles_mask", "line_pixels", "point_in_triangle", "Canvas", "ALGORITHMS",
           "RastrumError", "InputError", "__version__", "render_mesh", "scene",
           "polygon_coverage", "triangles_coverage"]

_v = lib.rast_version_number()
__version__ = "%d.%d.%d" % (_v // 10000, _v // 100 % 100, _v % 100)

#: The algorithm names each entry point accepts, and the fill rules each
#: algorithm supports.
ALGORITHMS = {
    "polygon_mask": {name: rules for name, (_, rules) in _core.POLYGON_ALGORITHMS.items()},
}
ALGORITHMS["Canvas.fill_polygon"] = ALGORITHMS["polygon_mask"]
# A triangle is the same under either rule.
ALGORITHMS["triangles_mask"] = {name: ("evenodd", "nonzero") for name in _TRIANGLE_ALGORITHMS}
ALGORITHMS["Canvas.fill_triangles"] = ALGORITHMS["triangles_mask"]
# Lines have no fill rules.
ALGORITHMS["Canvas.line"] = {"bresenham": (), "dda": ()}
# Coverage: the methods (DESIGN.md section 1a) and the rules each takes;
# a triangle batch is one region (a union), whatever the rule.
ALGORITHMS["polygon_coverage"] = {name: ("evenodd", "nonzero") for name in _COVERAGE_METHODS}
ALGORITHMS["triangles_coverage"] = {name: ("evenodd", "nonzero") for name in _COVERAGE_METHODS}

def polygon_mask(rings, shape, *, rule="evenodd", algorithm="aet", subpixel_bits=8, sample_offset=0.5,
                 rounding="exact", boundary="exact"):
    """Rasterise a polygon into a boolean mask.

    Parameters
    ----------
    rings : (N, 2) array_like or list of them
        The polygon's closed rings as (x, y) vertices in pixels; the last
        vertex joins the first.  Several rings make holes and islands.
    shape : (int, int)
        (height, width) of the mask, as numpy writes it.
    rule : {"evenodd", "nonzero"}
        Fill rule.  Under "nonzero", holes must run opposite to their outer
        ring.
    algorithm : str
        One of ``ALGORITHMS["polygon_mask"]``; all give the same pixels.
    subpixel_bits : int
        Vertices are snapped to 1/2**subpixel_bits pixel (0..16), the only
        approximation.  The coordinate range is +-(2**27 - 1) / 2**bits px.
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
    opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
    return _core.mask_polygon(_core.shape2(shape), rings, opts, opts.subpixel_bits)

"""Canvas: a target over a numpy array, with drawing methods."""

import numpy as np

from . import _core
from . import lines as _lines
from . import triangles as _triangles
from ._core import InputError
from ._native import ffi, lib

_NO_COLOR = object()  # equal to no colour: "nothing remembered yet"
_CHANNELS_TO_FORMAT = {1: "gray8", 3: "rgb888", 4: "rgba8888"}
_PIL_MODES = {"gray8": "L", "rgb888": "RGB", "rgba8888": "RGBA"}


class Canvas:
    """A picture that rastrum draws into.

    ``Canvas(width, height, format="rgb888", background=0)`` owns a new
    array; ``Canvas.wrap(array)`` draws into an existing one (a sub-view of
    a larger image is fine).  Formats: "gray8" (H, W), "rgb888" (H, W, 3),
    "rgba8888" (H, W, 4), all uint8.  A colour is an int for gray8, or a
    sequence of 3 or 4 ints; a single int is used for every channel.

    Bad input raises InputError (a ValueError) naming the argument and the
    problem, before any pixel is written: sizes that are negative, not
    ints or past 2**30 - 1; unknown formats; colours out of 0..255 or of
    the wrong length or type; NaN, infinite, out-of-range or non-real
    coordinates; too few vertices; unknown names; and drawing while the
    array is read-only (made so after ``Canvas.wrap``).  Empty input (no
    rings, no triangles, no points) draws nothing and is not an error; a
    canvas of width or height 0 is fine and never drawn on.  ``save``
    raises what Pillow raises (ValueError for an unknown file extension,
    OSError for a path it cannot write).

    Examples
    --------
    >>> import rastrum
    >>> c = rastrum.Canvas(8, 6, format="gray8")
    >>> c.fill_polygon([(1, 1), (7, 1), (4, 5)], 255)
    >>> int(c.array.sum() // 255)
    12
    """

    def __init__(self, width, height, format="rgb888", background=0):
        h, w = _core.shape2((height, width))
        fmt = _core._name(format, "format", _core.FORMATS)
        bpp = _core.FORMAT_BYTES[fmt]
        array = np.empty((h, w) if bpp == 1 else (h, w, bpp), np.uint8)
        array[...] = np.frombuffer(_pixel_bytes(background, fmt), np.uint8)
        self._set(array, fmt)

    @classmethod
    def wrap(cls, array, format=None):
        """Draw into an existing uint8 array (no copy).

        The format follows from the shape when not given: (H, W) is gray8,
        (H, W, 3) rgb888, (H, W, 4) rgba8888.  The array must be writable
        and each row's pixels contiguous (any row stride, so a slice
        ``big[10:-10, 10:-10]`` works).  InputError otherwise: not a numpy
        array, not uint8, another shape, a format that does not match,
        read-only (also a broadcast view), a column stride or reversed
        rows.  If the array is made read-only later, drawing raises
        InputError and writes nothing.
        """
        if not isinstance(array, np.ndarray):
            raise InputError("Canvas.wrap needs a numpy array, not %s" % type(array).__name__)
        if array.dtype != np.uint8:
            raise InputError("Canvas.wrap needs a uint8 array, not %s" % array.dtype)
        if array.ndim == 2:
            channels = 1
        elif array.ndim == 3 and array.shape[2] in (3, 4):
            channels = array.shape[2]
        else:
            raise InputError("Canvas.wrap needs shape (H, W), (H, W, 3) or (H, W, 4), not %s" % (array.shape,))
        fmt = _CHANNELS_TO_FORMAT[channels] if format is None else _core._name(format, "format", _core.FORMATS)
        if _core.FORMAT_BYTES[fmt] != channels:
            raise InputError("format %r does not match an array of shape %s" % (fmt, array.shape))
        if not array.flags.writeable:
            raise InputError("Canvas.wrap needs a writable array")
        h, w = array.shape[:2]
        if array.size and h > 1 and array.strides[0] < w * channels or (
            array.size and (array.strides[1] != channels or (channels > 1 and array.strides[2] != 1))
        ):
            raise InputError("Canvas.wrap needs each row's pixels contiguous and rows in order (strides %s)" % (array.strides,))
        canvas = cls.__new__(cls)
        canvas._set(array, fmt)
        return canvas

    def _writable(self):
        """The target, once the array is known to be still writable (it may
        have been made read-only after Canvas.wrap)."""
        if not self._array.flags.writeable:
            raise InputError("the canvas's array is read-only; nothing was drawn")
        return self._target

    def _pixel(self, color):
        """The colour's pixel bytes as a cdata, remembered for the last colour."""
        try:
            if color == self._last_color[0] and type(color) is type(self._last_color[0]):
                return self._last_color[1]
        except (TypeError, ValueError):  # e.g. a numpy array as the colour
            pass
        pixel = ffi.from_buffer(_pixel_bytes(color, self._format))
        self._last_color = (color if isinstance(color, (int, tuple)) else _NO_COLOR, pixel)
        return pixel

    def _set(self, array, fmt):
        self._last_color = (_NO_COLOR, None)
        self._array = array
        self._format = fmt
        self._code = _core.FORMATS[fmt]
        self._target = _core.make_target(array, self._code)

    @property
    def array(self):
        """The pixels as a numpy view: (H, W) or (H, W, channels)."""
        return self._array

    @property
    def width(self):
        return self._array.shape[1]

    @property
    def height(self):
        return self._array.shape[0]

    @property
    def format(self):
        return self._format

    def fill_polygon(self, rings, color, *, rule="evenodd", algorithm="aet", subpixel_bits=8,
                     sample_offset=0.5, rounding="exact", boundary="exact"):
        """Paint `color` on every pixel whose sample is inside the polygon.

        Arguments as :func:`rastrum.polygon_mask`.  Nothing is written when
        an argument is bad (an InputError says which; see the class).
        """
        opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
        pixel = self._pixel(color)
        _core.fill_polygon(self._writable(), rings, pixel, opts, opts.subpixel_bits)

    def fill_triangle(self, tri, color, *, algorithm="edge", subpixel_bits=8, sample_offset=0.5,
                      rounding="exact", boundary="exact"):
        """Paint `color` on every pixel the triangle `tri` owns.

        `tri` is three (x, y) vertices, in either winding order; the other
        arguments are those of :func:`rastrum.triangles_mask`.  A degenerate
        triangle paints nothing.  Nothing is written when an argument is bad.
        """
        opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
        batch = _triangles.tris_f64(tri, single=True)
        _triangles.fill_triangles(self._writable(), batch, self._pixel(color), opts, "tri")

    def fill_triangles(self, tris, color, *, algorithm="edge", subpixel_bits=8, sample_offset=0.5,
                       rounding="exact", boundary="exact"):
        """Paint `color` on every pixel owned by a triangle of the batch.

        `tris` is an (N, 3, 2) array-like of (x, y) vertices, drawn in one C
        call; the other arguments are those of
        :func:`rastrum.triangles_mask`.  Only the covered pixels are written,
        and nothing at all when an argument is bad.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas(6, 4, format="gray8")
        >>> c.fill_triangles([[(0, 0), (4, 0), (4, 4)], [(0, 0), (4, 4), (0, 4)]], 9)
        >>> c.array
        array([[9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0]], dtype=uint8)
        """
        opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
        batch = _triangles.tris_f64(tris)
        pixel = self._pixel(color)
        _triangles.fill_triangles(self._writable(), batch, pixel, opts)

    def line(self, p0, p1, color, *, algorithm="bresenham", subpixel_bits=8, sample_offset=0.5):
        """Paint `color` on the pixels of the segment p0 -> p1.

        The pixels are :func:`rastrum.line_pixels` (p0, p1) within the
        canvas; the rest of the line is clipped.  Arguments as there.
        Nothing is written when an argument is bad (an InputError says
        which).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas(6, 3, format="gray8")
        >>> c.line((0, 0), (5, 2), 1, subpixel_bits=0, sample_offset=0)
        >>> c.array
        array([[1, 1, 0, 0, 0, 0],
               [0, 0, 1, 1, 0, 0],
               [0, 0, 0, 0, 1, 1]], dtype=uint8)
        """
        opts = _lines.line_opts(algorithm, subpixel_bits, sample_offset)
        a = _lines.snap_point(p0, opts.subpixel_bits, "p0")
        b = _lines.snap_point(p1, opts.subpixel_bits, "p1")
        _core._check(lib.rast_draw_line(self._writable(), a, b, opts, self._pixel(color)))

    def polyline(self, points, color, *, closed=False, algorithm="bresenham", subpixel_bits=8,
                 sample_offset=0.5):
        """Paint the segments points[k] -> points[k+1]; with ``closed=True``
        also the last point -> the first (an outline).

        Each segment is :meth:`line`; a vertex shared by two segments is
        painted by both.  `points` is an (N, 2) array-like, N >= 2 (N = 0
        draws nothing; N = 1 is an InputError); `closed` is a bool.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas(5, 5, format="gray8")
        >>> c.polyline([(0, 0), (4, 0), (0, 4)], 1, closed=True, subpixel_bits=0, sample_offset=0)
        >>> c.array
        array([[1, 1, 1, 1, 1],
               [1, 0, 0, 1, 0],
               [1, 0, 1, 0, 0],
               [1, 1, 0, 0, 0],
               [1, 0, 0, 0, 0]], dtype=uint8)
        """
        opts = _lines.line_opts(algorithm, subpixel_bits, sample_offset)
        if not isinstance(closed, (bool, np.bool_)):
            raise InputError("closed must be True or False, not %r" % (closed,))
        pts = _lines.snap_polyline(points, opts.subpixel_bits, 2)
        pixel = self._pixel(color)
        target = self._writable()
        if len(pts):
            _core._check(lib.rast_draw_polyline(target, ffi.from_buffer("rast_point[]", pts), len(pts),
                                                1 if closed else 0, opts, pixel))

    def to_image(self):
        """A Pillow image (a copy): mode L, RGB or RGBA."""
        from PIL import Image

        return Image.fromarray(np.ascontiguousarray(self._array), _PIL_MODES[self._format])

    def save(self, path, **kwargs):
        """Save through Pillow; the format follows the file name (PNG, ...)."""
        self.to_image().save(path, **kwargs)

    def __repr__(self):
        return "Canvas(%d, %d, format=%r)" % (self.width, self.height, self._format)


def _pixel_bytes(color, fmt):
    """The pixel's bytes for `color` in format `fmt`, or InputError."""
    n = _core.FORMAT_BYTES[fmt]
    if isinstance(color, (int, np.integer)) and not isinstance(color, (bool, np.bool_)):
        values = [int(color)] * n
    else:
        try:
            values = [v for v in color]
        except TypeError:
            raise InputError("colour %r: give an int or a sequence of %d ints" % (color, n)) from None
        if len(values) != n or not all(
            isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_)) for v in values
        ):
            raise InputError("colour %r: format %s needs %d ints" % (color, fmt, n))
    if not all(0 <= v <= 255 for v in values):
        raise InputError("colour %r: every channel must be in 0..255" % (color,))
    return bytes(bytearray(int(v) for v in values))

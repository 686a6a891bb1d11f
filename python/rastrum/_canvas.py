"""Canvas: a target over a numpy array, with drawing methods."""

import functools
from typing import IO, TYPE_CHECKING, Any, Callable, Literal, Optional, Tuple, TypeVar, Union, cast, overload

import numpy as np
import numpy.typing as npt

from . import _core
from . import _coverage
from . import _lines
from . import _shading
from . import _triangles
from ._core import InputError
from ._native import ffi, lib
from ._typing import (Boundary, Color, CoverageMethod, Format, LineAlgorithm, Point, PolygonAlgorithm, Precision,
                      Rings, Rounding, Rule, Shading, Shape, TriangleAlgorithm)

if TYPE_CHECKING:
    import os

    import PIL.Image

_F = TypeVar("_F", bound=Callable[..., Any])
_NO_COLOR = object()  # equal to no colour: "nothing remembered yet"
_CHANNELS_TO_FORMAT = {1: "gray8", 3: "rgb888", 4: "rgba8888"}
_PIL_MODES = {"gray8": "L", "rgb888": "RGB", "rgba8888": "RGBA", "rgb565": "RGB", "mono1": "1"}
_FORMAT_NAMES = tuple(_core.FORMATS) + ("label",)
_CHANNELS = _shading._CHANNELS


def _label_spill(method: _F) -> _F:
    """Drawing on a label canvas whose items have 8 bytes (no C format has
    8-byte pixels): draw the same call with value 1 into a uint8 mask, then
    write the value where it is set.  Other canvases: the method itself."""
    @functools.wraps(method)
    def draw(self: "Canvas", *args: Any, **kwargs: Any) -> Any:
        if self._format != "label" or self._code is not None:
            return method(self, *args, **kwargs)
        names = method.__code__.co_varnames[1:method.__code__.co_argcount]
        kwargs.update(zip(names, args))
        color = kwargs.get("color", None)
        if kwargs.get("aa") is not None:
            raise InputError("a label canvas holds labels, which do not blend: aa=None")
        if kwargs.get("vertex_colors") is not None or kwargs.get("depth") is not None:
            raise InputError("a label canvas has no channels to shade: give one int color")
        value = np.frombuffer(self._value_bytes(color), self._array.dtype)[0]
        if not self._array.flags.writeable:
            raise InputError("the canvas's array is read-only; nothing was drawn")
        scratch = Canvas.wrap(np.zeros(self._array.shape, np.uint8))
        kwargs["color"] = 1
        method(scratch, **kwargs)
        self._array[scratch._array != 0] = value
    return cast(_F, draw)


class Canvas:
    """A picture that rastrum draws into.

    ``Canvas((height, width), format="rgb888", background=0)`` owns a new
    array of that shape, (H, W) as numpy writes it (the old spelling
    ``Canvas(width, height)`` still works for one release, with a
    DeprecationWarning); ``Canvas.wrap(array)`` draws into an existing one
    (a sub-view of a larger image is fine).  Formats: "gray8" (H, W), "rgb888" (H, W, 3),
    "rgba8888" (H, W, 4), all uint8; "rgb565" (H, W) uint16 (R in bits
    15-11, G 10-5, B 4-0, as TFT displays take it); "mono1", one bit per
    pixel (e-paper), kept packed 8 pixels a byte, MSB first, in an
    (H, ceil(W/8)) uint8 buffer (``packed``).  A colour is an int for
    gray8, or a sequence of 3 or 4 ints; a single int is used for every
    channel.  rgb565 takes (R, G, B) in 0..255 and keeps their top 5, 6 and
    5 bits; mono1 takes an int, on iff it is not 0.

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
    >>> c = rastrum.Canvas((6, 8), format="gray8")
    >>> c.fill_polygon([(1, 1), (7, 1), (4, 5)], 255)
    >>> int(c.array.sum() // 255)
    12
    """

    @overload
    def __init__(self, shape: Shape, format: Format = "rgb888", background: Color = 0) -> None: ...

    @overload
    def __init__(self, shape: Shape, *, format: Format = "rgb888", background: Color = 0) -> None: ...

    def __init__(self, shape: Optional[Shape] = None, *args: Any, format: Format = "rgb888",  # type: ignore[misc]
                 background: Color = 0, width: Optional[int] = None, height: Optional[int] = None) -> None:
        # format and background may come by position; so may the height of
        # the deprecated Canvas(width, height, format, background).
        _legacy_height, format, background = _positional(shape, args, format, background)
        h, w = _canvas_shape(shape, _legacy_height, width, height)
        fmt = _core._name(format, "format", _FORMAT_NAMES)
        if fmt == "label":
            raise InputError('format "label" is for Canvas.wrap of an integer (H, W) array; a new label '
                             'canvas: Canvas.wrap(np.zeros((H, W), np.int32), format="label")')
        value = _pixel_bytes(background, fmt)
        if fmt == "mono1":
            array = np.full((h, (w + 7) // 8), 0xFF if value[0] else 0, np.uint8)
        elif fmt == "rgb565":
            array = np.empty((h, w), np.uint16)
            array[...] = np.frombuffer(value, np.uint16)
        else:
            bpp = _core.FORMAT_BYTES[fmt]
            array = np.empty((h, w) if bpp == 1 else (h, w, bpp), np.uint8)
            array[...] = np.frombuffer(value, np.uint8)
        self._set(array, fmt, w)

    @classmethod
    def wrap(cls, array: npt.NDArray[Any], format: Union[Format, Literal["label"], None] = None) -> "Canvas":
        """Draw into an existing array (no copy).

        For uint8 arrays the format follows from the shape when not given:
        (H, W) is gray8, (H, W, 3) rgb888, (H, W, 4) rgba8888.  Any other
        dtype needs ``format=``, because the dtype alone does not say what
        a value means (a uint16 array may be RGB565 pixels or a label
        image):

        - ``format="rgb565"``: a uint16 (H, W) array of RGB565 pixels;
          colours are (R, G, B) in 0..255.
        - ``format="label"``: an (H, W) array of any integer dtype (int8 ..
          uint64; a uint8 array too), a label image: a colour is one int
          that fits the dtype, written as it is.  Polygons, triangles,
          lines and (for dtypes of 1, 2 or 4 bytes) flood and boundary
          fills work; shading does not (there are no channels).

        The array must be writable and each row's pixels contiguous (any row
        stride, so a slice ``big[10:-10, 10:-10]`` works).  mono1 cannot be
        wrapped (a packed row does not say its width).  InputError otherwise:
        not a numpy array, a dtype without ``format=``, another shape, a
        format that does not match, read-only (also a broadcast view), a
        column stride or reversed rows.  If the array is made read-only
        later, drawing raises InputError and writes nothing.

        Examples
        --------
        >>> import numpy as np, rastrum
        >>> labels = np.zeros((3, 4), np.int32)
        >>> c = rastrum.Canvas.wrap(labels, format="label")
        >>> c.fill_polygon([(0, 0), (3, 0), (3, 2), (0, 2)], 70000)
        >>> labels
        array([[70000, 70000, 70000,     0],
               [70000, 70000, 70000,     0],
               [    0,     0,     0,     0]], dtype=int32)
        """
        if not isinstance(array, np.ndarray):
            raise InputError("Canvas.wrap needs a numpy array, not %s" % type(array).__name__)
        if format is not None:
            format = _core._name(format, "format", _FORMAT_NAMES)
        if format == "label":
            return cls._wrap_label(array)
        if array.dtype == np.uint16 and format is None:
            raise InputError('Canvas.wrap of a uint16 array needs format="rgb565" (RGB565 pixels) or '
                             'format="label" (a label image): the dtype alone does not say which')
        if array.dtype == np.uint16 and format == "rgb565":
            if array.ndim != 2 or not array.flags.writeable or (array.size and array.strides[1] != 2):
                raise InputError("Canvas.wrap takes dtype uint16 only as rgb565: a writable (H, W) array with "
                                 "contiguous rows, not shape %s" % (array.shape,))
            canvas = cls.__new__(cls)
            canvas._set(array, "rgb565", array.shape[1])
            return canvas
        if array.dtype != np.uint8:
            raise InputError('Canvas.wrap needs a uint8 array (or uint16 with format="rgb565", or any integer '
                             'dtype with format="label"), not %s' % array.dtype)
        if array.ndim == 2:
            channels = 1
        elif array.ndim == 3 and array.shape[2] in (3, 4):
            channels = array.shape[2]
        else:
            raise InputError("Canvas.wrap needs shape (H, W), (H, W, 3) or (H, W, 4), not %s" % (array.shape,))
        fmt = _CHANNELS_TO_FORMAT[channels] if format is None else format
        if fmt in ("mono1", "rgb565"):
            raise InputError("Canvas.wrap: format %s needs %s" % (
                fmt, "a uint16 (H, W) array" if fmt == "rgb565" else "a Canvas of its own (a packed row does not say its width)"))
        if _core.FORMAT_BYTES[fmt] != channels:
            raise InputError("format %r does not match an array of shape %s" % (fmt, array.shape))
        _check_rows(array, channels)
        canvas = cls.__new__(cls)
        canvas._set(array, fmt, array.shape[1])
        return canvas

    @classmethod
    def _wrap_label(cls, array):
        """A label canvas: integer (H, W) values written as they are.  Items
        of 1, 2 and 4 bytes are drawn by C as gray8, rgb565 and rgba8888
        pixels whose bytes are the value's (those painters copy a pixel's
        bytes verbatim); 8-byte items through a uint8 mask (Python)."""
        if array.dtype.kind not in "iu":
            raise InputError('Canvas.wrap(format="label") needs an integer array, not %s' % array.dtype)
        if array.ndim != 2:
            raise InputError('Canvas.wrap(format="label") needs an (H, W) array, not shape %s' % (array.shape,))
        _check_rows(array, array.dtype.itemsize)
        canvas = cls.__new__(cls)
        canvas._set(array, "label", array.shape[1])
        return canvas

    def _writable(self):
        """The target, once the array is known to be still writable (it may
        have been made read-only after Canvas.wrap)."""
        if self._target is None:
            raise InputError("a label canvas of %d-byte integers takes polygons, triangles and lines, "
                             "not this call (seed fills need 1, 2 or 4-byte labels)" % self._array.dtype.itemsize)
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
        pixel = ffi.from_buffer(self._value_bytes(color))
        self._last_color = (color if isinstance(color, (int, tuple)) else _NO_COLOR, pixel)
        return pixel

    def _value_bytes(self, color):
        """A colour's pixel bytes in this canvas's format (a label: the
        value in the array's own dtype)."""
        if self._format == "label":
            return _label_bytes(color, self._array.dtype)
        return _pixel_bytes(color, self._format)

    def _set(self, array, fmt, width):
        self._last_color = (_NO_COLOR, None)
        self._array = array
        self._format = fmt
        self._width = width
        if fmt == "label":  # drawn by C through the format of the item's size
            code = _LABEL_FORMATS.get(array.dtype.itemsize)
            self._code = code
            self._target = None if code is None else _core.make_target(array, code)
        else:
            self._code = _core.FORMATS[fmt]
            self._target = _core.make_target(array, self._code, width if fmt == "mono1" else None)
        self._depth = None

    @property
    def array(self) -> npt.NDArray[Any]:
        """The pixels: a numpy VIEW of the canvas's buffer, (H, W) or (H, W,
        channels), rgb565 a uint16 (H, W) view, a label canvas the wrapped
        array itself; writing to it changes the picture.  The one
        exception is mono1, whose buffer packs 8 pixels a byte: there
        ``array`` is an unpacked (H, W) uint8 COPY of 0/1 made at each
        access (writing to it changes nothing); ``packed`` is the buffer
        itself."""
        if self._format == "mono1":
            return np.unpackbits(self._array, axis=1, count=self._width) if self._array.size else \
                np.zeros((self._array.shape[0], self._width), np.uint8)
        return self._array

    @property
    def packed(self) -> npt.NDArray[np.uint8]:
        """The buffer C draws into, as a view: for mono1 (H, ceil(W/8))
        uint8, pixel x of a row at bit 7 - x % 8 of byte x // 8; for the
        other formats the same as ``array``."""
        return self._array

    def clear_depth(self) -> None:
        """Forget the depth buffer: the next depth-tested fill starts afresh
        (``depth`` back to None)."""
        self._depth = None

    @property
    def depth(self) -> Optional[npt.NDArray[np.int32]]:
        """The depth buffer: None (none yet), or an (H, W) int32 array, C
        contiguous and writable, that depth-tested fills read and write.

        It may be set to such an array (or None); anything else raises
        InputError and leaves the buffer as it was: another shape, dtype
        (int64 too: C reads 4-byte pixels), byte order or layout, a
        read-only array, or not an array.  The buffer is checked again on
        every fill that uses it (an array can be reshaped in place)."""
        return self._depth

    @depth.setter
    def depth(self, value: Optional[npt.ArrayLike]) -> None:
        self._depth = self._checked_depth(value)

    def _checked_depth(self, value):
        if value is None:
            return None
        shape = (self.height, self.width)
        if not isinstance(value, np.ndarray):
            raise InputError("depth must be None or an (H, W) = %s int32 numpy array, not %s"
                             % (shape, type(value).__name__))
        if value.dtype != np.int32 or not value.dtype.isnative:
            raise InputError("depth must have dtype int32 (native byte order), not %s" % value.dtype)
        if value.shape != shape:
            raise InputError("depth must have the canvas's shape (H, W) = %s, not %s" % (shape, value.shape))
        if not value.flags.c_contiguous:
            raise InputError("depth must be C-contiguous (np.ascontiguousarray)")
        if not value.flags.aligned:  # C loads int32 from it (a fault on strict-alignment CPUs)
            raise InputError("depth must be aligned to 4 bytes (a view at an odd byte offset is not; "
                             "np.require(depth, np.int32, 'CA') copies it)")
        if not value.flags.writeable:
            raise InputError("depth must be writable")
        return value

    @property
    def width(self) -> int:
        return self._width

    @property
    def height(self) -> int:
        return self._array.shape[0]

    @property
    def format(self) -> str:
        return self._format

    def _fill_aa(self, geometry, color, aa, rule, subpixel_bits, sample_offset, entry, *,
                 vertex_colors=None, depth=None, **binary_only):
        """An anti-aliased fill (``aa=`` not None) of a polygon's rings, or of
        a checked (N, 3, 2) triangle batch for the triangle entries."""
        if depth is not None:
            raise InputError("%s: depth is for binary shaded fills (aa=None); with aa=%r leave "
                             "it out (draw the batch back to front)" % (entry, aa))
        if vertex_colors is not None and entry == "Canvas.fill_polygon":
            raise InputError("Canvas.fill_polygon: aa=%r paints one colour; vertex_colors is for "
                             "binary shaded polygons (aa=None), or triangulate the polygon and "
                             "use fill_triangles(..., vertex_colors=..., aa=%r)" % (aa, aa))
        shading = binary_only.pop("shading", ("gouraud", "gouraud"))[0]
        precision = binary_only.pop("precision", ("exact", "exact"))[0]
        if vertex_colors is None:  # one colour: no shading to choose
            binary_only.update(shading=(shading, "gouraud"), precision=(precision, "exact"))
        opts = _coverage.aa_opts(aa, rule, subpixel_bits, sample_offset, entry, binary_only)
        if self._format == "label":
            raise InputError("a label canvas holds labels, which do not blend: aa=None")
        if vertex_colors is not None:
            self._fill_shaded_aa(geometry, color, vertex_colors, shading, precision, aa, opts,
                                 entry)
            return
        if color is None:
            raise InputError("%s needs color" % entry)
        if _core.ndim(color) >= 2:
            raise InputError("%s: aa=%r takes one colour for the whole batch, not one per triangle"
                             % (entry, aa))
        pixel = self._pixel(color)
        if entry == "Canvas.fill_polygon":
            _coverage.fill_polygon_aa(self._writable(), geometry, pixel, opts)
        else:
            _coverage.fill_triangles_aa(self._writable(), geometry, pixel, opts,
                                        "tri" if entry == "Canvas.fill_triangle" else "tris")

    def _fill_shaded_aa(self, batch, color, vertex_colors, shading, precision, aa, opts, entry):
        """Gouraud (or flat) colour times the batch's coverage
        (rast_fill_triangles_shaded_aa)."""
        if color is not None:
            raise InputError("%s takes exactly one of color and vertex_colors" % entry)
        precision = _core.shading_precision(shading, precision)
        if not isinstance(precision, str) or precision not in ("exact", "flat"):
            raise InputError("%s: aa=%r shades with precision \"exact\" (or shading=\"flat\"), "
                             "not %r; precision=\"fixed\" is for binary fills (aa=None)"
                             % (entry, aa, precision))
        channels = _CHANNELS.get(self._format, 0)
        if not channels:
            raise InputError("format %s has no colours to shade" % self._format)
        if entry == "Canvas.fill_triangle":
            vc = np.asarray(vertex_colors)
            vertex_colors = vc[None] if vc.ndim == 2 else vc
        colors = _shading.rgba(vertex_colors, batch.shape[0], True, self._format, channels)
        _coverage.fill_triangles_shaded_aa(self._writable(), batch, colors, opts,
                                           _shading.shade_opts(precision, 16),
                                           "tri" if entry == "Canvas.fill_triangle" else "tris")

    @_label_spill
    def fill_polygon(self, rings: Rings, color: Optional[Color] = None, *, rule: Rule = "evenodd",
                     algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
                     rounding: Rounding = "exact", boundary: Boundary = "exact",
                     vertex_colors: Optional[npt.ArrayLike] = None, shading: Shading = "gouraud",
                     precision: Precision = "exact", aa: Optional[CoverageMethod] = None) -> None:
        """Paint `color` on every pixel whose sample is inside the polygon.

        Arguments as :func:`rastrum.polygon_mask`.  Nothing is written when
        an argument is bad (an InputError says which; see the class).

        With `aa` (one of ``AA_METHODS["Canvas.fill_polygon"]``: "area",
        "ss2".."ss16", "accumulate"; see :func:`rastrum.polygon_coverage`)
        the fill is anti-aliased: each pixel's coverage level c (0..255, as
        ``polygon_coverage(..., method=aa)`` gives it for the same `rule`,
        `subpixel_bits` and `sample_offset`) weights `color`: every channel
        d becomes (s*c + d*(255 - c) + 127) // 255 (rgb565: on its 5/6/5
        bits; rgba8888: alpha too), mono1 takes the colour where c >= 128,
        pixels with c = 0 are untouched.  `algorithm`, `rounding`,
        `boundary` and `vertex_colors` are for binary fills (aa=None) only
        (for colours per vertex, triangulate and use :meth:`fill_triangles`
        with `vertex_colors` and `aa`).

        With `vertex_colors` instead of `color`: one colour per vertex, an
        (N, C) array-like for the N vertices of all rings in order (or a
        list of one (N_k, C) per ring), C the canvas's channels; the
        active edge table interpolates them along each edge to the row,
        then along the span, rounded half up (``precision="exact"``);
        ``shading="flat"`` paints vertex 0's colour instead.  Only
        ``algorithm="aet"``.  Give exactly one of `color` and
        `vertex_colors`, as for :meth:`fill_triangle` and
        :meth:`fill_triangles`.
        """
        # The common call (one C-contiguous float64 (N, 2) ring, or a list of
        # (x, y) pairs, and a colour) goes straight to C, which snaps every
        # point before it writes a pixel (and refuses what the 64-bit path
        # must draw: subpixel_bits above 16, coordinates past the 32-bit
        # range); anything else, or an error status, takes the general path
        # below, which checks and says what is wrong.
        if aa is None and vertex_colors is None:
            if algorithm is _AET and rule is _EVENODD and subpixel_bits is _S8 and sample_offset is _HALF \
                    and rounding is _EXACT and boundary is _EXACT:
                opts = _DEFAULT_OPTS
            else:  # checked (InputError as below), remembered
                opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
            xy = None
            if type(rings) is _ndarray:
                if rings.dtype is _F64 and rings.strides == _PACKED and rings.shape[1] == 2:
                    xy, n = rings, len(rings)
            elif type(rings) is list:
                got = _seq_rings(rings, _ndarray, _RING_DTYPES)
                if got is not None and got[1] is None:  # one ring of pairs
                    xy = got[0]
                    n = len(xy) >> 4
            target = self._target
            if xy is not None and n >= 3 and color is not None and target is not None \
                    and self._array.flags.writeable:
                last = self._last_color
                pixel = last[1] if color is last[0] and type(color) is int else self._pixel(color)
                if not _fill_ring(target, _from_buffer(_DOUBLES, xy), n, opts, pixel):
                    return
        if aa is not None:
            self._fill_aa(rings, color, aa, rule, subpixel_bits, sample_offset, "Canvas.fill_polygon",
                          algorithm=(algorithm, "aet"), rounding=(rounding, "exact"),
                          boundary=(boundary, "exact"), shading=(shading, "gouraud"),
                          precision=(precision, "exact"), vertex_colors=vertex_colors)
            return
        opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
        if vertex_colors is not None:

            if color is not None:
                raise InputError("fill_polygon takes exactly one of color and vertex_colors")
            if self._format == "label":
                raise InputError("a label canvas has no channels to shade: give one int color")
            _shading.fill_polygon_gouraud(self, rings, vertex_colors, opts,
                                          _core.shading_precision(shading, precision))
            return
        if color is None:
            raise InputError("fill_polygon needs color or vertex_colors")
        pixel = self._pixel(color)
        _core.fill_polygon(self._writable(), rings, pixel, opts, opts.subpixel_bits)

    @_label_spill
    def fill_triangle(self, tri: npt.ArrayLike, color: Optional[Color] = None, *,
                      vertex_colors: Optional[npt.ArrayLike] = None, shading: Shading = "gouraud",
                      precision: Precision = "exact", fraction_bits: int = 16,
                      algorithm: TriangleAlgorithm = "edge", subpixel_bits: int = 8, sample_offset: float = 0.5,
                      rounding: Rounding = "exact", boundary: Boundary = "exact", aa: Optional[CoverageMethod] = None) -> None:
        """Paint `color` on every pixel the triangle `tri` owns.

        `tri` is three (x, y) vertices, in either winding order; the other
        arguments are those of :func:`rastrum.triangles_mask`.  A degenerate
        triangle paints nothing.  Nothing is written when an argument is bad.
        Give exactly one of `color` and `vertex_colors` (a (3, C) array, a
        colour per vertex, shaded as by :meth:`fill_triangles`), as for
        :meth:`fill_polygon`.  `aa`: anti-aliased, as :meth:`fill_triangles`.
        """
        if aa is not None:
            self._fill_aa(_triangles.tris_f64(tri, single=True), color, aa, "nonzero", subpixel_bits,
                          sample_offset, "Canvas.fill_triangle", algorithm=(algorithm, "edge"),
                          rounding=(rounding, "exact"), boundary=(boundary, "exact"),
                          shading=(shading, "gouraud"), precision=(precision, "exact"),
                          vertex_colors=vertex_colors)
            return
        if vertex_colors is not None:
            if color is not None:
                raise InputError("fill_triangle takes exactly one of color and vertex_colors")
            batch = _triangles.tris_f64(tri, single=True)
            vc = np.asarray(vertex_colors)
            self.fill_triangles(batch, vertex_colors=vc[None] if vc.ndim == 2 else vc, shading=shading,
                                precision=precision, fraction_bits=fraction_bits, algorithm=algorithm,
                                subpixel_bits=subpixel_bits, sample_offset=sample_offset, rounding=rounding,
                                boundary=boundary)
            return
        if color is None:
            raise InputError("fill_triangle needs color or vertex_colors")
        opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
        batch = _triangles.tris_f64(tri, single=True)
        _triangles.fill_triangles(self._writable(), batch, self._pixel(color), opts, "tri")

    @_label_spill
    def fill_triangles(self, tris: npt.ArrayLike, color: Optional[npt.ArrayLike] = None, *,
                       vertex_colors: Optional[npt.ArrayLike] = None, shading: Shading = "gouraud",
                       precision: Precision = "exact", fraction_bits: int = 16,
                       depth: Optional[npt.ArrayLike] = None, algorithm: TriangleAlgorithm = "edge",
                       subpixel_bits: int = 8, sample_offset: float = 0.5, rounding: Rounding = "exact",
                       boundary: Boundary = "exact", aa: Optional[CoverageMethod] = None) -> None:
        """Paint every pixel owned by a triangle of the batch.

        `tris` is an (N, 3, 2) array-like of (x, y) vertices, drawn in one C
        call; `algorithm`, `subpixel_bits`, `sample_offset`, `rounding` and
        `boundary` are those of :func:`rastrum.triangles_mask`.  Only the
        covered pixels are written, and nothing at all when an argument is
        bad.  Give exactly one of:

        - `color`: one colour for the whole batch, or an (N, C) int array,
          one colour per triangle (flat shading);
        - `vertex_colors`: an (N, 3, C) int array, a colour per vertex,
          interpolated over each triangle (Gouraud).  C is 1 (a level, used
          for R, G and B), 3 (R, G, B; alpha 255) or 4 (R, G, B, A: rgba8888
          stores the interpolated alpha, nothing is blended); gray8 and
          mono1 take C = 1.  Levels are 0..255 whatever the format: rgb565
          keeps their top bits, mono1 is on iff the level is >= 128.

        `shading`: "gouraud" (the default: vertex colours interpolated) or
        "flat" (each triangle in its first vertex's colour).  `precision`
        of the interpolation: "exact" (the rational barycentric value at
        the sample, rounded half up: floor(v + 1/2)) or "fixed" (fixed
        point with `fraction_bits` F in 1..16, stepped by additions:
        faster, off by about a level at small F; see the docs' table).
        ``precision="flat"`` is the old spelling of ``shading="flat"``
        (DeprecationWarning).  A shaded fill writes exactly the pixels the
        unshaded one writes.

        `depth`: (N, 3) vertex depths, rounded half up to int32 (the range
        -2**31..2**31-1).  The canvas then keeps a depth buffer,
        ``canvas.depth``, an (H, W) int32 array made on first use and filled
        with 2**31-1; a pixel is written iff its interpolated depth (same
        precision as the colour; exact for "flat") is less than the
        buffer's, which then takes it.  ``clear_depth()`` drops the buffer.
        Without `depth`, nothing depth-related is made or computed.

        `aa`: one of ``AA_METHODS["Canvas.fill_triangles"]`` ("area",
        "ss2".."ss16", "accumulate") paints one `color` anti-aliased over
        the batch's coverage as :func:`rastrum.triangles_coverage` gives it:
        the batch is ONE region (its union), so a mesh drawn in one call
        has no seams and nothing is blended twice.  The blend is
        :meth:`fill_polygon`'s.  With `vertex_colors` instead of `color`
        (shading "gouraud" or "flat", precision "exact") each pixel's
        colour is blended: where the binary rule gives its sample to a
        triangle, exactly the binary shaded fill's colour; on the
        silhouette (covered, sample outside every triangle), the last
        triangle touching the pixel's closed square, its plane extended to
        the sample, rounded as the binary fill, clamped to 0..255 (see
        docs/coverage.md).  `algorithm`, `rounding`, `boundary`, `depth`,
        fixed precision and per-triangle colours are for binary fills
        (aa=None) only.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((4, 6), format="gray8")
        >>> c.fill_triangles([[(0, 0), (4, 0), (4, 4)], [(0, 0), (4, 4), (0, 4)]], 9)
        >>> c.array
        array([[9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0],
               [9, 9, 9, 9, 0, 0]], dtype=uint8)
        """
        if aa is not None:
            self._fill_aa(_triangles.tris_f64(tris), color, aa, "nonzero", subpixel_bits, sample_offset,
                          "Canvas.fill_triangles", algorithm=(algorithm, "edge"),
                          rounding=(rounding, "exact"), boundary=(boundary, "exact"),
                          shading=(shading, "gouraud"), precision=(precision, "exact"),
                          vertex_colors=vertex_colors, depth=depth)
            return
        opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
        batch = _triangles.tris_f64(tris)
        precision = _core.shading_precision(shading, precision)
        if vertex_colors is None and depth is None and isinstance(precision, str) and precision == "exact" and (
                color is None or _core.ndim(color) < 2):
            if color is None:
                raise InputError("fill_triangles needs color or vertex_colors")
            _triangles.fill_triangles(self._writable(), batch, self._pixel(color), opts)
            return
        if (color is None) == (vertex_colors is None):
            raise InputError("fill_triangles takes exactly one of color and vertex_colors")
        sopts = _shading.shade_opts(precision, fraction_bits)
        n = batch.shape[0]
        channels = _CHANNELS[self._format] if self._format in _CHANNELS else 0
        if not channels:
            raise InputError("format %s has no colours to shade" % self._format)
        if vertex_colors is not None:
            colors = _shading.rgba(vertex_colors, n, True, self._format, channels)
        else:
            if _core.ndim(color) < 2:  # one colour for every triangle
                one = np.frombuffer(_rgba_bytes(color, self._format), np.uint8)
                colors = np.ascontiguousarray(np.broadcast_to(one, (n, 3, 4)))
            else:
                colors = _shading.rgba(color, n, False, self._format, channels)
            sopts = _shading.shade_opts("flat", fraction_bits)
        z = zbuf = None
        if depth is not None:
            z = _shading.depths(depth, n)
            zbuf = self._checked_depth(self._depth)
            if zbuf is None:  # kept only once a call has succeeded with it
                zbuf = np.full((self.height, self.width), _shading.INT32_MAX, np.int32)
        _shading.fill(self._writable(), batch, colors, z, zbuf, opts, sopts)
        if z is not None:
            self._depth = zbuf

    def fill_rect_gouraud(self, rect: npt.ArrayLike, corner_colors: npt.ArrayLike, *,
                          method: Literal["bilinear", "triangles"] = "bilinear", shading: Shading = "gouraud",
                          precision: Precision = "exact", fraction_bits: int = 16, subpixel_bits: int = 8,
                          sample_offset: float = 0.5) -> None:
        """A Gouraud rectangle: four corner colours, interpolated (the textbook's §3.2.3).

        `rect` is (x0, y0, x1, y1) in pixels; `corner_colors` is (4, C), C
        the canvas's channels, for the corners (x0, y0), (x1, y0), (x1, y1),
        (x0, y1).  The pixels are those :meth:`fill_polygon` gives the
        rectangle.  method "bilinear" interpolates the four corners at each
        sample (rounded half up in precision "exact"; "fixed" steps in
        `fraction_bits` bits as the textbook does; ``shading="flat"``
        paints corner 0);
        "triangles" splits the rectangle along the diagonal from (x0, y0)
        to (x1, y1) and fills the two Gouraud triangles instead: the
        difference of the textbook's Figure 3-18.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((2, 4), format="gray8")
        >>> c.fill_rect_gouraud((0, 0, 4, 2), [0, 80, 80, 0])
        >>> c.array
        array([[10, 30, 50, 70],
               [10, 30, 50, 70]], dtype=uint8)
        """

        if self._format == "label":
            raise InputError("a label canvas has no channels to shade")
        _shading.fill_rect_gouraud(self, rect, corner_colors, method, _core.shading_precision(shading, precision),
                                   fraction_bits, subpixel_bits, sample_offset)

    @_label_spill
    def line(self, p0: Point, p1: Point, color: Color, *, algorithm: LineAlgorithm = "bresenham",
             subpixel_bits: int = 8, sample_offset: float = 0.5) -> None:
        """Paint `color` on the pixels of the segment p0 -> p1.

        The pixels are :func:`rastrum.line_pixels` (p0, p1) within the
        canvas; the rest of the line is clipped.  Arguments as there.
        Nothing is written when an argument is bad (an InputError says
        which).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((3, 6), format="gray8")
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

    @_label_spill
    def polyline(self, points: npt.ArrayLike, color: Color, *, closed: bool = False,
                 algorithm: LineAlgorithm = "bresenham", subpixel_bits: int = 8,
                 sample_offset: float = 0.5) -> None:
        """Paint the segments points[k] -> points[k+1]; with ``closed=True``
        also the last point -> the first (an outline).

        Each segment is :meth:`line`; a vertex shared by two segments is
        painted by both.  `points` is an (N, 2) array-like, N >= 2 (N = 0
        draws nothing; N = 1 is an InputError); `closed` is a bool.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((5, 5), format="gray8")
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

    def flood_fill(self, seed: Tuple[int, int], value: Color, *_legacy: int,
                   connectivity: Literal[4, 8] = 4) -> None:
        """Flood fill: paint `value` on every pixel connected to `seed`
        through pixels of the seed's (original) value.

        `seed` is (x, y), inside the canvas; `connectivity` (keyword only)
        is 4 (through sides) or 8 (also through corners); `value` is a colour as for
        :meth:`fill_polygon`.  A value equal to the seed's paints nothing.
        Nothing is written when an argument is bad (an InputError says
        which).

        Examples
        --------
        >>> import rastrum
        >>> picture = [[0, 0, 1], [1, 0, 1], [0, 1, 0]]
        >>> c = rastrum.Canvas.wrap(np.array(picture, np.uint8))
        >>> c.flood_fill((0, 0), 7)
        >>> c.array
        array([[7, 7, 1],
               [1, 7, 1],
               [0, 1, 0]], dtype=uint8)
        >>> c = rastrum.Canvas.wrap(np.array(picture, np.uint8))
        >>> c.flood_fill((0, 0), 7, connectivity=8)
        >>> c.array
        array([[7, 7, 1],
               [1, 7, 1],
               [7, 1, 7]], dtype=uint8)
        """
        connectivity = _connectivity(_legacy, connectivity)
        pixel = self._pixel(value)
        _core.seed_fill(self._writable(), seed, pixel, None, connectivity)

    def boundary_fill(self, seed: Tuple[int, int], value: Color, boundary: Color, *_legacy: int,
                      connectivity: Literal[4, 8] = 4) -> None:
        """Boundary fill: paint `value` on every pixel connected to `seed`
        through pixels that are neither `boundary` nor `value`.

        The textbook's boundary fill: a pixel already of the fill value is
        done, and stops the fill like the boundary.  With
        ``boundary == value`` (an outline drawn in the fill colour) the
        region is every pixel connected to the seed through pixels that
        are not the boundary.  A seed of either value paints nothing.
        Other arguments as :meth:`flood_fill`.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((4, 5), format="gray8")
        >>> c.polyline([(0, 0), (3, 0), (3, 3), (0, 3)], 1, closed=True, subpixel_bits=0, sample_offset=0)
        >>> c.array[1, 2] = 7
        >>> c.boundary_fill((1, 1), 7, 1)
        >>> c.array
        array([[1, 1, 1, 1, 0],
               [1, 7, 7, 1, 0],
               [1, 7, 7, 1, 0],
               [1, 1, 1, 1, 0]], dtype=uint8)
        """
        connectivity = _connectivity(_legacy, connectivity)
        pixel = self._pixel(value)
        edge = ffi.from_buffer(self._value_bytes(boundary))
        _core.seed_fill(self._writable(), seed, pixel, edge, connectivity)

    def to_image(self) -> "PIL.Image.Image":
        """A Pillow image (a copy): mode L, RGB or RGBA; rgb565 as RGB (each
        channel widened to 8 bits by repeating its top bits), mono1 as
        mode "1"."""
        from PIL import Image

        if self._format == "label":  # what Pillow makes of the integers (mode L, I;16 or I)
            return Image.fromarray(np.ascontiguousarray(self._array))
        if self._format == "mono1":
            packed = np.ascontiguousarray(self._array)
            return Image.frombytes("1", (self._width, self.height), packed.tobytes())
        if self._format == "rgb565":
            p = self._array.astype(np.uint32)
            r, g, b = p >> 11, (p >> 5) & 63, p & 31
            rgb = np.stack([(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)], axis=-1)
            return Image.fromarray(rgb.astype(np.uint8), "RGB")
        return Image.fromarray(np.ascontiguousarray(self._array), _PIL_MODES[self._format])

    def save(self, path: Union[str, "os.PathLike[str]", IO[bytes]], **kwargs: Any) -> None:
        """Save through Pillow; the format follows the file name (PNG, ...)."""
        self.to_image().save(path, **kwargs)

    def __repr__(self) -> str:
        return "Canvas((%d, %d), format=%r)" % (self.height, self.width, self._format)


def _color_name(color, fmt):
    """A colour given as a string ("red", "#f00", "#ff0000", "#ff000080",
    any name or spelling Pillow's ImageColor takes) in `fmt`'s terms: an
    int for gray8 (Pillow's luminance) and mono1 (on iff not black), else
    (R, G, B) or (R, G, B, A)."""
    from PIL import ImageColor

    try:
        value = ImageColor.getcolor(color, "RGBA" if fmt == "rgba8888" else "RGB" if fmt in ("rgb888", "rgb565")
                                    else "L")
    except ValueError:
        raise InputError('colour %r: not a colour name (e.g. "red") nor "#rgb", "#rrggbb" or "#rrggbbaa" '
                         "(the names and spellings of Pillow's ImageColor)" % (color,)) from None
    return int(value != 0) if fmt == "mono1" else value


def _pixel_bytes(color, fmt):
    """The pixel's bytes for `color` in format `fmt`, or InputError."""
    if isinstance(color, str):
        color = _color_name(color, fmt)
    color = _core.as_numpy(color)
    if fmt == "mono1":
        if isinstance(color, (bool, np.bool_)) or not isinstance(color, (int, np.integer)):
            raise InputError("colour %r: format mono1 needs an int (0 off, else on)" % (color,))
        return b"\x01" if color else b"\x00"
    if fmt == "rgb565":
        out = ffi.new("uint8_t[2]")
        _core._check(lib.rast_pack_color(lib.RAST_FORMAT_RGB565, _rgba_bytes(color, fmt), out))
        return bytes(ffi.buffer(out))
    n = _core.FORMAT_BYTES[fmt]
    if isinstance(color, (int, np.integer)) and not isinstance(color, (bool, np.bool_)):
        values = [int(color)] * n
    else:
        try:
            values = [v for v in color]
        except TypeError:
            raise InputError("colour %r: give an int or a sequence of %s" % (color, _core.plural(n, "int"))) from None
        if len(values) != n or not all(
            isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_)) for v in values
        ):
            raise InputError("colour %r: format %s needs %s" % (color, fmt, _core.plural(n, "int")))
    if not all(0 <= v <= 255 for v in values):
        raise InputError("colour %r: every channel must be in 0..255" % (color,))
    return bytes(bytearray(int(v) for v in values))


def _rgba_bytes(color, fmt):
    """An 8-bit RGBA colour (4 bytes) for `color` given in `fmt`'s terms:
    an int (every channel; alpha 255) or 3 or 4 ints."""
    n = 4 if fmt == "rgba8888" else 3 if fmt in ("rgb888", "rgb565") else 1
    if isinstance(color, str):
        color = _color_name(color, fmt)
    if fmt == "mono1" and isinstance(color, (int, np.integer)) and not isinstance(color, (bool, np.bool_)):
        color = 255 if color else 0  # a flat mono1 colour: on iff not 0
    values = _pixel_bytes(color, "rgba8888" if n == 4 else "rgb888" if n == 3 else "gray8")
    return (values * 3)[:3] + b"\xff" if n == 1 else values + (b"\xff" if n == 3 else b"")


# A label value's bytes are copied verbatim by the painters of these formats.
_LABEL_FORMATS = {1: lib.RAST_FORMAT_GRAY8, 2: lib.RAST_FORMAT_RGB565, 4: lib.RAST_FORMAT_RGBA8888}


def _label_bytes(value, dtype):
    """The bytes of `value` as one item of `dtype`, or InputError when it is
    not an int or does not fit."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise InputError("label value %r: a label canvas takes one int" % (value,))
    info = np.iinfo(dtype)
    if not info.min <= int(value) <= info.max:
        raise InputError("label value %d does not fit the array's dtype %s (%d..%d)"
                         % (int(value), dtype, info.min, info.max))
    return np.array(int(value), dtype).tobytes()


def _check_rows(array, item):
    """A wrapped array must be writable, with each row's pixels contiguous
    (`item` bytes a pixel) and rows in order."""
    if not array.flags.writeable:
        raise InputError("Canvas.wrap needs a writable array")
    h, w = array.shape[:2]
    if array.size and (h > 1 and array.strides[0] < w * item or array.strides[1] != item
                       or (array.ndim > 2 and array.strides[2] != 1)):
        raise InputError("Canvas.wrap needs each row's pixels contiguous and rows in order (strides %s)"
                         % (array.strides,))


def _is_int(v):
    return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))


def _positional(shape, args, format, background):
    """(legacy height, format, background) from Canvas's positional
    arguments after `shape`: (format, background), or, after the width of
    the deprecated Canvas(width, height, ...), (height, format, background).
    A name given both by position and by keyword is a TypeError, as Python
    would raise it."""
    legacy_height = None
    if args and (_is_int(shape) or _is_int(args[0])):  # an int after a shape: refused as a height
        legacy_height, args = args[0], args[1:]
    if len(args) > 2:
        raise TypeError("Canvas() takes at most 3 positional arguments (%d given)" % (len(args) + 1))
    if args:
        if not (isinstance(format, str) and format == "rgb888"):
            raise TypeError("Canvas() got multiple values for argument 'format'")
        format = args[0]
    if len(args) == 2:
        if not (type(background) is int and background == 0):
            raise TypeError("Canvas() got multiple values for argument 'background'")
        background = args[1]
    return legacy_height, format, background


def _canvas_shape(shape, legacy_height, width, height):
    """(H, W) from Canvas(shape) or, deprecated, Canvas(width, height) /
    Canvas(width=, height=)."""
    if shape is not None and not _is_int(shape):
        if legacy_height is not None or width is not None or height is not None:
            raise InputError("Canvas takes shape=(height, width) alone, not with width or height")
        return _core.shape2(shape)
    if shape is not None and width is not None:
        raise InputError("Canvas: width given twice")
    w = shape if shape is not None else width
    h = legacy_height if legacy_height is not None else height
    if legacy_height is not None and height is not None:
        raise InputError("Canvas: height given twice")
    if w is None or h is None:
        raise InputError("Canvas needs shape=(height, width), as numpy writes it")
    if not (_is_int(w) and _is_int(h)):
        raise InputError("Canvas(width, height) takes two ints, not %r, %r; better: Canvas((height, width))"
                         % (w, h))
    _core.deprecated("Canvas(width, height) is now Canvas((height, width)), (H, W) as numpy writes it",
                     stacklevel=4)
    return _core.shape2((h, w))


# Canvas.fill_polygon's quick path: its default options (the very objects)
# and the C call for one ring.
_AET, _EVENODD, _S8, _HALF, _EXACT = (Canvas.fill_polygon.__wrapped__.__kwdefaults__[k] for k in (
    "algorithm", "rule", "subpixel_bits", "sample_offset", "rounding"))
assert Canvas.fill_polygon.__wrapped__.__kwdefaults__["boundary"] is _EXACT
_DEFAULT_OPTS = _core.fill_opts(_AET, _EVENODD, _S8, _HALF, _EXACT, _EXACT)
_ndarray, _F64, _PACKED = np.ndarray, np.dtype(np.float64), (16, 8)
_DOUBLES, _from_buffer, _fill_ring = ffi.typeof("double[]"), ffi.from_buffer, lib.rastpy_fill_ring
_seq_rings, _RING_DTYPES = _core._seq.rings, _core._RING_DTYPES


def _connectivity(legacy, connectivity):
    """connectivity is keyword-only; given by position it still works for
    one release, with a DeprecationWarning."""
    if legacy:
        if len(legacy) > 1 or connectivity != 4:
            raise InputError("connectivity is keyword-only: connectivity=4 or connectivity=8")
        _core.deprecated("connectivity by position is now keyword-only: connectivity=%r" % (legacy[0],),
                         stacklevel=4)
        return legacy[0]
    return connectivity

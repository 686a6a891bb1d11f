"""Canvas: a target over a numpy array, with drawing methods."""

import functools
import inspect
import math
from typing import (IO, TYPE_CHECKING, Any, Callable, Dict, Literal, Optional, Sequence, Tuple, TypeVar, Union, cast,
                    overload)

import numpy as np
import numpy.typing as npt

from . import _core
from . import _coverage
from . import _lines
from . import _shapes
from . import _shading
from . import _triangles
from ._core import InputError
from ._native import ffi, lib
from ._path import Path as _Path, fill_path_aa as _fill_path_aa, path_rings
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
        return _spill(self, method, kwargs)
    return cast(_F, draw)


def _spill(self: "Canvas", method: Callable[..., Any], kwargs: Dict[str, Any]) -> None:
    """_label_spill's drawing: `method` (undecorated) with the call's
    arguments by name, `kwargs`, into a uint8 mask, then the value where
    it is set.  Canvas.fill_polygon calls it itself (when self._code is
    None), which saves its common call the decorator's packing and
    unpacking of the arguments."""
    color = kwargs.get("color", None)
    if kwargs.get("aa") is not None:
        raise InputError("a label canvas holds labels, which do not blend: aa=None")
    if kwargs.get("vertex_colors") is not None or kwargs.get("depth") is not None:
        raise InputError("a label canvas has no channels to shade: give one int color")
    if kwargs.get("opacity") is not None or kwargs.get("gamma") is not None:
        raise InputError("a label canvas holds labels, which do not blend: no opacity or gamma")
    value = np.frombuffer(self._value_bytes(color), self._array.dtype)[0]
    if not self._array.flags.writeable:
        raise InputError("the canvas's array is read-only; nothing was drawn")
    scratch = Canvas.wrap(np.zeros(self._array.shape, np.uint8))
    kwargs["color"] = 1
    method(scratch, **kwargs)
    self._array[scratch._array != 0] = value


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
        # (the remembered call forgotten: its target is the one set here, as
        # Canvas.fill_polygon's C call takes it, python/ext/seq.c)
        self._fpq = Canvas._fpq
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
                 vertex_colors=None, depth=None, path_tolerance=None, shade_blend=None, **binary_only):
        """An anti-aliased fill (``aa=`` not None) of a polygon's rings, or of
        a checked (N, 3, 2) triangle batch for the triangle entries."""
        if depth is not None:
            raise InputError("%s: depth is for binary shaded fills (aa=None); with aa=%r leave "
                             "it out (draw the batch back to front)" % (entry, aa))
        if vertex_colors is not None and entry == "Canvas.fill_polygon" and color is not None:
            raise InputError("fill_polygon takes exactly one of color and vertex_colors")
        shading = binary_only.pop("shading", ("gouraud", "gouraud"))[0]
        precision = binary_only.pop("precision", ("exact", "exact"))[0]
        if vertex_colors is None:  # one colour: no shading to choose
            binary_only.update(shading=(shading, "gouraud"), precision=(precision, "exact"))
        opts = _coverage.aa_opts(aa, rule, subpixel_bits, sample_offset, entry, binary_only)
        if self._format == "label":
            raise InputError("a label canvas holds labels, which do not blend: aa=None")
        if vertex_colors is not None:
            self._fill_shaded_aa(geometry, color, vertex_colors, shading, precision, aa, opts,
                                 entry, shade_blend)
            return
        if color is None:
            raise InputError("%s needs color" % entry)
        if _core.ndim(color) >= 2:
            raise InputError("%s: aa=%r takes one colour for the whole batch, not one per triangle"
                             % (entry, aa))
        pixel = self._pixel(color)
        if type(geometry) is _Path:  # fill_polygon's Path, flattened in C (docs/paths.md)
            return _fill_path_aa(self._writable(), geometry, pixel, opts, path_tolerance)
        if entry == "Canvas.fill_polygon":
            _coverage.fill_polygon_aa(self._writable(), geometry, pixel, opts)
        else:
            _coverage.fill_triangles_aa(self._writable(), geometry, pixel, opts,
                                        "tri" if entry == "Canvas.fill_triangle" else "tris")

    def _fill_shaded_aa(self, batch, color, vertex_colors, shading, precision, aa, opts, entry,
                        shade_blend=None):
        """Gouraud (or flat) colour times the batch's coverage
        (rast_fill_triangles_shaded_aa); shade_blend: (RGBA vertex colours,
        rast_blend_opts) from _shaded_blend, blended source-over
        (rast_fill_triangles_shaded_aa_blend, docs/opacity.md)."""
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
        if shade_blend is not None:
            colors, blend = shade_blend
        else:
            colors, blend = _shading.rgba(vertex_colors, batch.shape[0], True, self._format, channels), None
        _coverage.fill_triangles_shaded_aa(self._writable(), batch, colors, opts,
                                           _shading.shade_opts(precision, 16),
                                           "tri" if entry == "Canvas.fill_triangle" else "tris", blend)

    def _shaded_blend(self, batch, vertex_colors, opacity, depth, entry):
        """None for a shaded fill that stores its colours (no `opacity`, and
        vertex colours without alpha or on rgba8888, which stores it); else
        (RGBA vertex colours as uint8 (N, 3, 4), ``rast_blend_opts *`` or
        None when nothing can blend: opacity 1, every alpha 255, a format
        without alpha), checked (docs/opacity.md "Shaded fills")."""
        fmt = self._format
        if opacity is None:
            if fmt not in ("gray8", "rgb888", "rgb565"):
                return None
            try:
                a = np.asarray(vertex_colors)
            except (TypeError, ValueError):
                return None
            if a.ndim != 3 or a.shape[-1] != (2 if fmt == "gray8" else 4):
                return None
            level = 255
        else:
            level = _blend_level(opacity, entry, fmt)
        if depth is not None:
            raise InputError("%s: depth is for shaded fills that store their colours; with opacity or "
                             "vertex alpha leave it out (draw the batch back to front)" % entry)
        n = batch.shape[0]
        colors = None
        if fmt == "gray8":  # (L, A) per vertex, as fill_polygon's gray8 colour
            try:
                a = np.asarray(vertex_colors)
            except (TypeError, ValueError):
                a = None
            if a is not None and a.dtype.kind in "iu" and a.shape == (n, 3, 2):
                colors = _shading.to_rgba(a[..., [0, 0, 0, 1]], "vertex_colors")
        if colors is None:
            colors = _shading.rgba(vertex_colors, n, True, fmt, _CHANNELS[fmt])
        if level == 255 and fmt != "rgba8888" and bool(np.all(colors[..., 3] == 255)):
            return colors, None  # opaque: the stored fill writes the same pixels
        return colors, ffi.new("rast_blend_opts *", {"opacity": level, "premultiplied": 0})

    def _vertex_blend(self, colors, opacity, entry, what):
        """_shaded_blend for the (N, C) corner or vertex colours of
        fill_rect_gouraud and fill_polygon: None (stored), else (RGBA
        colours as uint8 (N, 4), ``rast_blend_opts *`` or None when
        opaque), checked (docs/opacity.md "Shaded fills")."""
        fmt = self._format
        try:
            a = np.asarray(colors)
        except (TypeError, ValueError):
            a = None
        if opacity is None:
            if fmt not in ("gray8", "rgb888", "rgb565") or a is None or a.ndim != 2 \
                    or a.shape[-1] != (2 if fmt == "gray8" else 4):
                return None
            level = 255
        else:
            level = _blend_level(opacity, entry, fmt)
        rgba = None
        if fmt == "gray8" and a is not None and a.dtype.kind in "iu" and a.ndim == 2 and a.shape[-1] == 2:
            rgba = _shading.to_rgba(a[..., [0, 0, 0, 1]], what)  # (L, A), as fill_polygon's colour
        if rgba is None:
            n = a.shape[0] if a is not None and a.ndim >= 1 else -1
            rgba = _shading.colors_rgba(colors, n, fmt, what)
        if level == 255 and fmt != "rgba8888" and bool(np.all(rgba[..., 3] == 255)):
            return rgba, None  # opaque: the stored fill writes the same pixels
        return rgba, ffi.new("rast_blend_opts *", {"opacity": level, "premultiplied": 0})

    def _blend(self, entry, geometry, blend, aa, rule, subpixel_bits, sample_offset, algorithm, rounding,
               boundary, vertex_colors, depth=None):
        """A fill whose colour's alpha (times opacity) is applied: the
        geometry's uint8 coverage (aa) or mask (255 inside) through
        rast_blend_coverage (docs/opacity.md)."""
        from . import polygon_mask

        if vertex_colors is not None or depth is not None:
            raise InputError("%s: opacity and a colour's alpha are for one colour (color=), without "
                             "vertex_colors or depth" % entry)
        target = self._writable()
        shape = (self.height, self.width)
        tris = entry != "Canvas.fill_polygon"
        if aa is not None:
            _coverage.aa_opts(aa, rule, subpixel_bits, sample_offset, entry,
                              dict(algorithm=(algorithm, "edge" if tris else "aet"), rounding=(rounding, "exact"),
                                   boundary=(boundary, "exact")))
        if _blend_box(target, geometry, tris, blend, shape, aa, rule, subpixel_bits, sample_offset, algorithm,
                      rounding, boundary):
            return
        if aa is not None:
            if tris:
                cov = _coverage.triangles_coverage(geometry, shape, method=aa, subpixel_bits=subpixel_bits,
                                                   sample_offset=sample_offset)
            else:
                cov = _coverage.polygon_coverage(geometry, shape, rule=rule, method=aa,
                                                 subpixel_bits=subpixel_bits, sample_offset=sample_offset)
        elif tris:
            cov = _triangles.triangles_mask(geometry, shape, algorithm=algorithm, subpixel_bits=subpixel_bits,
                                            sample_offset=sample_offset, rounding=rounding, boundary=boundary)
        else:
            cov = polygon_mask(geometry, shape, rule=rule, algorithm=algorithm, subpixel_bits=subpixel_bits,
                               sample_offset=sample_offset, rounding=rounding, boundary=boundary)
        cov = np.ascontiguousarray(cov, np.uint8) * np.uint8(255 if cov.dtype == np.bool_ else 1)
        _blend_mask(target, cov, blend)

    def composite(self, coverage: npt.ArrayLike, color: Color, *, opacity: Optional[float] = None,
                  premultiplied: bool = False, gamma: Union[None, str, float] = None) -> None:
        """Blend `color` into the canvas through a coverage image, source-over.

        `coverage` is an (H, W) uint8 (levels out of 255) or uint16 (out of
        65535) array, e.g. :func:`rastrum.polygon_coverage` of the canvas's
        shape, computed once and composited in several colours.  The
        colour's alpha times `opacity` (0..1, the level
        floor(opacity*255 + 1/2)) times each pixel's coverage is rounded
        once to an alpha level, then each channel is mixed as
        docs/opacity.md states; an rgba8888 canvas is straight alpha, or
        premultiplied with ``premultiplied=True``.  ``gamma="srgb"`` (or a
        power in 0.3..3) mixes in linear light as :meth:`fill_polygon`
        does (not with ``premultiplied=True``: a stored product of alpha
        and an encoded level has no linear value).  gray8, rgb888, rgb565
        and rgba8888 canvases; nothing is written when an argument is bad.
        """
        entry = "Canvas.composite"
        if self._format not in _BLEND_FORMATS:
            raise InputError("%s: gray8, rgb888, rgb565 and rgba8888 canvases blend, not %s"
                             % (entry, self._format))
        if not isinstance(premultiplied, (bool, np.bool_)) or (premultiplied and self._format != "rgba8888"):
            raise InputError("%s: premultiplied must be True (an rgba8888 canvas only) or False, not %r"
                             % (entry, premultiplied))
        try:
            cov = np.asarray(coverage)
        except (TypeError, ValueError, OverflowError):  # ragged, or what numpy cannot hold
            raise InputError("Canvas.composite: coverage must be a uint8 or uint16 array of the canvas's shape,"
                             " not %s" % type(coverage).__name__) from None
        if cov.dtype not in (np.uint8, np.uint16) or cov.shape != (self.height, self.width):
            raise InputError("%s: coverage must be a uint8 or uint16 array of the canvas's shape %s, not %s %s"
                             % (entry, (self.height, self.width), cov.dtype, cov.shape))
        level = 255 if opacity is None else _opacity_level(opacity, entry)
        tables = None
        if gamma is not None:
            if premultiplied:
                raise InputError("%s: gamma= mixes straight alpha in linear light; premultiplied=True has "
                                 "no linear value" % entry)
            tables = _gamma_tables(gamma, entry)
        rgba = _blend_rgba(color, self._format)
        target = self._writable()
        cov = np.ascontiguousarray(cov)
        opts = ffi.new("rast_blend_opts *", {"opacity": level, "premultiplied": int(bool(premultiplied))})
        if cov.size:
            args = (target, ffi.from_buffer(cov), lib.RAST_COVERAGE_U16 if cov.dtype == np.uint16
                    else lib.RAST_COVERAGE_U8, cov.shape[1] * cov.itemsize, rgba, opts)
            _core._check(lib.rast_blend_coverage(*args) if tables is None
                         else lib.rast_blend_coverage_linear(*args, tables))

    # (target, color, their addresses, the array, the pixel) of the last
    # common fill_polygon call: see _seq.fill_method at the end
    _fpq: Tuple[Any, ...] = (None, None, b"", None, None, None, False)

    def fill_polygon(self, rings: Rings, color: Optional[Color] = None, *, rule: Rule = "evenodd",
                     algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
                     rounding: Rounding = "exact", boundary: Boundary = "exact",
                     vertex_colors: Optional[npt.ArrayLike] = None, shading: Shading = "gouraud",
                     precision: Precision = "exact", aa: Optional[CoverageMethod] = None,
                     tolerance: Optional[float] = None,
                     opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Paint `color` on every pixel whose sample is inside the polygon.

        Arguments as :func:`rastrum.polygon_mask` (`rings` may be a Path, a
        matplotlib Path or a shapely polygon; `tolerance` flattens a Path).  Nothing is written when
        an argument is bad (an InputError says which; see the class).

        With `aa` (one of ``AA_METHODS["Canvas.fill_polygon"]``: "area",
        "ss2".."ss16", "accumulate"; see :func:`rastrum.polygon_coverage`)
        the fill is anti-aliased: each pixel's coverage level c (0..255, as
        ``polygon_coverage(..., method=aa)`` gives it for the same `rule`,
        `subpixel_bits` and `sample_offset`) weights `color`: every channel
        d becomes (s*c + d*(255 - c) + 127) // 255 (rgb565: on its 5/6/5
        bits; rgba8888: alpha too), mono1 takes the colour where c >= 128,
        pixels with c = 0 are untouched.  `algorithm`, `rounding`
        and `boundary` are for binary fills (aa=None) only; with
        `vertex_colors` and `aa`, the anti-aliased colour polygon
        (docs/coverage.md "Shaded rectangles and polygons, anti-aliased").

        With `vertex_colors` instead of `color`: one colour per vertex, an
        (N, C) array-like for the N vertices of all rings in order (or a
        list of one (N_k, C) per ring), C the canvas's channels; the
        active edge table interpolates them along each edge to the row,
        then along the span, rounded half up (``precision="exact"``);
        ``shading="flat"`` paints vertex 0's colour instead.  Only
        ``algorithm="aet"``.  Give exactly one of `color` and
        `vertex_colors`, as for :meth:`fill_triangle` and
        :meth:`fill_triangles`.  A vertex colour's alpha ((R, G, B, A);
        gray8 (L, A)) and `opacity` are applied as :meth:`fill_triangles`
        applies them: each pixel's interpolated colour blended
        source-over at its interpolated alpha times the opacity level
        (rgba8888 without `opacity` stores the alpha).

        A colour's alpha ((R, G, B, A); gray8 (L, A); "#rrggbbaa") and
        `opacity` (a number in 0..1, the level floor(opacity*255 + 1/2))
        are applied source-over on gray8, rgb888, rgb565 and rgba8888
        canvases, binary or with `aa`: the alpha level
        round(alpha*o*c / 255**2) rounded once, then each channel's mix
        (rgba8888: straight alpha; there a colour without `opacity` is a
        pixel value, stored).  ``gamma="srgb"`` (or a power in 0.3..3)
        mixes gray8 and rgb888 in linear light.  See docs/opacity.md.
        """
        if self._code is None:  # a label canvas of 8-byte items (_label_spill, inline)
            args = dict(locals())
            del args["self"]
            return _spill(self, Canvas.fill_polygon, args)
        # (an exact ndarray or list first: isinstance's tuple costs 2-3% of the quick call)
        if tolerance is not None or (type(rings) is not _ndarray and type(rings) is not list
                                     and not isinstance(rings, (list, tuple, _ndarray))):  # docs/paths.md
            if type(rings) is _Path and aa is not None and type(color) is int and opacity is None \
                    and gamma is None and vertex_colors is None:  # flattened in C into the filler
                if self._fill_aa(rings, color, aa, rule, subpixel_bits, sample_offset, "Canvas.fill_polygon",
                                 algorithm=(algorithm, "aet"), rounding=(rounding, "exact"),
                                 boundary=(boundary, "exact"), shading=(shading, "gouraud"),
                                 precision=(precision, "exact"), path_tolerance=tolerance):
                    return
            rings = path_rings(rings, subpixel_bits, tolerance)
        if vertex_colors is not None and color is None and gamma is None and self._format != "label":
            vc = _shading.polygon_vertex_colors(vertex_colors)
            shade_blend = self._vertex_blend(vc, opacity, "Canvas.fill_polygon", "vertex_colors")
            if aa is not None:  # anti-aliased (docs/coverage.md "Anti-aliased Gouraud polygons")
                if shade_blend is None:
                    n = len(vc) if hasattr(vc, "__len__") and _core.ndim(vc) >= 1 else -1
                    shade_blend = _shading.colors_rgba(vc, n, self._format, "vertex_colors"), None
                _shading.fill_polygon_gouraud_aa(
                    self, rings, shade_blend[0], aa, rule, subpixel_bits, sample_offset,
                    _core.shading_precision(shading, precision), shade_blend[1], "Canvas.fill_polygon",
                    dict(algorithm=(algorithm, "aet"), rounding=(rounding, "exact"),
                         boundary=(boundary, "exact")))
                return
            if shade_blend is not None:  # blended (docs/opacity.md "Shaded fills")
                _shading.fill_polygon_gouraud(self, rings, vc, _core.fill_opts(
                    algorithm, rule, subpixel_bits, sample_offset, rounding, boundary), _core.shading_precision(
                    shading, precision), shade_blend)
                return
        if opacity is not None or gamma is not None or (color is not None and type(color) is not int):
            blend, color = _blend_args(color, opacity, self._format, "Canvas.fill_polygon", gamma)
            if blend is not None:
                self._blend("Canvas.fill_polygon", rings, blend, aa, rule, subpixel_bits, sample_offset,
                            algorithm, rounding, boundary, vertex_colors)
                return
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
                opts = _fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
            if type(color) is int and _fill_quick(self._fpq, self._target, rings, color, _opts_address(opts)):
                return  # the remembered target and colour, these options (_seq.fill_method)
            xy = None
            if type(rings) is _ndarray:
                if (rings.dtype is _F64 or rings.dtype == _F64) and rings.strides == _PACKED \
                        and rings.shape[1] == 2 \
                        and rings.flags.aligned:  # C reads doubles: not a view at an odd address
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
                    if type(color) is int:  # remembered for the next call (_seq.fill_method)
                        self._fpq = _fpq_of(target, color, self._array, pixel, self._format != "label")
                    return
        elif vertex_colors is None and type(color) is int and algorithm is _AET and rounding is _EXACT \
                and boundary is _EXACT and shading is _GOURAUD and precision is _EXACT and self._format != "label":
            # The common anti-aliased call (one colour as an int, the binary
            # fill's options at their defaults): what _fill_aa checks, made
            # here in a few comparisons; the coverage options come from the
            # cache of checked ones (or are checked there, with _fill_aa's
            # InputError).
            target = self._target
            if self._array.flags.writeable:
                opts = _coverage.aa_opts_quick(aa, rule, subpixel_bits, sample_offset, "Canvas.fill_polygon")
                last = self._last_color
                pixel = last[1] if color is last[0] else self._pixel(color)
                # one C-contiguous float64 ring of 3 points or more: straight to
                # C (an error status: fill_polygon_aa's call below says which)
                if type(rings) is _ndarray and (rings.dtype is _F64 or rings.dtype == _F64) \
                        and rings.strides == _PACKED \
                        and rings.shape[1] == 2 and len(rings) >= 3 and len(rings) <= _MAX_POINTS \
                        and rings.flags.aligned:
                    if not _lent(_fill_ring_aa, target, _from_buffer(_DOUBLES, rings), len(rings), _NULL, 1,
                                 opts, pixel):
                        # remembered for the next call (_seq.fill_method)
                        self._fpq = _fpq_of(target, color, self._array, pixel, True)
                        return
                _coverage.fill_polygon_aa(target, rings, pixel, opts)
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
                      rounding: Rounding = "exact", boundary: Boundary = "exact", aa: Optional[CoverageMethod] = None,
                      opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Paint `color` on every pixel the triangle `tri` owns.

        `tri` is three (x, y) vertices, in either winding order; the other
        arguments are those of :func:`rastrum.triangles_mask`.  A degenerate
        triangle paints nothing.  Nothing is written when an argument is bad.
        Give exactly one of `color` and `vertex_colors` (a (3, C) array, a
        colour per vertex, shaded as by :meth:`fill_triangles`), as for
        :meth:`fill_polygon`.  `aa`: anti-aliased, as :meth:`fill_triangles`;
        `opacity` and a colour's alpha as :meth:`fill_polygon`.
        """
        if vertex_colors is not None and color is None and gamma is None and self._format != "label":
            vc = _core.as_numpy(vertex_colors)
            alpha = self._format in ("gray8", "rgb888", "rgb565") and np.ndim(vc) == 2 and \
                np.shape(vc)[-1] == (2 if self._format == "gray8" else 4)
            if opacity is not None or alpha:  # blended: fill_triangles' shaded blend
                batch = _triangles.tris_f64(tri, single=True)
                vc = np.asarray(vc)
                self.fill_triangles(batch, vertex_colors=vc[None] if vc.ndim == 2 else vc, shading=shading,
                                    precision=precision, fraction_bits=fraction_bits, algorithm=algorithm,
                                    subpixel_bits=subpixel_bits, sample_offset=sample_offset,
                                    rounding=rounding, boundary=boundary, aa=aa, opacity=opacity)
                return
        if opacity is not None or gamma is not None or (color is not None and type(color) is not int):
            blend, color = _blend_args(color, opacity, self._format, "Canvas.fill_triangle", gamma)
            if blend is not None:
                self._blend("Canvas.fill_triangle", _triangles.tris_f64(tri, single=True), blend, aa, "nonzero",
                            subpixel_bits, sample_offset, algorithm, rounding, boundary, vertex_colors)
                return
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
                       boundary: Boundary = "exact", aa: Optional[CoverageMethod] = None,
                       opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
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
          for R, G and B), 3 (R, G, B; alpha 255) or 4 (R, G, B, A); gray8
          takes 1 or 2 (L, A), mono1 1.  Levels are 0..255 whatever the
          format: rgb565 keeps their top bits, mono1 is on iff the level
          is >= 128.  rgba8888 stores the interpolated alpha; on gray8,
          rgb888 and rgb565 an alpha is applied: each pixel's
          interpolated colour blended source-over with its interpolated
          alpha (times `opacity`, also on rgba8888), binary or with `aa`,
          as docs/opacity.md "Shaded fills" states (no `depth` then).

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
        if vertex_colors is not None and color is None and gamma is None and self._format != "label":
            batch = _triangles.tris_f64(tris)
            shade_blend = self._shaded_blend(batch, vertex_colors, opacity, depth, "Canvas.fill_triangles")
            if shade_blend is not None:
                colors, blend = shade_blend
                if aa is not None:
                    self._fill_aa(batch, None, aa, "nonzero", subpixel_bits, sample_offset,
                                  "Canvas.fill_triangles", algorithm=(algorithm, "edge"),
                                  rounding=(rounding, "exact"), boundary=(boundary, "exact"),
                                  shading=(shading, "gouraud"), precision=(precision, "exact"),
                                  vertex_colors=colors, shade_blend=shade_blend)
                    return
                opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
                sopts = _shading.shade_opts(_core.shading_precision(shading, precision), fraction_bits)
                _shading.fill(self._writable(), batch, colors, None, None, opts, sopts, blend)
                return
        if opacity is not None or gamma is not None or (
                color is not None and type(color) is not int and np.ndim(color) < 2):
            blend, color = _blend_args(color, opacity, self._format, "Canvas.fill_triangles", gamma)
            if blend is not None:
                self._blend("Canvas.fill_triangles", _triangles.tris_f64(tris), blend, aa, "nonzero",
                            subpixel_bits, sample_offset, algorithm, rounding, boundary, vertex_colors, depth)
                return
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
                          sample_offset: float = 0.5, opacity: Optional[float] = None,
                          aa: Optional[CoverageMethod] = None) -> None:
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

        A corner colour's alpha ((R, G, B, A); gray8 (L, A)) and `opacity`
        (0..1, the level floor(opacity*255 + 1/2)) are applied source-over
        on gray8, rgb888, rgb565 and rgba8888 canvases, as
        :meth:`fill_triangles` applies a vertex colour's: each pixel's
        interpolated colour at its interpolated alpha times the opacity
        (rgba8888 without `opacity` stores the alpha; docs/opacity.md
        "Shaded fills").  No `gamma`: shaded fills blend stored levels
        (the core's shaded blends have no linear-light tables), as
        :meth:`fill_triangles` refuses ``gamma=`` with `vertex_colors`.

        `aa` (one of ``AA_METHODS["Canvas.fill_polygon"]``) anti-aliases a
        rectangle with fractional sides: each pixel's colour weighted by
        the rectangle's coverage as :meth:`fill_polygon` weights a colour
        (times its alpha and the opacity, as above).  method "bilinear":
        the colour of the binary fill where it paints the pixel; on the
        rim, the bilinear colour at the rectangle's point nearest the
        pixel's sample (rast_fill_polygon_gouraud_aa of its four corners,
        docs/coverage.md "Shaded rectangles and polygons, anti-aliased");
        precision "exact" or shading "flat" (`fraction_bits` unused).
        method "triangles": the two triangles through
        ``fill_triangles(..., aa=aa)``.

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
        shade_blend = self._vertex_blend(corner_colors, opacity, "Canvas.fill_rect_gouraud", "corner_colors")
        if shade_blend is not None and shade_blend[0].shape[0] != 4:
            raise InputError("corner_colors must be 4 colours, one per corner, not %d" % shade_blend[0].shape[0])
        _shading.fill_rect_gouraud(self, rect, corner_colors, method, _core.shading_precision(shading, precision),
                                   fraction_bits, subpixel_bits, sample_offset, shade_blend, opacity, aa)

    @_label_spill
    def _line(self, p0: Point, p1: Point, color: Color, *, algorithm: LineAlgorithm = "bresenham",
              subpixel_bits: int = 8, sample_offset: float = 0.5, opacity: Optional[float] = None,
              gamma: Union[None, str, float] = None) -> None:
        """Paint `color` on the pixels of the segment p0 -> p1.

        The pixels are :func:`rastrum.line_pixels` (p0, p1) within the
        canvas; the rest of the line is clipped.  Arguments as there.
        Nothing is written when an argument is bad (an InputError says
        which).  (Canvas.line's binary width-1 case.)  `opacity`, `gamma`
        and a colour's alpha as :meth:`fill_polygon` (docs/opacity.md).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((3, 6), format="gray8")
        >>> c._line((0, 0), (5, 2), 1, subpixel_bits=0, sample_offset=0)
        >>> c.array
        array([[1, 1, 0, 0, 0, 0],
               [0, 0, 1, 1, 0, 0],
               [0, 0, 0, 0, 1, 1]], dtype=uint8)
        """
        blend = None
        if opacity is not None or gamma is not None or (type(color) is not int and not (
                type(color) is tuple and len(color) != (2 if self._format == "gray8" else 4))):
            blend, color = _blend_args(color, opacity, self._format, "Canvas.line", gamma)
        opts = _lines.line_opts(algorithm, subpixel_bits, sample_offset)
        a = _lines.snap_point(p0, opts.subpixel_bits, "p0")
        b = _lines.snap_point(p1, opts.subpixel_bits, "p1")
        if blend is not None:  # the line's pixels as a mask (255) over their box, blended once each
            _blend_polyline(self._writable(), ffi.new("rast_point[2]", [a, b]), 2, 0, opts, blend)
            return
        _core._check(lib.rast_draw_line(self._writable(), a, b, opts, self._pixel(color)))

    @_label_spill
    def polyline(self, points: npt.ArrayLike, color: Color, *, closed: bool = False,
                 algorithm: LineAlgorithm = "bresenham", subpixel_bits: int = 8,
                 sample_offset: float = 0.5, opacity: Optional[float] = None,
                 gamma: Union[None, str, float] = None) -> None:
        """Paint the segments points[k] -> points[k+1]; with ``closed=True``
        also the last point -> the first (an outline).

        Each segment is :meth:`line`; a vertex shared by two segments is
        painted by both.  `points` is an (N, 2) array-like, N >= 2 (N = 0
        draws nothing; N = 1 is an InputError); `closed` is a bool.
        `opacity`, `gamma` and a colour's alpha as :meth:`fill_polygon`:
        then the union of the segments' pixels is blended, each pixel once
        (docs/opacity.md).

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
        blend = None
        if opacity is not None or gamma is not None or (color is not None and type(color) is not int):
            blend, color = _blend_args(color, opacity, self._format, "Canvas.polyline", gamma)
        pts = _lines.snap_polyline(points, opts.subpixel_bits, 2)
        if blend is not None:  # the segments' union as a mask (255) over its box, blended once each
            target = self._writable()
            if len(pts):
                _blend_polyline(target, ffi.from_buffer("rast_point[]", pts), len(pts), 1 if closed else 0, opts,
                                blend)
            return
        pixel = self._pixel(color)
        target = self._writable()
        if len(pts):
            _core._check(lib.rast_draw_polyline(target, ffi.from_buffer("rast_point[]", pts), len(pts),
                                                1 if closed else 0, opts, pixel))

    def flood_fill(self, seed: Tuple[int, int], value: Color, *_legacy: int,
                   connectivity: Literal[4, 8] = 4, opacity: Optional[float] = None,
                   gamma: Union[None, str, float] = None) -> None:
        """Flood fill: paint `value` on every pixel connected to `seed`
        through pixels of the seed's (original) value.

        `seed` is (x, y), inside the canvas; `connectivity` (keyword only)
        is 4 (through sides) or 8 (also through corners); `value` is a colour as for
        :meth:`fill_polygon`.  A value equal to the seed's paints nothing.
        Nothing is written when an argument is bad (an InputError says
        which).  With `opacity`, `gamma` or a colour's alpha (as
        :meth:`fill_polygon`) the region (the pixels connected to the seed
        through the seed's value) is blended, each pixel once
        (docs/opacity.md).

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
        if opacity is not None or gamma is not None or (value is not None and type(value) is not int):
            blend, value = _blend_args(value, opacity, self._format, "Canvas.flood_fill", gamma)
            if blend is not None:
                self._seed_blend(seed, blend, None, connectivity)
                return
        pixel = self._pixel(value)
        _core.seed_fill(self._writable(), seed, pixel, None, connectivity)

    def boundary_fill(self, seed: Tuple[int, int], value: Color, boundary: Color, *_legacy: int,
                      connectivity: Literal[4, 8] = 4, opacity: Optional[float] = None,
                      gamma: Union[None, str, float] = None) -> None:
        """Boundary fill: paint `value` on every pixel connected to `seed`
        through pixels that are neither `boundary` nor `value`.

        The textbook's boundary fill: a pixel already of the fill value is
        done, and stops the fill like the boundary.  With
        ``boundary == value`` (an outline drawn in the fill colour) the
        region is every pixel connected to the seed through pixels that
        are not the boundary.  A seed of either value paints nothing.
        Other arguments as :meth:`flood_fill`.  With `opacity`, `gamma` or
        a colour's alpha the region is every pixel connected to the seed
        through pixels that are not `boundary` (a seed of the boundary
        paints nothing), blended once each (docs/opacity.md).

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
        if opacity is not None or gamma is not None or (value is not None and type(value) is not int):
            blend, value = _blend_args(value, opacity, self._format, "Canvas.boundary_fill", gamma)
            if blend is not None:
                self._seed_blend(seed, blend, self._value_bytes(boundary), connectivity)
                return
        pixel = self._pixel(value)
        edge = ffi.from_buffer(self._value_bytes(boundary))
        _core.seed_fill(self._writable(), seed, pixel, edge, connectivity)

    def _seed_blend(self, seed, blend, boundary, connectivity):
        """flood_fill (boundary None) or boundary_fill (`boundary` the
        boundary's pixel bytes) with a blend: the region found by the core's
        flood fill on a gray8 mask (1 where the pixel is the seed's value,
        or is not the boundary) of a window around the seed, grown on each
        side the region reaches until it reaches none (a path out of the
        window crosses its outermost pixels: the region in the window is
        then the canvas's), then blended over the region's box.  The work
        is about the final window's (a small region's box, not the
        canvas)."""
        target = self._writable()
        x, y = _core.seed_point(seed, target)
        arr = self._array
        if boundary is None:
            pixel = arr[y, x]
        else:
            pixel = np.frombuffer(boundary, arr.dtype)
            pixel = pixel if arr.ndim == 3 else pixel[0]
        h, w = arr.shape[:2]
        r = _SEED_WINDOW
        x0, y0, x1, y1 = max(x - r, 0), max(y - r, 0), min(x + r + 1, w), min(y + r + 1, h)
        while True:
            same = arr[y0:y1, x0:x1] == pixel
            if same.ndim == 3:
                same = same.all(axis=2)
            # (a fresh C-contiguous bool array: its bytes, 0 or 1, are the mask)
            mask = np.ascontiguousarray(same if boundary is None else ~same).view(np.uint8)
            if not mask[y - y0, x - x0]:
                return  # a seed on the boundary: nothing
            _core.seed_fill(_core.make_target(mask, lib.RAST_FORMAT_GRAY8), (x - x0, y - y0), b"\x02", None,
                            connectivity)
            region = mask == 2
            # each side the region reaches (not the canvas's edge): 4 times
            # the window's extent further (the windows' areas then add up to
            # little more than the last's), or the whole canvas once the
            # window would hold a quarter of it
            grow = (x0 > 0 and region[:, 0].any(), y0 > 0 and region[0].any(),
                    x1 < w and region[:, -1].any(), y1 < h and region[-1].any())
            if not any(grow):
                break
            dx, dy = 4 * (x1 - x0), 4 * (y1 - y0)
            x0, y0 = (max(x0 - dx, 0) if grow[0] else x0), (max(y0 - dy, 0) if grow[1] else y0)
            x1, y1 = (min(x1 + dx, w) if grow[2] else x1), (min(y1 + dy, h) if grow[3] else y1)
            if 4 * (x1 - x0) * (y1 - y0) > w * h:
                x0, y0, x1, y1 = 0, 0, w, h
        # blended over the region's box only (it holds the seed: never empty)
        rows = np.flatnonzero(region.any(axis=1))
        ry0, ry1 = int(rows[0]), int(rows[-1]) + 1
        cols = np.flatnonzero(region[ry0:ry1].any(axis=0))
        rx0, rx1 = int(cols[0]), int(cols[-1]) + 1
        cov = np.where(region[ry0:ry1, rx0:rx1], np.uint8(255), np.uint8(0))
        _blend_mask(target, cov, blend, (x0 + rx0, y0 + ry0, x0 + rx1, y0 + ry1))

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

    # ---- curves, strokes and Pillow's shapes (docs/paths.md) -------------------------------
    # Grouped here, after the other methods.  Pillow's methods take Pillow's
    # conventions: a bounding box (x0, y0, x1, y1) holds pixels x0..x1 and
    # y0..y1 inclusive, so the shape's box in rastrum's coordinates (pixel
    # (i, j) the square [i, i+1) x [j, j+1)) is [x0, x1 + 1] x [y0, y1 + 1];
    # a point (x, y) is the centre of pixel (x, y), (x + 0.5, y + 0.5).

    def stroke(self, geometry: Any, color: Color, width: float = 1.0, *, join: str = "miter",
               cap: str = "butt", miter_limit: float = 4.0, dash: Optional[Sequence[float]] = None,
               dash_offset: float = 0.0, tolerance: Optional[float] = None,
               aa: Optional[CoverageMethod] = None, subpixel_bits: int = 8, sample_offset: float = 0.5,
               outline: str = "exact", opacity: Optional[float] = None,
               gamma: Union[None, str, float] = None) -> None:
        """Paint `color` on the stroke of `geometry`, `width` pixels wide.

        The outline is :func:`rastrum.stroke` (`join`, `cap`,
        `miter_limit`, `dash`, `dash_offset`, `tolerance`, `outline` as
        there), filled
        non-zero by :meth:`fill_polygon`: ``aa=None`` (the default) the
        pixels whose sample is inside, ``aa="area"`` its exact coverage
        (crossings and overlaps counted once), "ss2".."ss16" sub-samples.
        `geometry`: a Path (rastrum's or matplotlib's), an (N, 2) polyline
        or a list of them, or a shapely / ``__geo_interface__`` LineString,
        MultiLineString, Polygon (its rings, closed) or MultiPolygon.
        Coordinates are rastrum's (the pixel (i, j) is the square
        [i, i+1) x [j, j+1)).  `opacity`, `gamma` and a colour's alpha as
        :meth:`fill_polygon`: the outline is one non-zero fill, so each
        pixel is blended once, where pieces, joins, a dash's ends or a
        path crossing itself overlap too (docs/opacity.md).  Nothing is
        written when an argument is bad (an InputError says which).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((5, 10), format="gray8")
        >>> c.stroke([(1, 2.5), (9, 2.5)], 255, width=1, aa="area")
        >>> c.array[1:4, 0:3].tolist()
        [[0, 0, 0], [0, 255, 255], [0, 0, 0]]
        """
        from ._strokes import stroke as _stroke

        paint = self._paint_kw(color, opacity, gamma, "Canvas.stroke")  # checked before the outline is made
        kw: Dict[str, Any] = {"join": join, "cap": cap, "miter_limit": miter_limit, "tolerance": tolerance,
                              "outline": outline}
        if dash is not None or dash_offset != 0.0:  # dashes as rastrum.stroke has them (docs/paths.md)
            kw.update(dash=dash, dash_offset=dash_offset)
        outline = _stroke(_stroke_geometry(geometry), width, **kw)
        self.fill_polygon(outline, color, rule="nonzero", aa=aa, subpixel_bits=subpixel_bits,
                          sample_offset=sample_offset, tolerance=tolerance, **paint)

    def _paint_kw(self, color, opacity, gamma, entry):
        """`color` with `opacity` and `gamma` checked as fill_polygon checks
        them (InputError, before anything is drawn; a label canvas takes
        neither), and the keywords that pass the two on to it: none
        without them, so that fill_polygon takes its opaque call."""
        if opacity is None and gamma is None:
            if self._format == "label" or type(color) is int:
                self._value_bytes(color)
                return {}
            blend, color = _blend_args(color, None, self._format, entry)
            if blend is None:
                self._value_bytes(color)
            return {}
        if self._format == "label":
            raise InputError("a label canvas holds labels, which do not blend: no opacity or gamma")
        _blend_args(color, opacity, self._format, entry, gamma)
        return {"opacity": opacity, "gamma": gamma}

    def _shape(self, shape: Any, fill: Optional[Color], outline_path: Any, outline: Optional[Color],
               aa: Optional[CoverageMethod], tolerance: Optional[float], entry: str,
               opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Fill `shape` with `fill`, then `outline_path` (nonzero) with
        `outline`, each blended once with `opacity` and `gamma` (or a
        colour's alpha) when given."""
        if fill is None and outline is None:
            raise InputError("%s needs fill or outline (a colour)" % entry)
        # both colours checked before anything is drawn
        paint = [None if c is None else self._paint_kw(c, opacity, gamma, "Canvas." + entry)
                 for c in (fill, outline)]
        # Both flattened (and their points range-checked) before either is
        # drawn: an outline too wide for the grid must not leave the fill.
        shape = path_rings(shape, 8, tolerance)
        if outline_path is not None:
            outline_path = (path_rings(outline_path[0], 8, tolerance), outline_path[1])
        if fill is not None:
            self.fill_polygon(shape, fill, rule="nonzero", aa=aa, **paint[0])
        if outline is not None and outline_path is not None:
            self.fill_polygon(outline_path[0], outline, rule=outline_path[1], aa=aa, **paint[1])

    def ellipse(self, xy: Any, fill: Optional[Color] = None, outline: Optional[Color] = None,
                width: int = 1, *, aa: Optional[CoverageMethod] = None, tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.ellipse``: the ellipse in the bounding box
        `xy` ((x0, y0, x1, y1) or ((x0, y0), (x1, y1)), inclusive: pixels
        x0..x1), filled with `fill`; `outline` paints the ring between it
        and the ellipse of the box inset by `width` (Pillow's outline,
        inside the box).  Rastrum's pixels: those whose centre is inside
        the true ellipse flattened within `tolerance` (or its exact coverage
        with ``aa="area"``); Pillow's own rasteriser differs by a pixel
        here and there on the boundary, never in the box.

        `opacity`, `gamma` and a colour's alpha as :meth:`fill_polygon`
        (docs/opacity.md): the fill, then the outline, each one fill
        blended once per pixel (where the outline lies on the fill, the
        outline is blended over the blended fill, as Pillow and SVG paint
        the fill and then the outline); the same for :meth:`circle`,
        :meth:`rounded_rectangle`, :meth:`pieslice`, :meth:`chord` and
        :meth:`regular_polygon`.  Nothing is written when an argument is
        bad (an InputError says which).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((5, 5), format="gray8")
        >>> c.ellipse((0, 0, 4, 4), fill=1)
        >>> c.array.tolist()
        [[0, 1, 1, 1, 0], [1, 1, 1, 1, 1], [1, 1, 1, 1, 1], [1, 1, 1, 1, 1], [0, 1, 1, 1, 0]]
        """
        x0, y0, x1, y1 = _pil_box(xy, "ellipse")
        w = _pil_width(width)
        shape = _shapes.ellipse((x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2)
        ring = None
        if outline is not None and w > 0:
            inner = _shapes.ellipse((x0 + x1) / 2, (y0 + y1) / 2, max((x1 - x0) / 2 - w, 0),
                                    max((y1 - y0) / 2 - w, 0))
            ring = _both(shape, inner)
        self._shape(shape, fill, ring, outline, aa, tolerance, "ellipse", opacity, gamma)

    def circle(self, xy: Point, radius: float, fill: Optional[Color] = None, outline: Optional[Color] = None,
               width: int = 1, *, aa: Optional[CoverageMethod] = None, tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.circle``: :meth:`ellipse` of the box
        (x - radius, y - radius, x + radius, y + radius); `opacity` and
        `gamma` as there."""
        c = _pil_point(xy, "circle: xy")
        r = _shapes._radius(radius, "radius")
        self.ellipse((c[0] - r, c[1] - r, c[0] + r, c[1] + r), fill, outline, width, aa=aa, tolerance=tolerance,
                     opacity=opacity, gamma=gamma)

    def rounded_rectangle(self, xy: Any, radius: float = 0, fill: Optional[Color] = None,
                          outline: Optional[Color] = None, width: int = 1, *,
                          corners: Optional[Sequence[bool]] = None, aa: Optional[CoverageMethod] = None,
                          tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.rounded_rectangle``: the box `xy` (inclusive)
        with its corners rounded by quarter circles of `radius` (clamped to
        half the shorter side; `corners` (top left, top right, bottom
        right, bottom left) says which), `outline` the ring between it and
        the box inset by `width` with radius - width.  radius 0 is the
        rectangle, pixels x0..x1 and y0..y1 as Pillow.  `opacity` and
        `gamma` as :meth:`ellipse`.

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((4, 6), format="gray8")
        >>> c.rounded_rectangle((1, 0, 4, 2), 0, fill=1)
        >>> c.array.tolist()
        [[0, 1, 1, 1, 1, 0], [0, 1, 1, 1, 1, 0], [0, 1, 1, 1, 1, 0], [0, 0, 0, 0, 0, 0]]
        """
        x0, y0, x1, y1 = _pil_box(xy, "rounded_rectangle")
        w = _pil_width(width)
        r = _shapes._radius(radius, "radius")
        shape = _shapes.rounded_rectangle(x0, y0, x1, y1, r, corners=corners)
        ring = None
        if outline is not None and w > 0:
            inner = _shapes.rounded_rectangle(min(x0 + w, (x0 + x1) / 2), min(y0 + w, (y0 + y1) / 2),
                                              max(x1 - w, (x0 + x1) / 2), max(y1 - w, (y0 + y1) / 2),
                                              max(r - w, 0), corners=corners)
            ring = _both(shape, inner)
        self._shape(shape, fill, ring, outline, aa, tolerance, "rounded_rectangle", opacity, gamma)

    def arc(self, xy: Any, start: float, end: float, fill: Optional[Color] = None, width: int = 1, *,
            aa: Optional[CoverageMethod] = None, tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.arc``: the arc of the ellipse in the box `xy`
        (inclusive) from `start` to `end` degrees, clockwise from 3 o'clock
        (the ellipse's parametric angle, as Pillow), `width` pixels wide
        inside the box: rastrum strokes the ellipse inset by width/2 with
        butt ends (on a circle, exactly the annular sector; on an ellipse
        the true offset curve, where Pillow insets the radii).  `opacity`
        and `gamma` as :meth:`stroke`: each pixel blended once."""
        x0, y0, x1, y1 = _pil_box(xy, "arc")
        w = _pil_width(width)
        if fill is None:
            raise InputError("arc needs fill (a colour)")
        if w == 0:
            self._paint_kw(fill, opacity, gamma, "Canvas.arc")
            return
        h = w / 2
        path = _shapes.arc((x0 + x1) / 2, (y0 + y1) / 2, max((x1 - x0) / 2 - h, 0), max((y1 - y0) / 2 - h, 0),
                           start, end)
        if len(path):
            self.stroke(path, fill, w, cap="butt", join="round", aa=aa, tolerance=tolerance, opacity=opacity,
                        gamma=gamma)
        else:
            self._paint_kw(fill, opacity, gamma, "Canvas.arc")

    def pieslice(self, xy: Any, start: float, end: float, fill: Optional[Color] = None,
                 outline: Optional[Color] = None, width: int = 1, *, aa: Optional[CoverageMethod] = None,
                 tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.pieslice``: the slice of the ellipse in the
        box `xy` (inclusive) from `start` to `end` (as :meth:`arc`).
        `outline`: rastrum strokes the slice's boundary `width` wide,
        mitred, centred on it (Pillow draws it inside).  `opacity` and
        `gamma` as :meth:`ellipse`."""
        x0, y0, x1, y1 = _pil_box(xy, "pieslice")
        shape = _shapes.pieslice((x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2, start, end)
        self._shape(shape, fill, _outline(shape, outline, width), outline, aa, tolerance, "pieslice", opacity, gamma)

    def chord(self, xy: Any, start: float, end: float, fill: Optional[Color] = None,
              outline: Optional[Color] = None, width: int = 1, *, aa: Optional[CoverageMethod] = None,
              tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.chord``: the arc from `start` to `end` (as
        :meth:`arc`) closed by a straight line; `outline`, `opacity` and
        `gamma` as :meth:`pieslice`."""
        x0, y0, x1, y1 = _pil_box(xy, "chord")
        shape = _shapes.chord((x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2, start, end)
        self._shape(shape, fill, _outline(shape, outline, width), outline, aa, tolerance, "chord", opacity, gamma)

    def regular_polygon(self, bounding_circle: Any, n_sides: int, rotation: float = 0,
                        fill: Optional[Color] = None, outline: Optional[Color] = None, width: int = 1, *,
                        aa: Optional[CoverageMethod] = None, tolerance: Optional[float] = None,
                opacity: Optional[float] = None, gamma: Union[None, str, float] = None) -> None:
        """Pillow's ``ImageDraw.regular_polygon``: `n_sides` vertices on the
        circle `bounding_circle` ((x, y, r) or ((x, y), r); the centre a
        pixel centre), rotated `rotation` degrees counter-clockwise, the
        first side at the bottom (Pillow's vertices, not rounded to 2
        decimals).  Filled by rastrum's rule (Pillow also paints the
        boundary's pixels); `outline`, `opacity` and `gamma` as
        :meth:`pieslice`."""
        try:
            bc = list(bounding_circle)
        except TypeError:
            bc = []
        if len(bc) == 3:
            centre, r = bc[:2], bc[2]
        elif len(bc) == 2 and _is_point(bc[0]):
            centre, r = bc[0], bc[1]
        else:
            raise InputError("bounding_circle: (x, y, r) or ((x, y), r), not %r" % (bounding_circle,))
        cx, cy = _pil_point(centre, "bounding_circle")
        shape = _shapes.regular_polygon(cx, cy, r, n_sides, rotation=rotation)
        self._shape(shape, fill, _outline(shape, outline, width), outline, aa, tolerance, "regular_polygon", opacity, gamma)

    def line(self, p0: Any, p1: Any = None, color: Optional[Color] = None, *, fill: Optional[Color] = None,
             width: float = 1, joint: Optional[str] = None, aa: Optional[CoverageMethod] = None,
             tolerance: Optional[float] = None, algorithm: LineAlgorithm = "bresenham", subpixel_bits: int = 8,
             sample_offset: float = 0.5, opacity: Optional[float] = None,
             gamma: Union[None, str, float] = None) -> None:
        """Paint `color` on the pixels of the segment p0 -> p1; or, as
        Pillow's ``ImageDraw.line(xy, fill, width, joint)``, on the
        polyline `xy`.

        ``line(p0, p1, color)`` (p0 and p1 points in rastrum's coordinates):
        width 1 without `aa` is the binary line, the pixels of
        :func:`rastrum.line_pixels` (p0, p1) (`algorithm`, `subpixel_bits`,
        `sample_offset` as there; the rest of the line clipped); a `width`
        other than 1, or `aa`, fills the segment's stroke, butt ends
        (:meth:`stroke`).

        ``line(xy, fill)`` or ``line(xy, fill=..., width=..., joint=...)``
        (`xy` a sequence of points, or of numbers x0, y0, x1, y1, ...):
        Pillow's call, points at pixel centres; width 1 without `aa` is
        the binary line through them, else the polyline stroked `width`
        wide, butt ends, joins round with ``joint="curve"`` and bevelled
        with None (Pillow leaves the bevel's notch open).  `opacity`,
        `gamma` and a colour's alpha as :meth:`fill_polygon`: the line's
        pixels (or its stroke's coverage) blended, each pixel once
        (docs/opacity.md).  Nothing is written when an argument is bad (an
        InputError says which).

        Examples
        --------
        >>> import rastrum
        >>> c = rastrum.Canvas((3, 6), format="gray8")
        >>> c.line((0, 0), (5, 2), 1, subpixel_bits=0, sample_offset=0)
        >>> c.array
        array([[1, 1, 0, 0, 0, 0],
               [0, 0, 1, 1, 0, 0],
               [0, 0, 0, 0, 1, 1]], dtype=uint8)
        >>> c = rastrum.Canvas((3, 6), format="gray8")
        >>> c.line([(0, 1), (5, 1)], fill=9, width=3, aa="area")  # butt ends at pixel centres
        >>> c.array[1].tolist()
        [5, 9, 9, 9, 9, 5]
        """
        if joint not in (None, "curve"):
            raise InputError('joint: %r; None or "curve" (Pillow\'s)' % (joint,))
        w = _real_width(width)
        single = _is_point(p0)
        if single:
            if fill is not None:
                if color is not None:
                    raise InputError("line: give the colour once, as color or fill")
                color = fill
            if color is None:
                raise InputError("line needs a colour")
            if w == 1 and aa is None:
                if opacity is None and gamma is None:  # the common call: no more keywords to pass
                    self._line(p0, p1, color, algorithm=algorithm, subpixel_bits=subpixel_bits,
                               sample_offset=sample_offset)
                else:
                    self._line(p0, p1, color, algorithm=algorithm, subpixel_bits=subpixel_bits,
                               sample_offset=sample_offset, opacity=opacity, gamma=gamma)
                return
            pts = np.array([_pil_point(p0, "p0"), _pil_point(p1, "p1")])
        else:
            if color is not None:
                raise InputError("line(xy, fill): the colour is the second argument or fill=")
            if (p1 is None) == (fill is None):
                raise InputError("line(xy, fill): give the colour once, as the second argument or fill=")
            color = fill if fill is not None else p1
            pts = _pil_points(p0) + 0.5
            if w == 1 and aa is None:
                if len(pts) == 1:
                    pts = np.concatenate([pts, pts])
                self.polyline(pts, color, algorithm=algorithm, subpixel_bits=subpixel_bits,
                              sample_offset=sample_offset, opacity=opacity, gamma=gamma)
                return
        paint = self._paint_kw(color, opacity, gamma, "Canvas.line")  # checked before anything is drawn
        if w == 0 or len(pts) == 0:
            return
        # the stroke's outline, one non-zero fill: blended once per pixel
        self.stroke(pts, color, w, join="round" if joint == "curve" else "bevel", cap="butt", aa=aa,
                    tolerance=tolerance, subpixel_bits=subpixel_bits, sample_offset=sample_offset, **paint)

    def __repr__(self) -> str:
        return "Canvas((%d, %d), format=%r)" % (self.height, self.width, self._format)


# ---- helpers of the curves, strokes and Pillow's shapes (docs/paths.md) -------------------------

def _pil_coords(xy, what):
    """Pillow's coordinates: a sequence of (x, y) pairs or of numbers
    x0, y0, x1, y1, ...; as an (N, 2) float64 array, finite.  Bools,
    complex numbers and strings are refused, not converted."""
    try:
        kind = np.asarray(xy).dtype.kind
    except (TypeError, ValueError):  # ragged: the float conversion below says so
        kind = "f"
    if kind not in "bcUSV" and isinstance(xy, (list, tuple)):  # numpy reads (True, 3) as ints
        for v in xy:
            for t in (v if isinstance(v, (list, tuple)) else (v,)):
                if isinstance(t, (bool, np.bool_)):
                    kind = "b"
    if kind in "bcUSV":
        raise InputError("%s: %r holds %s, not real numbers" % (what, xy, {
            "b": "bools", "c": "complex numbers"}.get(kind, "strings or bytes")))
    try:
        a = np.asarray(xy, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        raise InputError("%s: %r is not a sequence of (x, y) points or of numbers" % (what, xy)) from None
    if a.ndim == 1 and a.size % 2 == 0:
        a = a.reshape(-1, 2)
    if a.ndim != 2 or a.shape[1] != 2:
        raise InputError("%s: %r is not a sequence of (x, y) points or of numbers x0, y0, ..." % (what, xy))
    if not np.isfinite(a).all():
        raise InputError("%s: a coordinate is NaN or infinite" % what)
    return a


def _pil_box(xy, what):
    """Pillow's bounding box (inclusive) as rastrum's (x0, y0, x1 + 1, y1 + 1)."""
    a = _pil_coords(xy, what + ": xy")
    if a.shape != (2, 2):
        raise InputError("%s: xy is (x0, y0, x1, y1) or ((x0, y0), (x1, y1)), not %r" % (what, xy))
    (x0, y0), (x1, y1) = a.tolist()
    if x1 < x0 or y1 < y0:
        raise InputError("%s: xy = %r needs x1 >= x0 and y1 >= y0 (as Pillow)" % (what, xy))
    return x0, y0, x1 + 1.0, y1 + 1.0


def _pil_point(p, what):
    a = _pil_coords(p, what)
    if a.shape != (1, 2):
        raise InputError("%s: one point (x, y), not %r" % (what, p))
    return float(a[0, 0]), float(a[0, 1])


def _pil_points(xy):
    return _pil_coords(xy, "line: xy")


def _is_point(p):
    """Is `p` one point (x, y) (not a sequence of points)?"""
    if isinstance(p, (str, bytes)):
        return False
    try:
        return np.ndim(p) == 1 and len(p) == 2
    except (TypeError, ValueError):
        return False


def _pil_width(width):
    if isinstance(width, (bool, np.bool_)) or not isinstance(width, (int, float, np.integer, np.floating)):
        raise InputError("width: %r; a number of pixels >= 0" % (width,))
    try:
        w = float(width)
    except OverflowError:  # an int past float64's range (np.isfinite cannot take it)
        raise InputError("width: too large (beyond float64's range); a number of pixels >= 0") from None
    if not math.isfinite(w) or w < 0:
        raise InputError("width: %r; a number of pixels >= 0" % (w,))
    return w


def _real_width(width):
    return _pil_width(width)


def _both(outer, inner):
    """The ring between two closed shape Paths: one Path of both, with the
    rule that fills it (even-odd)."""
    p = outer.copy()
    p._verbs += inner._verbs
    p._pts += inner._pts
    p._start, p._cur, p._closed = inner._start, inner._cur, inner._closed
    return p, "evenodd"


def _outline(shape, outline, width):
    """A closed shape's outline stroked `width` wide, mitred, or None."""
    from ._strokes import stroke as _stroke

    w = _pil_width(width)
    if outline is None or w == 0 or len(shape) == 0:
        return None
    return _stroke(shape, w, join="miter"), "nonzero"


def _stroke_geometry(g):
    """rastrum.stroke's geometry from a Path (rastrum's or matplotlib's),
    polylines, or a shapely / __geo_interface__ line or polygon."""
    from ._path import Path, as_path

    p = as_path(g)
    if p is not None:
        return p
    gi = _core._geo_mapping(g)
    if gi is None:
        return g
    out = Path()

    def add(coords, closed):
        c = _pil_coords(coords, "geometry")
        if len(c) == 0:
            return
        out.move_to(*c[0])
        for q in c[1:]:
            out.line_to(*q)
        if closed:
            out.close()

    def walk(gi):
        kind = gi.get("type")
        if kind == "LineString":
            add(gi["coordinates"], False)
        elif kind == "MultiLineString":
            for c in gi["coordinates"]:
                add(c, False)
        elif kind == "Polygon":
            for c in gi["coordinates"]:
                add(c, True)
        elif kind == "MultiPolygon":
            for poly in gi["coordinates"]:
                for c in poly:
                    add(c, True)
        elif kind == "GeometryCollection":
            for sub in gi["geometries"]:
                walk(sub)
        else:
            raise InputError("geometry: a %s has no line to stroke" % (kind,))

    walk(gi)
    return out


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



# The formats a colour's alpha is applied on (rast_blend_coverage).
_BLEND_FORMATS = ("gray8", "rgb888", "rgb565", "rgba8888")


def _blend_level(opacity, entry, fmt):
    """`opacity` as a level (_opacity_level) on a canvas of format fmt, which
    must be one the blend takes."""
    level = _opacity_level(opacity, entry)
    if fmt not in _BLEND_FORMATS:
        raise InputError("%s: opacity is for gray8, rgb888, rgb565 and rgba8888 canvases, not %s"
                         % (entry, fmt))
    return level


def _opacity_level(opacity, entry):
    """`opacity` (a real number in 0..1) as a level 0..255:
    floor(opacity * 255 + 1/2) of the number's exact value (docs/opacity.md)."""
    import fractions
    import math

    if isinstance(opacity, (bool, np.bool_)) or not isinstance(opacity, (int, float, np.integer, np.floating)) \
            or not math.isfinite(float(opacity)) or not 0 <= opacity <= 1:
        raise InputError("%s: opacity must be a number in 0..1, not %r" % (entry, opacity))
    return math.floor(fractions.Fraction(float(opacity)) * 255 + fractions.Fraction(1, 2))


def _blend_rgba(color, fmt):
    """The straight 8-bit RGBA colour (4 bytes) `color` blends with on a
    `fmt` canvas: rgba8888 its pixel value (R, G, B, A); the others their
    colour (an int, (R, G, B) or gray8's level) with alpha 255, or that
    colour plus an alpha ((R, G, B, A), gray8 (L, A)), or a string through
    Pillow's ImageColor with its alpha ("#rrggbbaa")."""
    if fmt == "rgba8888":
        return _pixel_bytes(color, fmt)
    n = 1 if fmt == "gray8" else 3
    if isinstance(color, str):
        from PIL import ImageColor

        try:
            value = ImageColor.getcolor(color, "LA" if n == 1 else "RGBA")
        except ValueError:
            raise InputError('colour %r: not a colour name (e.g. "red") nor "#rgb", "#rrggbb" or "#rrggbbaa" '
                             "(the names and spellings of Pillow's ImageColor)" % (color,)) from None
        return bytes(bytearray([value[0]] * 3 + [value[1]] if n == 1 else list(value)))
    color = _core.as_numpy(color)
    if not _is_int(color):
        try:
            values = list(color)
        except TypeError:
            values = None
        if values is not None and len(values) == n + 1:
            alpha = values[n]
            if not _is_int(alpha) or not 0 <= alpha <= 255:
                raise InputError("colour %r: its alpha must be an int in 0..255" % (color,))
            rgb = _rgba_bytes(values[0] if n == 1 else values[:n], "rgb888" if n == 3 else fmt)
            return rgb[:3] + bytes(bytearray([int(alpha)]))
    return _rgba_bytes(color, "rgb888" if n == 3 else fmt)


def _blend_args(color, opacity, fmt, entry, gamma=None):
    """_made_blend_args, remembered for a colour of plain values (an int, a
    str, a tuple of ints), a float or no opacity and a str, float or no
    gamma: the exact level of an opacity (fractions) and the colour's
    parse were half of a small translucent fill's call (issue 34).  The
    cdata it returns are only read (const in C); errors are not
    remembered, so each call raises its own message."""
    tc = type(color)
    if (tc is int or tc is str or (tc is tuple and all(type(v) is int for v in color))) \
            and (opacity is None or type(opacity) is float) \
            and (gamma is None or type(gamma) is str or type(gamma) is float):
        key = (color, opacity, fmt, gamma)
        got = _BLEND_ARGS.get(key)
        if got is None:
            got = _made_blend_args(color, opacity, fmt, entry, gamma)
            if len(_BLEND_ARGS) < 256:
                _BLEND_ARGS[key] = got
        return got
    return _made_blend_args(color, opacity, fmt, entry, gamma)


_BLEND_ARGS: Dict[Any, Any] = {}


def _made_blend_args(color, opacity, fmt, entry, gamma=None):
    """(blend, color): blend None for a colour painted as a value (no
    opacity or gamma given, and alpha 255 or a format whose alpha is
    stored), with `color` less its alpha 255 if it had one; else (RGBA
    cdata, rast_blend_opts, gamma tables or None) for rast_blend_coverage
    or the linear-light blend."""
    n = 1 if fmt == "gray8" else 3
    if opacity is None and gamma is None and type(color) is tuple and len(color) != n + 1:
        return None, color  # the common opaque call, quickly
    if color is None:
        if opacity is not None or gamma is not None:
            raise InputError("%s: opacity and gamma are for one colour (color=), not vertex_colors" % entry)
        return None, color
    tables = None
    if gamma is not None:
        if fmt not in _BLEND_FORMATS:
            raise InputError("%s: gamma= blends gray8, rgb888, rgb565 and rgba8888 canvases, not %s"
                             % (entry, fmt))
        tables = _gamma_tables(gamma, entry)
        if opacity is None:
            opacity = 1.0
    if opacity is None:
        if fmt not in _BLEND_FORMATS or fmt == "rgba8888" or type(color) is int:
            return None, color
        if not isinstance(color, str):
            try:
                k = len(color)
            except TypeError:
                return None, color
            if k != n + 1 or np.ndim(color) != 1:
                return None, color
        level = 255
    else:
        level = _blend_level(opacity, entry, fmt)
        if np.ndim(color) >= 2:
            raise InputError("%s: opacity takes one colour, not one per triangle" % entry)
    rgba = _blend_rgba(color, fmt)
    if fmt != "rgba8888" and rgba[3] == 255 and level == 255 and tables is None:  # opaque: the value's fill
        if isinstance(color, str):
            return None, color
        return None, (color if _is_int(_core.as_numpy(color)) or len(color) == n
                      else (color[0] if n == 1 else tuple(color[:n])))
    opts = ffi.new("rast_blend_opts *")
    opts.opacity = level
    return (ffi.new("uint8_t[4]", list(bytearray(rgba))), opts, tables), color


# 2^24: the linear-light tables' scale (every table strictly increasing).
_LINEAR_ONE = 1 << 24


@functools.lru_cache(maxsize=16)
def _gamma_table(gamma):
    """The rast_gamma tables (docs/opacity.md): round(2**24 * decode(k / n))
    for n = 255, 63 and 31 (rgb565's fields), decode the sRGB curve or the
    power `gamma`; a cdata the core reads (rast_blend_coverage_linear)."""
    import math

    def decode(v):
        if gamma == "srgb":
            return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4
        return v ** gamma

    g = ffi.new("rast_gamma *")
    for name, n in (("dec8", 255), ("dec6", 63), ("dec5", 31)):
        setattr(g, name, [math.floor(_LINEAR_ONE * decode(k / n) + 0.5) for k in range(n + 1)])
    return g


def _gamma_tables(gamma, entry):
    """gamma "srgb" or a number in 0.3..3: the linear-light tables of every
    level, round(2**24 * decode(level / top)) (docs/opacity.md)."""
    if isinstance(gamma, str):
        if gamma != "srgb":
            raise InputError('%s: gamma must be "srgb" or a number in 0.3..3, not %r' % (entry, gamma))
    elif isinstance(gamma, (bool, np.bool_)) or not isinstance(gamma, (int, float, np.integer, np.floating)) \
            or not 0.3 <= float(gamma) <= 3:
        raise InputError('%s: gamma must be "srgb" or a number in 0.3..3, not %r' % (entry, gamma))
    else:
        gamma = float(gamma)
    return _gamma_table(gamma)


def _blend_box(target, geometry, tris, blend, shape, aa, rule, subpixel_bits, sample_offset, algorithm,
               rounding, boundary):
    """Canvas._blend over the geometry's pixel box only (issue 34): its mask
    or coverage computed there and blended there by one C call
    (python/glue/blend.c, coverage.c), with the vertices snapped as
    polygon_mask, triangles_mask and the coverage calls snap them (the
    clip changes, never a coordinate), so the pixels are those of the
    whole canvas's blend.  True when done; False when nothing was written
    and the whole-canvas path must take the call (anything this does not
    take: other ring forms, the 64-bit path, any error, whose message that
    path gives)."""
    try:
        if aa is not None:
            if aa[:2] == "ss" and max(shape) > _MAX_DIM >> 4:
                return False  # (the core refuses such a clip for ssK: that path says so)
            opts = _coverage._opts(aa, rule, subpixel_bits, sample_offset, "Canvas._blend")
        elif tris:
            opts = _triangles.tri_opts(algorithm, subpixel_bits, sample_offset, rounding, boundary)
        else:
            opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
    except InputError:
        return False
    gamma = ffi.NULL if blend[2] is None else blend[2]
    if tris:  # a checked C-contiguous float64 (N, 3, 2) array (tris_f64)
        xy = ffi.from_buffer("double[]", geometry)
        if aa is not None:
            st = _coverage._lent(lib.rastpy_blend_triangles_coverage, target, xy, geometry.shape[0], opts,
                                 blend[0], blend[1], gamma)
        else:
            st = lib.rastpy_blend_triangles(target, xy, geometry.shape[0], opts, blend[0], blend[1], gamma)
        return st == 0
    got = _coverage._quick_points(geometry)
    if got is None:  # any other form (int32 arrays, tuples, ...): checked and packed as polygon_mask packs it
        try:
            pts, sizes, nrings = _core._points(geometry)
        except Exception:  # whatever it is, the whole-canvas path raises it, with its message
            return False
        got = (ffi.from_buffer("double[]", pts) if len(pts) else ffi.NULL, len(pts), sizes, nrings)
    # The 64-bit path exactly where polygon_mask and polygon_coverage take
    # it (_core.use_wide, _coverage._use_wide: S above 16, or a point the
    # 32-bit snap refuses), never where they do not (python/glue/wide.c).
    # (subpixel_bits: an int, as opts took it)
    if aa is not None:
        st = _coverage._lent(lib.rastpy_blend_polygon_coverage, target, *got, opts, blend[0], blend[1], gamma)
    elif subpixel_bits <= _MAX_S32:
        st = lib.rastpy_blend_polygon(target, *got, opts, blend[0], blend[1], gamma)
    else:
        return lib.rastpy_blend_polygon64(target, *got, opts, blend[0], blend[1], gamma) == 0
    if not st:
        return True
    if st > 0 and got[1] and lib.rastpy_needs_wide(got[0], got[1], opts.subpixel_bits):  # past the 32-bit range
        if aa is None and _core.can_wide(opts):
            st = lib.rastpy_blend_polygon64(target, *got, opts, blend[0], blend[1], gamma)
        elif aa is not None and opts.method == lib.RAST_AA_AREA:
            st = lib.rastpy_blend_polygon_coverage64(target, *got, opts, blend[0], blend[1], gamma)
    return st == 0


_MAX_S32 = lib.RAST_MAX_SUBPIXEL_BITS

# A blended seed fill's first window: this many pixels each side of the
# seed (Canvas._seed_blend), grown while the region reaches its edge.
_SEED_WINDOW = 32


_MAX_DIM = lib.RAST_MAX_DIM


def _blend_polyline(target, points, n, closed, opts, blend):
    """Blend `blend` (from _blend_args) through the pixels of
    rast_draw_polyline(points[0 .. n), closed, opts) as a mask (255),
    computed and blended over their box only (python/glue/blend.c)."""
    gamma = ffi.NULL if blend[2] is None else blend[2]
    st = lib.rastpy_blend_polyline(target, points, n, closed, opts, blend[0], blend[1], gamma)
    if st == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for a line's mask")
    _core._check(st)


def _blend_mask(target, cov, blend, box=None):
    """Blend `blend` (from _blend_args) into `target` through the contiguous
    uint8 coverage `cov` of the target's shape (or, with `box` (x0, y0, x1,
    y1) inside the target, of that box: only its pixels are blended):
    rast_blend_coverage, or rast_blend_coverage_linear with gamma=
    (docs/opacity.md)."""
    if not cov.size:
        return
    if box is not None:  # the target's pixels in the box only (a copy of the target, its clip the box)
        target = ffi.new("rast_target *", target[0])
        target.clip.x0, target.clip.y0, target.clip.x1, target.clip.y1 = box
    if blend[2] is not None:
        _core._check(lib.rast_blend_coverage_linear(target, ffi.from_buffer(cov), lib.RAST_COVERAGE_U8,
                                                    cov.shape[1], blend[0], blend[1], blend[2]))
    else:
        _core._check(lib.rast_blend_coverage(target, ffi.from_buffer(cov), lib.RAST_COVERAGE_U8,
                                             cov.shape[1], blend[0], blend[1]))


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
_AET, _EVENODD, _S8, _HALF, _EXACT, _GOURAUD = (Canvas.fill_polygon.__kwdefaults__[k] for k in (
    "algorithm", "rule", "subpixel_bits", "sample_offset", "rounding", "shading"))
assert Canvas.fill_polygon.__kwdefaults__["boundary"] is _EXACT
assert Canvas.fill_polygon.__kwdefaults__["precision"] is _EXACT
_DEFAULT_OPTS = _core.fill_opts(_AET, _EVENODD, _S8, _HALF, _EXACT, _EXACT)
_ndarray, _F64, _PACKED = np.ndarray, np.dtype(np.float64), (16, 8)
_DOUBLES, _from_buffer, _fill_ring = ffi.typeof("double[]"), ffi.from_buffer, lib.rastpy_fill_ring
_seq_rings, _RING_DTYPES = _core._seq.rings, _core._RING_DTYPES
_FILL_OPTS: Dict[Any, Any] = {}
_cast, _UINTPTR, _fill_quick = ffi.cast, ffi.typeof("uintptr_t"), _core._seq.fill
# The options of keyword calls _seq.fill takes whole ({rule: {aa: address}}:
# rule= and aa= and no other keyword), checked here once and kept alive.
_KW_OPTS = [(rule, aa, _core.fill_opts(_AET, rule, _S8, _HALF, _EXACT, _EXACT) if aa is None
             else _coverage.aa_opts_quick(aa, rule, _S8, _HALF, "Canvas.fill_polygon"))
            for rule in ("evenodd", "nonzero") for aa in (None,) + tuple(_coverage.METHODS)]
_KW_TABLE: Dict[str, Dict[Optional[str], int]] = {}
for _rule, _aa, _o in _KW_OPTS:
    _KW_TABLE.setdefault(_rule, {})[_aa] = int(_cast(_UINTPTR, _o))
_core._seq.fill_setup(int(_cast(_UINTPTR, ffi.addressof(lib, "rastpy_fill_ring"))), int(_cast(_UINTPTR, _DEFAULT_OPTS)),
                      _ndarray, _F64, int(_cast(_UINTPTR, ffi.addressof(lib, "rastpy_fill_polygon_aa"))), _KW_TABLE)
_OPTS_ADDRESS: Dict[Any, int] = {}
_lent, _fill_ring_aa, _NULL, _MAX_POINTS = _coverage._lent, lib.rastpy_fill_polygon_aa, ffi.NULL, lib.RAST_MAX_POINTS
_TWO_ADDRESSES = ffi.typeof("uintptr_t[2]")


def _fpq_of(target: Any, color: int, array: Any, pixel: Any, aa: bool) -> Tuple[Any, ...]:
    """Canvas._fpq, the common call _seq.fill does in C: the target and
    colour objects, the target's and the pixel's addresses as the bytes of
    two uintptr_t, the array and pixel kept alive, and whether aa= may be
    given (python/ext/seq.c)."""
    addresses = ffi.new(_TWO_ADDRESSES, [int(_cast(_UINTPTR, target)), int(_cast(_UINTPTR, pixel))])
    return (target, color, ffi.buffer(addresses)[:], None, array, pixel, aa)


def _opts_address(opts):
    """The address of a checked rast_fill_opts for _seq.fill (None: the
    default options), remembered for those _fill_opts keeps."""
    if opts is _DEFAULT_OPTS:
        return None
    a = _OPTS_ADDRESS.get(opts)
    if a is None:
        a = int(_cast(_UINTPTR, opts))
        if len(_OPTS_ADDRESS) < 256 and opts in _FILL_OPTS.values():
            _OPTS_ADDRESS[opts] = a
    return a


# Canvas.fill_polygon's common call, a ring and an int colour and no
# keyword but rule= and aa= (the loop every cv2.fillPoly user writes), is
# done in C in one call (_seq.fill) once the full method has drawn with
# that canvas target and colour object and remembered them in _fpq: no
# frame of sixteen keyword arguments, no cffi conversions.  The class
# attribute is _seq.fill_method's method descriptor: the interpreter hands
# the canvas and the call's arguments to C as they are, with no Python
# frame (that frame, its keyword matching and **kw dict, cost ~930
# instructions of a tiny polygon's call, issue 33).  Anything else, and
# anything _seq.fill declines, is the full method's, called with the same
# arguments (this module's _fill_polygon, looked up at each such call):
# its checks, its InputErrors, its pixels (the same C fill for what both
# take).  Its text signature and docstring are the full method's (help(),
# inspect.signature); type checkers read the method in the class body.
_fill_polygon = Canvas.fill_polygon


def _text_signature(f):
    """f's signature as a builtin's __text_signature__ ("name($self, ...)"
    and "--") before its docstring: what help() and inspect read."""
    sig = inspect.signature(f)
    sig = sig.replace(parameters=[p.replace(annotation=inspect.Parameter.empty) for p in sig.parameters.values()],
                      return_annotation=inspect.Signature.empty)
    return "%s%s\n--\n\n%s" % (f.__name__, str(sig).replace("(self", "($self", 1), inspect.getdoc(f) or "")


setattr(Canvas, "fill_polygon", _core._seq.fill_method(Canvas, globals(), "_fill_polygon",
                                                         _text_signature(_fill_polygon)))


def _fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary):
    """_core.fill_opts, looked up by value alone for str names, an int S and
    a float offset (a plain tuple: cheaper than the general cache's key,
    which adds the types, so that True or 8.0 still take its checks)."""
    if type(subpixel_bits) is int and type(sample_offset) is float and type(algorithm) is str \
            and type(rule) is str and type(rounding) is str and type(boundary) is str:
        key = (algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
        opts = _FILL_OPTS.get(key)
        if opts is None:
            opts = _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)
            if len(_FILL_OPTS) < 256:
                _FILL_OPTS[key] = opts
        return opts
    return _core.fill_opts(algorithm, rule, subpixel_bits, sample_offset, rounding, boundary)


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

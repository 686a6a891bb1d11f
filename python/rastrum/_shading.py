"""Shaded fills: the checks and conversions behind
``Canvas.fill_triangles(..., vertex_colors=..., depth=...)``,
``Canvas.fill_polygon(..., vertex_colors=..., aa=...)`` and
``Canvas.fill_rect_gouraud(..., aa=...)``.

Thin, like the rest: colours become an (N, 3, 4) uint8 RGBA array, depths
an (N, 3) int32 array, and one C call (rast_fill_triangles_shaded, without
the GIL) snaps the vertices and paints the batch; a Gouraud rectangle is
checked, its corners snapped, and drawn by one C call.
"""

import numpy as np

from . import _core
from ._core import InputError
from . import _triangles
from ._native import ffi, lib

PRECISIONS = {
    "exact": lib.RAST_PRECISION_EXACT,
    "fixed": lib.RAST_PRECISION_FIXED,
    "flat": lib.RAST_PRECISION_FLAT,
}
INT32_MAX = 2 ** 31 - 1
INT32_MIN = -(2 ** 31)
# The channels of each pixel format (Canvas's formats) in a colour.
_CHANNELS = {"gray8": 1, "rgb888": 3, "rgba8888": 4, "rgb565": 3, "mono1": 1}


def _make_shade_opts(precision, fraction_bits):
    code = PRECISIONS[_core._name(precision, "precision", PRECISIONS)]
    if isinstance(fraction_bits, (bool, np.bool_)) or not isinstance(fraction_bits, (int, np.integer)):
        raise InputError("fraction_bits must be an int, not %r" % (fraction_bits,))
    if code == lib.RAST_PRECISION_FIXED and not 1 <= fraction_bits <= 16:
        raise InputError("fraction_bits must be in 1..16, not %d" % fraction_bits)
    opts = ffi.new("rast_shade_opts *")
    opts.precision = code
    opts.fraction_bits = int(fraction_bits)
    return opts


def shade_opts(precision, fraction_bits):
    """A checked, read-only ``rast_shade_opts *``."""
    return _core.cached_opts("shade", _make_shade_opts, precision, fraction_bits)


def rgba(colors, n, per_vertex, fmt, channels):
    """`colors` as a C-contiguous uint8 (n, 3, 4) RGBA array.

    per_vertex: (n, 3, C) vertex colours; else (n, C) one colour per
    triangle, given to its three vertices.  C = 1 (a level: R = G = B),
    3 (A = 255) or 4; gray8 and mono1 take C = 1 only.
    """
    if (per_vertex and type(colors) is np.ndarray and colors.dtype == np.uint8 and colors.shape == (n, 3, 4)
            and colors.flags.c_contiguous and channels == 4):
        return colors  # already what C reads: no copy
    what = "vertex_colors" if per_vertex else "color"
    want = "(N, 3, C)" if per_vertex else "(N, C)"
    try:
        a = np.asarray(colors)
    except (TypeError, ValueError):
        raise InputError("%s must be an array-like of ints of shape %s" % (what, want)) from None
    if a.dtype.kind not in "iu" or a.ndim != (3 if per_vertex else 2) or a.shape[0] != n or (
            per_vertex and a.shape[1] != 3):
        raise InputError("%s must be ints of shape %s with N = %d triangles, not %s %s"
                         % (what, want, n, a.dtype, a.shape))
    c = a.shape[-1]
    allowed = (1,) if channels == 1 else (1, 3, 4)
    if c not in allowed:
        raise InputError("%s: format %s takes %s channels per colour, not %d"
                         % (what, fmt, " or ".join(map(str, allowed)), c))
    if not per_vertex:
        a = np.repeat(a[:, None, :], 3, axis=1)
    return to_rgba(a, what)


def to_rgba(a, what):
    """Checked ints (..., C), C = 1 (a level: R = G = B), 3 (A = 255) or 4,
    as uint8 (..., 4) RGBA: the channel rule of every shaded call."""
    if a.size and (a.min() < 0 or a.max() > 255):
        raise InputError("%s: every channel must be in 0..255" % what)
    c = a.shape[-1]
    out = np.empty(a.shape[:-1] + (4,), np.uint8)
    out[..., 3] = 255
    if c == 1:
        out[..., :3] = a
    else:
        out[..., :c] = a
    return out


def depths(depth, n):
    """(n, 3) integers in int32, checked.  Depths are compared as int32:
    a value that is not an integer is refused, never rounded (0.4 and 0.2
    would tie), with a message naming a scale that makes them integers
    without losing their order."""
    d = _core.real_array(depth, "depth", "an (N, 3) array-like")
    if d.shape != (n, 3):
        raise InputError("depth must have shape (N, 3) = (%d, 3), not %s" % (n, d.shape))
    if not np.all(np.isfinite(d)) or (d.size and (d.min() < INT32_MIN or d.max() > INT32_MAX)):
        raise InputError("depth values must be finite integers in int32 (-2**31..2**31-1)")
    # (a Fraction, Decimal or longdouble with a fraction comes from
    # real_array as a float64 with one: exact_double keeps it off the grid)
    if not np.array_equal(np.floor(d), d):
        big = float(np.max(np.abs(d))) if d.size else 0.0
        k = 0
        while k < 30 and big * 2.0 ** (k + 1) < INT32_MAX:
            k += 1
        raise InputError(
            "depth values must be integers (they are compared as int32, so 0.4 and 0.2 would "
            "tie if rounded): scale them yourself, e.g. np.round(depth * 2**%d) (largest "
            "|depth| %r), or give integer depths" % (k, big))
    return np.ascontiguousarray(d, dtype=np.int32)



def fill(target, tris, colors, z, zbuf, opts, sopts, blend=None):
    """Snap the checked (N, 3, 2) float64 batch and paint it shaded (blend:
    a ``rast_blend_opts *``, source-over without depth,
    rast_fill_triangles_shaded_blend)."""
    n = tris.shape[0]
    if n == 0:
        return
    if blend is not None:
        result = lib.rastpy_fill_triangles_shaded_blend(
            target, ffi.from_buffer("double[]", tris), n, ffi.from_buffer("uint8_t[]", colors), opts, sopts,
            blend)
    else:
        result = lib.rastpy_fill_triangles_shaded(
            target, ffi.from_buffer("double[]", tris), n, ffi.from_buffer("uint8_t[]", colors),
            ffi.NULL if z is None else ffi.from_buffer("int32_t[]", z),
            ffi.NULL if zbuf is None else ffi.from_buffer("int32_t[]", zbuf, require_writable=True),
            opts, sopts)
    if result:
        _core._check_glue(result, tris.reshape(-1, 2), opts.subpixel_bits, "tris", 3)


RECT_METHODS = ("bilinear", "triangles")


def colors_rgba(colors, n, fmt, what):
    """(n, C) array-like of ints in 0..255 -> uint8 (n, 4) RGBA, with the
    channel rules of Canvas.fill_triangles: C = 1 (a level for R, G and B),
    3 (alpha 255) or 4; gray8 and mono1 take C = 1 (also given as (n,))."""
    try:
        a = np.asarray(colors)
    except (TypeError, ValueError):
        raise InputError("%s must be an array-like of ints" % what) from None
    if a.ndim == 1 and a.shape == (n,):
        a = a.reshape(n, 1)
    channels = _CHANNELS.get(fmt, 0)
    allowed = (1,) if channels == 1 else (1, 3, 4)
    if a.ndim != 2 or a.shape[0] != n or a.shape[1] not in allowed or a.dtype.kind not in "iu":
        raise InputError("%s must be ints of shape (%d, C), C in %s for format %s, not %s %s"
                         % (what, n, allowed, fmt, a.dtype, a.shape))
    return to_rgba(a, what)


def rect_corners(rect):
    r = _core.real_array(rect, "rect", "(x0, y0, x1, y1)")
    if r.shape != (4,):
        raise InputError("rect must be (x0, y0, x1, y1), not shape %s" % (r.shape,))
    return r


def fill_rect_gouraud(canvas, rect, corner_colors, method, precision, fraction_bits, subpixel_bits,
                      sample_offset, shade_blend=None, opacity=None, aa=None):
    """shade_blend: None (the colours stored), or (RGBA corner colours as
    uint8 (4, 4), ``rast_blend_opts *`` or None when opaque) from
    Canvas._vertex_blend: rast_fill_rect_gouraud_blend; method "triangles"
    hands the corner colours, `opacity` and `aa` to fill_triangles.  With
    `aa` (method "bilinear"): the rectangle's ring, its corners' colours,
    anti-aliased as fill_polygon_gouraud_aa paints it (docs/coverage.md
    "Shaded polygons"): at a pixel whose sample it owns, the bilinear
    colour of the binary fill."""
    r = rect_corners(rect)
    if not isinstance(method, str) or method not in RECT_METHODS:
        raise InputError("unknown method %r; choose one of: %s" % (method, ", ".join(RECT_METHODS)))
    blend = None
    if shade_blend is not None:
        cols, blend = shade_blend
    else:
        cols = colors_rgba(corner_colors, 4, canvas.format, "corner_colors")
    x0, y0, x1, y1 = r
    if method == "triangles":
        # The diagonal from corner 0 (x0, y0) to corner 2 (x1, y1).
        quad = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        split = [(0, 1, 2), (0, 2, 3)]
        tris = quad[split]
        vc = cols[split]
        if canvas.format == "gray8":
            vc = vc[..., [0, 3]]  # (L, A): gray8's spelling of a colour with alpha
        elif _CHANNELS.get(canvas.format) == 1:
            vc = vc[..., :1]  # a level
        canvas.fill_triangles(tris, vertex_colors=vc, precision=precision, fraction_bits=fraction_bits,
                              subpixel_bits=subpixel_bits, sample_offset=sample_offset, opacity=opacity, aa=aa)
        return
    if aa is not None:
        ring = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        fill_polygon_gouraud_aa(canvas, ring, cols, aa, "nonzero", subpixel_bits, sample_offset, precision,
                                blend, "Canvas.fill_rect_gouraud", {})
        return
    opts = _triangles.tri_opts("edge", subpixel_bits, sample_offset)
    sh = shade_opts(precision, fraction_bits)
    pts = _core.snap_points(r.reshape(2, 2), opts.subpixel_bits, "rect")
    side = np.abs(pts[1].astype(np.int64) - pts[0])
    if side.max() > lib.RAST_GOURAUD_RECT_MAX_SIZE:
        raise InputError("rect: a side of %g pixels is longer than the limit, 2**26 - 1 units of "
                         "1/2**subpixel_bits pixel (%g pixels at subpixel_bits=%d)"
                         % (side.max() / 2.0 ** opts.subpixel_bits,
                            lib.RAST_GOURAUD_RECT_MAX_SIZE / 2.0 ** opts.subpixel_bits, opts.subpixel_bits))
    p0 = ffi.new("rast_point *", (int(pts[0, 0]), int(pts[0, 1])))
    p1 = ffi.new("rast_point *", (int(pts[1, 0]), int(pts[1, 1])))
    if blend is not None:
        _core._check(lib.rast_fill_rect_gouraud_blend(canvas._writable(), p0[0], p1[0],
                                                      ffi.from_buffer("uint8_t[]", cols), opts, sh, blend))
        return
    _core._check(lib.rast_fill_rect_gouraud(canvas._writable(), p0[0], p1[0],
                                            ffi.from_buffer("uint8_t[]", cols), opts, sh))


def polygon_vertex_colors(vertex_colors):
    """fill_polygon's vertex colours as one array-like: a list of one
    (N_k, C) per ring concatenated."""
    if isinstance(vertex_colors, (list, tuple)) and vertex_colors and _core.ndim(vertex_colors[0]) == 2:
        return np.concatenate([np.asarray(v) for v in vertex_colors])
    return vertex_colors


def vertex_rgba(vertex_colors, fmt):
    """fill_polygon's vertex colours (an (N, C) array-like, or a list of
    one per ring) as uint8 (N, 4) RGBA, checked as colors_rgba checks."""
    vc = np.asarray(polygon_vertex_colors(vertex_colors))
    return colors_rgba(vc, vc.shape[0] if vc.ndim >= 1 else -1, fmt, "vertex_colors")


def fill_polygon_gouraud(canvas, rings, vertex_colors, opts, precision, shade_blend=None):
    """shade_blend as fill_rect_gouraud's: rast_fill_polygon_gouraud_blend."""
    cols, blend = shade_blend if shade_blend is not None else (vertex_rgba(vertex_colors, canvas.format), None)
    _core.fill_polygon_gouraud(canvas._writable(), rings, cols, opts, shade_opts(precision, 16),
                               opts.subpixel_bits, blend)


def fill_polygon_gouraud_aa(canvas, rings, colors, aa, rule, subpixel_bits, sample_offset, precision, blend,
                            entry, binary_only):
    """The anti-aliased Gouraud polygon (rast_fill_polygon_gouraud_aa, or
    with `blend` a ``rast_blend_opts *`` rast_fill_polygon_gouraud_aa_blend)
    of `rings` with the checked RGBA `colors` (uint8 (N, 4), one per vertex
    of the rings in order); `binary_only` as _coverage.aa_opts takes it.
    Everything is checked before the one C call, which checks again and
    writes nothing on an error."""
    from . import _coverage

    opts = _coverage.aa_opts(aa, rule, subpixel_bits, sample_offset, entry, binary_only)
    if not isinstance(precision, str) or precision not in ("exact", "flat"):
        raise InputError("%s: aa=%r shades with precision \"exact\" (or shading=\"flat\"), not %r; "
                         "precision=\"fixed\" is for binary fills (aa=None)" % (entry, aa, precision))
    pts, sizes, nrings = _coverage._points(rings)
    if colors.shape != (len(pts), 4):
        raise InputError("vertex_colors: %s for %s" % (_core.plural(colors.shape[0], "colour"),
                                                        _core.plural(len(pts), "vertex", "vertices")))
    if not nrings:
        return
    result = _coverage._lent(lib.rastpy_fill_polygon_gouraud_aa, canvas._writable(), ffi.from_buffer("double[]", pts),
                             len(pts), sizes, nrings, ffi.from_buffer("uint8_t[]", colors), opts,
                             shade_opts(precision, 16), ffi.NULL if blend is None else blend)
    if result:
        _coverage._check(result, pts, opts, "rings", [len(pts)] if nrings == 1 else sizes)

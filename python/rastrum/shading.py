"""Gouraud rectangles and the colour checks behind ``Canvas.fill_rect_gouraud``.

Thin like the rest: check the arguments, snap the corners, one C call.
"""

import numpy as np

from . import _core
from . import triangles as _triangles
from .shade import shade_opts, to_rgba
from ._core import InputError
from ._native import ffi, lib
from .canvas import _CHANNELS

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
                      sample_offset):
    r = rect_corners(rect)
    if not isinstance(method, str) or method not in RECT_METHODS:
        raise InputError("unknown method %r; choose one of: %s" % (method, ", ".join(RECT_METHODS)))
    cols = colors_rgba(corner_colors, 4, canvas.format, "corner_colors")
    x0, y0, x1, y1 = r
    if method == "triangles":
        # The diagonal from corner 0 (x0, y0) to corner 2 (x1, y1).
        quad = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        split = [(0, 1, 2), (0, 2, 3)]
        tris = quad[split]
        vc = cols[split]
        canvas.fill_triangles(tris, vertex_colors=vc, precision=precision, fraction_bits=fraction_bits,
                              subpixel_bits=subpixel_bits, sample_offset=sample_offset)
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
    _core._check(lib.rast_fill_rect_gouraud(canvas._writable(), p0[0], p1[0],
                                            ffi.from_buffer("uint8_t[]", cols), opts, sh))


def fill_polygon_gouraud(canvas, rings, vertex_colors, opts, precision):
    if isinstance(vertex_colors, (list, tuple)) and vertex_colors and np.ndim(vertex_colors[0]) == 2:
        vertex_colors = np.concatenate([np.asarray(v) for v in vertex_colors])
    vc = np.asarray(vertex_colors)
    n = vc.shape[0] if vc.ndim >= 1 else -1
    cols = colors_rgba(vc, n, canvas.format, "vertex_colors")
    _core.fill_polygon_gouraud(canvas._writable(), rings, cols, opts, shade_opts(precision, 16),
                               opts.subpixel_bits)

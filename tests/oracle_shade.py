"""Exact reference for shaded triangles (Gouraud, flat, depth), written from
the specification (rastrum.h, "shaded triangles") with fractions only.

Which pixels a triangle owns comes from the coverage oracles (oracle.py,
oracle_boundary.py); what each owned pixel gets is computed here, per
sample, as the barycentric interpolation of the snapped vertices at the
sample point (i + o, j + o):

    w0 = area(p, v1, v2), w1 = area(v0, p, v2), w2 = area(v0, v1, p),
    v  = (w0 c0 + w1 c1 + w2 c2) / (w0 + w1 + w2),   pixel = floor(v + 1/2),

clamped to 0..255 (depth: to int32).  A degenerate triangle takes vertex
0's values.  Depth: a pixel is written iff its depth is < the buffer's,
which then takes it.  Triangles are painted in order.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from oracle import oracle_mask, snap

INT32_MIN, INT32_MAX = -(2 ** 31), 2 ** 31 - 1


def _area(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _round(v: Fraction) -> int:
    return math.floor(v + Fraction(1, 2))


def owned(tri, shape, S, o, rounding="exact", boundary="exact"):
    """The bool mask of the pixels the triangle's fill owns."""
    ring = [list(map(tuple, tri))]
    if boundary == "exact":
        return oracle_mask(ring, shape, rule="evenodd", subpixel_bits=S, sample_offset=o,
                           rounding=rounding)
    from oracle_boundary import ORACLES
    return ORACLES[boundary](ring, shape, subpixel_bits=S, sample_offset=o,
                             rounding=rounding) > 0


def interpolate(tri, values, p, S):
    """The exact rational value at point p (pixels, Fractions) of the
    quantity with `values` at the snapped vertices of `tri`."""
    g = 1 << S
    v = [(Fraction(snap(x, S), g), Fraction(snap(y, S), g)) for x, y in tri]
    a = _area(v[0], v[1], v[2])
    if a == 0:
        return Fraction(values[0])
    w = (_area(p, v[1], v[2]), _area(v[0], p, v[2]), _area(v[0], v[1], p))
    return sum(wk * int(ck) for wk, ck in zip(w, values)) / a


def shade(tris, colors, shape, *, subpixel_bits=8, sample_offset=0.5, rounding="exact",
          boundary="exact", depth=None, precision="exact", zbuf=None):
    """Paint the batch: (rgba, zbuf).  rgba is (H, W, 4) int64, -1 where no
    triangle wrote; colors is (N, 3, 4) ints; depth (N, 3) ints or None;
    precision "exact" or "flat".  zbuf (H, W) ints to start from (default
    INT32_MAX everywhere) is updated in place when given."""
    H, W = shape
    S, o = subpixel_bits, Fraction(sample_offset)
    out = np.full((H, W, 4), -1, np.int64)
    if depth is not None and zbuf is None:
        zbuf = np.full((H, W), INT32_MAX, np.int64)
    for k, tri in enumerate(tris):
        mask = owned(tri, shape, S, sample_offset, rounding, boundary)
        for j, i in np.argwhere(mask):
            p = (i + o, j + o)
            if depth is not None:
                z = min(max(_round(interpolate(tri, depth[k], p, S)), INT32_MIN), INT32_MAX)
                if not z < zbuf[j, i]:
                    continue
                zbuf[j, i] = z
            for c in range(4):
                if precision == "flat":
                    out[j, i, c] = int(colors[k][0][c])
                else:
                    vals = [colors[k][m][c] for m in range(3)]
                    out[j, i, c] = min(max(_round(interpolate(tri, vals, p, S)), 0), 255)
    return out, zbuf


def pack(rgba, fmt):
    """Expected pixels of `fmt` for an (H, W, 4) colour array (no -1)."""
    r, g, b = rgba[..., 0], rgba[..., 1], rgba[..., 2]
    if fmt == "gray8":
        return r.astype(np.uint8)
    if fmt == "mono1":
        return (r >= 128).astype(np.uint8)
    if fmt == "rgb888":
        return rgba[..., :3].astype(np.uint8)
    if fmt == "rgba8888":
        return rgba.astype(np.uint8)
    if fmt == "rgb565":
        return (((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3)).astype(np.uint16)
    raise ValueError(fmt)

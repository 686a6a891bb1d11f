"""References for rastrum.rasterize, written from the documented rules
(docs/gis.md), sharing no code with python/rastrum/gis.py or _burn.py.

* ``pixel_coordinates``: GDAL's inverse geotransform (GDALInvGeoTransform,
  north-up special case included) applied in float64 to world (x, y);
* ``burn_reference``: the shapes burnt in order, each polygon by the exact
  rule on those float64 coordinates (tests/oracle.py with
  ``subpixel_bits=None``: exact rationals, no snapping), all_touched by
  tests/oracle_boundary.py's conservative reference, lines by a literal
  transcription of GDAL's integer Bresenham loop (GDALdllImageLine, with
  GDAL 3.10's tie rule), points by floor; merge "add" on Python numbers
  with saturation (integers) or the dtype's float addition.
"""

from __future__ import annotations

import math

import numpy as np

from oracle import oracle_mask
from oracle_boundary import oracle_conservative


def inverse(t):
    a, b, c, d, e, f = t
    if b == 0.0 and d == 0.0 and a != 0.0 and e != 0.0:
        return (-c / a, 1.0 / a, 0.0, -f / e, 0.0, 1.0 / e)
    det = a * e - b * d
    inv = 1.0 / det
    return ((b * f - c * e) * inv, e * inv, -b * inv, (-a * f + c * d) * inv, -d * inv, a * inv)


def pixel_coordinates(xy, t):
    g = inverse(t)
    out = []
    for x, y in xy:
        out.append((g[0] + x * g[1] + y * g[2], g[3] + x * g[4] + y * g[5]))
    return np.array(out, dtype=np.float64).reshape(-1, 2)


def gdal_line(points, h, w):
    """GDALdllImageLine for one line of float pixel coordinates, as a list
    of (row, col) burnt (repeats kept), transcribed as a loop: integer
    Bresenham from floor(p0) to floor(p1); the error term steps the minor
    axis when it is >= 0 (GDAL 3.10: a half goes towards the end); the end
    pixel only for the last segment."""
    out = []
    n = len(points)
    for j in range(1, n):
        p = [math.floor(points[j - 1][0]), math.floor(points[j - 1][1])]
        end = [math.floor(points[j][0]), math.floor(points[j][1])]
        d = [abs(end[0] - p[0]), abs(end[1] - p[1])]
        step = [-1 if p[i] > end[i] else 1 for i in (0, 1)]
        major = 0 if d[0] >= d[1] else 1  # x when |dx| >= |dy|
        minor = 1 - major
        err = 2 * d[minor] - d[major]
        for _ in range(d[major] + (j == n - 1)):
            if 0 <= p[0] < w and 0 <= p[1] < h:
                out.append((p[1], p[0]))
            p[major] += step[major]
            if err >= 0:
                p[minor] += step[minor]
                err -= 2 * d[major]
            err += 2 * d[minor]
    return out


def add(old, v, dtype):
    dt = np.dtype(dtype)
    if dt.kind == "f":
        return (np.array([old], dt) + np.array([v], dt))[0]
    info = np.iinfo(dt)
    return min(max(int(old) + int(v), info.min), info.max)


def parts(geom):
    """(kind, [rings or line or points]) of a GeoJSON-like mapping, in
    rasterio's order: multi-polygons and collections part by part."""
    t = geom["type"]
    c = geom.get("coordinates")
    if t == "Polygon":
        return [("polygon", [list(r) for r in c])]
    if t == "MultiPolygon":
        return [("polygon", [list(r) for r in p]) for p in c]
    if t == "LineString":
        return [("line", [list(c)])]
    if t == "MultiLineString":
        return [("line", [list(l) for l in c])]
    if t == "Point":
        return [("points", [[c]])]
    if t == "MultiPoint":
        return [("points", [list(c)])]
    if t == "GeometryCollection":
        return [p for g in geom["geometries"] for p in parts(g)]
    raise ValueError(t)


def burn_reference(shapes, shape, transform, dtype, *, fill=0, merge="replace", all_touched=False,
                   rule="evenodd"):
    """The raster rasterize must give for `shapes` ((GeoJSON mapping, value) pairs)."""
    h, w = shape
    out = np.full(shape, fill, dtype)

    def put(pixels, value):
        for r, c in pixels:
            out[r, c] = value if merge == "replace" else add(out[r, c], value, dtype)

    for geom, value in shapes:
        for kind, rings in parts(geom):
            px = [pixel_coordinates(r, transform) for r in rings]
            if kind == "polygon" or (kind == "line" and all_touched):
                if kind == "line":  # there and back: zero area, its edges
                    px = [np.concatenate([p, p[-2:0:-1]]) if len(p) > 2 else np.concatenate([p, p[:1]])
                          for p in px]
                if all_touched:
                    m = np.zeros(shape, bool)
                    for p in px if kind == "line" else [None]:
                        m |= oracle_conservative([p] if kind == "line" else px, shape, rule=rule,
                                                 subpixel_bits=None)
                else:
                    m = oracle_mask(px, shape, rule=rule, subpixel_bits=None)
                put(list(zip(*np.nonzero(m))), value)
            elif kind == "line":
                pix = [rc for p in px for rc in gdal_line(p.tolist(), h, w)]
                if merge == "add":
                    pix = sorted(set(pix))
                put(pix, value)
            else:
                for x, y in px[0].tolist():
                    c, r = math.floor(x), math.floor(y)
                    if 0 <= c < w and 0 <= r < h:
                        put([(r, c)], value)
    return out


"""The burning engine behind rastrum.rasterize (private).

``burn`` takes the parts of the shapes in order (polygons, lines, points)
in float64 pixel coordinates and burns them into a 2-D numpy array.
Polygons go to the C fillers; lines and points follow GDAL's rules
(llrasterize.cpp), computed here in integers with numpy:

* a point burns the pixel (floor(x), floor(y)) that contains it;
* a line burns, for each segment, the Bresenham line between the pixels
  (floor(x0), floor(y0)) and (floor(x1), floor(y1)) that GDAL's
  GDALdllImageLine draws: along the major axis (x when |dx| >= |dy|) one
  pixel per step, the minor coordinate at step k being
  floor((2k*dminor + dmajor) / (2dmajor)) (k*dminor/dmajor rounded, a half
  going towards the segment's end: measured against GDAL 3.10 through
  rasterio 1.4), the end pixel of a segment left out unless it is the
  line's last; in "add" a line (or MultiLineString) burns each pixel
  once, a MultiPoint each point (GDAL keeps a set of the pixels a line
  geometry has burnt);
* with all_touched, a line is the zero-area ring that walks it there and
  back, filled in the conservative boundary mode: every pixel whose open
  square the line meets.
"""

from __future__ import annotations

import numpy as np

from . import _core
from ._native import ffi, lib

#: Subpixel bits of rasterize's polygons: the 64-bit path at its finest,
#: so that vertices snap to 2^-32 px (an error of at most 2^-33 px).
SUBPIXEL_BITS = lib.RAST_MAX_SUBPIXEL_BITS64

#: Largest |pixel coordinate| rasterize accepts: the 64-bit path holds
#: +-2^28 px at every S.
COORD_LIMIT = float(2 ** lib.RAST_COORD64_PIXEL_BITS - 1)

_MERGES = {"replace": lib.RASTPY_MERGE_REPLACE, "add": lib.RASTPY_MERGE_ADD_SAT}
_DTYPES = {
    "uint8": lib.RASTPY_DT_U8, "int8": lib.RASTPY_DT_I8, "uint16": lib.RASTPY_DT_U16,
    "int16": lib.RASTPY_DT_I16, "uint32": lib.RASTPY_DT_U32, "int32": lib.RASTPY_DT_I32,
    "int64": lib.RASTPY_DT_I64, "float32": lib.RASTPY_DT_F32, "float64": lib.RASTPY_DT_F64,
}

_KIND_POLYGON, _KIND_LINE, _KIND_POINT = 0, 1, 2


# ---- merging ------------------------------------------------------------------------

def _add(cur, v, dt):
    """cur + v in dtype dt, as the glue's RASTPY_MERGE_ADD_SAT: integers
    saturate at the dtype's limits (exactly), floats add in the dtype (v
    rounded to it first)."""
    if dt.kind == "f":
        return cur + dt.type(v)
    info = np.iinfo(dt)
    if dt.itemsize < 8:
        return np.clip(cur.astype(np.int64) + v, info.min, info.max).astype(dt)
    if v >= 0:
        return np.where(cur > info.max - v, info.max, cur + np.int64(v))
    return np.where(cur < info.min - v, info.min, cur + np.int64(v))


def burn_pixels(target, rows, cols, v, merge):
    """Burn value v at (rows, cols) (in range; repeats count for "add")."""
    if not len(rows):
        return
    if merge == "replace":
        target[rows, cols] = v
        return
    h, w = target.shape
    flat, counts = np.unique(rows.astype(np.int64) * w + cols, return_counts=True)
    r, c = flat // w, flat % w
    vals = target[r, c]
    for k in range(int(counts.max())):
        sel = counts > k
        vals[sel] = _add(vals[sel], v, target.dtype)
    target[r, c] = vals


def _burn_mask(sub, m, v, merge):
    if merge == "replace":
        sub[m] = v
    else:
        sub[m] = _add(sub[m], v, sub.dtype)


# ---- lines and points (GDAL's rules) ----------------------------------------------------

def gdal_line_pixels(px, h, w):
    """The pixels GDALdllImageLine burns for one line (an (N, 2) float64
    array of pixel coordinates, N >= 2), inside (h, w), as (rows, cols);
    a pixel may repeat (a line crossing itself)."""
    ij = np.floor(px).astype(np.int64)
    x0, y0 = ij[:-1, 0], ij[:-1, 1]
    x1, y1 = ij[1:, 0], ij[1:, 1]
    last = np.zeros(len(x0), np.int64)
    last[-1] = 1
    dx, dy = np.abs(x1 - x0), np.abs(y1 - y0)
    xmaj = dx >= dy
    dmaj = np.where(xmaj, dx, dy)
    dmin = np.where(xmaj, dy, dx)
    m0 = np.where(xmaj, x0, y0)
    n0 = np.where(xmaj, y0, x0)
    smaj = np.where(xmaj, np.where(x0 > x1, -1, 1), np.where(y0 > y1, -1, 1))
    smin = np.where(xmaj, np.where(y0 > y1, -1, 1), np.where(x0 > x1, -1, 1))
    count = dmaj + last
    dim = np.where(xmaj, w, h)
    # Only the steps whose major coordinate lies in the raster: at most
    # the raster's side per segment, however long the segment.
    k0 = np.where(smaj > 0, np.maximum(0, -m0), np.maximum(0, m0 - dim + 1))
    k1 = np.where(smaj > 0, np.minimum(count, dim - m0), np.minimum(count, m0 + 1))
    n = np.maximum(k1 - k0, 0)
    total = int(n.sum())
    if not total:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    seg = np.repeat(np.arange(len(n)), n)
    start = np.cumsum(n) - n
    k = np.arange(total, dtype=np.int64) - start[seg] + k0[seg]
    a, b = dmaj[seg], dmin[seg]
    off = (2 * k * b + a) // np.maximum(2 * a, 1)
    major = m0[seg] + smaj[seg] * k
    minor = n0[seg] + smin[seg] * off
    xm = xmaj[seg]
    cols = np.where(xm, major, minor)
    rows = np.where(xm, minor, major)
    keep = (cols >= 0) & (cols < w) & (rows >= 0) & (rows < h)
    return rows[keep], cols[keep]


def point_pixels(px, h, w):
    ij = np.floor(px).astype(np.int64)
    keep = (ij[:, 0] >= 0) & (ij[:, 0] < w) & (ij[:, 1] >= 0) & (ij[:, 1] < h)
    return ij[keep, 1], ij[keep, 0]


# ---- polygons --------------------------------------------------------------------------------

def _polygons(target, px, ring_sizes, part_rings, values, merge, boundary, rule):
    """Polygon parts through rastpy_burn_polygons64 in one C call."""
    opts = _core.fill_opts("aet", rule, SUBPIXEL_BITS, 0.5, "exact", boundary)
    h, w = target.shape
    xy = np.ascontiguousarray(px)
    sizes = np.ascontiguousarray(ring_sizes, np.uint32)
    prings = np.ascontiguousarray(part_rings, np.uint32)
    v = np.ascontiguousarray(values, dtype=target.dtype)
    failed = ffi.new("uint32_t *")
    result = lib.rastpy_burn_polygons64(
        ffi.cast("void *", target.__array_interface__["data"][0]), h, w,
        target.strides[0], 0, _DTYPES[target.dtype.name], _MERGES[merge], ffi.from_buffer(v),
        ffi.from_buffer("double[]", xy), len(xy), ffi.from_buffer("uint32_t[]", sizes), len(sizes),
        ffi.from_buffer("uint32_t[]", prings), len(prings), opts, failed)
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for a batch of %d polygons" % len(prings))
    if result > 0:  # checked before: cannot happen
        raise _core.RastrumError("rastrum: point %d of a checked batch refused" % (result - 1))
    _core._check(result)


def burn(target, px, ring_sizes, part_rings, kind, values, feature, geom, merge, all_touched, rule,
         progress):
    """Burn every part in order (see the module's docstring).  feature: the
    index in shapes of each part (for progress); geom: the geometry it
    belongs to (a collection's members are geometries of their own)."""
    if not (target.flags.aligned and target.strides[1] == target.itemsize and target.strides[0] > 0):
        work = np.ascontiguousarray(target)  # a transposed or reversed view: burn a copy
        burn(work, px, ring_sizes, part_rings, kind, values, feature, geom, merge, all_touched, rule,
             progress)
        target[...] = work
        return
    h, w = target.shape
    if all_touched and len(kind):
        # The lines of one geometry become one part (one zero-area ring
        # each): "add" then burns a pixel once per geometry, as GDAL does.
        line = kind == _KIND_LINE
        same = np.zeros(len(kind), bool)
        same[1:] = line[1:] & line[:-1] & (geom[1:] == geom[:-1])
        if same.any():
            keep = ~same
            group = np.cumsum(keep) - 1
            part_rings = np.bincount(group, weights=part_rings).astype(np.int64)
            kind, feature, geom = kind[keep], feature[keep], geom[keep]
            values = values[keep]
    n = len(part_rings)
    ring_start = np.concatenate([[0], np.cumsum(part_rings)])
    pt_start = np.concatenate([[0], np.cumsum(ring_sizes)])
    boundary = "conservative" if all_touched else "exact"
    # Lines under all_touched are zero-area polygons: there and back.
    polyish = (kind == _KIND_POLYGON) | ((kind == _KIND_LINE) & all_touched)
    p = 0
    chunk = max(1024, n // 50) if progress.active else n
    while p < n:
        q = p
        if polyish[p]:
            while q < n and polyish[q] and q - p < chunk:
                q += 1
            r0, r1 = ring_start[p], ring_start[q]
            sub_px = px[pt_start[r0]:pt_start[r1]]
            sub_sizes = ring_sizes[r0:r1]
            sub_rings = part_rings[p:q]
            if all_touched and (kind[p:q] == _KIND_LINE).any():
                sub_px, sub_sizes = _there_and_back(sub_px, sub_sizes, kind[p:q], sub_rings)
            _polygons(target, sub_px, sub_sizes, sub_rings, values[p:q], merge, boundary, rule)
        else:
            # One geometry's lines (a MultiLineString) or points together:
            # in "add", GDAL burns a line's pixel once per geometry, a
            # point each time.
            while q < n and kind[q] == kind[p] and geom[q] == geom[p]:
                q += 1
            rows, cols = [], []
            for part in range(p, q):
                a, b = pt_start[ring_start[part]], pt_start[ring_start[part + 1]]
                rc = (point_pixels if kind[p] == _KIND_POINT else gdal_line_pixels)(px[a:b], h, w)
                rows.append(rc[0])
                cols.append(rc[1])
            rows, cols = np.concatenate(rows), np.concatenate(cols)
            if kind[p] == _KIND_LINE and merge == "add" and len(rows):
                flat = np.unique(rows * w + cols)
                rows, cols = flat // w, flat % w
            burn_pixels(target, rows, cols, values[p], merge)
        p = q
        progress(int(feature[q - 1]) + 1 if q < n else progress.total)


def _there_and_back(px, sizes, kinds, part_rings):
    """Each line's ring (one per line part) replaced by the line walked
    there and back (p0 .. pn-1 .. p1): zero area, its edges twice."""
    out, out_sizes = [], []
    starts = np.concatenate([[0], np.cumsum(sizes)])
    ring = 0
    for k, nr in zip(kinds.tolist(), part_rings.tolist()):
        for r in range(ring, ring + nr):
            seg = px[starts[r]:starts[r + 1]]
            if k == _KIND_LINE:
                seg = np.concatenate([seg, seg[-2:0:-1]]) if len(seg) > 2 else np.concatenate([seg, seg[:1]])
            out.append(seg)
            out_sizes.append(len(seg))
        ring += nr
    return np.concatenate(out), np.asarray(out_sizes, np.int64)

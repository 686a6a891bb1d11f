"""The burning engine behind rastrum.rasterize (private).

``burn`` takes the parts of the shapes in order (polygons, lines, points)
in float64 pixel coordinates and burns them into a 2-D numpy array.
Polygons go to the C fillers (rastpy_burn_polygons64); lines and points
follow GDAL's rules (llrasterize.cpp), walked in integers by
python/glue/gdalline.c and written by rastpy_burn_gdal_lines:

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
    "int64": lib.RASTPY_DT_I64, "uint64": lib.RASTPY_DT_U64, "float32": lib.RASTPY_DT_F32, "float64": lib.RASTPY_DT_F64,
}

_KIND_POLYGON, _KIND_LINE, _KIND_POINT = 0, 1, 2


# ---- polygons --------------------------------------------------------------------------------

def _polygons(target, px, ring_sizes, part_rings, values, merge, boundary, rule, origin=(0, 0)):
    """Polygon parts through rastpy_burn_polygons64 in one C call; target
    is the window of the plane whose pixel (0, 0) is the plane's pixel
    origin = (row, column), and the window is the clip (the same pixels
    as burning the whole plane)."""
    opts = _core.fill_opts("aet", rule, SUBPIXEL_BITS, 0.5, "exact", boundary)
    h, w = target.shape
    # aligned too: an array unpickled from a dask.distributed message may not be (C reads doubles)
    xy = np.require(px, np.float64, ["C", "A"])
    sizes = np.ascontiguousarray(ring_sizes, np.uint32)
    prings = np.ascontiguousarray(part_rings, np.uint32)
    v = np.ascontiguousarray(values, dtype=target.dtype)
    failed = ffi.new("uint32_t *")
    result = lib.rastpy_burn_polygons64_at(
        ffi.cast("void *", target.__array_interface__["data"][0]), origin[0], origin[1], h, w,
        target.strides[0], _DTYPES[target.dtype.name], _MERGES[merge], ffi.from_buffer(v),
        ffi.from_buffer("double[]", xy), len(xy), ffi.from_buffer("uint32_t[]", sizes), len(sizes),
        ffi.from_buffer("uint32_t[]", prings), len(prings), opts, failed)
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for a batch of %d polygons" % len(prings))
    if result > 0:  # checked before: cannot happen
        raise _core.RastrumError("rastrum: point %d of a checked batch refused" % (result - 1))
    _core._check(result)


def burn(target, px, ring_sizes, part_rings, kind, values, feature, geom, merge, all_touched, rule,
         progress, origin=(0, 0), _fresh=False):
    """Burn every part in order (see the module's docstring).  feature: the
    index in shapes of each part (for progress); geom: the geometry it
    belongs to (a collection's members are geometries of their own).
    origin: the (row, column) of target's pixel (0, 0) in the pixel
    coordinates of px: target is that window of the whole raster, burnt
    with exactly the whole raster's pixels (rastrum.dask)."""
    if not _fresh and (progress.active or not (target.flags.aligned and target.strides[1] == target.itemsize
                                               and target.strides[0] > 0)):
        # A transposed, reversed or misaligned view: burn a fresh (aligned,
        # C-ordered) copy; np.ascontiguousarray would hand back a misaligned
        # C-contiguous array itself.  With a progress callback too, so that
        # `out` changes only after the last callback (a raising callback
        # leaves it untouched, docs/bad-input.md).
        work = np.empty(target.shape, target.dtype)
        work[...] = target
        burn(work, px, ring_sizes, part_rings, kind, values, feature, geom, merge, all_touched, rule,
             progress, origin, True)
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
            _polygons(target, sub_px, sub_sizes, sub_rings, values[p:q], merge, boundary, rule, origin)
        else:
            while q < n and not polyish[q] and q - p < chunk:
                q += 1
            _lines_points(target, px, pt_start, ring_start, kind, values, geom, p, q, merge, origin)
        p = q
        progress(int(feature[q - 1]) + 1 if q < n else progress.total)


# ---- lines and points (GDAL's rules, python/glue/gdalline.c) ---------------------------

def _lines_points(target, px, pt_start, ring_start, kind, values, geom, p, q, merge, origin=(0, 0)):
    """Parts p..q-1 (lines and points) in one go: their pixels in order,
    each with its part's value; in "add" a line geometry (a LineString, or
    the lines of a MultiLineString) burns each pixel once, a point each
    time, as GDAL does.  A window at origin (row, column): the walk is on
    the pixels (floors) less the origin, integers, so it steps through the
    same pixels as on the whole raster and keeps those in the window."""
    h, w = target.shape
    a = pt_start[ring_start[p]]
    sub = px[a:pt_start[ring_start[q]]]
    sizes = pt_start[ring_start[p + 1:q + 1]] - pt_start[ring_start[p:q]]
    part_of = np.repeat(np.arange(p, q), sizes)  # the part of every position
    is_line = kind[part_of] == _KIND_LINE
    ends = np.cumsum(sizes) - 1  # the last position of each part
    last = np.where(is_line, 0, -1)
    last[ends] = -1
    last[ends[kind[p:q] == _KIND_LINE] - 1] = 1
    # Straight into the raster in C, in order: a point is a one-pixel last
    # segment (from itself to itself).
    rep = np.where(is_line, 1, 2)
    first = np.cumsum(rep) - rep
    last2 = np.repeat(last, rep).astype(np.int8)
    last2[first[~is_line]] = 1
    ij = np.ascontiguousarray(np.floor(np.repeat(sub, rep, axis=0)), dtype=np.int64)
    if origin != (0, 0):
        ij -= np.array([origin[1], origin[0]], np.int64)
    part = np.ascontiguousarray(np.repeat(part_of - p, rep), dtype=np.uint32)
    vals = np.ascontiguousarray(values[p:q], dtype=target.dtype)
    if merge == "add" and is_line.any():
        # a line geometry burns a pixel once; each point is a geometry
        g = np.where(kind[part_of] == _KIND_LINE, geom[part_of] - geom[p], 0)
        g = np.where(is_line, g, -1 - np.arange(len(g)))  # points: each its own
        g = np.ascontiguousarray(np.repeat(g, rep).astype(np.uint32))
        geom_arg = ffi.from_buffer("uint32_t[]", g)
    else:
        geom_arg = ffi.NULL
    result = lib.rastpy_burn_gdal_lines(
        ffi.cast("void *", target.__array_interface__["data"][0]), h, w, target.strides[0],
        _DTYPES[target.dtype.name], _MERGES[merge], ffi.from_buffer(vals),
        ffi.from_buffer("int64_t[]", ij), ffi.from_buffer("int8_t[]", last2),
        ffi.from_buffer("uint32_t[]", part), geom_arg, len(ij))
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for the pixels of a line")
    _core._check(result)


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

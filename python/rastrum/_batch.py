"""Many polygons, each with its value, into one array in one C call.

The engine behind the batched Python names (``rasterize``, ``masks``,
``labels``): the rings of every polygon are concatenated into one float64
array, and ``rastpy_burn_polygons`` (python/glue/batch.c) snaps them and
draws the whole batch through the core's ``rast_fill_polygons_spans``, each
polygon once, in order, writing its value into the array's own dtype.
Nothing is written unless every polygon is good.
"""

from typing import Any, Iterator, List, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from ._core import InputError, _check, bad_point_message, count_array, plural, real_array, use_wide
from ._native import ffi, lib

#: numpy dtype -> the glue's element type code.
DTYPES = {
    np.dtype(np.bool_): lib.RASTPY_DT_U8,
    np.dtype(np.uint8): lib.RASTPY_DT_U8,
    np.dtype(np.int8): lib.RASTPY_DT_I8,
    np.dtype(np.uint16): lib.RASTPY_DT_U16,
    np.dtype(np.int16): lib.RASTPY_DT_I16,
    np.dtype(np.uint32): lib.RASTPY_DT_U32,
    np.dtype(np.int32): lib.RASTPY_DT_I32,
    np.dtype(np.int64): lib.RASTPY_DT_I64,
    np.dtype(np.uint64): lib.RASTPY_DT_U64,
    np.dtype(np.float32): lib.RASTPY_DT_F32,
    np.dtype(np.float64): lib.RASTPY_DT_F64,
}

MERGES = {"replace": lib.RASTPY_MERGE_REPLACE, "add": lib.RASTPY_MERGE_ADD, "fresh": lib.RASTPY_MERGE_FRESH}


def pack(polygons):
    """(points float64 (P, 2), ring sizes uint32 (R,), rings per polygon
    uint32 (N,)) of a list of polygons, each a list of C-contiguous float64
    (N, 2) rings."""
    rings = [r for poly in polygons for r in poly]
    poly_rings = np.fromiter(map(len, polygons), np.uint32, len(polygons))
    sizes = np.fromiter(map(len, rings), np.uint32, len(rings))
    pts = np.concatenate(rings) if rings else np.zeros((0, 2))
    return pts, sizes, poly_rings


class Polygons:
    """A batch of polygons already packed for the C call (what
    ``rastrum.coco.polygons`` returns): ``rastrum.masks`` and
    ``rastrum.labels`` draw it without converting or copying anything.
    ``Polygons(points, ring_sizes, rings_per_polygon)`` makes one from the
    tables below (checked: they must agree; rings of at least one point).

    It is a read-only sequence: ``len(b)`` polygons, ``b[k]`` polygon k as a
    list of float64 (N, 2) rings (views of the batch's points), iteration in
    order.  Attributes: ``points`` (P, 2) float64, ``ring_sizes`` (R,)
    uint32, ``rings_per_polygon`` (N,) uint32, each ring a part (parts are
    united by ``rule="union"``).
    """

    __slots__ = ("points", "ring_sizes", "rings_per_polygon", "_ends", "_first")

    def __init__(self, points: npt.ArrayLike, ring_sizes: npt.ArrayLike, rings_per_polygon: npt.ArrayLike) -> None:
        # views: read-only below without touching the caller's arrays
        # one check where the tables enter: real numbers, int counts
        points = real_array(points, "Polygons: points", "a (P, 2) array-like").view()
        sizes = count_array(ring_sizes, "Polygons: ring_sizes").view()
        counts = count_array(rings_per_polygon, "Polygons: rings_per_polygon").view()
        if points.ndim != 2 or points.shape[1] != 2 or sizes.ndim != 1 or counts.ndim != 1:
            raise InputError("Polygons: points must be (P, 2), ring_sizes and rings_per_polygon 1-D; got "
                             "shapes %s, %s, %s" % (points.shape, sizes.shape, counts.shape))
        if not sizes.all() or sizes.sum(dtype=np.int64) != len(points) or \
                counts.sum(dtype=np.int64) != len(sizes):
            raise InputError("Polygons: the tables disagree: %s, ring sizes summing to %d (each >= 1), "
                             "%s, rings per polygon summing to %d"
                             % (plural(len(points), "point"), sizes.sum(dtype=np.int64), plural(len(sizes), "ring"),
                                counts.sum(dtype=np.int64)))
        for a in (points, sizes, counts):
            a.flags.writeable = False
        self.points, self.ring_sizes, self.rings_per_polygon = points, sizes, counts
        self._ends = np.cumsum(sizes, dtype=np.int64)
        self._first = np.concatenate(([0], np.cumsum(counts, dtype=np.int64)))

    def __len__(self) -> int:
        return len(self.rings_per_polygon)

    @overload
    def __getitem__(self, k: int) -> List[npt.NDArray[np.float64]]: ...

    @overload
    def __getitem__(self, k: slice) -> List[List[npt.NDArray[np.float64]]]: ...

    def __getitem__(self, k: Union[int, slice]) -> Any:
        k = range(len(self))[k]  # IndexError, negative indices, slices
        if isinstance(k, range):
            return [self[i] for i in k]
        r0, r1 = int(self._first[k]), int(self._first[k + 1])
        ends = self._ends[r0:r1].tolist()
        starts = [int(self._ends[r0 - 1]) if r0 else 0] + ends[:-1]
        return [self.points[a:b] for a, b in zip(starts, ends)]

    def __iter__(self) -> Iterator[List[npt.NDArray[np.float64]]]:
        return (self[k] for k in range(len(self)))

    def __repr__(self) -> str:
        return "<rastrum polygons: %s, %s, %s>" % (
            plural(len(self), "polygon"), plural(len(self.ring_sizes), "ring"), plural(len(self.points), "point"))

    def packed(self) -> Tuple[Any, ...]:
        """(points, ring sizes, rings per polygon, orientation +1 per ring)."""
        return self.points, self.ring_sizes, self.rings_per_polygon, np.ones(len(self.ring_sizes), np.int8)


def burn(out, polygons, opts, values=None, merge="replace", planes=False, what="polygon", orient=None):
    """Burn `polygons` into `out` (numpy, native byte order, rows of
    contiguous elements, writable).

    polygons: a list; item k is a list of C-contiguous float64 (N, 2) rings
    (already checked by the caller; rings of fewer than 3 points enclose
    nothing).  values: None (1 everywhere) or a 1-D array of out.dtype, one
    per polygon.  merge: "replace", "add", or "fresh" (out uninitialised
    uint8 or bool (N, H, W), C-contiguous, planes, no values: every byte
    written, 1 inside polygon k in plane k, 0 elsewhere).  planes: out is (N, H, W) and
    polygon k goes into out[k]; else out is (H, W).  Errors name `what` and
    the polygon's index; out is untouched then.
    """
    return burn_packed(out, *pack(polygons), opts, values, merge, planes, what, orient)


def burn_packed(out, pts, sizes, poly_rings, opts, values=None, merge="replace", planes=False,
                what="polygon", orient=None, first=0):
    """`burn` of a batch already packed (see `pack`): pts a C-contiguous
    float64 (P, 2) array, sizes and poly_rings uint32.  Errors name polygon
    first + k for the batch's polygon k."""
    npolys = len(poly_rings)
    dt = DTYPES.get(out.dtype)
    if dt is None or not out.dtype.isnative:
        raise InputError("cannot burn into an array of dtype %s" % out.dtype)
    if not out.flags.writeable:
        raise InputError("the output array is read-only")
    if out.ndim != (3 if planes else 2):
        raise InputError("the output array must be %s, not shape %s"
                         % ("(N, H, W)" if planes else "(H, W)", out.shape))
    if planes and out.shape[0] != npolys:
        raise InputError("%s for %s" % (plural(npolys, what), plural(out.shape[0], "plane")))
    h, w = out.shape[-2:]
    if w > 1 and out.strides[-1] != out.itemsize:
        raise InputError("the output array's rows must be contiguous (strides %s)" % (out.strides,))
    if values is not None:
        values = np.ascontiguousarray(values, dtype=out.dtype)
        if values.shape != (npolys,):
            raise InputError("%s for %s" % (plural(values.size, "value"), plural(npolys, what)))
    if not npolys or not h or not w:
        return out
    failed = ffi.new("uint32_t *", 0xFFFFFFFF)
    # The 64-bit path (S up to 32, +-2**28 pixels) when S or the coordinates
    # need it: the same pixels where both apply (_core.use_wide).  Turning
    # rings (orient, rastrum.masks' union) is 32-bit only.
    args = (ffi.cast("void *", out.__array_interface__["data"][0]), h, w,
            out.strides[-2] if h > 1 else 0, out.strides[0] if planes and npolys > 1 else 0,
            dt, MERGES[merge], ffi.from_buffer(values) if values is not None else ffi.NULL,
            ffi.from_buffer("double[]", pts), len(pts), ffi.from_buffer("uint32_t[]", sizes),
            len(sizes), ffi.from_buffer("uint32_t[]", poly_rings), npolys, opts, failed)
    wide = orient is None and use_wide(opts, pts)
    if orient is None:
        result = (lib.rastpy_burn_polygons64 if wide else lib.rastpy_burn_polygons)(*args)
    else:
        result = lib.rastpy_burn_polygons_oriented(*args, ffi.from_buffer("int8_t[]", orient))
    if result == 0:
        return out
    if result > 0:
        k = result - 1
        ends = np.cumsum(sizes)
        ring = int(np.searchsorted(ends, k, side="right"))
        poly = int(np.searchsorted(np.cumsum(poly_rings), ring, side="right"))
        first_ring = int(poly_rings[:poly].sum())
        name = "%s %d" % (what, first + poly)
        raise InputError(bad_point_message(
            name, pts[ends[ring] - sizes[ring]:ends[ring]],
            int(k - (ends[ring] - sizes[ring])), opts.subpixel_bits,
            None, wide).replace(name + ": ", "%s: ring %d, " % (name, ring - first_ring)))
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum: no memory for a batch of %d %ss" % (npolys, what))
    if failed[0] != 0xFFFFFFFF:
        try:
            _check(result)
        except InputError as e:
            raise InputError("%s %d: %s" % (what, first + failed[0], e)) from None
    _check(result)

"""rastrum.dask: :func:`rasterize` as a lazy Dask array, equal to
:func:`rastrum.rasterize` pixel for pixel for any chunking.

Every block is burnt by the same C code as the whole raster, on the same
float64 pixel coordinates (the whole raster's inverse transform, snapped
to the same 1/2^32 pixel grid), with the block as the clip window: the
coordinates are never shifted by the block's offset (a float subtraction
would move the snapping), the C call is told where the block lies.  Lines
and points take the whole raster's pixel walk, shifted by the block's
offset in integers.  So a pixel is decided by the same rule on the same
numbers whichever block it falls in.

How the work is split (docs/dask.md):

* in-memory shapes (a list, a GeoSeries, a GeoDataFrame) are read and
  checked on the client, as rastrum.rasterize reads them; each block's task
  carries only the parts whose bounds meet the block (a vectorised bounds
  test against the chunk edges), in input order;
* a dask-geopandas GeoDataFrame or GeoSeries is never collected: one task
  per partition reads it (its parts and their bounds); for each block, a
  small task per partition takes the partition's parts that meet the
  block (on the worker that holds the partition), and the block's task
  burns them into the fill partition after partition.  Burning in order is
  exactly burning every shape in input order, so "replace" keeps the input
  order across partitions and "add" adds in the same order (saturation and
  float rounding included).  With the frame's spatial_partitions, only the
  partitions whose hulls meet the block take part.

A block's task holds its block and the parts that meet it, never the whole
raster or the whole layer; a dask-geopandas partition is held by its
reading task's result until the blocks have taken their parts.
"""

from __future__ import annotations

import numbers
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np

from . import _burn, _core, gis
from ._core import InputError
from .gis import IDENTITY

# The message when an optional library of rastrum.dask is missing.
_NEEDS_DASK = '%s needs dask: pip install "rastrum[dask]"'

__all__ = ["rasterize", "to_xarray", "zonal_stats"]


# ---- the parts of a layer, and which blocks they meet ------------------------------------------

def _ranges(starts, stops):
    """The concatenation of arange(starts[k], stops[k]) over k, vectorised."""
    lens = stops - starts
    total = int(lens.sum())
    if total == 0:
        return np.zeros(0, np.int64)
    offs = np.cumsum(lens) - lens
    return np.repeat(starts - offs, lens) + np.arange(total)


class _Parts:
    """Parts in burning order (as _burn.burn takes them): float64 pixel
    coordinates px, ring_sizes, part_rings, kind, value, feature, geometry."""

    __slots__ = ("px", "ring_sizes", "part_rings", "kind", "values", "feature", "geom")

    def __init__(self, px, ring_sizes, part_rings, kind, values, feature, geom):
        self.px, self.ring_sizes, self.part_rings = px, ring_sizes, part_rings
        self.kind, self.values, self.feature, self.geom = kind, values, feature, geom

    def __len__(self):
        return len(self.part_rings)

    def take(self, parts, ring_start, pt_start):
        """The parts of index `parts` (ascending), with their rings and
        points (ring_start, pt_start: where each part's rings and each
        ring's points begin, one more at the end)."""
        rings = _ranges(ring_start[parts], ring_start[parts + 1])
        points = _ranges(pt_start[rings], pt_start[rings + 1])
        return _Parts(self.px[points], self.ring_sizes[rings], self.part_rings[parts], self.kind[parts],
                      self.values[parts], self.feature[parts], self.geom[parts])


class _Layer:
    """Parts and the blocks each meets: a part meets the blocks that its
    bounds, floored and widened by one pixel, overlap.  A polygon's pixels
    (exact or all_touched), a line's and a point's lie within its floored
    bounds (snapping to the 1/2^32 grid never moves a vertex across a pixel
    edge, integers being on the grid); the extra pixel is slack that costs
    a few more shapes at block borders."""

    def __init__(self, parts, row_edges, col_edges):
        self.parts = parts
        n = len(parts)
        nbj = len(col_edges) - 1
        self.ring_start = np.concatenate([[0], np.cumsum(parts.part_rings)]).astype(np.int64)
        self.pt_start = np.concatenate([[0], np.cumsum(parts.ring_sizes)]).astype(np.int64)
        if n == 0:
            self.order = np.zeros(0, np.int64)
            self.start = np.zeros((len(row_edges) - 1) * nbj + 1, np.int64)
            return
        first = self.pt_start[self.ring_start[:-1]]
        lo = np.floor(np.minimum.reduceat(parts.px, first, axis=0)) - 1  # (col, row)
        hi = np.floor(np.maximum.reduceat(parts.px, first, axis=0)) + 1
        bi0, bi1, ok_i = self._span(lo[:, 1], hi[:, 1], row_edges)
        bj0, bj1, ok_j = self._span(lo[:, 0], hi[:, 0], col_edges)
        ok = ok_i & ok_j
        ncols = np.where(ok, bj1 - bj0 + 1, 0)
        counts = np.where(ok, bi1 - bi0 + 1, 0) * ncols
        part = np.repeat(np.arange(n), counts)
        t = np.arange(len(part)) - np.repeat(np.cumsum(counts) - counts, counts)
        block = (bi0[part] + t // ncols[part]) * nbj + bj0[part] + t % ncols[part]
        order = np.argsort(block, kind="stable")  # parts stay in input order within a block
        self.order = part[order]
        self.start = np.searchsorted(block[order], np.arange((len(row_edges) - 1) * nbj + 1))

    @staticmethod
    def _span(lo, hi, edges):
        """First and last block index of [lo, hi] (pixel indices, inclusive)
        along one axis, and whether it meets the raster at all."""
        ok = (hi >= 0) & (lo < edges[-1])
        b0 = np.clip(np.searchsorted(edges, lo, side="right") - 1, 0, len(edges) - 2)
        b1 = np.clip(np.searchsorted(edges, hi, side="right") - 1, 0, len(edges) - 2)
        return b0, b1, ok

    def block_parts(self, b):
        """The parts that meet block b (linear index), in input order."""
        return self.parts.take(self.order[self.start[b]:self.start[b + 1]], self.ring_start, self.pt_start)


# ---- tasks -------------------------------------------------------------------------------------

def _burn_block(shape, origin, fill, dt, merge, all_touched, rule, *subsets):
    """The block of `shape` at origin (row, column) of the whole raster: the
    fill, then each _Parts of `subsets` burnt in turn (a dask-geopandas
    frame: one per partition, in partition order)."""
    target = np.full(shape, fill, dt)
    if 0 in shape:
        return target
    for parts in subsets:
        if len(parts):  # each on its own: geometry numbers are a partition's own
            _burn.burn(target, parts.px, parts.ring_sizes, parts.part_rings, parts.kind, parts.values,
                       parts.feature, parts.geom, merge, all_touched, rule, gis._Progress(None, 0), origin)
    return target


def _by_feature(parts, nfeat):
    """The polygon parts of features 0..nfeat-1 as one part per feature
    (its rings together, as rasterize(coverage=) fills them), features
    without parts left out; each part's `feature` is its feature's number
    and `values` its value."""
    counts = np.bincount(parts.feature, minlength=nfeat)
    rings = np.bincount(parts.feature, parts.part_rings, minlength=nfeat).astype(np.int64)
    has = counts > 0
    ids = np.flatnonzero(has)
    first = (np.cumsum(counts) - counts)[ids]  # each feature's first part (parts are in feature order)
    return _Parts(parts.px, parts.ring_sizes, rings[has], parts.kind[first], parts.values[first], ids,
                  parts.geom[first])


def _coverage_block(shape, origin, full, fill, dt, merge, rule, method, *subsets):
    """The block of `shape` at origin (row, column) of a raster of shape
    `full`: the fill, then the coverage of each _Parts of `subsets` (one
    part a feature) merged in turn.  Each feature's fractions are those of
    its whole window in the whole raster (the same call on the same
    numbers as rastrum.rasterize makes), cut to the block."""
    target = np.full(shape, fill, dt)
    if 0 in shape:
        return target
    for parts in subsets:
        if len(parts):
            _merge_coverage(target, origin, full, parts, merge, rule, method)
    return target


def _merge_coverage(target, origin, full, parts, merge, rule, method):
    """rasterize(coverage=)'s merge (_fractions.burn_coverage) of the
    features of `parts` into the block `target` at `origin`."""
    from . import _fractions

    dt = target.dtype
    n = len(parts)
    f, cells, cov = _fractions.fractions(parts.px, parts.ring_sizes, parts.part_rings, np.arange(n), n, full,
                                         rule, None, method=method, dtype=np.float64 if dt.kind == "f" else dt)
    h, w = target.shape
    r0, c0 = origin
    rr, cc = np.divmod(cells, full[1])
    keep = (rr >= r0) & (rr < r0 + h) & (cc >= c0) & (cc < c0 + w)
    if not keep.any():
        return
    _fractions.merge_cells(target, f[keep], (rr[keep] - r0) * w + (cc[keep] - c0), cov[keep], parts.values,
                           merge)


def _block_parts(layer, b):
    return layer.block_parts(b)


def _read_partition(frame, p, values, default_value, fill, dt, inv, row_edges, col_edges, coverage=None):
    """Partition p of a dask-geopandas frame as a _Layer (its shapes read and
    checked as rastrum.rasterize reads them; with `coverage`, one part a
    feature)."""
    try:
        geoms, vals = gis._split_shapes(frame, default_value, fill, values)
        vals, xy, ring_sizes, part_rings, kind, feature, geom = _read(geoms, vals, dt, coverage)
        px = gis._pixels(xy, inv, ring_sizes, part_rings, feature)
    except InputError as e:
        raise InputError("partition %d: %s" % (p, e)) from None
    return _Layer(_layer_parts(px, ring_sizes, part_rings, kind, vals, feature, geom, len(geoms), coverage),
                  row_edges, col_edges)


def _read(geoms, vals, dt, coverage):
    """The values (per feature) and the flattened geometries, checked as
    rastrum.rasterize checks them (with coverage: polygons only, values
    that fit the fractions' dtype)."""
    if coverage is not None:
        from . import _fractions

        _fractions.check_values(vals, dt)
        vals = gis._values(vals, np.dtype(np.float64)) if dt.kind == "f" else np.zeros(len(vals))
    else:
        vals = gis._values(vals, dt)
    xy, ring_sizes, part_rings, kind, feature, geom = gis._flatten(geoms)
    if coverage is not None:
        from . import _fractions

        _fractions._polygons_only(kind, feature, "shapes")
    return vals, xy, ring_sizes, part_rings, kind, feature, geom


def _layer_parts(px, ring_sizes, part_rings, kind, vals, feature, geom, nfeat, coverage):
    parts = _Parts(px, ring_sizes, part_rings, kind, vals[feature], feature, geom)
    return parts if coverage is None else _by_feature(parts, nfeat)


def _partition_blocks(frame, inv, row_edges, col_edges):
    """Per partition, the set of blocks its shapes may meet, from the
    frame's spatial_partitions (dask-geopandas: a hull per partition, set
    by calculate_spatial_partitions or spatial_shuffle), or
    None (every partition meets every block).  An affine map keeps a hull
    convex, so the bounds of its mapped vertices, floored and widened by a
    pixel, hold every pixel of its shapes."""
    hulls = getattr(frame, "spatial_partitions", None)
    if hulls is None or len(hulls) != frame.npartitions:
        return None
    import shapely

    out = []
    for hull in hulls:
        if hull is None or hull.is_empty:
            out.append(set())
            continue
        xy = shapely.get_coordinates(hull)
        px = np.c_[inv[0] + xy[:, 0] * inv[1] + xy[:, 1] * inv[2], inv[3] + xy[:, 0] * inv[4] + xy[:, 1] * inv[5]]
        if not np.isfinite(px).all():
            return None
        lo, hi = np.floor(px.min(axis=0)) - 1, np.floor(px.max(axis=0)) + 1
        bi0, bi1, ok_i = _Layer._span(lo[1:], hi[1:], row_edges)
        bj0, bj1, ok_j = _Layer._span(lo[:1], hi[:1], col_edges)
        nbj = len(col_edges) - 1
        out.append({i * nbj + j for i in range(bi0[0], bi1[0] + 1) for j in range(bj0[0], bj1[0] + 1)}
                   if ok_i[0] and ok_j[0] else set())
    return out


# ---- the public function -----------------------------------------------------------------------

def _is_dask_frame(shapes):
    return hasattr(shapes, "npartitions") and hasattr(shapes, "to_delayed")


def _chunks(chunks, shape, dt):
    """Dask's normalised chunks for `shape`, or InputError."""
    import dask.array as da

    if chunks is None:
        raise InputError("chunks must be given: rows and columns per block, e.g. 4096 or (4096, 8192), "
                         "or dask's forms ((rows, ...), (columns, ...)) or 'auto'")
    try:
        norm = da.core.normalize_chunks(chunks, shape=shape, dtype=dt)
    except ArithmeticError:  # chunks=0 or (0, 5): dask divides by it
        raise InputError("chunks %r: every chunk must be a whole number > 0 (rows and columns per block)"
                         % (chunks,)) from None
    except (ValueError, TypeError) as e:
        raise InputError("chunks %r do not fit out_shape %r: %s" % (chunks, shape, e)) from None
    if len(norm) != 2 or tuple(map(sum, norm)) != tuple(shape):
        raise InputError("chunks %r do not fit out_shape %r: the rows' and columns' chunks must sum "
                         "to %d and %d" % (chunks, shape, shape[0], shape[1]))
    for axis, sizes in zip(("rows", "columns"), norm):
        if any(not isinstance(c, numbers.Integral) or c <= 0 for c in sizes):
            raise InputError("chunks %r: every chunk of the %s must be a whole number > 0, not %r"
                             % (chunks, axis, sizes))
    return norm


def _frame_dtype(shapes, values, default_value):
    """rastrum.rasterize's default dtype for a dask-geopandas frame, read
    from its meta: float64 when the value column (or default_value) is a
    float, else int64."""
    if values is None:
        return np.dtype(np.float64 if isinstance(default_value, (float, np.floating)) else np.int64)
    return np.dtype(np.float64 if shapes._meta[values].dtype.kind == "f" else np.int64)


def rasterize(
    shapes: Any,
    out_shape: Tuple[int, int],
    *,
    transform: Any = IDENTITY,
    chunks: Any = None,
    fill: Union[int, float] = 0,
    all_touched: bool = False,
    merge_alg: Any = "replace",
    default_value: Union[int, float] = 1,
    dtype: Any = None,
    values: Union[str, Sequence[Union[int, float, None]], None] = None,
    rule: str = "evenodd",
    coverage: Optional[str] = None,
) -> "dask.array.Array":
    """Burn shapes into a lazy 2-D ``dask.array.Array``, block by block.

    The computed array equals ``rastrum.rasterize(shapes, out_shape,
    transform=transform, fill=fill, all_touched=all_touched,
    merge_alg=merge_alg, default_value=default_value, dtype=dtype,
    values=values, rule=rule, coverage=coverage)`` pixel for pixel (bit for
    bit with `coverage`), for any chunking.

    Parameters
    ----------
    shapes : geometries, (geometry, value) pairs, a GeoSeries or GeoDataFrame, or a dask-geopandas one
        As :func:`rastrum.rasterize`.  In-memory shapes are read and checked
        now (bad input raises here); a dask-geopandas GeoDataFrame or
        GeoSeries is read partition by partition by the tasks (bad input
        raises at compute time, naming the partition), never collected.
    out_shape : (int, int)
        (height, width) of the whole raster.
    transform : affine.Affine or 6 numbers (a, b, c, d, e, f)
        The whole raster's transform, as :func:`rastrum.rasterize`.
    chunks : int, tuple or str
        The blocks, in any form ``dask.array`` takes with ``shape=out_shape``:
        4096, (2048, 4096), ((rows, ...), (columns, ...)) (irregular), "auto".
    fill, all_touched, merge_alg, default_value, rule
        As :func:`rastrum.rasterize`.
    dtype : one of rastrum.gis.DTYPES, optional
        As :func:`rastrum.rasterize`; for a dask-geopandas frame the default
        comes from the value column's dtype (float64 for floats, else int64);
        with `coverage`, float64.
    values : str or sequence, optional
        A column name (GeoDataFrame, dask-geopandas too) or, for in-memory
        shapes, one value per shape.
    coverage : str, optional
        Coverage fractions, as :func:`rastrum.rasterize` burns them
        (merge_alg "replace", "add" or "max"; float64, float32, uint8 or
        uint16).  A block computes the whole window (in the whole raster)
        of every feature that meets it, and keeps the block's cells: the
        same fractions as one machine, a feature crossing k blocks computed
        k times (docs/dask.md).

    Returns
    -------
    dask.array.Array (H, W) of dtype, chunked as `chunks`.

    Raises
    ------
    InputError (a ValueError)
        As :func:`rastrum.rasterize`, and for chunks that do not fit
        out_shape.

    Examples
    --------
    >>> import rastrum.dask
    >>> square = {"type": "Polygon", "coordinates": [[(1, 1), (4, 1), (4, 3), (1, 3), (1, 1)]]}
    >>> a = rastrum.dask.rasterize([(square, 7)], (4, 5), chunks=(2, 3), dtype="uint8")
    >>> a.chunks
    ((2, 2), (3, 2))
    >>> a.compute()
    array([[0, 0, 0, 0, 0],
           [0, 7, 7, 7, 0],
           [0, 7, 7, 7, 0],
           [0, 0, 0, 0, 0]], dtype=uint8)
    """
    try:
        import dask
        import dask.array as da
    except ImportError:
        raise ImportError(_NEEDS_DASK % "rastrum.dask.rasterize") from None

    merge = gis._merge_name(merge_alg, coverage is not None)
    _core._name(rule, "fill rule", _core.RULES)
    if not isinstance(all_touched, (bool, np.bool_)):
        raise InputError("all_touched must be True or False, not %r" % (all_touched,))
    all_touched = bool(all_touched)
    if coverage is not None:
        from . import _fractions

        coverage = _fractions._method(coverage)
        if all_touched:
            raise InputError("all_touched=True has no meaning with coverage= (every touched cell has its fraction)")
        if dtype is None:
            dtype = "float64"
        _fractions._coverage_dtype(dtype)
    inv = gis._inverse(gis._transform6(transform))
    gis._real(fill, "fill")
    frame = _is_dask_frame(shapes)
    if frame:
        if values is not None and not isinstance(values, str):
            raise InputError("values: a dask-geopandas frame takes a column name, not %s"
                             % type(values).__name__)
        if getattr(shapes._meta, "ndim", 2) == 1 and values is not None:  # a GeoSeries
            raise InputError("values=%r: a column name needs a GeoDataFrame" % (values,))
        if values is not None and values not in shapes.columns:
            raise InputError("values=%r is not a column of the GeoDataFrame; columns: %s"
                             % (values, ", ".join(map(str, shapes.columns))))
        gis._real(default_value, "default_value")
        if dtype is None:
            dtype = _frame_dtype(shapes, values, default_value)
        (h, w, dt), _ = gis._out_array(None, out_shape, dtype, fill, [])
    else:
        geoms, vals = gis._split_shapes(shapes, default_value, fill, values)
        (h, w, dt), _ = gis._out_array(None, out_shape, dtype, fill, vals)
        vals, xy, ring_sizes, part_rings, kind, feature, geom = _read(geoms, vals, dt, coverage)
        px = gis._pixels(xy, inv, ring_sizes, part_rings, feature)
    fill_v = gis._fits(fill, dt, "fill")
    rows, cols = _chunks(chunks, (h, w), dt)
    row_edges = np.concatenate([[0], np.cumsum(rows)]).astype(np.int64)
    col_edges = np.concatenate([[0], np.cumsum(cols)]).astype(np.int64)
    args = (fill_v, dt, merge, all_touched, rule)
    if coverage is not None:
        args = ((h, w), fill_v, dt, merge, rule, coverage)

    def blocks(make):
        return [[da.from_delayed(make(i * len(cols) + j, (r, c), (int(row_edges[i]), int(col_edges[j]))),
                                 (r, c), dtype=dt)
                 for j, c in enumerate(cols)] for i, r in enumerate(rows)]

    burn = dask.delayed(_burn_block if coverage is None else _coverage_block, pure=False)
    if not frame:
        layer = _Layer(_layer_parts(px, ring_sizes, part_rings, kind, vals, feature, geom, len(geoms), coverage),
                       row_edges, col_edges)
        return da.block(blocks(lambda b, shape, origin: burn(shape, origin, *args, layer.block_parts(b))))

    read = dask.delayed(_read_partition, pure=False)
    layers = [read(part, p, values, default_value, fill, dt, inv, row_edges, col_edges, coverage)
              for p, part in enumerate(shapes.to_delayed())]
    meets = _partition_blocks(shapes, inv, row_edges, col_edges)
    take = dask.delayed(_block_parts, pure=False)

    def block(b, shape, origin):
        return burn(shape, origin, *args, *[take(lay, b) for p, lay in enumerate(layers)
                                            if meets is None or b in meets[p]])

    return da.block(blocks(block))


def to_xarray(array: Any, transform: Any = IDENTITY, *, crs: Any = None, name: Any = None) -> "xarray.DataArray":
    """The raster as an ``xarray.DataArray`` with dims ("y", "x") and the
    world coordinates of the pixel centres (a north-up or south-up
    transform: no rotation or shear); with rioxarray installed, its
    transform (and crs, if given) are written too (``.rio``).

    >>> import rastrum.dask
    >>> a = rastrum.dask.rasterize([], (2, 3), chunks=2, transform=(10, 0, 100, 0, -10, 50))
    >>> rastrum.dask.to_xarray(a, (10, 0, 100, 0, -10, 50)).x.values.tolist()
    [105.0, 115.0, 125.0]
    """
    try:
        import xarray as xr
    except ImportError:
        raise InputError('to_xarray needs xarray: pip install "rastrum[dask]"') from None
    a, b, c, d, e, f = gis._transform6(transform)
    if b != 0.0 or d != 0.0:
        raise InputError("to_xarray: transform %r is rotated or sheared; x and y coordinates need "
                         "b = d = 0" % ((a, b, c, d, e, f),))
    if getattr(array, "ndim", None) != 2:
        raise InputError("to_xarray: array must be 2-D (rows, columns), not %r" % (getattr(array, "shape", array),))
    h, w = array.shape
    x = c + a * (np.arange(w) + 0.5)
    y = f + e * (np.arange(h) + 0.5)
    out = xr.DataArray(array, dims=("y", "x"), coords={"y": y, "x": x}, name=name)
    try:
        import rioxarray  # noqa: F401  (registers .rio)
    except ImportError:
        return out
    import affine

    out = out.rio.write_transform(affine.Affine(a, b, c, d, e, f))
    if crs is not None:
        out = out.rio.write_crs(crs)
    return out


# ---- zonal statistics of a raster read block by block ---------------------------------------------

def _take(block, positions):
    """The values (and mask, for a masked block) of a block at its flat
    positions: what a block's task sends back, the covered cells only."""
    a = np.asarray(block) if not isinstance(block, np.ma.MaskedArray) else block
    flat = a.reshape(a.shape[:-2] + (-1,))
    if isinstance(a, np.ma.MaskedArray):
        return np.asarray(flat.data[..., positions]), np.ma.getmaskarray(flat)[..., positions]
    return flat[..., positions], None


def _edges(sizes):
    return np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)


def _gather(array, cells, W):
    """array (dask, ([bands,] H, W)) at the flat cells, read block by block:
    one small task per block that holds covered cells (the other blocks are
    never computed); (values (bands, n), mask (bands, n) or None), bands =
    1 for a 2-D array."""
    import dask

    rows_e, cols_e = _edges(array.chunks[-2]), _edges(array.chunks[-1])
    r, c = np.divmod(cells, W)
    bi = np.searchsorted(rows_e, r, side="right") - 1
    bj = np.searchsorted(cols_e, c, side="right") - 1
    ncb = len(cols_e) - 1
    block = bi * ncb + bj
    order = np.argsort(block, kind="stable")
    bounds = np.flatnonzero(np.r_[True, block[order][1:] != block[order][:-1]]) if len(order) else order
    delayed = array.to_delayed()
    band_edges = _edges(array.chunks[0]) if array.ndim == 3 else np.array([0, 1])
    tasks, where = [], []
    take = dask.delayed(_take, pure=True)
    for a, b in zip(bounds.tolist(), np.r_[bounds[1:], len(order)].tolist()):
        idx = order[a:b]
        i, j = int(bi[idx[0]]), int(bj[idx[0]])
        pos = (r[idx] - rows_e[i]) * (cols_e[j + 1] - cols_e[j]) + (c[idx] - cols_e[j])
        for k in range(len(band_edges) - 1):
            blk = delayed[k, i, j] if array.ndim == 3 else delayed[i, j]
            tasks.append(take(blk, pos))
            where.append((k, idx))
    results = dask.compute(*tasks) if tasks else ()
    nb = int(band_edges[-1])
    values = np.zeros((nb, len(cells)), array.dtype)
    mask = None
    for (k, idx), (v, m) in zip(where, results):
        bands = slice(int(band_edges[k]), int(band_edges[k + 1]))
        values[bands, idx] = v.reshape(-1, len(idx))
        if m is not None:
            if mask is None:
                mask = np.zeros((nb, len(cells)), bool)
            mask[bands, idx] = m.reshape(-1, len(idx))
    return values, mask


def zonal_stats(
    raster: Any,
    geometries: Any,
    *,
    transform: Any = None,
    stats: Any = ("mean",),
    weights: Any = None,
    nodata: Union[int, float, None] = None,
    coverage_weight: str = "fraction",
    rule: str = "evenodd",
    output: str = "auto",
) -> Any:
    """:func:`rastrum.zonal_stats` of a raster too large to hold: a dask
    array, or an xarray DataArray (rioxarray's ``open_rasterio(...,
    chunks=...)``), read block by block; the same table, bit for bit, for
    every chunking.

    How: the fractions depend on the geometries and the grid only; they
    are computed here, sparse (the cells each feature covers).  Each block
    that holds covered cells is read by one task, which returns the values
    of those cells only; blocks no feature touches are never read.  The
    statistics are then computed from the same arrays as
    :func:`rastrum.zonal_stats` computes them from, so every statistic
    (sums, stdev, majority, quantiles ...) is the single-machine one
    exactly, whatever the chunks.  Memory here: about 24 bytes per covered
    cell and band (fraction, cell, value), never the raster.

    Parameters are those of :func:`rastrum.zonal_stats`; `raster` is a dask
    array (2-D, or 3-D with bands first), a DataArray (its ``.rio``
    transform and nodata the defaults) or a numpy array; `weights` a dask
    or numpy array (or DataArray) of the raster's (rows, columns).

    Examples
    --------
    >>> import dask.array as da, numpy as np, rastrum.dask
    >>> raster = da.from_array(np.arange(16.0).reshape(4, 4), chunks=2)
    >>> sq = {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5)]]}
    >>> rastrum.dask.zonal_stats(raster, [sq], stats="count mean", output="records")
    [{'count': 4.0, 'mean': 5.0}]
    """
    try:
        import dask.array as da
    except ImportError:
        raise ImportError(_NEEDS_DASK % "rastrum.dask.zonal_stats") from None
    from . import _zonal

    ops = _zonal._check_options(stats, coverage_weight, output, rule)
    if hasattr(raster, "rio") and hasattr(raster, "dims"):  # rioxarray
        if transform is None:
            transform = raster.rio.transform()
        if nodata is None:
            nodata = raster.rio.nodata
    if hasattr(raster, "dims") and hasattr(raster, "data"):  # a DataArray: its dask (or numpy) array
        raster = raster.data
    if transform is None:
        transform = IDENTITY
    if not isinstance(raster, da.Array):
        return _zonal.zonal_stats(raster, geometries, transform=transform, stats=stats, weights=weights,
                                  nodata=nodata, coverage_weight=coverage_weight, rule=rule, output=output)
    if raster.ndim not in (2, 3) or 0 in raster.shape:
        raise InputError("raster must be a non-empty 2-D (rows, columns) or 3-D (bands, rows, columns) array, "
                         "not shape %r" % (raster.shape,))
    if raster.dtype.kind not in "iuf" or raster.dtype.itemsize > 8:
        raise InputError("raster: dtype %s is not supported (integers or floats)" % raster.dtype)
    if nodata is not None and (isinstance(nodata, (bool, np.bool_))
                               or not isinstance(nodata, (int, float, np.integer, np.floating))):
        raise InputError("nodata %r is not a number" % (nodata,))
    H, W = raster.shape[-2:]
    if hasattr(weights, "dims") and hasattr(weights, "data"):
        weights = weights.data
    _zonal._check_weights(ops, None if weights is None else getattr(weights, "shape", np.shape(weights)), (H, W))
    f, cells, c, index, nfeat = _zonal._features(geometries, transform, (H, W), rule, coverage_weight, None)
    values, mask = _gather(raster, cells, W)
    wt = None
    if weights is not None:
        if isinstance(weights, da.Array):
            wt = _gather(weights.astype(np.float64), cells, W)[0][0]
        else:
            wt = np.asarray(weights, np.float64).ravel()[cells]
    masks = None if mask is None else list(mask)
    columns = _zonal._columns(ops, f, c, list(values), masks, wt, nodata, raster.ndim == 3, nfeat)
    return _zonal._table(columns, nfeat, index, output)

"""Zonal statistics from coverage fractions: :func:`zonal_stats`.

Each feature's fraction of every raster cell is what
``polygon_coverage(method="area", dtype=numpy.float64)`` gives on the
feature's window (the raster cells its bounding box touches): for the
windows on its 64-bit path, all in one C call (python/glue/zonal.c) that
returns only the covered cells, bit for bit the same; the statistics of
all features are then computed together in vectorised numpy (grouped
sums, sorts and reductions: no Python loop over cells).
The operations and their definitions are exactextract's (see
docs/gis.md, "Zonal statistics").
"""

from __future__ import annotations

import re
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import gis
from . import _coverage as _cov, _fractions as _fr
from ._core import InputError
from ._fractions import _geometries, feature_fractions, subpixel_bits_for
from ._native import ffi, lib

_MAX_S32 = lib.RAST_MAX_SUBPIXEL_BITS  # polygon_coverage's 32-bit path takes S up to this

__all__ = ["zonal_stats", "STATS", "subpixel_bits_for"]

#: The statistics zonal_stats computes (exactextract's names); also
#: ``quantile(q=0.25)`` (column ``quantile_25``) and rasterstats'
#: ``percentile_25``, ``mode`` (= majority), ``std`` (= stdev).
STATS = ("count", "sum", "mean", "min", "max", "majority", "minority", "variety", "median",
         "stdev", "variance", "coefficient_of_variation", "weighted_count", "weighted_sum",
         "weighted_mean", "weighted_stdev", "weighted_variance")

_ALIASES = {"mode": "majority", "std": "stdev"}
_QUANTILE = re.compile(r"^quantile\(\s*q\s*=\s*([0-9.eE+-]+)\s*\)$")
_PERCENTILE = re.compile(r"^percentile_([0-9]+(?:\.[0-9]+)?)$")

# ---- statistics names ---------------------------------------------------------------

def _parse_stats(stats) -> List[Tuple[str, str, Optional[float]]]:
    """[(column, operation, q)] from stats= (a str of names separated by
    spaces, as rasterstats takes them, or a sequence of names)."""
    if isinstance(stats, str):
        names = stats.split()
    else:
        try:
            names = list(stats)
        except TypeError:
            raise InputError("stats must be a str or a sequence of statistic names, not %r" % (stats,)) from None
    if not names:
        raise InputError("stats is empty; choose from: %s, quantile(q=...), percentile_N" % ", ".join(STATS))
    out: List[Tuple[str, str, Optional[float]]] = []
    for name in names:
        if not isinstance(name, str):
            raise InputError("stats: %r is not a statistic name (a str)" % (name,))
        m, p = _QUANTILE.match(name), _PERCENTILE.match(name)
        if m is not None or p is not None:
            digits = m.group(1) if m is not None else p.group(1) if p is not None else ""
            try:
                q = float(digits) if m is not None else float(digits) / 100.0
            except ValueError:
                q = float("nan")
            if not 0.0 <= q <= 1.0:
                raise InputError("stats: %r: the quantile must be in 0..1 (a percentile in 0..100)" % name)
            column = "quantile_%s" % _pct(q) if m else name
            out.append((column, "quantile", q))
        elif name == "median":
            out.append((name, "quantile", 0.5))
        elif name in STATS or name in _ALIASES:
            out.append((name, _ALIASES.get(name, name), None))
        else:
            raise InputError("stats: unknown statistic %r; choose from: %s, quantile(q=...), percentile_N, "
                             "mode, std" % (name, ", ".join(STATS)))
    return out


def _pct(q: float) -> str:
    v = q * 100.0
    return ("%d" % v) if v == int(v) else ("%g" % v)


# ---- inputs ------------------------------------------------------------------------

def _raster(raster, transform, nodata):
    """(bands (B, H, W) array, mask of invalid cells or None, transform,
    nodata, whether the input had a band axis)."""
    if hasattr(raster, "rio") and hasattr(raster, "dims"):  # xarray with rioxarray
        if transform is None:
            transform = raster.rio.transform()
        if nodata is None:
            nodata = raster.rio.nodata
    elif hasattr(raster, "dims") and hasattr(raster, "values") and transform is None:
        transform = gis.IDENTITY
    if transform is None:
        transform = gis.IDENTITY
    mask = None
    if isinstance(raster, np.ma.MaskedArray):
        mask = np.ma.getmaskarray(raster)
        data = np.asarray(raster.data)
    else:
        try:
            data = np.asarray(raster)  # a dask array or a DataArray computes here
        except (ValueError, TypeError, OverflowError, RecursionError):  # ragged or self-holding lists
            raise InputError("raster must be a 2-D (rows, columns) or 3-D (bands, rows, columns) array, "
                             "not %s" % type(raster).__name__) from None
    if data.ndim not in (2, 3) or 0 in data.shape:
        raise InputError("raster must be a non-empty 2-D (rows, columns) or 3-D (bands, rows, columns) array, "
                         "not shape %r" % (data.shape,))
    if data.dtype.kind not in "iuf" or data.dtype.itemsize > 8:
        raise InputError("raster: dtype %s is not supported (integers or floats)" % data.dtype)
    banded = data.ndim == 3
    if not banded:
        data = data[None]
        mask = None if mask is None else mask[None]
    if nodata is not None:
        if isinstance(nodata, (bool, np.bool_)) or not isinstance(nodata, (int, float, np.integer, np.floating)):
            raise InputError("nodata %r is not a number" % (nodata,))
    return data, mask, transform, nodata, banded


_fractions = feature_fractions  # the tests' name

# how many windows one C call takes between progress updates
_WINDOWS_PER_CALL = 512
# the largest window (cells) the one C call takes: it fills each window
# densely, a cost per cell; a larger window is cheaper by runs
_BATCH_CELLS = 1 << 16


def _all_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress=None):
    """feature_fractions(..., method="area", dtype=float64)'s (feature ids,
    flat cells, fractions), the same bits, faster: the windows whose S is
    past the 32-bit path's (where polygon_coverage takes its 64-bit path,
    rastpy_polygon_coverage64) go to one C call for many windows
    (python/glue/zonal.c: the same C call on the same float64 points, the
    same 2^-62 to float64 conversion, the nonzero cells kept); the others
    (S <= 16, or a feature far outside the raster, whose rings are clipped
    first) through feature_fractions itself.  The windows and their S are
    feature_fractions' own (its _bits)."""
    H, W = shape
    if not len(px):
        return feature_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule)[:3]
    fpt, fring, inside, r0, c0, hw, ww, local, s_own, s_box = _fr._windows(px, ring_sizes, part_rings, feature,
                                                                             nfeat, shape, "area")
    # rings of 3 points or more (feature_fractions leaves the others out)
    ring_ok = ring_sizes >= 3
    ok_start = np.concatenate([[0], np.cumsum(ring_ok)])
    ok_rings = ok_start[fring[1:]] - ok_start[fring[:-1]]
    # (a window past _BATCH_CELLS goes to feature_fractions' sparse path,
    # which pays per run of equal cells, not per cell of the window)
    fast = inside & (s_own >= s_box) & (s_own > _MAX_S32) & (ok_rings > 0) & (hw * ww <= _BATCH_CELLS)
    if not fast.any():  # (all through feature_fractions: no renumbering, no merge)
        out = feature_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress)[:3]
        if progress is not None:
            progress(nfeat)
        return out
    parts = [_fast_fractions(np.flatnonzero(fast), local, ring_sizes, ring_ok, ok_start, fring, hw, ww, r0, c0,
                             s_own, W, rule, progress)]
    slow = ~fast & inside
    if slow.any():
        # the other features, renumbered, through feature_fractions
        ids = np.flatnonzero(slow)
        part_keep = slow[feature]
        ring_keep = np.repeat(part_keep, part_rings)
        pt_keep = np.repeat(ring_keep, ring_sizes)
        renum = np.cumsum(slow) - 1
        f, cells, c, _ = feature_fractions(px[pt_keep], ring_sizes[ring_keep], part_rings[part_keep],
                                           renum[feature[part_keep]], len(ids), shape, rule)
        parts.append((ids[f], cells, c))
    if progress is not None:
        progress(nfeat)
    if len(parts) == 1:
        return parts[0]
    f = np.concatenate([p[0] for p in parts])
    order = np.argsort(f, kind="stable")  # features in order, each one's cells as they came
    return f[order], np.concatenate([p[1] for p in parts])[order], np.concatenate([p[2] for p in parts])[order]


def _fast_fractions(ids, local, ring_sizes, ring_ok, ok_start, fring, hw, ww, r0, c0, s, W, rule, progress):
    """(feature ids, cells, fractions) of the features `ids` (ascending),
    their windows' fractions from rastpy_window_fractions64."""
    if not len(ids):
        return np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0)
    pts = np.ascontiguousarray(local[np.repeat(ring_ok, ring_sizes)])
    sizes = np.ascontiguousarray(ring_sizes[ring_ok], dtype=np.uint32)
    ok_pt_start = np.concatenate([[0], np.cumsum(sizes, dtype=np.int64)])
    first_ring = ok_start[fring[ids]]
    win = np.empty((len(ids), 8), np.int64)
    win[:, 0] = ids
    win[:, 1] = hw[ids]
    win[:, 2] = ww[ids]
    win[:, 3] = s[ids]
    win[:, 4] = ok_pt_start[first_ring]
    win[:, 5] = first_ring
    win[:, 6] = ok_start[fring[ids + 1]] - first_ring
    win[:, 7] = r0[ids] * W + c0[ids]
    cap = int((win[:, 1] * win[:, 2]).sum())
    out_f = np.empty(cap, np.int64)
    out_c = np.empty(cap, np.int64)
    out_v = np.empty(cap, np.float64)
    opts = _cov._opts("area", rule, _MAX_S32 + 1, 0.5, "polygon_coverage")  # its S: each window's
    failed = ffi.new("int64_t[2]")
    xy, rs = ffi.from_buffer("double[]", pts), ffi.from_buffer("uint32_t[]", sizes)
    done = 0
    for a in range(0, len(ids), _WINDOWS_PER_CALL):
        b = min(a + _WINDOWS_PER_CALL, len(ids))
        n = lib.rastpy_window_fractions64(b - a, ffi.from_buffer("int64_t[]", win[a:b]), xy, len(pts), rs,
                                          len(sizes), opts, W,
                                          ffi.from_buffer("int64_t[]", out_f[done:]),
                                          ffi.from_buffer("int64_t[]", out_c[done:]),
                                          ffi.from_buffer("double[]", out_v[done:]), cap - done, failed)
        if n < 0:
            k = int(ids[a + failed[0]])
            raise InputError("geometries: feature %d: its coverage failed (%s)"
                             % (k, "a bad vertex" if failed[1] else _core_status(n)))
        done += n
        if progress is not None:
            progress(int(ids[b - 1]) + 1)
    if done < cap // 2:  # do not hold the windows' worth of memory
        return out_f[:done].copy(), out_c[:done].copy(), out_v[:done].copy()
    return out_f[:done], out_c[:done], out_v[:done]


def _core_status(n):
    return "out of memory" if n == lib.RASTPY_E_NOMEM else "status %d" % n


# ---- grouped statistics ------------------------------------------------------------------

def _group_reduce(ufunc, x, f, nfeat, empty=np.nan):
    """ufunc.reduceat of x over the runs of equal f (f nondecreasing), one
    value per feature; `empty` for a feature without cells."""
    out = np.full(nfeat, empty)
    if len(x):
        starts = np.flatnonzero(np.r_[True, f[1:] != f[:-1]])
        out[f[starts]] = ufunc.reduceat(x, starts)
    return out


def _histogram(f, x, c):
    """The distinct (feature, value) pairs sorted by feature then value,
    with the sum of the coverage of each: (fu, xu, wu).  f is
    nondecreasing: each feature's run is sorted by value on its own (a
    loop over features: far cheaper than one global two-key sort)."""
    n = len(f)
    if not n:
        return f[:0], x[:0], c[:0]
    starts = np.flatnonzero(np.r_[True, f[1:] != f[:-1]])
    order = np.empty(n, np.int64)
    for a, b in zip(starts.tolist(), np.r_[starts[1:], n].tolist()):
        order[a:b] = np.argsort(x[a:b])
        order[a:b] += a
    fs, xs, cs = f, x[order], c[order]  # order permutes within each feature's run: f[order] is f
    new = np.r_[True, (fs[1:] != fs[:-1]) | (xs[1:] != xs[:-1])]
    first = np.flatnonzero(new)
    return fs[first], xs[first], np.add.reduceat(cs, first)


def _quantiles(fu, xu, wu, nfeat, q):
    """exactextract's weighted quantile of each feature (its distinct values
    xu with the coverage wu of each): with n values sorted, s_0 = 0 and
    s_i = i*w_i + (n - 1)*(w_0 + ... + w_{i-1}); the target t = q*(n - 1)*W
    (W the sum of the w); the first i with s_i > t; x_{n-1} if none, else
    x_{i-1} + (t - s_{i-1})*(x_i - x_{i-1})/(s_i - s_{i-1})."""
    out = np.full(nfeat, np.nan)
    if not len(fu):
        return out
    starts = np.flatnonzero(np.r_[True, fu[1:] != fu[:-1]])
    n = np.diff(np.r_[starts, len(fu)])
    g = np.repeat(np.arange(len(starts)), n)  # group of each entry
    i = np.arange(len(fu)) - starts[g]
    csum = np.cumsum(wu)
    before = csum - wu - np.repeat(csum[starts] - wu[starts], n)  # w_0 + ... + w_{i-1} of the group
    s = np.where(i == 0, 0.0, i * wu + (n[g] - 1) * before)
    total = np.add.reduceat(wu, starts)
    t = q * (total * (n - 1))
    above = s > t[g]
    big = len(fu)
    first = np.minimum.reduceat(np.where(above, np.arange(len(fu)), big), starts)
    last = starts + n - 1
    res = xu[last].astype(np.float64)
    has = first < big
    r = first[has]
    left = r - 1
    res[has] = xu[left] + (t[has] - s[left]) * (xu[r] - xu[left]) / (s[r] - s[left])
    out[fu[starts]] = res
    return out


def _band_stats(ops, f, x, c, wt, nfeat):
    """{column: per-feature values} of one band's valid cells."""
    res = {}
    count = np.bincount(f, c, nfeat)
    total = np.bincount(f, x * c, nfeat)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = total / count
        hist = None
        var = {}
        for column, op, q in ops:
            if op == "count":
                v = count
            elif op == "sum":
                v = total
            elif op == "mean":
                v = mean
            elif op == "min":
                v = _group_reduce(np.minimum, x, f, nfeat)
            elif op == "max":
                v = _group_reduce(np.maximum, x, f, nfeat)
            elif op in ("majority", "minority", "variety", "quantile"):
                if hist is None:
                    hist = _histogram(f, x, c)
                fu, xu, wu = hist
                if op == "variety":
                    v = np.bincount(fu, minlength=nfeat)
                elif op == "quantile":
                    v = _quantiles(fu, xu, wu, nfeat, q)
                else:
                    # exactextract: the value of greatest coverage, ties to
                    # the greatest value (majority); least, ties to the least
                    order = np.lexsort((xu, wu, fu))
                    fo = fu[order]
                    v = np.full(nfeat, np.nan)
                    if len(fo):
                        pick = np.r_[fo[1:] != fo[:-1], True] if op == "majority" else np.r_[True, fo[1:] != fo[:-1]]
                        v[fo[pick]] = xu[order][pick]
            elif op in ("stdev", "variance", "coefficient_of_variation"):
                if "u" not in var:
                    var["u"] = np.bincount(f, c * (x - mean[f]) ** 2, nfeat) / count
                v = var["u"]
                if op == "stdev":
                    v = np.sqrt(v)
                elif op == "coefficient_of_variation":
                    v = np.sqrt(v) / mean
            else:  # weighted
                if wt is None:
                    raise InputError("stats: %r needs weights=" % column)
                cw = c * wt
                wcount = np.bincount(f, cw, nfeat)
                wsum = np.bincount(f, x * cw, nfeat)
                if op == "weighted_count":
                    v = wcount
                elif op == "weighted_sum":
                    v = wsum
                elif op == "weighted_mean":
                    v = wsum / wcount
                else:
                    wmean = wsum / wcount
                    v = np.bincount(f, cw * (x - wmean[f]) ** 2, nfeat) / wcount
                    if op == "weighted_stdev":
                        v = np.sqrt(v)
            res[column] = v
    return res


# ---- the function -------------------------------------------------------------------------

def zonal_stats(
    raster: Any,
    geometries: Iterable[Any],
    *,
    transform: Optional[gis.Transform] = None,
    stats: Union[str, Sequence[str]] = ("mean",),
    weights: Any = None,
    nodata: Union[int, float, None] = None,
    coverage_weight: str = "fraction",
    rule: str = "evenodd",
    output: str = "auto",
    progress: Union[bool, Callable[[int, int], Any], None] = None,
) -> Any:
    """Per-feature statistics of a raster under polygons, weighted by the
    fraction of each cell the polygon covers (exactextract's definitions).

    Parameters
    ----------
    raster : array (H, W) or (bands, H, W)
        numpy array, masked array (masked cells excluded), dask array or
        xarray DataArray (computed here; with rioxarray, its transform and
        nodata are the defaults).
    geometries : iterable of polygons, a GeoSeries or a GeoDataFrame
        Polygon or MultiPolygon (shapely, ``__geo_interface__`` or GeoJSON
        mappings), in the raster's coordinates.  A feature's rings are
        filled together under `rule`.
    transform : affine.Affine or 6 numbers, optional
        Pixel to world, as for ``rasterize`` (default: the identity, or a
        DataArray's ``rio.transform()``).
    stats : str or sequence of str
        exactextract's operation names (rasterstats' "mean max ..." string
        too): count, sum, mean, min, max, majority (mode), minority,
        variety, median, quantile(q=0.25), percentile_25, stdev (std),
        variance, coefficient_of_variation, weighted_count, weighted_sum,
        weighted_mean, weighted_stdev, weighted_variance.
    weights : array (H, W), optional
        The weights raster of the ``weighted_*`` statistics (NaN weights
        make them NaN, as exactextract's nodata weights).
    nodata : number, optional
        Cells of this value are left out (NaN cells always are).
    coverage_weight : {"fraction", "none"}
        "fraction": each cell counts by its covered fraction c (exactextract's
        default); "none": every cell with c > 0 counts as 1.
    rule : {"evenodd", "nonzero"}
        How a feature's rings make its region.
    output : {"auto", "pandas", "records"}
        "auto": a pandas DataFrame when pandas is installed (the index of a
        GeoSeries/GeoDataFrame kept), else a list of dicts.
    progress : bool or callable(done, total), optional
        True shows a tqdm bar over the features.

    Returns
    -------
    pandas.DataFrame or list of dict
        One row per feature; columns named as exactextract names them
        ("mean", "quantile_25"; "band_1_mean" ... for a 3-D raster).  A
        feature covering no valid cell (outside the raster, or all nodata):
        count, sum and variety 0, the others NaN.

    Raises
    ------
    InputError (a ValueError)
        A geometry that is not a polygon, a bad raster, weights, transform,
        statistic name or option.

    Examples
    --------
    >>> import numpy as np, rastrum
    >>> raster = np.arange(16.0).reshape(4, 4)
    >>> square = {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5)]]}
    >>> rastrum.zonal_stats(raster, [square], stats=["count", "mean", "max"], output="records")
    [{'count': 4.0, 'mean': 5.0, 'max': 10.0}]
    """
    ops = _check_options(stats, coverage_weight, output, rule)
    data, mask, transform, nodata, banded = _raster(raster, transform, nodata)
    B, H, W = data.shape
    wt_raster = None
    if weights is not None:
        wt_raster = np.asarray(weights, dtype=np.float64)
    _check_weights(ops, None if weights is None else wt_raster.shape, (H, W))
    f, cells, c, index, nfeat = _features(geometries, transform, (H, W), rule, coverage_weight, progress)
    flat = data.reshape(B, H * W)
    xs = [flat[band][cells] for band in range(B)]
    masks = None if mask is None else [mask[band].ravel()[cells] for band in range(B)]
    wt = None if wt_raster is None else wt_raster.ravel()[cells]
    return _table(_columns(ops, f, c, xs, masks, wt, nodata, banded, nfeat), nfeat, index, output)


def _check_options(stats, coverage_weight, output, rule):
    """The parsed stats, once the options are checked."""
    ops = _parse_stats(stats)
    if coverage_weight not in ("fraction", "none"):
        raise InputError("coverage_weight must be 'fraction' or 'none', not %r" % (coverage_weight,))
    if output not in ("auto", "pandas", "records"):
        raise InputError("output must be 'auto', 'pandas' or 'records', not %r" % (output,))
    gis._core._name(rule, "fill rule", gis._core.RULES)
    return ops


def _check_weights(ops, shape, raster_shape):
    if shape is not None:
        if tuple(shape) != tuple(raster_shape):
            raise InputError("weights: shape %r differs from the raster's %r" % (tuple(shape), tuple(raster_shape)))
    elif any(op.startswith("weighted") for _, op, _ in ops):
        raise InputError("stats: %s need weights=" % ", ".join(c for c, op, _ in ops if op.startswith("weighted")))


def _features(geometries, transform, shape, rule, coverage_weight, progress):
    """(feature ids, flat cells, fractions, index, number of features): the
    cells every feature covers in a raster of `shape`, as zonal_stats
    weighs them."""
    H, W = shape
    inv = gis._inverse(gis._transform6(transform))
    geoms, index = _geometries(geometries)
    xy, ring_sizes, part_rings, kind, feature, _ = gis._flatten(geoms)
    if len(kind) and (kind != gis._KIND_POLYGON).any():
        k = int(np.flatnonzero(kind != gis._KIND_POLYGON)[0])
        raise InputError("geometries: feature %d is not a polygon (zonal_stats takes Polygon and MultiPolygon)"
                         % feature[k])
    px = gis._pixels(xy, inv, ring_sizes, part_rings, feature)
    nfeat = len(geoms)
    bar = gis._Progress(progress, nfeat)
    try:
        f, cells, c = _all_fractions(px, ring_sizes, part_rings, feature, nfeat, (H, W), rule,
                                     bar if bar.active else None)
    finally:
        bar.close()
    if coverage_weight == "none":
        c = np.ones_like(c)
    return f, cells, c, index, nfeat


def _columns(ops, f, c, xs, masks, wt_all, nodata, banded, nfeat):
    """{column: per-feature values}: xs[band] holds the band's value at
    every covered cell (masks[band] whether it is masked), wt_all the
    weights there."""
    columns: Dict[str, np.ndarray] = {}
    for band, x in enumerate(xs):
        valid = np.ones(len(x), bool)
        if x.dtype.kind == "f":
            valid &= ~np.isnan(x)
        if nodata is not None:
            valid &= x != nodata
        if masks is not None:
            valid &= ~masks[band]
        x = x.astype(np.float64)
        sel = valid if not valid.all() else slice(None)
        wt = None if wt_all is None else wt_all[sel]
        res = _band_stats(ops, f[sel], x[sel], c[sel], wt, nfeat)
        for column, v in res.items():
            columns[("band_%d_%s" % (band + 1, column)) if banded else column] = v
    return columns


def _table(columns, nfeat, index, output):
    if output != "records":
        try:
            import pandas as pd
        except ImportError:
            if output == "pandas":
                raise InputError("output='pandas' needs pandas (pip install pandas)") from None
            pd = None
        if pd is not None:
            return pd.DataFrame(columns, index=index if index is not None else pd.RangeIndex(nfeat))
    rows = [dict() for _ in range(nfeat)]
    for column, v in columns.items():
        for row, value in zip(rows, v.tolist()):
            row[column] = value
    return rows

"""Zonal statistics from coverage fractions: :func:`zonal_stats`.

Each feature's fraction of every raster cell comes from
``polygon_coverage(method="area", dtype=numpy.float64)`` on the feature's
window (the raster cells its bounding box touches), one C call a feature;
the statistics of all features are then computed together in vectorised
numpy (grouped sums, sorts and reductions: no Python loop over cells).
The operations and their definitions are exactextract's (see
docs/gis.md, "Zonal statistics").
"""

from __future__ import annotations

import math
import re
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import gis
from ._core import InputError
from ._native import lib
from ._coverage import polygon_coverage

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

# The 32-bit coverage path: |vertex| * 2^S <= RAST_COORD_MAX, S <= 16.
_COORD_MAX = lib.RAST_COORD_MAX
_MAX_S = lib.RAST_MAX_SUBPIXEL_BITS


def subpixel_bits_for(extent: float) -> int:
    """The largest S (at most 16) at which a vertex of |coordinate| <=
    `extent` pixels snaps inside the 32-bit coverage range:
    floor(extent * 2^S + 1/2) <= 2^27 - 1.  A vertex moves by at most
    2^-(S+1) px in x and in y, so a fraction is off by about 2^-S of a cell
    per edge crossing it (docs/gis.md has the measured figures)."""
    s = _MAX_S
    while s >= 0 and math.floor(extent * 2.0 ** s + 0.5) > _COORD_MAX:
        s -= 1
    return s


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


def _geometries(geometries):
    """(list of geometries, index or None)."""
    index = None
    if hasattr(geometries, "geometry") and hasattr(geometries, "columns"):  # GeoDataFrame
        index = geometries.index
        geoms = list(np.asarray(geometries.geometry.values, dtype=object))
    elif type(geometries).__name__ == "GeoSeries":
        index = geometries.index
        geoms = list(np.asarray(geometries.values, dtype=object))
    else:
        if isinstance(geometries, (str, bytes, dict)) or hasattr(geometries, "__geo_interface__"):
            raise InputError("geometries must be an iterable of geometries, not one geometry; wrap it in a list")
        try:
            geoms = list(geometries)
        except TypeError:
            raise InputError("geometries must be an iterable of geometries, not %r"
                             % type(geometries).__name__) from None
    return geoms, index


# ---- coverage fractions per feature -----------------------------------------------------

def _clip_rings(pts, sizes, x0, y0, x1, y1):
    """Rings (pts, one ring after another, `sizes` points each) clipped to
    the box [x0, x1] x [y0, y1] (Sutherland-Hodgman, each ring against each
    side in turn).  The winding number of every point inside the box is
    that of the unclipped rings, so the area inside the box, and thus every
    cell's fraction, is the same under either fill rule."""
    rings = np.split(pts, np.cumsum(sizes)[:-1])
    out = []
    for ring in rings:
        for axis, bound, keep_greater in ((0, x0, True), (0, x1, False), (1, y0, True), (1, y1, False)):
            if len(ring) == 0:
                break
            ring = _clip_side(ring, axis, bound, keep_greater)
        if len(ring) >= 3:
            out.append(np.ascontiguousarray(ring))
    return out


def _clip_side(ring, axis, bound, keep_greater):
    v = ring[:, axis]
    inside = v >= bound if keep_greater else v <= bound
    if inside.all():
        return ring
    if not inside.any():
        return ring[:0]
    nxt = np.roll(ring, -1, axis=0)
    nin = np.roll(inside, -1)
    cross = inside != nin
    # where an edge crosses the line: the point on it, on the line exactly
    a, b = ring[cross], nxt[cross]
    t = (bound - a[:, axis]) / (b[:, axis] - a[:, axis])
    p = a + t[:, None] * (b - a)
    p[:, axis] = bound
    # each edge gives its start (if inside) then its crossing (if any)
    n = len(ring)
    keep = np.zeros((n, 2), bool)
    keep[:, 0] = inside
    keep[:, 1] = cross
    both = np.empty((n, 2, 2))
    both[:, 0] = ring
    both[cross, 1] = p
    return both[keep]


def _bits(extent: np.ndarray) -> np.ndarray:
    """subpixel_bits_for of every extent, vectorised (-1 where even S = 0
    is out of range)."""
    s = np.full(len(extent), _MAX_S, np.int64)
    for _ in range(_MAX_S + 1):
        bad = (s >= 0) & (np.floor(extent * np.exp2(s) + 0.5) > _COORD_MAX)
        if not bad.any():
            break
        s[bad] -= 1
    return s


def _fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress=None):
    """Per feature, the cells of the raster it covers and their fractions:
    (feature ids, flat cell indices row * W + col, fractions), grouped by
    feature in order; and per feature (row0, col0, S) of its window (S =
    -1 for a feature outside the raster)."""
    H, W = shape
    info = np.full((nfeat, 3), -1, np.int64)
    empty = np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0), info
    if not len(px):
        return empty
    ring_start = np.concatenate([[0], np.cumsum(part_rings)])
    pt_start = np.concatenate([[0], np.cumsum(ring_sizes)])
    # rings and points of each feature (its parts are consecutive)
    fparts = np.bincount(feature, minlength=nfeat)
    fpart_start = np.concatenate([[0], np.cumsum(fparts)])
    fring = ring_start[fpart_start]
    fpt = pt_start[fring]
    # every feature's window (the cells its box touches in the raster), its
    # vertices' extent from the window's origin and its S, all at once
    has = np.flatnonzero(fpt[1:] > fpt[:-1])
    lo = np.full((nfeat, 2), np.inf)
    hi = np.full((nfeat, 2), -np.inf)
    lo[has] = np.minimum.reduceat(px, fpt[:-1][has], axis=0)
    hi[has] = np.maximum.reduceat(px, fpt[:-1][has], axis=0)
    with np.errstate(invalid="ignore"):
        c0 = np.maximum(np.floor(lo[:, 0]), 0)
        r0 = np.maximum(np.floor(lo[:, 1]), 0)
        c1 = np.minimum(np.ceil(hi[:, 0]), W)
        r1 = np.minimum(np.ceil(hi[:, 1]), H)
    inside = (c1 > c0) & (r1 > r0)
    c0, r0, c1, r1 = (np.where(inside, v, 0).astype(np.int64) for v in (c0, r0, c1, r1))
    hw, ww = r1 - r0, c1 - c0
    origin = np.c_[c0, r0].astype(np.float64)
    npts = np.diff(fpt)
    local = px - np.repeat(origin, npts, axis=0)
    extent = np.zeros(nfeat)
    extent[has] = np.maximum.reduceat(np.abs(local).max(axis=1), fpt[:-1][has])
    s_box = _bits(np.maximum(hw, ww) + 1.0)
    s_own = _bits(extent)
    wide = inside & (s_box < 0)
    if wide.any():
        k = int(np.flatnonzero(wide)[0])
        raise InputError("geometries: feature %d covers a window of %d x %d cells: wider than the "
                         "coverage path's range (2^27 px)" % (k, hw[k], ww[k]))
    rs = ring_sizes.tolist()
    covs, ids = [], []
    for k in np.flatnonzero(inside).tolist():
        if progress is not None:
            progress(k)
        h, w = int(hw[k]), int(ww[k])
        a, r_a, r_b = int(fpt[k]), int(fring[k]), int(fring[k + 1])
        rings = []
        for n in rs[r_a:r_b]:
            if n >= 3:
                rings.append(local[a:a + n])
            a += n
        s = int(s_own[k])
        if s < s_box[k]:
            # far outside the raster: clipped to the window plus a cell,
            # so that S is the window's
            pts = local[fpt[k]:fpt[k + 1]]
            rings = _clip_rings(pts, ring_sizes[r_a:r_b], -1.0, -1.0, w + 1.0, h + 1.0)
            s = int(s_box[k])
            if not rings:
                continue
        if not rings:
            continue
        info[k] = (r0[k], c0[k], s)
        covs.append(polygon_coverage(rings, (h, w), rule=rule, method="area", subpixel_bits=s,
                                     dtype=np.float64).ravel())
        ids.append(k)
    if not covs:
        return empty
    # the cells with a fraction, all windows at once
    ids = np.asarray(ids, np.int64)
    sizes = hw[ids] * ww[ids]
    start = np.concatenate([[0], np.cumsum(sizes)])
    cov = np.concatenate(covs)
    nz = np.flatnonzero(cov)
    g = np.searchsorted(start, nz, side="right") - 1
    f = ids[g]
    rr, cc = np.divmod(nz - start[g], ww[f])
    cells = (rr + r0[f]) * W + (cc + c0[f])
    return f, cells, cov[nz], info


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
    fs, xs, cs = f[order], x[order], c[order]
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
    ops = _parse_stats(stats)
    if coverage_weight not in ("fraction", "none"):
        raise InputError("coverage_weight must be 'fraction' or 'none', not %r" % (coverage_weight,))
    if output not in ("auto", "pandas", "records"):
        raise InputError("output must be 'auto', 'pandas' or 'records', not %r" % (output,))
    gis._core._name(rule, "fill rule", gis._core.RULES)
    data, mask, transform, nodata, banded = _raster(raster, transform, nodata)
    B, H, W = data.shape
    wt_raster = None
    if weights is not None:
        wt_raster = np.asarray(weights, dtype=np.float64)
        if wt_raster.shape != (H, W):
            raise InputError("weights: shape %r differs from the raster's (%d, %d)" % (wt_raster.shape, H, W))
    elif any(op.startswith("weighted") for _, op, _ in ops):
        raise InputError("stats: %s need weights=" % ", ".join(c for c, op, _ in ops if op.startswith("weighted")))
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
        f, cells, c, _ = _fractions(px, ring_sizes, part_rings, feature, nfeat, (H, W), rule,
                                    bar if bar.active else None)
    finally:
        bar.close()
    if coverage_weight == "none":
        c = np.ones_like(c)
    columns: Dict[str, np.ndarray] = {}
    flat = data.reshape(B, H * W)
    for band in range(B):
        x = flat[band][cells]
        valid = np.ones(len(x), bool)
        if x.dtype.kind == "f":
            valid &= ~np.isnan(x)
        if nodata is not None:
            valid &= x != nodata
        if mask is not None:
            valid &= ~mask[band].ravel()[cells]
        x = x.astype(np.float64)
        sel = valid if not valid.all() else slice(None)
        wt = None if wt_raster is None else wt_raster.ravel()[cells][sel]
        res = _band_stats(ops, f[sel], x[sel], c[sel], wt, nfeat)
        for column, v in res.items():
            columns[("band_%d_%s" % (band + 1, column)) if banded else column] = v
    return _table(columns, nfeat, index, output)


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

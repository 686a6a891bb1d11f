"""Coverage fractions on the caller's coordinates (private).

Every feature (a Polygon or MultiPolygon, its rings filled together under
the fill rule) is taken to float64 pixel coordinates by the transform's
inverse (as rasterize takes them), then to its window (the raster cells
its bounding box touches), and one ``polygon_coverage`` call gives the
fraction of each cell of the window.  So these functions get whatever
``polygon_coverage`` does: the snapping precision S is chosen per window
by :func:`_bits`, which asks ``polygon_coverage`` once which S it takes
(16 on the 32-bit coverage path; 32 once it has a 64-bit path, as the
binary fill has).

Public through rastrum: :func:`coverage_fractions` (per feature, the
cells and their fractions: exactextract's ``cell_id`` and ``coverage``)
and ``rasterize(..., coverage=...)`` (gis.py calls :func:`burn_coverage`).
See docs/gis.md.
"""

from __future__ import annotations

from typing import Any, Callable, Iterable, List, Literal, Optional, Tuple, Union, overload

import numpy as np

from . import _core, gis
from ._core import InputError
from ._coverage import polygon_coverage
from ._native import ffi, lib
from ._typing import CoverageMethod, Rule

__all__ = ["coverage_fractions", "COVERAGE_DTYPES"]

#: The dtypes of coverage output: fractions (float32, float64) or levels
#: (uint8: floor(a*255 + 1/2), uint16: floor(a*65535 + 1/2)).
COVERAGE_DTYPES = ("float32", "float64", "uint8", "uint16")

_LIMITS: Optional[Tuple[int, Callable[[np.ndarray, np.ndarray], np.ndarray]]] = None


def _limits():
    """(largest S polygon_coverage takes, in_range(extent, S)): asked of
    polygon_coverage once, so that a wider coverage path in the core is
    used as soon as polygon_coverage takes it."""
    global _LIMITS
    if _LIMITS is None:
        s64 = lib.RAST_MAX_SUBPIXEL_BITS64
        try:
            polygon_coverage(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), (1, 1), method="area",
                             subpixel_bits=s64, dtype=np.float64)
        except InputError:
            _LIMITS = (lib.RAST_MAX_SUBPIXEL_BITS, _fits32)
        else:
            pix = lib.RAST_COORD64_PIXEL_BITS

            def fits64(extent, s):  # |v| * 2^S, rounded, <= 2^(S + 28) - 1
                return np.floor(extent * np.exp2(s) + 0.5) <= np.exp2(s + pix) - 1

            _LIMITS = (s64, fits64)
    return _LIMITS


def _fits32(extent, s):
    return np.floor(extent * np.exp2(s) + 0.5) <= lib.RAST_COORD_MAX


def _bits(extent: np.ndarray, method: str = "area") -> np.ndarray:
    """Per extent (the largest |coordinate| of a window's vertices, in
    pixels), the largest S at which polygon_coverage takes them with
    `method` (the 64-bit path, when there is one, takes "area" only); -1
    where even S = 0 is out of range."""
    top, fits = _limits() if method == "area" else (lib.RAST_MAX_SUBPIXEL_BITS, _fits32)
    s = np.full(len(extent), top, np.int64)
    for _ in range(top + 1):
        bad = (s >= 0) & ~fits(extent, s)
        if not bad.any():
            break
        s[bad] -= 1
    return s


def subpixel_bits_for(extent: float) -> int:
    """The largest S at which a vertex of |coordinate| <= `extent` pixels
    snaps inside polygon_coverage's range (S <= 16 and floor(extent * 2^S
    + 1/2) <= 2^27 - 1 on the 32-bit coverage path).  A vertex moves by at
    most 2^-(S+1) px in x and in y, so a fraction is off by about 2^-S of a
    cell per edge crossing it (docs/gis.md has the measured figures)."""
    return int(_bits(np.array([float(extent)]))[0])


# ---- geometries --------------------------------------------------------------------------

def _geometries(geometries, what="geometries"):
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
            raise InputError("%s must be an iterable of geometries, not one geometry; wrap it in a list" % what)
        try:
            geoms = list(geometries)
        except TypeError:
            raise InputError("%s must be an iterable of geometries, not %r"
                             % (what, type(geometries).__name__)) from None
    return geoms, index


def _polygons_only(kind, feature, what):
    if len(kind) and (kind != gis._KIND_POLYGON).any():
        k = int(np.flatnonzero(kind != gis._KIND_POLYGON)[0])
        raise InputError("%s: feature %d is not a polygon (coverage fractions take Polygon and "
                         "MultiPolygon)" % (what, feature[k]))


# ---- the fractions of every feature -----------------------------------------------------------

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


def _windows(px, ring_sizes, part_rings, feature, nfeat, shape, method):
    """Every feature's window (the cells its box touches in the raster),
    its vertices less the window's origin, their extent and the S of the
    window (s_box) and of the vertices (s_own), all at once; InputError
    for a window wider than the coverage path's range.  Returns
    (fpt, fring, inside, r0, c0, hw, ww, local, s_own, s_box): per feature
    its first point and ring (n + 1 entries) and the rest per feature."""
    H, W = shape
    ring_start = np.concatenate([[0], np.cumsum(part_rings)])
    pt_start = np.concatenate([[0], np.cumsum(ring_sizes)])
    # rings and points of each feature (its parts are consecutive)
    fparts = np.bincount(feature, minlength=nfeat)
    fpart_start = np.concatenate([[0], np.cumsum(fparts)])
    fring = ring_start[fpart_start]
    fpt = pt_start[fring]
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
    s_box = _bits(np.maximum(hw, ww) + 1.0, method)
    s_own = _bits(extent, method)
    wide = inside & (s_box < 0)
    if wide.any():
        k = int(np.flatnonzero(wide)[0])
        raise InputError("geometries: feature %d covers a window of %d x %d cells: wider than the "
                         "coverage path's range" % (k, hw[k], ww[k]))
    return fpt, fring, inside, r0, c0, hw, ww, local, s_own, s_box


def feature_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress=None, *,
                      method="area", dtype=np.float64):
    """Per feature, the cells of the raster it covers and their fractions:
    (feature ids, flat cell indices row * W + col, fractions in `dtype`,
    zeros left out), grouped by feature in order, each feature's cells in
    increasing order; and per feature (row0, col0, S) of its window (S =
    -1 for a feature outside the raster)."""
    H, W = shape
    dtype = np.dtype(dtype)
    info = np.full((nfeat, 3), -1, np.int64)
    empty = np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0, dtype), info
    if not len(px):
        return empty
    fpt, fring, inside, r0, c0, hw, ww, local, s_own, s_box = _windows(px, ring_sizes, part_rings, feature,
                                                                         nfeat, shape, method)
    rs = ring_sizes.tolist()
    sizes32 = np.ascontiguousarray(ring_sizes, np.uint32)
    covs, ids = [], []
    # the 64-bit "area" path straight to the covered cells (C: no dense
    # window, no numpy pass over it), where polygon_coverage would take it
    sparse = method == "area" and dtype.kind == "f"
    fast_ids, fast_n, fast_cells, fast_cov = [], [], [], []
    # (plain lists: a numpy scalar a feature costs more than the C call of a small one)
    L_hw, L_ww, L_fpt, L_fring = hw.tolist(), ww.tolist(), fpt.tolist(), fring.tolist()
    L_own, L_box, L_r0, L_c0 = s_own.tolist(), s_box.tolist(), r0.tolist(), c0.tolist()
    done, done_s = [], []
    for k in np.flatnonzero(inside).tolist():
        if progress is not None:
            progress(k + 1)
        h, w = L_hw[k], L_ww[k]
        a, r_a, r_b = L_fpt[k], L_fring[k], L_fring[k + 1]
        own = rs[r_a:r_b]
        whole = min(own) >= 3 if own else False  # every ring kept: the feature's points as they are
        rings = []
        if not whole:
            for n in own:
                if n >= 3:
                    rings.append(local[a:a + n])
                a += n
        s = L_own[k]
        if s < L_box[k]:
            # far outside the raster: clipped to the window plus a cell,
            # so that S is the window's
            pts = local[L_fpt[k]:L_fpt[k + 1]]
            rings = _clip_rings(pts, ring_sizes[r_a:r_b], -1.0, -1.0, w + 1.0, h + 1.0)
            s = L_box[k]
            whole = False
            if not rings:
                continue
        if not whole and not rings:
            continue
        done.append(k)
        done_s.append(s)
        if sparse and s > _MAX_S32:
            if whole:
                pts, sz = local[L_fpt[k]:L_fpt[k + 1]], sizes32[r_a:r_b]
            else:
                pts, sz = None, None
            cells_k, cov_k = _cells64(rings, rule, s, h, w, L_r0[k] * W + L_c0[k], W, pts, sz)
            if len(cells_k):
                fast_ids.append(k)
                fast_n.append(len(cells_k))
                fast_cells.append(cells_k)
                fast_cov.append(cov_k if dtype == np.float64 else cov_k.astype(dtype))
            continue
        if whole:
            rings = [local[a + o:a + o + n] for o, n in zip(np.cumsum([0] + own[:-1]).tolist(), own)]
        covs.append(polygon_coverage(rings, (h, w), rule=rule, method=method, subpixel_bits=s,
                                     dtype=dtype).ravel())
        ids.append(k)
    if done:
        done_a = np.asarray(done, np.int64)
        info[done_a] = np.c_[r0[done_a], c0[done_a], np.asarray(done_s, np.int64)]
    fast = None
    if len(fast_ids) == 1:  # (one feature: its arrays as they are, no copy)
        fast = (np.full(fast_n[0], fast_ids[0], np.int64), fast_cells[0], fast_cov[0])
    elif fast_ids:
        fast = (np.repeat(np.asarray(fast_ids, np.int64), fast_n), np.concatenate(fast_cells),
                np.concatenate(fast_cov))
    if not covs:
        return fast + (info,) if fast is not None else empty
    # the cells with a fraction, all windows at once
    ids = np.asarray(ids, np.int64)
    sizes = hw[ids] * ww[ids]
    start = np.concatenate([[0], np.cumsum(sizes)])
    cov = np.concatenate(covs)
    nzmask = cov != 0
    nz = np.flatnonzero(nzmask)
    # the window of each nonzero cell: windows in order, so a repeat of
    # each window's count of them (no search)
    counts = np.add.reduceat(nzmask, start[:-1]) if len(nz) else np.zeros(len(ids), np.int64)
    g = np.repeat(np.arange(len(ids)), counts)
    f = ids[g]
    local = nz - start[g]
    w_f = ww[f]
    rr = local // w_f
    # row r0 + rr, column c0 + (local - rr * w): cell (r0 + rr) * W + c0 + local - rr * w
    cells = local + (r0[f] * W + c0[f]) + rr * (W - w_f)
    cov = cov[nz]
    if fast is not None:  # both paths (features past the 64-bit range): in feature order
        f, cells, cov = (np.concatenate([a, b]) for a, b in zip(fast, (f, cells, cov)))
        order = np.argsort(f, kind="stable")
        f, cells, cov = f[order], cells[order], cov[order]
    return f, cells, cov, info


def fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress=None, *, method="area",
              dtype=np.float64):
    """feature_fractions' (feature ids, cells, fractions), float64 "area"
    through zonal_stats' one C call for many windows (_zonal._all_fractions:
    the same bits, tested so), the rest through feature_fractions."""
    if method == "area" and np.dtype(dtype) == np.float64:
        from ._zonal import _all_fractions
        return _all_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress)
    return feature_fractions(px, ring_sizes, part_rings, feature, nfeat, shape, rule, progress, method=method,
                             dtype=dtype)[:3]


def _cells64(rings, rule, s, h, w, cell0, row_step, pts=None, sizes=None):
    """(cell ids, float64 fractions) of the nonzero cells of the (h, w)
    window of `rings` (float64 pixel coordinates from the window's
    origin; or `pts` and their uint32 ring `sizes`, as they are) on the
    64-bit "area" path at S = s: the cells polygon_coverage(rings, (h, w),
    method="area", subpixel_bits=s) gives, without the dense window
    (rastpy_coverage64_cells)."""
    opts = _OPTS64.get((rule, s))
    if opts is None:
        from ._coverage import _opts
        opts = _OPTS64[(rule, s)] = _opts("area", rule, s, 0.5, "polygon_coverage")
    if pts is None:
        pts = np.ascontiguousarray(np.concatenate(rings) if len(rings) > 1 else rings[0], np.float64)
        sizes = np.array([len(r) for r in rings], np.uint32)
    cells = np.empty(h * w, np.int64)
    cov = np.empty(h * w, np.float64)
    count = _ffi_new("size_t *")
    result = lib.rastpy_coverage64_cells(_from_buffer("double[]", pts), len(pts), _from_buffer("uint32_t[]", sizes),
                                         len(sizes), opts, h, w, cell0, row_step, 0,
                                         _from_buffer("int64_t[]", cells), _from_buffer("double[]", cov), count)
    if result:
        _core._check_glue(result, pts, s, "geometries", sizes.tolist(), True)
    n = count[0]
    return cells[:n], cov[:n]  # (the pages past n were never touched)


_OPTS64: dict = {}
_ffi_new, _from_buffer = ffi.new, ffi.from_buffer
_MAX_S32 = lib.RAST_MAX_SUBPIXEL_BITS


def _method(method):
    from ._coverage import METHODS
    if not isinstance(method, str) or method not in METHODS:
        raise InputError("coverage method %r is unknown; choose one of: %s" % (method, ", ".join(METHODS)))
    return method


def _coverage_dtype(dtype, what="dtype"):
    try:
        dt = np.dtype(dtype)
    except TypeError:
        raise InputError("%s %r is not a numpy dtype; coverage takes: %s"
                         % (what, dtype, ", ".join(COVERAGE_DTYPES))) from None
    if dt.name not in COVERAGE_DTYPES or not dt.isnative:
        raise InputError("%s %s: coverage takes %s (fractions, or levels floor(a*255 + 1/2) and "
                         "floor(a*65535 + 1/2))" % (what, dt, ", ".join(COVERAGE_DTYPES)))
    return dt


# ---- public: per-feature sparse fractions ---------------------------------------------------

@overload
def coverage_fractions(
    geometries: Iterable[Any], out_shape: Tuple[int, int], transform: gis.Transform = ..., *,
    rule: Rule = ..., method: CoverageMethod = ..., dtype: Any = ..., flat: Literal[False] = ...,
    progress: Union[bool, Callable[[int, int], Any], None] = ...,
) -> List[Tuple[np.ndarray, np.ndarray]]: ...


@overload
def coverage_fractions(
    geometries: Iterable[Any], out_shape: Tuple[int, int], transform: gis.Transform = ..., *,
    rule: Rule = ..., method: CoverageMethod = ..., dtype: Any = ..., flat: Literal[True],
    progress: Union[bool, Callable[[int, int], Any], None] = ...,
) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...


def coverage_fractions(
    geometries: Iterable[Any],
    out_shape: Tuple[int, int],
    transform: gis.Transform = gis.IDENTITY,
    *,
    rule: Rule = "evenodd",
    method: CoverageMethod = "area",
    dtype: Any = "float64",
    flat: bool = False,
    progress: Union[bool, Callable[[int, int], Any], None] = None,
) -> Union[List[Tuple[np.ndarray, np.ndarray]], Tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Per feature, the raster cells it covers and the fraction of each
    (exactextract's ``cell_id`` and ``coverage``), without a dense array:
    the memory is the covered cells', however far apart the features lie.

    Parameters
    ----------
    geometries : iterable of polygons, a GeoSeries or a GeoDataFrame
        Polygon or MultiPolygon (shapely, ``__geo_interface__`` or GeoJSON
        mappings) in world coordinates; a feature's rings are filled
        together under `rule`.
    out_shape : (int, int)
        (height, width) of the raster.
    transform : affine.Affine or 6 numbers
        Pixel to world, as for ``rasterize``.
    rule : {"evenodd", "nonzero"}
    method : str
        ``polygon_coverage``'s methods: "area" (the exact area of the
        snapped polygon, the default), "ss2" ... "ss16", "accumulate".
    dtype : float64, float32, uint8 or uint16
        Fractions, or levels as ``polygon_coverage`` makes them.
    flat : bool
        False: a list with one (cell_id, coverage) pair of arrays per
        feature; True: three flat arrays (feature, cell_id, coverage),
        sorted by feature then cell.
    progress : bool or callable(done, total), optional

    Returns
    -------
    list of (cell_id, coverage), or (feature, cell_id, coverage)
        cell_id = row * width + column (int64, increasing; exactextract's
        numbering); cells of fraction 0 are left out, so a feature outside
        the raster has two empty arrays.

    Raises
    ------
    InputError
        A geometry that is not a polygon, a bad shape, transform, rule,
        method or dtype.

    Examples
    --------
    >>> import rastrum
    >>> sq = {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2, 0.5), (2, 1), (0.5, 1)]]}
    >>> rastrum.coverage_fractions([sq], (2, 3))
    [(array([0, 1]), array([0.25, 0.5 ]))]
    """
    _core._name(rule, "fill rule", _core.RULES)
    method = _method(method)
    dt = _coverage_dtype(dtype)
    if not isinstance(flat, (bool, np.bool_)):
        raise InputError("flat must be True or False, not %r" % (flat,))
    h, w = _shape(out_shape)
    inv = gis._inverse(gis._transform6(transform))
    geoms, _ = _geometries(geometries)
    xy, ring_sizes, part_rings, kind, feature, _ = gis._flatten(geoms)
    _polygons_only(kind, feature, "geometries")
    px = gis._pixels(xy, inv, ring_sizes, part_rings, feature)
    bar = gis._Progress(progress, len(geoms))
    try:
        f, cells, cov = fractions(px, ring_sizes, part_rings, feature, len(geoms), (h, w), rule,
                                  bar if bar.active else None, method=method, dtype=dt)
    finally:
        bar.close()
    if flat:
        return f, cells, cov
    bounds = np.searchsorted(f, np.arange(len(geoms) + 1))
    return [(cells[bounds[k]:bounds[k + 1]], cov[bounds[k]:bounds[k + 1]]) for k in range(len(geoms))]


def _shape(out_shape):
    try:
        n = len(out_shape)
    except TypeError:
        n = None
    if n != 2:
        raise InputError("Invalid out_shape %r: must be 2-D (height, width)" % (out_shape,))
    h, w = _core.int_pair(out_shape, "Invalid out_shape %r: must be 2-D (height, width)",
                          "out_shape must hold two ints, not %r")
    if h <= 0 or w <= 0 or h > lib.RAST_MAX_DIM or w > lib.RAST_MAX_DIM:
        raise InputError("out_shape %r: width and height must be > 0 and at most %d" % (out_shape, lib.RAST_MAX_DIM))
    return h, w


# ---- rasterize(coverage=...) --------------------------------------------------------------

def check_values(vals, dt):
    """Levels (uint8, uint16) are the coverage itself: every value 1."""
    if dt.kind == "u":
        for k, v in enumerate(vals):
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)) or v != 1:
                raise InputError("shapes: feature %d: value %r: coverage levels (%s) burn the level itself, so "
                                 "every value must be 1; a float32/float64 dtype burns value * fraction"
                                 % (k, v, dt))


def burn_coverage(target, px, ring_sizes, part_rings, kind, feature, nfeat, values, merge, rule, method,
                  progress=None):
    """Merge every feature's coverage into target (float: value *
    fraction; uint8/uint16: levels), features in order; raises before
    writing anything."""
    dt = target.dtype
    _polygons_only(kind, feature, "shapes")
    f, cells, cov = fractions(px, ring_sizes, part_rings, feature, nfeat, target.shape, rule, progress,
                              method=method, dtype=np.float64 if dt.kind == "f" else dt)
    merge_cells(target, f, cells, cov, values, merge)


def merge_cells(target, f, cells, cov, values, merge):
    """Merge the fractions cov of features f at flat cells (row * W + col
    of target) into target, features in order: float targets take
    value * fraction, uint8/uint16 the levels; replace, add (levels
    saturate) or max (a NaN cell takes the fraction)."""
    if not len(f):
        return
    dt = target.dtype
    if dt.kind == "f":
        contrib = np.asarray(values, np.float64)[f] * cov
        work = np.float64
    else:
        contrib = cov.astype(np.int64)
        work = np.int64
    # the k-th feature covering each cell is its layer k (features in order)
    order = np.argsort(cells, kind="stable")
    cs = cells[order]
    run = np.r_[True, cs[1:] != cs[:-1]]
    W = target.shape[1]
    if merge == "replace":
        last = order[np.r_[run[1:], True]]
        rr, cc = np.divmod(cells[last], W)
        target[rr, cc] = contrib[last].astype(dt)
        return
    starts = np.flatnonzero(run)
    rank = np.arange(len(cs)) - np.repeat(starts, np.diff(np.r_[starts, len(cs)]))
    top = None if dt.kind == "f" else np.iinfo(dt).max
    for k in range(int(rank.max()) + 1):
        sel = order[rank == k]
        rr, cc = np.divmod(cells[sel], W)
        old = target[rr, cc].astype(work)
        if merge == "add":
            new = old + contrib[sel]
            if top is not None:
                new = np.minimum(new, top)
        else:  # max; a NaN cell takes the fraction
            new = np.fmax(old, contrib[sel])
        target[rr, cc] = new.astype(dt)

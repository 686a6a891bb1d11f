"""Masks for machine learning: many polygons in one C call.

``masks(polygons, shape)`` gives one (H, W) mask per polygon as an
(N, H, W) bool array; ``labels(polygons, shape)`` burns each instance's
id into one label image, later instances on top.  Both go through the
batch engine (``rastrum._batch``): all polygons checked, then drawn in one
C call, exactly (DESIGN section 1).
"""

from array import array
from itertools import chain

from typing import Any, Callable, Iterable, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _batch, _core, _path
from ._path import path_rings
from ._native import ffi, lib
from ._core import InputError
from ._typing import BatchRule, PolygonAlgorithm, Shape

_F64 = np.dtype(np.float64)
_RULES = ("union", "evenodd", "nonzero", "coco")


def _lengths(items):
    """len() of each item as uint32 (C unsigned int): array.array fills
    from map() a quarter faster than np.fromiter converting each int."""
    return np.frombuffer(array("I", map(len, items)), np.uintc).astype(np.uint32, copy=False)


def _packed(polygons):
    """The batch packed for the C call when every polygon is a float64
    (N, 2) array (one ring) or every one a list of them, as
    ``coco.rings`` makes them: (points (P, 2), ring sizes, rings per
    polygon), each ring a part.  None for anything else (the general path
    then checks and names what is wrong).  A handful of C-level passes over
    the list instead of Python per polygon: a batch of 10,000 instances
    spends its time drawing, not here."""
    types = set(map(type, polygons))
    if types == {np.ndarray}:
        rings, poly_rings = polygons, None
    elif types == {list}:
        rings = list(chain.from_iterable(polygons))
        if set(map(type, rings)) != {np.ndarray}:
            return None
        poly_rings = _lengths(polygons)
    else:
        return None
    sizes = _lengths(rings)
    if not len(sizes) or not sizes.all():
        return None  # empty rings are dropped: the general path
    try:
        # casting="no": float64 rings only (bool, object, other widths take
        # the general path, which converts exactly or refuses); equal
        # dimensions, so a (P, 2) result means every ring was (N, 2)
        pts = np.concatenate(rings, dtype=_F64, casting="no")
    except (TypeError, ValueError):
        return None
    if pts.ndim != 2 or pts.shape[1] != 2:
        return None
    if poly_rings is None:
        poly_rings = np.ones(len(rings), np.uint32)
    return pts, sizes, poly_rings, np.ones(len(sizes), np.int8)


def _polygons(polygons, what, subpixel_bits=8, tolerance=None):
    """The batch packed: (points float64 (P, 2), ring sizes uint32, rings
    per polygon uint32, orientation int8 per ring) for the union rule: +1
    for parts, -1 for holes (geometries' interiors); a Path's (or
    matplotlib Path's) rings, flattened within `tolerance`, keep the turn
    they have (the union rule fills a Path non-zero as it runs)."""
    if isinstance(polygons, _batch.Polygons):
        return polygons.packed()
    if isinstance(polygons, np.ndarray):
        if polygons.ndim != 3 or polygons.shape[-1] != 2:
            raise InputError("%s: an array of polygons must be (N, K, 2) (N rings of K points), "
                             "not shape %s" % (what, polygons.shape))
        polygons = list(polygons)
    elif _core.is_feature_collection(polygons):
        raise InputError("%s: got %s" % (what, _core.FEATURE_COLLECTION))
    elif _core._geo_mapping(polygons) is not None:
        raise InputError("%s: got one geometry; a list of polygons is needed ([geometry] for one)" % what)
    try:
        polygons = list(polygons)
    except TypeError:
        raise InputError("%s: polygons must be a list of polygons (each a list of (N, 2) rings, an "
                         "(N, 2) ring, an (N, 1, 2) contour or a shapely polygon), not %s"
                         % (what, type(polygons).__name__)) from None
    if tolerance is not None:
        _path._tolerance(tolerance)
    packed = _packed(polygons)
    if packed is not None:
        return packed
    out, orient = [], []
    for k, p in enumerate(polygons):
        holes = []
        try:
            path = _path.as_path(p)
            if path is not None:
                rings = [r for r in path_rings(path, subpixel_bits, tolerance)]
                out.append(rings)
                orient.extend(-1 if _area2(r) < 0 else 1 for r in rings)
                continue
            rings = _core.rings_f64(p, holes)
        except InputError as e:
            raise InputError("%s: polygon %d: %s" % (what, k, e)) from None
        out.append(rings)
        orient.extend(-1 if h else 1 for h in holes)
    return _batch.pack(out) + (np.array(orient, np.int8),)


def _area2(ring):
    """Twice the signed (shoelace) area of a ring."""
    x, y = ring[:, 0], ring[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _progress(progress, total):
    """A function called with the number of polygons done, or None."""
    if not progress:
        return None
    if callable(progress):
        return lambda done: progress(done, total)
    try:
        from tqdm.auto import tqdm
    except ImportError:
        raise InputError("progress=True needs tqdm (pip install tqdm); or pass a function "
                         "progress(done, total)") from None
    bar = tqdm(total=total)

    def update(done, _last=[0]):
        bar.update(done - _last[0])
        _last[0] = done
        if done >= total:
            bar.close()
    return update


def _chunks(n, report):
    """Index ranges of the batch: one, or about 100 when progress is shown."""
    if report is None or n < 2:
        return [(0, n)]
    step = max(1, -(-n // 100))
    return [(i, min(n, i + step)) for i in range(0, n, step)]


def _opts(rule, algorithm, subpixel_bits, sample_offset, what):
    if not isinstance(rule, str) or rule not in _RULES:
        raise InputError("%s: unknown rule %r; choose one of: %s" % (what, rule, ", ".join(_RULES)))
    if rule == "coco":
        if (algorithm, subpixel_bits, sample_offset) != ("aet", 8, 0.5):
            raise InputError("%s: rule=\"coco\" is pycocotools' own rasterisation, which has no algorithm, "
                             "subpixel_bits or sample_offset to choose" % what)
        return None
    return _core.fill_opts(algorithm, "nonzero" if rule == "union" else rule, subpixel_bits, sample_offset)


def _coco_planes(packed, h, w, what):
    """rule="coco": (N', H, W) bool, the union of each polygon's rings as
    pycocotools draws them (frPyObjects on every ring, then merge: what
    rastrum.coco.frPyObjects reproduces bit for bit), for the N' polygons
    that have rings; and their indices."""
    from . import coco

    pts, sizes, poly_rings, _ = packed
    nrings = len(sizes)
    if not nrings or not h or not w:
        return np.zeros((0, h, w), bool), np.zeros(0, np.int64)
    xy = np.ascontiguousarray(pts, np.float64)
    sizes = np.ascontiguousarray(sizes, np.uint32)
    r, data, offsets = coco._fr_call(ffi.from_buffer("double[]", xy), ffi.from_buffer("uint32_t[]", sizes),
                                     nrings, h, w, "coco")
    if r > 0:
        lib.rastpy_free(data[0])
        ring = int(np.searchsorted(np.cumsum(sizes, dtype=np.int64), r - 1, side="right"))
        poly = int(np.searchsorted(np.cumsum(poly_rings, dtype=np.int64), ring, side="right"))
        x, y = xy[r - 1].tolist()
        raise InputError("%s: polygon %d: point (%r, %r) is NaN, infinite or outside +-%d pixels (rule=\"coco\": "
                         "pycocotools' rule works on 5x upsampled int coordinates)"
                         % (what, poly, x, y, lib.RAST_COCO_COORD_MAX // 5))
    coco._glue(r, what)
    rings = coco.decode(coco._objs(coco._unpack(data, offsets, nrings), [(h, w)] * nrings))
    has = np.flatnonzero(poly_rings)
    starts = np.concatenate([[0], np.cumsum(poly_rings, dtype=np.int64)[:-1]])[has]
    return np.logical_or.reduceat(np.moveaxis(rings, 2, 0), starts, axis=0), has


def _burn(out, packed, opts, rule, values, merge, planes, what, report):
    """Burn in chunks (one when no progress is shown); orientation per
    ring for the union rule."""
    pts, sizes, poly_rings, orient = packed
    n = len(poly_rings)
    if not n:
        return
    chunks = _chunks(n, report)
    if len(chunks) == 1:
        _batch.burn_packed(out, pts, sizes, poly_rings, opts, values, merge, planes, what,
                           orient if rule == "union" else None)
        if report is not None:
            report(n)
        return
    ring_at = np.zeros(n + 1, np.int64)
    np.cumsum(poly_rings, out=ring_at[1:])
    pt_at = np.zeros(len(sizes) + 1, np.int64)
    np.cumsum(sizes, out=pt_at[1:])
    for i0, i1 in chunks:
        r0, r1 = ring_at[i0], ring_at[i1]
        _batch.burn_packed(out[i0:i1] if planes else out, pts[pt_at[r0]:pt_at[r1]], sizes[r0:r1],
                           poly_rings[i0:i1], opts, None if values is None else values[i0:i1], merge,
                           planes, what, orient[r0:r1] if rule == "union" else None, i0)
        report(i1)


def masks(polygons: Iterable[Any], shape: Shape, *, rule: BatchRule = "union",
          algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
          progress: Union[bool, Callable[[int, int], Any]] = False,
          tolerance: Optional[float] = None) -> npt.NDArray[np.bool_]:
    """One mask per polygon, in one C call.

    Parameters
    ----------
    polygons : list
        Each polygon is a list of rings (parts), or one ring.  A ring is an
        (N, 2) array-like of (x, y), an (N, 1, 2) OpenCV contour, and a
        polygon may also be a shapely (Multi)Polygon or anything with
        ``__geo_interface__``.  A COCO segmentation (flat lists) becomes
        rings through ``rastrum.coco.rings``; a list of them, all at once
        and fastest, through ``rastrum.coco.polygons``.  Rings of 1 or 2 points draw
        nothing.
    shape : (int, int)
        (height, width) of each mask.
    rule : {"union", "evenodd", "nonzero", "coco"}
        "union" (the default): a polygon is the union of its parts, less
        its geometry's holes: each ring is turned to positive area (holes
        to negative), then filled under the non-zero rule.  For parts that
        do not cross themselves (COCO parts, contours, valid geometries)
        that is exactly the union; where a part crosses itself, its lobes
        wound the other way subtract.  "evenodd" and "nonzero" take the
        rings as given.  These three are the library's exact rule
        (docs/semantics.md).  "coco" is pycocotools' own rasterisation,
        bit for bit: each ring drawn as ``pycocotools.mask.frPyObjects``
        draws a polygon (its points scaled 5x and rounded, not the exact
        rule), the rings of a polygon united as ``mask.merge`` unites the
        parts of a segmentation (no holes); algorithm, subpixel_bits and
        sample_offset do not apply.
    algorithm, subpixel_bits, sample_offset
        As for ``polygon_mask``; every algorithm gives the same pixels.
    progress : bool or callable
        True shows a tqdm bar (tqdm must be installed); a function is called
        as ``progress(done, total)``.  The batch is then drawn in about 100
        calls.
    tolerance : float or None
        A polygon may be a ``rastrum.Path`` or a matplotlib ``Path`` (a
        glyph's outline): flattened within `tolerance` pixels (None: the
        Path's own, else ``Path.DEFAULT_TOLERANCE``; docs/paths.md).  Its
        subpaths keep their turn, so "union" fills it non-zero as it runs
        (a font's holes run opposite to its outlines).

    Returns
    -------
    numpy.ndarray of bool, shape (N, H, W)

    Examples
    --------
    >>> import rastrum
    >>> m = rastrum.masks([[(1, 1), (4, 1), (4, 3)], [(0, 0), (2, 0), (2, 2), (0, 2)]], (4, 5))
    >>> m.shape, m.sum(axis=(1, 2)).tolist()
    ((2, 4, 5), [3, 4])
    """
    opts = _opts(rule, algorithm, subpixel_bits, sample_offset, "masks")
    h, w = _core.shape2(shape)
    packed = _polygons(polygons, "masks", subpixel_bits, tolerance)
    n = len(packed[2])
    # Uninitialised: the C call writes every byte once ("fresh"), instead
    # of a 30 MB clearing pass and then the spans into memory it evicted.
    out = np.empty((n, h, w), bool)
    if rule == "coco":
        report = _progress(progress, n)
        out[...] = False
        planes, has = _coco_planes(packed, h, w, "masks")
        out[has] = planes
        if report is not None and n:
            report(n)
        return out
    _burn(out, packed, opts, rule, None, "fresh", True, "polygon", _progress(progress, n))
    return out


def _fit(v, dtype, default):
    """Values v as dtype, each held exactly (as Canvas(format="label") and
    rasterize refuse what their dtype cannot hold), or InputError."""
    if dtype.kind in "iu":
        info = np.iinfo(dtype)
        if v.dtype.kind == "f":
            bad = ~np.isfinite(v) | (v != np.floor(v)) | (v < info.min) | (v >= info.max + 1)
        else:
            bad = (v < info.min) | (v > info.max)
    else:
        with np.errstate(over="ignore"):
            bad = np.isfinite(v) & ~np.isfinite(v.astype(dtype))
    if bad.any():
        k = int(np.argmax(bad))
        if default:
            raise InputError("labels: %d polygons need ids 1..%d; dtype %s holds at most %d (choose a "
                             "wider dtype)" % (len(v), len(v), dtype, np.iinfo(dtype).max))
        raise InputError("labels: values[%d] = %s does not fit dtype %s" % (k, v[k].item(), dtype))
    return v.astype(dtype)


@overload
def labels(polygons: Iterable[Any], shape: Shape, values: Optional[npt.ArrayLike] = None,
           dtype: npt.DTypeLike = np.int32, *, overlap: Literal[False] = False, rule: BatchRule = "union",
           algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
           progress: Union[bool, Callable[[int, int], Any]] = False,
           tolerance: Optional[float] = None) -> npt.NDArray[Any]: ...


@overload
def labels(polygons: Iterable[Any], shape: Shape, values: Optional[npt.ArrayLike] = None,
           dtype: npt.DTypeLike = np.int32, *, overlap: Literal[True], rule: BatchRule = "union",
           algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
           progress: Union[bool, Callable[[int, int], Any]] = False,
           tolerance: Optional[float] = None) -> Tuple[npt.NDArray[Any], npt.NDArray[np.uint16]]: ...


def labels(polygons: Iterable[Any], shape: Shape, values: Optional[npt.ArrayLike] = None,
           dtype: npt.DTypeLike = np.int32, *, overlap: bool = False, rule: BatchRule = "union",
           algorithm: PolygonAlgorithm = "aet", subpixel_bits: int = 8, sample_offset: float = 0.5,
           progress: Union[bool, Callable[[int, int], Any]] = False,
           tolerance: Optional[float] = None) -> Any:
    """Burn instances into one label image, in one C call.

    Polygon k (as in ``masks``) writes values[k] (default k + 1) over its
    pixels, later polygons on top of earlier ones; the background is 0.

    Parameters
    ----------
    values : array_like, optional
        One value per polygon, each one `dtype` holds exactly (else
        InputError: 300 in uint8, -1 in uint8, 2.7 in an integer dtype).
    dtype : numpy dtype
        Of the label image: uint8 .. int64, float32, float64.
    overlap : bool
        Also return a uint16 image counting the polygons that cover each
        pixel (a count past 65535 wraps).
    tolerance : float or None
        As ``masks``: how a Path's curves are flattened.

    Returns
    -------
    numpy.ndarray (H, W) of `dtype`, or (labels, count) with `overlap`.

    Examples
    --------
    >>> import rastrum
    >>> lab, n = rastrum.labels([[(0, 0), (3, 0), (3, 2), (0, 2)], [(2, 1), (5, 1), (5, 3), (2, 3)]],
    ...                         (3, 5), overlap=True)
    >>> lab.tolist(), int(n.max())
    ([[1, 1, 1, 0, 0], [1, 1, 2, 2, 2], [0, 0, 2, 2, 2]], 2)
    """
    opts = _opts(rule, algorithm, subpixel_bits, sample_offset, "labels")
    h, w = _core.shape2(shape)
    try:
        dtype = np.dtype(dtype)
    except TypeError:
        raise InputError("labels: dtype %r is not a numpy dtype" % (dtype,)) from None
    if dtype not in _batch.DTYPES or dtype == np.bool_:
        raise InputError("labels: dtype must be one of uint8..int64, float32, float64, not %s" % dtype)
    packed = _polygons(polygons, "labels", subpixel_bits, tolerance)
    n = len(packed[2])
    if values is None:
        v = np.arange(1, n + 1)
    else:
        v = np.asarray(values)
        if v.shape != (n,):
            raise InputError("labels: values has shape %s; %s need%s shape (%d,)"
                             % (v.shape, _core.plural(n, "polygon"), "s" if n == 1 else "", n))
        if v.dtype.kind not in "iuf":
            raise InputError("labels: values must be numbers, not dtype %s" % v.dtype)
    vals = _fit(v, dtype, values is None)
    out = np.zeros((h, w), dtype)
    report = _progress(progress, n * (2 if overlap else 1))
    if rule == "coco":
        planes, has = _coco_planes(packed, h, w, "labels")
        for k, i in enumerate(has):
            out[planes[k]] = vals[i]
        if report is not None and n:
            report(n * (2 if overlap else 1))
        if not overlap:
            return out
        return out, planes.sum(axis=0, dtype=np.uint16)
    _burn(out, packed, opts, rule, vals, "replace", False, "polygon", report)
    if not overlap:
        return out
    count = np.zeros((h, w), np.uint16)
    _burn(count, packed, opts, rule, None, "add", False, "polygon",
          None if report is None else (lambda done: report(n + done)))
    return out, count

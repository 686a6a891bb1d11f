"""Masks for machine learning: many polygons in one C call.

``masks(polygons, shape)`` gives one (H, W) mask per polygon as an
(N, H, W) bool array; ``labels(polygons, shape)`` burns each instance's
id into one label image, later instances on top.  Both go through the
batch engine (``rastrum._batch``): all polygons checked, then drawn in one
C call, exactly (DESIGN section 1).
"""

import numpy as np

from . import _batch, _core
from ._core import InputError

_F64 = np.dtype(np.float64)
_RULES = ("union", "evenodd", "nonzero")


def _polygons(polygons, what):
    """(list of lists of float64 (N, 2) rings, orientation int8 per ring)
    for the union rule: +1 for parts, -1 for holes (geometries' interiors)."""
    if isinstance(polygons, np.ndarray):
        if polygons.ndim != 3 or polygons.shape[-1] != 2:
            raise InputError("%s: an array of polygons must be (N, K, 2) (N rings of K points), "
                             "not shape %s" % (what, polygons.shape))
        polygons = list(polygons)
    elif _core._geo_mapping(polygons) is not None:
        raise InputError("%s: got one geometry; a list of polygons is needed ([geometry] for one)" % what)
    try:
        polygons = list(polygons)
    except TypeError:
        raise InputError("%s: polygons must be a list of polygons (each a list of (N, 2) rings, an "
                         "(N, 2) ring, an (N, 1, 2) contour or a shapely polygon), not %s"
                         % (what, type(polygons).__name__)) from None
    out, orient = [], []
    for k, p in enumerate(polygons):
        if type(p) is np.ndarray and p.dtype == _F64 and p.ndim == 2 and p.shape[1] == 2 \
                and p.flags.c_contiguous:
            out.append([p] if len(p) else [])
            if len(p):
                orient.append(1)
            continue
        if type(p) is list and p and all(type(r) is np.ndarray and r.dtype == _F64 and r.ndim == 2
                                         and r.shape[1] == 2 and r.flags.c_contiguous and len(r) for r in p):
            out.append(p)  # rings as coco.rings makes them
            orient.extend([1] * len(p))
            continue
        holes = []
        try:
            rings = _core.rings_f64(p, holes)
        except InputError as e:
            raise InputError("%s: polygon %d: %s" % (what, k, e)) from None
        out.append(rings)
        orient.extend(-1 if h else 1 for h in holes)
    return out, np.array(orient, np.int8)


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
    return _core.fill_opts(algorithm, "nonzero" if rule == "union" else rule, subpixel_bits, sample_offset)


def _burn(out, polys, orient, opts, rule, values, merge, planes, what, report):
    """Burn in chunks (one when no progress is shown); orientation per
    ring for the union rule."""
    n = len(polys)
    if not n:
        return
    ring_at = np.zeros(n + 1, np.int64)
    if rule == "union" and n:
        np.cumsum([len(p) for p in polys], out=ring_at[1:])
    for i0, i1 in _chunks(n, report):
        _batch.burn(out[i0:i1] if planes else out, polys[i0:i1], opts,
                    None if values is None else values[i0:i1], merge, planes, what,
                    orient[ring_at[i0]:ring_at[i1]] if rule == "union" else None)
        if report is not None:
            report(i1)


def masks(polygons, shape, *, rule="union", algorithm="aet", subpixel_bits=8, sample_offset=0.5,
          progress=False):
    """One mask per polygon, in one C call.

    Parameters
    ----------
    polygons : list
        Each polygon is a list of rings (parts), or one ring.  A ring is an
        (N, 2) array-like of (x, y), an (N, 1, 2) OpenCV contour, and a
        polygon may also be a shapely (Multi)Polygon or anything with
        ``__geo_interface__``.  A COCO segmentation (flat lists) becomes
        rings through ``rastrum.coco.rings``.  Rings of 1 or 2 points draw
        nothing.
    shape : (int, int)
        (height, width) of each mask.
    rule : {"union", "evenodd", "nonzero"}
        "union" (the default): a polygon is the union of its parts, less
        its geometry's holes: each ring is turned to positive area (holes
        to negative), then filled under the non-zero rule.  For parts that
        do not cross themselves (COCO parts, contours, valid geometries)
        that is exactly the union; where a part crosses itself, its lobes
        wound the other way subtract.  "evenodd" and "nonzero" take the
        rings as given.
    algorithm, subpixel_bits, sample_offset
        As for ``polygon_mask``; every algorithm gives the same pixels.
    progress : bool or callable
        True shows a tqdm bar (tqdm must be installed); a function is called
        as ``progress(done, total)``.  The batch is then drawn in about 100
        calls.

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
    polys, orient = _polygons(polygons, "masks")
    out = np.zeros((len(polys), h, w), bool)
    _burn(out, polys, orient, opts, rule, None, "replace", True, "polygon", _progress(progress, len(polys)))
    return out


def labels(polygons, shape, values=None, dtype=np.int32, *, overlap=False, rule="union", algorithm="aet",
           subpixel_bits=8, sample_offset=0.5, progress=False):
    """Burn instances into one label image, in one C call.

    Polygon k (as in ``masks``) writes values[k] (default k + 1) over its
    pixels, later polygons on top of earlier ones; the background is 0.

    Parameters
    ----------
    values : array_like, optional
        One value per polygon, converted to `dtype` (as numpy casts).
    dtype : numpy dtype
        Of the label image: uint8 .. int64, float32, float64.
    overlap : bool
        Also return a uint16 image counting the polygons that cover each
        pixel (a count past 65535 wraps).

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
    polys, orient = _polygons(polygons, "labels")
    n = len(polys)
    if values is None:
        vals = np.arange(1, n + 1).astype(dtype)
    else:
        v = np.asarray(values)
        if v.shape != (n,):
            raise InputError("labels: values has shape %s; %d polygons need shape (%d,)" % (v.shape, n, n))
        if v.dtype.kind not in "biuf":
            raise InputError("labels: values must be numbers, not dtype %s" % v.dtype)
        vals = v.astype(dtype)
    out = np.zeros((h, w), dtype)
    report = _progress(progress, n * (2 if overlap else 1))
    _burn(out, polys, orient, opts, rule, vals, "replace", False, "polygon", report)
    if not overlap:
        return out
    count = np.zeros((h, w), np.uint16)
    _burn(count, polys, orient, opts, rule, None, "add", False, "polygon",
          None if report is None else (lambda done: report(n + done)))
    return out, count

"""COCO masks: a drop-in for ``pycocotools.mask``.

``from rastrum import coco as mask_utils`` gives pycocotools' names with
its arguments, return types and results: run-length encodings (RLEs) as
``{"size": [h, w], "counts": bytes}`` with the same counts strings byte for
byte, masks as uint8 arrays in Fortran order, ``frPyObjects`` with
pycocotools' own polygon rule (reproduced exactly in the integer core,
``rast_coco_ring_toggles``).  What it adds:

- ``frPyObjects(..., rule="exact")``: polygons under rastrum's exact rule
  (pixel centres, DESIGN section 1) instead, still as RLEs;
- ``decode(..., out=array)``: decode into a caller's array (any layout);
- ``rings(segmentation)``: a COCO polygon list as (N, 2) rings for
  ``rastrum.masks`` and ``rastrum.labels``; ``polygons(segmentations)``:
  a list of them as one packed batch for the same, read in one C pass.

Every RLE is made straight from the filler's toggles or spans: no mask is
materialised on the way.  Bad input raises ``rastrum.InputError`` (a
ValueError) naming the argument, where pycocotools raises assorted
TypeErrors, IndexErrors or crashes.
"""

from typing import Any, Dict, Iterable, List, Literal, Mapping, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

from . import _batch, _core, _seq
from ._core import InputError
from ._batch import Polygons
from ._native import ffi, lib

__all__ = ["encode", "decode", "area", "toBbox", "merge", "iou", "frPyObjects", "rings", "polygons"]

_F64 = np.dtype(np.float64)


def _glue(result, what):
    if result == 0:
        return
    if result == lib.RASTPY_E_NOMEM:
        raise MemoryError("rastrum.coco: out of memory")
    if result == lib.RASTPY_E_RLE:
        raise InputError("%s: not a valid COCO RLE (counts must be a string of characters "
                         "'0'..'o' whose counts add up to at most h * w, as pycocotools "
                         "writes them)" % what)
    _core._check(result)


def _counts_bytes(obj, k, what):
    if not isinstance(obj, dict) or "counts" not in obj or "size" not in obj:
        raise InputError("%s: RLE %d must be a dict with 'size' and 'counts', not %s"
                         % (what, k, type(obj).__name__))
    c = obj["counts"]
    if isinstance(c, bytes):
        return c
    if isinstance(c, str):
        return c.encode()
    # uncompressed counts (a list of ints), as frPyObjects takes them
    return _fr_counts([c], what)[0]


def _size(obj, k, what):
    size = obj["size"]
    if type(size) is list and len(size) == 2:
        h, w = size
        if type(h) is int and type(w) is int and 0 <= h <= 0xFFFFFFFF and 0 <= w <= 0xFFFFFFFF \
                and h * w <= 0xFFFFFFFF:
            return h, w
    try:
        h, w = obj["size"]
        h, w = _core.int_pair((h, w), "", "")
    except Exception:
        raise InputError("%s: RLE %d has size %r; it must be [height, width], two ints"
                         % (what, k, obj.get("size"))) from None
    if h < 0 or w < 0 or h * w > 0xFFFFFFFF or max(h, w) > 0xFFFFFFFF:  # [2**32, 0] too
        raise InputError("%s: RLE %d has size %r; h, w >= 0 and h * w < 2**32 are needed"
                         % (what, k, obj["size"]))
    return h, w


def _pack(objs, what):
    """(bytes of all counts strings, size_t[n + 1] offsets, uint32_t[2n]
    sizes (h, w each), the sizes as a list of (h, w)); small calls stay in
    plain Python (numpy's per-call cost would be most of a merge)."""
    strs, hw, offs, flat = [], [], [0], []
    at = 0
    for k, o in enumerate(objs):
        c = _counts_bytes(o, k, what)
        strs.append(c)
        at += len(c)
        offs.append(at)
        size = _size(o, k, what)
        hw.append(size)
        flat.extend(size)
    return b"".join(strs), ffi.new("size_t[]", offs), ffi.new("uint32_t[]", flat or [0]), hw


def _unpack(data, offsets, n):
    """The n strings of a C-made buffer (freed here), offsets a size_t[n + 1]
    cdata, as a list of bytes."""
    try:
        buf = ffi.buffer(data[0], offsets[n])[:] if offsets[n] else b""
    finally:
        lib.rastpy_free(data[0])
    return [buf[offsets[k]:offsets[k + 1]] for k in range(n)]


def _objs(strs, sizes):
    return [{"size": [h, w], "counts": s} for s, (h, w) in zip(strs, sizes)]


def _fr_counts(counts_lists, what):
    arrays = []
    for k, c in enumerate(counts_lists):
        try:
            a = np.asarray(c)
            if a.dtype.kind not in "iu" or a.ndim != 1 or (a.size and (a.min() < 0 or a.max() > 0xFFFFFFFF)):
                raise ValueError
        except (ValueError, TypeError):
            raise InputError("%s: uncompressed counts %d must be a list of ints in 0..2**32-1"
                             % (what, k)) from None
        arrays.append(a.astype(np.uint32))
    offs = [0]
    for a in arrays:
        offs.append(offs[-1] + len(a))
    flat = np.concatenate(arrays) if arrays else np.zeros(1, np.uint32)
    data = ffi.new("char **")
    out = ffi.new("size_t[]", len(arrays) + 1)
    _glue(lib.rastpy_coco_fr_counts(ffi.from_buffer("uint32_t[]", flat), ffi.new("size_t[]", offs),
                                    len(arrays), data, out), what)
    return _unpack(data, out, len(arrays))


# ---- masks <-> RLE ----------------------------------------------------------

def _mask_array(bimask, what):
    try:
        a = bimask if isinstance(bimask, np.ndarray) else np.asarray(bimask)
    except (ValueError, TypeError, OverflowError):  # ragged lists
        raise InputError("%s: masks must be uint8 or bool arrays, not %s" % (what, type(bimask).__name__)) from None
    if a.dtype != np.uint8 and a.dtype != np.bool_:
        raise InputError("%s: masks must be uint8 or bool arrays, not dtype %s" % (what, a.dtype))
    return a


def encode(bimask: npt.ArrayLike) -> Any:
    """Run-length encode binary masks, as ``pycocotools.mask.encode``.

    bimask: (H, W) -> one RLE dict; (H, W, N) -> a list of N.  uint8 or bool
    in any memory order (pycocotools wants Fortran-ordered uint8).  Runs
    break wherever the byte changes, as pycocotools' do.
    """
    a = _mask_array(bimask, "encode")
    if a.ndim not in (2, 3):
        raise InputError("encode: bimask must be (H, W) or (H, W, N), not shape %s" % (a.shape,))
    single = a.ndim == 2
    if single:
        a = a[:, :, None]
    h, w, n = a.shape
    if h * w > 0xFFFFFFFF or max(h, w) > 0xFFFFFFFF:  # (2**32, 0) too
        raise InputError("encode: h, w and h * w must be below 2**32 (COCO counts are uint32), "
                         "not shape %s" % (a.shape,))
    if a.dtype == np.bool_:
        a = a.view(np.uint8)
    data = ffi.new("char **")
    offsets = ffi.new("size_t[]", n + 1)
    ptr = ffi.cast("uint8_t *", a.__array_interface__["data"][0]) if a.size else ffi.NULL
    _glue(lib.rastpy_coco_encode(ptr, h, w, n, a.strides[0], a.strides[1], a.strides[2], data, offsets),
          "encode")
    objs = _objs(_unpack(data, offsets, n), [(h, w)] * n)
    return objs[0] if single else objs


def decode(rleObjs: Union[Mapping[str, Any], Sequence[Mapping[str, Any]]],
           out: Optional[npt.NDArray[np.uint8]] = None) -> npt.NDArray[np.uint8]:
    """Masks of RLEs, as ``pycocotools.mask.decode``.

    A list of N RLEs (all of one size) -> (H, W, N) uint8 in Fortran order;
    one RLE dict -> (H, W) uint8.  With `out` (uint8 or bool, that shape,
    any memory order, writable) the masks are written there and `out` is
    returned.  An RLE whose counts pass h * w is an InputError (nothing is
    written); pixels after the last count are 0.
    """
    single = not isinstance(rleObjs, list)
    objs = [rleObjs] if single else rleObjs
    if not objs:
        raise InputError("decode: no RLEs to decode (an empty list has no size)")
    strs, offsets, _, hw = _pack(objs, "decode")
    h, w = hw[0]
    for k, size in enumerate(hw):
        if size != hw[0]:
            raise InputError("decode: RLE %d has size %s, RLE 0 %s; one size is needed"
                             % (k, list(size), [h, w]))
    n = len(objs)
    if out is None:
        res = np.empty((n, w, h), np.uint8).T  # (h, w, n), Fortran order
        target = res
    else:
        if not isinstance(out, np.ndarray) or out.dtype not in (np.uint8, np.bool_):
            raise InputError("decode: out must be a uint8 or bool numpy array")
        want = (h, w) if single else (h, w, n)
        if out.shape != want:
            raise InputError("decode: out has shape %s; these RLEs need %s" % (out.shape, want))
        if not out.flags.writeable:
            raise InputError("decode: out is read-only")
        target = out if not single else out[:, :, None]
        res = out
    ptr = ffi.cast("uint8_t *", target.__array_interface__["data"][0]) if target.size else ffi.NULL
    if not target.size:  # nothing to write, but the counts are judged all the same
        _glue(lib.rastpy_coco_area(strs, offsets, n, ffi.new("uint32_t[]", [h, w] * n),
                                   ffi.new("uint32_t[]", n)), "decode")
    else:
        _glue(lib.rastpy_coco_decode(strs, offsets, n, h, w, ptr,
                                     target.strides[0], target.strides[1], target.strides[2], 1),
              "decode")
    if out is None and single:
        return res[:, :, 0]
    return res


@overload
def area(rleObjs: Mapping[str, Any]) -> np.uint32: ...


@overload
def area(rleObjs: Sequence[Mapping[str, Any]]) -> npt.NDArray[np.uint32]: ...


def area(rleObjs: Union[Mapping[str, Any], Sequence[Mapping[str, Any]]]) -> Any:
    """Pixels inside each RLE (uint32), as ``pycocotools.mask.area``."""
    single = not isinstance(rleObjs, list)
    objs = [rleObjs] if single else rleObjs
    strs, offsets, sizes, _ = _pack(objs, "area")
    a = np.zeros(len(objs), np.uint32)
    if objs:
        _glue(lib.rastpy_coco_area(strs, offsets, len(objs), sizes,
                                   ffi.from_buffer("uint32_t[]", a)), "area")
    return a[0] if single else a


def toBbox(rleObjs: Union[Mapping[str, Any], Sequence[Mapping[str, Any]]]) -> npt.NDArray[np.float64]:
    """Boxes [x, y, w, h] (float64) of RLEs, as ``pycocotools.mask.toBbox``."""
    single = not isinstance(rleObjs, list)
    objs = [rleObjs] if single else rleObjs
    strs, offsets, sizes, _ = _pack(objs, "toBbox")
    bb = np.zeros((len(objs), 4), np.float64)
    if objs:
        _glue(lib.rastpy_coco_bbox(strs, offsets, len(objs), sizes, ffi.from_buffer("double[]", bb)),
              "toBbox")
    return bb[0] if single else bb


def merge(rleObjs: Sequence[Mapping[str, Any]], intersect: Union[bool, int] = 0) -> Dict[str, Any]:
    """Union (or with `intersect`, intersection) of RLEs of one size, as
    ``pycocotools.mask.merge``: one RLE dict.  RLEs of different sizes give
    pycocotools' empty {'size': [0, 0], 'counts': b''}."""
    if not isinstance(rleObjs, list):
        raise InputError("merge: rleObjs must be a list of RLE dicts, not %s" % type(rleObjs).__name__)
    strs, offsets, sizes, _ = _pack(rleObjs, "merge")
    data = ffi.new("char **")
    out = ffi.new("size_t[2]")
    size = ffi.new("uint32_t[2]")
    _glue(lib.rastpy_coco_merge(strs, offsets, len(rleObjs), sizes, 1 if intersect else 0, data, out, size),
          "merge")
    if data[0] == ffi.NULL:
        return {"size": [0, 0], "counts": b""}
    return {"size": [size[0], size[1]], "counts": _unpack(data, out, 1)[0]}


def _boxes(objs, what):
    try:
        a = np.array(objs, dtype=np.float64)
    except (ValueError, TypeError, OverflowError):
        raise InputError("iou: %s boxes must be (N, 4) [x, y, w, h] numbers" % what) from None
    if a.ndim == 1 and a.shape[0] == 4:
        a = a.reshape(1, 4)
    if a.ndim != 2 or a.shape[1] != 4:
        raise InputError("iou: %s boxes must be (N, 4) [x, y, w, h], not shape %s" % (what, a.shape))
    return np.ascontiguousarray(a)


def _crowd(pyiscrowd):
    """iscrowd as uint8 0/1: a list (or 1-D array) of bools or ints 0 and 1
    (pycocotools' np.array(..., dtype=np.uint8) would wrap 256 to 0)."""
    try:
        a = np.asarray(pyiscrowd)
    except (ValueError, TypeError):
        a = None
    if a is not None and a.size == 0:
        return np.zeros(0, np.uint8)
    if a is None or a.ndim > 1 or a.dtype.kind not in "biu" or (a.size and (a.min() < 0 or a.max() > 1)):
        raise InputError("iou: iscrowd must be a list of 0/1 (or bools), one per gt object, not %r"
                         % (pyiscrowd,))
    return a.reshape(-1).astype(np.uint8)


def iou(dt: Union[Sequence[Mapping[str, Any]], npt.ArrayLike], gt: Union[Sequence[Mapping[str, Any]], npt.ArrayLike],
        pyiscrowd: Sequence[Union[bool, int]]) -> Any:
    """IoU of each detection with each ground truth, as
    ``pycocotools.mask.iou``: (m, n) float64 (Fortran order), or [] when
    either is empty.  dt and gt: both lists of RLE dicts, or both boxes
    ((N, 4) arrays or lists of [x, y, w, h]).  Where pyiscrowd[g] is true,
    the union is the detection's area (pycocotools' crowd rule)."""
    def kind(objs, what):
        if isinstance(objs, np.ndarray):
            return "box", _boxes(objs, what) if len(objs) else objs
        if isinstance(objs, list):
            if not objs:
                return "empty", objs
            if all(isinstance(o, dict) for o in objs):
                return "rle", objs
            if all(isinstance(o, (list, np.ndarray)) and len(o) == 4 for o in objs):
                return "box", _boxes(objs, what)
            raise InputError("iou: %s must be a list of RLE dicts or of [x, y, w, h] boxes" % what)
        raise InputError("iou: %s must be a list or an (N, 4) array, not %s" % (what, type(objs).__name__))
    kd, d = kind(dt, "dt")
    kg, g = kind(gt, "gt")
    crowd = _crowd(pyiscrowd)
    m, n = len(d), len(g)
    if len(crowd) != n:
        raise InputError("iou: iscrowd has %s for %s" % (_core.plural(len(crowd), "entry", "entries"),
                                                         _core.plural(n, "gt object")))
    if m == 0 or n == 0:
        return []
    if kd != kg:
        raise InputError("iou: dt and gt must both be RLEs or both boxes")
    o = np.zeros(m * n, np.float64)
    if kd == "box":
        lib.rastpy_coco_bb_iou(ffi.from_buffer("double[]", d), ffi.from_buffer("double[]", g), m, n,
                               ffi.from_buffer("uint8_t[]", crowd), ffi.from_buffer("double[]", o))
    else:
        ds, do, dsz, _ = _pack(d, "iou dt")
        gs, go, gsz, _ = _pack(g, "iou gt")
        _glue(lib.rastpy_coco_iou(ds, do, dsz, m, gs, go, gsz, n,
                                  ffi.from_buffer("uint8_t[]", crowd), ffi.from_buffer("double[]", o)), "iou")
    return o.reshape((m, n), order="F")


# ---- polygons and boxes -> RLE ------------------------------------------------

def _hw(h, w):
    h, w = _core.int_pair((h, w), "frPyObjects: h, w must be two ints, not %r",
                          "frPyObjects: h and w must be ints, not %r")
    if h < 0 or w < 0 or h * w > 0xFFFFFFFF or max(h, w) > 0xFFFFFFFF:
        raise InputError("frPyObjects: h=%d, w=%d; h, w >= 0 and h * w < 2**32 are needed" % (h, w))
    return h, w


def _poly_hw(h, w):
    """Polygons and boxes go through the filler: sides up to RAST_MAX_DIM
    (uncompressed RLEs take any h * w < 2**32, as pycocotools)."""
    if max(h, w) > lib.RAST_MAX_DIM:
        raise InputError("frPyObjects: h=%d, w=%d; polygons and boxes need h and w at most %d "
                         "(uncompressed RLEs may be larger)" % (h, w, lib.RAST_MAX_DIM))


def _flat(p, k):
    """Polygon k as float64 (K, 2) points: a flat [x0, y0, x1, y1, ...] list
    (pycocotools' K = len // 2: an odd last coordinate is dropped) or an
    (N, 2) array-like."""
    a = _core.real_array(p, "frPyObjects: polygon %d" % k, "a flat [x0, y0, x1, y1, ...] list")
    if a.ndim == 1:
        return a[: a.shape[0] // 2 * 2].reshape(-1, 2)
    if a.ndim == 2 and a.shape[1] == 2:
        return a
    if a.ndim == 3 and a.shape[1:] == (1, 2):
        return a.reshape(-1, 2)
    raise InputError("frPyObjects: polygon %d has shape %s; a flat [x0, y0, x1, y1, ...] list "
                     "or an (N, 2) array is needed" % (k, a.shape))


# Toggles a window of pycocotools' rule holds at most (python/glue/coco.c);
# 0: the glue's default (2**18).  Tests make it small to cross many windows.
_WINDOW = 0


def _fr_call(xy, sizes, n, h, w, rule):
    """rastpy_coco_fr_polys or rastpy_coco_exact: (status, data, offsets)."""
    offsets = ffi.new("size_t[]", n + 1)
    data = ffi.new("char **")
    if rule == "coco":
        r = lib.rastpy_coco_fr_polys(xy, sizes, n, h, w, _WINDOW, data, offsets)
    else:
        opts = _core.fill_opts("aet", "evenodd", 8, 0.5)
        failed = ffi.new("uint32_t *", 0xFFFFFFFF)
        r = lib.rastpy_coco_exact(xy, sum(sizes), sizes, n, ffi.new("uint32_t[]", [1] * n or [0]), n, h, w,
                                  opts, data, offsets, failed)
    return r, data, offsets


def _fr_polys(polys, h, w, rule):
    """One RLE string per polygon (list of (K, 2) float64 arrays)."""
    n = len(polys)
    xy = np.ascontiguousarray(np.concatenate(polys)) if polys else np.zeros((1, 2))
    sizes = [len(p) for p in polys]
    r, data, offsets = _fr_call(ffi.from_buffer("double[]", xy), ffi.new("uint32_t[]", sizes or [0]), n, h, w,
                                rule)
    if r > 0:
        k = r - 1
        ends = np.cumsum(sizes)
        poly = int(np.searchsorted(ends, k, side="right"))
        x, y = xy[k].tolist()
        if rule == "coco":
            raise InputError("frPyObjects: polygon %d, point %d (%r, %r) is NaN, infinite or outside "
                             "+-%d pixels (pycocotools' rule works on 5x upsampled int coordinates)"
                             % (poly, k - (ends[poly] - sizes[poly]), x, y, lib.RAST_COCO_COORD_MAX // 5))
        _core._check_glue(r, xy, 8, "frPyObjects: polygon %d" % poly)
    _glue(r, "frPyObjects")
    return _objs(_unpack(data, offsets, n), [(h, w)] * n)


def _fr_lists(parts, h, w, rule):
    """The common case quickly: every part a flat list of numbers (no numpy
    on the way).  None when a part is not a plain list of floats and ints
    (the general path then checks and converts it)."""
    flat, sizes = [], []
    for p in parts:
        if type(p) is not list:
            return None
        k = len(p) // 2
        if 2 * k != len(p) and type(p[-1]) is not float and type(p[-1]) is not int:
            return None  # the coordinate dropped must be a number too
        flat += p if 2 * k == len(p) else p[:2 * k]
        sizes.append(k)
    try:
        xy = ffi.new("double[]", flat or [0.0])
    except (TypeError, OverflowError):
        return None
    for v in flat:  # bools and other numbers the general path refuses
        if type(v) is not float and type(v) is not int:
            return None
    r, data, offsets = _fr_call(xy, ffi.new("uint32_t[]", sizes or [0]), len(parts), h, w, rule)
    if r:
        lib.rastpy_free(data[0])
        return None  # the general path names the bad point
    return _objs(_unpack(data, offsets, len(parts)), [(h, w)] * len(parts))


def _box_polys(bb):
    try:
        bb = np.asarray(bb, dtype=np.float64)
    except (ValueError, TypeError, OverflowError):
        raise InputError("frPyObjects: boxes must be (N, 4) [x, y, w, h] numbers") from None
    if bb.ndim != 2 or bb.shape[1] != 4:
        raise InputError("frPyObjects: boxes must be (N, 4) [x, y, w, h], not shape %s" % (bb.shape,))
    xs, ys = bb[:, 0], bb[:, 1]
    xe, ye = xs + bb[:, 2], ys + bb[:, 3]  # in double, as pycocotools
    return list(np.stack([xs, ys, xs, ye, xe, ye, xe, ys], axis=1).reshape(-1, 4, 2))


def _is_rle(o):
    return isinstance(o, dict) and "counts" in o and "size" in o


@overload
def frPyObjects(pyobj: Union[Mapping[str, Any], Sequence[float]], h: int, w: int, *,
                rule: Literal["coco", "exact"] = "coco") -> Dict[str, Any]: ...


@overload
def frPyObjects(pyobj: Union[Sequence[Sequence[float]], Sequence[Mapping[str, Any]], npt.NDArray[Any]], h: int,
                w: int, *, rule: Literal["coco", "exact"] = "coco") -> List[Dict[str, Any]]: ...


def frPyObjects(pyobj: Any, h: int, w: int, *, rule: Literal["coco", "exact"] = "coco") -> Any:
    """RLEs of polygons, boxes or uncompressed RLEs, as
    ``pycocotools.mask.frPyObjects``.

    pyobj: an (N, 4) array or a list of [x, y, w, h] boxes -> a list; a
    list of polygons (each a flat [x0, y0, x1, y1, ...] list, or an (N, 2)
    array) -> a list, one RLE per polygon (``merge`` makes an object of
    its parts); a list of uncompressed RLEs ({'size', 'counts': [ints]}) ->
    a list; one box, one flat polygon or one uncompressed RLE -> one dict.

    rule: "coco" is pycocotools' polygon rule, bit for bit; "exact" is
    rastrum's exact rule (pixel centres, DESIGN section 1; boxes as their
    four-corner rings), each polygon under even-odd.
    """
    if rule not in ("coco", "exact"):
        raise InputError("frPyObjects: unknown rule %r; choose one of: coco, exact" % (rule,))
    h, w = _hw(h, w)
    if isinstance(pyobj, np.ndarray):
        _poly_hw(h, w)
        return _fr_polys(_box_polys(pyobj), h, w, rule)
    if isinstance(pyobj, dict):
        if not _is_rle(pyobj):
            raise InputError("frPyObjects: a dict must be an RLE with 'size' and 'counts'")
        return frPyObjects([pyobj], h, w, rule=rule)[0]
    if not isinstance(pyobj, list) or not pyobj:
        raise InputError("frPyObjects: pyobj must be a non-empty list (polygons, boxes or RLEs), "
                         "an (N, 4) array or an RLE dict, not %r" % (pyobj if not isinstance(pyobj, list) else "[]",))
    first = pyobj[0]
    if _is_rle(first):
        for k, o in enumerate(pyobj):
            if not _is_rle(o):
                raise InputError("frPyObjects: item %d is not an RLE dict like item 0" % k)
        strs = _fr_counts([o["counts"] for o in pyobj], "frPyObjects")
        return _objs(strs, [_size(o, k, "frPyObjects") for k, o in enumerate(pyobj)])
    _poly_hw(h, w)
    if _core.ndim(first) == 0:  # one flat polygon or one box
        if len(pyobj) == 4:
            return _fr_polys(_box_polys([pyobj]), h, w, rule)[0]
        return _fr_polys([_flat(pyobj, 0)], h, w, rule)[0]
    if len(first) == 4 and _core.ndim(first) == 1:
        return _fr_polys(_box_polys(pyobj), h, w, rule)
    quick = _fr_lists(pyobj, h, w, rule)
    if quick is not None:
        return quick
    return _fr_polys([_flat(p, k) for k, p in enumerate(pyobj)], h, w, rule)


def rings(segmentation: Any) -> List[npt.NDArray[np.float64]]:
    """A COCO polygon segmentation ([[x0, y0, x1, y1, ...], ...], one flat
    list per part) as a list of float64 (N, 2) rings, for
    ``rastrum.masks`` and ``rastrum.labels``.  A single flat list is one
    ring.  An odd trailing coordinate is dropped, as pycocotools drops it."""
    if isinstance(segmentation, dict):
        raise InputError("rings: an RLE segmentation has no polygon rings (use coco.decode)")
    if not isinstance(segmentation, (list, tuple, np.ndarray)):
        raise InputError("rings: segmentation must be a list of flat [x0, y0, ...] lists, not %s"
                         % type(segmentation).__name__)
    if len(segmentation) and type(segmentation[0]) is not list and _core.ndim(segmentation[0]) == 0:
        segmentation = [segmentation]
    out = []
    for k, p in enumerate(segmentation):
        try:
            a = np.asarray(p) if type(p) is list else None
        except (ValueError, TypeError, OverflowError):  # ragged: real_array names it
            a = None
        if a is not None and a.dtype is _F64 and a.ndim == 1 and not _core.has_bool(p):  # the usual: floats
            out.append(a.reshape(-1, 2) if not a.shape[0] & 1 else a[:-1].reshape(-1, 2))
            continue
        a = _core.real_array(p, "rings: part %d" % k, "a flat [x0, y0, x1, y1, ...] list")
        if a.ndim != 1:
            raise InputError("rings: part %d has shape %s; a flat [x0, y0, x1, y1, ...] list is needed"
                             % (k, a.shape))
        out.append(a[: a.shape[0] // 2 * 2].reshape(-1, 2))
    return out


def polygons(segmentations: Iterable[Any]) -> Polygons:
    """COCO polygon segmentations, one per object, as one batch for
    ``rastrum.masks`` and ``rastrum.labels``: the same polygons as
    ``[rings(s) for s in segmentations]``, read in one C pass when they are
    lists of floats and ints (numpy's conversion of a Python list costs
    about a microsecond a call and 10 ns a number; this is a few ns a
    number).  Parts without a point (fewer than 2 numbers) are left out.

    Returns a ``rastrum.Polygons``: a sequence whose item k is object k's
    rings (float64 (N, 2) arrays).  Bad input raises ``InputError`` naming
    the object, as ``rings`` words it.

    >>> import rastrum
    >>> from rastrum import coco
    >>> b = coco.polygons([[[1, 1, 6, 1, 6, 4]], [[0, 0, 3, 0, 3, 3, 0, 3], [4, 4, 6, 4, 6, 6]]])
    >>> second = b[1]
    >>> len(b), [len(p) for p in b], second[1].tolist()
    (2, [1, 2], [[4.0, 4.0], [6.0, 4.0], [6.0, 6.0]])
    >>> rastrum.masks(b, (8, 8)).sum(axis=(1, 2)).tolist()
    [8, 12]
    """
    flat = _seq.flat(segmentations)
    if flat is not None:
        pts, sizes, counts = flat
        return _batch.Polygons(np.frombuffer(pts, _F64).reshape(-1, 2), np.frombuffer(sizes, np.uint32),
                               np.frombuffer(counts, np.uint32))
    if isinstance(segmentations, (dict, str, bytes)) or not hasattr(segmentations, "__iter__"):
        raise InputError("polygons: segmentations must be a list of COCO polygon segmentations (one per "
                         "object), not %s" % type(segmentations).__name__)
    objs = []
    for k, s in enumerate(segmentations):
        try:
            objs.append([r for r in rings(s) if len(r)])
        except InputError as e:
            raise InputError("polygons: object %d: %s" % (k, e)) from None
    return _batch.Polygons(*_batch.pack(objs))

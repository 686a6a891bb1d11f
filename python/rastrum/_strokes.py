"""Strokes: the outline of a path drawn with a width, as a Path to fill
non-zero (docs/paths.md, "Strokes").

The outline is built by the C core's stroker (rast_path_stroke,
csrc/src/path/stroke.c): one ring per open subpath and per dash (two per
closed subpath), whose winding number is that of the union of pieces all
turning the same way (a parallelogram per segment, a join per vertex, a
cap per open end), so that a non-zero fill of it is exactly the union,
crossings and overlaps included.  Integer only, on a grid of 1/2**b pixel (b <= 16, the finest
that holds the stroke's extent): every polygonal vertex within
sqrt(2)/2 grid step of the ideal one, round joins and caps within the
tolerance (or 2 grid steps, when coarser) of the true arcs.
"""

from __future__ import annotations

import math
from typing import List, Optional, Sequence, Union

import numpy as np

from ._core import InputError
from ._native import ffi, lib
from ._path import DEFAULT_TOLERANCE, LINE, MOVE, Path, _real

__all__ = ["stroke"]


_JOINS = {"miter": lib.RAST_JOIN_MITER, "round": lib.RAST_JOIN_ROUND, "bevel": lib.RAST_JOIN_BEVEL}
_CAPS = {"butt": lib.RAST_CAP_BUTT, "round": lib.RAST_CAP_ROUND, "square": lib.RAST_CAP_SQUARE}
# rast__path_stroke_run's flags (csrc/src/path/path.h): RAST__STROKE_MEET | RAST__STROKE_ARCS
_OUTLINES = {"exact": 0, "compact": 3}
_MAX_LIMIT = (2 ** 31 - 1) / 65536.0
_ROOM = 1 << 22  # the most room a guess takes (np.empty: pages touched only as written)


def _circle_m(w: int, tol: int) -> int:
    """rast_path_stroke's m for round parts (4m points on the circle):
    ceil(sqrt(ceil(w / (4 tol - 3)))), at most w // 4, at least 1
    (csrc/src/path/stroke.c, "Round parts")."""
    need = (w + 4 * tol - 4) // (4 * tol - 3)
    m = math.isqrt(need - 1) + 1 if need > 0 else 0
    return max(1, min(m, w // 4))


def _as_path(geometry: object) -> Path:
    """A Path as is; polylines as open subpaths (a single point: a
    zero-length subpath, which round and square caps draw)."""
    if isinstance(geometry, Path):
        return geometry
    from ._core import ndim, real_array
    if isinstance(geometry, (str, bytes, dict)) or not hasattr(geometry, "__iter__"):
        raise InputError("geometry must be a Path, an (N, 2) array of (x, y) or a list of them, not %s"
                         % type(geometry).__name__)
    if ndim(geometry) == 2 and np.shape(geometry)[1:] == (2,):
        lines: Sequence[object] = [geometry]  # type: ignore[list-item]
    else:
        lines = geometry  # type: ignore[assignment]
    verbs: List[np.ndarray] = []
    pts: List[np.ndarray] = []
    for i, line in enumerate(lines):
        a = real_array(line, "geometry: polyline %d" % i, "an (N, 2) array of (x, y)")
        if a.ndim != 2 or a.shape[1] != 2:
            raise InputError("geometry: polyline %d is not an (N, 2) array of (x, y)" % i)
        if not np.isfinite(a).all():
            raise InputError("geometry: polyline %d has a NaN or infinite coordinate" % i)
        if not len(a):
            continue
        if len(a) == 1:
            a = np.concatenate([a, a])
        v = np.full(len(a), LINE, dtype=np.uint8)
        v[0] = MOVE
        verbs.append(v)
        pts.append(np.asarray(a, dtype=np.float64))
    if not verbs:
        return Path()
    return Path._lines(np.concatenate(verbs), np.concatenate(pts).reshape(-1, 2))


def stroke(geometry: Union[Path, Sequence[Sequence[float]], Sequence[Sequence[Sequence[float]]]],
           width: float, *, join: str = "miter", cap: str = "butt", miter_limit: float = 4.0,
           dash: Optional[Sequence[float]] = None, dash_offset: float = 0.0,
           tolerance: Optional[float] = None, outline: str = "exact") -> Path:
    """The outline of `geometry` stroked `width` pixels wide, as a Path.

    Fill the result with ``rule="nonzero"`` (every method then draws the
    stroke; "area" gives its exact coverage where crossings overlap).

    Parameters
    ----------
    geometry : Path, (N, 2) array_like, or list of them
        A Path (its subpaths; closed ones are joined all round), or open
        polylines of (x, y) pixels (a single point: a zero-length subpath).
    width : float
        The stroke's width in pixels (> 0).
    join : {"miter", "round", "bevel"}
    cap : {"butt", "round", "square"}
    miter_limit : float
        SVG's stroke-miterlimit (>= 1): a miter longer than miter_limit
        times the width (1/sin(theta/2) > miter_limit, theta the angle
        between the segments) is bevelled.
    dash : sequence of float or None
        SVG's stroke-dasharray: lengths in pixels along the path, on, off,
        on, ... (>= 0, not all 0; an odd count is repeated).  None: solid.
        A dash crossing a vertex keeps its join; a closed subpath starting
        inside a dash joins its last dash to its first; a dash of length 0
        is a dot with round or square caps.
    dash_offset : float
        SVG's stroke-dashoffset: where along the pattern each subpath
        starts, in pixels (any sign).
    tolerance : float or None
        How far the round joins and caps (and the geometry's curves) may
        be from the true arcs, in pixels; None: the Path's tolerance, else
        DEFAULT_TOLERANCE (1/256 px).
    outline : {"exact", "compact"}
        "exact": the non-zero region is exactly the union of the pieces
        (on the grid), the ring passing each join's inner side through
        the vertex itself (a small loop at every turn, which "area" pays
        for with its exact sweep and an accumulator counts twice) and
        round parts through points on the circle.  "compact": fewer
        vertices and no loop at a plain turn, within the same stated
        bound: the inner side through the two inner edges' meeting point
        (rounded) wherever both segments cover the corner (the region
        within sqrt(2)/2 grid step of the union there), and round parts
        through points just outside the circle, straddling it (about
        1/sqrt(2) as many at the same tolerance).  docs/paths.md.

    Returns
    -------
    Path
        Rings (one per open subpath or dash, two per closed subpath)
        whose non-zero region is the stroke.  A zero-length subpath gives a dot with round caps, a
        square with square caps and nothing with butt caps (SVG).

    Examples
    --------
    >>> import rastrum, numpy as np
    >>> outline = rastrum.stroke([(2, 4), (10, 4)], 2)
    >>> cov = rastrum.polygon_coverage(outline, (8, 12), rule="nonzero", dtype=np.float64)
    >>> float(cov.sum())
    16.0
    """
    w = _real(width, "width")
    if not w > 0:
        raise InputError("width: %r; it must be > 0" % (width,))
    if join not in _JOINS:
        raise InputError("join: %r; one of %s" % (join, ", ".join(_JOINS)))
    if cap not in _CAPS:
        raise InputError("cap: %r; one of %s" % (cap, ", ".join(_CAPS)))
    if outline not in _OUTLINES:
        raise InputError("outline: %r; one of %s" % (outline, ", ".join(_OUTLINES)))
    limit = _real(miter_limit, "miter_limit")
    if not limit >= 1:
        raise InputError("miter_limit: %r; it must be >= 1 (SVG)" % (miter_limit,))
    limit = min(limit, _MAX_LIMIT)
    off = _real(dash_offset, "dash_offset")
    dashes: Optional[List[float]] = None
    if dash is not None:
        try:
            dashes = [_real(v, "dash") for v in dash]
        except TypeError:
            raise InputError("dash: %r is not a sequence of lengths" % (dash,)) from None
        if any(v < 0 for v in dashes):
            raise InputError("dash: %r; lengths must be >= 0" % (dash,))
        if not dashes or not any(v > 0 for v in dashes):
            raise InputError("dash: %r; some length must be > 0 (or pass None)" % (dash,))
    path = _as_path(geometry)
    tol = tolerance if tolerance is not None else (path.tolerance if path.tolerance is not None
                                                   else DEFAULT_TOLERANCE)
    tol = _real(tol, "tolerance")
    if not tol > 0:
        raise InputError("tolerance: %r pixels; it must be > 0" % (tolerance,))
    out = Path(tolerance=tolerance)
    if not len(path):
        return out
    # the grid: the finest 1/2**b pixel (b <= 16) holding the points and
    # the outline (the width, a miter's tip at miter_limit times it)
    pts = path.points
    reach = w / 2 * max(limit if join == "miter" else 1.0, math.sqrt(2)) + 1
    ext = float(np.abs(pts).max()) + reach
    bits = min(lib.RAST_MAX_SUBPIXEL_BITS, math.floor(math.log2(lib.RAST_COORD_MAX / ext)))
    if bits < 0:
        raise InputError("geometry: the stroke reaches %.6g pixels from the origin, past the range +-%d"
                         % (ext, lib.RAST_COORD_MAX))
    one = float(1 << bits)
    style = ffi.new("rast_stroke_style *")
    style.width = max(0, min(lib.RAST_COORD_MAX, int(math.floor(w * one + 0.5))))
    if style.width < 1:
        return out  # narrower than one grid step: nothing
    style.join, style.cap = _JOINS[join], _CAPS[cap]
    style.miter_limit = min(2 ** 31 - 1, int(math.floor(limit * 65536 + 0.5)))
    style.tolerance = max(1, min(lib.RAST_COORD_MAX, int(math.floor(tol * one))))
    keep = []
    if dashes is not None:
        units = [int(math.floor(v * one + 0.5)) for v in dashes]
        if max(units) > lib.RAST_COORD_MAX:
            raise InputError("dash: a length past %.6g pixels" % (lib.RAST_COORD_MAX / one))
        if not any(units):
            raise InputError("dash: %r; every length is below one grid step (1/%d px)" % (dash, 1 << bits))
        period = sum(units) * (2 if len(units) % 2 else 1)
        arr = np.array(units, dtype=np.int32)
        keep.append(arr)
        style.dash = ffi.cast("int32_t *", ffi.from_buffer(arr))
        style.ndash = len(units)
        style.dash_offset = int(math.floor(off * one + 0.5)) % period
    fixed, verbs = path._fixed(bits)
    cpath = ffi.new("rast_path *")
    cpath.verbs = ffi.from_buffer("uint8_t[]", verbs)
    cpath.nverbs = len(verbs)
    cpath.points = ffi.cast("rast_point *", ffi.from_buffer(fixed)) if len(fixed) else ffi.NULL
    cpath.npoints = len(fixed)
    # One pass into room guessed from the path (python/glue/stroke.c), not a
    # count and then a second pass.  The guess, for lines without dashes:
    # per vertex a segment's 4 points, a join's pivot and an arc of about
    # half the circle's 4m points; per subpath two caps or a dot.  Curves
    # and dashes may need more; too little room only costs the count first
    # (the outline is the same either way).
    m = _circle_m(style.width, style.tolerance)
    nsub = int(np.count_nonzero(verbs == MOVE)) + 1
    room = min(lib.RAST_MAX_POINTS, len(fixed) * (2 * m + 6) + nsub * (4 * m + 4), _ROOM)
    rooms = min(lib.RAST_MAX_POINTS, 2 * (len(verbs) + 1))
    np_, nr = ffi.new("uint32_t *"), ffi.new("uint32_t *")
    flags = _OUTLINES[outline]
    for _ in range(2):
        ring_pts = np.empty((max(room, 1), 2), dtype=np.int32)
        sizes = np.empty(max(rooms, 1), dtype=np.uint32)
        st = lib.rastpy_path_stroke_flags(cpath, style, flags, ffi.cast("rast_point *", ffi.from_buffer(ring_pts)),
                                          room, ffi.from_buffer("uint32_t[]", sizes), rooms, np_, nr)
        if st != lib.RAST_E_SCRATCH:
            break
        st = lib.rastpy_path_stroke_flags(cpath, style, flags, ffi.NULL, 0, ffi.NULL, 0, np_, nr)  # how much
        if st != lib.RAST_OK:
            break
        room, rooms = np_[0], nr[0]
    if st == lib.RAST_E_TOO_MANY:
        raise InputError("geometry: the stroke's outline has more than %d vertices" % lib.RAST_MAX_POINTS)
    if st != lib.RAST_OK:
        raise InputError("geometry: %s" % ffi.string(lib.rast_status_str(st)).decode())
    n, r = np_[0], nr[0]
    sizes = sizes[:r]
    sizes = sizes[sizes > 0].astype(np.int64)
    if not n:
        return out
    # ring k: MOVE, LINE ..., CLOSE, its points after the k CLOSEs before it
    closes = np.cumsum(sizes) + np.arange(len(sizes))
    vs = np.full(n + len(sizes), LINE, dtype=np.uint8)
    vs[closes] = lib.RAST_PATH_CLOSE
    vs[closes - sizes] = MOVE
    # held as the stroker made it, on its grid: a fill at subpixel_bits <=
    # bits rounds the integers (Path._fixed), no float64 points made
    return Path._lines(vs, fixed=(ring_pts[:n], bits), tolerance=tolerance)

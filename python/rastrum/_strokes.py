"""Strokes: the outline of a path drawn with a width, as a Path to fill
non-zero (docs/paths.md, "Strokes").

The outline is a union of convex pieces all turning the same way: a
rectangle per segment, a join per vertex (bevel triangle, miter
quadrilateral, or a disc), a cap per open end (square, or a disc), so
that a non-zero fill of it is exactly the union, crossings and overlaps
included; "area" coverage of it is the ideal stroke's area up to the
snapping of its vertices (polygonal joins and caps) and the Path's
tolerance (round ones).  Built in Python for now; the C stroker, integer
only, is still to come.
"""

from __future__ import annotations

import math
from typing import Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from ._core import InputError
from ._path import CLOSE, LINE, MOVE, QUAD, Path, _real

__all__ = ["stroke"]

_Pt = Tuple[float, float]
_JOINS = ("miter", "round", "bevel")
_CAPS = ("butt", "round", "square")


def _area2(ring: Sequence[_Pt]) -> float:
    return sum(ring[i][0] * ring[(i + 1) % len(ring)][1] - ring[(i + 1) % len(ring)][0] * ring[i][1]
               for i in range(len(ring)))


def _subpaths(geometry: object, tolerance: Optional[float]) -> List[Tuple[List[_Pt], bool]]:
    """(points, closed) per subpath; a Path's curves flattened finely
    (curves: within its tolerance, at 1/65536 px)."""
    if isinstance(geometry, Path):
        out: List[Tuple[List[_Pt], bool]] = []
        verbs, pts = geometry._verbs, geometry._pts
        k = 0
        cur: List[_Pt] = []
        closed = False
        for v in verbs:
            if v == MOVE:
                if cur:
                    out.append((cur, closed))
                cur, closed = [pts[k]], False
                k += 1
            elif v == CLOSE:
                closed = True
            elif v == LINE:
                cur.append(pts[k])
                k += 1
            else:
                n = 2 if v == QUAD else 3
                sub = Path(tolerance=tolerance if tolerance is not None else geometry.tolerance)
                sub.move_to(*cur[-1])
                if v == QUAD:
                    sub.quad_to(*pts[k], *pts[k + 1])
                else:
                    sub.cubic_to(*pts[k], *pts[k + 1], *pts[k + 2])
                k += n
                from ._path import _flatten_fixed  # the C flattener, at 1/65536 px
                bits = 16
                tol = sub.tolerance if sub.tolerance is not None else 1.0 / 256
                fixed, fverbs = sub._fixed(bits)
                ring = _flatten_fixed(fverbs, fixed, max(1, math.floor(tol * (1 << bits))))[0]
                cur += [(float(x) / (1 << bits), float(y) / (1 << bits)) for x, y in ring[1:-1]]
                cur.append(pts[k - 1])
        if cur:
            out.append((cur, closed))
        return out
    from ._core import ndim, real_array
    if isinstance(geometry, (str, bytes, dict)) or not hasattr(geometry, "__iter__"):
        raise InputError("geometry must be a Path, an (N, 2) array of (x, y) or a list of them, not %s"
                         % type(geometry).__name__)
    if ndim(geometry) == 2 and np.shape(geometry)[1:] == (2,):
        lines: Iterable[object] = [geometry]
    else:
        lines = geometry  # type: ignore[assignment]
    out = []
    for i, line in enumerate(lines):
        a = real_array(line, "geometry: polyline %d" % i, "an (N, 2) array of (x, y)")
        if a.ndim != 2 or a.shape[1] != 2:
            raise InputError("geometry: polyline %d is not an (N, 2) array of (x, y)" % i)
        if not np.isfinite(a).all():
            raise InputError("geometry: polyline %d has a NaN or infinite coordinate" % i)
        if len(a):
            out.append(([tuple(p) for p in a.tolist()], False))
    return out


def stroke(geometry: Union[Path, Sequence[Sequence[float]], Sequence[Sequence[Sequence[float]]]],
           width: float, *, join: str = "miter", cap: str = "butt", miter_limit: float = 4.0,
           dash: Optional[Sequence[float]] = None, dash_offset: float = 0.0,
           tolerance: Optional[float] = None) -> Path:
    """The outline of `geometry` stroked `width` pixels wide, as a Path.

    Fill the result with ``rule="nonzero"`` (every method then draws the
    stroke; "area" gives its exact coverage where crossings overlap).

    Parameters
    ----------
    geometry : Path, (N, 2) array_like, or list of them
        A Path (its subpaths; closed ones are joined all round), or open
        polylines of (x, y) pixels.
    width : float
        The stroke's width in pixels (> 0).
    join : {"miter", "round", "bevel"}
    cap : {"butt", "round", "square"}
    miter_limit : float
        SVG's stroke-miterlimit (>= 1): a miter longer than miter_limit
        times the width (1/sin(theta/2) > miter_limit, theta the angle
        between the segments) is bevelled.
    dash, dash_offset
        Not supported yet: ``dash`` must be None.
    tolerance : float or None
        The returned Path's tolerance (its round parts and flattened
        curves); None: the Path default.

    Returns
    -------
    Path
        Convex pieces, all oriented the same way.  A zero-length subpath
        gives a dot with round caps, an axis-aligned square with square
        caps and nothing with butt caps (SVG).

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
    limit = _real(miter_limit, "miter_limit")
    if not limit >= 1:
        raise InputError("miter_limit: %r; it must be >= 1 (SVG)" % (miter_limit,))
    if dash is not None:
        raise InputError("dash: dashes are not supported yet; pass dash=None")
    _real(dash_offset, "dash_offset")
    h = w / 2
    out = Path(tolerance=tolerance)
    pieces: List[List[_Pt]] = []
    discs: List[_Pt] = []

    for pts, closed in _subpaths(geometry, tolerance):
        p = [pts[0]]
        for q in pts[1:]:
            if q != p[-1]:
                p.append(q)
        if closed and len(p) > 1 and p[-1] == p[0]:
            p.pop()
        if len(p) == 1:  # zero length: SVG's dot or square
            x, y = p[0]
            if cap == "round":
                discs.append((x, y))
            elif cap == "square":
                pieces.append([(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)])
            continue
        n = len(p)
        segs = [(p[i], p[i + 1]) for i in range(n - 1)] + ([(p[-1], p[0])] if closed else [])
        units = []
        for a, b in segs:
            dx, dy = b[0] - a[0], b[1] - a[1]
            ln = math.hypot(dx, dy)
            units.append((dx / ln, dy / ln))
        for (a, b), (ux, uy) in zip(segs, units):
            nx, ny = -uy * h, ux * h
            pieces.append([(a[0] + nx, a[1] + ny), (b[0] + nx, b[1] + ny), (b[0] - nx, b[1] - ny),
                           (a[0] - nx, a[1] - ny)])
        # joins: at every interior vertex, and all round when closed
        verts = range(n) if closed else range(1, n - 1)
        for i in verts:
            d1 = units[i - 1] if i > 0 else units[-1]
            d2 = units[i] if i < len(units) else units[0]
            v = p[i]
            cross = d1[0] * d2[1] - d1[1] * d2[0]
            dot = d1[0] * d2[0] + d1[1] * d2[1]
            if join == "round":
                discs.append(v)
                continue
            if cross == 0 and dot > 0:
                continue
            s = -1.0 if cross > 0 else 1.0
            o1 = (s * -d1[1], s * d1[0])
            o2 = (s * -d2[1], s * d2[0])
            a1 = (v[0] + o1[0] * h, v[1] + o1[1] * h)
            a2 = (v[0] + o2[0] * h, v[1] + o2[1] * h)
            # theta, the angle between the segments: cos theta = -d1.d2;
            # SVG's ratio 1/sin(theta/2) = sqrt(2 / (1 - cos theta))
            if join == "miter" and 1 + dot > 0 and 2 <= limit * limit * (1 + dot):
                m = h / (1 + o1[0] * o2[0] + o1[1] * o2[1])
                tip = (v[0] + (o1[0] + o2[0]) * m, v[1] + (o1[1] + o2[1]) * m)
                pieces.append([v, a1, tip, a2])
            else:
                pieces.append([v, a1, a2])
        if not closed:
            for end, (ux, uy) in ((p[0], (-units[0][0], -units[0][1])), (p[-1], units[-1])):
                if cap == "round":
                    discs.append(end)
                elif cap == "square":
                    nx, ny = -uy * h, ux * h
                    ex, ey = end[0] + ux * h, end[1] + uy * h
                    pieces.append([(end[0] + nx, end[1] + ny), (ex + nx, ey + ny), (ex - nx, ey - ny),
                                   (end[0] - nx, end[1] - ny)])
    for ring in pieces:
        sa = _area2(ring)
        if sa == 0:
            continue
        if sa < 0:
            ring = ring[::-1]
        out.move_to(*ring[0])
        for q in ring[1:]:
            out.line_to(*q)
        out.close()
    for x, y in discs:
        # two half circles; sweep chosen so that the disc turns as the
        # pieces do (positive shoelace area in (x, y), y down: clockwise
        # on screen, SVG's sweep=1)
        out.move_to(x + h, y).arc_to(h, h, 0, False, True, x - h, y).arc_to(h, h, 0, False, True, x + h, y)
        out.close()
    return out

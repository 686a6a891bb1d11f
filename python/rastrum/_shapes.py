"""Shapes as Paths: circles, ellipses, rounded rectangles, arcs, pie
slices, chords and regular polygons (docs/paths.md, "Shapes").

Continuous coordinates (pixels, y down, a pixel's square [x, x+1) as
everywhere in rastrum); angles in degrees, clockwise on screen from 3
o'clock, the parametric angle t of the ellipse (cx + rx cos t,
cy + ry sin t), as Pillow's ImageDraw measures them.  Every closed
shape runs the same way (positive shoelace area in (x, y): clockwise
on screen), so that a non-zero fill of several is their union.  The
elliptic parts are cubics within ``Path.ARC_ERROR`` (1/4096 px) of the
true curve; a fill flattens them within its tolerance on top.

Canvas's methods of the same names (Pillow's argument conventions:
inclusive bounding boxes, points at pixel centres) build these.
"""

from __future__ import annotations

import math
from typing import Optional, Sequence, Tuple

from ._core import InputError
from ._path import ARC_ERROR, Path, _real

__all__ = ["circle", "ellipse", "rounded_rectangle", "arc", "pieslice", "chord", "regular_polygon"]


# More sides are the circle: 65,536 sides are within r (1 - cos(pi/65536)),
# 6e-4 px at the grid's largest radius (524,288 px), of it; and a bound
# keeps n_sides = 2**64 from building points until memory runs out.
MAX_SIDES = 1 << 16


def _radius(v: object, what: str) -> float:
    r = _real(v, what)
    if r < 0:
        raise InputError("%s: %r; it must be >= 0" % (what, v))
    return r


def _segments(r: float, sweep: float) -> int:
    """Cubics for `sweep` radians of a circle of radius r within ARC_ERROR:
    a cubic with k = 4/3 tan(h/4) over angle h is at most
    r 2 sin^6(h/4) / (27 cos^2(h/4)) from the circle (an ellipse, its
    affine image: within max(rx, ry) times that), as Path.arc_to."""
    n = max(1, math.ceil(abs(sweep) / (math.pi / 2) - 1e-12))
    while r * 2 * math.sin(abs(sweep) / n / 4) ** 6 / (27 * math.cos(abs(sweep) / n / 4) ** 2) > ARC_ERROR:
        n += 1
    return n


def _elliptic(p: Path, cx: float, cy: float, rx: float, ry: float, t0: float, sweep: float,
              phi: float = 0.0, start: bool = False) -> None:
    """Append the ellipse's arc from parametric angle t0 over `sweep`
    radians (positive: clockwise on screen) as cubics; `start`: move_to
    its first point first, else line_to it."""
    c, s = math.cos(phi), math.sin(phi)

    def on(t: float) -> Tuple[float, float]:
        ex, ey = rx * math.cos(t), ry * math.sin(t)
        return (c * ex - s * ey + cx, s * ex + c * ey + cy)

    def d(t: float) -> Tuple[float, float]:
        ex, ey = -rx * math.sin(t), ry * math.cos(t)
        return (c * ex - s * ey, s * ex + c * ey)

    a = on(t0)
    if start:
        p.move_to(*a)
    else:
        p.line_to(*a)
    if sweep == 0 or (rx == 0 and ry == 0):
        return
    n = _segments(max(rx, ry), sweep)
    h = sweep / n
    k = 4.0 / 3.0 * math.tan(h / 4)
    for i in range(n):
        ta, tb = t0 + i * h, t0 + (i + 1) * h
        pa, pb, da, db = on(ta), on(tb), d(ta), d(tb)
        p.cubic_to(pa[0] + k * da[0], pa[1] + k * da[1], pb[0] - k * db[0], pb[1] - k * db[1], *pb)


def _sweep(start: float, end: float) -> Tuple[float, float]:
    """(t0, sweep) in radians for Pillow's start and end (degrees): from
    start clockwise to end; end - start >= 360 is the whole ellipse, and
    otherwise the sweep is (end - start) mod 360 (0: nothing)."""
    a, b = _real(start, "start"), _real(end, "end")
    span = b - a
    if span >= 360:
        span = 360.0
    else:
        span = math.fmod(span, 360.0)
        if span < 0:
            span += 360.0
    return math.radians(a), math.radians(span)


def ellipse(cx: float, cy: float, rx: float, ry: float, *, rotation: float = 0.0,
            tolerance: Optional[float] = None) -> Path:
    """The ellipse of centre (cx, cy) and radii rx, ry, its x axis turned
    `rotation` degrees clockwise on screen, as a closed Path.

    Examples
    --------
    >>> import rastrum
    >>> m = rastrum.polygon_mask(rastrum.Path.ellipse(4, 3, 4, 3), (6, 8))
    >>> int(m.sum())
    36
    """
    cx, cy = _real(cx, "cx"), _real(cy, "cy")
    rx, ry = _radius(rx, "rx"), _radius(ry, "ry")
    p = Path(tolerance=tolerance)
    if rx == 0 or ry == 0:
        return p
    _elliptic(p, cx, cy, rx, ry, 0.0, 2 * math.pi, math.radians(_real(rotation, "rotation")), start=True)
    return p.close()


def circle(cx: float, cy: float, r: float, *, tolerance: Optional[float] = None) -> Path:
    """The circle of centre (cx, cy) and radius r, as a closed Path."""
    return ellipse(cx, cy, r, r, tolerance=tolerance)


def arc(cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
        tolerance: Optional[float] = None) -> Path:
    """The open arc of the ellipse (cx, cy, rx, ry) from angle `start` to
    `end` (degrees, clockwise from 3 o'clock, Pillow's convention), for
    :func:`rastrum.stroke`."""
    cx, cy = _real(cx, "cx"), _real(cy, "cy")
    rx, ry = _radius(rx, "rx"), _radius(ry, "ry")
    t0, sweep = _sweep(start, end)
    p = Path(tolerance=tolerance)
    if sweep > 0:
        _elliptic(p, cx, cy, rx, ry, t0, sweep, start=True)
    return p


def pieslice(cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
             tolerance: Optional[float] = None) -> Path:
    """The pie slice: the arc from `start` to `end` (as :func:`arc`) and
    the two radii, closed.  A sweep of 360 is the whole ellipse."""
    cx, cy = _real(cx, "cx"), _real(cy, "cy")
    rx, ry = _radius(rx, "rx"), _radius(ry, "ry")
    t0, sweep = _sweep(start, end)
    p = Path(tolerance=tolerance)
    if sweep == 0 or rx == 0 or ry == 0:
        return p
    if sweep >= 2 * math.pi:
        return ellipse(cx, cy, rx, ry, tolerance=tolerance)
    p.move_to(cx, cy)
    _elliptic(p, cx, cy, rx, ry, t0, sweep)
    return p.close()


def chord(cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
          tolerance: Optional[float] = None) -> Path:
    """The chord: the arc from `start` to `end` (as :func:`arc`) closed by
    the straight line between its ends."""
    cx, cy = _real(cx, "cx"), _real(cy, "cy")
    rx, ry = _radius(rx, "rx"), _radius(ry, "ry")
    t0, sweep = _sweep(start, end)
    p = Path(tolerance=tolerance)
    if sweep == 0 or rx == 0 or ry == 0:
        return p
    _elliptic(p, cx, cy, rx, ry, t0, sweep, start=True)
    return p.close()


def rounded_rectangle(x0: float, y0: float, x1: float, y1: float, radius: float, *,
                      corners: Optional[Sequence[bool]] = None, tolerance: Optional[float] = None) -> Path:
    """The rectangle [x0, x1] x [y0, y1] with corners rounded by quarter
    circles of `radius` (clamped to half the shorter side), as a closed
    Path.  `corners`: four bools, (top left, top right, bottom right,
    bottom left) as Pillow, which corners are rounded (default all)."""
    x0, y0, x1, y1 = (_real(v, n) for v, n in ((x0, "x0"), (y0, "y0"), (x1, "x1"), (y1, "y1")))
    if x1 < x0 or y1 < y0:
        raise InputError("rounded_rectangle: (x0, y0, x1, y1) = %r needs x1 >= x0 and y1 >= y0"
                         % ((x0, y0, x1, y1),))
    r = min(_radius(radius, "radius"), (x1 - x0) / 2, (y1 - y0) / 2)
    if corners is None:
        corners = (True, True, True, True)
    try:
        cs = [bool(c) for c in corners]
    except TypeError:
        raise InputError("corners: %r; four bools (top left, top right, bottom right, bottom left)"
                         % (corners,)) from None
    if len(cs) != 4:
        raise InputError("corners: %r; four bools (top left, top right, bottom right, bottom left)"
                         % (corners,))
    p = Path(tolerance=tolerance)
    if x1 == x0 or y1 == y0:
        return p
    h = math.pi / 2
    # clockwise on screen from the top left: each corner's arc, or its point
    spec = ((x0 + r, y0 + r, 2 * h, x0, y0), (x1 - r, y0 + r, 3 * h, x1, y0),
            (x1 - r, y1 - r, 0.0, x1, y1), (x0 + r, y1 - r, h, x0, y1))
    first = True
    for (ccx, ccy, t0, px, py), rounded in zip(spec, cs):
        if rounded and r > 0:
            _elliptic(p, ccx, ccy, r, r, t0, h, start=first)
        elif first:
            p.move_to(px, py)
        else:
            p.line_to(px, py)
        first = False
    return p.close()


def regular_polygon(cx: float, cy: float, r: float, n_sides: int, *, rotation: float = 0.0,
                    tolerance: Optional[float] = None) -> Path:
    """The regular polygon of `n_sides` inscribed in the circle (cx, cy, r),
    Pillow's vertices: the first at angle 270 - 180/n_sides + rotation
    degrees counter-clockwise on screen from 3 o'clock (rotation 0: a flat
    bottom side), (cx + r cos a, cy - r sin a); not rounded to 2 decimals
    as Pillow rounds them.  n_sides is at most MAX_SIDES (65,536)."""
    cx, cy, r = _real(cx, "cx"), _real(cy, "cy"), _radius(r, "r")
    if type(n_sides) is not int or not 3 <= n_sides <= MAX_SIDES:
        raise InputError("n_sides: %r; an int in 3..%d" % (n_sides, MAX_SIDES))
    rot = _real(rotation, "rotation")
    p = Path(tolerance=tolerance)
    if r == 0:
        return p
    pts = []
    for k in range(n_sides):
        a = math.radians(270 - 180.0 / n_sides + rot + k * 360.0 / n_sides)
        pts.append((cx + r * math.cos(a), cy - r * math.sin(a)))
    pts.reverse()  # clockwise on screen, as every shape here
    p.move_to(*pts[0])
    for q in pts[1:]:
        p.line_to(*q)
    return p.close()

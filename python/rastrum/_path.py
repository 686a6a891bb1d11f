"""Paths: lines, quadratic and cubic Bezier curves and SVG arcs, flattened
in the C core within a stated tolerance (docs/paths.md).

A :class:`Path` is accepted wherever a polygon's rings are
(``polygon_mask``, ``polygon_coverage``): its curves become edges within
``path.tolerance`` pixels of the true curves, the rounding of the
flattened vertices to the grid included (the bound is proven in
csrc/src/path/flatten.c and checked in tests/test_path.py).
"""

from __future__ import annotations

import math
import re
from typing import List, Optional, Sequence, Tuple

import numpy as np

from ._core import InputError
from ._native import ffi, lib

__all__ = ["Path", "DEFAULT_TOLERANCE"]

#: The default flattening tolerance in pixels (or one grid step of the
#: fill, 1/2**subpixel_bits, when that is coarser): where the flattening
#: costs "area" coverage about one level of 255 (1.04 at worst on curved
#: shapes, bench/path_tolerance.py), as much as the default snapping
#: (subpixel_bits=8) does; docs/paths.md, "The default tolerance".
DEFAULT_TOLERANCE = 1.0 / 256

MOVE, LINE, QUAD, CUBIC, CLOSE = (lib.RAST_PATH_MOVE, lib.RAST_PATH_LINE, lib.RAST_PATH_QUAD,
                                  lib.RAST_PATH_CUBIC, lib.RAST_PATH_CLOSE)
_TAKES = {MOVE: 1, LINE: 1, QUAD: 2, CUBIC: 3, CLOSE: 0}

#: How far an arc's cubics may be from the true arc, in pixels (arc_to).
ARC_ERROR = 1.0 / 4096


def _real(v: object, what: str) -> float:
    if isinstance(v, (bool, complex, str, bytes)) or v is None:
        raise InputError("%s: %r is not a real number" % (what, v))
    try:
        f = float(v)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InputError("%s: %r is not a real number" % (what, v)) from None
    except OverflowError:  # an int past float64's range
        raise InputError("%s: too large a number (beyond float64's range)" % what) from None
    if not math.isfinite(f):
        raise InputError("%s: %r is not finite" % (what, v))
    return f


def _flag(v: object, what: str) -> bool:
    """An SVG arc flag: True/False or 0/1, else InputError."""
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, (int, np.integer)) and v in (0, 1):
        return bool(v)
    raise InputError("%s: %r is not a flag (True, False, 0 or 1)" % (what, v))


class Path:
    """A path: subpaths of lines and curves, built by chained calls.

    Coordinates are (x, y) in pixels, y down, as for ``polygon_mask``.
    Each subpath starts with :meth:`move_to`; :meth:`close` ends one (a
    fill closes open subpaths too, as SVG does).

    Parameters
    ----------
    tolerance : float or None
        How far, in pixels, the edges a fill makes of the curves may be
        from the true curves; at least one grid step of the fill
        (1/2**subpixel_bits).  None (the default): ``DEFAULT_TOLERANCE``
        (1/256 px), or one grid step when that is coarser.

    Examples
    --------
    >>> import rastrum
    >>> p = rastrum.Path().move_to(1, 1).quad_to(4, 7, 7, 1).close()
    >>> int(rastrum.polygon_mask(p, (4, 8)).sum())
    12
    """

    #: The default flattening tolerance, pixels, and how far an arc's cubics
    #: may be from the true arc (docs/paths.md).
    DEFAULT_TOLERANCE = DEFAULT_TOLERANCE
    ARC_ERROR = ARC_ERROR


    def __init__(self, *, tolerance: Optional[float] = None) -> None:
        self._vl: List[int] = []
        self._pl: List[Tuple[float, float]] = []
        # (verbs uint8, points (N, 2) float64) and {bits: int32 points on
        # the 1/2**bits grid}, made once and kept until the path changes
        self._arrays: Optional[Tuple[np.ndarray, np.ndarray]] = None
        self._fixed_at: dict = {}
        self._start: Optional[Tuple[float, float]] = None
        self._cur: Optional[Tuple[float, float]] = None
        self._closed = False
        self._tolerance: Optional[float] = None
        self.tolerance = tolerance

    # ---- storage: lists to build, arrays converted once --------------------------
    # Every change goes through these (the builders append to the lists and
    # call _changed; code that assigns or extends _verbs / _pts goes through
    # the setters), so the arrays a fill takes are converted once per edit,
    # not per draw.
    @property
    def _verbs(self) -> List[int]:
        return self._vl

    @_verbs.setter
    def _verbs(self, value: List[int]) -> None:
        self._vl = value
        self._changed()

    @property
    def _pts(self) -> List[Tuple[float, float]]:
        return self._pl

    @_pts.setter
    def _pts(self, value: List[Tuple[float, float]]) -> None:
        self._pl = value
        self._changed()

    def _changed(self) -> None:
        self._arrays = None
        if self._fixed_at:
            self._fixed_at = {}

    # ---- a Path of lines held as arrays (rastrum.stroke's input and outline) ---
    #: None, or (verbs, int32 points, bits) / (verbs, None, None): the
    #: arrays are the truth and the lists are made on first use (by
    #: __getattr__, which only runs when _vl / _pl are not set), so that a
    #: fill reads the outline without a Python tuple per vertex.
    _held: Optional[tuple] = None

    @classmethod
    def _lines(cls, verbs: np.ndarray, points: Optional[np.ndarray] = None, *,
               fixed: Optional[Tuple[np.ndarray, int]] = None, tolerance: Optional[float] = None) -> "Path":
        """A Path of MOVE, LINE and CLOSE verbs held as arrays: `points`
        (N, 2) float64 pixels, or `fixed` (int32 (N, 2) on the 1/2**bits
        grid, bits): rastrum.stroke's outline, which a fill at
        subpixel_bits <= bits then takes rounded from the integers (the
        same values as from the float64 points, which hold them exactly)."""
        p = cls.__new__(cls)
        p._start = p._cur = None
        p._closed = False
        p._tolerance = None
        p.tolerance = tolerance
        v = np.ascontiguousarray(verbs, dtype=np.uint8)
        v.flags.writeable = False
        p._fixed_at = {}
        if fixed is not None:
            q, bits = fixed
            q = np.ascontiguousarray(q, dtype=np.int32).reshape(-1, 2)
            q.flags.writeable = False
            p._arrays = None
            p._fixed_at[bits] = q
            p._held = (v, q, bits)
        else:
            q = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 2)
            q.flags.writeable = False
            p._arrays = (v, q)
            p._held = (v, None, None)
        return p

    def __getattr__(self, name: str) -> object:
        # only when normal lookup fails: a held Path's lists, made once
        held = self.__dict__.get("_held")
        if held is None or name not in ("_vl", "_pl"):
            raise AttributeError(name)
        v, q = self._as_arrays()
        d = self.__dict__
        d["_vl"], d["_pl"] = v.tolist(), list(map(tuple, q.tolist()))
        d["_held"] = None  # the lists are the truth from now on
        return d[name]

    def _as_arrays(self) -> Tuple[np.ndarray, np.ndarray]:
        a = self._arrays
        held = self._held
        if held is not None:
            if a is None:  # points from the integers: n / 2**bits, exact in float64
                q = held[1].astype(np.float64) / float(1 << held[2])
                q.flags.writeable = False
                a = self._arrays = (held[0], q)
            return a
        if a is None or len(a[0]) != len(self._vl) or len(a[1]) != len(self._pl):
            a = self._arrays = (np.array(self._vl, dtype=np.uint8),
                                np.array(self._pl, dtype=np.float64).reshape(-1, 2))
            a[0].flags.writeable = a[1].flags.writeable = False
            self._fixed_at = {}
        return a

    # ---- properties ---------------------------------------------------------
    @property
    def tolerance(self) -> Optional[float]:
        """The flattening tolerance in pixels (> 0), or None: the default."""
        return self._tolerance

    @tolerance.setter
    def tolerance(self, value: Optional[float]) -> None:
        if value is None:
            self._tolerance = None
            return
        t = _real(value, "tolerance")
        if not t > 0:
            raise InputError("tolerance: %r pixels; it must be > 0" % (value,))
        self._tolerance = t

    @property
    def verbs(self) -> np.ndarray:
        """The verbs as uint8 (0 move, 1 line, 2 quad, 3 cubic, 4 close)."""
        return self._as_arrays()[0].copy()

    @property
    def points(self) -> np.ndarray:
        """The points the verbs take, (N, 2) float64 (x, y)."""
        return self._as_arrays()[1].copy()

    def __len__(self) -> int:
        held = self._held
        return len(self._vl) if held is None else len(held[0])

    def __repr__(self) -> str:
        return "Path(%d verbs, %d points, tolerance=%r)" % (len(self._verbs), len(self._pts), self._tolerance)

    def copy(self) -> "Path":
        """An independent copy."""
        p = Path(tolerance=self._tolerance)
        p._vl, p._pl = list(self._vl), list(self._pl)
        p._start, p._cur, p._closed = self._start, self._cur, self._closed
        return p

    # ---- building -------------------------------------------------------------
    def _point(self, x: float, y: float, what: str) -> Tuple[float, float]:
        return (_real(x, what + ": x"), _real(y, what + ": y"))

    def _need_current(self, what: str) -> Tuple[float, float]:
        if self._cur is None:
            raise InputError("%s: no current point; a path starts with move_to" % what)
        self._changed()
        if self._closed:  # SVG: a new subpath at the closed one's start
            self._vl.append(MOVE)
            self._pl.append(self._cur)
            self._closed = False
        return self._cur

    def move_to(self, x: float, y: float) -> "Path":
        """Start a subpath at (x, y)."""
        p = self._point(x, y, "move_to")
        self._changed()
        self._vl.append(MOVE)
        self._pl.append(p)
        self._start = self._cur = p
        self._closed = False
        return self

    def line_to(self, x: float, y: float) -> "Path":
        """A line from the current point to (x, y)."""
        p = self._point(x, y, "line_to")
        self._need_current("line_to")
        self._vl.append(LINE)
        self._pl.append(p)
        self._cur = p
        return self

    def quad_to(self, x1: float, y1: float, x: float, y: float) -> "Path":
        """A quadratic Bezier curve: control point (x1, y1), end (x, y)."""
        c, p = self._point(x1, y1, "quad_to"), self._point(x, y, "quad_to")
        self._need_current("quad_to")
        self._vl.append(QUAD)
        self._pl += [c, p]
        self._cur = p
        return self

    def cubic_to(self, x1: float, y1: float, x2: float, y2: float, x: float, y: float) -> "Path":
        """A cubic Bezier curve: control points (x1, y1), (x2, y2), end (x, y)."""
        c1, c2 = self._point(x1, y1, "cubic_to"), self._point(x2, y2, "cubic_to")
        p = self._point(x, y, "cubic_to")
        self._need_current("cubic_to")
        self._vl.append(CUBIC)
        self._pl += [c1, c2, p]
        self._cur = p
        return self

    def close(self) -> "Path":
        """End the subpath; the current point returns to its start."""
        if self._cur is None:
            raise InputError("close: no current point; a path starts with move_to")
        if not self._closed:
            self._changed()
            self._vl.append(CLOSE)
            self._closed = True
        self._cur = self._start
        return self

    def arc_to(self, rx: float, ry: float, rotation: float, large_arc: bool, sweep: bool,
               x: float, y: float) -> "Path":
        """SVG's elliptical arc from the current point to (x, y).

        Radii rx, ry (pixels), the ellipse's x axis turned by `rotation`
        degrees, and SVG's flags choosing one of the four arcs (SVG 1.1
        appendix F.6: out-of-range radii are scaled up, a zero radius is a
        line).  Stored as cubics within ``ARC_ERROR`` (1/4096) px of the
        true arc.  With y down, ``sweep=True`` turns clockwise on screen.
        """
        large_arc, sweep = _flag(large_arc, "arc_to: large_arc"), _flag(sweep, "arc_to: sweep")
        rx, ry = abs(_real(rx, "arc_to: rx")), abs(_real(ry, "arc_to: ry"))
        phi = math.radians(_real(rotation, "arc_to: rotation"))
        x2, y2 = self._point(x, y, "arc_to")
        x1, y1 = self._need_current("arc_to")
        if (x1, y1) == (x2, y2):
            return self
        if rx == 0 or ry == 0:
            return self.line_to(x2, y2)
        cphi, sphi = math.cos(phi), math.sin(phi)
        dx, dy = (x1 - x2) / 2, (y1 - y2) / 2
        x1p, y1p = cphi * dx + sphi * dy, -sphi * dx + cphi * dy
        lam = (x1p / rx) ** 2 + (y1p / ry) ** 2
        if lam > 1:
            s = math.sqrt(lam)
            rx, ry = rx * s, ry * s
        num = rx * rx * ry * ry - rx * rx * y1p * y1p - ry * ry * x1p * x1p
        den = rx * rx * y1p * y1p + ry * ry * x1p * x1p
        co = math.sqrt(max(num, 0.0) / den) if den else 0.0
        if bool(large_arc) == bool(sweep):
            co = -co
        cxp, cyp = co * rx * y1p / ry, -co * ry * x1p / rx
        cx = cphi * cxp - sphi * cyp + (x1 + x2) / 2
        cy = sphi * cxp + cphi * cyp + (y1 + y2) / 2

        def angle(ux: float, uy: float, vx: float, vy: float) -> float:
            return math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)

        t1 = angle(1, 0, (x1p - cxp) / rx, (y1p - cyp) / ry)
        dt = angle((x1p - cxp) / rx, (y1p - cyp) / ry, (-x1p - cxp) / rx, (-y1p - cyp) / ry)
        if not sweep and dt > 0:
            dt -= 2 * math.pi
        elif sweep and dt < 0:
            dt += 2 * math.pi
        # segments of angle h: the cubic with k = 4/3 tan(h/4) is at most
        # r 2 sin^6(h/4) / (27 cos^2(h/4)) from the circle of radius r
        # (the ellipse's affine image: at most max(rx, ry) times that).
        r = max(rx, ry)
        n = max(1, math.ceil(abs(dt) / (math.pi / 2)))
        while r * 2 * math.sin(abs(dt) / n / 4) ** 6 / (27 * math.cos(abs(dt) / n / 4) ** 2) > ARC_ERROR:
            n += 1
        h = dt / n
        k = 4.0 / 3.0 * math.tan(h / 4)

        def on(t: float) -> Tuple[float, float]:
            ex, ey = rx * math.cos(t), ry * math.sin(t)
            return (cphi * ex - sphi * ey + cx, sphi * ex + cphi * ey + cy)

        def d(t: float) -> Tuple[float, float]:
            ex, ey = -rx * math.sin(t), ry * math.cos(t)
            return (cphi * ex - sphi * ey, sphi * ex + cphi * ey)

        for i in range(n):
            a, b = t1 + i * h, t1 + (i + 1) * h
            pa, pb, da, db = on(a), on(b), d(a), d(b)
            end = (x2, y2) if i == n - 1 else pb
            self.cubic_to(pa[0] + k * da[0], pa[1] + k * da[1], pb[0] - k * db[0], pb[1] - k * db[1], *end)
        return self

    # ---- SVG path data -------------------------------------------------------
    @classmethod
    def from_svg(cls, d: str, *, tolerance: Optional[float] = None) -> "Path":
        """A Path from SVG path data (the ``d`` attribute).

        All of SVG 1.1's commands, absolute (upper case) and relative
        (lower case): M L H V C S Q T A Z, implicit repeats (numbers after
        a command repeat it; after M/m they are lines), the S and T
        reflections, arc flags written without separators.

        Raises
        ------
        InputError
            On malformed data, naming the position.

        Examples
        --------
        >>> import rastrum
        >>> rastrum.Path.from_svg("M0 0 h4 v4 h-4 z").points.tolist()
        [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
        """
        if not isinstance(d, str):
            raise InputError("d: SVG path data must be a str, not %s" % type(d).__name__)
        p = cls(tolerance=tolerance)
        toks = _SvgTokens(d)
        cmd: Optional[str] = None
        cx = cy = 0.0
        last_ctrl: Optional[Tuple[float, float]] = None
        last_cmd = ""
        start = (0.0, 0.0)
        while True:
            c = toks.command()
            if c is None:
                if toks.done():
                    break
                if cmd is None or cmd in "zZ":
                    raise InputError("d: expected a command at position %d of %r" % (toks.pos, d))
                if cmd in "mM":
                    cmd = "l" if cmd == "m" else "L"
            else:
                cmd = c
            rel = cmd.islower()
            u = cmd.upper()
            ox, oy = (cx, cy) if rel else (0.0, 0.0)
            if u == "Z":
                p.close()
                cx, cy = start
                last_ctrl = None
                last_cmd = u
                continue
            if u == "M":
                x, y = toks.number() + ox, toks.number() + oy
                p.move_to(x, y)
                start = (x, y)
                cx, cy = x, y
                last_ctrl = None
            elif u == "L":
                cx, cy = toks.number() + ox, toks.number() + oy
                p.line_to(cx, cy)
                last_ctrl = None
            elif u == "H":
                cx = toks.number() + ox
                p.line_to(cx, cy)
                last_ctrl = None
            elif u == "V":
                cy = toks.number() + (cy if rel else 0.0)
                p.line_to(cx, cy)
                last_ctrl = None
            elif u in "CS":
                if u == "C":
                    x1, y1 = toks.number() + ox, toks.number() + oy
                else:
                    x1, y1 = (2 * cx - last_ctrl[0], 2 * cy - last_ctrl[1]) \
                        if last_cmd in ("C", "S") and last_ctrl is not None else (cx, cy)
                x2, y2 = toks.number() + ox, toks.number() + oy
                x, y = toks.number() + ox, toks.number() + oy
                p.cubic_to(x1, y1, x2, y2, x, y)
                last_ctrl = (x2, y2)
                cx, cy = x, y
            elif u in "QT":
                if u == "Q":
                    x1, y1 = toks.number() + ox, toks.number() + oy
                else:
                    x1, y1 = (2 * cx - last_ctrl[0], 2 * cy - last_ctrl[1]) \
                        if last_cmd in ("Q", "T") and last_ctrl is not None else (cx, cy)
                x, y = toks.number() + ox, toks.number() + oy
                p.quad_to(x1, y1, x, y)
                last_ctrl = (x1, y1)
                cx, cy = x, y
            elif u == "A":
                rx, ry, rot = toks.number(), toks.number(), toks.number()
                large, sweep = toks.flag(), toks.flag()
                x, y = toks.number() + ox, toks.number() + oy
                p.arc_to(rx, ry, rot, large, sweep, x, y)
                cx, cy = x, y
                last_ctrl = None
            else:
                raise InputError("d: unknown command %r at position %d" % (cmd, toks.pos))
            last_cmd = u
        return p

    # ---- other sources, transforms, shapes (docs/paths.md) -------------------------
    @classmethod
    def from_matplotlib(cls, path: object, *, tolerance: Optional[float] = None) -> "Path":
        """A Path from a matplotlib ``Path`` (e.g. ``matplotlib.textpath.TextPath``,
        any font's glyphs): its MOVETO, LINETO, CURVE3 (quadratic), CURVE4
        (cubic) and CLOSEPOLY segments as they are.  matplotlib's y axis
        points up: turn the result with :meth:`transformed`, e.g.
        ``(1, 0, x, 0, -1, y)`` puts its origin at pixel (x, y).
        """
        if not _is_matplotlib_path(path):
            raise InputError("path: a matplotlib Path is needed, not %s" % type(path).__name__)
        p = cls(tolerance=tolerance)
        for seg, code in path.iter_segments(curves=True, simplify=False):  # type: ignore[attr-defined]
            v = [float(t) for t in seg]
            if code == 1:
                p.move_to(v[0], v[1])
            elif code == 2:
                p.line_to(v[0], v[1])
            elif code == 3:
                p.quad_to(*v[:4])
            elif code == 4:
                p.cubic_to(*v[:6])
            elif code == 79:
                p.close()
            elif code != 0:
                raise InputError("path: unknown matplotlib path code %r" % (code,))
        return p

    def transformed(self, transform: object) -> "Path":
        """A copy with every point (x, y) taken to (a*x + b*y + c,
        d*x + e*y + f): `transform` is 6 numbers (a, b, c, d, e, f), an
        ``affine.Affine`` (the same order) or a 2x3 / 3x3 matrix.  Curves
        are affine-invariant: the result is the transformed path."""
        m = np.asarray(transform, dtype=object)
        if m.shape in ((2, 3), (3, 3)):
            flat = list(m[:2].ravel())
        else:
            try:
                flat = list(transform)[:6]  # type: ignore[call-overload]
            except TypeError:
                raise InputError("transform: 6 numbers (a, b, c, d, e, f), an Affine or a 2x3 matrix, "
                                 "not %s" % type(transform).__name__) from None
        if len(flat) != 6:
            raise InputError("transform: 6 numbers (a, b, c, d, e, f), not %d" % len(flat))
        a, b, c, d, e, f = (_real(v, "transform") for v in flat)
        out = self.copy()
        out._pts = [(a * x + b * y + c, d * x + e * y + f) for x, y in self._pts]
        for name in ("_start", "_cur"):
            q = getattr(self, name)
            if q is not None:
                setattr(out, name, (a * q[0] + b * q[1] + c, d * q[0] + e * q[1] + f))
        return out

    @classmethod
    def circle(cls, cx: float, cy: float, r: float, *, tolerance: Optional[float] = None) -> "Path":
        """A circle (docs/paths.md, "Shapes"): centre (cx, cy), radius r."""
        from ._shapes import circle
        return circle(cx, cy, r, tolerance=tolerance)

    @classmethod
    def ellipse(cls, cx: float, cy: float, rx: float, ry: float, *, rotation: float = 0.0,
                tolerance: Optional[float] = None) -> "Path":
        """An ellipse: centre, radii, its x axis turned `rotation` degrees clockwise."""
        from ._shapes import ellipse
        return ellipse(cx, cy, rx, ry, rotation=rotation, tolerance=tolerance)

    @classmethod
    def rounded_rectangle(cls, x0: float, y0: float, x1: float, y1: float, radius: float, *,
                          corners: Optional[Sequence[bool]] = None,
                          tolerance: Optional[float] = None) -> "Path":
        """The rectangle [x0, x1] x [y0, y1], corners rounded by `radius`."""
        from ._shapes import rounded_rectangle
        return rounded_rectangle(x0, y0, x1, y1, radius, corners=corners, tolerance=tolerance)

    @classmethod
    def arc(cls, cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
            tolerance: Optional[float] = None) -> "Path":
        """An open elliptic arc, degrees clockwise from 3 o'clock (Pillow's angles)."""
        from ._shapes import arc
        return arc(cx, cy, rx, ry, start, end, tolerance=tolerance)

    @classmethod
    def pieslice(cls, cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
                 tolerance: Optional[float] = None) -> "Path":
        """A pie slice: the arc and the two radii."""
        from ._shapes import pieslice
        return pieslice(cx, cy, rx, ry, start, end, tolerance=tolerance)

    pie = pieslice

    @classmethod
    def chord(cls, cx: float, cy: float, rx: float, ry: float, start: float, end: float, *,
              tolerance: Optional[float] = None) -> "Path":
        """A chord: the arc closed by a straight line."""
        from ._shapes import chord
        return chord(cx, cy, rx, ry, start, end, tolerance=tolerance)

    @classmethod
    def regular_polygon(cls, cx: float, cy: float, r: float, n_sides: int, *, rotation: float = 0.0,
                        tolerance: Optional[float] = None) -> "Path":
        """A regular polygon inscribed in the circle (cx, cy, r), Pillow's vertices."""
        from ._shapes import regular_polygon
        return regular_polygon(cx, cy, r, n_sides, rotation=rotation, tolerance=tolerance)

    # ---- flattening ------------------------------------------------------------
    def _fixed(self, bits: int) -> Tuple[np.ndarray, np.ndarray]:
        """The points on the 1/2**bits grid (int32, kept until the path
        changes) and the verbs."""
        held = self._held
        if held is not None and held[1] is not None and bits <= held[2]:
            v = self._fixed_at.get(bits)
            if v is None:  # floor(n / 2**k + 1/2) of the held integers n, exactly
                k = held[2] - bits
                v = self._fixed_at[bits] = held[1] if k == 0 else (held[1] + (1 << (k - 1))) >> k
                v.flags.writeable = False
            return v, held[0]
        verbs, pts = self._as_arrays()
        v = self._fixed_at.get(bits)
        if v is None:
            f = np.floor(pts * float(1 << bits) + 0.5)
            lim = lib.RAST_COORD_MAX
            if f.size and (np.abs(f) > lim).any():
                k = int(np.argmax((np.abs(f) > lim).any(axis=1)))
                raise InputError("path: point %d %s is outside the range +-%.6g pixels at subpixel_bits=%d"
                                 % (k, tuple(pts[k]), lim / float(1 << bits), bits))
            v = self._fixed_at[bits] = np.ascontiguousarray(f, dtype=np.int32)
            v.flags.writeable = False
        return v, verbs

    def _grid_tolerance(self, tolerance: Optional[float], bits: int, subpixel_bits: int) -> int:
        """The tolerance in grid steps (1/2**bits px) of a flattening at
        `tolerance` (None: the path's own, else the default), or InputError."""
        given = self._tolerance if tolerance is None else _tolerance(tolerance)
        if given is None:
            tol = max(1, math.floor(DEFAULT_TOLERANCE * (1 << bits)))
        else:
            tol = math.floor(given * (1 << bits))
        if tol < 1:
            raise InputError("tolerance: %r pixels is below one grid step (1/%d px at subpixel_bits=%d)"
                             % (given, 1 << bits, subpixel_bits))
        return min(tol, lib.RAST_COORD_MAX)

    def flatten(self, subpixel_bits: int = 8, tolerance: Optional[float] = None) -> List[np.ndarray]:
        """The path's subpaths as rings of vertices, (N, 2) float64 pixels.

        Each curve becomes edges within `tolerance` (None: ``self.tolerance``;
        both None: max(DEFAULT_TOLERANCE, 1/2**b)) pixels of the curve through its control
        points snapped to 1/2**b pixel, b = min(subpixel_bits, 16) (the
        vertices are on that grid, so a fill at `subpixel_bits` takes them
        exactly).  Subpaths of fewer than 3
        vertices enclose nothing and are left out.
        """
        if type(subpixel_bits) is not int or not 0 <= subpixel_bits <= 32:
            raise InputError("subpixel_bits: %r; it must be an int in 0..32" % (subpixel_bits,))
        bits = min(subpixel_bits, lib.RAST_MAX_SUBPIXEL_BITS)
        tol = self._grid_tolerance(tolerance, bits, subpixel_bits)
        pts, verbs = self._fixed(bits)
        if self._held is not None and len(pts) <= lib.RAST_MAX_POINTS:
            # lines only: each MOVE starts a ring of the points up to the
            # next MOVE, as rast_path_flatten makes them, cut from one array
            starts = (np.cumsum(verbs != CLOSE) - 1)[verbs == MOVE]
            rings = np.split(pts.astype(np.float64) / float(1 << bits), starts[1:])
            return [r for r in rings if len(r) >= 3]
        out = [r.astype(np.float64) / float(1 << bits) for r in _flatten_fixed(verbs, pts, tol)]
        return [r for r in out if len(r) >= 3]


def _tolerance(value: object) -> float:
    t = _real(value, "tolerance")
    if not t > 0:
        raise InputError("tolerance: %r pixels; it must be > 0" % (value,))
    return t


def _is_matplotlib_path(obj: object) -> bool:
    return type(obj).__module__.startswith("matplotlib.") and hasattr(obj, "iter_segments") \
        and hasattr(obj, "vertices")


def as_path(obj: object) -> Optional[Path]:
    """`obj` as a rastrum Path when it is one or a matplotlib Path; else None."""
    if isinstance(obj, Path):
        return obj
    if _is_matplotlib_path(obj):
        return Path.from_matplotlib(obj)
    return None


def path_rings(obj: object, subpixel_bits: object, tolerance: Optional[float]) -> object:
    """The rings a fill takes for `obj`: a Path's (or a matplotlib Path's)
    subpaths flattened within `tolerance` (None: the Path's own, else
    DEFAULT_TOLERANCE) at `subpixel_bits`; anything else as it is (the
    fill checks it; `tolerance` is still checked, curves or not)."""
    if tolerance is not None:
        tolerance = _tolerance(tolerance)
    p = as_path(obj)
    if p is None:
        return obj
    bits = subpixel_bits if type(subpixel_bits) is int and 0 <= subpixel_bits <= 32 else 8
    return p.flatten(bits, tolerance)


def fill_path_aa(target: object, path: Path, pixel: object, opts: object, tolerance: Optional[float]) -> bool:
    """Paint `path` anti-aliased into `target` as ``fill_polygon(path.flatten(
    opts.subpixel_bits, tolerance), ..., aa=...)`` paints it, pixel for
    pixel: flattened in C straight into the filler (python/glue/pathfill.c),
    the path's fixed-point points made once per subpixel_bits.  False when
    it did not paint (subpixel_bits above 16, or an error): the caller then
    takes the general way, which says what is wrong."""
    c = c_form(path, opts.subpixel_bits, tolerance)  # type: ignore[attr-defined]
    if c is None:
        return False
    if not c[1]:  # no verbs: nothing to paint
        return True
    from ._coverage import _lent
    return _lent(lib.rastpy_fill_path_aa, target, *c, opts, pixel) == 0


def c_form(path: Path, bits: int, tolerance: Optional[float]) -> Optional[tuple]:
    """The arguments python/glue/pathfill.c takes for `path` at
    subpixel_bits `bits`: (verbs, number of verbs, points, number of
    coordinates, tolerance on the grid); None above 16 bits, where the
    general (64-bit) way must take it."""
    if bits > lib.RAST_MAX_SUBPIXEL_BITS:
        return None
    tol = path._grid_tolerance(tolerance, bits, bits)
    pts, verbs = path._fixed(bits)
    return ffi.from_buffer("uint8_t[]", verbs), len(verbs), ffi.from_buffer("int32_t[]", pts), len(pts), tol


def _flatten_fixed(verbs: np.ndarray, pts: np.ndarray, tol: int) -> List[np.ndarray]:
    """rast_path_flatten on fixed-point points (int32, units of the grid):
    the rings as (N, 2) int32 arrays, one per subpath."""
    verbs = np.ascontiguousarray(verbs, dtype=np.uint8)
    pts = np.ascontiguousarray(pts, dtype=np.int32).reshape(-1, 2)
    path = ffi.new("rast_path *")
    path.verbs = ffi.from_buffer("uint8_t[]", verbs) if len(verbs) else ffi.NULL
    path.nverbs = len(verbs)
    path.points = ffi.cast("rast_point *", ffi.from_buffer(pts)) if len(pts) else ffi.NULL
    path.npoints = len(pts)
    np_, nr = ffi.new("uint32_t *"), ffi.new("uint32_t *")
    st = lib.rast_path_flatten_size(path, tol, np_, nr)
    if st == lib.RAST_E_TOO_MANY:
        raise InputError("path: more than %d vertices once flattened at this tolerance"
                         % lib.RAST_MAX_POINTS)
    if st != lib.RAST_OK:
        raise InputError("path: %s" % ffi.string(lib.rast_status_str(st)).decode())
    out = np.empty((max(np_[0], 1), 2), dtype=np.int32)
    sizes = np.empty(max(nr[0], 1), dtype=np.uint32)
    poly = ffi.new("rast_polygon *")
    st = lib.rast_path_flatten(path, tol, ffi.cast("rast_point *", ffi.from_buffer(out)), np_[0],
                               ffi.from_buffer("uint32_t[]", sizes), nr[0], poly)
    if st != lib.RAST_OK:  # pragma: no cover - the sizes came from the same path
        raise InputError("path: %s" % ffi.string(lib.rast_status_str(st)).decode())
    ends = np.cumsum(sizes[:nr[0]].astype(np.int64))
    return [out[e - n:e] for e, n in zip(ends, sizes[:nr[0]])]


class _SvgTokens:
    _NUM = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
    _SEP = re.compile(r"[\s,]*")

    def __init__(self, d: str) -> None:
        self.d = d
        self.pos = 0

    def _skip(self) -> None:
        self.pos = self._SEP.match(self.d, self.pos).end()  # type: ignore[union-attr]

    def done(self) -> bool:
        self._skip()
        return self.pos >= len(self.d)

    def command(self) -> Optional[str]:
        self._skip()
        if self.pos < len(self.d) and self.d[self.pos] in "MmLlHhVvCcSsQqTtAaZz":
            self.pos += 1
            return self.d[self.pos - 1]
        if self.pos < len(self.d) and self.d[self.pos].isalpha() and self.d[self.pos] not in "eE":
            raise InputError("d: unknown command %r at position %d" % (self.d[self.pos], self.pos))
        return None

    def number(self) -> float:
        self._skip()
        m = self._NUM.match(self.d, self.pos)
        if not m:
            raise InputError("d: expected a number at position %d of %r" % (self.pos, self.d))
        self.pos = m.end()
        return float(m.group())

    def flag(self) -> bool:
        self._skip()
        if self.pos < len(self.d) and self.d[self.pos] in "01":
            self.pos += 1
            return self.d[self.pos - 1] == "1"
        raise InputError("d: expected an arc flag (0 or 1) at position %d of %r" % (self.pos, self.d))

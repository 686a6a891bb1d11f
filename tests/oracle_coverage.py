"""Exact reference for anti-aliased coverage (docs/coverage.md).

Written from the specification only; shares no code with the C library.
Everything is exact rational arithmetic (``fractions.Fraction``).

Area coverage
-------------
The plane is cut into horizontal slabs at every event ordinate: every
vertex's y, every y where two edges cross, and every integer y (pixel row
boundaries).  Inside a slab no two edges cross and none starts or ends, so
the edges spanning it can be ordered by their abscissa at the slab's
middle, and the winding number is constant between neighbours (the sum of
the directions of the edges to the left: +1 for an edge going down).  The
inside is then a union of trapezoids [L(y), R(y)] (even-odd: odd winding,
non-zero: non-zero winding), and the area of each trapezoid inside column
[i, i+1) is computed exactly: A(i+1) - A(i), with A(X) the trapezoid's area
left of x = X.

This differs from the C code's method (a per-row sweep through the nearest
crossing of neighbours, with a fixed-point grid and 128-bit cell sums):
here every crossing of every pair of edges is found globally and nothing is
rounded.

``coverage_clip`` is a second, independent reference for the special case
of rings that neither cross nor overlap each other or themselves: it clips
each ring against each pixel square (Sutherland-Hodgman) and sums the
signed shoelace areas; the tests cross-check the two.

Supersampling
-------------
``coverage_ss`` is the binary oracle (tests/oracle.py) on a grid k times
finer, with counts per pixel and the value floor(count*M/k^2 + 1/2).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

import oracle

F = Fraction


def _edges(rl):
    """Non-horizontal edges as (xtop, ytop, xbot, ybot, dir)."""
    out = []
    for ring in rl:
        n = len(ring)
        for k in range(n):
            (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % n]
            if y0 == y1:
                continue
            if y0 < y1:
                out.append((x0, y0, x1, y1, 1))
            else:
                out.append((x1, y1, x0, y0, -1))
    return out


def _x_at(e, y):
    xt, yt, xb, yb, _ = e
    return xt + (y - yt) * (xb - xt) / (yb - yt)


def _crossing_y(a, b):
    """The y where the lines of edges a and b meet, or None (parallel)."""
    # x = xt + (y - yt) s  with s = dx/dy
    sa = (a[2] - a[0]) / (a[3] - a[1])
    sb = (b[2] - b[0]) / (b[3] - b[1])
    if sa == sb:
        return None
    # a[0] + (y - a[1]) sa = b[0] + (y - b[1]) sb
    return (b[0] - a[0] + a[1] * sa - b[1] * sb) / (sa - sb)


def _left_area(X, e0, e1, h):
    """Integral over a slab of height h of max(X - E(y), 0), E linear from
    e0 (top) to e1 (bottom)."""
    if e0 <= X and e1 <= X:
        return h * (X - (e0 + e1) / 2)
    if e0 >= X and e1 >= X:
        return F(0)
    if e0 < X:  # e0 < X < e1: E < X on the top part, down to y*
        ys = h * (X - e0) / (e1 - e0)
        return ys * (X - e0) / 2
    ys = h * (e0 - X) / (e0 - e1)  # e1 < X < e0: the bottom part
    return (h - ys) * (X - e1) / 2


def events_y(rl, h):
    """All event ordinates in [0, h]: vertices, crossings, row boundaries."""
    edges = _edges(rl)
    ys = set(F(j) for j in range(h + 1))
    for ring in rl:
        for _, y in ring:
            if 0 <= y <= h:
                ys.add(y)
    for p in range(len(edges)):
        for q in range(p + 1, len(edges)):
            a, b = edges[p], edges[q]
            y = _crossing_y(a, b)
            if y is None:
                continue
            lo = max(a[1], b[1])
            hi = min(a[3], b[3])
            if lo < y < hi and 0 < y < h:
                ys.add(y)
    return sorted(ys)


def _one_orientation(tris):
    """The triangles with positive signed area (degenerate ones dropped):
    under non-zero their union."""
    out = []
    for t in tris:
        (ax, ay), (bx, by), (cx, cy) = t
        cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if cross:
            out.append(t if cross > 0 else [t[0], t[2], t[1]])
    return out


def coverage_exact(rings, shape, *, rule="evenodd", subpixel_bits=8, triangles=False,
                   origin=(0, 0)):
    """The exact coverage of every pixel: an (H, W) object array of
    Fractions.  With ``triangles``, `rings` is a list of triangles and the
    region is their union (each triangle turned to one orientation, rule
    non-zero).  `origin` (integers x0, y0): the window is pixels
    [x0, x0 + W) x [y0, y0 + H) instead (the vertices are snapped first,
    then moved by -origin, exactly)."""
    h, w = shape
    rl = oracle.snapped_rings(rings, subpixel_bits)
    ox, oy = origin
    if ox or oy:
        rl = [[(x - ox, y - oy) for x, y in r] for r in rl]
    if triangles:
        rule, rl = "nonzero", _one_orientation(rl)
    edges = _edges(rl)
    out = np.empty((h, w), dtype=object)
    out.fill(F(0))
    ys = events_y(rl, h)
    for ya, yb in zip(ys, ys[1:]):
        j = math.floor(ya)
        if j < 0 or j >= h:
            continue
        hgt = yb - ya
        ym = (ya + yb) / 2
        span = [e for e in edges if e[1] <= ya and e[3] >= yb]
        span.sort(key=lambda e: _x_at(e, ym))
        wnd = 0
        left = None
        for e in span:
            before = wnd
            wnd += e[4]
            inside_b = (before % 2 == 1) if rule == "evenodd" else before != 0
            inside_a = (wnd % 2 == 1) if rule == "evenodd" else wnd != 0
            if not inside_b and inside_a:
                left = e
            elif inside_b and not inside_a:
                _add_trapezoid(out, j, w, left, e, ya, yb, hgt)
    return out


def _add_trapezoid(out, j, w, L, R, ya, yb, hgt):
    l0, l1 = _x_at(L, ya), _x_at(L, yb)
    r0, r1 = _x_at(R, ya), _x_at(R, yb)
    lo = math.floor(min(l0, l1))
    hi = math.ceil(max(r0, r1))

    def A(X):
        return _left_area(X, l0, l1, hgt) - _left_area(X, r0, r1, hgt)

    prev = A(F(max(lo, 0)))
    for i in range(max(lo, 0), min(hi, w)):
        cur = A(F(i + 1))
        out[j, i] += cur - prev
        prev = cur


# ---- a second reference: clipping (rings without overlaps only) ----------

def _clip(poly, axis, bound, keep_greater):
    res = []
    n = len(poly)
    for k in range(n):
        p, q = poly[k], poly[(k + 1) % n]
        pin = (p[axis] >= bound) if keep_greater else (p[axis] <= bound)
        qin = (q[axis] >= bound) if keep_greater else (q[axis] <= bound)
        if pin:
            res.append(p)
        if pin != qin:
            t = (bound - p[axis]) / (q[axis] - p[axis])
            res.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return res


def coverage_clip(rings, shape, *, subpixel_bits=8):
    """|signed area| of each ring clipped to each pixel, summed with the
    ring's orientation sign relative to the first ring: right for rings
    that do not overlap (an outer ring and holes inside it, islands)."""
    h, w = shape
    rl = oracle.snapped_rings(rings, subpixel_bits)
    out = np.empty((h, w), dtype=object)
    out.fill(F(0))

    def shoelace(p):
        return sum(p[k][0] * p[(k + 1) % len(p)][1] - p[(k + 1) % len(p)][0] * p[k][1]
                   for k in range(len(p))) / 2

    signs = [1 if shoelace(r) >= 0 else -1 for r in rl]
    outer = signs[0] if signs else 1
    for r, s in zip(rl, signs):
        for j in range(h):
            for i in range(w):
                p = r
                for axis, bound, g in ((0, F(i), True), (0, F(i + 1), False),
                                       (1, F(j), True), (1, F(j + 1), False)):
                    p = _clip(p, axis, bound, g)
                    if not p:
                        break
                if p:
                    out[j, i] += shoelace(p) * outer
    return out


# ---- levels and supersampling ---------------------------------------------

def level(a, M):
    """floor(a*M + 1/2), exactly."""
    return math.floor(a * M + F(1, 2))


def coverage_ss(rings, shape, k, *, rule="evenodd", subpixel_bits=8, sample_offset=0.5,
                M=255, triangles=False):
    """floor(count*M/k^2 + 1/2) per pixel, count = inside samples of the
    binary oracle on the k-times finer grid (vertices snapped first)."""
    h, w = shape
    rl = oracle.snapped_rings(rings, subpixel_bits)
    if triangles:
        rule, rl = "nonzero", _one_orientation(rl)
    fine = [[(float(x * k), float(y * k)) for x, y in r] for r in rl]  # exact dyadics
    if not fine:
        return np.zeros((h, w), dtype=np.int64)
    m = oracle.oracle_mask(fine, (h * k, w * k), rule=rule, subpixel_bits=None,
                           sample_offset=sample_offset)
    counts = m.reshape(h, k, w, k).sum(axis=(1, 3)).astype(np.int64)
    return (2 * counts * M + k * k) // (2 * k * k)

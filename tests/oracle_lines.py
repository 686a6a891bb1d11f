"""Exact references for rastrum's lines and point-in-triangle predicates.

Written from the comments of ``csrc/include/rastrum.h`` ("lines",
"predicates") only, with ``fractions.Fraction``; it shares no code with the
C library or the bindings.  Inputs are fixed-point integers (units of
1/2**S pixel), as the C functions take them.

Line (header): with dx = bx - ax, dy = by - ay,
* x-major (|dx| >= |dy|, also a = b): one pixel in each column i whose
  sample abscissa i + o lies in [min(ax, bx), max(ax, bx)]; its row is
  j = floor(y(i + o) - o + 1/2) with y(x) = ay + (x - ax) dy / dx (ay when
  dx = 0);
* y-major (|dy| > |dx|): the same with x and y swapped.
Listed in order from a to b.

DDA (header and line.c's documentation of RAST_LINE_DDA): the same major
pixels; the minor coordinate starts at the exact line at the first sample
rounded to 1/2**16 pixel (half up), grows by the slope rounded to 1/2**16
(half up) per step, and each pixel is floor(y - o + 1/2) of that value.
"""

from __future__ import annotations

import math
from fractions import Fraction

HALF = Fraction(1, 2)


def _floor(v: Fraction) -> int:
    return math.floor(v)


def _ceil(v: Fraction) -> int:
    return math.ceil(v)


def _axes(a, b, S):
    """(major, minor) coordinates of a and b in pixels, and whether y is major."""
    den = 1 << S
    ax, ay = Fraction(a[0], den), Fraction(a[1], den)
    bx, by = Fraction(b[0], den), Fraction(b[1], den)
    ymajor = abs(by - ay) > abs(bx - ax)
    if ymajor:
        return (ay, ax), (by, bx), True
    return (ax, ay), (bx, by), False


def _major_samples(amaj, bmaj, o):
    """The major pixel indices whose sample lies on the segment, from a
    (a range: a line may be 2**28 pixels long)."""
    lo = _ceil(min(amaj, bmaj) - o)
    hi = _floor(max(amaj, bmaj) - o)
    return range(lo, hi + 1) if bmaj >= amaj else range(hi, lo - 1, -1)


def _in_clip(xy, clip):
    return clip is None or (clip[0] <= xy[0] < clip[2] and clip[1] <= xy[1] < clip[3])


def _clip_majors(majors, ymajor, clip):
    """Keep the major indices inside the clip (so that a huge line seen
    through a small window costs only the window)."""
    if clip is None or not majors:
        return majors
    lo, hi = (clip[1], clip[3]) if ymajor else (clip[0], clip[2])
    first, last = majors[0], majors[-1]
    if first <= last:
        return range(max(first, lo), min(last + 1, hi))
    return range(min(first, hi - 1), max(last - 1, lo - 1), -1)


def line_pixels(a, b, S, o, clip=None):
    """The header's pixels of segment a -> b, as a list of (x, y) from a.

    a, b: (x, y) integers in 1/2**S pixel; o: 0 or Fraction(1, 2);
    clip: None or (x0, y0, x1, y1), keeping x0 <= x < x1, y0 <= y < y1."""
    o = Fraction(o)
    (amaj, amin), (bmaj, bmin), ymajor = _axes(a, b, S)
    out = []
    for p in _clip_majors(_major_samples(amaj, bmaj, o), ymajor, clip):
        t = p + o
        if bmaj == amaj:
            v = amin
        else:
            v = amin + (t - amaj) * (bmin - amin) / (bmaj - amaj)
        q = _floor(v - o + HALF)
        xy = (q, p) if ymajor else (p, q)
        if _in_clip(xy, clip):
            out.append(xy)
    return out


def dda_pixels(a, b, S, o, bits=16):
    """The documented integer DDA's pixels of a -> b, from a."""
    o = Fraction(o)
    one = 1 << bits
    (amaj, amin), (bmaj, bmin), ymajor = _axes(a, b, S)
    majors = _major_samples(amaj, bmaj, o)
    if not majors:
        return []
    adx = abs(bmaj - amaj)
    t0 = majors[0] + o
    if adx == 0:
        slope = Fraction(0)
        y0 = amin
    else:
        slope = (bmin - amin) / adx  # minor per major step, walking from a
        y0 = amin + abs(t0 - amaj) * slope
    y = Fraction(_floor(y0 * one + HALF), one)
    m = Fraction(_floor(slope * one + HALF), one)
    out = []
    for p in majors:
        q = _floor(y - o + HALF)
        out.append((q, p) if ymajor else (p, q))
        y += m
    return out


# ---- predicates --------------------------------------------------------------


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def in_closed_triangle(p, t):
    """p in the closed triangle t (edges and vertices included); a triangle of
    zero area contains no point (the header's choice for every closed test)."""
    area = _cross(t[0], t[1], t[2])
    if area == 0:
        return False
    # barycentric coordinates as exact fractions
    beta = Fraction(_cross(t[0], p, t[2]), area)
    gamma = Fraction(_cross(t[0], t[1], p), area)
    alpha = 1 - beta - gamma
    return alpha >= 0 and beta >= 0 and gamma >= 0


def owned(p, t):
    """DESIGN section 1 evaluated at a sample placed exactly at p: the
    crossings of row p.y by the ring t (top closed, bottom open) at
    X <= p.x, by their exact rational abscissa; inside iff the winding
    number is odd (a triangle's is 0 or +-1, so either rule)."""
    px, py = Fraction(p[0]), Fraction(p[1])
    wind = 0
    for k in range(3):
        (x0, y0), (x1, y1) = t[k], t[(k + 1) % 3]
        if y0 == y1:
            continue
        if min(y0, y1) <= py < max(y0, y1):
            X = x0 + (py - y0) * Fraction(x1 - x0, y1 - y0)
            if X <= px:
                wind += 1 if y1 > y0 else -1
    return wind % 2 == 1


def point_in_triangle(p, t, method):
    """The reference answer of every method of rast_point_in_triangle."""
    if method == "owner":
        return owned(p, t)
    if method in ("sameside", "cross", "area", "barycentric"):
        return in_closed_triangle(p, t)
    raise ValueError(method)

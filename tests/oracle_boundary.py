"""Exact references of the boundary modes (rastrum.h, rast_boundary).

Written from the header's definitions with fractions.Fraction, sharing
nothing with the C code (which works row by row in integers):

* "closed": the exact fill plus, for every edge of every ring, the pixels
  of the library's line between its two (snapped) vertices (the line's
  reference is tests/oracle_lines.py);
* "conservative": the exact fill plus every pixel whose OPEN square
  (i, i+1) x (j, j+1) meets an edge, a closed segment; tested here by
  clipping the segment's parameter t in [0, 1] against the four open
  half-planes of the square.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from oracle import oracle_mask, snapped_rings
from oracle_lines import line_pixels


def _t_window(p, d, lo, hi):
    """The t for which lo < p + t*d < hi, as (t0, t1) with open ends; None
    when empty; (None, None) when every t qualifies."""
    if d == 0:
        return (None, None) if lo < p < hi else None
    t0, t1 = (lo - p) / d, (hi - p) / d
    return (t0, t1) if t0 < t1 else (t1, t0)


def segment_meets_open_square(a, b, i, j):
    """Does the closed segment a-b meet (i, i+1) x (j, j+1)?"""
    lo, lo_open, hi, hi_open = Fraction(0), False, Fraction(1), False
    for p, d, c in ((a[0], b[0] - a[0], i), (a[1], b[1] - a[1], j)):
        w = _t_window(p, d, c, c + 1)
        if w is None:
            return False
        if w == (None, None):
            continue
        if w[0] > lo or (w[0] == lo and not lo_open):
            lo, lo_open = w[0], True
        if w[1] < hi or (w[1] == hi and not hi_open):
            hi, hi_open = w[1], True
    return lo < hi or (lo == hi and not lo_open and not hi_open)


def _edges(rings, subpixel_bits):
    for ring in snapped_rings(rings, subpixel_bits):
        n = len(ring)
        for k in range(n):
            yield ring[k], ring[(k + 1) % n]


def oracle_closed(rings, shape, *, rule="evenodd", subpixel_bits=8,
                  sample_offset=0.5, rounding="exact"):
    out = oracle_mask(rings, shape, rule=rule, subpixel_bits=subpixel_bits,
                      sample_offset=sample_offset, rounding=rounding).copy()
    h, w = shape
    scale = 1 << subpixel_bits
    for a, b in _edges(rings, subpixel_bits):
        fa = (int(a[0] * scale), int(a[1] * scale))
        fb = (int(b[0] * scale), int(b[1] * scale))
        for i, j in line_pixels(fa, fb, subpixel_bits, Fraction(sample_offset), (0, 0, w, h)):
            out[j, i] = True
    return out


def oracle_conservative(rings, shape, *, rule="evenodd", subpixel_bits=8,
                        sample_offset=0.5, rounding="exact"):
    out = oracle_mask(rings, shape, rule=rule, subpixel_bits=subpixel_bits,
                      sample_offset=sample_offset, rounding=rounding).copy()
    h, w = shape
    for a, b in _edges(rings, subpixel_bits):
        i0 = max(math.floor(min(a[0], b[0])) - 1, 0)
        i1 = min(math.ceil(max(a[0], b[0])) + 1, w)
        j0 = max(math.floor(min(a[1], b[1])) - 1, 0)
        j1 = min(math.ceil(max(a[1], b[1])) + 1, h)
        for j in range(j0, j1):
            for i in range(i0, i1):
                if not out[j, i] and segment_meets_open_square(a, b, i, j):
                    out[j, i] = True
    return out


ORACLES = {"closed": oracle_closed, "conservative": oracle_conservative}

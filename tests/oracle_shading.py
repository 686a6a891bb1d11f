"""Exact references for the Gouraud rectangle and the colour-interpolating
polygon fill, written from their definitions in rastrum.h with Fractions.
Independent of the C code: the pixel set comes from oracle.oracle_mask."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from oracle import oracle_mask, snap


def _round(x: Fraction) -> int:
    return math.floor(x + Fraction(1, 2))


def rect_gouraud(rect, colors, shape, *, precision="exact", fraction_bits=16, subpixel_bits=8,
                 sample_offset=0.5, channels=4, background=0):
    """(H, W, channels) uint8: the rectangle on a `background` canvas.

    colors: (4, channels) ints for (x0, y0), (x1, y0), (x1, y1), (x0, y1)."""
    h, w = shape
    S = subpixel_bits
    one_px = 1 << S
    x0, y0, x1, y1 = (Fraction(snap(v, S), one_px) for v in rect)
    out = np.full((h, w, channels), background, np.uint8)
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    mask = oracle_mask([[(float(a), float(b)) for a, b in ring]], shape, subpixel_bits=S,
                       sample_offset=sample_offset)
    cols = [[int(c) for c in col] for col in colors]
    o = Fraction(sample_offset)
    if precision == "flat":
        for j, i in zip(*np.nonzero(mask)):
            out[j, i] = cols[0]
        return out
    if precision == "exact":
        for j, i in zip(*np.nonzero(mask)):
            u = (i + o - x0) / (x1 - x0)
            v = (j + o - y0) / (y1 - y0)
            for ch in range(channels):
                c = ((1 - u) * (1 - v) * cols[0][ch] + u * (1 - v) * cols[1][ch]
                     + u * v * cols[2][ch] + (1 - u) * v * cols[3][ch])
                out[j, i, ch] = _round(c)
        return out
    # fixed: put the corners in order, colours following them
    c = [list(cc) for cc in cols]
    if x1 < x0:
        x0, x1 = x1, x0
        c = [c[1], c[0], c[3], c[2]]
    if y1 < y0:
        y0, y1 = y1, y0
        c = [c[3], c[2], c[1], c[0]]
    W, H = x1 - x0, y1 - y0
    one = 1 << fraction_bits
    rows, colsx = np.nonzero(mask)
    if rows.size == 0:
        return out
    # first row/column of the rectangle (unclipped): the first sample at or
    # below/right of the top/left side
    jr0 = math.ceil(y0 - o)
    ic0 = math.ceil(x0 - o)
    b0 = jr0 + o - y0
    a0 = ic0 + o - x0
    for j, i in zip(rows, colsx):
        k, m = j - jr0, i - ic0
        for ch in range(channels):
            L = _round((c[0][ch] + b0 * (c[3][ch] - c[0][ch]) / H) * one) + k * _round((c[3][ch] - c[0][ch]) * one / H)
            R = _round((c[1][ch] + b0 * (c[2][ch] - c[1][ch]) / H) * one) + k * _round((c[2][ch] - c[1][ch]) * one / H)
            C = L + _round((R - L) * a0 / W) + m * _round(Fraction(R - L) / W)
            val = math.floor(Fraction(C + (one >> 1), one))
            out[j, i, ch] = min(255, max(0, val))
    return out

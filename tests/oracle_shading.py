"""Exact references for the Gouraud rectangle and the colour-interpolating
polygon fill, written from their definitions in rastrum.h with Fractions.
Independent of the C code: the pixel set comes from oracle.oracle_mask."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

import oracle_shade
from oracle import oracle_mask, snap


_round = oracle_shade._round  # floor(v + 1/2), the one rounding of every shaded value


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


def polygon_gouraud(rings, colors, shape, *, rule="evenodd", subpixel_bits=8, sample_offset=0.5,
                    channels=4, background=0):
    """(H, W, channels) uint8: the colour polygon fill as rast_fill_polygon_gouraud
    defines it (edge, then span), in Fractions, on a `background` canvas.

    rings: list of (N_k, 2); colors: (sum N_k, channels) ints, vertices in order."""
    h, w = shape
    S = subpixel_bits
    o = Fraction(sample_offset)
    out = np.full((h, w, channels), background, np.uint8)
    pts, edges = [], []  # edges: (index of first vertex, a, b)
    for ring in rings:
        base = len(pts)
        ring = [(Fraction(snap(x, S), 1 << S), Fraction(snap(y, S), 1 << S)) for x, y in ring]
        pts.extend(ring)
        n = len(ring)
        for k in range(n):
            edges.append((base + k, base + k, base + (k + 1) % n))
    cols = [[int(c) for c in col] for col in colors]
    for j in range(h):
        yc = j + o
        cross = []  # (X, first vertex index, dir, colour list)
        for idx, ia, ib in edges:
            (xa, ya), (xb, yb) = pts[ia], pts[ib]
            if ya == yb or not (min(ya, yb) <= yc < max(ya, yb)):
                continue
            t = (yc - ya) / (yb - ya)
            X = xa + t * (xb - xa)
            c = [cols[ia][ch] + t * (cols[ib][ch] - cols[ia][ch]) for ch in range(channels)]
            cross.append((X, idx, 1 if yb > ya else -1, c))
        cross.sort(key=lambda e: (e[0], e[1]))
        runs = []
        if rule == "evenodd":
            runs = [(cross[k], cross[k + 1]) for k in range(0, len(cross) - 1, 2)]
        else:
            wnd, start = 0, None
            for e in cross:
                if wnd == 0:
                    start = e
                wnd += e[2]
                if wnd == 0:
                    runs.append((start, e))
        for l, r in runs:
            Xl, Xr = l[0], r[0]
            i0 = max(0, math.ceil(Xl - o))      # first sample >= Xl
            i1 = min(w, math.ceil(Xr - o))      # first sample >= Xr (excluded)
            for i in range(i0, i1):
                xs = i + o
                for ch in range(channels):
                    c = l[3][ch] + (xs - Xl) * (r[3][ch] - l[3][ch]) / (Xr - Xl)
                    out[j, i, ch] = _round(c)
    return out


def triangle_barycentric(tri, colors, shape, *, subpixel_bits=8, sample_offset=0.5, channels=4):
    """The barycentric (plane) Gouraud colours of one triangle, rounded half
    up, on the triangle's exact pixels (a zero background): the shaded
    triangles' reference (oracle_shade.shade), not a second copy of it."""
    rgba = np.zeros((1, 3, 4), np.int64)
    rgba[0, :, :channels] = np.asarray(colors, np.int64)[:, :channels]
    out, _ = oracle_shade.shade([tri], rgba, shape, subpixel_bits=subpixel_bits,
                                sample_offset=sample_offset)
    return np.where(out < 0, 0, out)[..., :channels].astype(np.uint8)

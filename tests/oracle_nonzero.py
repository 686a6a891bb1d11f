"""An exact oracle of "area" under the non-zero rule that stays quick where
hundreds of long edges cross in a strip (tests/oracle_coverage.py's
coverage_exact takes every pair of edges and every slab for the whole
canvas: minutes on 300 spanning edges).  Exact rational arithmetic
(fractions) wherever a value is kept; floats only choose which pairs of
edges to test exactly for a crossing (a wide margin) and order the edges
inside a slab where no two are within 1e-9 of each other (else exactly).
tests/test_coverage_few_live.py checks it against coverage_exact."""

import functools
import math
from fractions import Fraction as F

import numpy as np

import oracle


def _clamped(x0, x1, c, h):
    """Integral over a slab of height h of clamp(X(y) - c, 0, 1), X linear
    from x0 (top) to x1 (bottom): split where X crosses c and c + 1."""
    if x0 == x1:
        return h * min(max(x0 - c, F(0)), F(1))
    cuts = sorted({F(0), F(1)} | {(v - x0) / (x1 - x0) for v in (c, c + 1) if min(x0, x1) < v < max(x0, x1)})
    tot = F(0)
    for t0, t1 in zip(cuts, cuts[1:]):
        a, b = x0 + (x1 - x0) * t0, x0 + (x1 - x0) * t1
        m = (a + b) / 2  # a piece lies wholly left of c, inside, or right of c + 1
        tot += (t1 - t0) * h * (F(0) if m <= c else F(1) if m >= c + 1 else m - c)
    return tot


def _x(e, y):
    return e[0] + (y - e[1]) * (e[2] - e[0]) / (e[3] - e[1])


def nonzero_area(rings, shape, s=8):
    """Exact area of {winding != 0} in each pixel: row by row, the strip cut
    at every vertex and crossing inside it; in each slab the edges in order
    (no two cross inside it: by floats, exactly where two are within
    1e-9), the winding number summed left to right, and each column's area
    between the edges where it turns non-zero and back."""
    h, w = shape
    edges = []
    for ring in oracle.snapped_rings(rings, s):
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            if y0 != y1:
                edges.append((x0, y0, x1, y1, 1) if y0 < y1 else (x1, y1, x0, y0, -1))
    out = np.empty(shape, object)
    out[:] = F(0)
    bundle = {}  # coincident edges (the same ends): one, their directions summed
    for e in edges:
        bundle[e[:4]] = bundle.get(e[:4], 0) + e[4]
    edges = [k + (d,) for k, d in bundle.items() if d]
    for j in range(h):
        es = [e for e in edges if e[1] < j + 1 and e[3] > j]
        if not es:
            continue
        ys = {F(j), F(j + 1)} | {y for e in es for y in (e[1], e[3]) if j < y < j + 1}
        top = np.array([float(max(e[1], j)) for e in es])
        bot = np.array([float(min(e[3], j + 1)) for e in es])
        xt, yt = np.array([float(e[0]) for e in es]), np.array([float(e[1]) for e in es])
        sl = np.array([float((e[2] - e[0]) / (e[3] - e[1])) for e in es])
        lo, hi = np.maximum(top[:, None], top[None, :]), np.minimum(bot[:, None], bot[None, :])
        d0 = (xt[:, None] + (lo - yt[:, None]) * sl[:, None]) - (xt[None, :] + (lo - yt[None, :]) * sl[None, :])
        d1 = (xt[:, None] + (hi - yt[:, None]) * sl[:, None]) - (xt[None, :] + (hi - yt[None, :]) * sl[None, :])
        for p, q in np.argwhere(np.triu((hi > lo) & (d0 * d1 <= 1e-9 * (1 + np.abs(d0) + np.abs(d1))), 1)):
            a, b = es[p], es[q]
            sa, sb = (a[2] - a[0]) / (a[3] - a[1]), (b[2] - b[0]) / (b[3] - b[1])
            if sa != sb:
                y = (b[0] - a[0] + a[1] * sa - b[1] * sb) / (sa - sb)
                if max(a[1], b[1], j) < y < min(a[3], b[3], j + 1):
                    ys.add(y)
        ys = sorted(ys)
        dirs = np.array([e[4] for e in es])
        spans = {}  # edge: [top, bottom, sign] where it bounds the non-zero region
        for ya, yb in zip(ys, ys[1:]):
            ym = float((ya + yb) / 2)
            act = np.nonzero((top <= ym) & (bot >= ym))[0]
            xm = xt[act] + (ym - yt[act]) * sl[act]
            order = act[np.argsort(xm, kind="stable")]
            xs = np.sort(xm)
            if (np.diff(xs) < 1e-9).any():  # near: those exactly
                m, fx = (ya + yb) / 2, dict(zip(act, xm))

                def cmp(p, q):
                    d = fx[p] - fx[q]
                    if abs(d) > 1e-9:
                        return -1 if d < 0 else 1
                    d = _x(es[p], m) - _x(es[q], m)
                    return (d > 0) - (d < 0)
                order = np.array(sorted(act, key=functools.cmp_to_key(cmp)))
            wn = np.cumsum(dirs[order])
            nz = wn != 0
            was = np.concatenate(([False], nz[:-1]))
            for i in np.nonzero(nz != was)[0]:
                runs = spans.setdefault(order[i], [])
                sg = 1 if nz[i] else -1
                if runs and runs[-1][1] == ya and runs[-1][2] == sg:
                    runs[-1][1] = yb  # the same bound on: one piece
                else:
                    runs.append([ya, yb, sg])
        for k, runs in spans.items():
            e = es[k]
            for ya, yb, sg in runs:
                x0, x1, hgt = _x(e, ya), _x(e, yb), yb - ya
                c0, c1 = max(math.floor(min(x0, x1)), 0), min(math.ceil(max(x0, x1)), w)
                for c in range(min(c0, w)):  # wholly right of these columns
                    out[j, c] -= sg * hgt
                for c in range(c0, c1):
                    out[j, c] -= sg * _clamped(x0, x1, c, hgt)
    return out

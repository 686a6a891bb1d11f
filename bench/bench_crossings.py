"""What "area" pays per edge crossing: canvas-spanning overlapping triangles.

    python bench/bench_crossings.py                      # 1,000 .. 10,000 triangles, 512 x 512
    python bench/bench_crossings.py --counts 1000 2000 --seeds 0 1 2

Every triangle spans most of the canvas (bench/families.py's "span"
family), so almost every pair of edges crosses, inside the canvas and
so inside some pixel.  "accumulate" adds each edge's signed area and
pays nothing for a crossing (its coverage is wrong where shapes
overlap); "area" must find every crossing to be exact.  The price of
exactness is therefore

    (time of "area" - time of "accumulate") / k

with k the number of edge crossings, counted here exactly on the grid
the fills use (vertices snapped to 1/256 px; two edges cross when each
one's endpoints lie strictly on both sides of the other's line).  The
aim is <= 50 ns per crossing.  CPU time (process_time), median of
--reps draws (one draw above 5 s); Blend2D's anti-aliased fill of the
same triangles beside it, and each output's largest error against
"area"'s, which is exact (the tests check it against exact area).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bench  # noqa: E402
import families  # noqa: E402

rastrum = bench.import_rastrum()


def crossings(tris: np.ndarray, bits: int = 8, chunk: int = 256) -> int:
    """The number of proper crossings among the triangles' edges, in exact
    integer arithmetic on the 1/2**bits px grid."""
    v = np.floor(tris * float(1 << bits) + 0.5).astype(np.int64)
    a = v.reshape(-1, 2)
    b = np.roll(v, -1, axis=1).reshape(-1, 2)
    n, k = len(a), 0
    for i in range(0, n - 1, chunk):
        p, q = a[i:i + chunk, None, :], b[i:i + chunk, None, :]
        j0 = i + 1
        r, s = a[None, j0:, :], b[None, j0:, :]

        def orient(o, d, t):
            return (d[..., 0] - o[..., 0]) * (t[..., 1] - o[..., 1]) - (d[..., 1] - o[..., 1]) * (t[..., 0] - o[..., 0])
        d1, d2 = orient(p, q, r), orient(p, q, s)
        hit = (np.sign(d1) * np.sign(d2)) < 0
        d3, d4 = orient(r, s, p), orient(r, s, q)
        hit &= (np.sign(d3) * np.sign(d4)) < 0
        # pairs with j <= row's own index are counted by the earlier row
        idx = np.arange(i, min(i + chunk, n))[:, None] < np.arange(j0, n)[None, :]
        k += int((hit & idx).sum())
    return k


def cpu(f, reps):
    """Median CPU time of f() over reps calls (one call when the first
    takes more than 5 s), and the last output."""
    times, out = [], None
    for i in range(reps):
        t = time.process_time()
        out = f()
        times.append(time.process_time() - t)
        if times[0] > 5.0:
            break
    return statistics.median(times), out


def blend2d(tris, n):
    try:
        import blend2d as b
    except ImportError:
        return None
    path = b.BLPath()
    for t in tris:
        path.move_to(*t[0])
        path.line_to(*t[1])
        path.line_to(*t[2])
        path.close()

    def draw():
        img = b.BLImage(n, n, b.BLFormat.A8)
        ctx = b.BLContext(img)
        ctx.clear_all()
        ctx.fill_rule = b.BLFillRule.NON_ZERO
        ctx.set_fill_style((255, 255, 255, 255))
        ctx.fill_path(path)
        ctx.flush()
        return img.getDataAsNumPy().reshape(n, n)
    return draw


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--counts", type=int, nargs="+", default=[1000, 2000, 4000, 10000])
    ap.add_argument("--seeds", type=int, nargs="+", default=[0])
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--reps", type=int, default=5)
    a = ap.parse_args(argv)
    n = a.size
    print("| triangles | seed | crossings k | accumulate | area | area - accumulate per crossing | Blend2D "
          "| accumulate max error | Blend2D max error |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = []
    for count in a.counts:
        for seed in a.seeds:
            sc = families.span_triangles(count)(seed, n)
            tris = sc.tris()
            k = crossings(tris)
            t_acc, acc = cpu(lambda: rastrum.triangles_coverage(tris, (n, n), method="accumulate"), a.reps)
            t_area, area = cpu(lambda: rastrum.triangles_coverage(tris, (n, n), method="area"), a.reps)
            ref = area.astype(np.int32)
            b2d = blend2d(tris, n)
            if b2d is not None:
                t_b, img = cpu(b2d, a.reps)
                b_txt = "%.1f ms" % (1e3 * t_b)
                b_err = "%d/255" % int(np.abs(img.astype(np.int32) - ref).max())
            else:
                b_txt = b_err = "not installed"
            per = (t_area - t_acc) / k * 1e9 if k else float("nan")
            rows.append((count, seed, k, t_acc, t_area, per))
            print("| %d | %d | %s | %.1f ms | %.1f ms | %.0f ns | %s | %d/255 | %s |"
                  % (count, seed, format(k, ","), 1e3 * t_acc, 1e3 * t_area, per, b_txt,
                     int(np.abs(acc.astype(np.int32) - ref).max()), b_err), flush=True)
    worst = max(rows, key=lambda r: r[5])
    print("worst: %.0f ns per crossing beyond \"accumulate\" (%d triangles, seed %d; the aim is <= 50 ns)"
          % (worst[5], worst[0], worst[1]))
    by = {}
    for count, seed, k, t_acc, t_area, per in rows:
        by.setdefault(count, []).append((k, t_area))
    pts = sorted((statistics.median(x[0] for x in v), statistics.median(x[1] for x in v)) for v in by.values())
    if len(pts) >= 2:
        lk, lt = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
        print("\"area\" time grows as k^%.2f over these counts (k from %s to %s)"
              % (float(np.polyfit(lk, lt, 1)[0]), format(int(pts[0][0]), ","), format(int(pts[-1][0]), ",")))
    return 0


if __name__ == "__main__":
    sys.exit(main())

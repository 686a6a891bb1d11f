"""Gouraud triangles: the speed/accuracy trade of the colour interpolation.

1. Error table: for each fraction_bits F of precision="fixed", the max and
   mean error in colour levels against precision="exact" (the rational
   barycentric value rounded half up), over every channel of every pixel
   written, on two scenes: "small" (10,000 triangles of 10..50 px) and
   "large" (20 triangles of about a quarter of the screen, where stepping
   errors have room to add up).  Vertex colours random, rgb888.
2. Timing (1024x1024 rgba8888, medians of interleaved rounds, see
   bench_triangles.measure): exact, fixed at several F, flat, exact with a
   depth buffer, and the unshaded solid fill of the same batch, each as a
   ratio to a memset of the 4 MiB buffer; beside skia drawVertices (one
   call, kTriangles with per-vertex colours, no anti-aliasing, into the same
   rgba8888 buffer) where skia-python is installed.

``python bench/bench_shade.py [--quick]``; ``run(quick)`` returns the rows.
"""

from __future__ import annotations

import argparse
import ctypes
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_triangles as bt  # noqa: E402

H = W = 1024
F_VALUES = (2, 4, 6, 8, 10, 12, 14, 16)


def scenes(quick):
    rng = np.random.default_rng(6)
    n_small = 2000 if quick else 10000
    return {
        "small": bt.random_triangles(rng, n_small, 10, 50, margin=10),
        "large": bt.random_triangles(rng, 20, 200000, 300000, margin=300),
    }


def vertex_colors(rng, n, c):
    return rng.integers(0, 256, (n, 3, c), dtype=np.int64)


def error_table(rastrum, quick):
    """[(scene, F, max error, mean error)] in levels, fixed vs exact."""
    rows = []
    rng = np.random.default_rng(11)
    for name, tris in scenes(quick).items():
        cols = vertex_colors(rng, len(tris), 3)
        covered = rastrum.triangles_mask(tris, (H, W))
        ref = rastrum.Canvas((H, W), format="rgb888")
        ref.fill_triangles(tris, vertex_colors=cols, precision="exact")
        exact = ref.array[covered].astype(np.int64)
        for F in F_VALUES:
            c = rastrum.Canvas((H, W), format="rgb888")
            c.fill_triangles(tris, vertex_colors=cols, precision="fixed", fraction_bits=F)
            err = np.abs(c.array[covered].astype(np.int64) - exact)
            rows.append((name, F, int(err.max()), float(err.mean())))
    return rows


def skia_cand(tris, cols, buf):
    try:
        import skia
    except ImportError as e:
        return None, "skia: %s" % e
    pos = [skia.Point(float(x), float(y)) for x, y in tris.reshape(-1, 2).tolist()]
    c = cols.reshape(-1, 3)
    colors = [skia.ColorSetARGB(255, int(r), int(g), int(b)) for r, g, b in c.tolist()]
    verts = skia.Vertices(skia.Vertices.kTriangles_VertexMode, pos, None, colors)
    paint = skia.Paint(AntiAlias=False)
    canvas = skia.Canvas(buf, colorType=skia.kRGBA_8888_ColorType)

    # kDst: the vertex colours alone.  The default (kModulate) multiplies
    # them by the paint's colour, black: skia-python 144 then draws black
    # on black, which the check in timings() reports.
    def run(cv=canvas, v=verts, p=paint, mode=skia.BlendMode.kDst):
        cv.drawVertices(v, p, mode)
    return run, None


def check_peer(run, buf, exact, mask):
    """A peer's shaded output against rastrum's exact one: pixels whose
    coverage differs, and the level error on the pixels both cover; or
    "EMPTY" / "BLACK" when it drew nothing / no colour."""
    buf[...] = 0
    run()
    got = buf[..., 3] > 0
    if not got.any():
        return "EMPTY"
    if not buf[..., :3].any():
        return "BLACK (no colour drawn)"
    both = got & mask
    err = np.abs(buf[both][:, :3].astype(int) - exact[both][:, :3].astype(int))
    return "%d px coverage off, colour error max %d / mean %.2f levels" % (
        int(np.count_nonzero(got != mask)), int(err.max()), float(err.mean()))


def timings(rastrum, quick):
    rounds = 5 if quick else 31
    buf = np.zeros((H, W, 4), np.uint8)
    canvas = rastrum.Canvas.wrap(buf)
    addr, nbytes = buf.ctypes.data, buf.nbytes

    def do_memset(m=ctypes.memset, a=addr, n=nbytes):
        m(a, 0, n)

    rng = np.random.default_rng(12)
    tris = scenes(quick)["small"]
    n = len(tris)
    cols = vertex_colors(rng, n, 4).astype(np.uint8)  # what C reads: no conversion per call
    cols[..., 3] = 255
    depth = rng.integers(0, 1 << 24, (n, 3))
    f = canvas.fill_triangles
    cands = [("memset 4 MiB", do_memset),
             ("rastrum solid (unshaded)", lambda: f(tris, (9, 9, 9, 255))),
             ("rastrum flat", lambda: f(tris, vertex_colors=cols, shading="flat")),
             ("rastrum exact", lambda: f(tris, vertex_colors=cols, precision="exact"))]
    for F in (8, 16):
        cands.append(("rastrum fixed F=%d" % F,
                      lambda F=F: f(tris, vertex_colors=cols, precision="fixed", fraction_bits=F)))
    # the fastest filler (docs/benchmarks.md, triangles): the painter is the same
    cands.append(("rastrum solid, sweep", lambda: f(tris, (9, 9, 9, 255), algorithm="sweep")))
    cands.append(("rastrum fixed F=16, sweep",
                  lambda: f(tris, vertex_colors=cols, precision="fixed", algorithm="sweep")))
    cands.append(("rastrum exact, sweep",
                  lambda: f(tris, vertex_colors=cols, precision="exact", algorithm="sweep")))

    def with_depth(prec):
        def run():
            canvas.clear_depth()
            f(tris, vertex_colors=cols, precision=prec, depth=depth)
        return run
    cands.append(("rastrum exact + depth", with_depth("exact")))
    cands.append(("rastrum fixed F=16 + depth", with_depth("fixed")))
    note = None
    sk, note = skia_cand(tris, cols[..., :3], buf)
    if sk:
        cands.append(("skia drawVertices (colors)", sk))
        buf[...] = 0
        f(tris, vertex_colors=cols)
        exact = buf.copy()
        mask = rastrum.triangles_mask(tris, (H, W))
        note = "skia drawVertices checked against rastrum's exact output: " + check_peer(sk, buf, exact, mask)
    med = bt.measure(cands, rounds)
    pixels = int(rastrum.triangles_count(tris, (H, W)).sum())
    return med, n, pixels, note


def run(quick=False):
    rastrum = bt.import_rastrum()
    rows = error_table(rastrum, quick)
    print("Gouraud fixed point against exact (rgb888, random vertex colours): error in levels")
    print("%-6s %s" % ("scene", " ".join("%9s" % ("F=%d" % F) for F in F_VALUES)))
    for name in ("small", "large"):
        cells = {F: (mx, mean) for s, F, mx, mean in rows if s == name}
        print("%-6s %s" % (name, " ".join("%4d/%-4.2f" % cells[F] for F in F_VALUES)))
    print("(each cell: max / mean error over every channel of every written pixel)\n")
    med, n, pixels, note = timings(rastrum, quick)
    tm = med["memset 4 MiB"]
    sk = med.get("skia drawVertices (colors)")
    print("%d triangles of 10..50 px into 1024x1024 rgba8888 (%d px written); medians" % (n, pixels))
    print("%-28s %9s %9s %9s %9s" % ("candidate", "ms/call", "Mpx/s", "/memset", "/skia"))
    for label, t in med.items():
        if label.startswith("memset"):
            print("%-28s %9.3f" % (label, t * 1e3))
            continue
        print("%-28s %9.3f %9.1f %9.2f %9s" % (label, t * 1e3, pixels / t / 1e6, t / tm,
                                                "%.2f" % (t / sk) if sk else "-"))
    if note:
        print(note if note.startswith("skia drawVertices checked") else "skipped: " + note)
    return rows, med


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer triangles and rounds")
    args = ap.parse_args(argv)
    run(quick=args.quick)


if __name__ == "__main__":
    main()

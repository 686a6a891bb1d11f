"""Stroking a 2,000-segment polyline 3 px wide with round joins and drawing
it anti-aliased: rastrum (rastrum.stroke, the C stroker, then "area"
coverage filled non-zero, uint8) against Blend2D (blend2d-python:
BLContext.stroke_path into an A8 image), in one run.  Medians of
--repeat runs; each peer's output compared with rastrum's (exact to the
stroke's stated bound: docs/paths.md, "Strokes"): the largest difference
in levels and the pixels more than 1 level off (Blend2D's accumulator
counts the polyline's self-crossings twice).

    python bench/bench_stroke.py [--repeat 5] [--size 512]
"""

import argparse
import statistics
import time

import numpy as np

import rastrum


def polyline(size, n=2000, seed=1):
    rng = np.random.default_rng(seed)
    steps = rng.normal(0, 6, (n, 2))
    pts = np.cumsum(steps, axis=0) + size / 2
    return np.clip(pts, 4, size - 4)


def run_rastrum(pts, size):
    outline = rastrum.stroke(pts, 3, join="round", cap="butt")
    return rastrum.polygon_coverage(outline, (size, size), rule="nonzero", method="area", dtype=np.uint8)


def run_blend2d(pts, size):
    import blend2d as b
    img = b.BLImage(size, size, b.BLFormat.A8)
    ctx = b.BLContext(img)
    ctx.clear_all()
    ctx.set_stroke_style((255, 255, 255, 255))
    ctx.stroke_width = 3
    ctx.stroke_join = b.BLStrokeJoin.JOIN_ROUND
    p = b.BLPath()
    p.move_to(*pts[0])
    for x, y in pts[1:]:
        p.line_to(x, y)
    t = time.perf_counter()
    ctx.stroke_path(p)
    ctx.flush()
    dt = time.perf_counter() - t
    return img.getDataAsNumPy().reshape(size, size), dt


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--size", type=int, default=512)
    a = ap.parse_args(argv)
    pts = polyline(a.size)
    times = []
    for _ in range(a.repeat):
        t = time.perf_counter()
        ref = run_rastrum(pts, a.size)
        times.append(time.perf_counter() - t)
    print("rastrum  stroke + area fill: median %.2f ms" % (1e3 * statistics.median(times)))
    try:
        bt = []
        for _ in range(a.repeat):
            img, dt = run_blend2d(pts, a.size)  # the path prebuilt: stroke + fill timed
            bt.append(dt)
        d = np.abs(img.astype(int) - ref.astype(int))
        print("Blend2D  stroke_path:          median %.2f ms  (%.2fx rastrum's time); vs exact: max %d levels, "
              "%d pixels > 1 level off" % (1e3 * statistics.median(bt), statistics.median(times) /
                                          statistics.median(bt), d.max(), int((d > 1).sum())))
    except ImportError:
        print("Blend2D: not installed")


if __name__ == "__main__":
    main()

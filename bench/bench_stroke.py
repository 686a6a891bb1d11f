"""Stroking an N-segment polyline (2,000 by default) 3 px wide with round
joins and drawing it anti-aliased: rastrum (rastrum.stroke, the C stroker,
then its outline filled non-zero, uint8, by "area" (exact), "accumulate"
and "ss4") against Blend2D (blend2d-python: BLContext.stroke_path into an
A8 image, the path prebuilt), in one run.  CPU time (time.process_time;
the machine may be shared), medians of --repeat runs, per seed of the
random polyline (--seeds) and per length (--segments, e.g. 2000 4000
8000, to see how the time grows); the worst seed's ratio is printed last.
Each peer's output is compared with rastrum's "area" (exact to the
stroke's stated bound: docs/paths.md, "Strokes"): the largest difference
in levels and the pixels more than 1 level off (an accumulator counts the
polyline's self-crossings twice).

    python bench/bench_stroke.py [--repeat 5] [--size 512] [--seeds 1 2 3] [--segments 2000]
                                 [--join round] [--tolerance T] [--outline exact]

--join and --tolerance (pixels; default rastrum's, 1/256) change rastrum's
stroke only (Blend2D keeps round joins at its own tolerance, about 0.2 px):
"area"'s time follows the outline's vertex count, which round joins at a
fine tolerance dominate (docs/paths.md, "Strokes").  --outline compact
takes rastrum.stroke(outline="compact"): each join's inner side through
the offsets' meeting point (no loop) and round parts straddling the
circle (fewer points at the same tolerance).  Each line also gives
rastrum.stroke's time alone (the C stroker, one pass, and the Path it
returns), the outline's vertices per polyline vertex, and each method's
fill of the prebuilt outline alone.
"""

import argparse
import statistics
import time

import numpy as np

import rastrum

METHODS = ("area", "accumulate", "ss4")


def polyline(size, n=2000, seed=1):
    rng = np.random.default_rng(seed)
    steps = rng.normal(0, 6, (n, 2))
    pts = np.cumsum(steps, axis=0) + size / 2
    return np.clip(pts, 4, size - 4)


STYLE = {"join": "round", "tolerance": None, "outline": "exact"}


def run_rastrum(pts, size, method="area"):
    outline = rastrum.stroke(pts, 3, cap="butt", **STYLE)
    return rastrum.polygon_coverage(outline, (size, size), rule="nonzero", method=method, dtype=np.uint8)


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
    t = time.process_time()
    ctx.stroke_path(p)
    ctx.flush()
    dt = time.process_time() - t
    return img.getDataAsNumPy().reshape(size, size), dt


def timed(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.process_time()
        out = fn()
        times.append(time.process_time() - t)
    return statistics.median(times), out


def off(img, ref):
    d = np.abs(img.astype(int) - ref.astype(int))
    return "max %d levels, %d pixels > 1 level off" % (d.max(), int((d > 1).sum()))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--seeds", type=int, nargs="+", default=[1])
    ap.add_argument("--segments", type=int, nargs="+", default=[2000])
    ap.add_argument("--join", default="round", choices=["round", "miter", "bevel"])
    ap.add_argument("--tolerance", type=float, default=None)
    ap.add_argument("--outline", default="exact", choices=["exact", "compact"])
    a = ap.parse_args(argv)
    STYLE.update(join=a.join, tolerance=a.tolerance, outline=a.outline)
    try:
        import blend2d  # noqa: F401
        have_b2d = True
    except ImportError:
        have_b2d = False
        print("Blend2D: not installed (rastrum's times only)")
    worst = {}
    for n in a.segments:
        for seed in a.seeds:
            pts = polyline(a.size, n, seed)
            res = {m: timed(lambda: run_rastrum(pts, a.size, m), a.repeat) for m in METHODS}
            t_stroke, outline = timed(lambda: rastrum.stroke(pts, 3, cap="butt", **STYLE), a.repeat)
            fills = {m: timed(lambda: rastrum.polygon_coverage(outline, (a.size, a.size), rule="nonzero",
                                                               method=m, dtype=np.uint8), a.repeat)[0]
                     for m in METHODS}
            ref = res["area"][1]
            verbs, xy = outline._as_arrays()
            nv = int((verbs != rastrum._path.CLOSE).sum())
            line = "n=%d seed=%d: stroke alone %.2f ms (%d vertices, %.1f per polyline vertex, %d rings);" % (
                n, seed, 1e3 * t_stroke, nv, nv / n, int((verbs == rastrum._path.MOVE).sum()))
            for m in METHODS:
                line += " %s %.2f ms (fill of the outline alone %.2f ms)" % (m, 1e3 * res[m][0], 1e3 * fills[m])
                if m != "area":
                    line += " (vs exact: %s)" % off(res[m][1], ref)
                line += ";"
            print(line)
            if have_b2d:
                bt = []
                for _ in range(a.repeat):
                    img, dt = run_blend2d(pts, a.size)
                    bt.append(dt)
                tb = statistics.median(bt)
                ratios = {m: res[m][0] / tb for m in METHODS}
                print("    Blend2D stroke_path %.2f ms (vs exact: %s); rastrum / Blend2D CPU time: %s;"
                      " rastrum.stroke alone %.2fx" % (1e3 * tb, off(img, ref), ", ".join(
                          "%s %.1fx" % (m, r) for m, r in ratios.items()), t_stroke / tb))
                for m, r in ratios.items():
                    if r > worst.get((n, m), (0, 0))[0]:
                        worst[(n, m)] = (r, seed)
    for (n, m), (r, seed) in sorted(worst.items()):
        print("worst seed, n=%d, %s: %.1fx Blend2D's time (seed %d)" % (n, m, r, seed))


if __name__ == "__main__":
    main()

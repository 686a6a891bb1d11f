"""How the flattening tolerance trades coverage error against edges
(docs/paths.md, "The default tolerance"): curved shapes (circles of
several radii from SVG arcs, random closed cubic blobs) filled with
"area" coverage at each tolerance, against the same paths flattened at
1/65536 px (subpixel_bits=16, tolerance one grid step); the error is the
largest |coverage - reference| over the pixels, in levels of 255, and
the edges are the flattened vertices.

    PYTHONPATH=build/py python bench/path_tolerance.py

Then the trade on a curved scene, bench/bench_paths.py's paragraph of
glyphs (720x120 px): at tolerance 1, 1/4, 1/16, 1/64 and 1/256 px, the
edges, the largest coverage error against the true curves (the paragraph
flattened at 1/4096 px on the 1/65536 px grid) and the median CPU time of
``Canvas.fill_polygon(path, 255, rule="nonzero", aa=...)`` for "area" and
"accumulate", beside Blend2D's fill of the same path in the same run.
"""
import os
import random
import sys
import time

import numpy as np

import rastrum


def shapes():
    for r in (2.5, 8, 30, 120):
        c = r + 2
        yield "circle r=%g" % r, (int(2 * c) + 2,) * 2, (
            "M %g %g A %g %g 0 0 1 %g %g A %g %g 0 0 1 %g %g A %g %g 0 0 1 %g %g A %g %g 0 0 1 %g %g Z"
            % (c + r, c, r, r, c, c + r, r, r, c - r, c, r, r, c, c - r, r, r, c + r, c))
    rnd = random.Random(34)
    for k in range(4):
        pts = [(rnd.uniform(4, 60), rnd.uniform(4, 60)) for _ in range(10)]
        d = "M %g %g " % pts[0] + " ".join("C %g %g %g %g %g %g" % (pts[i] + pts[i + 1] + pts[i + 2])
                                           for i in (1, 4, 7)[:3]) + " Z"
        yield "blob %d" % k, (64, 64), d


def main():
    tols = [1 / 4, 1 / 8, 1 / 16, 1 / 32, 1 / 64, 1 / 128, 1 / 256]
    print("%-16s" % "shape" + "".join("%14s" % ("1/%d px" % round(1 / t)) for t in tols))
    worst = {t: 0.0 for t in tols}
    for name, shape, d in shapes():
        ref_path = rastrum.Path.from_svg(d, tolerance=2 ** -16)
        ref = rastrum.polygon_coverage(ref_path, shape, rule="nonzero", subpixel_bits=16, dtype=np.float64)
        row = []
        for t in tols:
            p = rastrum.Path.from_svg(d, tolerance=t)
            cov = rastrum.polygon_coverage(p, shape, rule="nonzero", subpixel_bits=16, dtype=np.float64)
            err = float(np.abs(cov - ref).max() * 255)
            edges = sum(len(r) for r in p.flatten(16))
            worst[t] = max(worst[t], err)
            row.append("%6.3f/%-6d" % (err, edges))
        print("%-16s" % name + "".join("%14s" % c for c in row))
    print("%-16s" % "worst (levels)" + "".join("%14.3f" % worst[t] for t in tols))
    trade()


def trade(repeats=9):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import bench_paths

    path = bench_paths.paragraph()
    blend = bench_paths.drawers(path).get("Blend2D")
    print("\nthe paragraph of glyphs (%d verbs), CPU time medians of %d draws" % (len(path), repeats))
    print("%-10s %8s %12s %12s %12s %10s" % ("tolerance", "edges", "error/255", "area ms", "accum. ms",
                                            "Blend2D ms"))
    for t in (1.0, 1 / 4, 1 / 16, 1 / 64, 1 / 256):
        times = {}
        for aa in ("area", "accumulate"):
            draws = bench_paths.drawers(path, aa, t)
            names = ["rastrum"] + (["Blend2D"] if blend else [])
            got = bench_paths.timed({n: draws[n] for n in names}, repeats)
            times[aa] = got["rastrum"][1]
            times["Blend2D"] = got.get("Blend2D", (0, float("nan")))[1]
            if aa == "area":
                err = bench_paths.check(path, {"rastrum": draws["rastrum"]})["rastrum"][0]
        print("1/%-8g %8d %12.2f %12.2f %12.2f %10.2f" % (1 / t, bench_paths.edges(path, t), err,
                                                          times["area"] * 1e3, times["accumulate"] * 1e3,
                                                          times["Blend2D"] * 1e3))


if __name__ == "__main__":
    main()

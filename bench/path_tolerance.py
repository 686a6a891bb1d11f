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

The same trade as a row family of the speed/accuracy table
(bench/bench_coverage.py, docs/coverage.md) and of bench/demo.py's table:
``curved_scene`` (glyph outlines of DejaVu Sans through matplotlib's
TextPath, or an SVG path of quadratic and cubic curves where matplotlib is
missing), ``tolerance_rows`` rastrum's "area" coverage of it at each of
TOLERANCES and the peers that draw curves themselves (Blend2D, skia,
cairo, where installed), every output checked against ``reference``: the
exact area of the true curves, taken as the path flattened at 1/4096 px
(REF_TOLERANCE) on the 1/65536 px grid, whose own error is about 0.1/255
(docs/paths.md, "The default tolerance").
"""
import os
import random
import sys
import time

import numpy as np

import rastrum

TOLERANCES = (1.0, 1 / 4, 1 / 16, 1 / 64, 1 / 256)
REF_TOLERANCE = 2.0 ** -12

# Where matplotlib (and so a font's outlines) is missing: loops, cusps,
# inflections and quadratic waves, in a 100x40 box (scaled to the scene).
SVG_CURVES = ("M 5 20 C 5 2 30 2 30 20 C 30 38 55 38 55 20 C 55 2 5 38 5 20 Z "
              "M 60 8 Q 70 -4 80 8 T 100 8 L 100 36 Q 90 24 80 36 T 60 36 Z "
              "M 20 14 C 40 14 0 26 20 26 Z")


def curved_scene(shape, text="Curves,\nexactly."):
    """(label, rastrum.Path) of glyph outlines filling `shape` (H, W):
    `text` in DejaVu Sans through matplotlib's TextPath (quadratic curves,
    as TrueType has them); where matplotlib is missing, SVG_CURVES scaled
    to the shape."""
    h, w = shape
    lines = text.split("\n")
    try:
        import paths_scene
        size = min(h / (len(lines) * 9 / 7 + 0.3), w / (0.62 * max(len(t) for t in lines)))
        whole = rastrum.Path()
        for k, line in enumerate(lines):
            p = paths_scene.text_path(line, size, 0.03 * w, size * (1.05 + 9 / 7 * k))
            whole._verbs += p._verbs
            whole._pts += p._pts
        return "glyph curves %r" % text.replace("\n", " "), whole
    except ImportError:
        s = min(w / 105, h / 42)
        d = rastrum.Path.from_svg(SVG_CURVES).transformed((s, 0, 0, 0, s, 0))
        return "SVG curves (no matplotlib)", d


def reference(path, shape):
    """The exact coverage of the true curves, levels of 255 (float64):
    the path flattened at REF_TOLERANCE px on the 1/65536 px grid, its
    exact area per pixel."""
    return rastrum.polygon_coverage(path, shape, rule="nonzero", subpixel_bits=16,
                                    tolerance=REF_TOLERANCE, dtype=np.float64) * 255


def curve_peers(path, shape):
    """{name: draw() -> uint8 (H, W)} for the peers installed that fill the
    curves themselves (each flattening them its own way), path prebuilt."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import paths_scene
    h, w = shape
    out = {}
    try:
        import blend2d as b

        bp = b.BLPath()
        paths_scene._trace(path, bp.move_to, bp.line_to, bp.quadric_to, bp.cubic_to, bp.close)
        img = b.BLImage(w, h, b.BLFormat.A8)

        def b_draw():
            ctx = b.BLContext(img)
            ctx.clear_all()
            ctx.fill_rule = b.BLFillRule.NON_ZERO
            ctx.set_fill_style((255, 255, 255, 255))
            ctx.fill_path(bp)
            ctx.end() if hasattr(ctx, "end") else ctx.flush()
            return img.getDataAsNumPy().reshape(h, w)
        out["Blend2D"] = b_draw
    except ImportError:
        pass
    try:
        import skia

        sp = skia.Path()
        sp.setFillType(skia.PathFillType.kWinding)
        paths_scene._trace(path, sp.moveTo, sp.lineTo, sp.quadTo, sp.cubicTo, sp.close)
        arr = np.zeros((h, w), np.uint8)
        surface = skia.Surface(arr, colorType=skia.ColorType.kAlpha_8_ColorType)
        paint = skia.Paint(AntiAlias=True, Color=skia.ColorWHITE)

        def s_draw():
            canvas = surface.getCanvas()
            canvas.clear(skia.ColorTRANSPARENT)
            canvas.drawPath(sp, paint)
            surface.flushAndSubmit() if hasattr(surface, "flushAndSubmit") else None
            return arr
        out["skia"] = s_draw
    except Exception:  # not installed, or a build without Alpha_8 surfaces
        pass
    try:
        try:
            import cairo as c
        except ImportError:
            import cairocffi as c
        surf = c.ImageSurface(c.FORMAT_A8, w, h)
        ctx = c.Context(surf)
        ctx.set_fill_rule(c.FILL_RULE_WINDING)

        def quad(x1, y1, x, y):  # a quadratic as the cubic it is
            x0, y0 = ctx.get_current_point()
            ctx.curve_to(x0 + 2 / 3 * (x1 - x0), y0 + 2 / 3 * (y1 - y0), x + 2 / 3 * (x1 - x),
                         y + 2 / 3 * (y1 - y), x, y)
        ctx.new_path()
        paths_scene._trace(path, ctx.move_to, ctx.line_to, quad, ctx.curve_to, ctx.close_path)
        cpath = ctx.copy_path()

        def c_draw():
            ctx.set_operator(c.OPERATOR_CLEAR)
            ctx.paint()
            ctx.set_operator(c.OPERATOR_OVER)
            ctx.new_path()
            ctx.append_path(cpath)
            ctx.fill()
            surf.flush()
            return np.frombuffer(bytes(surf.get_data()), np.uint8).reshape(h, surf.get_stride())[:, :w]
        out["cairo"] = c_draw
    except (ImportError, OSError):
        pass
    return out


def tolerance_label(t):
    return "1 px" if t == 1 else "1/%d px" % round(1 / t)


def tolerance_rows(path, shape, median_ms, peers=True, tolerances=TOLERANCES):
    """The row family: [(label, tolerance or None, ms, max error, mean
    error, pixels off by more than 1/255, edges or None)]: rastrum's "area"
    coverage (``polygon_coverage(path, shape, rule="nonzero",
    tolerance=t)``) at each tolerance, then each curve-drawing peer, every
    output against ``reference``; ms from median_ms(f)."""
    ref = reference(path, shape)
    rows = []

    def add(label, t, f, edges):
        err = np.abs(f().astype(np.float64) - ref)
        rows.append((label, t, median_ms(f), float(err.max()), float(err.mean()), int((err > 1).sum()),
                     edges))

    for t in tolerances:
        add("rastrum area, %s" % tolerance_label(t), t,
            lambda t=t: rastrum.polygon_coverage(path, shape, rule="nonzero", tolerance=t),
            sum(len(r) for r in path.flatten(8, t)))
    if peers:
        for name, f in curve_peers(path, shape).items():
            add(name, None, f, None)
    return rows


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

"""Filling a paragraph of glyph curves anti-aliased: rastrum against
Blend2D (and cairo, where installed), paths prebuilt, one run, every
peer's output checked against the exact coverage.

    python bench/bench_paths.py                 # wall-clock medians and ratios
    python bench/bench_paths.py --draws N       # N draws each, nothing printed
                                                # but the check (for callgrind)

The text is matplotlib's TextPath of DejaVu Sans (quadratic curves, as
TrueType has them), 14 px, ~600 glyphs; rastrum fills it with
``Canvas.fill_polygon(path, 255, rule="nonzero", aa="area")`` (its curves
flattened in C within Path.DEFAULT_TOLERANCE, then the exact area), Blend2D
with ``fill_path`` on an A8 image, cairo with ``fill`` on an A8 surface.
Wall-clock times on a shared machine are noisy: the ratios are also
given in CPU time (process_time), and ``--draws N`` draws N times with
no timing, for callgrind (the difference of a ``--draws 0`` run).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import bench  # noqa: E402
import paths_scene  # noqa: E402

rastrum = bench.import_rastrum()

TEXT = ("Where these peers are inexact, rastrum can be exact: the peers' coverage is wrong where a stroke\n"
        "crosses itself or a curve overlaps another, and none of them states how far its flattened curve\n"
        "is from the true one. Curves become edges in integer fixed point within a caller-set tolerance,\n"
        "with the bound proven in a comment and checked in tests against a finely sampled exact curve;\n"
        "the number of segments follows the curve's flatness, not a fixed count. Text, icons, charts,\n"
        "maps with outlined borders, a firmware gauge: the pictures people want anti-aliased are curves.")
SIZE = (120, 720)  # (H, W)


def paragraph():
    """The paragraph as one rastrum Path (lines 18 px apart)."""
    whole = rastrum.Path()
    for k, line in enumerate(TEXT.split("\n")):
        p = paths_scene.text_path(line, 14, 4, 16 + 18 * k)
        whole._verbs += p._verbs
        whole._pts += p._pts
    return whole


def drawers(path):
    """{name: draw()} for rastrum and the peers installed, paths prebuilt."""
    h, w = SIZE
    out = {}
    canvas = rastrum.Canvas(SIZE, format="gray8")

    def r_draw():
        canvas.array[...] = 0
        canvas.fill_polygon(path, 255, rule="nonzero", aa="area")
        return canvas.array
    out["rastrum"] = r_draw
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
        try:
            import cairo as c
        except ImportError:
            import cairocffi as c
        surf = c.ImageSurface(c.FORMAT_A8, w, h)
        ctx = c.Context(surf)
        ctx.set_fill_rule(c.FILL_RULE_WINDING)

        def quad(x1, y1, x, y):
            x0, y0 = ctx.get_current_point()
            ctx.curve_to(x0 + 2 / 3 * (x1 - x0), y0 + 2 / 3 * (y1 - y0), x + 2 / 3 * (x1 - x), y + 2 / 3 * (y1 - y),
                         x, y)
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


def check(path, draws):
    """Every drawer's output against the exact coverage (levels of 255)."""
    ref = rastrum.polygon_coverage(path, SIZE, rule="nonzero", dtype=np.float64) * 255
    rows = {}
    for name, draw in draws.items():
        d = np.abs(draw().astype(np.float64) - ref)
        rows[name] = (float(d.max()), int((d > 1.0).sum()))
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=21)
    ap.add_argument("--draws", type=int, default=None, help="draw each N times, print only the check")
    ap.add_argument("--only", default=None, help="one drawer (for callgrind)")
    a = ap.parse_args(argv)
    path = paragraph()
    draws = drawers(path)
    if a.only:
        draws = {a.only: draws[a.only]}
    print("paragraph: %d glyph-path verbs, %d points, %dx%d px" % (len(path), len(path._pts), SIZE[1], SIZE[0]))
    for name, (mx, off) in check(path, draws).items():
        print("%-8s against the exact coverage: max %.1f/255, %d pixels off by more than 1/255" % (name, mx, off))
    if a.draws is not None:
        for draw in draws.values():
            for _ in range(a.draws):
                draw()
        return 0
    wall, cpu = {}, {}
    for name, draw in draws.items():
        tw, tc = [], []
        for _ in range(a.repeats):
            w0, c0 = time.perf_counter(), time.process_time()
            draw()
            tc.append(time.process_time() - c0)
            tw.append(time.perf_counter() - w0)
        wall[name], cpu[name] = statistics.median(tw), statistics.median(tc)
    ref = "Blend2D" if "Blend2D" in wall else None
    for name in wall:
        print("%-8s median wall %.3f ms (%.2fx Blend2D), CPU time %.3f ms (%.2fx Blend2D)"
              % (name, wall[name] * 1e3, wall[name] / wall[ref] if ref else float("nan"), cpu[name] * 1e3,
                 cpu[name] / cpu[ref] if ref else float("nan")))
    # where rastrum's time goes: the Path's flattening (C, with its Python
    # conversions) and the fill of the rings
    path_rings = [r for r in path.flatten(8)]
    tf, tr = [], []
    canvas = rastrum.Canvas(SIZE, format="gray8")
    for _ in range(a.repeats):
        c0 = time.process_time()
        rings = path.flatten(8)
        c1 = time.process_time()
        canvas.fill_polygon(rings, 255, rule="nonzero", aa="area")
        c2 = time.process_time()
        tf.append(c1 - c0)
        tr.append(c2 - c1)
    print("rastrum: %d edges at the default tolerance; CPU time: flatten %.3f ms, fill the rings %.3f ms"
          % (sum(len(r) for r in path_rings), statistics.median(tf) * 1e3, statistics.median(tr) * 1e3))
    return 0


if __name__ == "__main__":
    sys.exit(main())

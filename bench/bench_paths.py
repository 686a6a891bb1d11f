"""Filling a paragraph of glyph curves anti-aliased: rastrum against
Blend2D (and skia and cairo, where installed), paths prebuilt, one run, every
peer's output checked against the exact coverage.

    python bench/bench_paths.py                 # wall-clock medians and ratios
    python bench/bench_paths.py --draws N       # N draws each, nothing printed
                                                # but the check (for callgrind)

The text is matplotlib's TextPath of DejaVu Sans (quadratic curves, as
TrueType has them), 14 px, ~600 glyphs; rastrum fills it with
``Canvas.fill_polygon(path, 255, rule="nonzero", aa="area")`` (its curves
flattened in C within Path.DEFAULT_TOLERANCE, then the exact area), Blend2D
with ``fill_path`` on an A8 image, skia with ``drawPath`` on an Alpha_8
surface, cairo with ``fill`` on an A8 surface.
Wall-clock times on a shared machine are noisy: the ratios are also
given in CPU time (process_time), and ``--draws N`` draws N times with
no timing, for callgrind (the difference of a ``--draws 0`` run).

    python bench/bench_paths.py --tolerance 0.25    # rastrum at 1/4 px
    python bench/bench_paths.py --aa accumulate     # the other engine
    python bench/bench_paths.py --seeds 8           # seeded texts instead:
                                                    # random words, 12-28 px

``--seeds N`` draws N seeded paragraphs (words of random letters, one
size per seed from 12 to 28 px, lines filling the canvas) and prints
each seed's ratios and the worst.  rastrum's row gives its flattened
edge count; the path is prebuilt for every drawer, and rastrum flattens
it in C straight into the filler on each draw (python/glue/pathfill.c).
"""

from __future__ import annotations

import argparse
import random
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


def paragraph(text=TEXT, size=14):
    """The paragraph as one rastrum Path (lines 9/7 of `size` apart)."""
    whole = rastrum.Path()
    for k, line in enumerate(text.split("\n")):
        p = paths_scene.text_path(line, size, 4, size * 8 / 7 + size * 9 / 7 * k)
        whole._verbs += p._verbs
        whole._pts += p._pts
    return whole


def seeded_text(seed):
    """Seed `seed`'s paragraph: (text, size in px): words of 1-10 random
    letters (upper and lower case, some digits and punctuation), lines of
    about the canvas's width, as many lines as fit."""
    rnd = random.Random(seed)
    size = rnd.randint(12, 28)
    letters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789,.;:'&?"
    per_line = int(SIZE[1] / (0.6 * size))
    lines = []
    for _ in range(max(1, int((SIZE[0] - size * 8 / 7) // (size * 9 / 7)) + 1)):
        line = ""
        while len(line) < per_line - 10:
            line += "".join(rnd.choice(letters[:52] if rnd.random() < 0.9 else letters)
                            for _ in range(rnd.randint(1, 10))) + " "
        lines.append(line.rstrip())
    return "\n".join(lines), size


def drawers(path, aa="area", tolerance=None):
    """{name: draw()} for rastrum and the curve-drawing peers installed
    (path_tolerance.curve_peers: Blend2D, skia, cairo), paths prebuilt."""
    import path_tolerance

    canvas = rastrum.Canvas(SIZE, format="gray8")

    def r_draw():
        canvas.array[...] = 0
        canvas.fill_polygon(path, 255, rule="nonzero", aa=aa, tolerance=tolerance)
        return canvas.array
    return {"rastrum": r_draw, **path_tolerance.curve_peers(path, SIZE)}


_REF: dict = {}


def check(path, draws):
    """Every drawer's output against the exact coverage of the true curves
    (levels of 255): the path flattened at 1/4096 px on the 1/65536 px grid
    (docs/paths.md: its coverage is within about 0.1/255 of the true
    curves'), its "area" coverage, computed once per path."""
    key = id(path)
    if _REF.get("key") != key:
        _REF["key"], _REF["ref"] = key, rastrum.polygon_coverage(
            path, SIZE, rule="nonzero", subpixel_bits=16, tolerance=2.0 ** -12, dtype=np.float64) * 255
    ref = _REF["ref"]
    rows = {}
    for name, draw in draws.items():
        d = np.abs(draw().astype(np.float64) - ref)
        rows[name] = (float(d.max()), int((d > 1.0).sum()))
    return rows


def timed(draws, repeats):
    """{name: (median wall, median CPU time)}, the drawers taking turns."""
    tw = {n: [] for n in draws}
    tc = {n: [] for n in draws}
    for _ in range(repeats):
        for name, draw in draws.items():
            w0, c0 = time.perf_counter(), time.process_time()
            draw()
            tc[name].append(time.process_time() - c0)
            tw[name].append(time.perf_counter() - w0)
    return {n: (statistics.median(tw[n]), statistics.median(tc[n])) for n in draws}


def edges(path, tolerance):
    return sum(len(r) for r in path.flatten(8, tolerance))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=21)
    ap.add_argument("--draws", type=int, default=None, help="draw each N times, print only the check")
    ap.add_argument("--only", default=None, help="one drawer (for callgrind)")
    ap.add_argument("--aa", default="area", help='rastrum\'s engine: "area" (default) or "accumulate"')
    ap.add_argument("--tolerance", type=float, default=None,
                    help="rastrum's flattening tolerance, px (default Path.DEFAULT_TOLERANCE)")
    ap.add_argument("--seeds", type=int, default=None, help="N seeded texts instead of the paragraph")
    a = ap.parse_args(argv)
    if a.seeds is not None:
        worst = None
        for seed in range(a.seeds):
            text, size = seeded_text(seed)
            path = paragraph(text, size)
            draws = drawers(path, a.aa, a.tolerance)
            err = check(path, draws)
            t = timed(draws, a.repeats)
            ref = t.get("Blend2D", (float("nan"),) * 2)
            ratio = (t["rastrum"][0] / ref[0], t["rastrum"][1] / ref[1])
            print("seed %d: %d px, %d verbs, %d edges; rastrum %.2f ms CPU = %.2fx Blend2D (wall %.2fx); "
                  "max error %s" % (seed, size, len(path), edges(path, a.tolerance), t["rastrum"][1] * 1e3,
                                    ratio[1], ratio[0],
                                    ", ".join("%s %.1f" % (n, e[0]) for n, e in err.items())))
            if worst is None or ratio[1] > worst[1]:
                worst = (seed, ratio[1])
        print("worst seed %d: rastrum %.2fx Blend2D's CPU time (aa=%r, tolerance %s)"
              % (worst[0], worst[1], a.aa, a.tolerance or "default"))
        return 0
    path = paragraph()
    draws = drawers(path, a.aa, a.tolerance)
    if a.only:
        draws = {a.only: draws[a.only]}
    print("paragraph: %d glyph-path verbs, %d points, %dx%d px; rastrum aa=%r at tolerance %s: %d edges"
          % (len(path), len(path._pts), SIZE[1], SIZE[0], a.aa, a.tolerance or "default",
             edges(path, a.tolerance)))
    for name, (mx, off) in check(path, draws).items():
        print("%-8s against the exact coverage: max %.1f/255, %d pixels off by more than 1/255" % (name, mx, off))
    if a.draws is not None:
        for draw in draws.values():
            for _ in range(a.draws):
                draw()
        return 0
    t = timed(draws, a.repeats)
    ref = t.get("Blend2D")
    for name, (w, c) in t.items():
        print("%-8s median wall %.3f ms (%.2fx Blend2D), CPU time %.3f ms (%.2fx Blend2D)"
              % (name, w * 1e3, w / ref[0] if ref else float("nan"), c * 1e3,
                 c / ref[1] if ref else float("nan")))
    return 0


if __name__ == "__main__":
    sys.exit(main())

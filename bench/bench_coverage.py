"""Anti-aliased coverage: each method's time and error, beside the peers.

    python bench/bench_coverage.py [--size 512] [--reps 7] [--plot docs/coverage_frontier.png]

For each scene (a 64-gon circle, a 200-spike star, a disc with holes,
four glyphs, the overlap scenes, 10,000 triangles in one path, a mesh in
one call and the same mesh drawn per triangle by the peers) it prints, per method, the median time (ms), its ratio to
a memset of the same buffer and to the fastest peer, and the coverage
error in 1/255 against the reference: the max, the mean, and the number of
pixels off by more than 1/255.

Then the tolerance row family (bench/path_tolerance.py): a curved scene,
glyph outlines of a real font (matplotlib's TextPath of DejaVu Sans; an SVG
path of curves where matplotlib is missing), filled by rastrum's "area" at
flattening tolerances 1, 1/4, 1/16, 1/64 and 1/256 px, beside the peers
that fill the curves themselves (Blend2D, skia, cairo), each output's error
against the exact area of the true curves (the path flattened at 1/4096 px
on the 1/65536 px grid, about 0.1/255 off them); on the plot, a curve
through rastrum's five points.

Reference: rastrum's "area" with subpixel_bits=16, as float64 - the exact
area (tests/test_coverage.py holds "area" to the rational oracle) of the
vertices snapped to 2^-16 pixel, so within about 2^-16 of the exact area of
the unsnapped input: far below 1/255.

Peers (skipped when not installed; `pip install .[bench]`): Blend2D
(blend2d-python), skia-python, AGG (aggdraw, no pen), FreeType (freetype-py:
its smooth rasteriser, FT_Outline_Get_Bitmap on an outline of line
segments), Pillow drawing 4x and 16x larger and reducing (box filter).
Every peer draws the same float vertices as one path with the scene's fill
rule - except in "mesh 32x32, peers per triangle", where each peer draws the
mesh triangle by triangle, each blended source-over onto the last, as a
renderer without a union would (the seams), while rastrum still draws the
union in one call; Pillow paints each polygon into one binary image at 4x or
16x, which is a union too.  Timings are medians of --reps runs measured in
one process; the machine may be noisy: compare ratios within one run.
"""

import argparse
import math
import sys
import os

import numpy as np

import rastrum

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from timing import median_s  # noqa: E402
import path_tolerance  # noqa: E402

# ---- scenes -------------------------------------------------------------------


def _ngon(cx, cy, r, n, phase=0.0):
    t = phase + np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], 1)


def _glyph_rings(text, size):
    """Outlines of `text` in DejaVu Sans (freetype-py), curves flattened."""
    import freetype
    import glob
    fonts = glob.glob("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf") or \
        glob.glob("/usr/share/fonts/**/*.ttf", recursive=True)
    face = freetype.Face(fonts[0])
    face.set_char_size(int(size * 0.3) * 64)
    rings, pen_x = [], size * 0.06
    for ch in text:
        face.load_char(ch, freetype.FT_LOAD_NO_BITMAP | freetype.FT_LOAD_NO_HINTING)
        outline = face.glyph.outline
        pts = np.array(outline.points, float) / 64.0  # 26.6 fixed point
        tags = outline.tags
        start = 0
        for end in outline.contours:
            cpts = pts[start:end + 1]
            ctags = tags[start:end + 1]
            ring = _flatten(cpts, ctags)
            rings.append(np.stack([pen_x + ring[:, 0], size * 0.7 - ring[:, 1]], 1))
            start = end + 1
        pen_x += face.glyph.advance.x / 64.0
    return rings


def _flatten(pts, tags, steps=8):
    """A TrueType contour (on/off curve points, quadratic) as a polyline."""
    on = [bool(t & 1) for t in tags]
    n = len(pts)
    # start at an on-curve point
    k0 = next((k for k in range(n) if on[k]), None)
    if k0 is None:
        pts = np.vstack([(pts[0] + pts[1]) / 2, pts])
        on = [True] + on
        n += 1
        k0 = 0
    out = [pts[k0]]
    k, done = k0, 0
    while done < n:
        k1 = (k + 1) % n
        if on[k1]:
            out.append(pts[k1])
            k, done = k1, done + 1
            continue
        ctrl = pts[k1]
        k2 = (k1 + 1) % n
        end = pts[k2] if on[k2] else (ctrl + pts[k2]) / 2
        p0 = out[-1]
        for s in range(1, steps + 1):
            t = s / steps
            out.append((1 - t) ** 2 * p0 + 2 * (1 - t) * t * ctrl + t * t * end)
        if on[k2]:
            k, done = k2, done + 2
        else:
            k, done = k1, done + 1
            pts = pts.copy()
            pts[k1] = end  # continue from the implied on-curve point
            on = list(on)
            on[k1] = True
    return np.array(out[:-1] if np.allclose(out[-1], out[0]) else out)


def scenes(size):
    c = size / 2
    rnd = np.random.default_rng(12)
    star = _ngon(c, c, 0.47 * size, 400)
    star[1::2] = _ngon(c, c, 0.2 * size, 400)[1::2]
    holes = [_ngon(c + 0.25 * size * math.cos(a), c + 0.25 * size * math.sin(a), 0.08 * size, 32)[::-1]
             for a in np.linspace(0, 2 * np.pi, 6, endpoint=False)]
    sq = np.array([(0.2, 0.2), (0.8, 0.2), (0.8, 0.8), (0.2, 0.8)]) * size + 0.3
    penta = _ngon(c, c, 0.45 * size, 5, -np.pi / 2)[[0, 2, 4, 1, 3]]
    tris = rnd.uniform(0.05 * size, 0.95 * size, (10000, 3, 2))
    g = np.linspace(0.1 * size, 0.9 * size, 33)
    pts = np.array([[x, y] for y in g for x in g])
    inner = (np.arange(33 * 33) % 33 > 0) & (np.arange(33 * 33) % 33 < 32) & \
        (np.arange(33 * 33) // 33 > 0) & (np.arange(33 * 33) // 33 < 32)
    pts[inner] += rnd.uniform(-3, 3, (inner.sum(), 2))
    mesh = []
    for r in range(32):
        for q in range(32):
            a, b, d, e = r * 33 + q, r * 33 + q + 1, r * 33 + q + 34, r * 33 + q + 33
            mesh += [[pts[a], pts[b], pts[d]], [pts[a], pts[d], pts[e]]]
    out = {
        "circle (64-gon)": ([_ngon(c, c, 0.4 * size, 64)], "nonzero", False),
        "star (200 spikes)": ([star], "nonzero", False),
        "disc with 6 holes": ([_ngon(c, c, 0.45 * size, 128)] + holes, "nonzero", False),
        "square twice, nonzero": ([sq, sq], "nonzero", False),
        "square twice, evenodd": ([sq, sq], "evenodd", False),
        "pentagram, nonzero": ([penta], "nonzero", False),
        "10,000 triangles, one path": (list(tris), "nonzero", True),
        "mesh 32x32 in one call": (list(np.array(mesh)), "nonzero", True),
        # the same mesh, the peers drawing it triangle by triangle (source-over):
        # rastrum still one call, the union
        "mesh 32x32, peers per triangle": (list(np.array(mesh)), "nonzero", "each"),
    }
    try:
        out["glyphs 'Rast'"] = (_glyph_rings("Rast", size), "nonzero", False)
    except Exception as exc:  # no freetype-py or no font
        print("(glyph scene skipped: %s)" % exc)
    return out


# ---- drawers ------------------------------------------------------------------


def rastrum_method(method):
    def draw(rings, rule, tris, size):
        if tris:
            return rastrum.triangles_coverage(np.asarray(rings), (size, size), method=method)
        return rastrum.polygon_coverage(rings, (size, size), rule=rule, method=method)
    return draw


def rastrum_binary(rings, rule, tris, size):
    if tris:
        return rastrum.triangles_mask(np.asarray(rings), (size, size)).view(np.uint8) * np.uint8(255)
    return rastrum.polygon_mask(rings, (size, size), rule=rule).view(np.uint8) * np.uint8(255)


def _trace(rings, move, line, close):
    """Each ring as move, lines and close on a peer's path object."""
    for r in rings:
        r = np.asarray(r, float)
        move(float(r[0, 0]), float(r[0, 1]))
        for x, y in r[1:].tolist():
            line(x, y)
        close()


def _paths(rings, tris):
    """The paths a peer fills: the scene as one path, or for "each" (the
    mesh drawn triangle by triangle) one path per triangle, each blended
    source-over onto the last (the seams a renderer without a union leaves)."""
    return [[r] for r in rings] if tris == "each" else [rings]


def peers():
    out = {}
    try:
        import blend2d as b

        def blend2d_draw(rings, rule, tris, size):
            img = b.BLImage(size, size, b.BLFormat.A8)
            ctx = b.BLContext(img)
            ctx.clear_all()
            ctx.fill_rule = b.BLFillRule.NON_ZERO if rule == "nonzero" else b.BLFillRule.EVEN_ODD
            ctx.set_fill_style((255, 255, 255, 255))
            for group in _paths(rings, tris):  # each a fill, blended source-over
                p = b.BLPath()
                _trace(group, p.move_to, p.line_to, p.close)
                ctx.fill_path(p)
            ctx.flush()
            return img.getDataAsNumPy().reshape(size, size)
        out["Blend2D"] = blend2d_draw
    except ImportError:
        pass
    try:
        import skia

        def skia_draw(rings, rule, tris, size):
            arr = np.zeros((size, size), np.uint8)
            surface = skia.Surface(arr, colorType=skia.ColorType.kAlpha_8_ColorType)
            canvas = surface.getCanvas()
            paint = skia.Paint(AntiAlias=True, Color=skia.ColorWHITE)
            for group in _paths(rings, tris):
                path = skia.Path()
                path.setFillType(skia.PathFillType.kWinding if rule == "nonzero" else skia.PathFillType.kEvenOdd)
                _trace(group, path.moveTo, path.lineTo, path.close)
                canvas.drawPath(path, paint)
            surface.flushAndSubmit() if hasattr(surface, "flushAndSubmit") else None
            return arr
        skia_draw([np.array([(0, 0), (4, 0), (0, 4)], float)], "nonzero", False, 8)
        out["skia"] = skia_draw
    except Exception:
        pass
    try:
        import aggdraw
        from PIL import Image

        def agg_draw(rings, rule, tris, size):
            img = Image.new("L", (size, size), 0)
            d = aggdraw.Draw(img)
            brush = aggdraw.Brush(255)
            for group in _paths(rings, tris):
                path = aggdraw.Path()
                _trace(group, path.moveto, path.lineto, path.close)
                d.path(path, None, brush)
            d.flush()
            return np.asarray(img)
        out["AGG (aggdraw)"] = agg_draw
    except ImportError:
        pass
    try:
        out["FreeType"] = _freetype_peer()
    except Exception:
        pass
    from PIL import Image, ImageDraw

    def pillow(k):
        def draw(rings, rule, tris, size):
            img = Image.new("L", (size * k, size * k), 0)
            d = ImageDraw.Draw(img)
            for r in rings:  # Pillow has no fill rule: each ring painted (a union)
                d.polygon([(x * k, y * k) for x, y in np.asarray(r, float).tolist()], fill=255)
            return np.asarray(img.reduce(k))
        return draw
    out["Pillow 4x"] = pillow(4)
    out["Pillow 16x"] = pillow(16)
    return out


def _freetype_peer():
    """FreeType's own rasteriser (the "smooth" one that renders glyphs):
    the rings as an FT_Outline of line segments (26.6 fixed point, y flipped:
    FreeType's y grows upward), rendered by FT_Outline_Get_Bitmap into a
    gray bitmap.  At most 32,767 points (FT_Outline counts them in a short)."""
    import ctypes
    import freetype
    from freetype import ft_structs as fs
    from freetype.raw import FT_Outline_Get_Bitmap

    lib = freetype.get_handle()

    def draw(rings, rule, tris, size):
        if tris == "each":  # each triangle in its own bitmap, composited source-over
            out = np.zeros((size, size), np.float64)
            for r in rings:
                r = np.asarray(r, float)
                x0, y0 = np.floor(r.min(0)).astype(int)
                x1, y1 = np.ceil(r.max(0)).astype(int)
                w, h = x1 - x0, y1 - y0
                if w <= 0 or h <= 0:
                    continue
                a = one(r - (x0, y0), rule, w, h).astype(np.float64)
                sub = out[y0:y1, x0:x1]
                sub[...] = a + sub * (255 - a) / 255
            return np.round(out).astype(np.uint8)
        return one(rings, rule, size, size)

    def one(rings, rule, width, height):
        if isinstance(rings, np.ndarray):
            rings = [rings]
        rings = [np.asarray(r, float) for r in rings]
        pts = np.concatenate(rings)
        n = len(pts)
        if n > 32767:
            raise ValueError("FT_Outline holds at most 32,767 points, %d given" % n)
        vec = (fs.FT_Vector * n)()
        flat = np.empty((n, 2), np.dtype("i%d" % ctypes.sizeof(ctypes.c_long)))  # FT_Pos
        flat[:, 0] = np.round(pts[:, 0] * 64)
        flat[:, 1] = np.round((height - pts[:, 1]) * 64)
        ctypes.memmove(vec, flat.ctypes.data, ctypes.sizeof(vec))
        tags = (ctypes.c_ubyte * n)(*([1] * n))  # every point on the curve: segments
        ends = np.cumsum([len(r) for r in rings]) - 1
        contours = (ctypes.c_short * len(rings))(*ends.tolist())
        outline = fs.FT_Outline()
        outline.n_contours = len(rings)
        outline.n_points = n
        outline.points = vec
        outline.tags = tags
        outline.contours = contours
        outline.flags = 0x2 if rule == "evenodd" else 0  # FT_OUTLINE_EVEN_ODD_FILL
        buf = np.zeros((height, width), np.uint8)
        bm = fs.FT_Bitmap()
        bm.rows = height
        bm.width = width
        bm.pitch = width
        bm.buffer = buf.ctypes.data_as(ctypes.POINTER(ctypes.c_ubyte))
        bm.num_grays = 256
        bm.pixel_mode = 2  # FT_PIXEL_MODE_GRAY
        err = FT_Outline_Get_Bitmap(lib, ctypes.byref(outline), ctypes.byref(bm))
        if err:
            raise RuntimeError("FT_Outline_Get_Bitmap: error %d" % err)
        return buf

    draw([np.array([(0, 0), (4, 0), (0, 4)], float)], "nonzero", False, 8)
    return draw


AREA_MAX_EDGES = 20000


def median_ms(f, reps, warm=3):
    """Median of reps timed calls of f in ms, after `warm` untimed ones."""
    return median_s(f, reps, warm) * 1e3


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--reps", type=int, default=7)
    ap.add_argument("--plot", default=None, help="write the speed/accuracy frontier here (PNG)")
    ap.add_argument("--scenes", default=None, help="comma-separated substrings of scene names")
    args = ap.parse_args()
    size = args.size
    ours = {"rastrum area": rastrum_method("area"), "rastrum accumulate": rastrum_method("accumulate"),
            "rastrum ss4": rastrum_method("ss4"), "rastrum ss16": rastrum_method("ss16"),
            "rastrum binary": rastrum_binary}
    others = peers()
    buf = np.empty((size, size), np.uint8)
    memset = median_ms(lambda: buf.fill(0), max(args.reps, 21))
    print("memset of %dx%d bytes: %.4f ms (median)" % (size, size, memset))
    points = {}
    for name, (rings, rule, tris) in scenes(size).items():
        if args.scenes and not any(s in name for s in args.scenes.split(",")):
            continue
        if tris and len(rings) * 3 > AREA_MAX_EDGES:  # the same union, exact by 16x16 samples
            ref = rastrum.triangles_coverage(np.asarray(rings), (size, size), method="ss16",
                                             subpixel_bits=12, dtype=np.float64) * 255
            print("(reference for %s: ss16, not area: max error <= ~1/8 of a pixel's edge length)" % name)
        elif tris:
            ref = rastrum.triangles_coverage(np.asarray(rings), (size, size), subpixel_bits=16,
                                             dtype=np.float64) * 255
        else:
            ref = rastrum.polygon_coverage(rings, (size, size), rule=rule, subpixel_bits=16,
                                           dtype=np.float64) * 255
        rows = []
        nedges = sum(len(r) for r in rings)
        for label, f in list(ours.items()) + list(others.items()):
            if label == "Pillow 16x" and nedges > 2000:
                print("  (Pillow 16x skipped on %s: %d polygons at 16x take minutes)" % (name, len(rings)))
                continue
            if label == "rastrum area" and nedges > AREA_MAX_EDGES:
                # each vertex event inside a row costs a pass over the row's
                # edges: 1,000 random triangles take ~3 s, 3,000 ~32 s (see
                # docs/coverage.md)
                print("  (rastrum area skipped on %s: %d edges, too many crossings per row)"
                      % (name, nedges))
                continue
            try:
                out = f(rings, rule, tris, size)
            except Exception as exc:
                print("  %s failed on %s: %s" % (label, name, exc))
                continue
            t = median_ms(lambda: f(rings, rule, tris, size), args.reps)
            err = np.abs(out.astype(np.float64) - ref)
            rows.append((label, t, err.max(), err.mean(), int((err > 1).sum())))
        fastest_peer = min((r[1] for r in rows if not r[0].startswith("rastrum")), default=float("nan"))
        print("\n%s (%s, %d edges)" % (name, rule, sum(len(r) for r in rings)))
        print("  %-20s %9s %9s %9s %8s %8s %9s" % ("method", "ms", "/memset", "/peer", "max err", "mean",
                                                "px > 1"))
        for label, t, mx, mean, n in rows:
            print("  %-20s %9.3f %9.1f %9.2f %8.2f %8.4f %9d" % (label, t, t / memset, t / fastest_peer, mx,
                                                               mean, n))
            points.setdefault(label, []).append((t / memset, mx))
    trade = []
    if not args.scenes or any(s in "curves tolerance" for s in args.scenes.split(",")):
        trade = tolerance_family(size, memset, args.reps, points)
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for label, pts in points.items():
            xs = [p[0] for p in pts]
            ys = [max(p[1], 0.05) for p in pts]
            ax.scatter(xs, ys, label=label, marker="o" if label.startswith("rastrum") else "x")
        if trade:
            ax.plot([p[0] for p in trade], [max(p[1], 0.05) for p in trade], "-", color="black", lw=1,
                    marker=".", label="rastrum area, tolerance 1 to 1/256 px (glyph curves)")
            for x, y, t in trade:
                ax.annotate(path_tolerance.tolerance_label(t).replace(" px", ""), (x, max(y, 0.05)),
                            fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.axhline(0.5, color="grey", lw=0.5, ls=":")
        ax.set_xlabel("time / memset of the same buffer (log)")
        ax.set_ylabel("max coverage error, 1/255 (log; 0.05 = exact)")
        ax.set_title("coverage at %dx%d: each point one scene" % (size, size))
        ax.legend(fontsize=7, loc="upper right")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
        print("\nwrote %s" % args.plot)


def tolerance_family(size, memset, reps, points):
    """The tolerance rows (bench/path_tolerance.py) at size x size, printed
    as the other scenes are (plus the edges rastrum filled); the peers'
    points join `points`; returns rastrum's [(time / memset, max error,
    tolerance)] for the plot's curve."""
    shape = (size, size)
    label, path = path_tolerance.curved_scene(shape)
    rows = path_tolerance.tolerance_rows(path, shape, lambda f: median_ms(f, reps))
    fastest_peer = min((r[2] for r in rows if r[1] is None), default=float("nan"))
    print("\n%s (nonzero, %d path verbs): tolerance rows, error against the true curves" % (label, len(path)))
    print("  %-24s %9s %9s %9s %8s %8s %9s %8s" % ("method", "ms", "/memset", "/peer", "max err", "mean",
                                                  "px > 1", "edges"))
    trade = []
    for name, t, ms, mx, mean, n, edges in rows:
        print("  %-24s %9.3f %9.1f %9.2f %8.2f %8.4f %9d %8s" % (name, ms, ms / memset, ms / fastest_peer, mx,
                                                               mean, n, "-" if edges is None else edges))
        if t is None:
            points.setdefault(name, []).append((ms / memset, mx))
        else:
            trade.append((ms / memset, mx, t))
    return trade


if __name__ == "__main__":
    main()

"""rastrum demo: render the benchmark scenes to PNG, then run the benchmark.

    python bench/demo.py [--out DIR] [--no-table]

Writes into DIR (default ./out):

- fig3_19.png       the polygon of Figure 3-19 on its 14 x 14 grid, one
                    enlarged square per pixel, under both sample offsets:
                    o = 0 (integer sample points, as the textbook and OpenCV)
                    and o = 1/2 (pixel centres, the default). Filled squares
                    are the pixels rastrum sets; dots are the sample points;
                    the red line is the exact polygon.
- fig3_19_textbook.png  the same polygon under rounding="textbook" (each
                    crossing rounded to the nearest column, as the book's
                    worked example) beside the exact rule.
- boundary_modes.png    one polygon under boundary="exact", "closed" (plus
                    the library's outline) and "conservative" (plus every
                    pixel an edge passes through).
- holes.png         the disc with three holes, even-odd | non-zero; top row
                    with the holes running opposite to the disc (both rules
                    agree), bottom row with the holes running the same way
                    (non-zero fills them: orientation matters to non-zero).
- star200.png       the 200-spike star.
- star200_67.png    the self-intersecting {200/67} star, even-odd | non-zero.
- canvas.png        an rgb888 Canvas composition.
- gouraud.png       twelve Gouraud triangles round a grey centre, labelled:
                    exact | the error of fixed point at F = 4 (x 16) |
                    rgb565 (5/6/5 bits: visible steps) | mono1 (a pixel on
                    iff its interpolated level is >= 128: a threshold, no
                    dithering).
- mesh_sphere_flat_vs_gouraud.png  one sphere, Lambert flat | Gouraud (the
                    Mach bands of seed 001 3.1.3 at the flat faces' edges).
- mesh_torus_depth.png  a tilted torus, its faces shuffled and culled,
                    drawn without depth (the last face wins) | z-buffered.
- fig3_18_gouraud_rect.png  Figure 3-18: a rectangle shaded bilinearly from
                    its four corners | split into two Gouraud triangles
                    along either diagonal.
- gouraud_polygon.png   Figure 3-19's polygon with a colour per vertex,
                    shaded by the AET (edge, then span).

- seedfill.png      region fill: outlines drawn with the library's lines,
                    before | flood-filled 4-connected | 8-connected.
- coverage.png      anti-aliasing, each pixel an enlarged square: a circle
                    and a pentagram (non-zero) as a binary mask | "area"
                    coverage; a square drawn twice under even-odd (nothing
                    inside) by "area" | by "accumulate", the signed-area
                    accumulation of FreeType, AGG and Blend2D (a ghost
                    outline where the two copies' edges coincide).

then prints a short table: rastrum against the peers it finds installed
(Pillow always; OpenCV, skia-python, scikit-image, pycocotools when
present), the time of one call and the pixels each result differs from the
exact mask; and the tolerance rows: a few words of a real font's curves
(an SVG path of curves without matplotlib) filled anti-aliased at
flattening tolerances 1 to 1/256 px, each row's time and coverage error
against the true curves, beside the peers installed that fill curves
(bench/path_tolerance.py).  A few seconds in all; --no-table skips it.  The full
benchmarks are ``make bench`` (bench/bench.py and its siblings), which
install the peers first.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import bench  # noqa: E402
import scenes  # noqa: E402

rastrum = bench.import_rastrum()


def _font(size):
    from PIL import ImageFont
    try:
        return ImageFont.load_default(size=size)
    except TypeError:          # Pillow < 10.1: fixed-size bitmap font
        return ImageFont.load_default()


def mask_image(mask, fg=0, bg=255):
    """A mode-L Pillow image of a bool mask (inside = fg)."""
    from PIL import Image
    return Image.fromarray(np.where(mask, fg, bg).astype(np.uint8), "L")


def labelled_row(images, labels, gap=16, pad_top=48, size=28):
    """Images side by side on white, each with a caption above it."""
    from PIL import Image, ImageDraw
    w = sum(im.width for im in images) + gap * (len(images) + 1)
    h = max(im.height for im in images) + pad_top + gap
    out = Image.new("RGB", (w, h), "white")
    d = ImageDraw.Draw(out)
    x = gap
    font = _font(size)
    for im, lab in zip(images, labels):
        out.paste(im.convert("RGB"), (x, pad_top))
        d.text((x, 10), lab, fill="black", font=font)
        x += im.width + gap
    return out


def stack(rows, gap=0):
    from PIL import Image
    w = max(r.width for r in rows)
    out = Image.new("RGB", (w, sum(r.height for r in rows)
                            + gap * (len(rows) - 1)), "white")
    y = 0
    for r in rows:
        out.paste(r, (0, y))
        y += r.height + gap
    return out


# ---------------------------------------------------------------------------
# Figure 3-19
# ---------------------------------------------------------------------------

def grid_panel(mask, ring, offset, scale=40, margin=36, labels=True):
    """A small mask upscaled nearest-neighbour, with the pixel grid, the
    sample points (filled when the pixel is set) and the exact polygon."""
    from PIL import Image, ImageDraw
    h, w = mask.shape
    big = mask_image(mask, fg=150, bg=255).resize((w * scale, h * scale),
                                                  Image.NEAREST)
    img = Image.new("RGB", (w * scale + 2 * margin, h * scale + 2 * margin),
                    "white")
    img.paste(Image.merge("RGB", (big.point(lambda v: 120 if v < 255
                                            else 255), big,
                                  big.point(lambda v: 230 if v < 255
                                            else 255))),
              (margin, margin))
    d = ImageDraw.Draw(img)
    small = _font(14)

    def P(x, y):
        return (margin + x * scale, margin + y * scale)
    for k in range(w + 1):           # pixel boundaries
        d.line([P(k, 0), P(k, h)], fill=(200, 200, 200))
    for k in range(h + 1):
        d.line([P(0, k), P(w, k)], fill=(200, 200, 200))
    for k in range(w):               # integer coordinates on the axes
        d.text((margin + k * scale + 2, margin - 18), str(k), fill="gray",
               font=small)
    for k in range(h):
        d.text((4, margin + k * scale + 2), str(k), fill="gray", font=small)
    r = 4                            # sample points
    for j in range(h):
        for i in range(w):
            cx, cy = P(i + offset, j + offset)
            box = [cx - r, cy - r, cx + r, cy + r]
            if mask[j, i]:
                d.ellipse(box, fill=(20, 40, 140))
            else:
                d.ellipse(box, outline=(120, 120, 120))
    pts = [P(x, y) for x, y in np.asarray(ring, float).tolist()]
    d.line(pts + [pts[0]], fill=(220, 0, 0), width=3)
    if labels:
        for k, (x, y) in enumerate(np.asarray(ring, float).tolist()):
            px, py = P(x, y)
            d.text((px + 6, py - 20), f"P{k}", fill=(220, 0, 0), font=small)
    return img


def fig3_19_panel(offset, rounding="exact"):
    rings, shape = scenes.fig3_19()
    mask = rastrum.polygon_mask(rings, shape, sample_offset=offset,
                                rounding=rounding)
    return grid_panel(mask, rings[0], offset), int(mask.sum())


def render_fig3_19(out: Path):
    panels, labels = [], []
    for o, name in ((0.0, "o = 0 (textbook, OpenCV)"),
                    (0.5, "o = 1/2 (pixel centres, default)")):
        img, n = fig3_19_panel(o)
        panels.append(img)
        labels.append(f"Figure 3-19, {name}: {n} pixels")
    path = out / "fig3_19.png"
    labelled_row(panels, labels, size=20).save(path)
    return [path, render_textbook(out), render_boundary_modes(out)]


def render_textbook(out: Path):
    """Figure 3-19 as the book rounds it (each crossing to the nearest
    column) beside the exact rule, both with samples on the corners."""
    panels, labels = [], []
    for rounding in ("textbook", "exact"):
        img, n = fig3_19_panel(0.0, rounding)
        panels.append(img)
        labels.append(f'rounding="{rounding}", o = 0: {n} pixels')
    path = out / "fig3_19_textbook.png"
    labelled_row(panels, labels, size=20).save(path)
    return path


BOUNDARY_RING = [(1.6, 1.3), (13.4, 3.2), (10.2, 10.6), (5.5, 7.2), (2.4, 9.7)]


def render_boundary_modes(out: Path):
    """One polygon under the three boundary modes (pixel centres)."""
    panels, labels = [], []
    for boundary in ("exact", "closed", "conservative"):
        mask = rastrum.polygon_mask(BOUNDARY_RING, (12, 15), boundary=boundary)
        panels.append(grid_panel(mask, BOUNDARY_RING, 0.5, scale=32,
                                 labels=False))
        labels.append(f'boundary="{boundary}": {int(mask.sum())} px')
    path = out / "boundary_modes.png"
    labelled_row(panels, labels, size=20).save(path)
    return path


# ---------------------------------------------------------------------------
# holes, stars
# ---------------------------------------------------------------------------

def render_holes(out: Path):
    rings, shape = scenes.ring_with_holes(1024)
    same = [rings[0]] + [r[::-1].copy() for r in rings[1:]]
    rows = []
    for rr, what in ((rings, "holes opposite"), (same, "holes same way")):
        ims, labs = [], []
        for rule in ("evenodd", "nonzero"):
            ims.append(mask_image(rastrum.polygon_mask(rr, shape,
                                                       rule=rule)))
            labs.append(f"{rule}, {what}")
        rows.append(labelled_row(ims, labs))
    path = out / "holes.png"
    stack(rows).save(path)
    return [path]


def render_stars(out: Path):
    paths = []
    rings, shape = scenes.star(200, 2048)
    p = out / "star200.png"
    mask_image(rastrum.polygon_mask(rings, shape)).save(p)
    paths.append(p)
    rings, shape = scenes.star_polygon(200, 67, 2048)
    ims = [mask_image(rastrum.polygon_mask(rings, shape, rule=r))
           for r in ("evenodd", "nonzero")]
    p = out / "star200_67.png"
    labelled_row(ims, ["{200/67} evenodd", "{200/67} nonzero"],
                 size=40, pad_top=64).save(p)
    paths.append(p)
    return paths


# ---------------------------------------------------------------------------
# Canvas composition
# ---------------------------------------------------------------------------

def render_canvas(out: Path):
    W, H = 1400, 760
    c = rastrum.Canvas((H, W), format="rgb888", background=(18, 24, 48))
    rng = np.random.default_rng(7)
    # scattered random polygons in the background, non-zero rule
    for k in range(24):
        cx, cy = rng.uniform(0, W), rng.uniform(0, H)
        pts = np.stack([cx + rng.normal(0, 60, 12),
                        cy + rng.normal(0, 60, 12)], axis=1)
        col = tuple(int(v) for v in rng.integers(40, 110, 3))
        c.fill_polygon(pts, col, rule="nonzero")
    # the disc with holes, on the left
    rings, _ = scenes.ring_with_holes(1024)
    c.fill_polygon([r * 0.65 + (20.0, 50.0) for r in rings],
                   (240, 140, 30), rule="nonzero")
    # the {200/67} star polygon, even-odd bands, on the right
    rings, _ = scenes.star_polygon(200, 67, 2048)
    c.fill_polygon([r * 0.32 + (720.0, 50.0) for r in rings],
                   (250, 220, 60), rule="evenodd")
    # the 200-spike star, small, in its solid centre
    rings, _ = scenes.star(200, 2048)
    k = 0.08
    c.fill_polygon([r * k + (720.0 + 1024 * (0.32 - k),
                             50.0 + 1024 * (0.32 - k)) for r in rings],
                   (90, 200, 255))
    # Figure 3-19 x10, at sample offset 0 like the book, between them
    rings, _ = scenes.fig3_19(10.0)
    c.fill_polygon([r + (600.0, 590.0) for r in rings], (120, 220, 120),
                   sample_offset=0)
    path = out / "canvas.png"
    c.save(path)
    return [path]


def render_shading(out):
    """Twelve Gouraud triangles round a grey centre, four labelled panels:
    exact, the error of fixed point at F = 4 (magnified), rgb565 and mono1
    (on iff the interpolated level is >= 128): out/gouraud.png."""
    rng = np.random.default_rng(3)
    n = 12
    ang = np.linspace(0, 2 * np.pi, n + 1)
    ring = np.stack([150 + 140 * np.cos(ang), 150 + 140 * np.sin(ang)], -1)
    tris = np.array([[ring[k], ring[k + 1], (150.0, 150.0)] for k in range(n)])
    cols = rng.integers(0, 256, (n, 3, 3))
    cols[:, 2] = 128  # a mid-grey centre
    cols[:, 1] = np.roll(cols[:, 0], -1, axis=0)  # shared rim vertices agree

    def draw(fmt, vc, **kw):
        c = rastrum.Canvas((300, 300), format=fmt)
        c.fill_triangles(tris, vertex_colors=vc, **kw)
        return c

    exact = draw("rgb888", cols)
    fixed = draw("rgb888", cols, precision="fixed", fraction_bits=4)
    err = np.abs(exact.array.astype(int) - fixed.array.astype(int))
    from PIL import Image
    err_img = Image.fromarray(np.clip(255 - 16 * err.max(axis=2), 0, 255).astype(np.uint8), "L")
    # mono1 takes one level a vertex: the colours' mean
    mono = draw("mono1", cols.mean(axis=2, keepdims=True).round().astype(int))
    tiles = [exact.to_image(), err_img, draw("rgb565", cols).to_image(), mono.to_image()]
    labels = ["exact (rgb888)", f"fixed F=4: error x16, max {int(err.max())}",
              "rgb565", "mono1: level >= 128"]
    path = out / "gouraud.png"
    labelled_row(tiles, labels, size=18, pad_top=36).save(path)
    return [path]


def render_meshes(out: Path):
    """The scene pipeline and the Gouraud rectangles/polygons (issue 6)."""
    from rastrum.scene import render_mesh, rotation, sphere, torus
    paths = []
    v, f, n = sphere(14, 28)
    kw = dict(normals=n, scale=0.9, light=(-0.5, 0.6, 0.7), color=(235, 235, 235), ambient=0.12)
    flat = render_mesh(v, f, shape=(360, 360), shading="flat", **kw)
    smooth = render_mesh(v, f, shape=(360, 360), shading="gouraud", **kw)
    p = out / "mesh_sphere_flat_vs_gouraud.png"
    labelled_row([flat.to_image(), smooth.to_image()], ["flat (Lambert per face)", "Gouraud (per vertex)"]).save(p)
    paths.append(p)

    v, f, n = torus(1.0, 0.42, 64, 32)
    kw = dict(normals=n, shading="gouraud", rotation=rotation(15, 30, -10), projection="perspective",
              distance=3.6, fov=40, scale=0.95, color=(245, 170, 70), light=(-0.3, 0.7, 0.65))
    shuffled = f[np.random.default_rng(1).permutation(len(f))]  # a mesh in no particular order
    no_depth = render_mesh(v, shuffled, shape=(360, 400), depth=False, **kw)
    z = render_mesh(v, shuffled, shape=(360, 400), depth=True, **kw)
    p = out / "mesh_torus_depth.png"
    labelled_row([no_depth.to_image(), z.to_image()], ["culled, no depth", "culled + depth buffer"]).save(p)
    paths.append(p)

    # Figure 3-18: P0 red (bottom left), P1 green, P2 yellow, P3 blue (the
    # book's y goes up; ours goes down).
    red, green, yellow, blue = (230, 30, 30), (30, 200, 60), (250, 230, 40), (40, 70, 230)
    W = H = 300
    panels = []
    for method, rect, cols in (
        ("bilinear", (0, 0, W, H), [blue, yellow, green, red]),
        ("triangles", (0, 0, W, H), [blue, yellow, green, red]),      # diagonal P3-P1
        ("triangles", (0, H, W, 0), [red, green, yellow, blue]),      # diagonal P0-P2
    ):
        c = rastrum.Canvas((H, W))
        c.fill_rect_gouraud(rect, cols, method=method)
        panels.append(c.to_image())
    p = out / "fig3_18_gouraud_rect.png"
    labelled_row(panels, ["bilinear (Fig. 3-12b)", "2 triangles, TL-BR", "2 triangles, BL-TR"]).save(p)
    paths.append(p)

    rings, _ = scenes.fig3_19(30.0)
    c = rastrum.Canvas((420, 420), background=(255, 255, 255))
    cols = [(230, 30, 30), (250, 200, 40), (40, 190, 60), (40, 70, 230), (250, 250, 250), (150, 40, 200),
            (20, 200, 220)]
    c.fill_polygon([r + (-15.0, -15.0) for r in rings], vertex_colors=cols)
    p = out / "gouraud_polygon.png"
    c.save(p)
    paths.append(p)
    return paths

# ---------------------------------------------------------------------------
# region fill: before / after
# ---------------------------------------------------------------------------

def render_seedfill(out: Path):
    """Outlines drawn with the library's lines, then flood-filled from a few
    seeds (inside the circle, the star and the bar, on the ink of the bar
    and the vertical line, on the paper): before | 4-connected |
    8-connected, which leaks through the corner steps of a line."""
    W, H, scale = 200, 130, 4
    ink, paper = (30, 30, 40), (250, 248, 240)

    def drawing():
        c = rastrum.Canvas((H, W), format="rgb888", background=paper)
        t = np.linspace(0, 2 * np.pi, 40, endpoint=False)
        c.polyline(np.stack([50 + 38 * np.cos(t), 62 + 38 * np.sin(t)], 1), ink, closed=True)
        a = np.linspace(0, 2 * np.pi, 11)[:-1]
        r = np.where(np.arange(10) % 2, 18, 40)
        c.polyline(np.stack([140 + r * np.sin(a), 62 - r * np.cos(a)], 1), ink, closed=True)
        c.polyline([(12, 112), (188, 112), (188, 124), (12, 124)], ink, closed=True)
        c.line((100, 0), (100, 130), ink)
        return c

    panels, labels = [], []
    for conn in (None, 4, 8):
        c = drawing()
        if conn:
            c.flood_fill((50, 62), (70, 150, 230), connectivity=conn)
            c.flood_fill((140, 62), (240, 170, 40), connectivity=conn)
            c.flood_fill((100, 118), (200, 60, 80), connectivity=conn)
            c.flood_fill((60, 118), (120, 200, 120), connectivity=conn)
            c.flood_fill((5, 5), (200, 225, 200), connectivity=conn)
        panels.append(c.to_image().resize((W * scale, H * scale), 0))
        labels.append("before" if conn is None else f"flood_fill, connectivity={conn}")
    path = out / "seedfill.png"
    labelled_row(panels, labels).save(path)
    return [path]


def peer_table(out=None, repeats=5):
    """rastrum against the peers installed here, on three scenes: the
    median time of one call and the pixels each result differs from the
    exact mask (rastrum's, at the sample offset that suits the peer best;
    rastrum equals the exact rational reference, which the tests check).
    An empty result is reported as such, not timed as a winner."""
    import time
    out = sys.stdout if out is None else out
    table = [("star200", scenes.star(200, 1024)), ("holes", scenes.ring_with_holes(1024)),
             ("coco-like", (scenes.coco_like(1)[0][0], (480, 640)))]
    peers = [p for p in bench.PEERS if bench.peer_available(p) is None and p.name != "skimage.draw"]
    rows = []
    for name, (rings, shape) in table:
        exact = {o: rastrum.polygon_mask(rings, shape, sample_offset=o) for o in (0.0, 0.5)}
        cands = [("rastrum", lambda r=rings, s=shape: rastrum.polygon_mask(r, s))]
        cands += [(p.name, p.make(rings, shape, "evenodd")) for p in peers]
        for label, fn in cands:
            got = np.asarray(fn()).astype(bool)
            times = []
            for _ in range(repeats):
                t0 = time.perf_counter()
                fn()
                times.append(time.perf_counter() - t0)
            off = min(int(np.count_nonzero(got != e)) for e in exact.values())
            rows.append((name, label, sorted(times)[repeats // 2] * 1e3, off, not got.any()))
    missing = [p.name for p in bench.PEERS if bench.peer_available(p) is not None]
    print("\nrastrum and the peers installed here (one call, median of %d; pixels that differ"
          " from the exact mask):" % repeats, file=out)
    print("%-10s %-15s %9s %10s" % ("scene", "library", "ms", "px off"), file=out)
    for name, label, ms, off, empty in rows:
        print("%-10s %-15s %9.3f %10s" % (name, label, ms, "empty!" if empty else "(exact)" if label == "rastrum" else off), file=out)
    print("(the exact mask: rastrum's, equal to the exact rule for the input snapped to 1/256 px; each peer"
          " compared at the sample offset, pixel centre or corner, that suits it best)", file=out)
    if missing:
        print("not installed: %s (make bench installs them and runs the full benchmarks)"
              % ", ".join(missing), file=out)
    return rows


def curve_table(out=None, repeats=5, shape=(64, 256)):
    """The tolerance row family on a small curved scene: rastrum's "area"
    coverage at each flattening tolerance and the curve-drawing peers
    installed, the median time of one call and the error in levels of 255
    against the exact area of the true curves (bench/path_tolerance.py)."""
    import time
    import path_tolerance
    out = sys.stdout if out is None else out

    def median_ms(f):
        f()
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            f()
            times.append(time.perf_counter() - t0)
        return sorted(times)[repeats // 2] * 1e3
    label, path = path_tolerance.curved_scene(shape)
    rows = path_tolerance.tolerance_rows(path, shape, median_ms)
    print("\n%s, %dx%d px, anti-aliased (one call, median of %d; coverage error in levels of 255 against"
          " the true curves):" % (label, shape[1], shape[0], repeats), file=out)
    print("%-24s %9s %9s %9s %8s" % ("library", "ms", "max err", "px > 1", "edges"), file=out)
    for name, t, ms, mx, mean, n, edges in rows:
        print("%-24s %9.3f %9.2f %9d %8s" % (name, ms, mx, n, "-" if edges is None else edges), file=out)
    print("(the true curves: the path flattened at 1/4096 px on the 1/65536 px grid, about 0.1/255 off them;"
          " rastrum's default tolerance is 1/256 px)", file=out)
    return rows


# ---------------------------------------------------------------------------
# Anti-aliased coverage
# ---------------------------------------------------------------------------

def render_coverage(out: Path, size=40, scale=8):
    """Binary mask | "area" coverage of one scene, and "area" |
    "accumulate" where contours coincide: out/coverage.png."""
    from PIL import Image
    shape = (size, size)
    t = np.linspace(0, 2 * np.pi, 48, endpoint=False)
    circle = np.stack([13.3 + 9.6 * np.cos(t), 14.2 + 9.6 * np.sin(t)], 1)
    k = np.arange(5)
    penta = np.stack([27.4 + 11.5 * np.sin(k * 4 * np.pi / 5), 25.1 - 11.5 * np.cos(k * 4 * np.pi / 5)], 1)
    scene = [circle, penta]
    sq = np.array([(6.3, 7.6), (33.4, 9.2), (31.7, 33.5), (8.2, 31.1)])

    def big(a):  # coverage 0..255 as ink on white, each pixel scale x scale
        return Image.fromarray(255 - np.kron(a, np.ones((scale, scale), np.uint8)), "L")

    binary = rastrum.polygon_mask(scene, shape, rule="nonzero").view(np.uint8) * np.uint8(255)
    area = rastrum.polygon_coverage(scene, shape, rule="nonzero")
    twice_area = rastrum.polygon_coverage([sq, sq], shape, rule="evenodd")
    twice_acc = rastrum.polygon_coverage([sq, sq], shape, rule="evenodd", method="accumulate")
    rows = [labelled_row([big(binary), big(area)], ["binary (polygon_mask)", 'coverage, "area"'],
                         size=20, pad_top=40),
            labelled_row([big(twice_area), big(twice_acc)],
                         ['square twice, even-odd: "area"', '"accumulate" (signed area)'],
                         size=20, pad_top=40)]
    path = out / "coverage.png"
    stack(rows).save(path)
    return [path]


def render_paths(out: Path):
    """Curves, strokes, text and a gauge, exact, beside Blend2D and cairo
    with each one's error: out/paths.png (bench/paths_scene.py).  Skipped,
    saying why, where matplotlib or a peer is missing."""
    import paths_scene

    if not paths_scene.available():
        print("paths.png: not drawn (needs matplotlib, blend2d-python and pycairo or cairocffi)")
        return []
    path = out / "paths.png"
    errs = paths_scene.render(path)
    for name, e in errs.items():
        print("paths.png: %s against the exact coverage: max %.1f/255, mean %.3f/255, %d pixels off by more "
              "than 1/255, %d by more than 16/255" % (name, e["max"], e["mean"], e["off>1"], e["off>16"]))
    return [path]


def main(argv=None):
    ap = argparse.ArgumentParser(description="render the rastrum demo pictures to PNG, then print a "
                                 "short table against the peers installed here")
    ap.add_argument("--out", default="out", help="output directory (default ./out)")
    ap.add_argument("--no-table", action="store_true", help="only write the pictures")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for f in (render_fig3_19, render_holes, render_stars, render_canvas, render_shading, render_meshes,
              render_seedfill, render_coverage, render_paths):
        written += f(out)
    print("wrote %d pictures to %s/: %s" % (len(written), out, ", ".join(p.name for p in written)))
    sys.stdout.flush()
    if not args.no_table:
        peer_table()
        curve_table()
    return written


if __name__ == "__main__":
    main()

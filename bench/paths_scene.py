"""A stroked, curved, anti-aliased scene -- text from a real font's
outlines (matplotlib's TextPath, DejaVu Sans), a chart with a dashed
series, a gauge, a looping curve stroked wide -- drawn by rastrum
exactly and by Blend2D and cairo with their own APIs (curves, strokes,
dashes natively), with each peer's error against the exact coverage.

Used by bench/demo.py (docs/paths.png, make demo / make figures) and
bench/bench_paths.py (the glyph-paragraph timing).
"""

from __future__ import annotations

import math
from typing import Callable, Dict, List, Optional, Tuple

import numpy as np

W, H = 360, 150


def text_path(text: str, size: float, x: float, y: float):
    """matplotlib's TextPath of `text` (DejaVu Sans, bundled with
    matplotlib) as a rastrum Path, baseline at (x, y), y down."""
    import rastrum
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    tp = TextPath((0, 0), text, size=size, prop=FontProperties(family="DejaVu Sans"))
    return rastrum.Path.from_matplotlib(tp).transformed((1, 0, x, 0, -1, y))


def dash_supported() -> bool:
    """Does rastrum.stroke take dash= yet (engineer stroke34's work)?"""
    import rastrum
    try:
        rastrum.stroke([(0, 0), (10, 0)], 1, dash=[2, 2])
        return True
    except rastrum.InputError:
        return False


def scene() -> List[Tuple]:
    """The operations: ("fill", Path) and ("stroke", Path, width, join,
    cap, dash or None), in rastrum Paths (peers get the same verbs)."""
    import rastrum
    P = rastrum.Path
    ops: List[Tuple] = [("fill", text_path("Curves, exactly", 27, 8, 30))]
    # the chart: axes, a solid series, a dashed series
    ops.append(("stroke", P().move_to(12, 52).line_to(12, 140).line_to(210, 140), 1.5, "miter", "butt", None))
    xs = np.linspace(14, 206, 25)
    a = 110 - 35 * np.sin(xs / 22.0) * np.exp(-(xs - 14) / 260)
    b = 120 - 18 * np.cos(xs / 15.0 + 1)
    for ys, w, dash in ((a, 2.2, None), (b, 1.6, [7.0, 4.0])):
        p = P().move_to(xs[0], ys[0])
        for x, y in zip(xs[1:], ys[1:]):
            p.line_to(float(x), float(y))
        ops.append(("stroke", p, w, "miter", "butt", dash))
    # a looping cubic stroked wide: its stroke crosses itself
    ops.append(("stroke", P().move_to(140, 68).cubic_to(222, 22, 128, 22, 210, 68), 5.0, "miter", "round", None))
    # the gauge: a 270-degree track, a value arc, a needle, a hub
    cx, cy, r = 295.0, 95.0, 42.0
    ops.append(("stroke", P.arc(cx, cy, r, r, 135, 405), 3.0, "miter", "butt", None))
    ops.append(("stroke", P.arc(cx, cy, r - 7, r - 7, 135, 320), 9.0, "miter", "butt", None))
    t = math.radians(320)
    ops.append(("stroke", P().move_to(cx, cy).line_to(cx + 30 * math.cos(t), cy + 30 * math.sin(t)), 3.0,
                "miter", "round", None))
    ops.append(("fill", P.circle(cx, cy, 5.5)))
    return ops


def exact(ops) -> np.ndarray:
    """rastrum: the union of every operation's region, its exact area in
    each pixel ("area", float64), as one non-zero fill (the text's holes run
    opposite to its outlines; every stroke outline is positive)."""
    import rastrum

    whole = rastrum.Path()
    dash_ok = dash_supported()
    for op in ops:
        if op[0] == "fill":
            p = op[1]
        else:
            _, path, w, join, cap, dash = op
            kw = {"dash": dash} if dash is not None and dash_ok else {}
            p = rastrum.stroke(path, w, join=join, cap=cap, **kw)
        whole._verbs += p._verbs
        whole._pts += p._pts
    return rastrum.polygon_coverage(whole, (H, W), rule="nonzero", dtype=np.float64)


def _trace(path, move, line, quad, cubic, close):
    from rastrum._path import CLOSE, CUBIC, LINE, MOVE, QUAD

    k = 0
    pts = path._pts
    for v in path._verbs:
        if v == MOVE:
            move(*pts[k])
            k += 1
        elif v == LINE:
            line(*pts[k])
            k += 1
        elif v == QUAD:
            quad(*pts[k], *pts[k + 1])
            k += 2
        elif v == CUBIC:
            cubic(*pts[k], *pts[k + 1], *pts[k + 2])
            k += 3
        elif v == CLOSE:
            close()


def blend2d(ops, dashes: bool) -> Optional[np.ndarray]:
    """Blend2D, A8, each operation painted source-over (coverage / 255)."""
    try:
        import blend2d as b
    except ImportError:
        return None
    img = b.BLImage(W, H, b.BLFormat.A8)
    ctx = b.BLContext(img)
    ctx.clear_all()
    ctx.fill_rule = b.BLFillRule.NON_ZERO
    ctx.set_fill_style((255, 255, 255, 255))
    ctx.set_stroke_style((255, 255, 255, 255))
    for op in ops:
        p = b.BLPath()
        _trace(op[1], p.move_to, p.line_to, p.quadric_to, p.cubic_to, p.close)
        if op[0] == "fill":
            ctx.fill_path(p)
            continue
        _, _, w, join, cap, dash = op
        ctx.stroke_width = w
        ctx.stroke_join = {"miter": b.BLStrokeJoin.JOIN_MITER_BEVEL, "round": b.BLStrokeJoin.JOIN_ROUND,
                           "bevel": b.BLStrokeJoin.JOIN_BEVEL}[join]  # SVG's miter: bevelled past the limit
        ctx.stroke_miter_limit = 4.0
        ctx.set_stroke_caps({"butt": b.BLStrokeCap.CAP_BUTT, "round": b.BLStrokeCap.CAP_ROUND,
                             "square": b.BLStrokeCap.CAP_SQUARE}[cap])
        arr = b.BLArrayDouble()
        arr.from_numpy(np.asarray(dash if dash is not None and dashes else [], np.float64))
        ctx.set_stroke_dash_array(arr)
        ctx.stroke_dash_offset = 0.0
        ctx.stroke_path(p)
    ctx.flush()
    return img.getDataAsNumPy().reshape(H, W).astype(np.float64) / 255


def cairo(ops, dashes: bool) -> Optional[np.ndarray]:
    """cairo, A8, ANTIALIAS_DEFAULT, each operation painted source-over
    (pycairo, or cairocffi: the same API over the system's libcairo)."""
    try:
        import cairo as c
    except ImportError:
        try:
            import cairocffi as c
        except (ImportError, OSError):
            return None
    surf = c.ImageSurface(c.FORMAT_A8, W, H)
    ctx = c.Context(surf)
    ctx.set_source_rgba(0, 0, 0, 1)
    ctx.set_fill_rule(c.FILL_RULE_WINDING)

    def quad(x1, y1, x, y):
        x0, y0 = ctx.get_current_point()
        ctx.curve_to(x0 + 2 / 3 * (x1 - x0), y0 + 2 / 3 * (y1 - y0), x + 2 / 3 * (x1 - x), y + 2 / 3 * (y1 - y), x, y)

    for op in ops:
        ctx.new_path()
        _trace(op[1], ctx.move_to, ctx.line_to, quad, ctx.curve_to, ctx.close_path)
        if op[0] == "fill":
            ctx.fill()
            continue
        _, _, w, join, cap, dash = op
        ctx.set_line_width(w)
        ctx.set_line_join({"miter": c.LINE_JOIN_MITER, "round": c.LINE_JOIN_ROUND, "bevel": c.LINE_JOIN_BEVEL}[join])
        ctx.set_miter_limit(4.0)
        ctx.set_line_cap({"butt": c.LINE_CAP_BUTT, "round": c.LINE_CAP_ROUND, "square": c.LINE_CAP_SQUARE}[cap])
        ctx.set_dash(list(dash) if dash is not None and dashes else [], 0.0)
        ctx.stroke()
    surf.flush()
    a = np.frombuffer(bytes(surf.get_data()), np.uint8).reshape(H, surf.get_stride())[:, :W]
    return a.astype(np.float64) / 255


PEERS: Dict[str, Callable] = {"Blend2D": blend2d, "cairo": cairo}


def errors(ref: np.ndarray, got: np.ndarray) -> Dict[str, float]:
    """A peer's error against the exact coverage, in levels of 255."""
    d = np.abs(got - ref) * 255
    return {"max": float(d.max()), "mean": float(d.mean()), "off>1": int((d > 1.0).sum()),
            "off>16": int((d > 16.0).sum())}


def available() -> bool:
    """Can this machine draw the whole picture (matplotlib for the font,
    both peers)?"""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return False
    ops = None
    try:
        ops = scene()
    except Exception:  # pragma: no cover - a missing font
        return False
    return all(f(ops[:1], False) is not None for f in PEERS.values())


def render(path) -> Dict[str, Dict[str, float]]:
    """The picture (docs/paths.png): rastrum's exact coverage, Blend2D's
    and cairo's renderings, and each peer's error against the exact one;
    returns the errors."""
    from PIL import Image, ImageDraw, ImageFont

    ops = scene()
    dashes = dash_supported()
    ref = exact(ops)
    try:
        font = ImageFont.load_default(size=13)
    except TypeError:  # Pillow < 10.1
        font = ImageFont.load_default()

    def ink(a):
        return Image.fromarray((255 - np.clip(a, 0, 1) * 255 + 0.5).astype(np.uint8), "L")

    def err(d):  # |error| in levels, 0 white .. 32+ levels full red
        t = np.clip(d / 32.0, 0, 1)
        rgb = np.stack([np.full_like(t, 255), 255 * (1 - t), 255 * (1 - t)], -1)
        return Image.fromarray((rgb + 0.5).astype(np.uint8), "RGB")

    panels = [(ink(ref), "rastrum, exact area coverage")]
    errs: Dict[str, Dict[str, float]] = {}
    err_panels = []
    for name, draw in PEERS.items():
        got = draw(ops, dashes)
        if got is None:
            blank = Image.new("L", (W, H), 255)
            panels.append((blank, "%s: not installed" % name))
            continue
        e = errors(ref, got)
        errs[name] = e
        panels.append((ink(got), name))
        err_panels.append((err(np.abs(got - ref) * 255), "%s - exact: max %.0f/255, %d px off > 1/255"
                           % (name, e["max"], e["off>1"])))
    gap, top = 10, 22
    rows = [panels, err_panels]
    out = Image.new("RGB", (gap + 3 * (W + gap), gap + len(rows) * (H + top + gap)), "white")
    d = ImageDraw.Draw(out)
    y = gap
    for row in rows:
        x = gap
        if row is err_panels:
            d.text((x, y + top + 4), "error against the exact\ncoverage (white 0, red\n>= 32 levels of 255)%s"
                   % ("" if dashes else ";\ndashes drawn solid\nuntil rastrum.stroke\ntakes dash="), fill="black",
                   font=font)
            x += W + gap
        for im, label in row:
            d.text((x, y + 4), label, fill="black", font=font)
            out.paste(im.convert("RGB"), (x, y + top))
            x += W + gap
        y += H + top + gap
    out.save(path)
    return errs

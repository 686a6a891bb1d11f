"""docs/opacity.png: opacity and the linear-light blend (docs/opacity.md).

    python tools/opacity_picture.py [out.png]

Four panels, each drawn by rastrum on an rgb888 Canvas: thin anti-aliased
strokes (0.5 to 1.5 px wide quads, aa="area") and three discs at alpha 140
overlapping, on a dark and on a light background; the top row mixes in
the stored levels (the default), the bottom row in linear light
(gamma="srgb").  In the stored levels thin light strokes on dark look too
thin and dark ones on light too heavy; linear light evens them out.
"""
import math
import sys

import numpy as np
from PIL import Image, ImageDraw

import rastrum

W, H, ZOOM = 170, 110, 2
DARK, LIGHT = (24, 26, 34), (242, 240, 232)


def disc(cx, cy, r, n=96):
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)) for k in range(n)]


def stroke(x0, y0, x1, y1, width):
    dx, dy = x1 - x0, y1 - y0
    n = math.hypot(dx, dy)
    ox, oy = -dy / n * width / 2, dx / n * width / 2
    return [(x0 + ox, y0 + oy), (x1 + ox, y1 + oy), (x1 - ox, y1 - oy), (x0 - ox, y0 - oy)]


def panel(background, ink, gamma):
    c = rastrum.Canvas((H, W), format="rgb888", background=background)
    for k in range(14):
        a = math.pi * (0.04 + 0.46 * k / 13)
        width = 0.5 + k / 13
        c.fill_polygon(stroke(8, 8, 8 + 150 * math.cos(a), 8 + 150 * math.sin(a), width), ink, aa="area", gamma=gamma)
    for (cx, cy), color in zip([(112, 48), (138, 48), (125, 70)], [(230, 40, 40), (40, 200, 60), (50, 90, 240)]):
        c.fill_polygon(disc(cx, cy, 20.5), color + (140,), aa="area", gamma=gamma)
    return c.array


def main(path):
    rows = []
    for gamma in (None, "srgb"):
        rows.append(np.concatenate([panel(DARK, (255, 255, 255), gamma), np.full((H, 4, 3), 128, np.uint8),
                                    panel(LIGHT, (0, 0, 0), gamma)], axis=1))
    gap = np.full((4, rows[0].shape[1], 3), 128, np.uint8)
    img = Image.fromarray(np.concatenate([rows[0], gap, rows[1]], axis=0), "RGB")
    img = img.resize((img.width * ZOOM, img.height * ZOOM), Image.NEAREST)
    d = ImageDraw.Draw(img)
    d.text((6, H * ZOOM - 14), "stored levels (default)", fill=(255, 160, 0))
    d.text((6, (2 * H + 4) * ZOOM - 14), 'linear light: gamma="srgb"', fill=(255, 160, 0))
    img.save(path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "opacity.png")

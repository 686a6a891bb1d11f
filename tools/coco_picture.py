"""docs/coco_rules.png: pycocotools' polygon rule against rastrum's exact
rule, pixel by pixel, on one COCO-style polygon.

    python tools/coco_picture.py [out.png]

Grey: both rules fill the pixel; red: only pycocotools' rule; blue: only
the exact rule (pixel centres).  The polygon is drawn over the pixels, a
dot at each pixel centre.  Prints the counts.
"""
import sys

import numpy as np
from PIL import Image, ImageDraw

from rastrum import coco

SEGM = [[2.3, 1.4, 9.8, 0.6, 17.6, 3.9, 21.2, 9.7, 16.1, 15.3, 10.4, 13.1, 6.2, 16.4, 1.1, 10.8, 4.4, 6.9],
        [12.2, 9.1, 22.7, 14.2, 21.9, 15.1, 11.4, 10.3], [3.6, 12.6, 8.9, 17.7, 2.2, 17.2]]
H, W, S = 18, 23, 24  # mask size, pixels per mask pixel in the picture


def main(path):
    coco_m = coco.decode(coco.merge(coco.frPyObjects(SEGM, H, W))).astype(bool)
    exact_m = coco.decode(coco.merge(coco.frPyObjects(SEGM, H, W, rule="exact"))).astype(bool)
    img = Image.new("RGB", (W * S, H * S), (255, 255, 255))
    d = ImageDraw.Draw(img)
    for y in range(H):
        for x in range(W):
            c = (255, 255, 255)
            if coco_m[y, x] and exact_m[y, x]:
                c = (190, 190, 190)
            elif coco_m[y, x]:
                c = (230, 70, 60)
            elif exact_m[y, x]:
                c = (60, 110, 230)
            d.rectangle([x * S, y * S, (x + 1) * S - 1, (y + 1) * S - 1], fill=c, outline=(225, 225, 225))
            d.ellipse([x * S + S // 2 - 1, y * S + S // 2 - 1, x * S + S // 2 + 1, y * S + S // 2 + 1],
                      fill=(90, 90, 90))
    for part in SEGM:
        pts = [(x * S, y * S) for x, y in np.array(part).reshape(-1, 2)]
        d.line(pts + pts[:1], fill=(0, 0, 0), width=2)
    img.save(path)
    print("both %d, pycocotools only %d, exact only %d" % (
        (coco_m & exact_m).sum(), (coco_m & ~exact_m).sum(), (exact_m & ~coco_m).sum()))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/coco_rules.png")

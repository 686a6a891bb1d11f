"""Polygon algorithms on real shapes, no downloads: which default?

    python bench/bench_realdata.py [--rounds N]

Scenes (each skipped when its source is not installed):

- glyphs: the printable ASCII letters of DejaVu Sans (Debian's
  fonts-dejavu-core) at 64 px, outlines flattened by freetype-py
  (quadratic curves in 8 steps), one mask per glyph;
- contours: the outlines cv2.findContours finds in scikit-image's bundled
  photographs (camera, coins, horse, text), thresholded at their mean, all
  of one image's contours as one even-odd polygon;
- countries: Natural Earth's 1:110m countries (177 features), which
  pyogrio's wheel ships as a test fixture: all of them as one world mask
  of 2048x1024 (even-odd), and each country in its own box at 10 px per
  degree (one mask per country, as a GIS burns features one by one);
- the benchmark's synthetic scenes (bench/scenes.py): circle64, star200,
  holes, coco100.

Prints each algorithm's median time as a ratio to aet's, even-odd, S = 8,
pixel centres (< 1: faster than aet).  Every algorithm gives the same
pixels (checked here against aet on every scene).
"""

import argparse
import os
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import scenes  # noqa: E402

import rastrum  # noqa: E402

FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def glyph_scene(size=64):
    import freetype
    face = freetype.Face(FONT)
    face.set_pixel_sizes(0, size)
    polys = []
    for ch in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789&@%$#":
        face.load_char(ch, freetype.FT_LOAD_NO_BITMAP)
        o = face.glyph.outline
        pts = np.array(o.points, float) / 64.0
        tags = o.tags
        rings, start = [], 0
        for end in o.contours:
            ring = []
            idx = list(range(start, end + 1))
            for k, i in enumerate(idx):
                on = tags[i] & 1
                if on:
                    ring.append(pts[i])
                else:  # quadratic control point: flatten with implied on-points
                    prev = pts[idx[k - 1]] if tags[idx[k - 1]] & 1 else (pts[idx[k - 1]] + pts[i]) / 2
                    nxt = pts[idx[(k + 1) % len(idx)]]
                    if not tags[idx[(k + 1) % len(idx)]] & 1:
                        nxt = (nxt + pts[i]) / 2
                    for t in np.linspace(0, 1, 9)[1:-1]:
                        ring.append((1 - t) ** 2 * prev + 2 * (1 - t) * t * pts[i] + t * t * nxt)
            start = end + 1
            if len(ring) >= 3:
                r = np.array(ring)
                r[:, 1] = size - r[:, 1] + 8  # y down, baseline inside
                rings.append(r + (4.0, 0.0))
        if rings:
            polys.append(rings)
    return polys, (size + 24, size + 16)


def contour_scene(name):
    import cv2
    from skimage import data
    img = getattr(data, name)()
    if img.ndim == 3:
        img = img.mean(axis=2)
    bw = (img > img.mean()).astype(np.uint8)
    cs, _ = cv2.findContours(bw, cv2.RETR_LIST, cv2.CHAIN_APPROX_SIMPLE)
    rings = [c.reshape(-1, 2).astype(float) + 0.25 for c in cs if len(c) >= 3]
    return [rings], img.shape[:2]


def _wkb_rings(b):
    """The rings of a WKB Polygon or MultiPolygon (2-D), as (N, 2) arrays."""
    import struct
    pos = 0

    def polygon(pos, e):
        (nr,) = struct.unpack_from(e + "I", b, pos)
        pos += 4
        rings = []
        for _ in range(nr):
            (n,) = struct.unpack_from(e + "I", b, pos)
            pos += 4
            rings.append(np.frombuffer(b, e.replace("<", "<f8").replace(">", ">f8"), 2 * n, pos).reshape(n, 2)
                         .astype(float))
            pos += 16 * n
        return rings, pos
    e = "<" if b[0] == 1 else ">"
    (kind,) = struct.unpack_from(e + "I", b, 1)
    pos = 5
    if kind == 3:
        return polygon(pos, e)[0]
    (np_,) = struct.unpack_from(e + "I", b, pos)
    pos += 4
    out = []
    for _ in range(np_):
        e2 = "<" if b[pos] == 1 else ">"
        rings, pos = polygon(pos + 5, e2)
        out += rings
    return out


def country_scenes():
    import pyogrio
    import pyogrio.raw
    path = os.path.join(os.path.dirname(pyogrio.__file__), "tests", "fixtures", "naturalearth_lowres",
                        "naturalearth_lowres.shp")
    meta, fids, geoms, fields = pyogrio.raw.read(path)
    countries = [[r[:-1] for r in _wkb_rings(bytes(g)) if len(r) > 3] for g in geoms]
    world = [np.stack([(r[:, 0] + 180) * 2048 / 360, (90 - r[:, 1]) * 1024 / 180], 1)
             for c in countries for r in c]
    own = []
    for c in countries:
        allp = np.concatenate(c)
        x0, y1 = allp[:, 0].min(), allp[:, 1].max()
        own.append([np.stack([(r[:, 0] - x0) * 10 + 0.5, (y1 - r[:, 1]) * 10 + 0.5], 1) for r in c])
    shapes = [(int(np.ceil(max(r[:, 1].max() for r in c))) + 2, int(np.ceil(max(r[:, 0].max() for r in c))) + 2)
              for c in own]
    return {"countries world": ([world], (1024, 2048)), "countries each": (own, shapes)}


def load_scenes():
    out = {}
    try:
        out.update(country_scenes())
    except Exception as e:
        print("skipped countries: %s" % e)
    try:
        out["DejaVu glyphs"] = glyph_scene()
    except Exception as e:
        print("skipped glyphs: %s" % e)
    for name in ("camera", "coins", "horse", "text"):
        try:
            out["contours " + name] = contour_scene(name)
        except Exception as e:
            print("skipped contours %s: %s" % (name, e))
            break
    for s in scenes.get(("circle64", "star200", "holes", "coco100")):
        out[s.name] = s.load()
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=15)
    args = ap.parse_args(argv)
    algos = [a for a, rules in rastrum.ALGORITHMS["polygon_mask"].items()
             if a not in ("crossing", "winding")]
    table = {}
    for name, (polys, shape) in load_scenes().items():
        shapes = shape if isinstance(shape, list) else [shape] * len(polys)
        ref = [rastrum.polygon_mask(r, sh, algorithm="aet") for r, sh in zip(polys, shapes)]
        for a in algos:
            assert all(np.array_equal(rastrum.polygon_mask(r, sh, algorithm=a), m)
                       for r, sh, m in zip(polys, shapes, ref)), a
        times = {a: [] for a in algos}
        work = list(zip(polys, shapes))
        for _ in range(args.rounds):
            for a in algos:
                t0 = time.perf_counter()
                for r, sh in work:
                    rastrum.polygon_mask(r, sh, algorithm=a)
                times[a].append(time.perf_counter() - t0)
        if isinstance(shape, list):
            shape = (max(h for h, w in shape), max(w for h, w in shape))
        med = {a: statistics.median(t) for a, t in times.items()}
        nv = sum(len(x) for r in polys for x in r)
        table[name] = (len(polys), nv, shape, med)
    print("even-odd, S = 8, pixel centres; time as a ratio to aet's (< 1: faster), medians of %d rounds"
          % args.rounds)
    print("%-18s %6s %7s %11s %9s " % ("scene", "masks", "verts", "shape", "aet ms") +
          " ".join("%9s" % a for a in algos if a != "aet"))
    for name, (n, nv, shape, med) in table.items():
        print("%-18s %6d %7d %11s %9.3f " % (name, n, nv, "%dx%d" % shape, med["aet"] * 1e3) +
              " ".join("%9.2f" % (med[a] / med["aet"]) for a in algos if a != "aet"))
    return table


if __name__ == "__main__":
    main()

"""rastrum.rasterize against rasterio.features.rasterize, side by side.

    python bench/bench_rasterize.py [--repeat 5] [--quick]

Three scenes (issue 13), each burnt by both libraries in the same run, the
median of --repeat timings each (wall clock, and the process's CPU time,
which a loaded shared machine disturbs less), and each output checked:

* "small": 20,000 small polygons (shapely, 4-12 vertices, 2-12 px across,
  a value each) into a 4096 x 4096 uint16 raster under a north-up
  transform (target: rastrum at most 0.1x rasterio's time);
* "holes": 100 large polygons with 3 holes each (64-vertex rings, up to
  700 px across) into 4096 x 4096 uint16 (target: faster than rasterio);
* "coast": one 100,000-vertex polygon (a noisy closed coastline) into
  4096 x 4096 uint8 (target: faster than rasterio);
* "lines", "points": 5,000 random 5-vertex lines and 100,000 points into
  4096 x 4096 uint16 (GDAL's own rules: checked equal to rasterio's).

Check: rastrum's raster must equal the exact rule on the float64 pixel
coordinates (the oracle of tests/oracle.py, unsnapped, burnt in order)
for the pixels it decides -- the whole raster for "holes" and "coast"
(one polygon per value), and a sample of 500 polygons for "small" -- and
the number of pixels where rasterio differs is printed beside it.
"""

import argparse
import os
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))

import rastrum  # noqa: E402

try:
    import shapely
    from affine import Affine
except ImportError:  # pragma: no cover
    sys.exit("bench_rasterize needs shapely and affine: pip install 'rastrum[gis]'")
try:
    from rasterio.features import rasterize as rio_rasterize
    from rasterio.enums import MergeAlg
except ImportError:  # pragma: no cover
    rio_rasterize = None

N = 4096
TRANSFORM = Affine(10.0, 0.0, 500000.0, 0.0, -10.0, 4200000.0)  # 10 m pixels, north up


def _ring(rng, cx, cy, r, n, noise=0.35):
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    rad = r * (1 - noise + noise * rng.uniform(0, 1, n))
    pts = np.c_[cx + rad * np.cos(ang), cy + rad * np.sin(ang)]
    return np.vstack([pts, pts[:1]])


def _world(pix):
    """Pixel (col, row) -> world under TRANSFORM."""
    a, b, c, d, e, f = TRANSFORM[:6]
    return np.c_[a * pix[:, 0] + b * pix[:, 1] + c, d * pix[:, 0] + e * pix[:, 1] + f]


def scene_small(rng, n=20000):
    polys = []
    for _ in range(n):
        cx, cy = rng.uniform(8, N - 8, 2)
        polys.append(shapely.Polygon(_world(_ring(rng, cx, cy, rng.uniform(1, 6), int(rng.integers(4, 13))))))
    values = rng.integers(1, 60000, n)
    return list(zip(polys, values.tolist())), "uint16"


def scene_holes(rng, n=100):
    polys = []
    for _ in range(n):
        cx, cy = rng.uniform(400, N - 400, 2)
        r = rng.uniform(100, 350)
        outer = _ring(rng, cx, cy, r, 64, 0.2)
        holes = [_ring(rng, cx + dx * r, cy + dy * r, r * 0.15, 64, 0.2)[::-1]
                 for dx, dy in ((-0.4, 0.0), (0.4, 0.0), (0.0, 0.45))]
        polys.append(shapely.Polygon(_world(outer), [_world(h) for h in holes]))
    return [(p, k + 1) for k, p in enumerate(polys)], "uint16"


def scene_coast(rng, n=100000):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = 1500 + 300 * np.sin(7 * t) + 80 * np.sin(53 * t) + np.cumsum(rng.normal(0, 3, n)) * 0
    r = r + rng.uniform(-12, 12, n)
    pix = np.c_[N / 2 + r * np.cos(t), N / 2 + r * np.sin(t)]
    pix = np.vstack([pix, pix[:1]])
    return [(shapely.Polygon(_world(pix)), 1)], "uint8"


def scene_lines(rng, n=5000):
    lines = [shapely.LineString(_world(rng.uniform(0, N, (5, 2)))) for _ in range(n)]
    return list(zip(lines, rng.integers(1, 60000, n).tolist())), "uint16"


def scene_points(rng, n=100000):
    pts = shapely.points(_world(rng.uniform(0, N, (n, 2))))
    return list(zip(pts, rng.integers(1, 60000, n).tolist())), "uint16"


def timed(fn, repeat):
    """(median wall seconds, median CPU seconds of this process, result).
    CPU time leaves out the time the shared machine gives to others."""
    wall, cpu, out = [], [], None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return statistics.median(wall), statistics.median(cpu), out


def exact_reference(shapes, dtype, sample=None):
    """The exact rule on rastrum's float64 pixel coordinates, burnt in
    order (replace): tests/oracle.py with subpixel_bits=None."""
    from oracle import oracle_mask
    ref = np.zeros((N, N), dtype)
    idx = range(len(shapes)) if sample is None else sample
    for k in idx:
        geom, value = shapes[k]
        rings = [np.asarray(geom.exterior.coords)] + [np.asarray(i.coords) for i in geom.interiors]
        pix = [rastrum.gis.pixel_coordinates(r, TRANSFORM) for r in rings]
        lo = np.floor(np.min([p.min(axis=0) for p in pix], axis=0)).astype(int)
        hi = np.ceil(np.max([p.max(axis=0) for p in pix], axis=0)).astype(int) + 1
        lo = np.maximum(lo, 0)
        hi = np.minimum(hi, N)
        # Subtracting the whole pixels lo (0 <= lo <= the coordinates, or
        # lo = 0) is exact in float64, and the rule is translation-exact.
        m = oracle_mask([p - lo for p in pix], (hi[1] - lo[1], hi[0] - lo[0]), subpixel_bits=None)
        ref[lo[1]:hi[1], lo[0]:hi[0]][m] = value
    return ref


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="a tenth of the small polygons, one timing")
    ap.add_argument("--no-check", action="store_true")
    args = ap.parse_args()
    rng = np.random.default_rng(13)
    scenes = [("small", scene_small(rng, 2000 if args.quick else 20000)),
              ("holes", scene_holes(rng)),
              ("coast", scene_coast(rng)),
              ("lines", scene_lines(rng, 500 if args.quick else 5000)),
              ("points", scene_points(rng, 10000 if args.quick else 100000))]
    repeat = 1 if args.quick else args.repeat
    print("rastrum.rasterize vs rasterio.features.rasterize, %dx%d, median of %d" % (N, N, repeat))
    print("%-6s %8s %16s %16s %12s %14s %14s" % ("scene", "shapes", "rastrum s", "rasterio s",
                                                 "ratio", "rastrum off", "rasterio off"))
    print("%-6s %8s %16s %16s %12s" % ("", "", "wall / cpu", "wall / cpu", "wall / cpu"))
    for name, (shapes, dtype) in scenes:
        t_r, c_r, a = timed(lambda: rastrum.rasterize(shapes, (N, N), transform=TRANSFORM, dtype=dtype), repeat)
        if rio_rasterize is not None:
            t_g, c_g, b = timed(lambda: rio_rasterize(shapes, (N, N), transform=TRANSFORM, dtype=dtype), repeat)
        else:
            t_g = c_g = float("nan")
            b = None
        off_r = off_g = "-"
        if not args.no_check:
            if name in ("lines", "points"):
                pass  # GDAL's rule itself: the check is rastrum == rasterio (below)
            elif name == "small":
                # A sample of polygons, each alone: the exact rule against
                # each library's raster of the same polygon alone.
                sample = rng.choice(len(shapes), 300 if not args.quick else 50, replace=False)
                off_r = off_g = 0
                for k in sample.tolist():
                    ref = exact_reference(shapes, dtype, [k])
                    one = [shapes[k]]
                    off_r += int((rastrum.rasterize(one, (N, N), transform=TRANSFORM, dtype=dtype) != ref).sum())
                    if b is not None:
                        off_g += int((rio_rasterize(one, (N, N), transform=TRANSFORM, dtype=dtype) != ref).sum())
                off_r, off_g = "%d (%d)" % (off_r, len(sample)), "%d (%d)" % (off_g, len(sample))
            else:
                ref = exact_reference(shapes, dtype)
                off_r = str(int((a != ref).sum()))
                off_g = str(int((b != ref).sum())) if b is not None else "-"
        same = "" if b is None else "  rastrum==rasterio on %.6f%% of pixels" % (100.0 * (a == b).mean())
        print("%-6s %8d %7.4f /%7.4f %7.4f /%7.4f %5.3f /%5.3f %14s %14s%s"
              % (name, len(shapes), t_r, c_r, t_g, c_g, t_r / t_g, c_r / c_g, off_r, off_g, same))


if __name__ == "__main__":
    main()

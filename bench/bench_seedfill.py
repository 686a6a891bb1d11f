"""Region (seed) fill speed: rastrum against cv2.floodFill and
skimage.segmentation.flood_fill (each skipped when not installed), and a
memset (numpy fill) of the same buffer, the physical limit of a fill.

    python bench/bench_seedfill.py [--rounds N] [--quick]

Scenes (gray8, seed at a 0 pixel, the fill writes 1 over its region):
- region4000: a 4000 x 4000 image that is one region;
- comb4000:   the same with walls from the top and bottom edges every
              4 px (one long folded corridor region);
- noise p:    2000 x 2000 random noise, walls with probability p, the
              seed in the largest region of 0s (of the connectivity)
              found on the middle row (p = 0.2: one giant region for both
              connectivities; 0.35: near the 4-connected percolation
              threshold, a fractal one; 0.5: giant only 8-connected).
Each round times every filler once on a fresh copy (interleaved), for
both connectivities; the table gives medians in ms and rastrum's time as
a ratio to memset and to each peer (< 1: rastrum faster).  Every peer's
result is checked equal to rastrum's.
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

rastrum = bench.import_rastrum()

try:
    import cv2
except ImportError:  # optional peer
    cv2 = None
try:
    from skimage.segmentation import flood_fill as sk_flood_fill
except ImportError:  # optional peer
    sk_flood_fill = None


def scenes(quick=False):
    side = 1000 if quick else 4000
    noise_side = 500 if quick else 2000
    out = []
    img = np.zeros((side, side), np.uint8)
    out.append(("region%d" % side, img, (side // 2, side // 2)))
    comb = np.zeros((side, side), np.uint8)
    comb[:side - 1, 1::4] = 2
    comb[1:, 3::4] = 2
    out.append(("comb%d" % side, comb, (0, 0)))
    rng = np.random.default_rng(1)
    for p in (0.2, 0.35, 0.5):
        img = (rng.random((noise_side, noise_side)) < p).astype(np.uint8) * 2
        out.append(("noise%d %.2f" % (noise_side, p), img, None))
    return out


def largest_seed(img, conn, tries=40):
    """A 0 pixel of the middle row whose `conn`-connected region is the
    largest of `tries` candidates (setup, not timed)."""
    row = img.shape[0] // 2
    xs = np.nonzero(img[row] == 0)[0][:: max(1, img.shape[1] // tries)]
    best, seed = -1, (int(xs[0]), row)
    for x in xs:
        a = img.copy()
        rastrum.Canvas.wrap(a).flood_fill((int(x), row), 1, connectivity=conn)
        n = int((a == 1).sum())
        if n > best:
            best, seed = n, (int(x), row)
    return seed


def fillers(conn):
    """name -> function(array, seed (x, y)) filling in place with 1."""
    out = {}

    def rast(a, seed):
        rastrum.Canvas.wrap(a).flood_fill(seed, 1, connectivity=conn)
    out["rastrum"] = rast
    if cv2 is not None:
        def ocv(a, seed):
            cv2.floodFill(a, None, seed, 1, flags=conn)
        out["cv2.floodFill"] = ocv
    if sk_flood_fill is not None:
        def sk(a, seed):
            sk_flood_fill(a, (seed[1], seed[0]), 1, connectivity=1 if conn == 4 else 2, in_place=True)
        out["skimage flood_fill"] = sk

    def memset(a, seed):
        a.fill(1)
    out["memset"] = memset
    return out


def measure(rounds, quick=False):
    rows = []
    for name, img, fixed_seed in scenes(quick):
        for conn in (4, 8):
            seed = fixed_seed or largest_seed(img, conn)
            fs = fillers(conn)
            times = {k: [] for k in fs}
            results = {}
            for _ in range(rounds):
                for k, f in fs.items():
                    a = img.copy()
                    t = time.perf_counter()
                    f(a, seed)
                    times[k].append(time.perf_counter() - t)
                    results[k] = a
            for k in fs:
                if k != "memset":
                    assert np.array_equal(results[k], results["rastrum"]), (name, conn, k)
            med = {k: statistics.median(v) * 1e3 for k, v in times.items()}
            rows.append((name, conn, med, int((results["rastrum"] == 1).sum())))
    return rows


def table(rows):
    peers = [k for k in ("cv2.floodFill", "skimage flood_fill") if k in rows[0][2]]
    head = ["scene", "conn", "pixels filled", "memset ms", "rastrum ms", "x memset"]
    for p in peers:
        head += [p + " ms", "rastrum / " + p.split()[0].split(".")[0]]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for name, conn, med, n in rows:
        cells = [name, str(conn), str(n), "%.2f" % med["memset"], "%.2f" % med["rastrum"],
                 "%.2f" % (med["rastrum"] / med["memset"])]
        for p in peers:
            cells += ["%.2f" % med[p], "%.2f" % (med["rastrum"] / med[p])]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--quick", action="store_true", help="smaller scenes, 3 rounds")
    args = ap.parse_args(argv)
    rounds = 3 if args.quick else args.rounds
    missing = [n for n, m in (("opencv", cv2), ("scikit-image", sk_flood_fill)) if m is None]
    if missing:
        print("(not installed, skipped: %s)" % ", ".join(missing))
    print(table(measure(rounds, args.quick)))


if __name__ == "__main__":
    main()

"""The accuracy picture of docs/gis.md: how far rastrum's coverage fractions
are from the exact cell-by-polygon area, per snapping precision S, beside
exactextract's.

    python bench/gis_accuracy.py [--plot docs/gis_accuracy.png] [--every 3] [--res 0.025]

Data and referee are bench/bench_gis_precision.py's: Natural Earth 1:110m
countries on a global grid (--res degrees), shapely's cell & polygon areas
in float64 world coordinates as the referee.  For every --every-th country
(all by default), every tile of its window: rastrum.polygon_coverage with
subpixel_bits S for S in 8, 10, ..., 32 (S > 16, or coordinates past the
32-bit path's range, take the 64-bit path by itself) and exactextract's
"coverage" on the same tile.  Printed and plotted: the largest
|fraction - referee| over all cells, per S, against the bound 2^-S a cell
per edge that snapping allows, and exactextract's, on the boundary cells
and on all cells (it drops a few fully covered interior cells: coverage 0
where the referee says 1).  Deterministic (no timing).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bench_gis_precision as gp  # noqa: E402  (exits with a message without shapely/geopandas)

import rastrum  # noqa: E402

BITS = (8, 10, 12, 14, 16, 20, 24, 28, 32)


def measure(res, every, tile):
    df = gp.world().iloc[::every]
    crs_wkt = gp.pyproj.CRS("EPSG:4326").to_wkt() if gp.exactextract is not None else None
    worst = {s: 0.0 for s in BITS}
    worst_ee = [0.0, 0.0, 0]  # all cells, boundary cells, cells off by more than 1/2
    bcells = 0
    for g in df.geometry:
        rings = gp.rings_px(g, res)
        for r, c, h, w, _ in gp.tiles_of(g, res, tile):
            exact, edge = gp.referee(g, res, r, c, h, w)
            bcells += int(edge.sum())
            local = [x - np.array([c, r], np.float64) for x in rings]
            for s in BITS:
                a = rastrum.polygon_coverage(local, (h, w), method="area", subpixel_bits=s, dtype=np.float64)
                worst[s] = max(worst[s], float(np.abs(a - exact).max()))
            if crs_wkt is not None:
                d = np.abs(gp.run_ee(g, res, r, c, h, w, crs_wkt) - exact)
                worst_ee[0] = max(worst_ee[0], float(d.max()))
                if edge.any():
                    worst_ee[1] = max(worst_ee[1], float(d[edge].max()))
                worst_ee[2] += int((d > 0.5).sum())
    return len(df), bcells, worst, (worst_ee if crs_wkt is not None else None)


def plot(path, worst, worst_ee, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=100)
    s = np.array(BITS)
    ax.semilogy(s, [worst[b] for b in BITS], "o-", label="rastrum \"area\", vertices snapped to 2^-S px")
    ax.semilogy(s, 2.0 ** -s, "--", color="0.5", label="2^-S (one snapping step)")
    if worst_ee is not None:
        ax.axhline(worst_ee[1], color="C3", lw=1.2, label="exactextract, on the boundary cells")
        if worst_ee[2]:
            ax.axhline(worst_ee[0], color="C3", lw=1.2, ls=":",
                       label="exactextract, all cells (%d off by > 1/2)" % worst_ee[2])
    ax.axvline(16.5, color="0.8", lw=0.8)
    ax.text(16.7, 2.0 ** -31, "S > 16: the 64-bit path", fontsize=8, color="0.4")
    ax.set_xlabel("snapping precision S (subpixel_bits)")
    ax.set_ylabel("max |fraction - exact| over all cells")
    ax.set_title(title, fontsize=9)
    ax.set_xticks(s)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--res", type=float, default=0.025, help="cell size in degrees")
    ap.add_argument("--every", type=int, default=1, help="every k-th country (1: all)")
    ap.add_argument("--tile", type=int, default=1024)
    ap.add_argument("--plot", default=None, help="draw the picture here (PNG; needs matplotlib)")
    args = ap.parse_args(argv)
    n, bcells, worst, worst_ee = measure(args.res, args.every, args.tile)
    print("%d countries at %.4f deg, %d boundary cells; max |fraction - referee|:" % (n, args.res, bcells))
    print("| S | rastrum | 2^-S |")
    print("|---|---|---|")
    for s in BITS:
        print("| %d | %.2g | %.2g |" % (s, worst[s], 2.0 ** -s))
    if worst_ee is not None:
        print("| exactextract %s, boundary cells | %.2g | - |" % (gp.exactextract.__version__, worst_ee[1]))
        print("| exactextract %s, all cells | %.2g (cells off by more than 1/2: %d) | - |"
              % (gp.exactextract.__version__, worst_ee[0], worst_ee[2]))
    if args.plot:
        plot(args.plot, worst, worst_ee, "Natural Earth 1:110m, %d countries, %.3g deg grid, %d boundary cells"
             % (n, args.res, bcells))
        print("wrote %s" % args.plot)
    return worst, worst_ee


if __name__ == "__main__":
    main()

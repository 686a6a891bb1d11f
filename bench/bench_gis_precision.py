"""Coverage fractions at GIS scale: rastrum's 64-bit "area" path against the
exact cell-by-polygon area and against exactextract, side by side.

    python bench/bench_gis_precision.py [--fine-tiles 40] [--tile 1024] [--repeat 3]

Data: Natural Earth 1:110m countries (pyogrio's test fixture,
naturalearth_lowres), EPSG:4326, on a global grid anchored at (-180, 90):

* coarse: 0.025 degree (14400 x 7200 cells), every country, its whole
  window (bounding box) in tiles of --tile cells a side;
* fine: 0.0025 degree (144000 x 72000 cells; Russia's window is 2^17
  columns wide), the tiles of every country that hold part of its boundary,
  --fine-tiles of them per country at most (evenly spaced over the list,
  deterministic), since the referee costs ~20 us a boundary cell.

For each tile: rastrum.polygon_coverage(rings - tile origin, tile shape,
subpixel_bits=32, dtype=float64), which takes the 64-bit path by itself
(S = 32 > 16, and coordinates far outside the tile), dense; and
rastrum.coverage_fractions([geometry], tile shape, the tile's transform),
sparse (cell_id + coverage, as exactextract gives them); exactextract 0.3's
"cell_id" + "coverage" on the same tile and geometry; the referee, shapely
(GEOS) in float64 world coordinates: 1 for cells the polygon contains, 0 for
cells it does not meet, area(cell & polygon) / area(cell) for cells its
boundary meets.  Printed: the largest |fraction - referee| of each library,
the number of cells above 1e-8, and the time of each (median of --repeat,
in this process; CPU time, the machine is shared) with rastrum / exactextract.

Caveat, measured not assumed: the referee itself is float64 (GEOS's
intersection and area carry ~1e-16 relative error of a cell's world area, and
the pixel coordinates of the vertices are (x + 180) / res, one rounding), so
differences below ~1e-12 are the referee's, not either library's.
"""

import argparse
import math
import os
import statistics
import sys
import time

import numpy as np

import rastrum

try:
    import shapely
    import geopandas as gpd
    import pyogrio
except ImportError:  # pragma: no cover
    sys.exit("bench_gis_precision needs shapely, geopandas and pyogrio (pip install 'rastrum[gis]')")
try:
    import exactextract
    from exactextract.raster import NumPyRasterSource
    import pyproj
except ImportError:  # pragma: no cover
    exactextract = None


def world():
    path = os.path.join(os.path.dirname(pyogrio.__file__), "tests", "fixtures", "naturalearth_lowres",
                        "naturalearth_lowres.shp")
    return gpd.read_file(path)


def rings_px(g, res):
    """The rings of polygon/multipolygon g in global pixel coordinates
    ((x + 180) / res, (90 - y) / res), float64."""
    polys = list(g.geoms) if g.geom_type == "MultiPolygon" else [g]
    out = []
    for p in polys:
        for r in [p.exterior, *p.interiors]:
            xy = np.asarray(r.coords)[:-1]
            out.append(np.column_stack([(xy[:, 0] + 180.0) / res, (90.0 - xy[:, 1]) / res]))
    return out


def _boxes(res, r0, c0, h, w):
    jj, ii = np.mgrid[r0:r0 + h, c0:c0 + w]
    return shapely.box(-180 + ii * res, 90 - (jj + 1) * res, -180 + (ii + 1) * res, 90 - jj * res)


def referee(g, res, r0, c0, h, w, block=32):
    """shapely's fractions of the tile's cells (float64, world coordinates):
    blocks of block x block cells that the boundary does not meet are all
    1 (the polygon contains the block) or all 0; in the others each cell is
    1, 0, or area(cell & polygon) / area(cell)."""
    exact = np.zeros((h, w))
    edge = np.zeros((h, w), bool)
    bd = g.boundary
    shapely.prepare(g)
    shapely.prepare(bd)
    for br in range(0, h, block):
        for bc in range(0, w, block):
            bh, bw = min(block, h - br), min(block, w - bc)
            r, c = r0 + br, c0 + bc
            blk = shapely.box(-180 + c * res, 90 - (r + bh) * res, -180 + (c + bw) * res, 90 - r * res)
            if not bd.intersects(blk):
                exact[br:br + bh, bc:bc + bw] = 1.0 if g.contains(blk) else 0.0
                continue
            boxes = _boxes(res, r, c, bh, bw)
            e = shapely.intersects(boxes, bd)
            ex = np.where(shapely.contains(g, boxes), 1.0, 0.0)
            if e.any():
                ex[e] = shapely.area(shapely.intersection(boxes[e], g)) / (res * res)
            exact[br:br + bh, bc:bc + bw] = ex
            edge[br:br + bh, bc:bc + bw] = e
    return exact, edge


def run_rastrum(rings, r0, c0, h, w):
    local = [r - np.array([c0, r0], np.float64) for r in rings]
    return rastrum.polygon_coverage(local, (h, w), method="area", subpixel_bits=32, dtype=np.float64)


def run_fractions(g, res, r0, c0, h, w):
    """rastrum.coverage_fractions on the tile (world coordinates, the
    tile's transform): exactextract's cell_id + coverage, sparse."""
    t = (res, 0.0, -180 + c0 * res, 0.0, -res, 90 - r0 * res)
    return rastrum.coverage_fractions([g], (h, w), t)[0]


def dense(cells_cov, h, w):
    cells, cov = cells_cov
    out = np.zeros(h * w)
    out[cells] = cov
    return out.reshape(h, w)


def run_ee(g, res, r0, c0, h, w, crs_wkt):
    src = NumPyRasterSource(np.zeros((h, w)), -180 + c0 * res, 90 - (r0 + h) * res, -180 + (c0 + w) * res,
                            90 - r0 * res, srs_wkt=crs_wkt)
    one = gpd.GeoDataFrame(geometry=[g], crs="EPSG:4326")
    out = exactextract.exact_extract(src, one, ["cell_id", "coverage"], output="pandas")
    cov = np.zeros(h * w)
    if len(out):
        ids = np.asarray(out["cell_id"][0], np.int64)
        cov[ids] = np.asarray(out["coverage"][0], np.float64)
    return cov.reshape(h, w)


def cpu(fn, repeat):
    ts, res = [], None
    for _ in range(repeat):
        t = time.process_time()
        res = fn()
        ts.append(time.process_time() - t)
    return statistics.median(ts), res


def tiles_of(g, res, tile):
    x0, y0, x1, y1 = g.bounds
    c0, r0 = int(math.floor((x0 + 180) / res)), int(math.floor((90 - y1) / res))
    c1, r1 = int(math.ceil((x1 + 180) / res)), int(math.ceil((90 - y0) / res))
    for r in range(r0, r1, tile):
        for c in range(c0, c1, tile):
            yield r, c, min(tile, r1 - r), min(tile, c1 - c), (c1 - c0, r1 - r0)


def grid(name, res, world_df, tile, repeat, max_tiles=None):
    crs_wkt = pyproj.CRS("EPSG:4326").to_wkt() if exactextract is not None else None
    worst = {"rastrum": 0.0, "ee": 0.0, "fr": 0.0}
    over = {"rastrum": 0, "ee": 0, "fr": 0}
    where = {"rastrum": None, "ee": None, "fr": None}
    t_r = t_e = t_f = 0.0
    cells = bcells = ntiles = 0
    widest = 0
    for cname, g in zip(world_df["name"], world_df.geometry):
        rings = rings_px(g, res)
        tl = list(tiles_of(g, res, tile))
        widest = max(widest, max(t[4][0] for t in tl))
        if max_tiles is not None:
            # tiles that hold boundary: a quick test on the tile's box
            def touches(t):
                r, c, h, w, _ = t
                box = shapely.box(-180 + c * res, 90 - (r + h) * res, -180 + (c + w) * res, 90 - r * res)
                return shapely.intersects(box, g.boundary)
            tl = [t for t in tl if touches(t)]
            if len(tl) > max_tiles:
                step = len(tl) / max_tiles
                tl = [tl[int(k * step)] for k in range(max_tiles)]
        for r, c, h, w, _ in tl:
            exact, edge = referee(g, res, r, c, h, w)
            tr, a = cpu(lambda: run_rastrum(rings, r, c, h, w), repeat)
            d = np.abs(a - exact)
            t_r += tr
            if d.max() > worst["rastrum"]:
                worst["rastrum"], where["rastrum"] = float(d.max()), (cname, r, c)
            over["rastrum"] += int((d > 1e-8).sum())
            tf, cc = cpu(lambda: run_fractions(g, res, r, c, h, w), repeat)
            d = np.abs(dense(cc, h, w) - exact)
            t_f += tf
            if d.max() > worst["fr"]:
                worst["fr"], where["fr"] = float(d.max()), (cname, r, c)
            over["fr"] += int((d > 1e-8).sum())
            if exactextract is not None:
                te, b = cpu(lambda: run_ee(g, res, r, c, h, w, crs_wkt), repeat)
                d = np.abs(b - exact)
                t_e += te
                if d.max() > worst["ee"]:
                    worst["ee"], where["ee"] = float(d.max()), (cname, r, c)
                over["ee"] += int((d > 1e-8).sum())
            cells += h * w
            bcells += int(edge.sum())
            ntiles += 1
    print("%s grid (%.4f deg): %d countries, %d tiles of <= %d cells a side, %d cells (%d on a boundary); "
          "widest window %d columns" % (name, res, len(world_df), ntiles, tile, cells, bcells, widest))
    print("  rastrum (64-bit area, S = 32): max |fraction - referee| = %.3g at %s; cells > 1e-8: %d; "
          "CPU %.3f s" % (worst["rastrum"], where["rastrum"], over["rastrum"], t_r))
    print("  rastrum.coverage_fractions (sparse): max |fraction - referee| = %.3g at %s; cells > 1e-8: %d; "
          "CPU %.3f s" % (worst["fr"], where["fr"], over["fr"], t_f))
    if exactextract is not None:
        print("  exactextract %s:              max |fraction - referee| = %.3g at %s; cells > 1e-8: %d; "
              "CPU %.3f s" % (exactextract.__version__, worst["ee"], where["ee"], over["ee"], t_e))
        print("  time ratio rastrum / exactextract: polygon_coverage %.3f, coverage_fractions %.3f"
              % (t_r / t_e, t_f / t_e))
    return worst, over, t_r, t_e, t_f


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tile", type=int, default=1024)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--fine-tiles", type=int, default=40)
    ap.add_argument("--only", choices=["coarse", "fine"], default=None)
    ap.add_argument("--countries", default=None, help="comma-separated names (default: every country)")
    a = ap.parse_args()
    w = world()
    if a.countries:
        w = w[w["name"].isin(a.countries.split(","))]
    if a.only != "fine":
        grid("coarse", 0.025, w, a.tile, a.repeat)
    if a.only != "coarse":
        grid("fine", 0.0025, w, a.tile, a.repeat, max_tiles=a.fine_tiles)


if __name__ == "__main__":
    main()

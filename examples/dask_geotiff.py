"""Rasterise a polygon layer on Dask and write a tiled GeoTIFF (or Zarr).

    python examples/dask_geotiff.py out.tif [--n 50000] [--size 8192] [--chunk 1024]
    python examples/dask_geotiff.py out.zarr           # Zarr instead (needs zarr)
    python examples/dask_geotiff.py out.tif --cluster  # on a LocalCluster, dashboard link printed

A synthetic layer (--n random polygons, a uint16 value each, in a
dask-geopandas GeoDataFrame) is burnt by rastrum.dask.rasterize into a
--size x --size raster, block by block.  The GeoTIFF is tiled and
compressed, its tiles the dask blocks, written with rasterio's windowed
writes as each block is computed: the whole raster is never in memory.
With xarray and rioxarray, rastrum.dask.to_xarray(array, transform,
crs=...) gives a DataArray with coordinates whose .rio.to_raster(path,
tiled=True, lock=...) writes the same file.
"""

import argparse
import sys
import threading

import dask.array as da
import numpy as np
import dask_geopandas
import geopandas as gpd
import rasterio
import shapely
from affine import Affine
from dask.diagnostics import ProgressBar
from rasterio.windows import Window

import rastrum.dask

CRS = "EPSG:32633"  # UTM 33N


def layer(n, size, transform, seed=1):
    """n random polygons over the raster, 4-8 vertices, 1-40 px across."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0, size, (n, 2))
    px = shapely.buffer(shapely.points(centres), rng.uniform(0.5, 20, n), quad_segs=2)
    geoms = shapely.transform(px, lambda xy: np.c_[transform.c + transform.a * xy[:, 0],
                                                    transform.f + transform.e * xy[:, 1]])
    gdf = gpd.GeoDataFrame({"v": rng.integers(1, 65536, n)}, geometry=geoms, crs=CRS)
    return dask_geopandas.from_geopandas(gdf, npartitions=8)


class _Windows:
    """A da.store target: each block into its window of the open file."""

    def __init__(self, dst):
        self.dst = dst

    def __setitem__(self, index, block):
        rows, cols = index
        self.dst.write(block, 1, window=Window.from_slices(rows, cols))


def write_geotiff(array, path, transform, client=None):
    """Each block into its window of a tiled GeoTIFF as it is computed
    (local schedulers: da.store with a lock; a cluster: the blocks as they
    complete, written by the client)."""
    rows, cols = array.chunks
    profile = dict(driver="GTiff", height=array.shape[0], width=array.shape[1], count=1, dtype=array.dtype.name,
                   crs=CRS, transform=transform, tiled=True, blockxsize=cols[0], blockysize=rows[0],
                   compress="deflate")
    with rasterio.open(path, "w", **profile) as dst:
        if client is None:
            da.store(array, _Windows(dst), lock=threading.Lock())
            return
        from distributed import as_completed

        edges = [np.cumsum((0,) + c) for c in array.chunks]
        futures = {}
        for (i, j), block in np.ndenumerate(array.to_delayed()):
            futures[client.compute(block)] = (slice(edges[0][i], edges[0][i + 1]), slice(edges[1][j], edges[1][j + 1]))
        for future in as_completed(futures):
            _Windows(dst)[futures.pop(future)] = future.result()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("path", help="out.tif (GeoTIFF) or out.zarr (Zarr)")
    ap.add_argument("--n", type=int, default=50_000)
    ap.add_argument("--size", type=int, default=8192)
    ap.add_argument("--chunk", type=int, default=1024, help="a multiple of 16 (GeoTIFF tiles)")
    ap.add_argument("--cluster", action="store_true", help="compute on a LocalCluster")
    args = ap.parse_args()
    transform = Affine(10.0, 0.0, 500000.0, 0.0, -10.0, 4600000.0)
    ddf = layer(args.n, args.size, transform)
    a = rastrum.dask.rasterize(ddf, (args.size, args.size), transform=transform, chunks=args.chunk,
                               values="v", dtype="uint16")
    client = None
    if args.cluster:
        from distributed import Client, LocalCluster

        client = Client(LocalCluster(n_workers=2, threads_per_worker=1))
        print("dashboard:", client.dashboard_link)  # every block's task, as it runs
    try:
        with ProgressBar():  # the local schedulers' bar
            if args.path.endswith(".zarr"):
                a.to_zarr(args.path, overwrite=True)
            else:
                write_geotiff(a, args.path, transform, client)
    finally:
        if client is not None:
            client.close()
    print("wrote", args.path, a.shape, a.dtype)


if __name__ == "__main__":
    sys.exit(main())

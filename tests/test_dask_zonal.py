"""rastrum.dask.zonal_stats: the single-machine table bit for bit for every
chunking (tile invariance), DataArrays with rioxarray's transform and
nodata, bands, weights, masked blocks, and blocks no feature touches never
read.  The single-machine statistics themselves are tested against exact
references in test_zonal.py."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_zonal import features, world

da = pytest.importorskip("dask.array")
pd = pytest.importorskip("pandas")
import rastrum.dask  # noqa: E402

STATS = ["count", "sum", "mean", "min", "max", "majority", "minority", "variety", "median",
         "quantile(q=0.3)", "stdev", "variance", "coefficient_of_variation", "weighted_mean",
         "weighted_sum", "weighted_stdev"]
T = (0.5, 0.0, 10.0, 0.0, -0.25, 20.0)


def chunking(draw, n):
    """Random irregular chunks of n (sizes summing to n)."""
    sizes, left = [], n
    while left:
        k = draw(st.integers(1, left))
        sizes.append(k)
        left -= k
    return tuple(sizes)


def same(a, b):
    """Two tables equal bit for bit (NaN equal to NaN)."""
    assert list(a.columns) == list(b.columns) and list(a.index) == list(b.index)
    for col in a.columns:
        x, y = a[col].to_numpy(np.float64), b[col].to_numpy(np.float64)
        assert np.array_equal(x.view(np.int64), y.view(np.int64)) or \
            np.array_equal(x, y, equal_nan=True) and np.array_equal(np.signbit(x), np.signbit(y)), col


@settings(max_examples=S_.examples(20))
@given(st.integers(2, 9), st.integers(2, 9), st.data())
def test_tile_invariance(h, w, data):
    """Every chunking (1-cell blocks up to one block, irregular) gives the
    table rastrum.zonal_stats gives on the whole numpy array, bit for bit."""
    rng = np.random.default_rng(data.draw(st.integers(0, 2 ** 32 - 1)))
    raster = rng.integers(0, 6, (h, w)).astype(np.float32) * np.float32(1.1)
    raster[rng.random((h, w)) < 0.1] = -1
    weights = rng.random((h, w))
    geoms = [world(data.draw(features(h, w)), T) for _ in range(data.draw(st.integers(1, 4)))]
    want = rastrum.zonal_stats(raster, geoms, transform=T, stats=STATS, weights=weights, nodata=-1)
    chunks = (chunking(data.draw, h), chunking(data.draw, w))
    wchunks = (chunking(data.draw, h), chunking(data.draw, w))
    got = rastrum.dask.zonal_stats(da.from_array(raster, chunks=chunks), geoms, transform=T, stats=STATS,
                                   weights=da.from_array(weights, chunks=wchunks), nodata=-1)
    same(got, want)


def test_bands_and_band_chunks():
    rng = np.random.default_rng(3)
    raster = rng.normal(5, 2, (3, 12, 10))
    geoms = [world(g, T) for g in (
        {"type": "Polygon", "coordinates": [[(1.2, 1.5), (8.5, 2.2), (6.1, 10.7), (1.2, 1.5)]]},
        {"type": "Polygon", "coordinates": [[(-3, -3), (4.5, -1), (2.2, 5.5), (-3, -3)]]},
    )]
    want = rastrum.zonal_stats(raster, geoms, transform=T, stats=["mean", "stdev", "median", "max"])
    for chunks in ((1, 5, 3), (2, 12, 10), (3, (7, 5), (1, 9))):
        got = rastrum.dask.zonal_stats(da.from_array(raster, chunks=chunks), geoms, transform=T,
                                       stats=["mean", "stdev", "median", "max"])
        assert list(got.columns)[:2] == ["band_1_mean", "band_1_stdev"]
        same(got, want)


def test_dataarray_rioxarray_transform_and_nodata():
    xr = pytest.importorskip("xarray")
    pytest.importorskip("rioxarray")
    rng = np.random.default_rng(4)
    raster = rng.integers(0, 9, (16, 20)).astype(np.int16)
    raster[2:5, 3:9] = -99
    arr = rastrum.dask.to_xarray(da.from_array(raster, chunks=(5, 6)), T)
    arr = arr.rio.write_nodata(-99)
    assert isinstance(arr, xr.DataArray) and isinstance(arr.data, da.Array)
    geoms = [world({"type": "Polygon", "coordinates": [[(0.5, 0.5), (15.2, 1.5), (9.3, 14.1), (0.5, 0.5)]]}, T)]
    got = rastrum.dask.zonal_stats(arr, geoms, stats="count mean majority")
    want = rastrum.zonal_stats(raster, geoms, transform=T, nodata=-99, stats="count mean majority")
    same(got, want)
    assert got["count"][0] < rastrum.zonal_stats(raster, geoms, transform=T, stats="count")["count"][0]


def test_untouched_blocks_are_not_read():
    """Blocks no feature covers are never computed (they would raise)."""
    def block(b, block_info=None):
        (r0, _), (c0, _) = block_info[None]["array-location"]
        if r0 >= 8 or c0 >= 8:
            raise AssertionError("block at (%d, %d) read" % (r0, c0))
        return np.full(b.shape, 2.0)

    raster = da.zeros((64, 64), chunks=8).map_blocks(block, dtype=np.float64)
    sq = {"type": "Polygon", "coordinates": [[(1.5, 1.5), (6.5, 1.5), (6.5, 6.5), (1.5, 6.5), (1.5, 1.5)]]}
    got = rastrum.dask.zonal_stats(raster, [sq], stats=["count", "sum"], output="records")
    assert got == [{"count": 25.0, "sum": 50.0}]


def test_masked_blocks():
    rng = np.random.default_rng(8)
    raster = np.ma.masked_less(rng.normal(0, 1, (10, 10)), -0.5)
    geoms = [{"type": "Polygon", "coordinates": [[(0.3, 0.3), (9.6, 0.9), (5.2, 9.1), (0.3, 0.3)]]}]
    want = rastrum.zonal_stats(raster, geoms, stats="count mean")
    got = rastrum.dask.zonal_stats(da.from_array(raster, chunks=3, asarray=False), geoms, stats="count mean")
    same(got, want)
    assert not math.isnan(got["mean"][0])


@pytest.mark.parametrize("kwargs, message", [
    (dict(stats="bogus"), "unknown statistic"),
    (dict(stats="weighted_mean"), "need weights"),
    (dict(weights=np.ones((3, 3))), "weights: shape"),
    (dict(nodata="x"), "not a number"),
    (dict(coverage_weight="area"), "coverage_weight"),
])
def test_bad_input(kwargs, message):
    raster = da.zeros((4, 4), chunks=2)
    sq = {"type": "Polygon", "coordinates": [[(0, 0), (2, 0), (2, 2), (0, 0)]]}
    with pytest.raises(rastrum.InputError, match=message):
        rastrum.dask.zonal_stats(raster, [sq], **kwargs)

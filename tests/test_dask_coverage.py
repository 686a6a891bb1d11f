"""rastrum.dask.rasterize(coverage=...): the lazy array equals
rastrum.rasterize(coverage=...) of the whole raster BIT for bit (float
fractions times values, uint8/uint16 levels; merge "replace", "add",
"max"), for any chunking and for dask-geopandas input.

rastrum.rasterize(coverage=) is itself held to the exact oracle
(test_gis_coverage.py); here it is the reference for the blocks.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import InputError
from strategies import examples
from test_dask import H, W, TRANSFORMS, _chunks_of, _square, border_shapes
from test_rasterize import random_shapes

dask = pytest.importorskip("dask")
import rastrum.dask  # noqa: E402  (needs dask)

MERGES = ["replace", "add", "max"]
# up to 4 blocks a side (each block computes the windows of the features it meets: cheap draws)
_cuts = st.integers(1, 4).flatmap(lambda n: st.lists(st.integers(1, 30), min_size=n, max_size=n))
DTYPES = ["float64", "float32", "uint8", "uint16"]


def polygons(tname, seed):
    """The polygons of test_dask's block-border shapes (one covering the
    raster, corners, a sliver on a border, partly and wholly outside) and
    random polygons and multipolygons (overlapping: add and max matter)."""
    t = TRANSFORMS[tname]
    shapes = [s for s in border_shapes(t) if s["type"] == "Polygon"]
    shapes = shapes[1:] + shapes[:1]  # the raster-wide one last but one: "replace" then leaves little of it
    shapes += random_shapes(seed, t, n=12, kinds=("polygon", "multipolygon"))
    return shapes, t


def valued(shapes, dtype, seed, merge="add"):
    """Values: levels take 1; floats some negative, some whole numbers and
    -0.0 (not under "max": IEEE maxNum leaves open which zero max(+0, -0)
    is, and numpy's fmax answers either, by the length of the array)."""
    if dtype.startswith("uint"):
        return [(s, 1) for s in shapes]  # levels: the coverage itself
    vals = np.random.default_rng(seed).uniform(-3.0, 5.0, len(shapes))
    vals[::5] = np.round(vals[::5])
    vals[3] = -0.0
    if merge == "max":
        vals += 0.0  # -0.0 + 0.0 is +0.0
    return list(zip(shapes, vals.tolist()))


def assert_bits(got, want):
    """The same bytes: -0.0 against 0.0 and NaN payloads count."""
    assert got.dtype == want.dtype and got.shape == want.shape
    off = got.view(np.uint8).reshape(H, -1) != want.view(np.uint8).reshape(H, -1)
    assert not off.any(), "%d bytes differ from rastrum.rasterize(coverage=), first at %s" % (
        off.sum(), np.argwhere(off)[:5].tolist())


@settings(max_examples=examples(5), deadline=None)
@given(rows=_cuts, cols=_cuts, seed=st.integers(0, 50), tname=st.sampled_from(sorted(TRANSFORMS)),
       merge=st.sampled_from(MERGES), dtype=st.sampled_from(DTYPES), fill=st.sampled_from([0, 0.25, float("nan")]))
def test_random_chunkings(rows, cols, seed, tname, merge, dtype, fill):
    shapes, t = polygons(tname, seed)
    if dtype.startswith("uint"):
        fill = 0
    kw = dict(transform=t, merge_alg=merge, dtype=dtype, coverage="area", fill=fill)
    pairs = valued(shapes, dtype, seed, merge)
    want = rastrum.rasterize(pairs, (H, W), **kw)
    chunks = (_chunks_of(rows, H), _chunks_of(cols, W))
    a = rastrum.dask.rasterize(pairs, (H, W), chunks=chunks, **kw)
    assert a.chunks == chunks and a.dtype == want.dtype
    assert_bits(a.compute(scheduler="sync"), want)


@pytest.mark.parametrize("merge", MERGES)
def test_fixed_chunkings_and_default_dtype(merge):
    shapes, t = polygons("rotated", 4)
    pairs = valued(shapes, "float64", 4, merge)
    want = rastrum.rasterize(pairs, (H, W), transform=t, merge_alg=merge, coverage="area")
    assert want.dtype == np.float64
    for chunks in [((1, 15, 44), (33, 1, 30, 16)), (1, W)]:
        got = rastrum.dask.rasterize(pairs, (H, W), transform=t, merge_alg=merge, coverage="area", chunks=chunks)
        assert_bits(got.compute(scheduler="threads"), want)


def test_coverage_methods():
    shapes, t = polygons("north-up", 9)
    for method in ("ss4",):
        want = rastrum.rasterize(shapes, (H, W), transform=t, coverage=method, merge_alg="add", dtype="uint16")
        got = rastrum.dask.rasterize(shapes, (H, W), transform=t, coverage=method, merge_alg="add", dtype="uint16",
                                     chunks=(7, 9))
        assert_bits(got.compute(scheduler="sync"), want)


def test_multipolygon_across_blocks_is_one_feature():
    """A MultiPolygon whose parts lie in different blocks: its fractions are
    the feature's (its rings filled together, one window), so a block holding
    one part still takes the whole feature; two overlapping parts cover their
    overlap once under even-odd (0 there), which a block given only its own
    parts could not know."""
    a = _square(2.5, 2.5, 20.25, 11.5)["coordinates"]
    b = _square(10.5, 5.5, 70.75, 50.5)["coordinates"]
    multi = {"type": "MultiPolygon", "coordinates": [a, b]}
    want = rastrum.rasterize([multi], (H, W), coverage="area")
    assert want[7, 15] == 0.0 and want[3, 3] == 1.0 and want[40, 60] == 1.0
    got = rastrum.dask.rasterize([multi], (H, W), coverage="area", chunks=(6, 12))
    assert_bits(got.compute(scheduler="sync"), want)


@pytest.mark.parametrize("merge", MERGES)
def test_dask_geopandas(merge):
    gpd = pytest.importorskip("geopandas")
    dgpd = pytest.importorskip("dask_geopandas")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    shapes, t = polygons("north-up", 11)
    pairs = valued(shapes, "float32", 11, merge)
    gdf = gpd.GeoDataFrame({"v": [v for _, v in pairs]}, geometry=[shapely_geometry.shape(g) for g in shapes])
    ddf = dgpd.from_geopandas(gdf, npartitions=3, sort=False)
    for values, dtype in (("v", "float32"), (None, "uint8")):
        kw = dict(transform=t, merge_alg=merge, values=values, dtype=dtype, coverage="area")
        want = rastrum.rasterize(gdf, (H, W), **kw)
        got = rastrum.dask.rasterize(ddf, (H, W), chunks=((20, 21, 19), (50, 30)), **kw)
        assert got.dtype == want.dtype
        assert_bits(got.compute(scheduler="sync"), want)


@pytest.mark.parametrize("kw, pattern", [
    (dict(all_touched=True), r"all_touched=True has no meaning with coverage="),
    (dict(coverage="exact"), r"coverage method 'exact' is unknown"),
    (dict(merge_alg="min"), r"unknown merge_alg 'min'"),
    (dict(dtype="int16"), r"dtype int16: coverage takes float32, float64, uint8, uint16"),
    (dict(dtype="uint8", shapes=[(_square(0, 0, 5, 5), 2)]), r"feature 0: value 2: coverage levels \(uint8\)"),
    (dict(shapes=[_square(0, 0, 5, 5), {"type": "LineString", "coordinates": [(0, 0), (5, 5)]}]),
     r"shapes: feature 1 is not a polygon"),
])
def test_bad_input(kw, pattern):
    kw = dict(kw)
    shapes = kw.pop("shapes", [_square(0, 0, 5, 5)])
    kw.setdefault("coverage", "area")
    with pytest.raises(InputError, match=pattern):
        rastrum.dask.rasterize(shapes, (H, W), chunks=10, **kw)

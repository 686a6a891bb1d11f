"""rastrum.dask.rasterize: the lazy Dask array equals rastrum.rasterize of
the whole raster pixel for pixel, for any chunking, any scheduler and
dask-geopandas input.

rastrum.rasterize is itself held to the exact oracle (test_rasterize.py);
here it is the reference for the blocks.  The merge-order tests also have
their own expectation, written out from the rule (pixel centres of
axis-aligned squares), so that they do not lean on rasterize alone.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import InputError
from strategies import examples
from test_rasterize import NORTH_UP, ROTATED, forward, random_shapes, values_for

dask = pytest.importorskip("dask")
import rastrum.dask  # noqa: E402  (needs dask)

H, W = 60, 80
DTYPES = ["uint8", "int8", "uint16", "int16", "uint32", "int32", "int64", "float32", "float64"]
ALL_KINDS = ("polygon", "multipolygon", "line", "multiline", "multipoint")
TRANSFORMS = {"identity": rastrum.IDENTITY, "north-up": NORTH_UP, "rotated": ROTATED}

# Regular, irregular (a 1-pixel block among others), single block, one row per block.
CHUNKINGS = {
    "regular": (8, 10),
    "irregular": ((1, 15, 44), (33, 1, 30, 16)),
    "single": (H, W),
    "rows": (1, W),
}


def border_shapes(t):
    """Shapes on the block borders of the (8, 10) chunking, in world
    coordinates under t: squares with corners on block corners, a triangle
    with a vertex on one, a sliver across a border, lines along borders,
    points on corners, shapes partly and wholly outside the raster, one
    covering it all."""
    def poly(*pts):
        ring = list(pts) + [pts[0]]
        return {"type": "Polygon", "coordinates": [forward(t, ring)]}

    def line(*pts):
        return {"type": "LineString", "coordinates": forward(t, pts)}

    return [
        poly((-30, -30), (W + 30, -30), (W + 30, H + 30), (-30, H + 30)),  # the whole raster
        poly((10, 8), (30, 8), (30, 24), (10, 24)),  # block corners
        poly((20, 16), (37.3, 21.9), (24.2, 40.5)),  # a vertex on a corner
        poly((9.999999, 0), (10.000001, 0), (10.000001, H), (9.999999, H)),  # a sliver on a border
        poly((49.5, 31.5), (50.5, 31.5), (50.5, 32.5), (49.5, 32.5)),  # a pixel around a corner
        poly((-50, -20), (-10, -20), (-10, 100), (-50, 100)),  # wholly outside
        poly((70, 50), (95, 50), (95, 75), (70, 75)),  # partly outside
        line((10, 0), (10, H)),  # along a column border
        line((0, 16), (W, 16), (W, 17)),  # along a row border
        line((-5, -4), (W + 5, H + 4)),  # through the corners, from outside
        line((20, 16), (30, 24)),
        {"type": "MultiPoint", "coordinates": forward(t, [(10, 8), (20, 16), (79.99, 59.99), (80, 60), (-1, 3)])},
        {"type": "Point", "coordinates": forward(t, [(40, 32)])[0]},
    ]


def layer(tname, seed=3, dtype="int32"):
    t = TRANSFORMS[tname]
    shapes = border_shapes(t) + random_shapes(seed, t, n=30, kinds=ALL_KINDS)
    return list(zip(shapes, values_for(dtype, len(shapes), seed))), t


def assert_same(got, want):
    assert got.dtype == want.dtype and got.shape == want.shape
    off = got != want
    if want.dtype.kind == "f":
        off &= ~(np.isnan(got) & np.isnan(want))
    assert not off.any(), "%d pixels differ from rastrum.rasterize, first at %s" % (
        off.sum(), np.argwhere(off)[:5].tolist())


@pytest.mark.parametrize("chunking", sorted(CHUNKINGS))
@pytest.mark.parametrize("tname", sorted(TRANSFORMS))
@pytest.mark.parametrize("merge", ["replace", "add"])
@pytest.mark.parametrize("all_touched", [False, True])
def test_equal_to_rasterize_for_chunkings(chunking, tname, merge, all_touched):
    shapes, t = layer(tname)
    kw = dict(transform=t, all_touched=all_touched, merge_alg=merge, dtype="int32", fill=-7)
    want = rastrum.rasterize(shapes, (H, W), **kw)
    a = rastrum.dask.rasterize(shapes, (H, W), chunks=CHUNKINGS[chunking], **kw)
    assert a.shape == (H, W) and a.dtype == np.int32
    assert_same(a.compute(scheduler="sync"), want)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("merge", ["replace", "add"])
def test_every_dtype(dtype, merge):
    shapes, t = layer("north-up", seed=5, dtype=dtype)  # large values: "add" saturates somewhere
    for all_touched in (False, True):
        kw = dict(transform=t, merge_alg=merge, dtype=dtype, all_touched=all_touched)
        want = rastrum.rasterize(shapes, (H, W), **kw)
        got = rastrum.dask.rasterize(shapes, (H, W), chunks=(8, 10), **kw).compute(scheduler="sync")
        assert_same(got, want)


def test_default_dtype_values_and_rule():
    shapes, t = layer("rotated")
    geoms = [g for g, _ in shapes]
    for kw in (dict(), dict(values=[float(k) / 3 for k in range(len(geoms))]),
               dict(values=list(range(len(geoms))), rule="nonzero"), dict(default_value=2.5, fill=1)):
        want = rastrum.rasterize(geoms, (H, W), transform=t, **kw)
        got = rastrum.dask.rasterize(geoms, (H, W), transform=t, chunks=((30, 30), (7, 73)), **kw)
        assert got.dtype == want.dtype
        assert_same(got.compute(scheduler="sync"), want)


def test_threaded_scheduler():
    shapes, t = layer("rotated", seed=11)
    for all_touched in (False, True):
        want = rastrum.rasterize(shapes, (H, W), transform=t, dtype="int64", all_touched=all_touched)
        a = rastrum.dask.rasterize(shapes, (H, W), transform=t, chunks=(7, 9), dtype="int64",
                                   all_touched=all_touched)
        with dask.config.set(scheduler="threads", num_workers=4):
            assert_same(a.compute(), want)


_cuts = st.integers(1, 8).flatmap(lambda n: st.lists(st.integers(1, 20), min_size=n, max_size=n))


def _chunks_of(sizes, total):
    """Cut `total` into the running pieces of `sizes` (the last one takes
    what is left)."""
    out, left = [], total
    for s in sizes:
        if s >= left:
            break
        out.append(s)
        left -= s
    return tuple(out + [left])


@settings(max_examples=examples(30))
@given(rows=_cuts, cols=_cuts, seed=st.integers(0, 50), tname=st.sampled_from(sorted(TRANSFORMS)),
       merge=st.sampled_from(["replace", "add"]), all_touched=st.booleans())
def test_random_chunkings(rows, cols, seed, tname, merge, all_touched):
    shapes, t = layer(tname, seed=seed)
    kw = dict(transform=t, all_touched=all_touched, merge_alg=merge, dtype="int32")
    want = rastrum.rasterize(shapes, (H, W), **kw)
    chunks = (_chunks_of(rows, H), _chunks_of(cols, W))
    a = rastrum.dask.rasterize(shapes, (H, W), chunks=chunks, **kw)
    assert a.chunks == chunks
    assert_same(a.compute(scheduler="sync"), want)


# ---- merge order, written out ----------------------------------------------------------

# Axis-aligned squares with corners on pixel edges: pixel (r, c) is inside
# (x0, y0, x1, y1) iff x0 <= c + 1/2 < x1 and y0 <= r + 1/2 < y1.
SQUARES = [(0, 0, 50, 40), (10, 5, 70, 55), (25, 20, 80, 60), (5, 30, 45, 58), (30, 0, 41, 60), (0, 12, 80, 19)]


def _square(x0, y0, x1, y1):
    return {"type": "Polygon", "coordinates": [[(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]]}


def _written_out(squares, vals, merge, dtype):
    want = np.zeros((H, W), dtype)
    for (x0, y0, x1, y1), v in zip(squares, vals):
        if merge == "replace":
            want[y0:y1, x0:x1] = v
        else:  # saturating, in order
            info = np.iinfo(dtype)
            want[y0:y1, x0:x1] = np.clip(want[y0:y1, x0:x1].astype(np.int64) + v, info.min, info.max)
    return want


def _frame(squares, vals, npartitions):
    gpd = pytest.importorskip("geopandas")
    dgpd = pytest.importorskip("dask_geopandas")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    gdf = gpd.GeoDataFrame({"v": vals}, geometry=[shapely_geometry.shape(_square(*s)) for s in squares])
    return gdf, dgpd.from_geopandas(gdf, npartitions=npartitions, sort=False)


@pytest.mark.parametrize("merge", ["replace", "add"])
def test_merge_order_across_blocks_and_partitions(merge):
    # int8 "add" saturates: 100 + 100 + (-100) is 27 in this order, 100 in
    # another; overlaps cross the (7, 9) blocks and the 3 partitions.
    vals = [100, 100, -100, 90, -128, 127]
    want = _written_out(SQUARES, vals, merge, np.int8)
    shapes = [(_square(*s), v) for s, v in zip(SQUARES, vals)]
    assert_same(rastrum.rasterize(shapes, (H, W), merge_alg=merge, dtype="int8"), want)
    got = rastrum.dask.rasterize(shapes, (H, W), chunks=(7, 9), merge_alg=merge, dtype="int8")
    assert_same(got.compute(scheduler="sync"), want)
    gdf, ddf = _frame(SQUARES, vals, 3)
    assert ddf.npartitions == 3
    got = rastrum.dask.rasterize(ddf, (H, W), chunks=(7, 9), merge_alg=merge, dtype="int8", values="v")
    assert_same(got.compute(scheduler="sync"), want)


# ---- dask-geopandas -----------------------------------------------------------------------

def _random_frame(seed, npartitions, tname="north-up"):
    gpd = pytest.importorskip("geopandas")
    dgpd = pytest.importorskip("dask_geopandas")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    shapes, t = layer(tname, seed=seed, dtype="int16")
    gdf = gpd.GeoDataFrame({"v": [v for _, v in shapes], "f": [v / 8 for _, v in shapes]},
                           geometry=[shapely_geometry.shape(g) for g, _ in shapes])
    return gdf, dgpd.from_geopandas(gdf, npartitions=npartitions, sort=False), t


@pytest.mark.parametrize("merge", ["replace", "add"])
@pytest.mark.parametrize("all_touched", [False, True])
def test_dask_geopandas(merge, all_touched):
    gdf, ddf, t = _random_frame(7, 4)
    for values, dtype in (("v", "int16"), ("v", None), ("f", None), (None, "uint8")):
        kw = dict(transform=t, merge_alg=merge, all_touched=all_touched, values=values, dtype=dtype)
        want = rastrum.rasterize(gdf, (H, W), **kw)
        a = rastrum.dask.rasterize(ddf, (H, W), chunks=((20, 21, 19), (50, 30)), **kw)
        assert a.dtype == want.dtype
        assert_same(a.compute(scheduler="sync"), want)
    want = rastrum.rasterize(gdf.geometry, (H, W), transform=t, merge_alg=merge)
    got = rastrum.dask.rasterize(ddf.geometry, (H, W), transform=t, chunks=16, merge_alg=merge)
    assert_same(got.compute(scheduler="threads"), want)


def test_dask_geopandas_is_not_read_until_computed():
    gdf, ddf, t = _random_frame(2, 3)
    read = []

    def spy(part):
        read.append(len(part))
        return part

    watched = ddf.map_partitions(spy, meta=ddf._meta)
    a = rastrum.dask.rasterize(watched, (H, W), transform=t, chunks=(30, 40), values="v")
    assert read == []
    assert_same(a.compute(scheduler="sync"), rastrum.rasterize(gdf, (H, W), transform=t, values="v"))
    assert sorted(read) == sorted(ddf.map_partitions(len).compute().tolist())  # each partition once


def test_local_cluster_two_processes():
    distributed = pytest.importorskip("distributed")
    shapes, t = layer("rotated", seed=13)
    gdf, ddf, t2 = _random_frame(9, 3)
    want1 = rastrum.rasterize(shapes, (H, W), transform=t, dtype="int32", merge_alg="add")
    want2 = rastrum.rasterize(gdf, (H, W), transform=t2, values="v")
    a1 = rastrum.dask.rasterize(shapes, (H, W), transform=t, chunks=(16, 20), dtype="int32", merge_alg="add")
    a2 = rastrum.dask.rasterize(ddf, (H, W), transform=t2, chunks=(25, 30), values="v")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
        client.wait_for_workers(2)
        assert len(client.nthreads()) == 2  # asked of the scheduler, not the client's cached view
        got1, got2 = client.compute([a1, a2], sync=True)
    assert_same(got1, want1)
    assert_same(got2, want2)


# ---- what a task carries ---------------------------------------------------------------

def test_blocks_carry_only_the_shapes_that_meet_them():
    shapes = [_square(1, 1, 5, 5), _square(41, 33, 49, 39), {"type": "Point", "coordinates": (79.5, 59.5)},
              _square(-40, -40, -20, -20)]  # the last: outside the raster, in no block
    geoms, _ = rastrum.gis._split_shapes(shapes, 1, 0, None)
    xy, ring_sizes, part_rings, kind, feature, geom = rastrum.gis._flatten(geoms)
    parts = rastrum.dask._Parts(xy, ring_sizes, part_rings, kind, np.ones(len(kind)), feature, geom)
    edges_r, edges_c = np.arange(0, H + 1, 10), np.arange(0, W + 1, 10)
    lay = rastrum.dask._Layer(parts, edges_r, edges_c)
    carried = {}
    for b in range((len(edges_r) - 1) * (len(edges_c) - 1)):
        p = lay.block_parts(b)
        if len(p):
            carried[divmod(b, len(edges_c) - 1)] = p.feature.tolist()
    # the pixels of each shape's floored bounds, widened by one (slack: snapping to the 2^-32 grid
    # keeps a vertex on its side of a pixel edge): the first square's 0..6 meet block (0, 0); the second's
    # columns 40..50 and rows 32..40 the blocks (3..4, 4..5); the point's 78..80, 58..60 (the
    # raster ends at 79, 59) block (5, 7); nothing else
    assert carried == {(0, 0): [0], (3, 4): [1], (3, 5): [1], (4, 4): [1], (4, 5): [1], (5, 7): [2]}


# ---- xarray --------------------------------------------------------------------------------

def test_to_xarray():
    pytest.importorskip("xarray")
    t = (0.5, 0.0, 100.0, 0.0, -0.5, 300.0)
    shapes, _ = layer("north-up")
    a = rastrum.dask.rasterize(shapes, (H, W), transform=t, chunks=20, dtype="int32")
    da = rastrum.dask.to_xarray(a, t, crs="EPSG:3857")
    assert da.dims == ("y", "x") and da.shape == (H, W)
    assert da.x.values[0] == 100.25 and da.y.values[0] == 299.75 and da.x.values[-1] == 100 + 0.5 * W - 0.25
    assert_same(da.values, rastrum.rasterize(shapes, (H, W), transform=t, dtype="int32"))
    if hasattr(da, "rio"):
        assert tuple(da.rio.transform())[:6] == t and da.rio.crs.to_epsg() == 3857
    with pytest.raises(InputError, match="rotated or sheared"):
        rastrum.dask.to_xarray(a, ROTATED)
    with pytest.raises(InputError, match=r"to_xarray: array must be 2-D \(rows, columns\), not \(2, 3, 4\)"):
        rastrum.dask.to_xarray(np.zeros((2, 3, 4)), t)


# ---- bad input --------------------------------------------------------------------------------

@pytest.mark.parametrize("kw, pattern", [
    (dict(chunks=((30, 20), (80,))), r"chunks .* do not fit out_shape \(60, 80\)"),
    (dict(chunks=((30, 30), (40, 40), (1,))), r"chunks .* do not fit out_shape"),
    (dict(chunks=None), r"chunks must be given"),
    (dict(chunks=-5), r"chunks -5"),
    (dict(chunks="lots"), r"chunks 'lots' do not fit"),
    (dict(chunks=((60, 0), (80,))), r"every chunk of the rows must be a whole number > 0"),
    (dict(chunks=10, out_shape=(0, 5)), r"width and height must be > 0"),
    (dict(chunks=10, out_shape=(10,)), r"Invalid out_shape"),
    (dict(chunks=10, merge_alg="max"), r"unknown merge_alg 'max'"),
    (dict(chunks=10, dtype="float16"), r"dtype float16 is not supported"),
    (dict(chunks=10, transform=(1, 2, 0, 2, 4, 0)), r"not invertible"),
    (dict(chunks=10, all_touched="yes"), r"all_touched must be True or False"),
    (dict(chunks=10, fill=300, dtype="uint8"), r"fill 300 does not fit dtype uint8"),
    (dict(chunks=10, shapes=[{"type": "Polygon", "coordinates": []}]), r"shapes: feature 0: empty Polygon"),
    (dict(chunks=10, shapes=[(_square(0, 0, 2, 2), 300)], dtype="uint8"),
     r"shapes: feature 0: value 300 does not fit dtype uint8"),
    (dict(chunks=10, values="v"), r"a column name needs a GeoDataFrame"),
])
def test_bad_input(kw, pattern):
    kw = dict(kw)
    shapes = kw.pop("shapes", [_square(0, 0, 5, 5)])
    out_shape = kw.pop("out_shape", (H, W))
    with pytest.raises(InputError, match=pattern):
        rastrum.dask.rasterize(shapes, out_shape, **kw)


def test_bad_input_dask_geopandas():
    gdf, ddf, t = _random_frame(1, 2)
    with pytest.raises(InputError, match=r"values='w' is not a column of the GeoDataFrame; columns: v, f"):
        rastrum.dask.rasterize(ddf, (H, W), chunks=20, values="w")
    with pytest.raises(InputError, match=r"values: a dask-geopandas frame takes a column name, not list"):
        rastrum.dask.rasterize(ddf, (H, W), chunks=20, values=[1] * len(gdf))
    with pytest.raises(InputError, match=r"a column name needs a GeoDataFrame"):
        rastrum.dask.rasterize(ddf.geometry, (H, W), chunks=20, values="v")
    # a value that does not fit: found by the task that reads the partition, which it names
    a = rastrum.dask.rasterize(ddf, (H, W), chunks=20, values="v", dtype="uint8", transform=t)
    with pytest.raises(InputError, match=r"partition \d: shapes: feature \d+: value -?\d+ does not fit dtype uint8"):
        a.compute(scheduler="sync")


def test_dask_geopandas_spatial_partitions_skip_blocks():
    """With spatial_partitions (a hull per partition), a block chains only
    the partitions whose hulls meet it: fewer tasks, the same pixels."""
    gpd = pytest.importorskip("geopandas")
    dgpd = pytest.importorskip("dask_geopandas")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    shapes, t = layer("rotated", seed=21, dtype="int16")
    order = np.argsort([shapely_geometry.shape(g).centroid.x for g, _ in shapes], kind="stable")
    shapes = [shapes[k] for k in order]  # spatially sorted: each partition covers a part of the raster
    gdf = gpd.GeoDataFrame({"v": [v for _, v in shapes]}, geometry=[shapely_geometry.shape(g) for g, _ in shapes])
    ddf = dgpd.from_geopandas(gdf, npartitions=4, sort=False)
    plain = rastrum.dask.rasterize(ddf, (H, W), transform=t, chunks=(10, 16), values="v", merge_alg="add")
    ddf.calculate_spatial_partitions()
    assert ddf.spatial_partitions is not None
    skipping = rastrum.dask.rasterize(ddf, (H, W), transform=t, chunks=(10, 16), values="v", merge_alg="add")
    assert len(skipping.__dask_graph__()) < len(plain.__dask_graph__())
    want = rastrum.rasterize(gdf, (H, W), transform=t, values="v", merge_alg="add")
    assert_same(skipping.compute(scheduler="sync"), want)
    assert_same(plain.compute(scheduler="sync"), want)


def test_example_writes_the_geotiff(tmp_path):
    """examples/dask_geotiff.py: the tiled GeoTIFF holds the array, on the
    local scheduler (da.store into windows)."""
    rasterio = pytest.importorskip("rasterio")
    pytest.importorskip("dask_geopandas")
    import importlib.util
    import os

    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples", "dask_geotiff.py")
    spec = importlib.util.spec_from_file_location("dask_geotiff", path)
    ex = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(ex)
    t = ex.Affine(10.0, 0.0, 500000.0, 0.0, -10.0, 4600000.0)
    ddf = ex.layer(300, 96, t)
    a = rastrum.dask.rasterize(ddf, (96, 112), transform=t, chunks=(32, 48), values="v", dtype="uint16")
    ex.write_geotiff(a, str(tmp_path / "out.tif"), t)
    with rasterio.open(tmp_path / "out.tif") as src:
        assert src.profile["tiled"] and (src.profile["blockxsize"], src.profile["blockysize"]) == (48, 32)
        got = src.read(1)
    want = rastrum.rasterize(ddf.compute(), (96, 112), transform=t, values="v", dtype="uint16")
    assert want.any() and not want.all()
    assert_same(got, want)


def test_blocks_are_not_burnt_on_shifted_floats():
    """Why a block is burnt on the whole raster's coordinates with the block
    as the clip: v - 40.0 is inexact for v = 2^-33 - 2^-60 (it rounds to
    -40 + 2^-33, a snapping tie), so a block at column 40 burnt on shifted
    floats would snap that vertex to 2^-32 instead of 0, and move the edge
    off the sample point (40.5, 20.5) that it passes through exactly."""
    v = 2.0 ** -33 - 2.0 ** -60
    assert v - 40.0 == -40.0 + 2.0 ** -33  # rounded
    tri = {"type": "Polygon", "coordinates": [[(v, 0.5), (81.0, 40.5), (81.0, 0.5), (v, 0.5)]]}
    whole = rastrum.rasterize([tri], (H, W), dtype="uint8")
    assert whole[20, 40] == 1  # on the edge, left closed: inside (the exact rule on the snapped vertex 0)
    shifted = {"type": "Polygon", "coordinates": [[(x - 40.0, y) for x, y in tri["coordinates"][0]]]}
    assert rastrum.rasterize([shifted], (H, 40), dtype="uint8")[20, 0] == 0  # the hazard is real
    got = rastrum.dask.rasterize([tri], (H, W), chunks=(H, 40), dtype="uint8").compute(scheduler="sync")
    assert_same(got, whole)


def test_misaligned_coordinates_are_burnt_from_an_aligned_copy():
    """Arrays unpickled from a dask.distributed message may be misaligned
    (UBSan found it: the glue reads doubles); the burn aligns them.  Under
    make asan-py, UBSan aborts here without the aligned copy."""
    shapes, t = layer("rotated", seed=4)
    geoms, vals = rastrum.gis._split_shapes(shapes, 1, 0, None)
    xy, ring_sizes, part_rings, kind, feature, geom = rastrum.gis._flatten(geoms)
    inv = rastrum.gis._inverse(rastrum.gis._transform6(t))
    px = rastrum.gis._pixels(xy, inv, ring_sizes, part_rings, feature)
    raw = np.zeros(px.nbytes + 1, np.uint8)[1:]
    odd = raw.view(np.float64).reshape(px.shape)
    odd[...] = px
    assert not odd.flags.aligned
    values = rastrum.gis._values(vals, np.dtype("int32"))[feature]
    parts = rastrum.dask._Parts(odd, ring_sizes, part_rings, kind, values, feature, geom)
    got = rastrum.dask._burn_block((H, 40), (0, 40), 0, np.dtype("int32"), "replace", False, "evenodd", parts)
    assert_same(got, rastrum.rasterize(shapes, (H, W), transform=t, dtype="int32")[:, 40:])


def test_dask_geopandas_empty_partition():
    gdf, ddf, t = _random_frame(3, 3)
    first = ddf.partitions[0].compute()
    some = ddf.map_partitions(lambda p: p[p.index > first.index.max()], meta=ddf._meta)  # partition 0 empty
    assert some.map_partitions(len).compute().tolist()[0] == 0
    a = rastrum.dask.rasterize(some, (H, W), transform=t, chunks=(25, 30), values="v")
    assert_same(a.compute(scheduler="sync"), rastrum.rasterize(some.compute(), (H, W), transform=t, values="v"))

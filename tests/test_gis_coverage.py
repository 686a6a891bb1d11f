"""Coverage fractions on the caller's coordinates: rastrum.coverage_fractions
(exactextract's cell_id + coverage per feature) and rasterize(coverage=...).

* coverage_fractions: every fraction the exact area of the snapped feature
  in the cell (tests/oracle_coverage.py, rationals; test_zonal's helpers),
  the cells exactextract reports, its fractions within the snapping bound;
* rasterize(coverage=...): the sparse fractions merged by a plain Python
  loop over the features and cells (replace, add, max; float32 rounded at
  each step as GDAL rounds "add"), levels, nodata/masked, and InputError
  with `out` untouched.
"""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from test_zonal import TRANSFORMS, exact_fractions, features, rings_of, world

F = Fraction


@settings(max_examples=S_.examples(25))
@given(st.integers(1, 6), st.integers(1, 6), st.data(), st.sampled_from(TRANSFORMS))
def test_coverage_fractions_exact(h, w, data, t):
    """Per feature: the cells in increasing order, each fraction the exact
    area of the snapped feature, rounded once (polygon_coverage's bound,
    docs/coverage.md); flat=True the same arrays end to end."""
    geoms = [world(data.draw(features(h, w)), t) for _ in range(data.draw(st.integers(1, 3)))]
    per = rastrum.coverage_fractions(geoms, (h, w), t)
    ff, fc, fv = rastrum.coverage_fractions(geoms, (h, w), t, flat=True)
    assert len(per) == len(geoms)
    assert np.array_equal(ff, np.repeat(np.arange(len(geoms)), [len(c) for c, _ in per]))
    assert np.array_equal(fc, np.concatenate([c for c, _ in per]))
    assert np.array_equal(fv, np.concatenate([v for _, v in per]))
    for k, (g, (cells, cov)) in enumerate(zip(geoms, per)):
        assert cells.dtype == np.int64 and cov.dtype == np.float64
        assert (np.diff(cells) > 0).all()
        want, _ = exact_fractions(g, t, (h, w))
        got = {(int(c) // w, int(c) % w): float(v) for c, v in zip(cells, cov)}
        e = sum(len(r) for r in rings_of(g))
        bound = F(e + e * (e - 1) // 2 + 1, 2 ** 58)
        for cell in set(got) | set(want):
            a, v = want.get(cell, F(0)), got.get(cell, 0.0)
            assert abs(F(v) - a) <= bound + abs(a) / 2 ** 53, (k, cell, v, float(a))


def merge_reference(per, values, shape, dtype, merge, fill):
    """The features' value * fraction merged cell by cell, feature after
    feature, in plain Python (float32: each step rounded, as GDAL's add)."""
    h, w = shape
    out = np.full((h, w), fill, dtype)
    for (cells, cov), v in zip(per, values):
        for c, a in zip(cells.tolist(), cov.tolist()):
            r, col = divmod(c, w)
            x = float(v) * a
            old = float(out[r, col])
            if merge == "replace":
                new = x
            elif merge == "add":
                new = old + x
            else:
                new = x if math.isnan(old) else max(old, x)
            out[r, col] = new
    return out


@settings(max_examples=S_.examples(25))
@given(st.integers(1, 6), st.integers(1, 6), st.data(), st.sampled_from(TRANSFORMS),
       st.sampled_from(["replace", "add", "max"]), st.sampled_from(["float64", "float32"]))
def test_rasterize_coverage_merges(h, w, data, t, merge, dtype):
    """rasterize(coverage="area") is the sparse fractions times the values,
    merged in feature order; cells no feature covers keep the fill."""
    n = data.draw(st.integers(1, 4))
    geoms = [world(data.draw(features(h, w)), t) for _ in range(n)]
    values = [data.draw(st.sampled_from([1, 2.5, -1.0, 0.1])) for _ in range(n)]
    fill = data.draw(st.sampled_from([0.0, 0.3, float("nan")]))
    per = rastrum.coverage_fractions(geoms, (h, w), t)
    got = rastrum.rasterize(list(zip(geoms, values)), (h, w), transform=t, coverage="area", merge_alg=merge,
                            dtype=dtype, fill=fill)
    want = merge_reference(per, values, (h, w), np.dtype(dtype), merge, fill)
    assert got.dtype == np.dtype(dtype)
    np.testing.assert_array_equal(got, want)


@settings(max_examples=S_.examples(20))
@given(st.integers(1, 6), st.integers(1, 6), st.data(), st.sampled_from(["uint8", "uint16"]),
       st.sampled_from(["replace", "add", "max"]))
def test_rasterize_coverage_levels(h, w, data, dtype, merge):
    """uint8/uint16: each feature's levels as coverage_fractions(dtype=...)
    gives them (within 1/2 level plus polygon_coverage's bound of the
    exact area), merged: the last, the sum saturating, the largest."""
    geoms = [data.draw(features(h, w)) for _ in range(data.draw(st.integers(1, 3)))]
    M = np.iinfo(dtype).max
    per = rastrum.coverage_fractions(geoms, (h, w), dtype=dtype)
    exact = rastrum.coverage_fractions(geoms, (h, w))
    for (cl, lv), (ce, a) in zip(per, exact):
        lookup = dict(zip(ce.tolist(), a.tolist()))
        for c, level in zip(cl.tolist(), lv.tolist()):
            assert abs(level - lookup[c] * M) <= 0.5 + 1e-9 * M
    got = rastrum.rasterize(geoms, (h, w), coverage="area", dtype=dtype, merge_alg=merge)
    want = np.zeros((h, w), np.int64)
    for cells, lv in per:
        for c, level in zip(cells.tolist(), lv.tolist()):
            r, col = divmod(c, w)
            old = int(want[r, col])
            want[r, col] = level if merge == "replace" else min(old + level, M) if merge == "add" else max(old, level)
    assert got.dtype == np.dtype(dtype)
    np.testing.assert_array_equal(got, want.astype(dtype))


def test_rasterize_coverage_ss4_and_out():
    """A polygon_coverage method other than "area", into `out` in place;
    the identity transform gives polygon_coverage's own fractions."""
    ring = [(0.5, 0.25), (3.75, 1.0), (2.0, 3.5)]
    geom = {"type": "Polygon", "coordinates": [ring + [ring[0]]]}
    out = np.full((4, 5), 7.0)
    res = rastrum.rasterize([geom], out=out, coverage="ss4")
    assert res is out
    want = rastrum.polygon_coverage([np.array(ring)], (4, 4), method="ss4", subpixel_bits=16, dtype=np.float64)
    assert np.array_equal(out[:, :4][want > 0], want[want > 0])
    assert (out[:, :4][want == 0] == 7.0).all() and (out[:, 4] == 7.0).all()


def test_rasterize_coverage_nodata_masked():
    sq = {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2, 0.5), (2, 2), (0.5, 2), (0.5, 0.5)]]}
    m = rastrum.rasterize([sq], (3, 3), coverage="area", fill=-1.0, nodata=-1.0, masked=True)
    assert isinstance(m, np.ma.MaskedArray)
    assert m.mask.tolist() == [[False, False, True], [False, False, True], [True, True, True]]
    assert m.data[:2, :2].tolist() == [[0.25, 0.5], [0.5, 1.0]]


def test_coverage_fractions_far_apart_and_outside():
    """Features far apart on a big grid: only their cells are reported
    (no dense array); a feature outside the raster: two empty arrays."""
    H = W = 1 << 20
    a = {"type": "Polygon", "coordinates": [[(1.5, 1.5), (2.5, 1.5), (2.5, 2.5), (1.5, 2.5), (1.5, 1.5)]]}
    x = W - 3.0
    b = {"type": "Polygon", "coordinates": [[(x, x), (x + 1, x), (x + 1, x + 1), (x, x + 1), (x, x)]]}
    out = {"type": "Polygon", "coordinates": [[(-5, -5), (-4, -5), (-4, -4), (-5, -5)]]}
    (ca, va), (cb, vb), (co, vo) = rastrum.coverage_fractions([a, b, out], (H, W))
    assert ca.tolist() == [1 * W + 1, 1 * W + 2, 2 * W + 1, 2 * W + 2] and va.tolist() == [0.25] * 4
    assert cb.tolist() == [(W - 3) * W + (W - 3)] and vb.tolist() == [1.0]
    assert len(co) == 0 and len(vo) == 0


def test_coverage_fractions_geodataframe_and_levels():
    shp = pytest.importorskip("shapely")
    gpd = pytest.importorskip("geopandas")
    gdf = gpd.GeoDataFrame(geometry=[shp.box(0.5, 0.5, 2, 1), shp.box(0, 0, 1, 1)])
    per = rastrum.coverage_fractions(gdf, (2, 3), dtype="uint8")
    assert [c.tolist() for c, _ in per] == [[0, 1], [0]]
    assert [v.tolist() for _, v in per] == [[64, 128], [255]]


def test_against_exactextract_cell_id_coverage():
    """exactextract's exact_extract(..., ["cell_id", "coverage"]): the same
    cells, each fraction within the snapping bound: a vertex moves by at
    most 2^-(S+1) px in x and y, so each of the n edges moves the area
    inside a cell by at most 2^-S of it (the edge's length in a unit cell
    is at most sqrt 2, its motion at most 2^-(S+1) sqrt 2)."""
    ee = pytest.importorskip("exactextract")
    shp = pytest.importorskip("shapely")
    gpd = pytest.importorskip("geopandas")
    pyproj = pytest.importorskip("pyproj")
    from exactextract.raster import NumPyRasterSource
    from test_zonal import star
    rng = np.random.default_rng(5)
    res, H, W, x0, y1 = 0.1, 60, 80, 20.0, 50.0
    t = (res, 0.0, x0, 0.0, -res, y1)
    polys = [shp.Polygon(star(rng.uniform(x0 - 0.5, x0 + W * res + 0.5), rng.uniform(y1 - H * res - 0.5, y1 + 0.5),
                              rng.uniform(0.05, 1.5, rng.integers(4, 20)), rng.uniform(0, 6))) for _ in range(25)]
    wkt = pyproj.CRS("EPSG:4326").to_wkt()
    src = NumPyRasterSource(np.zeros((H, W)), x0, y1 - H * res, x0 + W * res, y1, srs_wkt=wkt)
    gdf = gpd.GeoDataFrame(geometry=polys, crs="EPSG:4326")
    theirs = ee.exact_extract(src, gdf, ["cell_id", "coverage"], output="pandas")
    mine = rastrum.coverage_fractions(gdf, (H, W), t)
    s = rastrum._fractions.subpixel_bits_for(max(H, W) + 1.0)
    for k, g in enumerate(polys):
        cells, cov = mine[k]
        tc, tv = np.asarray(theirs["cell_id"].iloc[k]), np.asarray(theirs["coverage"].iloc[k])
        n = len(g.exterior.coords) - 1
        bound = n * 2.0 ** -s + 1e-7  # exactextract: 1e-8 to 1e-7 off the exact areas
        d_mine, d_theirs = dict(zip(cells.tolist(), cov.tolist())), dict(zip(tc.tolist(), tv.tolist()))
        for c in set(d_mine) | set(d_theirs):
            assert abs(d_mine.get(c, 0.0) - d_theirs.get(c, 0.0)) <= bound, (k, c, d_mine.get(c), d_theirs.get(c))
        # a cell only one of them reports is a sliver within the bound
        assert len(set(d_mine) ^ set(d_theirs)) <= 2 * n


def _sq():
    return {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2, 0.5), (2, 2), (0.5, 2), (0.5, 0.5)]]}


@pytest.mark.parametrize("kwargs, message", [
    (dict(shapes=[{"type": "LineString", "coordinates": [(0, 0), (2, 2)]}]), "not a polygon"),
    (dict(shapes=[(_sq(), 2)], dtype="uint8"), "every value must be 1"),
    (dict(shapes=[_sq()], all_touched=True), "all_touched"),
    (dict(shapes=[_sq()], dtype="int32"), "coverage takes"),
    (dict(shapes=[_sq()], coverage="ss3"), "coverage method"),
    (dict(shapes=[_sq()], merge_alg="min"), "unknown merge_alg"),
    (dict(shapes=[_sq(), {"type": "Polygon", "coordinates": [[(0, 0), (float("nan"), 1), (1, 1)]]}]), "NaN"),
])
def test_rasterize_coverage_bad_input_out_untouched(kwargs, message):
    kwargs = dict(kwargs)
    shapes = kwargs.pop("shapes")
    kwargs.setdefault("coverage", "area")
    dt = kwargs.get("dtype", "float64")
    out = np.full((3, 3), 5, dt if dt in ("uint8", "float64") else "float64")
    before = out.copy()
    with pytest.raises(rastrum.InputError, match=message):
        rastrum.rasterize(shapes, out=out, **kwargs)
    assert np.array_equal(out, before)


def test_max_merge_needs_coverage():
    out = np.zeros((3, 3), np.uint8)
    with pytest.raises(rastrum.InputError, match="coverage"):
        rastrum.rasterize([_sq()], out=out, merge_alg="max")
    assert not out.any()


@pytest.mark.parametrize("kwargs, message", [
    (dict(geometries=[{"type": "Point", "coordinates": (1, 1)}]), "not a polygon"),
    (dict(geometries=_sq()), "not one geometry"),
    (dict(geometries=[_sq()], dtype="int8"), "coverage takes"),
    (dict(geometries=[_sq()], method="bogus"), "coverage method"),
    (dict(geometries=[_sq()], out_shape=(0, 3)), "out_shape"),
    (dict(geometries=[_sq()], flat=1), "flat"),
])
def test_coverage_fractions_bad_input(kwargs, message):
    kwargs.setdefault("out_shape", (3, 3))
    with pytest.raises(rastrum.InputError, match=message):
        rastrum.coverage_fractions(**kwargs)


def test_oracle_level_helper_agrees():
    """The uint8 levels of one exact square (no snapping: corners on the
    2^-16 grid) are oracle_coverage.level of the exact fractions."""
    ring = [(0.25, 0.5), (2.75, 0.5), (2.75, 1.875), (0.25, 1.875)]
    geom = {"type": "Polygon", "coordinates": [ring + [ring[0]]]}
    exact = oc.coverage_exact([ring], (2, 3), subpixel_bits=16)
    (cells, lv), = rastrum.coverage_fractions([geom], (2, 3), dtype="uint8")
    want = {r * 3 + c: oc.level(a, 255) for (r, c), a in np.ndenumerate(exact) if a}
    assert dict(zip(cells.tolist(), lv.tolist())) == want

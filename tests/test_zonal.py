"""rastrum.zonal_stats against references written here, independently:

* the fractions against the exact area of every cell of the snapped
  polygon (tests/oracle_coverage.py, rationals), within polygon_coverage's
  documented bound ((n + m + 1) 2^-58, then one rounding to float64);
* every statistic against a brute-force reference: a Python loop over the
  cells of each feature with those exact fractions, sums in exact
  rationals, exactextract's definitions written out (the weighted quantile
  as its weighted_quantiles.cpp defines it);
* the fractions against shapely's cell-by-polygon intersection areas on
  the unsnapped polygon in float64, within the snapping bound;
* exactextract itself, where installed, on random rasters and polygons.
"""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
from rastrum import _zonal as zonal
from rastrum import gis
import strategies as S_

F = Fraction


# ---- random polygons --------------------------------------------------------------------

def star(cx, cy, radii, phase):
    """A star-shaped ring around (cx, cy): valid (simple), counter-clockwise."""
    n = len(radii)
    ang = phase + 2 * math.pi * np.arange(n) / n
    return np.c_[cx + np.asarray(radii) * np.cos(ang), cy + np.asarray(radii) * np.sin(ang)]


@st.composite
def features(draw, h, w):
    """A GeoJSON Polygon (maybe with a hole) or a MultiPolygon of two
    disjoint stars, in pixel coordinates around the raster (partly or
    wholly outside it sometimes)."""
    def one(cx, cy, rmax):
        n = draw(st.integers(3, 9))
        radii = [draw(st.floats(0.3 * rmax, rmax)) for _ in range(n)]
        phase = draw(st.floats(0, 2 * math.pi))
        outer = star(cx, cy, radii, phase)
        rings = [outer]
        if draw(st.booleans()) and n >= 3:
            hole = star(cx, cy, [0.25 * min(radii)] * draw(st.integers(3, 6)), phase)[::-1]
            rings.append(hole)
        return [r.tolist() + [r[0].tolist()] for r in rings]

    cx = draw(st.floats(-2.0, w + 2.0))
    cy = draw(st.floats(-2.0, h + 2.0))
    r = draw(st.floats(0.4, max(1.0, min(h, w) / 2.0)))
    if draw(st.booleans()):
        return {"type": "Polygon", "coordinates": one(cx, cy, r)}
    dx = draw(st.floats(2.2 * r + 0.1, 2.2 * r + 4.0))
    return {"type": "MultiPolygon", "coordinates": [one(cx, cy, r), one(cx + dx, cy, r)]}


def world(geom, t):
    """The geometry moved from pixel to world coordinates by transform t."""
    a, b, c, d, e, f = t

    def tr(ring):
        return [(a * x + b * y + c, d * x + e * y + f) for x, y in ring]

    if geom["type"] == "Polygon":
        return {"type": "Polygon", "coordinates": [tr(r) for r in geom["coordinates"]]}
    return {"type": "MultiPolygon", "coordinates": [[tr(r) for r in p] for p in geom["coordinates"]]}


def rings_of(geom):
    polys = [geom["coordinates"]] if geom["type"] == "Polygon" else geom["coordinates"]
    return [np.asarray(r, np.float64) for p in polys for r in p]


# ---- the exact fractions of one feature -----------------------------------------------------

def coverage_is_wide():
    """Whether polygon_coverage takes S = 32 (a 64-bit coverage path)."""
    try:
        rastrum.polygon_coverage([(0, 0), (1, 0), (0, 1)], (1, 1), subpixel_bits=32, dtype=np.float64)
    except rastrum.InputError:
        return False
    return True


def max_bits(extent):
    """The largest S polygon_coverage takes for |coordinate| <= extent,
    computed in rationals: S <= 16 with floor(extent * 2^S + 1/2) <=
    2^27 - 1 (the 32-bit path), or S <= 32 with it <= 2^(S + 28) - 1 (a
    64-bit one)."""
    top, pix = (32, 28) if coverage_is_wide() else (16, None)
    for s in range(top, -1, -1):
        if math.floor(F(extent) * 2 ** s + F(1, 2)) <= (2 ** 27 - 1 if pix is None else 2 ** (s + pix) - 1):
            return s
    return -1


def exact_fractions(geom, transform, shape):
    """{(row, col): Fraction} of the feature: its rings in pixels (the
    transform's inverse as rasterize applies it), less the window's origin
    (float64, as documented), snapped at the window's S, exact areas."""
    H, W = shape
    rings = [gis.pixel_coordinates(r, transform) for r in rings_of(geom)]
    pts = np.concatenate(rings)
    c0, r0 = max(math.floor(pts[:, 0].min()), 0), max(math.floor(pts[:, 1].min()), 0)
    c1, r1 = min(math.ceil(pts[:, 0].max()), W), min(math.ceil(pts[:, 1].max()), H)
    if c1 <= c0 or r1 <= r0:
        return {}, None
    local = [r - np.array([c0, r0], np.float64) for r in rings]
    s = max_bits(float(np.abs(np.concatenate(local)).max()))
    assert s == max_bits(max(r1 - r0, c1 - c0) + 1.0), "the tests keep features near the raster"
    cov = oc.coverage_exact([r.tolist() for r in local], (r1 - r0, c1 - c0), subpixel_bits=s)
    out = {}
    for (j, i), a in np.ndenumerate(cov):
        if a:
            out[(j + r0, i + c0)] = a
    return out, s


TRANSFORMS = [(1.0, 0.0, 0.0, 0.0, 1.0, 0.0), (0.25, 0.0, 100.0, 0.0, -0.5, 40.0)]


@settings(max_examples=S_.examples(40))
@given(st.integers(1, 7), st.integers(1, 7), st.data(), st.sampled_from(TRANSFORMS))
def test_fractions_exact(h, w, data, t):
    """Every fraction is the exact area of the snapped feature in the cell,
    rounded once to float64; no other cell is reported."""
    geoms = [world(data.draw(features(h, w)), t) for _ in range(data.draw(st.integers(1, 3)))]
    xy, sizes, prings, kind, feat, _ = gis._flatten(geoms)
    px = gis._pixels(xy, gis._inverse(gis._transform6(t)), sizes, prings, feat)
    f, cells, frac, info = zonal._fractions(px, sizes, prings, feat, len(geoms), (h, w), "evenodd")
    for k, g in enumerate(geoms):
        want, s = exact_fractions(g, t, (h, w))
        mine = f == k
        got = {(int(c) // w, int(c) % w): v for c, v in zip(cells[mine], frac[mine])}
        # polygon_coverage's bound (docs/coverage.md): |a' - a| <= (n + m + 1)
        # 2^-58 with n edges across the row and m pairs of them crossing
        # there (at most all E edges and all their pairs), a' then rounded
        # once to float64
        e = sum(len(r) for r in rings_of(g))
        bound = F(e + e * (e - 1) // 2 + 1, 2 ** 58)
        for cell in set(got) | set(want):
            a, v = want.get(cell, F(0)), got.get(cell, 0.0)
            assert abs(F(v) - a) <= bound + abs(a) / 2 ** 53, (k, cell, v, float(a))
        if s is not None:
            assert info[k, 2] == s


# ---- brute-force statistics ------------------------------------------------------------------

def quantile_ref(pairs, q):
    """exactextract's weighted quantile (weighted_quantiles.cpp) of
    (value, weight) pairs with distinct values, in rationals."""
    pairs = sorted(pairs)
    n = len(pairs)
    xs = [F(x) for x, _ in pairs]
    ws = [w for _, w in pairs]
    s, cum = [], F(0)
    for i in range(n):
        s.append(F(0) if i == 0 else i * ws[i] + (n - 1) * cum)
        cum += ws[i]
    t = F(q) * cum * (n - 1)
    for i in range(n):
        if s[i] > t:
            if i == 0:
                return xs[0]
            return xs[i - 1] + (t - s[i - 1]) * (xs[i] - xs[i - 1]) / (s[i] - s[i - 1])
    return xs[-1]


def reference_stats(values, weights, fr, nodata, qs):
    """The statistics of one feature from its exact fractions fr {(r, c): a}."""
    cells = [(rc, a) for rc, a in sorted(fr.items())
             if not (isinstance(values[rc], float) and math.isnan(values[rc])) and values[rc] != nodata]
    out = {}
    count = sum((a for _, a in cells), F(0))
    total = sum((F(values[rc]) * a for rc, a in cells), F(0))
    out["count"], out["sum"] = count, total
    out["mean"] = total / count if count else None
    xs = [F(values[rc]) for rc, _ in cells]
    out["min"] = min(xs) if xs else None
    out["max"] = max(xs) if xs else None
    hist = {}
    for rc, a in cells:
        hist[F(values[rc])] = hist.get(F(values[rc]), F(0)) + a
    out["variety"] = len(hist)
    out["hist"] = hist
    for q in qs:
        out["q%r" % q] = quantile_ref(list(hist.items()), q) if hist else None
    if count:
        mean = total / count
        var = sum((a * (F(values[rc]) - mean) ** 2 for rc, a in cells), F(0)) / count
        out["variance"] = var
    else:
        out["variance"] = None
    wc = sum((a * F(weights[rc]) for rc, a in cells), F(0))
    ws = sum((a * F(weights[rc]) * F(values[rc]) for rc, a in cells), F(0))
    out["weighted_sum"], out["weighted_count"] = ws, wc
    out["weighted_mean"] = ws / wc if wc else None
    return out


def close(got, want, scale, what):
    """got (float64, summed in another order) within float64 rounding of the
    exact want: |got - want| <= 1e-12 * scale (scale: the sum of the
    magnitudes summed; at most 64 terms here, eps = 2^-53)."""
    if want is None:
        assert math.isnan(got), what
        return
    assert math.isfinite(got), (what, got, float(want))
    assert abs(F(got) - want) <= F(1, 10 ** 12) * (scale + abs(want)), (what, got, float(want))


@settings(max_examples=S_.examples(40))
@given(st.integers(1, 7), st.integers(1, 7), st.data(), st.sampled_from(TRANSFORMS), st.booleans())
def test_stats_brute_force(h, w, data, t, ints):
    geoms = [world(data.draw(features(h, w)), t) for _ in range(data.draw(st.integers(1, 3)))]
    rng = np.random.default_rng(data.draw(st.integers(0, 2 ** 32 - 1)))
    values = rng.integers(0, 4, (h, w)).astype(np.float64) if ints else rng.normal(10, 3, (h, w))
    nodata = -1.0
    values[rng.random((h, w)) < 0.15] = nodata
    if not ints:
        values[rng.random((h, w)) < 0.1] = np.nan
    weights = rng.random((h, w))
    qs = (0.0, 0.25, 0.5, 0.9, 1.0)
    stats = ["count", "sum", "mean", "min", "max", "majority", "minority", "variety", "median", "stdev",
             "variance", "weighted_sum", "weighted_mean", "weighted_count"] + ["quantile(q=%r)" % q for q in qs]
    got = rastrum.zonal_stats(values, geoms, transform=t, stats=stats, weights=weights, nodata=nodata,
                              output="records")
    for k, g in enumerate(geoms):
        fr, _ = exact_fractions(g, t, (h, w))
        ref = reference_stats(values, weights, fr, nodata, qs)
        row = got[k]
        scale = sum((abs(F(values[rc])) * a for rc, a in fr.items() if math.isfinite(values[rc])), F(0)) + 1
        for name in ("count", "sum", "mean", "weighted_sum", "weighted_mean", "weighted_count"):
            close(row[name], ref[name], scale, (k, name))
        close(row["variance"], ref["variance"], scale * 100, (k, "variance"))
        if ref["variance"] is not None:
            assert abs(row["stdev"] - math.sqrt(ref["variance"])) <= 1e-6 * (1 + math.sqrt(ref["variance"]))
        for name in ("min", "max"):
            assert (row[name] == ref[name]) if ref[name] is not None else math.isnan(row[name]), (k, name)
        assert row["variety"] == ref["variety"]
        for q in qs:
            col = "median" if q == 0.5 else "quantile_%s" % zonal._pct(q)
            close(row[col], ref["q%r" % q], scale, (k, col))
        hist = ref["hist"]
        if not hist:
            assert math.isnan(row["majority"]) and math.isnan(row["minority"])
            continue
        # the most covered value, ties to the greatest (majority); the least,
        # ties to the least; a near-tie (float64 sums in another order) may go
        # either way
        top = max(hist.values())
        bottom = min(hist.values())
        near = F(1, 10 ** 12) * (1 + top)
        assert row["majority"] in {float(x) for x, a in hist.items() if top - a <= near}
        if not any(0 < top - a <= near for a in hist.values()):
            assert row["majority"] == float(max(x for x, a in hist.items() if a == top))
        assert row["minority"] in {float(x) for x, a in hist.items() if a - bottom <= near}
        if not any(0 < a - bottom <= near for a in hist.values()):
            assert row["minority"] == float(min(x for x, a in hist.items() if a == bottom))


# ---- against shapely: the snapping error ------------------------------------------------------

def test_fractions_against_shapely_areas():
    """On a 0.025 degree grid, fractions within 2^-S of a cell per edge of
    the exact (unsnapped) areas that shapely computes in float64."""
    shp = pytest.importorskip("shapely")
    rng = np.random.default_rng(5)
    res = 0.025
    t = (res, 0.0, -10.0, 0.0, -res, 10.0)
    H, W = 800, 800
    geoms = []
    for _ in range(10):  # 30 took 25-80 s of shapely in CI
        cx, cy = rng.uniform(-10, 10, 2)
        n = rng.integers(5, 40)
        radii = rng.uniform(0.2, 2.0, n)
        geoms.append(shp.Polygon(star(cx, cy, radii, rng.uniform(0, 6))))
    xy, sizes, prings, kind, feat, _ = gis._flatten(geoms)
    px = gis._pixels(xy, gis._inverse(gis._transform6(t)), sizes, prings, feat)
    f, cells, frac, info = zonal._fractions(px, sizes, prings, feat, len(geoms), (H, W), "evenodd")
    worst = 0.0
    for k, g in enumerate(geoms):
        r0, c0, s = info[k]
        mine = f == k
        rows, cols = np.divmod(cells[mine], W)
        # every cell the feature's box touches inside the raster
        x0, y0, x1, y1 = g.bounds
        cmin, cmax = max(int((x0 + 10) / res) - 1, 0), min(int((x1 + 10) / res) + 2, W)
        rmin, rmax = max(int((10 - y1) / res) - 1, 0), min(int((10 - y0) / res) + 2, H)
        jj, ii = np.mgrid[rmin:rmax, cmin:cmax]
        boxes = shp.box(-10 + ii * res, 10 - (jj + 1) * res, -10 + (ii + 1) * res, 10 - jj * res)
        exact = shp.area(shp.intersection(boxes, g)) / (res * res)
        got = np.zeros_like(exact)
        got[rows - rmin, cols - cmin] = frac[mine]
        err = np.abs(got - exact)
        n_edges = len(g.exterior.coords) - 1
        # a vertex moves by at most 2^-(S+1) px in x and y; the region
        # changes by at most that times the boundary length in a cell
        # (< sqrt(2) per edge through it, two edges at a vertex) plus the
        # float64 rounding of shapely's areas (~1e-12 of a cell)
        bound = 2.0 ** -(s + 1) * math.sqrt(2) * 2 * math.sqrt(2) * 2 + 1e-9
        assert err.max() <= bound, (k, err.max(), bound, s)
        worst = max(worst, err.max() * 2.0 ** s)
        assert n_edges >= 5
    assert worst > 0  # snapping did move something


# ---- against exactextract --------------------------------------------------------------------------

def test_against_exactextract():
    ee = pytest.importorskip("exactextract")
    shp = pytest.importorskip("shapely")
    gpd = pytest.importorskip("geopandas")
    pyproj = pytest.importorskip("pyproj")
    from exactextract.raster import NumPyRasterSource
    wkt = pyproj.CRS("EPSG:4326").to_wkt()
    rng = np.random.default_rng(11)
    res = 0.1
    H, W = 120, 150
    x0, y1 = 20.0, 50.0
    t = (res, 0.0, x0, 0.0, -res, y1)
    values = rng.integers(0, 20, (H, W)).astype(np.float64)
    values[rng.random((H, W)) < 0.05] = -99
    weights = rng.random((H, W))
    polys = []
    for _ in range(60):
        cx, cy = rng.uniform(x0 - 1, x0 + W * res + 1), rng.uniform(y1 - H * res - 1, y1 + 1)
        n = rng.integers(4, 30)
        polys.append(shp.Polygon(star(cx, cy, rng.uniform(0.05, 2.5, n), rng.uniform(0, 6))))
    gdf = gpd.GeoDataFrame({"id": np.arange(len(polys)) * 3}, geometry=polys, crs="EPSG:4326").set_index("id")
    ops = ["count", "sum", "mean", "min", "max", "variety", "stdev", "median", "quantile(q=0.2)",
           "weighted_mean", "weighted_sum", "majority", "minority"]
    src = NumPyRasterSource(values, x0, y1 - H * res, x0 + W * res, y1, nodata=-99, srs_wkt=wkt)
    wsrc = NumPyRasterSource(weights, x0, y1 - H * res, x0 + W * res, y1, srs_wkt=wkt)
    theirs = ee.exact_extract(src, gdf, ops, weights=wsrc, output="pandas")
    mine = rastrum.zonal_stats(values, gdf, transform=t, stats=ops, weights=weights, nodata=-99)
    assert list(mine.index) == list(gdf.index)
    assert list(mine.columns) == ["count", "sum", "mean", "min", "max", "variety", "stdev", "median",
                                  "quantile_20", "weighted_mean", "weighted_sum", "majority", "minority"]
    for k, g in enumerate(polys):
        a, b = mine.iloc[k], theirs.iloc[k]
        # exactextract's fractions and results are float32 (2^-24 relative);
        # ours are off the exact area by at most 2^-16 px of vertex motion
        # times the perimeter in cells
        per = g.length / res
        for name in ("count", "sum", "weighted_sum"):
            tol = 2.0 ** -15 * per * (1 + np.abs(values).max()) + 2.0 ** -20 * abs(b[name])
            assert abs(a[name] - b[name]) <= tol, (k, name, a[name], b[name])
        for name in ("mean", "stdev", "median", "quantile_20", "weighted_mean"):
            if math.isnan(b[name]):
                assert math.isnan(a[name]), (k, name)
                continue
            # a ratio of sums whose numerator and denominator are each off
            # by the bounds above (values and weights at most 20 and 1);
            # stdev and the quantiles are held to the same bound
            tol = (2.0 ** -15 * per * 20 * 2 + 2.0 ** -20 * (abs(b["sum"]) + abs(b[name]) * b["count"])) \
                / b["count"]
            assert abs(a[name] - b[name]) <= tol, (k, name, a[name], b[name])
        for name in ("min", "max", "variety"):
            assert (a[name] == b[name]) or (math.isnan(a[name]) and math.isnan(b[name])), (k, name)
        for name in ("majority", "minority"):
            assert (a[name] == b[name]) or (math.isnan(a[name]) and math.isnan(b[name])), (k, name)


# ---- inputs, options and bad input ----------------------------------------------------------------

SQ = {"type": "Polygon", "coordinates": [[(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5), (0.5, 0.5)]]}


def test_bands_masks_and_coverage_weight():
    r = np.arange(16.0).reshape(4, 4)
    bands = np.stack([r, 10 * r])
    got = rastrum.zonal_stats(bands, [SQ], stats=["count", "mean"], output="records")[0]
    assert got == {"band_1_count": 4.0, "band_1_mean": 5.0, "band_2_count": 4.0, "band_2_mean": 50.0}
    # a masked cell is left out: (1, 1) = 5 with fraction 1
    m = np.ma.masked_array(r, mask=np.zeros_like(r, bool))
    m.mask[1, 1] = True
    got = rastrum.zonal_stats(m, [SQ], stats=["count", "sum"], output="records")[0]
    assert got == {"count": 3.0, "sum": 20.0 - 5.0}
    # every touched cell counts 1: the 3 x 3 cells, values 0..10
    got = rastrum.zonal_stats(r, [SQ], stats=["count", "mean"], coverage_weight="none", output="records")[0]
    assert got == {"count": 9.0, "mean": float(r[:3, :3].mean())}


def test_pandas_index_and_xarray():
    pd = pytest.importorskip("pandas")
    r = np.arange(16.0).reshape(4, 4)
    got = rastrum.zonal_stats(r, [SQ, SQ], stats="count mean")
    assert isinstance(got, pd.DataFrame) and list(got.columns) == ["count", "mean"]
    assert list(got.index) == [0, 1]
    xr = pytest.importorskip("xarray")
    pytest.importorskip("rioxarray")
    from affine import Affine
    da = xr.DataArray(r, dims=("y", "x")).rio.write_transform(Affine(2.0, 0, 10.0, 0, -2.0, 8.0))
    da = da.rio.write_nodata(5.0)
    world = {"type": "Polygon", "coordinates": [[(11.0, 7.0), (15.0, 7.0), (15.0, 3.0), (11.0, 3.0), (11.0, 7.0)]]}
    got = rastrum.zonal_stats(da, [world], stats=["count", "sum"], output="records")[0]
    assert got == {"count": 3.0, "sum": 15.0}  # SQ in pixels; the nodata 5 left out


def test_outside_and_empty():
    r = np.ones((4, 4))
    far = {"type": "Polygon", "coordinates": [[(50, 50), (60, 50), (60, 60), (50, 50)]]}
    got = rastrum.zonal_stats(r, [far], stats=["count", "sum", "mean", "min", "variety", "median",
                                                "majority"], output="records")[0]
    assert got["count"] == 0 and got["sum"] == 0 and got["variety"] == 0
    assert all(math.isnan(got[k]) for k in ("mean", "min", "median", "majority"))
    assert rastrum.zonal_stats(r, [], stats=["count"], output="records") == []


def test_far_outside_is_clipped():
    """A feature reaching 10^7 px outside the raster: clipped to its window
    (plus a cell), so S stays the window's, and the fractions are the same
    as the part of it near the raster."""
    r = np.arange(64.0).reshape(8, 8)
    big = {"type": "Polygon", "coordinates": [[(2.3, 3.1), (1e7, 3.1), (1e7, 5.7), (2.3, 5.7), (2.3, 3.1)]]}
    near = {"type": "Polygon", "coordinates": [[(2.3, 3.1), (9.0, 3.1), (9.0, 5.7), (2.3, 5.7), (2.3, 3.1)]]}
    a = rastrum.zonal_stats(r, [big], stats=["count", "sum"], output="records")
    b = rastrum.zonal_stats(r, [near], stats=["count", "sum"], output="records")
    # each side moves by at most 2^-17 px (S = 16): the area by at most the
    # perimeter in the raster times that
    assert a == b and abs(a[0]["count"] - (8 - 2.3) * 2.6) <= 2 * (5.7 + 2.6) * 2 ** -17


@pytest.mark.parametrize("kw, match", [
    ({"stats": ["nope"]}, "unknown statistic 'nope'"),
    ({"stats": []}, "stats is empty"),
    ({"stats": ["quantile(q=1.5)"]}, "must be in 0..1"),
    ({"stats": ["weighted_mean"]}, "need weights="),
    ({"stats": ["mean"], "weights": np.ones((3, 3))}, "weights: shape"),
    ({"coverage_weight": "area"}, "coverage_weight must be"),
    ({"output": "csv"}, "output must be"),
    ({"rule": "odd"}, "fill rule"),
    ({"transform": (1, 2, 0, 2, 4, 0)}, "not invertible"),
    ({"nodata": "x"}, "nodata 'x' is not a number"),
])
def test_bad_options(kw, match):
    with pytest.raises(InputError, match=match):
        rastrum.zonal_stats(np.ones((4, 4)), [SQ], **kw)


@pytest.mark.parametrize("raster, geoms, match", [
    (np.ones((4, 4)), [{"type": "LineString", "coordinates": [(0, 0), (1, 1)]}], "feature 0 is not a polygon"),
    (np.ones((4, 4)), [SQ, {"type": "Circle"}], "feature 1: unknown geometry type"),
    (np.ones((4, 4)), SQ, "not one geometry"),
    (np.ones(4), [SQ], "2-D"),
    (np.ones((0, 4)), [SQ], "non-empty"),
    (np.ones((4, 4), complex), [SQ], "not supported"),
    (np.ones((4, 4)), [{"type": "Polygon", "coordinates": [[(0, 0), (float("nan"), 1), (1, 1)]]}], "NaN"),
])
def test_bad_input(raster, geoms, match):
    with pytest.raises(InputError, match=match):
        rastrum.zonal_stats(raster, geoms)


InputError = rastrum.InputError

"""rastrum.rasterize: exact on the float64 pixel coordinates, rasterio's
semantics, rasterio's own cases, bad input.

The references are in tests/gis_reference.py (the exact oracle on the
unsnapped float64 pixel coordinates, GDAL's line and point rules written
out as loops).  Tests that compare with rasterio skip when it is not
installed (CI installs it: .ci/run).
"""

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import InputError
from gis_reference import add, burn_reference, pixel_coordinates
from oracle import oracle_mask

DTYPES = ["uint8", "int8", "uint16", "int16", "uint32", "int32", "int64", "float32", "float64"]

NORTH_UP = (0.5, 0.0, 100.0, 0.0, -0.5, 300.0)
_c, _s = math.cos(math.radians(30)), math.sin(math.radians(30))
# rotation(30 degrees) * (0.5, 0, 10, 0, -0.5, 30), multiplied out
ROTATED = (_c * 0.5, _s * 0.5, _c * 10 - _s * 30, _s * 0.5, -_c * 0.5, _s * 10 + _c * 30)
TRANSFORMS = {"north-up": NORTH_UP, "rotated": ROTATED}

H, W = 60, 80


def forward(t, pix):
    a, b, c, d, e, f = t
    return [(a * x + b * y + c, d * x + e * y + f) for x, y in pix]


def _ring(rng, cx, cy, r, n):
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    rad = r * rng.uniform(0.4, 1.0, n)
    pts = np.c_[cx + rad * np.cos(ang), cy + rad * np.sin(ang)]
    return np.vstack([pts, pts[:1]])


def random_shapes(seed, t, n=24, kinds=("polygon", "multipolygon")):
    """GeoJSON polygons with holes and multipolygons (overlapping parts
    too), in world coordinates under transform t, partly outside the
    raster."""
    rng = np.random.default_rng(seed)
    shapes = []
    for k in range(n):
        kind = kinds[k % len(kinds)]
        cx, cy = rng.uniform(-5, W + 5), rng.uniform(-5, H + 5)
        r = rng.uniform(2, 18)
        if kind in ("polygon", "multipolygon"):
            outer = _ring(rng, cx, cy, r, int(rng.integers(3, 11)))
            rings = [forward(t, outer)]
            if rng.random() < 0.6:
                rings.append(forward(t, _ring(rng, cx, cy, r * 0.3, int(rng.integers(3, 7)))[::-1]))
            if kind == "polygon":
                geom = {"type": "Polygon", "coordinates": rings}
            else:
                other = _ring(rng, cx + rng.uniform(-r, r), cy + rng.uniform(-r, r), r * 0.6, 5)
                geom = {"type": "MultiPolygon", "coordinates": [rings, [forward(t, other)]]}
        elif kind == "line":
            pts = rng.uniform([cx - r, cy - r], [cx + r, cy + r], (int(rng.integers(2, 6)), 2))
            geom = {"type": "LineString", "coordinates": forward(t, pts)}
        elif kind == "multiline":
            geom = {"type": "MultiLineString", "coordinates": [
                forward(t, rng.uniform([cx - r, cy - r], [cx + r, cy + r], (3, 2))) for _ in range(2)]}
        else:
            pts = rng.uniform([cx - r, cy - r], [cx + r, cy + r], (int(rng.integers(1, 6)), 2))
            pts = np.vstack([pts, pts[:1]])  # a repeated point
            geom = {"type": "MultiPoint", "coordinates": forward(t, pts)}
        shapes.append(geom)
    return shapes


def values_for(dtype, n, seed):
    rng = np.random.default_rng(seed)
    dt = np.dtype(dtype)
    if dt.kind == "f":
        return [float(v) for v in rng.normal(0, 1e3, n)]
    info = np.iinfo(dt)
    # large values, so that "add" saturates somewhere
    lo, hi = max(info.min, -2 ** 62), min(info.max, 2 ** 62)
    return [int(v) for v in rng.integers(lo // 3, hi // 3 + 1, n)]


# ---- the reference's own basis: the transform ----------------------------------------

def test_pixel_coordinates_is_gdals_inverse():
    world = forward(ROTATED, [(3.25, 7.5), (-1.0, 2.0)])
    assert np.array_equal(rastrum.gis.pixel_coordinates(np.array(world), ROTATED),
                          pixel_coordinates(world, ROTATED))
    # north-up: col = -c/a + x/a exactly as GDAL writes it
    got = rastrum.gis.pixel_coordinates(np.array([[101.5, 296.0]]), NORTH_UP)
    assert got.tolist() == [[-100.0 / 0.5 + 101.5 * (1 / 0.5) + 296.0 * 0.0,
                             -300.0 / -0.5 + 101.5 * 0.0 + 296.0 * (1 / -0.5)]]


# ---- exactness: 0 pixels off on random data -------------------------------------------

_MASKS = {}


def part_masks(seed, tname, rule="evenodd"):
    """Per shape, the list of its parts' exact masks (oracle, unsnapped)."""
    key = (seed, tname, rule)
    if key not in _MASKS:
        t = TRANSFORMS[tname]
        out = []
        for g in random_shapes(seed, t):
            polys = [g["coordinates"]] if g["type"] == "Polygon" else g["coordinates"]
            out.append([oracle_mask([pixel_coordinates(r, t) for r in p], (H, W), rule=rule, subpixel_bits=None)
                        for p in polys])
        _MASKS[key] = out
    return _MASKS[key]


@pytest.mark.parametrize("seed", [1, 2])
@pytest.mark.parametrize("tname", sorted(TRANSFORMS))
@pytest.mark.parametrize("merge", ["replace", "add"])
@pytest.mark.parametrize("dtype", DTYPES)
def test_exact_on_float_pixel_coordinates(seed, tname, merge, dtype):
    t = TRANSFORMS[tname]
    shapes = random_shapes(seed, t)
    vals = values_for(dtype, len(shapes), seed)
    fill = vals[0] if np.dtype(dtype).kind == "f" else 0
    got = rastrum.rasterize(list(zip(shapes, vals)), (H, W), fill=fill, transform=t, merge_alg=merge,
                            dtype=dtype)
    want = np.full((H, W), fill, dtype)
    for masks, v in zip(part_masks(seed, tname), vals):
        for m in masks:
            for r, c in zip(*np.nonzero(m)):
                want[r, c] = v if merge == "replace" else add(want[r, c], v, dtype)
    assert got.dtype == np.dtype(dtype)
    off = got != want
    assert not off.any(), "%d pixels off the exact rule, first at %s" % (off.sum(), np.argwhere(off)[:5].tolist())


@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_rule(rule):
    t = ROTATED
    shapes = random_shapes(3, t, n=12)
    got = rastrum.rasterize(shapes, (H, W), transform=t, rule=rule, dtype="uint8", merge_alg="add")
    want = burn_reference([(g, 1) for g in shapes], (H, W), t, "uint8", merge="add", rule=rule)
    assert np.array_equal(got, want)


@pytest.mark.parametrize("tname", sorted(TRANSFORMS))
@pytest.mark.parametrize("kinds", [("line",), ("multiline",), ("points",), ("polygon", "line", "points")])
@pytest.mark.parametrize("merge", ["replace", "add"])
@pytest.mark.parametrize("all_touched", [False, True])
def test_lines_points_and_all_touched(tname, kinds, merge, all_touched):
    t = TRANSFORMS[tname]
    shapes = [(g, k + 1) for k, g in enumerate(random_shapes(7, t, n=10, kinds=kinds))]
    got = rastrum.rasterize(shapes, (24, 30), transform=t, merge_alg=merge, all_touched=all_touched,
                            dtype="int32")
    want = burn_reference(shapes, (24, 30), t, "int32", merge=merge, all_touched=all_touched)
    assert np.array_equal(got, want), np.argwhere(got != want)[:5].tolist()


@pytest.mark.parametrize("all_touched", [False, True])
def test_all_touched_polygons(all_touched):
    t = NORTH_UP
    shapes = [(g, k + 1) for k, g in enumerate(random_shapes(11, t, n=8))]
    got = rastrum.rasterize(shapes, (20, 24), transform=t, all_touched=all_touched, dtype="int16")
    want = burn_reference(shapes, (20, 24), t, "int16", all_touched=all_touched)
    assert np.array_equal(got, want)


# Nasty cases: vertices on sample points and pixel corners, horizontal
# edges on sample rows, slivers, repeated points; identity and flipped.
# Coordinates on a 2^-16 grid (any grid up to 2^-32 is snapped exactly;
# a float64 vertex off it moves by up to 2^-33 px: test_snapping_is_the_limit).
_coord = st.one_of(st.integers(-2, 14).map(float), st.integers(-4, 28).map(lambda v: v / 2),
                   st.floats(-2, 14, allow_nan=False, width=64).map(lambda v: round(v * 65536) / 65536))
_ring_st = st.lists(st.tuples(_coord, _coord), min_size=3, max_size=7)


@given(rings=st.lists(_ring_st, min_size=1, max_size=3), flip=st.booleans(),
       merge=st.sampled_from(["replace", "add"]))
def test_nasty_polygons_exact(rings, flip, merge):
    t = (1.0, 0.0, 0.0, 0.0, -1.0, 12.0) if flip else (1.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    world = [forward(t, r) for r in rings]
    shapes = [({"type": "Polygon", "coordinates": [w]}, 3) for w in world]
    shapes.append(({"type": "Polygon", "coordinates": world}, 5))
    got = rastrum.rasterize(shapes, (12, 12), transform=t, merge_alg=merge, dtype="uint8")
    want = burn_reference(shapes, (12, 12), t, "uint8", merge=merge)
    assert np.array_equal(got, want)


def test_snapping_is_the_limit():
    """rasterize snaps vertices to 2^-32 px (the 64-bit path at S = 32): a
    vertex 1e-280 px below a sample row lands on it.  The exact rule on the unsnapped input would fill the top-left
    pixel's sample (0.5, 0.5) of this sliver; the snapped one does not."""
    tri = {"type": "Polygon", "coordinates": [[(0.0, 0.0), (0.0, -3.25e-280), (1.0, 1.0), (0.0, 0.0)]]}
    exact = burn_reference([(tri, 1)], (2, 2), (1.0, 0.0, 0.0, 0.0, 1.0, 0.0), "uint8")
    got = rastrum.rasterize([tri], (2, 2), dtype="uint8")
    assert exact[0, 0] == 1 and got[0, 0] == 0


# ---- the same as rasterio, except where rasterio is off the exact rule ------------------

def _rasterio():
    features = pytest.importorskip("rasterio.features")
    enums = pytest.importorskip("rasterio.enums")
    affine = pytest.importorskip("affine")
    return features.rasterize, enums.MergeAlg, affine.Affine


@pytest.mark.parametrize("tname", sorted(TRANSFORMS))
@pytest.mark.parametrize("merge", ["replace", "add"])
@pytest.mark.parametrize("all_touched", [False, True])
def test_against_rasterio(tname, merge, all_touched):
    rio_rasterize, MergeAlg, Affine = _rasterio()
    t = TRANSFORMS[tname]
    kinds = ("polygon", "multipolygon", "line", "multiline", "points")
    shapes = [(g, k + 1) for k, g in enumerate(random_shapes(21, t, n=25, kinds=kinds))]
    ours = rastrum.rasterize(shapes, (H, W), transform=Affine(*t), merge_alg=merge, all_touched=all_touched,
                             dtype="int32")
    theirs = rio_rasterize(shapes, (H, W), transform=Affine(*t), all_touched=all_touched, dtype="int32",
                           merge_alg=MergeAlg.add if merge == "add" else MergeAlg.replace)
    exact = burn_reference(shapes, (H, W), t, "int32", merge=merge, all_touched=all_touched)
    assert np.array_equal(ours, exact)
    differ = ours != theirs
    # Every difference is a pixel where rasterio is off the exact rule.
    assert np.array_equal(differ, theirs != exact)
    print("%s %s all_touched=%s: rastrum off %d, rasterio off %d"
          % (tname, merge, all_touched, (ours != exact).sum(), differ.sum()))


def test_rasterio_off_the_rule_on_a_sample_point():
    """Where GDAL's float intersection lands on a pixel centre it takes
    the pixel on the right of a crossing (left open, right closed: it
    fills from floor(x + 0.5)), the exact rule the one on the left: a
    triangle whose left edge passes through sample (2.5, 1.5)."""
    rio_rasterize, _, _ = _rasterio()
    tri = {"type": "Polygon", "coordinates": [[(1.5, 0.5), (3.5, 2.5), (6.0, 0.5), (1.5, 0.5)]]}
    ours = rastrum.rasterize([tri], (4, 7), dtype="uint8")
    theirs = rio_rasterize([tri], (4, 7), dtype="uint8")
    exact = burn_reference([(tri, 1)], (4, 7), (1.0, 0.0, 0.0, 0.0, 1.0, 0.0), "uint8")
    assert np.array_equal(ours, exact)
    # rasterio (GDAL 3.10) leaves out the two pixels whose centres the
    # left edge passes through: (1, 0) and (2, 1).
    assert (theirs != exact).sum() == 2 and exact[0, 1] == exact[1, 2] == 1 and theirs[0, 1] == theirs[1, 2] == 0
    print("exact:\n%s\nrasterio:\n%s" % (exact, theirs))


# ---- rasterio's own test cases (tests/test_features.py), facts written anew --------------

SQUARE = {"type": "Polygon", "coordinates": [[(2, 2), (2, 4.25), (4.25, 4.25), (4.25, 2), (2, 2)]]}


def _image(cells, value=1, dtype="uint8", shape=(10, 10)):
    a = np.zeros(shape, dtype)
    for sl in cells:
        a[sl] = value
    return a


CASES = [
    ("point", [{"type": "Point", "coordinates": (2, 2)}], {}, _image([(2, 2)])),
    ("multipoint", [{"type": "MultiPoint", "coordinates": ((2, 2), (4, 4))}], {}, _image([(2, 2), (4, 4)])),
    ("line", [{"type": "LineString", "coordinates": ((2, 2), (4, 4))}], {}, _image([(2, 2), (3, 3), (4, 4)])),
    ("multiline", [{"type": "MultiLineString", "coordinates": (((2, 2), (4, 4)), ((0, 0), (4, 0)))}], {},
     _image([(2, 2), (3, 3), (4, 4), (0, slice(0, 5))])),
    ("polygon", [SQUARE], {}, _image([(slice(2, 4), slice(2, 4))])),
    ("multipolygon", [{"type": "MultiPolygon", "coordinates": (
        (((2, 2), (2, 4), (4, 4), (4, 2), (2, 2)),), (((0, 0), (0, 1), (1, 1), (1, 0), (0, 0)),))}], {},
     _image([(slice(0, 1), slice(0, 1)), (slice(2, 4), slice(2, 4))])),
    ("geometrycollection", [{"type": "GeometryCollection", "geometries": [
        {"type": "Polygon", "coordinates": (((2, 2), (2, 4), (4, 4), (4, 2), (2, 2)),)},
        {"type": "Polygon", "coordinates": (((0, 0), (0, 1), (1, 1), (1, 0), (0, 0)),)}]}], {},
     _image([(slice(0, 1), slice(0, 1)), (slice(2, 4), slice(2, 4))])),
    ("all_touched", [SQUARE], {"all_touched": True}, _image([(slice(2, 5), slice(2, 5))])),
    ("merge add", [SQUARE, SQUARE], {"merge_alg": "add"}, _image([(slice(2, 4), slice(2, 4))], 2)),
    ("value", [(SQUARE, 5)], {}, _image([(slice(2, 4), slice(2, 4))], 5)),
    ("default_value", [SQUARE], {"default_value": 2}, _image([(slice(2, 4), slice(2, 4))], 2)),
    ("value None burns fill", [(SQUARE, None)], {"fill": 2}, np.full((10, 10), 2)),
    ("fill", [SQUARE], {"fill": 1, "default_value": 2}, _image([(slice(2, 4), slice(2, 4))]) + 1),
    ("int64 value", [SQUARE], {"default_value": 1000000000000},
     _image([(slice(2, 4), slice(2, 4))], 1000000000000, "int64")),
    ("int64 fill", [SQUARE], {"fill": 1000000000000, "default_value": 2},
     np.where(_image([(slice(2, 4), slice(2, 4))]) == 1, 2, 1000000000000)),
]


@pytest.mark.parametrize("name,shapes,kw,expected", CASES, ids=[c[0] for c in CASES])
def test_rasterio_case(name, shapes, kw, expected):
    got = rastrum.rasterize(shapes, out_shape=(10, 10), **kw)
    assert np.array_equal(got, expected)


def test_rasterio_case_no_hole_where_parts_overlap():
    a = (((0, 0), (0, 5), (5, 5), (5, 0), (0, 0)),)
    b = (((2, 2), (2, 7), (7, 7), (7, 2), (2, 2)),)
    polys = [{"type": "Polygon", "coordinates": a}, {"type": "Polygon", "coordinates": b}]
    expected = rastrum.rasterize(polys, out_shape=(10, 10))
    assert expected[3, 3] == 1 and expected.sum() == 25 + 25 - 9
    assert np.array_equal(rastrum.rasterize([{"type": "MultiPolygon", "coordinates": [a, b]}], out_shape=(10, 10)),
                          expected)
    assert np.array_equal(rastrum.rasterize([{"type": "GeometryCollection", "geometries": polys}],
                                            out_shape=(10, 10)), expected)


def test_rasterio_case_geo_interface_and_out():
    class Geo:
        __geo_interface__ = SQUARE

    assert rastrum.rasterize([Geo()], out_shape=(10, 10)).sum() == 4
    out = np.zeros((10, 10))
    assert rastrum.rasterize([SQUARE], out=out) is out
    assert np.array_equal(out, _image([(slice(2, 4), slice(2, 4))]))
    out = np.zeros((10, 10), np.int64)  # int64 out is supported
    rastrum.rasterize([SQUARE], out=out)
    assert out.sum() == 4


@pytest.mark.parametrize("dtype,value", [("int16", -32768), ("int32", -2147483648), ("uint32", 4294967295),
                                         ("uint8", 255), ("uint16", 65535), ("float32", 1.434532),
                                         ("float64", -98332.133422114), ("int8", -127)])
def test_rasterio_case_supported_dtype(dtype, value):
    truth = np.zeros((10, 10), dtype)
    truth[2:4, 2:4] = value
    got = rastrum.rasterize([SQUARE], out_shape=(10, 10), default_value=value, dtype=dtype)
    assert got.dtype == np.dtype(dtype) and np.array_equal(got, truth)
    got = rastrum.rasterize([(SQUARE, value)], out_shape=(10, 10))  # dtype from the value
    assert got.dtype == (np.float64 if isinstance(value, float) else np.int64)
    truth = np.zeros((10, 10), got.dtype)
    truth[2:4, 2:4] = value
    assert np.array_equal(got, truth)


def test_rasterio_case_symmetric_with_shapes():
    """A square of pixels [2:5, 2:5] as a polygon under a y-flipped
    transform (1, 0, 0, 0, -1, 0) burns back to the same pixels."""
    truth = np.zeros((10, 10), np.uint8)
    truth[2:5, 2:5] = 1
    square = {"type": "Polygon", "coordinates": [[(2, -2), (2, -5), (5, -5), (5, -2), (2, -2)]]}
    got = rastrum.rasterize([square], out_shape=(10, 10), transform=(1.0, 0.0, 0.0, 0.0, -1.0, 0.0), dtype="uint8")
    assert np.array_equal(got, truth)


def test_rasterio_case_numpy_coordinates_far_outside():
    """rasterio issue 2385: lines with numpy coordinates, all outside."""
    lines = [({"type": "LineString", "coordinates": np.array(
        [[425596.0123443, 4932971.35636043], [425598.03434254, 4932966.09916503],
         [425592.56573176, 4932963.99585319], [425596.0123443, 4932971.35636043]])}, 2)]
    out = rastrum.rasterize(lines, out_shape=(100, 100))
    assert out.shape == (100, 100) and not out.any()


# ---- inputs: shapely, GeoSeries, GeoDataFrame, MergeAlg, Affine, progress ----------------

def test_shapely_and_geojson_give_the_same():
    shapely = pytest.importorskip("shapely")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    shapes = random_shapes(5, ROTATED, n=12, kinds=("polygon", "multipolygon", "line", "points"))
    geo = [shapely_geometry.shape(g) for g in shapes]
    assert all(isinstance(g, shapely.Geometry) for g in geo)
    a = rastrum.rasterize([(g, k + 1) for k, g in enumerate(geo)], (H, W), transform=ROTATED, merge_alg="add")
    b = rastrum.rasterize([(g, k + 1) for k, g in enumerate(shapes)], (H, W), transform=ROTATED, merge_alg="add")
    assert np.array_equal(a, b) and a.any()
    gc = shapely.GeometryCollection(geo[:4])
    c = rastrum.rasterize([gc], (H, W), transform=ROTATED, merge_alg="add")
    d = rastrum.rasterize(geo[:4], (H, W), transform=ROTATED, merge_alg="add")
    assert np.array_equal(c, d)


def test_geodataframe_and_geoseries():
    gpd = pytest.importorskip("geopandas")
    shapely_geometry = pytest.importorskip("shapely.geometry")
    shapes = random_shapes(6, NORTH_UP, n=10)
    geo = [shapely_geometry.shape(g) for g in shapes]
    df = gpd.GeoDataFrame({"v": list(range(1, 11))}, geometry=geo)
    want = rastrum.rasterize(list(zip(geo, range(1, 11))), (H, W), transform=NORTH_UP)
    assert np.array_equal(rastrum.rasterize(df, (H, W), transform=NORTH_UP, values="v"), want)
    assert np.array_equal(rastrum.rasterize(df.geometry, (H, W), transform=NORTH_UP, values=list(range(1, 11))), want)
    assert np.array_equal(rastrum.rasterize(df.geometry, (H, W), transform=NORTH_UP),
                          rastrum.rasterize(geo, (H, W), transform=NORTH_UP))


def test_affine_and_mergealg_objects():
    affine = pytest.importorskip("affine")
    enums = pytest.importorskip("rasterio.enums")
    shapes = random_shapes(8, NORTH_UP, n=6)
    gt = (100.0, 0.5, 0.0, 300.0, 0.0, -0.5)  # the GDAL geotransform of NORTH_UP
    a = rastrum.rasterize(shapes, (H, W), transform=affine.Affine.from_gdal(*gt), merge_alg=enums.MergeAlg.add)
    b = rastrum.rasterize(shapes, (H, W), transform=NORTH_UP, merge_alg="add")
    assert np.array_equal(a, b) and a.any()


def test_progress_callable_and_tqdm():
    shapes = random_shapes(9, NORTH_UP, n=30)
    seen = []
    a = rastrum.rasterize(shapes, (H, W), transform=NORTH_UP, progress=lambda done, total: seen.append((done, total)))
    assert seen and seen[-1] == (30, 30) and all(t == 30 for _, t in seen)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)
    assert np.array_equal(a, rastrum.rasterize(shapes, (H, W), transform=NORTH_UP))
    pytest.importorskip("tqdm")
    assert np.array_equal(a, rastrum.rasterize(shapes, (H, W), transform=NORTH_UP, progress=True))


def test_out_views_and_empty_shapes():
    big = np.full((30, 40), 9, np.int16)
    view = big[5:25, 3:33].T  # transposed: burnt through a copy, written back
    rastrum.rasterize([SQUARE], out=view, default_value=7)
    assert (big[5 + 2:5 + 4, 3 + 2:3 + 4] == 7).all() and (big == 7).sum() == 4
    assert np.array_equal(rastrum.rasterize([], out_shape=(3, 4), fill=5), np.full((3, 4), 5))


def test_typed_package():
    import os
    assert os.path.exists(os.path.join(os.path.dirname(rastrum.__file__), "py.typed"))
    hints = rastrum.rasterize.__annotations__
    assert {"shapes", "out_shape", "transform", "return"} <= set(hints)


# ---- bad input: InputError naming the feature and problem; out untouched -----------------

GOOD = {"type": "Polygon", "coordinates": [[(1, 1), (5, 1), (5, 4), (1, 1)]]}
INF = float("inf")
NAN = float("nan")

BAD = [
    # (label, shapes, keywords, message pattern)
    ("unknown type", [GOOD, {"type": "Circle", "coordinates": [1, 2]}], {}, r"feature 1: unknown geometry type Circle"),
    ("no type", [{"coordinates": [1, 2]}], {}, r"feature 0: unknown geometry type None"),
    ("not a geometry", [GOOD, 42], {}, r"feature 1: 'int' is not a geometry"),
    ("None geometry", [GOOD, None], {}, r"feature 1 is None"),
    ("empty polygon", [GOOD, {"type": "Polygon", "coordinates": []}], {}, r"feature 1: empty Polygon"),
    ("empty ring", [{"type": "Polygon", "coordinates": [[]]}], {}, r"feature 0: Polygon ring 0 is empty"),
    ("empty collection", [{"type": "GeometryCollection", "geometries": []}], {}, r"feature 0: empty GeometryCollection"),
    ("empty point", [{"type": "Point", "coordinates": []}], {}, r"feature 0: empty Point"),
    ("no coordinates", [{"type": "Point"}], {}, r"feature 0: Point without 'coordinates'"),
    ("ring of 2", [{"type": "Polygon", "coordinates": [[(0, 0), (1, 1)]]}], {}, r"feature 0: Polygon ring 0 has 2 position"),
    ("line of 1", [GOOD, GOOD, {"type": "LineString", "coordinates": [(0, 0)]}], {}, r"feature 2: LineString has 1 position"),
    ("bad position", [{"type": "LineString", "coordinates": [(0, 0), (1,)]}], {}, r"feature 0: LineString: positions"),
    ("string coordinates", [{"type": "LineString", "coordinates": [("a", "b"), (1, 2)]}], {}, r"feature 0: LineString: positions"),
    ("NaN", [GOOD, {"type": "Point", "coordinates": (NAN, 1.0)}], {}, r"feature 1: position \(nan, 1.0\) is NaN"),
    ("inf", [{"type": "LineString", "coordinates": [(0, 0), (1, INF)]}], {}, r"feature 0: position \(1.0, inf\) is infinite"),
    ("out of range", [{"type": "Point", "coordinates": (1e300, 1.0)}], {}, r"feature 0: position \(1e\+300, 1.0\) .*outside the range"),
    ("value too big", [(GOOD, 300)], {"dtype": "uint8"}, r"feature 0: value 300 does not fit dtype uint8"),
    ("value negative", [GOOD, (GOOD, -1)], {"dtype": "uint16"}, r"feature 1: value -1 does not fit dtype uint16"),
    ("value fraction", [(GOOD, 3.2423)], {"dtype": "uint8"}, r"feature 0: value 3.2423 does not fit dtype uint8 \(not a whole"),
    ("value NaN int", [(GOOD, NAN)], {"dtype": "int32"}, r"feature 0: value nan does not fit dtype int32"),
    ("value float32", [(GOOD, 1e300)], {"dtype": "float32"}, r"feature 0: value 1e\+300 does not fit dtype float32"),
    ("value str", [(GOOD, "5")], {}, r"feature 0: value '5' is not a real number"),
    ("value huge int", [(GOOD, 1), (GOOD, 10 ** 400)], {"dtype": "float64"}, r"feature 1: value 1000.* does not fit dtype float64"),
    ("value numpy", [(GOOD, np.int64(1)), (GOOD, np.int64(-1))], {"dtype": "uint8"}, r"feature 1: value -1 does not fit"),
    ("value bool", [(GOOD, True)], {}, r"feature 0: value True is not a real number"),
    ("default_value", [GOOD], {"default_value": -2147483648, "dtype": "uint8"}, r"feature 0: value -2147483648 does not fit"),
    ("fill", [GOOD], {"fill": 1000000, "dtype": "uint8"}, r"fill 1000000 does not fit dtype uint8"),
    ("triple", [(GOOD, 1, 2)], {}, r"feature 0 is a sequence of 3 items"),
    ("one geometry", GOOD, {}, r"not one geometry; wrap it in a list"),
    ("not iterable", 5, {}, r"shapes must be an iterable"),
    ("dtype float16", [GOOD], {"dtype": "float16"}, r"dtype float16 is not supported"),
    ("dtype complex64", [GOOD], {"dtype": "complex64"}, r"dtype complex64 is not supported"),
    ("dtype bool", [GOOD], {"dtype": bool}, r"dtype bool is not supported"),
    ("dtype nonsense", [GOOD], {"dtype": "nonsense"}, r"dtype 'nonsense' is not a numpy dtype"),
    ("transform 5 numbers", [GOOD], {"transform": (1, 0, 0, 0, 1)}, r"transform must be 6 numbers"),
    ("transform None", [GOOD], {"transform": None}, r"transform must be an affine.Affine or 6 numbers"),
    ("transform singular", [GOOD], {"transform": (1, 2, 0, 2, 4, 0)}, r"is not invertible"),
    ("transform zero", [GOOD], {"transform": (0, 0, 0, 0, 0, 0)}, r"is not invertible"),
    ("transform NaN", [GOOD], {"transform": (1, 0, NAN, 0, 1, 0)}, r"transform: nan is not finite"),
    ("transform str", [GOOD], {"transform": (1, 0, "x", 0, 1, 0)}, r"transform: 'x' is not a real number"),
    ("transform 3x3 row", [GOOD], {"transform": (1, 0, 0, 0, 1, 0, 0, 1, 1)}, r"last row"),
    ("merge_alg", [GOOD], {"merge_alg": "max"}, r"unknown merge_alg 'max'"),
    ("rule", [GOOD], {"rule": "winding"}, r"unknown fill rule 'winding'"),
    ("all_touched", [GOOD], {"all_touched": "yes"}, r"all_touched must be True or False"),
    ("progress", [GOOD], {"progress": "bar"}, r"progress must be True, False, None or a callable"),
    ("values column", [GOOD], {"values": "v"}, r"a column name needs a GeoDataFrame"),
    ("values count", [GOOD, GOOD], {"values": [1]}, r"values: 1 value for 2 shapes"),
]

BAD_SHAPE = [
    ("out_shape missing", {}, r"either out_shape or out must be given"),
    ("out_shape 3-D", {"out_shape": (1, 10, 10)}, r"Invalid out_shape"),
    ("out_shape 1-D", {"out_shape": (10,)}, r"Invalid out_shape"),
    ("out_shape zero", {"out_shape": (0, 10)}, r"must be > 0"),
    ("out_shape negative", {"out_shape": (10, -1)}, r"must be > 0"),
    ("out_shape float", {"out_shape": (10.0, 10)}, r"must hold two ints"),
    ("out_shape huge", {"out_shape": (2 ** 31, 10)}, r"at most"),
    ("out not an array", {"out": [[0, 0], [0, 0]]}, r"out must be a numpy array"),
    ("out 3-D", {"out": np.zeros((2, 3, 4), np.uint8)}, r"out must be 2-D"),
    ("out empty", {"out": np.zeros((0, 3), np.uint8)}, r"must be > 0"),
    ("out float16", {"out": np.zeros((3, 4), np.float16)}, r"dtype float16 is not supported"),
    ("out big-endian", {"out": np.zeros((3, 4), ">i4")}, r"is not supported"),
    ("out and dtype differ", {"out": np.zeros((3, 4), np.uint8), "dtype": "int16"}, r"differs from out's dtype"),
    ("out and out_shape differ", {"out": np.zeros((3, 4), np.uint8), "out_shape": (4, 3)}, r"differs from out's shape"),
]


@pytest.mark.parametrize("label,shapes,kw,pattern", BAD, ids=[r[0] for r in BAD])
def test_bad_input(label, shapes, kw, pattern):
    dtype = kw.get("dtype", "int32")
    try:
        dt = np.dtype(dtype)
        ok = dt.name in DTYPES
    except TypeError:
        ok = False
    out = np.arange(48, dtype=dtype if ok else "int32").reshape(6, 8)
    before = out.copy()
    kw = dict(kw)
    if ok:
        kw.pop("dtype", None)
    with pytest.raises(InputError, match=pattern):
        rastrum.rasterize(shapes, out=out, **kw)
    assert np.array_equal(out, before), "out was written"
    # the same with out_shape: the same error
    kw2 = {k: v for k, v in kw.items()}
    if ok:
        kw2["dtype"] = dtype
    with pytest.raises(ValueError, match=pattern):
        rastrum.rasterize(shapes, out_shape=(6, 8), **kw2)


@pytest.mark.parametrize("label,kw,pattern", BAD_SHAPE, ids=[r[0] for r in BAD_SHAPE])
def test_bad_out_and_shape(label, kw, pattern):
    before = kw["out"].copy() if isinstance(kw.get("out"), np.ndarray) else None
    with pytest.raises(InputError, match=pattern):
        rastrum.rasterize([GOOD], **kw)
    if before is not None:
        assert np.array_equal(kw["out"], before)


def test_read_only_out():
    out = np.zeros((3, 4), np.uint8)
    out.setflags(write=False)
    with pytest.raises(InputError, match="read-only"):
        rastrum.rasterize([GOOD], out=out)


def test_bad_shapely_inputs():
    shapely = pytest.importorskip("shapely")
    good = shapely.box(1, 1, 4, 3)
    out = np.full((6, 8), 3, np.uint8)
    for shapes, pattern in [([good, shapely.Polygon()], r"feature 1: empty Polygon"),
                            ([good, shapely.GeometryCollection([good, shapely.LineString()])], r"feature 1: empty"),
                            ([good, shapely.MultiPolygon()], r"feature 1: empty MultiPolygon"),
                            ([good, good, shapely.GeometryCollection([good, shapely.MultiPoint()])],
                             r"feature 2: empty"),
                            ([good, shapely.Point(np.nan, 1)], r"feature 1: position \(nan, 1.0\) is NaN"),
                            ([good, shapely.LinearRing([(0, 0), (1, 0), (1, 1)]), None], r"feature 2 is None")]:
        with pytest.raises(InputError, match=pattern):
            rastrum.rasterize(shapes, out=out)
        assert (out == 3).all()


@pytest.mark.parametrize("all_touched", [False, True])
def test_add_counts_a_line_once_per_geometry(all_touched):
    """In "add", a (Multi)LineString burns each pixel once, a collection's
    members are geometries of their own, a MultiPoint adds per point."""
    line = [(0.5, 1.5), (3.5, 1.5)]
    shapes = [
        {"type": "MultiLineString", "coordinates": [line, line]},
        {"type": "LineString", "coordinates": line + [(0.5, 1.5)]},
        {"type": "GeometryCollection", "geometries": [{"type": "LineString", "coordinates": line}] * 2},
        {"type": "MultiPoint", "coordinates": [(1.5, 1.5), (1.5, 1.5)]},
    ]
    got = rastrum.rasterize(shapes, (3, 4), merge_alg="add", all_touched=all_touched, dtype="uint8")
    want = burn_reference([(g, 1) for g in shapes], (3, 4), (1.0, 0.0, 0.0, 0.0, 1.0, 0.0), "uint8",
                          merge="add", all_touched=all_touched)
    assert np.array_equal(got, want)
    assert got[1].tolist() == [4, 6, 4, 4]
    try:
        rio_rasterize, MergeAlg, _ = _rasterio()
    except pytest.skip.Exception:
        return
    assert np.array_equal(got, rio_rasterize(shapes, (3, 4), merge_alg=MergeAlg.add, all_touched=all_touched,
                                             dtype="uint8"))


def test_long_lines_cross_the_raster():
    """Segments 10^8 px long: only their steps inside the raster are
    walked; the pixels are GDAL's (row 5 across; the diagonal)."""
    lines = [{"type": "LineString", "coordinates": [(-1e8, 5.5), (1e8, 5.5)]},
             {"type": "LineString", "coordinates": [(-1e8 + 0.5, -1e8 + 0.5), (1e8 + 0.5, 1e8 + 0.5)]}]
    got = rastrum.rasterize([(lines[0], 1), (lines[1], 2)], (8, 9), dtype="uint8")
    want = np.zeros((8, 9), np.uint8)
    want[5, :] = 1
    for i in range(8):
        want[i, i] = 2
    assert np.array_equal(got, want)

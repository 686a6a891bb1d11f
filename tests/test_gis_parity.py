"""rasterio parity: rasterize(nodata=, masked=, skip_invalid=), uint64,
geometry_mask, geometry_window and grid (gdal_rasterize -te/-tr/-tap).

The cases of rasterio's own tests/test_features.py are ported as facts
(the expected arrays and windows written out here); each is also compared
with rasterio itself in the same test when rasterio is installed.  Bad
input is an InputError with `out` untouched."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import InputError
from rastrum.gis import ShapeSkipWarning, Window

import strategies as S_

try:
    import rasterio.features as rf
    from rasterio.errors import ShapeSkipWarning as RioSkip, WindowError
    from affine import Affine
except ImportError:  # pragma: no cover
    rf = None

SHAPE = (10, 10)
IDENT = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0)
# rasterio's fixtures (tests/conftest.py there)
BASIC = {"type": "Polygon", "coordinates": [[(2, 2), (2, 4.25), (4.25, 4.25), (4.25, 2), (2, 2)]]}
MULTIPOINT = {"type": "MultiPoint", "coordinates": ((2, 2), (4, 4))}


def basic_2x2():
    image = np.zeros(SHAPE, np.uint8)
    image[2:4, 2:4] = 1
    return image


def rio(fn, *args, **kw):
    """rasterio's result, its warnings silenced, or None without rasterio."""
    if rf is None:
        return None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return getattr(rf, fn)(*args, **kw)


# ---- geometry_mask -------------------------------------------------------------------------

def test_geometry_mask():
    got = rastrum.geometry_mask([BASIC], out_shape=SHAPE, transform=IDENT)
    assert got.dtype == bool and np.array_equal(got, basic_2x2() == 0)
    theirs = rio("geometry_mask", [BASIC], out_shape=SHAPE, transform=Affine.identity()) if rf else None
    if theirs is not None:
        assert np.array_equal(got, theirs)


def test_geometry_mask_invert():
    got = rastrum.geometry_mask([BASIC], out_shape=SHAPE, transform=IDENT, invert=True)
    assert np.array_equal(got, basic_2x2().astype(bool))
    if rf is not None:
        assert np.array_equal(got, rio("geometry_mask", [BASIC], out_shape=SHAPE, transform=Affine.identity(),
                                       invert=True))


def test_geometry_mask_all_touched():
    got = rastrum.geometry_mask([BASIC], SHAPE, IDENT, all_touched=True, invert=True)
    want = np.zeros(SHAPE, bool)
    want[2:5, 2:5] = True  # rasterio's basic_image: the all_touched burn of BASIC
    assert np.array_equal(got, want)
    if rf is not None:
        assert np.array_equal(got, rio("geometry_mask", [BASIC], SHAPE, Affine.identity(), all_touched=True,
                                       invert=True))


@pytest.mark.parametrize("shape", [(0, 0), (1, 0), (0, 1)])
def test_geometry_mask_invalid_shape(shape):
    with pytest.raises(InputError, match="must be > 0"):
        rastrum.geometry_mask([BASIC], out_shape=shape, transform=IDENT)


@pytest.mark.parametrize("geom", [{"type": "Invalid"}, {"type": "Point"}, {"type": "Point", "coordinates": []}])
def test_geometry_mask_invalid_geom(geom):
    # rasterio's test_geometry_invalid_geom: a ValueError (rasterio: "No
    # valid geometry objects found", after a ShapeSkipWarning); rastrum's
    # InputError (a ValueError) names the feature
    with pytest.raises(InputError, match="feature 0"):
        rastrum.geometry_mask([geom], out_shape=SHAPE, transform=IDENT)


def test_geometry_mask_no_transform():
    # rasterio raises TypeError; rastrum's InputError names the argument
    with pytest.raises(InputError, match="transform"):
        rastrum.geometry_mask([BASIC], out_shape=SHAPE, transform=None)


@settings(max_examples=S_.examples(30))
@given(st.integers(0, 2 ** 32 - 1), st.integers(3, 9), st.booleans(), st.booleans())
def test_geometry_mask_random_against_rasterio(seed, n, all_touched, invert):
    """Random (uniform float) polygons: the same mask as rasterio's.  The
    exact rule and GDAL differ only on borderline input (a sample within
    float rounding of an edge, edges along pixel borders under all_touched:
    docs/gis.md), which uniform random floats do not produce."""
    if rf is None:
        pytest.skip("rasterio not installed")
    pts = np.random.default_rng(seed).uniform(-2, 12, (n, 2)).tolist()
    poly = {"type": "Polygon", "coordinates": [pts + [pts[0]]]}
    t = (0.5, 0.0, 3.0, 0.0, -0.5, 8.0)
    world = {"type": "Polygon", "coordinates": [[(3.0 + 0.5 * x, 8.0 - 0.5 * y) for x, y in pts + [pts[0]]]]}
    got = rastrum.geometry_mask([world], SHAPE, t, all_touched=all_touched, invert=invert)
    theirs = rio("geometry_mask", [world], SHAPE, Affine(*t), all_touched=all_touched, invert=invert)
    assert np.array_equal(got, theirs)
    assert poly


# ---- geometry_window -------------------------------------------------------------------------------

class Dataset:
    """A dataset-like: what geometry_window reads of a rasterio dataset."""

    def __init__(self, transform, height, width):
        self.transform, self.height, self.width = transform, height, width


def same_window(got, theirs):
    assert isinstance(got, Window)
    if theirs is not None:
        assert got.astuple() == (theirs.col_off, theirs.row_off, theirs.width, theirs.height)


def flatten(w):
    """rasterio's Window.flatten(): (col_off, row_off, width, height)."""
    return w.astuple()


def rio_window(ds, shapes, **kw):
    if rf is None:
        return None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PendingDeprecationWarning)  # inside rasterio 1.4 with affine 3.1
        return rf.geometry_window(Dataset(Affine(*ds.transform), ds.height, ds.width), shapes, **kw)


def test_geometry_window_no_pad():
    ds = Dataset(IDENT, 10, 10)
    got = rastrum.geometry_window(ds, [BASIC, BASIC])
    assert flatten(got) == (2, 2, 3, 3)
    same_window(got, rio_window(ds, [BASIC, BASIC]))


def test_geometry_window_geo_interface_and_pair():
    class Geo:
        __geo_interface__ = BASIC
    assert flatten(rastrum.geometry_window(Dataset(IDENT, 10, 10), [Geo()])) == (2, 2, 3, 3)
    assert flatten(rastrum.geometry_window(((10, 10), IDENT), [Geo()])) == (2, 2, 3, 3)


def test_geometry_window_pixel_precision():
    """Offsets are floors, width and height ceilings (pixel_precision is ignored, as in rasterio 1.4)."""
    geom2 = {"type": "Polygon", "coordinates": [[(1.99999, 2), (1.99999, 4.0001), (4.0001, 4.0001),
                                                  (4.0001, 2), (1.99999, 2)]]}
    ds = Dataset(IDENT, 10, 10)
    got = rastrum.geometry_window(ds, [geom2], pixel_precision=6)
    assert flatten(got) == (1, 2, 4, 3)
    same_window(got, rio_window(ds, [geom2], pixel_precision=6))


def test_geometry_window_north_up():
    # rasterio's RGB.byte.tif grid
    ds = Dataset((300.0379266750948, 0.0, 101985.0, 0.0, -300.041782729805, 2826915.0), 718, 791)
    geometry = {"type": "Polygon", "coordinates": [[(200000, 2700000), (200000, 2750000), (250000, 2750000),
                                                    (250000, 2700000), (200000, 2700000)]]}
    got = rastrum.geometry_window(ds, [geometry])
    assert flatten(got) == (326, 256, 168, 167)
    same_window(got, rio_window(ds, [geometry]))


def test_geometry_window_rotated_boundless():
    s2 = math.sqrt(2.0)
    # Affine.rotation(-45) * translation(-s2, s2) * scale(s2/2, -s2/2), multiplied out
    c, s = math.cos(math.radians(-45.0)), math.sin(math.radians(-45.0))
    a, e = s2 / 2.0, -s2 / 2.0
    t = (c * a, -s * e, c * -s2 - s * s2, s * a, c * e, s * -s2 + c * s2)
    if rf is not None:
        t = tuple(Affine.rotation(-45.0) @ Affine.translation(-s2, s2) @ Affine.scale(s2 / 2.0, -s2 / 2.0))[:6]
    ds = Dataset(t, 4, 4)
    geometry = {"type": "Polygon", "coordinates": [[(-2.0, -2.0), (-2.0, 2.0), (2.0, 2.0), (2.0, -2.0),
                                                    (-2.0, -2.0)]]}
    got = rastrum.geometry_window(ds, [geometry, geometry], boundless=True)
    assert (got.col_off, got.row_off, got.width, got.height) == (-2, -2, 8, 8)
    same_window(got, rio_window(ds, [geometry, geometry], boundless=True))


def test_geometry_window_pad():
    ds = Dataset(IDENT, 10, 10)
    got = rastrum.geometry_window(ds, [BASIC], pad_x=0.5, pad_y=0.5)
    assert flatten(got) == (1, 1, 4, 4)
    same_window(got, rio_window(ds, [BASIC], pad_x=0.5, pad_y=0.5))


def test_geometry_window_large_shapes():
    ds = Dataset(IDENT, 10, 10)
    geometry = {"type": "Polygon", "coordinates": [[(-2000, -2000), (-2000, 2000), (2000, 2000), (2000, -2000),
                                                    (-2000, -2000)]]}
    got = rastrum.geometry_window(ds, [geometry])
    assert flatten(got) == (0, 0, 10, 10)
    same_window(got, rio_window(ds, [geometry]))


def test_geometry_window_no_overlap():
    ds = Dataset((300.0379266750948, 0.0, 101985.0, 0.0, -300.041782729805, 2826915.0), 718, 791)
    with pytest.raises(InputError, match="does not overlap"):
        rastrum.geometry_window(ds, [BASIC])
    if rf is not None:
        with pytest.raises(WindowError):
            rio_window(ds, [BASIC])


def test_geometry_window_slices():
    w = rastrum.geometry_window(((10, 10), IDENT), [BASIC])
    a = np.arange(100).reshape(10, 10)
    assert np.array_equal(a[w.toslices()], a[2:5, 2:5])
    assert w.toranges() == ((2, 5), (2, 5))


@settings(max_examples=S_.examples(60))
@given(st.lists(st.tuples(st.floats(-30, 30), st.floats(-30, 30)), min_size=1, max_size=6),
       st.floats(0.01, 5), st.floats(-5, 5), st.floats(-5, 5), st.floats(0, 2), st.floats(0, 2),
       st.booleans(), st.booleans())
def test_geometry_window_random_against_rasterio(pts, res, x0, y0, pad_x, pad_y, boundless, rotate):
    if rf is None:
        pytest.skip("rasterio not installed")
    t = (res, 0.0, x0, 0.0, -res, y0) if not rotate else (res, 0.3 * res, x0, -0.2 * res, -res, y0)
    ds = Dataset(t, 17, 23)
    geom = {"type": "LineString", "coordinates": pts + pts[:1]} if len(pts) > 1 else \
        {"type": "Point", "coordinates": pts[0]}
    try:
        theirs = rio_window(ds, [geom], pad_x=pad_x, pad_y=pad_y, boundless=boundless)
    except WindowError:
        with pytest.raises(InputError, match="does not overlap"):
            rastrum.geometry_window(ds, [geom], pad_x=pad_x, pad_y=pad_y, boundless=boundless)
        return
    got = rastrum.geometry_window(ds, [geom], pad_x=pad_x, pad_y=pad_y, boundless=boundless)
    same_window(got, theirs)


@pytest.mark.parametrize("args, match", [
    ((None, [BASIC]), "dataset must have"),
    ((((10, 10), IDENT), []), "no shapes"),
    ((((0, 10), IDENT), [BASIC]), "must be > 0"),
    ((((10, 10), (1, 2, 0, 2, 4, 0)), [BASIC]), "not invertible"),
    ((((10, 10), IDENT), [{"type": "Circle"}]), "unknown geometry type"),
])
def test_geometry_window_bad_input(args, match):
    with pytest.raises(InputError, match=match):
        rastrum.geometry_window(*args)


# ---- rasterize: nodata, masked -------------------------------------------------------------

def test_rasterize_multipoint_masked():
    want = np.zeros(SHAPE, np.int64)
    want[2, 2] = want[4, 4] = 1
    want = np.ma.masked_equal(want, 0)
    got = rastrum.rasterize([MULTIPOINT], out_shape=SHAPE, masked=True, nodata=0)
    assert isinstance(got, np.ma.MaskedArray)
    assert np.array_equal(got.mask, want.mask) and np.array_equal(got.data, want.data)
    assert got.fill_value == 0
    if rf is not None:
        theirs = rio("rasterize", [MULTIPOINT], out_shape=SHAPE, masked=True, nodata=0)
        assert np.array_equal(got.mask, theirs.mask) and np.array_equal(got.data, theirs.data)
        assert got.fill_value == theirs.fill_value


@pytest.mark.parametrize("kw", [
    {"masked": True},                                  # no nodata: nothing masked
    {"masked": True, "nodata": 1, "fill": 5},          # nodata does not change fill
    {"nodata": 0},                                     # without masked: a plain array
    {"masked": True, "nodata": 0.5, "dtype": "float32"},
    {"masked": True, "nodata": 7, "dtype": "uint64", "fill": 7},
])
def test_rasterize_nodata_masked_as_rasterio(kw):
    got = rastrum.rasterize([BASIC], out_shape=SHAPE, **kw)
    assert isinstance(got, np.ma.MaskedArray) == bool(kw.get("masked"))
    if rf is not None:
        theirs = rio("rasterize", [BASIC], out_shape=SHAPE, **kw)
        assert type(got) is type(theirs)
        assert np.array_equal(np.ma.getdata(got), np.ma.getdata(theirs))
        assert np.array_equal(np.ma.getmaskarray(got), np.ma.getmaskarray(theirs))
        if kw.get("masked"):
            assert got.fill_value == theirs.fill_value


def test_rasterize_masked_out_shares_memory():
    out = np.full(SHAPE, 3, np.uint8)
    got = rastrum.rasterize([BASIC], out=out, masked=True, nodata=3)
    assert np.shares_memory(got.data, out) and got.mask.sum() == 96


def test_rasterize_masked_nan():
    # rasterio's masked_equal masks no NaN (NaN != NaN); rastrum masks them
    got = rastrum.rasterize([BASIC], out_shape=SHAPE, fill=np.nan, dtype="float32", masked=True, nodata=np.nan)
    assert np.array_equal(got.mask, basic_2x2() == 0)


@pytest.mark.parametrize("kw, match", [
    ({"nodata": 300, "dtype": "uint8", "masked": True}, "nodata 300 does not fit dtype uint8"),
    ({"nodata": "x", "dtype": "uint8"}, "nodata 'x' is not a real number"),
    ({"nodata": 1.5, "dtype": "int16", "masked": True}, "not a whole number"),
    ({"masked": "yes"}, "masked must be True or False"),
])
def test_rasterize_bad_nodata_out_untouched(kw, match):
    out = np.full(SHAPE, 9, dtype=kw.get("dtype", "int64"))
    before = out.copy()
    with pytest.raises(InputError, match=match):
        rastrum.rasterize([BASIC], out=out, **kw)
    assert np.array_equal(out, before)


# ---- rasterize: skip_invalid -------------------------------------------------------------------

INVALID = [
    [{"type"}],
    [{"type": "Invalid"}],
    [{"type": "Point"}],
    [{"type": "Point", "coordinates": []}],
    [{"type": "GeometryCollection", "geometries": []}],
    [{"foo": "bar"}],
]


@pytest.mark.parametrize("shapes", INVALID)
def test_rasterize_invalid_geom_skipped(shapes):
    with pytest.warns(ShapeSkipWarning, match="index 0"):
        got = rastrum.rasterize(shapes, out_shape=SHAPE, skip_invalid=True)
    assert got.shape == SHAPE and (got == 0).all()
    if rf is not None:
        with pytest.warns(RioSkip):
            theirs = rf.rasterize(shapes, out_shape=SHAPE)
        assert np.array_equal(got, theirs)


@pytest.mark.parametrize("shapes", INVALID)
def test_rasterize_invalid_geom_no_skip(shapes):
    out = np.full(SHAPE, 4, np.uint8)
    with pytest.raises(InputError):
        rastrum.rasterize(shapes, out=out)
    with pytest.raises(InputError):
        rastrum.rasterize(shapes, out=out, skip_invalid=False)
    assert (out == 4).all()
    if rf is not None:
        with pytest.raises(ValueError):
            rf.rasterize(shapes, out_shape=SHAPE, skip_invalid=False)


def test_rasterize_skip_only_invalid_geom():
    with pytest.warns(ShapeSkipWarning, match="index 1"):
        got = rastrum.rasterize([BASIC, {"type": "Polygon", "coordinates": []}], out_shape=SHAPE,
                                skip_invalid=True)
    assert np.array_equal(got, basic_2x2())
    if rf is not None:
        theirs = rio("rasterize", [BASIC, {"type": "Polygon", "coordinates": []}], out_shape=SHAPE)
        assert np.array_equal(got, theirs)


def test_rasterize_skip_invalid_keeps_values():
    # NaN and out-of-range positions are skipped too (rasterio passes them to GDAL)
    bad_nan = {"type": "Polygon", "coordinates": [[(0, 0), (float("nan"), 0), (1, 1), (0, 0)]]}
    far = {"type": "Point", "coordinates": (1e300, 0)}
    with pytest.warns(ShapeSkipWarning) as rec:
        got = rastrum.rasterize([(bad_nan, 3), (BASIC, 7), (far, 9)], out_shape=SHAPE, skip_invalid=True,
                                dtype="uint8")
    assert len(rec) == 2
    assert np.array_equal(got, basic_2x2() * 7)


# ---- uint64 ------------------------------------------------------------------------------------------

def test_rasterize_uint64():
    big = 2 ** 64 - 1
    got = rastrum.rasterize([(BASIC, big)], out_shape=SHAPE)
    assert got.dtype == np.uint64 and got[2, 2] == big and got.sum(dtype=object) == 4 * big
    out = np.zeros(SHAPE, np.uint64)
    rastrum.rasterize([(BASIC, 2 ** 63 + 5)], out=out, merge_alg="add")
    rastrum.rasterize([(BASIC, 2 ** 63 + 5)], out=out, merge_alg="add")
    assert out[2, 2] == big  # "add" saturates, as GDAL does
    if rf is not None:
        # GDAL burns a double: rasterio's uint64 values are exact up to
        # 2^53 and at doubles (2^63 + 2^11); 2^64 - 1 comes out 0 there
        for v in (2 ** 53, 2 ** 63 + 2 ** 11):
            theirs = rio("rasterize", [(BASIC, v)], out_shape=SHAPE)
            mine = rastrum.rasterize([(BASIC, v)], out_shape=SHAPE)
            assert theirs.dtype == mine.dtype == np.uint64 if v > 2 ** 63 else mine.dtype == theirs.dtype
            assert np.array_equal(mine, theirs)
        assert rio("rasterize", [(BASIC, big)], out_shape=SHAPE)[2, 2] == 0
    with pytest.raises(InputError, match="does not fit dtype uint64"):
        rastrum.rasterize([(BASIC, -1)], out_shape=SHAPE, dtype="uint64")


# ---- grid: gdal_rasterize -te -tr [-tap] -------------------------------------------------------

def test_grid_facts():
    assert rastrum.grid((0.3, 0.2, 2.9, 1.1), 0.5, tap=True) == ((3, 6), (0.5, 0.0, 0.0, 0.0, -0.5, 1.5))
    # without -tap: the origin is (xmin, ymax); sizes rounded to the nearest
    assert rastrum.grid((0.3, 0.2, 2.9, 1.1), 0.5) == ((2, 5), (0.5, 0.0, 0.3, 0.0, -0.5, 1.1))
    assert rastrum.grid((-180, -90, 180, 90), (0.025, 0.025)) == ((7200, 14400), (0.025, 0.0, -180.0, 0.0,
                                                                                   -0.025, 90.0))
    assert rastrum.grid((10, 20, 40, 30), (10, 5)) == ((2, 3), (10.0, 0.0, 10.0, 0.0, -5.0, 30.0))


@settings(max_examples=S_.examples(100))
@given(st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.integers(1, 500), st.integers(1, 500),
       st.sampled_from([0.01, 0.025, 0.1, 0.3, 1.0, 10.0, 30.0]))
def test_grid_tap_against_rasterio(x0, y1, n, m, res):
    """-tap aligns the box outward to multiples of the resolution: the same
    origin as rasterio.warp.aligned_target (gdalwarp's -tap) on the box of
    an n x m grid at (x0, y1); the same size where its ceil and GDAL's
    int(0.5 + ...) agree (a quotient a rounding above a whole number gives
    rasterio one pixel more)."""
    xmin, xmax, ymax = x0, x0 + n * res, y1
    ymin = y1 + m * -res  # as aligned_target computes it
    (h, w), t = rastrum.grid((xmin, ymin, xmax, ymax), res, tap=True)
    ax0, ax1 = math.floor(xmin / res) * res, math.ceil(xmax / res) * res
    ay0, ay1 = math.floor(ymin / res) * res, math.ceil(ymax / res) * res
    assert t == (res, 0.0, ax0, 0.0, -res, ay1)
    assert (w, h) == (int(0.5 + (ax1 - ax0) / res), int(0.5 + (ay1 - ay0) / res))
    try:
        from rasterio.warp import aligned_target
    except ImportError:
        return
    at, aw, ah = aligned_target(Affine(res, 0, x0, 0, -res, y1), n, m, res)
    assert (t[2], t[5]) == (at.c, at.f)
    assert aw in (w, w + 1) and ah in (h, h + 1)
    if (ax1 - ax0) / res <= round((ax1 - ax0) / res):
        assert aw == w
    if (ay1 - ay0) / res <= round((ay1 - ay0) / res):
        assert ah == h


@pytest.mark.parametrize("args, match", [
    (((0, 0, 1), 1), "bounds must be 4"),
    (((0, 0, 0, 1), 1), "xmax must be > xmin"),
    (((0, 0, 1, 1), 0), "must be > 0"),
    (((0, 0, 1, 1), (1, -1)), "must be > 0"),
    (((0, 0, 1, 1), (1, 2, 3)), "one number or"),
    (((0, 0, float("nan"), 1), 1), "finite"),
    (((0, 0, 1, 1), 10), "give 0 x 0 pixels"),
    (((0, 0, 1, 1), "1"), "not a real number"),
])
def test_grid_bad_input(args, match):
    with pytest.raises(InputError, match=match):
        rastrum.grid(*args)


# ---- docs/gis.md: its Python examples run as written ---------------------------------------------

def _doc_blocks():
    import os
    import re
    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "gis.md")
    with open(path, encoding="utf-8") as f:
        return re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)


@pytest.mark.parametrize("k", range(len(_doc_blocks())))
def test_gis_doc_example(k):
    block = _doc_blocks()[k]
    if "rioxarray" in block:
        pytest.importorskip("rioxarray")
        pytest.importorskip("affine")
    exec(compile(block, "docs/gis.md block %d" % k, "exec"), {})


def test_gis_doc_has_examples():
    assert len(_doc_blocks()) >= 4

"""The traps of a new user's first hour (issue 37): each gives a message
that says what to do instead."""

import inspect
import sys
import warnings

import numpy as np
import pytest
from PIL import ImageColor

import rastrum
import rastrum.dask

FC = {"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[(0, 0), (4, 0), (4, 4)]]}}]}
HINT = r'FeatureCollection; pass the list of its features, fc\["features"\]'


@pytest.mark.parametrize("call", [
    lambda: rastrum.rasterize(FC, out_shape=(5, 5)),
    lambda: rastrum.rasterize([FC], out_shape=(5, 5)),
    lambda: rastrum.rasterize([(FC, 3)], out_shape=(5, 5)),
    lambda: rastrum.masks(FC, (5, 5)),
    lambda: rastrum.masks([FC], (5, 5)),
    lambda: rastrum.labels(FC, (5, 5)),
    lambda: rastrum.polygon_mask(FC, (5, 5)),
])
def test_a_feature_collection_points_to_its_features(call):
    with pytest.raises(rastrum.InputError, match=HINT):
        call()


def test_the_features_of_a_feature_collection_burn():
    assert rastrum.rasterize(FC["features"], out_shape=(5, 5)).sum() == rastrum.masks(
        [f["geometry"] for f in FC["features"]], (5, 5)).sum() > 0


def test_a_feature_collection_to_dask():
    pytest.importorskip("dask.array")
    with pytest.raises(rastrum.InputError, match=HINT):
        rastrum.dask.rasterize(FC, (5, 5)).compute()


@pytest.mark.parametrize("fmt", ["gray8", "rgb888", "rgba8888", "rgb565", "mono1"])
@pytest.mark.parametrize("name", ["red", "Olive", "#abc", "#12aB9f", "#12ab9f80", "rgb(10, 20, 30)", "black"])
def test_colour_names_are_pillows(fmt, name):
    """A colour string is what Pillow's ImageColor makes of it in the
    canvas's mode: the same pixels as the tuple (or int) it stands for."""
    mode = {"gray8": "L", "mono1": "L", "rgb888": "RGB", "rgb565": "RGB", "rgba8888": "RGBA"}[fmt]
    value = ImageColor.getcolor(name, mode)
    if fmt == "mono1":
        value = int(value != 0)
    tri = [(0.5, 0.5), (7.0, 1.0), (2.0, 5.5)]
    by_name = rastrum.Canvas((6, 9), format=fmt, background=name)
    by_value = rastrum.Canvas((6, 9), format=fmt, background=value)
    assert np.array_equal(by_name.array, by_value.array)
    for c, colour in ((by_name, "white" if fmt != "mono1" else "black"), (by_value, None)):
        if colour is None:
            colour = ImageColor.getcolor("white", mode) if fmt != "mono1" else 0
        c.fill_polygon(tri, colour)
        c.line((0, 5), (8, 0), colour)
        c.fill_polygon(tri, colour, aa="area") if fmt not in ("mono1",) else None
        c.flood_fill((8, 5), colour)
    assert np.array_equal(by_name.array, by_value.array)


def test_a_bad_colour_string_is_named():
    c = rastrum.Canvas((3, 3))
    for bad in ("redd", "#12", "#ggg", ""):
        with pytest.raises(rastrum.InputError, match="colour %r: not a colour name" % bad):
            c.fill_polygon([(0, 0), (2, 0), (2, 2)], bad)
    with pytest.raises(rastrum.InputError, match="colour 'nope'"):
        rastrum.Canvas((3, 3), background="nope")


def test_render_mesh_takes_a_colour_name():
    from rastrum.scene import sphere

    v, f, n = sphere(6, 8)
    a = rastrum.render_mesh(v, f, shape=(24, 24), color="#e6e6e6")
    b = rastrum.render_mesh(v, f, shape=(24, 24), color=(230, 230, 230))
    assert np.array_equal(a.array, b.array)


def test_canvas_signature_is_clean():
    params = inspect.signature(rastrum.Canvas).parameters
    assert "_legacy_height" not in params
    assert list(params)[:1] == ["shape"] and {"format", "background"} <= set(params)
    assert rastrum.Canvas((2, 3), "gray8", 7).array.tolist() == [[7, 7, 7], [7, 7, 7]]
    with pytest.raises(TypeError, match="multiple values for argument 'format'"):
        rastrum.Canvas((2, 3), "rgb888", format="gray8")


def test_canvas_width_height_still_works_with_its_warning():
    with pytest.warns(DeprecationWarning, match=r"Canvas\(width, height\) is now"):
        c = rastrum.Canvas(3, 2, "gray8", 7)
    assert c.array.tolist() == [[7, 7, 7], [7, 7, 7]]


def test_counts_in_messages_are_singular_or_plural():
    gray = rastrum.Canvas((3, 3), format="gray8")
    with pytest.raises(rastrum.InputError, match=r"format gray8 needs 1 int$"):
        gray.fill_polygon([(0, 0), (2, 0), (2, 2)], (1, 2, 3))  # (1, 2) is (L, A) now: docs/opacity.md
    with pytest.raises(rastrum.InputError, match=r"format rgb888 needs 3 ints$"):
        rastrum.Canvas((3, 3)).fill_polygon([(0, 0), (2, 0), (2, 2)], (1, 2))
    with pytest.raises(rastrum.InputError, match=r"points: 1 point given"):
        gray.polyline([(0, 0)], 1)
    with pytest.raises(rastrum.InputError, match=r"labels: values has shape \(2,\); 1 polygon needs shape"):
        rastrum.labels([[(0, 0), (2, 0), (2, 2)]], (3, 3), values=[1, 2])
    with pytest.raises(rastrum.InputError, match=r"values: 1 value for 2 shapes"):
        rastrum.rasterize([{"type": "Point", "coordinates": (1, 1)}] * 2, out_shape=(3, 3), values=[1])
    p = rastrum.coco.polygons([[[0.0, 0.0, 2.0, 0.0, 2.0, 2.0]]])
    assert repr(p) == "<rastrum polygons: 1 polygon, 1 ring, 3 points>"


def test_rastrum_lib_is_not_public():
    with pytest.warns(DeprecationWarning, match="rastrum.lib .* is not public"):
        lib = rastrum.lib
    assert lib is rastrum._native.lib and "lib" not in rastrum.__all__
    with pytest.raises(AttributeError):
        rastrum.no_such_name


def test_a_missing_dask_says_what_to_install(monkeypatch):
    for name in [m for m in sys.modules if m == "dask" or m.startswith("dask.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "dask", None)  # import dask raises ImportError
    monkeypatch.setitem(sys.modules, "dask.array", None)
    with pytest.raises(ImportError, match=r'rastrum.dask.rasterize needs dask: pip install "rastrum\[dask\]"'):
        rastrum.dask.rasterize([], (2, 2), chunks=1)


def test_the_tests_see_rastrums_deprecations_as_errors():
    """pyproject's filterwarnings: a test that uses a deprecated spelling
    without pytest.warns fails."""
    with pytest.raises(DeprecationWarning):
        rastrum.Canvas(3, 2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rastrum.Canvas(3, 2)

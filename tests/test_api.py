"""The API's traps (issue 17), each with what it does now: one size
convention, (H, W) as numpy writes it; no silent reinterpretation of a
wrapped array; one spelling for flat shading; colour and connectivity
keywords alike everywhere; old spellings warn for one release."""

import warnings

import numpy as np
import pytest

import rastrum
from rastrum.scene import sphere

RECT = [(1, 1), (5, 1), (5, 3), (1, 3)]  # 4 x 2 pixels at pixel centres


def no_warning(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn(*args, **kwargs)


# ---- sizes: (H, W) everywhere ---------------------------------------------------

def test_canvas_takes_shape_as_numpy_writes_it():
    c = no_warning(rastrum.Canvas, (3, 7), format="gray8")
    assert c.array.shape == (3, 7) and (c.height, c.width) == (3, 7)
    assert no_warning(rastrum.Canvas, shape=(3, 7)).array.shape == (3, 7, 3)
    # the same shape as the mask of the same picture
    m = rastrum.polygon_mask(RECT, (3, 7))
    c.fill_polygon(RECT, 1)
    assert np.array_equal(c.array.astype(bool), m)


def test_canvas_width_height_is_deprecated_but_means_what_it_meant():
    with pytest.warns(DeprecationWarning, match=r"Canvas\(\(height, width\)\)"):
        c = rastrum.Canvas(7, 3, format="gray8")
    assert c.array.shape == (3, 7)
    with pytest.warns(DeprecationWarning):
        assert rastrum.Canvas(width=7, height=3).array.shape == (3, 7, 3)
    with pytest.warns(DeprecationWarning):
        assert rastrum.Canvas(7, 3, "gray8").format == "gray8"


@pytest.mark.parametrize("args, kwargs", [
    (((3, 7), 5), {}), (((3, 7),), {"width": 7}), ((), {}), ((7,), {}), ((7,), {"width": 7, "height": 3}),
])
def test_canvas_mixed_spellings_are_refused(args, kwargs):
    with pytest.raises(rastrum.InputError, match="shape|width|height"):
        rastrum.Canvas(*args, **kwargs)


def test_render_mesh_shape_and_deprecated_size():
    v, f, n = sphere(6, 12)
    c = no_warning(rastrum.render_mesh, v, f, shape=(20, 30), normals=n)
    assert (c.height, c.width) == (20, 30)
    with pytest.warns(DeprecationWarning, match="shape=\\(height, width\\)"):
        old = rastrum.render_mesh(v, f, (30, 20), normals=n)
    assert np.array_equal(old.array, c.array)
    with pytest.warns(DeprecationWarning):
        assert rastrum.render_mesh(v, f, size=(30, 20), normals=n).array.shape == (20, 30, 3)
    assert no_warning(rastrum.render_mesh, v, f).array.shape == (256, 256, 3)


def test_render_mesh_swapped_shape_against_its_canvas_is_refused():
    v, f, n = sphere(6, 12)
    canvas = rastrum.Canvas((20, 30))
    before = canvas.array.copy()
    with pytest.raises(rastrum.InputError, match="swapped"):
        rastrum.render_mesh(v, f, shape=(30, 20), canvas=canvas)
    assert np.array_equal(canvas.array, before)
    rastrum.render_mesh(v, f, shape=(20, 30), canvas=canvas)
    with pytest.raises(rastrum.InputError, match="not also size"):
        rastrum.render_mesh(v, f, (30, 20), shape=(20, 30))


# ---- Canvas.wrap: no silent reinterpretation --------------------------------------

def test_wrap_uint16_needs_a_format():
    a = np.zeros((4, 6), np.uint16)
    with pytest.raises(rastrum.InputError, match='format="rgb565".*format="label"'):
        rastrum.Canvas.wrap(a)
    assert not a.any()
    c = rastrum.Canvas.wrap(a, format="rgb565")
    c.fill_polygon(RECT, (255, 255, 255))
    assert a[1, 1] == 0xFFFF


@pytest.mark.parametrize("dtype", [np.uint8, np.int8, np.uint16, np.int16, np.int32, np.uint32, np.int64,
                                   np.uint64])
def test_label_image_of_any_integer_dtype(dtype):
    info = np.iinfo(dtype)
    big = int(info.max)
    a = np.full((6, 9), 3, dtype)
    c = rastrum.Canvas.wrap(a, format="label")
    c.fill_polygon(RECT, big)
    c.fill_triangle([(6, 0), (9, 0), (9, 3)], 1)
    c.fill_triangles([[(0, 4), (3, 4), (0, 6)]], int(info.min))
    c.line((0, 5.5), (9, 5.5), 2)
    want = np.full((6, 9), 3, dtype)
    want[rastrum.polygon_mask(RECT, (6, 9))] = big
    want[rastrum.triangles_mask([[(6, 0), (9, 0), (9, 3)]], (6, 9))] = 1
    want[rastrum.triangles_mask([[(0, 4), (3, 4), (0, 6)]], (6, 9))] = info.min
    want[5, :] = 2
    assert a.dtype == dtype and np.array_equal(a, want)


@pytest.mark.parametrize("dtype", [np.uint16, np.int32])
def test_label_seed_fill(dtype):
    a = np.zeros((5, 5), dtype)
    a[2, :] = 40000 if dtype == np.int32 else 7
    c = rastrum.Canvas.wrap(a, format="label")
    c.flood_fill((0, 0), 65535)
    assert (a[:2] == 65535).all() and (a[3:] == 0).all()


@pytest.mark.parametrize("value", [256, -1, 1.5, True, (1, 2)])
def test_label_value_must_fit_the_dtype(value):
    a = np.zeros((4, 4), np.uint8)
    with pytest.raises(rastrum.InputError, match="label value"):
        rastrum.Canvas.wrap(a, format="label").fill_polygon(RECT, value)
    assert not a.any()


def test_label_canvas_refuses_what_it_cannot_do():
    a = np.zeros((4, 4), np.int64)
    c = rastrum.Canvas.wrap(a, format="label")
    with pytest.raises(rastrum.InputError, match="seed fills"):
        c.flood_fill((0, 0), 1)
    with pytest.raises(rastrum.InputError, match="no channels"):
        c.fill_triangles([RECT[:3]], vertex_colors=[[(1,), (2,), (3,)]])
    for bad in (np.zeros((4, 4), np.float32), np.zeros((4, 4, 2), np.int32)):
        with pytest.raises(rastrum.InputError, match="label"):
            rastrum.Canvas.wrap(bad, format="label")
    with pytest.raises(rastrum.InputError, match="label"):
        rastrum.Canvas((4, 4), format="label")
    assert not a.any()


# ---- one spelling for flat shading -------------------------------------------------

TRIS = np.array([[(1, 1), (9, 2), (3, 8)]], float)
VCOL = np.array([[(200, 10, 10), (10, 200, 10), (10, 10, 200)]])


def test_shading_flat_and_deprecated_precision_flat():
    a = rastrum.Canvas((10, 10))
    no_warning(a.fill_triangles, TRIS, vertex_colors=VCOL, shading="flat")
    b = rastrum.Canvas((10, 10))
    with pytest.warns(DeprecationWarning, match='shading="flat"'):
        b.fill_triangles(TRIS, vertex_colors=VCOL, precision="flat")
    assert np.array_equal(a.array, b.array)
    assert {tuple(p) for p in a.array.reshape(-1, 3)} == {(0, 0, 0), (200, 10, 10)}
    with pytest.raises(rastrum.InputError, match="shading"):
        a.fill_triangles(TRIS, vertex_colors=VCOL, shading="phong")
    r = rastrum.Canvas((4, 4))
    with pytest.warns(DeprecationWarning):
        r.fill_rect_gouraud((0, 0, 4, 4), [(9, 9, 9), (1, 1, 1), (1, 1, 1), (1, 1, 1)], precision="flat")
    s = rastrum.Canvas((4, 4))
    no_warning(s.fill_rect_gouraud, (0, 0, 4, 4), [(9, 9, 9), (1, 1, 1), (1, 1, 1), (1, 1, 1)], shading="flat")
    assert np.array_equal(r.array, s.array) and (s.array == 9).all()


# ---- colour: optional everywhere, exactly one of color / vertex_colors -----------------

def test_color_keyword_is_the_same_for_polygon_and_triangle():
    tri = TRIS[0]
    for call in (lambda c: c.fill_polygon(tri), lambda c: c.fill_triangle(tri),
                 lambda c: c.fill_triangles([tri])):
        c = rastrum.Canvas((10, 10))
        with pytest.raises(rastrum.InputError, match="needs color or vertex_colors"):
            call(c)
        assert not c.array.any()
    a, b, t = rastrum.Canvas((10, 10)), rastrum.Canvas((10, 10)), rastrum.Canvas((10, 10))
    a.fill_polygon(tri, vertex_colors=VCOL[0])
    b.fill_triangle(tri, vertex_colors=VCOL[0])
    t.fill_triangles([tri], vertex_colors=VCOL)
    assert np.array_equal(a.array, t.array) and np.array_equal(b.array, t.array) and t.array.any()
    for c in (a, b):
        with pytest.raises(rastrum.InputError, match="exactly one"):
            (c.fill_polygon if c is a else c.fill_triangle)(tri, (1, 2, 3), vertex_colors=VCOL[0])


# ---- connectivity: keyword-only --------------------------------------------------------

def test_connectivity_is_keyword_only():
    pic = np.array([[0, 1], [1, 0]], np.uint8)
    c = rastrum.Canvas.wrap(pic.copy())
    no_warning(c.flood_fill, (0, 0), 5, connectivity=8)
    assert c.array[1, 1] == 5
    d = rastrum.Canvas.wrap(pic.copy())
    with pytest.warns(DeprecationWarning, match="keyword-only"):
        d.flood_fill((0, 0), 5, 8)
    assert np.array_equal(c.array, d.array)
    e = rastrum.Canvas.wrap(pic.copy())
    with pytest.warns(DeprecationWarning):
        e.boundary_fill((0, 0), 5, 1, 8)
    with pytest.raises(rastrum.InputError, match="keyword-only"):
        e.flood_fill((0, 0), 6, 8, 4)


def test_connectivity_not_an_integer_is_an_input_error():
    """An array (hypothesis found np.zeros((3, 2)) given by position) used
    to reach numpy's "truth value ... ambiguous"; a float or string slipped
    through as 4.  Each is an InputError naming the value, nothing drawn."""
    c = rastrum.Canvas((5, 5), format="gray8")
    for bad in (np.zeros((3, 2)), 4.0, "4", None, True):
        with pytest.raises(rastrum.InputError, match="connectivity must be 4 or 8"):
            c.flood_fill((3, 4), 7, connectivity=bad)
        with pytest.raises(rastrum.InputError, match="connectivity must be 4 or 8"):
            c.boundary_fill((3, 4), 7, 1, connectivity=bad)
    assert not c.array.any()
    c.flood_fill((3, 4), 7, connectivity=np.int64(8))
    assert (c.array == 7).all()


# ---- triangles_mask has one dtype; the count has its own name ------------------------------

def test_triangles_mask_is_bool_and_triangles_count_is_uint16():
    tris = [[(0, 0), (4, 0), (4, 4)], [(0, 0), (4, 4), (0, 4)], [(0, 0), (4, 0), (0, 4)]]
    m = no_warning(rastrum.triangles_mask, tris, (5, 5))
    n = no_warning(rastrum.triangles_count, tris, (5, 5))
    assert m.dtype == bool and n.dtype == np.uint16
    assert np.array_equal(m, n > 0) and n.max() == 2
    with pytest.warns(DeprecationWarning, match="triangles_count"):
        old = rastrum.triangles_mask(tris, (5, 5), mode="count")
    assert old.dtype == np.uint16 and np.array_equal(old, n)


# ---- Canvas.array: a view, except mono1 (documented) -----------------------------------------

def test_canvas_array_is_a_view_except_mono1():
    for fmt in ("gray8", "rgb888", "rgba8888", "rgb565"):
        c = rastrum.Canvas((2, 3), format=fmt)
        c.array[...] = 1
        assert (c.packed == 1).all() and c.array.base is not None or c.array is c.packed
    m = rastrum.Canvas((2, 10), format="mono1")
    m.array[...] = 1  # a copy: nothing changes
    assert not m.packed.any() and not m.array.any()
    assert "COPY" in rastrum.Canvas.array.__doc__

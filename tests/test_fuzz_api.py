"""A Python-level fuzz test (issue 18): hypothesis throws arbitrary values
at every public drawing call's arguments and at Canvas.depth -- good
values, wrong shapes and dtypes, huge and tiny numbers, NaN, bools,
strings, None, memoryviews, exact numbers, non-contiguous and read-only
arrays -- over a canvas wrapped around a slice of a guard-patterned array.

Whatever the input, a call either works or raises InputError (a
ValueError) -- never another exception, never a crash -- and when it
raises, not one byte of the array (guards included) nor the depth buffer
has changed; when it works, the guard bytes around the canvas are still
untouched.  `make asan-py` runs it with the extension built under
AddressSanitizer + UBSan, and `make valgrind-py` under memcheck: an
out-of-bounds access anywhere below the checks is a report there.
"""

from __future__ import annotations

import decimal
from fractions import Fraction

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

import rastrum

H, W = 9, 11
FORMATS = ["gray8", "rgb888", "rgba8888"]


def _arrays(draw_shape):
    """Arrays of many dtypes and layouts, of a drawn shape."""
    return st.builds(_make_array, draw_shape, st.sampled_from(
        ["f8", "f4", "i4", "i8", "u1", "u2", "?", "c16", "O", "U3", "longdouble", "i2", ">i4"]),
        st.integers(0, 2 ** 32 - 1), st.sampled_from(["plain", "strided", "fortran", "readonly", "mv"]))


def _make_array(shape, dtype, seed, layout):
    rng = np.random.default_rng(seed)
    a = rng.uniform(-20, 20, size=shape)
    if dtype == "O":
        a = np.array([Fraction(v).limit_denominator(1000) for v in a.reshape(-1).tolist()] or [],
                     dtype=object).reshape(shape)
    elif dtype == "longdouble":
        a = a.astype(np.longdouble)
    else:
        a = a.astype(dtype)
    if layout == "strided" and a.ndim:
        big = np.zeros(a.shape[:-1] + (2 * a.shape[-1],), a.dtype)
        big[..., ::2] = a
        a = big[..., ::2]
    elif layout == "fortran":
        a = np.asfortranarray(a)
    elif layout == "readonly":
        a = a.copy()
        a.setflags(write=False)
    elif layout == "mv" and a.dtype.kind in "fiu" and a.dtype.isnative:
        return memoryview(np.ascontiguousarray(a))
    return a


SCALARS = st.one_of(
    st.integers(-300, 300), st.integers(-(2 ** 70), 2 ** 70), st.just(2 ** 1024), st.just(-(2 ** 1024)),
    st.floats(allow_nan=True, allow_infinity=True), st.booleans(), st.none(), st.text(max_size=3),
    st.fractions(max_denominator=2 ** 70), st.decimals(allow_nan=True, places=3),
    st.just(np.longdouble(0.5) - np.longdouble(2.0) ** -60), st.complex_numbers(max_magnitude=10),
    st.just(np.int64(2 ** 62)), st.just(np.float32(3.5)))

SHAPES = st.lists(st.integers(0, 5), min_size=0, max_size=4).map(tuple)
VALUES = st.one_of(
    SCALARS,
    st.lists(SCALARS, max_size=4),
    st.lists(st.tuples(SCALARS, SCALARS), max_size=5),
    _arrays(SHAPES),
    _arrays(st.sampled_from([(3, 2), (4, 2), (1, 3, 2), (2, 3, 2), (2, 3), (2, 3, 4), (4,), (2,)])),
)


def good_or(value_strategy, good):
    """Mostly good values, so that the other arguments get exercised too."""
    return st.one_of(st.just(good), value_strategy)


RING = np.array([(1.5, 1.0), (10.0, 2.25), (4.0, 8.5)])
TRIS = np.array([[(1.5, 1.0), (10.0, 2.25), (4.0, 8.5)]])
CALLS = {
    "fill_polygon": lambda c, a: c.fill_polygon(a[0], a[1], subpixel_bits=a[2], algorithm=a[3], rule=a[4]),
    "fill_triangle": lambda c, a: c.fill_triangle(a[0], a[1], subpixel_bits=a[2], sample_offset=a[3]),
    "fill_triangles": lambda c, a: c.fill_triangles(a[0], a[1], subpixel_bits=a[2]),
    "fill_triangles(depth)": lambda c, a: c.fill_triangles(a[0], vertex_colors=a[1], depth=a[2],
                                                           precision=a[3]),
    "fill_rect_gouraud": lambda c, a: c.fill_rect_gouraud(a[0], a[1], precision=a[2], fraction_bits=a[3]),
    "line": lambda c, a: c.line(a[0], a[1], a[2], subpixel_bits=a[3]),
    "polyline": lambda c, a: c.polyline(a[0], a[1], closed=a[2], subpixel_bits=a[3]),
    "flood_fill": lambda c, a: c.flood_fill(a[0], a[1], connectivity=a[2]),
    "boundary_fill": lambda c, a: c.boundary_fill(a[0], a[1], a[2], connectivity=a[3]),
    "depth=": lambda c, a: setattr(c, "depth", a[0]),
    "polygon_mask": lambda c, a: rastrum.polygon_mask(a[0], a[1], subpixel_bits=a[2]),
    "triangles_mask": lambda c, a: rastrum.triangles_mask(a[0], a[1], mode=a[2]),
    "line_pixels": lambda c, a: rastrum.line_pixels(a[0], a[1], clip=a[2], max_pixels=a[3]),
    "point_in_triangle": lambda c, a: rastrum.point_in_triangle(a[0], a[1], method=a[2]),
}
GOOD = {
    "fill_polygon": (RING, 7, 8, "aet", "evenodd"),
    "fill_triangle": (TRIS[0], 7, 8, 0.5),
    "fill_triangles": (TRIS, 7, 8),
    "fill_triangles(depth)": (TRIS, np.full((1, 3, 3), 9), [[1, 2, 3]], "exact"),
    "fill_rect_gouraud": ((1, 1, 8, 7), [0, 80, 160, 240], "exact", 16),
    "line": ((0.5, 0.5), (9.5, 6.5), 5, 8),
    "polyline": (RING, 5, True, 8),
    "flood_fill": ((3, 4), 7, 4),
    "boundary_fill": ((3, 4), 7, 9, 8),
    "depth=": (np.zeros((H, W), np.int32),),
    "polygon_mask": (RING, (H, W), 8),
    "triangles_mask": (TRIS, (H, W), "set"),
    "line_pixels": ((0, 0), (9, 4), None, 1000),
    "point_in_triangle": ((3, 3), TRIS[0], "owner"),
}


@st.composite
def calls(draw):
    name = draw(st.sampled_from(sorted(CALLS)))
    good = GOOD[name]
    args = tuple(draw(good_or(VALUES | st.sampled_from(
        ["aet", "edgeflag", "nonzero", "exact", "fixed", "flat", "set", "add", "owner", "bogus"]), g))
        for g in good)
    fmt = draw(st.sampled_from(FORMATS))
    with_depth = draw(st.booleans())
    return name, args, fmt, with_depth


def _canvas(fmt, with_depth):
    channels = {"gray8": (), "rgb888": (3,), "rgba8888": (4,)}[fmt]
    big = (np.arange((H + 4) * (W + 4) * int(np.prod(channels or (1,)))) % 251).astype(np.uint8)
    big = big.reshape((H + 4, W + 4) + channels)
    canvas = rastrum.Canvas.wrap(big[2:2 + H, 2:2 + W], format=fmt)
    if with_depth:
        canvas.depth = np.full((H, W), 5, np.int32)
    return big, canvas


def _guards(big):
    return np.concatenate([big[:2].reshape(-1), big[-2:].reshape(-1), big[:, :2].reshape(-1),
                           big[:, -2:].reshape(-1)])


@settings(suppress_health_check=list(HealthCheck), deadline=None,
          max_examples=10 * settings.default.max_examples)  # a fuzz test: ten times the profile
@given(calls())
def test_public_api_takes_anything(call):
    name, args, fmt, with_depth = call
    big, canvas = _canvas(fmt, with_depth)
    before, guards = big.copy(), _guards(big).copy()
    depth = None if canvas.depth is None else canvas.depth.copy()
    try:
        CALLS[name](canvas, args)
    except rastrum.InputError as e:
        assert isinstance(e, ValueError) and str(e)
        assert np.array_equal(big, before), "%s raised but wrote pixels" % name
        if depth is None:
            assert canvas.depth is None
        else:
            assert np.array_equal(canvas.depth, depth)
        return
    except rastrum.RastrumError as e:  # only the seed fill's work limit may stop a call
        assert name.endswith("fill") and "work limit" in str(e), e
        return
    except DeprecationWarning:  # an old spelling drawn (precision="flat"): an error in the tests
        assert np.array_equal(big, before), "%s warned but wrote pixels" % name
        return
    assert np.array_equal(_guards(big), guards), "%s wrote outside the canvas" % name


# ---- issue 35: the surfaces added since (coco, rasterize, masks/labels, dask) ----

def _misaligned(shape, dtype):
    n = int(np.prod(shape)) * np.dtype(dtype).itemsize
    return np.zeros(n + 1, np.uint8)[1:].view(dtype).reshape(shape)


def _recursive_list():
    a = [1.0, 2.0]
    a.append(a)
    return a


HOSTILE = st.one_of(
    st.none(), st.booleans(), st.complex_numbers(allow_nan=True), st.text(max_size=3), st.binary(max_size=4),
    st.sampled_from([float("nan"), float("inf"), -float("inf"), 2 ** 64, -(2 ** 63) - 1, 10 ** 400, 2.0 ** 63,
                     1e-320, 0, -1, 256]),
    st.builds(_recursive_list), st.builds(dict), st.just({"size": [2, 2], "counts": [True, 3]}),
    st.just({"size": [2 ** 32, 1], "counts": b""}), st.just({"size": [2, 2], "counts": "\x00\xff"}),
    st.builds(lambda: _misaligned((4, 5), np.int32)), st.builds(lambda: np.zeros((4, 10))[:, ::2]),
    st.builds(lambda: np.zeros((4, 5), np.complex128)), st.builds(lambda: np.array(["a", "b"])),
    st.lists(st.one_of(st.floats(allow_nan=True), st.booleans(), st.integers()), max_size=6),
    st.lists(st.lists(st.one_of(st.floats(-10, 10), st.booleans(), st.text(max_size=1)), max_size=6), max_size=3),
)

_SQ = {"type": "Polygon", "coordinates": [[(0, 0), (3, 0), (3, 3), (0, 3), (0, 0)]]}
_RLE = {"size": [4, 5], "counts": b"61L0"}
_RING = [np.array([[0, 0], [3, 0], [3, 3], [0, 3]], float)]


def _surface():
    from rastrum import coco
    calls = {
        "coco.encode": (coco.encode, [np.zeros((4, 5), np.uint8, order="F")]),
        "coco.decode": (coco.decode, [_RLE]),
        "coco.area": (coco.area, [[_RLE]]),
        "coco.toBbox": (coco.toBbox, [[_RLE]]),
        "coco.merge": (coco.merge, [[_RLE, _RLE]]),
        "coco.iou": (coco.iou, [[_RLE], [_RLE], [0]]),
        "coco.frPyObjects": (coco.frPyObjects, [[[0.0, 0.0, 3.0, 0.0, 3.0, 3.0]], 4, 5]),
        "coco.rings": (coco.rings, [[[0.0, 0.0, 3.0, 0.0, 3.0, 3.0]]]),
        "coco.polygons": (coco.polygons, [[[[0.0, 0.0, 3.0, 0.0, 3.0, 3.0]]]]),
        "masks": (rastrum.masks, [[_RING], (4, 5)]),
        "labels": (rastrum.labels, [[_RING], (4, 5)]),
        "rasterize": (rastrum.rasterize, [[(_SQ, 1)], (4, 5)]),
    }
    return calls


@settings(suppress_health_check=list(HealthCheck), deadline=None, max_examples=400)
@given(st.sampled_from(sorted(_surface())), st.integers(0, 2), HOSTILE)
def test_new_surfaces_take_anything(name, pos, bad):
    fn, args = _surface()[name]
    args = list(args)
    pos = pos % len(args)
    args[pos] = bad
    try:
        fn(*args)
    except rastrum.InputError:
        pass
    except MemoryError:
        pass  # a size the machine cannot hold, said before anything is written


@settings(suppress_health_check=list(HealthCheck), deadline=None, max_examples=150)
@given(HOSTILE, st.sampled_from(["decode", "rasterize"]))
def test_new_surfaces_out_untouched(bad, which):
    from rastrum import coco
    out = np.full((4, 5), 7, np.uint8)
    try:
        if which == "decode":
            coco.decode(bad, out=out)
        else:
            rastrum.rasterize([(bad, 1)], out=out)
    except rastrum.InputError:
        assert (out == 7).all()


# ---- issue 35: every public name, fuzzed as a whole ---------------------------------
#
# FUZZ has an entry for every public name: rastrum.__all__, rastrum.coco,
# rastrum.dask, rastrum.gis, rastrum.scene and the public methods of Canvas,
# Path and Polygons; NOT_CALLED lists the names that are data, not calls.
# test_every_public_name_has_a_fuzz_entry fails when a new public name has
# neither.  Each call gets its good arguments with one replaced by a hostile
# object; it must work or raise InputError (or the exceptions the docs name
# for it, ALSO), never RecursionError, write nothing into a canvas when it
# raises, and allocate (Python's heap, tracemalloc) under 64 MB.

import contextlib
import io
import os
import tempfile
import tracemalloc
import types

_TRI3 = np.array([[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]])
_MESH_V = np.array([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 0.5]])
_MESH_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
_DATASET = types.SimpleNamespace(transform=rastrum.IDENTITY, height=4, width=5, shape=(4, 5))


def _mpl_path():
    """A matplotlib Path (a triangle with a quadratic side) where matplotlib
    is installed; else a duck with its .vertices and .codes."""
    v = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [0.0, 0.0]])
    codes = np.array([1, 2, 3, 3, 79], np.uint8)  # MOVETO LINETO CURVE3 CURVE3 CLOSEPOLY
    try:
        from matplotlib.path import Path as MplPath
    except ImportError:
        return types.SimpleNamespace(vertices=v, codes=codes)
    return MplPath(v, codes)


def _fuzz_table():
    from rastrum import coco, gis, scene
    P = rastrum.Path
    plain = {
        "polygon_mask": (rastrum.polygon_mask, [RING, (4, 5)]),
        "triangles_mask": (rastrum.triangles_mask, [TRIS, (4, 5)]),
        "triangles_count": (rastrum.triangles_count, [TRIS, (4, 5)]),
        "polygon_coverage": (rastrum.polygon_coverage, [RING, (4, 5)]),
        "triangles_coverage": (rastrum.triangles_coverage, [TRIS, (4, 5)]),
        "line_pixels": (rastrum.line_pixels, [(0, 0), (3, 2)]),
        "point_in_triangle": (rastrum.point_in_triangle, [(1, 1), _TRI3]),
        "Canvas": (rastrum.Canvas, [(4, 5)]),
        "Polygons": (rastrum.Polygons, [_TRI3, [3], [1]]),
        "Path": (lambda t: rastrum.Path(tolerance=t), [0.1]),
        "stroke": (rastrum.stroke, [[(0, 0), (3, 3)], 1.0]),
        "masks": (rastrum.masks, [[_RING], (4, 5)]),
        "labels": (rastrum.labels, [[_RING], (4, 5)]),
        "rasterize": (rastrum.rasterize, [[(_SQ, 1)], (4, 5)]),
        "zonal_stats": (lambda r, g: rastrum.zonal_stats(r, g, transform=rastrum.IDENTITY, output="records"),
                        [np.ones((4, 5)), [_SQ]]),
        "geometry_mask": (rastrum.geometry_mask, [[_SQ], (4, 5), rastrum.IDENTITY]),
        "geometry_window": (rastrum.geometry_window, [_DATASET, [_SQ]]),
        "grid": (rastrum.grid, [(0.0, 0.0, 4.0, 5.0), 1.0]),
        "render_mesh": (lambda v, f: rastrum.render_mesh(v, f, shape=(6, 6)), [_MESH_V, _MESH_F]),
        "scene.sphere": (scene.sphere, [3, 4]),
        "scene.torus": (scene.torus, [1.0, 0.4, 4, 3]),
        "scene.read_obj": (scene.read_obj, [io.StringIO("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")]),
        "scene.write_obj": (scene.write_obj, [io.StringIO(), _MESH_V, _MESH_F]),
        "scene.rotation": (scene.rotation, [0.1, 0.2, 0.3]),
        "scene.project": (scene.project, [_MESH_V, (6, 6)]),
        "scene.lambert": (scene.lambert, [np.array([[0.0, 0.0, 1.0]]), (0.0, 0.0, 1.0), 0.2, (200, 100, 50)]),
        "scene.vertex_normals": (scene.vertex_normals, [_MESH_V, _MESH_F]),
        "Path.from_svg": (P.from_svg, ["M 0 0 L 3 0 L 3 3 Z"]),
        "coverage_fractions": (rastrum.coverage_fractions, [[_SQ], (4, 5), rastrum.IDENTITY]),
    }
    for name, (fn, args) in _surface().items():
        plain[name] = (fn, args)
    plain["gis.rasterize"] = plain["rasterize"]
    plain["gis.geometry_mask"] = plain["geometry_mask"]
    plain["gis.geometry_window"] = plain["geometry_window"]
    plain["gis.grid"] = plain["grid"]
    plain["scene.render_mesh"] = plain["render_mesh"]
    try:
        import rastrum.dask as rdask
        plain["dask.rasterize"] = (lambda s, o, c: rdask.rasterize(s, o, chunks=c).compute(),
                                   [[(_SQ, 1)], (4, 5), (2, 5)])
        plain["dask.to_xarray"] = (rdask.to_xarray, [np.zeros((4, 5)), rastrum.IDENTITY])
        plain["dask.zonal_stats"] = (lambda r, g, t: rdask.zonal_stats(r, g, transform=t, output="records"),
                                     [np.ones((4, 5)), [_SQ], rastrum.IDENTITY])
    except ImportError:  # dask is an extra: its two names are checked where it is installed
        pass
    assert gis is not None and coco is not None
    canvas = {  # called on a canvas wrapped around a guard-patterned array
        "Canvas.fill_polygon": (lambda c, *a: c.fill_polygon(*a), [RING, 7]),
        "Canvas.fill_triangle": (lambda c, *a: c.fill_triangle(*a), [TRIS[0], 7]),
        "Canvas.fill_triangles": (lambda c, *a: c.fill_triangles(*a), [TRIS, 7]),
        "Canvas.fill_rect_gouraud": (lambda c, *a: c.fill_rect_gouraud(*a), [(1, 1, 8, 7), [0, 80, 160, 240]]),
        "Canvas.line": (lambda c, *a: c.line(*a), [(0.5, 0.5), (9.5, 6.5), 5]),
        "Canvas.polyline": (lambda c, *a: c.polyline(*a), [RING, 5]),
        "Canvas.flood_fill": (lambda c, *a: c.flood_fill(*a), [(3, 4), 7]),
        "Canvas.boundary_fill": (lambda c, *a: c.boundary_fill(*a), [(3, 4), 7, 9]),
        "Canvas.depth": (lambda c, d: setattr(c, "depth", d), [np.zeros((H, W), np.int32)]),
        "Canvas.clear_depth": (lambda c, *a: c.clear_depth(*a), []),
        "Canvas.save": (lambda c, *a: c.save(*a), ["out.png"]),
        "Canvas.to_image": (lambda c: c.to_image(), []),
        "Canvas.wrap": (lambda c, a: rastrum.Canvas.wrap(a), [np.zeros((4, 5), np.uint8)]),
        # canvas34's shapes and stroke, blend34's composite (the Pillow ImageDraw spellings)
        "Canvas.ellipse": (lambda c, *a: c.ellipse(*a), [(1, 1, 6, 4), 7, 9, 2]),
        "Canvas.circle": (lambda c, *a: c.circle(*a), [(3.5, 2.5), 2.0, 7, 9, 1]),
        "Canvas.rounded_rectangle": (lambda c, *a: c.rounded_rectangle(*a), [(1, 1, 8, 6), 2.0, 7, 9, 1]),
        "Canvas.arc": (lambda c, *a: c.arc(*a), [(1, 1, 8, 6), 30.0, 250.0, 7, 2]),
        "Canvas.pieslice": (lambda c, *a: c.pieslice(*a), [(1, 1, 8, 6), 30.0, 250.0, 7, 9, 1]),
        "Canvas.chord": (lambda c, *a: c.chord(*a), [(1, 1, 8, 6), 30.0, 250.0, 7, 9, 1]),
        "Canvas.regular_polygon": (lambda c, *a: c.regular_polygon(*a), [(4.5, 3.5, 3.0), 5, 10.0, 7, 9, 1]),
        "Canvas.stroke": (lambda c, *a: c.stroke(*a), [[(0.5, 0.5), (8.5, 6.5), (2.0, 6.0)], 7, 1.5]),
        "Canvas.composite": (lambda c, m, k, o: c.composite(m, k, opacity=o), [np.full((H, W), 0.5, np.float32), (10, 20, 30), 0.5]),
    }
    path = {  # called on a fresh Path that has moved to (0, 0)
        "Path.move_to": (lambda p, *a: p.move_to(*a), [1.0, 2.0]),
        "Path.line_to": (lambda p, *a: p.line_to(*a), [3.0, 2.0]),
        "Path.quad_to": (lambda p, *a: p.quad_to(*a), [1.0, 2.0, 3.0, 0.0]),
        "Path.cubic_to": (lambda p, *a: p.cubic_to(*a), [1.0, 2.0, 2.0, 2.0, 3.0, 0.0]),
        "Path.arc_to": (lambda p, *a: p.arc_to(*a), [2.0, 1.0, 0.0, False, True, 3.0, 0.0]),
        "Path.close": (lambda p: p.close(), []),
        "Path.copy": (lambda p: p.copy(), []),
        "Path.flatten": (lambda p, *a: p.flatten(*a), [8]),
        "Polygons.packed": (lambda p: rastrum.Polygons(_TRI3, [3], [1]).packed(), []),
        "Path.transformed": (lambda p, *a: p.line_to(3.0, 1.0).transformed(*a), [(0.5, 0.0, 1.0, 0.0, -0.5, 9.0)]),
        "Path.from_matplotlib": (lambda p, *a: rastrum.Path.from_matplotlib(*a), [_mpl_path()]),
        "Path.circle": (lambda p, *a: rastrum.Path.circle(*a), [3.0, 2.0, 1.5]),
        "Path.ellipse": (lambda p, *a: rastrum.Path.ellipse(*a), [3.0, 2.0, 2.5, 1.5]),
        "Path.rounded_rectangle": (lambda p, *a: rastrum.Path.rounded_rectangle(*a), [0.0, 0.0, 5.0, 4.0, 1.0]),
        "Path.arc": (lambda p, *a: rastrum.Path.arc(*a), [3.0, 2.0, 2.5, 1.5, 10.0, 200.0]),
        "Path.pieslice": (lambda p, *a: rastrum.Path.pieslice(*a), [3.0, 2.0, 2.5, 1.5, 10.0, 200.0]),
        "Path.pie": (lambda p, *a: rastrum.Path.pie(*a), [3.0, 2.0, 2.5, 1.5, 10.0, 200.0]),
        "Path.chord": (lambda p, *a: rastrum.Path.chord(*a), [3.0, 2.0, 2.5, 1.5, 10.0, 200.0]),
        "Path.regular_polygon": (lambda p, *a: rastrum.Path.regular_polygon(*a), [3.0, 2.0, 1.5, 6]),
    }
    return plain, canvas, path


# Public names that are data, not calls (nothing to fuzz), with what they are.
NOT_CALLED = {
    "ALGORITHMS": "a dict", "AA_METHODS": "a dict", "IDENTITY": "a tuple", "__version__": "a string",
    "RastrumError": "an exception class", "InputError": "an exception class", "coco": "a module",
    "scene": "a module", "gis.IDENTITY": "a tuple", "gis.DTYPES": "a dict", "gis.Window": "a named tuple",
    "gis.ShapeSkipWarning": "a warning class", "Canvas.array": "a property", "Canvas.format": "a property",
    "Canvas.width": "a property", "Canvas.packed": "a property", "Canvas.height": "a property", "Path.ARC_ERROR": "a number",
    "Path.DEFAULT_TOLERANCE": "a number", "Path.points": "a property", "Path.verbs": "a property",
    "Path.tolerance": "a property", "Polygons.points": "an attribute", "Polygons.ring_sizes": "an attribute",
    "Polygons.rings_per_polygon": "an attribute",
}
# Exceptions the docs name for a call besides InputError (docs/bad-input.md):
# Pillow's for a file it cannot write, the OS's for a file it cannot read.
ALSO = {"Canvas.save": (ValueError, OSError, TypeError, KeyError), "scene.read_obj": (OSError, TypeError),
        "scene.write_obj": (OSError, TypeError)}


def _public_names():
    from rastrum import coco, gis, scene
    names = set(rastrum.__all__)
    for mod, prefix in ((coco, "coco."), (gis, "gis."), (scene, "scene.")):
        names |= {prefix + n for n in mod.__all__}
    try:
        import rastrum.dask as rdask
        names |= {"dask." + n for n in rdask.__all__}
    except ImportError:
        pass
    for cls in (rastrum.Canvas, rastrum.Path, rastrum.Polygons):
        names |= {cls.__name__ + "." + n for n in dir(cls) if not n.startswith("_")}
    return names


def test_every_public_name_has_a_fuzz_entry():
    plain, canvas, path = _fuzz_table()
    covered = set(plain) | set(canvas) | set(path) | set(NOT_CALLED)
    missing = sorted(_public_names() - covered)
    assert not missing, "public names without a fuzz entry (add them to _fuzz_table): %s" % missing


_ENTRIES = None


@contextlib.contextmanager
def _cwd(path):  # contextlib.chdir is Python 3.11's
    old = os.getcwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(old)


def _entry(name):
    global _ENTRIES
    if _ENTRIES is None:
        plain, canvas, path = _fuzz_table()
        _ENTRIES = {**{k: ("plain",) + v for k, v in plain.items()},
                    **{k: ("canvas",) + v for k, v in canvas.items()}, **{k: ("path",) + v for k, v in path.items()}}
    return _ENTRIES[name]


def _names():
    plain, canvas, path = _fuzz_table()
    return sorted(set(plain) | set(canvas) | set(path))


HOSTILE_ALL = HOSTILE | st.sampled_from([np.float64("nan"), np.int64(2 ** 62), np.True_, np.uint8(255), 1 + 2j]) | \
    st.builds(lambda: np.zeros((4, 5), np.uint8)[:, ::2]) | st.builds(lambda: np.zeros((4, 5), np.uint8, order="F")) | \
    st.builds(lambda: np.full((4, 5), np.nan))


@settings(suppress_health_check=list(HealthCheck), deadline=None,
          max_examples=settings.default.max_examples)  # the profile's count
@given(st.sampled_from(_names()), st.integers(0, 6), HOSTILE_ALL)
def test_every_public_name_takes_anything(name, pos, bad):
    kind, fn, good = _entry(name)
    args = list(good)
    if args:
        args[pos % len(args)] = bad
    also = ALSO.get(name, ())
    big = before = None
    with tempfile.TemporaryDirectory() as tmp, _cwd(tmp):
        tracemalloc.start()
        try:
            if kind == "canvas":
                big, c = _canvas("rgb888", True)
                before = big.copy()
                fn(c, *args)
            elif kind == "path":
                fn(rastrum.Path().move_to(0.0, 0.0), *args)
            else:
                fn(*args)
        except rastrum.InputError as e:
            assert "np." not in str(e), e  # plain numbers, not numpy reprs
            if big is not None:
                assert np.array_equal(big, before), "%s raised but wrote pixels" % name
        except also:
            pass
        except MemoryError:
            pass  # a size the machine cannot hold, said before anything is written
        except rastrum.RastrumError as e:  # the seed fill's work limit
            assert name.endswith("fill") and "work limit" in str(e), e
        finally:
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
    assert peak < 64 * 2 ** 20, "%s took %d bytes" % (name, peak)

"""The mesh pipeline (rastrum.scene): viewport, culling, Lambert, depth,
OBJ, procedural meshes.  Expected values are computed by hand or from the
definitions in the module docstring, never by the code under test."""

import io
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum.scene import (face_normals, front_facing, project, read_obj, render_mesh, rotation, sphere,
                           torus, viewport, write_obj)
from strategies import examples


def test_viewport_corners_and_centres():
    W, H = 40, 30
    got = viewport([(-1, 1), (1, 1), (1, -1), (-1, -1), (0, 0)], (W, H))
    np.testing.assert_array_equal(got, [(0, 0), (W, 0), (W, H), (0, H), (W / 2, H / 2)])
    # the NDC point of pixel (i, j)'s centre maps to (i + 1/2, j + 1/2)
    i, j = 7, 11
    ndc = ((2 * i + 1) / W - 1, 1 - (2 * j + 1) / H)
    np.testing.assert_allclose(viewport([ndc], (W, H)), [(i + 0.5, j + 0.5)], rtol=0, atol=1e-12)


def test_projection_aspect_keeps_circles_round():
    xy, _, _ = project([(1, 0, 0), (0, 1, 0)], (200, 100))
    # x is divided by W/H = 2: both unit vectors are 50 px from the centre
    np.testing.assert_allclose(xy, [(150, 50), (100, 0)])


FRONT = np.array([(-0.8, -0.8, 0.0), (0.8, -0.8, 0.0), (0.0, 0.8, 0.0)])  # CCW seen from +z


def test_front_facing_winding():
    xy, _, _ = project(FRONT, (10, 10))
    assert front_facing(xy[None]).tolist() == [True]
    assert front_facing(xy[None, ::-1]).tolist() == [False]


@pytest.mark.parametrize("light, ambient, want", [
    ((0, 0, 1), 0.2, 200),                         # n . l = 1
    ((0, 1, 1), 0.2, 153),                         # 0.2 + 0.8 cos 45 = 0.76569 -> 153.1
    ((0, 0, -1), 0.25, 50),                        # turned away: ambient only
    ((1, 0, math.sqrt(3)), 0.0, 173),              # cos 30 = 0.866 -> 173.2
])
def test_lambert_flat_by_hand(light, ambient, want):
    c = render_mesh(FRONT, [(0, 1, 2)], shape=(10, 10), light=light, ambient=ambient, color=(200, 200, 200),
                    depth=False)
    assert c.array[5, 5].tolist() == [want] * 3
    assert set(np.unique(c.array)) == {0, want}


def test_culling_drops_back_faces_only():
    c = render_mesh(FRONT[::-1], [(0, 1, 2)], shape=(10, 10), depth=False)
    assert not c.array.any()
    c = render_mesh(FRONT[::-1], [(0, 1, 2)], shape=(10, 10), depth=False, cull=False)
    assert c.array.any()


@pytest.mark.parametrize("mesh", ["sphere", "torus"])
def test_closed_mesh_front_faces_cover_each_pixel_once(mesh):
    """After culling, a closed convex-ish mesh seen orthographically is
    covered at most once per pixel where no part hides another (the
    sphere), and exactly on its silhouette."""
    v, f, _ = sphere(10, 20) if mesh == "sphere" else torus(1, 0.4, 24, 12)
    rot = rotation(30, 20, 0)
    xy, _, _ = project(v, (64, 64), rotation=rot, scale=0.9 if mesh == "sphere" else 0.6)
    tris = xy[f]
    front = tris[front_facing(tris)]
    count_front = rastrum.triangles_count(front, (64, 64))
    everything = rastrum.triangles_mask(tris, (64, 64))
    assert (count_front > 0).tolist() == everything.tolist()
    if mesh == "sphere":
        assert count_front.max() == 1
        # and the back faces cover the same silhouette once more
        assert (rastrum.triangles_count(tris, (64, 64)) == 2 * (count_front > 0)).all()


@pytest.mark.parametrize("shading", ["flat", "gouraud"])
@pytest.mark.parametrize("projection", ["orthographic", "perspective"])
def test_sphere_culling_on_off_same_image_with_depth(shading, projection):
    v, f, n = sphere(12, 24)
    kw = dict(normals=n, shading=shading, rotation=rotation(25, -15, 5), projection=projection, scale=0.9)
    a = render_mesh(v, f, shape=(80, 96), cull=True, **kw)
    b = render_mesh(v, f, shape=(80, 96), cull=False, **kw)
    np.testing.assert_array_equal(a.array, b.array)
    assert a.array.any()


TWO = np.array([(-0.9, -0.9, 0.5), (0.6, -0.9, 0.5), (-0.2, 0.8, 0.5),      # near (z = 0.5)
                (-0.6, -0.7, -0.5), (0.9, -0.7, -0.8), (0.3, 0.9, -0.4)])   # far, tilted


def test_depth_order_free():
    near, far = (0, 1, 2), (3, 4, 5)
    kw = dict(shape=(40, 40), light=(0.3, 0.2, 1), color=(250, 120, 30), shading="gouraud")
    a = render_mesh(TWO, [near, far], **kw)
    b = render_mesh(TWO, [far, near], **kw)
    np.testing.assert_array_equal(a.array, b.array)
    # without depth the last face drawn wins where they overlap
    c = render_mesh(TWO, [near, far], depth=False, **kw)
    assert (c.array != a.array).any()
    # the near face alone equals the depth image wherever it is drawn
    alone = render_mesh(TWO, [near], **kw)
    drawn = alone.array.any(axis=2)
    np.testing.assert_array_equal(a.array[drawn], alone.array[drawn])


def test_gouraud_differs_from_flat_and_is_smoother():
    v, f, n = sphere(8, 16)
    a = render_mesh(v, f, shape=(64, 64), normals=n, shading="flat").array[..., 0].astype(int)
    b = render_mesh(v, f, shape=(64, 64), normals=n, shading="gouraud").array[..., 0].astype(int)
    inside = (a > 0) & (b > 0)
    # the largest jump between horizontal neighbours inside the sphere: flat
    # has steps at the face edges (the Mach bands), Gouraud does not
    da = np.abs(np.diff(a, axis=1))[inside[:, 1:] & inside[:, :-1]].max()
    db = np.abs(np.diff(b, axis=1))[inside[:, 1:] & inside[:, :-1]].max()
    assert db < da


def test_meshes_are_closed_and_outward():
    for v, f, n in (sphere(6, 9), torus(2, 0.5, 7, 5)):
        # closed: every edge is used once in each direction
        edges = {}
        for t in f:
            for k in range(3):
                e = (int(t[k]), int(t[(k + 1) % 3]))
                edges[e] = edges.get(e, 0) + 1
        assert all(edges.get((b, a)) == 1 for (a, b), c in edges.items() if c == 1)
        assert all(c == 1 for c in edges.values())
        np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1)
        # each face normal points the way of its vertices' normals (outward)
        assert (np.sum(face_normals(v, f) * n[f].mean(axis=1), axis=1) > 0).all()
    v, f, n = sphere(6, 9)
    assert len(v) == 2 + 5 * 9 and len(f) == 2 * 9 * 5
    v, f, n = torus(2, 0.5, 7, 5)
    assert len(v) == 35 and len(f) == 70


def test_obj_round_trip():
    v, f, n = torus(1, 0.3, 9, 6)
    for normals in (None, n):
        buf = io.StringIO()
        write_obj(buf, v, f, normals)
        buf.seek(0)
        v2, f2, n2 = read_obj(buf)
        np.testing.assert_array_equal(v2, v)
        np.testing.assert_array_equal(f2, f)
        if normals is None:
            assert n2 is None
        else:
            np.testing.assert_array_equal(n2, n)


def test_obj_forms_fans_and_negative_indices(tmp_path):
    text = """# a quad and a triangle
o thing
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0 1.0
vt 0 0
vn 0 0 1
vn 0 0 -1
g group
s off
f 1/1/1 2/1/1 3/1/1 4/1/1
f -4//-2 -2//-1 -1//-1
"""
    p = tmp_path / "m.obj"
    p.write_text(text)
    v, f, n = read_obj(str(p))
    # the second face: vertices 1, 3, 4 with normals 1, 2, 2: vertex 1 (index
    # 0) keeps normal 1 as before, 3 and 4 (indices 2, 3) come again as copies
    np.testing.assert_array_equal(v, [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (1, 1, 0), (0, 1, 0)])
    np.testing.assert_array_equal(f, [(0, 1, 2), (0, 2, 3), (0, 4, 5)])
    np.testing.assert_array_equal(n, [(0, 0, 1)] * 4 + [(0, 0, -1)] * 2)
    v, f, n = read_obj(io.StringIO("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nf 1 2 3 4\nf 2/7 3/1 -1/2\n"))
    np.testing.assert_array_equal(f, [(0, 1, 2), (0, 2, 3), (1, 2, 3)])
    assert n is None


@pytest.mark.parametrize("text, words", [
    ("v 0 0\n", "3 numbers"),
    ("v 0 x 0\n", "bad number"),
    ("v 0 0 nan\n", "non-finite"),
    ("v 0 0 0\nv 1 0 0\nf 1 2\n", "at least 3"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3//1\n", "some corners"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 3\n", "some faces"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n", "bad face corner"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf a 2 3\n", "bad vertex index"),
])
def test_obj_errors(text, words):
    with pytest.raises(ValueError, match=words):
        read_obj(io.StringIO(text))


def test_obj_error_names_the_line():
    with pytest.raises(ValueError, match=":3:"):
        read_obj(io.StringIO("v 0 0 0\n\nv 1 0\n"))


def test_render_mesh_errors():
    with pytest.raises(ValueError):
        render_mesh(FRONT, [(0, 1, 3)], shape=(8, 8))
    with pytest.raises(ValueError):
        render_mesh(FRONT, [(0, 1, 2)], shape=(8, 8), shading="phong")
    with pytest.raises(ValueError):
        render_mesh(FRONT, [(0, 1, 2)], shape=(8, 8), light=(0, 0, 0))
    with pytest.raises(ValueError):
        render_mesh(FRONT, [(0, 1, 2)], shape=(8, 8), projection="perspective", distance=-1)
    with pytest.raises(ValueError):
        sphere(1, 5)
    with pytest.raises(ValueError):
        torus(1, 2)


@settings(max_examples=examples(30))
@given(yaw=st.floats(-180, 180), pitch=st.floats(-90, 90), roll=st.floats(-180, 180))
def test_any_view_of_the_sphere_culled_equals_unculled(yaw, pitch, roll):
    v, f, n = sphere(6, 10)
    kw = dict(normals=n, shading="gouraud", rotation=rotation(yaw, pitch, roll), scale=0.8)
    a = render_mesh(v, f, shape=(40, 48), **kw)
    b = render_mesh(v, f, shape=(40, 48), cull=False, **kw)
    np.testing.assert_array_equal(a.array, b.array)

"""A small mesh pipeline (after the textbook's chapters): camera, viewport, back-face
culling, Lambert shading (flat or Gouraud), optional depth buffer.

Everything here is plain numpy in floating point, like any application of
the library: the geometry ends as float pixel coordinates, per-corner
colours and quantised depths, handed to ONE call of the integer core
(:meth:`Canvas.fill_triangles` with ``vertex_colors`` and ``depth``).

Conventions
-----------
World and camera space are right-handed: x right, y up, z towards the
viewer.  The camera first rotates the mesh (``rotation``, a 3x3 matrix; see
:func:`rotation`), then projects it:

* ``"orthographic"``: (x, y) scaled by ``scale``; the depth of a point is
  its distance -z in front of the plane z = 0 (smaller is nearer);
* ``"perspective"``: the eye sits at (0, 0, ``distance``) looking down -z
  with a vertical field of view ``fov`` degrees; a point at distance
  d = distance - z projects to (x, y) * f / d, f = 1 / tan(fov / 2), and
  its depth is -1/d, which unlike d is linear in screen space (so the
  core's linear interpolation of depth across a triangle is exact).

x is divided by the aspect ratio W / H so that a circle stays round.  That
gives normalised device coordinates (NDC) with the visible square
[-1, 1]^2, y up.

Viewport (the textbook's M_viewport, y flipped): NDC (x, y) goes to pixel
coordinates ((x + 1) W / 2, (1 - y) H / 2): x grows right and y DOWN, the
NDC square covers the canvas [0, W] x [0, H] exactly, and the sample of
pixel (i, j) is its centre (i + 1/2, j + 1/2), which is the NDC point
((2 i + 1) / W - 1, 1 - (2 j + 1) / H).

Faces are front faces when their vertices run counter-clockwise as seen
(in NDC, y up; the OBJ and OpenGL convention), which is clockwise in pixel
coordinates (y down).  Back-face culling keeps the faces whose NDC signed
area is positive; zero-area faces own no pixel anyway.

Lambert: with unit normal n and unit light direction l (towards
the light, in camera space), the intensity is
``ambient + (1 - ambient) * max(0, n . l)`` and the colour
``floor(color * intensity + 1/2)`` per channel.  "flat" takes n from the
face's plane (the cross product of its edges) and paints the face in one
colour; "gouraud" evaluates Lambert at each vertex with the vertex normal
and lets the core interpolate the colours across the face (the textbook's
smooth shading: no Mach bands at the edges).

Depth: the depths of the visible faces are mapped linearly onto the
integers 0 .. 2^24 - 1 (int32), and a sample is written iff its
interpolated depth is less than the depth buffer's (nearer wins; the
buffer starts at its largest value).
"""

from __future__ import annotations

import io
import math
import os

from typing import IO, TYPE_CHECKING, Any, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from ._core import InputError
from ._typing import Color, Format, Precision, Shading

if TYPE_CHECKING:
    from ._canvas import Canvas

__all__ = ["render_mesh", "sphere", "torus", "read_obj", "write_obj", "rotation", "project",
           "lambert", "vertex_normals"]

DEPTH_MAX = (1 << 24) - 1


# ---- meshes -----------------------------------------------------------------------

def sphere(n_lat: int = 16, n_lon: int = 32
           ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.float64]]:
    """The unit sphere as a UV mesh: (vertices (V, 3), faces (F, 3), normals (V, 3)).

    `n_lat` bands from pole to pole (>= 2), `n_lon` segments around
    (>= 3).  Faces are counter-clockwise seen from outside; the poles are
    single vertices, so the mesh is closed.
    """
    n_lat, n_lon = _count(n_lat, "n_lat", 2), _count(n_lon, "n_lon", 3)
    verts = [(0.0, 1.0, 0.0)]
    for i in range(1, n_lat):
        theta = math.pi * i / n_lat
        for k in range(n_lon):
            phi = 2 * math.pi * k / n_lon
            verts.append((math.sin(theta) * math.cos(phi), math.cos(theta),
                          -math.sin(theta) * math.sin(phi)))
    verts.append((0.0, -1.0, 0.0))
    v = np.array(verts)
    south = len(verts) - 1

    def ring(i, k):  # vertex k of latitude ring i (1 .. n_lat - 1)
        return 1 + (i - 1) * n_lon + k % n_lon

    faces = []
    for k in range(n_lon):
        faces.append((0, ring(1, k), ring(1, k + 1)))
        faces.append((south, ring(n_lat - 1, k + 1), ring(n_lat - 1, k)))
    for i in range(1, n_lat - 1):
        for k in range(n_lon):
            a, b = ring(i, k), ring(i, k + 1)
            c, d = ring(i + 1, k), ring(i + 1, k + 1)
            faces.append((a, c, d))
            faces.append((a, d, b))
    return v, np.array(faces, np.int64), v.copy()


def torus(R: float = 1.0, r: float = 0.4, n: int = 32, m: int = 16
          ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.float64]]:
    """A torus around the y axis: (vertices, faces, normals).

    Ring radius `R`, tube radius `r` (0 < r < R), `n` segments around the
    ring and `m` around the tube (each >= 3).  Closed; faces
    counter-clockwise seen from outside.
    """
    n, m = _count(n, "n", 3), _count(m, "m", 3)
    R, r = _real(R, "torus: R"), _real(r, "torus: r")
    if not (0 < r < R):
        raise InputError("torus needs 0 < r < R, not R=%r r=%r" % (R, r))
    u = 2 * math.pi * np.arange(n) / n
    w = 2 * math.pi * np.arange(m) / m
    U, Wt = np.meshgrid(u, w, indexing="ij")
    # Around the ring in the x-z plane, counter-clockwise seen from +y.
    cx, cz = np.cos(U), -np.sin(U)
    normals = np.stack([np.cos(Wt) * cx, np.sin(Wt), np.cos(Wt) * cz], -1).reshape(-1, 3)
    centres = np.stack([R * cx, np.zeros_like(cx), R * cz], -1).reshape(-1, 3)
    verts = centres + r * normals
    idx = np.arange(n * m).reshape(n, m)
    a = idx
    b = np.roll(idx, -1, axis=0)             # next around the ring
    c = np.roll(idx, -1, axis=1)             # next around the tube
    d = np.roll(np.roll(idx, -1, axis=0), -1, axis=1)
    faces = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3),
                            np.stack([a, d, c], -1).reshape(-1, 3)])
    return verts, faces.astype(np.int64), normals


def _count(v, name, least):
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < least:
        raise InputError("%s must be an int >= %d, not %r" % (name, least, v))
    return int(v)


# ---- OBJ ----------------------------------------------------------------------------

MAX_FACE_CORNERS = 1 << 16


def read_obj(source: Union[str, os.PathLike[str], IO[str]], *, max_face_corners: int = MAX_FACE_CORNERS
             ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Optional[npt.NDArray[np.float64]]]:
    """Read a Wavefront OBJ mesh: (vertices (V, 3), faces (F, 3), normals (V, 3) or None).

    `source` is a path or a text file object.  Understood: ``v x y z [w]``,
    ``vn x y z``, ``f`` with corners ``i``, ``i/t``, ``i/t/n`` or ``i//n``
    (1-based; negative indices count back from the last one read); faces of
    more than three corners are fanned into triangles from their first
    corner.  Other statements (vt, o, g, s, usemtl, mtllib, l, comments)
    are ignored.  When faces carry normal indices, `normals` is per vertex:
    a vertex takes the first normal a face gives it, and each other
    normal it is given makes a copy of the vertex (appended after the
    others); a vertex no face uses gets (0, 0, 0).

    Raises InputError naming the line for a malformed number, a face of
    fewer than 3 corners or more than `max_face_corners` (default 65536: a
    face is fanned into corners - 2 triangles, and one 30 MB line of
    corners would otherwise take gigabytes; None for no limit), an index
    of 0 or out of range, or faces that give normals for some corners but
    not others.
    """
    if max_face_corners is not None and (
            isinstance(max_face_corners, (bool, np.bool_)) or not isinstance(max_face_corners, (int, np.integer))
            or max_face_corners < 3):
        raise InputError("max_face_corners must be an int >= 3 or None, not %r" % (max_face_corners,))
    if isinstance(source, (str, os.PathLike)):
        with open(source, "r", encoding="utf-8") as f:
            try:
                return _read_obj(f, str(source), max_face_corners)
            except UnicodeDecodeError as e:
                raise InputError("%s: not a text (UTF-8) OBJ file: %s" % (source, e)) from None
    if not hasattr(source, "read"):
        raise InputError("source must be a path or a text file object, not %r" % (source,))
    return _read_obj(source, getattr(source, "name", "<obj>"), max_face_corners)


def _read_obj(f, name, max_corners=None):
    vs, vns, corners = [], [], []  # corners: per face, list of (v, n or None)
    for lineno, line in enumerate(f, 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        # At most max_corners + 1 fields (the rest of the line stays one
        # string): a face past the limit is found without splitting it all.
        parts = line.split() if max_corners is None else line.split(None, max_corners + 1)
        tag, args = parts[0], parts[1:]
        if max_corners is not None and tag == "f" and len(args) > max_corners:
            raise InputError("%s:%d: a face of more than max_face_corners=%d corners (pass a larger "
                             "max_face_corners, or None, to read it)" % (name, lineno, max_corners))
        where = "%s:%d" % (name, lineno)
        if tag in ("v", "vn"):
            if len(args) < 3 or (tag == "vn" and len(args) != 3) or len(args) > 4:
                raise InputError("%s: %s needs 3 numbers, got %r" % (where, tag, line))
            try:
                xyz = tuple(float(a) for a in args[:3])
            except ValueError:
                raise InputError("%s: bad number in %r" % (where, line)) from None
            if not all(math.isfinite(c) for c in xyz):
                raise InputError("%s: non-finite number in %r" % (where, line))
            (vs if tag == "v" else vns).append(xyz)
        elif tag == "f":
            if len(args) < 3:
                raise InputError("%s: a face needs at least 3 corners, got %r" % (where, line))
            face = []
            for a in args:
                fields = a.split("/")
                if len(fields) > 3 or not fields[0]:
                    raise InputError("%s: bad face corner %r" % (where, a))
                vi = _obj_index(fields[0], len(vs), where, "vertex")
                ni = None
                if len(fields) == 3 and fields[2]:
                    ni = _obj_index(fields[2], len(vns), where, "normal")
                face.append((vi, ni))
            if len({n is None for _, n in face}) > 1:
                raise InputError("%s: normals given for some corners only: %r" % (where, line))
            corners.append(face)
    with_n = [face[0][1] is not None for face in corners]
    if any(with_n) and not all(with_n):
        raise InputError("%s: some faces give normals and others do not" % name)
    verts = np.array(vs, np.float64).reshape(-1, 3)
    tris = [(face[0], face[k], face[k + 1]) for face in corners for k in range(1, len(face) - 1)]
    if not any(with_n):
        faces = np.array([[c[0] for c in t] for t in tris], np.int64).reshape(-1, 3)
        return verts, faces, None
    # Normals per vertex: a vertex keeps its place and takes the first normal
    # it is used with; each further (vertex, normal) pair it is used with
    # becomes a new vertex after the others.  Unused vertices get (0, 0, 0).
    out_v = list(vs)
    out_n = [None] * len(vs)
    index, faces = {}, []
    for t in tris:
        row = []
        for vi, ni in t:
            if (vi, ni) not in index:
                if out_n[vi] is None:
                    out_n[vi] = vns[ni]
                    index[(vi, ni)] = vi
                else:
                    index[(vi, ni)] = len(out_v)
                    out_v.append(vs[vi])
                    out_n.append(vns[ni])
            row.append(index[(vi, ni)])
        faces.append(row)
    out_n = [(0.0, 0.0, 0.0) if c is None else c for c in out_n]
    return (np.array(out_v, np.float64).reshape(-1, 3), np.array(faces, np.int64).reshape(-1, 3),
            np.array(out_n, np.float64).reshape(-1, 3))


def _obj_index(text, count, where, what):
    try:
        k = int(text)
    except ValueError:
        raise InputError("%s: bad %s index %r" % (where, what, text)) from None
    if k > 0 and k <= count:
        return k - 1
    if k < 0 and -k <= count:
        return count + k
    raise InputError("%s: %s index %d out of range (%d read so far)" % (where, what, k, count))


def write_obj(target: Union[str, os.PathLike[str], IO[str]], vertices: npt.ArrayLike, faces: npt.ArrayLike,
              normals: Optional[npt.ArrayLike] = None) -> None:
    """Write a triangle mesh as OBJ text to a path or a text file object
    (``v`` lines with 17 significant digits, so floats read back equal;
    ``f i//i`` when there are normals)."""
    if not isinstance(target, (str, os.PathLike)) and not callable(getattr(target, "write", None)):
        raise InputError("write_obj: target must be a path or a text file object, not %s" % type(target).__name__)
    v, fc, n = _mesh(vertices, faces, normals)
    out = io.StringIO()
    for p in v:
        out.write("v %.17g %.17g %.17g\n" % tuple(p))
    if n is not None:
        for p in n:
            out.write("vn %.17g %.17g %.17g\n" % tuple(p))
    for t in fc + 1:
        if n is None:
            out.write("f %d %d %d\n" % tuple(t))
        else:
            out.write("f %d//%d %d//%d %d//%d\n" % (t[0], t[0], t[1], t[1], t[2], t[2]))
    if isinstance(target, (str, os.PathLike)):
        with open(target, "w", encoding="utf-8") as f:
            f.write(out.getvalue())
    else:
        target.write(out.getvalue())


# ---- camera, viewport, shading ------------------------------------------------

def rotation(yaw: float = 0.0, pitch: float = 0.0, roll: float = 0.0) -> npt.NDArray[np.float64]:
    """A 3x3 rotation: `roll` about z, then `pitch` about x, then `yaw`
    about y, in degrees (a positive yaw turns the mesh's front to the
    right, a positive pitch tilts its top towards the viewer)."""
    a, b, c = (math.radians(_real(t, "rotation: " + w)) for t, w in ((yaw, "yaw"), (pitch, "pitch"), (roll, "roll")))
    ry = np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])
    rx = np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    return ry @ rx @ rz


def _real(x, what):
    """A finite real number (not a bool or a string), as a float."""
    try:
        ok = not isinstance(x, (bool, np.bool_)) and isinstance(x, (int, float, np.integer, np.floating)) \
            and math.isfinite(x)
    except OverflowError:  # an int past float's range
        ok = False
    if not ok:
        raise InputError("%s must be a finite number, not %r" % (what, x))
    return float(x)


def _finite(x, what, shape, text):
    """A float64 array of `shape`, all finite, or InputError naming `what`."""
    from ._core import real_array
    a = real_array(x, what, text)
    if a.shape != shape:
        raise InputError("%s must be %s, not shape %s" % (what, text, a.shape))
    if not np.all(np.isfinite(a)):
        bad = np.argwhere(~np.isfinite(a))[0]
        raise InputError("%s must be finite: %s at index %s" % (what, a[tuple(bad)], tuple(int(i) for i in bad)))
    return a


def _mesh(vertices, faces, normals=None):
    from ._core import real_array
    v = real_array(vertices, "vertices", "a (V, 3) array-like")
    try:
        f = np.asarray(faces)
    except (TypeError, ValueError):
        raise InputError("faces must be (F, 3) ints") from None
    if v.ndim != 2 or v.shape[1] != 3:
        raise InputError("vertices must have shape (V, 3), not %s" % (v.shape,))
    if not np.all(np.isfinite(v)):
        raise InputError("vertices must be finite")
    if f.size == 0:
        f = f.reshape(0, 3).astype(np.int64)
    if f.ndim != 2 or f.shape[1] != 3 or f.dtype.kind not in "iu":
        raise InputError("faces must be an int array of shape (F, 3), not %s %s" % (f.dtype, f.shape))
    if f.size and (f.min() < 0 or f.max() >= len(v)):
        raise InputError("faces index vertices 0..%d only" % (len(v) - 1))
    n = None
    if normals is not None:
        n = _finite(normals, "normals", v.shape, "the shape of vertices %s" % (v.shape,))
    return v, f.astype(np.int64), n


def project(vertices: npt.ArrayLike, size: Tuple[int, int], *, rotation: Optional[npt.ArrayLike] = None,
            projection: Literal["orthographic", "perspective"] = "orthographic", scale: float = 1.0,
            fov: float = 40.0, distance: float = 4.0) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Camera and viewport: (pixel xy (V, 2), depth key (V,), camera-space
    vertices (V, 3)).  See the module's conventions; a smaller key is
    nearer."""
    from ._core import int_pair, real_array
    v = real_array(vertices, "project: vertices", "a (V, 3) array")
    if v.ndim != 2 or v.shape[1] != 3 or not np.all(np.isfinite(v)):
        raise InputError("project: vertices must be a (V, 3) array of finite numbers, not shape %s" % (v.shape,))
    w, h = int_pair(size, "project: size must be a pair (width, height), not %r",
                    "project: size must hold two ints, not %r")
    scale, fov, distance = _real(scale, "project: scale"), _real(fov, "project: fov"), _real(distance, "project: distance")
    rot = np.eye(3) if rotation is None else real_array(rotation, "rotation", "a 3x3 matrix")
    if rot.shape != (3, 3):
        raise InputError("rotation must be a 3x3 matrix, not shape %s" % (rot.shape,))
    cam = v @ rot.T
    if projection == "orthographic":
        xy = cam[:, :2] * float(scale)
        key = -cam[:, 2]
    elif projection == "perspective":
        d = float(distance) - cam[:, 2]
        if np.any(d <= 0):
            raise InputError("a vertex is at or behind the eye (distance %g)" % distance)
        f = 1.0 / math.tan(math.radians(float(fov)) / 2)
        xy = cam[:, :2] * (float(scale) * f / d)[:, None]
        key = -1.0 / d
    else:
        raise InputError("unknown projection %r; choose orthographic or perspective" % (projection,))
    xy = xy * np.array([h / w, 1.0]) if w else xy
    return viewport(xy, size), key, cam


def viewport(ndc: npt.ArrayLike, size: Tuple[int, int]) -> npt.NDArray[np.float64]:
    """NDC (N, 2), y up, to pixel coordinates: ((x + 1) W/2, (1 - y) H/2)."""
    w, h = size
    ndc = np.asarray(ndc, dtype=np.float64)
    return np.stack([(ndc[:, 0] + 1) * (w / 2), (1 - ndc[:, 1]) * (h / 2)], -1)


def face_normals(v: npt.NDArray[np.float64], faces: npt.NDArray[np.integer[Any]]) -> npt.NDArray[np.float64]:
    """Unit normals of the faces' planes, (v1 - v0) x (v2 - v0) normalised
    (zero for a degenerate face)."""
    t = v[faces]
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 0)


def vertex_normals(vertices: npt.ArrayLike, faces: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Per-vertex normals: the area-weighted sum of the adjacent faces'
    normals, normalised (what a mesh without ``vn`` gets for Gouraud)."""
    v, f, _ = _mesh(vertices, faces)
    t = v[f]
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])  # twice the area, along the normal
    acc = np.zeros_like(v)
    for k in range(3):
        np.add.at(acc, f[:, k], n)
    length = np.linalg.norm(acc, axis=1, keepdims=True)
    return np.divide(acc, length, out=np.zeros_like(acc), where=length > 0)


def lambert(normals: npt.ArrayLike, light: npt.ArrayLike, ambient: float, color: npt.ArrayLike) -> npt.NDArray[np.int64]:
    """Colours (N, C) uint8 of Lambert shading for unit `normals` (N, 3):
    floor(color * (ambient + (1 - ambient) max(0, n . l)) + 1/2)."""
    from ._core import real_array
    l = real_array(light, "lambert: light", "3 numbers")
    nrm = real_array(normals, "lambert: normals", "an (N, 3) array")
    c = real_array(color, "lambert: color", "1-D numbers")
    ambient = _real(ambient, "lambert: ambient")
    if l.shape != (3,) or not np.all(np.isfinite(l)) or not np.any(l):
        raise InputError("lambert: light must be 3 finite numbers, not all 0")
    if nrm.ndim != 2 or nrm.shape[1] != 3 or not np.all(np.isfinite(nrm)):
        raise InputError("lambert: normals must be an (N, 3) array of finite numbers, not shape %s" % (nrm.shape,))
    if c.ndim != 1 or not np.all(np.isfinite(c)):
        raise InputError("lambert: color must be 1-D finite numbers, not shape %s" % (c.shape,))
    l = l / np.linalg.norm(l)
    k = ambient + (1 - ambient) * np.clip(nrm @ l, 0, None)
    return np.floor(k[:, None] * c[None, :] + 0.5).astype(np.int64)


def render_mesh(vertices: npt.ArrayLike, faces: npt.ArrayLike, size: Optional[Tuple[int, int]] = None, *,
                shape: Optional[Tuple[int, int]] = None, normals: Optional[npt.ArrayLike] = None,
                shading: Shading = "flat", light: Sequence[float] = (-0.4, 0.5, 0.75), ambient: float = 0.15,
                color: Optional[Color] = None, rotation: Optional[npt.ArrayLike] = None,
                projection: Literal["orthographic", "perspective"] = "orthographic", scale: float = 1.0,
                fov: float = 40.0, distance: float = 4.0, cull: bool = True, depth: bool = True,
                background: Color = 0, format: Format = "rgb888", canvas: Optional[Canvas] = None,
                precision: Precision = "exact", subpixel_bits: int = 8) -> Canvas:
    """Render a triangle mesh into a Canvas (a new one, or `canvas`).

    Parameters
    ----------
    vertices : (V, 3) array_like
        Positions in world space (x right, y up, z towards the viewer).
    faces : (F, 3) int array_like
        Vertex indices, counter-clockwise seen from the front.
    shape : (int, int)
        (height, width) of a new canvas, as numpy writes it; default
        (256, 256).  With `canvas`, None or the canvas's own shape.
    size : (int, int)
        Deprecated: the old spelling, (width, height), by position or as
        ``size=``; it still works for one release, with a
        DeprecationWarning.
    normals : (V, 3) array_like, optional
        Vertex normals for "gouraud" (else :func:`vertex_normals`).
    shading : {"flat", "gouraud"}
        Lambert per face, or per vertex then interpolated.
    light : 3 numbers
        Direction towards the light, in camera space.
    ambient : float in [0, 1]
        Intensity of a face turned away from the light.
    color : sequence of C ints, or one int
        The surface colour (C = the canvas's channels); None: 230 in
        every channel.
    rotation, projection, scale, fov, distance
        The camera: see :func:`project` and the module's conventions.
    cull : bool
        Drop back faces (negative NDC area) before drawing.
    depth : bool
        Use the canvas's depth buffer (cleared first): nearer wins.
        Without it, faces are drawn in order and the last one wins.
    precision : {"exact", "fixed"}
        The colour interpolation of the core (``Canvas.fill_triangles``);
        ``"flat"`` is deprecated (use ``shading="flat"``).

    Returns
    -------
    Canvas

    Examples
    --------
    >>> import rastrum
    >>> from rastrum.scene import sphere
    >>> v, f, n = sphere(8, 16)
    >>> c = rastrum.render_mesh(v, f, shape=(32, 32), normals=n, shading="gouraud")
    >>> c.array.shape
    (32, 32, 3)
    """
    from ._canvas import Canvas

    v, f, n = _mesh(vertices, faces, normals)
    if not isinstance(shading, str) or shading not in ("flat", "gouraud"):
        raise InputError("unknown shading %r; choose flat or gouraud" % (shading,))
    ambient = _real(ambient, "ambient")
    if not 0 <= ambient <= 1:
        raise InputError("ambient must be in [0, 1], not %r" % (ambient,))
    light = _finite(light, "light", (3,), "3 numbers (x, y, z)")
    if np.linalg.norm(light) == 0:
        raise InputError("light must be a non-zero direction")
    if rotation is not None:
        rotation = _finite(rotation, "rotation", (3, 3), "a 3x3 matrix")
    scale = _real(scale, "scale")
    if projection == "perspective":
        fov, distance = _real(fov, "fov"), _real(distance, "distance")
        if not 0 < fov < 180:
            raise InputError("fov must be in (0, 180) degrees, not %r" % (fov,))
    for name, flag in (("cull", cull), ("depth", depth)):
        if not isinstance(flag, (bool, np.bool_)):
            raise InputError("%s must be True or False, not %r" % (name, flag))
    from ._core import deprecated, int_pair, plural, shape2
    if size is not None:
        if shape is not None:
            raise InputError("render_mesh takes shape=(height, width), not also size")
        width, height = int_pair(size, "size must be a pair (width, height), not %r",
                                 "size must hold two ints (width, height), not %r")
        deprecated("render_mesh(..., size=(width, height)) is now shape=(height, width), as numpy writes it")
        shape = (height, width)
    if precision == "flat":
        deprecated('render_mesh(precision="flat") is now shading="flat"')
    if canvas is None:
        canvas = Canvas(shape2((256, 256) if shape is None else shape), format=format, background=background)
    elif not isinstance(canvas, Canvas):
        raise InputError("canvas must be a rastrum.Canvas, not %s" % type(canvas).__name__)
    elif shape is not None and shape2(shape) != (canvas.height, canvas.width):
        raise InputError("shape %r does not match the canvas's (height, width) = (%d, %d)%s"
                         % (shape, canvas.height, canvas.width,
                            " (swapped?)" if shape2(shape) == (canvas.width, canvas.height) else ""))
    channels = canvas.array.shape[2] if canvas.array.ndim == 3 else 1
    if color is None:
        color = (230,) * channels
    if isinstance(color, str):  # a colour name or "#rrggbb", as the Canvas takes it
        from ._canvas import _color_name
        color = _color_name(color, canvas.format)
    col = np.asarray(color)
    if col.dtype.kind not in "iu" or col.ndim > 1 or (col.size != channels and col.size != 1):
        raise InputError("color must be %s in 0..255 for format %s, not %r"
                         % (" or ".join(sorted({"1 int", plural(channels, "int")})), canvas.format, color))
    if col.min() < 0 or col.max() > 255:
        raise InputError("color: every channel must be in 0..255, not %r" % (color,))
    w, h = canvas.width, canvas.height
    xy, key, cam = project(v, (w, h), rotation=rotation, projection=projection, scale=scale, fov=fov,
                           distance=distance)
    rot = np.eye(3) if rotation is None else np.asarray(rotation, dtype=np.float64)
    f_all = f
    tri_xy = xy[f]
    if cull and len(f):
        f = f[front_facing(tri_xy)]
        tri_xy = xy[f]
    col = np.broadcast_to(col.astype(np.int64).reshape(-1), (channels,))
    if not np.all(np.isfinite(xy)):
        raise InputError("the projected vertices are not finite (scale %r, fov %r, distance %r)"
                         % (scale, fov, distance))
    if shading == "flat":
        face_c = lambert(face_normals(cam, f), light, float(ambient), col)
        vcol = np.repeat(face_c[:, None, :], 3, axis=1)
    else:
        vn = vertex_normals(v, f_all) if n is None else n
        vcol = lambert(vn @ rot.T, light, float(ambient), col)[f]
    zq, kept = None, canvas.depth
    if depth:
        zq = quantise_depth(key)[f]
        canvas.clear_depth()
    try:
        canvas.fill_triangles(tri_xy, vertex_colors=vcol, depth=zq, subpixel_bits=subpixel_bits,
                              **({"shading": "flat"} if precision == "flat" else {"precision": precision}))
    except InputError as e:
        canvas.depth = kept  # nothing was drawn: the depth buffer as it was
        if str(e).startswith("tris"):  # the projected triangles: name what the caller gave
            raise InputError("render_mesh: the projected mesh is out of range (scale, fov or distance "
                             "too large?): %s" % e) from None
        raise
    return canvas


def front_facing(tri_xy: npt.ArrayLike) -> npt.NDArray[np.bool_]:
    """Which triangles (pixel coordinates, y down) are front faces:
    counter-clockwise in NDC (y up), that is a negative signed area in
    pixels."""
    t = np.asarray(tri_xy, dtype=np.float64)
    a = ((t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1])
         - (t[:, 2, 0] - t[:, 0, 0]) * (t[:, 1, 1] - t[:, 0, 1]))
    return a < 0


def quantise_depth(key: npt.ArrayLike) -> npt.NDArray[np.int32]:
    """Depth keys onto 0 .. DEPTH_MAX (int32), linearly over their range."""
    key = np.asarray(key, dtype=np.float64)
    if key.size == 0:
        return key.astype(np.int32)
    lo, hi = key.min(), key.max()
    if hi == lo:
        return np.zeros(key.shape, np.int32)
    return np.floor((key - lo) / (hi - lo) * DEPTH_MAX + 0.5).astype(np.int32)

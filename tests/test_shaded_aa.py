"""Anti-aliased Gouraud triangle batches (``fill_triangles(vertex_colors=...,
aa=...)``, rast_fill_triangles_shaded_aa) against an exact reference
written here from the documented definition, in rational arithmetic:

- coverage c: the batch's union coverage; the levels rastrum gives
  (``triangles_coverage``, the ones the fill blends with) are first held
  against the exact oracles (oracle_coverage.py: area within half a level
  of 255 a, ssK bit for bit);
- colour of a pixel a triangle owns: the binary shaded fill's colour
  (oracle_shade.py: ownership from the binary oracle, barycentric value
  at the sample, floor(v + 1/2));
- colour of a silhouette pixel (c > 0, owned by none): the last
  non-degenerate triangle whose closed region meets the closed pixel
  square (a separating-axis test on Fractions, not the C code's row
  extents), its plane at the sample, rounded, clamped to 0..255;
- the colour, packed for the format (oracle_shade.pack), blended with c:
  channel (s c + d (255 - c) + 127) // 255 (rgb565 on its 5/6/5 fields),
  mono1 the value where c >= 128.
"""

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage
import oracle_shade
import rastrum
import strategies as S_
from oracle import snap
from test_coverage_paint import mix, random_canvas  # the blend written from the docs; guarded canvases

METHODS = ["area", "ss2", "ss4", "ss8", "ss16", "accumulate"]
FORMATS = ["gray8", "rgb888", "rgba8888", "rgb565", "mono1"]
NCH = {"gray8": 1, "mono1": 1, "rgb888": 3, "rgb565": 3, "rgba8888": 4}


def _snapped(tri, S):
    g = 1 << S
    return [(F(snap(x, S), g), F(snap(y, S), g)) for x, y in tri]


def _area2(v):
    return (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])


def touches(v, i, j):
    """Do the closed triangle v (snapped, pixels) and the closed square
    [i, i+1] x [j, j+1] meet?  Convex and closed: they are disjoint iff
    their projections on one of the sides' normals are disjoint."""
    square = [(F(i), F(j)), (F(i + 1), F(j)), (F(i + 1), F(j + 1)), (F(i), F(j + 1))]
    axes = [(1, 0), (0, 1)] + [(v[m][1] - v[(m + 1) % 3][1], v[(m + 1) % 3][0] - v[m][0])
                               for m in range(3)]
    for ax, ay in axes:
        pt = [ax * x + ay * y for x, y in v]
        ps = [ax * x + ay * y for x, y in square]
        if max(pt) < min(ps) or max(ps) < min(pt):
            return False
    return True


def reference_colors(tris, colors, shape, S, o, shading, cov):
    """(H, W, 4) ints: the documented colour of every pixel with cov > 0
    (-1 elsewhere)."""
    prec = "flat" if shading == "flat" else "exact"
    rgba, _ = oracle_shade.shade(tris, colors, shape, subpixel_bits=S, sample_offset=o,
                                 precision=prec)
    snapped = [_snapped(t, S) for t in tris]
    h, w = shape
    out = np.full((h, w, 4), -1, np.int64)
    for j in range(h):
        for i in range(w):
            if cov[j, i] == 0:
                continue
            if rgba[j, i, 0] >= 0:
                out[j, i] = rgba[j, i]
                continue
            ks = [k for k, v in enumerate(snapped) if _area2(v) != 0 and touches(v, i, j)]
            assert ks, "coverage %d at (%d, %d) with no triangle touching" % (cov[j, i], i, j)
            k = ks[-1]
            p = (i + F(o), j + F(o))
            for c in range(4):
                if prec == "flat":
                    out[j, i, c] = int(colors[k][0][c])
                else:
                    vals = [int(colors[k][m][c]) for m in range(3)]
                    out[j, i, c] = min(max(oracle_shade._round(oracle_shade.interpolate(
                        tris[k], vals, p, S)), 0), 255)
    return out


def blended(fmt, before, rgba, cov):
    """The documented blend of per-pixel colours rgba (H, W, 4) with cov."""
    src = oracle_shade.pack(np.where(rgba < 0, 0, rgba), fmt).astype(np.int64)
    d = before.astype(np.int64)
    if fmt in ("gray8", "rgb888", "rgba8888"):
        c = cov if fmt == "gray8" else cov[..., None]
        out = mix(src, d, c)
    elif fmt == "rgb565":
        out = (mix(src >> 11, d >> 11, cov) << 11) | (mix((src >> 5) & 63, (d >> 5) & 63, cov) << 5) \
            | mix(src & 31, d & 31, cov)
    else:
        out = np.where(cov >= 128, src, d)
    keep = cov == 0
    if out.ndim == 3:
        keep = keep[..., None]
    return np.where(keep, d, out).astype(before.dtype)


def checked_coverage(tris, shape, method, S, o):
    """rastrum's coverage levels, held against the exact oracles first."""
    cov = rastrum.triangles_coverage(tris, shape, method=method, subpixel_bits=S, sample_offset=o)
    rl = [list(map(tuple, t)) for t in tris]
    if method == "area":
        a = oracle_coverage.coverage_exact(rl, shape, subpixel_bits=S, triangles=True)
        err = np.abs(cov.astype(object) - a * 255)
        assert all(e <= F(1, 2) + F(1, 2 ** 20) for e in err.ravel())
    elif method.startswith("ss"):
        k = int(method[2:])
        want = oracle_coverage.coverage_ss(rl, shape, k, subpixel_bits=S, sample_offset=o,
                                           triangles=True)
        np.testing.assert_array_equal(cov, want)
    return cov.astype(np.int64)


def check(tris, colors, shape, fmt, method, S, o, shading, seed):
    rng = np.random.default_rng(seed)
    canvas, guard = random_canvas(fmt, shape, rng)
    before = canvas.array.copy()
    cov = checked_coverage(tris, shape, method, S, o)
    vc = np.asarray(colors)[..., :NCH[fmt]]
    canvas.fill_triangles(tris, vertex_colors=vc, shading=shading, subpixel_bits=S, sample_offset=o,
                          aa=method)
    # the colours the call reads: C channels widened as the binary fill does
    rgba = np.zeros(np.shape(colors), np.int64)
    rgba[..., :3] = vc[..., :1] if vc.shape[-1] == 1 else vc[..., :3]
    rgba[..., 3] = vc[..., 3] if vc.shape[-1] == 4 else 255
    ref = reference_colors(tris, rgba, shape, S, o, shading, cov)
    np.testing.assert_array_equal(canvas.array, blended(fmt, before, ref, cov))
    assert guard()
    return canvas, cov


@settings(max_examples=S_.examples(50), deadline=None)
@given(data=st.data(), fmt=st.sampled_from(FORMATS), method=st.sampled_from(METHODS),
       S=st.sampled_from([0, 2, 8]), o=st.sampled_from([0.5, 0.0]),
       shading=st.sampled_from(["gouraud", "gouraud", "flat"]), seed=st.integers(0, 2 ** 32 - 1))
def test_equals_reference(data, fmt, method, S, o, shading, seed):
    shape = data.draw(S_.shapes(10, 10), label="shape")
    h, w = shape
    n = data.draw(st.integers(1, 4), label="n")
    coord = st.one_of(st.floats(-2, max(h, w) + 2, allow_nan=False),
                      st.integers(-1, max(h, w) + 1).map(float))  # vertices on pixel corners
    tris = np.array(data.draw(st.lists(st.tuples(coord, coord), min_size=3 * n, max_size=3 * n),
                              label="v"), np.float64).reshape(n, 3, 2)
    colors = np.array(data.draw(st.lists(st.integers(0, 255), min_size=12 * n, max_size=12 * n),
                                label="colors")).reshape(n, 3, 4)
    check(tris, colors, shape, fmt, method, S, o, shading, seed)


def test_mesh_interior_is_the_binary_fill_and_bands_join():
    """A fan mesh over 40 rows (three bands of colour): every fully
    covered pixel has the binary shaded fill's colour exactly, no seam
    anywhere, and the whole equals the reference."""
    shape = (40, 23)
    c = (11.3, 19.7)
    ring = [(1.2, 0.6), (21.5, 2.25), (22.0, 30.0), (13.0, 39.4), (0.4, 33.3)]
    tris = np.array([[c, ring[k], ring[(k + 1) % len(ring)]] for k in range(len(ring))], np.float64)
    rng = np.random.default_rng(5)
    colors = rng.integers(0, 256, (len(tris), 3, 4))
    colors[:, 0] = (250, 240, 30, 255)  # the centre shared, so the mesh is continuous
    for k in range(len(tris)):  # each outer vertex one colour in both its triangles
        colors[k, 2] = colors[(k + 1) % len(tris), 1]
    canvas, cov = check(tris, colors, shape, "rgba8888", "area", 8, 0.5, "gouraud", 1)
    binary = rastrum.Canvas(shape, format="rgba8888")
    binary.fill_triangles(tris, vertex_colors=colors)
    aa = rastrum.Canvas(shape, format="rgba8888")
    aa.fill_triangles(tris, vertex_colors=colors, aa="area")
    full = cov == 255
    assert full.sum() > 500
    np.testing.assert_array_equal(aa.array[full], binary.array[full])
    inside = rastrum.polygon_coverage([ring], shape, method="area") == 255
    assert (cov[inside] == 255).all()  # no seam between the triangles


def test_single_triangle_and_clipped_geometry():
    tri = [(-3.25, -1.5), (14.75, 4.0), (2.0, 12.5)]
    vc = [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    check(np.array([tri], np.float64), np.array([[v + (255,) for v in vc]]), (9, 11), "rgb888",
          "ss4", 4, 0.5, "gouraud", 3)
    a = rastrum.Canvas((9, 11), format="rgb888")
    a.fill_triangle(tri, vertex_colors=vc, subpixel_bits=4, aa="ss4")
    b = rastrum.Canvas((9, 11), format="rgb888")
    b.fill_triangles([tri], vertex_colors=[vc], subpixel_bits=4, aa="ss4")
    np.testing.assert_array_equal(a.array, b.array)
    assert a.array.any()


def test_empty_batch_writes_nothing():
    c = rastrum.Canvas((4, 4), format="rgb888", background=(1, 2, 3))
    c.fill_triangles(np.zeros((0, 3, 2)), vertex_colors=np.zeros((0, 3, 3), np.uint8), aa="area")
    assert (c.array == (1, 2, 3)).all()


BAD = [
    (dict(precision="fixed"), r'precision="fixed" is for binary fills'),
    (dict(depth=[(1, 2, 3)]), r"depth is for binary shaded fills"),
    (dict(color=(1, 2, 3)), r"exactly one of color and vertex_colors"),
    (dict(vertex_colors=[[(1, 2, 3)] * 2]), r"vertex_colors"),
    (dict(algorithm="sweep"), r"algorithm='sweep' is for binary fills"),
    (dict(aa="bogus"), r"aa='bogus'"),
    (dict(tris=[[(0, 0), (1e12, 0), (0, 1)]]), r"tris"),
]


@pytest.mark.parametrize("kwargs,match", BAD, ids=[str(i) for i in range(len(BAD))])
def test_bad_input_writes_nothing(kwargs, match):
    canvas = rastrum.Canvas((6, 6), format="rgb888", background=(5, 6, 7))
    before = canvas.array.copy()
    kw = dict(aa="area", vertex_colors=[[(200, 0, 0), (0, 200, 0), (0, 0, 200)]])
    kw.update(kwargs)
    tris = kw.pop("tris", [[(0, 0), (5, 1), (2, 5)]])
    with pytest.raises(rastrum.InputError, match=match):
        canvas.fill_triangles(tris, **kw)
    np.testing.assert_array_equal(canvas.array, before)


def test_polygon_vertex_colors_with_aa_is_the_colour_polygon():
    # (It refused the pair until the anti-aliased colour polygon existed;
    # tests/test_shaded_polygon_aa.py holds that fill to its oracle.)  One
    # colour at every vertex: the one-colour anti-aliased fill, byte for byte.
    ring = [(0.3, 0.2), (5.6, 1.1), (2.2, 5.7)]
    canvas = rastrum.Canvas((6, 6), format="rgb888")
    canvas.fill_polygon(ring, vertex_colors=[(1, 2, 250)] * 3, aa="area")
    plain = rastrum.Canvas((6, 6), format="rgb888")
    plain.fill_polygon(ring, (1, 2, 250), aa="area")
    assert canvas.array.any() and (canvas.array == plain.array).all()
    with pytest.raises(rastrum.InputError, match=r"fixed"):
        canvas.fill_polygon(ring, vertex_colors=[(9, 9, 9)] * 3, aa="area", precision="fixed")
    assert (canvas.array == plain.array).all()

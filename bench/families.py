"""Scene families for bench/bench_scale.py: generators with a seed and a size.

Each family is a function ``make(seed, size)`` returning a :class:`Scene`:
rings of (x, y) float64 vertices in pixels on a size x size canvas (y down),
the fill rule, and how it is drawn:

- ``"poly"``: all rings in one call (polygon_mask / polygon_coverage);
- ``"tris"``: an (N, 3, 2) triangle batch in one call (triangles_mask /
  triangles_coverage, a union);
- ``"loop"``: one call per ring (Canvas.fill_polygon in a loop, cv2.fillPoly
  in a loop); the rings do not overlap, so the exact result of the loop is
  the exact coverage of the union.

The seed moves everything that is not the family's point: which words and
glyph sizes, which part of the map, where the triangles fall.  Nothing is
tuned to a seed; the runner reports each family's worst one.

Families (the issue 33 list):
  text      a paragraph of DejaVu Sans outlines (matplotlib's TextPath; curves
            flattened by matplotlib's fixed curve approximation), glyphs
            14-22 px, about 1,400 rings at 512 x 512;
  map       Natural Earth countries (pyogrio's naturalearth_lowres test data),
            plate carree, a seeded window over the world;
  tri3k, tri10k
            3,000 / 10,000 small overlapping triangles (2-24 px);
  span      canvas-spanning overlapping triangles (1,000; --span-count);
  mesh      a 40 x 40 jittered grid given as 3,200 triangle rings;
  loop      400 tiny polygons (4-8 vertices, 3-12 px), one call each;
  circle, star, holes, glyphs
            the scenes of bench/bench_coverage.py, shifted by a seeded
            sub-pixel offset.
"""

from __future__ import annotations

import functools
import glob
import os
import sys
from dataclasses import dataclass
from typing import Callable, Dict, List

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

#: canvas-spanning triangles per scene (10,000 is the issue's worst case)
SPAN_COUNT = 1000


@dataclass
class Scene:
    rings: List[np.ndarray]
    rule: str
    kind: str  # "poly", "tris" or "loop"
    size: int

    @property
    def edges(self) -> int:
        return int(sum(len(r) for r in self.rings))

    def tris(self) -> np.ndarray:
        return np.ascontiguousarray(np.asarray(self.rings, np.float64).reshape(-1, 3, 2))


def _ccw(tri):
    """Every triangle of an (N, 3, 2) batch turned the same way round, so
    that a peer's one non-zero path of them is their union (as
    triangles_* draw it), not a cancellation where two overlap."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    neg = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    tri[neg] = tri[neg][:, ::-1]
    return tri


def _rng(seed, name):
    return np.random.default_rng([seed, sum(map(ord, name))])


# ---- text -------------------------------------------------------------------------

_WORDS = ("the quick brown fox jumps over lazy dog rastrum fills polygons exactly with "
          "one rule shared by every algorithm text maps meshes and many small shapes "
          "Blend2D Natural Earth coverage area accumulate glyph outline paragraph "
          "QWERTY 0123456789 & @ % ? ! gjpqy").split()


@functools.lru_cache(maxsize=None)
def _font():
    from matplotlib.font_manager import FontProperties, findfont
    path = findfont(FontProperties(family="DejaVu Sans"))
    if "DejaVuSans" not in os.path.basename(path):
        raise RuntimeError("DejaVu Sans not found (matplotlib ships it): %s" % path)
    return FontProperties(fname=path)


def text(seed, size):
    """A paragraph: lines of seeded words at a seeded 14-22 px size each."""
    from matplotlib.textpath import TextPath
    rng = _rng(seed, "text")
    prop = _font()
    rings, y = [], 4.0
    scale = size / 512.0
    target = int(1400 * scale)  # rings: about 1,400 at 512, more at 2048 (more lines)
    while y < size - 24 and len(rings) < target:
        px = float(rng.uniform(14, 22))
        line = []
        while len(" ".join(line)) * px * 0.55 < size - 20:
            line.append(_WORDS[int(rng.integers(len(_WORDS)))])
        y += px * 1.1
        path = TextPath((0, 0), " ".join(line[:-1]), size=px, prop=prop)
        x0 = 4.0 + float(rng.uniform(0, 3))
        for poly in path.to_polygons(closed_only=True):
            p = np.asarray(poly, np.float64)[:-1]  # closed: last = first
            if len(p) >= 3:
                rings.append(np.ascontiguousarray(np.stack([x0 + p[:, 0], y - p[:, 1]], 1)))
    return Scene(rings, "nonzero", "poly", size)


# ---- map ----------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def _countries():
    """Every country's rings as (lon, lat) arrays (exterior and holes)."""
    import pyogrio
    import shapely
    base = os.path.dirname(pyogrio.__file__)
    shp = glob.glob(os.path.join(base, "tests", "fixtures", "naturalearth_lowres", "*.shp"))
    if not shp:
        raise RuntimeError("pyogrio's naturalearth_lowres test data not found")
    meta, fids, geoms, fields = pyogrio.raw.read(shp[0])
    out = []
    for g in shapely.from_wkb(geoms):
        for poly in getattr(g, "geoms", [g]):
            out.append(np.asarray(poly.exterior.coords)[:-1])
            out.extend(np.asarray(h.coords)[:-1] for h in poly.interiors)
    return out


def map_layer(seed, size):
    """Countries in plate carree, a seeded zoom (1-1.5x) and pan; y down."""
    rng = _rng(seed, "map")
    zoom = float(rng.uniform(1.0, 1.5))
    w = 360.0 / zoom
    lon0 = float(rng.uniform(-180, 180 - w))
    lat0 = float(rng.uniform(-90, 90 - w / 2))
    k = size / w
    rings = [np.ascontiguousarray(np.stack([(r[:, 0] - lon0) * k, (lat0 + w / 2 - r[:, 1]) * k * 2], 1))
             for r in _countries()]
    return Scene(rings, "nonzero", "poly", size)


# ---- triangles ------------------------------------------------------------------

def small_triangles(count):
    def make(seed, size):
        rng = _rng(seed, "tri%d" % count)
        c = rng.uniform(0, size, (count, 1, 2))
        r = rng.uniform(1, 12, (count, 1, 1)) * (size / 512.0) ** 0.5
        t = rng.uniform(0, 2 * np.pi, (count, 1, 1)) + np.array([0, 2.1, 4.2])[None, :, None] \
            + rng.uniform(-0.4, 0.4, (count, 3, 1))
        tri = c + r * np.concatenate([np.cos(t), np.sin(t)], 2)
        return Scene(list(_ccw(tri)), "nonzero", "tris", size)
    return make


def span_triangles(count=None):
    def make(seed, size):
        n = SPAN_COUNT if count is None else count
        rng = _rng(seed, "span")
        tri = rng.uniform(0.02 * size, 0.98 * size, (n, 3, 2))
        return Scene(list(_ccw(tri)), "nonzero", "tris", size)
    return make


def mesh(seed, size, n=40):
    """An n x n jittered grid, each cell two triangles, given as 2 n^2 rings
    (polygon_* in one call, non-zero: the union)."""
    rng = _rng(seed, "mesh")
    g = np.linspace(0.05 * size, 0.95 * size, n + 1)
    pts = np.stack(np.meshgrid(g, g), -1).reshape(-1, 2)
    step = g[1] - g[0]
    inner = np.ones((n + 1, n + 1), bool)
    inner[[0, -1], :] = inner[:, [0, -1]] = False
    pts[inner.ravel()] += rng.uniform(-0.3, 0.3, (int(inner.sum()), 2)) * step
    rings = []
    for r in range(n):
        for q in range(n):
            a, b, d, e = r * (n + 1) + q, r * (n + 1) + q + 1, (r + 1) * (n + 1) + q + 1, (r + 1) * (n + 1) + q
            rings.append(np.ascontiguousarray(pts[[a, b, d]]))
            rings.append(np.ascontiguousarray(pts[[a, d, e]]))
    return Scene(rings, "nonzero", "poly", size)


def loop(seed, size, count=400):
    """`count` tiny polygons (4-8 vertices, 3-12 px across) in cells of a
    grid, one per cell (so they never overlap), each drawn by its own call."""
    rng = _rng(seed, "loop")
    side = int(np.ceil(np.sqrt(count)))
    cell = size / side
    rings = []
    for k in range(count):
        cx, cy = (k % side + 0.5) * cell, (k // side + 0.5) * cell
        m = int(rng.integers(4, 9))
        # at most 0.35 cell from the cell's centre: a gap of 0.3 cell
        # (>= 1.9 px at 128 x 128) between neighbours, so no shared pixel
        rad = min(rng.uniform(1.5, 6.0), 0.25 * cell)
        t = rng.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(m) / m
        x = cx + rng.uniform(-0.1, 0.1) * cell + rad * np.cos(t)
        y = cy + rng.uniform(-0.1, 0.1) * cell + rad * np.sin(t)
        rings.append(np.ascontiguousarray(np.stack([x, y], 1)))
    return Scene(rings, "nonzero", "loop", size)


# ---- the scenes of bench_coverage.py, shifted ---------------------------------------

def _coverage_scene(name):
    def make(seed, size):
        import bench_coverage
        rings, rule, tris = bench_coverage.scenes(size)[name]
        off = _rng(seed, name).uniform(-0.5, 0.5, 2)
        return Scene([np.ascontiguousarray(np.asarray(r, np.float64) + off) for r in rings], rule, "poly", size)
    return make


FAMILIES: Dict[str, Callable[[int, int], Scene]] = {
    "text": text,
    "map": map_layer,
    "tri3k": small_triangles(3000),
    "tri10k": small_triangles(10000),
    "span": span_triangles(),
    "mesh": mesh,
    "loop": loop,
    "circle": _coverage_scene("circle (64-gon)"),
    "star": _coverage_scene("star (200 spikes)"),
    "holes": _coverage_scene("disc with 6 holes"),
    "glyphs": _coverage_scene("glyphs 'Rast'"),
}


# ---- doubling series --------------------------------------------------------------
# Each maps a step k = 0, 1, 2, ... to a scene whose one quantity is 2^k
# times step 0's: the runner fits time ~ 2^(k * exponent).

def series_edges(k, size):
    """A 64 * 2^k-gon circle: edges x2, the same pixels."""
    import bench_coverage
    c = size / 2
    return Scene([np.ascontiguousarray(bench_coverage._ngon(c + 0.31, c + 0.17, 0.4 * size, 64 << k))],
                 "nonzero", "poly", size)


def series_rings(k, size):
    """250 * 2^k small triangles as rings in one call: rings x2."""
    s = small_triangles(250 << k)(1, size)
    return Scene(s.rings, "nonzero", "poly", size)


def series_depth(k, size):
    """4 * 2^k canvas-spanning triangles: overlap depth x2."""
    return span_triangles(4 << k)(1, size)


SERIES = {"edges x2": series_edges, "rings x2": series_rings, "depth x2": series_depth}

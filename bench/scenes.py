"""Benchmark and demo scenes for rastrum.

Every scene is plain geometry: rings of (x, y) vertices in pixel units, with
x to the right and y DOWN (docs/semantics.md). Vertices are float64 and on
purpose most of them are not integers and not multiples of 1/2^S, so that the
snapping to the subpixel grid is exercised and its cost can be measured
against the exact result on the unsnapped input. (The small textbook polygon
of Figure 3-19 is the exception: its vertices are the book's integers.)

Each scene function returns ``(rings, shape)``: ``rings`` is a list of (N, 2)
float64 arrays (one array per ring) and ``shape`` is ``(H, W)`` as numpy
writes it. ``random_polygons`` returns ``(polygons, shape)`` where
``polygons`` is a list of such ring lists, each rendered to its own mask.

Orientation: with the shoelace signed area computed on (x, y) as given,
outer rings have positive area and holes negative (the "outer CCW, holes CW"
convention in the y-up mathematical frame; on a y-down screen this looks the
other way round). Only the relative orientation matters to the non-zero rule.

``SCENES`` maps a scene name to a :class:`Scene` that the benchmark and the
demo iterate.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, List, Sequence, Tuple

import numpy as np

Ring = np.ndarray                     # (N, 2) float64, (x, y)
Rings = List[Ring]
Shape = Tuple[int, int]               # (H, W)

#: Figure 3-19 of the textbook (seed 001, section 3.4): P0 .. P6.
FIG3_19_VERTICES = ((7, 8), (3, 12), (1, 7), (3, 1), (6, 5), (8, 1), (12, 9))


def signed_area(ring: Ring) -> float:
    """Shoelace area of a ring on (x, y) as given (positive = CCW, y up)."""
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _orient(ring: Ring, positive: bool) -> Ring:
    if (signed_area(ring) > 0) != positive:
        ring = ring[::-1]
    return np.ascontiguousarray(ring, dtype=np.float64)


def regular_polygon(n: int, cx: float, cy: float, r: float,
                    phase: float = 0.0) -> Ring:
    """n-gon inscribed in the circle (cx, cy, r), first vertex at `phase`."""
    t = phase + 2.0 * np.pi * np.arange(n) / n
    return np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], axis=1)


# ---------------------------------------------------------------------------
# scene functions
# ---------------------------------------------------------------------------

def fig3_19(scale: float = 1.0) -> Tuple[Rings, Shape]:
    """The polygon of Figure 3-19: P0(7,8) P1(3,12) P2(1,7) P3(3,1) P4(6,5)
    P5(8,1) P6(12,9), on a 14 x 14 grid, optionally scaled by `scale`
    (vertices and shape both; a non-integer scale gives non-integer
    vertices)."""
    ring = np.array(FIG3_19_VERTICES, dtype=np.float64) * scale
    n = int(round(14 * scale))
    return [np.ascontiguousarray(ring)], (n, n)


def ring_with_holes(size: int = 1024) -> Tuple[Rings, Shape]:
    """A disc (a 360-gon) with three holes of different shapes: a 96-gon
    circle, a rotated square and a five-pointed (simple) star. The holes run
    opposite to the disc, so even-odd and non-zero agree."""
    s = size / 1024.0
    cx, cy = 512.37 * s, 511.71 * s
    outer = _orient(regular_polygon(360, cx, cy, 470.3 * s, 0.013), True)
    holes = []
    for k, kind in enumerate(("circle", "square", "star")):
        a = np.pi / 2 + k * 2 * np.pi / 3
        hx, hy = cx + 235.2 * s * np.cos(a), cy + 235.2 * s * np.sin(a)
        if kind == "circle":
            h = regular_polygon(96, hx, hy, 120.6 * s, 0.1)
        elif kind == "square":
            h = regular_polygon(4, hx, hy, 140.4 * s, 0.3)
        else:
            t = np.pi * np.arange(10) / 5 - np.pi / 2
            rad = np.where(np.arange(10) % 2 == 0, 150.9 * s, 60.2 * s)
            h = np.stack([hx + rad * np.cos(t), hy + rad * np.sin(t)], axis=1)
        holes.append(_orient(h, False))
    return [outer] + holes, (size, size)


def star(spikes: int = 200, size: int = 2048) -> Tuple[Rings, Shape]:
    """A simple (non self-intersecting) star: `spikes` points alternating
    between radii 0.49*size and 0.34*size, 2*spikes vertices."""
    c = size / 2.0
    t = 0.0123 + np.pi * np.arange(2 * spikes) / spikes
    rad = np.where(np.arange(2 * spikes) % 2 == 0, 0.49 * size, 0.34 * size)
    ring = np.stack([c + 0.37 + rad * np.cos(t), c - 0.29 + rad * np.sin(t)],
                    axis=1)
    return [_orient(ring, True)], (size, size)


def star_polygon(n: int = 200, k: int = 67,
                 size: int = 2048) -> Tuple[Rings, Shape]:
    """The regular star polygon {n/k}: n vertices on a circle, each joined to
    the one k steps further; self-intersecting, with winding numbers 1 .. k
    from the rim to the centre, so even-odd (alternating bands) and non-zero
    (solid) differ. gcd(n, k) must be 1 for a single ring."""
    if np.gcd(n, k) != 1:
        raise ValueError("{n/k} needs gcd(n, k) == 1 for one ring")
    c = size / 2.0
    t = 0.0071 + 2.0 * np.pi * k * np.arange(n) / n
    r = 0.49 * size
    ring = np.stack([c + 0.41 + r * np.cos(t), c - 0.23 + r * np.sin(t)],
                    axis=1)
    return [np.ascontiguousarray(ring)], (size, size)


def circle(n: int = 64, size: int = 2048) -> Tuple[Rings, Shape]:
    """A regular n-gon of radius 0.49*size, centre off the pixel grid."""
    c = size / 2.0
    return ([_orient(regular_polygon(n, c + 0.31, c + 0.17, 0.49 * size,
                                     0.05), True)], (size, size))


def random_polygons(count: int = 100, shape: Shape = (480, 640),
                    min_vertices: int = 20, max_vertices: int = 60,
                    seed: int = 20240601) -> Tuple[List[Rings], Shape]:
    """`count` random polygons, each one ring of 20..60 vertices drawn
    uniformly inside the W x H image: a random vertex list, hence heavily
    self-intersecting (even-odd and non-zero differ). Seeded, reproducible."""
    rng = np.random.default_rng(seed)
    h, w = shape
    polys = []
    for _ in range(count):
        n = int(rng.integers(min_vertices, max_vertices + 1))
        pts = rng.uniform((0.0, 0.0), (float(w), float(h)), size=(n, 2))
        polys.append([np.ascontiguousarray(pts, dtype=np.float64)])
    return polys, shape


def coco_like(count: int = 100, shape: Shape = (480, 640),
              min_vertices: int = 20, max_vertices: int = 60,
              seed: int = 20240602) -> Tuple[List[Rings], Shape]:
    """`count` COCO-like instance outlines, each to its own mask: simple
    (star-shaped about a centre, so never self-intersecting) rings of
    20..60 vertices whose radius wanders smoothly around a mean radius
    drawn log-uniformly from 12 to 200 px, centred anywhere in the image
    (so some are cut by its border), as annotation polygons are.
    Seeded, reproducible."""
    rng = np.random.default_rng(seed)
    h, w = shape
    polys = []
    for _ in range(count):
        n = int(rng.integers(min_vertices, max_vertices + 1))
        r0 = float(np.exp(rng.uniform(np.log(12.0), np.log(200.0))))
        t = np.sort(rng.uniform(0.0, 2.0 * np.pi, n))
        # a smooth wobble: a few low harmonics with random phases
        k = np.arange(1, 5)
        amp = rng.uniform(0.0, 0.25, k.size) / k
        ph = rng.uniform(0.0, 2.0 * np.pi, k.size)
        rad = r0 * (1.0 + (amp[None, :] * np.sin(k[None, :] * t[:, None]
                                                  + ph[None, :])).sum(1))
        cx, cy = rng.uniform(0.0, w), rng.uniform(0.0, h)
        ring = np.stack([cx + rad * np.cos(t), cy + rad * np.sin(t)], axis=1)
        polys.append([_orient(ring, True)])
    return polys, shape


def small_polygons(count: int = 10000, size: int = 1024,
                   seed: int = 20240603) -> Tuple[List[Rings], Shape]:
    """`count` small quadrilaterals and pentagons, 10..30 px across, at
    random positions and angles in one size x size canvas (they overlap):
    the "many small shapes" case (sprites, glyph-like marks, map symbols),
    where the cost per call matters more than the cost per pixel.
    All run the same way round. Seeded, reproducible."""
    rng = np.random.default_rng(seed)
    polys = []
    for _ in range(count):
        n = int(rng.integers(4, 6))
        r = rng.uniform(5.0, 15.0)
        t = rng.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(n) / n \
            + rng.uniform(-0.3, 0.3, n)
        rad = r * rng.uniform(0.7, 1.0, n)
        cx, cy = rng.uniform(0.0, size, 2)
        ring = np.stack([cx + rad * np.cos(t), cy + rad * np.sin(t)], axis=1)
        polys.append([_orient(ring, True)])
    return polys, (size, size)


# ---------------------------------------------------------------------------
# registry
# ---------------------------------------------------------------------------

@dataclass
class Scene:
    name: str
    description: str
    make: Callable[[], tuple]
    batch: bool = False              # make() returns a list of polygons
    canvas: bool = False             # batch drawn into ONE canvas, not masks
    _cache: tuple = field(default=None, repr=False)

    def load(self) -> Tuple[List[Rings], Shape]:
        """(polygons, shape); polygons is a list of ring lists (one item for
        a single-polygon scene), each rendered to its own (H, W) mask."""
        if self._cache is None:
            geo, shape = self.make()
            self._cache = (geo if self.batch else [geo], tuple(shape))
        return self._cache

    @property
    def shape(self) -> Shape:
        return self.load()[1]

    @property
    def polygons(self) -> List[Rings]:
        return self.load()[0]

    def summary(self) -> str:
        polys, (h, w) = self.load()
        nv = sum(len(r) for p in polys for r in p)
        nr = sum(len(p) for p in polys)
        what = (f"{len(polys)} fills into 1 canvas" if self.canvas else
                f"{len(polys)} masks" if self.batch else "1 mask")
        return (f"{self.description}; {nr} ring(s), {nv} vertices; "
                f"{what} of {w}x{h}")


SCENES = {s.name: s for s in [
    Scene("fig3_19", "textbook Figure 3-19 polygon, 14x14",
          lambda: fig3_19(1.0)),
    Scene("fig3_19_1k", "Figure 3-19 scaled x1024/14 (float vertices)",
          lambda: fig3_19(1024 / 14)),
    Scene("holes", "disc with 3 holes (opposite orientation)",
          lambda: ring_with_holes(1024)),
    Scene("star200", "200-spike simple star",
          lambda: star(200, 2048)),
    Scene("star200_67", "{200/67} star polygon, self-intersecting",
          lambda: star_polygon(200, 67, 2048)),
    Scene("circle64", "64-gon circle",
          lambda: circle(64, 2048)),
    Scene("random100", "100 random self-intersecting 20-60-gons",
          lambda: random_polygons(100), batch=True),
    Scene("coco100", "100 COCO-like simple 20-60-gons, 12-200 px",
          lambda: coco_like(100), batch=True),
    Scene("small10k", "10000 quads/pentagons 10-30 px, one canvas",
          lambda: small_polygons(10000), batch=True, canvas=True),
]}

#: The scenes of the one summary table (issue 4), in its column order.
TABLE_SCENES = ("circle64", "star200", "holes", "coco100", "small10k")


def get(names: Sequence[str] = ()) -> List[Scene]:
    """Scenes by name (all of them, in order, when `names` is empty)."""
    if not names:
        return list(SCENES.values())
    unknown = [n for n in names if n not in SCENES]
    if unknown:
        raise KeyError(f"unknown scene(s) {unknown}; known: {list(SCENES)}")
    return [SCENES[n] for n in names]


if __name__ == "__main__":
    for s in get():
        print(f"{s.name:12s} {s.summary()}")

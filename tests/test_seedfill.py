"""Region (seed) fill: rast_flood_fill, rast_boundary_fill, Canvas.flood_fill
and Canvas.boundary_fill against references written here.

References, independent of the C code:
- ``ref_region``: breadth-first search over the pixels (a deque, Python
  ints), the connected component of the seed among the "inside" pixels;
- ``textbook_fill``: the recursive 4-/8-connected fill of seed 001 3.6
  as the textbook writes it (FloodFill4 / BoundaryFill4, and their 8-way
  forms), on small images, recursion limit raised;
- the 4000 x 4000 region is drawn by the test itself, so its answer is
  known without any search.
The C fill must equal them pixel for pixel, for every format, both
connectivities, every stack size (0 bytes up: the fixed-memory fallback),
inside a clip, with guard bytes around the buffer never written.
"""

from __future__ import annotations

import collections
import sys

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from rastrum import _core
from rastrum._native import ffi, lib
from strategies import examples

N4 = ((1, 0), (-1, 0), (0, 1), (0, -1))
N8 = N4 + ((1, 1), (1, -1), (-1, 1), (-1, -1))

FORMATS = {  # code, bytes per pixel
    "gray8": (lib.RAST_FORMAT_GRAY8, 1),
    "rgb888": (lib.RAST_FORMAT_RGB888, 3),
    "rgba8888": (lib.RAST_FORMAT_RGBA8888, 4),
    "count16": (lib.RAST_FORMAT_COUNT16, 2),
    "rgb565": (lib.RAST_FORMAT_RGB565, 2),
}
GUARD = 0xA5
PAD = 8


# ---- references -----------------------------------------------------------------

def ref_region(inside, seed, conn):
    """bool mask of the component of `seed` in the bool array `inside`."""
    h, w = inside.shape
    out = np.zeros((h, w), bool)
    x, y = seed
    if not inside[y, x]:
        return out
    rows = inside.tolist()
    seen = [[False] * w for _ in range(h)]
    seen[y][x] = True
    queue = collections.deque([(x, y)])
    nb = N8 if conn == 8 else N4
    while queue:
        x, y = queue.popleft()
        for dx, dy in nb:
            a, b = x + dx, y + dy
            if 0 <= a < w and 0 <= b < h and rows[b][a] and not seen[b][a]:
                seen[b][a] = True
                queue.append((a, b))
    out[:] = np.array(seen, bool)
    return out


def textbook_fill(img, x, y, new, conn, boundary=None):
    """Seed 001 3.6 as written: recursive, on a list of lists, in place.
    Flood: fill pixels of the seed's old value; boundary: pixels that are
    neither the boundary nor the new value."""
    h, w = len(img), len(img[0])
    old = img[y][x]
    nb = N8 if conn == 8 else N4

    def flood(x, y):
        if 0 <= x < w and 0 <= y < h and img[y][x] == old:
            img[y][x] = new
            for dx, dy in nb:
                flood(x + dx, y + dy)

    def bound(x, y):
        if 0 <= x < w and 0 <= y < h and img[y][x] != boundary and img[y][x] != new:
            img[y][x] = new
            for dx, dy in nb:
                bound(x + dx, y + dy)

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 4 * h * w + 100))
    try:
        if boundary is None:
            if old != new:
                flood(x, y)
        else:
            bound(x, y)
    finally:
        sys.setrecursionlimit(limit)
    return img


def expected(labels, seed, new, conn, boundary=None):
    """The labels image after the fill, by ref_region."""
    x, y = seed
    out = labels.copy()
    if boundary is None:
        if labels[y, x] != new:
            out[ref_region(labels == labels[y, x], seed, conn)] = new
    else:
        out[ref_region((labels != boundary) & (labels != new), seed, conn)] = new
    return out


# ---- scenes: label images (small ints), drawn from a numpy seed ---------------

def noise(rng, h, w, density, ncolors=2):
    """Pixels 1 with probability `density`, else 0 (or more colours)."""
    img = (rng.random((h, w)) < density).astype(np.int64)
    if ncolors > 2:
        img[img == 1] = rng.integers(1, ncolors, int(img.sum()))
    return img


def maze(rng, h, w, loops=0.0):
    """Corridors 0, walls 1: a perfect maze on odd cells by depth-first
    carving, then a fraction `loops` of the remaining inner walls knocked
    out (loops around islands, the fallback's hard case)."""
    img = np.ones((h, w), np.int64)
    cells_y, cells_x = (h - 1) // 2, (w - 1) // 2
    if cells_x < 1 or cells_y < 1:
        return img
    seen = np.zeros((cells_y, cells_x), bool)
    stack = [(0, 0)]
    seen[0, 0] = True
    img[1, 1] = 0
    while stack:
        cx, cy = stack[-1]
        options = [(cx + dx, cy + dy) for dx, dy in N4
                   if 0 <= cx + dx < cells_x and 0 <= cy + dy < cells_y and not seen[cy + dy, cx + dx]]
        if not options:
            stack.pop()
            continue
        nx, ny = options[rng.integers(len(options))]
        seen[ny, nx] = True
        img[2 * ny + 1, 2 * nx + 1] = 0
        img[cy + ny + 1, cx + nx + 1] = 0
        stack.append((nx, ny))
    if loops:
        ys, xs = np.nonzero(img[1:-1, 1:-1] == 1)
        pick = rng.random(len(ys)) < loops
        img[ys[pick] + 1, xs[pick] + 1] = 0
    return img


def spiral(h, w, gap=1):
    """A square spiral wall (1) with a corridor (0) `gap` pixels wide that
    winds from the border to the centre: one long thin region."""
    img = np.zeros((h, w), np.int64)
    x0, y0, x1, y1 = 0, 0, w - 1, h - 1
    step = gap + 1
    side = 0
    while x0 <= x1 and y0 <= y1:
        if side == 0:
            img[y0, x0:x1 + 1] = 1
            y0 += step
        elif side == 1:
            img[y0 - step:y1 + 1, x1] = 1
            x1 -= step
        elif side == 2:
            img[y1, x0:x1 + step + 1] = 1
            y1 -= step
        else:
            img[y0:y1 + step + 1, x0] = 1
            x0 += step
        side = (side + 1) % 4
    return img


def scene(kind, rng, h, w, density):
    if kind == "noise":
        return noise(rng, h, w, density)
    if kind == "noise3":
        return noise(rng, h, w, density, ncolors=3)
    if kind == "maze":
        return maze(rng, h, w)
    if kind == "braid":
        return maze(rng, h, w, loops=density / 4)
    return spiral(h, w, gap=1 + int(density * 3))


# ---- the C call on a guarded buffer, any format -------------------------------

def palette(fmt):
    """Distinct pixel byte strings for labels 0..5 (differing in one byte
    only, so that a partial compare would be caught)."""
    bpp = FORMATS[fmt][1]
    out = []
    for k in range(6):
        b = bytearray([7] * bpp)
        b[-1] = 7 + k
        if bpp == 2:  # count16: a native uint16 with a high byte too
            b = bytearray(np.array([0x1207 + 0x100 * k], np.uint16).tobytes())
        out.append(bytes(b))
    return out


class Guarded:
    """A target of `fmt` over labels (H, W), inside a buffer with PAD guard
    pixels around it and stride padding."""

    def __init__(self, labels, fmt, clip=None):
        self.fmt = fmt
        code, bpp = FORMATS[fmt]
        self.h, self.w = labels.shape
        self.bpp = bpp
        self.stride = (self.w + 2 * PAD) * bpp + 2  # padding the target must not touch
        self.stride += self.stride % 2
        self.buf = np.full(((self.h + 2 * PAD) * self.stride + 8,), GUARD, np.uint8)
        self.pal = palette(fmt)
        self.off = PAD * self.stride + PAD * bpp
        table = np.frombuffer(b"".join(self.pal), np.uint8).reshape(len(self.pal), bpp)
        for j in range(self.h):
            row = self.off + j * self.stride
            self.buf[row:row + self.w * bpp] = table[labels[j]].ravel()
        self.before = self.buf.copy()
        self.target = ffi.new("rast_target *")
        ptr = ffi.cast("unsigned char *", ffi.from_buffer(self.buf)) + self.off
        assert lib.rast_target_init(self.target, ptr, self.w, self.h, self.stride, code) == lib.RAST_OK
        if clip is not None:
            self.target.clip.x0, self.target.clip.y0, self.target.clip.x1, self.target.clip.y1 = clip

    def pixel(self, label):
        return ffi.from_buffer(self.pal[label])

    def labels(self):
        """The target read back as labels; -1 for a pixel matching none."""
        lookup = {p: k for k, p in enumerate(self.pal)}
        out = np.empty((self.h, self.w), np.int64)
        for j in range(self.h):
            row = self.off + j * self.stride
            data = self.buf[row:row + self.w * self.bpp].tobytes()
            for i in range(self.w):
                out[j, i] = lookup.get(data[i * self.bpp:(i + 1) * self.bpp], -1)
        return out

    def outside_untouched(self):
        """Every byte outside the target's pixels is as before."""
        mask = np.ones(self.buf.shape, bool)
        for j in range(self.h):
            row = self.off + j * self.stride
            mask[row:row + self.w * self.bpp] = False
        return np.array_equal(self.buf[mask], self.before[mask])

    def fill(self, seed, new, conn, boundary=None, stack_bytes=1 << 20):
        stack = np.empty(max(1, (stack_bytes + 7) // 8), np.uint64)
        mem = ffi.from_buffer(stack) if stack_bytes else ffi.NULL
        x, y = seed
        if boundary is None:
            return lib.rast_flood_fill(self.target, x, y, self.pixel(new), conn, mem, stack_bytes)
        return lib.rast_boundary_fill(self.target, x, y, self.pixel(new), self.pixel(boundary),
                                      conn, mem, stack_bytes)


def run_case(labels, fmt, seed, new, conn, boundary, stack_bytes, clip=None):
    g = Guarded(labels, fmt, clip)
    assert g.fill(seed, new, conn, boundary, stack_bytes) == lib.RAST_OK
    got = g.labels()
    if clip is None:
        want = expected(labels, seed, new, conn, boundary)
    else:
        x0, y0, x1, y1 = clip
        want = labels.copy()
        sx, sy = seed
        if x0 <= sx < x1 and y0 <= sy < y1:
            want[y0:y1, x0:x1] = expected(labels[y0:y1, x0:x1], (sx - x0, sy - y0), new, conn, boundary)
    assert g.outside_untouched(), "a byte outside the target changed"
    np.testing.assert_array_equal(got, want)


# ---- hypothesis: every scene, fill, connectivity, format, stack size ----------

KINDS = ("noise", "noise3", "maze", "braid", "spiral")
STACKS = (0, 16, 32, 64, 1 << 20)  # 0 .. 4 entries: the fixed-memory fallback; then plenty


@st.composite
def cases(draw, max_side=40):
    kind = draw(st.sampled_from(KINDS))
    h = draw(st.integers(1, max_side))
    w = draw(st.integers(1, max_side))
    density = draw(st.sampled_from((0.05, 0.3, 0.45, 0.55, 0.7, 0.95)))
    labels = scene(kind, np.random.default_rng(draw(st.integers(0, 2**32 - 1))), h, w, density)
    seed = (draw(st.integers(0, w - 1)), draw(st.integers(0, h - 1)))
    if draw(st.booleans()):  # seed on the region most of the time
        ys, xs = np.nonzero(labels == 0)
        if len(ys):
            k = draw(st.integers(0, len(ys) - 1))
            seed = (int(xs[k]), int(ys[k]))
    return labels, seed


@settings(max_examples=examples(300))
@given(cases(), st.sampled_from(tuple(FORMATS)), st.sampled_from((4, 8)), st.sampled_from(STACKS),
       st.integers(0, 4))
def test_flood_fill_equals_reference(case, fmt, conn, stack_bytes, new):
    labels, seed = case
    run_case(labels, fmt, seed, new, conn, None, stack_bytes)


@settings(max_examples=examples(300))
@given(cases(), st.sampled_from(tuple(FORMATS)), st.sampled_from((4, 8)), st.sampled_from(STACKS),
       st.integers(0, 4), st.integers(0, 3))
def test_boundary_fill_equals_reference(case, fmt, conn, stack_bytes, new, boundary):
    labels, seed = case
    run_case(labels, fmt, seed, new, conn, boundary, stack_bytes)


@settings(max_examples=examples(150))
@given(cases(), st.sampled_from(tuple(FORMATS)), st.sampled_from((4, 8)), st.sampled_from(STACKS),
       st.booleans(), st.data())
def test_fill_confined_to_clip(case, fmt, conn, stack_bytes, boundary, data):
    """The region is the component within the clip; nothing outside the
    clip is read into it or written."""
    labels, seed = case
    h, w = labels.shape
    x0 = data.draw(st.integers(-3, w))
    x1 = data.draw(st.integers(x0, w + 3))
    y0 = data.draw(st.integers(-3, h))
    y1 = data.draw(st.integers(y0, h + 3))
    cut = (max(x0, 0), max(y0, 0), min(x1, w), min(y1, h))
    if cut[0] >= cut[2] or cut[1] >= cut[3]:
        cut = (0, 0, 0, 0)
    g = Guarded(labels, fmt, (x0, y0, x1, y1))
    assert g.fill(seed, 4, conn, 1 if boundary else None, stack_bytes) == lib.RAST_OK
    want = labels.copy()
    cx0, cy0, cx1, cy1 = cut
    sx, sy = seed
    if cx0 <= sx < cx1 and cy0 <= sy < cy1:
        want[cy0:cy1, cx0:cx1] = expected(labels[cy0:cy1, cx0:cx1], (sx - cx0, sy - cy0), 4, conn,
                                          1 if boundary else None)
    assert g.outside_untouched()
    np.testing.assert_array_equal(g.labels(), want)


@settings(max_examples=examples(100))
@given(cases(max_side=22), st.sampled_from((4, 8)), st.integers(0, 3), st.booleans())
def test_textbook_recursion_agrees(case, conn, new, boundary):
    """The recursive textbook fill, the BFS reference and the C fill with a
    one-entry stack: three ways, one answer."""
    labels, seed = case
    b = (new + 1) % 4 if boundary else None
    book = np.array(textbook_fill(labels.tolist(), seed[0], seed[1], new, conn, b), np.int64)
    np.testing.assert_array_equal(book, expected(labels, seed, new, conn, b))
    run_case(labels, "gray8", seed, new, conn, b, 16)


# ---- named scenes, larger: mazes, spirals, noise at several densities ----------

@pytest.mark.parametrize("conn", (4, 8))
@pytest.mark.parametrize("stack_bytes", (0, 16, 64, None))
@pytest.mark.parametrize("kind", ("maze", "braid", "spiral", "spiral3"))
def test_mazes_and_spirals_tiny_stack(kind, stack_bytes, conn):
    rng = np.random.default_rng(7)
    if kind == "spiral":
        labels = spiral(121, 97)
    elif kind == "spiral3":
        labels = spiral(80, 120, gap=3)
    else:
        labels = maze(rng, 81, 101, loops=0.08 if kind == "braid" else 0.0)
    ys, xs = np.nonzero(labels == 0)
    seed = (int(xs[len(xs) // 2]), int(ys[len(ys) // 2]))
    if stack_bytes is None:
        stack_bytes = 1 << 20
    run_case(labels, "gray8", seed, 2, conn, None, stack_bytes)
    run_case(labels, "rgb888", seed, 2, conn, 1, stack_bytes)


@pytest.mark.parametrize("conn", (4, 8))
@pytest.mark.parametrize("density", (0.1, 0.4, 0.5, 0.6, 0.9))
def test_noise_densities(density, conn):
    rng = np.random.default_rng(int(density * 100) + conn)
    labels = noise(rng, 150, 170, density)
    for stack_bytes in (16, 1 << 20):
        for seed in ((0, 0), (85, 75), (169, 149)):
            run_case(labels, "gray8", seed, 3, conn, None, stack_bytes)
            run_case(labels, "rgba8888", seed, 3, conn, 1, stack_bytes)


@pytest.mark.parametrize("conn", (4, 8))
def test_4000_square_single_region(conn):
    """A 4000 x 4000 region whose answer the test draws itself: a
    background with walls that never close (a comb of walls from the top
    and bottom edge alternately, gaps left open) is one region; the walls
    and the isolated dots stay, everything else is filled."""
    h = w = 4000
    img = np.zeros((h, w), np.uint8)
    img[:h - 2, 3::8] = 1          # walls from the top, open at the bottom
    img[2:, 7::8] = 1              # walls from the bottom, open at the top
    img[1::4, 1::8] = 1            # isolated dots inside the corridors
    want = np.where(img == 0, 5, img).astype(np.uint8)
    c = rastrum.Canvas.wrap(img)
    c.flood_fill((0, 0), 5, connectivity=conn)
    np.testing.assert_array_equal(c.array, want)
    c.boundary_fill((0, h - 1), 9, 1, connectivity=conn)
    np.testing.assert_array_equal(c.array, np.where(want == 5, 9, want))


def test_fallback_on_large_serpentine_region():
    """The same kind of region, 300 x 300, with a one-entry stack: a long
    corridor folded on itself, filled in fixed memory."""
    h = w = 300
    img = np.zeros((h, w), np.uint8)
    img[:h - 1, 1::4] = 1
    img[1:, 3::4] = 1
    run_case(img.astype(np.int64), "gray8", (0, 0), 2, 4, None, 16)
    run_case(img.astype(np.int64), "gray8", (0, 0), 2, 8, None, 0)


# ---- outcomes of the edge cases --------------------------------------------------

def test_noop_cases_write_nothing():
    labels = maze(np.random.default_rng(3), 21, 21)
    for fmt in FORMATS:
        g = Guarded(labels, fmt)
        # flood with the region's own value
        assert g.fill((1, 1), 0, 4) == lib.RAST_OK
        # boundary fill seeded on the boundary, and on a pixel of the fill value
        assert g.fill((0, 0), 2, 4, boundary=1) == lib.RAST_OK
        assert g.fill((1, 1), 0, 4, boundary=1) == lib.RAST_OK
        assert np.array_equal(g.buf, g.before)
    # boundary == value: fills every pixel connected through non-boundary
    g = Guarded(labels, "gray8")
    assert g.fill((1, 1), 1, 4, boundary=1) == lib.RAST_OK
    np.testing.assert_array_equal(g.labels(), np.ones_like(labels))


def test_errors_write_nothing():
    labels = noise(np.random.default_rng(5), 9, 11, 0.5)
    for fmt in FORMATS:
        g = Guarded(labels, fmt)
        stack = np.empty(8, np.uint64)
        mem = ffi.from_buffer(stack)
        px = g.pixel(2)
        t = g.target
        assert lib.rast_flood_fill(t, -1, 0, px, 4, mem, 64) == lib.RAST_E_ARG
        assert lib.rast_flood_fill(t, 11, 0, px, 4, mem, 64) == lib.RAST_E_ARG
        assert lib.rast_flood_fill(t, 0, 9, px, 4, mem, 64) == lib.RAST_E_ARG
        assert lib.rast_flood_fill(t, 0, 0, px, 6, mem, 64) == lib.RAST_E_ARG
        assert lib.rast_flood_fill(t, 0, 0, px, 0, mem, 64) == lib.RAST_E_ARG
        assert lib.rast_flood_fill(t, 0, 0, ffi.NULL, 4, mem, 64) == lib.RAST_E_NULL
        assert lib.rast_flood_fill(ffi.NULL, 0, 0, px, 4, mem, 64) == lib.RAST_E_NULL
        assert lib.rast_boundary_fill(t, 0, 0, px, ffi.NULL, 4, mem, 64) == lib.RAST_E_NULL
        assert lib.rast_flood_fill(t, 0, 0, px, 4, ffi.NULL, 64) == lib.RAST_E_NULL
        odd = ffi.cast("unsigned char *", mem) + 4
        assert lib.rast_flood_fill(t, 0, 0, px, 4, odd, 32) == lib.RAST_E_ALIGN
        assert np.array_equal(g.buf, g.before)
    # a seed in the target but outside the clip: nothing, RAST_OK
    g = Guarded(labels, "gray8", clip=(3, 3, 6, 6))
    assert g.fill((0, 0), 2, 4) == lib.RAST_OK
    assert g.fill((0, 0), 2, 8, boundary=1) == lib.RAST_OK
    assert np.array_equal(g.buf, g.before)


def test_stack_size():
    need = ffi.new("size_t *")
    assert lib.rast_seed_stack_size(100, 50, need) == lib.RAST_OK
    assert need[0] == 16 * (2 * 50 * 50 + 2)
    assert lib.rast_seed_stack_size(0, 0, need) == lib.RAST_OK and need[0] == 32
    assert lib.rast_seed_stack_size(lib.RAST_MAX_DIM, lib.RAST_MAX_DIM, need) == lib.RAST_OK
    assert need[0] >= 2**60 or need[0] == ffi.cast("size_t", -1)
    assert lib.rast_seed_stack_size(-1, 5, need) == lib.RAST_E_SIZE
    assert lib.rast_seed_stack_size(5, 5, ffi.NULL) == lib.RAST_E_NULL


# ---- the Python methods -----------------------------------------------------------

@settings(max_examples=examples(60))
@given(cases(max_side=30), st.sampled_from(("gray8", "rgb888", "rgba8888")), st.sampled_from((4, 8)))
def test_canvas_methods(case, fmt, conn):
    labels, seed = case
    pal = {"gray8": [0, 200, 17], "rgb888": [(0, 0, 0), (0, 0, 1), (9, 9, 9)],
           "rgba8888": [(1, 2, 3, 4), (1, 2, 3, 5), (255, 0, 0, 255)]}[fmt]
    bpp = FORMATS[fmt][1]
    def paint(lab):
        arr = np.array([np.array(pal[k], np.uint8).reshape(bpp) for k in lab.ravel()], np.uint8)
        return arr.reshape(lab.shape) if bpp == 1 else arr.reshape(lab.shape + (bpp,))
    c = rastrum.Canvas.wrap(paint(labels))
    c.flood_fill(seed, pal[2], connectivity=conn)
    np.testing.assert_array_equal(c.array, paint(expected(labels, seed, 2, conn)))
    c = rastrum.Canvas.wrap(paint(labels))
    c.boundary_fill(seed, pal[2], pal[1], connectivity=conn)
    np.testing.assert_array_equal(c.array, paint(expected(labels, seed, 2, conn, 1)))


def test_canvas_bad_input_raises_and_writes_nothing():
    c = rastrum.Canvas((5, 6), format="rgb888", background=(1, 2, 3))
    before = c.array.copy()
    bad_calls = [
        lambda: c.flood_fill((6, 0), 1),
        lambda: c.flood_fill((0, 5), 1),
        lambda: c.flood_fill((-1, 0), 1),
        lambda: c.flood_fill((0.5, 0), 1),
        lambda: c.flood_fill((True, 0), 1),
        lambda: c.flood_fill((0,), 1),
        lambda: c.flood_fill(None, 1),
        lambda: c.flood_fill((0, 0), None),
        lambda: c.flood_fill((0, 0), 1.5),
        lambda: c.flood_fill((0, 0), (1, 2)),
        lambda: c.flood_fill((0, 0), 256),
        lambda: c.flood_fill((0, 0), 1, connectivity=6),
        lambda: c.flood_fill((0, 0), 1, connectivity="4"),
        lambda: c.flood_fill((0, 0), 1, connectivity=True),
        lambda: c.flood_fill((0, 0), 1, connectivity=None),
        lambda: c.boundary_fill((0, 0), 1, None),
        lambda: c.boundary_fill((0, 0), 1, (1, 2, 3, 4)),
        lambda: c.boundary_fill((9, 9), 1, 2),
        lambda: c.boundary_fill((0, 0), 1, 2, connectivity=3),
    ]
    for call in bad_calls:
        with pytest.raises(rastrum.InputError):
            call()
        assert np.array_equal(c.array, before)


def test_canvas_subview_and_gil():
    """A sub-view: the fill stays inside it (the canvas is the target)."""
    big = np.zeros((20, 30), np.uint8)
    view = big[5:15, 10:20]
    rastrum.Canvas.wrap(view).flood_fill((0, 0), 4, connectivity=8)
    want = np.zeros_like(big)
    want[5:15, 10:20] = 4
    np.testing.assert_array_equal(big, want)


@settings(max_examples=examples(40))
@given(cases(max_side=40), st.sampled_from((4, 8)), st.sampled_from((0, 16, None)), st.booleans())
def test_canvas_mono1(case, conn, stack_bytes, boundary):
    """Two values, eight pixels a byte: after the fill a filled pixel and
    one that was on before look the same, and the fill must still be
    exact (the fallback, with 0 or 1 stack entries, too)."""
    labels, seed = case
    bits = (labels != 0).astype(np.int64)
    h, w = bits.shape
    c = rastrum.Canvas((h, w), format="mono1")
    c.packed[...] = np.packbits(bits.astype(np.uint8), axis=1)
    if boundary:
        _core.seed_fill(c._target, seed, c._pixel(1), c._pixel(0), conn, stack_bytes)
        want = expected(bits, seed, 1, conn, 0)
    else:
        _core.seed_fill(c._target, seed, c._pixel(1), None, conn, stack_bytes)
        want = expected(bits, seed, 1, conn)
    np.testing.assert_array_equal(c.array, want)

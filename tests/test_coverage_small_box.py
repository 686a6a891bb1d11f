"""One small convex ring painted into gray8 by the solid painter's fast
kind (coverage_small.c's rast__cs_direct, formats.c's
rast__gray8_blend_rows): the ring's box of levels blended whole, every row
of it inside the clip, where each row's run went to the painter before.
Every pixel of the array must be (s*c + d*(255 - c) + 127) // 255 of its
background d, the colour s and the level c of the ring's exact coverage
(tests/oracle_coverage.py: floor(255 a + 1/2) of the exact area for
"area" and "accumulate", which are the same on a convex ring, the
samples counted for "ss2"/"ss4"), written here from the docs
(docs/coverage.md), never from the C code; pixels the ring does not reach
keep their background.  The Canvas wraps a view into a larger array (a
row every stride bytes, not its width): the bytes round the view must not
change.  Rings cross each side and corner of the canvas (the box cut to
the clip: its first row and column are not the box's) and lie inside."""

import numpy as np
import pytest

import oracle_coverage as oc
import rastrum
from test_coverage import blend, blended, levels_near_ties

SHAPE = (14, 17)      # the view's (H, W)
PAD = (3, 5, 2, 7)    # rows above, columns left, rows below, columns right in the larger array
S = 8


def _ring(cx, cy, r, n, seed):
    """A convex n-gon round (cx, cy) of radius r, its angles jittered."""
    g = np.random.default_rng(seed)
    a = np.sort(g.uniform(0, 2 * np.pi, n))
    return [(cx + r * np.cos(t), cy + r * np.sin(t)) for t in a]


def _levels(ring, method, rule):
    """The oracle's uint8 levels and, for "area"/"accumulate", the pixels
    where an exact tie (or one within the engines' 2^-58 bound) lets the
    level be one less or more (tests/test_coverage.py, check_area)."""
    if method in ("ss2", "ss4"):
        k = 2 if method == "ss2" else 4
        return oc.coverage_ss([ring], SHAPE, k, rule=rule, subpixel_bits=S, sample_offset=0.5), None
    return levels_near_ties(oc.coverage_exact([ring], SHAPE, rule=rule, subpixel_bits=S), 255, len(ring))


def _check(ring, method, color, seed, rule="nonzero"):
    h, w = SHAPE
    top, left, bottom, right = PAD
    big = np.random.default_rng(seed).integers(1, 256, (top + h + bottom, left + w + right), dtype=np.uint8)
    before = big.copy()
    view = big[top:top + h, left:left + w]
    rastrum.Canvas.wrap(view).fill_polygon(np.asarray(ring, np.float64), color, rule=rule, aa=method,
                                           subpixel_bits=S)
    want, near = _levels(ring, method, rule)
    bg = before[top:top + h, left:left + w]
    got = view.astype(np.int64)
    bad = np.argwhere(~blended(got, color, bg, want, near))
    assert not len(bad), "%s colour %d: %d pixel(s) off the blend of the exact levels, first %s: got %d want %d (bg %d); ring %r" % (
        method, color, len(bad), tuple(bad[0]), got[tuple(bad[0])], blend(color, bg, want)[tuple(bad[0])],
        bg[tuple(bad[0])], ring)
    around = before.copy()
    around[top:top + h, left:left + w] = big[top:top + h, left:left + w]
    assert np.array_equal(big, around), "%s: a byte outside the view changed" % method
    return int((want > 0).sum())


# centres: inside, past each side, past each corner (radius 4: the box cut)
PLACES = {
    "inside": (8.3, 7.1),
    "left": (0.7, 6.4),
    "right": (16.2, 7.6),
    "top": (9.1, 0.4),
    "bottom": (7.7, 13.6),
    "top left": (0.9, 1.2),
    "top right": (16.4, 0.8),
    "bottom left": (1.1, 13.3),
    "bottom right": (15.8, 13.9),
}


@pytest.mark.parametrize("place", sorted(PLACES))
@pytest.mark.parametrize("method", ["area", "accumulate", "ss4"])
def test_rings_across_the_clip(place, method):
    cx, cy = PLACES[place]
    reached = 0
    for n, r in ((3, 2.7), (5, 3.9), (8, 4.6)):
        for color in (0, 77, 255):
            ring = _ring(cx, cy, r, n, seed=n * 31 + color)
            reached += _check(ring, method, color, seed=n + color, rule="nonzero") > 0
    # the other rule, the ring turned the other way
    reached += _check(_ring(cx, cy, 4.2, 6, seed=5)[::-1], method, 200, seed=9, rule="evenodd") > 0
    assert reached >= 8, "rings that reach no pixel test nothing"


@pytest.mark.parametrize("width", [1, 2, 3, 4, 5, 7, 8, 9, 12, 15, 16])
def test_box_widths(width):
    """Rows of every width round the blend's steps of 4 and 8 pixels: a
    rectangle 0.4 px inside its box, with a slanted right side."""
    x0, y0 = 2.6, 3.3
    ring = [(x0, y0), (x0 + width - 0.2, y0 + 0.1), (x0 + width - 0.5, y0 + 4.5), (x0 + 0.1, y0 + 4.4)]
    for method in ("area", "ss2"):
        assert _check(ring, method, 190, seed=width) > 0

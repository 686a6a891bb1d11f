"""A finished row of levels handed to a painter (csrc/src/coverage/rows.c,
rast__cov_row_done): its runs of levels not 0 to the levels entry, its
stretches of 255 at least 16 long to the full entry, the 0s skipped,
which x86 builds scan 16 bytes a step (SSE2) and then byte by byte.
Rows of whole-row bars (several rings: the accumulation's rows, not the
one-small-ring path) painted on a gray8 Canvas of 17 to 70 columns:
bars and gaps of 0 to 40 pixels, stretches of 255 of 14 to 35, runs
that reach the last column, ends at every sixteenth of a pixel but the
half (so no level is a tie).  Every pixel must be
(s c + d (255 - c) + 127) // 255 of its background d, the colour s and
the level c = floor(255 a + 1/2) of the bar's exact area a, here the
length of the bar in the pixel (docs/coverage.md); pixels no bar
reaches keep their background."""
from fractions import Fraction as F

import numpy as np
import pytest

import rastrum

S = 8


def _mix(s, d, c):
    s, d, c = (np.asarray(v, np.int64) for v in (s, d, c))
    return (s * c + d * (255 - c) + 127) // 255


def _frac(g):
    return F(int(g.choice([0, 1, 3, 5, 7, 9, 11, 13, 15])), 16)


def _scene(w, h, seed):
    """Bars, each one row high, apart in each row; the levels of their
    exact areas."""
    g = np.random.default_rng(seed)
    rings, want = [], np.zeros((h, w), np.int64)
    for j in range(h):
        x = F(int(g.integers(0, 20)))
        while True:
            x0 = x + _frac(g)
            x1 = x0 + int(g.choice([0, 1, 2, 13, 14, 15, 16, 17, 18, 33, 35, 40])) + _frac(g) + F(1, 16)
            if g.random() < 0.2:
                x1 = F(w + int(g.integers(0, 3)))  # to the last column and past it
            if x1 > w + 3:
                break
            rings.append([(float(x0), j), (float(x1), j), (float(x1), j + 1), (float(x0), j + 1)][::(-1) ** j])
            for i in range(int(x0), min(w, int(np.ceil(float(x1))))):
                a = min(x1, i + 1) - max(x0, i)
                want[j, i] = int(a * 255 + F(1, 2))
            x = F(int(np.ceil(float(x1)))) + 1 + int(g.choice([0, 1, 5, 15, 16, 17, 31, 40]))
            if x >= w:
                break
    return rings, want


@pytest.mark.parametrize("w", [17, 31, 32, 33, 47, 64, 70])
@pytest.mark.parametrize("method", ["area", "accumulate"])
@pytest.mark.parametrize("color", [255, 90])
def test_row_runs(w, method, color):
    h = 24
    for seed in range(6):
        rings, want = _scene(w, h, seed * 97 + w)
        assert len(rings) >= 2 and (want == 255).any()
        bg = np.random.default_rng(seed).integers(0, 256, (h, w), dtype=np.uint8)
        img = bg.copy()
        rastrum.Canvas.wrap(img).fill_polygon([np.asarray(r, np.float64) for r in rings], color,
                                              aa=method, subpixel_bits=S)
        exp = _mix(color, bg, want)
        bad = np.argwhere(img.astype(np.int64) != exp)
        assert not len(bad), "seed %d: %d pixel(s) off, first %s: got %d want %d (level %d)" % (
            seed, len(bad), tuple(bad[0]), img[tuple(bad[0])], exp[tuple(bad[0])], want[tuple(bad[0])])

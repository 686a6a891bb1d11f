"""How often the integer DDA differs from the exact line (Bresenham).

    PYTHONPATH=python python bench/line_dda.py

Random segments, endpoints uniform in a square of the given half-width;
prints, per setting, the share of lines with at least one pixel different
and the share of pixels different.  Seeded: the figures are reproducible.
"""

import numpy as np

import rastrum


def rates(n, span, S, o, seed=1):
    rng = np.random.default_rng(seed)
    lines = pixels = total = 0
    for _ in range(n):
        if S == 0:
            p = rng.integers(-span, span + 1, 4).astype(float)
        else:
            p = rng.uniform(-span, span, 4)
        a, b = tuple(p[:2]), tuple(p[2:])
        d = rastrum.line_pixels(a, b, algorithm="dda", subpixel_bits=S, sample_offset=o)
        e = rastrum.line_pixels(a, b, subpixel_bits=S, sample_offset=o)
        assert d.shape == e.shape
        k = int(np.any(d != e, axis=1).sum())
        lines += k > 0
        pixels += k
        total += len(e)
    return lines / n, pixels / max(total, 1)


def main():
    print("setting                                   lines differ  pixels differ")
    for S, o, what in [(0, 0, "integer endpoints, samples at integers"),
                       (8, 0.5, "S=8 endpoints, pixel centres")]:
        for span in (20, 200, 2000):
            lr, pr = rates(2000 if span < 2000 else 500, span, S, o)
            print("%-40s %5d px  %6.2f%%      %7.4f%%" % (what, span, 100 * lr, 100 * pr))


if __name__ == "__main__":
    main()

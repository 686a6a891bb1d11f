""""area" on swept rows of 16 to 23 vertex events: from 20 events (before,
24) they are listed by start and by end (coverage_area.c,
rast__cov_ev_lists), each list sorted by rast__cov_ev_sort (a counting
pass over 16 bins of the ordinates' top bits, then an insertion sort),
fewer are scanned at each event.  A
closed walk inside one pixel row (every edge starts and ends inside it,
so that the row's events are its edges), crossing itself, on grids of q
px (vertices on one ordinate, in one bin and across bins), at several
subpixel_bits (the bins' shift: S - 4, or none for S <= 4), against the
exact oracle of tests/oracle_coverage.py within the bound of rastrum.h."""

import numpy as np
import pytest

import rastrum
from test_coverage import M_OF, _n_m, check_area, exact_area


def _walk(rnd, w, n, q):
    """n vertices of a closed walk strictly inside row 0 of a canvas w px
    wide, steps of up to 1.5 px, on the grid of q px."""
    pts = []
    x = rnd.uniform(0, w)
    for _ in range(n):
        x = min(max(x + rnd.uniform(-1.5, 1.5), 0.0), float(w))
        y = rnd.uniform(q, 1 - q)
        pts.append((float(np.round(x / q) * q), float(np.round(y / q) * q)))
    return pts


@pytest.mark.parametrize("S", [2, 4, 8, 12])
@pytest.mark.parametrize("rule", ["evenodd", "nonzero"])
def test_16_to_23_events_a_row_equal_oracle(S, rule):
    q = max(2.0 ** -S, 1 / 64)
    for seed in range(12):
        rnd = np.random.default_rng(1000 * S + seed)
        n = 16 + seed % 8
        rl = [_walk(rnd, 3, n, q)]
        for dtype in (np.uint8, np.uint16):
            out = rastrum.polygon_coverage(rl, (1, 3), rule=rule, dtype=dtype, subpixel_bits=S)
            n_, m = _n_m(rl, S)
            check_area(out, exact_area(rl, (1, 3), rule, S), M_OF[dtype], n_, m,
                       repr((S, seed, rule, dtype)))


def test_events_on_few_ordinates_equal_oracle():
    """Many events on a few ordinates (q = 1/4 px: three inside the row), so
    that each list has runs of equal keys in one bin, in rows of 16 to 23
    events; and on a fine grid (q = 1/256), keys spread over every bin."""
    for q in (0.25, 1 / 256):
        for seed in range(16):
            rnd = np.random.default_rng(seed)
            rl = [_walk(rnd, 3, 16 + seed % 8, q)]
            for rule in ("evenodd", "nonzero"):
                out = rastrum.polygon_coverage(rl, (1, 3), rule=rule, dtype=np.uint8)
                n, m = _n_m(rl, 8)
                check_area(out, exact_area(rl, (1, 3), rule, 8), 255, n, m, repr((q, seed, rule)))

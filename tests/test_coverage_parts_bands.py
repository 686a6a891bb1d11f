""""area" of a polygon tested part by part (csrc/src/coverage/coverage_plain.c,
rast__cov_parts_test) in lines: the rings' pixel boxes are put in bands of
rows (between two bands no box reaches both rows) and paired within a band
only, by column.  Two rings whose boxes share only one pixel row, the last
of one and the first of the other, are one part; so are a ring and a flat
one inside its last row.  The scenes: a line of glyph-like rings, an empty
row, then such a pair (in the second band, so that the key's band matters)
wound the opposite ways, or the same way one inside the other (winding 0,
1 and 2 in one pixel: not plain together, plain each alone), and lines
apart (plain).  Each is held to the exact oracle (tests/oracle_coverage.py)
under both rules, in uint8 and uint16; where the accumulation alone is
wrong, the scene says so (else it would test nothing)."""
import numpy as np
import pytest

import rastrum
from test_coverage_fast import _check
from test_coverage_plain_parts import _ring

SHAPE = (16, 14)


# the first line: rows 0 to 2, then row 3 empty
LINE = [_ring(2, 1.6, 1.1, 1.2, 12, 0.2, False), _ring(5.5, 1.6, 1.1, 1.2, 12, 0.4, False),
        _ring(9, 1.6, 1.1, 1.2, 12, 0.1, True)]

SCENES = {
    # rows 4 to 9 and 9 to 13 (y 4.8-9.2, 9.4-13.8): row 9 shared, wound opposite ways in it
    "two lines sharing a row, opposite ways": LINE + [_ring(4, 7, 1.3, 2.2, 14, 0.3, False),
                                                      _ring(4.4, 11.6, 1.3, 2.2, 14, 0.3, True),
                                                      _ring(10, 7, 1.0, 2.2, 14, 0.3, False)],
    # rows 4 to 9 (y 4.4-9.6) and a flat ring inside its last row (y 9.1-9.3), the same way: 0, 1, 2
    "a flat ring in another's last row": LINE + [_ring(5, 7, 1.3, 2.6, 14, 0.3, False),
                                                 [(4.75, 9.125), (5.25, 9.125), (5.25, 9.3125), (4.75, 9.3125)],
                                                 _ring(10, 7, 1.0, 2.2, 14, 0.3, True)],
    # lines a row apart, each ring plain, either way
    "lines apart": LINE + [_ring(4, 7, 1.3, 2.2, 14, 0.3, False), _ring(10, 7, 1.0, 2.2, 14, 0.3, True),
                           _ring(4.4, 12.8, 1.3, 1.8, 14, 0.3, True)],
}
NOT_PLAIN = {"two lines sharing a row, opposite ways", "a flat ring in another's last row"}


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_bands(name, rule):
    rings = SCENES[name]
    exact = _check(rings, rule, shape=SHAPE)
    if name in NOT_PLAIN:
        acc = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.float64)
        assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@pytest.mark.parametrize("shift", range(8))
def test_bands_moved(shift):
    """The pair sharing a row moved by eighths of a pixel down and right
    (a row shared or not, and where in it)."""
    d = shift / 8
    rings = LINE + [(np.array(r) + d).tolist() for r in SCENES["two lines sharing a row, opposite ways"][3:]]
    _check(rings, ("nonzero", "evenodd")[shift % 2], shape=SHAPE)

""""area" of a polygon some of whose parts are not plain, by the parts'
boxes (csrc/src/entry/coverage.c, rast__cov_by_boxes; the boxes from
rast__cov_parts_boxes, csrc/src/coverage/coverage_plain.c): the rings
outside every box by their accumulation, then each box's pixels again by
the exact area of its rings alone.  A box must hold every ring that
reaches it (a plain ring in the corner of an L-shaped part that is not
plain, whose own pixel box meets neither ring of the L), two boxes that
meet must be one (two parts that are not plain, one inside the other's
box), and a box is cut to the canvas where it reaches past an edge.  The
scenes are lines of glyph-like rings (short edges: the test part by part
runs, docs/coverage.md), each held to the exact oracle
(tests/oracle_coverage.py) under both rules, in uint8 and uint16; where
the accumulation alone is wrong the scene says so (else it would test
nothing)."""
import numpy as np
import pytest

import rastrum
from test_coverage_fast import _check
from test_coverage_plain_parts import _ring

SHAPE = (18, 20)

# an L that is not plain: two rings the same way round overlapping at its
# corner (winding 2 there); its box is columns 0-9, rows 1-15
L = [_ring(5, 2.5, 4.2, 1.2, 24, 0.2, False), _ring(2, 8, 1.2, 6.5, 24, 0.3, False)]
# plain glyphs on the right, so that most edges are plain
RIGHT = [_ring(14, 3, 1.2, 2.2, 16, 0.1, False), _ring(14, 3, 0.6, 1.4, 12, 0.4, True),
         _ring(17.5, 3, 1.1, 2.2, 16, 0.3, True), _ring(14, 10, 1.2, 2.2, 16, 0.2, True),
         _ring(17.5, 10, 1.1, 2.2, 16, 0.5, False), _ring(17.5, 10, 0.5, 1.3, 12, 0.1, True),
         _ring(15.5, 15.5, 2.5, 1.3, 20, 0.3, False)]

SCENES = {
    # a plain ring in the L's corner (columns 5-8, rows 7-12): in the L's
    # box, its own box meeting neither ring's
    "a ring in the corner of an L": L + [_ring(7, 9.5, 1.3, 2.0, 16, 0.4, False)] + RIGHT,
    # and wound the other way, with a hole
    "an o in the corner of an L": L + [_ring(7, 9.5, 1.3, 2.0, 16, 0.4, True),
                                       _ring(7, 9.5, 0.6, 1.2, 12, 0.2, False)] + RIGHT,
    # a second part that is not plain in the L's corner: two overlapping
    # rings wound opposite ways (winding 1, 0, -1)
    "a part not plain in the corner of an L": L + [_ring(6.5, 9.5, 1.0, 2.0, 16, 0.4, False),
                                                   _ring(7.8, 9.5, 1.0, 2.0, 16, 0.1, True)] + RIGHT,
}


def _moved(rings, dx, dy):
    return [(np.array(r) + (dx, dy)).tolist() for r in rings]


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_boxes(name, rule):
    rings = SCENES[name]
    exact = _check(rings, rule, shape=SHAPE)
    acc = rastrum.polygon_coverage(rings, SHAPE, rule=rule, method="accumulate", dtype=np.float64)
    assert np.abs(acc - np.array(exact, dtype=np.float64)).max() > 0.01, "the scene tests nothing"


@pytest.mark.parametrize("name", sorted(SCENES))
@pytest.mark.parametrize("dx, dy", [(-3.375, -2.5), (-1.125, -4.0), (11.0, 3.25), (10.625, 5.875),
                                    (0.5, 0.125), (-0.25, 2.0)])
def test_boxes_past_the_edges(name, dx, dy):
    """The scenes moved: the boxes past the canvas's left and top edges,
    or its right and bottom (the plain glyphs then wholly off it), by
    whole, half and eighth pixels (a ring's box ending on a pixel's edge
    or inside it)."""
    rule = ("nonzero", "evenodd")[int(dx * 8 + dy * 8) % 2]
    _check(_moved(SCENES[name], dx, dy), rule, shape=SHAPE)

"""Canvas.fill_polygon(aa=...)'s glue (python/glue/coverage.c) calls the
core's anti-aliased fill without the core's second round of checks
(rast__fill_polygon_aa_snapped, painters/paint.h: the glue has checked the
options, sizes and scratch, and its snap every point's range): the
supersampling methods' own narrower range (a vertex times 2^k must fit)
is still checked there.  Each call -- an (N, 2) array, the same call
again (then in C, python/ext/seq.c), a list of pairs, two rings -- with
every method, near that range's edge and inside the canvas, fails where
the core's checked entry (rast_fill_polygon_aa, every check of its own,
of the vertices snapped here exactly) gives an error status, with
polygon_coverage's InputError where that one refuses them too, except
that "area" draws vertices past the 32-bit range by the 64-bit path as
polygon_coverage does; and else paints 255 on 0 as the levels
polygon_coverage gives (uint8; held to the exact oracle by the coverage
tests)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from fractions import Fraction
from rastrum._native import ffi, lib

SHAPE = (10, 12)
METHODS = ("area", "accumulate", "ss2", "ss4", "ss8", "ss16")


def _outcome(f):
    try:
        return f(), None
    except rastrum.InputError as e:
        return None, str(e)


def _checked_status(rings, method, rule, s):
    """rast_fill_polygon_aa's status (every check of the core's) for the
    rings snapped exactly (floor(v 2^s + 1/2)); None where the snap
    itself refuses a vertex (past +-RAST_COORD_MAX)."""
    pts = []
    for ring in rings:
        for x, y in ring:
            for v in (x, y):
                q = Fraction(v) * (1 << s) + Fraction(1, 2)
                pts.append(q.numerator // q.denominator)
    if max(abs(v) for v in pts) > S_.COORD_MAX:
        return None
    opts = ffi.new("rast_coverage_opts *", {"method": getattr(lib, "RAST_AA_" + method.upper()),
                                            "rule": getattr(lib, "RAST_RULE_" + rule.upper()),
                                            "subpixel_bits": s, "sample": lib.RAST_SAMPLE_CENTER})
    out = np.zeros(SHAPE, np.uint8)
    t = ffi.new("rast_target *")
    assert lib.rast_target_init(t, ffi.from_buffer(out), SHAPE[1], SHAPE[0], SHAPE[1], lib.RAST_FORMAT_GRAY8) == 0
    need = ffi.new("size_t *")
    st = lib.rast_coverage_scratch_size(opts, len(pts) // 2, SHAPE[1], SHAPE[0], need)
    if st != 0:
        return st
    poly = ffi.new("rast_polygon *")
    p = ffi.new("int32_t[]", pts)
    sizes = ffi.new("uint32_t[]", [len(r) for r in rings])
    poly.points, poly.ring_sizes, poly.nrings = ffi.cast("rast_point *", p), sizes, len(rings)
    scratch = ffi.new("uint64_t[]", need[0] // 8 + 1)
    return lib.rast_fill_polygon_aa(t, poly, opts, ffi.new("uint8_t *", 255), scratch, need[0])


def _same(rings, method, rule, s):
    want, err = _outcome(lambda: rastrum.polygon_coverage(rings, SHAPE, rule=rule, method=method,
                                                          subpixel_bits=s, dtype=np.uint8))
    st = _checked_status(rings, method, rule, s)
    one = len(rings) == 1
    calls = [np.array(rings[0], np.float64), np.array(rings[0], np.float64), list(rings[0])] if one else [rings]
    c = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
    for src in calls:
        c.array[...] = 0
        got, e = _outcome(lambda: c.fill_polygon(src, 255, rule=rule, aa=method, subpixel_bits=s))
        # drawn where the core's checked entry draws, and also, for "area",
        # where a vertex is past the 32-bit snap (st None) and
        # polygon_coverage draws it by its 64-bit path: the opaque fill
        # takes that path too (docs/coverage.md)
        wide = method == "area" and st is None and err is None
        assert (e is None) == (st == 0 or wide), (S_.lit(rings), method, s, e, st)
        if err is not None:
            assert e == err, (S_.lit(rings), method, s, e, err)
        if e is None:
            assert np.array_equal(c.array, want), (S_.lit(rings), method, s)
    return e


def _edge(method, s):
    """The largest |v| in pixels a vertex of `method` may have at s."""
    k = {"ss2": 1, "ss4": 2, "ss8": 3, "ss16": 4}.get(method, 0)
    return (S_.COORD_MAX >> max(k - s, 0)) / (1 << s)


@settings(max_examples=S_.examples(40), deadline=None)
@given(st.sampled_from(METHODS), st.sampled_from([0, 1, 2, 3, 8, 16]), st.sampled_from(S_.RULES),
       st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=3, max_size=6),
       st.sampled_from([(1, 1), (-1, 1), (1, -1), (0, 0)]), st.booleans())
def test_range_edge_as_polygon_coverage(method, s, rule, offs, side, two):
    """Vertices within a few grid steps of the method's range edge (in and
    out of it, off the canvas), and a ring inside the canvas."""
    e, q = _edge(method, s), 1.0 / (1 << s)
    ring = [(side[0] * e + dx * q if side[0] else 3 + dx, side[1] * e + dy * q if side[1] else 3 + dy)
            for dx, dy in offs]
    rings = [ring, [(1.5, 1.5), (8.25, 2.0), (5.0, 7.5)]] if two else [ring]
    _same(rings, method, rule, s)


@pytest.mark.parametrize("method", METHODS)
def test_one_step_past_the_edge(method):
    """One vertex one grid step past the edge: refused (the snap's range for
    "accumulate", the fine grid's for ss), drawn by "area" (its 64-bit
    path, as polygon_coverage); on the edge: drawn."""
    drawn = method == "area"
    for s in (0, 2, 8):
        e, q = _edge(method, s), 1.0 / (1 << s)
        assert _same([[(e, 1.0), (e - 1, 1.0), (e - 1, 4.0)]], method, "nonzero", s) is None
        assert (_same([[(e + q, 1.0), (e - 1, 1.0), (e - 1, 4.0)]], method, "nonzero", s) is None) == drawn
        assert (_same([[(2.0, 1.0), (-e - q, 1.0), (5.0, 8.0)]], method, "evenodd", s) is None) == drawn

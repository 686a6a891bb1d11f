"""The 64-bit "area" coverage's output by runs (csrc/src/coverage/coverage64.c,
rast__w64_emit: only the cells an edge touched are computed, the cells between
them written as runs) and its sparse form for coverage_fractions
(python/glue/wide.c, rastpy_coverage64_cells).

* rows wider than a word of dirty bits (63..200 columns, clips cut left and
  right of the polygon): every cell against the exact rational oracle
  (tests/oracle_coverage.py), FIX62 and the levels, with guard bytes after
  every row (stride wider than the row) and after the output untouched;
* the sparse cells in bands of 1, 2, 3 ... rows: exactly the nonzero cells of
  the dense polygon_coverage64 (itself checked against the oracle here and in
  test_coverage64.py), in row-major order, numbered cell0 + row * row_step +
  column, nothing written past the count."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import oracle_coverage as oc
import rastrum
import strategies as S_
from rastrum._native import ffi, lib
from test_coverage import _n_m
from test_coverage64 import c_poly64, check_fix62, check_levels, local_rings

GUARD = 0xA5


def c_rows(ints, shape, x0, rule, s, fmt, pad):
    """rast_polygon_coverage64 into rows of w cells followed by `pad` guard
    cells each (stride (w + pad) cells), clip columns x0 .. x0 + w, plus a
    guard row after the last."""
    h, w = shape
    poly, opts, scratch, need, dt, _keep = c_poly64(ints, shape, rule, s, fmt)
    clip = ffi.new("rast_rect *", {"x0": x0, "y0": 0, "x1": x0 + w, "y1": h})
    buf = np.zeros((h + 1, w + pad), dtype=dt)
    buf.view(np.uint8)[...] = GUARD
    r = lib.rast_polygon_coverage64(poly, opts, clip, fmt, ffi.from_buffer(buf), (w + pad) * buf.itemsize,
                                    ffi.from_buffer(scratch), need[0])
    assert r == lib.RAST_OK, r
    raw = buf.view(np.uint8).reshape(h + 1, -1)
    assert (raw[:h, w * buf.itemsize:] == GUARD).all(), "a guard byte after a row was written"
    assert (raw[h] == GUARD).all(), "the guard row after the output was written"
    return buf[:h, :w]


@st.composite
def steep_rings(draw, s, w, h, max_rings=3):
    """1..max_rings quadrilaterals whose sides are near vertical (or
    vertical), spanning rows: long runs of whole cells between two dirty
    ones, which may fall anywhere among the words of dirty bits (columns
    62..66, 126..130 included)."""
    def x():
        c = draw(st.one_of(st.integers(-2, w + 2), st.sampled_from([62, 63, 64, 65, 66, 126, 127, 128, 129])))
        return c + draw(st.integers(0, (1 << s) - 1)) / float(1 << s) * draw(st.sampled_from([0, 1]))
    def y():
        return draw(st.integers(-1, h + 1)) + draw(st.integers(0, 3)) / 4.0
    rings = []
    for _ in range(draw(st.integers(1, max_rings))):
        xl, xr, yt, yb = x(), x(), y(), y()
        j = [draw(st.integers(-3, 3)) / float(1 << s) for _ in range(2)]
        rings.append([(xl, yt), (xr, yt), (xr + j[0], yb), (xl + j[1], yb)])
    return rings


@settings(max_examples=S_.examples(15), deadline=None)
@given(st.data(), st.integers(17, 32), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from([63, 64, 65, 127, 128, 129]), st.integers(1, 2))
def test_runs_in_wide_rows_match_exact_area(data, s, rule, w, h):
    """Vertices across the whole row (and past it), the clip cut anywhere in
    the polygon's columns: every cell the exact area, formats FIX62, U8 and
    U16, guard bytes untouched."""
    local = data.draw(st.one_of(local_rings(s, w, h), steep_rings(s, w, h)))
    x0 = data.draw(st.sampled_from([0, 0, 1, w // 3, -5]))
    cw = data.draw(st.integers(1, w + 2))
    rl = oc.oracle.snapped_rings(local, s)
    ints = [[(int(x * (1 << s)), int(y * (1 << s))) for x, y in r] for r in rl]
    # the window x0 .. x0 + cw of the exact coverage (the rings moved by -x0)
    moved = [[(float(x) - x0, float(y)) for x, y in r] for r in rl]
    exact = oc.coverage_exact(moved, (h, cw), rule=rule, subpixel_bits=s)
    n, m = _n_m(moved, s)
    pad = data.draw(st.integers(1, 9))
    what = "S=%d w=%d x0=%d cw=%d %s" % (s, w, x0, cw, rule)
    check_fix62(c_rows(ints, (h, cw), x0, rule, s, lib.RAST_COVERAGE_FIX62, pad), exact, n, m, what)
    check_levels(c_rows(ints, (h, cw), x0, rule, s, lib.RAST_COVERAGE_U8, pad), exact, 255, n, m, what)
    check_levels(c_rows(ints, (h, cw), x0, rule, s, lib.RAST_COVERAGE_U16, pad), exact, 65535, n, m, what)


def box_fix62(x0, y0, x1, y1, shape):
    """The exact coverage of the box [x0, x1] x [y0, y1] (corners on the
    quarter pixel) in 2^-62 units: per cell, its overlap in x times its
    overlap in y, in quarters (16ths of a cell: 2^58 units each)."""
    h, w = shape
    def overlap(a, b, n):
        c = np.arange(n) * 4
        return np.clip(np.minimum(int(b * 4), c + 4) - np.maximum(int(a * 4), c), 0, None).astype(np.uint64)
    assert all(v * 4 == int(v * 4) for v in (x0, y0, x1, y1))
    return (overlap(y0, y1, h)[:, None] * overlap(x0, x1, w)[None, :]) << np.uint64(58)


@pytest.mark.parametrize("left", [v + f for v in (61, 62, 63, 64, 65, 125, 126, 127, 128) for f in (0, 0.5)])
def test_runs_across_dirty_words(left):
    """Boxes whose sides fall in every column around the first two word
    boundaries of the dirty bits (63/64, 127/128), on a pixel boundary or
    not: the interior runs 1, the outside 0, the boundary cells exact."""
    s = 32
    shape = (4, 200)
    for right in (left + 1.25, left + 6, left + 64.75):
        box = (left, 0.25, right, 2.5)
        ring = [(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])]
        ints = [[(int(x * (1 << s)), int(y * (1 << s))) for x, y in ring]]
        out = c_rows(ints, shape, 0, "evenodd", s, lib.RAST_COVERAGE_FIX62, 3)
        assert np.array_equal(out, box_fix62(*box, shape)), box


def sparse_cells(rings, shape, rule, s, cell0, row_step, band):
    h, w = shape
    pts = np.ascontiguousarray(np.concatenate([np.asarray(r, np.float64) for r in rings]))
    sizes = ffi.new("uint32_t[]", [len(r) for r in rings])
    opts = ffi.new("rast_coverage_opts *")
    opts.method, opts.subpixel_bits = lib.RAST_AA_AREA, s
    opts.rule = lib.RAST_RULE_EVENODD if rule == "evenodd" else lib.RAST_RULE_NONZERO
    cells = np.full(h * w + 3, -7, np.int64)
    cov = np.full(h * w + 3, -7.0)
    count = ffi.new("size_t *")
    r = lib.rastpy_coverage64_cells(ffi.from_buffer("double[]", pts), len(pts), sizes, len(rings), opts, h, w,
                                    cell0, row_step, band, ffi.from_buffer("int64_t[]", cells),
                                    ffi.from_buffer("double[]", cov), count)
    assert r == 0, r
    n = count[0]
    assert (cells[n:] == -7).all() and (cov[n:] == -7.0).all(), "written past the count"
    return cells[:n], cov[:n]


@settings(max_examples=S_.examples(30), deadline=None)
@given(st.data(), st.integers(17, 32), st.sampled_from(["evenodd", "nonzero"]), st.integers(1, 70),
       st.integers(1, 7), st.integers(0, 9))
def test_sparse_cells_are_the_dense_nonzeros(data, s, rule, w, h, band):
    """rastpy_coverage64_cells in bands of `band` rows (0: its own choice)
    gives the nonzero cells of polygon_coverage64, in order, numbered
    cell0 + row * row_step + column, fractions bit for bit."""
    rings = data.draw(st.one_of(local_rings(s, w, h), steep_rings(s, w, h)))
    cell0 = data.draw(st.integers(0, 10 ** 9))
    row_step = w + data.draw(st.integers(0, 1000))
    cells, cov = sparse_cells(rings, (h, w), rule, s, cell0, row_step, band)
    dense = rastrum._coverage.polygon_coverage64(rings, (h, w), rule=rule, subpixel_bits=s)
    rr, cc = np.nonzero(dense)
    assert np.array_equal(cells, cell0 + rr * row_step + cc)
    assert np.array_equal(cov.view(np.uint64), dense[rr, cc].view(np.uint64))

"""rastrum.stroke's one pass (python/glue/stroke.c, rast__path_stroke_into
in csrc/src/path/stroke.c): the C stroker writes its outline into room the
caller guessed.  Checked against the public two-pass rast_path_stroke
(count, then store): with room below the count it returns RAST_E_SCRATCH
and writes nothing past the room; with enough (exact or more) it returns
the same points and ring sizes, bit for bit; and rastrum.stroke, whose
guess is short for curves and dashes and then counts first, returns that
same outline either way.  Cheap: small paths, examples as the hypothesis
profile says (tests/conftest.py).
"""

import numpy as np
from hypothesis import given, strategies as st

import rastrum
from rastrum._native import ffi, lib

SENTINEL = -123456789


@st.composite
def strokes(draw):
    n = draw(st.integers(1, 12))
    pts = draw(st.lists(st.tuples(st.integers(0, 4000), st.integers(0, 4000)), min_size=n, max_size=n))
    verbs = [lib.RAST_PATH_MOVE]
    for _ in pts[1:]:
        verbs.append(draw(st.sampled_from([lib.RAST_PATH_LINE] * 6 + [lib.RAST_PATH_MOVE, lib.RAST_PATH_CLOSE])))
    npts = []
    vs = []
    for v, p in zip(verbs, pts):  # a CLOSE takes no point: close, then draw a line to p
        if v == lib.RAST_PATH_CLOSE:
            vs += [lib.RAST_PATH_CLOSE, lib.RAST_PATH_LINE]
        else:
            vs.append(v)
        npts.append(p)
    style = ffi.new("rast_stroke_style *")
    style.width = draw(st.integers(1, 600))
    style.join = draw(st.sampled_from([lib.RAST_JOIN_MITER, lib.RAST_JOIN_ROUND, lib.RAST_JOIN_BEVEL]))
    style.cap = draw(st.sampled_from([lib.RAST_CAP_BUTT, lib.RAST_CAP_ROUND, lib.RAST_CAP_SQUARE]))
    style.miter_limit = draw(st.integers(65536, 6 * 65536))
    style.tolerance = draw(st.integers(1, 40))
    dash = None
    if draw(st.booleans()):
        dash = np.array(draw(st.lists(st.integers(0, 900), min_size=1, max_size=3)), dtype=np.int32)
        dash[0] += 1
        style.dash = ffi.cast("int32_t *", ffi.from_buffer(dash))
        style.ndash = len(dash)
        style.dash_offset = draw(st.integers(-500, 500))
    return np.array(vs, dtype=np.uint8), np.array(npts, dtype=np.int32).reshape(-1, 2), style, dash


def _cpath(verbs, pts):
    path = ffi.new("rast_path *")
    path.verbs = ffi.from_buffer("uint8_t[]", verbs)
    path.nverbs = len(verbs)
    path.points = ffi.cast("rast_point *", ffi.from_buffer(pts))
    path.npoints = len(pts)
    return path


def _public_stroke(path, style):
    """The outline by the public two-pass rast_path_stroke: (points, rings,
    the points, the ring sizes)."""
    np_, nr = ffi.new("uint32_t *"), ffi.new("uint32_t *")
    assert lib.rast_path_stroke_size(path, style, np_, nr) == lib.RAST_OK
    n, r = np_[0], nr[0]
    want = np.zeros((max(n, 1), 2), dtype=np.int32)
    wsizes = np.zeros(max(r, 1), dtype=np.uint32)
    poly = ffi.new("rast_polygon *")
    assert lib.rast_path_stroke(path, style, ffi.cast("rast_point *", ffi.from_buffer(want)), n,
                                ffi.from_buffer("uint32_t[]", wsizes), r, poly) == lib.RAST_OK
    return n, r, want, wsizes


@given(strokes(), st.integers(0, 3), st.integers(0, 40))
def test_one_pass_into_any_room(case, extra_rings, extra):
    verbs, pts, style, dash = case
    path = _cpath(verbs, pts)
    n, r, want, wsizes = _public_stroke(path, style)
    for room, rooms in ((n + extra, r + extra_rings), (n, r), (max(n - 1 - extra, 0), r),
                        (n, max(r - 1 - extra_rings, 0))):
        got = np.full((room + 8, 2), SENTINEL, dtype=np.int32)
        sizes = np.full(rooms + 4, 0xFFFFFFFF, dtype=np.uint32)
        gn, gr = ffi.new("uint32_t *"), ffi.new("uint32_t *")
        st_ = lib.rastpy_path_stroke(path, style, ffi.cast("rast_point *", ffi.from_buffer(got)), room,
                                     ffi.from_buffer("uint32_t[]", sizes), rooms, gn, gr)
        assert (got[room:] == SENTINEL).all() and (sizes[rooms:] == 0xFFFFFFFF).all()  # nothing past the room
        if room >= n and rooms >= r:
            assert st_ == lib.RAST_OK and (gn[0], gr[0]) == (n, r)
            assert np.array_equal(got[:n], want[:n]) and np.array_equal(sizes[:r], wsizes[:r])
        else:
            assert st_ == lib.RAST_E_SCRATCH


@given(strokes())
def test_stroke_same_outline_guessed_or_counted(case):
    """rastrum.stroke (a guess, then a count if short) against the public
    rast_path_stroke, on the same grid (pixels = units here: bits 0 by a
    path far from the origin is not needed; compare through the Path)."""
    verbs, pts, style, dash = case
    path = _cpath(verbs, pts)
    n, r, want, wsizes = _public_stroke(path, style)
    # the same stroke through rastrum.stroke: points at 1/2**16 px (the grid
    # stroke() picks for this extent), width and tolerance in pixels
    one = float(1 << 16)
    p = rastrum.Path()
    k = 0
    for v in verbs:
        if v == lib.RAST_PATH_MOVE:
            p.move_to(pts[k][0] / one, pts[k][1] / one)
            k += 1
        elif v == lib.RAST_PATH_LINE:
            p.line_to(pts[k][0] / one, pts[k][1] / one)
            k += 1
        else:
            p.close()
    join = {lib.RAST_JOIN_MITER: "miter", lib.RAST_JOIN_ROUND: "round", lib.RAST_JOIN_BEVEL: "bevel"}[style.join]
    cap = {lib.RAST_CAP_BUTT: "butt", lib.RAST_CAP_ROUND: "round", lib.RAST_CAP_SQUARE: "square"}[style.cap]
    kw = {}
    if dash is not None:
        kw = dict(dash=[d / one for d in dash], dash_offset=style.dash_offset / one)
    out = rastrum.stroke(p, style.width / one, join=join, cap=cap, miter_limit=style.miter_limit / 65536.0,
                         tolerance=(style.tolerance + 0.5) / one, **kw)
    v, q = out._as_arrays()
    keep = v != lib.RAST_PATH_CLOSE
    assert np.array_equal(q * one, want[:n].astype(np.float64)[: len(q)]) and len(q) == n
    sizes = wsizes[:r]
    assert int((v == lib.RAST_PATH_MOVE).sum()) == int((sizes > 0).sum()) and keep.sum() == n

"""Issue 33, many small calls: Canvas.fill_polygon's keyword calls done in
C (rastrum._seq.fill with rule= and aa=), and anti-aliased fills into a
target cut to the shape's box (python/glue/coverage.c, rastpy_cov_cut).

Each quick path is held to the general path (the same call through input
only the general path takes: a non-contiguous view), and anti-aliased
fills to the documented blend of polygon_coverage's levels over the whole
canvas, (s*c + d*(255 - c) + 127) // 255, pixels with c = 0 untouched
(docs/opacity.md): a pixel outside the cut box with coverage would show
there.  Bad input gives the general path's InputError, the target
untouched."""

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

import rastrum
from rastrum import _core, _coverage
from rastrum._core import InputError
from rastrum._native import ffi, lib
from strategies import examples

METHODS = sorted(rastrum.AA_METHODS["Canvas.fill_polygon"])
_FORMATS = {"gray8": 200, "rgb888": 77, "rgb565": 140, "rgba8888": 17, "mono1": 1}
_EMPTY = np.zeros((3, 2))  # a degenerate ring: no pixel, but the call is remembered


def _general(a):
    """The same points as a non-contiguous view: the general path."""
    b = np.empty((len(a), 4))
    b[:, ::2] = a
    return b[:, ::2]


def _rings():
    c = st.floats(-20, 60, allow_nan=False)  # on a 40 x 44 canvas: some off it
    return st.lists(st.tuples(c, c), min_size=3, max_size=10)


def _canvas(fmt, back=False):
    if fmt.startswith("label"):
        return rastrum.Canvas.wrap(np.zeros((40, 44), np.int32), format="label")
    if fmt == "gray8" and back:
        return rastrum.Canvas.wrap((np.arange(40 * 44).reshape(40, 44) * 7 % 256).astype(np.uint8))
    return rastrum.Canvas((40, 44), format=fmt, background=0)


class _COnly:
    """Within: the full method raises, so that only the C call can draw."""

    def __enter__(self):
        import rastrum._canvas as m

        def boom(*a, **k):
            raise AssertionError("the C call declined")
        self.m, self.saved = m, m._fill_polygon
        m._fill_polygon = boom

    def __exit__(self, *exc):
        self.m._fill_polygon = self.saved


# a pentagram: its centre has winding 2, so evenodd and nonzero differ there
_STAR = [(float(20 + 18 * np.cos(a)), float(20 + 18 * np.sin(a))) for a in np.pi / 2 + 4 * np.pi / 5 * np.arange(5)]


def _blend(back, c, s):
    c = c.astype(np.int64)
    return np.where(c > 0, (s * c + back.astype(np.int64) * (255 - c) + 127) // 255, back).astype(back.dtype)


@settings(max_examples=examples(40), deadline=None)
@given(_rings(), st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([None] + METHODS),
       st.sampled_from(list(_FORMATS)), st.booleans(), st.sampled_from([("rule", "aa"), ("rule",), ("aa",)]))
@example(_STAR, "nonzero", None, "gray8", False, ("rule",))
@example(_STAR, "nonzero", "area", "rgb888", True, ("rule", "aa"))
@example(_STAR, "evenodd", "ss4", "gray8", False, ("rule", "aa"))
@example(_STAR, "nonzero", "area", "gray8", True, ("rule", "aa"))
def test_keyword_c_call_as_the_general_path(pts, rule, aa, fmt, tuples, given_kw):
    color = _FORMATS[fmt]
    kw = {k: {"rule": rule, "aa": aa}[k] for k in given_kw}
    a = np.array(pts, np.float64)
    src = [tuple(p) for p in pts] if tuples else a
    general, quick = _canvas(fmt, back=True), _canvas(fmt, back=True)
    back = general.array.copy()
    general.fill_polygon(_general(a), color, **kw)
    quick.fill_polygon(_EMPTY, color, **kw)  # remembered
    assert quick._fpq[0] is quick._target and quick._fpq[1] is color
    with _COnly():
        quick.fill_polygon(src, color, **kw)
    assert np.array_equal(quick.array, general.array)
    if fmt == "gray8" and kw.get("aa"):  # the documented blend of the whole canvas's levels
        cov = rastrum.polygon_coverage(a, (40, 44), method=kw["aa"], rule=kw.get("rule", "evenodd"))
        assert np.array_equal(quick.array, _blend(back, cov, color))


def _fresh(s):
    """A str of the same value as s that is another object (not interned)."""
    t = "".join([s[:1], s[1:]])
    assert t == s and t is not s
    return t


@settings(max_examples=examples(20), deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["evenodd", "nonzero"]), st.sampled_from([None] + METHODS),
                          st.booleans()), min_size=2, max_size=8))
@example([("nonzero", "area", False), ("nonzero", "area", True), ("evenodd", "area", False),
          ("evenodd", None, True), ("nonzero", "ss4", False), ("nonzero", "ss4", False)])
def test_keyword_c_call_options_follow_each_call(calls):
    """_seq.fill remembers the last rule= and aa= objects it looked up
    (python/ext/seq.c, seq_table_opts): calls that alternate them, as the
    same objects or as other str objects of the same value, each draw with
    their own options, as the general path draws the same sequence."""
    general, quick = _canvas("gray8", back=True), _canvas("gray8", back=True)
    quick.fill_polygon(_EMPTY, 200, rule="nonzero", aa="area")  # remembered
    for k, (rule, aa, fresh) in enumerate(calls):
        a = np.array(_STAR, np.float64) + (k % 3, k % 2)
        if fresh:
            rule, aa = _fresh(rule), aa and _fresh(aa)
        general.fill_polygon(_general(a), 200, rule=rule, aa=aa)
        with _COnly():
            quick.fill_polygon(a, 200, rule=rule, aa=aa)
        assert np.array_equal(quick.array, general.array)


@pytest.mark.parametrize("kw", [
    dict(aa="area", subpixel_bits=8), dict(aa="area", opacity=None), dict(rule=np.str_("nonzero")),
    dict(aa=np.str_("area")), dict(aa="ss4", sample_offset=0.5), dict(rule="nonzero", algorithm="aet"),
    dict(aa="accumulate", gamma=None),
])
def test_keyword_c_call_declines_other_keywords(kw):
    """Keywords other than rule= and aa= (even at their defaults), and names
    that are not exact str, go to the full method: the same pixels."""
    import rastrum._canvas as m
    a = np.array([(0.5, 0.25), (30.0, 3.0), (25.5, 31.0), (2.0, 20.0)])
    want = _canvas("gray8")
    want.fill_polygon(_general(a), 200, **kw)
    got = _canvas("gray8")
    got.fill_polygon(_EMPTY, 200, **kw)
    entered = []
    saved = m._fill_polygon
    m._fill_polygon = lambda *x, **k: entered.append(1) or saved(*x, **k)
    try:
        got.fill_polygon(a, 200, **kw)
    finally:
        m._fill_polygon = saved
    assert entered and np.array_equal(got.array, want.array)


@pytest.mark.parametrize("aa", ["area", "ss4", "accumulate"])
def test_keyword_c_call_leaves_errors_to_the_general_path(aa):
    tri = np.array([[1.0, 1.0], [9.0, 2.0], [4.0, 6.0]])
    for bad in (np.nan, np.inf, 1e9):
        a = tri.copy()
        a[2, 1] = bad
        msgs = []
        for src in (a, [tuple(p) for p in a.tolist()]):
            fresh, primed = (rastrum.Canvas.wrap(np.full((10, 10), 9, np.uint8)) for _ in range(2))
            primed.fill_polygon(_EMPTY, 255, rule="nonzero", aa=aa)
            for c in (fresh, primed):
                with pytest.raises(InputError) as e:
                    c.fill_polygon(src, 255, rule="nonzero", aa=aa)
                msgs.append(str(e.value))
                assert (c.array == 9).all()
        assert len(set(msgs)) == 1
    for kw, word in ((dict(aa="ss3"), "aa="), (dict(aa="area", rule="winding"), "rule")):
        c = rastrum.Canvas.wrap(np.full((10, 10), 9, np.uint8))
        c.fill_polygon(_EMPTY, 255, aa=aa)
        with pytest.raises(InputError, match=word):
            c.fill_polygon(tri, 255, **kw)
        assert (c.array == 9).all()
    arr = np.zeros((8, 8), np.uint8)
    ro = rastrum.Canvas.wrap(arr)
    ro.fill_polygon(_EMPTY, 255, aa=aa)
    arr.flags.writeable = False
    with pytest.raises(InputError, match="read-only"):
        ro.fill_polygon(tri, 255, aa=aa)
    label = _canvas("label")  # remembered by a binary call: aa= still refused, as ever
    label.fill_polygon(_EMPTY, 3, rule="nonzero")
    with pytest.raises(InputError, match="label"):
        label.fill_polygon(tri, 3, rule="nonzero", aa=aa)
    assert not label.array.any()


# ---- the cut: an anti-aliased fill into a target with a clip of its own
# paints what the full fill paints inside that clip, nothing outside.

@settings(max_examples=examples(30), deadline=None)
@given(_rings(), st.sampled_from(METHODS), st.tuples(st.integers(-5, 50), st.integers(-5, 50),
                                                     st.integers(0, 50), st.integers(0, 50)),
       st.booleans())
def test_cut_to_the_box_inside_a_target_clip(pts, method, xywh, triangles):
    box = (xywh[0], xywh[1], xywh[0] + xywh[2], xywh[1] + xywh[3])
    a = np.array(pts, np.float64)
    if triangles:
        a = np.ascontiguousarray(a[: len(a) // 3 * 3])
    opts = _coverage._opts(method, "nonzero", 8, 0.5, "test")
    pixel = ffi.new("uint8_t[1]", [200])
    full = np.full((40, 44), 9, np.uint8)
    clipped = full.copy()
    for arr, clip in ((full, None), (clipped, box)):
        t = _core.make_target(arr, lib.RAST_FORMAT_GRAY8)
        if clip is not None:
            t.clip.x0, t.clip.y0, t.clip.x1, t.clip.y1 = clip
        xy = ffi.from_buffer("double[]", a)
        if triangles:
            st_ = lib.rastpy_fill_triangles_aa(t, xy, len(a) // 3, opts, pixel, ffi.NULL)
        else:
            st_ = lib.rastpy_fill_polygon_aa(t, xy, len(a), ffi.NULL, 1, opts, pixel, ffi.NULL)
        assert st_ == 0
    x0, y0, x1, y1 = max(box[0], 0), max(box[1], 0), min(box[2], 44), min(box[3], 40)
    inside = np.zeros((40, 44), bool)
    if x1 > x0 and y1 > y0:
        inside[y0:y1, x0:x1] = True
    assert np.array_equal(clipped[inside], full[inside])
    assert (clipped[~inside] == 9).all()
    if triangles:
        cov = rastrum.triangles_coverage(a.reshape(-1, 3, 2), (40, 44), method=method)
    else:
        cov = rastrum.polygon_coverage(a, (40, 44), method=method, rule="nonzero")
    assert np.array_equal(full, _blend(np.full((40, 44), 9, np.uint8), cov, 200))


@pytest.mark.parametrize("bad_point", [False, True])
@pytest.mark.parametrize("clip", [None, (2, 3, 30, 20), (0, 0, 2**30 + 5, 10), (10, 10, 5, 30), (-7, 0, 40, 2**30)])
@pytest.mark.parametrize("change", [None, ("method", 99), ("rule", 7), ("subpixel_bits", 40), ("subpixel_bits", -1),
                                    ("sample", 3), "null"])
def test_fill_polygon_aa_status_order(change, clip, bad_point):
    """rastpy_fill_polygon_aa (python/glue/coverage.c) answers the status
    rast_coverage_scratch_size gives for the options, the target's whole
    clip and the count before any point's (k + 1 for bad point k), whether
    it checks them before the snap or after it (rastpy_cov_late); with
    good options and a good clip, the point's; nothing written but for 0."""
    opts = _coverage._opts("area", "nonzero", 8, 0.5, "test")
    if change == "null":
        opts = ffi.NULL
    elif change is not None:
        opts = ffi.new("rast_coverage_opts *", {f: getattr(opts, f) for f in ("method", "rule", "subpixel_bits",
                                                                          "sample")})
        setattr(opts, *change)
    a = np.array([[1.0, 1.0], [19.0, 2.5], [6.0, 17.0], [2.0, 9.0]])
    if bad_point:
        a[2, 0] = np.nan
    arr = np.full((30, 40), 9, np.uint8)
    t = _core.make_target(arr, lib.RAST_FORMAT_GRAY8)
    if clip is not None:
        t.clip.x0, t.clip.y0, t.clip.x1, t.clip.y1 = clip
    need = ffi.new("size_t *")
    want = lib.rast_coverage_scratch_size(opts, len(a), t.clip.x1 - t.clip.x0, t.clip.y1 - t.clip.y0, need)
    if want == 0 and bad_point:
        want = 3
    got = lib.rastpy_fill_polygon_aa(t, ffi.from_buffer("double[]", a), len(a), ffi.NULL, 1, opts,
                                     ffi.new("uint8_t[1]", [200]), ffi.NULL)
    assert got == want
    assert want == 0 or (arr == 9).all()

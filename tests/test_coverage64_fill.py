"""An opaque ``Canvas.fill_polygon(aa="area")`` takes the vertices the
translucent fills and polygon_coverage take (the 64-bit path past the
32-bit range, docs/coverage.md): the levels polygon_coverage gives,
painted as the anti-aliased fill paints them (an exact-rational mix per
channel, mono1 thresholded; python/glue/wide.c rastpy_fill_polygon_aa64)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import strategies as S_
from test_opacity import mix

FORMATS = {"gray8": 1, "rgb888": 3, "rgb565": 3, "rgba8888": 4, "mono1": 1}
VALUE = {"gray8": 200, "rgb888": (200, 100, 50), "rgb565": (200, 100, 48), "rgba8888": (200, 100, 50, 60),
         "mono1": 1}


def painted(kind, before, cov, value):
    """The anti-aliased fill's rule (docs/coverage.md): each channel (each
    byte on rgba8888, each 5/6/5 field on rgb565) mixed at level c, mono1
    the value where c >= 128, c = 0 untouched."""
    out = before.copy()
    for y, x in zip(*np.nonzero(cov)):
        c = int(cov[y, x])
        if kind == "mono1":
            out[y, x] = value if c >= 128 else out[y, x]
        elif kind == "gray8":
            out[y, x] = mix(value, int(before[y, x]), c)
        elif kind == "rgb565":
            d = int(before[y, x])
            d = (d >> 11, (d >> 5) & 63, d & 31)
            s = (value[0] >> 3, value[1] >> 2, value[2] >> 3)
            r, g, b = (mix(s[k], d[k], c) for k in range(3))
            out[y, x] = (r << 11) | (g << 5) | b
        else:
            out[y, x] = [mix(value[k], int(before[y, x, k]), c) for k in range(FORMATS[kind])]
    return out


far = st.sampled_from([2.0 ** 20, 2.0 ** 23 + 0.3, 2.0 ** 27 - 1, 3e6, 1e8])


@settings(max_examples=S_.examples(40), deadline=None)
@given(kind=st.sampled_from(list(FORMATS)), d=far, sx=st.sampled_from([-1, 1]), sy=st.sampled_from([-1, 1]),
       near=st.lists(st.tuples(st.floats(-2, 14, allow_nan=False), st.floats(-2, 10, allow_nan=False)),
                     min_size=2, max_size=5),
       rule=st.sampled_from(["evenodd", "nonzero"]), seed=st.integers(0, 99))
def test_opaque_area_fill_takes_far_vertices(kind, d, sx, sy, near, rule, seed):
    """What polygon_coverage and the translucent fills accept (a vertex
    past 2**19 pixels at S = 8), the opaque aa="area" fill accepts: the
    levels polygon_coverage gives, painted by the fill's rule."""
    ring = near + [(sx * d, 4.5), (5.0, sy * d)]
    shape = (8, 12)
    c = rastrum.Canvas(shape, format=kind)
    rng = np.random.default_rng(seed)
    if kind == "mono1":
        c.array[...] = rng.integers(0, 2, shape)
    elif kind == "rgb565":
        c.array[...] = rng.integers(0, 65536, shape, dtype=np.uint16)
    else:
        c.array[...] = rng.integers(0, 256, c.array.shape, dtype=np.uint8)
    before = c.array.copy()
    cov = rastrum.polygon_coverage(ring, shape, rule=rule)
    c.fill_polygon(np.array(ring), VALUE[kind], rule=rule, aa="area")
    np.testing.assert_array_equal(c.array, painted(kind, before, cov, VALUE[kind]))
    c.array[...] = before  # the list of pairs and the int colour: the other entries of the same call
    if kind in ("gray8", "mono1"):
        c.fill_polygon([tuple(p) for p in ring], VALUE[kind], rule=rule, aa="area")
        np.testing.assert_array_equal(c.array, painted(kind, before, cov, VALUE[kind]))


def test_opaque_area_fill_is_polygon_coverage_composited():
    ring = [(-3e6, 1.3), (11.5, 0.2), (9.7, 7.9), (-1.0, 2e7)]
    a, b = (rastrum.Canvas((8, 12), format="rgb888", background=(9, 80, 200)) for _ in range(2))
    a.fill_polygon(ring, (250, 10, 60), aa="area")
    b.composite(rastrum.polygon_coverage(ring, (8, 12)), (250, 10, 60))
    np.testing.assert_array_equal(a.array, b.array)
    assert (a.array != (9, 80, 200)).any()


def test_opaque_area_fill_far_errors():
    """Past the 64-bit range (2**28 pixels), or ss4 past the 32-bit one: an
    InputError naming the point, nothing written."""
    c = rastrum.Canvas((4, 4), format="gray8", background=3)
    for ring, aa in (([(0, 0), (3e8, 0), (0, 3)], "area"), ([(0, 0), (3e6, 0), (0, 3)], "ss4"),
                     ([(0, 0), (3e6, 0), (0, 3)], "accumulate")):
        with pytest.raises(rastrum.InputError, match="point 1"):
            c.fill_polygon(ring, 9, aa=aa)
        assert (c.array == 3).all()

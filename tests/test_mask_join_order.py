"""polygon_mask's quick paths equal the exact oracle (docs/semantics.md),
bit for bit:

- rows on which many edges start at once, in no order across the row or
  nearly in order, row after row: the AET sorts a row's new edges by
  insertion within a budget and heapsorts past it (csrc/src/base/aet.h,
  rast__aet_join);
- a list of one ring ([ring]), which polygon_mask hands to C as the ring
  itself, as float64, int32 and an unaligned float64 view (which must
  take the general path: the glue reads aligned doubles).
"""

import numpy as np
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import examples, rings

SHAPE = (40, 40)


@st.composite
def rows_of_teeth(draw):
    """Triangles hanging from a few rows, 9-11 from each (so that more
    than 16 edges start on the row), each row's triangles in a random
    order or left to right; 2-11 such rows, so that rows sorted by
    insertion and rows past its budget follow each other."""
    H, W = SHAPE
    nrows = draw(st.integers(2, 11))
    tops = draw(st.lists(st.integers(0, 4 * (H - 2)), min_size=nrows, max_size=nrows))
    out = []
    for top in tops:
        y = top / 4 + draw(st.sampled_from([0.0, 0.25, 0.5, 0.625]))  # on and off the sample row
        m = draw(st.integers(9, 11))
        xs = draw(st.lists(st.integers(-8, 4 * W + 8), min_size=m, max_size=m))
        tri = []
        for x in xs:
            x = x / 4
            w = draw(st.integers(1, 16)) / 4
            h = draw(st.integers(1, 16)) / 4
            tip = draw(st.sampled_from(["up", "down"]))
            if tip == "up":  # the apex on the row: two edges start there
                tri.append([(x, y), (x + w, y + h), (x - w, y + h)])
            else:  # the base on the row: two edges start there too
                tri.append([(x - w, y), (x + w, y), (x, y + h)])
        order = draw(st.sampled_from(["shuffled", "sorted", "reversed"]))
        if order == "shuffled":
            tri = draw(st.permutations(tri))
        elif order == "sorted":
            tri.sort(key=lambda t: t[0][0])
        else:
            tri.sort(key=lambda t: -t[0][0])
        out.extend(tri)
    return out


@settings(max_examples=examples(20))
@given(rows_of_teeth(), st.sampled_from(["evenodd", "nonzero"]))
def test_rows_of_many_new_edges(tri, rule):
    got = rastrum.polygon_mask(tri, SHAPE, rule=rule, algorithm="aet")
    exp = oracle_mask(tri, SHAPE, rule=rule)
    assert np.array_equal(got, exp), (
        "%d pixels off the oracle, rule=%s, rings=%r" % (int((got != exp).sum()), rule, tri))


def _unaligned(a):
    """A C-contiguous float64 copy of `a` at an odd address."""
    buf = np.zeros(a.size * 8 + 1, np.uint8)
    v = np.frombuffer(buf.data, np.float64, count=a.size, offset=1).reshape(a.shape)
    v[...] = a  # frombuffer of a writable buffer is writable
    assert not v.flags.aligned and v.flags.c_contiguous
    return v


@settings(max_examples=examples(30))
@given(rings(8, 0.5, (20, 24)), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from(["f64", "i32", "unaligned"]))
def test_list_of_one_ring(ring, rule, form):
    r = np.array(ring, np.float64)
    if form == "i32":
        r = np.round(r).clip(-1000, 1000)  # exact as int32 and as float64
        arg = r.astype(np.int32)
    elif form == "unaligned":
        arg = _unaligned(r)
    else:
        arg = r.copy()
    exp = oracle_mask([r], (20, 24), rule=rule)
    got = rastrum.polygon_mask([arg], (20, 24), rule=rule)
    assert got.dtype == np.bool_ and got.shape == (20, 24)
    assert np.array_equal(got, exp), "%s ring %r, rule %s" % (form, r.tolist(), rule)
    # the list's one ring as the ring itself: the same pixels
    assert np.array_equal(rastrum.polygon_mask(arg, (20, 24), rule=rule), got)

"""Issue 33: Canvas.fill_polygon is a method descriptor made in C
(rastrum._seq.fill_method, python/ext/seq.c): the common call -- rings and
an int colour by position, no keyword but rule= and aa= -- goes from the
interpreter to C with no Python frame; every other call goes to the full
method (_canvas._fill_polygon, looked up at the call) with the same
arguments.

Held here: the C call draws the exact mask (tests/oracle.py) and what the
full method draws; it does not enter the full method; every other form of
the call (keywords, a class call, a subclass, a bound method kept) reaches
the full method with exactly the arguments given, or draws the same
pixels; a canvas given another array (Canvas._set) forgets its remembered
call; the bound method reads as the full method's signature and
docstring."""

import inspect

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
import rastrum._canvas as m
from oracle import oracle_mask
from strategies import examples

_EMPTY = np.zeros((3, 2))  # a degenerate ring: nothing drawn, the call remembered


class _Full:
    """Within: the full method records its arguments (and draws, unless
    `draw` is False)."""

    def __init__(self, draw=True):
        self.calls, self.draw = [], draw

    def __enter__(self):
        saved = self.saved = m._fill_polygon

        def full(*a, **k):
            self.calls.append((a, k))
            return saved(*a, **k) if self.draw else None
        m._fill_polygon = full
        return self

    def __exit__(self, *exc):
        m._fill_polygon = self.saved


def _general(a):
    """The same points as a non-contiguous view: only the full method takes it."""
    b = np.empty((len(a), 4))
    b[:, ::2] = a
    return b[:, ::2]


def _ring():
    c = st.floats(-4, 28, allow_nan=False)  # on a 20 x 24 canvas: some off it
    return st.lists(st.tuples(c, c), min_size=3, max_size=8)


@settings(max_examples=examples(30), deadline=None)
@given(_ring(), st.sampled_from(["evenodd", "nonzero"]), st.booleans())
def test_c_call_draws_the_exact_mask_without_the_full_method(pts, rule, tuples):
    a = np.array(pts, np.float64)
    c = rastrum.Canvas.wrap(np.zeros((20, 24), np.uint8))
    c.fill_polygon(_EMPTY, 7, rule=rule)  # remembered by the full method
    with _Full() as full:
        c.fill_polygon([tuple(p) for p in pts] if tuples else a, 7, rule=rule)
    assert full.calls == []
    want = oracle_mask([a], (20, 24), rule=rule)
    assert np.array_equal(c.array, np.where(want, 7, 0).astype(np.uint8))


@pytest.mark.parametrize("aa", sorted(rastrum.AA_METHODS["Canvas.fill_polygon"]))
def test_c_call_aa_as_the_full_method(aa):
    a = np.array([(1.25, 2.5), (17.5, 0.75), (21.0, 15.25), (6.5, 18.0)])
    want = rastrum.Canvas.wrap(np.full((20, 24), 30, np.uint8))
    want.fill_polygon(_general(a), 200, rule="nonzero", aa=aa)
    got = rastrum.Canvas.wrap(np.full((20, 24), 30, np.uint8))
    got.fill_polygon(_EMPTY, 200, rule="nonzero", aa=aa)
    with _Full() as full:
        got.fill_polygon(a, 200, rule="nonzero", aa=aa)
    assert full.calls == [] and np.array_equal(got.array, want.array)


@pytest.mark.parametrize("args, kw", [
    ((), {}),                                     # no rings: the full method's TypeError
    ((_EMPTY,), {}),                              # no colour: its InputError
    ((), {"rings": _EMPTY, "color": 5}),          # rings and colour by keyword
    ((_EMPTY, 5, "nonzero"), {}),                 # rule by position: its TypeError
    ((_EMPTY, 5), {"rule": "nonzero", "opacity": 0.5}),
    ((_EMPTY, 5), {"rul": "nonzero"}),
    ((_EMPTY, (5, 6, 7)), {"aa": "area"}),        # a colour not an int
])
def test_other_calls_reach_the_full_method_with_their_arguments(args, kw):
    c = rastrum.Canvas((20, 24), format="rgb888")
    with _Full(draw=False) as full:
        c.fill_polygon(*args, **kw)
    assert len(full.calls) == 1
    (a, k), = full.calls
    assert a[0] is c and len(a) == len(args) + 1 and all(x is y for x, y in zip(a[1:], args))
    assert k == kw and all(k[n] is kw[n] for n in kw)


def test_class_call_subclass_and_kept_bound_method_draw_alike():
    a = np.array([(2.5, 3.0), (19.0, 4.5), (11.0, 17.5)])
    want = rastrum.Canvas.wrap(np.zeros((20, 24), np.uint8))
    want.fill_polygon(a, 9, aa="ss4")

    class Sub(rastrum.Canvas):
        pass
    for how in ("class", "sub", "bound"):
        c = (Sub if how == "sub" else rastrum.Canvas).wrap(np.zeros((20, 24), np.uint8))
        if how == "class":
            rastrum.Canvas.fill_polygon(c, a, 9, aa="ss4")
        else:
            f = c.fill_polygon
            f(_EMPTY, 9, aa="ss4")
            with _Full() as full:
                f(a, 9, aa="ss4")
            assert full.calls == []
        assert np.array_equal(c.array, want.array), how
    with pytest.raises(TypeError):
        rastrum.Canvas.fill_polygon(object(), a, 9)


def test_another_array_forgets_the_remembered_call():
    first, second = np.zeros((20, 24), np.uint8), np.zeros((20, 24), np.uint8)
    c = rastrum.Canvas.wrap(first)
    c.fill_polygon(_EMPTY, 9, aa="area")
    assert c._fpq[0] is c._target
    c._set(second, "gray8", 24)
    assert c._fpq[0] is None
    c.fill_polygon(np.array([(2.0, 2.0), (12.0, 2.5), (6.0, 11.0)]), 9, aa="area")
    assert not first.any() and second.any()


def test_bound_method_reads_as_the_full_method():
    c = rastrum.Canvas.wrap(np.zeros((4, 4), np.uint8))
    full = inspect.signature(m._fill_polygon)
    got = inspect.signature(c.fill_polygon)
    want = [(p.name, p.kind, p.default) for p in list(full.parameters.values())[1:]]
    assert [(p.name, p.kind, p.default) for p in got.parameters.values()] == want
    assert c.fill_polygon.__doc__ == inspect.getdoc(m._fill_polygon)
    assert rastrum.Canvas.fill_polygon.__qualname__ == "Canvas.fill_polygon"

"""rastrum.polygon_mask equals the exact oracle bit for bit (docs/semantics.md)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import (COORD_MAX, RULES, as_input_form, examples,
                        input_forms, limit_px, scenes)

ALGOS = rastrum.ALGORITHMS["polygon_mask"]
CASES = [(alg, rule) for alg, rules in ALGOS.items() for rule in rules]
UNSUPPORTED = [(alg, rule) for alg, rules in ALGOS.items()
               for rule in RULES if rule not in rules]
OFFSETS = [0.5, 0.0]


def describe(rings, shape, **kw):
    """A reproducer as Python literals."""
    rl = rings if isinstance(rings, list) else [rings]
    lits = [np.asarray(r, dtype=np.float64).tolist() for r in rl]
    args = ", ".join(f"{k}={v!r}" for k, v in kw.items())
    return f"rastrum.polygon_mask({lits!r}, {tuple(shape)!r}, {args})"


def mismatch(got, exp, rings, shape, **kw):
    """None if ``got`` is the oracle's ``exp``, else a description."""
    if not isinstance(got, np.ndarray):
        return f"returned {type(got)!r}: {describe(rings, shape, **kw)}"
    if got.dtype != np.bool_ or got.shape != tuple(shape):
        return (f"returned dtype {got.dtype} shape {got.shape}: "
                f"{describe(rings, shape, **kw)}")
    if np.array_equal(got, exp):
        return None
    diff = np.argwhere(got != exp)
    return (f"{len(diff)} pixel(s) differ from the oracle, first (row, col): "
            f"{diff[:10].tolist()}; rastrum has {bool(got[tuple(diff[0])])} "
            f"at the first\nreproducer: {describe(rings, shape, **kw)}")


def check_equal(rings, shape, *, algorithms=None, rule="evenodd", **kw):
    """Every algorithm in ``algorithms`` (default: all supporting ``rule``)
    equals the oracle; all failures are reported together."""
    if "algorithm" in kw:
        algorithms = kw.pop("algorithm")
    if algorithms is None:
        algorithms = [a for a, rules in ALGOS.items() if rule in rules]
    elif isinstance(algorithms, str):
        algorithms = [algorithms]
    exp = oracle_mask(rings, shape, rule=rule, **kw)
    errors = []
    for alg in algorithms:
        got = rastrum.polygon_mask(rings, shape, rule=rule, algorithm=alg,
                                   **kw)
        err = mismatch(got, exp, rings, shape, rule=rule, algorithm=alg, **kw)
        if err:
            errors.append(err)
    if errors:
        raise AssertionError("\n".join(errors))


def test_algorithms_registry():
    assert "aet" in ALGOS
    for alg, rules in ALGOS.items():
        assert isinstance(rules, tuple) and rules
        assert set(rules) <= set(RULES), (alg, rules)


# Each example is checked against every algorithm that lists the rule: the
# scene and the oracle are computed once, so new algorithms cost little time.
@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("S", range(9))
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(100))
@given(data=st.data())
def test_matches_oracle(rule, S, o, data):
    rl, shape = data.draw(scenes(S, o), label="scene")
    form = data.draw(input_forms, label="form")
    check_equal(as_input_form(rl, form), shape, rule=rule, subpixel_bits=S,
                sample_offset=o)


@pytest.mark.parametrize("S", range(9, 17))
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(25))
@given(data=st.data())
def test_matches_oracle_fine_subpixel(rule, S, data):
    o = data.draw(st.sampled_from(OFFSETS), label="o")
    rl, shape = data.draw(scenes(S, o), label="scene")
    check_equal(rl, shape, rule=rule, subpixel_bits=S, sample_offset=o)


# The textbook rounding (a crossing counts for column i iff X < i + o + 1/2)
# is a second rule every algorithm must keep exactly, as the oracle has it.
@pytest.mark.parametrize("o", OFFSETS)
@pytest.mark.parametrize("S", [0, 1, 4, 8, 16])
@pytest.mark.parametrize("rule", RULES)
@settings(max_examples=examples(40))
@given(data=st.data())
def test_matches_oracle_textbook_rounding(rule, S, o, data):
    rl, shape = data.draw(scenes(S, o), label="scene")
    check_equal(rl, shape, rule=rule, subpixel_bits=S, sample_offset=o,
                rounding="textbook")


@pytest.mark.parametrize("alg,rule", CASES)
def test_figure_3_19_textbook_rounding(alg, rule):
    """The book's own polygon at integer samples, rounded as the book does."""
    fig = [(7, 8), (3, 12), (1, 7), (3, 1), (6, 5), (8, 1), (12, 9)]
    for rounding in ("exact", "textbook"):
        check_equal(fig, (14, 14), rule=rule, algorithm=alg, subpixel_bits=0,
                    sample_offset=0.0, rounding=rounding)


def test_listed_rules_are_the_registry_and_others_are_refused():
    """ALGORITHMS lists exactly the rules the C registry reports for each
    algorithm, and a rule an algorithm does not list raises ValueError
    (never a silent fallback)."""
    from rastrum._native import ffi, lib

    bits = {"evenodd": lib.RAST_RULE_EVENODD, "nonzero": lib.RAST_RULE_NONZERO}
    name = ffi.new("char **")
    mask = ffi.new("uint32_t *")
    registry = {}
    for code in range(lib.RAST_ALGO_COUNT_):
        assert lib.rast_algorithm_info(code, name, mask) == lib.RAST_OK
        registry[ffi.string(name[0]).decode()] = {r for r, b in bits.items() if mask[0] >> b & 1}
    assert {a: set(r) for a, r in ALGOS.items()} == registry
    for alg, rule in UNSUPPORTED:
        with pytest.raises(ValueError, match=alg):
            rastrum.polygon_mask([(0, 0), (4, 0), (0, 4)], (4, 4), rule=rule, algorithm=alg)


def test_default_arguments():
    tri = [(0.3, 0.2), (7.9, 1.1), (2.2, 6.6)]
    got = rastrum.polygon_mask(tri, (8, 9))
    exp = oracle_mask(tri, (8, 9), rule="evenodd", subpixel_bits=8,
                      sample_offset=0.5)
    assert np.array_equal(got, exp)


# --- extremes ------------------------------------------------------------

@pytest.mark.parametrize("S", range(17))
@pytest.mark.parametrize("alg,rule", CASES)
def test_at_range_limit(alg, rule, S):
    lim = limit_px(S)
    g = 1 << S
    # whole target covered by a square with corners at the limit
    sq = [(-lim, -lim), (lim, -lim), (lim, lim), (-lim, lim)]
    m = rastrum.polygon_mask(sq, (5, 6), rule=rule, algorithm=alg,
                             subpixel_bits=S)
    assert m.all(), describe(sq, (5, 6), rule=rule, algorithm=alg,
                             subpixel_bits=S)
    # long thin edges from the limits through the target
    scenes_ = [
        [(-lim, -lim), (lim, 3.25), (2.5, lim)],
        [(lim, -lim), (-lim, 2.0), (lim, lim)],
        [(-lim, 0.5), (lim, 0.5 + 1.0 / g), (lim, 4.75), (-lim, 3.5)],
        [((COORD_MAX + 0.25) / g, -(COORD_MAX + 0.5) / g), (1.5, 6.5),
         (-lim, lim)],
        [(0.5, -lim), (0.5 + 1.0 / g, lim), (3.5, lim), (3.5 - 1.0 / g, -lim)],
    ]
    for sc in scenes_:
        for o in OFFSETS:
            check_equal(sc, (7, 9), rule=rule, algorithm=alg, subpixel_bits=S,
                        sample_offset=o)


@pytest.mark.parametrize("S", [0, 1, 4, 8, 12, 16])
@pytest.mark.parametrize("alg,rule", CASES)
def test_past_range_limit(alg, rule, S):
    g = 1 << S
    # "aet" goes on to the 64-bit path past the 32-bit range: its limit is
    # 2**(S+28) - 1 units (2**28 pixels) at every S
    M = COORD_MAX if alg != "aet" else 2 ** (S + 28) - 1
    past = [
        (M + 1) / g,            # one grid step past
        -(M + 1) / g,
        (M + 0.5) / g,          # tie rounds up past the limit
        -(M + 0.75) / g,        # snaps to -(max + 1)
        1e12, -1e12, 1e300,
    ]
    for v in past:
        for ring in ([(v, 0.0), (3.0, 0.0), (0.0, 3.0)],
                     [(0.0, 0.0), (3.0, v), (0.0, 3.0)]):
            with pytest.raises(ValueError):
                rastrum.polygon_mask(ring, (4, 4), rule=rule, algorithm=alg,
                                     subpixel_bits=S)
    # the last values that are still accepted
    for v in ((M + 0.25) / g, -(M + 0.5) / g):
        ring = [(v, 0.0), (3.0, v), (0.0, 3.0)]
        check_equal(ring, (4, 4), rule=rule, algorithm=alg, subpixel_bits=S)


def star(n_points, cx, cy, r_out, r_in, phase=0.0):
    pts = []
    for k in range(2 * n_points):
        r = r_out if k % 2 == 0 else r_in
        a = phase + math.pi * k / n_points
        pts.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    return pts


@pytest.mark.parametrize("alg,rule", CASES)
def test_thousands_of_vertices(alg, rule):
    s = star(2500, 40.3, 38.7, 36.0, 20.0, phase=0.1)      # 5000 vertices
    assert len(s) == 5000
    for S, o in ((8, 0.5), (0, 0.0), (3, 0.5)):
        check_equal(s, (80, 82), rule=rule, algorithm=alg, subpixel_bits=S,
                    sample_offset=o)
    # a 5000-vertex self-intersecting random ring partly outside the target
    rng = np.random.default_rng(5)
    walk = rng.uniform(-10, 70, size=(5000, 2))
    check_equal(walk, (60, 64), rule=rule, algorithm=alg)
    # many small rings (holes in holes)
    rl = [np.asarray(star(3 + k % 5, 30 + 17 * math.sin(k), 30 + 17 *
                          math.cos(k), 6 + k % 7, 2.5, phase=k))
          for k in range(300)]
    check_equal(rl, (61, 61), rule=rule, algorithm=alg, subpixel_bits=6,
                sample_offset=0.0)


@pytest.mark.parametrize("alg,rule", CASES)
def test_empty_and_degenerate(alg, rule):
    kw = dict(rule=rule, algorithm=alg)
    m = rastrum.polygon_mask([], (5, 7), **kw)
    assert m.shape == (5, 7) and m.dtype == np.bool_ and not m.any()
    degenerate = [
        [(0, 0), (2, 2), (4, 4)],                       # collinear
        [(0.5, 0.5), (3.5, 3.5), (1.5, 1.5), (2.5, 2.5)],
        [(1.5, 1.5)] * 6,                                # one point
        [(0, 1.5), (6, 1.5), (3, 1.5)],                  # horizontal only
        [(2.5, 0), (2.5, 7), (2.5, 3)],                  # vertical only
        [(1.0, 1.0), (1.001, 1.0), (1.001, 5.0), (1.0, 5.0)],  # < 1/256 wide
    ]
    for ring in degenerate:
        for o in OFFSETS:
            m = rastrum.polygon_mask(ring, (5, 7), sample_offset=o, **kw)
            assert not m.any(), describe(ring, (5, 7), sample_offset=o, **kw)
    # an unsnapped-only sliver: snapped to nothing at S=8 (oracle agrees)
    sliver = [(0.5, 0.0), (0.5 + 2 ** -10, 0.0), (0.5 + 2 ** -10, 4.0),
              (0.5, 4.0)]
    check_equal(sliver, (4, 2), subpixel_bits=8, **kw)
    # zero-sized targets
    for shape in ((0, 5), (5, 0), (0, 0)):
        m = rastrum.polygon_mask([(0, 0), (4, 0), (0, 4)], shape, **kw)
        assert m.shape == shape and m.dtype == np.bool_


@pytest.mark.parametrize("alg,rule", CASES)
def test_large_target(alg, rule):
    # a wide, tall target with a 400-edge scene partly outside it
    rng = np.random.default_rng(11)
    rl = [rng.uniform(-30, 530, size=(100, 2)) for _ in range(4)]
    check_equal(rl, (480, 512), rule=rule, algorithm=alg)

"""rastrum.Canvas: fill_polygon paints exactly the oracle's pixels, never
writes outside its target (guard bytes), and round-trips through Pillow."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import rastrum
from oracle import oracle_mask
from strategies import assert_same, examples, limit_px, lit, scenes

ALGOS = rastrum.ALGORITHMS.get("Canvas.fill_polygon",
                               rastrum.ALGORITHMS["polygon_mask"])
CASES = [(alg, rule) for alg, rules in ALGOS.items() for rule in rules]
FORMATS = {"gray8": 1, "rgb888": 3, "rgba8888": 4}
PIL_MODES = {"gray8": "L", "rgb888": "RGB", "rgba8888": "RGBA"}
GUARD = 0xA5


def pixel_value(fmt, color):
    """The bytes a colour must produce in format ``fmt``."""
    n = FORMATS[fmt]
    if isinstance(color, (int, np.integer)):
        return np.full(n, color, dtype=np.uint8)
    return np.asarray(color, dtype=np.uint8)


def expected_after(before, mask, value):
    exp = before.copy()
    if exp.ndim == 2:
        exp[mask] = value[0]
    else:
        exp[mask] = value
    return exp


def colors(fmt):
    c = st.integers(0, 255)
    if fmt == "gray8":
        return c
    n = FORMATS[fmt]
    return st.one_of(c, st.tuples(*[c] * n), st.lists(c, min_size=n,
                                                     max_size=n))




# --- construction ------------------------------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
def test_new_canvas(fmt):
    c = rastrum.Canvas((5, 7), format=fmt)
    a = c.array
    n = FORMATS[fmt]
    assert a.dtype == np.uint8
    assert a.shape == ((5, 7) if n == 1 else (5, 7, n))
    assert not a.any()
    c2 = rastrum.Canvas((5, 7), format=fmt, background=9)
    assert (c2.array == 9).all()


def test_default_format_is_rgb888():
    c = rastrum.Canvas((3, 4))
    assert c.array.shape == (3, 4, 3)


@pytest.mark.parametrize("fmt", FORMATS)
def test_array_is_a_view(fmt):
    c = rastrum.Canvas((4, 6), format=fmt)
    c.array[1, 2] = 77
    c.fill_polygon([(0, 0), (1, 0), (1, 1), (0, 1)], 200)
    assert (c.array[1, 2] == 77).all()
    assert (c.array[0, 0] == 200).all()


# --- painting exactly the oracle pixels --------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("alg,rule", CASES)
@settings(max_examples=examples(40))
@given(data=st.data())
def test_fill_polygon_matches_oracle(alg, rule, fmt, data):
    S = data.draw(st.integers(0, 8), label="S")
    o = data.draw(st.sampled_from([0.5, 0.0]), label="o")
    rl, (H, W) = data.draw(scenes(S, o, max_h=24, max_w=24), label="scene")
    bg = data.draw(st.integers(0, 255), label="background")
    color = data.draw(colors(fmt), label="color")
    c = rastrum.Canvas((H, W), format=fmt, background=bg)
    before = c.array.copy()
    c.fill_polygon(rl, color, rule=rule, algorithm=alg, subpixel_bits=S,
                   sample_offset=o)
    mask = oracle_mask(rl, (H, W), rule=rule, subpixel_bits=S,
                       sample_offset=o)
    exp = expected_after(before, mask, pixel_value(fmt, color))
    assert_same(c.array, exp, f"Canvas({W}, {H}, format={fmt!r}, "
                 f"background={bg}).fill_polygon({lit(rl)!r}, {color!r}, "
                 f"rule={rule!r}, algorithm={alg!r}, subpixel_bits={S}, "
                 f"sample_offset={o})")


@pytest.mark.parametrize("alg,rule", CASES)
def test_fill_polygon_defaults_and_overdraw(alg, rule):
    c = rastrum.Canvas((16, 20), format="rgb888", background=3)
    a = [(1.2, 0.7), (18.3, 2.2), (9.9, 15.1)]
    b = [(0.0, 8.0), (20.0, 8.0), (20.0, 16.0), (0.0, 16.0)]
    c.fill_polygon(a, (10, 20, 30))
    c.fill_polygon(b, (40, 50, 60), rule=rule, algorithm=alg)
    exp = np.full((16, 20, 3), 3, np.uint8)
    exp[oracle_mask(a, (16, 20))] = (10, 20, 30)
    exp[oracle_mask(b, (16, 20), rule=rule)] = (40, 50, 60)
    assert_same(c.array, exp, "two overlapping fills, second wins")


# --- guard bytes -------------------------------------------------------------

def guarded(fmt, H, W, g, rng):
    n = FORMATS[fmt]
    shape = (H + 2 * g, W + 2 * g) + (() if n == 1 else (n,))
    big = np.full(shape, GUARD, dtype=np.uint8)
    inner = big[g:g + H, g:g + W]
    inner[...] = rng.integers(0, 256, size=inner.shape, dtype=np.uint8)
    return big, inner


def guard_intact(big, g, H, W):
    m = np.ones(big.shape[:2], dtype=bool)
    m[g:g + H, g:g + W] = False
    return bool((big[m] == GUARD).all())


@st.composite
def wild_scenes(draw, S):
    """Scenes that stress clipping: far outside, huge, at the limit."""
    o = 0.5
    kind = draw(st.sampled_from(["nasty", "huge", "outside", "limit"]))
    rl, shape = draw(scenes(S, o, max_h=20, max_w=20))
    H, W = shape
    if kind == "huge":
        s = draw(st.floats(1e2, 1e5))
        rl = [r * s - s / 2 for r in rl]
    elif kind == "outside":
        dx = draw(st.sampled_from([-1, 0, 1]))
        dy = draw(st.sampled_from([-1, 0, 1]) if dx else st.sampled_from([-1, 1]))
        rl = [r + np.array([dx * (W + 30.0), dy * (H + 30.0)]) for r in rl]
    elif kind == "limit":
        lim = limit_px(S)
        rl = rl + [np.array([[-lim, -lim], [lim, -lim], [lim, lim],
                             [-lim, lim]])]
    # keep every coordinate inside the documented range
    lim = limit_px(S)
    rl = [np.clip(r, -lim, lim) for r in rl]
    return rl, shape


@pytest.mark.parametrize("fmt", FORMATS)
@settings(max_examples=examples(60))
@given(data=st.data())
def test_guard_bytes_survive(fmt, data):
    S = data.draw(st.sampled_from([0, 3, 8]), label="S")
    rl, (H, W) = data.draw(wild_scenes(S), label="scene")
    g = data.draw(st.integers(1, 5), label="guard width")
    seed = data.draw(st.integers(0, 2 ** 32 - 1), label="seed")
    rng = np.random.default_rng(seed)
    big, inner = guarded(fmt, H, W, g, rng)
    before = inner.copy()
    c = rastrum.Canvas.wrap(inner)              # format inferred
    assert c.array.shape == inner.shape
    for alg, rule in CASES:
        color = 0x5A if fmt == "gray8" else [0x5A] * FORMATS[fmt]
        c.fill_polygon(rl, color, rule=rule, algorithm=alg, subpixel_bits=S)
        assert guard_intact(big, g, H, W), (
            f"guard bytes overwritten: fmt={fmt} H={H} W={W} g={g} "
            f"rings={lit(rl)!r} rule={rule} alg={alg} S={S}")
        mask = oracle_mask(rl, (H, W), rule=rule, subpixel_bits=S)
        exp = expected_after(before, mask, pixel_value(fmt, color))
        assert_same(inner, exp, f"wrapped fill: fmt={fmt} rings="
                     f"{lit(rl)!r} rule={rule} alg={alg} S={S}")
        # the canvas writes into the caller's memory, not into a copy
        assert np.shares_memory(c.array, big)
        inner[...] = before


@pytest.mark.parametrize("fmt", FORMATS)
def test_wrap_explicit_format_and_writes_through(fmt):
    n = FORMATS[fmt]
    arr = np.zeros((6, 9) + (() if n == 1 else (n,)), np.uint8)
    c = rastrum.Canvas.wrap(arr, format=fmt)
    c.fill_polygon([(0, 0), (9, 0), (9, 6), (0, 6)], 255)
    assert (arr == 255).all()


@pytest.mark.parametrize("sl", [np.s_[4:5, 1:11], np.s_[1:9, 5:6],
                                np.s_[2:8:2, 3:9], np.s_[0:10, 0:12]])
def test_wrap_views(sl):
    """One-row, one-column and row-strided views: only the view changes."""
    big = np.full((10, 12, 3), GUARD, np.uint8)
    view = big[sl]
    c = rastrum.Canvas.wrap(view)
    c.fill_polygon([(-5, -5), (50, -5), (50, 50), (-5, 50)], (1, 2, 3))
    mark = np.zeros((10, 12), bool)
    mark[sl] = True
    assert (big[mark] == (1, 2, 3)).all()
    assert (big[~mark] == GUARD).all()


# --- Pillow -------------------------------------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
def test_to_image_and_save(fmt, tmp_path):
    PIL = pytest.importorskip("PIL.Image")
    c = rastrum.Canvas((7, 13), format=fmt, background=20)
    tri = [(0.5, 0.5), (12.0, 3.0), (2.0, 6.5)]
    color = 250 if fmt == "gray8" else [250, 100, 7, 128][:FORMATS[fmt]]
    c.fill_polygon(tri, color)
    img = c.to_image()
    assert img.mode == PIL_MODES[fmt]
    assert img.size == (13, 7)
    assert np.array_equal(np.asarray(img), c.array)
    p = tmp_path / f"out_{fmt}.png"
    c.save(p)
    with PIL.open(p) as back:
        assert back.format == "PNG"
        assert back.mode == PIL_MODES[fmt]
        assert np.array_equal(np.asarray(back), c.array)
    c.save(str(tmp_path / "as_str.png"))
    with PIL.open(tmp_path / "as_str.png") as back:
        assert np.array_equal(np.asarray(back), c.array)

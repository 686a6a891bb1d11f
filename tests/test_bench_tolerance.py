"""Smoke test of the tolerance row family (bench/path_tolerance.py, used by
bench/bench_coverage.py and bench/demo.py's table; issue 34): the curved
scene is curves (a font's glyphs, or the SVG fallback without matplotlib),
the reference is the exact area of the true curves, every peer's output is
checked -- a peer that draws nothing is reported far off in the same run --
and rastrum's error shrinks with the tolerance to the stated ~1/255 at
1/256 px.  Small scenes, one timed call each; no timing is asserted (speed
claims live in bench/)."""

import io
import math
import os
import sys

import numpy as np
import pytest

import rastrum

BENCH = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench")
sys.path.insert(0, BENCH)

path_tolerance = pytest.importorskip("path_tolerance")

SHAPE = (32, 128)


def one_call(f):
    f()
    return 0.0


def test_reference_is_the_true_curves_area():
    # a circle of SVG arcs (cubics within 1/4096 px of it): the reference's
    # total coverage is pi r^2 within the flattening's and the arcs' error
    # (2 * 1/4096 px times the circumference) -- an oracle the code under
    # test does not compute
    r = 10.0
    d = "M 26 16 A 10 10 0 0 1 16 26 A 10 10 0 0 1 6 16 A 10 10 0 0 1 16 6 A 10 10 0 0 1 26 16 Z"
    ref = path_tolerance.reference(rastrum.Path.from_svg(d), (32, 32))
    assert abs(ref.sum() / 255 - math.pi * r * r) <= 2 * 2 * math.pi * r / 4096
    assert ref.max() <= 255 and ref.min() >= 0


def test_svg_fallback_without_matplotlib(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib fails
    monkeypatch.setitem(sys.modules, "matplotlib.font_manager", None)
    monkeypatch.setitem(sys.modules, "matplotlib.textpath", None)
    label, path = path_tolerance.curved_scene(SHAPE)
    assert label.startswith("SVG curves")
    from rastrum._path import CUBIC, QUAD
    assert CUBIC in path._verbs and QUAD in path._verbs
    cov = rastrum.polygon_coverage(path, SHAPE, rule="nonzero")
    assert cov.any() and not cov[:, -1].any()  # drawn, and inside the shape


def test_rows_shrink_with_the_tolerance_and_check_every_peer(monkeypatch):
    label, path = path_tolerance.curved_scene(SHAPE)
    if "glyph" in label:
        from rastrum._path import QUAD
        assert QUAD in path._verbs  # TrueType's quadratic curves
    wrong = {"draws nothing": lambda: np.zeros(SHAPE, np.uint8)}
    monkeypatch.setattr(path_tolerance, "curve_peers", lambda p, s: wrong)
    rows = path_tolerance.tolerance_rows(path, SHAPE, one_call)
    ours = [r for r in rows if r[1] is not None]
    assert [r[1] for r in ours] == list(path_tolerance.TOLERANCES)
    errs = [r[3] for r in ours]
    edges = [r[6] for r in ours]
    assert all(a > b for a, b in zip(errs, errs[1:])), errs  # finer: closer to the true curves
    assert all(a < b for a, b in zip(edges, edges[1:])), edges
    assert errs[-1] <= 2.0  # 1/256 px: about one level (docs/paths.md)
    (peer,) = [r for r in rows if r[1] is None]
    assert peer[0] == "draws nothing" and peer[3] > 200 and peer[5] > 0  # reported far off


def test_bench_coverage_family_and_demo_table(monkeypatch):
    import bench_coverage
    import demo
    monkeypatch.setattr(path_tolerance, "curve_peers", lambda p, s: {})
    out = io.StringIO()
    points = {}
    monkeypatch.setattr(sys, "stdout", out)
    trade = bench_coverage.tolerance_family(48, 0.01, 1, points)
    rows = demo.curve_table(out=out, repeats=1, shape=SHAPE)
    monkeypatch.undo()
    assert [t for _, _, t in trade] == list(path_tolerance.TOLERANCES)
    assert len(rows) == len(path_tolerance.TOLERANCES)
    text = out.getvalue()
    assert "rastrum area, 1/256 px" in text and "true curves" in text

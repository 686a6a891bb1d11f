"""The demo and the benchmarks' peer checks (issue 17): make demo writes
every picture and a short table without verdict words; a peer whose output
is empty or black is reported as such, not timed as a winner."""

import io
import os
import sys
from contextlib import redirect_stdout

import numpy as np
import pytest

import rastrum

BENCH = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench")
sys.path.insert(0, BENCH)

VERDICTS = ("SLOWER", "MISS", "PASS", "target", "issue 3", "FAIL")


def test_demo_writes_every_picture_and_a_plain_table(tmp_path):
    import demo
    out = io.StringIO()
    with redirect_stdout(out):
        written = demo.main(["--out", str(tmp_path)])
    names = {p.name for p in written}
    assert {"fig3_19.png", "gouraud.png", "holes.png", "seedfill.png", "mesh_torus_depth.png"} <= names
    assert all((tmp_path / n).stat().st_size > 0 for n in names)
    text = out.getvalue()
    assert "rastrum" in text and "PIL.ImageDraw" in text  # Pillow is a dependency: always a peer
    assert not any(v in text for v in VERDICTS), text


def test_demo_table_reports_an_empty_peer(monkeypatch):
    import bench
    import demo
    empty = bench.Peer("nothing", "numpy", ("evenodd",),
                       lambda rings, shape, rule: (lambda: np.zeros(shape, np.uint8)))
    monkeypatch.setattr(bench, "PEERS", [empty])
    out = io.StringIO()
    rows = demo.peer_table(out=out, repeats=1)
    assert all(r[4] for r in rows if r[1] == "nothing") and "empty!" in out.getvalue()


def test_triangle_bench_checks_every_candidate():
    import bench_triangles as bt
    tris = np.array([[(1, 1), (30, 2), (5, 25)], [(30, 2), (31, 30), (5, 25)]], float)
    buf = np.zeros((bt.H, bt.W), np.uint8)
    masks = [rastrum.triangles_mask(tris, (bt.H, bt.W), sample_offset=o) for o in (0.5, 0.0)]
    canvas = rastrum.Canvas.wrap(buf)
    half = tris[:1]

    def good():
        canvas.fill_triangles(tris, 1)

    def part():
        canvas.fill_triangles(half, 1)

    res = bt.check_outputs([("good", good), ("part", part), ("nothing", lambda: None)], buf, masks)
    assert res["good"] == 0 and res["nothing"] == "EMPTY"
    assert res["part"] == int(masks[0].sum() - rastrum.triangles_mask(half, (bt.H, bt.W)).sum())


def test_shade_bench_catches_black_on_black():
    import bench_shade
    buf = np.zeros((8, 8, 4), np.uint8)
    exact = np.zeros_like(buf)
    exact[2:6, 2:6] = (200, 100, 50, 255)
    mask = exact[..., 3] > 0

    def black():
        buf[2:6, 2:6] = (0, 0, 0, 255)

    def right():
        buf[...] = exact

    assert bench_shade.check_peer(black, buf, exact, mask).startswith("BLACK")
    assert bench_shade.check_peer(lambda: None, buf, exact, mask) == "EMPTY"
    assert bench_shade.check_peer(right, buf, exact, mask).startswith("0 px coverage off, colour error max 0")


def test_skia_peers_draw_something():
    """With skia-python installed (make bench), its paints are the fixed
    ones: the polygon peer writes the mask, drawVertices the colours."""
    skia = pytest.importorskip("skia")
    import bench
    import bench_shade
    rings = [np.array([(2.0, 2.0), (28.0, 4.0), (14.0, 27.0)])]
    got = bench._skia_make(rings, (32, 32), "evenodd")()
    assert got.any() and np.count_nonzero(got.astype(bool) != rastrum.polygon_mask(rings, (32, 32))) < 20
    tris = rings[0].reshape(1, 3, 2)
    cols = np.array([[(200, 10, 10), (10, 200, 10), (10, 10, 200)]])
    buf = np.zeros((32, 32, 4), np.uint8)
    run, note = bench_shade.skia_cand(tris, cols, buf)
    c = rastrum.Canvas((32, 32), format="rgba8888")
    c.fill_triangles(tris, vertex_colors=cols)
    report = bench_shade.check_peer(run, buf, c.array.copy(), rastrum.triangles_mask(tris, (32, 32)))
    assert "px coverage off" in report, report
    del skia

"""Issue 35 (Hardening III): what an outside probe found in the surfaces
added the wave before, one test per finding, named after it, each the
tester's reproducer (docs/bad-input.md lists them with what happens now).
The binding's own C (python/glue, python/ext/seq.c) is fuzzed by
tests/fuzz/fuzz_coco.c, fuzz_burn.c and fuzz_seq.c."""

from __future__ import annotations

import numpy as np
import pytest

import rastrum
from rastrum import coco
from rastrum._core import InputError


def _rle(counts, h, w):
    return coco.frPyObjects([{"size": [h, w], "counts": list(counts)}], h, w)[0]


# ---- finding 2: the RLE parser shifted by 65 bits on hostile strings ------

def test_finding2_rle_parser_long_count():
    bad = {"size": [1, 1], "counts": b"oooooooooooo" + b"O"}  # 13 groups for one count
    for f in (coco.area, coco.toBbox, coco.decode):
        with pytest.raises(InputError, match="not a valid COCO RLE"):
            f(bad)
    with pytest.raises(InputError, match="not a valid COCO RLE"):
        coco.merge([bad, bad])
    with pytest.raises(InputError, match="not a valid COCO RLE"):
        coco.iou([bad], [bad], [0])
    # 8 groups: more than a uint32 count needs; a count past 2^32 - 1
    for s in (b"0" + b"P" * 7 + b"0", b"ooooooO"):
        with pytest.raises(InputError, match="not a valid COCO RLE"):
            coco.area({"size": [1, 1], "counts": s})
    # a negative count (a difference below the count two before)
    with pytest.raises(InputError, match="not a valid COCO RLE"):
        coco.area({"size": [4, 4], "counts": b"011N"})
    # the longest valid count, 2^32 - 1, still reads
    big = _rle([0, 2**32 - 1], 1, 2**32 - 1)
    assert coco.area(big) == 2**32 - 1


# ---- finding 4: pycocotools' polygon rule took memory vertices x width -------

# The tester's case: 100 vertices zig-zagging across a 1 x W mask (every
# edge crosses every column: 100 W toggles), and the same ring on a 1 x 0
# mask (pycocotools' width 0 takes every column).  The counts strings are
# pycocotools' own, from running it on these rings (at W = 1,600,000 it
# peaked at 8.2 GB; bench/coco_memory.py runs both again and compares).
_ZIGZAG = """
import resource, sys
from rastrum import coco
W = int(sys.argv[1])
zig = []
for k in range(100):
    zig += [0.0 if k % 2 == 0 else float(W), -0.4 + 0.021 * k]
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
for w in (W, 0):
    r = coco.frPyObjects([zig], 1, w)[0]
    grew = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
    print(w, grew, r["counts"].decode())
"""
_PYCOCOTOOLS = {  # (W, w): pycocotools' counts string
    (1600000, 1600000): "^dob0bc]5PX]h0", (1600000, 0): "0^dob0bc]5bc]5",
    (400000, 400000): "Tmg4l\\[1PZS6", (400000, 0): "0Tmg4l\\[1l\\[1",
}


def test_finding4_coco_rule_memory_follows_the_output():
    """Peak RSS (ru_maxrss, kB) of a fresh interpreter grows by less than
    100 MB over the call; it was 100 W toggles of 24 bytes (3.8 GB at
    W = 1.6 million; pycocotools takes 8.2 GB).  Sanitizer runs (the quick
    profile) take W = 400,000: 40 million toggles, 960 MB before."""
    import os
    import subprocess
    import sys
    big = 400000 if os.environ.get("RASTRUM_HYPOTHESIS_PROFILE") in ("quick", "valgrind") else 1600000
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = subprocess.run([sys.executable, "-c", _ZIGZAG, str(big)], env=env, capture_output=True, text=True,
                         check=True).stdout.split("\n")
    for line, w in zip(out, (big, 0)):
        got_w, grew, counts = line.split()
        assert int(got_w) == w and int(grew) < 100 * 1024, line  # kB, both calls
        assert counts == _PYCOCOTOOLS[big, w]


# ---- finding 5: merge / iou past 2^31 pixels ---------------------------------

def test_finding5_merge_iou_past_2_31_pixels():
    h, w = 1, 2**31 + 1
    empty = _rle([h * w], h, w)
    allbutone = _rle([1, h * w - 1], h, w)
    m = coco.merge([empty, allbutone])
    assert coco.area(m) == h * w - 1
    assert m["counts"] == allbutone["counts"]
    assert coco.iou([allbutone], [allbutone], [0])[0, 0] == 1.0
    assert coco.merge([allbutone, allbutone], intersect=1)["counts"] == allbutone["counts"]
    half = _rle([2**30, 2**31 - 2**30 + 1], h, w)
    # in = 2^31 - 2^30 + 1 - 1 (half misses pixel 0, allbutone too), union h*w - 1
    assert coco.iou([half], [allbutone], [0])[0, 0] == (2**31 - 2**30 + 1) / (h * w - 1)
    # a size pycocotools accepts: h = 1, w = 2^31 + 3
    w2 = 2**31 + 3
    r = _rle([5, w2 - 5], 1, w2)
    assert coco.area(r) == w2 - 5
    assert coco.toBbox(r).tolist() == [5.0, 0.0, w2 - 5.0, 1.0]


# ---- finding 7: counts past h * w -----------------------------------------------

def test_finding7_counts_past_hw():
    over = {"size": [4, 5], "counts": [0, 21]}
    over_s = {"size": [4, 5], "counts": coco.frPyObjects([over], 4, 5)[0]["counts"]}
    for f in (coco.area, coco.toBbox, coco.decode):
        with pytest.raises(InputError, match="at most h \\* w"):
            f(over_s)
    with pytest.raises(InputError, match="at most h \\* w"):
        coco.merge([over_s, over_s])
    with pytest.raises(InputError, match="at most h \\* w"):
        coco.iou([over_s], [over_s], [0])
    with pytest.raises(InputError, match="at most h \\* w"):
        coco.decode({"size": [0, 0], "counts": b"1"})
    ok = {"size": [4, 5], "counts": coco.frPyObjects([{"size": [4, 5], "counts": [0, 20]}], 4, 5)[0]["counts"]}
    assert coco.area(ok) == 20 and coco.toBbox(ok).tolist() == [0.0, 0.0, 5.0, 4.0]


# ---- finding 1: a misaligned depth buffer ---------------------------------------

def test_finding1_misaligned_depth():
    c = rastrum.Canvas((8, 10), format="gray8")
    raw = np.zeros(8 * 10 * 4 + 1, np.uint8)[1:]
    d = raw.view(np.int32).reshape(8, 10)
    assert not d.flags.aligned and d.flags.c_contiguous
    with pytest.raises(InputError, match="depth must be aligned"):
        c.depth = d
    assert c.depth is None
    c.depth = np.require(d, np.int32, "CA")  # an aligned copy is taken
    assert c.depth.flags.aligned


# ---- finding 3: rasterize(out=<misaligned C-contiguous array>) --------------------

def test_finding3_rasterize_misaligned_out():
    square = {"type": "Polygon", "coordinates": [[(1, 1), (5, 1), (5, 4), (1, 4), (1, 1)]]}
    raw = np.zeros(6 * 8 * 4 + 1, np.uint8)[1:]
    out = raw.view(np.int32).reshape(6, 8)
    assert not out.flags.aligned and out.flags.c_contiguous
    got = rastrum.rasterize([(square, 7)], out=out)
    want = rastrum.rasterize([(square, 7)], out_shape=(6, 8), dtype="int32")
    assert got is out
    np.testing.assert_array_equal(out, want)
    assert (want == 7).sum() == 12


# ---- finding 6: int64 burn of 2^63 ---------------------------------------------

def test_finding6_int64_value_2_63():
    square = {"type": "Polygon", "coordinates": [[(0, 0), (2, 0), (2, 2), (0, 2), (0, 0)]]}
    for v in (2.0**63, -(2.0**63) * 1.0000001, 2.0**64):
        with pytest.raises(InputError, match="does not fit dtype int64"):
            rastrum.rasterize([(square, v)], out_shape=(3, 3), dtype="int64")
    with pytest.raises(InputError, match="does not fit dtype uint32"):
        rastrum.rasterize([(square, 2.0**32)], out_shape=(3, 3), dtype="uint32")
    a = rastrum.rasterize([(square, -(2.0**63))], out_shape=(3, 3), dtype="int64")
    assert a[0, 0] == -(2**63)
    a = rastrum.rasterize([(square, 2.0**32 - 1)], out_shape=(3, 3), dtype="uint32")
    assert a[0, 0] == 2**32 - 1


# ---- finding 10: a raising progress callback ------------------------------------

def test_finding10_progress_raises_out_untouched():
    shapes = [({"type": "Polygon", "coordinates": [[(k % 50, k // 50), (k % 50 + 1, k // 50),
                                                   (k % 50 + 1, k // 50 + 1), (k % 50, k // 50)]]}, 1)
              for k in range(3000)]
    out = np.full((70, 60), 9, np.uint8)
    calls = []

    def progress(done, total):
        calls.append(done)
        if len(calls) == 2:
            raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt):
        rastrum.rasterize(shapes, out=out, progress=progress)
    assert len(calls) == 2
    assert (out == 9).all()


# ---- finding 9: errors that were not InputError ----------------------------------

def test_finding9_errors_are_input_errors():
    with pytest.raises(InputError, match="RLE 0 has size"):
        coco.area({"size": [2**32, 0], "counts": b""})
    with pytest.raises(InputError, match="below 2\\*\\*32"):
        coco.encode(np.zeros((2**32, 0), np.uint8))
    r = coco.encode(np.ones((2, 2), np.uint8, order="F"))
    for crowd in ([256], [None], ["a"], [-1], [[0]]):
        with pytest.raises(InputError, match="iscrowd"):
            coco.iou([r], [r], crowd)
    assert coco.iou([r], [r], [True])[0, 0] == 1.0
    pytest.importorskip("dask")
    import rastrum.dask
    for chunks in (0, (0, 5)):
        with pytest.raises(InputError, match="chunks .*every chunk must be a whole number > 0") as e:
            rastrum.dask.rasterize([], (4, 5), chunks=chunks, dtype="uint8")
        assert "division" not in str(e.value)  # was Python's ZeroDivisionError text


def test_finding9_tiny_transform_blames_transform():
    square = {"type": "Polygon", "coordinates": [[(0, 0), (2, 0), (2, 2), (0, 2), (0, 0)]]}
    with pytest.raises(InputError, match="^transform .*inverse is not finite"):
        rastrum.rasterize([(square, 1)], out_shape=(3, 3), transform=(1e-320, 0, 0, 0, -1, 0))


# ---- a GDAL-ordered geotransform tuple -------------------------------------------

def test_gdal_ordered_geotransform_refused():
    square = {"type": "Polygon", "coordinates": [[(100, 50), (120, 50), (120, 30), (100, 30), (100, 50)]]}
    gdal = (100.0, 10.0, 0.0, 50.0, 0.0, -10.0)  # (c, a, b, f, d, e)
    with pytest.raises(InputError, match="GDAL geotransform"):
        rastrum.rasterize([(square, 1)], out_shape=(4, 4), transform=gdal)
    affine_order = (10.0, 0.0, 100.0, 0.0, -10.0, 50.0)
    a = rastrum.rasterize([(square, 1)], out_shape=(4, 4), transform=affine_order)
    assert a.sum() == 4 and a[:2, :2].all()


# ---- labels wrapped values its dtype cannot hold ----------------------------------

def test_labels_values_that_do_not_fit():
    sq = [np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)]
    for v, dt in ((300, "uint8"), (-1, "uint8"), (2.7, "int32"), (float("nan"), "int16"), (2.0**63, "int64"),
                  (1e39, "float32")):
        with pytest.raises(InputError, match="does not fit dtype"):
            rastrum.labels([sq], (3, 3), values=[v], dtype=dt)
    with pytest.raises(InputError, match="values must be numbers"):
        rastrum.labels([sq], (3, 3), values=[True])
    with pytest.raises(InputError, match="300 polygons need ids 1..300; dtype uint8"):
        rastrum.labels([sq] * 300, (3, 3), dtype="uint8")
    assert rastrum.labels([sq] * 255, (3, 3), dtype="uint8")[0, 0] == 255
    assert rastrum.labels([sq], (3, 3), values=[255.0], dtype="uint8")[0, 0] == 255


# ---- finding 8: bools read as 0 / 1 inside float lists ------------------------------

def test_finding8_bools_in_float_lists():
    seg = [[1.0, 1.0, 6.0, True, 6.0, 4.0]]
    with pytest.raises(InputError, match="bool"):
        coco.rings(seg)
    with pytest.raises(InputError, match="bool"):
        coco.polygons([seg])
    with pytest.raises(InputError, match="bool"):
        coco.frPyObjects(seg, 8, 8)
    with pytest.raises(InputError, match="bool"):
        rastrum.polygon_mask([(1.0, 1.0), (6.0, True), (6.0, 4.0)], (8, 8))
    assert len(coco.rings([[1.0, 1.0, 6.0, 1, 6.0, 4.0]])[0]) == 3  # ints are numbers


def test_finding9_deep_or_recursive_geometry_collection():
    sq = {"type": "Polygon", "coordinates": [[(0, 0), (2, 0), (2, 2), (0, 2), (0, 0)]]}
    deep = sq
    for _ in range(5000):
        deep = {"type": "GeometryCollection", "geometries": [deep]}
    with pytest.raises(InputError, match="nested more than 100 deep"):
        rastrum.rasterize([(deep, 1)], out_shape=(3, 3))
    loop = {"type": "GeometryCollection", "geometries": [sq]}
    loop["geometries"].append(loop)
    out = np.zeros((3, 3), np.uint8)
    with pytest.raises(InputError, match="holding itself"):
        rastrum.rasterize([(loop, 1)], out=out)
    assert not out.any()
    ok = sq
    for _ in range(50):
        ok = {"type": "GeometryCollection", "geometries": [ok]}
    assert rastrum.rasterize([(ok, 1)], out_shape=(3, 3)).sum() == 4


# ---- finding 8, the rest: Polygons' tables, a scalar part ----------------------------

def test_finding8_polygons_tables_checked_where_they_enter():
    tri = [[0, 0], [4, 0], [4, 4]]
    for points, match in ((np.array(tri, complex), "points .* not dtype complex128"),
                          (np.array(tri, str), "points .* not dtype <U1"),
                          ([[0, 0], [True, 0], [4, 4]], "points .* not bools"),
                          ([[0, 0], [None, 0], [4, 4]], "points .* not None")):
        with pytest.raises(InputError, match="Polygons: " + match):
            rastrum.Polygons(points, [3], [1])
    for sizes, counts, match in (([3.7], [1], "ring_sizes .* ints"), ([3.0], [1], "ring_sizes .* ints"),
                                 ([True, True, True], [3], "ring_sizes .* ints"), ([3], [1.2], "rings_per_polygon"),
                                 (["3"], [1], "ring_sizes"), ([[3]], [1], "ring_sizes must be 1-D"),
                                 ([-3], [1], "ring_sizes must be counts"), ([3], [2**32], "rings_per_polygon")):
        with pytest.raises(InputError, match=match):
            rastrum.Polygons(np.array(tri, float), sizes, counts)
    b = rastrum.Polygons(np.array(tri), np.array([3], np.int64), [1])  # ints of any width: counts
    assert b[0][0].tolist() == [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]]


def test_finding8_scalar_part_refused():
    seg = [[0, 0, 4, 0, 4, 4], 5]  # was: the 5 read as a part of no point, dropped
    with pytest.raises(InputError, match="rings: part 1 has shape \\(\\)"):
        coco.rings(seg)
    with pytest.raises(InputError, match="polygons: object 0: rings: part 1 has shape \\(\\)"):
        coco.polygons([seg])
    with pytest.raises(InputError, match="frPyObjects: polygon 1 has shape \\(\\)"):
        coco.frPyObjects(seg, 5, 5)


# ---- finding 9, the rest: ragged and recursive lists, numpy reprs --------------------

def test_finding9_ragged_lists_name_the_object():
    with pytest.raises(InputError, match="polygons: object 1: rings: part 0 "):
        coco.polygons([[[0, 0, 4, 0, 4, 4]], [[0, 0, [4], 0, 4, 4]]])
    with pytest.raises(InputError, match="^rings: part 1 "):
        coco.rings([[0, 0, 4, 0, 4, 4], [0, [0, 1], 4, 0]])
    loop = []
    loop.append(loop)
    for call in (lambda: coco.rings(loop), lambda: coco.polygons([loop]), lambda: coco.frPyObjects(loop, 3, 3),
                 lambda: rastrum.polygon_mask(loop, (3, 3)), lambda: rastrum.Polygons(loop, [1], [1])):
        with pytest.raises(InputError):  # was numpy's ValueError (more than 64 dimensions)
            call()


def test_finding9_messages_print_plain_numbers():
    sq = {"type": "Polygon", "coordinates": [[(0, 0), (2, 0), (2, 2), (0, 0)]]}
    with pytest.raises(InputError) as e:
        rastrum.rasterize([(sq, np.float64(300.5))], out_shape=(4, 4), dtype="uint8")
    assert "value 300.5 does not fit" in str(e.value), e.value
    for call in (lambda: rastrum.rasterize([(sq, 1)], out_shape=(4, 4),
                                           transform=tuple(np.array([1e-320, 0, 0, 0, 1, 0]))),
                 lambda: rastrum.Canvas((4, 4)).flood_fill((np.int64(9), np.int64(1)), 1),
                 lambda: rastrum.Canvas((4, 4)).fill_polygon([(0, 0), (1, 1), (0, 1)], (np.float64(1.5),)),
                 lambda: rastrum.polygon_mask([(0, 0), (1, 1), (0, 1)], (4, 4), sample_offset=np.float64(0.25)),
                 lambda: rastrum.rasterize([(sq, np.True_)], out_shape=(4, 4))):
        with pytest.raises(InputError) as e:
            call()
        assert "np." not in str(e.value), e.value

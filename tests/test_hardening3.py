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

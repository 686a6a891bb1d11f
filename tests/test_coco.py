"""rastrum.coco against pycocotools (bit for bit) and the exact oracle.

pycocotools is the reference for rule="coco" and for every RLE function:
the tests compare with pycocotools itself (skipped when it is missing; CI
installs it).  rule="exact" is compared with tests/oracle.py.
"""
import importlib.util
import os

import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import coco as C
from oracle import oracle_mask

M = pytest.importorskip("pycocotools.mask")

_spec = importlib.util.spec_from_file_location(
    "compat_coco", os.path.join(os.path.dirname(__file__), "..", "bench", "compat_coco.py"))
compat = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compat)


def test_random_objects_ci_subset():
    """A CI-sized run of bench/compat_coco.py (the 100,000-object run is
    reported in docs/coco.md): every name, every kind of part."""
    done, bad = compat.check(600, seed=2024)
    assert done >= 600 and bad == 0


# Coordinates on the 1/5 grid put pycocotools' walk on exact halves (its
# doubles' ties); small integers and halves, and general floats.
fifths = st.integers(-60, 260).map(lambda v: v / 5.0)
floats = st.floats(-30, 80, allow_nan=False, allow_infinity=False)
coord = st.one_of(fifths, floats, st.integers(-5, 60).map(float))
part = st.lists(coord, min_size=6, max_size=24)


@given(st.lists(part, min_size=1, max_size=3), st.integers(0, 50), st.integers(1, 50))
def test_fr_py_objects_matches_pycocotools(parts, h, w):
    a, b = M.frPyObjects(parts, h, w), C.frPyObjects(parts, h, w)
    assert a == b
    assert M.merge(a) == C.merge(b)
    if h:
        da, db = M.decode(a), C.decode(b)
        assert da.flags.f_contiguous and db.flags.f_contiguous and db.dtype == np.uint8
        assert np.array_equal(da, db)
    assert np.array_equal(M.area(a), C.area(b)) and C.area(b).dtype == np.uint32
    assert np.array_equal(M.toBbox(a), C.toBbox(b))


@given(st.lists(part, min_size=1, max_size=3),
       st.one_of(st.integers(0, 40), st.sampled_from([2**26 + 3, 2**30 - 1])),
       st.one_of(st.just(0), st.integers(1, 40)), st.integers(1, 24))
def test_fr_py_objects_in_windows_matches_pycocotools(parts, h, w, window):
    """pycocotools' rule a few toggles at a time (rastrum.coco._WINDOW;
    python/glue/coco.c), so that run ends fall on window edges: the same
    strings as pycocotools.  Width 0 (every column takes toggles, counts
    past the empty mask) and heights whose positions pass 2^32 (pycocotools
    wraps them) too; height 0."""
    if h * w > 2**32 - 1:
        w = 0
    a = M.frPyObjects(parts, h, w)
    try:
        C._WINDOW = window
        b = C.frPyObjects(parts, h, w)
    finally:
        C._WINDOW = 0
    assert a == b
    assert C.frPyObjects(parts, h, w) == a


@given(st.lists(st.floats(0.5, 8, allow_nan=False), min_size=3, max_size=3).map(
    lambda v: [[float(int(v[0] * 5)) / 5, float(int(v[1] * 5)) / 5]]),
    st.integers(1, 7), st.integers(1, 97))
def test_ties_along_long_edges(start, dx, dy):
    """Edges whose slope is a fraction with odd denominators: pycocotools'
    s*t lands on .5 and its doubles round either way."""
    x, y = start[0]
    p = [x, y, x + dx / 5.0, y + dy / 5.0 * 7, x - dy / 5.0, y + dx]
    assert M.frPyObjects([p], 60, 40) == C.frPyObjects([p], 60, 40)


def test_single_object_forms():
    p = [1.0, 1.0, 6.5, 1.2, 4.0, 7.0]
    assert C.frPyObjects(p, 10, 10) == M._mask.frPoly([p], 10, 10)[0]
    bb = [1.5, 2.0, 4.0, 3.0]
    assert C.frPyObjects(bb, 10, 10) == M.frPyObjects(np.array([bb]), 10, 10)[0]
    assert C.frPyObjects(np.array([bb]), 10, 10) == M.frPyObjects(np.array([bb]), 10, 10)
    unc = {"size": [5, 4], "counts": [3, 2, 15]}
    assert C.frPyObjects(unc, 1, 1) == M.frPyObjects(unc, 1, 1)
    assert C.frPyObjects([unc], 1, 1) == M.frPyObjects([unc], 1, 1)
    rle = M.frPyObjects([p], 10, 10)[0]
    assert type(C.area(rle)) is type(M.area(rle))
    assert C.decode(rle).shape == (10, 10) and C.decode(rle).flags.f_contiguous
    assert np.array_equal(C.toBbox(rle), M.toBbox(rle))
    assert C.merge([]) == M.merge([])
    assert C.iou([], [], []) == M.iou([], [], []) == []
    other = M.frPyObjects([[2.0, 2.0, 9.0, 2.0, 9.0, 9.0]], 12, 10)[0]
    assert C.merge([rle, other]) == M.merge([rle, other])  # sizes differ: pycocotools' empty


@given(st.lists(st.lists(st.integers(0, 2), min_size=1, max_size=40), min_size=1, max_size=5),
       st.integers(1, 9), st.sampled_from([np.uint8, np.bool_]), st.booleans())
def test_encode_decode_out(rows, h, dtype, fortran):
    n = len(rows)
    w = 4
    flat = np.array([(r * 40)[:h * w] for r in rows], np.uint8)  # bytes 0..2: pycocotools' runs
    masks = np.asfortranarray(flat.reshape(n, w, h).transpose(2, 1, 0))
    if dtype == np.bool_:
        masks = np.asfortranarray(masks.astype(bool).astype(np.uint8))
    ref = M.encode(masks)
    arr = masks.astype(dtype)
    assert C.encode(arr if fortran else np.ascontiguousarray(arr)) == ref
    assert C.encode(np.asfortranarray(arr[:, :, 0])) == M.encode(np.asfortranarray(masks[:, :, 0]))
    dec = M.decode(ref)
    assert np.array_equal(C.decode(ref), dec)
    out = np.zeros((h, w, n), bool)  # C order, bool
    assert C.decode(ref, out=out) is out and np.array_equal(out, dec.astype(bool))
    out1 = np.full((h, w), 7, np.uint8)
    C.decode(ref[0], out=out1)
    assert np.array_equal(out1, dec[:, :, 0])


def test_iou_rle_and_boxes_with_crowd():
    rng = np.random.default_rng(5)
    dt = [M.merge(M.frPyObjects([list(rng.uniform(-5, 45, 10))], 40, 40)) for _ in range(7)]
    gt = [M.merge(M.frPyObjects([list(rng.uniform(-5, 45, 12))], 40, 40)) for _ in range(5)]
    crowd = [0, 1, 0, 1, 1]
    a, b = M.iou(dt, gt, crowd), C.iou(dt, gt, crowd)
    assert np.array_equal(a, b) and b.flags.f_contiguous and b.shape == (7, 5)
    boxes_d, boxes_g = rng.uniform(0, 30, (6, 4)), rng.uniform(0, 30, (3, 4))
    assert np.array_equal(M.iou(boxes_d, boxes_g, [1, 0, 1]), C.iou(boxes_d, boxes_g, [1, 0, 1]))
    assert np.array_equal(M.iou(boxes_d.tolist(), boxes_g.tolist(), [0, 0, 1]),
                          C.iou(boxes_d.tolist(), boxes_g.tolist(), [0, 0, 1]))


def test_counts_strings_long_runs():
    """Counts past 2**15 and differences of both signs in the string form."""
    m = np.zeros((300, 400), np.uint8, order="F")
    m[:, 200:] = 1
    m[5:7, 3] = 2
    r = M.encode(m)
    assert C.encode(m) == r and np.array_equal(C.decode(r), M.decode(r))


@given(st.lists(st.lists(fifths, min_size=6, max_size=16), min_size=1, max_size=3),
       st.integers(1, 30), st.integers(1, 30))
def test_exact_rule_equals_oracle(parts, h, w):
    """rule="exact": each part's RLE decodes to the oracle's even-odd mask
    of that part (pixel centres, subpixel_bits 8)."""
    rles = C.frPyObjects(parts, h, w, rule="exact")
    for p, r in zip(parts, rles):
        ring = np.array(p[:len(p) // 2 * 2], float).reshape(-1, 2)
        want = oracle_mask([ring], (h, w), rule="evenodd")
        assert np.array_equal(C.decode(r).astype(bool), want)
    union = C.decode(C.merge(rles)).astype(bool)
    want = np.zeros((h, w), bool)
    for p in parts:
        want |= oracle_mask([np.array(p[:len(p) // 2 * 2], float).reshape(-1, 2)], (h, w), rule="evenodd")
    assert np.array_equal(union, want)


def test_rings_helper_feeds_masks():
    segm = [[1.0, 1.0, 8.0, 1.0, 8.0, 6.0], [0.0, 5.0, 3.0, 5.0, 3.0, 9.0, 0.0, 9.0]]
    r = C.rings(segm)
    assert [a.shape for a in r] == [(3, 2), (4, 2)]
    m = rastrum.masks([r], (10, 10))[0]
    want = oracle_mask([r[0]], (10, 10)) | oracle_mask([r[1]], (10, 10))
    assert np.array_equal(m, want)
    assert [a.shape for a in C.rings([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0])] == [(3, 2)]


# ---- bad input: InputError (a ValueError) naming the argument -------------------

BAD = [
    ("frPyObjects rule", lambda: C.frPyObjects([[1.0, 1, 5, 1, 5, 5]], 9, 9, rule="bogus"), r"rule"),
    ("frPyObjects NaN", lambda: C.frPyObjects([[1.0, 1, 5, float("nan"), 5, 5]], 9, 9), r"polygon 0, point 1.*NaN"),
    ("frPyObjects range", lambda: C.frPyObjects([[1.0, 1, 5, 1e9, 5, 5]], 9, 9), r"outside"),
    ("frPyObjects h", lambda: C.frPyObjects([[1.0, 1, 5, 1, 5, 5]], -1, 9), r"h=-1"),
    ("frPyObjects w float", lambda: C.frPyObjects([[1.0, 1, 5, 1, 5, 5]], 9, 2.5), r"ints"),
    ("frPyObjects empty", lambda: C.frPyObjects([], 9, 9), r"non-empty list"),
    ("frPyObjects str", lambda: C.frPyObjects("abc", 9, 9), r"pyobj"),
    ("frPyObjects polygon shape", lambda: C.frPyObjects([np.zeros((4, 3))], 9, 9), r"polygon 0 has shape \(4, 3\)"),
    ("frPyObjects complex", lambda: C.frPyObjects([[1j, 1, 5, 1, 5, 5]], 9, 9), r"real"),
    ("frPyObjects box shape", lambda: C.frPyObjects(np.zeros((2, 3)), 9, 9), r"\(N, 4\)"),
    ("frPyObjects exact NaN", lambda: C.frPyObjects([[1.0, 1, 5, float("nan"), 5, 5]], 9, 9, rule="exact"), r"NaN"),
    ("decode bad char", lambda: C.decode({"size": [3, 3], "counts": b"3 "}), r"not a valid COCO RLE"),
    ("decode unfinished", lambda: C.decode({"size": [3, 3], "counts": b"3P"}), r"not a valid COCO RLE"),
    ("decode too long", lambda: C.decode({"size": [3, 3], "counts": b";"}), r"not a valid COCO RLE"),
    ("decode sizes", lambda: C.decode([{"size": [3, 3], "counts": b"9"}, {"size": [3, 2], "counts": b"6"}]),
     r"RLE 1 has size \[3, 2\]"),
    ("decode empty list", lambda: C.decode([]), r"no RLEs"),
    ("decode not dict", lambda: C.decode([b"9"]), r"RLE 0 must be a dict"),
    ("decode size", lambda: C.decode({"size": [3], "counts": b"9"}), r"size"),
    ("decode out shape", lambda: C.decode({"size": [3, 3], "counts": b"9"}, out=np.zeros((3, 4), np.uint8)),
     r"out has shape \(3, 4\).*\(3, 3\)"),
    ("decode out dtype", lambda: C.decode({"size": [3, 3], "counts": b"9"}, out=np.zeros((3, 3))), r"out"),
    ("decode out read-only", lambda: C.decode({"size": [3, 3], "counts": b"9"},
                                              out=np.zeros((3, 3), np.uint8)[None][0].view().__array__()
                                              if False else _ro()), r"read-only"),
    ("encode dtype", lambda: C.encode(np.zeros((3, 3))), r"uint8 or bool"),
    ("encode ndim", lambda: C.encode(np.zeros(3, np.uint8)), r"shape \(3,\)"),
    ("merge not list", lambda: C.merge({"size": [3, 3], "counts": b"9"}), r"list"),
    ("merge bad", lambda: C.merge([{"size": [3, 3], "counts": b"9"}, {"size": [3, 3], "counts": b"~"}]),
     r"not a valid"),
    ("area bad", lambda: C.area([{"size": [3, 3]}]), r"RLE 0 must be a dict"),
    ("toBbox bad", lambda: C.toBbox({"size": [3, 3], "counts": b"\x01"}), r"not a valid"),
    ("iou crowd", lambda: C.iou([[0, 0, 1, 1]], [[0, 0, 1, 1]], [0, 1]), r"iscrowd has 2 entries for 1"),
    ("iou mixed", lambda: C.iou([[0, 0, 1, 1]], [{"size": [3, 3], "counts": b"9"}], [0]), r"both"),
    ("iou kind", lambda: C.iou("x", [[0, 0, 1, 1]], [0]), r"dt must be"),
    ("iou box shape", lambda: C.iou(np.zeros((2, 3)), np.zeros((1, 4)), [0]), r"\(N, 4\)"),
    ("rings flat nested", lambda: C.rings([[[1, 2], [3, 4]]]), r"part 0 has shape"),
    ("rings dict", lambda: C.rings({"size": [1, 1], "counts": b"1"}), r"RLE"),
    ("uncompressed negative", lambda: C.frPyObjects({"size": [3, 3], "counts": [-1, 10]}, 3, 3), r"0\.\.2\*\*32"),
]


def _ro():
    a = np.zeros((3, 3), np.uint8)
    a.setflags(write=False)
    return a


@pytest.mark.parametrize("name,call,problem", BAD, ids=[b[0] for b in BAD])
def test_bad_input(name, call, problem):
    with pytest.raises(rastrum.InputError, match=problem):
        call()


def test_bad_decode_writes_nothing():
    out = np.full((3, 3), 7, np.uint8)
    with pytest.raises(rastrum.InputError):
        C.decode({"size": [3, 3], "counts": b";"}, out=out)
    assert (out == 7).all()


def test_docs_coco_examples_run():
    """docs/coco.md's python blocks run as written."""
    import re
    path = os.path.join(os.path.dirname(__file__), "..", "docs", "coco.md")
    with open(path, encoding="utf-8") as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)
    assert len(blocks) == 3
    for code in blocks:
        exec(compile(code, "docs/coco.md", "exec"), {})

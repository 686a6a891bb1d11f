"""rastrum.masks and rastrum.labels against the exact oracle.

The union rule is checked two ways: for rings that do not cross themselves
against the oracle's mask of each ring on its own, OR-ed (what "union"
means); for any rings against the oracle's non-zero fill of the rings each
turned to positive area (exact Fractions on the snapped vertices), which is
the rule's definition where a ring crosses itself.
"""
import numpy as np
import pytest
from hypothesis import given, strategies as st

import rastrum
from rastrum import _ml as ml
from oracle import oracle_mask, snapped_rings

coord = st.one_of(st.integers(-4, 24).map(float), st.floats(-4, 24, allow_nan=False).map(lambda v: round(v, 2)))
ring = st.lists(st.tuples(coord, coord), min_size=1, max_size=7).map(lambda r: np.array(r, float))
polygon = st.lists(ring, min_size=1, max_size=3)
SHAPE = (17, 21)


def _simple(r):
    """The ring's points in order of angle around their mean: a ring that
    does not cross itself (star-shaped; it may touch itself on a ray)."""
    c = r.mean(axis=0)
    return r[np.lexsort((np.hypot(*(r - c).T), np.arctan2(*(r - c).T[::-1])))]


simple_polygon = st.lists(ring.map(_simple), min_size=1, max_size=3)


def or_oracle(rings, shape):
    m = np.zeros(shape, bool)
    for r in rings:
        m |= oracle_mask([r], shape, rule="nonzero")
    return m


def union_oracle(rings, shape):
    """Non-zero over the rings turned to positive (snapped) area."""
    turned = []
    for r in rings:
        (pts,) = snapped_rings([r], 8)
        area2 = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))
        turned.append(r[::-1] if area2 < 0 else r)
    return oracle_mask(turned, shape, rule="nonzero") if turned else np.zeros(shape, bool)


@given(st.lists(simple_polygon, min_size=0, max_size=4))
def test_masks_union_of_parts_equals_oracle(polys):
    m = rastrum.masks(polys, SHAPE)
    assert m.shape == (len(polys),) + SHAPE and m.dtype == bool
    for k, p in enumerate(polys):
        assert np.array_equal(m[k], or_oracle(p, SHAPE)), k


@given(st.lists(polygon, min_size=1, max_size=3))
def test_masks_union_rule_for_self_crossing_rings(polys):
    m = rastrum.masks(polys, SHAPE)
    for k, p in enumerate(polys):
        assert np.array_equal(m[k], union_oracle(p, SHAPE)), k


@given(st.lists(polygon, min_size=1, max_size=3), st.sampled_from(["evenodd", "nonzero"]),
       st.sampled_from(["aet", "xscan", "edgeflag"]))
def test_masks_rules_as_given(polys, rule, algorithm):
    m = rastrum.masks(polys, SHAPE, rule=rule, algorithm=algorithm)
    for k, p in enumerate(polys):
        assert np.array_equal(m[k], oracle_mask(p, SHAPE, rule=rule))


@given(st.lists(polygon, min_size=0, max_size=5), st.sampled_from([np.uint8, np.int32, np.float32, np.int64]))
def test_labels_later_on_top_and_overlap(polys, dtype):
    lab, count = rastrum.labels(polys, SHAPE, dtype=dtype, overlap=True)
    want = np.zeros(SHAPE, dtype)
    n = np.zeros(SHAPE, np.uint16)
    for k, p in enumerate(polys):
        m = union_oracle(p, SHAPE)
        want[m] = k + 1
        n += m
    assert lab.dtype == dtype and np.array_equal(lab, want)
    assert count.dtype == np.uint16 and np.array_equal(count, n)
    vals = np.arange(len(polys))[::-1] * 3 + 2
    assert np.array_equal(rastrum.labels(polys, SHAPE, values=vals, dtype=np.int16),
                          np.select([union_oracle(p, SHAPE) for p in polys[::-1]], vals[::-1], 0)
                          if polys else np.zeros(SHAPE, np.int16))


def test_inputs_users_have():
    sq = np.array([[2, 2], [12, 2], [12, 10], [2, 10]], float)
    want = oracle_mask([sq], SHAPE)
    contour = sq.astype(np.int32).reshape(-1, 1, 2)  # cv2.findContours' shape
    assert np.array_equal(rastrum.polygon_mask(contour, SHAPE), want)
    assert np.array_equal(rastrum.masks([contour, [contour]], SHAPE), np.stack([want, want]))
    shapely = pytest.importorskip("shapely.geometry")
    hole = [(4, 4), (4, 6), (6, 6), (6, 4)]
    poly = shapely.Polygon(sq, [hole])
    want_hole = want & ~oracle_mask([np.array(hole, float)], SHAPE)
    assert np.array_equal(rastrum.polygon_mask(poly, SHAPE), want_hole)
    assert np.array_equal(rastrum.masks([poly], SHAPE)[0], want_hole)
    multi = shapely.MultiPolygon([poly, shapely.Polygon(sq + 20)])
    assert np.array_equal(rastrum.masks([multi], SHAPE)[0], want_hole)
    geo = {"type": "Polygon", "coordinates": [sq.tolist()]}
    assert np.array_equal(rastrum.masks([geo], SHAPE)[0], want)


def test_short_rings_draw_nothing():
    """1- and 2-point rings draw nothing, as in C (and rasterio, cv2, skia);
    they used to raise."""
    for r in ([(1, 1)], [(1, 1), (5, 5)]):
        assert not rastrum.polygon_mask(r, SHAPE).any()
        assert not rastrum.masks([[np.array(r, float)]], SHAPE).any()
    sq = np.array([[2, 2], [12, 2], [12, 10]], float)
    assert np.array_equal(rastrum.polygon_mask([sq, [(1, 1), (3, 3)]], SHAPE), oracle_mask([sq], SHAPE))


def test_progress_reports_to_the_end():
    polys = [np.array([[0, 0], [5, 0], [5, 5]], float) + k % 7 for k in range(250)]
    seen = []
    m = rastrum.masks(polys, SHAPE, progress=lambda done, total: seen.append((done, total)))
    assert np.array_equal(m, rastrum.masks(polys, SHAPE))
    assert seen[-1] == (250, 250) and len(seen) > 10 and seen == sorted(seen)
    seen.clear()
    lab = rastrum.labels(polys, SHAPE, progress=lambda d, t: seen.append((d, t)))
    assert np.array_equal(lab, rastrum.labels(polys, SHAPE)) and seen[-1] == (250, 250)
    pytest.importorskip("tqdm")
    assert np.array_equal(rastrum.masks(polys, SHAPE, progress=True), m)


SQ = np.array([[0, 0], [4, 0], [4, 4]], float)
BAD = [
    ("masks flat COCO list", lambda: rastrum.masks([[1.0, 2, 3, 4, 5, 6]], SHAPE),
     r"polygon 0: rings: got a flat list of 6 numbers \(shape \(6,\)\).*\(N, 2\).*coco\.rings"),
    ("masks ring shape", lambda: rastrum.masks([[np.zeros((4, 3))]], SHAPE), r"polygon 0.*shape \(4, 3\).*\(N, 2\)"),
    ("masks NaN", lambda: rastrum.masks([SQ, SQ * np.nan], SHAPE), r"polygon 1.*NaN"),
    ("masks shape", lambda: rastrum.masks([SQ], (5,)), r"shape"),
    ("masks rule", lambda: rastrum.masks([SQ], SHAPE, rule="xor"), r"rule"),
    ("masks algorithm", lambda: rastrum.masks([SQ], SHAPE, algorithm="bogus"), r"algorithm"),
    ("masks subpixel", lambda: rastrum.masks([SQ], SHAPE, subpixel_bits=20), r"subpixel"),
    ("masks not a list", lambda: rastrum.masks(3, SHAPE), r"list of polygons"),
    ("masks one geometry", lambda: rastrum.masks({"type": "Polygon", "coordinates": [SQ.tolist()]}, SHAPE),
     r"one geometry"),
    ("masks point geometry", lambda: rastrum.masks([{"type": "Point", "coordinates": [1, 2]}], SHAPE), r"Point"),
    ("masks array ndim", lambda: rastrum.masks(np.zeros((3, 2)), SHAPE), r"\(N, K, 2\)"),
    ("masks complex", lambda: rastrum.masks([SQ * 1j], SHAPE), r"real"),
    ("labels dtype", lambda: rastrum.labels([SQ], SHAPE, dtype=bool), r"dtype"),
    ("labels dtype str", lambda: rastrum.labels([SQ], SHAPE, dtype="nonsense"), r"dtype"),
    ("labels values", lambda: rastrum.labels([SQ, SQ], SHAPE, values=[1]), r"values has shape \(1,\).*\(2,\)"),
    ("labels values str", lambda: rastrum.labels([SQ], SHAPE, values=["a"]), r"numbers"),
    ("labels range", lambda: rastrum.labels([SQ * 1e12], SHAPE), r"range"),
    ("polygon_mask flat list", lambda: rastrum.polygon_mask([1.0, 2, 3, 4, 5, 6], SHAPE), r"flat list"),
    ("polygon_mask contour shape", lambda: rastrum.polygon_mask(np.zeros((4, 2, 2)) + [[[0, 0], [1, 1]]], SHAPE)
     if False else rastrum.polygon_mask([np.zeros((4, 2, 2))], SHAPE), r"shape \(4, 2, 2\).*\(N, 1, 2\)"),
]


@pytest.mark.parametrize("name,call,problem", BAD, ids=[b[0] for b in BAD])
def test_bad_input(name, call, problem):
    with pytest.raises(rastrum.InputError, match=problem):
        call()


def test_progress_without_tqdm(monkeypatch):
    import builtins
    real = builtins.__import__

    def no_tqdm(name, *a, **k):
        if name.startswith("tqdm"):
            raise ImportError(name)
        return real(name, *a, **k)
    monkeypatch.setattr(builtins, "__import__", no_tqdm)
    with pytest.raises(rastrum.InputError, match="tqdm"):
        rastrum.masks([SQ], SHAPE, progress=True)


def _general(polys):
    """The same polygons in a form the packed fast path does not take (one
    Python list of (x, y) tuples per ring): the general, per-polygon path."""
    return [[[tuple(map(float, p)) for p in r] for r in poly] for poly in polys]


@given(st.lists(polygon, min_size=1, max_size=5), st.sampled_from(["union", "evenodd", "nonzero"]))
def test_packed_fast_path_equals_general_path_and_oracle(polys, rule):
    """masks/labels pack a batch of float64 arrays (or lists of them, as
    coco.rings makes them) with a few C-level passes; other inputs go
    polygon by polygon.  Both give the oracle's pixels."""
    polys = [[r for r in p] for p in polys]
    assert ml._packed(polys) is not None and ml._packed(_general(polys)) is None  # both paths run
    fast = rastrum.masks(polys, SHAPE, rule=rule)
    assert np.array_equal(fast, rastrum.masks(_general(polys), SHAPE, rule=rule))
    for k, p in enumerate(polys):
        want = union_oracle(p, SHAPE) if rule == "union" else oracle_mask(p, SHAPE, rule=rule)
        assert np.array_equal(fast[k], want)
    one_ring = [p[0] for p in polys]  # a list of (N, 2) arrays: one ring each
    assert np.array_equal(rastrum.masks(one_ring, SHAPE, rule=rule),
                          rastrum.masks([[r] for r in one_ring], SHAPE, rule=rule))
    assert np.array_equal(rastrum.labels(one_ring, SHAPE, rule=rule),
                          rastrum.labels(_general([[r] for r in one_ring]), SHAPE, rule=rule))


def test_packed_fast_path_leaves_other_arrays_to_the_general_path():
    """Only float64 (N, 2) rings are packed directly: other dtypes convert
    exactly or are refused by the general path, contours are reshaped,
    empty rings dropped, and an error names the polygon's index in the
    whole batch (also when progress draws it in chunks)."""
    sq = np.array([[2, 2], [12, 2], [12, 10], [2, 10]], float)
    want = oracle_mask([sq], SHAPE)
    for ring in (sq.astype(np.float32), sq.astype(np.int64), sq.astype(">f8"), sq.reshape(-1, 1, 2),
                 np.asfortranarray(sq), sq[::-1][::-1]):
        assert np.array_equal(rastrum.masks([sq, ring], SHAPE), np.stack([want, want]))
        assert np.array_equal(rastrum.masks([[sq], [ring, np.zeros((0, 2))]], SHAPE), np.stack([want, want]))
    with pytest.raises(rastrum.InputError, match=r"polygon 1: .*bool"):
        rastrum.masks([sq, sq.astype(bool)], SHAPE)
    polys = [sq] * 250 + [sq * np.nan]
    for progress in (False, lambda done, total: None):
        with pytest.raises(rastrum.InputError, match=r"polygon 250: ring 0, point 0 .*NaN"):
            rastrum.masks(polys, SHAPE, progress=progress)

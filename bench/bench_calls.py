"""The cost of a Python call: small polygons one call each, and many rings in one.

    python bench/bench_calls.py [--reps 9] [--calls 2000]

Three cases (issue 33), each against OpenCV doing the same:

1. ``rastrum.polygon_mask`` of one 6-gon (a float64 (6, 2) array) into a
   new 32 x 32 mask, against a cv2.fillPoly loop that makes the mask and
   converts the float vertices to int32 in the loop, as its users write it;
2. ``Canvas.fill_polygon`` in a loop, from an (N, 2) float64 array and
   from a list of (x, y) tuples, with no keyword, with ``rule="nonzero"``
   and with ``aa=`` (the calls of bench/families.py's "loop" family: one
   C call each, rastrum._seq.fill), against cv2.fillPoly of int32
   vertices converted beforehand;
3. a list of 1,409 small ring arrays (a paragraph's worth) in one
   ``polygon_mask`` call: the whole call, and the Python work before the C
   call (``_core._points``), against cv2.fillPoly of the same rings.

Each figure is the median over --reps batches of --calls calls, in
microseconds a call, the methods interleaved batch by batch.  Outputs are
checked in the same run: every quick path's pixels equal the general
path's (the same call through input the quick path does not take: a
non-contiguous copy), and cv2's pixels off rastrum's exact mask are
reported (cv2 takes every pixel its outline touches, so some differ).
Wall-clock timings on a shared machine are noisy: compare ratios within
one run.
"""

import argparse
import time

import numpy as np

import rastrum
from rastrum import _core

HEXA = np.array([[10.3, 5.2], [20.1, 8.7], [22.4, 18.2], [14.2, 24.9], [6.1, 19.3], [4.4, 11.1]])
SHAPE = (32, 32)


def _rings(n=1409, seed=7):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        m = int(rng.integers(8, 40))
        t = np.sort(rng.uniform(0, 2 * np.pi, m))
        r = rng.uniform(3, 9)
        c = rng.uniform(10, 500, 2)
        out.append(np.ascontiguousarray(np.stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)], 1)))
    return out


def _slow(a):
    """The same points through the general path: a non-contiguous view."""
    b = np.empty((len(a), 4))
    b[:, ::2] = a
    return b[:, ::2]


def measure(cases, reps, calls):
    ts = {k: [] for k in cases}
    for f in cases.values():
        for _ in range(50):
            f()
    for _ in range(reps):
        for k, f in cases.items():
            n = calls if not k.startswith("3") else max(1, calls // 200)
            t = time.perf_counter()
            for _ in range(n):
                f()
            ts[k].append((time.perf_counter() - t) / n * 1e6)
    return {k: sorted(v)[len(v) // 2] for k, v in ts.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reps", type=int, default=9)
    ap.add_argument("--calls", type=int, default=2000)
    args = ap.parse_args()
    import cv2

    hexa_tuples = [tuple(p) for p in HEXA.tolist()]
    hexa32 = np.round(HEXA - 0.5).astype(np.int32)
    rings = _rings()
    rings32 = [np.round(r - 0.5).astype(np.int32) for r in rings]
    canvas = rastrum.Canvas.wrap(np.zeros((512, 512), np.uint8))
    img = np.zeros((512, 512), np.uint8)

    def cv2_mask():
        m = np.zeros(SHAPE, np.uint8)
        cv2.fillPoly(m, [np.round(HEXA - 0.5).astype(np.int32)], 1)
        return m

    # -- outputs checked --------------------------------------------------------
    exact = rastrum.polygon_mask(_slow(HEXA), SHAPE)
    assert np.array_equal(rastrum.polygon_mask(HEXA, SHAPE), exact), "polygon_mask quick path differs"
    assert np.array_equal(rastrum.polygon_mask(hexa_tuples, SHAPE), exact)
    for src in (HEXA, hexa_tuples):
        a = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
        b = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
        a.fill_polygon(np.zeros((3, 2)), 255)  # remembered: the next call is one C call (_seq.fill)
        a.fill_polygon(src, 255)
        b.fill_polygon(_slow(HEXA), 255)
        assert np.array_equal(a.array, b.array), "Canvas.fill_polygon quick path differs"
    for kw in ({"rule": "nonzero"}, {"rule": "nonzero", "aa": "area"}, {"aa": "accumulate"}, {"aa": "ss4"}):
        a = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
        b = rastrum.Canvas.wrap(np.zeros(SHAPE, np.uint8))
        a.fill_polygon(np.zeros((3, 2)), 255, **kw)  # remembered: the next call is one C call
        a.fill_polygon(HEXA, 255, **kw)
        b.fill_polygon(_slow(HEXA), 255, **kw)
        assert np.array_equal(a.array, b.array), "Canvas.fill_polygon(%s) quick path differs" % kw
    many = rastrum.polygon_mask(rings, (512, 512))
    assert np.array_equal(many, rastrum.polygon_mask([_slow(r) for r in rings], (512, 512)))
    off1 = int((cv2_mask().astype(bool) != exact).sum())
    cvm = np.zeros((512, 512), np.uint8)
    cv2.fillPoly(cvm, rings32, 1)
    off3 = int((cvm.astype(bool) != many).sum())
    print("outputs: rastrum's quick paths equal its general path; cv2 pixels off the exact mask: "
          "6-gon %d of %d, 1,409 rings %d of %d" % (off1, SHAPE[0] * SHAPE[1], off3, 512 * 512))

    cases = {
        "1 polygon_mask 6-gon": lambda: rastrum.polygon_mask(HEXA, SHAPE),
        "1 cv2 loop (zeros, float->int32, fillPoly)": cv2_mask,
        "2 Canvas.fill_polygon (6, 2) array": lambda: canvas.fill_polygon(HEXA, 255),
        "2 Canvas.fill_polygon list of tuples": lambda: canvas.fill_polygon(hexa_tuples, 255),
        "2 Canvas.fill_polygon (6, 2) array, rule nonzero": lambda: canvas.fill_polygon(HEXA, 255, rule="nonzero"),
        "2 Canvas.fill_polygon (6, 2) array, aa accumulate": lambda: canvas.fill_polygon(HEXA, 255, aa="accumulate"),
        "2 Canvas.fill_polygon (6, 2) array, aa ss4": lambda: canvas.fill_polygon(HEXA, 255, aa="ss4"),
        "2 Canvas.fill_polygon (6, 2) array, aa area": lambda: canvas.fill_polygon(HEXA, 255, aa="area"),
        "2 cv2.fillPoly int32 (converted before)": lambda: cv2.fillPoly(img, [hexa32], 255),
        "2 cv2.fillPoly with float->int32 in the loop": lambda: cv2.fillPoly(
            img, [np.round(HEXA - 0.5).astype(np.int32)], 255),
        "3 polygon_mask 1,409 rings": lambda: rastrum.polygon_mask(rings, (512, 512)),
        "3 ... its Python before C (_core._points)": lambda: _core._points(rings),
        "3 cv2.fillPoly 1,409 int32 rings": lambda: cv2.fillPoly(img, rings32, 255),
    }
    med = measure(cases, args.reps, args.calls)
    print("\n| case | us a call (median of %d) | / cv2 |" % args.reps)
    print("|---|---|---|")
    peer = {"1": med["1 cv2 loop (zeros, float->int32, fillPoly)"],
            "2": med["2 cv2.fillPoly int32 (converted before)"],
            "3": med["3 cv2.fillPoly 1,409 int32 rings"]}
    for k, v in med.items():
        print("| %s | %.2f | %.2f |" % (k[2:], v, v / peer[k[0]]))


if __name__ == "__main__":
    main()

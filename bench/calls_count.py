"""Instructions a call (callgrind) for the small calls of bench_calls.py.

    python bench/calls_count.py [CASE ...] [--calls 500]

Each case runs under ``valgrind --tool=callgrind``, counting only inside
the loop of --calls calls (``--toggle-collect=functools_reduce``: the
set-up and the imports are not counted); the count over --calls is the
figure, repeatable on a noisy machine where wall-clock times are not.
"""

import argparse
import functools
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HEXA = np.array([[10.3, 5.2], [20.1, 8.7], [22.4, 18.2], [14.2, 24.9], [6.1, 19.3], [4.4, 11.1]])
HEXA32 = np.round(HEXA).astype(np.int32)
PATH = None  # made in cases(): rastrum.Path needs the package


def _path():
    import rastrum
    return rastrum.Path().move_to(10.3, 5.2).quad_to(30.0, 2.0, 22.4, 18.2).line_to(6.1, 19.3).close()


TRIS = np.array([[HEXA[0], HEXA[1], HEXA[2]], [HEXA[0], HEXA[2], HEXA[4]]])


def cases():
    import rastrum
    global PATH
    PATH = _path()
    from rastrum import _core
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import families
    from bench_calls import _rings
    tup = [tuple(p) for p in HEXA.tolist()]
    canvas = rastrum.Canvas.wrap(np.zeros((512, 512), np.uint8))
    rings = _rings()
    loop = families.loop(0, 512).rings
    boxed = rastrum.Canvas.wrap(np.zeros((512, 512), np.uint8))  # a 31 x 31 region inside an outline
    boxed.polyline([(10, 10), (40, 10), (40, 40), (10, 40)], 9, closed=True, subpixel_bits=0, sample_offset=0)
    out = {
        "mask6": lambda: rastrum.polygon_mask(HEXA, (32, 32)),
        "mask6_int32": lambda: rastrum.polygon_mask(HEXA32, (32, 32)),
        "cov6": lambda: rastrum.polygon_coverage(HEXA, (32, 32)),
        "fill_array": lambda: canvas.fill_polygon(HEXA, 255),
        "fill_tuples": lambda: canvas.fill_polygon(tup, 255),
        "fill_nonzero": lambda: canvas.fill_polygon(HEXA, 255, rule="nonzero"),
        "fill_opacity": lambda: canvas.fill_polygon(HEXA, 255, opacity=0.5),
        "fill_opacity_area": lambda: canvas.fill_polygon(HEXA, 255, opacity=0.5, aa="area"),
        "fill_opacity_accumulate": lambda: canvas.fill_polygon(HEXA, 255, opacity=0.5, aa="accumulate"),
        "fill_opacity_ss4": lambda: canvas.fill_polygon(HEXA, 255, opacity=0.5, aa="ss4"),
        "tris_opacity": lambda: canvas.fill_triangles(TRIS, 255, opacity=0.5),
        "tris_opacity_area": lambda: canvas.fill_triangles(TRIS, 255, opacity=0.5, aa="area"),
        # the translucent entries that blended the whole canvas before opa34e (issue 34)
        "path_opacity": lambda: canvas.fill_polygon(PATH, 255, opacity=0.5),
        "path_opacity_area": lambda: canvas.fill_polygon(PATH, 255, opacity=0.5, aa="area"),
        "int32_opacity": lambda: canvas.fill_polygon(HEXA32, 255, opacity=0.5),
        "int32_opacity_area": lambda: canvas.fill_polygon(HEXA32, 255, opacity=0.5, aa="area"),
        "tuples_opacity": lambda: canvas.fill_polygon(tuple(tup), 255, opacity=0.5),
        "s20_opacity": lambda: canvas.fill_polygon(HEXA, 255, opacity=0.5, subpixel_bits=20),
        "line_opacity": lambda: canvas.line((3.2, 4.1), (40.5, 30.7), 255, opacity=0.5),
        "polyline_opacity": lambda: canvas.polyline(HEXA, 255, closed=True, opacity=0.5),
        "stroke_alpha": lambda: canvas.stroke(HEXA, (255, 128), 2.0),
        "flood_opacity": lambda: boxed.flood_fill((20, 20), 255, opacity=0.5),
        "loop_binary": lambda: [canvas.fill_polygon(r, 255, rule="nonzero") for r in loop],
        "loop_accumulate": lambda: [canvas.fill_polygon(r, 255, rule="nonzero", aa="accumulate") for r in loop],
        "loop_ss4": lambda: [canvas.fill_polygon(r, 255, rule="nonzero", aa="ss4") for r in loop],
        "loop_area": lambda: [canvas.fill_polygon(r, 255, rule="nonzero", aa="area") for r in loop],
        "fill_area": lambda: canvas.fill_polygon(HEXA, 255, aa="area"),
        "rings1409_mask": lambda: rastrum.polygon_mask(rings, (512, 512)),
        "rings1409_points": lambda: _core._points(rings),
        "rings1409_cov": lambda: rastrum.polygon_coverage(rings, (512, 512)),
    }
    try:
        import cv2
    except ImportError:  # the peers' cases only where OpenCV is installed
        return out
    hexa32 = np.round(HEXA - 0.5).astype(np.int32)
    img = np.zeros((512, 512), np.uint8)
    rings32 = [np.round(r - 0.5).astype(np.int32) for r in rings]

    def cv2_mask6():
        m = np.zeros((32, 32), np.uint8)
        cv2.fillPoly(m, [np.round(HEXA - 0.5).astype(np.int32)], 1)
        return m
    out.update({
        "cv2_mask6": cv2_mask6,  # as bench_calls.py's loop: the float->int32 conversion inside
        "cv2_fill_int32": lambda: cv2.fillPoly(img, [hexa32], 255),
        "cv2_rings1409": lambda: cv2.fillPoly(img, rings32, 255),
    })
    return out


PER = {"loop_binary": 400, "loop_accumulate": 400, "loop_ss4": 400, "loop_area": 400}


def child(name, calls):
    f = cases()[name]
    for _ in range(3):
        f()
    # the calls inside functools.reduce: `valgrind --tool=callgrind
    # --toggle-collect=functools_reduce` profiles them and nothing else
    functools.reduce(lambda a, _: f(), range(calls), None)


def count(name, calls):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=functools_reduce",
                        "--callgrind-out-file=" + out, sys.executable,
                        os.path.abspath(__file__), "--child", name, "--calls", str(calls)],
                       check=True, stderr=subprocess.DEVNULL, stdout=subprocess.DEVNULL)
        with open(out) as fh:
            return int(re.search(r"^(?:summary|totals): (\d+)", fh.read(), re.M).group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", nargs="*")
    ap.add_argument("--calls", type=int, default=300)
    ap.add_argument("--child")
    args = ap.parse_args()
    if args.child:
        child(args.child, args.calls)
        return
    names = args.case or list(cases())
    print("| case | instructions a call (callgrind, %d calls) |" % args.calls)
    print("|---|---|")
    for name in names:
        n = args.calls // 20 if name in PER else args.calls
        per = count(name, n) / n / PER.get(name, 1)
        print("| %s | %.0f |" % (name, per), flush=True)


if __name__ == "__main__":
    main()

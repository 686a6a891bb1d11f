"""rastrum benchmark: time and exactness of polygon masks, against peers.

One run prints, for every scene (bench/scenes.py), fill rule and algorithm
in ``rastrum.ALGORITHMS["polygon_mask"]``:

- the median time of one call (of the whole batch for batch scenes), taken
  over many interleaved repeats;
- the ratio to a memset of the same number of bytes (the physical limit of a
  fill) and to OpenCV ``cv2.fillPoly`` doing the same work;
- the number of pixels that differ from the exact result on the UNSNAPPED
  float input (tests/oracle.py, rational arithmetic), and for rastrum also
  from the exact result on the snapped input (0 = bit-exact).

Peers (optional extras, skipped with a note when missing): OpenCV, Pillow,
scikit-image, rasterio, pycocotools, skia-python.

Run ``python bench/bench.py [--quick] [--scenes NAME ...]``; the table goes
to stdout, progress to stderr, all numbers to bench/results.json.
"""

from __future__ import annotations

import argparse
import ctypes
import functools
import gc
import importlib.util
import json
import os
import platform
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Tuple

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import scenes as scenes_mod  # noqa: E402

RULES = ("evenodd", "nonzero")
DEFAULT_S = 8
TRADE_S = (0, 2, 4, 8)


# ---------------------------------------------------------------------------
# imports
# ---------------------------------------------------------------------------

def import_rastrum():
    try:
        import rastrum
    except ImportError:
        sys.path.insert(0, str(ROOT / "python"))
        import rastrum
    return rastrum


def load_oracle():
    """tests/oracle.py, imported by path (it is not part of the package)."""
    path = ROOT / "tests" / "oracle.py"
    if not path.exists():
        return None
    spec = importlib.util.spec_from_file_location("_rastrum_bench_oracle",
                                                  path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# ---------------------------------------------------------------------------
# progress on stderr
# ---------------------------------------------------------------------------

class Progress:
    def __init__(self, enabled: bool = True):
        self.enabled = enabled
        self.tty = sys.stderr.isatty()
        self._last = 0.0
        self._dirty = False

    def __call__(self, msg: str, force: bool = False):
        if not self.enabled:
            return
        now = time.monotonic()
        if self.tty:
            if force or now - self._last > 0.1:
                sys.stderr.write("\r\x1b[K" + msg)
                sys.stderr.flush()
                self._last = now
                self._dirty = True
        elif force or now - self._last > 5.0:
            sys.stderr.write(msg + "\n")
            sys.stderr.flush()
            self._last = now

    def done(self):
        if self.enabled and self.tty and self._dirty:
            sys.stderr.write("\r\x1b[K")
            sys.stderr.flush()
            self._dirty = False


# ---------------------------------------------------------------------------
# exact references (cached per run)
# ---------------------------------------------------------------------------

class References:
    """oracle_mask results, computed once per (scene, rule, offset, S)."""

    def __init__(self, oracle, progress: Progress):
        self.oracle = oracle
        self.progress = progress
        self.cache: Dict[tuple, List[np.ndarray]] = {}

    def get(self, scene, rule: str, offset: float,
            subpixel_bits: Optional[int] = None) -> Optional[List[np.ndarray]]:
        if self.oracle is None:
            return None
        key = (scene.name, rule, offset, subpixel_bits)
        if key not in self.cache:
            polys, shape = scene.load()
            out = []
            for k, rings in enumerate(polys):
                self.progress(f"  exact reference {scene.name} {rule} "
                              f"o={offset:g} S={subpixel_bits} "
                              f"[{k + 1}/{len(polys)}]")
                out.append(self.oracle.oracle_mask(
                    rings, shape, rule=rule, subpixel_bits=subpixel_bits,
                    sample_offset=offset))
            self.cache[key] = out
        return self.cache[key]


def count_diff(masks: List[np.ndarray], refs: Optional[List[np.ndarray]]):
    if refs is None or masks is None:
        return None
    return int(sum(np.count_nonzero(np.asarray(m).astype(bool) != r)
                   for m, r in zip(masks, refs)))


# ---------------------------------------------------------------------------
# peers: prepared input outside the timing, fresh (H, W) mask out inside it
# ---------------------------------------------------------------------------

def keyhole(rings) -> np.ndarray:
    """Join rings into one ring by zero-width bridges: the outer ring r0,
    then for each further ring ri: r0[0] -> ri[0], round ri back to ri[0],
    and back to r0[0]. Each bridge is run through twice, once each way, so
    its crossings cancel under both rules: this is how peers that take one
    ring per polygon get the holes. Their outline drawing (if any) still
    draws the bridges; that shows in their pixel error."""
    if len(rings) == 1:
        return rings[0]
    parts = [rings[0], rings[0][:1]]
    for r in rings[1:]:
        parts += [r, r[:1], rings[0][:1]]
    return np.ascontiguousarray(np.concatenate(parts))


@dataclass
class Peer:
    """make(rings, shape, rule) prepares the peer's best input form (not
    timed) and returns a callable that produces one fresh (H, W) mask (timed);
    every global lookup is bound in advance, as for rastrum."""
    name: str
    module: str                      # import to test availability
    rules: Tuple[str, ...]
    make: Callable
    note: str = ""


def _cv2_make(rings, shape, rule):
    import cv2
    # OpenCV's best input form: int32 points with 8 fractional bits.
    pts = [np.round(r * 256.0).astype(np.int32).reshape(-1, 1, 2)
           for r in rings]

    def run(zeros=np.zeros, u8=np.uint8, fill=cv2.fillPoly,
            lt=cv2.LINE_8):
        img = zeros(shape, u8)
        fill(img, pts, 1, lt, 8)
        return img
    return run


def _pil_make(rings, shape, rule):
    from PIL import Image, ImageDraw
    xy = keyhole(rings).ravel().tolist()
    size = (shape[1], shape[0])

    def run(new=Image.new, draw=ImageDraw.Draw):
        im = new("L", size, 0)
        draw(im).polygon(xy, fill=1)
        return im      # no numpy conversion timed (in Pillow's favour)
    return run


def _skimage_make(rings, shape, rule):
    from skimage.draw import polygon
    k = keyhole(rings)
    r, c = np.ascontiguousarray(k[:, 1]), np.ascontiguousarray(k[:, 0])

    def run(zeros=np.zeros, u8=np.uint8):
        img = zeros(shape, u8)
        rr, cc = polygon(r, c, shape)
        img[rr, cc] = 1
        return img
    return run


def _rasterio_make(rings, shape, rule):
    import affine
    from rasterio.features import rasterize
    shapes = [({"type": "Polygon", "coordinates": [r.tolist()
                                                   for r in rings]}, 1)]
    tr = affine.Affine.identity()

    def run():
        return rasterize(shapes, out_shape=shape, transform=tr, fill=0,
                         dtype=np.uint8)
    return run


def _coco_make(rings, shape, rule):
    from pycocotools import mask as cm
    poly = [keyhole(rings).ravel().tolist()]
    h, w = shape

    def run(fr=cm.frPyObjects, dec=cm.decode):
        return dec(fr(poly, h, w))[:, :, 0]
    return run


def _skia_make(rings, shape, rule):
    import skia
    path = skia.Path()
    for r in rings:
        path.moveTo(float(r[0, 0]), float(r[0, 1]))
        for x, y in r[1:].tolist():
            path.lineTo(x, y)
        path.close()
    path.setFillType(skia.PathFillType.kEvenOdd if rule == "evenodd"
                     else skia.PathFillType.kWinding)
    paint = skia.Paint(AntiAlias=False, Color=skia.ColorBLACK)
    ct = skia.kAlpha_8_ColorType

    def run(zeros=np.zeros, u8=np.uint8, canvas=skia.Canvas):
        img = zeros(shape, u8)
        canvas(img, colorType=ct).drawPath(path, paint)
        return img
    return run


PEERS = [
    Peer("cv2.fillPoly", "cv2", ("evenodd",), _cv2_make,
         "int32 points, shift=8, LINE_8; np.zeros + fillPoly"),
    Peer("PIL.ImageDraw", "PIL", ("evenodd",), _pil_make,
         "Image.new('L') + polygon; holes by keyhole bridges"),
    Peer("skimage.draw", "skimage", ("evenodd",), _skimage_make,
         "np.zeros + draw.polygon + index; keyhole"),
    Peer("rasterio", "rasterio", ("evenodd",), _rasterio_make,
         "features.rasterize, identity transform, uint8"),
    Peer("pycocotools", "pycocotools", ("evenodd",), _coco_make,
         "frPyObjects + decode; keyhole"),
    Peer("skia", "skia", ("evenodd", "nonzero"), _skia_make,
         "np.zeros + Canvas(Alpha8) + drawPath, no AA"),
]


def peer_available(p: Peer) -> Optional[str]:
    """None if importable, else the reason."""
    try:
        __import__(p.module)
        if p.name == "rasterio":
            __import__("affine")
    except Exception as e:  # ImportError, or a broken binary wheel
        return f"{type(e).__name__}: {e}"
    return None


# ---------------------------------------------------------------------------
# timing
# ---------------------------------------------------------------------------

@dataclass
class Cand:
    """One timed thing: fn() does the whole scene (all its masks)."""
    label: str
    fn: Callable[[], Any]
    info: Dict[str, Any]
    number: int = 1
    repeats: int = 1
    times: List[float] = field(default_factory=list)
    error: Optional[str] = None

    def stats(self):
        t = sorted(self.times)
        med = statistics.median(t)
        if len(t) >= 4:
            q = statistics.quantiles(t, n=4)
            iqr = (q[2] - q[0]) / med if med > 0 else 0.0
        else:
            iqr = None
        return med, iqr


def _time_block(fn, number):
    t0 = time.perf_counter()
    for _ in range(number):
        fn()
    return (time.perf_counter() - t0) / number


def calibrate(c: Cand, first: float, target: float, repeats: int,
              budget: float):
    """Choose calls per repeat (a repeat lasts about `target` seconds) and
    the number of repeats (fewer, at least 1, for candidates so slow that
    `repeats` repeats would exceed `budget` seconds). `first` is the time of
    the first (untimed) call; a candidate slower than `budget` keeps that
    one call as its only measurement."""
    if first >= budget:
        c.number, c.repeats, c.times = 1, 1, [first]
        return
    if first * 5 >= target:
        per = _time_block(c.fn, 1)
    else:
        n = 1
        while True:
            per = _time_block(c.fn, n)
            if per * n >= target / 5:
                break
            n = max(n + 1, int(target / 5 / max(per, 1e-9)) + 1)
    c.number = max(1, int(round(target / max(per, 1e-9))))
    c.repeats = repeats
    if per * c.number * repeats > budget:
        c.number = 1
        c.repeats = max(1, min(repeats, int(budget / max(per, 1e-9))))


def measure(cands: List[Cand], progress: Progress, title: str):
    """Interleaved repeats: round r times every candidate once (in a rotated
    order), so a burst of machine noise hits all candidates alike."""
    live = [c for c in cands if c.error is None]
    rounds = max((c.repeats for c in live), default=0)
    gc.collect()
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for r in range(rounds):
            progress(f"  {title}: timing round {r + 1}/{rounds}")
            k = r % len(live)
            for c in live[k:] + live[:k]:
                if len(c.times) < c.repeats:
                    c.times.append(_time_block(c.fn, c.number))
    finally:
        if gc_was:
            gc.enable()


# ---------------------------------------------------------------------------
# the benchmark
# ---------------------------------------------------------------------------

def _fmt_ms(t):
    ms = t * 1e3
    if ms >= 100:
        return f"{ms:9.1f}"
    if ms >= 1:
        return f"{ms:9.3f}"
    return f"{ms:9.4f}"


def _fmt_ratio(x):
    if x is None:
        return "     -"
    if x >= 100:
        return f"{x:6.0f}"
    return f"{x:6.2f}"


def _fmt_int(x, w):
    return f"{'-' if x is None else x:>{w}}"


def _fmt_o(o):
    return {0.0: "0", 0.5: "1/2", None: "-"}.get(o, f"{o:g}")


def _scene_callable(fns: List[Callable]) -> Callable:
    """One callable doing the whole scene: the mask function itself for a
    one-mask scene (no wrapper), a loop over all of them for a batch."""
    if len(fns) == 1:
        return fns[0]

    def batch(fns=fns):
        for f in fns:
            f()
    return batch


def scratch_bytes(rastrum, alg, rule, s, o, polys, shape):
    """The scratch a caller allocates for the scene: the largest
    rast_scratch_size over its calls (the clip is the whole mask)."""
    from rastrum import _core
    from rastrum._native import ffi, lib
    opts = _core.fill_opts(alg, rule, s, o)
    out = ffi.new("size_t *")
    best = 0
    for rings in polys:
        n = sum(len(r) for r in rings)
        if lib.rast_scratch_size(opts, n, shape[1], shape[0], out) != lib.RAST_OK:
            return None
        best = max(best, int(out[0]))
    return best


def run_scene(scene, rastrum, refs: References, peers, args, progress,
              trade: bool):
    polys, shape = scene.load()
    h, w = shape
    nbytes = h * w
    canvas = getattr(scene, "canvas", False)
    # a canvas scene draws all its polygons into one buffer: one memset
    nmask = 1 if canvas else len(polys)
    algos = rastrum.ALGORITHMS["polygon_mask"]
    cands: List[Cand] = []
    makers: Dict[int, List[Callable]] = {}     # id(cand) -> per-mask fns

    # physical limit: ctypes.memset on a preallocated, already touched
    # buffer of H*W bytes (once per mask of the scene)
    buf = np.ones(nbytes, np.uint8)
    addr = buf.ctypes.data
    memset = ctypes.memset
    cands.append(Cand("memset", _scene_callable(
        [functools.partial(memset, addr, 1, nbytes)] * nmask),
        dict(kind="baseline", impl="memset", rule=None)))
    if not canvas:
        cands.append(Cand("np.ones", _scene_callable(
            [functools.partial(np.ones, shape, bool)] * nmask),
            dict(kind="baseline", impl="np.ones", rule=None)))

    # rastrum: the natural input, a list of C-contiguous float64 (N, 2)
    # arrays, as the scenes make them.  The summary table: every algorithm
    # and rule at S = 8, o = 1/2; --detail: both offsets, and the S trade.
    combos = []
    for alg, alg_rules in algos.items():
        for rule in RULES:
            if rule not in alg_rules:
                continue
            for o in ((0.0, 0.5) if args.detail else (0.5,)):
                combos.append((alg, rule, DEFAULT_S, o))
        if args.detail and trade and "evenodd" in alg_rules:
            for s in TRADE_S:
                if s != DEFAULT_S:
                    combos.append((alg, "evenodd", s, 0.5))
    for alg, rule, s, o in combos:
        info = dict(kind="rastrum", impl=f"rastrum/{alg}", algorithm=alg,
                    rule=rule, S=s, o=o, mode="into" if canvas else "new",
                    scratch=scratch_bytes(rastrum, alg, rule, s, o, polys,
                                          shape))
        if canvas:
            # every polygon by its own call into one gray8 canvas
            cv = rastrum.Canvas((h, w), format="gray8", background=0)
            fns = [functools.partial(cv.fill_polygon, rings, 1, rule=rule,
                                     algorithm=alg, subpixel_bits=s,
                                     sample_offset=o) for rings in polys]
            c = Cand(f"rastrum/{alg}", _scene_callable(fns), info)
            makers[id(c)] = [lambda fns=fns, a=cv.array:
                             ([f() for f in fns], a)[1]]
        else:
            fns = [functools.partial(rastrum.polygon_mask, rings, shape,
                                     rule=rule, algorithm=alg,
                                     subpixel_bits=s, sample_offset=o)
                   for rings in polys]
            c = Cand(f"rastrum/{alg}", _scene_callable(fns), info)
            makers[id(c)] = fns
        cands.append(c)

    # peers
    for p in peers:
        if canvas:
            break                      # cv2 alone, below
        for rule in p.rules:
            fns, err = None, None
            try:
                fns = [p.make(rings, shape, rule) for rings in polys]
            except Exception as e:
                err = f"prepare: {type(e).__name__}: {e}"
            c = Cand(p.name, _scene_callable(fns) if fns else None,
                     dict(kind="peer", impl=p.name, rule=rule, note=p.note,
                          mode="new"),
                     error=err)
            if fns:
                makers[id(c)] = fns
            cands.append(c)

    # "into": paint into a preallocated, zeroed buffer (one per mask, made
    # outside the timing): Canvas(gray8).fill_polygon against cv2.fillPoly
    # without its np.zeros. Same work again, minus the fresh mask.  A
    # canvas scene is only this, all polygons into one buffer.
    if any(p.name == "cv2.fillPoly" for p in peers) and (canvas or
                                                         args.detail):
        import cv2
        fns, arrs = [], []
        img = np.zeros(shape, np.uint8) if canvas else None
        for rings in polys:
            pts = [np.round(r * 256.0).astype(np.int32).reshape(-1, 1, 2)
                   for r in rings]
            if not canvas:
                img = np.zeros(shape, np.uint8)
            fns.append(functools.partial(cv2.fillPoly, img, pts, 1,
                                         cv2.LINE_8, 8))
            arrs.append(img)
        c = Cand("cv2.fillPoly into" if not canvas else "cv2.fillPoly",
                 _scene_callable(fns),
                 dict(kind="peer", impl="cv2.fillPoly", rule="evenodd",
                      mode="into", note="fillPoly into a zeroed buffer"))
        if canvas:
            makers[id(c)] = [lambda fns=fns, a=img:
                             ([f() for f in fns], a)[1]]
        else:
            makers[id(c)] = [lambda f=f, a=a: (f(), a)[1]
                             for f, a in zip(fns, arrs)]
        cands.append(c)
    if (any(p.name == "cv2.fillPoly" for p in peers) and args.detail
            and not canvas):
        for alg, alg_rules in rastrum.ALGORITHMS.get(
                "Canvas.fill_polygon", {}).items():
            if "evenodd" not in alg_rules:
                continue
            fns, arrs = [], []
            for rings in polys:
                cv = rastrum.Canvas((h, w), format="gray8", background=0)
                fns.append(functools.partial(
                    cv.fill_polygon, rings, 1, rule="evenodd",
                    algorithm=alg, subpixel_bits=DEFAULT_S,
                    sample_offset=0.0))
                arrs.append(cv.array)
            c = Cand(f"rastrum/{alg} into", _scene_callable(fns),
                     dict(kind="rastrum", impl=f"rastrum/{alg}",
                          algorithm=alg, rule="evenodd", S=DEFAULT_S, o=0.0,
                          mode="into"))
            makers[id(c)] = [lambda f=f, a=a: (f(), a)[1]
                             for f, a in zip(fns, arrs)]
            cands.append(c)

    # one untimed pass each: the masks for the accuracy columns, a warm-up,
    # and a first estimate of the time per call
    results = {}
    for i, c in enumerate(cands):
        if c.error:
            continue
        progress(f"  {scene.name}: first call {c.label} "
                 f"[{i + 1}/{len(cands)}]")
        try:
            t0 = time.perf_counter()
            if id(c) in makers:
                results[id(c)] = [np.asarray(f()) for f in makers[id(c)]]
            else:
                c.fn()
            first = time.perf_counter() - t0
            calibrate(c, first, args.target, args.repeats,
                      args.budget if c.info["kind"] == "peer"
                      else 10 * args.budget)
        except Exception as e:
            c.error = f"{type(e).__name__}: {e}"

    measure(cands, progress, scene.name)

    # accuracy
    rows = []
    memset_t = cands[0].stats()[0]
    cv2_t = None
    cv2_by_mode = {}
    for c in cands:
        if c.info["impl"] == "cv2.fillPoly" and c.times:
            cv2_by_mode[c.info["mode"]] = c
    for c in cands:
        row = dict(scene=scene.name, label=c.label, **c.info)
        cv2_c = cv2_by_mode.get(c.info.get("mode"))
        cv2_t = cv2_c.stats()[0] if cv2_c is not None else None
        if c.error or not c.times:
            row["error"] = c.error or "not timed"
            rows.append(row)
            continue
        med, iqr = c.stats()
        row.update(ms=med * 1e3, iqr=iqr, repeats=len(c.times),
                   number=c.number, x_memset=med / memset_t,
                   x_cv2=(med / cv2_t) if cv2_t and
                   c.info["kind"] != "baseline" else None)
        if c.info.get("mode") == "into":
            row["cv2_ref"] = "cv2.fillPoly into"
        row["min_ms"] = min(c.times) * 1e3
        if cv2_c is not None and c.info["kind"] == "rastrum":
            # robust companions of x_cv2 on a noisy machine: the median of
            # the per-round ratios (both timed in the same round) and the
            # ratio of the best times
            pairs = [a / b for a, b in zip(c.times, cv2_c.times)]
            row["x_cv2_paired"] = statistics.median(pairs) if pairs else None
            row["x_cv2_best"] = min(c.times) / min(cv2_c.times)
        out = results.get(id(c))
        if canvas:
            # no per-mask oracle for 10000 fills into one canvas: compare
            # with the AET's canvas (the AET is held to the oracle by the
            # tests) - every exact algorithm must give 0
            ref = next((results.get(id(x)) for x in cands
                        if x.info.get("algorithm") == "aet"
                        and x.info.get("rule") == c.info.get("rule")
                        and x.info.get("S") == DEFAULT_S), None)
            if c.info["kind"] != "baseline":
                row["diff_aet"] = count_diff(out, ref)
        elif c.info["kind"] == "rastrum":
            progress(f"  {scene.name}: accuracy {c.label}")
            if args.detail:
                row["diff_exact"] = count_diff(
                    out, refs.get(scene, c.info["rule"], c.info["o"], None))
            row["diff_snap"] = count_diff(
                out, refs.get(scene, c.info["rule"], c.info["o"],
                              c.info["S"]))
        if c.info["kind"] == "peer" and not canvas and out is not None:
            # every peer's output checked in every run, against rastrum's
            # exact mask at S = 8 (equal to the exact rational reference,
            # as the tests check) at the sample offset that suits the peer
            # best: a peer drawing nothing is reported, not timed as a winner
            check = {}
            for o in (0.0, 0.5):
                ref = [rastrum.polygon_mask(rings, shape, rule=c.info["rule"], sample_offset=o)
                       for rings in polys]
                check[o] = count_diff(out, ref)
            row["px_off"] = min(check.values())
            row["empty"] = all(not np.asarray(m).any() for m in out) and any(
                r.any() for r in ref)
        if c.info["kind"] == "peer" and args.detail:
            progress(f"  {scene.name}: accuracy {c.label}")
            best = None
            for o in (0.0, 0.5):
                d = count_diff(out, refs.get(scene, c.info["rule"], o, None))
                if d is not None and (best is None or d < best[0]):
                    best = (d, o)
            if best is not None:
                row["diff_exact"], row["o"] = best
        rows.append(row)

    # do the two rules give the same exact result on this scene?
    same = None
    if not canvas:
        a = refs.get(scene, "evenodd", 0.5, DEFAULT_S)
        b = refs.get(scene, "nonzero", 0.5, DEFAULT_S)
        same = None if a is None or b is None else all(
            np.array_equal(x, y) for x, y in zip(a, b))
    progress.done()
    return rows, same


HEADER = (f"{'implementation':<20} {'rule':<8} {'S':>2} {'o':>3} "
          f"{'ms':>9} {'iqr%':>5} {'n':>4} {'xmemset':>7} {'xcv2':>6} "
          f"{'!=exact':>8} {'!=snap':>7}")


def format_row(r) -> str:
    if "error" in r:
        return (f"{r['label']:<20} {r.get('rule') or '':<8} "
                f"{'':>2} {'':>3} error: {r['error']}")[:200]
    iqr = "    -" if r.get("iqr") is None else f"{100 * r['iqr']:5.1f}"
    s = r.get("S")
    return (f"{r['label']:<20} {r.get('rule') or '':<8} "
            f"{'' if s is None else s:>2} "
            f"{_fmt_o(r.get('o')) if r['kind'] != 'baseline' else '':>3} "
            f"{_fmt_ms(r['ms'] / 1e3)} {iqr} {r['repeats']:>4} "
            f" {_fmt_ratio(r['x_memset'])} {_fmt_ratio(r.get('x_cv2'))} "
            f"{_fmt_int(r.get('diff_exact'), 8)} "
            f"{_fmt_int(r.get('diff_snap'), 7)}")


def print_scene(scene, rows, same, out=sys.stdout):
    print(f"\n== {scene.name}: {scene.summary()}", file=out)
    if same is not None:
        print("   exact evenodd and nonzero results are "
              + ("identical" if same else "DIFFERENT"), file=out)
    print(HEADER, file=out)
    main_rows = [r for r in rows if not (r["kind"] == "rastrum"
                                         and r.get("S") != DEFAULT_S)]
    for r in main_rows:
        print(format_row(r), file=out)


def _fmt_bytes(n):
    if n is None:
        return "-"
    if n < 1024:
        return f"{n} B"
    for unit in ("KiB", "MiB", "GiB"):
        n /= 1024.0
        if n < 1024 or unit == "GiB":
            return f"{n:.0f} {unit}" if n >= 100 else f"{n:.1f} {unit}"


def _table_rows(all_rows, scene_meta):
    """[(implementation, rule, {scene: row})] in table order: memset,
    cv2.fillPoly, the rastrum algorithms (registry order, even-odd before
    non-zero, as measured), then the other peers; S = 8 and o = 1/2 only."""
    groups: Dict[tuple, Dict[str, dict]] = {}
    for r in all_rows:
        sc = r["scene"]
        if sc not in scene_meta:
            continue
        if r["kind"] == "rastrum" and (r.get("S") != DEFAULT_S
                                       or r.get("o") != 0.5
                                       or (r.get("mode") == "into")
                                       != scene_meta[sc]["canvas"]):
            continue
        if r["kind"] == "baseline" and r["impl"] != "memset":
            continue
        if r["kind"] == "peer" and (r.get("mode") == "into") != \
                scene_meta[sc]["canvas"]:
            continue
        impl = r["algorithm"] if r["kind"] == "rastrum" else r["impl"]
        k = (r["kind"], impl, r.get("rule"))
        groups.setdefault(k, {})[sc] = r
    rank = {"baseline": 0, "rastrum": 2}
    keys = sorted(groups, key=lambda k: (
        1 if k[1] == "cv2.fillPoly" else rank.get(k[0], 3)))
    return [(k[1], k[2], groups[k]) for k in keys]


def _exact_mark(r):
    d = r.get("diff_snap", r.get("diff_aet"))
    return "" if not d else "!"


def print_table(all_rows, scene_meta, out=sys.stdout):
    """THE table: algorithm x scene -> time / memset, time / cv2.fillPoly,
    scratch bytes (rast_scratch_size)."""
    names = list(scene_meta)
    print("\n== rastrum polygon fillers, S = 8, o = 1/2: x memset | x cv2 | "
          "scratch per call   (memset and cv2 rows: ms)", file=out)
    w0 = 25
    head = f"{'algorithm':<16}{'rule':<9}" + "".join(
        f"{n:>22}" for n in names)
    sub = " " * w0 + "".join(
        f"{scene_meta[n]['size']:>22}" for n in names)
    print(head, file=out)
    print(sub, file=out)
    for impl, rule, by in _table_rows(all_rows, scene_meta):
        label = impl.replace("rastrum/", "")
        cells = []
        for n in names:
            r = by.get(n)
            if r is None or "error" in r:
                cells.append(f"{'-' if r is None else 'error':>22}")
            elif r["kind"] == "baseline" or impl == "cv2.fillPoly":
                off = "" if r["kind"] == "baseline" or r.get("px_off") is None else \
                    " EMPTY" if r.get("empty") else f" {r['px_off']}px"
                cells.append(f"{_fmt_ms(r['ms'] / 1e3).strip() + ' ms' + off:>22}")
            else:
                scr = _fmt_bytes(r.get("scratch")) if r["kind"] == "rastrum" \
                    else "EMPTY" if r.get("empty") else \
                    "" if r.get("px_off") is None else f"{r['px_off']}px"
                cells.append(f"{_fmt_ratio(r['x_memset']).strip():>7}"
                             f"{_fmt_ratio(r.get('x_cv2')).strip():>6}"
                             f"{scr:>9}" + (_exact_mark(r) or ""))
        print(f"{label:<16}{rule or '':<9}" + "".join(cells), file=out)
    print("   (rastrum cells: scratch bytes; ! = not bit-exact, and every rastrum cell without one\n"
          "   is exact: 0 pixels off the exact mask of the snapped input, or for a canvas scene\n"
          "   off the AET's canvas.  Peer cells: pixels that differ from the exact mask at S = 8\n"
          "   and the sample offset that suits the peer best; EMPTY = the peer drew nothing)", file=out)


def table_markdown(all_rows, scene_meta) -> str:
    """The same table in Markdown, for docs/benchmarks.md."""
    names = list(scene_meta)
    lines = ["| algorithm | rule | " + " | ".join(
        f"{n} ({scene_meta[n]['size']})" for n in names) + " |",
        "|---|---|" + "---|" * len(names)]
    for impl, rule, by in _table_rows(all_rows, scene_meta):
        label = impl.replace("rastrum/", "")
        cells = []
        for n in names:
            r = by.get(n)
            if r is None or "error" in r:
                cells.append("-")
            elif r["kind"] == "baseline" or impl == "cv2.fillPoly":
                cells.append(f"{r['ms']:.3g} ms" + ("" if r["kind"] == "baseline" or r.get("px_off") is None
                                                    else f" / {r['px_off']} px off"))
            else:
                c = (f"{_fmt_ratio(r['x_memset']).strip()} / "
                     f"{_fmt_ratio(r.get('x_cv2')).strip()}")
                if r["kind"] == "rastrum":
                    c += f" / {_fmt_bytes(r.get('scratch'))}"
                elif r.get("empty"):
                    c += " / EMPTY"
                elif r.get("px_off") is not None:
                    c += f" / {r['px_off']} px off"
                cells.append(c + (" (not exact)" if _exact_mark(r) else ""))
        lines.append(f"| {label} | {rule or ''} | " + " | ".join(cells)
                     + " |")
    return "\n".join(lines) + "\n"


def print_trade(scene, rows, out=sys.stdout):
    tr = [r for r in rows if r["kind"] == "rastrum"
          and r.get("rule") == "evenodd" and r.get("o") == 0.5
          and "error" not in r]
    if not tr:
        return
    print(f"\n== speed/accuracy trade: {scene.name}, evenodd, o=1/2 "
          f"(ms, pixels != exact on the unsnapped input)", file=out)
    print(f"{'algorithm':<20} " + " ".join(f"{'S=' + str(s):>18}"
                                          for s in TRADE_S), file=out)
    for alg in dict.fromkeys(r["algorithm"] for r in tr):
        cells = []
        for s in TRADE_S:
            r = next((x for x in tr if x["algorithm"] == alg
                      and x["S"] == s), None)
            cells.append(f"{'-':>18}" if r is None else
                         f"{_fmt_ms(r['ms'] / 1e3)}{_fmt_int(r.get('diff_exact'), 9)}")
        print(f"{alg:<20} " + " ".join(cells), file=out)


def summarize(all_rows, out=sys.stdout):
    """The default algorithm (aet) against cv2.fillPoly, scene by scene, as
    ratios of time (< 1: rastrum takes less time); then anything that is
    not exact or failed (none expected: the tests hold every algorithm to
    the exact reference)."""
    aet = [r for r in all_rows if r["kind"] == "rastrum" and "error" not in r and r.get("S") == DEFAULT_S
           and r.get("algorithm") == "aet" and r.get("x_cv2") is not None]
    if aet:
        print("\n== the default algorithm (aet) against cv2.fillPoly: time ratio (< 1: rastrum takes less "
              "time; paired = median of per-round ratios)", file=out)
        for r in aet:
            print(f"   {r['scene']:<11} {r['rule']:<8} o={_fmt_o(r['o']):<3} {r['ms']:8.3f} ms vs "
                  f"{r['ms'] / r['x_cv2']:8.3f} ms: x{r['x_cv2']:.2f} (paired x{r['x_cv2_paired']:.2f}, "
                  f"best-of x{r['x_cv2_best']:.2f})", file=out)
    for r in all_rows:
        if r["kind"] != "rastrum":
            continue
        if "error" in r:
            print(f"   error: {r['scene']:<12} {r['label']:<16} {r.get('rule')}: {r['error']}", file=out)
        elif r.get("diff_snap") or r.get("diff_aet"):
            print(f"   differs from the exact mask: {r['scene']:<12} {r['label']:<16} {r['rule']:<8} "
                  f"o={_fmt_o(r['o'])} S={r['S']}: {r.get('diff_snap') or r.get('diff_aet')} pixels "
                  "(a bug: please report it)", file=out)


LEGEND = """\
columns: ms = median time of one scene (all its masks), over n interleaved
repeats (each repeat averages enough calls to last ~{target:g} ms); iqr% =
interquartile range / median; xmemset = ms / ctypes.memset of H*W bytes per
mask on a preallocated, already touched buffer (the physical limit);
xcv2 = ms / cv2.fillPoly's ms on the same scene (np.zeros + fillPoly, its
even-odd fill; < 1: faster than OpenCV); !=exact = pixels differing from the
exact mask of the UNSNAPPED float input at the same sample offset o (for
peers: the offset, 0 or 1/2, that fits them best); !=snap = pixels
differing from the exact mask of the input snapped to S subpixel bits
(0 = bit-exact). Baselines: memset; np.ones = allocate + fill a fresh mask.
Rows "... into" paint into preallocated zeroed buffers instead of returning
a fresh mask: rastrum Canvas(gray8).fill_polygon vs cv2.fillPoly without
np.zeros (their xcv2 is against "cv2.fillPoly into")."""


TABLE_LEGEND = """\
One table, algorithm x scene.  Each cell: the median time of the scene (all
its masks; for a canvas scene all its fills into one canvas), over
interleaved repeats (each round times every row once; each repeat averages
enough calls to last ~{target:g} ms), as a ratio to ctypes.memset of the same
H*W bytes per mask (x memset; one memset for a canvas scene) and to
cv2.fillPoly doing the same work (x cv2: np.zeros + fillPoly per mask, or
fillPoly per polygon into one canvas; < 1 = faster than OpenCV), then the
scratch bytes rast_scratch_size asks for (the largest call of the scene).
rastrum at S = 8 (1/256 px), samples at pixel centres; cv2 has even-odd
only, so non-zero rows are compared with its even-odd fill."""


def build_parser():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--quick", action="store_true",
                   help="fewer, shorter repeats (a quick look, noisier)")
    p.add_argument("--scenes", nargs="+", metavar="NAME", default=[],
                   help="scenes to run (default all): "
                   + " ".join(scenes_mod.SCENES))
    p.add_argument("--repeats", type=int, default=None,
                   help="repeats per measurement (default 21, quick 7)")
    p.add_argument("--trade-scene", default="star200", metavar="NAME",
                   help="scene for the S = 0, 2, 4, 8 trade rows "
                   "(default star200)")
    p.add_argument("--no-peers", action="store_true",
                   help="time rastrum and the baselines only (and cv2)")
    p.add_argument("--detail", action="store_true",
                   help="also print a block per scene (both sample offsets, "
                   "pixels off the\nUNSNAPPED exact mask, peers' accuracy, "
                   "'into' rows) and the S trade;\ndefault scenes then: all")
    p.add_argument("--markdown", default="", metavar="PATH",
                   help="also write the table as Markdown to PATH")
    p.add_argument("--json", default=str(HERE / "results.json"),
                   metavar="PATH", help="where to write the results "
                   "(default bench/results.json; '' for none)")
    p.add_argument("--quiet", action="store_true", help="no progress")
    return p


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    unknown = [n for n in args.scenes if n not in scenes_mod.SCENES]
    if unknown:
        parser.error(f"unknown scene(s) {' '.join(unknown)}; known: "
                     + " ".join(scenes_mod.SCENES))
    if args.repeats is None:
        args.repeats = 7 if args.quick else 21
    args.repeats = max(1, args.repeats)
    args.target = 0.004 if args.quick else 0.012   # seconds per repeat
    args.budget = 1.0 if args.quick else 2.5       # seconds per slow peer
    progress = Progress(not args.quiet)

    rastrum = import_rastrum()
    oracle = load_oracle()
    refs = References(oracle, progress)
    chosen = scenes_mod.get(args.scenes or
                            (() if args.detail else scenes_mod.TABLE_SCENES))

    peers, missing = [], []
    for p in PEERS:
        if args.no_peers and p.name != "cv2.fillPoly":
            continue
        why = peer_available(p)
        (missing.append((p.name, why)) if why else peers.append(p))

    t_start = time.monotonic()
    print(f"rastrum {getattr(rastrum, '__version__', '?')} benchmark - "
          f"{platform.machine()} {platform.processor() or ''} "
          f"{os.cpu_count()} cpu, Python {platform.python_version()}, "
          f"numpy {np.__version__}"
          + (", --quick" if args.quick else ""))
    print((LEGEND if args.detail else TABLE_LEGEND).format(
        target=args.target * 1e3))
    print("vertices are float64 (bench/scenes.py); rastrum at S=8 unless "
          "noted; o = sample offset")
    if oracle is None:
        print("NOTE: tests/oracle.py not found: accuracy columns empty")
    for name, why in missing:
        print(f"NOTE: {name} not installed, skipped ({why})")

    all_rows, scene_meta = [], {}
    for i, sc in enumerate(chosen):
        progress(f"[{i + 1}/{len(chosen)}] {sc.name}", force=True)
        rows, same = run_scene(sc, rastrum, refs, peers, args, progress,
                               trade=(sc.name == args.trade_scene))
        if args.detail:
            print_scene(sc, rows, same)
            if sc.name == args.trade_scene:
                print_trade(sc, rows)
        sys.stdout.flush()
        all_rows.extend(rows)
        h, w = sc.shape
        canvas = getattr(sc, "canvas", False)
        scene_meta[sc.name] = dict(
            summary=sc.summary(), shape=sc.shape, masks=len(sc.polygons),
            rules_agree=same, canvas=canvas,
            size=(f"{len(sc.polygons)}x{w}x{h}" if sc.batch and not canvas
                  else f"{len(sc.polygons)}->{w}x{h}" if canvas
                  else f"{w}x{h}"))
    progress.done()
    print_table(all_rows, scene_meta)
    if args.markdown:
        Path(args.markdown).write_text(table_markdown(all_rows, scene_meta))
    summarize(all_rows)
    elapsed = time.monotonic() - t_start
    print(f"\n({elapsed:.0f} s)")

    result = dict(
        meta=dict(
            date=time.strftime("%Y-%m-%dT%H:%M:%S%z"),
            python=platform.python_version(), numpy=np.__version__,
            machine=platform.machine(), cpus=os.cpu_count(),
            rastrum=getattr(rastrum, "__version__", None),
            quick=args.quick, repeats=args.repeats,
            seconds_per_repeat=args.target,
            memset="ctypes.memset of H*W bytes per mask on a preallocated, "
                   "touched buffer",
            cv2="np.zeros(shape, uint8) + cv2.fillPoly(int32 pts, "
                "shift=8, LINE_8)",
            reference="tests/oracle.py oracle_mask, subpixel_bits=None "
                      "(exact, unsnapped) for diff_exact; =S for diff_snap",
            missing_peers=dict(missing), elapsed_s=elapsed),
        scenes=scene_meta, rows=all_rows)
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1,
                                              default=float) + "\n")
    return result


if __name__ == "__main__":
    main()

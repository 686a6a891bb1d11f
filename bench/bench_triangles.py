"""Triangle batches at 1024x1024: rastrum's fillers against memset and peers.

Scenes (one 1024x1024 gray8 buffer, allocated once; no call clears it):

- small:  10,000 triangles of about 10..50 px each, anywhere on screen;
- medium:  2,000 triangles of about 1,000 px;
- large:      20 triangles of about a quarter of the screen (262,144 px);
- mesh:   20,000 triangles cutting the whole square (a jittered grid).

For each scene and candidate: the median time of one call over interleaved
rounds (every round times every candidate once, in rotated order, so noise
hits them alike), triangles/s, pixels/s (pixels written: the covered pixels,
counted once per triangle owning them), and the time as a ratio to a memset
of the whole buffer (ctypes.memset, 1 MiB) and per covered pixel to memset
per byte ("px/memset": 1.0 means writing the triangles' pixels costs what
memset costs per byte).

Candidates: rastrum.Canvas.fill_triangles (one call per batch, float64
input snapped in C) for each algorithm in rastrum.ALGORITHMS; and where
installed: cv2.fillConvexPoly in a Python loop (int32 points with shift=8,
converted before timing), cv2.fillPoly with the whole batch in one call
(even-odd of all the triangles together: the union only where they do not
overlap, so NOT the same job; listed for reference), skia drawVertices
(kTriangles, one call, no anti-aliasing) and Pillow ImageDraw.polygon in a
loop.  On the mesh it also reports the overdraw of cv2 and Pillow: the
share of the square's pixels that two or more triangles write (and that
none writes), from the sum of per-triangle masks.

Every candidate's output is checked once before the timing, against the
exact union of the triangles (rastrum's triangles_mask, at the sample
offset that suits the peer best): the "px off" column; a candidate that
draws nothing shows EMPTY instead of being timed as a winner.

Then, measured side by side in the same interleaved rounds: each rastrum
filler's speed-up over the faster of cv2.fillConvexPoly (loop) and skia
drawVertices on the small triangles and the mesh (peer ms / rastrum ms),
and on the large triangles its time per pixel as a multiple of memset's.

The machine may be shared and noisy: read medians and ratios, not single
times (short timed blocks and many rounds, so that a block the scheduler
interrupts is an outlier the median drops; ``--clock cpu`` times each
block in this thread's CPU time instead, which leaves the other processes
out).  ``python bench/bench_triangles.py [--quick] [--clock cpu]``;
``run(quick)`` returns the rows.
"""

from __future__ import annotations

import argparse
import ctypes
import gc
import os
import statistics
import sys
import time
from pathlib import Path

# Single-threaded numpy: an idle BLAS thread spinning on the second core
# would be timed as noise on a two-core machine.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
H = W = 1024


def import_rastrum():
    try:
        import rastrum
    except ImportError:
        sys.path.insert(0, str(ROOT / "python"))
        import rastrum
    return rastrum


# --- scenes --------------------------------------------------------------------

def random_triangles(rng, n, area_lo, area_hi, margin=0.0):
    """n triangles with areas spread over [area_lo, area_hi] px, near
    equilateral with jittered angles, centres anywhere at least `margin`
    px inside the screen."""
    area = rng.uniform(area_lo, area_hi, n)
    # jittered angles change the area; rescale to the drawn one exactly
    ang = rng.uniform(0, 2 * np.pi, (n, 1)) + np.arange(3) * 2 * np.pi / 3
    ang += rng.uniform(-0.35, 0.35, (n, 3))
    unit = np.stack([np.cos(ang), np.sin(ang)], -1)  # (n, 3, 2)
    a = unit[:, 1] - unit[:, 0]
    b = unit[:, 2] - unit[:, 0]
    ua = 0.5 * np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    r = np.sqrt(area / ua)
    c = rng.uniform(margin, W - margin, (n, 1, 2))
    return c + unit * r[:, None, None]


def jittered_mesh(n=100, size=1024.0, seed=7):
    """2 n^2 triangles cutting [0, size]^2 (as in tests/test_triangles.py)."""
    rng = np.random.default_rng(seed)
    cell = size / n
    ij = np.arange(n + 1) * cell
    x, y = np.meshgrid(ij, ij)
    jx = rng.uniform(-0.15, 0.15, x.shape) * cell
    jy = rng.uniform(-0.15, 0.15, y.shape) * cell
    jx[:, [0, -1]] = 0
    jy[[0, -1], :] = 0
    p = np.stack([x + jx, y + jy], axis=-1)
    p00, p10, p01, p11 = p[:-1, :-1], p[:-1, 1:], p[1:, :-1], p[1:, 1:]
    diag = rng.random((n, n)) < 0.5
    t1 = np.where(diag[..., None, None], np.stack([p00, p10, p11], -2), np.stack([p00, p10, p01], -2))
    t2 = np.where(diag[..., None, None], np.stack([p00, p11, p01], -2), np.stack([p10, p11, p01], -2))
    tris = np.concatenate([t1.reshape(-1, 3, 2), t2.reshape(-1, 3, 2)])
    return np.ascontiguousarray(tris[rng.permutation(len(tris))])


def scenes(quick):
    rng = np.random.default_rng(2024)
    k = 4 if quick else 1
    return {
        "small": random_triangles(rng, 10000 // k, 10, 50),
        "medium": random_triangles(rng, 2000 // k, 800, 1200, margin=20),
        "large": random_triangles(rng, 20 // k, 0.24 * H * W, 0.26 * H * W, margin=440),
        "mesh": jittered_mesh(),
    }


# --- candidates ------------------------------------------------------------------

def rastrum_cands(rastrum, tris, buf):
    canvas = rastrum.Canvas.wrap(buf)
    out = []
    for alg in rastrum.ALGORITHMS["Canvas.fill_triangles"]:
        def run(f=canvas.fill_triangles, t=tris, a=alg):
            f(t, 1, algorithm=a)
        out.append(("rastrum " + alg, run))
    return out


def cv2_cands(tris, buf):
    try:
        import cv2
    except Exception as e:  # ImportError or a broken wheel
        return [], "cv2: %s" % e
    pts = np.round(tris * 256.0).astype(np.int32)
    polys = [p.reshape(-1, 1, 2) for p in pts]

    def loop(img=buf, fill=cv2.fillConvexPoly, ps=polys, lt=cv2.LINE_8):
        for p in ps:
            fill(img, p, 1, lt, 8)

    def batch(img=buf, fill=cv2.fillPoly, ps=polys, lt=cv2.LINE_8):
        fill(img, ps, 1, lt, 8)
    return [("cv2.fillConvexPoly loop", loop), ("cv2.fillPoly batch (even-odd!)", batch)], None


def skia_cands(tris, buf):
    try:
        import skia
    except Exception as e:
        return [], "skia: %s" % e
    pos = [skia.Point(float(x), float(y)) for x, y in tris.reshape(-1, 2).tolist()]
    verts = skia.Vertices(skia.Vertices.kTriangles_VertexMode, pos)
    # Alpha8 keeps only the paint's alpha: an opaque colour (alpha 255)
    # writes 255 where a triangle is; the output check below catches a
    # paint that draws nothing.
    paint = skia.Paint(AntiAlias=False, Color=skia.ColorWHITE)
    canvas = skia.Canvas(buf, colorType=skia.kAlpha_8_ColorType)

    def run(c=canvas, v=verts, p=paint):
        c.drawVertices(v, p)
    return [("skia drawVertices", run)], None


def pil_cands(tris, quick):
    try:
        from PIL import Image, ImageDraw
    except Exception as e:
        return [], "PIL: %s" % e
    im = Image.new("L", (W, H), 0)
    draw = ImageDraw.Draw(im)
    polys = [t.ravel().tolist() for t in tris]

    def run(d=draw.polygon, ps=polys):
        for p in ps:
            d(p, fill=1)
    run.output = lambda: np.asarray(im)
    run.reset = lambda: im.paste(0, (0, 0, W, H))
    return [("PIL ImageDraw.polygon loop", run)], None


def check_outputs(cands, buf, masks):
    """{label: pixels off the exact union (the best sample offset), or
    "EMPTY" when the candidate drew nothing}: each candidate run once into
    a cleared target."""
    res = {}
    for label, fn in cands:
        if label.startswith("memset"):
            continue
        buf[...] = 0
        getattr(fn, "reset", lambda: None)()
        fn()
        out = np.asarray(getattr(fn, "output", lambda: buf)()).astype(bool)
        res[label] = "EMPTY" if not out.any() else min(int(np.count_nonzero(out != m)) for m in masks)
    buf[...] = 0
    return res


# --- overdraw of the peers on the mesh ---------------------------------------------

def overdraw_cv2(tris):
    import cv2
    cnt = np.zeros((H, W), np.int32)
    pts = np.round(tris * 256.0).astype(np.int64)
    for p in pts:
        x0, y0 = max(int(p[:, 0].min() >> 8) - 1, 0), max(int(p[:, 1].min() >> 8) - 1, 0)
        x1, y1 = min(int(p[:, 0].max() >> 8) + 2, W), min(int(p[:, 1].max() >> 8) + 2, H)
        patch = np.zeros((y1 - y0, x1 - x0), np.uint8)
        q = (p - [x0 << 8, y0 << 8]).astype(np.int32).reshape(-1, 1, 2)
        cv2.fillConvexPoly(patch, q, 1, cv2.LINE_8, 8)
        cnt[y0:y1, x0:x1] += patch
    return cnt


def overdraw_pil(tris):
    from PIL import Image, ImageDraw
    cnt = np.zeros((H, W), np.int32)
    for t in tris:
        x0, y0 = max(int(np.floor(t[:, 0].min())) - 1, 0), max(int(np.floor(t[:, 1].min())) - 1, 0)
        x1, y1 = min(int(np.ceil(t[:, 0].max())) + 2, W), min(int(np.ceil(t[:, 1].max())) + 2, H)
        im = Image.new("L", (x1 - x0, y1 - y0), 0)
        ImageDraw.Draw(im).polygon((t - [x0, y0]).ravel().tolist(), fill=1)
        cnt[y0:y1, x0:x1] += np.asarray(im)
    return cnt


def coverage_stats(cnt):
    n = cnt.size
    return 100.0 * (cnt > 1).sum() / n, 100.0 * (cnt == 0).sum() / n


# --- timing ------------------------------------------------------------------------

# The clock: wall time (time.perf_counter), or the CPU time of this thread
# (time.thread_time), which leaves out the time the scheduler gives other
# processes: on a shared machine with more runnable processes than cores,
# wall-time blocks are interrupted at random and even medians wander.  Every
# candidate here runs in the calling thread (cv2.fillConvexPoly and skia's
# raster drawVertices start no threads), so its CPU time is its cost.
CLOCKS = {"wall": time.perf_counter, "cpu": time.thread_time}
_clock = time.perf_counter


def _block(fn, number):
    t0 = _clock()
    for _ in range(number):
        fn()
    return (_clock() - t0) / number


def measure(cands, rounds, target=0.005):
    """{label: median seconds per call}, interleaved rounds; each timed
    block lasts about `target` seconds (at least one call)."""
    numbers = {}
    for label, fn in cands:
        fn()  # warm up
        t = _block(fn, 1)
        numbers[label] = max(1, int(target / max(t, 1e-9)))
    times = {label: [] for label, _ in cands}
    gc.collect()
    gc.disable()
    try:
        for r in range(rounds):
            k = r % len(cands)
            for label, fn in cands[k:] + cands[:k]:
                times[label].append(_block(fn, numbers[label]))
    finally:
        gc.enable()
    return {label: statistics.median(t) for label, t in times.items()}


def run(quick=False, progress=True, clock="wall"):
    """Time every scene; return the rows (dicts) and print the table."""
    global _clock
    _clock = CLOCKS[clock]
    rastrum = import_rastrum()
    rounds = 7 if quick else 25
    buf = np.zeros((H, W), np.uint8)
    memset = ctypes.memset
    addr = buf.ctypes.data

    def do_memset(m=memset, a=addr, n=buf.nbytes):
        m(a, 0, n)

    rows, notes = [], []
    for name, tris in scenes(quick).items():
        if progress:
            print("timing %s (%d triangles)..." % (name, len(tris)), file=sys.stderr)
        cnt = rastrum.triangles_count(tris, (H, W))
        masks = [rastrum.triangles_mask(tris, (H, W), sample_offset=o) for o in (0.5, 0.0)]
        pixels = int(cnt.sum())
        cands = [("memset 1 MiB", do_memset)] + rastrum_cands(rastrum, tris, buf)
        for make in (cv2_cands, skia_cands):
            c, note = make(tris, buf)
            cands += c
            if note and note not in notes:
                notes.append(note)
        c, note = pil_cands(tris, quick)
        if name in ("small", "mesh") or not quick:
            cands += c
        if note and note not in notes:
            notes.append(note)
        off = check_outputs(cands, buf, masks)
        med = measure(cands, rounds)
        tm = med["memset 1 MiB"]
        best_peer = min((t for l, t in med.items() if not l.startswith(("rastrum", "memset"))
                         and "even-odd" not in l), default=None)
        for label, t in med.items():
            if label.startswith("memset"):
                continue
            rows.append(dict(scene=name, candidate=label, triangles=len(tris), pixels=pixels,
                             seconds=t, tris_per_s=len(tris) / t, px_per_s=pixels / t,
                             vs_memset=t / tm, px_vs_memset=(t / pixels) / (tm / buf.nbytes),
                             vs_best_peer=(t / best_peer) if best_peer else None, px_off=off.get(label)))
        if name == "mesh":
            over = {"rastrum (every filler)": coverage_stats(cnt)}
            try:
                over["cv2.fillConvexPoly"] = coverage_stats(overdraw_cv2(tris))
            except ImportError:
                pass
            try:
                over["PIL ImageDraw.polygon"] = coverage_stats(overdraw_pil(tris))
            except ImportError:
                pass
            for label, (o, h) in over.items():
                rows.append(dict(scene="mesh overdraw", candidate=label, overdraw_pct=o, holes_pct=h))
    rows += targets(rows)
    print_table(rows, tm, notes, clock)
    return rows


# --- rastrum against the fastest peer ----------------------------------------------

TARGET_PEERS = ("cv2.fillConvexPoly loop", "skia drawVertices")


def targets(rows):
    """One row per (comparison, rastrum filler): the figures, no verdict."""
    out = []
    for scene in ("small", "mesh"):
        cells = {r["candidate"]: r for r in rows if r.get("scene") == scene and "seconds" in r}
        n = next((r["triangles"] for r in cells.values()), 0)
        what = "%s %s: speed-up over the fastest peer" % (format(n, ","), scene)
        peers = [(cells[p]["seconds"], p) for p in TARGET_PEERS if p in cells]
        best = min(peers) if peers else None
        for label, r in cells.items():
            if not label.startswith("rastrum"):
                continue
            speedup = best[0] / r["seconds"] if best else None
            out.append(dict(scene="target", target=what, candidate=label, seconds=None,
                            rastrum_ms=r["seconds"] * 1e3, peer=best[1] if best else None,
                            peer_ms=best[0] * 1e3 if best else None, value=speedup))
    for r in rows:
        if r.get("scene") == "large" and r["candidate"].startswith("rastrum") and "seconds" in r:
            v = r["px_vs_memset"]
            out.append(dict(scene="target", target="large: time per pixel, x memset's",
                            candidate=r["candidate"], seconds=None, rastrum_ms=r["seconds"] * 1e3,
                            peer="memset", peer_ms=None, value=v))
    return out


def print_table(rows, tm, notes, clock="wall"):
    print("1024x1024 gray8; medians of interleaved rounds (%s); memset of 1 MiB = %.1f us"
          % ("wall time" if clock == "wall" else "thread CPU time", tm * 1e6))
    print("%-7s %-32s %9s %10s %10s %9s %10s %10s %8s" % (
        "scene", "candidate", "ms/call", "tris/s", "Mpx/s", "/memset", "px/memset", "/best peer", "px off"))
    for r in rows:
        if r.get("seconds") is None:
            continue
        vp = "%.2f" % r["vs_best_peer"] if r["vs_best_peer"] else "-"
        print("%-7s %-32s %9.3f %10.3g %10.1f %9.1f %10.2f %10s %8s" % (
            r["scene"], r["candidate"], r["seconds"] * 1e3, r["tris_per_s"], r["px_per_s"] / 1e6,
            r["vs_memset"], r["px_vs_memset"], vp, "-" if r.get("px_off") is None else r["px_off"]))
    print()
    print("mesh of 20,000 triangles: share of the square's pixels written twice or more / never")
    for r in rows:
        if "overdraw_pct" in r:
            print("  %-28s overdraw %6.2f %%   holes %6.2f %%" % (r["candidate"], r["overdraw_pct"], r["holes_pct"]))
    print()
    print("rastrum against the fastest peer (speed-up = peer ms / rastrum ms), and the large triangles'")
    print("time per pixel against memset's, measured side by side in the rounds above:")
    print("%-40s %-9s %10s  %-30s %16s" % ("comparison", "filler", "rastrum", "fastest peer", "ratio"))
    for r in rows:
        if r.get("scene") != "target":
            continue
        if r["peer"] == "memset":
            peer, ratio = "-", "%.2fx memset/px" % r["value"]
        elif r["peer"]:
            peer, ratio = "%s %.3f ms" % (r["peer"], r["peer_ms"]), "%.2fx" % r["value"]
        else:
            peer, ratio = "(no peer installed)", "-"
        print("%-40s %-9s %7.3f ms  %-30s %16s" % (
            r["target"], r["candidate"].replace("rastrum ", ""), r["rastrum_ms"], peer, ratio))
    for n in notes:
        print("skipped: " + n)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer triangles and rounds")
    ap.add_argument("--clock", choices=sorted(CLOCKS), default="wall",
                    help="wall time, or this thread's CPU time (steadier on a loaded machine)")
    args = ap.parse_args(argv)
    run(quick=args.quick, clock=args.clock)


if __name__ == "__main__":
    main()

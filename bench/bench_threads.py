"""Threads: the same total work on 1, 2 and 4 Python threads, per entry point.

The C calls run without the GIL (cffi releases it around each one), so
threads drawing at once should scale with the cores while the work is in
C.  For each entry point a fixed job list is split evenly between k
threads (k = 1, 2, 4), each thread drawing into its own output; the wall
time of the whole job list is taken over interleaved rounds (every round
times k = 1, 2, 4 once each, in rotated order), and the table gives the
median time and the speed-up t(1) / t(k).  Entry points whose calls are
small (a line, a 30-vertex mask) spend much of each call in Python, under
the GIL, and scale less: that share is what the table shows.

The machine has 2 cores (shared): 4 threads cannot beat 2, and when other
work keeps a core busy, 2 cannot beat 1 either.  The first row is a
control that is not rastrum (numpy's matrix product, which also releases
the GIL): it shows what the machine gives at the time of the run.

``python bench/bench_threads.py [--quick]``; ``run(quick)`` returns the rows.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import threading
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def import_rastrum():
    try:
        import rastrum
    except ImportError:
        sys.path.insert(0, str(ROOT / "python"))
        import rastrum
    return rastrum


def star(n, r0, r1, cx, cy):
    t = np.arange(2 * n) * np.pi / n
    r = np.where(np.arange(2 * n) % 2 == 0, r1, r0)
    return np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], axis=1)


def workloads(rastrum, quick):
    """{name: (list of jobs, make_output)}: a job is f(out) drawing into
    the thread's own output; make_output() gives a fresh one."""
    rng = np.random.default_rng(5)
    scale = 1 if quick else 3
    stars = [star(100, 200, 480, 512 + d, 512 - d) for d in rng.uniform(-20, 20, 60 * scale)]
    small = [rng.uniform(0, 30, (20, 2)) for _ in range(3000 * scale)]
    # batches of 2000 small triangles (10-50 px) anywhere on the 1024² screen
    tris = [rng.uniform(0, 1000, (2000, 1, 2)) + rng.uniform(0, 9, (2000, 3, 2)) for _ in range(16 * scale)]
    lines = rng.uniform(-50, 1074, (1000 * scale, 2, 2))
    masks = [(s, (1024, 1024)) for s in stars]

    def canvas():
        return rastrum.Canvas((1024, 1024), format="gray8")

    spiky = star(200, 60, 120, 128, 128)
    mat = rng.uniform(0, 1, (200, 200))
    return {
        # What the machine gives at the moment: numpy's matrix product also
        # runs without the GIL (single-threaded BLAS, see the top).
        "control: numpy 200² matmul": ([lambda out: mat @ mat] * (40 * scale), lambda: None),
        "polygon_mask 256² winding (C-bound)": (
            [lambda out: rastrum.polygon_mask(spiky, (256, 256), algorithm="winding")] * (8 * scale),
            lambda: None),
        "polygon_mask 1024² star": (
            [lambda out, s=s: rastrum.polygon_mask(s, (1024, 1024)) for s, _ in masks], lambda: None),
        "polygon_mask 30 px (many calls)": (
            [lambda out, s=s: rastrum.polygon_mask(s, (32, 32)) for s in small],
            lambda: None),
        "Canvas.fill_polygon 1024² star": (
            [lambda out, s=s: out.fill_polygon(s, 255, algorithm="edgeflag") for s in stars], canvas),
        "triangles_mask 2000 tris": (
            [lambda out, t=t: rastrum.triangles_mask(t, (1024, 1024), mode="count") for t in tris],
            lambda: None),
        "Canvas.fill_triangles 2000 tris": (
            [lambda out, t=t: out.fill_triangles(t, 255, algorithm="sweep") for t in tris], canvas),
        "Canvas.line (one call each)": (
            [lambda out, ab=ab: out.line(ab[0], ab[1], 255) for ab in lines], canvas),
        "Canvas.polyline (250 points)": (
            [lambda out, p=p: out.polyline(p, 255) for p in lines.reshape(-1, 250, 2)], canvas),
    }


def timed(jobs, make_output, k):
    """Wall time of running `jobs` split evenly over k threads."""
    parts = [jobs[i::k] for i in range(k)]
    outs = [make_output() for _ in range(k)]
    start = threading.Barrier(k + 1)
    done = []

    def work(i):
        start.wait()
        for job in parts[i]:
            job(outs[i])
        done.append(i)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(k)]
    for t in threads:
        t.start()
    start.wait()
    t0 = time.perf_counter()
    for t in threads:
        t.join()
    elapsed = time.perf_counter() - t0
    assert len(done) == k
    return elapsed


KS = (1, 2, 4)


def run(quick=False):
    rastrum = import_rastrum()
    rounds = 5 if quick else 11
    rows = []
    for name, (jobs, make_output) in workloads(rastrum, quick).items():
        timed(jobs, make_output, 1)  # warm up
        times = {k: [] for k in KS}
        for r in range(rounds):
            for j in range(len(KS)):
                k = KS[(r + j) % len(KS)]
                times[k].append(timed(jobs, make_output, k))
        med = {k: statistics.median(v) for k, v in times.items()}
        rows.append((name, len(jobs), med))
    return rows


def print_table(rows):
    print("| entry point | calls | 1 thread | 2 threads | 4 threads | speed-up 2 | speed-up 4 |")
    print("|---|---|---|---|---|---|---|")
    for name, n, med in rows:
        print("| %s | %d | %.1f ms | %.1f ms | %.1f ms | %.2fx | %.2fx |"
              % (name, n, med[1] * 1e3, med[2] * 1e3, med[4] * 1e3, med[1] / med[2], med[1] / med[4]))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer rounds and less work")
    args = ap.parse_args(argv)
    print("cores: %d" % (os.cpu_count() or 1))
    print_table(run(args.quick))


if __name__ == "__main__":
    main()

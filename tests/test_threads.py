"""The C calls run without the GIL, and threads drawing at once agree with
one thread: every drawing entry point, results compared with those of a
single-threaded run."""

import importlib.util
import os
import re
import threading

import numpy as np

import rastrum
from rastrum._native import lib

HERE = os.path.dirname(os.path.abspath(__file__))


def test_c_calls_release_the_gil():
    # PyGILState_Check() from inside a C call: 0 means the GIL was released.
    assert lib.rastpy_gil_held() == 0


def test_every_c_wrapper_releases_the_gil():
    """cffi's out-of-line API mode wraps each C call in
    Py_BEGIN_ALLOW_THREADS / Py_END_ALLOW_THREADS.  Regenerate the C source
    of rastrum._native from the build script and check that every wrapper
    does, so that a declaration added later cannot silently hold the GIL."""
    path = os.path.join(HERE, "..", "python", "rastrum", "_build.py")
    spec = importlib.util.spec_from_file_location("rastrum_build_check", path)
    build = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(build)
    out = os.path.join(os.environ.get("TMPDIR", "/tmp"), "rastrum_native_check_%d.c" % os.getpid())
    try:
        build.ffibuilder.emit_c_code(out)
        with open(out) as f:
            src = f.read()
    finally:
        if os.path.exists(out):
            os.remove(out)
    wrappers = re.findall(r"static PyObject \*\n(_cffi_f_\w+)\(PyObject \*self, PyObject \*\w+\)\n\{(.*?)\n\}\n",
                          src, re.S)
    names = {n for n, _ in wrappers}
    # every drawing call of the glue and the core has a wrapper ...
    for fn in ("rastpy_fill_polygon", "rastpy_mask_polygon", "rastpy_fill_triangles", "rastpy_snap_points",
               "rast_draw_line", "rast_draw_polyline", "rast_line_pixels", "rast_point_in_triangle"):
        assert "_cffi_f_" + fn in names, fn
    # ... and every wrapper releases the GIL around its call
    held = [n for n, body in wrappers if "Py_BEGIN_ALLOW_THREADS" not in body]
    assert not held, held


# ---- every drawing entry point, single-threaded and in threads ------------------

def _jobs():
    """(name, call) pairs; call() returns something comparable with ==
    (arrays as bytes).  Each canvas job draws into a canvas of its own."""
    rng = np.random.default_rng(7)
    polys = [rng.uniform(-20, 220, (int(rng.integers(3, 40)), 2)) for _ in range(12)]
    tris = rng.uniform(-10, 210, (300, 3, 2))
    lines = rng.uniform(-30, 230, (60, 2, 2))
    jobs = []
    for i, p in enumerate(polys):
        alg = ("aet", "xscan", "edgeflag", "winding")[i % 4]
        jobs.append(("polygon_mask %d %s" % (i, alg),
                     lambda p=p, alg=alg: rastrum.polygon_mask(p, (200, 200), rule="nonzero",
                                                               algorithm=alg).tobytes()))
        jobs.append(("polygon_mask evenodd %d" % i,
                     lambda p=p, alg=("fence", "edgefill")[i % 2]:
                     rastrum.polygon_mask([p, p[::-1] * 0.5 + 50], (200, 200), algorithm=alg).tobytes()))

    def fill_polygon():
        c = rastrum.Canvas((200, 200), format="rgb888")
        for k, p in enumerate(polys):
            c.fill_polygon(p, (k * 20, 255 - k * 20, 7), rule="nonzero", boundary=("exact", "closed")[k % 2])
        return c.array.tobytes()

    def fill_triangles():
        c = rastrum.Canvas((200, 200), format="gray8")
        for k, alg in enumerate(("edge", "sweep", "edgeflag")):
            c.fill_triangles(tris[k::3], 50 * (k + 1), algorithm=alg)
        return c.array.tobytes()

    def fill_triangle():
        c = rastrum.Canvas((200, 200), format="rgba8888")
        for k, t in enumerate(tris[:40]):
            c.fill_triangle(t, (k, 2 * k, 3 * k, 255))
        return c.array.tobytes()

    def line_and_polyline():
        c = rastrum.Canvas((200, 200), format="gray8")
        for k, (a, b) in enumerate(lines):
            c.line(a, b, k + 1, algorithm=("bresenham", "dda")[k % 2])
        c.polyline(lines.reshape(-1, 2)[:30], 255, closed=True)
        return c.array.tobytes()

    def line_pixels():
        return b"".join(rastrum.line_pixels(a, b, clip=(0, 0, 200, 200)).tobytes() for a, b in lines)

    def point_in_triangle():
        pts = rng_pts
        return tuple(rastrum.point_in_triangle(p, tris[k % 300], method=m)
                     for k, p in enumerate(pts) for m in ("owner", "barycentric"))

    rng_pts = np.random.default_rng(3).uniform(-10, 210, (100, 2))
    jobs += [("Canvas.fill_polygon", fill_polygon), ("Canvas.fill_triangles", fill_triangles),
             ("Canvas.fill_triangle", fill_triangle), ("Canvas.line/polyline", line_and_polyline),
             ("line_pixels", line_pixels), ("point_in_triangle", point_in_triangle),
             ("triangles_mask count", lambda: rastrum.triangles_count(tris, (200, 200),
                                                                     algorithm="sweep").tobytes())]
    return jobs


def test_threads_draw_what_one_thread_draws():
    jobs = _jobs()
    expected = {name: call() for name, call in jobs}  # single-threaded
    nthreads, rounds = 4, 3
    results = [dict() for _ in range(nthreads)]
    errors = []
    start = threading.Barrier(nthreads)

    def work(k):
        try:
            order = list(range(len(jobs)))
            rng = np.random.default_rng(100 + k)
            start.wait()  # all threads at once
            for r in range(rounds):
                rng.shuffle(order)  # each thread in its own order
                for i in order:
                    name, call = jobs[i]
                    got = call()
                    if results[k].setdefault(name, got) != got:
                        results[k][name] = None  # differs from its own earlier run
        except Exception as e:  # pragma: no cover - reported below
            errors.append(repr(e))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(nthreads)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for k in range(nthreads):
        assert set(results[k]) == set(expected)
        bad = [name for name in expected if results[k][name] != expected[name]]
        assert not bad, "thread %d differs from one thread on %s" % (k, bad)


def test_threads_share_a_canvas_on_disjoint_rows():
    """Threads may draw into one canvas at once where their pixels do not
    overlap (the C calls keep no shared state): each thread owns a band of
    rows, and the result equals drawing the bands one after another."""
    rng = np.random.default_rng(11)
    bands = [(k * 50, k * 50 + 50) for k in range(4)]
    shapes = [[rng.uniform((0, y0), (200, y1), (12, 2)) for _ in range(25)] for y0, y1 in bands]
    want = rastrum.Canvas((200, 200), format="gray8")
    for k, polys in enumerate(shapes):
        for p in polys:
            want.fill_polygon(p, 10 * k + 1, rule="nonzero")
    got = rastrum.Canvas((200, 200), format="gray8")
    start = threading.Barrier(len(bands))

    def work(k):
        view = rastrum.Canvas.wrap(got.array[bands[k][0]:bands[k][1]])
        start.wait()
        for p in shapes[k]:
            view.fill_polygon(p - (0, bands[k][0]), 10 * k + 1, rule="nonzero")

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(bands))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert np.array_equal(got.array, want.array)

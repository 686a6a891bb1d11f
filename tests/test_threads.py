"""The C calls run without the GIL, and threads drawing at once agree."""

import threading

import numpy as np

import rastrum
from rastrum._native import lib


def test_c_calls_release_the_gil():
    # PyGILState_Check() from inside a C call: 0 means the GIL was released.
    assert lib.rastpy_gil_held() == 0


def test_threads_draw_the_same_pixels():
    rng = np.random.default_rng(7)
    polys = [rng.uniform(-20, 220, (rng.integers(3, 40), 2)) for _ in range(40)]
    expected = [rastrum.polygon_mask(p, (200, 200), rule="nonzero") for p in polys]
    results = {}
    canvas_results = {}

    def work(k):
        # Every thread draws every polygon, in its own order.
        order = list(range(len(polys)))
        np.random.default_rng(k).shuffle(order)
        results[k] = {i: rastrum.polygon_mask(polys[i], (200, 200), rule="nonzero") for i in order}
        c = rastrum.Canvas(200, 200, format="gray8")
        for i in order[:10]:
            c.fill_polygon(polys[i], i + 1, rule="nonzero")
        canvas_results[k] = (order[:10], c.array.copy())

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 4
    for k in range(4):
        for i, m in results[k].items():
            assert np.array_equal(m, expected[i])
        order, arr = canvas_results[k]
        want = np.zeros((200, 200), np.uint8)
        for i in order:
            want[expected[i]] = i + 1
        assert np.array_equal(arr, want)

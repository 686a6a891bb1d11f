"""The benchmarks' timer: the median of timed calls, after untimed warm-up
calls (the first calls of a process run slower: every method and peer is
warmed alike)."""

import time


def median_s(f, reps, warm=1):
    """Median wall time in seconds of `reps` calls of f, after `warm`
    untimed ones."""
    for _ in range(warm):
        f()
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return sorted(ts)[len(ts) // 2]

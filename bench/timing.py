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


def medians_interleaved(fs, reps, warm=1, floor_s=1e-3):
    """{name: median seconds per call} of the callables in `fs`, timed in
    turns: each of `reps` rounds calls every f once (a batch, below), so a
    burst of load from elsewhere on a shared machine falls on all of them
    alike instead of on whichever happened to be timed then, and ratios of
    the medians compare calls made under the same conditions.

    A call shorter than `floor_s` is timed as a batch of calls lasting about
    `floor_s` (the count fixed per f from its warm-up calls), its time the
    batch's over the count: a single 30-microsecond sample is at the mercy
    of one interrupt.  Every f is batched by the same rule."""
    names = list(fs)
    count = {}
    for name in names:
        f = fs[name]
        t = time.perf_counter()
        for _ in range(max(1, warm)):
            f()
        one = (time.perf_counter() - t) / max(1, warm)
        count[name] = max(1, min(1000, int(floor_s / one) if one > 0 else 1000))
    ts = {name: [] for name in names}
    for _ in range(reps):
        for name in names:
            f, n = fs[name], count[name]
            t = time.perf_counter()
            for _ in range(n):
                f()
            ts[name].append((time.perf_counter() - t) / n)
    return {name: sorted(v)[len(v) // 2] for name, v in ts.items()}

"""pycocotools' polygon rule: memory, rastrum against pycocotools.

    python bench/coco_memory.py [W]

The case of docs/bad-input.md (finding 4): 100 vertices zig-zagging across
a 1 x W mask (every edge crosses every column: 100 W toggles), and the same
ring on a 1 x 0 mask.  Each library runs in a fresh interpreter; printed:
the growth of its peak RSS (ru_maxrss) over the call, CPU seconds, and
whether the counts strings are equal.  W = 1,600,000 (the default) needs
about 8.2 GB for pycocotools.
"""
import subprocess
import sys

RUN = """
import resource, sys, time
W, lib = int(sys.argv[1]), sys.argv[2]
if lib == "rastrum":
    from rastrum import coco as m
else:
    from pycocotools import mask as m
zig = []
for k in range(100):
    zig += [0.0 if k % 2 == 0 else float(W), -0.4 + 0.021 * k]
for w in (W, 0):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t = time.process_time()
    r = m.frPyObjects([zig], 1, w)[0]
    print(w, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before, time.process_time() - t,
          r["counts"].decode())
"""


def main():
    W = int(sys.argv[1]) if len(sys.argv) > 1 else 1600000
    got = {}
    for lib in ("rastrum", "pycocotools"):
        out = subprocess.run([sys.executable, "-c", RUN, str(W), lib], capture_output=True, text=True, check=True)
        for line in out.stdout.splitlines():
            w, kb, cpu, counts = line.split()
            got[lib, w] = counts
            print("%-12s 1 x %-8s RSS +%9.1f MB  %6.2f s CPU  %s" % (lib, w, int(kb) / 1024, float(cpu), counts))
    for w in (str(W), "0"):
        print("1 x %s: same counts as pycocotools: %s" % (w, got["rastrum", w] == got["pycocotools", w]))


if __name__ == "__main__":
    main()

"""Write a path for bench/cbench_flatten.c: bench_paths.py's paragraph
(default) or a seeded text, its points on the 1/2^bits grid and its
default tolerance there, as the fill takes them (python/glue/pathfill.c).

    python bench/dump_path.py OUT [--seed N] [--bits 8]

The file: "NVERBS NPOINTS TOLERANCE", the verbs, then the points' x y.
"""

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bench_paths  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=None, help="bench_paths.seeded_text(N) instead")
    ap.add_argument("--bits", type=int, default=8)
    a = ap.parse_args(argv)
    p = bench_paths.paragraph() if a.seed is None else bench_paths.paragraph(*bench_paths.seeded_text(a.seed))
    pts, verbs = p._fixed(a.bits)
    tol = p._grid_tolerance(None, a.bits, a.bits)
    with open(a.out, "w") as f:
        f.write("%d %d %d\n" % (len(verbs), len(pts), tol))
        f.write(" ".join(str(int(v)) for v in verbs) + "\n")
        f.write(" ".join("%d %d" % (int(x), int(y)) for x, y in pts) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())

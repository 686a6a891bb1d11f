"""Write a family's scene (bench/families.py) for build/cbench_scale.

    python bench/dump_scene.py FAMILY SEED SIZE OUT

so that one C call of it is counted under callgrind without Python
(`valgrind --tool=callgrind --toggle-collect=draw build/cbench_scale @OUT
0 accumulate`).  The file, little-endian: b"RSC1", then uint32 kind (0 one
polygon call, 1 one triangle batch, 2 a call a ring: the "loop" family),
rule (0 non-zero, 1 even-odd), size, nrings, npoints, the ring sizes
(uint32 each) and the vertices (int32 x, y in 1/256 px, rounded half to
even, as numpy rounds).
"""

import os
import struct
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import families  # noqa: E402


def main(argv):
    fam, seed, size, out = argv[0], int(argv[1]), int(argv[2]), argv[3]
    sc = families.FAMILIES[fam](seed, size)
    kind = {"poly": 0, "tris": 1, "loop": 2}[sc.kind]
    rings = [np.asarray(r, np.float64).reshape(-1, 2) for r in sc.rings]
    pts = np.concatenate(rings) if rings else np.zeros((0, 2))
    fixed = np.rint(pts * 256).astype("<i4")
    with open(out, "wb") as f:
        f.write(b"RSC1")
        f.write(struct.pack("<5I", kind, 0 if sc.rule == "nonzero" else 1, size, len(rings), len(fixed)))
        f.write(np.array([len(r) for r in rings], "<u4").tobytes())
        f.write(fixed.tobytes())
    print(f"{fam} seed {seed} size {size}: {len(rings)} rings, {len(fixed)} vertices -> {out}")


if __name__ == "__main__":
    main(sys.argv[1:])

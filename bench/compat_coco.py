"""rastrum.coco against pycocotools on random objects, bit for bit.

    python bench/compat_coco.py [N] [seed]

Each object: random parts (polygons of 1..12 points: tiny, degenerate,
past the image edge, coordinates on the 1/5 grid where pycocotools'
doubles tie, large coordinates), image sizes 0..300 (with a side of 0 only
frPyObjects is compared: pycocotools' counts then pass the empty mask and
its merge of them never returns).  Checks frPyObjects
(each part; lists and single objects; boxes), merge, decode, area, toBbox,
iou (with iscrowd) and encode of the decoded masks against pycocotools.
Prints the number of objects and mismatches; exits 1 on any mismatch.
"""
import sys

import numpy as np
import pycocotools.mask as M

from rastrum import coco as C


def random_part(rng, h, w):
    kind = rng.integers(0, 6)
    k = int(rng.choice([1, 2, 3, 3, 4, 5, 6, 8, 12]))
    if kind == 0:    # on the 1/5 grid: the walk's doubles tie
        xy = rng.integers(-10, 5 * max(w, 1) + 10, 2 * k) / 5.0
    elif kind == 1:  # tiny
        c = rng.uniform(-2, max(w, h) + 2, 2)
        xy = (c[None, :] + rng.uniform(-1.5, 1.5, (k, 2))).ravel()
    elif kind == 2:  # large coordinates (rarely up to 1e6: pycocotools walks them)
        xy = rng.uniform(-1, 1, 2 * k) * (1e6 if rng.random() < 0.01 else 2e4)
    elif kind == 3:  # degenerate: repeated points, collinear
        base = rng.uniform(-5, max(w, h) + 5, (max(k // 2, 1), 2))
        xy = base[rng.integers(0, len(base), k)].ravel()
    elif kind == 4:  # integers and halves
        xy = rng.integers(-20, max(w, h) + 20, 2 * k) / rng.choice([1.0, 2.0, 10.0])
    else:            # general
        xy = rng.uniform(-0.3 * w - 5, 1.3 * w + 5, 2 * k)
        xy[1::2] = rng.uniform(-0.3 * h - 5, 1.3 * h + 5, k)
    return [float(v) for v in xy]


def check(n, seed):
    rng = np.random.default_rng(seed)
    bad = 0
    done = 0
    while done < n:
        h = int(rng.integers(0, 300)) if rng.random() < 0.05 else int(rng.integers(1, 120))
        w = int(rng.integers(0, 300)) if rng.random() < 0.05 else int(rng.integers(1, 120))
        objs = [[random_part(rng, h, w) for _ in range(int(rng.integers(1, 4)))] for _ in range(8)]
        for parts in objs:  # a first part of 4 numbers would be a box to pycocotools
            parts.sort(key=len, reverse=True)
            if len(parts[0]) <= 4:
                first = list(parts[0])
                while len(first) <= 4:
                    first += [first[0] + 1.0, first[1] + 0.4]
                parts.insert(0, first)
        done += len(objs)
        if done % 5000 < len(objs):
            print("... %d objects, %d mismatches" % (done, bad), flush=True)
        for parts in objs:
            a, b = M.frPyObjects(parts, h, w), C.frPyObjects(parts, h, w)
            if a != b:
                bad += 1
                print("frPyObjects", h, w, parts, a, b)
                continue
            if h * w == 0:
                # pycocotools' counts then pass the empty mask (its unsigned
                # w - 1 wraps) and its merge of them loops forever
                continue
            ma, mb = M.merge(a), C.merge(b)
            if ma != mb:
                bad += 1
                print("merge", h, w, parts)
            if h * w and not np.array_equal(M.decode(ma), C.decode(mb)):
                bad += 1
                print("decode", h, w, parts)
        if h * w == 0:
            continue
        rl = [M.merge(M.frPyObjects(p, h, w)) for p in objs]
        if not (np.array_equal(M.area(rl), C.area(rl)) and np.array_equal(M.toBbox(rl), C.toBbox(rl))):
            bad += 1
            print("area/toBbox", h, w, objs)
        crowd = list(rng.integers(0, 2, len(rl)))
        ia, ib = M.iou(rl[:4], rl[4:], crowd[4:]), C.iou(rl[:4], rl[4:], crowd[4:])
        if not np.array_equal(np.asarray(ia), np.asarray(ib)):
            bad += 1
            print("iou", h, w, objs, ia, ib)
        if h * w:
            masks = M.decode(rl)
            if M.encode(masks) != C.encode(masks):
                bad += 1
                print("encode", h, w)
        boxes = rng.uniform(-10, 100, (4, 4))
        if M.frPyObjects(boxes, h, w) != C.frPyObjects(boxes, h, w):
            bad += 1
            print("boxes", h, w, boxes.tolist())
    return done, bad


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    done, bad = check(n, seed)
    print("%d objects, %d mismatches" % (done, bad))
    sys.exit(1 if bad else 0)

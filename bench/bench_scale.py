"""Speed on scene families, worst seed per family, and growth exponents.

    python bench/bench_scale.py [--quick] [--families text,map,...] [--sizes 512,2048]
                                [--seeds 10] [--reps 5] [--limit 10] [--json out.json]
                                [--methods binary,area]

For every family of bench/families.py, size and seed it times each rastrum
method -- binary (polygon_mask / triangles_mask, the new bool mask a user
gets, no conversion inside the clock; Canvas.fill_polygon in
the loop family), "accumulate", "ss4", "area" (polygon_coverage /
triangles_coverage; Canvas.fill_polygon(aa=...) in the loop) -- and the
peers that fit (Blend2D's anti-aliased fill with its path built before
the clock starts, skia, cv2.fillPoly for binary), medians of --reps calls
in one process, each as a ratio to Blend2D's time on the same scene.  The
drawers of a scene are timed in turns (each round calls each once, a call
under a millisecond timed as a batch of about a millisecond: see
bench/timing.py), so load from elsewhere falls on all of them alike.  The
table gives, per family and size, the WORST seed's ratio per method.

Every output is checked in the same run against rastrum's exact result
(the binary rule's mask for binary fills; "area" at the finest subpixel_bits, up to 16, the coordinates fit, for
coverage, or ss16 where "area" passes the time limit): pixels off (by more
than one level of 255 for coverage, any difference for a mask) and the max
error are reported, and a draw whose total coverage is not within 10% of
the exact total is marked WRONG, so that an empty or misplaced draw cannot
win.  A call that takes longer than --limit seconds (run first in a forked
child) is reported as "> limit" and not timed.

The doubling series (families.SERIES) give each method's growth exponent:
the least-squares slope of log(time) against log(2^k).

Wall-clock timings on a shared machine are noisy: compare ratios within
one run, and rerun on a quiet one for figures to quote.
"""

import argparse
import json
import math
import multiprocessing
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import families  # noqa: E402
from timing import medians_interleaved  # noqa: E402
import rastrum  # noqa: E402

METHODS = ("binary", "accumulate", "ss4", "area")


# ---- drawers: each prepare(scene) -> draw() returning a uint8 (H, W) image ----------

def rastrum_prep(method):
    def prep(sc):
        n = sc.size
        if sc.kind == "loop":
            aa = None if method == "binary" else method

            def draw():
                c = rastrum.Canvas.wrap(np.zeros((n, n), np.uint8))
                for r in sc.rings:
                    c.fill_polygon(r, 255, rule=sc.rule, aa=aa)
                return c.array
            return draw
        if sc.kind == "tris":
            tris = sc.tris()
            if method == "binary":
                return lambda: rastrum.triangles_mask(tris, (n, n))  # bool: check() scales it
            return lambda: rastrum.triangles_coverage(tris, (n, n), method=method)
        rings = sc.rings
        if method == "binary":
            return lambda: rastrum.polygon_mask(rings, (n, n), rule=sc.rule)  # bool: check() scales it
        return lambda: rastrum.polygon_coverage(rings, (n, n), rule=sc.rule, method=method)
    return prep


def _groups(sc):
    """The paths a peer fills: one per ring in the loop family, else one."""
    return [[r] for r in sc.rings] if sc.kind == "loop" else [sc.rings]


def peers():
    """name -> (prepare, binary?) for the peers installed."""
    from bench_coverage import _trace
    out = {}
    try:
        import blend2d as b

        def blend2d_prep(sc):
            n = sc.size
            paths = []
            for g in _groups(sc):  # built before the clock starts
                p = b.BLPath()
                _trace(g, p.move_to, p.line_to, p.close)
                paths.append(p)
            rule = b.BLFillRule.NON_ZERO if sc.rule == "nonzero" else b.BLFillRule.EVEN_ODD

            def draw():
                img = b.BLImage(n, n, b.BLFormat.A8)
                ctx = b.BLContext(img)
                ctx.clear_all()
                ctx.fill_rule = rule
                ctx.set_fill_style((255, 255, 255, 255))
                for p in paths:
                    ctx.fill_path(p)
                ctx.flush()
                return img.getDataAsNumPy().reshape(n, n)
            return draw
        out["Blend2D"] = (blend2d_prep, False)
    except ImportError:
        pass
    try:
        import skia

        def skia_prep(sc):
            n = sc.size
            paths = []
            for g in _groups(sc):
                p = skia.Path()
                p.setFillType(skia.PathFillType.kWinding if sc.rule == "nonzero" else skia.PathFillType.kEvenOdd)
                _trace(g, p.moveTo, p.lineTo, p.close)
                paths.append(p)
            paint = skia.Paint(AntiAlias=True, Color=skia.ColorWHITE)

            def draw():
                arr = np.zeros((n, n), np.uint8)
                surface = skia.Surface(arr, colorType=skia.ColorType.kAlpha_8_ColorType)
                canvas = surface.getCanvas()
                for p in paths:
                    canvas.drawPath(p, paint)
                return arr
            return draw
        out["skia"] = (skia_prep, False)
    except ImportError:
        pass
    try:
        import cv2

        def cv2_prep(sc):
            n = sc.size
            if sc.kind == "loop":  # the user's loop: float -> int32 in it
                def draw():
                    img = np.zeros((n, n), np.uint8)
                    for r in sc.rings:
                        cv2.fillPoly(img, [np.round(r - 0.5).astype(np.int32)], 255)
                    return img
                return draw
            # one call, 4 fractional bits; cv2 has no fill rule (even-odd
            # within a call) and samples at pixel corners: shift by 1/2
            pts = [np.round((np.asarray(r) - 0.5) * 16).astype(np.int32) for r in sc.rings]

            def draw():
                img = np.zeros((n, n), np.uint8)
                if sc.kind == "tris":
                    for p in pts:  # a union: each triangle its own call
                        cv2.fillPoly(img, [p], 255, shift=4)
                else:
                    cv2.fillPoly(img, pts, 255, shift=4)
                return img
            return draw
        out["cv2"] = (cv2_prep, True)
    except ImportError:
        pass
    return out


# ---- the exact result, checks, time limit --------------------------------------------

def reference(sc, limit):
    """(exact mask as 0/255 uint8, exact coverage x 255 as float64, its name)."""
    n = sc.size
    # the finest grid the coordinates fit (16 bits up to +-2048 px; a map's
    # off-canvas rings need fewer), at most 16, the most "area" takes
    most = max(float(np.abs(np.concatenate([np.asarray(r).reshape(-1, 2) for r in sc.rings])).max()), 1.0)
    bits = int(min(16, math.floor(math.log2((2 ** 27 - 1) / (most + 1)))))
    if sc.kind == "tris":
        tris = sc.tris()
        mask = rastrum.triangles_mask(tris, (n, n)).view(np.uint8) * np.uint8(255)
        area = lambda: rastrum.triangles_coverage(tris, (n, n), subpixel_bits=bits, dtype=np.float64)  # noqa: E731
        ss16 = lambda: rastrum.triangles_coverage(tris, (n, n), method="ss16", subpixel_bits=min(bits, 12),  # noqa: E731
                                                  dtype=np.float64)
    else:
        rule = sc.rule if sc.kind == "poly" else "nonzero"
        mask = rastrum.polygon_mask(sc.rings, (n, n), rule=rule).view(np.uint8) * np.uint8(255)
        area = lambda: rastrum.polygon_coverage(sc.rings, (n, n), rule=rule, subpixel_bits=bits,  # noqa: E731
                                                dtype=np.float64)
        ss16 = lambda: rastrum.polygon_coverage(sc.rings, (n, n), rule=rule, method="ss16",  # noqa: E731
                                                subpixel_bits=min(bits, 12), dtype=np.float64)
    if within_limit(area, limit):
        return mask, area() * 255, "area, %d bits" % bits
    return mask, ss16() * 255, "ss16 (area past the limit)"


def check(out, ref, binary):
    """(pixels off, max error in 1/255, wrong?) of an output against the
    exact result: wrong when the total coverage is off by more than 10%.
    A bool mask (what polygon_mask / triangles_mask return, timed as the
    user gets it) counts as 0/255."""
    if getattr(out, "dtype", None) == np.bool_:
        out = out.view(np.uint8) * np.uint8(255)
    out = np.asarray(out, np.float64)
    err = np.abs(out - ref)
    off = int((err > 0).sum()) if binary else int((err > 1).sum())
    total = float(ref.sum())
    # a binary fill by another rule (cv2 takes the pixels its outline
    # touches, which on 3-px shapes is most of them) gets more slack
    slack = 0.5 if binary else 0.1
    wrong = out.shape != ref.shape or abs(float(out.sum()) - total) > slack * max(total, 255.0)
    return off, float(err.max()) if err.size else 0.0, bool(wrong)


def _child(f):
    try:
        f()
    except Exception:
        os._exit(1)  # the parent's own call raises it again, with its message
    os._exit(0)


def within_limit(f, limit):
    """Does one call of f finish within `limit` seconds?  Run in a forked
    child (a C call cannot be interrupted), killed at the limit."""
    if limit is None or limit <= 0:
        return True
    ctx = multiprocessing.get_context("fork")
    p = ctx.Process(target=_child, args=(f,))
    p.start()
    p.join(limit)
    if p.is_alive():
        p.kill()
        p.join()
        return False
    return p.exitcode == 0


# ---- runs ---------------------------------------------------------------------------

def drawers(extra_peers=None):
    out = {"rastrum " + m: (rastrum_prep(m), m == "binary") for m in METHODS}
    out.update(peers())
    if extra_peers:
        out.update(extra_peers)
    return out


def run_scene(sc, draw_set, reps, limit, slow_first=True):
    """{drawer: {"s": median seconds or None (past the limit), "off", "max", "wrong"}}"""
    mask, cov, refname = reference(sc, limit)
    res = {"_ref": refname}
    timed = {}
    for name, (prep, binary) in draw_set.items():
        try:
            f = prep(sc)
        except Exception as exc:  # a peer that cannot draw this scene
            res[name] = {"s": None, "error": str(exc)}
            continue
        if slow_first and not within_limit(f, limit):
            res[name] = {"s": None, "limit": limit}
            continue
        out = f()
        off, mx, wrong = check(out, mask if binary else cov, binary)
        res[name] = {"s": None, "off": off, "max": mx, "wrong": wrong}
        timed[name] = f
    # every drawer that passed is timed in turns, round by round (timing.py)
    for name, s in medians_interleaved(timed, reps).items():
        res[name]["s"] = s
    return res


def fmt_ratio(r, base, limit):
    if r.get("s") is None:
        return "> %gs" % limit if "limit" in r else "-"
    v = "%.2f" % (r["s"] / base) if base else "%.3gms" % (r["s"] * 1e3)
    return v + (" WRONG" if r.get("wrong") else "")


def exponent(ts):
    """Least-squares slope of log2(time) against the step k."""
    ks = [k for k, t in enumerate(ts) if t]
    if len(ks) < 2:
        return float("nan")
    y = [math.log2(ts[k]) for k in ks]
    return float(np.polyfit(ks, y, 1)[0])


def main(argv=None, extra_peers=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="2 seeds, 128 px, 2 reps, 3 series steps (CI smoke)")
    ap.add_argument("--families", default=None, help="comma-separated: " + ",".join(families.FAMILIES))
    ap.add_argument("--sizes", default=None, help="comma-separated canvas sizes (default 512,2048; --quick 128)")
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--limit", type=float, default=10.0, help="seconds a call may take (default 10)")
    ap.add_argument("--steps", type=int, default=5, help="doubling steps per series")
    ap.add_argument("--no-series", action="store_true")
    ap.add_argument("--span-count", type=int, default=None,
                    help="canvas-spanning triangles in the span family (default %d)" % families.SPAN_COUNT)
    ap.add_argument("--json", default=None, help="write every measurement here (rewritten after each family)")
    ap.add_argument("--methods", default=None,
                    help="comma-separated rastrum methods to time (default all: %s); the peers always run"
                    % ",".join(METHODS))
    args = ap.parse_args(argv)
    if args.span_count:
        families.SPAN_COUNT = args.span_count
    seeds, reps, steps = args.seeds, args.reps, args.steps
    sizes = "512,2048"
    if args.quick:
        sizes, seeds, reps, steps = "128", 2, 2, 3
    sizes = [int(s) for s in (args.sizes or sizes).split(",")]
    names = args.families.split(",") if args.families else list(families.FAMILIES)
    unknown = [n for n in names if n not in families.FAMILIES]
    if unknown:
        ap.error("unknown families %s; known: %s" % (unknown, ", ".join(families.FAMILIES)))
    draw_set = drawers(extra_peers)
    if args.methods:
        keep = args.methods.split(",")
        if set(keep) - set(METHODS):
            ap.error("unknown methods %s; known: %s" % (sorted(set(keep) - set(METHODS)), ", ".join(METHODS)))
        draw_set = {k: v for k, v in draw_set.items() if not k.startswith("rastrum ") or k[8:] in keep}
    cols = list(draw_set)
    record = {"families": {}, "series": {}, "limit": args.limit}
    rows = []
    for fam in names:
        for size in sizes:
            worst = {}
            per_seed = []
            for seed in range(seeds):
                try:
                    sc = families.FAMILIES[fam](seed, size)
                except Exception as exc:
                    print("(%s skipped: %s)" % (fam, exc))
                    break
                res = run_scene(sc, draw_set, reps, args.limit)
                base = res.get("Blend2D", {}).get("s")
                per_seed.append({"seed": seed, "edges": sc.edges, "rings": len(sc.rings), "base_s": base,
                                 "results": res})
                for name in cols:
                    r = res[name]
                    ratio = r["s"] / base if (r.get("s") and base) else (math.inf if r.get("s") is None else
                                                                          r["s"])
                    if name not in worst or ratio > worst[name][0] or r.get("wrong"):
                        if not (worst.get(name, (0, {}))[1].get("wrong") and not r.get("wrong")):
                            worst[name] = (ratio, r, base)
                print("  %s %d seed %d: %d rings, %d edges, ref %s, Blend2D %s" % (
                    fam, size, seed, len(sc.rings), sc.edges, res["_ref"],
                    "%.3f ms" % (base * 1e3) if base else "-"), flush=True)
            if not per_seed:
                continue
            record["families"]["%s@%d" % (fam, size)] = per_seed
            if args.json:  # after every family: a long run (2048 x 2048) keeps what it finished
                _write(args.json, record)
            rows.append((fam, size, per_seed[0]["rings"], per_seed[0]["edges"],
                         {n: fmt_ratio(w[1], w[2], args.limit) for n, w in worst.items()},
                         {n: (w[1].get("off"), w[1].get("max")) for n, w in worst.items()}))
    print("\n## Worst seed per family: time / Blend2D's AA time (medians of %d; %d seeds)\n" % (reps, seeds))
    print("| family | size | rings / edges | " + " | ".join(cols) + " |")
    print("|---" * (3 + len(cols)) + "|")
    for fam, size, nr, ne, ratios, _ in rows:
        print("| %s | %d | %d / %d | %s |" % (fam, size, nr, ne, " | ".join(ratios.get(c, "-") for c in cols)))
    print("\nPixels off / max error (1/255) of the worst seed's output against the exact result:\n")
    print("| family | size | " + " | ".join(cols) + " |")
    print("|---" * (2 + len(cols)) + "|")
    for fam, size, nr, ne, _, errs in rows:
        print("| %s | %d | %s |" % (fam, size, " | ".join(
            "%d / %.0f" % errs[c] if errs.get(c, (None,))[0] is not None else "-" for c in cols)))
    if not args.no_series:
        size = sizes[0]
        print("\n## Growth exponents at %d x %d (time ~ quantity^e over %d doublings)\n" % (size, size, steps - 1))
        print("| series | " + " | ".join(cols) + " |")
        print("|---" * (1 + len(cols)) + "|")
        for sname, make in families.SERIES.items():
            ts = {c: [] for c in cols}
            for k in range(steps):
                res = run_scene(make(k, size), draw_set, reps, args.limit)
                for c in cols:
                    ts[c].append(res[c].get("s") if not res[c].get("wrong") else None)
            record["series"][sname] = ts
            print("| %s | %s |" % (sname, " | ".join("%.2f" % exponent(ts[c]) for c in cols)), flush=True)
    if args.json:
        _write(args.json, record)
        print("\nwrote %s" % args.json)
    return record


def _write(path, record):
    with open(path + ".tmp", "w") as fh:
        json.dump(record, fh, indent=1, default=float)
    os.replace(path + ".tmp", path)


if __name__ == "__main__":
    main()

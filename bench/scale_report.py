"""The speed table and frontier plot of the README, from a bench_scale.py run.

    python bench/bench_scale.py --json bench/results.json
    python bench/scale_report.py bench/results.json [--markdown t.md] [--plot docs/scale_frontier.png]

Reads the measurements ``bench_scale.py --json`` wrote (every seed of every
family, every method and peer, each output's error against the exact
result) and prints, per family and size (a table per canvas size), the WORST seed's time as a ratio
to Blend2D's anti-aliased fill for each rastrum method, marked against the
speed targets the library holds itself to (docs/benchmarks.md):

- binary at most 0.5x Blend2D's time;
- "accumulate" at most 1.0x;
- "area" at most 1.0x where no two shapes overlap, and at most 3x
  "accumulate"'s time (the same seed) where thousands of small shapes do;
- "ss4" at most 3x binary's time (the same seed);

and the growth exponents of the doubling series (at most 1.1).  A ratio
that misses its target is printed with a trailing ``!``; a draw whose
output was wrong is ``WRONG`` and always misses.

``--plot`` draws the speed/accuracy frontier: each anti-aliasing method's
worst-seed time ratio against its max error in levels of 255, one point per
family and size (matplotlib); binary fills, exact for their own rule, are
in the table only.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Dict, List, Optional, Tuple

#: families whose shapes overlap one another (the rest do not)
OVERLAPPING = ("tri3k", "tri10k", "span")

METHODS = ("binary", "accumulate", "ss4", "area")
GROWTH_LIMIT = 1.1


def _ratio(entry: dict, name: str) -> Optional[float]:
    """time(name) / Blend2D's time for one seed, None where not measured."""
    r = entry["results"].get(name, {})
    base = entry.get("base_s")
    if not r.get("s") or not base:
        return None
    return r["s"] / base


def _relative(entry: dict, name: str, other: str) -> Optional[float]:
    a, b = entry["results"].get(name, {}), entry["results"].get(other, {})
    if not a.get("s") or not b.get("s"):
        return None
    return a["s"] / b["s"]


def worst(seeds: List[dict], method: str, family: str) -> Tuple[str, bool]:
    """(cell text, target met) for one method over one family's seeds."""
    name = "rastrum " + method
    wrong = any(e["results"].get(name, {}).get("wrong") for e in seeds)
    timed_out = any("limit" in e["results"].get(name, {}) for e in seeds)
    ratios = [_ratio(e, name) for e in seeds]
    if timed_out:
        return "> limit !", False
    if any(r is None for r in ratios) or not ratios:
        return "-", True
    w = max(ratios)
    if method == "binary":
        ok = w <= 0.5
        extra = ""
    elif method == "accumulate":
        ok = w <= 1.0
        extra = ""
    elif method == "ss4":
        rel = max(_relative(e, name, "rastrum binary") or math.inf for e in seeds)
        ok = rel <= 3.0
        extra = " (%.1fx bin)" % rel
    else:  # area
        if family in OVERLAPPING:
            rel = max(_relative(e, name, "rastrum accumulate") or math.inf for e in seeds)
            ok = rel <= 3.0
            extra = " (%.1fx acc)" % rel
        else:
            ok = w <= 1.0
            extra = ""
    text = "%.2f%s" % (w, extra)
    if wrong:
        return text + " WRONG", False
    return text + ("" if ok else " !"), ok


def sizes(record: dict) -> List[int]:
    """The canvas sizes the record holds, smallest first."""
    return sorted({int(key.rsplit("@", 1)[1]) for key in record["families"]})


def table(record: dict, size: Optional[int] = None) -> Tuple[str, int, int]:
    """The Markdown table (of one canvas size, or of all), the number of
    cells and the number meeting their target."""
    lines = ["| family | size | worst rings / edges | binary | \"accumulate\" | \"ss4\" | \"area\" |",
             "|---|---|---|---|---|---|---|"]
    cells = met = 0
    for key, seeds in record["families"].items():
        fam, size_text = key.rsplit("@", 1)
        if size is not None and int(size_text) != size:
            continue
        edges = max(e["edges"] for e in seeds)
        rings = max(e["rings"] for e in seeds)
        row = []
        for m in METHODS:
            text, ok = worst(seeds, m, fam)
            if text != "-":
                cells += 1
                met += ok
            row.append(text)
        lines.append("| %s | %s | %d / %d | %s |" % (fam, size_text, rings, edges, " | ".join(row)))
    return "\n".join(lines), cells, met


def exponent(ts: List[Optional[float]]) -> float:
    """Least-squares slope of log2(time) against the doubling step k."""
    pts = [(k, math.log2(t)) for k, t in enumerate(ts) if t]
    if len(pts) < 2:
        return float("nan")
    n = len(pts)
    mk = sum(k for k, _ in pts) / n
    my = sum(y for _, y in pts) / n
    return sum((k - mk) * (y - my) for k, y in pts) / sum((k - mk) ** 2 for k, _ in pts)


def growth(record: dict) -> str:
    if not record.get("series"):
        return ""
    lines = ["| series | binary | \"accumulate\" | \"ss4\" | \"area\" | Blend2D |",
             "|---|---|---|---|---|---|"]
    for sname, ts in record["series"].items():
        row = []
        for name in ["rastrum " + m for m in METHODS] + ["Blend2D"]:
            e = exponent(ts.get(name, []))
            mark = " !" if name.startswith("rastrum") and not (e <= GROWTH_LIMIT) else ""
            row.append("%.2f%s" % (e, mark))
        lines.append("| %s | %s |" % (sname, " | ".join(row)))
    return "\n".join(lines)


def plot(record: dict, path: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    # binary fills are checked against the binary rule (0 pixels off), not
    # against the exact area, so they have no place on a coverage frontier
    names = ["rastrum " + m for m in METHODS[1:]] + ["Blend2D", "skia", "cv2"]
    marks = dict(zip(names, "s^Dvxp"))
    for name in names:
        xs, ys = [], []
        for seeds in record["families"].values():
            ratios = [_ratio(e, name) for e in seeds]
            if not ratios or any(r is None for r in ratios):
                continue
            xs.append(max(ratios))
            ys.append(max(e["results"][name].get("max") or 0.0 for e in seeds) + 0.1)
        if xs:
            ax.scatter(xs, ys, marker=marks[name], label=name.replace("rastrum ", ""), alpha=0.75)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axvline(1.0, color="0.6", lw=0.8, ls="--")
    ax.set_xlabel("worst seed's time / Blend2D's anti-aliased time (log)")
    ax.set_ylabel("max error, levels of 255 (+0.1, log)")
    ax.set_title("One point per scene family and size: lower left is better")
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})
    print("wrote %s" % path, file=sys.stderr)


def main(argv: Optional[List[str]] = None) -> Dict[str, object]:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json", help="the file bench_scale.py --json wrote")
    ap.add_argument("--markdown", default=None, help="also write the tables here")
    ap.add_argument("--plot", default=None, help="draw the frontier here (PNG; needs matplotlib)")
    args = ap.parse_args(argv)
    with open(args.json) as fh:
        record = json.load(fh)
    out: List[str] = []
    cells = met = 0
    for size in sizes(record):  # a table per canvas size (512 and 2048 x 2048: issue 33)
        seeds = min(len(v) for k, v in record["families"].items() if int(k.rsplit("@", 1)[1]) == size)
        text, c, m = table(record, size)
        cells, met = cells + c, met + m
        out += ["%sWorst of %d seeds per family at %d x %d: time / Blend2D's anti-aliased time "
                "(`!`: misses its target)\n" % ("\n" if out else "", seeds, size, size), text, "",
                "%d of %d cells meet their target." % (m, c)]
    g = growth(record)
    if g:
        out += ["", "Growth exponents (time ~ work^e over the doubling series; target <= %.1f):\n" % GROWTH_LIMIT,
                g]
    doc = "\n".join(out) + "\n"
    sys.stdout.write(doc)
    if args.markdown:
        with open(args.markdown, "w") as fh:
            fh.write(doc)
    if args.plot:
        plot(record, args.plot)
    return {"cells": cells, "met": met}


if __name__ == "__main__":
    main()

"""The figures of README.md and docs/, made by one command (make figures),
and checked for drift (make figures-check, a CI stage).

    python tools/figures.py make                       # write docs/*.png
    python tools/figures.py check [--firmware-log F]   # compare, write nothing

Where each comes from:

- pictures of fills (deterministic: checked pixel for pixel):
    docs/fig3_19.png, fig3_19_textbook.png, boundary_modes.png, holes.png,
    fig3_18_gouraud_rect.png, gouraud_polygon.png,
    mesh_sphere_flat_vs_gouraud.png, mesh_torus_depth.png, seedfill.png,
    coverage.png, paths.png           bench/demo.py (make demo writes them
                                      to out/ with the others)
    docs/coco_rules.png               tools/coco_picture.py
    docs/opacity.png                  tools/opacity_picture.py
    docs/display_gauge.png            examples/display_rgb565.c's PPM
                                      (make display-example), enlarged
- firmware size tables (deterministic for a given arm-none-eabi-gcc:
  checked against what make firmware-check prints):
    README.md "What typical applications link", docs/c.md's table of the
    firmware examples and its per-file sums (Cortex-M0; the rv32 sums only
    when firmware-check built rv32)
- timing tables and the frontier plot (NOT drift-checked: timings vary
  from run to run and machine to machine; each page says which run made
  them): docs/benchmarks.md (bench/bench.py, bench_realdata.py, ...),
  docs/coverage.md and docs/coverage_frontier.png (bench/bench_coverage.py
  --plot), README's speed table, docs/benchmarks.md's scene families and
  docs/scale_frontier.png (bench/bench_scale.py, then bench/scale_report.py
  --plot), docs/gis.md (bench/bench_rasterize.py, bench/bench_zonal.py;
  its accuracy picture docs/gis_accuracy.png from bench/gis_accuracy.py,
  deterministic but minutes of shapely),
  docs/coco.md (bench/bench_coco.py), docs/dask.md (bench/bench_dask.py),
  docs/precision.md (make bench-precision). make bench runs them.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(ROOT, "docs")

# The pictures bench/demo.py writes that the pages show.
DEMO_PICTURES = ["fig3_19.png", "fig3_19_textbook.png", "boundary_modes.png", "holes.png",
                 "fig3_18_gouraud_rect.png", "gouraud_polygon.png", "mesh_sphere_flat_vs_gouraud.png",
                 "mesh_torus_depth.png", "seedfill.png", "coverage.png"]

# (page, a regular expression matching the table row or sentence, the
# firmware-check key whose number the row's last "N B" must equal)
FIRMWARE_ROWS = [
    ("README.md", r"^\|.*`examples/firmware_min\.c`.*\|$", "firmware_min"),
    ("README.md", r"^\|.*`examples/firmware_tri\.c`.*\|$", "firmware_tri"),
    ("README.md", r"^\|.*`examples/firmware_lines\.c`.*\|$", "firmware_lines"),
    ("README.md", r"^\|.*`examples/firmware_gauge\.c`.*\|$", "firmware_gauge"),
    ("README.md", r"^\|.*`examples/display_rgb565\.c`.*\|$", "display_rgb565"),
    ("README.md", r"^\| the same without a header .*\|$", "display_rgb565_full"),
    ("README.md", r"^\| the whole core, every feature .*\|$", "single cortex-m0"),
    ("README.md", r"^\| the calls the core had before anti-aliasing.*\|$", "api_0_1"),
    ("docs/c.md", r"^\| `examples/firmware_min\.c`.*\|$", "firmware_min"),
    ("docs/c.md", r"^\| `examples/firmware_tri\.c`.*\|$", "firmware_tri"),
    ("docs/c.md", r"^\| `examples/firmware_lines\.c`.*\|$", "firmware_lines"),
    ("docs/c.md", r"^\| `examples/firmware_gauge\.c`.*\|$", "firmware_gauge"),
    ("docs/c.md", r"^\| `examples/display_rgb565\.c`.*\|$", "display_rgb565"),
    ("docs/c.md", r"^\| the same without a configuration header .*\|$", "display_rgb565_full"),
    ("docs/c.md", r"^\| every public function, no configuration .*\|$", "whole_api"),
    ("docs/c.md", r"^\| every public function but anti-aliasing.*\|$", "whole_api_pre_aa"),
    ("docs/c.md", r"^\| the whole core, one file, nothing dropped .*\|$", "single cortex-m0"),
    ("docs/c.md", r"^\| the 31 calls the core had before.*\|$", "api_0_1"),
]
# docs/c.md's sentence "per-file sum: A B against B B on Cortex-M0, C B against D B on rv32imac"
SUMS = re.compile(r"per-file sum: ([\d,]+) B against ([\d,]+) B on Cortex-M0, ([\d,]+) B against\s+([\d,]+) B on rv32imac")


def run(args, **kw):
    print("figures: python " + " ".join(os.path.relpath(a, ROOT) if a.startswith(ROOT) else a for a in args[1:]))
    subprocess.run(args, check=True, cwd=ROOT, **kw)


def render(out):
    """Every deterministic picture into out/."""
    run([sys.executable, os.path.join(ROOT, "bench", "demo.py"), "--out", out, "--no-table"],
        stdout=subprocess.DEVNULL)
    run([sys.executable, os.path.join(ROOT, "tools", "coco_picture.py"), os.path.join(out, "coco_rules.png")],
        stdout=subprocess.DEVNULL)
    run([sys.executable, os.path.join(ROOT, "tools", "opacity_picture.py"), os.path.join(out, "opacity.png")],
        stdout=subprocess.DEVNULL)
    display_gauge(os.path.join(out, "display_gauge.png"))
    # docs/paths.png needs matplotlib (the font) and the peers (Blend2D, cairo)
    # beside rastrum: drawn, and so checked, only where they are installed
    paths = ["paths.png"] if os.path.exists(os.path.join(out, "paths.png")) else []
    if not paths:
        print("figures: docs/paths.png not drawn here (needs matplotlib, blend2d-python, pycairo or cairocffi)")
    return DEMO_PICTURES + ["coco_rules.png", "opacity.png", "display_gauge.png"] + paths


def display_gauge(path):
    """docs/display_gauge.png: the frame the display example draws band by
    band (make display-example writes it as a PPM), twice its size, beside
    its anti-aliased gauge four times its size."""
    print("figures: make display-example")
    subprocess.run(["make", "--no-print-directory", "-s", "display-example"], check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL)
    frame = Image.open(os.path.join(ROOT, "build", "display_rgb565.ppm")).convert("RGB")
    whole = frame.resize((frame.width * 2, frame.height * 2), Image.NEAREST)
    gauge = frame.crop((108, 126, 212, 230)).resize((416, 416), Image.NEAREST)
    pic = Image.new("RGB", (whole.width + 16 + gauge.width, whole.height), (255, 255, 255))
    pic.paste(whole, (0, 0))
    pic.paste(gauge, (whole.width + 16, (whole.height - gauge.height) // 2))
    pic.save(path)


def pixels(path):
    return np.asarray(Image.open(path).convert("RGBA"))


def firmware_numbers(log):
    """{key: bytes} from make firmware-check's output."""
    got = {}
    for line in log.splitlines():
        m = re.match(r"^(\w+) cortex-m0: (\d+) B$", line)
        if m:
            got[m.group(1)] = int(m.group(2))
        m = re.match(r"^whole core (\S+): (\d+) B$", line)
        if m:
            got["single " + m.group(1)] = int(m.group(2))
    section = None
    for line in log.splitlines():
        m = re.match(r"^(\S+) \(\S+-gcc ", line)
        if m:
            section = m.group(1)
        m = re.match(r"^  core +(\d+)$", line)
        if m and section:
            got["core " + section] = int(m.group(1))
    return got


def check_firmware(log):
    got = firmware_numbers(log)
    if "single cortex-m0" not in got:
        return ["the firmware-check output has no Cortex-M0 sizes"]
    bad = []
    for page, row, key in FIRMWARE_ROWS:
        text = open(os.path.join(ROOT, page), encoding="utf-8").read()
        lines = [ln for ln in text.splitlines() if re.match(row, ln)]
        if len(lines) != 1:
            bad.append("%s: %d rows match %r (want 1)" % (page, len(lines), row))
            continue
        said = int(re.findall(r"([\d,]+) B", lines[0])[-1].replace(",", ""))
        if key not in got:
            bad.append("%s: firmware-check printed no %s" % (page, key))
        elif said != got[key]:
            bad.append("%s says %s B for %s, firmware-check %s B" % (page, format(said, ","), key,
                                                                        format(got[key], ",")))
    text = open(os.path.join(DOCS, "c.md"), encoding="utf-8").read()
    m = SUMS.search(text)
    if not m:
        bad.append("docs/c.md: the per-file sum sentence is gone")
    else:
        said = [int(g.replace(",", "")) for g in m.groups()]
        for (k, v) in zip(["single cortex-m0", "core cortex-m0", "single rv32imac", "core rv32imac"], said):
            if k in got and got[k] != v:
                bad.append("docs/c.md's per-file sums say %s B for %s, firmware-check %s B"
                           % (format(v, ","), k, format(got[k], ",")))
        if "core rv32imac" not in got:
            print("figures: rv32 not built by firmware-check: docs/c.md's rv32 sums not checked")
    return bad


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["make", "check"])
    ap.add_argument("--firmware-log", help="make firmware-check's output, to check the size tables against")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        names = render(tmp)
        if a.what == "make":
            for n in names:
                shutil.copyfile(os.path.join(tmp, n), os.path.join(DOCS, n))
            print("figures: wrote %d pictures to docs/: %s" % (len(names), ", ".join(names)))
            print("figures: the firmware tables come from make firmware-check, the timing tables and"
                  " docs/coverage_frontier.png from make bench (not remade here)")
            return 0
        bad = []
        for n in names:
            old = os.path.join(DOCS, n)
            if not os.path.exists(old):
                bad.append("docs/%s is missing" % n)
                continue
            p, q = pixels(os.path.join(tmp, n)), pixels(old)
            if p.shape != q.shape:
                bad.append("docs/%s is %dx%d, the script draws %dx%d" % (n, q.shape[1], q.shape[0], p.shape[1],
                                                                         p.shape[0]))
            elif (p != q).any():
                bad.append("docs/%s: %d pixels differ from what the script draws" % (n, int((p != q).any(2).sum())))
        print("figures: %d pictures compared pixel for pixel" % len(names))
    if a.firmware_log:
        with open(a.firmware_log, encoding="utf-8") as f:
            bad += check_firmware(f.read())
        print("figures: %d firmware size rows compared with make firmware-check" % len(FIRMWARE_ROWS))
    for b in bad:
        print("figures: DRIFT: " + b)
    if bad:
        print("figures: run `make figures` (pictures) or copy make firmware-check's sizes into the pages")
        return 1
    print("figures: no drift")
    return 0


if __name__ == "__main__":
    sys.exit(main())

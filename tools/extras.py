"""Say what `make test-py` is about to install, and why (make test prints
this before it installs anything): each extra named in PY_TEST_EXTRAS with
its packages, read from pyproject.toml, and what it is for.

    python tools/extras.py test,gis,compat-test,dask
"""

import os
import re
import sys

try:
    import tomllib  # Python 3.11+
except ImportError:  # older Pythons: the copy pip carries
    from pip._vendor import tomli as tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# What each extra is for (tests/test_release.py checks every extra of
# pyproject.toml has a line here).
WHY = {
    "test": "the test runner and the property-based tests",
    "gis": "rastrum.rasterize's optional inputs: shapely geometries, affine transforms, tqdm progress bars",
    "compat-test": "the peers the compatibility tests compare with pixel for pixel: rasterio "
                   "(rasterize), geopandas, pycocotools (rastrum.coco), exactextract (zonal_stats)",
    "dask": "rastrum.dask: lazy Dask arrays, dask-geopandas input, a LocalCluster, xarray output",
    "bench": "the benchmarks' peers (make bench)",
    "docs": "the documentation site (make docs)",
    "typecheck": "mypy, for make typecheck (an extra issue 37 adds)",
}
# Measured for issue 37 on a fresh Debian machine: what pip downloaded for
# the four extras make test installs.
FULL = ("test", "gis", "compat-test", "dask")
FULL_MB = 722


def main(argv):
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        extras = tomllib.load(f)["project"]["optional-dependencies"]
    asked = [e for e in argv[1].split(",") if e] if len(argv) > 1 else []
    print("make test-py installs rastrum (cffi, numpy, Pillow) and the extras %s:" % ",".join(asked))
    for name in asked:
        if name not in extras:
            sys.exit("tools/extras.py: pyproject.toml has no extra %r" % name)
        names = sorted({re.split(r"[<>=!~;\s\[]", r, 1)[0] for r in extras[name]})
        print("  %-12s %s" % (name + ":", ", ".join(names)))
        print("  %-12s for %s" % ("", WHY.get(name, "(no note)")))
    if set(FULL) <= set(asked):
        print("  about %d MB to download on a fresh machine; `make test-core` installs only the "
              "'test' extra (the tests that need the others skip)" % FULL_MB)


if __name__ == "__main__":
    main(sys.argv)

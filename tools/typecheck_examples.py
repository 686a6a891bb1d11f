"""mypy --strict on every Python example of the README and docs/*.md.

Each ```python block is written as a module of its own (the blocks run in a
fresh namespace each, tests/test_readme.py) into a temporary directory, and
one mypy run checks them all against the rastrum found on the import path
(its py.typed marks it typed).  Usage:

    PYTHONPATH=build/py python tools/typecheck_examples.py [mypy options]

Exit status: mypy's.
"""

import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FENCE = re.compile(r"^```([A-Za-z0-9_+-]*)\n(.*?)^```", re.S | re.M)


def main(argv):
    pages = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
    with tempfile.TemporaryDirectory() as tmp:
        files = []
        for path in pages:
            with open(path, encoding="utf-8") as f:
                found = [code for tag, code in FENCE.findall(f.read()) if tag == "python"]
            stem = re.sub(r"\W", "_", os.path.relpath(path, ROOT)[:-3])
            for k, code in enumerate(found):
                name = os.path.join(tmp, "%s_%d.py" % (stem, k))
                with open(name, "w", encoding="utf-8") as f:
                    f.write(code)
                files.append(name)
        print("mypy --strict on %d examples of %d pages" % (len(files), len(pages)), flush=True)
        # The examples' other libraries are not what is checked here: those
        # without types (geopandas, shapely, dask) are taken as they are.
        cmd = [sys.executable, "-m", "mypy", "--strict", "--no-incremental", "--cache-dir", os.devnull,
               "--ignore-missing-imports", "--untyped-calls-exclude=dask", *argv, *files]
        return subprocess.call(cmd)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

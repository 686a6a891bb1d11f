"""pytest configuration: hypothesis profiles for the rastrum test suite.

Select a profile with the environment variable RASTRUM_HYPOTHESIS_PROFILE:

* ``default`` -- 100 examples per hypothesis test (per parametrization);
* ``ci``      -- the same counts, no example database, derandomised so that
  a CI failure reproduces on a developer machine;
* ``quick``   -- about a fifth of the examples, for slow runs (sanitizers);
* ``valgrind`` -- 5 examples, derandomised (make valgrind-py).

Profiles only change how many examples run; no assertion depends on them.
Tests that want more or fewer examples than the profile's base scale their
count with ``strategies.examples(n)`` (or the same formula inline).
"""

import os
import sys

from hypothesis import HealthCheck, settings

sys.path.insert(0, os.path.dirname(__file__))

_common = dict(
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    print_blob=True,
)

settings.register_profile("default", max_examples=100, **_common)
settings.register_profile("ci", max_examples=100, database=None,
                          derandomize=True, **_common)
settings.register_profile("quick", max_examples=20, **_common)
# make valgrind-py: memcheck runs Python ~50x slower; a handful of examples
# each, derandomised so that a report reproduces.
settings.register_profile("valgrind", max_examples=5, database=None,
                          derandomize=True, **_common)

_profile = os.environ.get("RASTRUM_HYPOTHESIS_PROFILE", "default")
if _profile not in ("default", "ci", "quick", "valgrind"):
    raise RuntimeError(
        f"RASTRUM_HYPOTHESIS_PROFILE={_profile!r}: expected default, ci, quick or valgrind")
settings.load_profile(_profile)


# make test-core installs only the 'test' extra: a docs example (test_readme's
# test_python_block) that imports an optional package which is not installed
# (dask, geopandas, shapely, ...: the extras make test installs) is skipped,
# saying which, instead of failing; make test installs them all, so there it
# runs.  Decided from the block's own import lines, before it runs.
_OPTIONAL = {"affine", "dask", "dask_geopandas", "geopandas", "matplotlib", "pycocotools", "rasterio",
             "rioxarray", "shapely", "tqdm", "xarray"}


def pytest_collection_modifyitems(config, items):
    import importlib.util
    import re

    import pytest

    for item in items:
        code = getattr(getattr(item, "callspec", None), "params", {}).get("code")
        if item.originalname != "test_python_block" or not isinstance(code, str):
            continue
        wanted = set(re.findall(r"^\s*(?:import|from)\s+(\w+)", code, re.M)) & _OPTIONAL
        if re.search(r"^\s*(?:import|from)\s+rastrum\.dask\b", code, re.M):
            wanted.add("dask")  # rastrum.dask needs dask itself
        missing = sorted(m for m in wanted if importlib.util.find_spec(m) is None)
        if missing:
            item.add_marker(pytest.mark.skip(reason="needs %s (an optional extra; make test installs it)"
                                             % ", ".join(missing)))

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

# The C extensions: rastrum._native is built by cffi from
# python/rastrum/_build.py, which compiles the same csrc/ sources as the
# Makefile; rastrum._seq (python/ext/seq.c) reads COCO's Python lists with
# the C API, which cffi does not reach.  Everything else about the package
# is in pyproject.toml, except the version: that is the C header's
# (RAST_VERSION_MAJOR/MINOR/PATCH), read here, so that the library, its
# soname, the wheel and rastrum.__version__ carry one number.
#
# Both extensions use only the stable ABI (Py_LIMITED_API: cffi defines it
# in the C it generates and marks its Extension py_limited_api; _seq below
# names 3.9), so one wheel, tagged cp39-abi3, serves CPython 3.9 and later
# (make test-wheel installs it into two Python versions).
import os
import re
import shlex

from setuptools import Extension, setup

HERE = os.path.dirname(os.path.abspath(__file__))


def header_version():
    """"MAJOR.MINOR.PATCH" from csrc/include/rastrum.h."""
    with open(os.path.join(HERE, "csrc", "include", "rastrum.h"), encoding="utf-8") as f:
        text = f.read()
    parts = [re.search(r"^#define RAST_VERSION_%s (\d+)\s*$" % k, text, re.M) for k in ("MAJOR", "MINOR", "PATCH")]
    if not all(parts):
        raise RuntimeError("csrc/include/rastrum.h: RAST_VERSION_MAJOR/MINOR/PATCH not found")
    return ".".join(m.group(1) for m in parts)


seq = Extension(
    "rastrum._seq",
    ["python/ext/seq.c"],
    py_limited_api=True,
    define_macros=[("Py_LIMITED_API", "0x03090000")],
    extra_compile_args=["-std=c99", "-O2"] + shlex.split(os.environ.get("RASTRUM_CFLAGS", "")),
    extra_link_args=shlex.split(os.environ.get("RASTRUM_LDFLAGS", "")),
)

setup(
    version=header_version(),
    cffi_modules=["python/rastrum/_build.py:ffibuilder"],
    ext_modules=[seq],
    options={"bdist_wheel": {"py_limited_api": "cp39"}},
)

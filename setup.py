# The C extensions: rastrum._native is built by cffi from
# python/rastrum/_build.py, which compiles the same csrc/ sources as the
# Makefile; rastrum._seq (python/ext/seq.c) reads COCO's Python lists with
# the C API, which cffi does not reach.  Everything else about the package
# is in pyproject.toml.
import os
import shlex

from setuptools import Extension, setup

seq = Extension(
    "rastrum._seq",
    ["python/ext/seq.c"],
    py_limited_api=True,
    define_macros=[("Py_LIMITED_API", "0x03090000")],
    extra_compile_args=["-std=c99", "-O2"] + shlex.split(os.environ.get("RASTRUM_CFLAGS", "")),
    extra_link_args=shlex.split(os.environ.get("RASTRUM_LDFLAGS", "")),
)

setup(cffi_modules=["python/rastrum/_build.py:ffibuilder"], ext_modules=[seq])

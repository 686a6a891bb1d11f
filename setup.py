# The C extension is built by cffi from python/rastrum/_build.py, which
# compiles the same csrc/ sources as the Makefile.  Everything else about the
# package is in pyproject.toml.
from setuptools import setup

setup(cffi_modules=["python/rastrum/_build.py:ffibuilder"])

"""The examples in the package's docstrings run and print what they say
(they are what the API reference shows)."""
import doctest
import importlib
import pkgutil

import pytest

import rastrum

OPTIONAL = {"dask": "dask"}  # module -> the optional package it needs
MODULES = ["rastrum"] + ["rastrum." + m.name for m in pkgutil.iter_modules(rastrum.__path__)
                         if m.name not in ("_build", "_native", "_seq")]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    short = name.rpartition(".")[2]
    if short in OPTIONAL:
        pytest.importorskip(OPTIONAL[short])
    mod = importlib.import_module(name)
    failed, attempted = doctest.testmod(mod, optionflags=doctest.ELLIPSIS, report=True)
    assert failed == 0, "%d of %d docstring examples in %s failed (above)" % (failed, attempted, name)

"""docs/coverage.md: its Python examples run as written (docs that match
the code)."""

import os
import re

import pytest

DOC = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "coverage.md")


def _blocks():
    with open(DOC, encoding="utf-8") as f:
        return re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)


@pytest.mark.parametrize("k", range(len(_blocks())))
def test_coverage_doc_example(k):
    exec(compile(_blocks()[k], "docs/coverage.md block %d" % k, "exec"), {})


def test_doc_has_examples():
    assert len(_blocks()) >= 2

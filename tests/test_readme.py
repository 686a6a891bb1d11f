"""The README's and the docs' examples run as written (docs that match the
code): every ```python block of README.md and docs/*.md is executed, each
in a fresh namespace and an empty directory; every ```c block that
defines ``int main`` or ``int draw(void)`` (then called by a main added
here) is compiled against the core with the strict
warnings and run.  Output and shell sessions go in ```text / ```console
blocks, which are not run."""

import glob
import os
import re
import shutil
import subprocess
import warnings

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGES = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
FENCE = re.compile(r"^```([A-Za-z0-9_+-]*)\n(.*?)^```", re.S | re.M)


def blocks(lang):
    """[(page name, n-th block, code)] of every ```lang block."""
    out = []
    for path in PAGES:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found = [code for tag, code in FENCE.findall(text) if tag == lang]
        out += [(os.path.relpath(path, ROOT), k, code) for k, code in enumerate(found)]
    return out


def test_the_pages_exist_and_have_examples():
    names = {os.path.relpath(p, ROOT) for p in PAGES}
    assert {"README.md", "docs/index.md", "docs/python.md", "docs/c.md"} <= names
    assert len(blocks("python")) >= 4 and blocks("c")


def test_no_unrun_python_blocks():
    """A block tagged py, python3, pycon ... would silently not run."""
    for path in PAGES:
        with open(path, encoding="utf-8") as f:
            tags = {tag for tag, _ in FENCE.findall(f.read())}
        assert not {t for t in tags if t.startswith("py") and t != "python"}, path


def test_no_reference_to_files_a_clone_lacks():
    for path in PAGES:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for bad in ("../shared", "DESIGN.md", "seed 001", "issue 3"):
            assert bad not in text, (path, bad)


@pytest.mark.parametrize("page, k, code", blocks("python"), ids=lambda v: str(v) if not isinstance(v, str) or
                         len(v) < 40 else "code")
def test_python_block(page, k, code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # the docs use today's spellings
        exec(compile(code, "%s, python block %d" % (page, k), "exec"), {"__name__": "__docs__"})


def test_readme_example_writes_its_picture(tmp_path, monkeypatch):
    code = next(c for p, k, c in blocks("python") if p == "README.md")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert (tmp_path / "square.png").exists()


@pytest.mark.parametrize("page, k, code", [b for b in blocks("c") if "int draw(void)" in b[2] or "int main(" in b[2]],
                         ids=lambda v: str(v) if not isinstance(v, str) or len(v) < 40 else "code")
def test_c_block(page, k, code, tmp_path):
    cc = shutil.which(os.environ.get("CC", "cc"))
    if cc is None:
        pytest.fail("no C compiler to build the docs' C examples")
    src = tmp_path / "example.c"
    src.write_text(code if "int main(" in code else code + "\nint main(void) { return draw(); }\n")
    exe = tmp_path / "example"
    sources = sorted(glob.glob(os.path.join(ROOT, "csrc", "src", "*", "*.c")))
    subprocess.run(
        [cc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-I", os.path.join(ROOT, "csrc", "include"), "-I",
         os.path.join(ROOT, "csrc", "src"), str(src)] + sources + ["-o", str(exe)],
        check=True,
    )
    subprocess.run([str(exe)], check=True, cwd=tmp_path)
    if '"quad.pgm"' in code:  # the README's program: check the image it wrote
        data = (tmp_path / "quad.pgm").read_bytes()
        header = b"P5 320 240 255\n"
        assert data.startswith(header) and len(data) == len(header) + 320 * 240
        pixels = data[len(header):]
        assert set(pixels) == {0, 255} and 0 < pixels.count(255) < 320 * 240

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
        for bad in ("../shared", "DESIGN" + ".md", "seed 001", "issue 3"):
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


CONF_PROBE = r"""
#include <stdio.h>
#include "rastrum.h"
#include "%s"

/* Each value is kept (its info call succeeds) iff the header's mask has
 * its bit; 64-bit vertices iff RAST_CONFIG_POLYGON64. */
int main(void)
{
    int v, bad = 0;
    int32_t bytes;
    size_t need;
    rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_EVENODD, 0, RAST_SAMPLE_CENTER, RAST_ROUND_EXACT,
                        RAST_BOUNDARY_EXACT};
    for (v = 0; v < RAST_ALGO_COUNT_; v++)
        bad |= (rast_algorithm_info((rast_algorithm)v, NULL, NULL) == RAST_OK) !=
               (int)((RAST_CONFIG_ALGORITHMS >> v) & 1u);
    for (v = 0; v < RAST_TRI_COUNT_; v++)
        bad |= (rast_tri_algorithm_info((rast_tri_algorithm)v, NULL) == RAST_OK) !=
               (int)((RAST_CONFIG_TRI_ALGORITHMS >> v) & 1u);
    for (v = 0; v < RAST_AA_COUNT_; v++)
        bad |= (rast_aa_method_info((rast_aa_method)v, NULL) == RAST_OK) !=
               (int)((RAST_CONFIG_AA_METHODS >> v) & 1u);
    for (v = 0; v < RAST_FORMAT_COUNT_; v++)
        bad |= (rast_format_bytes((rast_format)v, &bytes) == RAST_OK) !=
               (int)((RAST_CONFIG_FORMATS >> v) & 1u);
    bad |= (rast_scratch_size64(&o, 3, 8, 8, &need) == RAST_OK) != (RAST_CONFIG_POLYGON64 != 0);
    printf("%%s\n", bad ? "config probe: FAILED" : "config probe: ok");
    return bad;
}
"""


CONF_BLOCKS = [b for b in blocks("c") if "#define RAST_CONFIG_" in b[2] and "int main(" not in b[2]]


def test_the_pages_show_a_configuration_header():
    assert {p for p, k, c in CONF_BLOCKS} == {"README.md", "docs/c.md"}


@pytest.mark.parametrize("page, k, conf", CONF_BLOCKS, ids=lambda v: str(v) if not isinstance(v, str) or
                         len(v) < 40 else "code")
def test_config_header_block(page, k, conf, tmp_path):
    """A configuration header of the pages, as written: the core compiled
    with it keeps exactly what it names, and the README's program (which
    calls only what the headers keep: the AET into GRAY8) still builds and
    runs against it."""
    cc = shutil.which(os.environ.get("CC", "cc"))
    if cc is None:
        pytest.fail("no C compiler to build the docs' C examples")
    (tmp_path / "my_rast_conf.h").write_text(conf)
    (tmp_path / "probe.c").write_text(CONF_PROBE % "my_rast_conf.h")
    quad = next(c for p, k, c in blocks("c") if p == "README.md" and '"quad.pgm"' in c)
    (tmp_path / "quad.c").write_text(quad)
    sources = sorted(glob.glob(os.path.join(ROOT, "csrc", "src", "*", "*.c")))
    for name in ("probe", "quad"):
        subprocess.run(
            [cc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", '-DRAST_CONFIG_HEADER="my_rast_conf.h"',
             "-I", str(tmp_path), "-I", os.path.join(ROOT, "csrc", "include"), "-I", os.path.join(ROOT, "csrc", "src"),
             str(tmp_path / (name + ".c"))] + sources + ["-o", str(tmp_path / name)],
            check=True,
        )
        subprocess.run([str(tmp_path / name)], check=True, cwd=tmp_path)
    assert (tmp_path / "quad.pgm").exists()

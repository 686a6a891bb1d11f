"""The README's examples run as written (docs that match the code)."""

import os
import re
import shutil
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def blocks(lang):
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        text = f.read()
    return re.findall(r"```%s\n(.*?)```" % lang, text, flags=re.S)


def test_python_example(tmp_path, monkeypatch):
    (code,) = blocks("python")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert (tmp_path / "square.png").exists()


def test_c_example(tmp_path):
    cc = shutil.which(os.environ.get("CC", "cc"))
    if cc is None:
        pytest.fail("no C compiler to build the README's C example")
    # The first C block is a whole program (make test-install also builds
    # it against an installed library, through pkg-config and CMake).
    code = blocks("c")[0]
    src = tmp_path / "readme.c"
    src.write_text(code)
    exe = tmp_path / "readme"
    sources = [os.path.join(ROOT, "csrc", "src", f) for f in sorted(os.listdir(os.path.join(ROOT, "csrc", "src"))) if f.endswith(".c")]
    subprocess.run(
        [cc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-I", os.path.join(ROOT, "csrc", "include"), "-I", os.path.join(ROOT, "csrc", "src"), str(src)] + sources + ["-o", str(exe)],
        check=True,
    )
    pgm = tmp_path / "quad.pgm"
    subprocess.run([str(exe), str(pgm)], check=True)
    data = pgm.read_bytes()
    header = b"P5 320 240 255\n"
    assert data.startswith(header) and len(data) == len(header) + 320 * 240
    pixels = data[len(header):]
    assert set(pixels) == {0, 255} and 0 < pixels.count(255) < 320 * 240

"""The Makefile's choice of Python (make -n: what would run, nothing run):
an explicit PYTHON=, else the active virtualenv, else the project's .venv,
made from BASE_PYTHON on first use; never pip into the system's Python."""

import os
import shutil
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def dry_run(target, env_extra=None, args=()):
    if shutil.which("make") is None:
        pytest.fail("make is needed to build rastrum")
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHON", "MAKEFLAGS", "MFLAGS")}
    env.update(env_extra or {})
    out = subprocess.run(["make", "-n", "--no-print-directory", target, *args], cwd=ROOT, env=env,
                         capture_output=True, text=True, check=True)
    return out.stdout


@pytest.mark.parametrize("target", ["test-py", "demo", "bench", "docs", "asan-py", "valgrind-py"])
def test_project_venv_when_none_is_active(target):
    out = dry_run(target, args=["BASE_PYTHON=/usr/bin/python3-for-test"])
    venv = os.path.join(ROOT, ".venv", "bin", "python")
    runs = [line for line in out.splitlines() if "pip install" in line or "pytest" in line or "bench/" in line
            or "mkdocs" in line]
    assert runs and all(venv in line for line in runs), out
    if not os.path.exists(venv):  # made first, from BASE_PYTHON
        assert "/usr/bin/python3-for-test -m venv" in out, out


@pytest.mark.parametrize("target", ["test-py", "demo"])
def test_active_virtualenv_and_explicit_python_win(target):
    out = dry_run(target, {"VIRTUAL_ENV": "/opt/some-venv"})
    assert "/opt/some-venv/bin/python -m pip install" in out and ".venv" not in out, out
    out = dry_run(target, {"VIRTUAL_ENV": "/opt/some-venv"}, ["PYTHON=/opt/py/bin/python3"])
    assert "/opt/py/bin/python3 -m pip install" in out and "some-venv" not in out and ".venv" not in out, out


def test_demo_installs_no_peers_and_bench_does():
    assert "[bench" not in dry_run("demo", {"VIRTUAL_ENV": "/v"})
    assert "'.[bench,test]'" in dry_run("bench", {"VIRTUAL_ENV": "/v"})

"""cffi build script: compiles csrc/ into ``rastrum._native``.

The declarations are not written twice: they come from the public header,
run through the C preprocessor with ``RAST_CDEF`` defined (which drops the
system includes and the visibility attribute and expands the status
X-macro) and ``RAST_STATIC_LINKING_ONLY`` (the binding is built with the
core, so it may use the part of the API that may change).  Named by ``setup.py`` (``cffi_modules``).

Extra compiler and linker flags (a sanitizer build, say) come from the
environment variables ``RASTRUM_CFLAGS`` and ``RASTRUM_LDFLAGS``.
"""

import glob
import os
import re
import shlex
import subprocess
import sysconfig

from cffi import FFI

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CSRC = os.path.join(ROOT, "csrc")
HEADER = os.path.join(CSRC, "include", "rastrum.h")


def _compiler():
    cc = os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"
    return shlex.split(cc)


def _cdef():
    cmd = _compiler() + ["-E", "-P", "-DRAST_CDEF", "-DRAST_STATIC_LINKING_ONLY", "-x", "c", HEADER]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return out.stdout


def _path(p):
    # setuptools wants source paths relative to the project root, where pip
    # runs setup.py; run from elsewhere (python _build.py), keep them absolute.
    return os.path.relpath(p, ROOT) if os.path.abspath(os.getcwd()) == ROOT else p


GLUE = os.path.join(ROOT, "python", "glue")


def _glue_cdef():
    """The binding glue's declarations: the text between the cdef-begin and
    cdef-end markers of each python/glue/*.h, and its RASTPY_ constants."""
    out = []
    for h in sorted(glob.glob(os.path.join(GLUE, "*.h"))):
        text = open(h, encoding="utf-8").read()
        head, sep, rest = text.partition("/* cdef-begin */")
        if not sep:
            continue
        out += ["#define %s ..." % m for m in re.findall(r"^#define (RASTPY_\w+) ", head, re.M)]
        out.append(rest.partition("/* cdef-end */")[0])
    return "\n".join(out)


ffibuilder = FFI()
ffibuilder.cdef(_cdef() + _glue_cdef())
ffibuilder.set_source(
    "rastrum._native",
    "".join('#include "%s"\n' % os.path.basename(h) for h in sorted(glob.glob(os.path.join(GLUE, "*.h")))),
    sources=sorted(_path(p) for p in glob.glob(os.path.join(CSRC, "src", "*", "*.c")) + glob.glob(os.path.join(GLUE, "*.c"))),
    # the binding uses the whole header, RAST_STATIC_LINKING_ONLY part included
    define_macros=[("RAST_STATIC_LINKING_ONLY", None)],
    include_dirs=[_path(os.path.join(CSRC, "include")), _path(os.path.join(CSRC, "src")), _path(GLUE)],
    extra_compile_args=["-std=c99", "-O2", "-fvisibility=hidden"] + shlex.split(os.environ.get("RASTRUM_CFLAGS", "")),
    extra_link_args=shlex.split(os.environ.get("RASTRUM_LDFLAGS", "")),
)

if __name__ == "__main__":
    ffibuilder.compile(verbose=True)

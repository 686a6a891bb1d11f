"""cffi build script: compiles csrc/ into ``rastrum._native``.

The declarations are not written twice: they come from the public header,
run through the C preprocessor with ``RAST_CDEF`` defined (which drops the
system includes and the visibility attribute and expands the status
X-macro).  Named by ``setup.py`` (``cffi_modules``).

Extra compiler and linker flags (a sanitizer build, say) come from the
environment variables ``RASTRUM_CFLAGS`` and ``RASTRUM_LDFLAGS``.
"""

import glob
import os
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
    cmd = _compiler() + ["-E", "-P", "-DRAST_CDEF", "-x", "c", HEADER]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return out.stdout


def _path(p):
    # setuptools wants source paths relative to the project root, where pip
    # runs setup.py; run from elsewhere (python _build.py), keep them absolute.
    return os.path.relpath(p, ROOT) if os.path.abspath(os.getcwd()) == ROOT else p


# Binding glue, not part of the core.  Snapping float64 input to the 1/2^S
# grid belongs to the Python layer (the core is integer only), and a small
# call's cost is mostly Python-to-C round trips; so one glue function snaps,
# takes the scratch the core asks for and calls the core, all without the
# GIL.  It holds no drawing logic.
GLUE_CDEF = """
#define RASTPY_E_NOMEM ...
long rastpy_fill_polygon(const rast_target *target, const double *xy,
                         uint32_t npoints, const uint32_t *ring_sizes,
                         uint32_t nrings, const rast_fill_opts *opts,
                         const void *pixel, const void *background);
long rastpy_mask_polygon(void *mask, int32_t height, int32_t width,
                         const double *xy, uint32_t npoints,
                         const uint32_t *ring_sizes, uint32_t nrings,
                         const rast_fill_opts *opts);
long rastpy_snap_points(const double *xy, size_t npoints, int s, int32_t *out);
long rastpy_fill_triangles(const rast_target *target, const double *xy,
                           uint32_t ntris, const rast_tri_opts *opts,
                           const void *pixel);
int rastpy_gil_held(void);
"""
GLUE_SOURCE = r"""
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rastrum.h"

#define RASTPY_E_NOMEM (-1000)

/* out = floor(xy * 2^s + 1/2), exactly.  t = xy * 2^s is exact (a power
 * of two), and so is its fraction t - floor(t); but t + 1/2 is NOT: for
 * t = 1/2 - 2^-54 it rounds up to 1.  So round by comparing the fraction
 * with 1/2 instead of adding it.  Returns the index of the first point that
 * is NaN, infinite or outside +-RAST_COORD_MAX after snapping, or -1 when
 * all are good. */
static long rastpy_snap(const double *xy, size_t npoints, int s, int32_t *out)
{
    const double scale = ldexp(1.0, s), lim = (double)RAST_COORD_MAX + 1.0;
    size_t i;
    /* Branch-free but for the range test (which a batch passes): the
     * rounding of random input is a coin toss a branch would mispredict.
     * Inside +-lim, t converts to int32_t exactly (truncating) and floor
     * and the fraction follow in integers and exact doubles. */
    for (i = 0; i < 2 * npoints; i++) {
        double t = xy[i] * scale;
        int32_t v;
        if (!(t >= -lim && t <= lim)) return (long)(i / 2); /* also NaN */
        v = (int32_t)t;
        v -= (double)v > t;                 /* floor */
        v += t - (double)v >= 0.5;          /* half up */
        if (v < -RAST_COORD_MAX || v > RAST_COORD_MAX) return (long)(i / 2);
        out[i] = v;
    }
    return -1;
}

/* rastpy_snap for callers in Python (lines, predicates, small inputs). */
long rastpy_snap_points(const double *xy, size_t npoints, int s, int32_t *out)
{
    return rastpy_snap(xy, npoints, s, out);
}

/* Paint the pixels of rectangle r (inside the target) with the pixel
 * bytes px: the background outside a cut opaque fill. */
static void rastpy_paint_rect(const rast_target *t, rast_rect r, const void *px)
{
    int32_t bpp = 1, x, y;
    rast_format_bytes(t->format, &bpp);
    for (y = r.y0; y < r.y1; y++) {
        unsigned char *row = (unsigned char *)t->pixels + (ptrdiff_t)y * t->stride + (ptrdiff_t)r.x0 * bpp;
        if (bpp == 1)
            memset(row, *(const unsigned char *)px, (size_t)(r.x1 - r.x0));
        else
            for (x = r.x0; x < r.x1; x++) memcpy(row + (ptrdiff_t)(x - r.x0) * bpp, px, (size_t)bpp);
    }
}

/* Snap, then rast_fill_polygon (or rast_fill_polygon_opaque when
 * background is not NULL) with scratch from malloc.  The fill's clip is
 * cut to rast_fill_bounds first, so that the scratch grows with the
 * polygon's box, not with the target (the mask algorithms need a bit, or
 * a counter, per clip pixel); an opaque fill's background outside the
 * cut is painted here, after the core has accepted every argument.
 * ring_sizes NULL means one ring of all the points.  Returns 0, a
 * negative rast_status (or RASTPY_E_NOMEM), or k + 1 when point k is bad
 * (see rastpy_snap). */
long rastpy_fill_polygon(const rast_target *target, const double *xy,
                         uint32_t npoints, const uint32_t *ring_sizes,
                         uint32_t nrings, const rast_fill_opts *opts,
                         const void *pixel, const void *background)
{
    rast_polygon poly;
    rast_target cut = *target;
    rast_rect c = target->clip, b;
    rast_status st;
    size_t need;
    int32_t *pts;
    void *scratch;
    long bad;
    pts = (int32_t *)malloc((size_t)npoints * sizeof(rast_point) + 1);
    if (!pts) return RASTPY_E_NOMEM;
    bad = rastpy_snap(xy, npoints, opts->subpixel_bits, pts);
    if (bad >= 0) {
        free(pts);
        return bad + 1;
    }
    poly.points = (const rast_point *)pts;
    poly.ring_sizes = ring_sizes ? ring_sizes : &npoints;
    poly.nrings = ring_sizes ? nrings : 1;
    /* The target's clip cut to the target, as the core cuts it. */
    if (c.x0 < 0) c.x0 = 0;
    if (c.y0 < 0) c.y0 = 0;
    if (c.x1 > target->width) c.x1 = target->width;
    if (c.y1 > target->height) c.y1 = target->height;
    st = rast_fill_bounds(opts, &poly, &c, &b);
    if (st == RAST_OK) st = rast_scratch_size(opts, npoints, b.x1 - b.x0, b.y1 - b.y0, &need);
    if (st != RAST_OK) {
        free(pts);
        return st;
    }
    scratch = malloc(need + 1);
    if (!scratch) {
        free(pts);
        return RASTPY_E_NOMEM;
    }
    cut.clip = b;
    st = background ? rast_fill_polygon_opaque(&cut, &poly, opts, pixel, background, scratch, need)
                    : rast_fill_polygon(&cut, &poly, opts, pixel, scratch, need);
    free(scratch);
    free(pts);
    if (st == RAST_OK && background && c.x0 < c.x1 && c.y0 < c.y1) {
        /* Above, below, left and right of the cut. */
        rast_rect r;
        if (b.x0 == b.x1 || b.y0 == b.y1) b.y0 = b.y1 = c.y1; /* nothing cut: all background */
        r = c; r.y1 = b.y0; rastpy_paint_rect(target, r, background);
        r = c; r.y0 = b.y1; rastpy_paint_rect(target, r, background);
        r.y0 = b.y0; r.y1 = b.y1;
        r.x0 = c.x0; r.x1 = b.x0; rastpy_paint_rect(target, r, background);
        r.x0 = b.x1; r.x1 = c.x1; rastpy_paint_rect(target, r, background);
    }
    return st;
}

/* A complete gray8 (height, width) mask, 1 inside and 0 outside, written
 * in one pass over uninitialised memory. */
long rastpy_mask_polygon(void *mask, int32_t height, int32_t width,
                         const double *xy, uint32_t npoints,
                         const uint32_t *ring_sizes, uint32_t nrings,
                         const rast_fill_opts *opts)
{
    static const unsigned char one = 1, zero = 0;
    rast_target t;
    rast_status st = rast_target_init(&t, mask, width, height, width, RAST_FORMAT_GRAY8);
    if (st != RAST_OK) return st;
    return rastpy_fill_polygon(&t, xy, npoints, ring_sizes, nrings, opts, &one, &zero);
}

/* Snap the 3 * ntris vertices xy (x, y float pairs), then
 * rast_fill_triangles with scratch from malloc.  Returns 0, a negative
 * rast_status (or RASTPY_E_NOMEM), or k + 1 when vertex k is bad (see
 * rastpy_snap). */
long rastpy_fill_triangles(const rast_target *target, const double *xy,
                           uint32_t ntris, const rast_tri_opts *opts,
                           const void *pixel)
{
    rast_status st;
    size_t need, n = 3 * (size_t)ntris;
    size_t head = (n * sizeof(rast_point) + 15) & ~(size_t)15;
    unsigned char *mem;
    long bad;
    st = rast_tri_scratch_size(opts, target->clip.x1 - target->clip.x0,
                               target->clip.y1 - target->clip.y0, &need);
    if (st != RAST_OK) return st;
    mem = (unsigned char *)malloc(head + need + 1);
    if (!mem) return RASTPY_E_NOMEM;
    bad = rastpy_snap(xy, n, opts->subpixel_bits, (int32_t *)mem);
    if (bad >= 0) {
        free(mem);
        return bad + 1;
    }
    st = rast_fill_triangles(target, (const rast_point *)mem, ntris, opts, pixel, mem + head, need);
    free(mem);
    return st;
}

/* For the tests: does the thread running a C call hold the GIL?  cffi
 * releases it around every call, so this answers 0.  Declared here because
 * cffi compiles against the limited API, whose Python.h leaves it out
 * (the symbol is in every CPython since 3.4); without the declaration it
 * is an implicit one, an error for newer compilers. */
int PyGILState_Check(void);
int rastpy_gil_held(void)
{
    return PyGILState_Check();
}
"""

ffibuilder = FFI()
ffibuilder.cdef(_cdef() + GLUE_CDEF)
ffibuilder.set_source(
    "rastrum._native",
    GLUE_SOURCE,
    sources=sorted(_path(p) for p in glob.glob(os.path.join(CSRC, "src", "*.c"))),
    include_dirs=[_path(os.path.join(CSRC, "include")), _path(os.path.join(CSRC, "src"))],
    extra_compile_args=["-std=c99", "-O2", "-fvisibility=hidden"] + shlex.split(os.environ.get("RASTRUM_CFLAGS", "")),
    extra_link_args=shlex.split(os.environ.get("RASTRUM_LDFLAGS", "")),
)

if __name__ == "__main__":
    ffibuilder.compile(verbose=True)

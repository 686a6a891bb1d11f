/* wide.c - glue for the 64-bit vertex path (not part of the core): exact
 * snapping of float64 to int64 at S = 0..32 and the polygon fills on
 * rast_polygon64, with scratch from malloc.
 *
 * rastpy_snap64(xy, n, s, out): out = floor(xy * 2^s + 1/2), exactly, for
 * the 2n coordinates; returns -1 when every one is finite and inside
 * +-RAST_COORD64_MAX(s) after snapping (all of out written), else the index
 * of the first point that is not.  t = xy * 2^s is exact (a power of two;
 * an overflow is infinite and refused), floor(t) is exact and so is the
 * fraction t - floor(t); the half is decided by comparing the fraction with
 * 1/2, never by adding it (t + 1/2 rounds for |t| >= 2^52).  |t| < 2^(s+28)
 * <= 2^60 is tested first, so floor(t) converts to int64_t exactly.
 *
 * rastpy_needs_wide(xy, n, s): 1 when the 32-bit path cannot take the
 * input (s > RAST_MAX_SUBPIXEL_BITS, or a coordinate that is not finite or
 * that snaps outside +-RAST_COORD_MAX: t = v * 2^s outside
 * -M - 1/2 <= t < M + 1/2, the 32-bit glue's own test, python/glue/fill.c),
 * else 0.  So a call takes the 64-bit path exactly when the 32-bit one
 * would refuse it, whether it comes the quick way (the 32-bit call first,
 * the general way on its error) or the general way (this test first): the
 * two paths give the same binary pixels, but an "area" level at a tie may
 * be either neighbour (docs/coverage.md), so the same call must not take
 * one path one time and the other the next. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "wide.h"
#include "blend.h"

long rastpy_snap64(const double *xy, size_t npoints, int s, int64_t *out)
{
    const double scale = ldexp(1.0, s), bound = ldexp(1.0, s + RAST_COORD64_PIXEL_BITS);
    const int64_t lim = RAST_COORD64_MAX(s);
    size_t i;
    if (s < 0 || s > RAST_MAX_SUBPIXEL_BITS64) return npoints ? 0 : -1;
    for (i = 0; i < 2 * npoints; i++) {
        double t = xy[i] * scale, f;
        int64_t v;
        if (!(t > -bound && t < bound)) return (long)(i / 2); /* also NaN */
        f = floor(t);
        v = (int64_t)f + (t - f >= 0.5);
        if (v > lim || v < -lim) return (long)(i / 2);
        out[i] = v;
    }
    return -1;
}

int rastpy_needs_wide(const double *xy, size_t npoints, int s)
{
    const double scale = ldexp(1.0, s), lim = (double)RAST_COORD_MAX + 0.5;
    size_t i;
    if (s < 0 || s > RAST_MAX_SUBPIXEL_BITS) return 1;
    for (i = 0; i < 2 * npoints; i++) {
        const double t = xy[i] * scale;
        if (!(t >= -lim && t < lim)) return 1; /* also NaN */
    }
    return 0;
}

/* What the fills below share: the points snapped (rastpy_snap64) into
 * c->pts, described by c->poly (ring_sizes NULL: one ring of all the
 * points), and need bytes of scratch, both from malloc; wide_end frees
 * them.  Returns 0, RAST_E_ARG (sizes not summing to npoints,
 * rastpy_check_rings), RASTPY_E_NOMEM, or k + 1 when point k is bad, with
 * nothing left allocated unless it returns 0. */
typedef struct {
    rast_polygon64 poly;
    uint32_t one_ring;
    int64_t *pts;
    void *scratch;
} wide_call;

static long wide_begin(wide_call *c, const double *xy, uint32_t npoints,
                       const uint32_t *ring_sizes, uint32_t nrings, int s, size_t need)
{
    long bad = rastpy_check_rings(npoints, ring_sizes, nrings);
    if (bad != RAST_OK) return bad;
    c->scratch = NULL;
    c->pts = (int64_t *)malloc((size_t)npoints * sizeof(rast_point64) + 1);
    if (!c->pts) return RASTPY_E_NOMEM;
    bad = rastpy_snap64(xy, npoints, s, c->pts);
    if (bad < 0) c->scratch = malloc(need + 1);
    if (bad >= 0 || !c->scratch) {
        free(c->pts);
        return bad >= 0 ? bad + 1 : RASTPY_E_NOMEM;
    }
    c->one_ring = npoints;
    c->poly.points = (const rast_point64 *)(const void *)c->pts;
    c->poly.ring_sizes = ring_sizes ? ring_sizes : &c->one_ring;
    c->poly.nrings = ring_sizes ? nrings : 1;
    return 0;
}

static void wide_end(wide_call *c)
{
    free(c->scratch);
    free(c->pts);
}

/* Snap, then rast_fill_polygon64 (rast_fill_polygon64_opaque when
 * background is not NULL) with scratch from malloc.  ring_sizes NULL means
 * one ring of all the points.  Returns 0, a negative rast_status (or
 * RASTPY_E_NOMEM), or k + 1 when point k is bad (rastpy_snap64). */
long rastpy_fill_polygon64(const rast_target *target, const double *xy, uint32_t npoints,
                           const uint32_t *ring_sizes, uint32_t nrings,
                           const rast_fill_opts *opts, const void *pixel,
                           const void *background)
{
    wide_call c;
    rast_status st;
    size_t need;
    long r;
    if (!target || !opts) return RAST_E_NULL;
    st = rast_scratch_size64(opts, npoints, target->clip.x1 - target->clip.x0,
                             target->clip.y1 - target->clip.y0, &need);
    if (st != RAST_OK) return st;
    r = wide_begin(&c, xy, npoints, ring_sizes, nrings, opts->subpixel_bits, need);
    if (r) return r;
    st = background ? rast_fill_polygon64_opaque(target, &c.poly, opts, pixel, background, c.scratch, need)
                    : rast_fill_polygon64(target, &c.poly, opts, pixel, c.scratch, need);
    wide_end(&c);
    return st;
}

/* A complete gray8 (height, width) mask, 1 inside and 0 outside. */
long rastpy_mask_polygon64(void *mask, int32_t height, int32_t width, const double *xy,
                           uint32_t npoints, const uint32_t *ring_sizes, uint32_t nrings,
                           const rast_fill_opts *opts)
{
    static const unsigned char one = 1, zero = 0;
    rast_target t;
    rast_status st = rast_target_init(&t, mask, width, height, width, RAST_FORMAT_GRAY8);
    if (st != RAST_OK) return st;
    return rastpy_fill_polygon64(&t, xy, npoints, ring_sizes, nrings, opts, &one, &zero);
}

/* Snap, then rast_polygon_coverage64 (opts->subpixel_bits up to 32, method
 * area) of a whole (height, width) array of `format`, with scratch from
 * malloc.  ring_sizes NULL means one ring of all the points.  Returns 0, a
 * negative rast_status (or RASTPY_E_NOMEM), or k + 1 when point k is bad
 * (rastpy_snap64). */
long rastpy_polygon_coverage64(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                               uint32_t nrings, const rast_coverage_opts *opts)
{
    static const int32_t size[3] = {1, 2, 8};
    wide_call c;
    rast_rect clip;
    rast_status st;
    size_t need;
    long r;
    if (!opts) return RAST_E_NULL;
    if (format < 0 || format > 2) return RAST_E_ARG;
    st = rast_coverage64_scratch_size(opts, npoints, width, height, &need);
    if (st != RAST_OK) return st;
    r = wide_begin(&c, xy, npoints, ring_sizes, nrings, opts->subpixel_bits, need);
    if (r) return r;
    clip.x0 = 0;
    clip.y0 = 0;
    clip.x1 = width;
    clip.y1 = height;
    st = rast_polygon_coverage64(&c.poly, opts, &clip, (rast_coverage_format)format, out,
                                 (ptrdiff_t)width * size[format], c.scratch, need);
    wide_end(&c);
    return st;
}

/* The sparse form of rastpy_polygon_coverage64 (FIX62, as fractions):
 * the cells of the (height, width) window whose coverage is not 0, in
 * row-major order, cells[i] = cell0 + row * row_step + column and cov[i]
 * = the fraction, (double)a62 * 2^-62, the value rastpy_fix62_to_double
 * gives (a62 <= 2^62 < 2^63: the conversion from int64_t is the same
 * rounding); *count of them.  cells and cov hold height * width.  The
 * window is computed in bands of band_rows rows (0: about 2^18 cells a
 * band; one clip each, the vertices snapped once), so the dense buffer is
 * a band's, not the window's (tests/test_coverage64_runs.py sets it).
 * Returns as rastpy_polygon_coverage64; *count is 0 on an error. */
long rastpy_coverage64_cells(const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts, int32_t height,
                             int32_t width, int64_t cell0, int64_t row_step, int32_t band_rows,
                             int64_t *cells, double *cov, size_t *count)
{
    wide_call c;
    rast_rect clip;
    rast_status st = RAST_OK;
    size_t need, n = 0, band;
    uint64_t *buf;
    long r;
    int32_t y0;
    if (!opts || !count) return RAST_E_NULL;
    *count = 0;
    st = rast_coverage64_scratch_size(opts, npoints, width, height, &need);
    if (st != RAST_OK) return st;
    if (height == 0 || width == 0) return RAST_OK;
    /* about 2^18 cells (2 MB) a band, at least a row */
    band = band_rows > 0 ? (size_t)band_rows : ((size_t)1 << 18) / (size_t)width;
    if (band < 1) band = 1;
    if (band > (size_t)height) band = (size_t)height;
    r = wide_begin(&c, xy, npoints, ring_sizes, nrings, opts->subpixel_bits, need);
    if (r) return r;
    buf = (uint64_t *)malloc(band * (size_t)width * sizeof(uint64_t) + 1);
    if (!buf) {
        wide_end(&c);
        return RASTPY_E_NOMEM;
    }
    clip.x0 = 0;
    clip.x1 = width;
    for (y0 = 0; y0 < height; y0 += (int32_t)band) {
        int32_t y1 = height - y0 < (int32_t)band ? height : y0 + (int32_t)band, y, x;
        clip.y0 = y0;
        clip.y1 = y1;
        st = rast_polygon_coverage64(&c.poly, opts, &clip, RAST_COVERAGE_FIX62, buf,
                                     (ptrdiff_t)width * 8, c.scratch, need);
        if (st != RAST_OK) {
            n = 0;
            break;
        }
        for (y = y0; y < y1; y++) {
            const uint64_t *row = buf + (size_t)(y - y0) * (size_t)width;
            const int64_t c0 = cell0 + (int64_t)y * row_step;
            for (x = 0; x < width;) {
                uint64_t a = row[x];
                int32_t e = x + 1, k;
                double v;
                if (!a) {
                    x++;
                    continue;
                }
                /* a run of equal cells (the core writes runs): one conversion */
                while (e < width && row[e] == a) e++;
                v = (double)(int64_t)a * 0x1p-62;
                for (k = x; k < e; k++, n++) {
                    cells[n] = c0 + k;
                    cov[n] = v;
                }
                x = e;
            }
        }
    }
    free(buf);
    wide_end(&c);
    *count = n;
    return st;
}

/* The translucent fills on rast_polygon64 (blend.h, issue 34): snapped
 * (rastpy_snap64), the mask (opts: rast_fill_bounds64, then the spans) or
 * the uint8 "area" coverage (cov_opts: rast_polygon_coverage64 over the
 * points' box, rastpy_box_cut) computed over a window of the target's
 * clip only, then blended there (rastpy_blend_window), or with `pixel`
 * (rgba NULL) painted there as rast_fill_polygon_aa paints its coverage
 * (rastpy_paint_window).  Results as rastpy_fill_polygon64's. */
static long rastpy_blend64(const rast_target *target, const double *xy, uint32_t npoints,
                           const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                           const rast_coverage_opts *cov_opts, const uint8_t *rgba,
                           const rast_blend_opts *blend, const rast_gamma *gamma, const void *pixel)
{
    wide_call c;
    rast_rect clip;
    rastpy_window win;
    rast_status st;
    size_t need = 0;
    unsigned char *mem = NULL;
    long r;
    if (!target || !(rgba || pixel) || !(opts || cov_opts)) return RAST_E_NULL;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    r = wide_begin(&c, xy, npoints, ring_sizes, nrings, opts ? opts->subpixel_bits : cov_opts->subpixel_bits, 0);
    if (r) return r;
    clip = rastpy_target_clip(target);
    if (opts) {
        st = rast_fill_bounds64(opts, &c.poly, &clip, &win.r);
        if (st == RAST_OK)
            st = rast_scratch_size64(opts, npoints, win.r.x1 - win.r.x0, win.r.y1 - win.r.y0, &need);
    } else {
        const int64_t *p = c.pts;
        int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        uint32_t i;
        for (i = 0; i < npoints; i++) {
            if (!i || p[2 * i] < x0) x0 = p[2 * i];
            if (!i || p[2 * i] > x1) x1 = p[2 * i];
            if (!i || p[2 * i + 1] < y0) y0 = p[2 * i + 1];
            if (!i || p[2 * i + 1] > y1) y1 = p[2 * i + 1];
        }
        win.r = rastpy_box_cut(&clip, x0, y0, x1, y1, cov_opts->subpixel_bits);
        if (!npoints) win.r.x1 = win.r.x0, win.r.y1 = win.r.y0;
        st = rast_coverage64_scratch_size(cov_opts, npoints, win.r.x1 - win.r.x0, win.r.y1 - win.r.y0, &need);
    }
    if (st == RAST_OK && !(mem = rastpy_window_new(&win, need))) st = (rast_status)RASTPY_E_NOMEM;
    if (st == RAST_OK) {
        st = opts ? rast_fill_polygon64_spans(&c.poly, opts, &win.r, rastpy_window_span, &win, mem, need)
                  : rast_polygon_coverage64(&c.poly, cov_opts, &win.r, RAST_COVERAGE_U8, win.cov,
                                            win.r.x1 - win.r.x0, mem, need);
        if (st == RAST_OK)
            st = pixel ? rastpy_paint_window(target, &win.r, win.cov, pixel)
                       : rastpy_blend_window(target, &win.r, win.cov, rgba, blend, gamma);
    }
    free(mem);
    wide_end(&c);
    return st;
}

long rastpy_blend_polygon64(const rast_target *target, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                            const uint8_t *rgba, const rast_blend_opts *blend, const rast_gamma *gamma)
{
    if (!opts) return RAST_E_NULL;
    return rastpy_blend64(target, xy, npoints, ring_sizes, nrings, opts, NULL, rgba, blend, gamma, NULL);
}

long rastpy_blend_polygon_coverage64(const rast_target *target, const double *xy, uint32_t npoints,
                                     const uint32_t *ring_sizes, uint32_t nrings,
                                     const rast_coverage_opts *opts, const uint8_t *rgba,
                                     const rast_blend_opts *blend, const rast_gamma *gamma)
{
    if (!opts) return RAST_E_NULL;
    return rastpy_blend64(target, xy, npoints, ring_sizes, nrings, NULL, opts, rgba, blend, gamma, NULL);
}

long rastpy_fill_polygon_aa64(const rast_target *target, const double *xy, uint32_t npoints,
                              const uint32_t *ring_sizes, uint32_t nrings, const rast_coverage_opts *opts,
                              const void *pixel)
{
    if (!opts || !pixel) return RAST_E_NULL;
    return rastpy_blend64(target, xy, npoints, ring_sizes, nrings, NULL, opts, NULL, NULL, NULL, pixel);
}

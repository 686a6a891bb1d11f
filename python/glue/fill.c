/* Binding glue for the Python layer (not part of the core): snapping float64
 * input to the 1/2^S grid, scratch from malloc, and one C call per Python
 * call.  It holds no drawing logic.  Built into rastrum._native by
 * python/rastrum/_build.py and by make strict with the core's warnings. */

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rastpy.h"
#include "painters/paint.h"

/* out = floor(xy * 2^s + 1/2), exactly.  t = xy * 2^s is exact (a power
 * of two), and so is its fraction t - floor(t); but t + 1/2 is NOT: for
 * t = 1/2 - 2^-54 it rounds up to 1.  So round by comparing the fraction
 * with 1/2 instead of adding it.  Returns the index of the first point that
 * is NaN, infinite or outside +-RAST_COORD_MAX after snapping, or -1 when
 * all are good (then all of out is written).  The snapped value is in
 * range iff -M - 1/2 <= t < M + 1/2 (M = RAST_COORD_MAX; exact doubles),
 * which NaN fails too. */
static long rastpy_snap_scalar(const double *xy, size_t npoints, double scale, int32_t *out, size_t i)
{
    const double lim = (double)RAST_COORD_MAX + 0.5;
    /* Branch-free but for the range test (which a batch passes): the
     * rounding of random input is a coin toss a branch would mispredict.
     * Inside +-lim, t converts to int32_t exactly (truncating) and floor
     * and the fraction follow in integers and exact doubles. */
    for (; i < 2 * npoints; i++) {
        double t = xy[i] * scale;
        int32_t v;
        if (!(t >= -lim && t < lim)) return (long)(i / 2); /* also NaN */
        v = (int32_t)t;
        v -= (double)v > t;                 /* floor */
        v += t - (double)v >= 0.5;          /* half up */
        out[i] = v;
    }
    return -1;
}

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RASTPY_AVX 1
#include <immintrin.h>

/* The same, four coordinates at a time (AVX: floor in one instruction), for
 * i = 0 .. 2n - 4 in steps of 4; the mask of good coordinates goes to *ok.
 * Compiled for AVX whatever the build's target and called only where the
 * CPU has it. */
__attribute__((target("avx"))) static size_t rastpy_snap_avx(const double *xy, size_t n2, double scale,
                                                             int32_t *out, int *ok)
{
    const double lim = (double)RAST_COORD_MAX + 0.5;
    const __m256d vs = _mm256_set1_pd(scale), lo = _mm256_set1_pd(-lim), hi = _mm256_set1_pd(lim),
                  one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5);
    __m256d good = _mm256_cmp_pd(one, one, _CMP_EQ_OQ);
    size_t i;
    for (i = 0; i + 4 <= n2; i += 4) {
        __m256d t = _mm256_mul_pd(_mm256_loadu_pd(xy + i), vs), f;
        good = _mm256_and_pd(good, _mm256_and_pd(_mm256_cmp_pd(t, lo, _CMP_GE_OQ),
                                                 _mm256_cmp_pd(t, hi, _CMP_LT_OQ)));
        f = _mm256_floor_pd(t);
        f = _mm256_add_pd(f, _mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(t, f), half, _CMP_GE_OQ), one));
        _mm_storeu_si128((__m128i *)(void *)(out + i), _mm256_cvttpd_epi32(f));
    }
    *ok = _mm256_movemask_pd(good) == 15;
    return i;
}
#endif

/* The same, two coordinates at a time where SSE2 is there (every x86-64),
 * four where AVX is: the same steps, with the range test folded into a
 * mask checked once at the end (then the scalar loop finds the first bad
 * point).  A batch of 20,000 triangles snaps in a fraction of the scalar
 * loop's time. */
long rastpy_snap(const double *xy, size_t npoints, int s, int32_t *out)
{
    size_t i = 0;
    /* 2^s, exactly, as ldexp(1.0, s) gives it: a shift where it fits (the
     * S of every call); libm's ldexp, called once a path, was ~140
     * instructions of a tiny polygon's call (issue 33) */
    const double pow2 = s >= 0 && s < 63 ? (double)((uint64_t)1 << s) : ldexp(1.0, s);
#if defined(RASTPY_AVX)
    if (__builtin_cpu_supports("avx")) {
        int ok;
        i = rastpy_snap_avx(xy, 2 * npoints, pow2, out, &ok);
        if (!ok) return rastpy_snap_scalar(xy, npoints, pow2, out, 0);
    }
#endif
#if defined(__SSE2__)
    {
        const double lim = (double)RAST_COORD_MAX + 0.5;
        const __m128d scale = _mm_set1_pd(pow2), lo = _mm_set1_pd(-lim),
                      hi = _mm_set1_pd(lim), one = _mm_set1_pd(1.0), half = _mm_set1_pd(0.5);
        __m128d ok = _mm_cmpeq_pd(one, one);
        for (; i + 2 <= 2 * npoints; i += 2) {
            __m128d t = _mm_mul_pd(_mm_loadu_pd(xy + i), scale), f;
            ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpge_pd(t, lo), _mm_cmplt_pd(t, hi)));
            f = _mm_cvtepi32_pd(_mm_cvttpd_epi32(t));                       /* trunc */
            f = _mm_sub_pd(f, _mm_and_pd(_mm_cmpgt_pd(f, t), one));          /* floor */
            f = _mm_add_pd(f, _mm_and_pd(_mm_cmpge_pd(_mm_sub_pd(t, f), half), one));
            _mm_storel_epi64((__m128i *)(void *)(out + i), _mm_cvttpd_epi32(f));
        }
        if (_mm_movemask_pd(ok) != 3) return rastpy_snap_scalar(xy, npoints, pow2, out, 0);
    }
#endif
    return rastpy_snap_scalar(xy, npoints, pow2, out, i);
}

/* rastpy_snap for callers in Python (lines, predicates, small inputs). */
long rastpy_snap_points(const double *xy, size_t npoints, int s, int32_t *out)
{
    return rastpy_snap(xy, npoints, s, out);
}

/* 64-bit words of stack for a small polygon's points and scratch (half
 * each): 4 KB of scratch holds the AET's for a few vertices and a clip of
 * ~1,000 rows (the rows' counts), uncut (rastpy_poly). */
#define RASTPY_LOCAL_WORDS 1024

/* Pixels of a clip that rastpy_poly fills whole instead of cutting it to
 * the polygon's bounds first. */
#define RASTPY_SMALL_CLIP 1024

/* Paint the pixels of rectangle r (inside the target) with the pixel
 * bytes px: the background outside a cut opaque fill. */
static void rastpy_paint_rect(const rast_target *t, rast_rect r, const void *px)
{
    int32_t bpp = 1, x, y;
    if (r.x0 >= r.x1) return;
    rast_format_bytes(t->format, &bpp);
    for (y = r.y0; y < r.y1; y++) {
        unsigned char *row = (unsigned char *)t->pixels + (ptrdiff_t)y * t->stride + (ptrdiff_t)r.x0 * bpp;
        if (bpp == 1)
            memset(row, *(const unsigned char *)px, (size_t)(r.x1 - r.x0));
        else
            for (x = r.x0; x < r.x1; x++) memcpy(row + (ptrdiff_t)(x - r.x0) * bpp, px, (size_t)bpp);
    }
}

rast_status rastpy_check_rings(uint32_t npoints, const uint32_t *ring_sizes, uint32_t nrings)
{
    uint64_t sum = 0;
    uint32_t k;
    if (!ring_sizes) return RAST_OK;
    for (k = 0; k < nrings; k++) {
        sum += ring_sizes[k];
        if (sum > npoints) return RAST_E_ARG; /* past the buffer: stop reading sizes */
    }
    return sum == npoints ? RAST_OK : RAST_E_ARG;
}

/* rastpy_snap of each ring from its own memory (ring_xy[k], ring_sizes[k]
 * points) into out, one after the other: -1, or the index of the first
 * bad point counted over all the rings. */
static long rastpy_snap_rings(const double *const *ring_xy, const uint32_t *ring_sizes, uint32_t nrings,
                              int s, int32_t *out)
{
    size_t at = 0;
    uint32_t k;
    for (k = 0; k < nrings; at += ring_sizes[k], k++) {
        const long bad = rastpy_snap(ring_xy[k], ring_sizes[k], s, out + 2 * at);
        if (bad >= 0) return (long)at + bad;
    }
    return -1;
}

/* Snap, then rast_fill_polygon (or rast_fill_polygon_opaque when
 * background is not NULL, or rast_fill_polygon_gouraud when shade is not
 * NULL) with scratch from malloc.  The fill's clip is cut to
 * rast_fill_bounds first, so that the scratch grows with the polygon's
 * box, not with the target (the mask algorithms need a bit, or a counter,
 * per clip pixel; the AET's grows with the vertices, and is not cut when
 * its count a clip row is no more than them); an opaque fill's background outside the cut is painted
 * here (rastpy_paint_rect: byte formats, which is what the opaque path,
 * rastpy_mask_polygon's gray8, uses), after the core has accepted every
 * argument.  ring_sizes NULL means one ring of all the points; ring_xy
 * not NULL: ring k's points are at ring_xy[k] (xy unused).  Returns 0,
 * a negative rast_status (or RASTPY_E_NOMEM), or k + 1 when point k is bad
 * (see rastpy_snap). */
static long rastpy_poly(const rast_target *target, const double *xy,
                        const double *const *ring_xy, uint32_t npoints, const uint32_t *ring_sizes,
                        uint32_t nrings, const rast_fill_opts *opts,
                        const void *pixel, const void *background,
                        const uint8_t *colors, const rast_shade_opts *shade,
                        const rast_blend_opts *blend)
{
    rast_polygon poly;
    rast_target cut = *target;
    rast_rect c = target->clip, b;
    rast_status st;
    size_t need;
    int32_t *pts;
    void *scratch;
    long bad;
    /* A small polygon's points and scratch live here, not in malloc's
     * memory: for a 14 x 14 mask the two mallocs were a tenth of the call. */
    uint64_t local[RASTPY_LOCAL_WORDS];
    const size_t half = sizeof local / 2;
    st = rastpy_check_rings(npoints, ring_sizes, nrings);
    if (st != RAST_OK) return st;
    pts = (size_t)npoints * sizeof(rast_point) <= half ? (int32_t *)(void *)local
                                                       : (int32_t *)malloc((size_t)npoints * sizeof(rast_point) + 1);
    if (!pts) return RASTPY_E_NOMEM;
    bad = ring_xy ? rastpy_snap_rings(ring_xy, ring_sizes, nrings, opts->subpixel_bits, pts)
                  : rastpy_snap(xy, npoints, opts->subpixel_bits, pts);
    if (bad >= 0) {
        if (pts != (int32_t *)(void *)local) free(pts);
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
    /* A small clip is filled whole: cutting it to the polygon's bounds
     * (and painting the background around them row by row) costs more
     * than it saves there, and a small clip's scratch is small. */
    if (c.x0 < c.x1 && c.y0 < c.y1 && (int64_t)(c.x1 - c.x0) * (c.y1 - c.y0) <= RASTPY_SMALL_CLIP) {
        b = c;
        st = RAST_OK;
    } else if (!shade && opts->algorithm == RAST_ALGO_AET && opts->boundary == RAST_BOUNDARY_EXACT &&
               ((uint64_t)npoints * 2 * RAST_AET_EDGE_BYTES >= ((uint64_t)(c.y1 - c.y0) + 1) * 4 ||
                ((size_t)(c.y1 - c.y0) < half / RAST_AET_ROW_BYTES && /* (no overflow below) */
                 RAST_AET_SCRATCH_BOUND(npoints, c.y1 - c.y0) <= half))) {
        /* The AET's scratch grows with the vertices (two edge records
         * each) and the clip's height (a count a row), never its width:
         * when the rows' counts are no more than the records, or all of
         * it fits the stack, nothing to cut, and the fill's own painter
         * writes the background (rast_fill_bounds was a pass over every
         * vertex, a twentieth of a paragraph of text's call, and with its
         * checks a tenth of the C work of a tiny polygon's
         * Canvas.fill_polygon). */
        b = c;
        st = RAST_OK;
    } else {
        st = rast_fill_bounds(opts, &poly, &c, &b);
    }
    if (st == RAST_OK)
        st = shade ? rast_polygon_gouraud_scratch_size(npoints, b.x1 - b.x0, b.y1 - b.y0, &need)
                   : rast_scratch_size(opts, npoints, b.x1 - b.x0, b.y1 - b.y0, &need);
    if (st != RAST_OK) {
        if (pts != (int32_t *)(void *)local) free(pts);
        return st;
    }
    scratch = need <= half ? (void *)(local + RASTPY_LOCAL_WORDS / 2) : malloc(need + 1);
    if (!scratch) {
        if (pts != (int32_t *)(void *)local) free(pts);
        return RASTPY_E_NOMEM;
    }
    cut.clip = b;
    st = shade && blend ? rast_fill_polygon_gouraud_blend(&cut, &poly, colors, opts, shade, blend, scratch, need)
         : shade ? rast_fill_polygon_gouraud(&cut, &poly, colors, opts, shade, scratch, need)
         /* rast_fill_polygon(_opaque) without the core's second pass over
          * the points for their range: rastpy_snap has refused every point
          * outside it (rast__fill_snapped's contract, painters/paint.h) */
         : rast__fill_target(&cut, &poly, opts, pixel, background, background != NULL, rast__fill_snapped,
                             scratch, need);
    if (scratch != (void *)(local + RASTPY_LOCAL_WORDS / 2)) free(scratch);
    if (pts != (int32_t *)(void *)local) free(pts);
    if (st == RAST_OK && background && c.x0 < c.x1 && c.y0 < c.y1 &&
        (b.x0 != c.x0 || b.y0 != c.y0 || b.x1 != c.x1 || b.y1 != c.y1)) {
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

long rastpy_fill_polygon(const rast_target *target, const double *xy,
                         uint32_t npoints, const uint32_t *ring_sizes,
                         uint32_t nrings, const rast_fill_opts *opts,
                         const void *pixel, const void *background)
{
    return rastpy_poly(target, xy, NULL, npoints, ring_sizes, nrings, opts, pixel, background, NULL, NULL, NULL);
}

/* A complete gray8 (height, width) mask, 1 inside and 0 outside, written
 * in one pass over uninitialised memory; the points at xy, or (ring_xy
 * not NULL) ring k's at ring_xy[k]. */
static long rastpy_mask_any(void *mask, int32_t height, int32_t width, const double *xy,
                            const double *const *ring_xy, uint32_t npoints, const uint32_t *ring_sizes,
                            uint32_t nrings, const rast_fill_opts *opts)
{
    static const unsigned char one = 1, zero = 0;
    rast_target t;
    rast_status st = rast_target_init(&t, mask, width, height, width, RAST_FORMAT_GRAY8);
    if (st != RAST_OK) return st;
    return rastpy_poly(&t, xy, ring_xy, npoints, ring_sizes, nrings, opts, &one, &zero, NULL, NULL, NULL);
}

long rastpy_mask_polygon(void *mask, int32_t height, int32_t width,
                         const double *xy, uint32_t npoints,
                         const uint32_t *ring_sizes, uint32_t nrings,
                         const rast_fill_opts *opts)
{
    return rastpy_mask_any(mask, height, width, xy, NULL, npoints, ring_sizes, nrings, opts);
}

/* rastpy_mask_polygon for one ring: the small-call path of polygon_mask
 * (fewer arguments for cffi to convert). */
long rastpy_mask_ring(void *mask, int32_t height, int32_t width, const double *xy,
                      uint32_t npoints, const rast_fill_opts *opts)
{
    return rastpy_mask_polygon(mask, height, width, xy, npoints, NULL, 1, opts);
}

/* rastpy_mask_polygon for the points and ring sizes as _seq.rings packs
 * them in bytes objects (polygon_mask's list of rings: a cffi call takes a
 * bytes object as a char * with no ffi.from_buffer made of it, two of
 * which were ~0.8 us of a glyph's call); ring_sizes NULL: one ring.  Their
 * memory is aligned for its items wherever CPython makes bytes objects,
 * and RASTPY_E_ALIGN says it is not (then the caller packs them anew). */
long rastpy_mask_packed(void *mask, int32_t height, int32_t width, const char *xy,
                        uint32_t npoints, const char *ring_sizes, uint32_t nrings,
                        const rast_fill_opts *opts)
{
    if ((uintptr_t)xy % sizeof(double) || (uintptr_t)ring_sizes % sizeof(uint32_t)) return RASTPY_E_ALIGN;
    return rastpy_mask_polygon(mask, height, width, (const double *)(const void *)xy, npoints,
                               (const uint32_t *)(const void *)ring_sizes, nrings, opts);
}

/* rastpy_mask_polygon with each ring's points in its own memory, as
 * _seq.ring_ptrs gives them: ring_xy their addresses, ring_sizes their
 * sizes (bytes objects, as rastpy_mask_packed takes them), npoints the
 * sizes' total; each ring snapped straight from the caller's array, with
 * no copy of them all made first (polygon_mask's list of float64 rings). */
long rastpy_mask_rings(void *mask, int32_t height, int32_t width, const char *ring_xy, uint32_t npoints,
                       const char *ring_sizes, uint32_t nrings, const rast_fill_opts *opts)
{
    if ((uintptr_t)ring_xy % sizeof(double *) || (uintptr_t)ring_sizes % sizeof(uint32_t)) return RASTPY_E_ALIGN;
    return rastpy_mask_any(mask, height, width, NULL, (const double *const *)(const void *)ring_xy, npoints,
                           (const uint32_t *)(const void *)ring_sizes, nrings, opts);
}

/* rastpy_fill_polygon for one ring, no background: the small-call path of
 * Canvas.fill_polygon (fewer arguments for cffi to convert). */
long rastpy_fill_ring(const rast_target *target, const double *xy, uint32_t npoints,
                      const rast_fill_opts *opts, const void *pixel)
{
    return rastpy_poly(target, xy, NULL, npoints, NULL, 1, opts, pixel, NULL, NULL, NULL, NULL);
}

/* Snap the 3 * ntris vertices xy (x, y float pairs), then
 * rast_fill_triangles (shade NULL) or rast_fill_triangles_shaded with
 * scratch from malloc.  Returns 0, a negative rast_status (or
 * RASTPY_E_NOMEM), or k + 1 when vertex k is bad (see rastpy_snap). */
static long rastpy_tris(const rast_target *target, const double *xy, uint32_t ntris,
                        const rast_tri_opts *opts, const void *pixel,
                        const rast_shade_opts *shade, const uint8_t *colors,
                        const int32_t *z, int32_t *zbuf, const rast_blend_opts *blend)
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
    bad = rastpy_snap(xy, n, opts->subpixel_bits, (int32_t *)(void *)mem);
    if (bad >= 0) {
        free(mem);
        return bad + 1;
    }
    if (shade && blend)
        st = rast_fill_triangles_shaded_blend(target, (const rast_point *)(void *)mem, ntris,
                                              colors, opts, shade, blend, mem + head, need);
    else st = shade ? rast_fill_triangles_shaded(target, (const rast_point *)(void *)mem, ntris, colors, z,
                                            zbuf, opts, shade, mem + head, need)
               : rast_fill_triangles(target, (const rast_point *)(void *)mem, ntris, opts, pixel,
                                     mem + head, need);
    free(mem);
    return st;
}

long rastpy_fill_triangles(const rast_target *target, const double *xy,
                           uint32_t ntris, const rast_tri_opts *opts,
                           const void *pixel)
{
    return rastpy_tris(target, xy, ntris, opts, pixel, NULL, NULL, NULL, NULL, NULL);
}

long rastpy_fill_triangles_shaded(const rast_target *target, const double *xy,
                                  uint32_t ntris, const uint8_t *colors,
                                  const int32_t *z, int32_t *zbuf,
                                  const rast_tri_opts *opts,
                                  const rast_shade_opts *shade)
{
    return rastpy_tris(target, xy, ntris, opts, NULL, shade, colors, z, zbuf, NULL);
}

/* rastpy_fill_triangles_shaded blended, without depth
 * (rast_fill_triangles_shaded_blend). */
long rastpy_fill_triangles_shaded_blend(const rast_target *target, const double *xy,
                                        uint32_t ntris, const uint8_t *colors,
                                        const rast_tri_opts *opts, const rast_shade_opts *shade,
                                        const rast_blend_opts *blend)
{
    if (!shade) return RAST_E_NULL;
    return rastpy_tris(target, xy, ntris, opts, NULL, shade, colors, NULL, NULL, blend);
}

/* rastpy_poly with vertex colours: rast_fill_polygon_gouraud, or with
 * blend not NULL rast_fill_polygon_gouraud_blend. */
long rastpy_fill_polygon_gouraud(const rast_target *target, const double *xy,
                                 uint32_t npoints, const uint32_t *ring_sizes,
                                 uint32_t nrings, const rast_fill_opts *opts,
                                 const uint8_t *colors, const rast_shade_opts *shade,
                                 const rast_blend_opts *blend)
{
    if (!shade) return RAST_E_NULL;
    return rastpy_poly(target, xy, NULL, npoints, ring_sizes, nrings, opts, NULL, NULL, colors, shade, blend);
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

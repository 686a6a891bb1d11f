/* Binding glue of the coverage calls (not part of the core): snapping,
 * scratch lent by the caller (rastpy_scratch, else malloc), and one C
 * call per Python call, writing a whole (height, width) array of uint8,
 * uint16 or uint64 (2^-62 units), or painting the coverage into a target
 * (rast_fill_polygon_aa, rast_fill_triangles_aa,
 * rast_fill_triangles_shaded_aa). */

#include <stdlib.h>
#include <string.h>
#include "coverage.h"
#include "blend.h"
#include "painters/paint.h"

static const int32_t rastpy_cov_size[3] = {1, 2, 8};

/* Where the values go: an array (target NULL: out, format, its clip) or a
 * target painted with `pixel`, or (colors not NULL) shaded with the
 * vertex colours `colors` and `shade`. */
typedef struct rastpy_cov_dest {
    void *out;
    int format;
    rast_rect clip;
    const rast_target *target;
    const void *pixel;
    const uint8_t *colors;
    const rast_shade_opts *shade;
    const rast_blend_opts *blend; /* shaded: blended (rast_fill_triangles_shaded_aa_blend);
                                     with rgba, the blend's options */
    const uint8_t *rgba;          /* not NULL: `rgba` blended through the uint8 coverage
                                     (rastpy_blend_window), colors NULL */
    const rast_gamma *gamma;      /* with rgba: linear light, or NULL */
} rastpy_cov_dest;

/* Points of a call snapped on the stack (else malloc): a small polygon's
 * call then takes only its scratch. */
#define RASTPY_COV_LOCAL_POINTS 256

/* The scratch the call of rastpy_coverage needs for `clip`. */
static rast_status rastpy_cov_need(const rastpy_cov_dest *d, const rast_coverage_opts *opts,
                                   uint32_t npoints, int triangles, const rast_rect *clip,
                                   size_t *need)
{
    int32_t w = clip->x1 - clip->x0, h = clip->y1 - clip->y0;
    if (d->colors && triangles) return rast_shaded_aa_scratch_size(opts, npoints / 3, w, h, need);
    if (d->colors) return rast_polygon_gouraud_aa_scratch_size(opts, npoints, w, h, need);
    return rast_coverage_scratch_size(opts, npoints, w, h, need);
}

/* Does rastpy_coverage check a target's options after the snap, with the
 * cut clip only?  For a plain fill (rast_coverage_scratch_size: options,
 * then the clip's size, then the point count) of a count the core takes
 * and a target clip whose size it takes: the cut clip's status is then
 * the whole clip's (the options' alone), and the points are not too many
 * to snap first; opts not NULL and its S one the snap and the cut take. */
static int rastpy_cov_late(const rastpy_cov_dest *d, const rast_coverage_opts *opts, uint32_t npoints)
{
    const rast_rect *c;
    if (!d->target || d->colors || npoints > RAST_MAX_POINTS || !opts || opts->subpixel_bits < 0 ||
        opts->subpixel_bits > RAST_MAX_SUBPIXEL_BITS)
        return 0;
    c = &d->target->clip;
    return c->x1 - (int64_t)c->x0 >= 0 && c->y1 - (int64_t)c->y0 >= 0 &&
           c->x1 - (int64_t)c->x0 <= RAST_MAX_DIM && c->y1 - (int64_t)c->y0 <= RAST_MAX_DIM;
}

/* Do the ring sizes (NULL: one ring) add up to npoints, the count the
 * scratch and the snap were made for?  (rast__fill_polygon_aa_snapped
 * reads the count from them and trusts the scratch.) */
static int rastpy_rings_add_up(const uint32_t *ring_sizes, uint32_t nrings, uint32_t npoints)
{
    uint64_t n = 0;
    uint32_t k;
    if (!ring_sizes) return 1;
    for (k = 0; k < nrings; k++) n += ring_sizes[k];
    return n == npoints;
}

static long rastpy_coverage(const rastpy_cov_dest *d, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings, int triangles,
                            const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    rast_polygon poly;
    rast_status st;
    size_t need;
    unsigned char *mem = NULL;
    int32_t *pts;
    int32_t local[2 * RASTPY_COV_LOCAL_POINTS];
    void *scratch;
    long bad;
    const rast_rect *clip = d->target ? &d->target->clip : &d->clip;
    rast_target cut;
    const rast_target *tg = NULL;
    rast_rect c;
    ptrdiff_t stride = 0;
    int late;
    size_t head = 0, total; /* a blend's window: `total` bytes, its coverage from `head` */
    st = rastpy_check_rings(npoints, ring_sizes, nrings);
    if (st != RAST_OK) return st;
    if (!d->target) {
        if (d->format < 0 || d->format > 2) return RAST_E_ARG;
        stride = (ptrdiff_t)(d->clip.x1 - d->clip.x0) * rastpy_cov_size[d->format];
    }
    /* the options and sizes checked first, with the whole clip, as the
     * core checks them (its statuses before any point's).  A target's
     * plain fill whose clip size and count the core takes
     * (rastpy_cov_late) is checked with the cut clip below instead, or
     * when a point is bad: the same status (the options' alone), and one
     * call for the scratch size, not two (issue 33). */
    late = rastpy_cov_late(d, opts, npoints);
    if (!late) {
        st = rastpy_cov_need(d, opts, npoints, triangles, clip, &need);
        if (st != RAST_OK) return st;
    }
    pts = npoints <= RASTPY_COV_LOCAL_POINTS ? local
                                             : (int32_t *)malloc((size_t)npoints * sizeof(rast_point) + 1);
    if (!pts) return RASTPY_E_NOMEM;
    bad = rastpy_snap_points(xy, npoints, opts->subpixel_bits, pts);
    if (bad >= 0) {
        if (pts != local) free(pts);
        if (late && (st = rastpy_cov_need(d, opts, npoints, triangles, clip, &need)) != RAST_OK) return st;
        return bad + 1;
    }
    if (d->target) {
        /* A target is painted only where the coverage is not 0: its clip
         * (cut to the target, as the core cuts it) cut to the points' box,
         * and the scratch that needs. */
        c = rastpy_target_clip(d->target);
        cut = *d->target;
        cut.clip = rastpy_points_box(&c, pts, npoints, opts->subpixel_bits);
        tg = &cut;
        clip = &cut.clip;
        st = rastpy_cov_need(d, opts, npoints, triangles, clip, &need);
        if (st != RAST_OK) {
            if (pts != local) free(pts);
            return st;
        }
    }
    total = need;
    if (d->rgba) { /* the cut clip's uint8 coverage after the scratch (16-byte aligned) */
        size_t wh = (size_t)(clip->x1 - clip->x0) * (size_t)(clip->y1 - clip->y0);
        head = (need + 15) & ~(size_t)15;
        total = head < need || wh > (size_t)-1 - 1 - head ? (size_t)-1 : head + wh;
    }
    if (total > (size_t)-1 - 1 || (!(sc && sc->buf && total + 1 <= sc->size) &&
                                   !(mem = (unsigned char *)malloc(total + 1)))) {
        if (pts != local) free(pts);
        return RASTPY_E_NOMEM;
    }
    if (sc) sc->want = total + 1;
    if (!mem) mem = (unsigned char *)sc->buf;
    scratch = mem;
    poly.points = (const rast_point *)(void *)pts;
    poly.ring_sizes = ring_sizes ? ring_sizes : &npoints;
    poly.nrings = ring_sizes ? nrings : 1;
    if (d->colors && !triangles && d->blend)
        st = rast_fill_polygon_gouraud_aa_blend(tg, &poly, d->colors, opts, d->shade, d->blend,
                                                scratch, need);
    else if (d->colors && !triangles)
        st = rast_fill_polygon_gouraud_aa(tg, &poly, d->colors, opts, d->shade, scratch, need);
    else if (d->colors && d->blend)
        st = rast_fill_triangles_shaded_aa_blend(tg, poly.points, npoints / 3, d->colors,
                                                 opts, d->shade, d->blend, scratch, need);
    else if (d->colors)
        st = rast_fill_triangles_shaded_aa(tg, poly.points, npoints / 3, d->colors, opts,
                                           d->shade, scratch, need);
    else if (d->rgba) {
        unsigned char *win = (unsigned char *)mem + head;
        ptrdiff_t w = clip->x1 - clip->x0;
        st = triangles ? rast_triangles_coverage(poly.points, npoints / 3, opts, clip, RAST_COVERAGE_U8,
                                                 win, w, scratch, need)
                       : rast_polygon_coverage(&poly, opts, clip, RAST_COVERAGE_U8, win, w, scratch, need);
        if (st == RAST_OK) st = rastpy_blend_window(d->target, clip, win, d->rgba, d->blend, d->gamma);
    }
    else if (d->target && triangles)
        st = rast_fill_triangles_aa(tg, poly.points, npoints / 3, opts, d->pixel, scratch,
                                    need);
#if !defined(__OPTIMIZE_SIZE__)
    else if (d->target && rastpy_rings_add_up(ring_sizes, nrings, npoints))
        /* what rast__cov_begin and rast__cov_check_points would check
         * again is checked above (rastpy_cov_need for the cut clip and
         * this count, the snap, the scratch): that function's contract */
        st = rast__fill_polygon_aa_snapped(tg, &poly, opts, d->pixel, scratch, need);
#endif
    else if (d->target)
        st = rast_fill_polygon_aa(tg, &poly, opts, d->pixel, scratch, need);
    else if (triangles)
        st = rast_triangles_coverage(poly.points, npoints / 3, opts, clip,
                                     (rast_coverage_format)d->format, d->out, stride, scratch,
                                     need);
    else
        st = rast_polygon_coverage(&poly, opts, clip, (rast_coverage_format)d->format, d->out,
                                   stride, scratch, need);
    if (!sc || mem != sc->buf) free(mem);
    if (pts != local) free(pts);
    return st;
}

/* a of a FIX62 value u (units of 2^-62) as a double: u rounded to the
 * nearest double once, then scaled by 2^-62 (exact). */
static double rastpy_fix62_value(const unsigned char *p)
{
    uint64_t u;
    memcpy(&u, p, 8);
    return (double)u * 0x1p-62;
}

#if defined(__SSE2__)
#include <emmintrin.h>
/* Two values at once, the same doubles: x86 has no unsigned (before
 * AVX-512) nor vector 64-bit integer conversion, and the scalar one (a
 * test, a branch, a conversion) was half of a 512 x 512 float call.  Each
 * 32-bit half goes into the mantissa of a double: hi = 2^84 + h 2^32 and
 * lo = 2^52 + l, exact; (hi - (2^84 + 2^52)) = h 2^32 - 2^52 is exact too,
 * and adding lo gives h 2^32 + l = u rounded once, to the nearest. */
static __m128d rastpy_fix62_pair(const unsigned char *p)
{
    const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)p);
    const __m128i lo = _mm_or_si128(_mm_and_si128(v, _mm_set1_epi64x(0xFFFFFFFF)),
                                    _mm_set1_epi64x(0x4330000000000000));
    const __m128i hi = _mm_or_si128(_mm_srli_epi64(v, 32), _mm_set1_epi64x(0x4530000000000000));
    const __m128d u = _mm_add_pd(_mm_sub_pd(_mm_castsi128_pd(hi), _mm_set1_pd(0x1p84 + 0x1p52)),
                                 _mm_castsi128_pd(lo));
    return _mm_mul_pd(u, _mm_set1_pd(0x1p-62));
}
#endif

void rastpy_fix62_to_double(void *buf, size_t n)
{
    unsigned char *p = (unsigned char *)buf;
    size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= n; i += 2, p += 16) _mm_storeu_pd((double *)(void *)p, rastpy_fix62_pair(p));
#endif
    for (; i < n; i++, p += 8) {
        double a = rastpy_fix62_value(p);
        memcpy(p, &a, 8);
    }
}

void rastpy_fix62_to_float(const void *buf, void *out, size_t n)
{
    const unsigned char *p = (const unsigned char *)buf;
    float *o = (float *)out; /* a numpy float32 array's memory: aligned */
    size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= n; i += 2, p += 16) _mm_storel_pi((__m64 *)(void *)(o + i), _mm_cvtpd_ps(rastpy_fix62_pair(p)));
#endif
    for (; i < n; i++, p += 8) o[i] = (float)rastpy_fix62_value(p);
}

static rastpy_cov_dest rastpy_array(void *out, int32_t height, int32_t width, int format)
{
    rastpy_cov_dest d;
    d.out = out;
    d.format = format;
    d.clip.x0 = d.clip.y0 = 0;
    d.clip.x1 = width;
    d.clip.y1 = height;
    d.target = NULL;
    d.pixel = NULL;
    d.colors = NULL;
    d.shade = NULL;
    d.blend = NULL;
    d.rgba = NULL;
    d.gamma = NULL;
    return d;
}

static rastpy_cov_dest rastpy_paint(const rast_target *target, const void *pixel)
{
    rastpy_cov_dest d = rastpy_array(NULL, 0, 0, 0);
    d.target = target;
    d.pixel = pixel;
    return d;
}

/* A shaded fill's destination: the target, a colour per vertex, the
 * shading and the blend (NULL: the colours stored). */
static rastpy_cov_dest rastpy_shaded(const rast_target *target, const uint8_t *colors,
                                     const rast_shade_opts *shade, const rast_blend_opts *blend)
{
    rastpy_cov_dest d = rastpy_paint(target, NULL);
    d.colors = colors;
    d.shade = shade;
    d.blend = blend;
    return d;
}

long rastpy_polygon_coverage(void *out, int32_t height, int32_t width, int format,
                             const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    rastpy_cov_dest d = rastpy_array(out, height, width, format);
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, 0, opts, sc);
}

long rastpy_triangles_coverage(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t ntris, const rast_coverage_opts *opts,
                               rastpy_scratch *sc)
{
    rastpy_cov_dest d = rastpy_array(out, height, width, format);
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

long rastpy_fill_polygon_aa(const rast_target *target, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings,
                            const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target) return RAST_E_NULL;
    d = rastpy_paint(target, pixel);
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, 0, opts, sc);
}

long rastpy_fill_triangles_aa(const rast_target *target, const double *xy, uint32_t ntris,
                              const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target) return RAST_E_NULL;
    d = rastpy_paint(target, pixel);
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

/* `rgba` blended (docs/opacity.md) through the polygon's uint8 coverage
 * (ring_sizes NULL: one ring) or, with `triangles`, that of the union of
 * npoints / 3 triangles: computed and blended over the points' box only
 * (rastpy_points_box: a pixel outside it has coverage 0, which leaves it
 * as it is), not the whole target; the same pixels as
 * rast_blend_coverage(_linear) of the whole target's coverage. */
static long rastpy_blend_cov(const rast_target *target, const double *xy, uint32_t npoints,
                             const uint32_t *ring_sizes, uint32_t nrings, int triangles,
                             const rast_coverage_opts *opts, const uint8_t *rgba,
                             const rast_blend_opts *blend, const rast_gamma *gamma, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target || !rgba) return RAST_E_NULL;
    d = rastpy_paint(target, NULL);
    d.rgba = rgba;
    d.blend = blend;
    d.gamma = gamma;
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, triangles, opts, sc);
}

long rastpy_blend_polygon_coverage(const rast_target *target, const double *xy, uint32_t npoints,
                                   const uint32_t *ring_sizes, uint32_t nrings,
                                   const rast_coverage_opts *opts, const uint8_t *rgba,
                                   const rast_blend_opts *blend, const rast_gamma *gamma,
                                   rastpy_scratch *sc)
{
    return rastpy_blend_cov(target, xy, npoints, ring_sizes, nrings, 0, opts, rgba, blend, gamma, sc);
}

long rastpy_blend_triangles_coverage(const rast_target *target, const double *xy, uint32_t ntris,
                                     const rast_coverage_opts *opts, const uint8_t *rgba,
                                     const rast_blend_opts *blend, const rast_gamma *gamma,
                                     rastpy_scratch *sc)
{
    if (ntris > RAST_MAX_POINTS / 3) return RAST_E_TOO_MANY;
    return rastpy_blend_cov(target, xy, 3 * ntris, NULL, 0, 1, opts, rgba, blend, gamma, sc);
}

/* Shaded triangles with coverage, blended (opacity, the colours' alpha)
 * or, with blend NULL, stored. */
long rastpy_fill_triangles_shaded_aa_blend(const rast_target *target, const double *xy,
                                           uint32_t ntris, const uint8_t *colors,
                                           const rast_coverage_opts *opts,
                                           const rast_shade_opts *shade,
                                           const rast_blend_opts *blend, rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target || !colors || !shade) return RAST_E_NULL;
    d = rastpy_shaded(target, colors, shade, blend);
    return rastpy_coverage(&d, xy, 3 * ntris, NULL, 0, 1, opts, sc);
}

long rastpy_fill_triangles_shaded_aa(const rast_target *target, const double *xy, uint32_t ntris,
                                     const uint8_t *colors, const rast_coverage_opts *opts,
                                     const rast_shade_opts *shade, rastpy_scratch *sc)
{
    return rastpy_fill_triangles_shaded_aa_blend(target, xy, ntris, colors, opts, shade, NULL, sc);
}

/* A polygon with a colour per vertex, with coverage: blended (opacity,
 * the colours' alpha) or, with blend NULL, as rast_fill_polygon_gouraud_aa. */
long rastpy_fill_polygon_gouraud_aa(const rast_target *target, const double *xy, uint32_t npoints,
                                    const uint32_t *ring_sizes, uint32_t nrings,
                                    const uint8_t *colors, const rast_coverage_opts *opts,
                                    const rast_shade_opts *shade, const rast_blend_opts *blend,
                                    rastpy_scratch *sc)
{
    rastpy_cov_dest d;
    if (!target || !colors || !shade) return RAST_E_NULL;
    d = rastpy_shaded(target, colors, shade, blend);
    return rastpy_coverage(&d, xy, npoints, ring_sizes, nrings, 0, opts, sc);
}

/*
 * fuzz_blend.c - the binding's translucent fills (python/glue/blend.c and
 * the "blend" destination of python/glue/coverage.c): rastpy_blend_polygon,
 * rastpy_blend_triangles, rastpy_blend_polygon_coverage and
 * rastpy_blend_triangles_coverage compute the mask or coverage over the
 * geometry's pixel box only and blend that window (docs/opacity.md).
 *
 * Input: a target (every format, the four the blend takes most often; up
 * to 64 x 64; a clip around it; a stride with 0..7 bytes of padding; the
 * pixels from a generator seeded by the input), a polygon (1..3 rings,
 * their sizes sometimes any values: not summing to the points, or summing
 * to them only modulo 2^32, which the glue refuses) or triangles,
 * with float64 coordinates near
 * the target, anywhere in range, out of it, NaN or infinite; the options
 * (binary: algorithm, rule, S, sample, rounding, boundary; coverage:
 * method, rule, S, sample; some invalid), an RGBA colour, the blend
 * (opacity, premultiplied, or NULL; some invalid) and sometimes gamma
 * tables (a power law or linear; sometimes not increasing).
 *
 * The input's last byte 1 takes the polygon to the 64-bit path
 * (rastpy_blend_polygon64 / rastpy_blend_polygon_coverage64, S up to 32;
 * oracle rast_fill_polygon64_spans / rast_polygon_coverage64), 2 takes its
 * points, snapped, as a polyline (rastpy_blend_polyline, any line
 * algorithm and sample; oracle rast_draw_polyline_spans), both over the
 * whole cut clip as below.
 *
 * Oracle, the whole-canvas way with public core calls: the snapped points
 * (the glue's own snap, tested elsewhere) filled over the whole cut clip
 * (rast_fill_polygon_spans / rast_fill_triangles_spans into a 255 mask, or
 * rast_polygon_coverage / rast_triangles_coverage as uint8), then
 * rast_blend_coverage or rast_blend_coverage_linear over that clip, on a
 * copy of the memory.  The glue's status equals the oracle's (a bad point
 * k: k + 1, after the coverage options' errors for the coverage calls, as
 * the other coverage calls order them), every byte of the memory equals
 * the oracle's (so the guard bytes around the target, the stride padding
 * and the pixels outside the clip are never written), and on an error the
 * memory is untouched.  The glue is compiled in (#include), as Python
 * builds it.
 */
#include "glue.h"
#include "fuzz.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BZ_MAXDIM 64
#define BZ_MAXPAD 7
#define BZ_GUARD 64 /* bytes before and after the target's rows */
#define BZ_MEM (2 * BZ_GUARD + BZ_MAXDIM * (BZ_MAXDIM * 4 + BZ_MAXPAD))
#define BZ_MAXPTS 300 /* past RASTPY_BLEND_LOCAL_POINTS: the malloc path too */

static unsigned char bz_orig[BZ_MEM], bz_glue[BZ_MEM], bz_want[BZ_MEM];
static uint8_t bz_mask[BZ_MAXDIM * BZ_MAXDIM];
static double bz_xy[2 * BZ_MAXPTS];
static int32_t bz_pts[2 * BZ_MAXPTS];
static int64_t bz_pts64[2 * BZ_MAXPTS];
static rast_gamma bz_gamma;

/* Mask spans over the whole target: 255 where a span is. */
static void bz_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    int32_t w = *(const int32_t *)user;
    FZ_ASSERT(x0 < x1 && y >= 0 && x0 >= 0 && x1 <= w);
    memset(bz_mask + (size_t)y * (size_t)w + (size_t)x0, 255, (size_t)(x1 - x0));
}

/* The oracle's blend of bz_mask's cut clip c (w columns) into cut. */
static rast_status bz_blend(const rast_target *cut, const rast_rect *c, int32_t w, const uint8_t *rgba,
                            const rast_blend_opts *blend, const rast_gamma *gamma)
{
    const uint8_t *cov = bz_mask + c->y0 * w + c->x0;
    return gamma ? rast_blend_coverage_linear(cut, cov, RAST_COVERAGE_U8, w, rgba, blend, gamma)
                 : rast_blend_coverage(cut, cov, RAST_COVERAGE_U8, w, rgba, blend);
}

/* A coordinate in pixels: fz_coord's (units of 1/2^s) as a double, or that
 * plus a fraction of a unit (the snap's rounding), or a value no snap takes. */
static double bz_coord(fz_in *in, int s, int32_t extent)
{
    uint32_t m = fz_u8(in);
    int32_t v;
    if (m >= 250) {
        static const double odd[6] = {0.0, 0.0, 0.0, 1e300, -3e9, 3e9};
        if (m == 250) return NAN;
        if (m == 251) return INFINITY;
        if (m == 252) return -INFINITY;
        return odd[m - 250];
    }
    v = fz_coord(in, s, extent);
    if (m & 1) return ((double)v + (double)fz_u8(in) / 256.0) / (double)(1 << s);
    return (double)v / (double)(1 << s);
}

static void bz_gamma_init(fz_in *in)
{
    uint32_t k, kind = fz_u8(in);
    for (k = 0; k < 256; k++) bz_gamma.dec8[k] = kind & 1 ? k * k * 258u : k * 65793u;
    for (k = 0; k < 64; k++) bz_gamma.dec6[k] = kind & 2 ? k * k * 4227u : k * 266305u;
    for (k = 0; k < 32; k++) bz_gamma.dec5[k] = kind & 4 ? k * k * 17458u : k * 541200u;
    if (kind >= 248) bz_gamma.dec8[kind - 247] = bz_gamma.dec8[kind - 248]; /* not increasing */
    if (kind == 247) bz_gamma.dec5[31] = (1u << 24) + 1;                  /* above 2^24 */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_target t, cut;
    rast_rect c;
    rast_format f;
    int32_t w, h, bpp = 1, x, y, s;
    ptrdiff_t stride;
    uint32_t kind, npoints, nrings = 1, rings[3], i, seed, ntris = 0;
    int triangles, coverage, has_rings, sizes_ok, closed = 0;
    uint32_t mode;
    int32_t s64 = 0;
    rast_line_opts lo;
    rast_fill_opts fo;
    rast_tri_opts to;
    rast_coverage_opts co;
    rast_blend_opts bo, *blend = NULL;
    const rast_gamma *gamma = NULL;
    uint8_t rgba[4];
    long got, want;
    rast_status st;
    size_t need = 0;
    void *scratch = NULL;
    rast_polygon poly;

    /* the target */
    {
        static const rast_format blendable[4] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888,
                                                 RAST_FORMAT_RGB565, RAST_FORMAT_RGBA8888};
        f = fz_u8(&in) < 224 ? blendable[fz_u8(&in) % 4] : fz_format(&in);
    }
    w = 1 + fz_below(&in, BZ_MAXDIM);
    h = 1 + fz_below(&in, BZ_MAXDIM);
    rast_format_bytes(f, &bpp);
    if (bpp < 1) bpp = 1;
    stride = (ptrdiff_t)w * bpp + (ptrdiff_t)(fz_u8(&in) % (BZ_MAXPAD + 1));
    if (f == RAST_FORMAT_MONO1) stride = (w + 7) / 8 + (ptrdiff_t)(fz_u8(&in) % (BZ_MAXPAD + 1));
    seed = fz_u32(&in) | 1u;
    for (i = 0; i < BZ_MEM; i++) {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        bz_orig[i] = (unsigned char)(seed >> 24);
    }
    if (rast_target_init(&t, bz_orig + BZ_GUARD, w, h, stride, f) != RAST_OK) return 0;
    t.clip = fz_clip(&in, w, h);
    /* the oracle's clip: the target's cut to the target (each side clamped) */
    c = t.clip;
    c.x0 = c.x0 < 0 ? 0 : c.x0 > w ? w : c.x0;
    c.y0 = c.y0 < 0 ? 0 : c.y0 > h ? h : c.y0;
    c.x1 = c.x1 < c.x0 ? c.x0 : c.x1 > w ? w : c.x1;
    c.y1 = c.y1 < c.y0 ? c.y0 : c.y1 > h ? h : c.y1;
    cut = t;
    cut.clip = c;

    /* the call and its options */
    kind = fz_u8(&in);
    triangles = kind & 1;
    coverage = (kind >> 1) & 1;
    s = fz_below(&in, RAST_MAX_SUBPIXEL_BITS + 1);
    memset(&fo, 0, sizeof fo);
    memset(&to, 0, sizeof to);
    memset(&co, 0, sizeof co);
    if (coverage) {
        co.method = (rast_aa_method)fz_below(&in, RAST_AA_COUNT_ + 1);
        co.rule = (rast_fill_rule)fz_below(&in, 3);
        co.subpixel_bits = s;
        co.sample = (rast_sample)fz_below(&in, 3);
    } else if (triangles) {
        to.algorithm = (rast_tri_algorithm)fz_below(&in, RAST_TRI_COUNT_ + 1);
        to.subpixel_bits = s;
        to.sample = (rast_sample)fz_below(&in, 2);
        to.rounding = (rast_rounding)fz_below(&in, 2);
        to.boundary = (rast_boundary)fz_below(&in, 3);
    } else {
        fo = fz_fill_opts(&in);
        fo.subpixel_bits = s;
    }
    if (kind & 4) { /* an invalid S: checked after the snap, which needs a valid one */
        if (coverage) co.subpixel_bits = RAST_MAX_SUBPIXEL_BITS + 1;
    }
    for (i = 0; i < 4; i++) rgba[i] = (uint8_t)fz_u8(&in);
    if (kind & 8) {
        uint32_t o = fz_u8(&in);
        bo.opacity = o == 255 ? (int32_t)fz_u8(&in) - 8 + ((fz_u8(&in) & 1) ? 256 : 0) : (int32_t)o;
        if (o == 254) bo.opacity = 255;
        bo.premultiplied = (int32_t)(fz_u8(&in) % 3 == 2 ? fz_u8(&in) % 3 : 0);
        blend = &bo;
    }
    if (kind & 16) {
        bz_gamma_init(&in);
        gamma = &bz_gamma;
    }

    /* the geometry */
    if (triangles) {
        ntris = (uint32_t)fz_below(&in, 5);
        npoints = 3 * ntris;
        has_rings = 0;
    } else {
        has_rings = kind & 32;
        nrings = has_rings ? 1 + (uint32_t)fz_below(&in, 3) : 1;
        npoints = 0;
        for (i = 0; i < nrings; i++) {
            rings[i] = (uint32_t)fz_below(&in, 9);
            npoints += rings[i];
        }
    }
    for (i = 0; i < npoints; i++) {
        bz_xy[2 * i] = bz_coord(&in, s, w);
        bz_xy[2 * i + 1] = bz_coord(&in, s, h);
    }
    if (!triangles && (kind & 64) && npoints > 0) { /* many points: the glue's malloc */
        for (i = npoints; i < BZ_MAXPTS; i++) {
            bz_xy[2 * i] = bz_xy[2 * (i % npoints)] + (double)(i / npoints) / 64.0;
            bz_xy[2 * i + 1] = bz_xy[2 * (i % npoints) + 1];
        }
        rings[nrings - 1] += BZ_MAXPTS - npoints;
        npoints = BZ_MAXPTS;
    }
    /* ring sizes fuzzed freely: the core reads their sum, and the glue
     * refuses (RAST_E_ARG, before anything is read past the points or
     * written) any sum but npoints (rastpy_check_rings): one short, one
     * ring set to any value, or sizes whose 32-bit sum wraps to npoints */
    sizes_ok = 1;
    if (has_rings) {
        uint32_t mode = fz_u8(&in);
        uint64_t sum = 0;
        if (mode == 255 && rings[0] > 0) rings[0]--;
        if (mode >= 240 && mode < 255) rings[fz_below(&in, (int32_t)nrings)] = fz_u32(&in);
        if (mode == 239 && nrings >= 2) {
            rings[0] = 0xFFFFFFFFu;
            rings[1] = npoints + 1u - (nrings == 3 ? rings[2] : 0u);
        }
        for (i = 0; i < nrings; i++) sum += rings[i];
        sizes_ok = sum == npoints;
    }

    /* the last byte read: 1, the polygon on the 64-bit path (S up to 32);
     * 2, the points as a polyline (rastpy_blend_polyline) */
    mode = triangles ? 0 : fz_u8(&in);
    if (mode == 1) {
        s64 = s + fz_below(&in, RAST_MAX_SUBPIXEL_BITS64 - RAST_MAX_SUBPIXEL_BITS + 1);
        fo.subpixel_bits = s64;
        co.subpixel_bits = (kind & 4) ? RAST_MAX_SUBPIXEL_BITS64 + 1 : s64;
    } else if (mode == 2) {
        memset(&lo, 0, sizeof lo);
        lo.algorithm = (rast_line_algorithm)fz_below(&in, RAST_LINE_COUNT_ + 1);
        lo.subpixel_bits = (kind & 4) ? RAST_MAX_SUBPIXEL_BITS + 1 : s;
        lo.sample = (rast_sample)fz_below(&in, 3);
        closed = fz_u8(&in) & 1;
        /* the glue takes the points snapped (Python snaps them) */
        if (rastpy_snap_points(bz_xy, npoints, s, bz_pts) >= 0) return 0;
    }

    /* the glue */
    memcpy(bz_glue, bz_orig, BZ_MEM);
    t.pixels = bz_glue + BZ_GUARD;
    if (mode == 1)
        got = coverage ? rastpy_blend_polygon_coverage64(&t, bz_xy, npoints, has_rings ? rings : NULL, nrings,
                                                         &co, rgba, blend, gamma)
                       : rastpy_blend_polygon64(&t, bz_xy, npoints, has_rings ? rings : NULL, nrings, &fo,
                                                rgba, blend, gamma);
    else if (mode == 2)
        got = rastpy_blend_polyline(&t, (const rast_point *)(void *)bz_pts, npoints, closed, &lo, rgba, blend,
                                    gamma);
    else if (coverage)
        got = triangles ? rastpy_blend_triangles_coverage(&t, bz_xy, ntris, &co, rgba, blend, gamma, NULL)
                        : rastpy_blend_polygon_coverage(&t, bz_xy, npoints, has_rings ? rings : NULL,
                                                        nrings, &co, rgba, blend, gamma, NULL);
    else
        got = triangles ? rastpy_blend_triangles(&t, bz_xy, ntris, &to, rgba, blend, gamma)
                        : rastpy_blend_polygon(&t, bz_xy, npoints, has_rings ? rings : NULL, nrings,
                                               &fo, rgba, blend, gamma);

    /* the oracle: the whole cut clip's mask or coverage, then its blend */
    memcpy(bz_want, bz_orig, BZ_MEM);
    cut.pixels = bz_want + BZ_GUARD;
    want = sizes_ok || mode == 2 ? RAST_OK : RAST_E_ARG; /* the sizes first, as the glue checks them */
    if (mode == 1 && want == RAST_OK) { /* the 64-bit path over the whole cut clip */
        int32_t cw = c.x1 - c.x0, ch = c.y1 - c.y0;
        rast_polygon64 p64;
        long bad = rastpy_snap64(bz_xy, npoints, coverage ? co.subpixel_bits : s64, bz_pts64);
        memset(bz_mask, 0, sizeof bz_mask);
        p64.points = (const rast_point64 *)(void *)bz_pts64;
        p64.ring_sizes = has_rings ? rings : &npoints;
        p64.nrings = nrings;
        if (bad >= 0)
            want = bad + 1;
        else {
            st = coverage ? rast_coverage64_scratch_size(&co, npoints, cw, ch, &need)
                          : rast_scratch_size64(&fo, npoints, cw, ch, &need);
            if (st == RAST_OK) {
                scratch = malloc(need + 1);
                FZ_ASSERT(scratch);
                st = coverage ? rast_polygon_coverage64(&p64, &co, &c, RAST_COVERAGE_U8, bz_mask + c.y0 * w + c.x0,
                                                        w, scratch, need)
                              : rast_fill_polygon64_spans(&p64, &fo, &c, bz_span, &w, scratch, need);
                free(scratch);
            }
            if (st == RAST_OK)
                st = bz_blend(&cut, &c, w, rgba, blend, gamma);
            want = st;
        }
    } else if (mode == 2) { /* the polyline's spans over the whole cut clip */
        memset(bz_mask, 0, sizeof bz_mask);
        st = rast_draw_polyline_spans((const rast_point *)(void *)bz_pts, npoints, closed, &lo, &c, bz_span, &w);
        if (st == RAST_OK)
            st = bz_blend(&cut, &c, w, rgba, blend, gamma);
        want = st;
    } else if (want == RAST_OK && coverage) { /* the options' errors first, as every coverage call of the binding */
        want = rast_coverage_scratch_size(&co, npoints, t.clip.x1 - t.clip.x0, t.clip.y1 - t.clip.y0, &need);
    }
    if (want == RAST_OK && mode != 1 && mode != 2) {
        long bad = rastpy_snap_points(bz_xy, npoints, coverage ? co.subpixel_bits : s, bz_pts);
        if (bad >= 0) want = bad + 1;
    }
    if (want == RAST_OK && mode != 1 && mode != 2) {
        int32_t cw = c.x1 - c.x0, ch = c.y1 - c.y0;
        poly.points = (const rast_point *)(void *)bz_pts;
        poly.ring_sizes = has_rings ? rings : &npoints;
        poly.nrings = nrings;
        memset(bz_mask, 0, sizeof bz_mask);
        if (coverage)
            st = rast_coverage_scratch_size(&co, npoints, cw, ch, &need);
        else if (triangles)
            st = rast_tri_scratch_size(&to, cw, ch, &need);
        else
            st = rast_scratch_size(&fo, npoints, cw, ch, &need);
        if (st == RAST_OK) {
            scratch = malloc(need + 1);
            FZ_ASSERT(scratch);
            if (coverage && triangles)
                st = rast_triangles_coverage(poly.points, ntris, &co, &c, RAST_COVERAGE_U8,
                                             bz_mask + c.y0 * w + c.x0, w, scratch, need);
            else if (coverage)
                st = rast_polygon_coverage(&poly, &co, &c, RAST_COVERAGE_U8, bz_mask + c.y0 * w + c.x0, w,
                                           scratch, need);
            else if (triangles)
                st = rast_fill_triangles_spans(poly.points, ntris, &to, &c, bz_span, &w, scratch, need);
            else
                st = rast_fill_polygon_spans(&poly, &fo, &c, bz_span, &w, scratch, need);
            free(scratch);
        }
        if (st == RAST_OK)
            st = bz_blend(&cut, &c, w, rgba, blend, gamma);
        want = st;
    }
    if (got != want) {
        fprintf(stderr, "status: glue %ld, oracle %ld (%s%s, format %d, %d x %d, clip %d %d %d %d)\n", got,
                want, coverage ? "coverage " : "", triangles ? "triangles" : "polygon", (int)f, (int)w,
                (int)h, (int)t.clip.x0, (int)t.clip.y0, (int)t.clip.x1, (int)t.clip.y1);
        FZ_ASSERT(got == want);
    }
    if (got != RAST_OK) FZ_ASSERT(memcmp(bz_glue, bz_orig, BZ_MEM) == 0);
    if (memcmp(bz_glue, bz_want, BZ_MEM) != 0) {
        for (i = 0; i < BZ_MEM; i++)
            if (bz_glue[i] != bz_want[i]) {
                long off = (long)i - BZ_GUARD;
                fprintf(stderr, "byte %ld (row %ld, byte %ld of it): glue %u, oracle %u\n", off,
                        off / (long)stride, off % (long)stride, bz_glue[i], bz_want[i]);
                break;
            }
        FZ_ASSERT(!"the glue's pixels are the whole target's blend");
    }
    /* and what the oracle wrote stays in the clip's pixels */
    for (y = -1; y <= h; y++) {
        const unsigned char *a = bz_want + BZ_GUARD + (ptrdiff_t)y * stride,
                            *b = bz_orig + BZ_GUARD + (ptrdiff_t)y * stride;
        if (y < 0 || y >= h) continue;
        for (x = 0; x < (int32_t)stride; x++)
            if (a[x] != b[x]) FZ_ASSERT(y >= c.y0 && y < c.y1 && x >= c.x0 * bpp && x < c.x1 * bpp);
    }
    FZ_ASSERT(memcmp(bz_want, bz_orig, BZ_GUARD) == 0);
    FZ_ASSERT(memcmp(bz_want + BZ_GUARD + (ptrdiff_t)h * stride, bz_orig + BZ_GUARD + (ptrdiff_t)h * stride,
                     BZ_MEM - BZ_GUARD - (size_t)h * (size_t)stride) == 0);
    return 0;
}

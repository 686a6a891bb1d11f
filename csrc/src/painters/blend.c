/*
 * blend.c - opacity (rastrum.h, "opacity: source-over"): an 8-bit RGBA
 * colour whose alpha (times an opacity level, times a pixel's coverage)
 * is applied, source-over, to GRAY8, RGB888, RGB565 and RGBA8888
 * (straight or premultiplied) targets.  A painter of its own, so that the
 * solid painter of the opaque fills (paint.c, formats.c) is untouched and
 * only callers of these entry points link this file.
 *
 * Rounding, once per step (docs/opacity.md):
 *  - the pixel's alpha level A = round(alpha * opacity * c / (255 * C)),
 *    c the coverage level out of C (255: binary fills, inside; uint8
 *    coverage; 65535: uint16 coverage): the level of the product of the
 *    three fractions alpha/255, opacity/255 and c/C; 255^2 and 255 * 65535
 *    are odd, so the nearest integer is never a tie;
 *  - each channel mixed by rast__blend8 at level A (premultiplied: the
 *    source's alpha channel is 255, its colour channels the straight
 *    ones), except straight RGBA8888's colour channels: the exact straight
 *    colour of the exact mix, (s A 255 + d a (255 - A)) / (255 A + a (255 - A)),
 *    rounded half up.
 * A = 0 leaves the pixel untouched.  Integers only, 32 bits.
 *
 * rast_blend_coverage_linear mixes in linear light through the caller's
 * tables (rast_gamma, docs/opacity.md "Linear light"): the same A; each
 * colour channel the level whose table value is nearest the exact mix of
 * the table values, the lower on a tie (rast__encode); 64-bit products.
 */
#include <string.h>

#include "paint.h"

typedef struct rast__blender {
    unsigned char *base;
    ptrdiff_t stride;
    rast_format format;
    int premultiplied;
    unsigned src[4];  /* the colour in the target's channel levels */
    uint32_t ao;      /* alpha * opacity, 0 .. 255^2 */
    unsigned full;    /* A of a full run (c = 255) */
    const rast_gamma *gamma; /* NULL: stored levels (rast_blend_coverage) */
} rast__blender;

/* A for a uint8 coverage level c (0..255): round(ao c / 255^2); ao c is
 * at most 255^3. */
static unsigned rast__level8(uint32_t ao, unsigned c)
{
    return (unsigned)((ao * c + 32512u) / 65025u);
}

/* A for a uint16 coverage level c (0..65535): round(ao c / (255 65535));
 * ao c + 8355712 is at most 4,269,769,087 < 2^32. */
static unsigned rast__level16(uint32_t ao, unsigned c)
{
    return (unsigned)(((uint32_t)ao * c + 8355712u) / 16711425u);
}

/* Pixel x of `row` with the colour at alpha level a (1..255). */
static void rast__blend_px(const rast__blender *b, unsigned char *row, int32_t x, unsigned a)
{
    unsigned char *p;
    uint16_t d;
    unsigned da, m, k;
    switch (b->format) {
    case RAST_FORMAT_GRAY8:
        row[x] = (unsigned char)rast__blend8(b->src[0], row[x], a);
        break;
    case RAST_FORMAT_RGB888:
        p = row + (ptrdiff_t)x * 3;
        for (k = 0; k < 3; k++) p[k] = (unsigned char)rast__blend8(b->src[k], p[k], a);
        break;
    case RAST_FORMAT_RGB565:
        memcpy(&d, row + (ptrdiff_t)x * 2, 2);
        d = (uint16_t)((rast__blend8(b->src[0], (unsigned)d >> 11, a) << 11) |
                       (rast__blend8(b->src[1], ((unsigned)d >> 5) & 63u, a) << 5) |
                       rast__blend8(b->src[2], (unsigned)d & 31u, a));
        memcpy(row + (ptrdiff_t)x * 2, &d, 2);
        break;
    default: /* RAST_FORMAT_RGBA8888 */
        p = row + (ptrdiff_t)x * 4;
        da = p[3];
        if (!b->premultiplied) {
            /* m = 255 x the exact alpha of the mix, > 0 since a > 0; the
             * numerators stay below 2^25 */
            m = 255u * a + da * (255u - a);
            for (k = 0; k < 3; k++) {
                unsigned num = b->src[k] * a * 255u + p[k] * da * (255u - a);
                p[k] = (unsigned char)((2u * num + m) / (2u * m));
            }
        } else {
            for (k = 0; k < 3; k++) p[k] = (unsigned char)rast__blend8(b->src[k], p[k], a);
        }
        p[3] = (unsigned char)rast__blend8(255u, da, a);
        break;
    }
}

/* The level k of 0..n-1 whose dec[k] is nearest x / den (the lower level on
 * a tie): the number of midpoints (dec[j] + dec[j + 1]) / 2, j < n - 1,
 * strictly below x / den, by bisection over the strictly increasing table
 * (2 x < 2^42 and den (dec[j] + dec[j + 1]) < 2^16 2^25: no overflow). */
static unsigned rast__encode(const uint32_t *dec, unsigned n, uint64_t x, uint64_t den)
{
    unsigned lo = 0, hi = n - 1;
    while (lo < hi) {
        unsigned mid = (lo + hi) / 2;
        if (2u * x > den * ((uint64_t)dec[mid] + dec[mid + 1]))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Channel d (of n levels, table dec) after source s at alpha level a in
 * linear light: the level nearest (dec[s] a + dec[d] (255 - a)) / 255. */
static unsigned rast__lin(const uint32_t *dec, unsigned n, unsigned s, unsigned d, unsigned a)
{
    return rast__encode(dec, n, (uint64_t)dec[s] * a + (uint64_t)dec[d] * (255u - a), 255u);
}

/* Pixel x of `row` with the colour at alpha level a (1..255), mixed in
 * linear light (b->gamma; straight alpha). */
static void rast__blend_px_linear(const rast__blender *b, unsigned char *row, int32_t x, unsigned a)
{
    const rast_gamma *g = b->gamma;
    unsigned char *p;
    uint16_t d;
    unsigned da, m, k;
    switch (b->format) {
    case RAST_FORMAT_GRAY8:
        row[x] = (unsigned char)rast__lin(g->dec8, 256u, b->src[0], row[x], a);
        break;
    case RAST_FORMAT_RGB888:
        p = row + (ptrdiff_t)x * 3;
        for (k = 0; k < 3; k++) p[k] = (unsigned char)rast__lin(g->dec8, 256u, b->src[k], p[k], a);
        break;
    case RAST_FORMAT_RGB565:
        memcpy(&d, row + (ptrdiff_t)x * 2, 2);
        d = (uint16_t)((rast__lin(g->dec5, 32u, b->src[0], (unsigned)d >> 11, a) << 11) |
                       (rast__lin(g->dec6, 64u, b->src[1], ((unsigned)d >> 5) & 63u, a) << 5) |
                       rast__lin(g->dec5, 32u, b->src[2], (unsigned)d & 31u, a));
        memcpy(row + (ptrdiff_t)x * 2, &d, 2);
        break;
    default: /* RAST_FORMAT_RGBA8888, straight: the linear colour of the
              * exact source-over, (dec[s] a 255 + dec[d] da (255 - a)) / m */
        p = row + (ptrdiff_t)x * 4;
        da = p[3];
        m = 255u * a + da * (255u - a);
        for (k = 0; k < 3; k++)
            p[k] = (unsigned char)rast__encode(
                g->dec8, 256u,
                (uint64_t)g->dec8[b->src[k]] * a * 255u + (uint64_t)g->dec8[p[k]] * da * (255u - a), m);
        p[3] = (unsigned char)rast__blend8(255u, da, a);
        break;
    }
}

/* Each table strictly increasing and at most 2^24. */
static int rast__gamma_ok(const rast_gamma *g)
{
    const uint32_t *t[3];
    static const unsigned n[3] = {256u, 64u, 32u};
    unsigned i, k;
    t[0] = g->dec8;
    t[1] = g->dec6;
    t[2] = g->dec5;
    for (i = 0; i < 3; i++) {
        if (t[i][n[i] - 1] > (1u << 24)) return 0;
        for (k = 0; k + 1 < n[i]; k++)
            if (t[i][k] >= t[i][k + 1]) return 0;
    }
    return 1;
}

static void rast__blend_full(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__blender *b = (const rast__blender *)user;
    unsigned char *row = b->base + (ptrdiff_t)y * b->stride;
    int32_t k, x;
    if (!b->full) return;
    for (k = 0; k < n; k++)
        for (x = xs[2 * k]; x < xs[2 * k + 1]; x++) rast__blend_px(b, row, x, b->full);
}

static void rast__blend_levels(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__blender *b = (const rast__blender *)user;
    unsigned char *row = b->base + (ptrdiff_t)y * b->stride;
    int32_t x;
    for (x = x0; x < x1; x++) {
        unsigned a = rast__level8(b->ao, cov[x - x0]);
        if (a) rast__blend_px(b, row, x, a);
    }
}

/* Check the target, colour and options; set up *b and the painter *p
 * (full and levels entries) for the target's clip, into *clip. */
static rast_status rast__blend_init(rast__blender *b, const rast_target *t, const uint8_t *rgba,
                                    const rast_blend_opts *opts, rast_rect *clip,
                                    rast__painter *p)
{
    int32_t opacity = opts ? opts->opacity : 255, premultiplied = opts ? opts->premultiplied : 0;
    rast_status st = rast__target_check(t, clip);
    if (st != RAST_OK) return st;
    if (t->format != RAST_FORMAT_GRAY8 && t->format != RAST_FORMAT_RGB888 &&
        t->format != RAST_FORMAT_RGB565 && t->format != RAST_FORMAT_RGBA8888)
        return RAST_E_FORMAT;
    if (!rgba) return RAST_E_NULL;
    if (opacity < 0 || opacity > 255 || premultiplied < 0 || premultiplied > 1) return RAST_E_ARG;
    memset(b, 0, sizeof *b);
    b->base = (unsigned char *)t->pixels;
    b->stride = t->stride;
    b->format = t->format;
    b->premultiplied = (int)premultiplied;
    if (t->format == RAST_FORMAT_RGB565) { /* the top bits, as rast_pack_color */
        b->src[0] = rgba[0] >> 3u;
        b->src[1] = rgba[1] >> 2u;
        b->src[2] = rgba[2] >> 3u;
    } else {
        b->src[0] = rgba[0];
        b->src[1] = rgba[1];
        b->src[2] = rgba[2];
    }
    b->ao = (uint32_t)rgba[3] * (uint32_t)opacity;
    b->full = rast__level8(b->ao, 255u);
    memset(p, 0, sizeof *p);
    p->full = rast__blend_full;
    p->levels = rast__blend_levels;
    p->user = b;
    return RAST_OK;
}

static rast_status rast__blend_image(const rast_target *target, const void *coverage,
                                     rast_coverage_format format, ptrdiff_t stride,
                                     const uint8_t *rgba, const rast_blend_opts *opts,
                                     const rast_gamma *gamma)
{
    rast__blender b;
    rast__painter p;
    rast_rect c;
    ptrdiff_t size = format == RAST_COVERAGE_U16 ? 2 : 1;
    int32_t x, y;
    rast_status st = rast__blend_init(&b, target, rgba, opts, &c, &p);
    if (st != RAST_OK) return st;
    if (format != RAST_COVERAGE_U8 && format != RAST_COVERAGE_U16) return RAST_E_ARG;
    if (gamma) {
        if (b.premultiplied || !rast__gamma_ok(gamma)) return RAST_E_ARG;
        b.gamma = gamma;
    }
    if (c.x0 >= c.x1 || c.y0 >= c.y1) return RAST_OK;
    if (!coverage) return RAST_E_NULL;
    if (stride < (ptrdiff_t)(c.x1 - c.x0) * size || stride % size != 0) return RAST_E_ARG;
    if ((uintptr_t)coverage % (uintptr_t)size != 0) return RAST_E_ALIGN;
    for (y = c.y0; y < c.y1; y++) {
        const unsigned char *cr = (const unsigned char *)coverage + (ptrdiff_t)(y - c.y0) * stride;
        unsigned char *row = b.base + (ptrdiff_t)y * b.stride;
        for (x = c.x0; x < c.x1; x++) {
            unsigned a;
            if (format == RAST_COVERAGE_U8) {
                a = rast__level8(b.ao, cr[x - c.x0]);
            } else {
                uint16_t v;
                memcpy(&v, cr + (ptrdiff_t)(x - c.x0) * 2, 2);
                a = rast__level16(b.ao, v);
            }
            if (!a) continue;
            if (gamma)
                rast__blend_px_linear(&b, row, x, a);
            else
                rast__blend_px(&b, row, x, a);
        }
    }
    return RAST_OK;
}

rast_status rast_blend_coverage(const rast_target *target, const void *coverage,
                                rast_coverage_format format, ptrdiff_t stride,
                                const uint8_t *rgba, const rast_blend_opts *opts)
{
    return rast__blend_image(target, coverage, format, stride, rgba, opts, NULL);
}

rast_status rast_blend_coverage_linear(const rast_target *target, const void *coverage,
                                       rast_coverage_format format, ptrdiff_t stride,
                                       const uint8_t *rgba, const rast_blend_opts *opts,
                                       const rast_gamma *gamma)
{
    if (!gamma) return RAST_E_NULL;
    return rast__blend_image(target, coverage, format, stride, rgba, opts, gamma);
}

rast_status rast_fill_polygon_blend(const rast_target *target, const rast_polygon *polygon,
                                    const rast_fill_opts *opts, const uint8_t *rgba,
                                    const rast_blend_opts *blend, void *scratch,
                                    size_t scratch_bytes)
{
    rast__blender b;
    rast__painter p;
    rast_rect clip;
    rast_status st = rast__blend_init(&b, target, rgba, blend, &clip, &p);
    if (st != RAST_OK) return st;
    return rast__fill(polygon, opts, &clip, &p, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_aa_blend(const rast_target *target, const rast_polygon *polygon,
                                       const rast_coverage_opts *opts, const uint8_t *rgba,
                                       const rast_blend_opts *blend, void *scratch,
                                       size_t scratch_bytes)
{
    rast__blender b;
    rast__painter p;
    rast_rect clip;
    rast_status st;
    if (!polygon) return RAST_E_NULL;
    st = rast__blend_init(&b, target, rgba, blend, &clip, &p);
    if (st != RAST_OK) return st;
    return rast__cov_paint(polygon, NULL, 0, opts, &clip, &p, scratch, scratch_bytes);
}

rast_status rast_fill_triangles_aa_blend(const rast_target *target, const rast_point *tris,
                                         uint32_t ntris, const rast_coverage_opts *opts,
                                         const uint8_t *rgba, const rast_blend_opts *blend,
                                         void *scratch, size_t scratch_bytes)
{
    rast__blender b;
    rast__painter p;
    rast_rect clip;
    rast_status st = rast__blend_init(&b, target, rgba, blend, &clip, &p);
    if (st != RAST_OK) return st;
    return rast__cov_paint(NULL, tris, ntris, opts, &clip, &p, scratch, scratch_bytes);
}

/* ---- shaded fills: a source colour per pixel ------------------------------- */

/* The blend of rast__fill_shaded*: ctx a rast__blender whose src is set
 * per pixel (rast__blend_init's checks and opacity; its colour unused). */
static void rast__rgba_put(const void *ctx, unsigned char *row, int32_t x, int32_t n,
                           const unsigned char *rgba, const uint8_t *cov)
{
    rast__blender b = *(const rast__blender *)ctx;
    const uint32_t o = b.ao / 255u; /* the opacity level (b's colour: alpha 255) */
    int32_t k;
    for (k = 0; k < n; k++, rgba += 4) {
        unsigned a = rast__level8((uint32_t)rgba[3] * o, cov ? cov[k] : 255u);
        if (!a) continue;
        if (b.format == RAST_FORMAT_RGB565) { /* the top bits, as rast_pack_color */
            b.src[0] = rgba[0] >> 3u;
            b.src[1] = rgba[1] >> 2u;
            b.src[2] = rgba[2] >> 3u;
        } else {
            b.src[0] = rgba[0];
            b.src[1] = rgba[1];
            b.src[2] = rgba[2];
        }
        rast__blend_px(&b, row, x + k, a);
    }
}

/* The blender of a shaded fill (rast__rgba_put's ctx): rast__blend_init's
 * checks of the target and options, its colour unused. */
static rast_status rast__shade_blender(rast__blender *b, const rast_target *target,
                                       const rast_blend_opts *blend)
{
    static const uint8_t white[4] = {255, 255, 255, 255};
    rast__painter p;
    rast_rect clip;
    return rast__blend_init(b, target, white, blend, &clip, &p);
}

rast_status rast_fill_triangles_shaded_blend(const rast_target *target, const rast_point *tris,
                                             uint32_t ntris, const uint8_t *colors,
                                             const rast_tri_opts *opts,
                                             const rast_shade_opts *shade,
                                             const rast_blend_opts *blend, void *scratch,
                                             size_t scratch_bytes)
{
    rast__blender b;
    rast_status st = rast__shade_blender(&b, target, blend);
    return st != RAST_OK ? st
                         : rast__fill_shaded(target, tris, ntris, colors, NULL, NULL, opts, shade,
                                             rast__rgba_put, &b, scratch, scratch_bytes);
}

rast_status rast_fill_triangles_shaded_aa_blend(const rast_target *target, const rast_point *tris,
                                                uint32_t ntris, const uint8_t *colors,
                                                const rast_coverage_opts *opts,
                                                const rast_shade_opts *shade,
                                                const rast_blend_opts *blend, void *scratch,
                                                size_t scratch_bytes)
{
    rast__blender b;
    rast_status st = rast__shade_blender(&b, target, blend);
    return st != RAST_OK ? st
                         : rast__fill_shaded_aa(target, tris, ntris, colors, opts, shade,
                                                rast__rgba_put, &b, scratch, scratch_bytes);
}

rast_status rast_fill_rect_gouraud_blend(const rast_target *target, rast_point p0, rast_point p1,
                                         const uint8_t *colors, const rast_tri_opts *opts,
                                         const rast_shade_opts *shade,
                                         const rast_blend_opts *blend)
{
    rast__blender b;
    rast_status st = rast__shade_blender(&b, target, blend);
    return st != RAST_OK ? st
                         : rast__fill_rect_shaded(target, p0, p1, colors, opts, shade,
                                                  rast__rgba_put, &b);
}

rast_status rast_fill_polygon_gouraud_blend(const rast_target *target, const rast_polygon *polygon,
                                            const uint8_t *colors, const rast_fill_opts *opts,
                                            const rast_shade_opts *shade,
                                            const rast_blend_opts *blend, void *scratch,
                                            size_t scratch_bytes)
{
    rast__blender b;
    rast_status st = rast__shade_blender(&b, target, blend);
    return st != RAST_OK ? st
                         : rast__fill_polygon_shaded(target, polygon, colors, opts, shade,
                                                     rast__rgba_put, &b, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_gouraud_aa_blend(const rast_target *target,
                                               const rast_polygon *polygon,
                                               const uint8_t *colors,
                                               const rast_coverage_opts *opts,
                                               const rast_shade_opts *shade,
                                               const rast_blend_opts *blend, void *scratch,
                                               size_t scratch_bytes)
{
    rast__blender b;
    rast_status st = rast__shade_blender(&b, target, blend);
    return st != RAST_OK ? st
                         : rast__fill_polygon_shaded_aa(target, polygon, colors, opts, shade,
                                                        rast__rgba_put, &b, scratch,
                                                        scratch_bytes);
}

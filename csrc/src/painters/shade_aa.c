/*
 * shade_aa.c - anti-aliased Gouraud triangle batches (rastrum.h,
 * rast_fill_triangles_shaded_aa): the batch's union coverage (the
 * coverage spans) times a colour per pixel, band by band.
 *
 * For each band of rows, the colour of every pixel goes into an RGBA
 * band in the caller's scratch in two passes of the Gouraud painter
 * (shade.c): first each triangle over the pixels whose closed square
 * meets one of its edges (rast__tri_touching below), the plane
 * extrapolated and clamped, later triangles over earlier ones; then the
 * binary shaded fill on top, so every pixel a triangle owns has exactly
 * the binary colour.  The first pass gives a pixel the colour the
 * definition asks for (the last triangle whose closed region meets its
 * closed square) wherever no triangle owns it: a triangle that meets the
 * square but none of whose edges does holds the whole square inside, so
 * it owns the pixel's sample.  The coverage spans of the band then blend the
 * colour into the target by the format's blend (formats.c).
 */
#include <string.h>

#include "paint.h"
#include "../base/wide.h"

/* Rows of colour a band holds at the least (rast_shaded_aa_scratch_size);
 * a bigger scratch doubles them while it holds them. */
#define RAST__AA_SHADE_ROWS 16

/* floor(a / u), ceil(a / u) for u > 0 */
static int64_t rast__fl(int64_t a, int64_t u) { return rast__floordiv(a, u); }
static int64_t rast__cl(int64_t a, int64_t u) { return -rast__floordiv(-a, u); }

/* Widen [*lo, *hi] by the pixels whose closed column [i, i+1] holds the
 * abscissa num / den (fixed point, den > 0) for unit u: i from
 * ceil(X) - 1 to floor(X), X = num / (den u). */
static void rast__touch_x(int64_t num, int64_t den, int64_t u, int64_t *lo, int64_t *hi)
{
    int64_t a = rast__cl(rast__cl(num, den), u) - 1, b = rast__fl(rast__fl(num, den), u);
    if (a < *lo) *lo = a;
    if (b > *hi) *hi = b;
}

/* The columns [*lo, *hi] of the pixels whose closed square meets the
 * closed segment ab in the closed strip yt <= y <= yb (input units, u a
 * pixel), cut to the clip's columns: 0 when there are none. */
static inline int rast__seg_strip(const rast_point *a, const rast_point *b, int64_t u, int64_t yt,
                                  int64_t yb, const rast_rect *clip, int64_t *lo, int64_t *hi)
{
    *lo = INT64_MAX;
    *hi = INT64_MIN;
    if (a->y > b->y) {
        const rast_point *c = a;
        a = b;
        b = c;
    }
    if (b->y < yt || a->y > yb) return 0; /* the edge misses the strip */
    /* its part in the strip: its ends inside, its crossings of the
     * strip's closed sides */
    if (a->y >= yt) rast__touch_x(a->x, 1, u, lo, hi);
    if (b->y <= yb) rast__touch_x(b->x, 1, u, lo, hi);
    if (a->y < yt && yt < b->y)
        rast__touch_x((int64_t)a->x * (b->y - a->y) + (yt - a->y) * (b->x - a->x), b->y - a->y, u,
                      lo, hi);
    if (a->y < yb && yb < b->y)
        rast__touch_x((int64_t)a->x * (b->y - a->y) + (yb - a->y) * (b->x - a->x), b->y - a->y, u,
                      lo, hi);
    if (*lo < clip->x0) *lo = clip->x0;
    if (*hi > clip->x1 - 1) *hi = clip->x1 - 1;
    return *lo <= *hi;
}

rast_status rast__tri_touching(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                               const rast__grid *g, const rast_rect *clip, const rast__painter *p,
                               rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes)
{
    uint32_t k;
    int64_t u;
    (void)scratch;
    (void)scratch_bytes;
    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK;
    u = (int64_t)1 << opts->subpixel_bits;
    for (k = 0; k < ntris; k++) {
        const rast_point *t = tris + 3 * (size_t)k;
        int64_t ymin = t[0].y, ymax = t[0].y, j, j0, j1;
        int m;
        if ((int64_t)(t[1].x - t[0].x) * (t[2].y - t[0].y) ==
            (int64_t)(t[1].y - t[0].y) * (t[2].x - t[0].x))
            continue; /* degenerate: no area, no plane */
        for (m = 1; m < 3; m++) {
            if (t[m].y < ymin) ymin = t[m].y;
            if (t[m].y > ymax) ymax = t[m].y;
        }
        j0 = rast__cl(ymin, u) - 1;
        j1 = rast__fl(ymax, u);
        if (j0 < clip->y0) j0 = clip->y0;
        if (j1 > clip->y1 - 1) j1 = clip->y1 - 1;
        if (j0 > j1) continue;
        if (begin && !begin(p->user, t, k, g)) continue;
        for (j = j0; j <= j1; j++) {
            const int64_t yt = j * u, yb = yt + u;
            for (m = 0; m < 3; m++) {
                int64_t lo, hi;
                int32_t xs[2];
                if (!rast__seg_strip(&t[m], &t[(m + 1) % 3], u, yt, yb, clip, &lo, &hi)) continue;
                xs[0] = (int32_t)lo;
                xs[1] = (int32_t)(hi + 1);
                p->full(p->user, (int32_t)j, xs, 1);
            }
        }
    }
    return RAST_OK;
}

/* The band's colours, and the target they are blended into. */
typedef struct rast__aa_shade {
    unsigned char *base;
    ptrdiff_t stride;
    const rast__format *fmt;
    const unsigned char *rgba; /* the band's colours */
    ptrdiff_t rgba_stride;
    rast_rect band;
    rast__rgba_put_fn bput; /* NULL, or the blend in place of the format's (blend.c) */
    const void *bctx;
} rast__aa_shade;

static void rast__aa_shade_run(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__aa_shade *p = (const rast__aa_shade *)user;
    unsigned char *row = p->base + (ptrdiff_t)y * p->stride;
    const unsigned char *col =
        p->rgba + (ptrdiff_t)(y - p->band.y0) * p->rgba_stride + (ptrdiff_t)(x0 - p->band.x0) * 4;
    int32_t x, c, n = p->fmt->value;
    if (p->bput) {
        p->bput(p->bctx, row, x0, x1 - x0, col, cov);
        return;
    }
    if (p->fmt->bits == 8 * n && p->fmt->channels == n) {
        /* GRAY8, RGB888, RGBA8888: a colour packs to its first n levels,
         * each blended as the format's blend does (rast__blend8) */
        unsigned char *o = row + (ptrdiff_t)x0 * n;
        for (x = x0; x < x1; x++, col += 4, o += n)
            for (c = 0; c < n; c++) o[c] = (unsigned char)rast__blend8(col[c], o[c], cov[x - x0]);
        return;
    }
    for (x = x0; x < x1; x++, col += 4) {
        unsigned char v[4] = {0, 0, 0, 0};
        p->fmt->pack(col, v);
        p->fmt->blend(row, x, x + 1, cov + (x - x0), v);
    }
}

/* ---- polygons: the colour of a pixel no sample of which the fill owns ---- */

/* A squared distance n / d, d > 0. */
typedef struct rast__dist {
    rast__i128 n;
    int64_t d;
} rast__dist;

/* From the sample (px, py) (internal units) to the closed segment ab
 * (vertices of non-zero length): the squared distance *r to its nearest
 * point, and (rgba not NULL) the colour there: ca and cb, a's and b's,
 * interpolated along ab, rounded half up.  The pixel's square meets ab,
 * so the nearest point is within its diagonal: |wx|, |wy| < 2^30 where
 * squared, l2 < 2^60, the colour's numerator < 2^70. */
static void rast__seg_near(int64_t px, int64_t py, const rast_point *a, const rast_point *b,
                           const uint8_t *ca, const uint8_t *cb, rast__dist *r,
                           unsigned char *rgba)
{
    int64_t dx = 2 * ((int64_t)b->x - a->x), dy = 2 * ((int64_t)b->y - a->y);
    int64_t wx = px - 2 * (int64_t)a->x, wy = py - 2 * (int64_t)a->y;
    int64_t l2 = dx * dx + dy * dy, t = wx * dx + wy * dy, q, rem;
    int ch;
    if (t <= 0 || t >= l2) { /* an end: a (t <= 0) or b */
        const uint8_t *c = t <= 0 ? ca : cb;
        if (t > 0) {
            wx -= dx;
            wy -= dy;
        }
        r->n = rast__i128_from(wx * wx + wy * wy);
        r->d = 1;
        if (rgba)
            for (ch = 0; ch < 4; ch++) rgba[ch] = c[ch];
        return;
    }
    q = wx * dy - wy * dx; /* |ab x ap| = |ab| times the distance */
    r->n = rast__i128_mul(q, q);
    r->d = l2;
    if (rgba)
        for (ch = 0; ch < 4; ch++) { /* floor(ca + (t / l2) (cb - ca) + 1/2) */
            rast__i128 num = rast__i128_add(rast__i128_mul(2 * (int64_t)ca[ch], l2),
                                            rast__i128_mul(2 * t, (int64_t)cb[ch] - ca[ch]));
            rast__i128_floordiv(rast__i128_add(num, rast__i128_from(l2)), 2 * l2, &q, &rem);
            rgba[ch] = (unsigned char)q;
        }
}

/* a < b, exactly: the integer parts, then the remainders crossed (both
 * below 2^60, their products below 2^120). */
static int rast__dist_less(const rast__dist *a, const rast__dist *b)
{
    int64_t qa, ra, qb, rb;
    rast__i128_floordiv(a->n, a->d, &qa, &ra);
    rast__i128_floordiv(b->n, b->d, &qb, &rb);
    if (qa != qb) return qa < qb;
    return rast__i128_cmp(rast__i128_mul(ra, b->d), rast__i128_mul(rb, a->d)) < 0;
}

/* Into the band's colours (rgba, stride) every pixel of `band` whose
 * closed square meets an edge of the polygon (one of non-zero length,
 * from a vertex to the next of its ring): the colour at the point of
 * those edges nearest its sample (rast__seg_near), of the first edge in
 * ring order among the nearest.  near: 2 int32 a pixel (the winning
 * edge's ends), band-sized. */
static void rast__poly_touching(unsigned char *rgba, ptrdiff_t stride, int32_t *near,
                                const rast_rect *band, const rast_polygon *poly,
                                const uint8_t *colors, const rast__grid *g, int32_t sb)
{
    const rast_point *pts = poly->points;
    const int64_t u = (int64_t)1 << sb, w = band->x1 - band->x0;
    const size_t npx = (size_t)w * (size_t)(band->y1 - band->y0);
    uint32_t r, k, base = 0;
    size_t i;
    for (i = 0; i < npx; i++) near[2 * i] = -1;
    for (r = 0; r < poly->nrings; base += poly->ring_sizes[r], r++) {
        const uint32_t n = poly->ring_sizes[r];
        for (k = 0; k < n; k++) {
            const int32_t ia = (int32_t)(base + k), ib = (int32_t)(base + (k + 1 == n ? 0 : k + 1));
            const rast_point *a = &pts[ia], *b = &pts[ib];
            int64_t j, j0, j1, lo, hi, x;
            if (a->x == b->x && a->y == b->y) continue;
            j0 = rast__cl(a->y < b->y ? a->y : b->y, u) - 1;
            j1 = rast__fl(a->y < b->y ? b->y : a->y, u);
            if (j0 < band->y0) j0 = band->y0;
            if (j1 > band->y1 - 1) j1 = band->y1 - 1;
            for (j = j0; j <= j1; j++) {
                if (!rast__seg_strip(a, b, u, j * u, j * u + u, band, &lo, &hi)) continue;
                for (x = lo; x <= hi; x++) {
                    int32_t *m = near + 2 * ((j - band->y0) * w + (x - band->x0));
                    int64_t px = x * g->unit + g->off, py = j * g->unit + g->off;
                    rast__dist d, e;
                    if (m[0] >= 0) {
                        rast__seg_near(px, py, a, b, NULL, NULL, &d, NULL);
                        rast__seg_near(px, py, &pts[m[0]], &pts[m[1]], NULL, NULL, &e, NULL);
                        if (!rast__dist_less(&d, &e)) continue;
                    }
                    m[0] = ia;
                    m[1] = ib;
                    rast__seg_near(px, py, a, b, colors + 4 * ia, colors + 4 * ib, &d,
                                   rgba + (j - band->y0) * stride + 4 * (x - band->x0));
                }
            }
        }
    }
}

/* ---- the band loop, triangles and polygons --------------------------------- */

/* Bytes of the coverage part (aligned) and the whole, for a band of
 * `rows` rows of `width` pixels: the coverage's, the band's colours (4
 * bytes a pixel) and, for a polygon (poly), each pixel's nearest edge (8
 * bytes) and the binary shaded walk's scratch. */
static rast_status rast__aa_shade_need(const rast_coverage_opts *opts, int poly, uint32_t npoints,
                                       int32_t width, int32_t rows, size_t *cov, size_t *all)
{
    rast_status st;
    size_t px = rast__size_mul((size_t)width, (size_t)rows), walk;
    st = rast_coverage_scratch_size(opts, npoints, width, rows, cov);
    if (st != RAST_OK) return st;
    *cov = rast__align(*cov);
    if (!poly) {
        *all = rast__size_add(*cov, rast__size_mul(px, 4));
        return RAST_OK;
    }
    st = rast_polygon_gouraud_scratch_size(npoints, width, rows, &walk);
    if (st != RAST_OK) return st;
    *all = rast__size_add(rast__size_add(*cov, rast__align(rast__size_mul(px, 4))),
                          rast__size_add(rast__align(rast__size_mul(px, 8)), walk));
    return RAST_OK;
}

static rast_status rast__aa_tris_need(const rast_coverage_opts *opts, uint32_t ntris,
                                      int32_t width, int32_t rows, size_t *cov, size_t *all)
{
    if (ntris > RAST_MAX_POINTS / 3) return RAST_E_TOO_MANY;
    return rast__aa_shade_need(opts, 0, 3 * ntris, width, rows, cov, all);
}

/* The rows of the least band for a clip of width x height (the public
 * scratch sizes' checks first). */
static rast_status rast__aa_rows(const size_t *bytes, int32_t width, int32_t height, int32_t *rows)
{
    if (!bytes) return RAST_E_NULL;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    *rows = height < RAST__AA_SHADE_ROWS ? height : RAST__AA_SHADE_ROWS;
    return RAST_OK;
}

rast_status rast_shaded_aa_scratch_size(const rast_coverage_opts *opts, uint32_t ntris,
                                        int32_t width, int32_t height, size_t *bytes)
{
    size_t cov;
    int32_t rows;
    rast_status st = rast__aa_rows(bytes, width, height, &rows);
    return st != RAST_OK ? st : rast__aa_tris_need(opts, ntris, width, rows, &cov, bytes);
}

rast_status rast_polygon_gouraud_aa_scratch_size(const rast_coverage_opts *opts, uint32_t npoints,
                                                 int32_t width, int32_t height, size_t *bytes)
{
    size_t cov;
    int32_t rows;
    rast_status st = rast__aa_rows(bytes, width, height, &rows);
    if (st != RAST_OK) return st;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    return rast__aa_shade_need(opts, 1, npoints, width, rows, &cov, bytes);
}

rast_status rast_fill_triangles_shaded_aa(const rast_target *target, const rast_point *tris,
                                          uint32_t ntris, const uint8_t *colors,
                                          const rast_coverage_opts *opts,
                                          const rast_shade_opts *shade, void *scratch,
                                          size_t scratch_bytes)
{
    return rast__fill_shaded_aa(target, tris, ntris, colors, opts, shade, NULL, NULL, scratch,
                                scratch_bytes);
}

rast_status rast_fill_polygon_gouraud_aa(const rast_target *target, const rast_polygon *polygon,
                                         const uint8_t *colors, const rast_coverage_opts *opts,
                                         const rast_shade_opts *shade, void *scratch,
                                         size_t scratch_bytes)
{
    return rast__fill_polygon_shaded_aa(target, polygon, colors, opts, shade, NULL, NULL, scratch,
                                        scratch_bytes);
}

/* The anti-aliased shaded fill of a triangle batch (poly NULL) or of a
 * polygon, band by band (see the top of the file). */
static rast_status rast__shaded_aa(const rast_target *target, const rast_polygon *poly,
                                   const rast_point *tris, uint32_t ntris, const uint8_t *colors,
                                   const rast_coverage_opts *opts, const rast_shade_opts *shade,
                                   rast__rgba_put_fn bput, const void *bctx, void *scratch,
                                   size_t scratch_bytes)
{
    rast__aa_shade p;
    rast__painter paint;
    rast_rect clip;
    rast_tri_opts exact, touch;
    rast__grid g;
    uint32_t npoints = 0;
    size_t cov_bytes, need, px_bytes = 0;
    int32_t width, height, rows, y;
    rast_status st;

    if (!target || !opts || !shade) return RAST_E_NULL;
    if (!poly && ntris > 0 && (!tris || !colors)) return RAST_E_NULL;
    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    if (shade->precision != RAST_PRECISION_EXACT && shade->precision != RAST_PRECISION_FLAT)
        return RAST_E_ARG;
    p.fmt = &rast__formats[target->format];
    p.bput = bput;
    p.bctx = bctx;
    if (!p.fmt->pack) return RAST_E_FORMAT;
    width = clip.x1 - clip.x0;
    height = clip.y1 - clip.y0;
    rows = height < RAST__AA_SHADE_ROWS ? height : RAST__AA_SHADE_ROWS;
    if (poly) {
        st = rast__poly_shade_check(poly, colors, &npoints);
        if (st != RAST_OK) return st;
        st = rast__aa_shade_need(opts, 1, npoints, width, rows, &cov_bytes, &need);
    } else {
        st = rast__aa_tris_need(opts, ntris, width, rows, &cov_bytes, &need);
    }
    if (st != RAST_OK) return st;
    st = rast__scratch_check(scratch, scratch_bytes, need);
    if (st != RAST_OK) return st;
    while (rows < height) { /* as many rows as the scratch holds: fewer bands */
        int32_t more = rows > height / 2 ? height : 2 * rows;
        size_t c2, n2;
        if ((poly ? rast__aa_shade_need(opts, 1, npoints, width, more, &c2, &n2)
                  : rast__aa_tris_need(opts, ntris, width, more, &c2, &n2)) != RAST_OK ||
            n2 > scratch_bytes)
            break;
        rows = more;
        cov_bytes = c2;
    }
    /* The painter of the band's colours times the coverage: levels runs. */
    memset(&paint, 0, sizeof paint);
    paint.levels = rast__aa_shade_run;
    paint.user = &p;
    if (clip.y0 >= clip.y1 || width == 0) /* nothing to paint: the checks only */
        return rast__cov_paint(poly, tris, ntris, opts, &clip, &paint, scratch, cov_bytes);

    memset(&exact, 0, sizeof exact);
    exact.algorithm = RAST_TRI_EDGE;
    exact.subpixel_bits = opts->subpixel_bits;
    exact.sample = opts->sample;
    exact.rounding = RAST_ROUND_EXACT;
    exact.boundary = RAST_BOUNDARY_EXACT;
    touch = exact;
    touch.boundary = RAST_BOUNDARY_CONSERVATIVE; /* not the packed painter: it clamps */

    p.base = (unsigned char *)target->pixels;
    p.stride = target->stride;
    p.rgba = (unsigned char *)scratch + cov_bytes;
    p.rgba_stride = (ptrdiff_t)width * 4;
    /* Every check once, before anything is written: the batch and the
     * binary options (the touching filler's differ only in the boundary,
     * which is not in the grid), then the coverage's for the whole clip in
     * bands of `rows` rows. */
    if (poly)
        st = rast__grid_init(&g, opts->subpixel_bits, opts->sample, RAST_ROUND_EXACT,
                             RAST_BOUNDARY_EXACT);
    else
        st = rast__tri_check(tris, ntris, &exact, &clip, &g, NULL, 0);
    if (st != RAST_OK) return st;
    st = rast__cov_paint_check(poly, tris, ntris, opts, &clip, rows, scratch, cov_bytes, &npoints);
    if (st != RAST_OK) return st;
    if (poly) px_bytes = rast__align((size_t)width * 4 * (size_t)rows);
    /* Band by band, nothing checked again. */
    for (y = clip.y0; y < clip.y1; y += rows) {
        unsigned char *rgba = (unsigned char *)scratch + cov_bytes;
        p.band = clip;
        p.band.y0 = y;
        if (clip.y1 - y > rows) p.band.y1 = y + rows;
        memset(rgba, 0, (size_t)width * 4 * (size_t)(p.band.y1 - p.band.y0));
        if (poly) {
            unsigned char *more = rgba + px_bytes;
            size_t near_bytes = rast__align((size_t)width * 8 * (size_t)rows);
            if (shade->precision == RAST_PRECISION_FLAT) { /* every pixel vertex 0's colour */
                size_t k, n = (size_t)width * (size_t)(p.band.y1 - p.band.y0);
                for (k = 0; k < n; k++) memcpy(rgba + 4 * k, colors, 4);
            } else {
                rast__poly_touching(rgba, p.rgba_stride, (int32_t *)(void *)more, &p.band, poly,
                                    colors, &g, opts->subpixel_bits);
                st = rast__poly_shade_band(rgba, p.rgba_stride, &p.band, poly, npoints, colors,
                                           &g, opts->rule, 0, more + near_bytes,
                                           scratch_bytes - cov_bytes - px_bytes - near_bytes);
                if (st != RAST_OK) return st;
            }
        } else {
            st = rast__shade_band(rgba, p.rgba_stride, &p.band, tris, ntris, colors, &touch, &g,
                                  shade, rast__tri_touching, NULL, 0);
            if (st != RAST_OK) return st;
            st = rast__shade_band(rgba, p.rgba_stride, &p.band, tris, ntris, colors, &exact, &g,
                                  shade, rast__tri_fill_checked, NULL, 0);
            if (st != RAST_OK) return st;
        }
        st = rast__cov_paint_checked(poly, tris, ntris, npoints, opts, &p.band, &paint, scratch,
                                     cov_bytes);
        if (st != RAST_OK) return st;
    }
    return RAST_OK;
}

rast_status rast__fill_shaded_aa(const rast_target *target, const rast_point *tris,
                                 uint32_t ntris, const uint8_t *colors,
                                 const rast_coverage_opts *opts, const rast_shade_opts *shade,
                                 rast__rgba_put_fn bput, const void *bctx, void *scratch,
                                 size_t scratch_bytes)
{
    return rast__shaded_aa(target, NULL, tris, ntris, colors, opts, shade, bput, bctx, scratch,
                           scratch_bytes);
}

rast_status rast__fill_polygon_shaded_aa(const rast_target *target, const rast_polygon *polygon,
                                         const uint8_t *colors, const rast_coverage_opts *opts,
                                         const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                         const void *bctx, void *scratch, size_t scratch_bytes)
{
    if (!polygon) return RAST_E_NULL;
    return rast__shaded_aa(target, polygon, NULL, 0, colors, opts, shade, bput, bctx, scratch,
                           scratch_bytes);
}

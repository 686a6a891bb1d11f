/* Binding glue of the translucent fills (not part of the core): the
 * mask or coverage of a fill computed over the geometry's box only and
 * blended there (blend.h).  A pixel outside the box has mask and coverage
 * 0, which the blend leaves as it is, so the pixels are those of the
 * whole target's blend; the vertices are snapped as the other calls snap
 * them (rastpy_snap), never moved: only the clip changes (issue 34). */

#include <stdlib.h>
#include <string.h>
#include "blend.h"
#include "painters/paint.h"

rast_rect rastpy_target_clip(const rast_target *target)
{
    rast_rect c = target->clip;
    if (c.x0 < 0) c.x0 = 0;
    if (c.y0 < 0) c.y0 = 0;
    if (c.x1 > target->width) c.x1 = target->width;
    if (c.y1 > target->height) c.y1 = target->height;
    if (c.x1 < c.x0) c.x1 = c.x0;
    if (c.y1 < c.y0) c.y1 = c.y0;
    return c;
}

/* A pixel's coverage comes from the part of the shape inside that
 * pixel's square (its samples too lie in it, docs/semantics.md), and a
 * mask's boundary modes add only pixels an edge passes through: every
 * pixel outside the box has coverage 0. */
rast_rect rastpy_box_cut(const rast_rect *clip, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int s)
{
    rast_rect b = *clip;
    /* floor(v / 2^s) of |v| < 2^62, without a shift of a negative value
     * (implementation-defined in C99) */
#define RASTPY_FLOOR_PX(v) ((v) >= 0 ? (v) >> s : -((-(v) - 1) >> s) - 1)
    x0 = RASTPY_FLOOR_PX(x0) - 1;
    y0 = RASTPY_FLOOR_PX(y0) - 1;
    x1 = RASTPY_FLOOR_PX(x1) + 2;
    y1 = RASTPY_FLOOR_PX(y1) + 2;
#undef RASTPY_FLOOR_PX
    if (x0 > b.x0) b.x0 = (int32_t)x0;
    if (y0 > b.y0) b.y0 = (int32_t)y0;
    if (x1 < b.x1) b.x1 = (int32_t)x1;
    if (y1 < b.y1) b.y1 = (int32_t)y1;
    if (b.x1 < b.x0) b.x1 = b.x0;
    if (b.y1 < b.y0) b.y1 = b.y0;
    return b;
}

rast_rect rastpy_points_box(const rast_rect *clip, const int32_t *pts, uint32_t n, int s)
{
    rast_rect b = *clip;
    int32_t x0, y0, x1, y1;
    uint32_t i;
    if (n == 0) {
        b.x1 = b.x0;
        b.y1 = b.y0;
        return b;
    }
    x0 = x1 = pts[0];
    y0 = y1 = pts[1];
    for (i = 1; i < n; i++) {
        int32_t x = pts[2 * i], y = pts[2 * i + 1];
        if (x < x0) x0 = x;
        if (x > x1) x1 = x;
        if (y < y0) y0 = y;
        if (y > y1) y1 = y;
    }
    return rastpy_box_cut(clip, x0, y0, x1, y1, s);
}

rast_status rastpy_blend_window(const rast_target *target, const rast_rect *r, const uint8_t *cov,
                                const uint8_t *rgba, const rast_blend_opts *blend,
                                const rast_gamma *gamma)
{
    rast_target cut = *target;
    ptrdiff_t w = r->x1 - r->x0;
    cut.clip = *r;
    return gamma ? rast_blend_coverage_linear(&cut, cov, RAST_COVERAGE_U8, w, rgba, blend, gamma)
                 : rast_blend_coverage(&cut, cov, RAST_COVERAGE_U8, w, rgba, blend);
}

rast_status rastpy_paint_window(const rast_target *target, const rast_rect *r, const uint8_t *cov,
                                const void *pixel)
{
    const size_t w = (size_t)(r->x1 - r->x0);
    rast__solid solid;
    rast__painter p;
    rast_rect c;
    rast_status st = rast__target_check(target, &c);
    size_t k, e;
    int32_t y;
    if (st == RAST_OK) st = rast__solid_init(&solid, target, r, pixel, NULL, &p);
    if (st != RAST_OK) return st;
    for (y = r->y0; y < r->y1; y++) {
        const uint8_t *row = cov + (size_t)(y - r->y0) * w; /* row[k]: column r->x0 + k */
        for (k = 0; k < w; k = e) { /* each run of levels not 0, as the core hands them on */
            for (; k < w && !row[k]; k++) {}
            for (e = k; e < w && row[e]; e++) {}
            if (k < e) p.levels(p.user, y, r->x0 + (int32_t)k, r->x0 + (int32_t)e, row + k);
        }
    }
    return RAST_OK;
}

void rastpy_window_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    const rastpy_window *w = (const rastpy_window *)user;
    memset(w->cov + (size_t)(y - w->r.y0) * (size_t)(w->r.x1 - w->r.x0) + (size_t)(x0 - w->r.x0), 255,
           (size_t)(x1 - x0));
}

unsigned char *rastpy_window_new(rastpy_window *w, size_t need)
{
    size_t head = (need + 15) & ~(size_t)15;
    size_t wh = (size_t)(w->r.x1 - w->r.x0) * (size_t)(w->r.y1 - w->r.y0);
    unsigned char *mem;
    if (head < need || wh > (size_t)-1 - 1 - head || !(mem = (unsigned char *)malloc(head + wh + 1)))
        return NULL;
    w->cov = mem + head;
    memset(w->cov, 0, wh);
    return mem;
}

/* Points of a call snapped on the stack (else malloc). */
#define RASTPY_BLEND_LOCAL_POINTS 256

/* Snap, then the fill's spans over its box (a polygon: rast_fill_bounds;
 * triangles: rastpy_points_box) into a zeroed window, then the blend. */
static long rastpy_blend_fill(const rast_target *target, const double *xy, uint32_t npoints,
                              const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *fopts,
                              const rast_tri_opts *topts, const uint8_t *rgba,
                              const rast_blend_opts *blend, const rast_gamma *gamma)
{
    int32_t local[2 * RASTPY_BLEND_LOCAL_POINTS];
    int32_t *pts;
    rast_polygon poly;
    rast_rect c;
    rastpy_window win;
    rast_status st;
    size_t need = 0;
    unsigned char *mem = NULL;
    long bad;
    if (!target || !rgba || !(fopts || topts)) return RAST_E_NULL;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    st = rastpy_check_rings(npoints, ring_sizes, nrings);
    if (st != RAST_OK) return st;
    pts = npoints <= RASTPY_BLEND_LOCAL_POINTS ? local
                                               : (int32_t *)malloc((size_t)npoints * sizeof(rast_point) + 1);
    if (!pts) return RASTPY_E_NOMEM;
    bad = rastpy_snap(xy, npoints, fopts ? fopts->subpixel_bits : topts->subpixel_bits, pts);
    if (bad >= 0) {
        if (pts != local) free(pts);
        return bad + 1;
    }
    poly.points = (const rast_point *)(void *)pts;
    poly.ring_sizes = ring_sizes ? ring_sizes : &npoints;
    poly.nrings = ring_sizes ? nrings : 1;
    c = rastpy_target_clip(target);
    if (fopts) {
        st = rast_fill_bounds(fopts, &poly, &c, &win.r);
        if (st == RAST_OK) st = rast_scratch_size(fopts, npoints, win.r.x1 - win.r.x0, win.r.y1 - win.r.y0, &need);
    } else {
        win.r = rastpy_points_box(&c, pts, npoints, topts->subpixel_bits);
        st = rast_tri_scratch_size(topts, win.r.x1 - win.r.x0, win.r.y1 - win.r.y0, &need);
    }
    if (st == RAST_OK && !(mem = rastpy_window_new(&win, need))) st = (rast_status)RASTPY_E_NOMEM;
    if (st == RAST_OK) {
        st = fopts ? rast_fill_polygon_spans(&poly, fopts, &win.r, rastpy_window_span, &win, mem, need)
                   : rast_fill_triangles_spans(poly.points, npoints / 3, topts, &win.r, rastpy_window_span,
                                               &win, mem, need);
        if (st == RAST_OK) st = rastpy_blend_window(target, &win.r, win.cov, rgba, blend, gamma);
    }
    free(mem);
    if (pts != local) free(pts);
    return st;
}

long rastpy_blend_polygon(const rast_target *target, const double *xy, uint32_t npoints,
                          const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                          const uint8_t *rgba, const rast_blend_opts *blend, const rast_gamma *gamma)
{
    if (!opts) return RAST_E_NULL;
    return rastpy_blend_fill(target, xy, npoints, ring_sizes, nrings, opts, NULL, rgba, blend, gamma);
}

long rastpy_blend_triangles(const rast_target *target, const double *xy, uint32_t ntris,
                            const rast_tri_opts *opts, const uint8_t *rgba,
                            const rast_blend_opts *blend, const rast_gamma *gamma)
{
    if (!opts) return RAST_E_NULL;
    if (ntris > RAST_MAX_POINTS / 3) return RAST_E_TOO_MANY;
    return rastpy_blend_fill(target, xy, 3 * ntris, NULL, 0, NULL, opts, rgba, blend, gamma);
}

/* The box of the spans handed to it (rastpy_blend_polyline's first pass). */
static void rastpy_box_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    rast_rect *b = (rast_rect *)user;
    if (b->x0 >= b->x1) { /* the first span */
        b->x0 = x0;
        b->x1 = x1;
        b->y0 = y;
        b->y1 = y + 1;
        return;
    }
    if (x0 < b->x0) b->x0 = x0;
    if (x1 > b->x1) b->x1 = x1;
    if (y < b->y0) b->y0 = y;
    if (y + 1 > b->y1) b->y1 = y + 1;
}

long rastpy_blend_polyline(const rast_target *target, const rast_point *points, uint32_t npoints,
                           int closed, const rast_line_opts *opts, const uint8_t *rgba,
                           const rast_blend_opts *blend, const rast_gamma *gamma)
{
    rast_rect c;
    rastpy_window win;
    unsigned char *mem;
    rast_status st;
    if (!target || !rgba) return RAST_E_NULL;
    c = rastpy_target_clip(target);
    /* the segments' box: their spans in the clip, every error first */
    win.r = c;
    win.r.x1 = win.r.x0;
    win.r.y1 = win.r.y0;
    st = rast_draw_polyline_spans(points, npoints, closed, opts, &c, rastpy_box_span, &win.r);
    if (st != RAST_OK) return st;
    if (!(mem = rastpy_window_new(&win, 0))) return RASTPY_E_NOMEM;
    /* the same segments in that box: the same pixels (both clip exactly) */
    st = rast_draw_polyline_spans(points, npoints, closed, opts, &win.r, rastpy_window_span, &win);
    if (st == RAST_OK) st = rastpy_blend_window(target, &win.r, win.cov, rgba, blend, gamma);
    free(mem);
    return st;
}

/*
 * coverage_paint.c - anti-aliased fills (rastrum.h, "anti-aliased
 * fills"): the coverage of a polygon or a triangle batch, row by row as
 * runs of uint8 levels (rast_polygon_coverage_spans,
 * rast_triangles_coverage_spans), painted into a target by its format's
 * blend function (formats.c).  Every check before the first run.
 */
#include "painters/paint.h"

/* The painter: the target's rows and format, and the value. */
typedef struct rast__aa_painter {
    unsigned char *base;
    ptrdiff_t stride;
    const rast__format *fmt;
    unsigned char value[4];
} rast__aa_painter;

static void rast__aa_run(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__aa_painter *p = (const rast__aa_painter *)user;
    p->fmt->blend(p->base + (ptrdiff_t)y * p->stride, x0, x1, cov, p->value);
}

static rast_status rast__fill_aa(const rast_target *target, const rast_polygon *poly,
                                 const rast_point *tris, uint32_t ntris,
                                 const rast_coverage_opts *opts, const void *pixel,
                                 void *scratch, size_t scratch_bytes)
{
    rast__aa_painter p;
    rast_rect clip;
    rast_status st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    p.fmt = &rast__formats[target->format];
    if (p.fmt->value && !pixel) return RAST_E_NULL;
    p.base = (unsigned char *)target->pixels;
    p.stride = target->stride;
    memset(p.value, 0, sizeof p.value);
    if (p.fmt->value) memcpy(p.value, pixel, (size_t)p.fmt->value);
    if (poly)
        return rast_polygon_coverage_spans(poly, opts, &clip, rast__aa_run, &p, scratch,
                                           scratch_bytes);
    return rast_triangles_coverage_spans(tris, ntris, opts, &clip, rast__aa_run, &p, scratch,
                                         scratch_bytes);
}

rast_status rast_fill_polygon_aa(const rast_target *target, const rast_polygon *polygon,
                                 const rast_coverage_opts *opts, const void *pixel,
                                 void *scratch, size_t scratch_bytes)
{
    if (!polygon) return RAST_E_NULL;
    return rast__fill_aa(target, polygon, NULL, 0, opts, pixel, scratch, scratch_bytes);
}

rast_status rast_fill_triangles_aa(const rast_target *target, const rast_point *tris,
                                   uint32_t ntris, const rast_coverage_opts *opts,
                                   const void *pixel, void *scratch, size_t scratch_bytes)
{
    return rast__fill_aa(target, NULL, tris, ntris, opts, pixel, scratch, scratch_bytes);
}

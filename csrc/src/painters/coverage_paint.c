/*
 * coverage_paint.c - anti-aliased fills (rastrum.h, "anti-aliased
 * fills"): the coverage of a polygon or a triangle batch, row by row as
 * levels runs (rast__cov_paint), fed to the target's solid painter
 * (paint.c), whose levels entry is the format's blend (formats.c): the
 * same painter a binary fill feeds full runs.  Every check before the
 * first run.
 */
#include "paint.h"

typedef rast_status (*rast__cov_paint_fn)(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                                          const rast_coverage_opts *opts, const rast_rect *clip,
                                          const rast__painter *p, void *scratch, size_t scratch_bytes);

/* The target checked, its solid painter made, and `paint` (rast__cov_paint,
 * or rast__cov_paint_snapped for the binding) run into it. */
static rast_status rast__fill_aa(const rast_target *target, const rast_polygon *poly,
                                 const rast_point *tris, uint32_t ntris,
                                 const rast_coverage_opts *opts, const void *pixel,
                                 void *scratch, size_t scratch_bytes, rast__cov_paint_fn paint)
{
    rast__solid solid;
    rast__painter p;
    rast_rect clip;
    rast_status st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    st = rast__solid_init(&solid, target, &clip, pixel, NULL, &p);
    if (st != RAST_OK) return st;
    return paint(poly, tris, ntris, opts, &clip, &p, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_aa(const rast_target *target, const rast_polygon *polygon,
                                 const rast_coverage_opts *opts, const void *pixel,
                                 void *scratch, size_t scratch_bytes)
{
    if (!polygon) return RAST_E_NULL;
    return rast__fill_aa(target, polygon, NULL, 0, opts, pixel, scratch, scratch_bytes, rast__cov_paint);
}

#if !defined(__OPTIMIZE_SIZE__)
rast_status rast__fill_polygon_aa_snapped(const rast_target *target, const rast_polygon *polygon,
                                          const rast_coverage_opts *opts, const void *pixel,
                                          void *scratch, size_t scratch_bytes)
{
    if (!polygon) return RAST_E_NULL;
    return rast__fill_aa(target, polygon, NULL, 0, opts, pixel, scratch, scratch_bytes, rast__cov_paint_snapped);
}
#endif

rast_status rast_fill_triangles_aa(const rast_target *target, const rast_point *tris,
                                   uint32_t ntris, const rast_coverage_opts *opts,
                                   const void *pixel, void *scratch, size_t scratch_bytes)
{
    return rast__fill_aa(target, NULL, tris, ntris, opts, pixel, scratch, scratch_bytes, rast__cov_paint);
}

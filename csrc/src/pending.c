/*
 * pending.c - entry points declared in rastrum.h whose files have not
 * landed yet.  Each returns RAST_E_ARG.  This file goes when it is empty.
 */
#include "internal.h"

/* lines and predicates (line.c, predicate.c) */
rast_status rast_draw_line(const rast_target *target, rast_point a, rast_point b,
                           const rast_line_opts *opts, const void *pixel)
{
    (void)target; (void)a; (void)b; (void)opts; (void)pixel;
    return RAST_E_ARG;
}

rast_status rast_draw_polyline(const rast_target *target, const rast_point *points,
                               uint32_t npoints, int closed, const rast_line_opts *opts,
                               const void *pixel)
{
    (void)target; (void)points; (void)npoints; (void)closed; (void)opts; (void)pixel;
    return RAST_E_ARG;
}

rast_status rast_line_pixels(rast_point a, rast_point b, const rast_line_opts *opts,
                             const rast_rect *clip, int32_t *xy, size_t capacity, size_t *count)
{
    (void)a; (void)b; (void)opts; (void)clip; (void)xy; (void)capacity; (void)count;
    return RAST_E_ARG;
}

rast_status rast_point_in_triangle(rast_point p, const rast_point *t, rast_predicate method,
                                   int *inside)
{
    (void)p; (void)t; (void)method; (void)inside;
    return RAST_E_ARG;
}

/*
 * boundary.c - RAST_BOUNDARY_CLOSED and _CONSERVATIVE (in progress).
 */
#include "internal.h"

size_t rast__bound_scratch(uint32_t npoints, int32_t height)
{
    (void)npoints;
    (void)height;
    return 0;
}

rast_status rast__bound_begin(rast__bound *b, const rast_polygon *poly,
                              uint32_t npoints, const rast__grid *g,
                              rast_boundary mode, const rast_rect *clip,
                              rast__sink *out, rast__arena *arena)
{
    (void)b; (void)poly; (void)npoints; (void)g; (void)mode; (void)clip; (void)out; (void)arena;
    return RAST_E_ARG;
}

void rast__bound_end(rast__bound *b)
{
    (void)b;
}

/* Binding glue of strokes (not part of the core): rast_path_stroke's
 * outline made in one pass into the room given (rast__path_stroke_into,
 * path/path.h).  Too little room returns RAST_E_SCRATCH with some of it
 * written; rastrum.stroke (python/rastrum/_strokes.py) then counts with
 * rast_path_stroke_size, which also names any other error first, and
 * calls again with the room the count gave. */

#include "stroke.h"
#include "path/path.h"

long rastpy_path_stroke(const rast_path *path, const rast_stroke_style *style, rast_point *points,
                        uint32_t max_points, uint32_t *ring_sizes, uint32_t max_rings,
                        uint32_t *npoints, uint32_t *nrings)
{
    return (long)rast__path_stroke_into(path, style, points, max_points, ring_sizes, max_rings, npoints,
                                        nrings);
}

long rastpy_path_stroke_flags(const rast_path *path, const rast_stroke_style *style, unsigned flags,
                              rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                              uint32_t max_rings, uint32_t *npoints, uint32_t *nrings)
{
    return (long)rast__path_stroke_run(path, style, flags, points, max_points, ring_sizes, max_rings, npoints,
                                       nrings);
}

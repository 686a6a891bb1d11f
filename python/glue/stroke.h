/* stroke.h - the binding glue of strokes (python/glue/stroke.c): the C
 * stroker's outline in one pass into room the caller guessed
 * (rastrum.stroke), not a count and then a second pass.  Results as
 * rastpy.h's: 0, or a negative status. */
#ifndef RASTPY_STROKE_H
#define RASTPY_STROKE_H

#include "rastpy.h"

/* cdef-begin */
long rastpy_path_stroke(const rast_path *path, const rast_stroke_style *style, rast_point *points,
                        uint32_t max_points, uint32_t *ring_sizes, uint32_t max_rings,
                        uint32_t *npoints, uint32_t *nrings);
/* The same with rast__path_stroke_run's flags (path/path.h: 1 the inner
 * joins' meeting points, 2 round parts straddling the circle; 3 is
 * rastrum.stroke(outline="compact")); points NULL: counted only. */
long rastpy_path_stroke_flags(const rast_path *path, const rast_stroke_style *style, unsigned flags,
                              rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                              uint32_t max_rings, uint32_t *npoints, uint32_t *nrings);
/* cdef-end */

#endif

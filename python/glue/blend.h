/* blend.h - the binding glue of the translucent fills (python/glue/blend.c):
 * a colour blended source-over through a fill's mask (255 inside) or
 * coverage computed over the geometry's pixel box only, not the whole
 * target (issue 34), with the pixels of rast_blend_coverage (or
 * rast_blend_coverage_linear) over the whole target's mask or coverage
 * (docs/opacity.md).  Results as rastpy.h's: 0, a negative status (or
 * RASTPY_E_NOMEM), or k + 1 when point k is bad. */
#ifndef RASTPY_BLEND_H
#define RASTPY_BLEND_H

#include "rastpy.h"

/* For the other glue files, not for Python: */

/* target->clip cut to the target, as the core cuts it (never reversed). */
rast_rect rastpy_target_clip(const rast_target *target);

/* The part of `clip` where a fill of the snapped points pts[0 .. n)
 * (x, y pairs, subpixel_bits s) can paint: their box in pixels, widened
 * by a pixel on each side, cut to the clip; n = 0: an empty rectangle. */
rast_rect rastpy_points_box(const rast_rect *clip, const int32_t *pts, uint32_t n, int s);

/* `rgba` blended with `blend` (and `gamma`: linear light, or NULL)
 * through the uint8 levels cov (row y at cov + (y - r->y0) * width of r)
 * onto the pixels of r, a rectangle inside target's clip (it may be
 * empty: then only the checks). */
rast_status rastpy_blend_window(const rast_target *target, const rast_rect *r, const uint8_t *cov,
                                const uint8_t *rgba, const rast_blend_opts *blend,
                                const rast_gamma *gamma);

/* cdef-begin */
long rastpy_blend_polygon(const rast_target *target, const double *xy, uint32_t npoints,
                          const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                          const uint8_t *rgba, const rast_blend_opts *blend, const rast_gamma *gamma);
long rastpy_blend_triangles(const rast_target *target, const double *xy, uint32_t ntris,
                            const rast_tri_opts *opts, const uint8_t *rgba,
                            const rast_blend_opts *blend, const rast_gamma *gamma);
/* cdef-end */

#endif

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

/* rastpy_points_box of the box [x0, x1] x [y0, y1] of snapped points
 * (|v| < 2^62: the 64-bit vertices' too). */
rast_rect rastpy_box_cut(const rast_rect *clip, int64_t x0, int64_t y0, int64_t x1, int64_t y1, int s);

/* A fill's window: the uint8 mask or coverage of the rectangle r, row y at
 * cov + (y - r.y0) * (r.x1 - r.x0). */
typedef struct rastpy_window {
    uint8_t *cov;
    rast_rect r;
} rastpy_window;

/* A rast_span_fn writing 255 over a span into the rastpy_window `user`. */
void rastpy_window_span(void *user, int32_t y, int32_t x0, int32_t x1);

/* One malloc block: `need` bytes of scratch (at its start, 16-byte
 * aligned), then w->r's window, zeroed, at w->cov.  NULL when it does not
 * fit a size_t or malloc fails; else free() it. */
unsigned char *rastpy_window_new(rastpy_window *w, size_t need);

/* `rgba` blended with `blend` (and `gamma`: linear light, or NULL)
 * through the uint8 levels cov (row y at cov + (y - r->y0) * width of r)
 * onto the pixels of r, a rectangle inside target's clip (it may be
 * empty: then only the checks). */
rast_status rastpy_blend_window(const rast_target *target, const rast_rect *r, const uint8_t *cov,
                                const uint8_t *rgba, const rast_blend_opts *blend,
                                const rast_gamma *gamma);

/* `pixel` (a value of the target's format) painted through the uint8
 * levels cov (laid out as rastpy_blend_window's) onto the pixels of r, a
 * rectangle inside the target's clip, as rast_fill_polygon_aa paints its
 * coverage (the core's solid painter, painters/paint.h: each channel
 * rast__blend8, MONO1 thresholded, COUNT16 counted); levels 0 untouched.
 * The opaque twin of rastpy_blend_window (the 64-bit "area" fill,
 * python/glue/wide.c).  Errors: the target's (rast__target_check),
 * RAST_E_NULL (pixel). */
rast_status rastpy_paint_window(const rast_target *target, const rast_rect *r, const uint8_t *cov,
                                const void *pixel);

/* cdef-begin */
long rastpy_blend_polygon(const rast_target *target, const double *xy, uint32_t npoints,
                          const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                          const uint8_t *rgba, const rast_blend_opts *blend, const rast_gamma *gamma);
long rastpy_blend_triangles(const rast_target *target, const double *xy, uint32_t ntris,
                            const rast_tri_opts *opts, const uint8_t *rgba,
                            const rast_blend_opts *blend, const rast_gamma *gamma);
/* The pixels of rast_draw_polyline (Canvas.line and polyline) as a mask
 * blended over their box only: its spans in the target's clip, their box,
 * then the spans again in that box (two passes over the segments, no
 * bound to prove for either line algorithm). */
long rastpy_blend_polyline(const rast_target *target, const rast_point *points, uint32_t npoints,
                           int closed, const rast_line_opts *opts, const uint8_t *rgba,
                           const rast_blend_opts *blend, const rast_gamma *gamma);
/* cdef-end */

#endif

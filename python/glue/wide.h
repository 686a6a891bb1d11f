/* wide.h - the 64-bit vertex path for the Python layer (wide.c): exact
 * snapping of float64 to int64 at S up to 32, and the polygon fills on
 * rast_polygon64 (issue 13).  The batch burn's 64-bit twin,
 * rastpy_burn_polygons64, is declared in batch.h. */
#ifndef RASTPY_WIDE_H
#define RASTPY_WIDE_H

#include "rastpy.h"

/* cdef-begin */
long rastpy_snap64(const double *xy, size_t npoints, int s, int64_t *out);
int rastpy_needs_wide(const double *xy, size_t npoints, int s);
long rastpy_fill_polygon64(const rast_target *target, const double *xy, uint32_t npoints,
                           const uint32_t *ring_sizes, uint32_t nrings,
                           const rast_fill_opts *opts, const void *pixel,
                           const void *background);
long rastpy_mask_polygon64(void *mask, int32_t height, int32_t width, const double *xy,
                           uint32_t npoints, const uint32_t *ring_sizes, uint32_t nrings,
                           const rast_fill_opts *opts);
long rastpy_polygon_coverage64(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                               uint32_t nrings, const rast_coverage_opts *opts);
long rastpy_coverage64_cells(const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts, int32_t height,
                             int32_t width, int64_t cell0, int64_t row_step, int32_t band_rows,
                             int64_t *cells, double *cov, size_t *count);
/* The translucent fills of blend.h on the 64-bit path: the mask (binary
 * opts) or the "area" coverage computed over the polygon's box only. */
long rastpy_blend_polygon64(const rast_target *target, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings, const rast_fill_opts *opts,
                            const uint8_t *rgba, const rast_blend_opts *blend, const rast_gamma *gamma);
long rastpy_blend_polygon_coverage64(const rast_target *target, const double *xy, uint32_t npoints,
                                     const uint32_t *ring_sizes, uint32_t nrings,
                                     const rast_coverage_opts *opts, const uint8_t *rgba,
                                     const rast_blend_opts *blend, const rast_gamma *gamma);
/* The opaque anti-aliased fill (Canvas.fill_polygon(aa="area") of a
 * colour painted as a value) on the 64-bit path: the "area" coverage
 * over the polygon's box, as rastpy_blend_polygon_coverage64 computes it,
 * painted with `pixel` as rast_fill_polygon_aa paints its levels
 * (rastpy_paint_window): the pixels of polygon_coverage's levels painted,
 * where the 32-bit fill refuses a vertex.  Results as
 * rastpy_fill_polygon64's. */
long rastpy_fill_polygon_aa64(const rast_target *target, const double *xy, uint32_t npoints,
                              const uint32_t *ring_sizes, uint32_t nrings, const rast_coverage_opts *opts,
                              const void *pixel);
/* cdef-end */

#endif

/* batch.h - burning many polygons, each with its value, into one array
 * (rastrum.rasterize, rastrum.masks, rastrum.labels): batch.c. */
#ifndef RASTPY_BATCH_H
#define RASTPY_BATCH_H

#include "rastpy.h"

/* Element types of the array burnt into (numpy's names). */
#define RASTPY_DT_U8 1
#define RASTPY_DT_I8 2
#define RASTPY_DT_U16 3
#define RASTPY_DT_I16 4
#define RASTPY_DT_U32 5
#define RASTPY_DT_I32 6
#define RASTPY_DT_I64 7
#define RASTPY_DT_U64 8
#define RASTPY_DT_F32 9
#define RASTPY_DT_F64 10
/* How a value meets what is there: replace it, or add to it (integers
 * wrap modulo 2^bits, as numpy's in-place add; floats add in IEEE). */
#define RASTPY_MERGE_REPLACE 0
#define RASTPY_MERGE_ADD 1
/* Add as GDAL's rasterizer adds (rastrum.rasterize): integers saturate at
 * their type's limits instead of wrapping; floats as RASTPY_MERGE_ADD. */
#define RASTPY_MERGE_ADD_SAT 2
/* Masks into an uninitialised array (rastrum.masks): every byte of the
 * planes written once, 1 inside a polygon, 0 elsewhere, instead of
 * clearing the array first and writing the spans into it.  Only u8 with
 * values NULL, into C-contiguous planes (row_stride == width,
 * plane_stride == height * width), else RAST_E_ARG; out is then written
 * only when the call succeeds, wholly. */
#define RASTPY_MERGE_FRESH 3

/* For the glue's own files (not for cffi): snap and lay out a polygon
 * table (batch.c). */
long rastpy_polygon_table(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys, int s,
                          rast_polygon **polys_out, int32_t **pts_out);

/* cdef-begin */
long rastpy_burn_polygons(void *out, int32_t height, int32_t width, int64_t row_stride,
                          int64_t plane_stride, int dtype, int merge, const void *values,
                          const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                          const rast_fill_opts *opts, uint32_t *failed);
long rastpy_burn_polygons64(void *out, int32_t height, int32_t width, int64_t row_stride,
                            int64_t plane_stride, int dtype, int merge, const void *values,
                            const double *xy, size_t npoints, const uint32_t *ring_sizes,
                            size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                            const rast_fill_opts *opts, uint32_t *failed);
/* rastpy_burn_polygons64 into a window of the plane (one plane): out is
 * height x width pixels, its pixel (0, 0) being the plane's pixel (y0, x0)
 * (row, column), and the window is the clip: every pixel equals the one
 * of burning the whole plane (the same snapped points, the same rule), so
 * tiles burnt apart assemble to the whole (rastrum.dask.rasterize).  The
 * window must lie within +-RAST_MAX_DIM, else RAST_E_SIZE. */
long rastpy_burn_polygons64_at(void *out, int32_t y0, int32_t x0, int32_t height, int32_t width,
                               int64_t row_stride, int dtype, int merge, const void *values,
                               const double *xy, size_t npoints, const uint32_t *ring_sizes,
                               size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                               const rast_fill_opts *opts, uint32_t *failed);
/* Lines burnt as GDAL burns them (gdalline.c's walk over ij, last and
 * npoints), segment k's pixels with values[part[k]] through the span
 * writers of rastpy_burn_polygons (dtype, merge as there; values not
 * NULL).  geom NULL: pixel by pixel in order.  Else geom[k] numbers the
 * geometry of position k (equal on consecutive positions of one
 * geometry): each geometry burns each of its pixels once (GDAL's rule for
 * "add"), the geometries in order.  Returns 0, RAST_E_ARG for a bad dtype
 * or merge, or RASTPY_E_NOMEM. */
long rastpy_burn_gdal_lines(void *out, int32_t height, int32_t width, int64_t row_stride, int dtype,
                            int merge, const void *values, const int64_t *ij, const int8_t *last,
                            const uint32_t *part, const uint32_t *geom, size_t npoints);
/* The same, each ring r first turned so that its signed area has the sign
 * orient[r] (+1, -1; 0 leaves it): with the non-zero rule, the union of
 * the +1 rings less the -1 rings (rastrum.masks' parts and holes). */
long rastpy_burn_polygons_oriented(void *out, int32_t height, int32_t width, int64_t row_stride,
                                   int64_t plane_stride, int dtype, int merge, const void *values,
                                   const double *xy, size_t npoints, const uint32_t *ring_sizes,
                                   size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                                   const rast_fill_opts *opts, uint32_t *failed,
                                   const int8_t *orient);
/* cdef-end */

#endif

/* zonal.h - every feature's coverage fractions in one call, for
 * rastrum.zonal_stats (python/rastrum/_zonal.py): the 64-bit "area" path
 * (rastpy_polygon_coverage64) on each feature's window, the nonzero cells
 * kept as (feature, cell, fraction) triples. */
#ifndef RASTPY_ZONAL_H
#define RASTPY_ZONAL_H

#include "rastpy.h"

/* cdef-begin */
long rastpy_window_fractions64(uint32_t nwin, const int64_t *win, const double *xy, size_t npoints,
                               const uint32_t *ring_sizes, size_t nrings, const rast_coverage_opts *opts,
                               int64_t raster_width, int64_t *out_feature, int64_t *out_cell,
                               double *out_fraction, size_t capacity, int64_t *failed);
/* cdef-end */

#endif

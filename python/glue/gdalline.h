/* gdalline.h - the pixels GDAL's rasterizer burns for lines
 * (rastrum.rasterize): gdalline.c; burnt by batch.c's
 * rastpy_burn_gdal_lines.  Nothing here is for Python. */
#ifndef RASTPY_GDALLINE_H
#define RASTPY_GDALLINE_H

#include "rastpy.h"

/* The walk itself: fn(user, k, row, col) for every pixel inside the
 * raster, in order (k: the segment); returns how many. */
typedef void (*rastpy_pixel_fn)(void *user, size_t k, int64_t row, int64_t col);
size_t rastpy_gdal_line_walk(const int64_t *ij, const int8_t *last, size_t npoints, int32_t height,
                             int32_t width, rastpy_pixel_fn fn, void *user);

/* An upper bound of the pixels the walk hands to fn. */
size_t rastpy_gdal_line_count(const int64_t *ij, const int8_t *last, size_t npoints,
                              int32_t height, int32_t width);

#endif

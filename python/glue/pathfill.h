/* pathfill.h - the binding glue of paths (python/glue/pathfill.c): a Path's
 * fixed-point verbs and points flattened (rast_path_flatten) straight into
 * the anti-aliased filler (rast_fill_polygon_aa) or the coverage of an
 * array (rast_polygon_coverage), without the rings going back through
 * Python.  Results as rastpy.h's: 0, a negative status (or
 * RASTPY_E_NOMEM). */
#ifndef RASTPY_PATHFILL_H
#define RASTPY_PATHFILL_H

#include "coverage.h"

/* cdef-begin */
long rastpy_fill_path_aa(const rast_target *target, const uint8_t *verbs, uint32_t nverbs,
                         const int32_t *xy, uint32_t npoints, int32_t tolerance,
                         const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc);
long rastpy_path_coverage(void *out, int32_t height, int32_t width, int format, const uint8_t *verbs,
                          uint32_t nverbs, const int32_t *xy, uint32_t npoints, int32_t tolerance,
                          const rast_coverage_opts *opts, rastpy_scratch *sc);
/* cdef-end */

#endif

/* rastpy.h - the binding glue's declarations (the .c files of python/glue).
 *
 * Not part of the core and not installed: these functions exist for the
 * Python layer.  They snap float64 input, take scratch from malloc and call
 * the core, one C call per Python call, with the GIL released by cffi.
 * python/rastrum/_build.py hands cffi the declarations between the
 * cdef-begin and cdef-end markers of every header in this folder (python/glue), and a
 * "#define NAME ..." for every RASTPY_ constant defined above them. */
#ifndef RASTPY_H
#define RASTPY_H

#include <stddef.h>
#include <stdint.h>
#include "rastrum.h"

/* Out of memory in the glue (malloc failed); never a core status. */
#define RASTPY_E_NOMEM (-1000)

/* Packed points or ring sizes not aligned for their items
 * (rastpy_mask_packed, rastpy_mask_rings); never a core status. */
#define RASTPY_E_ALIGN (-1001)

/* Snap 2 * npoints float64 coordinates to the 1/2^s grid:
 * out = floor(xy * 2^s + 1/2) exactly.  Returns -1 when all are good (all
 * of out written), else the index of the first point that is NaN, infinite
 * or outside +-RAST_COORD_MAX after snapping.  (fill.c; for the other glue
 * files, not for Python.) */
long rastpy_snap(const double *xy, size_t npoints, int s, int32_t *out);

/* RAST_OK when the ring sizes (NULL: one ring of all the points) sum to
 * exactly npoints, else RAST_E_ARG: the core reads sum(ring_sizes)
 * points (rast_polygon holds no count), and the glue's snapped buffer
 * holds npoints, so sizes summing past it would make the core read past
 * it.  The Python layer always passes matching sizes; this guards any
 * other caller of the glue.  A ring of size 0 is allowed, as the core
 * allows rings of fewer than 3 points; the sum is 64-bit (no overflow).
 * (fill.c; for the other glue files, not for Python.) */
rast_status rastpy_check_rings(uint32_t npoints, const uint32_t *ring_sizes, uint32_t nrings);

/* cdef-begin */
long rastpy_fill_polygon(const rast_target *target, const double *xy,
                         uint32_t npoints, const uint32_t *ring_sizes,
                         uint32_t nrings, const rast_fill_opts *opts,
                         const void *pixel, const void *background);
long rastpy_mask_polygon(void *mask, int32_t height, int32_t width,
                         const double *xy, uint32_t npoints,
                         const uint32_t *ring_sizes, uint32_t nrings,
                         const rast_fill_opts *opts);
long rastpy_mask_ring(void *mask, int32_t height, int32_t width, const double *xy,
                      uint32_t npoints, const rast_fill_opts *opts);
long rastpy_mask_packed(void *mask, int32_t height, int32_t width, const char *xy,
                        uint32_t npoints, const char *ring_sizes, uint32_t nrings,
                        const rast_fill_opts *opts);
long rastpy_mask_rings(void *mask, int32_t height, int32_t width, const char *ring_xy, uint32_t npoints,
                       const char *ring_sizes, uint32_t nrings, const rast_fill_opts *opts);
long rastpy_fill_ring(const rast_target *target, const double *xy, uint32_t npoints,
                      const rast_fill_opts *opts, const void *pixel);
long rastpy_snap_points(const double *xy, size_t npoints, int s, int32_t *out);
long rastpy_fill_triangles(const rast_target *target, const double *xy,
                           uint32_t ntris, const rast_tri_opts *opts,
                           const void *pixel);
long rastpy_fill_triangles_shaded(const rast_target *target, const double *xy,
                                  uint32_t ntris, const uint8_t *colors,
                                  const int32_t *z, int32_t *zbuf,
                                  const rast_tri_opts *opts,
                                  const rast_shade_opts *shade);
long rastpy_fill_triangles_shaded_blend(const rast_target *target, const double *xy,
                                        uint32_t ntris, const uint8_t *colors,
                                        const rast_tri_opts *opts, const rast_shade_opts *shade,
                                        const rast_blend_opts *blend);
int rastpy_gil_held(void);
long rastpy_fill_polygon_gouraud(const rast_target *target, const double *xy,
                                 uint32_t npoints, const uint32_t *ring_sizes,
                                 uint32_t nrings, const rast_fill_opts *opts,
                                 const uint8_t *colors, const rast_shade_opts *shade,
                                 const rast_blend_opts *blend);
/* cdef-end */

#endif

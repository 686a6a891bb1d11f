/* coverage.h - the binding glue of the coverage entry points
 * (python/glue/coverage.c): snap float64 input, take scratch from malloc,
 * one call to rast_polygon_coverage or rast_triangles_coverage (an array),
 * or to rast_fill_polygon_aa, rast_fill_triangles_aa or
 * rast_fill_triangles_shaded_aa or rast_fill_polygon_gouraud_aa (a target).
 * Results as rastpy.h's: 0, a negative status (or RASTPY_E_NOMEM), or
 * k + 1 when point k is bad. */
#ifndef RASTPY_COVERAGE_H
#define RASTPY_COVERAGE_H

#include "rastpy.h"

/* cdef-begin */
/* Scratch the caller lends to the calls below (the last argument; NULL:
 * each call takes its own from malloc and frees it).  buf (16-byte
 * aligned, size bytes) is used when it is large enough, else malloc; the
 * call sets want to the bytes it needed, so that the caller can keep a
 * buffer that large for the next call.  (A block of a few hundred KB
 * taken and freed on every call can be handed back to the system each
 * time, and its pages then fault in again on the next: on some sizes that
 * cost more than the fill.) */
typedef struct rastpy_scratch {
    void *buf;
    size_t size;
    size_t want;
} rastpy_scratch;
long rastpy_polygon_coverage(void *out, int32_t height, int32_t width, int format,
                             const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts, rastpy_scratch *sc);
long rastpy_triangles_coverage(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t ntris,
                               const rast_coverage_opts *opts, rastpy_scratch *sc);
long rastpy_fill_polygon_aa(const rast_target *target, const double *xy, uint32_t npoints,
                            const uint32_t *ring_sizes, uint32_t nrings,
                            const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc);
long rastpy_fill_triangles_aa(const rast_target *target, const double *xy, uint32_t ntris,
                              const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc);
long rastpy_fill_triangles_shaded_aa(const rast_target *target, const double *xy, uint32_t ntris,
                                     const uint8_t *colors, const rast_coverage_opts *opts,
                                     const rast_shade_opts *shade, rastpy_scratch *sc);
long rastpy_fill_triangles_shaded_aa_blend(const rast_target *target, const double *xy,
                                           uint32_t ntris, const uint8_t *colors,
                                           const rast_coverage_opts *opts,
                                           const rast_shade_opts *shade,
                                           const rast_blend_opts *blend, rastpy_scratch *sc);
long rastpy_fill_polygon_gouraud_aa(const rast_target *target, const double *xy, uint32_t npoints,
                                    const uint32_t *ring_sizes, uint32_t nrings,
                                    const uint8_t *colors, const rast_coverage_opts *opts,
                                    const rast_shade_opts *shade, const rast_blend_opts *blend,
                                    rastpy_scratch *sc);
/* `rgba` blended through the coverage of the polygon (or of the union
 * of ntris triangles) as rast_blend_coverage (gamma NULL) or
 * rast_blend_coverage_linear gives it for the whole target's coverage,
 * computed and blended over the points' box only (issue 34). */
long rastpy_blend_polygon_coverage(const rast_target *target, const double *xy, uint32_t npoints,
                                   const uint32_t *ring_sizes, uint32_t nrings,
                                   const rast_coverage_opts *opts, const uint8_t *rgba,
                                   const rast_blend_opts *blend, const rast_gamma *gamma,
                                   rastpy_scratch *sc);
long rastpy_blend_triangles_coverage(const rast_target *target, const double *xy, uint32_t ntris,
                                     const rast_coverage_opts *opts, const uint8_t *rgba,
                                     const rast_blend_opts *blend, const rast_gamma *gamma,
                                     rastpy_scratch *sc);
/* The n values of buf, a in units of 2^-62 as uint64_t (the
 * RAST_COVERAGE_FIX62 output), turned in place into the double a: each
 * integer rounded to the nearest double once, then scaled by 2^-62
 * (exact).  Each value is read before its own 8 bytes are written. */
void rastpy_fix62_to_double(void *buf, size_t n);
/* The same values as float32: each the double above rounded to the
 * nearest float (what numpy's astype(float32) of it gives), written to
 * out[0 .. n), which must not overlap buf: one pass, not the double array
 * then a cast of it. */
void rastpy_fix62_to_float(const void *buf, void *out, size_t n);
/* cdef-end */

#endif

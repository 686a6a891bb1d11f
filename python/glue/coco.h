/* coco.h - glue for rastrum.coco (coco.c): COCO run-length encoding.
 *
 * Several RLEs travel as one buffer: their compressed strings (COCO's
 * 6-bits-a-character form) one after the other, string k being
 * strs[offsets[k] .. offsets[k + 1]).  Functions that make strings return
 * them in a malloc'd buffer (*data; free it with rastpy_free) with the
 * offsets in the caller's offsets[0 .. n]. */
#ifndef RASTPY_COCO_H
#define RASTPY_COCO_H

#include "rastpy.h"

/* A string that is not a valid COCO RLE (a character outside '0'..'o',
 * a count that does not end) or whose counts pass height * width. */
#define RASTPY_E_RLE (-1001)
/* RLEs of different sizes given together where one size is needed. */
#define RASTPY_E_RLE_SIZE (-1002)

/* rastpy_coco_fr_polys: pycocotools' rule, each ring's toggles taken at
 * most `budget` at a time (0: 2^18; more are taken where one position
 * holds more), so that memory follows the RLE, not npoints * width. */
/* cdef-begin */
void rastpy_free(void *p);
long rastpy_coco_fr_polys(const double *xy, const uint32_t *npoints, uint32_t npolys,
                          uint32_t height, uint32_t width, size_t budget, char **data,
                          size_t *offsets);
long rastpy_coco_exact(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                       size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                       uint32_t height, uint32_t width, const rast_fill_opts *opts,
                       char **data, size_t *offsets, uint32_t *failed);
long rastpy_coco_encode(const uint8_t *mask, uint32_t height, uint32_t width, uint32_t n,
                        int64_t sy, int64_t sx, int64_t sk, char **data, size_t *offsets);
long rastpy_coco_decode(const char *strs, const size_t *offsets, uint32_t n, uint32_t height,
                        uint32_t width, uint8_t *out, int64_t sy, int64_t sx, int64_t sk,
                        uint8_t one);
long rastpy_coco_merge(const char *strs, const size_t *offsets, uint32_t n,
                       const uint32_t *sizes, int intersect, char **data, size_t *offsets_out,
                       uint32_t *size_out);
long rastpy_coco_area(const char *strs, const size_t *offsets, uint32_t n,
                      const uint32_t *sizes, uint32_t *out);
long rastpy_coco_bbox(const char *strs, const size_t *offsets, uint32_t n,
                      const uint32_t *sizes, double *out);
long rastpy_coco_iou(const char *dstrs, const size_t *doffsets, const uint32_t *dsizes,
                     uint32_t m, const char *gstrs, const size_t *goffsets,
                     const uint32_t *gsizes, uint32_t n, const uint8_t *iscrowd, double *o);
void rastpy_coco_bb_iou(const double *dt, const double *gt, uint32_t m, uint32_t n,
                        const uint8_t *iscrowd, double *o);
long rastpy_coco_fr_counts(const uint32_t *counts, const size_t *offsets, uint32_t n,
                           char **data, size_t *offsets_out);
/* cdef-end */

#endif

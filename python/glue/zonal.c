/* zonal.c - every feature's coverage fractions in one call (zonal.h).
 *
 * The same numbers as polygon_coverage(method="area", dtype=float64) on
 * each window through its 64-bit path: the same rastpy_polygon_coverage64
 * on the same float64 points, the same conversion of the 2^-62 fixed
 * point (rastpy_fix62_to_double), the cells whose fraction is not 0. */
#include <stdlib.h>
#include <string.h>

#include "zonal.h"
#include "wide.h"
#include "coverage.h"

/* win holds 8 int64 per window: feature id, height, width, subpixel bits
 * S, first point, first ring, number of rings, the raster cell of the
 * window's top-left corner.  A window's rings are ring_sizes[first ring
 * ..] and its points xy[2 * first point ..] (window-local pixels); xy
 * holds npoints points and ring_sizes nrings sizes, and a window whose
 * rings or points run past them is refused (RAST_E_ARG) before anything
 * is read there.
 * opts: the method, the rule (its subpixel_bits is replaced by each
 * window's S).  Writes the nonzero cells of window after window, each
 * window's in row-major order, cell = corner + row * raster_width +
 * column, mod 2^64 (capacity: at most that many).  S above 32 is
 * RAST_E_SUBPIXEL, whatever its low 32 bits.  Returns the number of cells
 * written, or a negative status with failed[0] the window's index and
 * failed[1] rastpy_polygon_coverage64's code k + 1 when its point k was
 * bad (then RAST_E_ARG), else 0.  One window buffer (malloc), grown to
 * the largest window so far, and only once the window's table, S and
 * options are checked (rast_coverage64_scratch_size). */
long rastpy_window_fractions64(uint32_t nwin, const int64_t *win, const double *xy, size_t npoints,
                               const uint32_t *ring_sizes, size_t nrings, const rast_coverage_opts *opts,
                               int64_t raster_width, int64_t *out_feature, int64_t *out_cell,
                               double *out_fraction, size_t capacity, int64_t *failed)
{
    rast_coverage_opts o;
    double *buf = NULL;
    size_t have = 0, written = 0, need;
    uint32_t k;
    if (!win || !xy || !ring_sizes || !opts || !out_feature || !out_cell || !out_fraction || !failed)
        return RAST_E_NULL;
    o = *opts;
    for (k = 0; k < nwin; k++) {
        const int64_t *v = win + (size_t)8 * k;
        int64_t h = v[1], w = v[2], r, c;
        size_t cells, i;
        uint64_t npts = 0;
        long st;
        uint32_t j;
        failed[0] = k;
        failed[1] = 0;
        /* the window's rings inside ring_sizes[0 .. nrings), then its
         * points inside xy[0 .. npoints) (each sum < 2^32 * 2^32: no wrap) */
        if (h <= 0 || w <= 0 || h > RAST_MAX_DIM || w > RAST_MAX_DIM || v[3] < 0 || v[6] <= 0 ||
            v[6] > (int64_t)UINT32_MAX || v[5] < 0 || (uint64_t)v[5] > (uint64_t)nrings ||
            (uint64_t)v[6] > (uint64_t)nrings - (uint64_t)v[5] || v[4] < 0) {
            free(buf);
            return RAST_E_ARG;
        }
        for (j = 0; j < (uint32_t)v[6]; j++) npts += ring_sizes[v[5] + j];
        if ((uint64_t)v[4] > (uint64_t)npoints || npts > (uint64_t)npoints - (uint64_t)v[4] || npts > UINT32_MAX) {
            free(buf);
            return RAST_E_ARG;
        }
        /* S past 32 is RAST_E_SUBPIXEL; (int) alone would take 2^32 + 5 as 5 */
        o.subpixel_bits = v[3] > RAST_MAX_SUBPIXEL_BITS64 ? RAST_MAX_SUBPIXEL_BITS64 + 1 : (int)v[3];
        /* the options, S and the window's size checked as
         * rastpy_polygon_coverage64 checks them first, before the window
         * buffer is allocated: a bad window is its status, never
         * RASTPY_E_NOMEM for a buffer it would not have used */
        st = rast_coverage64_scratch_size(&o, (uint32_t)npts, (int32_t)w, (int32_t)h, &need);
        if (st != RAST_OK) {
            free(buf);
            return st;
        }
        cells = (size_t)h * (size_t)w;
        if (cells > have) {
            free(buf);
            buf = (double *)malloc(cells * sizeof(double));
            if (!buf) return RASTPY_E_NOMEM;
            have = cells;
        }
        st = rastpy_polygon_coverage64(buf, (int32_t)h, (int32_t)w, 2, xy + 2 * (size_t)v[4], (uint32_t)npts,
                                       ring_sizes + v[5], (uint32_t)v[6], &o);
        if (st != 0) {
            free(buf);
            if (st > 0) {
                failed[1] = st;
                return RAST_E_ARG;
            }
            return st;
        }
        rastpy_fix62_to_double(buf, cells);
        for (r = 0, i = 0; r < h; r++) {
            /* mod 2^64 (two's complement): any corner and raster_width are defined */
            uint64_t row = (uint64_t)v[7] + (uint64_t)r * (uint64_t)raster_width;
            for (c = 0; c < w; c++, i++) {
                if (buf[i] != 0.0) {
                    if (written == capacity) {
                        free(buf);
                        return RAST_E_ARG;
                    }
                    out_feature[written] = v[0];
                    out_cell[written] = (int64_t)(row + (uint64_t)c);
                    out_fraction[written] = buf[i];
                    written++;
                }
            }
        }
    }
    free(buf);
    return (long)written;
}

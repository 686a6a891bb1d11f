/* Binding glue of the coverage calls (not part of the core): snapping,
 * scratch from malloc, and one C call per Python call, writing a whole
 * (height, width) array of uint8, uint16 or uint64 (2^-62 units). */

#include <stdlib.h>
#include "coverage.h"

static const int32_t rastpy_cov_size[3] = {1, 2, 8};

static long rastpy_coverage(void *out, int32_t height, int32_t width, int format,
                            const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                            uint32_t nrings, int triangles, const rast_coverage_opts *opts)
{
    rast_rect clip;
    rast_polygon poly;
    rast_status st;
    size_t need;
    int32_t *pts;
    void *scratch;
    long bad;
    if (format < 0 || format > 2) return RAST_E_ARG;
    clip.x0 = clip.y0 = 0;
    clip.x1 = width;
    clip.y1 = height;
    st = rast_coverage_scratch_size(opts, npoints, width, height, &need);
    if (st != RAST_OK) return st;
    pts = (int32_t *)malloc((size_t)npoints * sizeof(rast_point) + 1);
    if (!pts) return RASTPY_E_NOMEM;
    bad = rastpy_snap_points(xy, npoints, opts->subpixel_bits, pts);
    if (bad >= 0) {
        free(pts);
        return bad + 1;
    }
    scratch = malloc(need + 1);
    if (!scratch) {
        free(pts);
        return RASTPY_E_NOMEM;
    }
    if (triangles) {
        st = rast_triangles_coverage((const rast_point *)(void *)pts, npoints / 3, opts, &clip,
                                     (rast_coverage_format)format, out,
                                     (ptrdiff_t)width * rastpy_cov_size[format], scratch, need);
    } else {
        poly.points = (const rast_point *)(void *)pts;
        poly.ring_sizes = ring_sizes ? ring_sizes : &npoints;
        poly.nrings = ring_sizes ? nrings : 1;
        st = rast_polygon_coverage(&poly, opts, &clip, (rast_coverage_format)format, out,
                                   (ptrdiff_t)width * rastpy_cov_size[format], scratch, need);
    }
    free(scratch);
    free(pts);
    return st;
}

long rastpy_polygon_coverage(void *out, int32_t height, int32_t width, int format,
                             const double *xy, uint32_t npoints, const uint32_t *ring_sizes,
                             uint32_t nrings, const rast_coverage_opts *opts)
{
    return rastpy_coverage(out, height, width, format, xy, npoints, ring_sizes, nrings, 0, opts);
}

long rastpy_triangles_coverage(void *out, int32_t height, int32_t width, int format,
                               const double *xy, uint32_t ntris, const rast_coverage_opts *opts)
{
    return rastpy_coverage(out, height, width, format, xy, 3 * ntris, NULL, 0, 1, opts);
}

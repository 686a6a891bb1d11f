/* Binding glue of paths (not part of the core): rast_path_flatten into
 * one block (scratch lent by the caller, else malloc), subpaths of fewer
 * than 3 vertices left out (as rastrum.Path.flatten leaves them out: they
 * enclose nothing), then one rast_fill_polygon_aa.  The vertices are
 * rast_path_flatten's: counted by rast_path_flatten_size, then made in one
 * pass of rast__path_flatten (path/path.h) into the block sized by the
 * count, without rast_path_flatten's second count.  The points are in
 * units of the fill's grid (1/2^opts->subpixel_bits pixel) already, so the
 * filler takes the flattened vertices exactly as Path.flatten returns them
 * (docs/paths.md). */

#include <stdlib.h>
#include <string.h>
#include "pathfill.h"
#include "path/path.h"

static size_t rastpy_up16(size_t n)
{
    return (n + 15) & ~(size_t)15;
}

/* Flatten the path and fill it: into `target` with `pixel` (target not
 * NULL), else into the (height, width) array `out` of coverage format
 * `format` (rast_polygon_coverage). */
static long rastpy_path_run(const rast_target *target, const void *pixel, void *out, int format,
                            int32_t height, int32_t width, const uint8_t *verbs, uint32_t nverbs,
                            const int32_t *xy, uint32_t npoints, int32_t tolerance,
                            const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    static const int32_t size[3] = {1, 2, 8};
    rast_path path;
    rast_polygon poly;
    rast__flat flat;
    rast_status st;
    uint32_t np, nr, k, kept, from, to;
    size_t need, head, sizes;
    unsigned char *mem;
    rast_point *pts;
    uint32_t *ring_sizes;
    rast_rect clip;
    if (!opts || (npoints && !xy) || (nverbs && !verbs)) return RAST_E_NULL;
    if (target) {
        if (!pixel) return RAST_E_NULL;
        clip = target->clip;
    } else {
        if (!out) return RAST_E_NULL;
        if (format < 0 || format > 2 || height < 0 || width < 0) return RAST_E_ARG;
        clip.x0 = clip.y0 = 0;
        clip.x1 = width;
        clip.y1 = height;
    }
    path.verbs = verbs;
    path.nverbs = nverbs;
    path.points = (const rast_point *)(const void *)xy;
    path.npoints = npoints;
    st = rast_path_flatten_size(&path, tolerance, &np, &nr);
    if (st != RAST_OK) return st;
    if (!nr && target) return 0;
    st = rast_coverage_scratch_size(opts, np, clip.x1 - clip.x0, clip.y1 - clip.y0, &need);
    if (st != RAST_OK) return st;
    /* one block: the vertices, the ring sizes, then the filler's scratch
     * (sized for all np vertices, at least what the kept ones need) */
    head = rastpy_up16((size_t)np * sizeof(rast_point));
    sizes = rastpy_up16((size_t)nr * sizeof(uint32_t));
    if (need > (size_t)-1 - 1 - head - sizes) return RASTPY_E_NOMEM;
    if (sc) sc->want = head + sizes + need + 1;
    if (sc && sc->buf && head + sizes + need + 1 <= sc->size)
        mem = (unsigned char *)sc->buf;
    else if (!(mem = (unsigned char *)malloc(head + sizes + need + 1)))
        return RASTPY_E_NOMEM;
    pts = (rast_point *)(void *)mem;
    ring_sizes = (uint32_t *)(void *)(mem + head);
    /* the path checked and counted above: flattened in one pass, not
     * counted again first as rast_path_flatten would (path/path.h) */
    memset(&flat, 0, sizeof flat);
    flat.points = pts;
    flat.ring_sizes = ring_sizes;
    st = rast__path_flatten(&path, tolerance, &flat);
    poly.points = pts;
    poly.ring_sizes = ring_sizes;
    if (st == RAST_OK) {
        /* leave out the rings of fewer than 3 vertices, in place */
        kept = from = to = 0;
        for (k = 0; k < nr; k++) {
            uint32_t n = ring_sizes[k];
            if (n >= 3) {
                if (to != from) memmove(pts + to, pts + from, (size_t)n * sizeof(rast_point));
                ring_sizes[kept++] = n;
                to += n;
            }
            from += n;
        }
        poly.nrings = kept;
        if (target && kept)
            st = rast_fill_polygon_aa(target, &poly, opts, pixel, mem + head + sizes, need);
        else if (!target)  /* no rings: the coverage is all 0, written by the call */
            st = rast_polygon_coverage(&poly, opts, &clip, (rast_coverage_format)format, out,
                                       (ptrdiff_t)width * size[format], mem + head + sizes, need);
    }
    if (!sc || mem != sc->buf) free(mem);
    return st;
}

long rastpy_fill_path_aa(const rast_target *target, const uint8_t *verbs, uint32_t nverbs,
                         const int32_t *xy, uint32_t npoints, int32_t tolerance,
                         const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    if (!target) return RAST_E_NULL;
    return rastpy_path_run(target, pixel, NULL, 0, 0, 0, verbs, nverbs, xy, npoints, tolerance, opts,
                           sc);
}

long rastpy_path_coverage(void *out, int32_t height, int32_t width, int format, const uint8_t *verbs,
                          uint32_t nverbs, const int32_t *xy, uint32_t npoints, int32_t tolerance,
                          const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    return rastpy_path_run(NULL, NULL, out, format, height, width, verbs, nverbs, xy, npoints,
                           tolerance, opts, sc);
}

/* Binding glue of paths (not part of the core): rast_path_flatten into
 * one block (scratch lent by the caller, else malloc), subpaths of fewer
 * than 3 vertices left out (as rastrum.Path.flatten leaves them out: they
 * enclose nothing), then one rast_fill_polygon_aa.  The points are in
 * units of the fill's grid (1/2^opts->subpixel_bits pixel) already, so the
 * filler takes the flattened vertices exactly as Path.flatten returns them
 * (docs/paths.md). */

#include <stdlib.h>
#include <string.h>
#include "pathfill.h"

static size_t rastpy_up16(size_t n)
{
    return (n + 15) & ~(size_t)15;
}

long rastpy_fill_path_aa(const rast_target *target, const uint8_t *verbs, uint32_t nverbs,
                         const int32_t *xy, uint32_t npoints, int32_t tolerance,
                         const rast_coverage_opts *opts, const void *pixel, rastpy_scratch *sc)
{
    rast_path path;
    rast_polygon poly;
    rast_status st;
    uint32_t np, nr, k, kept, from, to;
    size_t need, head, sizes;
    unsigned char *mem;
    rast_point *pts;
    uint32_t *ring_sizes;
    if (!target || !opts || !pixel || (npoints && !xy) || (nverbs && !verbs)) return RAST_E_NULL;
    path.verbs = verbs;
    path.nverbs = nverbs;
    path.points = (const rast_point *)(const void *)xy;
    path.npoints = npoints;
    st = rast_path_flatten_size(&path, tolerance, &np, &nr);
    if (st != RAST_OK) return st;
    if (!nr) return 0;
    st = rast_coverage_scratch_size(opts, np, target->clip.x1 - target->clip.x0,
                                    target->clip.y1 - target->clip.y0, &need);
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
    st = rast_path_flatten(&path, tolerance, pts, np, ring_sizes, nr, &poly);
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
        if (kept)
            st = rast_fill_polygon_aa(target, &poly, opts, pixel, mem + head + sizes, need);
    }
    if (!sc || mem != sc->buf) free(mem);
    return st;
}

/* Binding glue of paths (not part of the core): rast_path_flatten into
 * one block (scratch lent by the caller, else malloc), subpaths of fewer
 * than 3 vertices left out (as rastrum.Path.flatten leaves them out: they
 * enclose nothing), then one rast_fill_polygon_aa.  The vertices are
 * rast_path_flatten's: counted by rast_path_flatten_size, then made in one
 * pass of rast__path_flatten (path/path.h) into the block sized by the
 * count, without rast_path_flatten's second count; or, when the caller
 * lends a block, made first straight into it, the room given
 * (rast__path_flatten's max_points, max_rings), with no count at all: the
 * count was a fifth of the instructions of a draw of bench_paths.py's
 * paragraph (1.6 M of 7.8 M flattening, 24.7 M filling); too little room
 * goes the counted way.  The points are in
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

/* The subpaths of fewer than 3 vertices left out, in place; returns how
 * many are kept. */
static uint32_t rastpy_keep_rings(rast_point *pts, uint32_t *ring_sizes, uint32_t nr)
{
    uint32_t k, kept = 0, from = 0, to = 0;
    for (k = 0; k < nr; k++) {
        uint32_t n = ring_sizes[k];
        if (n >= 3) {
            if (to != from) memmove(pts + to, pts + from, (size_t)n * sizeof(rast_point));
            ring_sizes[kept++] = n;
            to += n;
        }
        from += n;
    }
    return kept;
}

/* The fill of the flattened rings poly (its nrings, kept) into target, or
 * into the array out (rast_polygon_coverage), with the scratch given. */
static rast_status rastpy_fill_flat(const rast_target *target, const void *pixel, void *out, int format,
                                    int32_t width, const rast_rect *clip, const rast_polygon *poly,
                                    const rast_coverage_opts *opts, unsigned char *scratch, size_t need)
{
    static const int32_t size[3] = {1, 2, 8};
    if (target && poly->nrings)
        return rast_fill_polygon_aa(target, poly, opts, pixel, scratch, need);
    if (!target) /* no rings: the coverage is all 0, written by the call */
        return rast_polygon_coverage(poly, opts, clip, (rast_coverage_format)format, out,
                                     (ptrdiff_t)width * size[format], scratch, need);
    return RAST_OK;
}

/* The one pass into the lent block sc (a count's block is laid out the
 * same way but for the ring sizes): [points | the filler's scratch |
 * ring sizes], the ring sizes at the block's end, room for nverbs of them
 * (a subpath starts at a MOVE or at a verb after a CLOSE: at most nverbs
 * subpaths), the points from its start, as many as fit before them.  Not
 * tried when the last call lent the block wanted more than it (sc->want:
 * a path too large for the block the caller keeps, whose one pass would
 * stop at the block's end each time, its work lost).
 * Returns 1 when it filled (*st its status), 0 when the block was too
 * small for the vertices, for the ring sizes or for the filler's scratch
 * after the vertices (nothing painted; *st RAST_OK, or an error of the
 * path or the fill, returned as the counted way would return it: the
 * caller goes the counted way on 0 with RAST_OK). */
static int rastpy_path_lent(const rast_target *target, const void *pixel, void *out, int format,
                            int32_t width, const rast_rect *clip, const rast_path *path, int32_t tolerance,
                            const rast_coverage_opts *opts, rastpy_scratch *sc, rast_status *st)
{
    unsigned char *const mem = (unsigned char *)sc->buf;
    size_t at, head, need, pts_room;
    rast_polygon poly;
    rast__flat flat;
    *st = RAST_OK;
    if (!path->nverbs || path->nverbs >= sc->size / sizeof(uint32_t)) return 0;
    at = (sc->size - (size_t)path->nverbs * sizeof(uint32_t)) & ~(size_t)15; /* the ring sizes */
    pts_room = at / sizeof(rast_point);
    if (pts_room < 1) return 0;
    memset(&flat, 0, sizeof flat);
    flat.points = (rast_point *)(void *)mem;
    flat.ring_sizes = (uint32_t *)(void *)(mem + at);
    flat.max_points = pts_room > RAST_MAX_POINTS ? (uint32_t)RAST_MAX_POINTS : (uint32_t)pts_room;
    flat.max_rings = path->nverbs;
    *st = rast__path_flatten(path, tolerance, &flat);
    if (*st == RAST_E_SCRATCH) {
        *st = RAST_OK;
        return 0;
    }
    if (*st != RAST_OK) return 0;
    if (!flat.nrings && target) return 1; /* (nothing to paint: *st RAST_OK) */
    *st = rast_coverage_scratch_size(opts, flat.npoints, clip->x1 - clip->x0, clip->y1 - clip->y0, &need);
    if (*st != RAST_OK) return 0;
    head = rastpy_up16((size_t)flat.npoints * sizeof(rast_point));
    if (head > at || need >= at - head) return 0; /* (the scratch and its byte after would meet the ring sizes) */
    poly.points = flat.points;
    poly.ring_sizes = flat.ring_sizes;
    poly.nrings = rastpy_keep_rings(flat.points, flat.ring_sizes, flat.nrings);
    *st = rastpy_fill_flat(target, pixel, out, format, width, clip, &poly, opts, mem + head, need);
    return 1;
}

/* Flatten the path and fill it: into `target` with `pixel` (target not
 * NULL), else into the (height, width) array `out` of coverage format
 * `format` (rast_polygon_coverage). */
static long rastpy_path_run(const rast_target *target, const void *pixel, void *out, int format,
                            int32_t height, int32_t width, const uint8_t *verbs, uint32_t nverbs,
                            const int32_t *xy, uint32_t npoints, int32_t tolerance,
                            const rast_coverage_opts *opts, rastpy_scratch *sc)
{
    rast_path path;
    rast_polygon poly;
    rast__flat flat;
    rast_status st;
    uint32_t np, nr;
    size_t need, head, sizes, lent;
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
    if (sc && sc->buf && sc->want <= sc->size) { /* the one pass, in the lent block (rastpy_path_lent) */
        if (rastpy_path_lent(target, pixel, out, format, width, &clip, &path, tolerance, opts, sc, &st)) {
            sc->want = sc->size;
            return st;
        }
        if (st != RAST_OK) return st;
    }
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
    /* the block the caller should keep: one the one pass fits in next
     * time (rastpy_path_lent: the ring sizes' room at the end is for
     * nverbs of them, and 15 bytes at most go to align it) */
    lent = (size_t)nverbs * sizeof(uint32_t) + 15;
    if (sc) sc->want = need + 1 + head + (lent > sizes ? lent : sizes);
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
        poly.nrings = rastpy_keep_rings(pts, ring_sizes, nr);
        st = rastpy_fill_flat(target, pixel, out, format, width, &clip, &poly, opts, mem + head + sizes, need);
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

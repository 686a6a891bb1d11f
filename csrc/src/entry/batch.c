/*
 * batch.c - many polygons in one call, each drawn once in its own bounds.
 *
 * The band renderer (bands.c) walks every primitive for every band, which
 * is right for a display fed a few rows at a time and wrong for 20,000
 * small polygons burnt into one large raster: there each polygon should be
 * set up once, over the rows it covers.  So here each polygon's clip is cut
 * to its bounds (rast_fill_bounds: its box within the clip) and it is
 * filled in one go; the scratch is that of the largest polygon's own box.
 * A caller that does want bands passes a band as the clip.
 *
 * The options are checked once, every polygon once (in the pass that
 * measures it), and its scratch compared with what the caller gave,
 * before the first span: the call draws the whole batch or nothing.  The
 * drawing pass measures each polygon's bounds again and fills it through
 * the checked fill (rast__fill_checked, rast__fill64_checked), which
 * checks nothing.
 */
#include "../painters/paint.h"
#include "../fillers/poly.h"
#include "../fillers/small.h"

/* A batch of rast_polygon (wide == 0) or rast_polygon64 (wide == 1),
 * with the options checked once (f, or g64 for 64-bit ones). */
typedef struct rast__polys {
    const void *p;
    int wide;
    rast__fill_setup f;
    rast__grid64 g64;
} rast__polys;

static rast__polys rast__polys_of(const void *p, int wide)
{
    rast__polys b;
    b.p = p;
    b.wide = wide;
    return b;
}

/* What polygon k of the batch needs in span clip c: its bounds, vertex
 * count and scratch.  The polygon is checked and measured in one pass
 * over its vertices (rast__fill_measure, rast__fill64_measure), with the
 * options checked once for the batch. */
static rast_status rast__batch_need(const rast__polys *ps, uint32_t k, const rast_fill_opts *opts,
                                    const rast_rect *c, rast_rect *b, uint32_t *npoints,
                                    size_t *need)
{
    rast_status st;
    *npoints = 0;
    if (!ps->wide)
        st = rast__fill_measure(&ps->f, (const rast_polygon *)ps->p + k, c, npoints, b);
    else
        st = rast__fill64_measure(opts, &ps->g64, (const rast_polygon64 *)ps->p + k, c, npoints,
                                  b);
    if (st != RAST_OK) return st;
    /* rast_scratch_size's (rast_scratch_size64's) limit on the clip's sides */
    if (b->x1 - b->x0 > RAST_MAX_DIM || b->y1 - b->y0 > RAST_MAX_DIM) return RAST_E_SIZE;
    *need = ps->wide ? rast__fill64_scratch(opts, *npoints, b->y1 - b->y0)
                     : rast__fill_scratch(&ps->f, *npoints, b->x1 - b->x0, b->y1 - b->y0);
    return RAST_OK;
}

/* The batch's checks and its largest need; *failed names the polygon. */
static rast_status rast__batch_check(rast__polys *ps, uint32_t n, const rast_fill_opts *opts,
                                     const rast_rect *clip, size_t *most, uint32_t *failed)
{
    rast_rect c, b;
    size_t need;
    uint32_t k, npoints;
    rast_status st;
    if (!opts || !clip || (n > 0 && !ps->p)) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    /* The options are the batch's: their errors name no polygon. */
    st = ps->wide ? rast__fill64_prepare(opts, &ps->g64) : rast__fill_prepare(opts, &ps->f);
    if (st != RAST_OK) return st;
    *most = 0;
    for (k = 0; k < n; k++) {
        st = rast__batch_need(ps, k, opts, &c, &b, &npoints, &need);
        if (st != RAST_OK) {
            if (failed) *failed = k;
            return st;
        }
        if (need > *most) *most = need;
    }
    return RAST_OK;
}

rast_status rast_polygons_scratch_size(const rast_polygon *polygons, uint32_t n,
                                       const rast_fill_opts *opts, const rast_rect *clip,
                                       size_t *bytes, uint32_t *failed)
{
    rast__polys ps = rast__polys_of(polygons, 0);
    size_t most;
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__batch_check(&ps, n, opts, clip, &most, failed);
    if (st == RAST_OK) *bytes = most;
    return st;
}

rast_status rast_polygons64_scratch_size(const rast_polygon64 *polygons, uint32_t n,
                                         const rast_fill_opts *opts, const rast_rect *clip,
                                         size_t *bytes, uint32_t *failed)
{
    rast__polys ps = rast__polys_of(polygons, 1);
    size_t most;
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__batch_check(&ps, n, opts, clip, &most, failed);
    if (st == RAST_OK) *bytes = most;
    return st;
}

/* The batch's span callback, behind the per-polygon one. */
typedef struct rast__batch {
    rast_batch_span_fn span;
    void *user;
    uint32_t index;
} rast__batch;

/* The painter: each full run to the batch's callback, with the index. */
static void rast__batch_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__batch *b = (const rast__batch *)user;
    int32_t k;
    for (k = 0; k < n; k++) b->span(b->user, b->index, y, xs[2 * k], xs[2 * k + 1]);
}

static rast_status rast__batch_fill(rast__polys *ps, uint32_t n, const rast_fill_opts *opts,
                                    const rast_rect *clip, rast_batch_span_fn span, void *user,
                                    void *scratch, size_t scratch_bytes, uint32_t *failed)
{
    rast__batch ctx;
    rast__painter painter;
    rast_rect c, b;
    size_t most, need;
    uint32_t k, npoints;
    rast_status st;
    int small;
    if (!span) return RAST_E_NULL;
    st = rast__batch_check(ps, n, opts, clip, &most, failed);
    if (st != RAST_OK) return st;
    rast__span_clip(clip, &c); /* checked above */
    if (most > scratch_bytes) {
        /* Name the first polygon that does not fit. */
        for (k = 0; k < n; k++) {
            rast__batch_need(ps, k, opts, &c, &b, &npoints, &need);
            if (need > scratch_bytes) break;
        }
        if (failed) *failed = k;
        return RAST_E_SCRATCH;
    }
    st = rast__scratch_check(scratch, scratch_bytes, most);
    if (st != RAST_OK) return st;

    /* Polygons of few vertices: the small filler (small.c), the AET's
     * pixels, when the AET with the exact boundary is asked for. */
    small = !ps->wide && opts->algorithm == RAST_ALGO_AET &&
            (!RAST__BOUNDARY_MODES || opts->boundary == RAST_BOUNDARY_EXACT) &&
            c.x1 - c.x0 <= RAST_MAX_DIM && c.x0 < c.x1 && c.y0 < c.y1;
    ctx.span = span;
    ctx.user = user;
    memset(&painter, 0, sizeof painter);
    painter.full = rast__batch_row;
    painter.user = &ctx;
    for (k = 0; k < n; k++) {
        ctx.index = k;
        /* checked above: the bounds again, the polygon drawn in them */
        if (ps->wide) {
            const rast_polygon64 *p = (const rast_polygon64 *)ps->p + k;
            rast__fill64_measure(opts, &ps->g64, p, &c, &npoints, &b);
            if (b.x0 == b.x1 || b.y0 == b.y1) continue;
            st = rast__fill64_checked(p, npoints, opts, &ps->g64, &b, &painter, scratch,
                                      scratch_bytes);
        } else {
            const rast_polygon *p = (const rast_polygon *)ps->p + k;
            if (small) {
                /* The small filler takes the span clip as it is (it
                 * finds the rows from the edges, and clamps to any
                 * columns): no pass over the points for the box. */
                uint32_t r;
                for (r = 0, npoints = 0; r < p->nrings; r++) npoints += p->ring_sizes[r];
                if (rast__small_fill(p, npoints, &ps->f.g, opts->rule, &c, span, user, k, scratch,
                                     scratch_bytes))
                    continue;
            }
            rast__fill_measure(&ps->f, p, &c, &npoints, &b);
            if (b.x0 == b.x1 || b.y0 == b.y1) continue;
            st = rast__fill_checked(&ps->f, p, npoints, &b, &painter, scratch, scratch_bytes);
        }
        if (st != RAST_OK) return st; /* not reached: everything was checked */
    }
    return RAST_OK;
}

rast_status rast_fill_polygons_spans(const rast_polygon *polygons, uint32_t n,
                                     const rast_fill_opts *opts, const rast_rect *clip,
                                     rast_batch_span_fn span, void *user, void *scratch,
                                     size_t scratch_bytes, uint32_t *failed)
{
    rast__polys ps = rast__polys_of(polygons, 0);
    return rast__batch_fill(&ps, n, opts, clip, span, user, scratch, scratch_bytes, failed);
}

rast_status rast_fill_polygons64_spans(const rast_polygon64 *polygons, uint32_t n,
                                       const rast_fill_opts *opts, const rast_rect *clip,
                                       rast_batch_span_fn span, void *user, void *scratch,
                                       size_t scratch_bytes, uint32_t *failed)
{
    rast__polys ps = rast__polys_of(polygons, 1);
    return rast__batch_fill(&ps, n, opts, clip, span, user, scratch, scratch_bytes, failed);
}

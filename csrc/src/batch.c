/*
 * batch.c - many polygons in one call, each drawn once in its own bounds.
 *
 * The band renderer (bands.c) walks every primitive for every band, which
 * is right for a display fed a few rows at a time and wrong for 20,000
 * small polygons burnt into one large raster: there each polygon should be
 * set up once, over the rows it covers.  So here each polygon's clip is cut
 * to rast_fill_bounds (its box within the clip) and it is drawn by
 * rast_fill_polygon_spans in one go; the scratch is that of the largest
 * polygon's own box.  A caller that does want bands passes a band as the
 * clip.
 *
 * Every polygon is checked, and its scratch compared with what the caller
 * gave, before the first span: the call draws the whole batch or nothing.
 */
#include "paint.h"

/* What polygon k of the batch needs in clip c: its bounds and scratch. */
static rast_status rast__batch_need(const rast_polygon *p, const rast_fill_opts *opts,
                                    const rast_rect *c, rast_rect *b, size_t *need)
{
    uint32_t npoints = 0, i;
    rast_status st = rast_fill_bounds(opts, p, c, b);
    if (st != RAST_OK) return st;
    /* rast_fill_bounds has checked the ring sizes and their sum. */
    for (i = 0; i < p->nrings; i++) npoints += p->ring_sizes[i];
    return rast_scratch_size(opts, npoints, b->x1 - b->x0, b->y1 - b->y0, need);
}

/* The batch's checks and its largest need; *failed names the polygon. */
static rast_status rast__batch_check(const rast_polygon *polygons, uint32_t n,
                                     const rast_fill_opts *opts, const rast_rect *clip,
                                     size_t *most, uint32_t *failed)
{
    rast_rect c, b;
    size_t need;
    uint32_t k;
    rast_status st;
    if (!opts || !clip || (n > 0 && !polygons)) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    /* The options are the batch's: their errors name no polygon. */
    st = rast_scratch_size(opts, 0, 0, 0, most);
    if (st != RAST_OK) return st;
    *most = 0;
    for (k = 0; k < n; k++) {
        st = rast__batch_need(&polygons[k], opts, &c, &b, &need);
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
    size_t most;
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__batch_check(polygons, n, opts, clip, &most, failed);
    if (st == RAST_OK) *bytes = most;
    return st;
}

/* The batch's span callback, behind the per-polygon one. */
typedef struct rast__batch {
    rast_batch_span_fn span;
    void *user;
    uint32_t index;
} rast__batch;

static void rast__batch_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    const rast__batch *b = (const rast__batch *)user;
    b->span(b->user, b->index, y, x0, x1);
}

rast_status rast_fill_polygons_spans(const rast_polygon *polygons, uint32_t n,
                                     const rast_fill_opts *opts, const rast_rect *clip,
                                     rast_batch_span_fn span, void *user, void *scratch,
                                     size_t scratch_bytes, uint32_t *failed)
{
    rast__batch ctx;
    rast_rect c, b;
    size_t most, need;
    uint32_t k;
    rast_status st;
    if (!span) return RAST_E_NULL;
    st = rast__batch_check(polygons, n, opts, clip, &most, failed);
    if (st != RAST_OK) return st;
    if (most > scratch_bytes) {
        /* Name the first polygon that does not fit. */
        rast__span_clip(clip, &c);
        for (k = 0; k < n; k++) {
            rast__batch_need(&polygons[k], opts, &c, &b, &need);
            if (need > scratch_bytes) break;
        }
        if (failed) *failed = k;
        return RAST_E_SCRATCH;
    }
    st = rast__scratch_check(scratch, scratch_bytes, most);
    if (st != RAST_OK) return st;

    rast__span_clip(clip, &c); /* checked above */
    ctx.span = span;
    ctx.user = user;
    for (k = 0; k < n; k++) {
        ctx.index = k;
        rast__batch_need(&polygons[k], opts, &c, &b, &need); /* checked above */
        if (b.x0 == b.x1 || b.y0 == b.y1) continue;
        st = rast_fill_polygon_spans(&polygons[k], opts, &b, rast__batch_span, &ctx, scratch,
                                     scratch_bytes);
        if (st != RAST_OK) return st; /* not reached: everything was checked */
    }
    return RAST_OK;
}

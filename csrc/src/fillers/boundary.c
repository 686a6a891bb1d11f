/*
 * boundary.c - the boundary modes: a fill plus the pixels of its edges
 * (rastrum.h, rast_boundary).
 *
 * The filler runs unchanged into a sink of ours.  Beside it, a small
 * active edge list yields, row by row, the columns each edge adds to that
 * row: its line's run (RAST_BOUNDARY_CLOSED, linerun.c) or the pixels whose
 * open square it meets (RAST_BOUNDARY_CONSERVATIVE).  Each row of the fill
 * is merged with the edges' runs of the same row, in x order, and passed on;
 * rows the fill does not reach get the runs alone.  So the union arrives at
 * the painter (or the user's span callback) in the order every fill keeps:
 * rows top to bottom, spans left to right, none overlapping.
 *
 * Scratch: an edge record and an active slot per vertex, two run ends per
 * vertex, and a bucket head per clip row.
 */
#include "../base/wide.h"

static void rast__bound_row(void *user, int32_t y, const int32_t *xs, int32_t n);

size_t rast__bound_scratch(uint32_t npoints, int32_t height)
{
    size_t e = rast__align(rast__size_mul(npoints, sizeof(rast__bound_edge)));
    size_t rows = rast__align(rast__size_mul((size_t)height + 1, sizeof(int32_t)));
    size_t act = rast__align(rast__size_mul(npoints, 3 * sizeof(int32_t)));
    return rast__size_add(rast__size_add(e, rows), act);
}

/* Rows [*r0, *r1) in which the open square of some pixel meets the closed
 * segment a-b (a.y <= b.y), internal units.  A row's open strip
 * (jU, (j+1)U) meets [ay, by] iff floor(ay/U) <= j < ceil(by/U); a
 * horizontal segment lying on a pixel border meets none. */
static void rast__touch_rows(int64_t ay, int64_t by, int64_t u, int64_t *r0, int64_t *r1)
{
    if (ay == by) {
        *r0 = rast__floordiv(ay, u);
        *r1 = ay % u ? *r0 + 1 : *r0;
        return;
    }
    *r0 = rast__floordiv(ay, u);
    *r1 = rast__ceildiv(by, u);
}

/* Columns [*x0, *x1) of row j whose open squares meet the closed segment
 * a-b (internal units, ay <= by, row j among its touch rows; possibly
 * empty).  The part of the segment inside the open strip spans a
 * positive length of y, so unless it is vertical its x extent [lo, hi]
 * has a positive length and meets (i, i+1) iff floor(lo) <= i < ceil(hi).
 * Products: |ax * dy| < 2^58 and (y - ay) * |dx| < 2^58. */
static void rast__touch_run(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t u,
                            int64_t j, int64_t *x0, int64_t *x1)
{
    int64_t dx = bx - ax, dy = by - ay, ylo, yhi, nlo, nhi, t;
    if (dx == 0 || dy == 0) {
        int64_t lo = ax < bx ? ax : bx, hi = ax < bx ? bx : ax;
        if (lo < hi) { /* horizontal, off the pixel borders */
            *x0 = rast__floordiv(lo, u);
            *x1 = rast__ceildiv(hi, u);
        } else { /* vertical, or a point: on a border it meets nothing */
            *x0 = rast__floordiv(lo, u);
            *x1 = lo % u ? *x0 + 1 : *x0;
        }
        return;
    }
    ylo = j * u > ay ? j * u : ay;
    yhi = (j + 1) * u < by ? (j + 1) * u : by;
    /* x(y) = ax + (y - ay) dx / dy, as numerators over dy > 0 */
    nlo = ax * dy + (ylo - ay) * dx;
    nhi = ax * dy + (yhi - ay) * dx;
    if (nlo > nhi) {
        t = nlo;
        nlo = nhi;
        nhi = t;
    }
    *x0 = rast__floordiv(nlo, u * dy);
    *x1 = rast__ceildiv(nhi, u * dy);
}

/* rast__touch_run for a 64-bit polygon's edge: internal coordinates below
 * 2^61 in magnitude, differences below 2^62, so the numerators are 128-bit
 * (rast__i128); x = floor(n / (u dy)) is taken as floor(floor(n / dy) / u),
 * the inner quotient being an abscissa on the segment (below 2^61). */
static void rast__touch_run64(const rast__bound_edge64 *e, int64_t u, int64_t j, int64_t *x0,
                              int64_t *x1)
{
    int64_t ax = e->ax, ay = e->ay, bx = e->bx, by = e->by;
    int64_t dx = bx - ax, dy = by - ay, ylo, yhi, q, r;
    rast__i128 nlo, nhi, base;
    if (dx == 0 || dy == 0) {
        int64_t lo = ax < bx ? ax : bx, hi = ax < bx ? bx : ax;
        *x0 = rast__floordiv(lo, u);
        if (lo < hi)
            *x1 = rast__ceildiv(hi, u);
        else
            *x1 = lo % u ? *x0 + 1 : *x0;
        return;
    }
    ylo = j * u > ay ? j * u : ay;
    yhi = (j + 1) * u < by ? (j + 1) * u : by;
    base = rast__i128_mul(ax, dy);
    nlo = rast__i128_add(base, rast__i128_mul(ylo - ay, dx));
    nhi = rast__i128_add(base, rast__i128_mul(yhi - ay, dx));
    if (dx < 0) {
        rast__i128 t = nlo;
        nlo = nhi;
        nhi = t;
    }
    rast__wide_floordiv(nlo, dy, &q, &r);
    *x0 = rast__floordiv(q, u);
    rast__wide_floordiv(nhi, dy, &q, &r);
    *x1 = rast__ceildiv(q + (r > 0), u);
}

size_t rast__bound_scratch64(uint32_t npoints, int32_t height)
{
    size_t e = rast__align(rast__size_mul(npoints, sizeof(rast__bound_edge64)));
    size_t rows = rast__align(rast__size_mul((size_t)height + 1, sizeof(int32_t)));
    size_t act = rast__align(rast__size_mul(npoints, 3 * sizeof(int32_t)));
    return rast__size_add(rast__size_add(e, rows), act);
}

/* What both begins share: the state, and the bucket and run arrays. */
static rast_status rast__bound_init(rast__bound *b, uint32_t npoints, const rast_rect *clip,
                                    rast__sink *out, rast__arena *arena)
{
    int32_t j;
    b->out = out;
    b->y0 = clip->y0;
    b->y1 = clip->y1;
    b->row = clip->y0 - 1; /* no row prepared yet */
    b->nactive = b->nxs = b->k = 0;
    b->in = *out;
    b->in.fn = rast__bound_row;
    b->in.user = b;
    b->in.n = 0;
    b->bucket = (int32_t *)rast__take(arena, ((size_t)(clip->y1 - clip->y0) + 1) * sizeof(int32_t));
    b->active = (int32_t *)rast__take(arena, (size_t)npoints * sizeof(int32_t));
    b->xs = (int32_t *)rast__take(arena, (size_t)npoints * 2 * sizeof(int32_t));
    if ((npoints && (!b->active || !b->xs)) || !b->bucket) return RAST_E_SCRATCH;
    for (j = clip->y0; j < clip->y1; j++) b->bucket[j - clip->y0] = -1;
    return RAST_OK;
}

rast_status rast__bound_begin64(rast__bound *b, const rast_polygon64 *poly,
                                uint32_t npoints, const rast__grid64 *g,
                                const rast_rect *clip, rast__sink *out,
                                rast__arena *arena)
{
    uint32_t i, k, base;
    int32_t n = 0;
    rast_status st;

    b->g = NULL;
    b->g64 = g;
    b->mode = RAST_BOUNDARY_CONSERVATIVE;
    b->edges = NULL;
    b->edges64 = (rast__bound_edge64 *)rast__take(arena, (size_t)npoints * sizeof(rast__bound_edge64));
    st = rast__bound_init(b, npoints, clip, out, arena);
    if (st != RAST_OK || (npoints && !b->edges64)) return RAST_E_SCRATCH;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t m = poly->ring_sizes[k];
        for (i = 0; i < m; i++) {
            rast__bound_edge64 *e = &b->edges64[n];
            rast_point64 p = poly->points[base + i];
            rast_point64 q = poly->points[base + (i + 1 == m ? 0 : i + 1)];
            int64_t r0, r1;
            if (q.y < p.y) {
                rast_point64 t = p;
                p = q;
                q = t;
            }
            rast__touch_rows(2 * p.y, 2 * q.y, g->unit, &r0, &r1);
            if (r0 < clip->y0) r0 = clip->y0;
            if (r1 > clip->y1) r1 = clip->y1;
            if (r0 >= r1) continue;
            e->ax = 2 * p.x;
            e->ay = 2 * p.y;
            e->bx = 2 * q.x;
            e->by = 2 * q.y;
            e->row = (int32_t)r0;
            e->end = (int32_t)r1;
            e->pad = 0;
            e->next = b->bucket[r0 - clip->y0];
            b->bucket[r0 - clip->y0] = n++;
        }
    }
    return RAST_OK;
}

rast_status rast__bound_begin(rast__bound *b, const rast_polygon *poly,
                              uint32_t npoints, const rast__grid *g,
                              rast_boundary mode, const rast_rect *clip,
                              rast__sink *out, rast__arena *arena)
{
    uint32_t i, k, base;
    int32_t n = 0;
    rast_status st;

    b->g = g;
    b->g64 = NULL;
    b->mode = mode;
    b->edges64 = NULL;
    b->edges = (rast__bound_edge *)rast__take(arena, (size_t)npoints * sizeof(rast__bound_edge));
    st = rast__bound_init(b, npoints, clip, out, arena);
    if (st != RAST_OK || (npoints && !b->edges)) return RAST_E_SCRATCH;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t m = poly->ring_sizes[k];
        for (i = 0; i < m; i++) {
            rast__bound_edge *e = &b->edges[n];
            rast_point p = poly->points[base + i];
            rast_point q = poly->points[base + (i + 1 == m ? 0 : i + 1)];
            int64_t r0, r1;
            if (q.y < p.y) {
                rast_point t = p;
                p = q;
                q = t;
            }
            if (mode == RAST_BOUNDARY_CLOSED)
                rast__line_rows(p, q, g, &r0, &r1);
            else
                rast__touch_rows(2 * (int64_t)p.y, 2 * (int64_t)q.y, g->unit, &r0, &r1);
            if (r0 < clip->y0) r0 = clip->y0;
            if (r1 > clip->y1) r1 = clip->y1;
            if (r0 >= r1) continue;
            e->a = p;
            e->b = q;
            e->row = (int32_t)r0;
            e->end = (int32_t)r1;
            e->next = b->bucket[r0 - clip->y0];
            b->bucket[r0 - clip->y0] = n++;
        }
    }
    return RAST_OK;
}

/* The edges' runs of row b->row, clipped, sorted and merged, into xs. */
static void rast__bound_prepare(rast__bound *b)
{
    const rast__grid *g = b->g;
    int32_t e, n, m, row = b->row;

    if (b->g64)
        for (e = b->bucket[row - b->y0]; e >= 0; e = b->edges64[e].next) b->active[b->nactive++] = e;
    else
        for (e = b->bucket[row - b->y0]; e >= 0; e = b->edges[e].next) b->active[b->nactive++] = e;
    b->nxs = b->k = 0;
    for (n = 0, m = 0; n < b->nactive; n++) {
        int64_t x0, x1;
        int32_t p;
        if (b->g64) {
            const rast__bound_edge64 *e64 = &b->edges64[b->active[n]];
            if (e64->end <= row) continue; /* ended: drop it */
            rast__touch_run64(e64, b->g64->unit, row, &x0, &x1);
        } else {
            const rast__bound_edge *ed = &b->edges[b->active[n]];
            if (ed->end <= row) continue; /* ended: drop it */
            if (b->mode == RAST_BOUNDARY_CLOSED)
                rast__line_run(ed->a, ed->b, g, row, &x0, &x1);
            else
                rast__touch_run(2 * (int64_t)ed->a.x, 2 * (int64_t)ed->a.y,
                                2 * (int64_t)ed->b.x, 2 * (int64_t)ed->b.y, g->unit, row,
                                &x0, &x1);
        }
        b->active[m++] = b->active[n];
        if (x0 < b->in.cx0) x0 = b->in.cx0;
        if (x1 > b->in.cx1) x1 = b->in.cx1;
        if (x0 >= x1) continue;
        /* insertion by x0: a row has few runs */
        for (p = b->nxs; p > 0 && b->xs[2 * p - 2] > x0; p--) {
            b->xs[2 * p] = b->xs[2 * p - 2];
            b->xs[2 * p + 1] = b->xs[2 * p - 1];
        }
        b->xs[2 * p] = (int32_t)x0;
        b->xs[2 * p + 1] = (int32_t)x1;
        b->nxs++;
    }
    b->nactive = m;
}

/* Pass on the runs of the prepared row that start before column x. */
static void rast__bound_emit(rast__bound *b, int64_t x)
{
    while (b->k < b->nxs && b->xs[2 * b->k] < x) {
        rast__sink_span(b->out, b->row, b->xs[2 * b->k], b->xs[2 * b->k + 1]);
        b->k++;
    }
}

/* Finish every row before y and prepare row y (when inside the clip). */
static void rast__bound_upto(rast__bound *b, int32_t y)
{
    while (b->row < y) {
        if (b->row >= b->y0) rast__bound_emit(b, INT64_MAX);
        b->row++;
        if (b->row >= b->y1) break;
        if (b->nactive || b->bucket[b->row - b->y0] >= 0) {
            rast__bound_prepare(b);
        } else {
            b->nxs = b->k = 0;
        }
    }
}

static void rast__bound_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__bound *b = (rast__bound *)user;
    int32_t s;
    rast__bound_upto(b, y);
    for (s = 0; s < n; s++) {
        rast__bound_emit(b, xs[2 * s]);
        rast__sink_span(b->out, y, xs[2 * s], xs[2 * s + 1]);
    }
}

void rast__bound_end(rast__bound *b)
{
    rast__sink_flush(&b->in);
    rast__bound_upto(b, b->y1);
    rast__sink_flush(b->out);
}

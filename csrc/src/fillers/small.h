/*
 * small.h - the batch's filler for polygons of few vertices (small.c).
 * Not installed; used only by the polygon batch (entry/batch.c).
 */
#ifndef RAST_SMALL_H
#define RAST_SMALL_H

#include "../base/internal.h"

/* Polygons of at most this many vertices take the small filler. */
#define RAST__SMALL_POINTS 256

/* Fill `poly` (npoints vertices, checked) in `clip` (non-empty, at most
 * RAST_MAX_DIM columns wide: the span clip, or the polygon's box within
 * it; the rows drawn are those its edges cross within the clip's, so the
 * box need not be measured first) under `rule` with the exact boundary, as polygon
 * `index` of a batch: each run to span(user, index, y, x0, x1), the runs
 * the AET filler gives through a sink (maximal runs, rows top to bottom,
 * in increasing x).  `scratch` (aligned, `bytes` long)
 * as the AET filler's for the polygon's box is always enough.  Returns 0, having
 * done nothing, when npoints is past RAST__SMALL_POINTS or the scratch is
 * too small; 1 when filled. */
int rast__small_fill(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                     rast_fill_rule rule, const rast_rect *clip, rast_batch_span_fn span,
                     void *user, uint32_t index, void *scratch, size_t bytes);

/* The walk itself (rast__small_fill's body, the same arguments and
 * result): inline, so that a filler that hands the runs on itself (the
 * AET filler's few-vertex way, aet.c) has its span function inlined into
 * its own copy of the loops, with no call a row.  How it works: small.c. */
typedef struct rast__small_row {
    rast_batch_span_fn span;
    void *user;
    uint32_t index;
    int32_t y;
} rast__small_row;

/* The runs of one row from its n crossing keys (sorted here). */
static inline void rast__small_spans(rast__small_row *r, uint32_t *key, int32_t n, rast_fill_rule rule,
                              int32_t c0)
{
    int32_t i, k;
    if (n == 2) {
        /* Most rows: two crossings, of opposite directions (a closed
         * ring's sum to 0), one run between them under either rule. */
        int32_t x0 = (int32_t)(key[0] >> 1), x1 = (int32_t)(key[1] >> 1);
        if (x0 > x1) {
            int32_t t = x0;
            x0 = x1;
            x1 = t;
        }
        if (x0 < x1) {
            r->span(r->user, r->index, r->y, c0 + x0, c0 + x1);
        }
        return;
    }
    for (i = 1; i < n; i++) {
        uint32_t v = key[i];
        for (k = i; k > 0 && key[k - 1] > v; k--) key[k] = key[k - 1];
        key[k] = v;
    }
    /* The inside runs, each handed on once it is maximal: a run that
     * touches the next one (an even-odd pair ending where the next
     * begins, a winding that returns to 0 and leaves it at one column)
     * grows instead. */
    {
        int32_t x0 = 0, x1 = -1, w = 0, start = 0;
        for (i = 0; i < n; i++) {
            const int32_t x = (int32_t)(key[i] >> 1);
            int32_t a, b;
            if (rule == RAST_RULE_EVENODD) {
                if (!(i & 1)) {
                    start = x;
                    continue;
                }
            } else {
                if (w == 0) start = x;
                w += (key[i] & 1) ? 1 : -1;
                if (w != 0) continue;
            }
            a = start;
            b = x;
            if (a >= b) continue;
            if (a <= x1) {
                if (b > x1) x1 = b;
                continue;
            }
            if (x1 > x0) r->span(r->user, r->index, r->y, c0 + x0, c0 + x1);
            x0 = a;
            x1 = b;
        }
        if (x1 > x0) r->span(r->user, r->index, r->y, c0 + x0, c0 + x1);
    }
}

static inline int rast__small_walk(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                                   rast_fill_rule rule, const rast_rect *clip, rast_batch_span_fn span,
                                   void *user, uint32_t index, void *scratch, size_t bytes)
{
    rast__edge *ed = (rast__edge *)scratch;
    const rast_point *pts = poly->points;
    const int32_t c0 = clip->x0, c1 = clip->x1;
    int32_t row0 = clip->y0, row1 = clip->y1;
    rast__small_row r;
    uint32_t *keys;
    int32_t *cnt, ne = 0, hb, j0;
    uint32_t k, i, base;
    size_t room;

    if (npoints > RAST__SMALL_POINTS || (size_t)npoints * sizeof(rast__edge) > bytes) return 0;
    room = (bytes - (size_t)npoints * sizeof(rast__edge)) / sizeof(int32_t);
    /* The edges crossing the clip's rows (set up as a triangle's are:
     * inline, or out of line in a build for size). */
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++)
            ne += rast__edge_setup_tri(&ed[ne], pts[base + i], pts[base + (i + 1 == n ? 0 : i + 1)],
                                       g, row0, row1);
    }
    if (ne == 0) return 1;
    /* The rows the edges cross: the polygon's own, within the clip's. */
    row0 = row1;
    row1 = clip->y0;
    for (k = 0; k < (uint32_t)ne; k++) {
        if (ed[k].row < row0) row0 = ed[k].row;
        if (ed[k].end > row1) row1 = ed[k].end;
    }
    /* Rows per band: a count and ne slots each. */
    if (room < (size_t)ne + 1) return 0;
    hb = room / ((size_t)ne + 1) < (size_t)(row1 - row0) ? (int32_t)(room / ((size_t)ne + 1))
                                                        : row1 - row0;
    cnt = (int32_t *)(void *)(ed + npoints);
    keys = (uint32_t *)(void *)(cnt + hb);
    r.span = span;
    r.user = user;
    r.index = index;
    for (j0 = row0; j0 < row1; j0 += hb) {
        const int32_t j1 = row1 - j0 > hb ? j0 + hb : row1;
        int32_t e, j;
        memset(cnt, 0, (size_t)(j1 - j0) * sizeof *cnt);
        /* Edge by edge: its crossings of the band's rows into their slots. */
        for (e = 0; e < ne; e++) {
            rast__edge *d = &ed[e];
            const int32_t a = d->row > j0 ? d->row : j0, b = d->end < j1 ? d->end : j1;
            const uint32_t down = d->dir > 0;
            for (j = a; j < b; j++) {
                int32_t x = d->x < c0 ? c0 : d->x > c1 ? c1 : d->x;
                keys[(size_t)(j - j0) * (size_t)ne + (size_t)cnt[j - j0]++] =
                    ((uint32_t)(x - c0) << 1) | down;
                rast__edge_step(d);
            }
        }
        /* Row by row: the runs. */
        for (j = j0; j < j1; j++) {
            if (cnt[j - j0] < 2) continue;
            r.y = j;
            rast__small_spans(&r, keys + (size_t)(j - j0) * (size_t)ne, cnt[j - j0], rule, c0);
        }
    }
    return 1;
}

#endif /* RAST_SMALL_H */

/*
 * aet.h - the active edge table walk (seed 001, section 3.4), shared by
 * the AET filler (aet.c) and the colour-interpolating polygon fill
 * (shade_poly.c).  Static inline so that each user's span function is
 * inlined into its own copy of the loop: the plain fill pays no call per
 * span.  Not installed.
 *
 * A bucket edge table holds each edge under the first visible row it
 * crosses; the active edge table holds the edges crossing the current row,
 * sorted by their crossing column.  Each row: move the row's bucket into the
 * AET, pair the crossings into spans (even-odd) or sum their directions
 * (non-zero), then drop the edges that end and step the others one row down
 * with the exact DDA.  Insertion sort keeps the AET ordered: from one row to
 * the next the order changes only where edges cross, so it is nearly sorted.
 */
#ifndef RAST_AET_H
#define RAST_AET_H

#include "internal.h"

/* One inside run of row `row`: columns [l->x, r->x) (possibly empty),
 * bounded on the left by the crossing of edge l and on the right by that
 * of edge r.  Even-odd: the crossings 2k and 2k+1 of the row; non-zero:
 * the crossing where the winding number leaves 0 and the one where it
 * comes back.  An edge's `next` is its index in the walk's edge table
 * (see `src`); `order` may be NULL.  Runs come row by row, in increasing x. */
typedef void (*rast__aet_span_fn)(void *user, int32_t row, const rast__edge *l,
                                  const rast__edge *r);

/* Called for each row with its active edges sorted by column, before the
 * row's runs are formed; it may reorder edges of EQUAL column (which
 * changes no pixel, only which edges bound the runs). */
typedef void (*rast__aet_order_fn)(void *user, int32_t row, rast__edge *aet, int32_t n);

/* The walk: every run of `poly` inside `clip` to `span`.  Scratch as
 * rast__aet_scratch.  With `src` (room for 2 * npoints) not NULL, the edge
 * of index k is the ring edge from vertex src[2k] to vertex src[2k+1]
 * (indices into poly->points). */
/* Insertion sort of the AET by crossing column.  The edges are held by
 * value: comparisons read consecutive records and stepping walks the array
 * in order; a record moves only when its edge crosses another. */
static inline void rast__aet_sort(rast__edge *aet, int32_t n)
{
    int32_t i, k;
    for (i = 1; i < n; i++) {
        if (aet[i - 1].x > aet[i].x) {
            rast__edge v = aet[i];
            for (k = i; k > 0 && aet[k - 1].x > v.x; k--) aet[k] = aet[k - 1];
            aet[k] = v;
        }
    }
}

static inline rast_status rast__aet_walk(const rast_polygon *poly, uint32_t npoints,
                                         const rast__grid *g, rast_fill_rule rule,
                                         const rast_rect *clip, rast__arena *arena,
                                         rast__aet_span_fn span, rast__aet_order_fn order,
                                         void *user, int32_t *src)
{
    const rast_point *pts = poly->points;
    rast__edge *edges, *aet;
    int32_t *bucket;
    int32_t miny, maxy, row0, row1, j, nactive = 0, nedges = 0;
    uint32_t i, k, base;
    int64_t r;

    if (npoints == 0) return RAST_OK;

    /* Visible rows: the clip's rows that the polygon's y extent reaches. */
    miny = maxy = pts[0].y;
    for (i = 1; i < npoints; i++) {
        if (pts[i].y < miny) miny = pts[i].y;
        if (pts[i].y > maxy) maxy = pts[i].y;
    }
    r = rast__row_at_or_after(2 * (int64_t)miny, g);
    row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)maxy, g);
    row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    if (row0 >= row1) return RAST_OK;

    edges = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    aet = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    bucket = (int32_t *)rast__take(arena, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));
    if (!edges || !aet || !bucket) return RAST_E_SCRATCH;

    for (j = row0; j < row1; j++) bucket[j - row0] = -1;

    /* The bucket edge table: each edge listed under its first visible row. */
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            rast__edge *ed = &edges[nedges];
            rast_point a = pts[base + i];
            rast_point b = pts[base + (i + 1 == n ? 0 : i + 1)];
            if (rast__edge_setup(ed, a, b, g, row0, row1)) {
                if (src) {
                    src[2 * nedges] = (int32_t)(base + i);
                    src[2 * nedges + 1] = (int32_t)(base + (i + 1 == n ? 0 : i + 1));
                }
                ed->next = bucket[ed->row - row0];
                bucket[ed->row - row0] = nedges++;
            }
        }
    }

    for (j = row0; j < row1; j++) {
        int32_t e, m, n;

        /* Edges starting on this row join the AET, kept sorted. */
        for (e = bucket[j - row0]; e >= 0; e = edges[e].next) {
            int32_t x = edges[e].x, p = nactive++;
            while (p > 0 && aet[p - 1].x > x) {
                aet[p] = aet[p - 1];
                p--;
            }
            aet[p] = edges[e];
            aet[p].next = e; /* from here on: which edge it is */
        }
        if (nactive == 0) continue;
        if (order) order(user, j, aet, nactive);

        /* Spans: sample i is inside iff the crossings with x <= i make it so. */
        if (rule == RAST_RULE_EVENODD) {
            for (n = 0; n + 1 < nactive; n += 2) span(user, j, &aet[n], &aet[n + 1]);
        } else {
            int32_t w = 0, start = 0;
            for (n = 0; n < nactive; n++) {
                if (w == 0) start = n;
                w += aet[n].dir;
                if (w == 0) span(user, j, &aet[start], &aet[n]);
            }
        }

        /* Step every edge to the next row; drop those that end here (few
         * rows have any, so the compaction is a separate, rare pass). */
        for (n = 0, m = 0; n < nactive; n++) {
            rast__edge_step(&aet[n]);
            m += aet[n].end == j + 1;
        }
        if (m) {
            for (n = 0, m = 0; n < nactive; n++)
                if (aet[n].end != j + 1) aet[m++] = aet[n];
            nactive = m;
        }
        rast__aet_sort(aet, nactive);
    }
    return RAST_OK;
}

#endif /* RAST_AET_H */

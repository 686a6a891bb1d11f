/*
 * aet.c - the active edge table filler (seed 001, section 3.4).
 *
 * A bucket edge table holds each edge under the first visible row it
 * crosses; the active edge table holds the edges crossing the current row,
 * sorted by their crossing column.  Each row: move the row's bucket into the
 * AET, pair the crossings into spans (even-odd) or sum their directions
 * (non-zero), then drop the edges that end and step the others one row down
 * with the exact DDA.  Insertion sort keeps the AET ordered: from one row to
 * the next the order changes only where edges cross, so it is nearly sorted.
 *
 * Scratch: the edge table and the AET (an edge record each) and one bucket
 * head per visible row.
 */
#include "internal.h"

/* The edge record's size is part of the scratch contract in rastrum.h. */
typedef char rast__aet_edge_size_check[sizeof(rast__edge) == RAST_AET_EDGE_BYTES ? 1 : -1];

size_t rast__aet_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    return rast__size_add(
        rast__size_mul(2, rast__align(rast__size_mul(npoints, sizeof(rast__edge)))),
        rast__align(rast__size_mul((size_t)height + 1, sizeof(int32_t))));
}

/* Insertion sort of the AET by crossing column.  The edges are held by
 * value: comparisons read consecutive records and stepping walks the array
 * in order; a record moves only when its edge crosses another. */
static void rast__aet_sort(rast__edge *aet, int32_t n)
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

rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena)
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
        }
        if (nactive == 0) continue;

        /* Spans: sample i is inside iff the crossings with x <= i make it so. */
        if (rule == RAST_RULE_EVENODD) {
            for (n = 0; n + 1 < nactive; n += 2)
                rast__sink_span(sink, j, aet[n].x, aet[n + 1].x);
        } else {
            int32_t w = 0, start = 0;
            for (n = 0; n < nactive; n++) {
                if (w == 0) start = aet[n].x;
                w += aet[n].dir;
                if (w == 0) rast__sink_span(sink, j, start, aet[n].x);
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
    rast__sink_flush(sink);
    return RAST_OK;
}

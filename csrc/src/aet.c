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
 * Scratch: the edges, the AET (an index per edge) and one bucket head per
 * visible row.
 */
#include "internal.h"

/* The edge record's size is part of the scratch contract in rastrum.h. */
typedef char rast__aet_edge_size_check[sizeof(rast__edge) == RAST_AET_EDGE_BYTES ? 1 : -1];

size_t rast__aet_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    return rast__align((size_t)npoints * sizeof(rast__edge)) +
           rast__align((size_t)npoints * sizeof(int32_t)) +
           rast__align(((size_t)height + 1) * sizeof(int32_t));
}

/* Insertion sort of the AET indices by crossing column. */
static void rast__aet_sort(int32_t *active, int32_t n, const rast__edge *edges)
{
    int32_t i, k;
    for (i = 1; i < n; i++) {
        int32_t v = active[i];
        int32_t xv = edges[v].x;
        for (k = i; k > 0 && edges[active[k - 1]].x > xv; k--)
            active[k] = active[k - 1];
        active[k] = v;
    }
}

rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena)
{
    const rast_point *pts = poly->points;
    rast__edge *edges;
    int32_t *active, *bucket;
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
    active = (int32_t *)rast__take(arena, (size_t)npoints * sizeof(int32_t));
    bucket = (int32_t *)rast__take(arena, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));
    if (!edges || !active || !bucket) return RAST_E_SCRATCH;

    for (j = row0; j < row1; j++) bucket[j - row0] = -1;

    /* The bucket edge table. */
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
            while (p > 0 && edges[active[p - 1]].x > x) {
                active[p] = active[p - 1];
                p--;
            }
            active[p] = e;
        }
        if (nactive == 0) continue;

        /* Spans: sample i is inside iff the crossings with x <= i make it so. */
        if (rule == RAST_RULE_EVENODD) {
            for (n = 0; n + 1 < nactive; n += 2)
                rast__sink_span(sink, j, edges[active[n]].x, edges[active[n + 1]].x);
        } else {
            int32_t w = 0, start = 0;
            for (n = 0; n < nactive; n++) {
                const rast__edge *ed = &edges[active[n]];
                if (w == 0) start = ed->x;
                w += ed->dir;
                if (w == 0) rast__sink_span(sink, j, start, ed->x);
            }
        }

        /* Drop the edges that end here; step the rest to the next row. */
        for (n = 0, m = 0; n < nactive; n++) {
            rast__edge *ed = &edges[active[n]];
            if (ed->end == j + 1) continue;
            rast__edge_step(ed);
            active[m++] = active[n];
        }
        nactive = m;
        rast__aet_sort(active, nactive, edges);
    }
    rast__sink_flush(sink);
    return RAST_OK;
}

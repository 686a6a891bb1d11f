/*
 * xscan.c - the x-scanline filler (seed 001, section 3.4.1; seed 003
 * FillPolygonbySL): for every row, intersect every edge with it, sort the
 * crossings, and pair them into spans (even-odd) or sum their directions
 * (non-zero).
 *
 * This is the baseline the AET improves on: no edge table and no coherence.
 * Each row tests every edge, and each crossing is computed from scratch by
 * one exact division, X = x0 + (yc - y0) dx / dy, where the AET steps an
 * integer DDA.  The crossing's first counting column is rast__cross_col of
 * num / dy with num = x0 dy + (yc - y0) dx, |num| < 2^57 + 2^58 < 2^59 and
 * dy < 2^29 (poly.h): inside the bounds rast__cross_col states.
 *
 * Scratch: one rast__line (32 bytes) per vertex, and one uint32_t crossing
 * key per vertex (a row crosses at most every edge once).
 */
#include "poly.h"

size_t rast__xscan_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return rast__align((size_t)npoints * sizeof(rast__line)) +
           rast__align((size_t)npoints * sizeof(uint32_t));
}

/* Sort keys ascending: insertion sort for the few crossings of most rows,
 * heapsort (no recursion, no extra memory) when a row has many. */
static void rast__sort_keys(uint32_t *a, int32_t n)
{
    int32_t i, k, end;
    if (n <= 32) {
        for (i = 1; i < n; i++) {
            uint32_t v = a[i];
            for (k = i; k > 0 && a[k - 1] > v; k--) a[k] = a[k - 1];
            a[k] = v;
        }
        return;
    }
    for (i = n / 2 - 1; i >= 0; i--) { /* heapify */
        uint32_t v = a[i];
        for (k = i; 2 * k + 1 < n;) {
            int32_t c = 2 * k + 1;
            if (c + 1 < n && a[c + 1] > a[c]) c++;
            if (a[c] <= v) break;
            a[k] = a[c];
            k = c;
        }
        a[k] = v;
    }
    for (end = n - 1; end > 0; end--) { /* move the largest behind the heap */
        uint32_t v = a[end];
        a[end] = a[0];
        for (k = 0; 2 * k + 1 < end;) {
            int32_t c = 2 * k + 1;
            if (c + 1 < end && a[c + 1] > a[c]) c++;
            if (a[c] <= v) break;
            a[k] = a[c];
            k = c;
        }
        a[k] = v;
    }
}

rast_status rast__xscan_fill(const rast_polygon *poly, uint32_t npoints,
                             const rast__grid *g, rast_fill_rule rule,
                             const rast_rect *clip, rast__sink *sink,
                             rast__arena *arena)
{
    rast__box box;
    rast__line *lines;
    uint32_t *keys;
    int32_t nlines, j, e, n;

    if (!rast__poly_box(poly, npoints, g, clip, &box)) return RAST_OK;
    lines = (rast__line *)rast__take(arena, (size_t)npoints * sizeof(rast__line));
    keys = (uint32_t *)rast__take(arena, (size_t)npoints * sizeof(uint32_t));
    if (!lines || !keys) return RAST_E_SCRATCH;
    nlines = rast__poly_lines(poly, g, &box, lines);

    for (j = box.row0; j < box.row1; j++) {
        int64_t yc = (int64_t)j * g->unit + g->off;

        /* Every edge crossing the row: its first counting column, clamped
         * to [col0, col1] (a crossing left of the box counts for all of its
         * samples, one right of it for none, as before clamping), as the
         * key 2 (col - col0) + (dir > 0) < 2^32. */
        for (e = 0, n = 0; e < nlines; e++) {
            const rast__line *l = &lines[e];
            int64_t c;
            if (j < l->row || j >= l->end) continue;
            c = rast__cross_col((int64_t)l->x0 * l->dy + (yc - l->y0) * l->dx, l->dy, g);
            if (c < box.col0) c = box.col0;
            if (c > box.col1) c = box.col1;
            keys[n++] = 2 * (uint32_t)(c - box.col0) + (uint32_t)(l->dir > 0);
        }
        rast__sort_keys(keys, n);

        /* Pair: sample i is inside iff the crossings with column <= i make
         * it so (left closed, right open). */
        if (rule == RAST_RULE_EVENODD) {
            for (e = 0; e + 1 < n; e += 2)
                rast__sink_span(sink, j, box.col0 + (int32_t)(keys[e] >> 1),
                                box.col0 + (int32_t)(keys[e + 1] >> 1));
        } else {
            int32_t w = 0, start = 0;
            for (e = 0; e < n; e++) {
                int32_t c = box.col0 + (int32_t)(keys[e] >> 1);
                if (w == 0) start = c;
                w += (keys[e] & 1) ? 1 : -1;
                if (w == 0) rast__sink_span(sink, j, start, c);
            }
        }
    }
    rast__sink_flush(sink);
    return RAST_OK;
}

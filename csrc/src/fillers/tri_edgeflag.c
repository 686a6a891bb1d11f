/*
 * tri_edgeflag.c - the textbook's edge-flag triangle filler (seed 001,
 * section 3.3.4, algorithm 9, Example 3-1).
 *
 * Each of the three edges is discretised by the exact DDA into one of two
 * flag arrays, SpanLeft or SpanRight, one entry per row: the edges on the
 * left of the triangle's spans (the book's edges whose "feature is true")
 * into SpanLeft, the others into SpanRight.  Then each row is filled from
 * SpanLeft (closed) to SpanRight (open), and the last row is left out by
 * the rows' own rule (top closed, bottom open): the book's "左闭右开,
 * 下闭上开".  The book rounds each crossing to the nearest column; that is
 * RAST_ROUND_TEXTBOOK, and the exact rule is the default.
 *
 * Scratch: the two arrays, one int32_t each per clip row.
 */
#include "../base/internal.h"

size_t rast__tri_edgeflag_scratch(int32_t width, int32_t height)
{
    (void)width;
    return rast__size_mul(2, rast__align(rast__size_mul((size_t)height, sizeof(int32_t))));
}

int rast__tri_span_flags(const rast_point *t, const rast__grid *g,
                         int32_t row_lo, int32_t row_hi, int32_t *span_left,
                         int32_t *span_right, int32_t *r0, int32_t *r1)
{
    rast__edge ed;
    int64_t area;
    int k;

    /* Orientation: the edge function of t0->t1 at t2 (input units, products
     * below 2^56).  With area > 0 the edges going down (dir > 0) have the
     * inside on their right, so they start spans; with area < 0 the edges
     * going up do.  Zero: degenerate, no sample inside. */
    area = (int64_t)(t[2].x - t[0].x) * (t[1].y - t[0].y) -
           (int64_t)(t[2].y - t[0].y) * (t[1].x - t[0].x);
    if (area == 0) return 0;
    *r0 = row_hi;
    *r1 = row_lo;
    for (k = 0; k < 3; k++) {
        int32_t *flags, j;
        rast__edge e;
        if (!rast__edge_setup_tri(&ed, t[k], t[k == 2 ? 0 : k + 1], g, row_lo, row_hi)) continue;
        /* The walk on a local copy: the int32_t stores into the flags
         * could alias ed, whose address was taken, and force reloads. */
        e = ed;
        flags = ((e.dir > 0) == (area > 0)) ? span_left : span_right;
        flags -= row_lo;
        for (j = e.row; j < e.end; j++) {
            flags[j] = e.x;
            rast__edge_step(&e);
        }
        if (e.row < *r0) *r0 = e.row;
        if (e.end > *r1) *r1 = e.end;
    }
    return *r0 < *r1;
}

rast_status rast__tri_edgeflag_fill(const rast_point *t, const rast__grid *g,
                                    const rast_rect *clip, rast__sink *sink,
                                    rast__arena *arena)
{
    size_t n = (size_t)(clip->y1 - clip->y0);
    int32_t *left, *right, r0, r1, j, xmin, xmax;
    rast__rows o;

    left = (int32_t *)rast__take(arena, n * sizeof(int32_t));
    right = (int32_t *)rast__take(arena, n * sizeof(int32_t));
    if (!left || !right) return RAST_E_SCRATCH;
    if (!rast__tri_span_flags(t, g, clip->y0, clip->y1, left, right, &r0, &r1)) return RAST_OK;
    /* Every crossing lies between the vertices' abscissae. */
    xmin = t[0].x < t[1].x ? t[0].x : t[1].x;
    xmin = xmin < t[2].x ? xmin : t[2].x;
    xmax = t[0].x > t[1].x ? t[0].x : t[1].x;
    xmax = xmax > t[2].x ? xmax : t[2].x;
    o = rast__rows_of(sink);
    left -= clip->y0;
    right -= clip->y0;
    if (rast__rows_direct_uncut(&o, 2 * (int64_t)xmin, 2 * (int64_t)xmax, g)) {
        unsigned char *p = rast__rows_at(&o, r0, 1);
        for (j = r0; j < r1; j++) rast__rows_emit(&o, &p, j, left[j], right[j], 1);
    } else {
        for (j = r0; j < r1; j++) rast__rows_put(&o, j, left[j], right[j]);
    }
    return RAST_OK;
}

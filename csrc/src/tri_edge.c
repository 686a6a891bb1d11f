/*
 * tri_edge.c - the edge-function triangle filler (seeds 000, 002, 004):
 * bounding box, fixed-point edge functions stepped by additions only, and
 * the top-left rule.
 *
 * With the triangle turned so that its inside is on the positive side of
 * each edge a->b, the edge function
 *     E(p) = (px - ax)(by - ay) - (py - ay)(bx - ax)
 * is positive inside, and on a non-horizontal edge it is dy * (xc - X),
 * X the edge's crossing of the sample's row: the sign of E compares the
 * sample with the crossing, which is what the polygon rule compares.  A
 * sample exactly on an edge (E = 0) belongs to the triangle iff the edge is
 * a left edge (dy > 0: spans are left closed) - the top-left rule, whose
 * "top" half (a horizontal top edge is in, a bottom one out) is the rows'
 * own rule (top closed, bottom open), kept by visiting only the rows the
 * triangle covers.  So the filler owns exactly the samples the polygon rule
 * gives the triangle, vertices and all.
 *
 * Textbook rounding counts a crossing for column i iff X < i + o + 1/2: the
 * exact test at the sample moved half a pixel right, with the tie flipped
 * (left edges open, right edges closed).
 *
 * Instead of testing every sample of the box, each row keeps, per edge, the
 * column where the edge's test turns (the first column inside a left edge,
 * the first column outside a right edge) and walks it from the previous
 * row's with additions, Bresenham-like: the work per row is the number of
 * columns the edges move, and the span between is handed on whole.
 *
 * Scratch: none.
 */
#include "internal.h"

size_t rast__tri_edge_scratch(int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return 0;
}

/* One edge as a column bound walked along the rows.  With G the edge
 * function turned into a test "G >= 0" that grows with the column (for a
 * right edge, the test "outside"), c is the first column of [lo, hi] with
 * G >= 0 (hi if there is none) and g is G at column c of the current row. */
typedef struct rast__fe {
    int64_t g;  /* G at (c, current row) */
    int64_t da; /* G's growth per column, > 0 */
    int64_t db; /* G's growth per row */
    int32_t c;
} rast__fe;

static void rast__fe_walk(rast__fe *f, int32_t lo, int32_t hi)
{
    /* One column either way without a branch: from one row to the next
     * most edges move by at most one column, and which way is a coin toss
     * a branch would mispredict.  (back and fwd exclude each other.) */
    int32_t back = (f->g - f->da >= 0) & (f->c > lo);
    int32_t fwd = (f->g < 0) & (f->c < hi);
    f->c += fwd - back;
    f->g += (fwd - back) * f->da;
    /* Flatter edges walk on. */
    if (f->g >= 0) {
        while (f->c > lo && f->g - f->da >= 0) {
            f->g -= f->da;
            f->c--;
        }
    } else {
        while (f->c < hi && f->g < 0) {
            f->g += f->da;
            f->c++;
        }
    }
}

rast_status rast__tri_edge_fill(const rast_point *t, const rast__grid *g,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    int64_t x[3], y[3], area, xmin, xmax, ymin, ymax, shift, r;
    int64_t u = g->unit, px, py;
    rast__fe fl[2], fr[2]; /* left and right bounds */
    int32_t row0, row1, lo, hi, j, k, nl = 0, nr = 0;
    (void)arena;

    for (k = 0; k < 3; k++) {
        x[k] = 2 * (int64_t)t[k].x; /* internal units, |x| < 2^28 */
        y[k] = 2 * (int64_t)t[k].y;
    }
    /* Orientation: E of t0->t1 at t2; differences < 2^29, products < 2^58. */
    area = (x[2] - x[0]) * (y[1] - y[0]) - (y[2] - y[0]) * (x[1] - x[0]);
    if (area == 0) return RAST_OK; /* degenerate: no sample inside */
    if (area < 0) {                /* turn it so that inside is E > 0 */
        int64_t s;
        s = x[1]; x[1] = x[2]; x[2] = s;
        s = y[1]; y[1] = y[2]; y[2] = s;
    }

    xmin = xmax = x[0];
    ymin = ymax = y[0];
    for (k = 1; k < 3; k++) {
        if (x[k] < xmin) xmin = x[k];
        if (x[k] > xmax) xmax = x[k];
        if (y[k] < ymin) ymin = y[k];
        if (y[k] > ymax) ymax = y[k];
    }
    /* Rows: samples in [ymin, ymax), cut to the clip. */
    r = rast__row_at_or_after(ymin, g);
    row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(ymax, g);
    row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    if (row0 >= row1) return RAST_OK;
    /* Columns: tested samples (moved by `shift`) in [xmin, xmax], cut to the
     * clip; every inside sample is one of them. */
    shift = g->off + (g->textbook ? u / 2 : 0);
    r = rast__ceildiv(xmin - shift, u);
    lo = r > clip->x0 ? (int32_t)r : clip->x0;
    r = rast__floordiv(xmax - shift, u) + 1;
    hi = r < clip->x1 ? (int32_t)r : clip->x1;
    if (lo >= hi) return RAST_OK;

    /* Each non-horizontal edge at (lo, row0), as a left bound (the first
     * column inside it) or a right one (the first column outside it); a
     * triangle has one or two of each.  px - x and py - y stay below
     * 2^29 + 2 unit on the box's samples, so each product is below 2^59. */
    px = (int64_t)lo * u + shift;
    py = (int64_t)row0 * u + g->off;
    for (k = 0; k < 3; k++) {
        int32_t n = k == 2 ? 0 : k + 1;
        int64_t dx = x[n] - x[k], dy = y[n] - y[k], e;
        rast__fe *f;
        int in_on_tie;
        if (dy == 0) continue; /* horizontal: the rows already say it */
        e = (px - x[k]) * dy - (py - y[k]) * dx;
        /* Inside is E > 0, or E == 0 on an edge that owns its samples:
         * exact, left edges (dy > 0); textbook, right edges. */
        in_on_tie = (dy > 0) != (g->textbook != 0);
        if (dy > 0) { /* left edge: G = E - 1 + in_on_tie >= 0 is inside */
            f = &fl[nl++];
            f->g = e - 1 + in_on_tie;
            f->da = dy * u;
            f->db = -dx * u;
        } else {      /* right edge: G = -E - in_on_tie >= 0 is outside */
            f = &fr[nr++];
            f->g = -e - in_on_tie;
            f->da = -dy * u;
            f->db = dx * u;
        }
        f->c = lo;
    }

    for (j = row0; j < row1; j++) {
        int32_t x0, x1;
        rast__fe_walk(&fl[0], lo, hi);
        rast__fe_walk(&fr[0], lo, hi);
        x0 = fl[0].c;
        x1 = fr[0].c;
        fl[0].g += fl[0].db;
        fr[0].g += fr[0].db;
        if (nl > 1) {
            rast__fe_walk(&fl[1], lo, hi);
            if (fl[1].c > x0) x0 = fl[1].c;
            fl[1].g += fl[1].db;
        } else if (nr > 1) {
            rast__fe_walk(&fr[1], lo, hi);
            if (fr[1].c < x1) x1 = fr[1].c;
            fr[1].g += fr[1].db;
        }
        rast__sink_row(sink, j, x0, x1);
    }
    return RAST_OK;
}

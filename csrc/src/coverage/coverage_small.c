/*
 * coverage_small.c - "area" and "accumulate" of one small convex ring
 * painted through a painter (the anti-aliased fills: a tiny polygon a
 * call, Canvas.fill_polygon in a loop, issue 33), without the engines'
 * setup: no edge records, no sort, no bands, one row of cells.
 *
 * A convex ring (entry/coverage.c's test) is plain (coverage_plain.c):
 * its winding number is 0 outside and +1 or -1 inside, so the
 * accumulation of its edges is its exact coverage, for "area" and
 * "accumulate" alike, under either rule (docs/coverage.md).  Each pixel
 * gets the level floor(a M + 1/2), M = 255, of its exact area a, as the
 * 128-bit sums of the engines give it away from a tie; here a is summed
 * in 64 bits, the signed area right of each edge's piece in each cell
 * (FreeType's cover and area in one word a column, run along the row),
 * on a grid of 2^-K pixel (K = 26) relative to the ring's pixel box.
 * Only the crossings of an edge with the row lines (abscissae) and with
 * the column lines (ordinates) are rounded, down, by less than one unit;
 * a pixel's value is then off by less than 2^(K + 4) units of 2^-(2K + 1)
 * pixel per edge in its row (the columns left of it: the two ends of the
 * edge's run there; its own cell: the piece's height and its abscissae).
 * Where some level lies within that bound of a tie (times M, and the
 * engines' own 2^-50) the call declines before it has painted a pixel,
 * and the engines take the ring: the levels are theirs, bit for bit.
 *
 * Bounds: a pixel box of at most RAST__SMALL_DIM pixels a side, S <= 16
 * (so that K - S >= 10), at most RAST__SMALL_EDGES vertices.  Ordinates
 * and abscissae from the box's corner are below 2^(K + 5) = 2^31, so a
 * product of two differences (a crossing's numerator) is below 2^62; a
 * piece's part dt (f0 + f1) is below 2^53, a row's running sum below
 * 2^54 (a convex ring's pieces of one sign cover a column's height
 * once), a level's numerator below 2^62.  Not in size-optimised builds.
 */
#include "coverage.h"

#if !defined(__OPTIMIZE_SIZE__)

#define RAST__SMALL_K 26
#define RAST__SMALL_ONE ((int64_t)1 << RAST__SMALL_K)
#define RAST__SMALL_FULL ((int64_t)1 << (2 * RAST__SMALL_K + 1)) /* a pixel's area, in the cells' units */

/* An edge, top end first, in units of 2^-K pixel from the box's corner;
 * s its direction (+1 down). */
typedef struct rast__small_edge {
    int64_t x0, y0, x1, y1, dx, dy;
    int32_t s;
} rast__small_edge;

int rast__cov_small_fits(const rast_polygon *poly, int32_t s, rast_rect *box)
{
    const rast_point *p = poly->points;
    uint32_t n, i;
    int32_t x0, y0, x1, y1;
    if (poly->nrings != 1 || s > 16 || (n = poly->ring_sizes[0]) < 3 || n > RAST__SMALL_EDGES) return 0;
    x0 = x1 = p[0].x;
    y0 = y1 = p[0].y;
    for (i = 1; i < n; i++) {
        if (p[i].x < x0) x0 = p[i].x;
        if (p[i].x > x1) x1 = p[i].x;
        if (p[i].y < y0) y0 = p[i].y;
        if (p[i].y > y1) y1 = p[i].y;
    }
    /* the pixels the ring reaches (|coordinates| < 2^27: no overflow) */
    box->x0 = x0 >> s;
    box->y0 = y0 >> s;
    box->x1 = (int32_t)(((int64_t)x1 + ((int64_t)1 << s) - 1) >> s);
    box->y1 = (int32_t)(((int64_t)y1 + ((int64_t)1 << s) - 1) >> s);
    return box->x1 - box->x0 <= RAST__SMALL_DIM && box->y1 - box->y0 <= RAST__SMALL_DIM;
}

/* floor(a / b), b > 0. */
static int64_t rast__small_floordiv(int64_t a, int64_t b)
{
    int64_t q, r;
    rast__floordivmod(a, b, &q, &r);
    return q;
}

/* The piece from (f0, t0) to (f1, t1) (abscissae from column c's left,
 * ordinates from the row's top), sign s: its area right of it in cell c,
 * the whole height in every cell right of c (acc[c + 1] holds the rest,
 * for the running sum). */
static void rast__small_add(int64_t *acc, int64_t c, int64_t f0, int64_t f1, int64_t t0, int64_t t1, int32_t s)
{
    const int64_t dt = t1 - t0, a = dt * (f0 + f1), whole = dt * (2 * RAST__SMALL_ONE);
    acc[c] += s > 0 ? whole - a : a - whole;
    acc[c + 1] += s > 0 ? a : -a;
}

/* Edge e's piece in the row whose top is rt (ordinates ya < yb in it):
 * split at the column lines it crosses, into acc. */
static void rast__small_piece(int64_t *acc, const rast__small_edge *e, int64_t rt, int64_t ya, int64_t yb)
{
    const int64_t xa = ya == e->y0 ? e->x0 : e->x0 + rast__small_floordiv(e->dx * (ya - e->y0), e->dy);
    const int64_t xb = yb == e->y1 ? e->x1 : e->x0 + rast__small_floordiv(e->dx * (yb - e->y0), e->dy);
    const int64_t ca = xa >> RAST__SMALL_K, cb = xb >> RAST__SMALL_K;
    int64_t c, f = xa - (ca << RAST__SMALL_K), t = ya - rt, tx;
    const int64_t tb = yb - rt;
    if (ca < cb) { /* going right: the lines ca + 1 .. cb, at ordinates floor(.) in [t, tb] */
        for (c = ca; c < cb; c++) {
            tx = e->y0 + (int64_t)((uint64_t)(((c + 1) << RAST__SMALL_K) - e->x0) * (uint64_t)e->dy /
                                   (uint64_t)e->dx) - rt;
            if (tx < t) tx = t;
            if (tx > tb) tx = tb;
            rast__small_add(acc, c, f, RAST__SMALL_ONE, t, tx, e->s);
            t = tx;
            f = 0;
        }
    } else {
        for (c = ca; c > cb; c--) { /* going left: the lines ca .. cb + 1 */
            tx = e->y0 + (int64_t)((uint64_t)(e->x0 - (c << RAST__SMALL_K)) * (uint64_t)e->dy /
                                   (uint64_t)(-e->dx)) - rt;
            if (tx < t) tx = t;
            if (tx > tb) tx = tb;
            rast__small_add(acc, c, f, 0, t, tx, e->s);
            t = tx;
            f = RAST__SMALL_ONE;
        }
    }
    rast__small_add(acc, cb, f, xb - (cb << RAST__SMALL_K), t, tb, e->s);
}

int rast__cov_small(const rast_polygon *poly, int32_t s, const rast__cov_out *o, const rast_rect *box)
{
    rast__small_edge e[RAST__SMALL_EDGES];
    unsigned char lv[RAST__SMALL_DIM * RAST__SMALL_DIM];
    int64_t acc[RAST__SMALL_DIM + 2];
    const rast_point *p = poly->points;
    const uint32_t n = poly->ring_sizes[0];
    const int32_t w = box->x1 - box->x0, h = box->y1 - box->y0, sh = RAST__SMALL_K - s;
    const int64_t bx = (int64_t)box->x0 << s, by = (int64_t)box->y0 << s;
    uint32_t i, ne = 0;
    int32_t r, c, x0, x1;
    rast__cov_out row;
    if (w <= 0 || h <= 0) return 1; /* no area: nothing to paint */
    for (i = 0; i < n; i++) { /* the edges not horizontal, top end first */
        const rast_point a = p[i], b = p[i + 1 < n ? i + 1 : 0];
        const int down = a.y < b.y;
        const rast_point t = down ? a : b, u = down ? b : a;
        if (a.y == b.y) continue;
        e[ne].x0 = (int64_t)((uint64_t)(t.x - bx) << sh);
        e[ne].y0 = (int64_t)((uint64_t)(t.y - by) << sh);
        e[ne].x1 = (int64_t)((uint64_t)(u.x - bx) << sh);
        e[ne].y1 = (int64_t)((uint64_t)(u.y - by) << sh);
        e[ne].dx = e[ne].x1 - e[ne].x0;
        e[ne].dy = e[ne].y1 - e[ne].y0;
        e[ne].s = down ? 1 : -1;
        ne++;
    }
    for (r = 0; r < h; r++) {
        const int64_t rt = (int64_t)r << RAST__SMALL_K, rb = rt + RAST__SMALL_ONE;
        int64_t v = 0, win;
        uint32_t m = 0;
        memset(acc, 0, (size_t)(w + 2) * sizeof(acc[0]));
        for (i = 0; i < ne; i++) {
            const int64_t ya = e[i].y0 > rt ? e[i].y0 : rt, yb = e[i].y1 < rb ? e[i].y1 : rb;
            if (ya >= yb) continue;
            m++;
            rast__small_piece(acc, &e[i], rt, ya, yb);
        }
        /* the window round a tie: M times m edges' bound, and the
         * engines' own error (below 2^-50 pixel: 2^3 units) */
        win = 255 * (int64_t)m * ((int64_t)1 << (RAST__SMALL_K + 4)) + 4096;
        for (c = 0; c < w; c++) {
            int64_t a, num, fr;
            v += acc[c];
            if (!v) { /* (exact: no piece reached it, or they cancel) */
                lv[r * w + c] = 0;
                continue;
            }
            a = v < 0 ? -v : v;
            if (a > RAST__SMALL_FULL) a = RAST__SMALL_FULL;
            num = a * 255 + RAST__SMALL_FULL / 2;
            fr = num & (RAST__SMALL_FULL - 1);
            if (fr <= win || fr >= RAST__SMALL_FULL - win) return 0; /* near a tie: the engines' */
            lv[r * w + c] = (unsigned char)(num >> (2 * RAST__SMALL_K + 1));
        }
    }
    /* every level decided: the rows inside the clip handed on */
    x0 = box->x0 > o->clip.x0 ? box->x0 : o->clip.x0;
    x1 = box->x1 < o->clip.x1 ? box->x1 : o->clip.x1;
    if (x0 >= x1) return 1;
    row = *o;
    row.clip.x0 = x0;
    row.clip.x1 = x1;
    for (r = 0; r < h; r++) {
        const int32_t y = box->y0 + r;
        if (y < o->clip.y0 || y >= o->clip.y1) continue;
        row.base = lv + r * w + (x0 - box->x0);
        rast__cov_row_done(&row, y);
    }
    return 1;
}

#else
typedef int rast__cov_small_unused; /* (ISO C: a translation unit declares something) */
#endif

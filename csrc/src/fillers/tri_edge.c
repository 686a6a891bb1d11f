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
 * Instead of testing every sample of the box, each edge keeps, per row,
 * the column where its test turns (the first column inside a left edge,
 * the first column outside a right edge) and the value of its edge
 * function there.  One division puts it on the first row; from row to row
 * the function grows by a constant, so the column moves by a constant
 * number of columns plus one more when the function's remainder runs out:
 * an integer DDA on E, with additions only.  Every row takes the last of
 * the left bounds and the first of the right ones (the triangle is the
 * intersection of its edges' half-planes), with no branch on which edge is
 * active: the edge lines are followed past their vertices, and the other
 * edge of the same side decides there.  The span between is handed on
 * whole.
 *
 * Scratch: none.
 */
#include "../base/internal.h"
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__FE_SSE2 1
#else
#define RAST__FE_SSE2 0
#endif

size_t rast__tri_edge_scratch(int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return 0;
}

/* One edge as a column bound walked along the rows.  With G the edge
 * function turned into a test "G >= 0" that grows with the column (for a
 * right edge, the test "outside"), c is the first column with G >= 0 on
 * the current row and g is G there, 0 <= g < da.  Followed past the
 * edge's vertices, c may leave the int32_t range: |c| < 2^59. */
typedef struct rast__fe {
    int64_t c;
    int64_t g;    /* G at (c, current row), in [0, da) */
    int64_t da;   /* G's growth per column, > 0 */
    int64_t r0;   /* -(G's growth per row) = s0*da + r0, 0 <= r0 < da */
    int64_t s0;
} rast__fe;

/* The next row: G falls by s0*da + r0, so the bound moves s0 columns, and
 * one more when the remainder runs out.  Branch-free: whether it does is a
 * coin toss for most slopes, which a branch would mispredict. */
static inline void rast__fe_step(rast__fe *f)
{
    int64_t g = f->g - f->r0;
    int64_t carry = g < 0;
    f->c += f->s0 + carry;
    f->g = g + (f->da & -carry);
}

/* Bound f for edge k -> k+1 of x[], y[] (internal units) on the first
 * row, whose sample is at ordinate py, from the sample at abscissa px
 * (column c0): with E its edge function, G = sign(dy)*E - t, t = 1 for
 * textbook rounding, else 0 (see the loop in rast__tri_edge_fill), which
 * grows by |dy|*u per column and whose turning column moves dx/dy columns
 * per row.  A horizontal edge becomes a left bound that never binds (the
 * rows already say it; the other two edges are one left, one right).
 * |px - x| and |py - y| < 2^29 + 2 unit, so each product is below 2^59. */
RAST__HOT void rast__fe_start(rast__fe *f, const int64_t *x, const int64_t *y, int32_t k,
                                  int64_t c0, int64_t px, int64_t py, const rast__grid *g)
{
    int32_t n = k == 2 ? 0 : k + 1;
    int64_t dx = x[n] - x[k], dy = y[n] - y[k], e, q, r;
    if (dy == 0) {
        f->c = -((int64_t)1 << 62);
        f->g = f->r0 = f->s0 = 0;
        f->da = 1;
        return;
    }
    e = (px - x[k]) * dy - (py - y[k]) * dx;
    if (dy < 0) {
        e = -e;
        dx = -dx;
        dy = -dy;
    }
    f->da = dy * g->unit;
    rast__floordivmod(dx, dy, &f->s0, &r);
    f->r0 = r * g->unit;
    rast__floordivmod(e - (g->textbook != 0), f->da, &q, &r); /* G0 = q*da + r */
    f->c = c0 - q;
    f->g = r;
}

/* The rows [row0, row1) of a triangle with left bound a, right bound c
 * and a third bound b (on the left if pair_left).  `direct` (a constant,
 * so this is two loops): the sink writes inline and every run lies inside
 * the clip, so each row is one memset down a row pointer, with no clip
 * test.  The bounds are the caller's locals, whose addresses go to
 * inline functions only: they stay in registers. */
RAST__HOT void rast__fe_rows(const rast__rows *o, int32_t row0, int32_t row1, rast__fe *a,
                                 rast__fe *b, rast__fe *c, int32_t pair_left, int direct)
{
    unsigned char *p = rast__rows_at(o, row0, direct);
    int32_t j;
    for (j = row0; j < row1; j++) {
        int64_t x0 = a->c, x1 = c->c;
        int64_t bl = pair_left ? b->c : x0, br = pair_left ? x1 : b->c;
        x0 = x0 > bl ? x0 : bl;
        x1 = x1 < br ? x1 : br;
        rast__rows_emit(o, &p, j, (int32_t)x0, (int32_t)x1, direct);
        rast__fe_step(a);
        rast__fe_step(b);
        rast__fe_step(c);
    }
}

#if !defined(__OPTIMIZE_SIZE__)
/* Rows a batch of rast__fe_half takes (its runs' ends on the stack, 512
 * bytes). */
#define RAST__FE_BATCH 64

/* Rows [0, n) from row pointer p between left bound l and right bound r,
 * each row one memset, uncut (rast__rows_direct_uncut held).  The bounds
 * are walked a batch of rows at a time in a loop of their own, the runs'
 * ends stored, and the runs then written in another loop: a memset call
 * in the walk's loop (as in rast__fe_rows) clobbers the caller-saved
 * registers, so that the bounds went to the stack and back every row.
 * The bounds are read from *l and *r before a batch and written back
 * after it (where a memset may write, as far as the compiler knows: so
 * it does not keep them in registers across the memsets, saving and
 * restoring them around every call).
 * With SSE2 the two bounds step side by side, one in each 64-bit lane of
 * a vector: the same additions, the carry a lane's sign spread over it.
 *
 * No run is empty, so none needs the clamp of rast__rows_emit: on a row
 * of the half both bounds are of edges whose crossings X_l <= X_r bound
 * the triangle's row, and both bounds are the same monotone function of
 * the crossing (the first column whose sample is at or right of X, exact
 * rounding; strictly right of X moved half a pixel, textbook), so that
 * l <= r. */
RAST__APART void rast__fe_half(unsigned char *p, ptrdiff_t stride, int value, int32_t n,
                               rast__fe *l, rast__fe *r)
{
    int32_t xs[2 * RAST__FE_BATCH], k, m;
#if RAST__FE_SSE2
    const __m128i da = _mm_set_epi64x(r->da, l->da), r0 = _mm_set_epi64x(r->r0, l->r0);
    const __m128i s0 = _mm_set_epi64x(r->s0, l->s0);
#endif
    for (; n > 0; n -= m) {
        m = n < RAST__FE_BATCH ? n : RAST__FE_BATCH;
        {
#if RAST__FE_SSE2
            __m128i c = _mm_set_epi64x(r->c, l->c), g = _mm_set_epi64x(r->g, l->g);
            int64_t out[4]; /* the columns, then the edge functions, l's then r's */
            for (k = 0; k < m; k++) {
                __m128i carry;
                /* the low halves of both columns (within the clip's, so
                 * int32_t), x0 then x1 */
                _mm_storel_epi64((__m128i *)(void *)(xs + 2 * k), _mm_shuffle_epi32(c, 0x08));
                g = _mm_sub_epi64(g, r0);
                carry = _mm_shuffle_epi32(_mm_srai_epi32(g, 31), 0xF5); /* -1 where g < 0 */
                c = _mm_sub_epi64(_mm_add_epi64(c, s0), carry);
                g = _mm_add_epi64(g, _mm_and_si128(da, carry));
            }
            _mm_storeu_si128((__m128i *)(void *)out, c);
            _mm_storeu_si128((__m128i *)(void *)(out + 2), g);
            l->c = out[0];
            r->c = out[1];
            l->g = out[2];
            r->g = out[3];
#else
            rast__fe a = *l, c = *r;
            for (k = 0; k < m; k++) {
                xs[2 * k] = (int32_t)a.c;
                xs[2 * k + 1] = (int32_t)c.c;
                rast__fe_step(&a);
                rast__fe_step(&c);
            }
            *l = a;
            *r = c;
#endif
        }
        for (k = 0; k < m; k++) {
            memset(p + xs[2 * k], value, (size_t)(xs[2 * k + 1] - xs[2 * k]));
            p += stride;
        }
    }
}
#endif

rast_status rast__tri_edge_fill(const rast_point *t, const rast__grid *g,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    int64_t x[3], y[3], area, xmin, xmax, ymin, ymax, shift, r;
    int64_t u = g->unit, px, py;
    rast__fe a, b, c;
    rast__rows o;
    int32_t row0, row1, lo, hi, k, left[3], lone, other, pair_left;
    (void)arena;

    for (k = 0; k < 3; k++) {
        x[k] = 2 * (int64_t)t[k].x; /* internal units, |x| < 2^28 */
        y[k] = 2 * (int64_t)t[k].y;
    }
    /* Orientation: E of t0->t1 at t2; differences < 2^29, products < 2^58.
     * Inside is E > 0 on every edge when area > 0; when area < 0 it is
     * E < 0, which is E > 0 for the edges walked the other way round. */
    area = (x[2] - x[0]) * (y[1] - y[0]) - (y[2] - y[0]) * (x[1] - x[0]);
    if (area == 0) return RAST_OK; /* degenerate: no sample inside */

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
    r = rast__ceil_unit(xmin - shift, g);
    lo = r > clip->x0 ? (int32_t)r : clip->x0;
    r = rast__floor_unit(xmax - shift, g) + 1;
    hi = r < clip->x1 ? (int32_t)r : clip->x1;
    if (lo >= hi) return RAST_OK;

    /* Each edge at (lo, row0), as a left bound (the first column inside
     * it) or a right one (the first column outside it); a triangle has one
     * or two of each.  Walked the way that puts the inside at E > 0 (edge
     * a->b as it is when area > 0, as b->a otherwise, which negates E, dx
     * and dy), an edge going down (dy > 0) is a left edge, and inside is
     * E > 0, or E == 0 on an edge that owns its samples: exact, left
     * edges; textbook, right edges.  So the test is G = E - t >= 0 on a
     * left edge ("inside") and G = -E - t >= 0 on a right one
     * ("outside"), t = 1 for textbook rounding, else 0: in both
     * orientations G = sign(dy)*E - t of the edge as given.  Two bounds
     * on one side, one on the other: a is a left bound, c a right one, b
     * the third (left if pair_left); chosen before they are set up, by
     * index, not by branch (which edge is which is a coin toss). */
    for (k = 0; k < 3; k++) {
        int64_t dy = y[k == 2 ? 0 : k + 1] - y[k];
        left[k] = dy == 0 || (dy > 0) == (area > 0);
    }
    lone = left[0] == left[1] ? 2 : (left[0] == left[2] ? 1 : 0);
    pair_left = !left[lone];
    other = lone == 2 ? 1 : 2;
    px = (int64_t)lo * u + shift;
    py = (int64_t)row0 * u + g->off;

    /* Each row, the last of the left bounds to the first of the right
     * ones.  On the rows of the triangle these are its own crossings, so
     * within the columns of [xmin, xmax] (and int32_t) even where a bound
     * followed past its edge's end is far outside; the sink cuts them to
     * the clip, unless those columns are inside it. */
    o = rast__rows_of(sink);
#if !defined(__OPTIMIZE_SIZE__)
    if (rast__rows_direct_uncut(&o, xmin, xmax, g)) {
        /* The pair's two edges meet at vertex m, the middle one in y (the
         * lone edge, never horizontal, runs from the top vertex to the
         * bottom one).  Above m's ordinate the pair's edge from the top
         * vertex bounds the rows, from it down the other one: the third
         * bound never binds there (the triangle is the intersection of
         * the half-planes, and at m's ordinate both pair edges cross at
         * m, with the same test).  So each half walks two bounds, the
         * other edge of the pair set up at the first row at or below m. */
        int32_t m = lone == 0 ? 2 : lone - 1, pm = m == 0 ? 2 : m - 1, nm = m == 2 ? 0 : m + 1;
        int32_t top = y[pm] < y[nm] ? pm : m; /* edge pm runs pm -> m, edge m m -> nm */
        int32_t rowm;
        unsigned char *p = rast__rows_at(&o, row0, 1);
        r = rast__row_at_or_after(y[m], g);
        rowm = r < row0 ? row0 : (r > row1 ? row1 : (int32_t)r);
        rast__fe_start(&b, x, y, lone, lo, px, py, g);
        if (rowm > row0) {
            rast__fe_start(&a, x, y, top, lo, px, py, g);
            if (pair_left)
                rast__fe_half(p, o.stride, o.value, rowm - row0, &a, &b);
            else
                rast__fe_half(p, o.stride, o.value, rowm - row0, &b, &a);
        }
        if (row1 > rowm) {
            rast__fe_start(&a, x, y, top == m ? pm : m, lo, px, (int64_t)rowm * u + g->off, g);
            p = rast__rows_at(&o, rowm, 1);
            if (pair_left)
                rast__fe_half(p, o.stride, o.value, row1 - rowm, &a, &b);
            else
                rast__fe_half(p, o.stride, o.value, row1 - rowm, &b, &a);
        }
        return RAST_OK;
    }
#endif
    rast__fe_start(&a, x, y, pair_left ? other : lone, lo, px, py, g);
    rast__fe_start(&b, x, y, lone == 0 ? 1 : 0, lo, px, py, g);
    rast__fe_start(&c, x, y, pair_left ? lone : other, lo, px, py, g);
    if (rast__rows_direct_uncut(&o, xmin, xmax, g))
        rast__fe_rows(&o, row0, row1, &a, &b, &c, pair_left, 1);
    else
        rast__fe_rows(&o, row0, row1, &a, &b, &c, pair_left, 0);
    return RAST_OK;
}

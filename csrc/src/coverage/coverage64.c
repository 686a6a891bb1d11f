/*
 * coverage64.c - exact-area coverage on 64-bit vertices
 * (rast_polygon_coverage64): the coverage twin of rast_fill_polygon64, for
 * S up to 32 and coordinates up to 2^28 pixels (docs/coverage.md, "64-bit
 * vertices").  Only callers of rast_polygon_coverage64 link it.
 *
 * Units.  Vertices are in units of 2^-S pixel, |v| <= 2^(S+28) - 1, so an
 * edge's |dx|, |dy| < 2^(S+29) <= 2^61.  Inside pixel row j (the strip
 * j <= y < j + 1, whose top is Yj = j 2^S in vertex units) an ordinate is
 * t, in units U = 2^-62 pixel from the row's top (0 <= t <= T = 2^62); an
 * abscissa X is in units V = 2^-62 pixel from x = 0, a signed 128-bit
 * integer (|X| < 2^91).  H = 62 - S turns vertex units into U and V.
 *
 * The sweep.  Each row is cut at its vertices' ordinates.  Between two of
 * them the edges spanning the piece are sorted by their abscissae at the
 * piece's top (then at its bottom); two neighbours whose order is reversed
 * at the bottom cross inside, and the first such crossing (of all adjacent
 * pairs) ends the sub-piece: there no two edges cross, and the winding
 * number is constant between neighbours.  An edge whose left and right
 * sides differ under the rule bounds the inside; with
 * sigma = in(right) - in(left), a cell's area is
 *     sum over pieces of sigma * integral of (c + 1 - clamp(x(y), c, c + 1)) dy
 * (an inside interval [L, R] gives clamp(R) - clamp(L)): a piece in
 * column c adds sigma dt (1 - (fa + fb)/2) to the cell, and sigma dt to
 * every cell right of it (a difference array: cover).  The products
 * dt (2^63 - fa - fb) are exact in 128 bits (units 2^-125 pixel^2); the
 * sums wrap modulo 2^128, harmlessly, since each cell's total is its area.
 *
 * Rounding.  Every abscissa at a piece's ends is the exact floor on the V
 * grid, every ordinate where an edge meets a vertical the exact floor on
 * the U grid (clamped into its piece); the ordinate of a crossing is within
 * a few U of the true one (from the abscissae, scaled to 61 bits).  Each
 * piece's share of a cell is therefore off by at most a few 2^-62 pixel^2,
 * and a crossing misplaced by d pixels moves at most d times the two edges'
 * distance d |s1 - s2| (s = dx/dy, |s| < 2^61): the bound
 * |a' - a| <= (n + m + 1) 2^-50 stated in rastrum.h is loose by orders of
 * magnitude (tests/test_coverage64.py checks it against exact rationals).
 *
 * Cost.  Per row: the edges spanning it, a sort of them at each vertex or
 * crossing inside the row (insertion sort: they arrive nearly in order),
 * one 128-by-64-bit division per edge end and per column an edge crosses,
 * and per row its dirty cells (those an edge touched) and the runs of equal
 * cells between them (rast__w64_emit).  Memory: rast_coverage64_scratch_size.
 */
#include "../base/internal.h"
#include "../base/wide.h"
#include "../base/bits.h" /* rast__ctz64 */

#define RAST__W64_G 62
#define RAST__W64_T ((uint64_t)1 << RAST__W64_G)

/* ---- 128-bit helpers (wide.h's two's-complement rast__i128) ------------- */

/* The exact product a b of two unsigned 64-bit numbers (< 2^127 here). */
static inline rast__i128 rast__w64_umul(uint64_t a, uint64_t b)
{
    rast__i128 r;
    r.hi = rast__mulhi(a, b);
    r.lo = a * b;
    return r;
}

/* floor(n / d) for 0 < d < 2^62, any n with |n| < 2^126; *rem = the
 * remainder in [0, d).  The quotient may need more than 64 bits. */
static rast__i128 rast__w64_div(rast__i128 n, int64_t d, uint64_t *rem)
{
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
    __extension__ typedef __int128 rast__s128;
    __extension__ typedef unsigned __int128 rast__u128;
    rast__s128 v = (rast__s128)(((rast__u128)n.hi << 64) | n.lo), q = v / d, r = v % d;
    rast__i128 out;
    if (r < 0) {
        q -= 1;
        r += d;
    }
    *rem = (uint64_t)r;
    out.lo = (uint64_t)q;
    out.hi = (uint64_t)((rast__u128)q >> 64);
    return out;
#else
    int neg = rast__i128_neg_p(n), i;
    uint64_t ud = (uint64_t)d, r, qlo = 0, lo;
    rast__i128 q;
    if (neg) n = rast__i128_neg(n);
    q.hi = n.hi / ud;
    r = n.hi % ud;
    lo = n.lo;
    for (i = 0; i < 64; i++) { /* r < d < 2^62: r << 1 stays in range */
        r = (r << 1) | (lo >> 63);
        lo <<= 1;
        qlo <<= 1;
        if (r >= ud) {
            r -= ud;
            qlo |= 1u;
        }
    }
    q.lo = qlo;
    if (neg) {
        q = rast__i128_neg(q);
        if (r) {
            q = rast__i128_sub(q, rast__i128_from(1));
            r = ud - r;
        }
    }
    *rem = r;
    return q;
#endif
}

/* ---- edges ------------------------------------------------------------- */

/* An edge from its top (xt, yt) to its bottom (xb, yb) (vertex units),
 * dir +1 going down, -1 going up; for the current row, its abscissa
 *     X(t) = bx + floor((br + (t - bt) dx) / dy)        (V)
 * and its extent [tt, tb] in the row (U). */
typedef struct rast__w64e {
    int64_t xt, yt, xb, yb, dx, dy;
    rast__i128 bx, br;
    uint64_t bt, tt, tb;
    int32_t dir, pad;
} rast__w64e;

/* The row's abscissa of e at t (exact floor, V). */
static inline rast__i128 rast__w64_x(const rast__w64e *e, uint64_t t)
{
    uint64_t rem;
    rast__i128 n = rast__i128_add(e->br, rast__i128_mul((int64_t)(t - e->bt), e->dx));
    return rast__i128_add(e->bx, rast__w64_div(n, e->dy, &rem));
}

/* Vertex ordinate y as t in the row whose top is yj, clamped to [0, T]. */
static inline uint64_t rast__w64_t(int64_t y, int64_t yj, int32_t s, int32_t h)
{
    if (y <= yj) return 0;
    if (y - yj >= ((int64_t)1 << s)) return RAST__W64_T;
    return (uint64_t)(y - yj) << h;
}

/* Set up e for the row whose top is yj. */
static void rast__w64_row(rast__w64e *e, int64_t yj, int32_t s, int32_t h)
{
    e->tt = rast__w64_t(e->yt, yj, s, h);
    e->tb = rast__w64_t(e->yb, yj, s, h);
    if (e->yt >= yj) { /* starts inside the row (or at its top) */
        e->bt = e->tt;
        e->bx = rast__i128_shl(rast__i128_from(e->xt), h);
        e->br = rast__i128_from(0);
    } else { /* (yj - yt) dx / dy = q + r / dy, 0 <= yj - yt < dy */
        uint64_t r;
        rast__i128 q = rast__w64_div(rast__i128_mul(yj - e->yt, e->dx), e->dy, &r);
        e->bt = 0;
        e->bx = rast__i128_shl(rast__i128_from(e->xt + (int64_t)q.lo), h);
        e->br = rast__i128_shl(rast__i128_from((int64_t)r), h);
    }
}

/* The ordinate (U, floor) where e meets the vertical x = c pixels, which
 * lies within e's x extent; clamped to [lo, hi]. */
static uint64_t rast__w64_tcol(const rast__w64e *e, int64_t c, int64_t yj, int32_t s, int32_t h,
                               uint64_t lo, uint64_t hi)
{
    int64_t b = c * ((int64_t)1 << s) - e->xt, adx = e->dx < 0 ? -e->dx : e->dx;
    uint64_t r, r2;
    rast__i128 q, f, t;
    /* y - yt = b dy / dx = q + r / |dx| (vertex units) */
    q = rast__w64_div(rast__i128_mul(e->dx < 0 ? -b : b, e->dy), adx, &r);
    f = rast__w64_div(rast__i128_shl(rast__i128_from((int64_t)r), h), adx, &r2);
    t = rast__i128_add(rast__i128_shl(rast__i128_from(e->yt - yj + (int64_t)q.lo), h), f);
    if (rast__i128_neg_p(t) || rast__i128_cmp(t, rast__i128_from((int64_t)lo)) < 0) return lo;
    if (rast__i128_cmp(t, rast__i128_from((int64_t)hi)) > 0) return hi;
    return t.lo;
}

/* ---- the row's cells --------------------------------------------------- */

typedef struct rast__w64cells {
    rast__i128 *area;  /* [w]: sigma dt (2^63 - fa - fb), 2^-125 pixel^2 */
    rast__i128 *cover; /* [w + 1]: sigma dt 2^63 for the cells right of it */
    uint64_t *dirty;   /* [w / 64 + 1]: bit k when area[k] or cover[k] was written */
    int64_t x0, x1;    /* the clip's columns */
    int64_t yj;
    int32_t s, h;
} rast__w64cells;

static inline void rast__w64_mark(rast__w64cells *c, size_t k)
{
    c->dirty[k >> 6] |= (uint64_t)1 << (k & 63);
}

static inline rast__i128 rast__w64_signed(rast__i128 v, int32_t sigma)
{
    return sigma > 0 ? v : rast__i128_neg(v);
}

/* Everything left of the clip: a whole height dt for every clip cell. */
static inline void rast__w64_left(rast__w64cells *c, uint64_t dt, int32_t sigma)
{
    rast__i128 v;
    v.hi = dt >> 1;
    v.lo = dt << 63;
    c->cover[0] = rast__i128_add(c->cover[0], rast__w64_signed(v, sigma));
    rast__w64_mark(c, 0);
}

/* Column col (inside the clip): from fraction f0 to f1 (V, 0..2^62) over
 * a height dt (U). */
static inline void rast__w64_cell(rast__w64cells *c, int64_t col, uint64_t f0, uint64_t f1,
                                  uint64_t dt, int32_t sigma)
{
    size_t k = (size_t)(col - c->x0);
    rast__i128 v;
    if (!dt) return;
    v = rast__w64_umul(dt, ((uint64_t)1 << 63) - f0 - f1);
    c->area[k] = rast__i128_add(c->area[k], rast__w64_signed(v, sigma));
    v.hi = dt >> 1;
    v.lo = dt << 63;
    c->cover[k + 1] = rast__i128_add(c->cover[k + 1], rast__w64_signed(v, sigma));
    rast__w64_mark(c, k);
    rast__w64_mark(c, k + 1);
}

/* The piece of e from (xa, ta) to (xb, tb) (V, U; ta <= tb), sign sigma. */
static void rast__w64_piece(rast__w64cells *c, const rast__w64e *e, rast__i128 xa, uint64_t ta,
                            rast__i128 xb, uint64_t tb, int32_t sigma)
{
    const uint64_t one = RAST__W64_T, mask = one - 1;
    int64_t ca = (int64_t)rast__i128_sar(xa, RAST__W64_G).lo;
    int64_t cb = (int64_t)rast__i128_sar(xb, RAST__W64_G).lo;
    uint64_t fa = xa.lo & mask, fb = xb.lo & mask, t = ta, f;
    int64_t col;
    if (ta >= tb) return;
    if (ca == cb) {
        if (ca < c->x0) rast__w64_left(c, tb - ta, sigma);
        else if (ca < c->x1) rast__w64_cell(c, ca, fa, fb, tb - ta, sigma);
        return;
    }
    if (ca < cb) { /* rightwards: leave each column at f = 1, enter at 0 */
        if (cb < c->x0) {
            rast__w64_left(c, tb - ta, sigma);
            return;
        }
        if (ca >= c->x1) return;
        col = ca;
        f = fa;
        if (ca < c->x0) {
            t = rast__w64_tcol(e, c->x0, c->yj, c->s, c->h, ta, tb);
            rast__w64_left(c, t - ta, sigma);
            col = c->x0;
            f = 0;
        }
        for (; col < cb; col++) {
            uint64_t tn;
            if (col >= c->x1) return;
            tn = rast__w64_tcol(e, col + 1, c->yj, c->s, c->h, t, tb);
            rast__w64_cell(c, col, f, one, tn - t, sigma);
            t = tn;
            f = 0;
        }
        if (cb < c->x1) rast__w64_cell(c, cb, 0, fb, tb - t, sigma);
        return;
    }
    /* leftwards: leave each column at f = 0, enter the next at 1 */
    if (ca < c->x0) {
        rast__w64_left(c, tb - ta, sigma);
        return;
    }
    if (cb >= c->x1) return;
    col = ca;
    f = fa;
    if (ca >= c->x1) {
        t = rast__w64_tcol(e, c->x1, c->yj, c->s, c->h, ta, tb);
        col = c->x1 - 1;
        f = one;
    }
    for (; col > cb; col--) {
        uint64_t tn = rast__w64_tcol(e, col, c->yj, c->s, c->h, t, tb);
        rast__w64_cell(c, col, f, 0, tn - t, sigma);
        t = tn;
        f = one;
        if (col - 1 < c->x0) {
            rast__w64_left(c, tb - t, sigma);
            return;
        }
    }
    rast__w64_cell(c, cb, one, fb, tb - t, sigma);
}

/* A cell's value in format: v = its area in 2^-125 pixel^2, rounded to
 * 2^-62 (round(v / 2^63), clamped to [0, 2^62]), then to a level. */
static uint64_t rast__w64_value(rast__i128 v, rast_coverage_format format)
{
    uint64_t a62;
    v = rast__i128_sar(rast__i128_add(v, rast__i128_from((int64_t)1 << 62)), 63);
    if (rast__i128_neg_p(v)) a62 = 0;
    else if (v.hi || v.lo > RAST__W64_T) a62 = RAST__W64_T;
    else a62 = v.lo;
    if (format != RAST_COVERAGE_FIX62) { /* floor((a62 M + 2^61) / 2^62) */
        rast__i128 p = rast__w64_umul(a62, format == RAST_COVERAGE_U8 ? 255u : 65535u);
        p = rast__i128_add(p, rast__i128_from((int64_t)1 << 61));
        a62 = (p.hi << 2) | (p.lo >> 62);
    }
    return a62;
}

/* row[k0..k1) = value (a run of equal cells). */
static void rast__w64_fill(unsigned char *row, rast_coverage_format format, int64_t k0, int64_t k1,
                           uint64_t value)
{
    int64_t k;
    if (k0 >= k1) return;
    if (format == RAST_COVERAGE_U8) {
        memset(row + k0, (int)value, (size_t)(k1 - k0));
    } else if (format == RAST_COVERAGE_U16) {
        uint16_t *p = (uint16_t *)(void *)row;
        if (!value) memset(p + k0, 0, (size_t)(k1 - k0) * 2);
        else
            for (k = k0; k < k1; k++) p[k] = (uint16_t)value;
    } else {
        uint64_t *p = (uint64_t *)(void *)row;
        if (!value) memset(p + k0, 0, (size_t)(k1 - k0) * 8);
        else
            for (k = k0; k < k1; k++) p[k] = value;
    }
}

static void rast__w64_put(unsigned char *row, rast_coverage_format format, int64_t k, uint64_t value)
{
    if (format == RAST_COVERAGE_U8) row[k] = (unsigned char)value;
    else if (format == RAST_COVERAGE_U16) ((uint16_t *)(void *)row)[k] = (uint16_t)value;
    else ((uint64_t *)(void *)row)[k] = value;
}

/* Row y's values into out's row, the cells then cleared.  Only the dirty
 * cells (a piece of an edge wrote their area, or their cover) are
 * computed: between two of them the running cover is constant and the
 * area zero, so the cells hold one value, written as a run.  The cost is
 * per crossed cell and per run, not per cell (plus the fill itself, and
 * one word of the dirty bits per 64 columns). */
static void rast__w64_emit(rast__w64cells *c, rast_coverage_format format, unsigned char *row)
{
    const int64_t w = c->x1 - c->x0;
    const size_t nwords = (size_t)(w >> 6) + 1;
    rast__i128 acc = rast__i128_from(0);
    uint64_t run = 0; /* the value of acc alone (0 before any cover) */
    int64_t k = 0;    /* row[0..k) written */
    size_t i;
    for (i = 0; i < nwords; i++) {
        uint64_t bits = c->dirty[i];
        c->dirty[i] = 0;
        while (bits) {
            int64_t d = (int64_t)(i << 6) + (int64_t)rast__ctz64(bits);
            bits &= bits - 1;
            /* cells k..d-1 are clean: the run; d is dirty (d <= w) */
            rast__w64_fill(row, format, k, d, run);
            acc = rast__i128_add(acc, c->cover[d]);
            c->cover[d] = rast__i128_from(0);
            if (d == w) { /* the cover past the last cell: no cell */
                k = w;
                break;
            }
            rast__w64_put(row, format, d, rast__w64_value(rast__i128_add(acc, c->area[d]), format));
            c->area[d] = rast__i128_from(0);
            run = rast__w64_value(acc, format);
            k = d + 1;
        }
    }
    rast__w64_fill(row, format, k, w, run);
}

/* ---- the sweep ---------------------------------------------------------- */

static inline int rast__w64_in(rast_fill_rule rule, int32_t w)
{
    return rule == RAST_RULE_EVENODD ? (w & 1) : w != 0;
}

/* The first ordinate after cur (U; up to end) where a, left of b at cur
 * (abscissae a0 <= b0) and right of it at end (a1 > b1), crosses it: from
 * the abscissae, their differences scaled to 61 bits (rounded up, and
 * always after cur). */
static uint64_t rast__w64_cross(rast__i128 a0, rast__i128 a1, rast__i128 b0, rast__i128 b1,
                                uint64_t cur, uint64_t end)
{
    rast__i128 d0 = rast__i128_sub(b0, a0), d1 = rast__i128_sub(a1, b1), sum;
    uint64_t n0, n1, den, h = end - cur, r;
    rast__i128 q;
    if (rast__i128_neg_p(d0)) d0 = rast__i128_from(0);
    sum = rast__i128_add(d0, d1);
    /* scale both so that the sum is below 2^61 */
    while (sum.hi || sum.lo >= ((uint64_t)1 << 61)) {
        d0 = rast__i128_sar(d0, 8);
        d1 = rast__i128_sar(d1, 8);
        sum = rast__i128_sar(sum, 8);
    }
    n0 = d0.lo;
    n1 = d1.lo;
    den = n0 + n1;
    if (!den) return cur + 1 < end ? cur + 1 : end;
    q = rast__w64_div(rast__w64_umul(n0, h), (int64_t)den, &r);
    if (r) q = rast__i128_add(q, rast__i128_from(1));
    if (q.hi || q.lo >= h) return end;
    return q.lo ? cur + q.lo : cur + 1;
}

/* Sort ix[0..n) by (k0, k1) of the edges: insertion sort (the order of
 * the last piece is nearly right). */
static void rast__w64_sort(int32_t *ix, int32_t n, const rast__i128 *k0, const rast__i128 *k1)
{
    int32_t i, j;
    for (i = 1; i < n; i++) {
        int32_t v = ix[i];
        for (j = i; j > 0; j--) {
            int32_t u = ix[j - 1];
            int c = rast__i128_cmp(k0[u], k0[v]);
            if (c < 0 || (c == 0 && rast__i128_cmp(k1[u], k1[v]) <= 0)) break;
            ix[j] = u;
        }
        ix[j] = v;
    }
}

/* Sort ts[0..n) ascending (shell sort, gaps 3k + 1), return the count
 * of distinct values left at the front. */
static int32_t rast__w64_sort_ts(uint64_t *ts, int32_t n)
{
    int32_t gap = 1, i, j, m;
    while (gap < n / 3) gap = 3 * gap + 1;
    for (; gap > 0; gap /= 3)
        for (i = gap; i < n; i++) {
            uint64_t v = ts[i];
            for (j = i; j >= gap && ts[j - gap] > v; j -= gap) ts[j] = ts[j - gap];
            ts[j] = v;
        }
    for (i = 1, m = n ? 1 : 0; i < n; i++)
        if (ts[i] != ts[m - 1]) ts[m++] = ts[i];
    return m;
}

/* Heapsort of the edge indices ix[0..n) by the edges' top ordinate. */
static void rast__w64_sort_tops(int32_t *ix, int32_t n, const rast__w64e *e)
{
    int32_t start, end, root, child;
    for (start = n / 2 - 1, end = n; end > 1 || start >= 0;) {
        int32_t v;
        if (start >= 0) {
            root = start--;
        } else {
            end--;
            v = ix[end];
            ix[end] = ix[0];
            ix[0] = v;
            root = 0;
        }
        v = ix[root];
        for (;;) {
            child = 2 * root + 1;
            if (child >= end) break;
            if (child + 1 < end && e[ix[child + 1]].yt > e[ix[child]].yt) child++;
            if (e[ix[child]].yt <= e[v].yt) break;
            ix[root] = ix[child];
            root = child;
        }
        ix[root] = v;
    }
}

typedef struct rast__w64work {
    rast__w64e *e;
    int32_t *order, *active, *span;
    rast__i128 *k0, *k1, *kn;
    uint64_t *ts;
} rast__w64work;

/* The pieces of row j (top yj) from the active edges act[0..na). */
static void rast__w64_sweep_row(rast__w64work *wk, rast__w64cells *c, int32_t na,
                                rast_fill_rule rule)
{
    rast__w64e *e = wk->e;
    int32_t nt = 0, i, k, nv;
    for (i = 0; i < na; i++) {
        rast__w64e *ed = &e[wk->active[i]];
        rast__w64_row(ed, c->yj, c->s, c->h);
        wk->ts[nt++] = ed->tt;
        wk->ts[nt++] = ed->tb;
    }
    wk->ts[nt++] = 0;
    wk->ts[nt++] = RAST__W64_T;
    nv = rast__w64_sort_ts(wk->ts, nt);
    for (k = 0; k + 1 < nv; k++) {
        const uint64_t v0 = wk->ts[k], v1 = wk->ts[k + 1];
        uint64_t cur = v0;
        int32_t ns = 0;
        for (i = 0; i < na; i++) {
            int32_t ix = wk->active[i];
            if (e[ix].tt <= v0 && e[ix].tb >= v1) {
                wk->span[ns++] = ix;
                wk->k0[ix] = rast__w64_x(&e[ix], v0);
                wk->k1[ix] = rast__w64_x(&e[ix], v1);
            }
        }
        if (ns < 2) continue; /* (a lone edge: its two sides are one inside) */
        for (;;) {
            uint64_t tn = v1;
            int32_t wnd = 0;
            const rast__i128 *kn = wk->k1;
            rast__w64_sort(wk->span, ns, wk->k0, wk->k1);
            for (i = 0; i + 1 < ns; i++) {
                int32_t a = wk->span[i], b = wk->span[i + 1];
                if (rast__i128_cmp(wk->k1[a], wk->k1[b]) > 0) {
                    uint64_t tc = rast__w64_cross(wk->k0[a], wk->k1[a], wk->k0[b], wk->k1[b],
                                                  cur, v1);
                    if (tc < tn) tn = tc;
                }
            }
            if (tn < v1) {
                for (i = 0; i < ns; i++) {
                    int32_t ix = wk->span[i];
                    wk->kn[ix] = rast__w64_x(&e[ix], tn);
                }
                kn = wk->kn;
            }
            for (i = 0; i < ns; i++) {
                int32_t ix = wk->span[i], before = wnd, sigma;
                wnd += e[ix].dir;
                sigma = rast__w64_in(rule, wnd) - rast__w64_in(rule, before);
                if (sigma) rast__w64_piece(c, &e[ix], wk->k0[ix], cur, kn[ix], tn, sigma);
            }
            if (tn >= v1) break;
            for (i = 0; i < ns; i++) {
                int32_t ix = wk->span[i];
                wk->k0[ix] = wk->kn[ix];
            }
            cur = tn;
        }
    }
}

/* ---- entry ---------------------------------------------------------------- */

/* Per vertex: the edge, three indices, three abscissae, two ordinates;
 * per clip column: two cells (plus one), 16 bytes each, and a dirty bit. */
static size_t rast__w64_need(uint32_t npoints, int32_t width)
{
    size_t n = (size_t)npoints, need = 0;
    need = rast__size_add(need, rast__align(rast__size_mul(n, sizeof(rast__w64e))));
    need = rast__size_add(need, 3 * rast__align(rast__size_mul(n, sizeof(int32_t))));
    need = rast__size_add(need, 3 * rast__align(rast__size_mul(n, sizeof(rast__i128))));
    need = rast__size_add(need, rast__align(rast__size_mul(2 * n + 2, sizeof(uint64_t))));
    need = rast__size_add(need,
                          rast__align(rast__size_mul(2 * (size_t)width + 1, sizeof(rast__i128))));
    need = rast__size_add(need, rast__align(rast__size_mul((size_t)(width >> 6) + 1, sizeof(uint64_t))));
    return need;
}

rast_status rast_coverage64_scratch_size(const rast_coverage_opts *opts, uint32_t npoints,
                                         int32_t width, int32_t height, size_t *bytes)
{
    if (!opts || !bytes) return RAST_E_NULL;
    if (opts->method != RAST_AA_AREA) return RAST_E_WIDE;
    if ((unsigned)opts->rule > RAST_RULE_NONZERO) return RAST_E_ARG;
    if (opts->subpixel_bits < 0 || opts->subpixel_bits > RAST_MAX_SUBPIXEL_BITS64)
        return RAST_E_SUBPIXEL;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__w64_need(npoints, width);
    return RAST_OK;
}

rast_status rast_polygon_coverage64(const rast_polygon64 *polygon, const rast_coverage_opts *opts,
                                    const rast_rect *clip, rast_coverage_format format, void *out,
                                    ptrdiff_t stride, void *scratch, size_t scratch_bytes)
{
    static const int32_t size[3] = {1, 2, 8};
    rast__w64work wk;
    rast__w64cells cells;
    rast__arena ar;
    int64_t lim, miny = 0, maxy = 0, rlo, rhi;
    uint64_t n64 = 0;
    uint32_t npoints, k, i, base;
    int32_t s, h, w, ne = 0, na = 0, next = 0, y;
    rast_status st;

    if (!polygon || !opts || !clip) return RAST_E_NULL;
    {
        size_t dummy;
        st = rast_coverage64_scratch_size(opts, 0, 0, 0, &dummy); /* the options */
        if (st != RAST_OK) return st;
    }
    if ((unsigned)format > RAST_COVERAGE_FIX62) return RAST_E_ARG;
    if (polygon->nrings > 0 && !polygon->ring_sizes) return RAST_E_NULL;
    for (n64 = 0, k = 0; k < polygon->nrings; k++) {
        n64 += polygon->ring_sizes[k];
        if (n64 > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    npoints = (uint32_t)n64;
    if (npoints > 0 && !polygon->points) return RAST_E_NULL;
    s = opts->subpixel_bits;
    lim = RAST_COORD64_MAX(s);
    for (i = 0; i < npoints; i++) {
        int64_t px = polygon->points[i].x, py = polygon->points[i].y;
        if (px < -lim || px > lim || py < -lim || py > lim) return RAST_E_RANGE;
        if (i == 0 || py < miny) miny = py;
        if (i == 0 || py > maxy) maxy = py;
    }
    if (clip->x0 < -RAST_MAX_DIM || clip->x1 > RAST_MAX_DIM || clip->y0 < -RAST_MAX_DIM ||
        clip->y1 > RAST_MAX_DIM || clip->x1 < -RAST_MAX_DIM || clip->x0 > RAST_MAX_DIM ||
        clip->y1 < -RAST_MAX_DIM || clip->y0 > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK; /* nothing to write */
    w = clip->x1 - clip->x0;
    if (!out) return RAST_E_NULL;
    if (stride % size[format] || (uintptr_t)out % (uintptr_t)size[format] ||
        stride < (ptrdiff_t)w * size[format])
        return RAST_E_ARG;
    st = rast__scratch_check(scratch, scratch_bytes, rast__w64_need(npoints, w));
    if (st != RAST_OK) return st;

    ar = rast__arena_of(scratch, scratch_bytes);
    wk.e = (rast__w64e *)rast__take(&ar, (size_t)npoints * sizeof(rast__w64e));
    wk.order = (int32_t *)rast__take(&ar, (size_t)npoints * sizeof(int32_t));
    wk.active = (int32_t *)rast__take(&ar, (size_t)npoints * sizeof(int32_t));
    wk.span = (int32_t *)rast__take(&ar, (size_t)npoints * sizeof(int32_t));
    wk.k0 = (rast__i128 *)rast__take(&ar, (size_t)npoints * sizeof(rast__i128));
    wk.k1 = (rast__i128 *)rast__take(&ar, (size_t)npoints * sizeof(rast__i128));
    wk.kn = (rast__i128 *)rast__take(&ar, (size_t)npoints * sizeof(rast__i128));
    wk.ts = (uint64_t *)rast__take(&ar, (2 * (size_t)npoints + 2) * sizeof(uint64_t));
    cells.area = (rast__i128 *)rast__take(&ar, (size_t)w * sizeof(rast__i128));
    cells.cover = (rast__i128 *)rast__take(&ar, ((size_t)w + 1) * sizeof(rast__i128));
    for (i = 0; i < (uint32_t)w; i++) cells.area[i] = rast__i128_from(0);
    for (i = 0; i <= (uint32_t)w; i++) cells.cover[i] = rast__i128_from(0);
    cells.dirty = (uint64_t *)rast__take(&ar, ((size_t)(w >> 6) + 1) * sizeof(uint64_t));
    for (i = 0; i <= (uint32_t)(w >> 6); i++) cells.dirty[i] = 0;
    h = RAST__W64_G - s;
    cells.x0 = clip->x0;
    cells.x1 = clip->x1;
    cells.s = s;
    cells.h = h;

    /* the non-horizontal edges, top first */
    for (k = 0, base = 0; k < polygon->nrings; base += polygon->ring_sizes[k], k++) {
        uint32_t m = polygon->ring_sizes[k];
        for (i = 0; i < m; i++) {
            rast_point64 a = polygon->points[base + i];
            rast_point64 b = polygon->points[base + (i + 1 == m ? 0 : i + 1)];
            rast__w64e *ed = &wk.e[ne];
            if (a.y == b.y) continue;
            ed->dir = 1;
            if (a.y > b.y) {
                rast_point64 t = a;
                a = b;
                b = t;
                ed->dir = -1;
            }
            ed->xt = a.x;
            ed->yt = a.y;
            ed->xb = b.x;
            ed->yb = b.y;
            ed->dx = b.x - a.x;
            ed->dy = b.y - a.y;
            ed->pad = 0;
            wk.order[ne] = ne;
            ne++;
        }
    }
    rast__w64_sort_tops(wk.order, ne, wk.e);

    /* rows the polygon reaches: floor(miny / 2^S) .. ceil(maxy / 2^S) */
    {
        const int64_t bias = (int64_t)1 << 62;
        rlo = (int64_t)((uint64_t)(miny + bias) >> s) - (bias >> s);
        rhi = (int64_t)((uint64_t)(maxy + bias + ((int64_t)1 << s) - 1) >> s) - (bias >> s);
    }
    for (y = clip->y0; y < clip->y1; y++) {
        unsigned char *row = (unsigned char *)out + (ptrdiff_t)(y - clip->y0) * stride;
        int64_t yj = (int64_t)y * ((int64_t)1 << s), ynext;
        int32_t m;
        if (npoints == 0 || y < rlo || y >= rhi) {
            memset(row, 0, (size_t)w * (size_t)size[format]);
            continue;
        }
        ynext = yj + ((int64_t)1 << s);
        /* drop the edges that end at or above the row's top; add those
         * that start above its bottom */
        for (i = 0, m = 0; i < (uint32_t)na; i++)
            if (wk.e[wk.active[i]].yb > yj) wk.active[m++] = wk.active[i];
        na = m;
        while (next < ne && wk.e[wk.order[next]].yt < ynext) {
            if (wk.e[wk.order[next]].yb > yj) wk.active[na++] = wk.order[next];
            next++;
        }
        cells.yj = yj;
        if (na >= 2) rast__w64_sweep_row(&wk, &cells, na, opts->rule);
        rast__w64_emit(&cells, format, row);
    }
    return RAST_OK;
}

/*
 * coverage_area.c - exact area coverage ("area") and signed-area
 * accumulation ("accumulate"), row by row (DESIGN section 1a; the bound in
 * rastrum.h).
 *
 * Area.  Pixel row j is the strip j <= y < j + 1.  Its edges (those whose
 * open y extent meets the strip) are swept from the strip's top: at the
 * current ordinate t they are put in their exact order just below t (by
 * abscissa, then slope), and the sweep goes on to the next event: an
 * edge's end or start, or the first crossing of two neighbours (only
 * neighbours can cross first).  Between t and that event no two edges
 * cross, so the region is a union of trapezoids [L(y), R(y)] bounded by
 * the edges where the winding number enters and leaves "inside" (every
 * edge under even-odd; under non-zero those where it leaves or returns to
 * 0): coverage counts what lies right of each left boundary minus what
 * lies right of each right boundary, per column, as FreeType counts its
 * cells (cover and area per cell, then a running sum along the row).  A
 * crossing's ordinate is rounded up to the grid of 2^-60 pixel, abscissae
 * at the pieces' ends down to it; everything else is exact (the order of
 * the edges, the crossings' positions before rounding, the sums, which
 * are 128-bit and modular: the true per-pixel result is small).
 *
 * Most rows need no sweep: where the winding number only takes 0 and one
 * sign of 1 in the strip ("fast rows", below: the test is exact), every
 * edge bounds the inside all the way through the row, and its part is
 * added whole, as the sweep would add it with no event inside the row.
 * Before any row, coincident edges of opposite directions cancel
 * (rast__cov_cancel).
 *
 * Accumulate.  The same cells, but every edge adds its whole part in the
 * row with the sign of its direction: the sum is the integral of the
 * winding number over the pixel, turned into a coverage by the rule.
 * Right where no parts of the region overlap.
 */
#include "coverage.h"
#include "cells.h"
#include "../base/bits.h" /* rast__ctz64 */

#define G RAST__COV_G
#define T ((uint64_t)1 << G)
#define QF 30 /* the quick accumulation's grid, 2^-QF pixel (below) */

/* Shortcuts that only save instructions (the same results as the general
 * way next to each) are left out of size-optimised builds (firmware, -Os):
 * with them, "area" took 1.2 KB more .text on Cortex-M0. */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__SHORTCUTS 1
#else
#define RAST__SHORTCUTS 0
#endif

/* Is a strictly before b just below the ordinate both have cached? */
static int rast__cov_before(const rast__cedge *a, const rast__cedge *b)
{
    int c = rast__i128_cmp(a->x, b->x);
    int64_t l, r;
    if (c) return c < 0;
    l = a->r * b->dy;
    r = b->r * a->dy;
    if (l != r) return l < r;
    return (int64_t)a->dx * b->dy < (int64_t)b->dx * a->dy;
}

/* Where a (cached at ordinate t of row j) lies against b there, when b's
 * cache says without b's abscissa at t: -1 strictly left of it, 1
 * strictly right, 0 not known.  b's line at t lies between its abscissae
 * at its cached ordinate (tx <= t, row j) and at the row's bottom (xT,
 * rast__cov_row_area sets it for the row's edges), each a floor with a
 * remainder in [0, 1): a's abscissa, in [a->x, a->x + 1), is left of both
 * when a->x is below both floors, right of both when above both.  The
 * test that spares most of the placements' exact abscissae (a 128-bit
 * product and division each; on a stroke, most of rast__cov_place's and
 * rast__cov_replace's instructions).  Size-optimised builds compute the
 * abscissa (RAST__SHORTCUTS). */
static int rast__cov_apart(const rast__cedge *a, const rast__cedge *b, int32_t j, uint64_t t)
{
    int lo, hi;
    if (!RAST__SHORTCUTS || b->rowx != j || b->tx > t) return 0;
    lo = rast__i128_cmp(a->x, b->x);
    hi = rast__i128_cmp(a->x, b->xT);
    if (lo < 0 && hi < 0) return -1;
    if (lo > 0 && hi > 0) return 1;
    return 0;
}

/* rast__cov_before at ordinate t of row j, where a is cached and b is
 * cached there or computed here (b's own cache, the start of its piece,
 * is left alone). */
static int rast__cov_before_at(const rast__cedge *a, const rast__cedge *b, int64_t Yj, int32_t j,
                               uint64_t t, int32_t h)
{
    rast__cedge bt;
    int r;
    if (b->rowx == j && b->tx == t) return rast__cov_before(a, b);
    if ((r = rast__cov_apart(a, b, j, t)) != 0) return r < 0;
    bt.dx = b->dx;
    bt.dy = b->dy;
    rast__cov_x_at(b, Yj, t, h, &bt.x, &bt.r);
    return rast__cov_before(a, &bt);
}

/* Is b strictly before a just below ordinate t of row j, a cached there,
 * b computed here (rast__cov_before_at with the roles turned)? */
static int rast__cov_behind_at(const rast__cedge *a, const rast__cedge *b, int64_t Yj, int32_t j,
                              uint64_t t, int32_t h)
{
    rast__cedge bt;
    int r;
    if (b->rowx == j && b->tx == t) return rast__cov_before(b, a);
    if ((r = rast__cov_apart(a, b, j, t)) != 0) return r > 0;
    bt.dx = b->dx;
    bt.dy = b->dy;
    rast__cov_x_at(b, Yj, t, h, &bt.x, &bt.r);
    return rast__cov_before(&bt, a);
}

#if !defined(__OPTIMIZE_SIZE__) /* (the speed builds' quick tests only) */
/* v + 2^20 as an unsigned word: below 2^21 for v in [-2^20, 2^20). */
static inline uint64_t rast__cov_off(int64_t v)
{
    return (uint64_t)v + ((uint64_t)1 << 20);
}
#endif

/* The first ordinate after t (U; up to T) where a, left of b just below
 * t, crosses it; T when they do not cross inside the row.  Inlined in its
 * two callers where speed counts (a call of it cost tri10k 0.6 M
 * instructions once rast__grp_few called it too). */
#if RAST__SHORTCUTS
#define RAST__CROSS RAST__HOT
#else
#define RAST__CROSS static
#endif
RAST__CROSS uint64_t rast__cov_cross(const rast__cedge *a, const rast__cedge *b, int64_t Yj,
                                uint64_t t, const rast__cells *c)
{
    int64_t D = (int64_t)a->dx * b->dy - (int64_t)b->dx * a->dy, q0, r0, qq, rr;
    rast__i128 N;
    uint64_t tc;
    if (D <= 0) return T; /* a is not steeper to the right: no crossing */
    /* The crossing's ordinate y = Yj + N / D (fixed units), N below.
     * When the seven factors of N's three products all lie in
     * [-2^20, 2^20) (coordinates within 4,096 px at S = 8, as on most
     * canvases; v + 2^20 < 2^21 for each, so for the OR of them), each
     * product is at most 2^60 in magnitude, |N| <= 3 2^60 < 2^62 and
     * D <= 2^41: N in 64 bits, and the time by one division
     * (rast__shl_div_ceil); the same value as the 128-bit way below, which
     * the other pairs take.  Size-optimised builds (firmware, -Os) take
     * the 128-bit way for every pair: less .text on Cortex-M0, where a
     * 64-bit division is a library call too. */
#if !defined(__OPTIMIZE_SIZE__)
    {
        const int64_t ex = (int64_t)b->xt - a->xt, ea = (int64_t)a->yt - Yj, eb = (int64_t)b->yt - Yj;
        if ((rast__cov_off(ex) | rast__cov_off(ea) | rast__cov_off(eb) | rast__cov_off(a->dx) |
             rast__cov_off(a->dy) | rast__cov_off(b->dx) | rast__cov_off(b->dy)) < ((uint64_t)1 << 21)) {
            const int64_t n = ex * a->dy * b->dy + ea * a->dx * b->dy - eb * b->dx * a->dy;
            /* inside the row: 0 <= n < D P, i.e. floor(n / P) < D (P = 2^S) */
            if (n < 0 || ((uint64_t)n >> (G - c->h)) >= (uint64_t)D) return T;
            tc = rast__shl_div_ceil((uint64_t)n, (uint64_t)D, c->h); /* < T: n 2^H < D 2^G */
            if (tc <= t) tc = t + 1;
            return tc > T ? T : tc;
        }
    }
#endif
    N = rast__i128_mul((int64_t)(b->xt - a->xt) * a->dy, b->dy);
    N = rast__i128_add(N, rast__i128_mul((a->yt - Yj) * a->dx, b->dy));
    N = rast__i128_sub(N, rast__i128_mul((b->yt - Yj) * b->dx, a->dy));
    /* Not inside the row unless 0 <= N < D P (N < 0 cannot be); then both
     * quotients below are small, and rast__wide_floordiv takes one machine
     * division each where the compiler has a 128-bit type (a bit-by-bit
     * long division took a quarter of "area"'s instructions on 300
     * canvas-spanning triangles). */
    if (rast__i128_neg_p(N) || rast__i128_cmp(N, rast__i128_mul(D, c->p)) >= 0) return T;
    rast__wide_floordiv(N, D, &q0, &r0);
    /* t = ceil(N 2^H / D) = q0 2^H + ceil(r0 2^H / D). */
    rast__wide_floordiv(rast__i128_shl(rast__i128_from(r0), c->h), D, &qq, &rr);
    tc = ((uint64_t)q0 << c->h) + (uint64_t)qq + (rr > 0);
    if (tc <= t) tc = t + 1;
    return tc > T ? T : tc;
}

size_t rast__cov_area_scratch(uint32_t n, int32_t width)
{
    size_t b = rast__align(rast__size_mul(n, sizeof(rast__cedge)));
    b = rast__size_add(b, 7 * rast__align(rast__size_mul(n, sizeof(int32_t))));
    b = rast__size_add(b, rast__align(rast__size_mul(n, sizeof(uint64_t))));
    b = rast__size_add(b, rast__align(rast__size_mul(((size_t)width + 63) / 64, sizeof(uint64_t))));
    b = rast__size_add(b, rast__align(rast__size_mul((size_t)width, sizeof(uint64_t))));
    b = rast__size_add(b, 2 * rast__align(rast__size_mul((size_t)width, sizeof(rast__i128))));
    /* rast__cov_acc's band: RAST__ACC_BAND rows of width + 1 cells and
     * their bits */
    b = rast__size_add(b, rast__align(rast__size_mul(RAST__ACC_BAND,
                                                     rast__size_mul((size_t)width + 1, sizeof(uint64_t)))));
    return rast__size_add(b, rast__align(rast__size_mul(RAST__ACC_BAND,
                                                        rast__size_mul(((size_t)width + 63) / 64,
                                                                       sizeof(uint64_t)))));
}

/* Heapsort of the indices ix[0..n) by the edges' top ordinate. */
/* ix[0..n) ordered by the edges' tops (by a radix sort of yt - min yt:
 * a few passes over the edges, where a heap sort took 8% of the
 * instructions of "area" on four glyphs); tmp and key: room for n each. */
static void rast__cov_sort_tops(int32_t *ix, int32_t *tmp, int32_t *key, const rast__cedge *e,
                                uint32_t n)
{
    int32_t ymin = n ? e[0].yt : 0;
    uint32_t i;
    for (i = 1; i < n; i++)
        if (e[i].yt < ymin) ymin = e[i].yt;
    for (i = 0; i < n; i++) key[i] = (int32_t)((uint32_t)e[i].yt - (uint32_t)ymin);
    rast__cov_radix_sort(ix, tmp, key, n);
}

/* a before b by (xt, dx, dy): the order in which coincident edges of
 * one top are neighbours. */
static int rast__cov_key_before(const rast__cedge *a, const rast__cedge *b)
{
    if (a->xt != b->xt) return a->xt < b->xt;
    if (a->dx != b->dx) return a->dx < b->dx;
    return a->dy < b->dy;
}

/* Coincident edges of opposite directions (a mesh's inner edges, two rings
 * sharing a side) change no winding number on either side, and their cells
 * would cancel exactly (the same pieces, signs opposite): both go, and the
 * rows they were in may be fast rows.  order[0..n) is sorted by top (key[],
 * rast__cov_sort_tops': one top, one key; a map's runs of one top found
 * by the edges' records were half rast__cov_cancel's time, a cache miss an
 * edge); each
 * run of one top is sorted by (xt, dx, dy) (Shell sort, in place), so that
 * coincident edges are neighbours; in each block of them as many pairs go
 * as there are edges of the rarer direction.  The rest, in order, are
 * counted back. */
#if RAST__SHORTCUTS
/* order[a..b) (one top's run) by insertion with rast__cov_key_before, a
 * budget of moves: 1 when it ends strictly increasing (no two coincident
 * edges: the one order, which the Shell sort below gives too); else 0 and
 * order[a..b) as it came (kept in tmp[a..b)), for the Shell sort, whose
 * order among coincident edges is then the same as before.  A run of one
 * top is nearly in order already (the rings by their index, laid left to
 * right, a few edges each): text's Shell sort passes were 1.6 M
 * instructions of 51 M (issue 33). */
static int rast__cov_tops_insert(int32_t *order, int32_t *tmp, const rast__cedge *e, uint32_t a, uint32_t b)
{
    uint32_t p, q;
    int32_t budget = (int32_t)(b - a) * 2 + 16;
    for (p = a; p < b; p++) tmp[p] = order[p];
    for (p = a + 1; p < b; p++) {
        const int32_t v = order[p];
        for (q = p; q > a && rast__cov_key_before(&e[v], &e[order[q - 1]]); q--) order[q] = order[q - 1];
        order[q] = v;
        budget -= (int32_t)(p - q);
        /* (its right neighbour, if any, is after it: it moved for it) */
        if (budget < 0 || (q > a && !rast__cov_key_before(&e[order[q - 1]], &e[v]))) {
            for (p = a; p < b; p++) order[p] = tmp[p];
            return 0;
        }
    }
    return 1;
}
#endif

static uint32_t rast__cov_cancel(int32_t *order, const rast__cedge *e, const int32_t *key, uint32_t n,
                                 int32_t *tmp)
{
    uint32_t a = 0, b, p, q, gap, out = 0;
#if RAST__SHORTCUTS
    int32_t credit = 2; /* rast__cov_tops_insert's answers: +1 each yes, -2 each no */
#else
    (void)tmp;
#endif
    while (a < n) {
        for (b = a + 1; b < n && key[order[b]] == key[order[a]]; b++) { /* (the keys: not a record's cache line an edge) */
        }
        if (b == a + 1) { /* one edge of its top: nothing to cancel with */
            order[out++] = order[a++];
            continue;
        }
        if (RAST__SHORTCUTS && b == a + 2) { /* two (a ring's cusp, most often): in their order, unless coincident */
            const rast__cedge *x = &e[order[a]], *y = &e[order[a + 1]];
            if (x->xt != y->xt || x->dx != y->dx || x->dy != y->dy) {
                const int32_t u = order[a], v = order[a + 1], sw = rast__cov_key_before(y, x);
                order[out++] = sw ? v : u;
                order[out++] = sw ? u : v;
                a = b;
                continue;
            }
        }
#if RAST__SHORTCUTS
        /* (tried while it ends so twice as often as not, or nearly: a
         * mesh's runs hold coincident edges, which it leaves to the Shell
         * sort) */
        if (credit >= 0) {
            if (rast__cov_tops_insert(order, tmp, e, a, b)) { /* no two coincident: all kept, in order */
                for (p = a; p < b; p++) order[out++] = order[p];
                credit++;
                a = b;
                continue;
            }
            credit -= 2;
        }
#endif
        for (gap = (b - a) / 2; gap > 0; gap = gap == 2 ? 1 : gap * 5 / 11) {
            for (p = a + gap; p < b; p++) {
                int32_t v = order[p];
                for (q = p; q >= a + gap && rast__cov_key_before(&e[v], &e[order[q - gap]]); q -= gap)
                    order[q] = order[q - gap];
                order[q] = v;
            }
        }
        for (p = a; RAST__SHORTCUTS && p + 1 < b && rast__cov_key_before(&e[order[p]], &e[order[p + 1]]); p++) {
        }
        if (RAST__SHORTCUTS && p + 1 == b) { /* no two coincident (each its own block): all kept, in order */
            for (p = a; p < b; p++) order[out++] = order[p];
            a = b;
            continue;
        }
        for (p = a; p < b;) { /* a block of coincident edges: [p, q) */
            const rast__cedge *x = &e[order[p]];
            int32_t bal = 0, kept;
            for (q = p; q < b && e[order[q]].xt == x->xt && e[order[q]].dx == x->dx &&
                        e[order[q]].dy == x->dy;
                 q++)
                bal += e[order[q]].dir;
            /* keep |bal| edges of the commoner direction */
            for (kept = 0; p < q; p++) {
                int32_t d = e[order[p]].dir;
                if ((bal > 0 && d > 0) || (bal < 0 && d < 0)) {
                    if (kept < (bal > 0 ? bal : -bal)) {
                        order[out++] = order[p];
                        kept++;
                    }
                }
            }
        }
        a = b;
    }
    return out;
}

/* The sweep's arrays, by position in the row's order: the edges (live),
 * the winding number left of each (wb); a heap (m entries) of the
 * positions p whose edge crosses the next one inside the row (the pair p),
 * by the crossing's time: h[s] the pair at slot s, ct[s] its time, hidx[p]
 * its slot (-1: not in the heap, no crossing in the row). */
typedef struct rast__sweep {
    int32_t *live, *wb, *h, *hidx;
    uint64_t *ct;
    int32_t m;
    int32_t swept; /* rast__cov_row_groups swept a group in the last row */
    int32_t unsorted; /* rast__grp_sort's insertion ran past its budget in the last row sorted */
    int32_t room;  /* the arrays' length (the polygon's edges) */
} rast__sweep;

#define NONE (T + 1)

/* (rast__heap_sink) */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__HEAP_END 1
#else
#define RAST__HEAP_END 0
#endif

/* The heap moves a hole, not swapped pairs: the entry (pos, key) goes up
 * from slot i (or down, below) and is written once where it stops.  The
 * arrays and the size are read into locals once: through w, every store
 * to an int32_t array would read them again (it may alias w->m). */
static inline void rast__heap_up(rast__sweep *w, int32_t i)
{
    int32_t *const h = w->h, *const hidx = w->hidx;
    uint64_t *const ct = w->ct;
    const int32_t pos = h[i];
    const uint64_t key = ct[i];
    while (i > 0) {
        const int32_t p = (i - 1) / 2;
        if (ct[p] <= key) break;
        h[i] = h[p];
        ct[i] = ct[p];
        hidx[h[i]] = i;
        i = p;
    }
    h[i] = pos;
    ct[i] = key;
    hidx[pos] = i;
}

static void rast__heap_down(rast__sweep *w, int32_t i)
{
    int32_t *const h = w->h, *const hidx = w->hidx;
    uint64_t *const ct = w->ct;
    const int32_t pos = h[i], m = w->m;
    const uint64_t key = ct[i];
    for (;;) {
        int32_t l = 2 * i + 1;
        if (l >= m) break;
        if (l + 1 < m && ct[l + 1] < ct[l]) l++;
        if (ct[l] >= key) break;
        h[i] = h[l];
        ct[i] = ct[l];
        hidx[h[i]] = i;
        i = l;
    }
    h[i] = pos;
    ct[i] = key;
    hidx[pos] = i;
}

/* The entry at slot i, most likely to belong near the leaves (the last
 * one, or a crossing after the one just done), goes down: the hole sinks
 * to a leaf (the smaller child up each time: one comparison a level; the
 * slot past the end holds NONE meanwhile, so that a lone child needs no
 * test, 20 B more on Cortex-M0: size-optimised builds test for it), the
 * entry goes in there, and up. */
static void rast__heap_sink(rast__sweep *w, int32_t i)
{
    int32_t *const h = w->h, *const hidx = w->hidx;
    uint64_t *const ct = w->ct;
    const int32_t pos = h[i], m = w->m;
    const uint64_t key = ct[i];
    int32_t l;
    if (RAST__HEAP_END) ct[m] = NONE;
    while ((l = 2 * i + 1) < m) {
        if ((RAST__HEAP_END || l + 1 < m) && ct[l + 1] < ct[l]) l++;
        h[i] = h[l];
        ct[i] = ct[l];
        hidx[h[i]] = i;
        i = l;
    }
    h[i] = pos;
    ct[i] = key;
    rast__heap_up(w, i);
}

/* Pair pos's crossing time becomes v: in the heap while it is inside the
 * row (v < T), out of it (hidx -1) otherwise, so that the heap holds only
 * the pairs that cross: most neighbours do not, in a row. */
static void rast__heap_set(rast__sweep *w, int32_t pos, uint64_t v)
{
    const int32_t s = w->hidx[pos];
    uint64_t old;
    if (s < 0) {
        if (v >= T) return;
        w->h[w->m] = pos;
        w->ct[w->m] = v;
        rast__heap_up(w, w->m++);
        return;
    }
    old = w->ct[s];
    if (v >= T) { /* out: its slot sinks to a leaf (the smaller child up
                   * each time: one comparison a level), where the last
                   * entry goes in, and up */
        const int32_t last = --w->m;
        w->hidx[pos] = -1;
        if (s == last) return;
        w->h[s] = w->h[last];
        w->ct[s] = w->ct[last];
        rast__heap_sink(w, s);
        return;
    }
    w->ct[s] = v;
    if (v < old)
        rast__heap_up(w, s);
    else if (v > old)
        rast__heap_down(w, s);
}

/* The top (the crossing just done, whose pair is in order now) leaves and
 * pair q, not in the heap, comes in with time v < T: it takes the top's
 * slot and sinks, one pass instead of the removal's and the insertion's
 * (the removal alone was a quarter of "area"'s instructions on 2,000
 * canvas-spanning triangles).  Size-optimised builds (firmware, -Os)
 * remove and insert, as before (RAST__SHORTCUTS). */
static void rast__heap_retop(rast__sweep *w, int32_t q, uint64_t v)
{
    w->hidx[w->h[0]] = -1;
    w->h[0] = q;
    w->ct[0] = v;
    rast__heap_sink(w, 0);
}

/* The heap of the pairs 0..np of live[] from their times (pair k's in
 * ct[k]; those inside the row kept, each at its slot). */
static void rast__heap_build(rast__sweep *w, int32_t np)
{
    int32_t k;
    w->m = 0;
    for (k = 0; k <= np; k++) {
        if (w->ct[k] < T) {
            w->h[w->m] = k;
            w->ct[w->m] = w->ct[k];
            w->hidx[k] = w->m++;
        } else {
            w->hidx[k] = -1;
        }
    }
    for (k = w->m / 2; k-- > 0;) rast__heap_down(w, k);
}

/* The sign of an edge's piece with winding wb on its left. */
static int32_t rast__cov_sign(rast_fill_rule rule, int32_t wb, int32_t dir)
{
    if (rule == RAST_RULE_EVENODD) return (wb & 1) ? -1 : 1;
    return wb == 0 ? 1 : (wb + dir == 0) ? -1 : 0;
}

/* The first crossing of a, left of b (edge ib), in row j, rounded up
 * (rast__cov_cross), from the row's top; T or NONE when they do not cross
 * inside the row (lines in order at the row's bottom do not cross in
 * between).  The crossing does not depend on where the sweep is (a pair in
 * order just after t crosses after it), so each edge keeps the last one it
 * computed, for its right neighbour: a vertex event finds most pairs
 * unchanged. */
static uint64_t rast__cov_pair_t(rast__cedge *a, int32_t ib, const rast__cedge *b, int64_t Yj,
                                 int32_t j, const rast__cells *c)
{
    if (a->cn != ib || a->crow != j) {
        int cmp = rast__i128_cmp(a->xT, b->xT);
        a->ctime = (cmp < 0 || (cmp == 0 && a->rT * b->dy <= b->rT * a->dy))
                       ? NONE
                       : rast__cov_cross(a, b, Yj, 0, c);
        a->cn = ib;
        a->crow = j;
    }
    return a->ctime;
}

/* When a, left of b (edge ib) just after t, crosses it (after t; T or
 * NONE: not in the row).  Not cut at the slab's end: the sweep takes
 * only the crossings before it, and a vertex event that leaves a pair
 * neighbours keeps its time (rast__cov_event). */
static uint64_t rast__cov_pair(rast__cedge *a, int32_t ib, const rast__cedge *b, int64_t Yj,
                               int32_t j, uint64_t t, const rast__cells *c)
{
    uint64_t tc = rast__cov_pair_t(a, ib, b, Yj, j, c);
    return tc <= t ? t + 1 : tc;
}

/* Edge e's piece sign becomes s at tc: the piece so far is added. */
static void rast__cov_resign(rast__cells *c, rast__cedge *e, int64_t Yj, int32_t j, uint64_t tc,
                             int32_t s)
{
    if (s == e->sg) return;
    rast__cov_x_at(e, Yj, tc, c->h, &e->xn, &e->rn);
    if (e->sg) rast__cells_piece(c, e, Yj, e->x, e->tx, e->xn, tc, e->sg);
    e->x = e->xn;
    e->r = e->rn;
    e->rowx = j;
    e->tx = tc;
    e->sg = s;
}

/* The ordinates (U from the top of row j, Yj = j P) where e starts and
 * ends in the row: 0 and T where it passes the row's top and bottom. */
static void rast__cov_span(const rast__cedge *e, int64_t Yj, const rast__cells *c, uint64_t *t0,
                           uint64_t *t1)
{
    const int64_t rel0 = (int64_t)e->yt - Yj, rel1 = (int64_t)e->yt + e->dy - Yj;
    *t0 = rel0 <= 0 ? 0 : (uint64_t)rel0 << c->h;
    *t1 = rel1 >= c->p ? T : (uint64_t)rel1 << c->h;
}

/* Edge ed starts at tv inside row j (a vertex: tv a whole number of
 * fixed units): its abscissa there, cached, is its top's, xt V units, no
 * remainder, as rast__cov_x_at gives it (without its call: on a stroke,
 * an event's edges' ends are most of their abscissae). */
static void rast__cov_at_top(rast__cedge *ed, int64_t Yj, int32_t j, uint64_t tv, int32_t h)
{
    if (RAST__SHORTCUTS) {
        ed->x = rast__i128_shl(rast__i128_from(ed->xt), h);
        ed->r = 0;
    } else {
        rast__cov_x_at(ed, Yj, tv, h, &ed->x, &ed->r);
    }
    ed->rowx = j;
    ed->tx = tv;
}

/* Edge ed ends at tv inside row j (its bottom vertex): its piece ends
 * there, at xt + dx V units (rast__cov_x_end's value), which it keeps. */
static void rast__cov_end_at(rast__cells *c, rast__cedge *ed, int64_t Yj, int32_t j, uint64_t tv)
{
    if (!RAST__SHORTCUTS) {
        rast__cov_x_end(ed, Yj, ed->tx, tv, c->h);
        if (ed->sg) rast__cells_piece(c, ed, Yj, ed->x, ed->tx, ed->xn, tv, ed->sg);
        rast__cov_x_keep(ed, j, tv);
        return;
    }
    ed->xn = rast__i128_shl(rast__i128_from((int64_t)ed->xt + ed->dx), c->h);
    if (ed->sg) rast__cells_piece(c, ed, Yj, ed->x, ed->tx, ed->xn, tv, ed->sg);
    ed->x = ed->xn; /* (rast__cov_x_keep, tv inside the row) */
    ed->r = ed->rn = 0;
    ed->rowx = j;
    ed->tx = tv;
}

/* An edge starting at tv (row j): its top, and the slot among
 * live[0..n) it goes into (the first edge it comes before). */
static int32_t rast__cov_place(const rast__cells *c, const rast__cedge *e, rast__cedge *ed,
                               const int32_t *live, int32_t n, int64_t Yj, int32_t j, uint64_t tv)
{
    int32_t lo = 0, hi = n;
    rast__cov_at_top(ed, Yj, j, tv, c->h);
    while (lo < hi) {
        const int32_t mid = lo + (hi - lo) / 2;
        if (rast__cov_before_at(ed, &e[live[mid]], Yj, j, tv, c->h))
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* Is b, starting at a's bottom vertex (at tv), strictly beside f (a's
 * neighbour, f spanning tv) the way a is, as far as the lines alone say:
 * when a's line and f's are not parallel.  The sweep's order just below
 * tv is their true order there (a crossing of theirs before tv is done,
 * one at tv, or within the grid before it, rounds up to tv, and the
 * caller's heap has none at or before tv), so the difference of their
 * lines' abscissae, linear and not constant, is strictly of one sign at tv:
 * if it were 0 there, it would change sign at tv (a crossing at tv) or
 * have been 0 just below it.  Then a's vertex is strictly on a's side of
 * f at tv, and b, from it, just below tv: the exact test's answer without
 * its abscissa.  Parallel lines (coincident, or apart) take the test. */
static int rast__cov_apart_at_vertex(const rast__cedge *a, const rast__cedge *b, const rast__cedge *f)
{
    return RAST__SHORTCUTS && b->xt == a->xt + a->dx && b->yt == a->yt + a->dy &&
           (int64_t)a->dx * f->dy != (int64_t)f->dx * a->dy;
}

/* One edge ending at tv, in slot pa of live[0..n), and one of its
 * direction, ib, starting there, with no neighbours' crossing at or before
 * tv: when ib lies strictly between the old edge's neighbours just below
 * tv, it takes the old edge's place (whose piece ends at tv), its winding
 * and sign, and only the two pairs it is in change: returns 1.  Else 0,
 * nothing changed but ib's top.  Where ib continues the old edge from its
 * bottom vertex (a ring's vertex: on a stroke, most events), the
 * neighbours not parallel to it need no exact test
 * (rast__cov_apart_at_vertex). */
static int rast__cov_replace(rast__cells *c, rast__cedge *e, rast__sweep *sw, int32_t n, int32_t pa,
                             int32_t ib, int64_t Yj, int32_t j, rast_fill_rule rule, uint64_t tv)
{
    int32_t *live = sw->live;
    rast__cedge *a = &e[live[pa]], *b = &e[ib];
    rast__cov_at_top(b, Yj, j, tv, c->h);
    if (!((pa == 0 || rast__cov_apart_at_vertex(a, b, &e[live[pa - 1]]) ||
           rast__cov_behind_at(b, &e[live[pa - 1]], Yj, j, tv, c->h)) &&
          (pa + 1 == n || rast__cov_apart_at_vertex(a, b, &e[live[pa + 1]]) ||
           rast__cov_before_at(b, &e[live[pa + 1]], Yj, j, tv, c->h))))
        return 0;
    rast__cov_end_at(c, a, Yj, j, tv);
    b->sg = rast__cov_sign(rule, sw->wb[pa], b->dir);
    live[pa] = ib;
    if (RAST__SHORTCUTS) b->pos = pa; /* (rast__cov_find) */
    if (pa > 0) rast__heap_set(sw, pa - 1, rast__cov_pair(&e[live[pa - 1]], ib, b, Yj, j, tv, c));
    if (pa + 1 < n) rast__heap_set(sw, pa, rast__cov_pair(b, live[pa + 1], &e[live[pa + 1]], Yj, j, tv, c));
    return 1;
}

/* The vertex event at tv (inside the row) without sorting the row again:
 * the order just after tv is the order just before it (live[0..*pn), the
 * crossings before tv done) with the edges ending at tv taken out and
 * those starting there put in (a binary search each, by their exact order
 * just below tv), when no two edges that stay neighbours cross at or
 * before tv (their cached crossing, rounded up, comes after tv: then they
 * are strictly in order at tv and just below it).  Only the edges ending
 * there, and those whose sign changes (rast__cov_sign: the winding on
 * their left changed), end a piece at tv; the others' pieces go on.  So an
 * event costs its own edges and a pass of integer work over the live ones,
 * not an exact abscissa for each (on a stroke's round joins, most of
 * "area"'s instructions).  Returns 1 with live[0..*pn), wb, the signs and
 * the crossings' heap set for the slab up to the next event (*ptvn); 0,
 * nothing changed but the pair caches, when neighbours meet at tv: the
 * caller ends every piece there and sorts again. */
static int rast__cov_event(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                           rast__sweep *sw, int32_t *pn, int32_t j, rast_fill_rule rule, int32_t w0,
                           uint64_t tv, uint64_t *ptvn)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t *live = sw->live, n = *pn, k, m, prev = -1, wsum = w0, nend = 0, nbeg = 0, ia = -1, ib = -1;
    uint64_t t0, t1, tvn = T;
    for (k = 0; k < nrow; k++) { /* the edges ending and starting at tv; the next event */
        rast__cov_span(&e[row[k]], Yj, c, &t0, &t1);
        if (t0 > tv) {
            if (t0 < tvn) tvn = t0;
            continue;
        }
        if (t0 == tv) {
            nbeg++;
            ib = row[k];
        }
        if (t1 == tv) {
            nend++;
            ia = row[k];
        } else if (t1 > tv && t1 < tvn) {
            tvn = t1;
        }
    }
    /* One edge ends and one of its direction starts (a ring's vertex, but
     * a turn in y), no neighbours' crossing at or before tv (the heap's
     * least time is after it), and the new edge strictly between the old
     * one's neighbours just below tv: it takes the old one's place, its
     * winding and sign, and only the two pairs it is in change.  What the
     * general way below would do, without its passes over the order. */
    if (nend == 1 && nbeg == 1 && e[ia].dir == e[ib].dir && (sw->m == 0 || sw->ct[0] > tv)) {
        int32_t pa = 0;
        while (live[pa] != ia) pa++;
        if (rast__cov_replace(c, e, sw, n, pa, ib, Yj, j, rule, tv)) {
            *ptvn = tvn;
            return 1;
        }
    }
    for (k = 0; k < n; k++) { /* the neighbours that stay */
        rast__cedge *ed = &e[live[k]];
        rast__cov_span(ed, Yj, c, &t0, &t1);
        if (t1 == tv) continue;
        if (prev >= 0 && rast__cov_pair_t(&e[prev], live[k], ed, Yj, j, c) <= tv) return 0;
        prev = live[k];
    }
    for (k = 0, m = 0; k < n; k++) { /* the edges ending at tv: their pieces end */
        rast__cedge *ed = &e[live[k]];
        rast__cov_span(ed, Yj, c, &t0, &t1);
        if (t1 != tv) {
            live[m++] = live[k];
            continue;
        }
        rast__cov_end_at(c, ed, Yj, j, tv);
    }
    n = m;
    for (k = 0; k < nrow; k++) { /* those starting at tv go in; the next event */
        rast__cedge *ed = &e[row[k]];
        int32_t lo;
        rast__cov_span(ed, Yj, c, &t0, &t1);
        if (t0 > tv && t0 < tvn) tvn = t0;
        if (t0 <= tv && t1 > tv && t1 < tvn) tvn = t1;
        if (t0 != tv) continue;
        lo = rast__cov_place(c, e, ed, live, n, Yj, j, tv);
        memmove(live + lo + 1, live + lo, (size_t)(n - lo) * sizeof *live);
        live[lo] = row[k];
        n++;
        ed->sg = 2; /* new: its sign below */
    }
    for (k = 0; k < n; k++) { /* windings and signs */
        rast__cedge *ed = &e[live[k]];
        const int32_t sg = rast__cov_sign(rule, wsum, ed->dir);
        sw->wb[k] = wsum;
        if (ed->sg == 2)
            ed->sg = sg;
        else
            rast__cov_resign(c, ed, Yj, j, tv, sg);
        wsum += ed->dir;
    }
    for (k = 0; k + 1 < n; k++)
        sw->ct[k] = rast__cov_pair(&e[live[k]], live[k + 1], &e[live[k + 1]], Yj, j, tv, c);
    rast__heap_build(sw, n - 2);
    *pn = n;
    *ptvn = tvn;
    return 1;
}

/* ---- a vertex event mended where it happens ------------------------------
 *
 * The heap holds the pairs of neighbours by position (pair p: live[p] and
 * live[p + 1]).  An edge taken out of live[] or put in moves the positions
 * right of it by one: the heap's entries, the pairs' crossing times and
 * their slots are relabelled in one pass of integer work (no comparison,
 * no exact abscissa), the heap's order unchanged; the pairs the edit makes
 * or breaks are marked (time 0, which no pair has: a pair's time is after
 * the ordinate it was set at) and computed once all edits are done. */
/* Size-optimised builds (firmware, -Os) leave this out, and every event
 * takes rast__cov_event's passes: the same pieces and levels, 2.4 KB less
 * .text on Cortex-M0 for the apps that link "area". */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__LOCAL_EVENTS 1
#define RAST__EV_MAX 8 /* edits in one event mended this way; more: rast__cov_event's passes */

/* Pair dp of the np pairs leaves; those right of it move left by one. */
static void rast__heap_drop(rast__sweep *w, int32_t dp, int32_t np)
{
    int32_t i;
    rast__heap_set(w, dp, NONE);
    for (i = 0; i < w->m; i++) w->h[i] -= w->h[i] > dp;
    memmove(w->hidx + dp, w->hidx + dp + 1, (size_t)(np - dp - 1) * sizeof *w->hidx);
}

/* A new pair np comes in (np0 pairs before), marked; the pairs from np
 * on move right. */
static void rast__heap_make(rast__sweep *w, int32_t np, int32_t np0)
{
    int32_t i;
    for (i = 0; i < w->m; i++) w->h[i] += w->h[i] >= np;
    memmove(w->hidx + np + 1, w->hidx + np, (size_t)(np0 - np) * sizeof *w->hidx);
    w->hidx[np] = -1;
    rast__heap_set(w, np, 0);
}

/* Pair p is marked (its time computed when the event's edits are done). */
static void rast__heap_mark(rast__sweep *w, int32_t p)
{
    rast__heap_set(w, p, 0);
}

/* Edge id's slot in live[0..n) (n when it is not there): with hints (a
 * row of many events, listed: rast__cov_ev_lists), its hint first
 * (rast__cedge's pos, set where the sweep puts an edge), then outwards
 * from it (an event's edits move a slot by a few); else a scan from the
 * left (a short row: the outward walk cost tri3k more than it saved).  The
 * scan found the ending edges of a stroke's events: 2.4 M instructions of
 * 93 M. */
RAST__HOT int32_t rast__cov_find(const rast__cedge *e, const int32_t *live, int32_t n, int32_t id, int hints)
{
    int32_t h, d;
    if (!hints) {
        for (d = 0; d < n && live[d] != id; d++) {
        }
        return d;
    }
    h = e[id].pos < 0 ? 0 : e[id].pos >= n ? n - 1 : e[id].pos;
    for (d = 0; h - d >= 0 || h + d < n; d++) {
        if (h + d < n && live[h + d] == id) return h + d;
        if (h - d >= 0 && live[h - d] == id) return h - d;
    }
    return n;
}

#define RAST__EV_LISTS_MIN 20 /* rows of more events list them (below); fewer are scanned */

/* The link of edge id's list (0: by start, 1: by end) while a row is
 * swept: the edge's quick range, which no one reads again in the row
 * (rast__grp_dead uses it as room too). */
#define RAST__EV_NEXT(ed, l) (*((l) ? &(ed)->qhi : &(ed)->qlo))

#define RAST__EV_BINS 16 /* the first pass's bins (rast__cov_ev_sort) */

/* ix[0..n) stably by key[ix[k]], keys in [0, 2^sb) (tmp: room for n): a
 * counting sort by the keys' top 4 bits, then an insertion sort, whose
 * moves stay within a bin.  The order rast__cov_radix_sort gives (a
 * stable sort's is unique) without its 256 bins a pass: a row's events
 * are a few dozen (on a stroke's rows of 24 events or more,
 * rast__cov_ev_lists took 4.35 M instructions with the radix sort, 3.48 M
 * with this one; so rows of 20 to 23 events are listed too). */
static void rast__cov_ev_sort(int32_t *ix, int32_t *tmp, const int32_t *key, int32_t n, int32_t sb)
{
    int32_t cnt[RAST__EV_BINS + 1], k, q;
    const int32_t sh = sb > 4 ? sb - 4 : 0;
    for (k = 0; k <= RAST__EV_BINS; k++) cnt[k] = 0;
    for (k = 0; k < n; k++) cnt[(key[ix[k]] >> sh) + 1]++;
    for (k = 1; k <= RAST__EV_BINS; k++) cnt[k] += cnt[k - 1]; /* cnt[b]: where bin b starts */
    for (k = 0; k < n; k++) tmp[cnt[key[ix[k]] >> sh]++] = ix[k];
    for (k = 0; k < n; k++) {
        const int32_t x = tmp[k], kx = key[x];
        for (q = k; q > 0 && key[ix[q - 1]] > kx; q--) ix[q] = ix[q - 1];
        ix[q] = x;
    }
}

/* The row's events ev[0..nev) in two lists, by the ordinate (units from
 * the row's top) where each starts (0 for one above the row) and where
 * it ends (P for one below), each stable (ev's order among equal
 * ordinates, the order the scan of rast__cov_event_local finds them in):
 * head[0] and head[1] the first edges, each edge's next in
 * RAST__EV_NEXT, -1 after the last.  The sweep's room (h, hidx, wb) is
 * free: the sweep sets it up after this. */
static void rast__cov_ev_lists(rast__cedge *e, const int32_t *ev, int32_t nev, rast__sweep *sw,
                               int64_t Yj, const rast__cells *c, int32_t *head)
{
    int32_t *const ix = sw->h, *const key = sw->wb;
    int32_t k, l;
    for (l = 0; l < 2; l++) {
        for (k = 0; k < nev; k++) { /* keys in [0, P): the start, or the end less 1 */
            const rast__cedge *ed = &e[ev[k]];
            const int64_t r0 = (int64_t)ed->yt - Yj, r1 = r0 + ed->dy;
            ix[k] = ev[k];
            key[ev[k]] = (int32_t)(l == 0 ? (r0 < 0 ? 0 : r0) : (r1 > c->p ? c->p : r1) - 1);
        }
        rast__cov_ev_sort(ix, sw->hidx, key, nev, G - c->h);
        for (k = 0; k + 1 < nev; k++) RAST__EV_NEXT(&e[ix[k]], l) = ix[k + 1];
        RAST__EV_NEXT(&e[ix[nev - 1]], l) = -1;
        head[l] = ix[0];
    }
}

/* rast__cov_event where few edges start and end at tv: ev[0..nev) the
 * row's edges that start or end inside it (the others span it), listed
 * when evq[0] is not -2 (rast__cov_ev_lists: evq holds where each list's
 * walk is; the sweep's events come in order).  The same order, windings,
 * signs and pieces as rast__cov_event's passes; returns -1 when it cannot
 * (too many edits, or neighbours that may meet at tv: nothing changed,
 * the passes decide). */
static int rast__cov_event_local(rast__cells *c, rast__cedge *e, const int32_t *ev, int32_t nev,
                                 int32_t *evq, rast__sweep *sw, int32_t *pn, int32_t j,
                                 rast_fill_rule rule, int32_t w0, uint64_t tv, uint64_t *ptvn)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t *live = sw->live, n = *pn, k, i, nend = 0, nbeg = 0, nd = 0;
    int32_t ends[RAST__EV_MAX], begs[RAST__EV_MAX], pos[RAST__EV_MAX], dirty[2 * RAST__EV_MAX];
    uint64_t tvn = T;
    int32_t wsum;
    /* The edges ending and starting at tv, and the next event: the scan
     * of rast__cov_span's ordinates, in units from the row's top (tv, a
     * vertex's, is v 2^H, 0 < v < P; an end at or past P is none), one
     * pass over the row's events at each (on a stroke's round joins, a
     * tenth of "area"'s instructions); in a row of many events, the walk
     * of their lists from the last event's place instead (the same edges
     * in the same order: the next event is the least start or end after
     * tv). */
    if (evq[0] != -2) {
        const int64_t v = (int64_t)(tv >> c->h);
        int64_t vn = c->p, r = 0;
        int32_t l, id;
        for (l = 0; l < 2; l++) {
            int32_t *const got = l ? ends : begs, ng = 0;
            for (id = evq[l]; id >= 0; id = (int32_t)RAST__EV_NEXT(&e[id], l)) {
                r = (int64_t)e[id].yt - Yj + (l ? e[id].dy : 0);
                if (r > v) break;
                if (r == v) {
                    if (ng == RAST__EV_MAX) return -1;
                    got[ng++] = id;
                }
            }
            evq[l] = id;
            if (id >= 0 && r < vn) vn = r;
            if (l)
                nend = ng;
            else
                nbeg = ng;
        }
        if (vn < c->p) tvn = (uint64_t)vn << c->h;
    } else {
        const int64_t v = (int64_t)(tv >> c->h);
        int64_t vn = c->p;
        for (k = 0; k < nev; k++) {
            const rast__cedge *ed = &e[ev[k]];
            const int64_t r0 = (int64_t)ed->yt - Yj, r1 = r0 + ed->dy;
            if (r0 > v) {
                if (r0 < vn) vn = r0;
                continue;
            }
            if (r0 == v) {
                if (nbeg == RAST__EV_MAX) return -1;
                begs[nbeg++] = ev[k];
            }
            if (r1 == v) {
                if (nend == RAST__EV_MAX) return -1;
                ends[nend++] = ev[k];
            } else if (r1 > v && r1 < vn) {
                vn = r1;
            }
        }
        if (vn < c->p) tvn = (uint64_t)vn << c->h;
    }
    /* One edge ends and one of its direction starts (a ring's vertex, but
     * a turn in y), no neighbours' crossing at or before tv, and the new
     * edge strictly between the old one's neighbours just below tv: it
     * takes the old one's place, its winding and sign, and only the two
     * pairs it is in change. */
    if (nend == 1 && nbeg == 1 && e[ends[0]].dir == e[begs[0]].dir && (sw->m == 0 || sw->ct[0] > tv)) {
        const int32_t pa = rast__cov_find(e, live, n, ends[0], evq[0] != -2);
        if (pa == n) return -1; /* (not expected) */
        if (rast__cov_replace(c, e, sw, n, pa, begs[0], Yj, j, rule, tv)) {
            *ptvn = tvn;
            return 1;
        }
    }
    /* Neighbours that meet at or before tv (the crossings before it are
     * done: the heap's times are tv or later): the passes decide, unless
     * one of the two ends at tv (a ring's lower vertex). */
    if (sw->m > 0 && sw->ct[0] <= tv) {
        int32_t stack[32], ns = 1;
        stack[0] = 0;
        while (ns > 0) {
            const int32_t s = stack[--ns], p = sw->h[s];
            int32_t l = 2 * s + 1, q;
            for (q = 0; q < nend && ends[q] != live[p] && ends[q] != live[p + 1]; q++) {
            }
            if (q == nend) return -1;
            for (; l <= 2 * s + 2; l++) {
                if (l < sw->m && sw->ct[l] <= tv) {
                    if (ns == 32) return -1;
                    stack[ns++] = l;
                }
            }
        }
    }
    /* Where the ending edges are (ascending), and whether the neighbours
     * they leave may meet at or before tv (then the passes decide). */
    for (i = 0; i < nend; i++) {
        const int32_t p = rast__cov_find(e, live, n, ends[i], evq[0] != -2);
        if (p == n) return -1; /* (not expected: an ending edge not in the order) */
        for (k = i; k > 0 && pos[k - 1] > p; k--) pos[k] = pos[k - 1];
        pos[k] = p;
    }
    for (i = 0; i < nend;) {
        int32_t a = pos[i], b = a;
        while (i + 1 < nend && pos[i + 1] == b + 1) {
            i++;
            b++;
        }
        i++;
        if (a > 0 && b + 1 < n &&
            rast__cov_pair_t(&e[live[a - 1]], live[b + 1], &e[live[b + 1]], Yj, j, c) <= tv)
            return -1;
    }
    /* The ending edges' pieces end; they go (right to left, so that the
     * positions found stay right). */
    for (i = nend; i-- > 0;) {
        const int32_t p = pos[i];
        rast__cov_end_at(c, &e[live[p]], Yj, j, tv);
        if (n >= 2) rast__heap_drop(sw, p < n - 1 ? p : p - 1, n - 1);
        n--;
        memmove(live + p, live + p + 1, (size_t)(n - p) * sizeof *live);
        memmove(sw->wb + p, sw->wb + p + 1, (size_t)(n - p) * sizeof *sw->wb);
        for (k = 0; k < nd; k++) dirty[k] -= dirty[k] > p;
        if (p > 0 && p < n) rast__heap_mark(sw, p - 1);
        dirty[nd++] = p;
    }
    for (i = 0; i < nbeg; i++) { /* those starting at tv go in */
        rast__cedge *ed = &e[begs[i]];
        const int32_t lo = rast__cov_place(c, e, ed, live, n, Yj, j, tv);
        memmove(live + lo + 1, live + lo, (size_t)(n - lo) * sizeof *live);
        memmove(sw->wb + lo + 1, sw->wb + lo, (size_t)(n - lo) * sizeof *sw->wb);
        live[lo] = begs[i];
        ed->pos = lo;
        if (n >= 1) {
            rast__heap_make(sw, lo < n ? lo : lo - 1, n - 1);
            if (lo > 0 && lo < n) rast__heap_mark(sw, lo - 1);
        }
        n++;
        for (k = 0; k < nd; k++) dirty[k] += dirty[k] >= lo;
        dirty[nd++] = lo;
        ed->sg = 2; /* new: its sign below */
    }
    /* Windings and signs: from each edit on, as far as they change. */
    for (i = 1; i < nd; i++) { /* the edits' positions in order */
        const int32_t v = dirty[i];
        for (k = i; k > 0 && dirty[k - 1] > v; k--) dirty[k] = dirty[k - 1];
        dirty[k] = v;
    }
    for (i = 0; i < nd && dirty[i] < n;) {
        k = dirty[i];
        wsum = k > 0 ? sw->wb[k - 1] + e[live[k - 1]].dir : w0;
        for (; k < n; k++) {
            rast__cedge *ed = &e[live[k]];
            if (ed->sg != 2 && sw->wb[k] == wsum) break; /* as before, up to the next edit */
            sw->wb[k] = wsum;
            if (ed->sg == 2)
                ed->sg = rast__cov_sign(rule, wsum, ed->dir);
            else
                rast__cov_resign(c, ed, Yj, j, tv, rast__cov_sign(rule, wsum, ed->dir));
            wsum += ed->dir;
        }
        while (i < nd && dirty[i] <= k) i++;
    }
    while (sw->m > 0 && sw->ct[0] == 0) { /* the pairs made */
        const int32_t p = sw->h[0];
        rast__heap_set(sw, p, rast__cov_pair(&e[live[p]], live[p + 1], &e[live[p + 1]], Yj, j, tv, c));
    }
    *pn = n;
    *ptvn = tvn;
    return 1;
}

#define RAST__SPLIT_MIN 16 /* rows of more edges split them (below) */

/* row[0..nrow) with the edges that start or end inside row j moved to
 * its end, the others (spanning the row) in their order before them
 * (tmp: room for nrow); returns where the first moved. */
static int32_t rast__cov_split(const rast__cedge *e, int32_t *row, int32_t nrow, int32_t *tmp,
                               int64_t Yj, const rast__cells *c)
{
    int32_t k, a = 0, b = 0;
    for (k = 0; k < nrow; k++) {
        uint64_t t0, t1;
        rast__cov_span(&e[row[k]], Yj, c, &t0, &t1);
        if (t0 == 0 && t1 == T)
            row[a++] = row[k];
        else
            tmp[b++] = row[k];
    }
    memcpy(row + a, tmp, (size_t)b * sizeof *row);
    return a;
}

#else
#define RAST__LOCAL_EVENTS 0
#endif

/* Edge e's line at the bottom of row j (Yj = j P), as rast__cov_x_at
 * gives it at t = T (floor in V into *x, the rest r/dy into *r), for the
 * sweep's xT.  The ordinate is a whole number of fixed units there, rel =
 * Yj + P - yt > 0 below the edge's top, so the abscissa's offset is
 * floor(|dx| rel 2^H / dy): with |dx|, rel and dy below 2^31, n = |dx| rel
 * fits 64 bits, and n / dy then the rest's bits, at most 31 a step (the
 * rest below dy < 2^31), by 64-bit divisions, while the quotient stays
 * below 2^62 (n / dy < 2^(62 - H)); otherwise rast__cov_x_at's 128-bit
 * way, whose value it is (docs/coverage.md: the abscissae exact).  On a
 * stroke, most of the sweep's edges start and end inside the row and get
 * their line's bottom this way.  Size-optimised builds take
 * rast__cov_x_at (RAST__SHORTCUTS). */
static void rast__sweep_x_bottom(const rast__cedge *e, int64_t Yj, const rast__cells *c, rast__i128 *x,
                                 int64_t *r)
{
    const int64_t rel = Yj + c->p - e->yt;
    const uint64_t adx = (uint64_t)(e->dx < 0 ? -(int64_t)e->dx : (int64_t)e->dx), dy = (uint64_t)e->dy;
    const uint64_t lim = (uint64_t)1 << 31;
    uint64_t n, q, rm, s;
    int32_t h = c->h;
    rast__i128 base;
    if (!RAST__SHORTCUTS || e->dx == 0 || rel <= 0 || (uint64_t)rel >= lim || adx >= lim || dy >= lim) {
        rast__cov_x_at(e, Yj, T, c->h, x, r);
        return;
    }
    n = adx * (uint64_t)rel;
    q = n / dy;
    if (q >> (62 - h)) {
        rast__cov_x_at(e, Yj, T, c->h, x, r);
        return;
    }
    rm = n % dy;
    while (h > 0) {
        s = h > 31 ? 31 : (uint64_t)h;
        q = (q << s) | ((rm << s) / dy); /* (rm < dy: the new bits below 2^s) */
        rm = (rm << s) % dy;
        h -= (int32_t)s;
    }
    base = rast__i128_shl(rast__i128_from(e->xt), c->h);
    if (e->dx > 0) {
        *x = rast__i128_add(base, rast__i128_u64(q));
        *r = (int64_t)rm;
    } else if (rm) {
        *x = rast__i128_sub(rast__i128_sub(base, rast__i128_u64(q)), rast__i128_from(1));
        *r = e->dy - (int64_t)rm;
    } else {
        *x = rast__i128_sub(base, rast__i128_u64(q));
        *r = 0;
    }
}

/* The row's sweep (area): edges row[0..nrow) of row j.  Between vertex
 * events (an edge starting or ending inside the row) the order changes
 * only where neighbours cross: the earliest crossing comes off the heap,
 * the two edges swap, and only they can change sign (the winding number
 * between them is the only one that changes); an edge's piece runs from
 * one change of its sign to the next.  At a vertex event the order is
 * mended (rast__cov_event), or, where neighbours meet there, every piece
 * ends and the edges are sorted again.  w0: the winding number left of
 * them all (rast__cov_row_groups sweeps a group of a row alone).  qtops:
 * every edge's part in row j has its quick start set (rast__fast_range,
 * for every part of the row before its groups; rast__grp_lines moves
 * only the starts inside the strip), qa + qar/dy, the exact abscissa at
 * the row's top in units of 2^-30 pixel (the quick accumulation, below).
 * Speed builds only. */
static void rast__cov_row_area(rast__cells *c, rast__cedge *e, int32_t *row, int32_t nrow,
                               rast__sweep *sw, int32_t j, rast_fill_rule rule, int32_t w0, int qtops)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t *live = sw->live;
    uint64_t t = 0, tv = T;
    int32_t k, n = 0, mended = 0; /* mended: live[] by rast__cov_event, not sorted at t */
    /* row[nfull..nrow): the edges of the row's events (in a short row,
     * all: those that span it have none) */
#if RAST__LOCAL_EVENTS
    int32_t nfull = nrow > RAST__SPLIT_MIN ? rast__cov_split(e, row, nrow, live, Yj, c) : 0;
    int32_t evq[2] = {-2, -2}; /* the events' lists' walks (rast__cov_event_local) */
    if (nrow - nfull >= RAST__EV_LISTS_MIN) rast__cov_ev_lists(e, row + nfull, nrow - nfull, sw, Yj, c, evq);
#endif
    for (k = 0; k < nrow; k++) { /* every line at the row's bottom */
        rast__cedge *ed = &e[row[k]];
        if (RAST__SHORTCUTS && (ed->rowx != j || ed->tx != 0) && (int64_t)ed->yt <= Yj) {
            /* it reaches the row's top, where the sort below (t = 0) needs
             * its abscissa: that one now, the bottom a row's step below it
             * (one exact abscissa, not two: a tenth of the sweep's
             * instructions on 10,000 small triangles) */
            if (qtops) {
                /* from its part's quick start: the same rational, G - 30
                 * bits more of fraction, x = qa 2^(G - 30) + floor(qar
                 * 2^(G - 30) / dy), r the rest (qar < dy < 2^31: below
                 * 2^61), one 64-bit division for rast__cov_x_at's 128-bit
                 * product and division (tri10k's groups: 40,000 tops) */
                const uint64_t qn = (uint64_t)ed->qar << (G - QF);
                ed->x = rast__i128_add(rast__i128_shl(rast__i128_from(ed->qa), G - QF),
                                       rast__i128_u64(qn / (uint64_t)ed->dy));
                ed->r = (int64_t)(qn % (uint64_t)ed->dy);
            } else {
                rast__cov_x_at(ed, Yj, 0, c->h, &ed->x, &ed->r);
            }
            ed->rowx = j;
            ed->tx = 0;
        }
        if (ed->rowx == j && ed->tx == 0) {
            ed->xT = ed->x;
            ed->rT = ed->r;
            rast__cov_x_row(ed, &ed->xT, &ed->rT);
        } else {
            rast__sweep_x_bottom(ed, Yj, c, &ed->xT, &ed->rT);
        }
    }
    while (t < T) {
        int32_t rest = nrow; /* live[rest..nrow): the others */
        if (!mended) {
            int32_t wsum = w0;
            tv = T;
            n = 0;
            /* The edges reaching below t, in order; the next start or end. */
            for (k = 0; k < nrow; k++) {
                rast__cedge *ed = &e[row[k]];
                uint64_t t0, t1;
                rast__cov_span(ed, Yj, c, &t0, &t1);
                if (t0 > t || t1 <= t) {
                    if (t0 > t && t0 < tv) tv = t0;
                    live[--rest] = row[k];
                    continue;
                }
                if (t1 < tv) tv = t1;
                if (ed->rowx != j || ed->tx != t) {
                    rast__cov_x_at(ed, Yj, t, c->h, &ed->x, &ed->r);
                    ed->rowx = j;
                    ed->tx = t;
                }
                {   /* insertion, by the exact order below t */
                    int32_t m = n++, id = row[k];
                    while (m > 0 && rast__cov_before(ed, &e[live[m - 1]])) {
                        live[m] = live[m - 1];
                        m--;
                    }
                    live[m] = id;
                }
            }
            /* Windings and signs; every piece starts at t. */
            for (k = 0; k < n; k++) {
                rast__cedge *ed = &e[live[k]];
                sw->wb[k] = wsum;
                if (RAST__LOCAL_EVENTS) ed->pos = k; /* (rast__cov_find) */
                ed->sg = rast__cov_sign(rule, wsum, ed->dir);
                wsum += ed->dir;
            }
            /* The neighbours' crossings before tv, in a heap. */
            for (k = 0; k + 1 < n; k++)
                sw->ct[k] = rast__cov_pair(&e[live[k]], live[k + 1], &e[live[k + 1]], Yj, j, t, c);
            rast__heap_build(sw, n - 2);
        }
        while (sw->m > 0 && sw->ct[0] < tv) {
            int32_t p = sw->h[0], ia = live[p], ib = live[p + 1];
            uint64_t tc = sw->ct[0];
            rast__cedge *a = &e[ia], *b = &e[ib];
            live[p] = ib;
            live[p + 1] = ia;
            if (RAST__LOCAL_EVENTS) {
                b->pos = p;
                a->pos = p + 1;
            }
            sw->wb[p + 1] = sw->wb[p] + b->dir;
            rast__cov_resign(c, b, Yj, j, tc, rast__cov_sign(rule, sw->wb[p], b->dir));
            rast__cov_resign(c, a, Yj, j, tc, rast__cov_sign(rule, sw->wb[p + 1], a->dir));
            {   /* pair p is in order now; its neighbours' times change.  A
                 * neighbour new to the heap takes the top's slot. */
                const uint64_t vl = p > 0 ? rast__cov_pair(&e[live[p - 1]], ib, b, Yj, j, tc, c) : NONE;
                const uint64_t vr = p + 2 < n ? rast__cov_pair(a, live[p + 2], &e[live[p + 2]], Yj, j, tc, c) : NONE;
                if (RAST__SHORTCUTS && vl < T && sw->hidx[p - 1] < 0) {
                    rast__heap_retop(sw, p - 1, vl);
                    if (p + 2 < n) rast__heap_set(sw, p + 1, vr);
                } else if (RAST__SHORTCUTS && vr < T && sw->hidx[p + 1] < 0) {
                    rast__heap_retop(sw, p + 1, vr);
                    if (p > 0) rast__heap_set(sw, p - 1, vl);
                } else {
                    rast__heap_set(sw, p, NONE);
                    if (p > 0) rast__heap_set(sw, p - 1, vl);
                    if (p + 2 < n) rast__heap_set(sw, p + 1, vr);
                }
            }
        }
        if (tv < T) { /* a vertex event: mended where it can be */
            uint64_t tvn;
            int r = -1;
#if RAST__LOCAL_EVENTS
            r = rast__cov_event_local(c, e, row + nfull, nrow - nfull, evq, sw, &n, j, rule, w0, tv, &tvn);
#endif
            if (r < 0) r = rast__cov_event(c, e, row, nrow, sw, &n, j, rule, w0, tv, &tvn);
            if (r) {
                mended = 1;
                t = tv;
                tv = tvn;
                continue;
            }
        }
        /* The open pieces end at tv.  At the row's bottom an edge's
         * abscissa is its line's there, xT + rT/dy (set above, exact): no
         * division for a piece that starts at a crossing or a vertex (on
         * 10,000 small triangles, most pieces that reach the bottom). */
        for (k = 0; k < n; k++) {
            rast__cedge *ed = &e[live[k]];
            if (RAST__SHORTCUTS && tv == T && ed->tx != 0) {
                ed->xn = ed->xT;
                ed->rn = ed->rT;
            } else {
                rast__cov_x_end(ed, Yj, ed->tx, tv, c->h);
            }
            if (ed->sg) rast__cells_piece(c, ed, Yj, ed->x, ed->tx, ed->xn, tv, ed->sg);
            rast__cov_x_keep(ed, j, tv);
        }
        /* The row's edges in this order, so that the next sort (here, or
         * in the next row) has little to do: when live[] came from a sort
         * at t, with the others after them; else the edges reaching the
         * row's bottom (all live in its last slab) and the others. */
        if (!mended) {
            memcpy(row, live, (size_t)n * sizeof *row);
            for (k = rest; k < nrow; k++) row[n + k - rest] = live[k];
#if RAST__LOCAL_EVENTS
            if (tv < T && nfull > 0) {
                nfull = rast__cov_split(e, row, nrow, live, Yj, c);
                if (evq[0] != -2) rast__cov_ev_lists(e, row + nfull, nrow - nfull, sw, Yj, c, evq); /* (their order) */
            }
#endif
        } else if (tv == T) {
            int32_t m = n;
            for (k = 0; k < nrow && m < nrow; k++) {
                uint64_t t0, t1;
                rast__cov_span(&e[row[k]], Yj, c, &t0, &t1);
                if (t1 < T) live[m++] = row[k];
            }
            if (m == nrow && k == nrow) memcpy(row, live, (size_t)nrow * sizeof *row);
        }
        mended = 0;
        t = tv;
    }
}

/* "area" sets an edge's exact steps (rast__cov_exact_steps) when it first
 * goes the exact way, not every edge's before the rows (their divisions
 * were 4% of "area" on a paragraph, whose rows are mostly quick): xsr < 0
 * marks an edge without them (they set it in [0, dy)).  Size-optimised
 * builds set them all before the rows, as before (less .text). */
static void rast__area_steps(rast__cedge *e, const int32_t *row, int32_t nrow)
{
    int32_t k;
    for (k = 0; RAST__SHORTCUTS && k < nrow; k++)
        if (e[row[k]].xsr < 0) rast__cov_exact_steps(&e[row[k]], 1);
}

/* rast__row_exact and rast__cov_row_area on edges whose exact steps may
 * not be set yet (above). */
static void rast__area_exact(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow, int32_t j,
                             int32_t s)
{
    rast__area_steps(e, row, nrow);
    rast__row_exact(c, e, row, nrow, j, s);
}

#if RAST__SHORTCUTS
/* ---- sweeps of two or three edges that span the row
 *
 * rast__cov_row_area on a group of two or three edges that all span row j
 * (no vertex event), without its sort, heap and passes over the live
 * edges: the same steps in the same order on each edge, so the same
 * pieces, caches and row order.  At the row's top each edge's abscissa
 * (cached or computed), its bottom a row's step below; the edges in their
 * exact order there (the sweep's insertion); their signs from w0; then
 * the crossings of neighbours (rast__cov_pair, rounded up as the sweep
 * takes them) in the order of their times, each swapping its pair, which
 * resigns there; then every piece ends at the row's bottom.  With three
 * edges the sweep's heap holds the two pairs' times at first (the earlier
 * on top; at a tie pair 0, rast__heap_build's order), and after a
 * crossing one time at most: the pair that crossed is in order (out), the
 * other pair, one of whose edges just moved, is timed again (in, at its
 * new time, or out when it does not cross inside the row).  Groups of two
 * and three edges were most of the sweeps (tri10k: 5,000 of 18,800; tri3k
 * 4,700 of 7,000), half of them spanning the row. */

/* Row j's edges row[0..n) at the row's top and bottom (the sweep's first
 * loop), sorted by their exact order just below the top (its insertion). */
static void rast__area_tops(rast__cells *c, rast__cedge *e, int32_t *row, int32_t n, int32_t j)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    for (k = 0; k < n; k++) {
        rast__cedge *ed = &e[row[k]];
        if (ed->rowx != j || ed->tx != 0) {
            rast__cov_x_at(ed, Yj, 0, c->h, &ed->x, &ed->r);
            ed->rowx = j;
            ed->tx = 0;
        }
        ed->xT = ed->x;
        ed->rT = ed->r;
        rast__cov_x_row(ed, &ed->xT, &ed->rT);
    }
    for (k = 1; k < n; k++) {
        int32_t m = k, id = row[k];
        while (m > 0 && rast__cov_before(&e[id], &e[row[m - 1]])) {
            row[m] = row[m - 1];
            m--;
        }
        row[m] = id;
    }
}

/* Pair p of row[] (row[p] left of row[p + 1]) crosses at tc: they swap,
 * and each takes the sign of its new winding on the left (wb: the
 * windings left of each slot, wb[p + 1] updated). */
static void rast__area_swap(rast__cells *c, rast__cedge *e, int32_t *row, int32_t *wb, int32_t p, int32_t j,
                            rast_fill_rule rule, uint64_t tc)
{
    const int64_t Yj = (int64_t)j * c->p;
    const int32_t ia = row[p], ib = row[p + 1];
    rast__cedge *a = &e[ia], *b = &e[ib];
    row[p] = ib;
    row[p + 1] = ia;
    b->pos = p;
    a->pos = p + 1;
    wb[p + 1] = wb[p] + b->dir;
    rast__cov_resign(c, b, Yj, j, tc, rast__cov_sign(rule, wb[p], b->dir));
    rast__cov_resign(c, a, Yj, j, tc, rast__cov_sign(rule, wb[p + 1], a->dir));
}

/* The open pieces of edges row[0..n) end at the row's bottom, as the
 * sweep ends them (rast__cov_row_area, tv = T). */
static void rast__area_ends(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t n, int32_t j)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    for (k = 0; k < n; k++) {
        rast__cedge *ed = &e[row[k]];
        if (ed->tx != 0) {
            ed->xn = ed->xT;
            ed->rn = ed->rT;
        } else {
            rast__cov_x_end(ed, Yj, 0, T, c->h);
        }
        if (ed->sg) rast__cells_piece(c, ed, Yj, ed->x, ed->tx, ed->xn, T, ed->sg);
        rast__cov_x_keep(ed, j, T);
    }
}

/* The sweep of row[0..2), both edges spanning row j (above): their one
 * crossing inside the row, if any. */
static void rast__area_two(rast__cells *c, rast__cedge *e, int32_t *row, int32_t j, rast_fill_rule rule,
                           int32_t w0)
{
    const int64_t Yj = (int64_t)j * c->p;
    rast__cedge *a, *b;
    uint64_t tc;
    int32_t k;
    for (k = 0; k < 2; k++) {
        rast__cedge *ed = &e[row[k]];
        if (ed->rowx != j || ed->tx != 0) {
            rast__cov_x_at(ed, Yj, 0, c->h, &ed->x, &ed->r);
            ed->rowx = j;
            ed->tx = 0;
        }
        ed->xT = ed->x;
        ed->rT = ed->r;
        rast__cov_x_row(ed, &ed->xT, &ed->rT);
    }
    if (rast__cov_before(&e[row[1]], &e[row[0]])) {
        k = row[0];
        row[0] = row[1];
        row[1] = k;
    }
    a = &e[row[0]];
    b = &e[row[1]];
    a->pos = 0;
    b->pos = 1;
    a->sg = rast__cov_sign(rule, w0, a->dir);
    b->sg = rast__cov_sign(rule, w0 + a->dir, b->dir);
    tc = rast__cov_pair(a, row[1], b, Yj, j, 0, c);
    if (tc < T) { /* they cross: b left of a from tc */
        row[0] = (int32_t)(b - e);
        row[1] = (int32_t)(a - e);
        b->pos = 0;
        a->pos = 1;
        rast__cov_resign(c, b, Yj, j, tc, rast__cov_sign(rule, w0, b->dir));
        rast__cov_resign(c, a, Yj, j, tc, rast__cov_sign(rule, w0 + b->dir, a->dir));
    }
    rast__area_ends(c, e, row, 2, j);
}

/* The sweep of row[0..3), every edge spanning row j (above): pair 0
 * (row[0], row[1]) and pair 1 (row[1], row[2]), their times in ct[]. */
static void rast__area_few(rast__cells *c, rast__cedge *e, int32_t *row, int32_t j, rast_fill_rule rule,
                           int32_t w0)
{
    const int32_t n = 3;
    const int64_t Yj = (int64_t)j * c->p;
    int32_t wb[3], k;
    uint64_t ct[2];
    rast__area_tops(c, e, row, n, j);
    for (k = 0; k < n; k++) {
        rast__cedge *ed = &e[row[k]];
        wb[k] = k ? wb[k - 1] + e[row[k - 1]].dir : w0;
        ed->pos = k;
        ed->sg = rast__cov_sign(rule, wb[k], ed->dir);
    }
    for (k = 0; k + 1 < n; k++) ct[k] = rast__cov_pair(&e[row[k]], row[k + 1], &e[row[k + 1]], Yj, j, 0, c);
    for (;;) {
        const int32_t p = ct[1] < ct[0]; /* the earlier; pair 0 at a tie */
        const uint64_t tc = ct[p];
        if (tc >= T) break;
        rast__area_swap(c, e, row, wb, p, j, rule, tc);
        ct[p] = NONE;
        if (p) /* the other pair, timed again */
            ct[0] = rast__cov_pair(&e[row[0]], row[1], &e[row[1]], Yj, j, tc, c);
        else
            ct[1] = rast__cov_pair(&e[row[1]], row[2], &e[row[2]], Yj, j, tc, c);
    }
    rast__area_ends(c, e, row, n, j);
}

/* row[0..nrow) swept by rast__area_two or rast__area_few when nrow is 2
 * or 3 and every edge spans row j: 1 (its exact steps set); else 0,
 * nothing done.  Called by rast__grp_blocks (a group's blocks: where the
 * edges span the row) before rast__area_sweep, not from inside it: with
 * the test there, GCC inlined the whole sweep into rast__area_sweep
 * instead of it into its callers (+0.5 M instructions on the stroke). */
RAST__APART int rast__area_small(rast__cells *c, rast__cedge *e, int32_t *row, int32_t nrow, int32_t j,
                                 rast_fill_rule rule, int32_t w0)
{
    const int64_t Yj = (int64_t)j * c->p, Yb = Yj + c->p;
    int32_t k;
    if (nrow < 2) return 0;
    for (k = 0; k < nrow; k++) {
        const rast__cedge *ed = &e[row[k]];
        if ((int64_t)ed->yt > Yj || (int64_t)ed->yt + ed->dy < Yb) return 0;
    }
    rast__area_steps(e, row, nrow);
    if (nrow == 2)
        rast__area_two(c, e, row, j, rule, w0);
    else
        rast__area_few(c, e, row, j, rule, w0);
    return 1;
}
#endif

/* rast__cov_row_area on edges whose exact steps may not be set yet;
 * qtops as there. */
static void rast__area_sweep(rast__cells *c, rast__cedge *e, int32_t *row, int32_t nrow, rast__sweep *sw,
                             int32_t j, rast_fill_rule rule, int32_t w0, int qtops)
{
    rast__area_steps(e, row, nrow);
    rast__cov_row_area(c, e, row, nrow, sw, j, rule, w0, qtops);
}

/* ---- the quick accumulation ----------------------------------------------
 *
 * Rows whose parts are added whole (fast rows, and every row when
 * accumulating) are first added in 64-bit arithmetic on a grid of 2^-30
 * pixel (Q = 2^-30; G = 60 above): a part's ends' abscissae and its column
 * crossings' ordinates are the floors of the exact values on that grid (a
 * 64-bit stepper per edge from row to row, rast__q_top, and one from column
 * to column, both carrying their remainder exactly), the ends' ordinates (0, 1
 * or a vertex's, S <= 16) exact; per column, cover += dy and area +=
 * floor((f0 + f1) dy / 2^10), modular, so that a pixel's value is
 * v = a 2^51 = 2^21 cover - area.  Each part moves a pixel's value by less
 * than 2 Q + 2^-51 < 2^-28 from its exact share (a rounded crossing or end
 * moves the trapezoid right of it by less than Q times the column's width,
 * and a part meets a pixel at two such points at most).  Only the pixels
 * in a part's columns (from its top end's to its bottom end's) are moved:
 * a part wholly left of a column adds to the cover summed along the row
 * its exact height (its column crossings' ordinates cancel in the sum, its
 * ends' are exact), one wholly right of it nothing.  So with at most n
 * parts meeting any one column (the row's parts, or those of the largest
 * of its groups, whose columns lie apart: rast__cov_row_groups),
 * |v 2^-51 - a| < n 2^-28; and v = a 2^51 in a column that no part meets,
 * which is one without a cell (every part marks a cell in each column of
 * the clip from its top end's to its bottom end's, rast__q_add): no window
 * there (a pixel half covered by a horizontal edge between two parts, an
 * exact tie, is rounded as the exact way rounds it, not added again).
 * The level floor(a M + 1/2) is then
 * known unless a' M + 1/2 lies within (n + 1) M 2^-27 of an integer (a tie,
 * or nearly): then the row is added again the exact way above, and only
 * then.  So a row's levels are floor(a M + 1/2) where the quick values
 * decide them, the exact sweep's elsewhere: the bound holds unchanged.
 * (FIX62 output, 512 parts or more in a row, or (n + 1) M >= 2^25: the
 * exact way only.) */
#define QT ((uint64_t)1 << QF)
#define QONE ((int64_t)1 << 51)

/* floor(v / 2^QF) for |v| < 2^62 (no >> of a negative value) */
static inline int64_t rast__q_col(int64_t v)
{
    return (int64_t)(((uint64_t)v + ((uint64_t)1 << 62)) >> QF) - ((int64_t)1 << 32);
}

/* e's exact abscissa at the top of row j (which e spans: yt <= j P < yt +
 * dy), in 2^-30 pixel: qx + qxr/dy (qx is the floor the 128-bit abscissa
 * in V units gives shifted by 30).  Stepped from the row above, else two
 * divisions (dx (jP - yt) < 2^56; the remainder times 2^(30 - S) < 2^58). */
static inline int64_t rast__q_top(rast__cedge *e, int32_t j, const rast__cells *c)
{
    return rast__cov_qtop(e, j, c->p, QF - (G - c->h));
}

/* The quick abscissae of e's part in row j (rows Yj = j P): its ends'
 * ordinates (2^-30 pixel from the row's top) into *ta, *tb, abscissae into
 * *xa, *xb; the stepper is left at row j + 1's top when e reaches it. */
static inline void rast__q_part(rast__cedge *e, int32_t j, const rast__cells *c, int64_t *xa,
                                uint64_t *ta, int64_t *xb, uint64_t *tb)
{
    const int32_t hq = QF - (G - c->h);
    const int64_t Yj = (int64_t)j * c->p;
    int64_t rel0 = (int64_t)e->yt - Yj, rel1 = (int64_t)e->yt + e->dy - Yj;
    if (rel0 > 0) {
        *ta = (uint64_t)rel0 << hq;
        *xa = (int64_t)e->xt * ((int64_t)1 << hq);
        e->qar = 0;
    } else {
        *ta = 0;
        *xa = rast__q_top(e, j, c);
        e->qar = e->qxr;
    }
    if (rel1 < c->p) {
        *tb = (uint64_t)rel1 << hq;
        *xb = ((int64_t)e->xt + e->dx) * ((int64_t)1 << hq);
        e->qbr = 0;
    } else {
        *tb = QT;
        *xb = rast__q_top(e, j + 1, c);
        e->qbr = e->qxr;
    }
}

/* e's quick stepper at vertical X (which e's x range reaches: |X P - xt|
 * <= |dx|): t = floor(|X P - xt| dy 2^HQ / |dx|), HQ = 30 - S, in two
 * 64-bit divisions (|X P - xt| dy < 2^56, the remainder times 2^HQ < 2^58). */
static void rast__q_t_first(rast__cedge *e, int64_t X, const rast__cells *c)
{
    rast__cov_qt_first(e, X, c->p, QF - (G - c->h));
}

static inline void rast__q_t_next(rast__cedge *e)
{
    uint32_t adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    e->qt += e->qts;
    e->qtr += e->qtsr;
    if (e->qtr >= adx) {
        e->qtr -= adx;
        e->qt++;
    }
    e->qX += e->dx > 0 ? 1 : -1;
}

/* The stepper's ordinate from the row's top (off: the row's top from the
 * edge's), kept in [lo, hi]. */
static inline uint64_t rast__q_t_val(const rast__cedge *e, int64_t off, uint64_t lo, uint64_t hi)
{
    int64_t t = e->qt - off;
    if (t < (int64_t)lo) return lo;
    if (t > (int64_t)hi) return hi;
    return (uint64_t)t;
}

static inline void rast__q_add(rast__cells *c, int64_t col, uint64_t f0, uint64_t f1, uint64_t t0,
                               uint64_t t1, int32_t s)
{
    uint64_t dy = t1 - t0, ar;
    rast__i128 *cell;
    if (col >= c->x1) return; /* (dy 0: the column marked all the same, see above) */
    if (col < c->x0) {
        c->qcarry += s < 0 ? 0 - dy : dy;
        return;
    }
    ar = ((f0 + f1) * dy) >> 10; /* < 2^61 before the shift */
    col -= c->x0;
    cell = &c->cover[col];
    if (s < 0) {
        cell->lo -= dy;
        cell->hi -= ar;
    } else {
        cell->lo += dy;
        cell->hi += ar;
    }
    c->bits[col >> 6] |= (uint64_t)1 << (col & 63);
    if ((int32_t)(col >> 6) < c->wmin) c->wmin = (int32_t)(col >> 6);
    if ((int32_t)(col >> 6) > c->wmax) c->wmax = (int32_t)(col >> 6);
}

/* The piece from column ca (fraction fa, ordinate ta) to cb != ca (fb,
 * tb), both inside the clip: rast__q_piece's loops with the stepper in
 * registers and no clip tests. */
static void rast__q_inner(rast__cells *c, rast__cedge *e, int64_t off, int64_t ca, int64_t cb,
                          uint64_t fa, uint64_t fb, uint64_t ta, uint64_t tb, int32_t s)
{
    const uint32_t adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    const int64_t step = ca < cb ? 1 : -1, X = ca < cb ? ca + 1 : ca;
    const uint64_t neg = s < 0 ? ~(uint64_t)0 : 0; /* x ^ neg - neg: x signed by s */
    rast__i128 *cell = c->cover;
    uint64_t *bits = c->bits;
    const int64_t x0 = c->x0;
    uint64_t t = ta, f = fa, fend = ca < cb ? QT : 0;
    int64_t qt, col, lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
    uint32_t qtr;
    if (e->qX != X) rast__q_t_first(e, X, c);
    qt = e->qt - off;
    qtr = e->qtr;
    for (col = ca; col != cb; col += step) {
        uint64_t tx = qt < (int64_t)t ? t : qt > (int64_t)tb ? tb : (uint64_t)qt, dy = tx - t;
        uint64_t ar = ((f + fend) * dy) >> 10;
        int64_t k = col - x0;
        cell[k].lo += (dy ^ neg) - neg;
        cell[k].hi += (ar ^ neg) - neg;
        bits[k >> 6] |= (uint64_t)1 << (k & 63);
        t = tx;
        f = QT - fend;
        qt += e->qts;
        qtr += e->qtsr;
        if (qtr >= adx) {
            qtr -= adx;
            qt++;
        }
    }
    {
        uint64_t dy = tb - t, ar = ((f + fb) * dy) >> 10;
        int64_t k = cb - x0;
        cell[k].lo += (dy ^ neg) - neg;
        cell[k].hi += (ar ^ neg) - neg;
        bits[k >> 6] |= (uint64_t)1 << (k & 63);
    }
    e->qt = qt + off;
    e->qtr = qtr;
    e->qX = X + (cb - ca);
    lo = (lo - x0) >> 6;
    hi = (hi - x0) >> 6;
    if ((int32_t)lo < c->wmin) c->wmin = (int32_t)lo;
    if ((int32_t)hi > c->wmax) c->wmax = (int32_t)hi;
}

/* rast__cells_piece, the quick way: xa, xb in units of 2^-30 pixel, ta,
 * tb of 2^-30 pixel from the row's top. */
static void rast__q_piece(rast__cells *c, rast__cedge *e, int64_t Yj, int64_t xa, uint64_t ta,
                          int64_t xb, uint64_t tb, int32_t s)
{
    const uint64_t fm = QT - 1;
    const int32_t hq = QF - (G - c->h);
    int64_t ca = rast__q_col(xa), cb = rast__q_col(xb), col;
    int64_t off = (Yj - e->yt) * ((int64_t)1 << hq);
    uint64_t fa = (uint64_t)xa & fm, fb = (uint64_t)xb & fm, t = ta;
    if (ta >= tb) return;
    if (ca == cb) {
        rast__q_add(c, ca, fa, fb, ta, tb, s);
        return;
    }
    if (ca < c->x0 && cb < c->x0) {
        rast__q_add(c, c->x0 - 1, 0, 0, ta, tb, s);
        return;
    }
    if (ca >= c->x0 && cb >= c->x0 && ca < c->x1 && cb < c->x1) { /* inside the clip */
        rast__q_inner(c, e, off, ca, cb, fa, fb, ta, tb, s);
        return;
    }
    if (ca < cb) { /* going right: the verticals ca + 1, ..., cb */
        if (ca >= c->x1) return;
        col = ca;
        if (col < c->x0) {
            uint64_t tx;
            if (e->qX != c->x0) rast__q_t_first(e, c->x0, c);
            tx = rast__q_t_val(e, off, t, tb);
            rast__q_add(c, c->x0 - 1, 0, 0, t, tx, s);
            t = tx;
            col = c->x0;
            fa = 0;
            rast__q_t_next(e);
        } else if (e->qX != col + 1) {
            rast__q_t_first(e, col + 1, c);
        }
        for (; col < cb; col++) {
            uint64_t tx;
            if (col >= c->x1) return;
            tx = rast__q_t_val(e, off, t, tb);
            rast__q_add(c, col, fa, QT, t, tx, s);
            t = tx;
            fa = 0;
            rast__q_t_next(e);
        }
        rast__q_add(c, cb, 0, fb, t, tb, s);
    } else { /* going left: the verticals ca, ..., cb + 1 */
        if (cb >= c->x1) return;
        col = ca;
        if (col >= c->x1) {
            if (e->qX != c->x1) rast__q_t_first(e, c->x1, c);
            t = rast__q_t_val(e, off, t, tb);
            col = c->x1 - 1;
            fa = QT;
            rast__q_t_next(e);
        } else if (e->qX != col) {
            rast__q_t_first(e, col, c);
        }
        for (; col > cb; col--) {
            uint64_t tx;
            if (col < c->x0) {
                rast__q_add(c, c->x0 - 1, 0, 0, t, tb, s);
                return;
            }
            tx = rast__q_t_val(e, off, t, tb);
            rast__q_add(c, col, fa, 0, t, tx, s);
            t = tx;
            fa = QT;
            rast__q_t_next(e);
        }
        rast__q_add(c, cb, QT, fb, t, tb, s);
    }
}

/* The level of v (a 2^51, the rule applied when accumulating); *amb set
 * when a tie is within win / 2^51 of it (see above). */
static inline uint64_t rast__q_level(const rast__cells *c, int64_t v, uint64_t win, uint64_t *amb)
{
    const uint64_t fm = (uint64_t)QONE - 1;
    uint64_t x, fr, lev;
    if (c->accumulate) {
        if (v < 0) v = -v;
        if (c->rule == RAST_RULE_NONZERO) {
            if (v > QONE) v = QONE;
        } else {
            v &= 2 * QONE - 1; /* mod 2 */
            if (v > QONE) v = 2 * QONE - v;
        }
    } else if (v < 0) {
        v = 0;
    } else if (v > QONE) {
        v = QONE;
    }
    if (c->quick == 255) {
        x = (uint64_t)v * 255 + ((uint64_t)1 << 50);
        lev = x >> 51;
        fr = x & fm;
    } else {
        rast__i128 p = rast__i128_add(rast__i128_mul(v, (int64_t)c->quick),
                                      rast__i128_u64((uint64_t)1 << 50));
        lev = rast__i128_sar(p, 51).lo;
        fr = p.lo & fm;
    }
    if (fr < win || fr > (uint64_t)QONE - win) *amb = 1;
    return lev;
}

/* The level of a fast row's value v in uint8, without branches: such
 * values lie in [-E, 1 + E] (E M 2^51 <= win / 2 < 2^49), where v 255 +
 * 2^50 needs no clamp to give the levels 0 .. 255; *bad set as
 * rast__q_level sets *amb. */
static inline uint64_t rast__q_u8(uint64_t v, uint64_t win, uint64_t *bad)
{
    const uint64_t x = v * 255 + ((uint64_t)1 << 50);
    *bad |= (uint64_t)((x & ((uint64_t)QONE - 1)) - win > (uint64_t)QONE - 2 * win);
    return x >> 51;
}

/* How rast__q_scan turns a value into a level: rast__q_level (any format
 * and rule), or into uint8 by rast__q_u8: a fast row's value, or an
 * accumulated one with the rule applied first by rast__q_fold (non-zero:
 * |v| up to 1; even-odd: |v| folded mod 2), as rast__q_level applies it. */
enum { RAST__Q_ANY, RAST__Q_U8_FAST, RAST__Q_U8_NONZERO, RAST__Q_U8_EVENODD };

/* v as rast__q_run takes it in `mode` (above): accumulated values with
 * the rule applied, others as they are. */
static inline uint64_t rast__q_fold(uint64_t v, const int mode)
{
    uint64_t a = (int64_t)v < 0 ? 0 - v : v;
    if (mode == RAST__Q_U8_NONZERO) return a > (uint64_t)QONE ? (uint64_t)QONE : a;
    if (mode != RAST__Q_U8_EVENODD) return v;
    a &= 2 * (uint64_t)QONE - 1;
    return a > (uint64_t)QONE ? 2 * (uint64_t)QONE - a : a;
}

/* Columns [k0, k1) of the row get the level of v (rast__q_fold's); u8: by
 * rast__q_u8, else by rast__q_level. */
static inline void rast__q_run(const rast__cells *c, unsigned char *row, int32_t k0, int32_t k1,
                               uint64_t v, uint64_t win, const int u8, uint64_t *bad)
{
    uint64_t lev;
    if (k0 >= k1) return;
    lev = u8 ? rast__q_u8(v, win, bad) : rast__q_level(c, (int64_t)v, win, bad);
    if (k1 > k0 + 1)
        rast__cov_fill(u8 ? RAST_COVERAGE_U8 : c->o->format, row, k0, k1, lev);
    else if (u8)
        row[k0] = (unsigned char)lev;
    else
        rast__cov_store(c->o->format, row, k0, lev);
}

/* The quick cells into row y's values, then cleared; mode (a constant at
 * each call, so that the compiler makes a loop for each): rast__q_run's.
 * Returns 1 when a level is not certain. */
RAST__HOT int rast__q_scan(rast__cells *c, unsigned char *row, uint64_t win, const int mode)
{
    const int u8 = mode != RAST__Q_ANY;
    uint64_t acc = c->qcarry, bad = 0;
    int32_t k = 0, wi;
    for (wi = c->wmin; wi <= c->wmax; wi++) {
        uint64_t b = c->bits[wi];
        c->bits[wi] = 0;
        for (; b; b &= b - 1) {
            int32_t col = (wi << 6) + (int32_t)rast__ctz64(b);
            if (k < col) /* the run before it: no part meets it, exact (no window) */
                rast__q_run(c, row, k, col, rast__q_fold(acc << 21, mode), 0, u8, &bad);
            acc += c->cover[col].lo;
            rast__q_run(c, row, col, col + 1, rast__q_fold((acc << 21) - c->cover[col].hi, mode),
                        win, u8, &bad);
            c->cover[col].lo = c->cover[col].hi = 0;
            k = col + 1;
        }
    }
    rast__q_run(c, row, k, c->x1 - c->x0, rast__q_fold(acc << 21, mode), 0, u8, &bad);
    return bad != 0;
}

/* rast__q_scan in each mode, a loop of its own each. */
static int rast__q_scan_any(rast__cells *c, unsigned char *row, uint64_t win)
{
    return rast__q_scan(c, row, win, RAST__Q_ANY);
}

static int rast__q_scan_fast(rast__cells *c, unsigned char *row, uint64_t win)
{
    return rast__q_scan(c, row, win, RAST__Q_U8_FAST);
}

static int rast__q_scan_nonzero(rast__cells *c, unsigned char *row, uint64_t win)
{
    return rast__q_scan(c, row, win, RAST__Q_U8_NONZERO);
}

static int rast__q_scan_evenodd(rast__cells *c, unsigned char *row, uint64_t win)
{
    return rast__q_scan(c, row, win, RAST__Q_U8_EVENODD);
}

/* The quick cells into row y, then cleared (nrow: the most parts meeting
 * one column, which sets the window): 1 (the row is done, handed on), or 0
 * when a level is not certain (the row is left to the exact way; its
 * values written here are all written again). */
static int rast__q_emit(rast__cells *c, int32_t y, int32_t nrow)
{
    const rast__cov_out *o = c->o;
    unsigned char *row = rast__cov_row(o, y);
    uint64_t win = ((uint64_t)nrow + 1) * c->quick << 24;
    int amb;
    if (o->format != RAST_COVERAGE_U8)
        amb = rast__q_scan_any(c, row, win);
    else if (!c->accumulate)
        amb = rast__q_scan_fast(c, row, win);
    else if (c->rule == RAST_RULE_NONZERO)
        amb = rast__q_scan_nonzero(c, row, win);
    else
        amb = rast__q_scan_evenodd(c, row, win);
    c->qcarry = 0;
    c->wmin = INT32_MAX;
    c->wmax = -1;
    if (amb) return 0;
    rast__cov_row_done(o, y);
    c->emitted = 1;
    return 1;
}

/* May a row be added the quick way, nrow parts at most meeting one column
 * (above)?  (The bound needs (n + 1) M < 2^25; past 511 parts a row would
 * too often be added twice.) */
static int rast__q_may(const rast__cells *c, int32_t nrow)
{
    return c->quick && nrow < 512 && ((uint64_t)nrow + 1) * c->quick < ((uint64_t)1 << 25);
}

/* ---- the fast row --------------------------------------------------------
 *
 * When the winding number takes, everywhere in the row's strip, only the
 * values 0 and one s (+1 or -1), the inside is where it is s, under both
 * rules, and the sweep above would find no crossing (two edges crossing make
 * four winding values around the crossing, at most two of them in {0, s})
 * and give every edge one sign, dir * s, from the row's top to its bottom:
 * an edge enters the inside (winding 0 to s: dir = s, sign +1) or leaves it
 * (s to 0: dir = -s, sign -1).  The row is then each edge's part, whole,
 * added with sign dir * s: the same cells and the same roundings as the
 * sweep makes for a piece (only its two ends' abscissae are rounded, and a
 * column crossing's ordinate), so the bound of the sweep holds (with fewer
 * roundings where the sweep would cut the piece at a vertex inside the
 * row).  In rows without a vertex inside, the values are the sweep's, bit
 * for bit.
 *
 * The test, all exact, costs a pass over the row's edges: each edge's part
 * in the strip lies in the abscissae [lo, hi) (V units: the floors at its
 * two ends, hi one more); the edges, sorted by lo, fall into groups whose
 * ranges overlap, and distinct groups cannot meet.  A group is accepted when
 * it is
 *   - edges that all span the strip, in the same order at its top and at
 *     its bottom (exact comparisons; equal at one end at most): they do not
 *     cross inside, and the winding number between neighbours is the sum
 *     of the directions on the left;
 *   - two edges that share an end inside the strip: a chain (one ends where
 *     the other starts, the same direction: y-monotone) or a cusp (both
 *     start, or both end, there; opposite directions; not collinear), the
 *     winding number inside the cusp being the one on its left plus its
 *     left branch's direction.
 * Every winding number met, from the left, must be 0 or s; else (overlaps,
 * crossings, several vertices close together, horizontal edges inside the
 * strip) the row is swept. */

/* e's part in row j, quick units (rast__q_part), into e->qa .. e->qtb,
 * and its range [qlo, qhi) (the floors at its two ends, qhi one more). */
static inline void rast__fast_range(rast__cedge *e, int32_t j, const rast__cells *c)
{
    rast__q_part(e, j, c, &e->qa, &e->qta, &e->qb, &e->qtb);
    e->qlo = e->qa < e->qb ? e->qa : e->qb;
    e->qhi = (e->qa < e->qb ? e->qb : e->qa) + 1;
}

/* The exact abscissae xa + ra/dy and xb + rb/dy (quick units) of a and b:
 * -1, 0, 1 as a's is smaller, equal, larger. */
static int rast__fast_cmpx(int64_t xa, uint32_t ra, const rast__cedge *a, int64_t xb, uint32_t rb,
                           const rast__cedge *b)
{
    int64_t l, r;
    if (xa != xb) return xa < xb ? -1 : 1;
    l = (int64_t)ra * b->dy;
    r = (int64_t)rb * a->dy;
    return (l > r) - (l < r);
}

/* Winding number w met: 0 or the row's one sign *s (set by the first). */
static int rast__fast_ok(int32_t w, int32_t *s)
{
    if (w == 0) return 1;
    if (w != 1 && w != -1) return 0;
    if (*s == 0) *s = w;
    return w == *s;
}

/* Edges g[0..m) (sorted by lo) of a group, all spanning the strip: sort
 * them by their top abscissa (insertion: a few), check the order at the
 * bottom, and walk the windings from *w. */
static int rast__fast_full(const rast__cedge *e, int32_t *g, int32_t m, int32_t *w, int32_t *s)
{
    int32_t k;
    for (k = 1; k < m; k++) {
        int32_t id = g[k], q = k;
        const rast__cedge *a = &e[id];
        while (q > 0) {
            const rast__cedge *b = &e[g[q - 1]];
            int c = rast__fast_cmpx(a->qa, a->qar, a, b->qa, b->qar, b);
            if (c > 0 || (c == 0 && rast__fast_cmpx(a->qb, a->qbr, a, b->qb, b->qbr, b) >= 0)) break;
            g[q] = g[q - 1];
            q--;
        }
        g[q] = id;
    }
    for (k = 0; k < m; k++) {
        const rast__cedge *a = &e[g[k]];
        if (k + 1 < m) {
            const rast__cedge *b = &e[g[k + 1]];
            int ct = rast__fast_cmpx(a->qa, a->qar, a, b->qa, b->qar, b);
            int cb = rast__fast_cmpx(a->qb, a->qbr, a, b->qb, b->qbr, b);
            if (ct > 0 || cb > 0 || (ct == 0 && cb == 0)) return 0;
        }
        *w += a->dir;
        if (!rast__fast_ok(*w, s)) return 0;
    }
    return 1;
}

/* At most this many ordinates inside a fast row where an edge starts or
 * ends (more: the row is swept), and this many edges in a group that has
 * such an edge. */
#define RAST__FAST_CUTS 32
#define RAST__FAST_MIXED 32

/* The ordinates inside row Yj's strip where e starts or ends (U from its
 * top) into u[1..*nu), sorted, once each (u[0] = 0): 0 when there would be
 * more than RAST__FAST_CUTS (u[] has room for RAST__FAST_CUTS + 2).  The
 * entries are moved by a loop, not memmove: a few, and a call each took 4%
 * of "area" on a paragraph (with the search). */
static inline int rast__fast_cuts(const rast__cedge *e, int64_t Yj, const rast__cells *c, uint64_t *u,
                           int32_t *nu)
{
    const int64_t rel0 = (int64_t)e->yt - Yj, rel1 = (int64_t)e->yt + e->dy - Yj;
    uint64_t cut[2];
    int32_t z;
    cut[0] = rel0 <= 0 ? 0 : (uint64_t)rel0 << c->h;
    cut[1] = rel1 >= c->p ? 0 : (uint64_t)rel1 << c->h;
    for (z = 0; z < 2; z++) {
        int32_t y = *nu, i;
        if (!cut[z]) continue;
        while (y > 1 && u[y - 1] > cut[z]) y--;
        if (u[y - 1] == cut[z]) continue;
        if (*nu > RAST__FAST_CUTS) return 0;
        for (i = *nu; i > y; i--) u[i] = u[i - 1];
        u[y] = cut[z];
        (*nu)++;
    }
    return 1;
}

/* A group g[0..m) with edges starting or ending inside the strip, at the
 * ordinates u[1..nu-1) (u[0] = 0, u[nu-1] = T): in each slab between two
 * of them its edges there span the slab; they must be in the same order at
 * the slab's top and bottom (exact abscissae, by cross multiplication), and
 * the windings walked from w[i], the slab's winding on the group's left,
 * which then becomes the one on its right. */
/* e's abscissa at ordinate Y (fixed units, within its extent) times its
 * dy: exact, |.| < 2^57. */
static int64_t rast__fast_num(const rast__cedge *e, int64_t Y)
{
    return (int64_t)e->xt * e->dy + (int64_t)e->dx * (Y - e->yt);
}

/* The abscissae na/a->dy and nb/b->dy compared exactly: -1, 0, 1. */
static int rast__fast_cmpn(int64_t na, const rast__cedge *a, int64_t nb, const rast__cedge *b)
{
    return rast__i128_cmp(rast__i128_mul(na, b->dy), rast__i128_mul(nb, a->dy));
}

static int rast__fast_mixed(const rast__cedge *e, const int32_t *g, int32_t m, const uint64_t *u,
                            int32_t nu, int64_t Yj, const rast__cells *c, int32_t *w, int32_t *s)
{
    int64_t na[RAST__FAST_MIXED], nb[RAST__FAST_MIXED];
#if RAST__SHORTCUTS
    int64_t r0[RAST__FAST_MIXED], r1[RAST__FAST_MIXED]; /* each edge's top and bottom - Yj */
#endif
    int32_t id[RAST__FAST_MIXED], i, k, n;
    if (m > RAST__FAST_MIXED) return 0;
#if RAST__SHORTCUTS
    for (k = 0; k < m; k++) { /* (read once, not once a slab) */
        r0[k] = (int64_t)e[g[k]].yt - Yj;
        r1[k] = r0[k] + e[g[k]].dy;
    }
#endif
    for (i = 0; i + 1 < nu; i++) {
        /* the slab [Ya, Yb] (fixed units: the ordinates inside the row are
         * vertices', multiples of 2^H) */
        const int64_t ra = (int64_t)(u[i] >> c->h), rb = (int64_t)(u[i + 1] >> c->h);
        const int64_t Ya = Yj + ra, Yb = Yj + rb;
#if RAST__SHORTCUTS
        for (k = 0, n = 0; k < m; k++) /* the edges over the slab */
            if (r0[k] <= ra && r1[k] >= rb) id[n++] = g[k];
#else
        for (k = 0, n = 0; k < m; k++) { /* the edges over the slab */
            const rast__cedge *ed = &e[g[k]];
            if (ed->yt <= Ya && (int64_t)ed->yt + ed->dy >= Yb) id[n++] = g[k];
        }
#endif
        if (n == 1) { /* (most slabs: no order to check) */
            w[i] += e[id[0]].dir;
            if (!rast__fast_ok(w[i], s)) return 0;
            continue;
        }
        if (RAST__SHORTCUTS && n == 2) { /* (most others: one pair, compared once at each end) */
            const rast__cedge *a = &e[id[0]], *b = &e[id[1]];
            const int ct = rast__fast_cmpn(rast__fast_num(a, Ya), a, rast__fast_num(b, Ya), b);
            const int cb = rast__fast_cmpn(rast__fast_num(a, Yb), a, rast__fast_num(b, Yb), b);
            /* equal at both ends, or crossing: not fast; else a first
             * when it is before b by (top, bottom), as the sort below */
            if ((ct == 0 && cb == 0) || (ct < 0 && cb > 0) || (ct > 0 && cb < 0)) return 0;
            if (ct > 0 || (ct == 0 && cb > 0)) {
                a = &e[id[1]];
                b = &e[id[0]];
            }
            w[i] += a->dir;
            if (!rast__fast_ok(w[i], s)) return 0;
            w[i] += b->dir;
            if (!rast__fast_ok(w[i], s)) return 0;
            continue;
        }
        for (k = 0; k < n; k++) { /* by top, then bottom (insertion, as they came) */
            const int32_t ik = id[k];
            const rast__cedge *ed = &e[ik];
            const int64_t x0 = rast__fast_num(ed, Ya), x1 = rast__fast_num(ed, Yb);
            int32_t q = k;
            while (q > 0) {
                const rast__cedge *b = &e[id[q - 1]];
                int ct = rast__fast_cmpn(x0, ed, na[q - 1], b);
                if (ct > 0 || (ct == 0 && rast__fast_cmpn(x1, ed, nb[q - 1], b) >= 0)) break;
                id[q] = id[q - 1];
                na[q] = na[q - 1];
                nb[q] = nb[q - 1];
                q--;
            }
            id[q] = ik;
            na[q] = x0;
            nb[q] = x1;
        }
        for (k = 0; k < n; k++) {
            if (k + 1 < n) {
                const rast__cedge *a = &e[id[k]], *b = &e[id[k + 1]];
                int ct = rast__fast_cmpn(na[k], a, na[k + 1], b);
                int cb = rast__fast_cmpn(nb[k], a, nb[k + 1], b);
                if (ct > 0 || cb > 0 || (ct == 0 && cb == 0)) return 0;
            }
            w[i] += e[id[k]].dir;
            if (!rast__fast_ok(w[i], s)) return 0;
        }
    }
    return 1;
}

/* rast__fast_mixed's test, and its ordinates' (rast__fast_cuts), for a
 * group g[0..m) whose parts tile the strip: by their spans in it, sorted,
 * the first from the strip's top, each from where the one before it ends,
 * the last to the bottom (a chain of a ring's edges through the row: most
 * of a paragraph's groups with a vertex inside the row).  Each slab then
 * holds one edge, no order to check, and the winding on the group's right
 * there is wl plus its direction, which must be 0 or *s (rast__fast_ok)
 * and wr, the winding right of the group at the row's top: 1 when fast,
 * 0 when not (*s as rast__fast_mixed leaves it); -1 when the parts do not
 * tile the strip (nothing changed).  A walk of the edges, not of the slabs
 * times the edges with their cuts sorted in. */
static int rast__fast_chain(const rast__cedge *e, const int32_t *g, int32_t m, int64_t Yj, int32_t p,
                            int32_t wl, int32_t wr, int32_t *s)
{
    int64_t r0[RAST__FAST_MIXED], r1[RAST__FAST_MIXED];
    int32_t k;
    if (m > RAST__FAST_MIXED) return -1;
    for (k = 0; k < m; k++) { /* the spans, by their tops (insertion: a few) */
        const rast__cedge *ed = &e[g[k]];
        const int64_t a = (int64_t)ed->yt - Yj, b = a + ed->dy;
        int32_t q = k;
        for (; q > 0 && r0[q - 1] > a; q--) {
            r0[q] = r0[q - 1];
            r1[q] = r1[q - 1];
        }
        r0[q] = a < 0 ? 0 : a;
        r1[q] = b > p ? p : b;
    }
    if (r0[0] != 0 || r1[m - 1] != p) return -1;
    for (k = 0; k + 1 < m; k++)
        if (r1[k] != r0[k + 1]) return -1;
    for (k = 0; k < m; k++) {
        const int32_t w = wl + e[g[k]].dir;
        if (!rast__fast_ok(w, s) || w != wr) return 0;
    }
    return 1;
}

/* A group too big for rast__fast_mixed (more than RAST__FAST_MIXED edges,
 * or more than RAST__FAST_CUTS ordinates inside the strip): the same test,
 * made as a sweep that only checks.  The edges over the strip are kept in
 * their order (lv[0..n)), the others by the ordinate where they start
 * (pend[]); at each ordinate inside the strip where an edge starts or
 * ends, the edges ending there leave the order and those starting there
 * enter it (by their exact abscissa there, then their slope).  Two edges
 * are neighbours from the ordinate where they become so to the one where
 * they stop (a start or end between them, or the strip's bottom): in order
 * at both (exact), and not equal at both, they do not cross in between,
 * being straight; the first crossing in the strip is between neighbours,
 * so none is missed.  Each entry keeps the winding number right of its
 * edge; after an ordinate's changes the windings are walked again from the
 * leftmost change until past every changed entry and equal to the kept
 * ones (the rest then follows unchanged): every one 0 or s, the last wr.
 * The test's work is its edges' starts and ends and what lies between
 * an ordinate's changes, not slabs times edges.  1 when the group is fast. */
#define RAST__FS_ID(v) ((int32_t)((v) & 0xFFFFFFFFu))
#define RAST__FS_REL(v) ((int64_t)(((v) >> 32) & 0xFFFFF)) /* when the pair became neighbours */
#define RAST__FS_W(v) ((int32_t)(((v) >> 52) & 3) - 1)    /* the winding right of the edge */
#define RAST__FS_EQ ((uint64_t)1 << 55)                    /* the pair equal when it began */

static int rast__fs_cmp(const rast__cedge *a, const rast__cedge *b, int64_t Y)
{
    return rast__fast_cmpn(rast__fast_num(a, Y), a, rast__fast_num(b, Y), b);
}

/* The pair (lv[k], lv[k + 1]) stops being neighbours at Y (rel: Y - Yj): 1
 * when they kept their order since they became neighbours. */
static int rast__fs_close(const rast__cedge *e, const uint64_t *lv, int32_t k, int64_t Y, int64_t rel)
{
    int cm;
    if (RAST__FS_REL(lv[k]) == rel) return 1; /* neighbours for no length */
    cm = rast__fs_cmp(&e[RAST__FS_ID(lv[k])], &e[RAST__FS_ID(lv[k + 1])], Y);
    return cm < 0 || (cm == 0 && !(lv[k] & RAST__FS_EQ));
}

/* lv[k] (k + 1 < n) becomes neighbour of lv[k + 1] at Y (rel). */
static void rast__fs_open(const rast__cedge *e, uint64_t *lv, int32_t k, int64_t Y, int64_t rel)
{
    const uint64_t keep = lv[k] & (0xFFFFFFFFu | ((uint64_t)3 << 52));
    lv[k] = keep | ((uint64_t)rel << 32)
            | (rast__fs_cmp(&e[RAST__FS_ID(lv[k])], &e[RAST__FS_ID(lv[k + 1])], Y) == 0 ? RAST__FS_EQ : 0);
}

/* Edge id, which starts at Y (or is over the strip's top there), into the
 * order lv[0..*n); its position, or -1 when it would lie on a neighbour
 * (collinear) or its neighbours crossed before Y. */
static int32_t rast__fs_insert(const rast__cedge *e, uint64_t *lv, int32_t *n, int32_t id, int64_t Y,
                               int64_t rel)
{
    const rast__cedge *a = &e[id];
    int32_t lo = 0, hi = *n;
    while (lo < hi) { /* the first edge after a */
        const int32_t mid = lo + (hi - lo) / 2;
        const rast__cedge *b = &e[RAST__FS_ID(lv[mid])];
        int cm = rast__fs_cmp(a, b, Y);
        if (cm == 0) {
            const int64_t l = (int64_t)a->dx * b->dy, r = (int64_t)b->dx * a->dy;
            if (l == r) return -1;
            cm = l < r ? -1 : 1;
        }
        if (cm < 0) hi = mid;
        else lo = mid + 1;
    }
    if (lo > 0 && lo < *n && !rast__fs_close(e, lv, lo - 1, Y, rel)) return -1;
    memmove(lv + lo + 1, lv + lo, (size_t)(*n - lo) * sizeof *lv);
    lv[lo] = (uint32_t)id | ((uint64_t)rel << 32) | ((uint64_t)1 << 52);
    (*n)++;
    if (lo > 0) rast__fs_open(e, lv, lo - 1, Y, rel);
    if (lo + 1 < *n) rast__fs_open(e, lv, lo, Y, rel);
    return lo;
}

/* The ordinate sorted by: an edge's top (bot 0) or bottom (bot 1). */
static int64_t rast__fs_key(const rast__cedge *e, int bot)
{
    return (int64_t)e->yt + (bot ? e->dy : 0);
}

/* Edges ids[0..np) by their tops (bot 0) or bottoms (bot 1), all in the
 * strip from Yj (0 < key - Yj < 2^20), ties by id: each packed into room[]
 * as (key - Yj) 2^32 + id, so that the sort compares plain numbers in a
 * row of memory, not edges through their indices; by insertion when
 * few, else a heapsort (any number, no more room). */
static void rast__fs_sort(const rast__cedge *e, int32_t *ids, int32_t np, int bot, int64_t Yj,
                          uint64_t *room)
{
    int32_t end, i;
    for (i = 0; i < np; i++)
        room[i] = ((uint64_t)(rast__fs_key(&e[ids[i]], bot) - Yj) << 32) | (uint32_t)ids[i];
    if (np <= 16) {
        for (i = 1; i < np; i++) {
            const uint64_t v = room[i];
            int32_t q = i;
            for (; q > 0 && room[q - 1] > v; q--) room[q] = room[q - 1];
            room[q] = v;
        }
    } else {
        for (end = np, i = np / 2; end > 1;) {
            int32_t r, ch;
            uint64_t v;
            if (i > 0) {
                r = --i;
            } else {
                v = room[0];
                room[0] = room[--end];
                room[end] = v;
                r = 0;
            }
            v = room[r];
            while ((ch = 2 * r + 1) < end) {
                if (ch + 1 < end && room[ch + 1] > room[ch]) ch++;
                if (room[ch] <= v) break;
                room[r] = room[ch];
                r = ch;
            }
            room[r] = v;
        }
    }
    for (i = 0; i < np; i++) ids[i] = (int32_t)(uint32_t)room[i];
}

/* Where edge id (over the strip at Y, in the order) is in lv[0..n): -1
 * when not found (the order broke: some neighbours crossed). */
static int32_t rast__fs_find(const rast__cedge *e, const uint64_t *lv, int32_t n, int32_t id, int64_t Y)
{
    const rast__cedge *a = &e[id];
    int32_t lo = 0, hi = n;
    while (lo < hi) { /* the first edge not left of a at Y */
        const int32_t mid = lo + (hi - lo) / 2;
        if (rast__fs_cmp(&e[RAST__FS_ID(lv[mid])], a, Y) < 0) lo = mid + 1;
        else hi = mid;
    }
    for (; lo < n; lo++) {
        if (RAST__FS_ID(lv[lo]) == id) return lo;
        if (rast__fs_cmp(&e[RAST__FS_ID(lv[lo])], a, Y) != 0) break;
    }
    return -1;
}

static int rast__fast_sweep(const rast__cedge *e, int32_t *g, int32_t m, int64_t Yj,
                            const rast__cells *c, int32_t wl, int32_t wr, int32_t *s, int32_t *pend,
                            uint64_t *lv)
{
    int32_t n = 0, np = 0, ip = 0, ne = 0, ie = 0, k, lo = 0, hi;
    int64_t rel;
    if (c->p > ((int32_t)1 << 19)) return 0;
    for (k = 0; k < m; k++) { /* the edges starting inside the strip */
        if ((int64_t)e[g[k]].yt > Yj) pend[np++] = g[k];
    }
    for (k = 0; k < m; k++) { /* the edges ending inside it, first in g[] (reordered) */
        const int32_t id = g[k];
        if ((int64_t)e[id].yt + e[id].dy < Yj + c->p) {
            g[k] = g[ne];
            g[ne++] = id;
        }
    }
    rast__fs_sort(e, pend, np, 0, Yj, lv); /* (lv: room until the order is made) */
    rast__fs_sort(e, g, ne, 1, Yj, lv);
    for (k = 0; k < m; k++) /* the order at the top (made in any order: no pair is closed there) */
        if ((int64_t)e[g[k]].yt <= Yj && rast__fs_insert(e, lv, &n, g[k], Yj, 0) < 0) return 0;
    hi = n - 1;
    for (;;) {
        int32_t w = lo > 0 ? RAST__FS_W(lv[lo - 1]) : wl;
        int64_t next = c->p;
        for (k = lo; k < n; k++) { /* the windings from the leftmost change */
            w += e[RAST__FS_ID(lv[k])].dir;
            if (k > hi && w == RAST__FS_W(lv[k])) break; /* the rest as it was */
            if (!rast__fast_ok(w, s)) return 0;
            lv[k] = (lv[k] & ~((uint64_t)3 << 52)) | ((uint64_t)(w + 1) << 52);
        }
        if (k == n && w != wr) return 0;
        if (ie < ne) next = rast__fs_key(&e[g[ie]], 1) - Yj;
        if (ip < np && (int64_t)e[pend[ip]].yt - Yj < next) next = (int64_t)e[pend[ip]].yt - Yj;
        if (next >= c->p) break;
        rel = next;
        lo = n;
        hi = -1;
        while (ie < ne && rast__fs_key(&e[g[ie]], 1) - Yj == rel) { /* the edges ending at rel leave */
            const int64_t Y = Yj + rel;
            const int32_t at = rast__fs_find(e, lv, n, g[ie++], Y);
            if (at < 0) return 0;
            if (at > 0 && !rast__fs_close(e, lv, at - 1, Y, rel)) return 0;
            if (at + 1 < n && !rast__fs_close(e, lv, at, Y, rel)) return 0;
            memmove(lv + at, lv + at + 1, (size_t)(n - at - 1) * sizeof *lv);
            n--;
            if (at > 0 && at < n) rast__fs_open(e, lv, at - 1, Y, rel);
            if (hi > at) hi--;
            if (at > hi) hi = at; /* (the entry now there: its winding may change) */
            if (at - 1 < lo) lo = at > 0 ? at - 1 : 0;
        }
        while (ip < np && (int64_t)e[pend[ip]].yt - Yj == rel) { /* those starting there enter */
            const int32_t at = rast__fs_insert(e, lv, &n, pend[ip++], Yj + rel, rel);
            if (at < 0) return 0;
            if (hi >= at) hi++;
            if (at + 1 > hi) hi = at + 1;
            if (at - 1 < lo) lo = at > 0 ? at - 1 : 0;
        }
        if (lo > n) lo = n;
    }
    for (k = 0; k + 1 < n; k++) /* the strip's bottom */
        if (!rast__fs_close(e, lv, k, Yj + c->p, c->p)) return 0;
    return 1;
}

/* A fast row's parts (rast__fast_range has set them), whole, each with the
 * sign dir * s. */
static void rast__fast_add(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                           int32_t j, int32_t s)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    if (rast__q_may(c, nrow)) {
        for (k = 0; k < nrow; k++) {
            rast__cedge *ed = &e[row[k]];
            rast__q_piece(c, ed, Yj, ed->qa, ed->qta, ed->qb, ed->qtb, ed->dir * s);
        }
        if (rast__q_emit(c, j, nrow)) return;
    }
    rast__area_exact(c, e, row, nrow, j, s);
}

/* The row's edges, as a fast row if it is one: its s (+1 or -1), its parts
 * added, row[] left to right (groups in order, each by its top then its
 * bottom abscissae); else 0, nothing added, the edges' caches valid for the
 * sweep, row[] reordered. */
static int rast__cov_row_fast(rast__cells *c, rast__cedge *e, int32_t *row, int32_t nrow,
                              int32_t j)
{
    const int64_t Yj = (int64_t)j * c->p;
    uint64_t u[RAST__FAST_CUTS + 2];
    int32_t w[RAST__FAST_CUTS + 1];
    int32_t k, g, i, nu = 1, s = 0;
    u[0] = 0;
    for (k = 0; k < nrow; k++) { /* the ends of each part, sorted by lo */
        rast__cedge *ed = &e[row[k]];
        int32_t id = row[k], q = k;
        int64_t lo;
        if (!rast__fast_cuts(ed, Yj, c, u, &nu)) return 0;
        rast__fast_range(ed, j, c);
        lo = ed->qlo;
        while (q > 0 && lo < e[row[q - 1]].qlo) {
            row[q] = row[q - 1];
            q--;
        }
        row[q] = id;
    }
    u[nu++] = T;
    for (i = 0; i + 1 < nu; i++) w[i] = 0;
    for (k = 0; k < nrow; k = g) { /* the groups, left to right */
        int64_t hi = e[row[k]].qhi;
        int32_t full = 1, m;
        for (g = k; g < nrow; g++) {
            const rast__cedge *ed = &e[row[g]];
            if (g > k && ed->qlo >= hi) break;
            if (ed->qhi > hi) hi = ed->qhi;
            if (ed->yt > Yj || (int64_t)ed->yt + ed->dy < Yj + c->p) full = 0;
        }
        m = g - k;
        if (full) { /* the same in every slab: walked once per winding on its left */
            int32_t sum = 0, walked[2] = {0, 0}, z;
            for (z = 0; z < m; z++) sum += e[row[k + z]].dir;
            for (i = 0; i + 1 < nu; i++) {
                int32_t w0 = w[i]; /* 0 or s */
                if (!walked[w0 != 0]) {
                    int32_t ww = w0;
                    if (!rast__fast_full(e, row + k, m, &ww, &s)) return 0;
                    walked[w0 != 0] = 1;
                }
                w[i] = w0 + sum;
                if (!rast__fast_ok(w[i], &s)) return 0;
            }
        } else if (!rast__fast_mixed(e, row + k, m, u, nu, Yj, c, w, &s)) {
            return 0;
        }
    }
    for (i = 0; i + 1 < nu; i++)
        if (w[i] != 0) return 0;
    if (s == 0) return 0;
    rast__fast_add(c, e, row, nrow, j, s);
    return s;
}

/* Under non-zero, do edges g[0..m), the winding number w on their left,
 * bound nothing?  Every winding number among them, anywhere in the strip,
 * is w plus the directions of some of them, so lies in [w + the negative
 * ones, w + the positive ones]; when 0 is not in it, every piece's sign
 * (rast__cov_sign: 0 unless the winding on its left or right is 0) is 0,
 * and the sweep would add nothing (deep inside overlapping shapes). */
static int rast__grp_none(const rast__cedge *e, const int32_t *g, int32_t m, rast_fill_rule rule,
                          int32_t w)
{
    int32_t lo = w, hi = w, k;
    if (rule != RAST_RULE_NONZERO || w == 0) return 0;
#if RAST__SHORTCUTS
    /* w > 0: hi >= w > 0, so lo > 0 decides, and lo only falls: the
     * first prefix that takes it to 0 decides too (w < 0 likewise) */
    if (w > 0) {
        for (k = 0; k < m; k++)
            if (e[g[k]].dir < 0 && (lo += e[g[k]].dir) <= 0) return 0;
        return 1;
    }
    for (k = 0; k < m; k++)
        if (e[g[k]].dir > 0 && (hi += e[g[k]].dir) >= 0) return 0;
    return 1;
#endif
    for (k = 0; k < m; k++) {
        const int32_t d = e[g[k]].dir;
        if (d > 0)
            hi += d;
        else
            lo += d;
    }
    return lo > 0 || hi < 0;
}

/* Is a's abscissa at the strip's bottom less than b's (or equal: *eq)? */
static int rast__grp_below(const rast__cedge *a, const rast__cedge *b, int *eq)
{
    int c = rast__fast_cmpx(a->qb, a->qbr, a, b->qb, b->qbr, b);
    *eq = c == 0;
    return c < 0;
}

/* Groups of more edges than this that are not all full (they start or
 * end inside the strip) are cut into blocks by their lines, too.
 * Size-optimised builds (firmware, -Os) sweep such a group whole, as
 * before: the same levels, 480 B less .text on Cortex-M0. */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__GRP_LINES_MIN 128
#else
#define RAST__GRP_LINES_MIN INT32_MAX
#endif

/* The winding number an edge adds just below the strip's top (Yj): its
 * direction if it reaches there, else 0. */
static int32_t rast__grp_dir_top(const rast__cedge *e, int64_t Yj)
{
    return (int64_t)e->yt <= Yj ? e->dir : 0;
}

/* The group g[0..m)'s edges' lines (not their parts) at the strip's top
 * and bottom, quick units, into qa + qar/dy and qb + qbr/dy, for
 * rast__grp_blocks: an edge that starts inside the strip has its line's
 * top from its bottom's (or its vertex's) and the row's step, one that
 * ends inside its bottom from the top's.  Exact, as the parts' ends are.
 * Only for a group about to be swept: its parts' quick values are not
 * read again in the row. */
#if !defined(__OPTIMIZE_SIZE__)
static void rast__grp_lines(rast__cedge *e, const int32_t *g, int32_t m, int32_t j,
                            const rast__cells *c)
{
    const int32_t hq = QF - (G - c->h);
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    for (k = 0; k < m; k++) {
        rast__cedge *ed = &e[g[k]];
        const int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = rel0 + ed->dy;
        const uint32_t dy = (uint32_t)ed->dy;
        if (rel0 > 0 && rel1 < c->p) { /* both ends inside: the top from its vertex
                                        * (|dx rel0 2^HQ| <= 2^58, as rast__cov_qtop_set) */
            int64_t q, r;
            rast__floordivmod((int64_t)ed->dx * -rel0 * ((int64_t)1 << hq), ed->dy, &q, &r);
            ed->qa = (int64_t)ed->xt * ((int64_t)1 << hq) + q;
            ed->qar = (uint32_t)r;
        } else if (rel0 > 0) { /* the top a row's step above the bottom */
            ed->qa = ed->qb - ed->qxs;
            ed->qar = ed->qbr - ed->qxsr;
            if (ed->qbr < ed->qxsr) {
                ed->qar += dy;
                ed->qa--;
            }
        }
        if (rel1 < c->p) { /* the bottom a row's step below the top */
            ed->qb = ed->qa + ed->qxs;
            ed->qbr = ed->qar + ed->qxsr;
            if (ed->qbr >= dy) {
                ed->qbr -= dy;
                ed->qb++;
            }
        }
    }
}
#endif

/* Under non-zero, does no edge of the block g[0..m) (the winding number w
 * on its left all the way down the strip) bound anything in row j?  Each
 * edge's line lies, across the strip, in [lo, hi) (its abscissae at the
 * top and bottom, quick units, the floor's 1 up: rast__grp_lines; here in
 * 1/256 pixel, lo down and hi up).  An edge f that spans the strip with
 * hi(f) <= lo(e) is left of e wherever e is, so before it in the sweep's
 * order always (the two never swap: their lines do not meet; every
 * insertion is by the exact order); one with lo(f) >= hi(e) is never
 * before it; any other may or may not be, at any moment of the sweep.  So
 * the winding number the sweep gives e's left lies in [w + the first
 * ones' directions + the others' negative ones, ... + their positive
 * ones]; when neither it nor it plus e's direction can be 0, e's sign is 0
 * all the way down (rast__cov_sign).  When every edge's is, the sweep
 * would add nothing: the block is left out, as rast__grp_none leaves out
 * one whose winding numbers are all of one sign.  A finer test than that
 * one, for the blocks at the edge of many overlapping shapes (0 on their
 * left, deep inside further right): on 2,000 canvas-spanning triangles,
 * the sweeps these blocks took were 84% of the row's crossings.  Sorts the
 * block's edges by lo and by hi (radix, the sweep's room, which is free
 * here), then two walks; the edges' qlo and qhi (not read again in the
 * row: the groups after this one read their own) hold each one's sums of
 * the first kind, and they stay there for rast__grp_few, with the keys
 * (sw->wb[id], sw->hidx[id]) and the block by lo (sw->live[0..m)).
 * Returns 0 when no edge may add anything; else how many may (the test
 * failed for them), their ids in sw->h[m - nl .. m) (more than m /
 * RAST__FEW_PER: that many, the scan stopped), or -1 when the test is not
 * made (a small block, even-odd).  w = 0 too (the block at the edge of
 * the shapes, whose leftmost edge may add: its bound holds w, no edge is
 * of the first kind for it): on 10,000 canvas-spanning triangles, blocks
 * of 15,000 edges, the sweep's crossings two thirds of "area"'s time,
 * and most of their edges deep inside.  Size-optimised builds (firmware,
 * -Os) leave it out: the sweep adds the same nothing. */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__DEAD_MIN 16 /* smaller blocks are swept: as cheap */
#define RAST__FEW_PER 8   /* live edges of a block added alone (rast__grp_few) when it has this many edges per live one */
#define RAST__DEAD_SH (QF - 8) /* quick units to 1/256 pixel */

/* floor(v / 2^RAST__DEAD_SH), |v| < 2^62 */
static inline int64_t rast__dead_floor(int64_t v)
{
    return (int64_t)(((uint64_t)v + ((uint64_t)1 << 62)) >> RAST__DEAD_SH) -
           ((int64_t)1 << (62 - RAST__DEAD_SH));
}

RAST__APART int32_t rast__grp_dead(const rast__cells *c, rast__cedge *e, const int32_t *g, int32_t m,
                                   rast__sweep *sw, int32_t j, rast_fill_rule rule, int32_t w)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t *const klo = sw->wb, *const khi = sw->hidx, *const bl = sw->live, *const bh = sw->h;
    int64_t mn = INT64_MAX, mx = INT64_MIN;
    int32_t k, q, pa = 0, na = 0, ps = 0, ns = 0, nl = 0;
    if (rule != RAST_RULE_NONZERO || m < RAST__DEAD_MIN) return -1;
    for (k = 0; k < m; k++) {
        rast__cedge *ed = &e[g[k]];
        const int64_t a = ed->qa < ed->qb ? ed->qa : ed->qb, b = ed->qa < ed->qb ? ed->qb : ed->qa;
        ed->qlo = rast__dead_floor(a);
        ed->qhi = rast__dead_floor(b + ((int64_t)1 << RAST__DEAD_SH)); /* ceil((b + 1) / 2^SH) */
        if (ed->qlo < mn) mn = ed->qlo;
        if (ed->qhi > mx) mx = ed->qhi;
        if (ed->dir > 0)
            pa += ed->dir;
        else
            na += ed->dir;
    }
    if (mx - mn >= ((int64_t)1 << 31)) return -1;
    for (k = 0; k < m; k++) {
        const rast__cedge *ed = &e[g[k]];
        klo[g[k]] = (int32_t)(ed->qlo - mn);
        khi[g[k]] = (int32_t)(ed->qhi - mn);
        bl[k] = bh[k] = g[k];
    }
    rast__cov_radix_sort(bl, (int32_t *)(void *)sw->ct, klo, (uint32_t)m);
    rast__cov_radix_sort(bh, (int32_t *)(void *)sw->ct, khi, (uint32_t)m);
    /* by lo, up: the spanning edges with hi <= lo, their positive and
     * negative directions' sums into qlo, qhi */
    for (k = 0, q = 0; k < m; k++) {
        rast__cedge *ed = &e[bl[k]];
        for (; q < m && khi[bh[q]] <= klo[bl[k]]; q++) {
            const rast__cedge *f = &e[bh[q]];
            if ((int64_t)f->yt <= Yj && (int64_t)f->yt + f->dy >= Yj + c->p) {
                if (f->dir > 0)
                    ps += f->dir;
                else
                    ns += f->dir;
            }
        }
        ed->qlo = ps;
        ed->qhi = ns;
    }
    /* by hi, down: the edges with lo >= hi (their sums ps, ns), and the test */
    for (k = m, q = m, ps = 0, ns = 0; k-- > 0;) {
        const rast__cedge *ed = &e[bh[k]];
        const int32_t d = ed->dir, dp = d > 0 ? d : 0, dn = d > 0 ? 0 : d;
        int32_t lo, hi;
        for (; q > 0 && klo[bl[q - 1]] >= khi[bh[k]]; q--) {
            const int32_t df = e[bl[q - 1]].dir;
            if (df > 0)
                ps += df;
            else
                ns += df;
        }
        /* w + the first kind's sum + the others' negative (positive) ones */
        lo = w + (int32_t)ed->qlo + na - ns - dn;
        hi = w + (int32_t)ed->qhi + pa - ps - dp;
        if (!((lo > 0 || hi < 0) && (lo + d > 0 || hi + d < 0))) { /* it may add something: to
                                                                   * bh's end (read already) */
            bh[m - ++nl] = bh[k];
            if (nl * RAST__FEW_PER > m) return nl;
        }
    }
    return nl;
}

/* Is f before e (see rast__cov_before) just below ordinate Y (fixed
 * units), both reaching below it?  By the sign of their lines' gap there,
 * times e->dy f->dy (cov_cross's N with Y for Yj: 64-bit where its seven
 * factors are small, as there); level there, by their slopes; the same
 * line: tie.  Exact, no division. */
static int rast__few_before(const rast__cedge *e, const rast__cedge *f, int64_t Y, int tie)
{
    const int64_t ex = (int64_t)f->xt - e->xt, ea = (int64_t)e->yt - Y, eb = (int64_t)f->yt - Y;
    const int64_t D = (int64_t)e->dx * f->dy - (int64_t)f->dx * e->dy;
    int sg;
    if ((rast__cov_off(ex) | rast__cov_off(ea) | rast__cov_off(eb) | rast__cov_off(e->dx) |
         rast__cov_off(e->dy) | rast__cov_off(f->dx) | rast__cov_off(f->dy)) < ((uint64_t)1 << 21)) {
        const int64_t n = ex * e->dy * f->dy + ea * e->dx * f->dy - eb * f->dx * e->dy;
        sg = n < 0 ? -1 : n > 0;
    } else {
        rast__i128 N = rast__i128_mul(ex * e->dy, f->dy);
        N = rast__i128_add(N, rast__i128_mul(ea * e->dx, f->dy));
        N = rast__i128_sub(N, rast__i128_mul(eb * f->dx, e->dy));
        sg = rast__i128_neg_p(N) ? -1 : (N.hi | N.lo) != 0;
    }
    if (sg) return sg < 0;
    return D ? D > 0 : tie;
}

/* keys[0..n) ascending (a heap sort: no room needed). */
static void rast__few_sort(uint64_t *a, int32_t n)
{
    int32_t k = n / 2, i, l;
    uint64_t v;
    for (;;) {
        if (k > 0) {
            v = a[--k];
        } else {
            if (--n <= 0) return;
            v = a[n];
            a[n] = a[0];
        }
        for (i = k; (l = 2 * i + 1) < n; i = l) {
            if (l + 1 < n && a[l + 1] > a[l]) l++;
            if (a[l] <= v) break;
            a[i] = a[l];
        }
        a[i] = v;
    }
}

/* What edge f (not ed) does to the winding number on live edge ed's left
 * while ed is in the strip ([t0, t1)): adds its direction to *wl (before
 * ed from t0 on), or keys at key[*nk...] (the moment, and whether the
 * winding goes up there: f starts or ends before ed, or crosses it).
 * elo, ehi: ed's line across the strip, quick units (rast__grp_few). */
static void rast__few_one(const rast__cells *c, const rast__cedge *ed, int32_t id, const rast__cedge *f,
                          int32_t fid, int64_t elo, int64_t ehi, uint64_t t0, uint64_t t1, int64_t Yj,
                          int32_t *wl, uint64_t *key, int32_t *nk)
{
    const int64_t flo = f->qa < f->qb ? f->qa : f->qb, fhi = (f->qa < f->qb ? f->qb : f->qa) + 1;
    uint64_t f0, f1, ts, te, tc, up;
    int before;
    rast__cov_span(f, Yj, c, &f0, &f1);
    if (f1 <= t0 || f0 >= t1) return; /* never beside it */
    ts = f0 > t0 ? f0 : t0;
    te = f1 < t1 ? f1 : t1;
    /* lines apart across the strip (most of a block's, each a floor with
     * its remainder in [0, 1)): that side all the way, no crossing; else
     * the exact test */
    before = fhi < elo ? 1 : flo > ehi ? 0 : rast__few_before(ed, f, Yj + (int64_t)(ts >> c->h), fid < id);
    up = f->dir > 0; /* key: the moment, and whether w goes up there */
    if (before && ts > t0)
        key[(*nk)++] = ts << 1 | up;
    else if (before)
        *wl += f->dir;
    tc = fhi < elo || flo > ehi ? T : before ? rast__cov_cross(f, ed, Yj, 0, c) : rast__cov_cross(ed, f, Yj, 0, c);
    if (tc < te) { /* (after ts: they are apart just below it) */
        before = !before;
        key[(*nk)++] = tc << 1 | (before ? up : !up);
    }
    if (before && te < t1) key[(*nk)++] = te << 1 | !up; /* f ends */
}

/* The block g[0..m) of rast__grp_blocks (the winding number w on its left
 * all the way down the strip, every edge's line across it) where only the
 * nl edges sw->h[m - nl .. m) may add anything (rast__grp_dead: the
 * others' sign is 0 all the way down, whatever the order).  What the sweep
 * gives one of them depends only on the winding number on its left, w plus
 * the directions of the edges before it, and that changes only where
 * another edge starts or ends before it, or crosses it: each live edge
 * alone takes those moments (rast__few_one: an exact side test and
 * rast__cov_cross, the sweep's crossing time, per edge; no abscissa),
 * sorted, and its sign changes there (rast__cov_resign), as in the sweep.
 * Its pieces are the sweep's (moments that fall together, which the
 * sweep takes one after another or at a re-sort, give pieces that differ
 * by less than the grid: the bound holds).  The crossings of the dead
 * edges among themselves, which the sweep must take one by one to keep
 * its order (on 4,000 canvas-spanning triangles, blocks of thousands of
 * edges and one live edge: half of all the crossings), are not looked at.
 *
 * Nor are the edges whose lines lie apart from a live edge's: of an edge
 * that spans the strip, with its line's keys [lo, hi) (rast__grp_dead's,
 * 1/256 pixel) wholly left of the live edge's lo, only its direction
 * counts, and rast__grp_dead's sums hold them all (qlo + qhi: those with
 * hi <= lo); one wholly right of its hi adds nothing.  So the block's
 * spanning edges narrower than 2^b (keys) are taken by lo (sw->live, by
 * rast__grp_dead's sort), from lo - 2^b to hi: an edge left of that has
 * hi < lo, in the sums, apart (strictly: rast__few_one adds its direction
 * too); the wider ones and those that start or end inside the strip (not
 * in the sums) after them, each looked at.  b makes the two parts' work
 * least (a count of widths by bit length).  Each edge looked at that is
 * in the sums is taken out of them first.  On 10,000 canvas-spanning
 * triangles, blocks of thousands of edges and up to hundreds of live
 * ones: a live edge's work is the edges near it, not the block's.
 * Returns 0, nothing done, when the keys may not fit the room. */
RAST__APART int rast__grp_few(rast__cells *c, rast__cedge *e, const int32_t *g, int32_t m,
                              rast__sweep *sw, int32_t j, rast_fill_rule rule, int32_t w, int32_t nl)
{
    const int64_t Yj = (int64_t)j * c->p;
    uint64_t *const key = sw->ct;
    const int32_t *const few = sw->h + (m - nl), *const klo = sw->wb, *const khi = sw->hidx;
    int32_t *const bl = sw->live;
    int32_t i, k, ninner = 0, nr = 0, nx = 0, b = 0;
    int32_t cnt[33];
    int64_t best = INT64_MAX, span, nfull;
    for (k = 0; k < 33; k++) cnt[k] = 0;
    for (k = 0; k < m; k++) { /* each edge: a key for a start, a crossing, an end; at most two */
        const rast__cedge *f = &e[g[k]];
        const int in = (int64_t)f->yt > Yj || (int64_t)f->yt + f->dy < Yj + c->p;
        uint32_t wd = (uint32_t)(khi[g[k]] - klo[g[k]]);
        int32_t bits = 0;
        if (f->dir != 1 && f->dir != -1) return 0;
        ninner += in;
        while (wd) {
            bits++;
            wd >>= 1;
        }
        if (!in) cnt[bits]++;
    }
    if ((int64_t)m + ninner > sw->room) return 0;
    /* b: least (wider ones, each looked at) + (spanning ones) 2^b / (the
     * keys' span) (those in a window of 2^b, about) */
    span = (int64_t)klo[bl[m - 1]] - klo[bl[0]] + 1;
    nfull = m - ninner;
    for (k = 0, i = 0; k <= 32; k++) { /* i: the spanning ones of width >= 2^k */
        int64_t wide = nfull, cost;
        int32_t q;
        for (q = 0; q <= k; q++) wide -= cnt[q];
        cost = wide + (k >= 31 ? nfull : (nfull << k) / span);
        if (cost < best) {
            best = cost;
            b = k;
        }
    }
    /* bl: the spanning ones narrower than 2^b (by lo), then the others
     * (through the keys' room, free until the first live edge's) */
    for (k = 0; k < m; k++) {
        const int32_t id = bl[k];
        const rast__cedge *f = &e[id];
        if ((int64_t)f->yt <= Yj && (int64_t)f->yt + f->dy >= Yj + c->p &&
            (int64_t)khi[id] - klo[id] < ((int64_t)1 << b))
            bl[nr++] = id;
        else
            key[nx++] = (uint64_t)id;
    }
    for (k = 0; k < nx; k++) bl[nr + k] = (int32_t)key[k];
    rast__area_steps(e, few, nl);
    for (i = 0; i < nl; i++) {
        const int32_t id = few[i];
        rast__cedge *ed = &e[id];
        /* its line across the strip, quick units: [elo, ehi] */
        const int64_t elo = ed->qa < ed->qb ? ed->qa : ed->qb, ehi = (ed->qa < ed->qb ? ed->qb : ed->qa) + 1;
        const int64_t from = (int64_t)klo[id] - ((int64_t)1 << b);
        uint64_t t0, t1;
        int32_t wl = w + (int32_t)(ed->qlo + ed->qhi), nk = 0, lo = 0, hi = nr;
        rast__cov_span(ed, Yj, c, &t0, &t1);
        while (lo < hi) { /* the first narrow one with lo >= from */
            const int32_t mid = lo + (hi - lo) / 2;
            if (klo[bl[mid]] < from)
                lo = mid + 1;
            else
                hi = mid;
        }
        for (k = lo; k < m; k++) { /* the narrow ones near it, then the others */
            const int32_t fid = bl[k];
            const rast__cedge *f = &e[fid];
            if (k < nr && klo[fid] > khi[id]) {
                k = nr - 1;
                continue;
            }
            if (fid == id) continue;
            if ((k < nr || ((int64_t)f->yt <= Yj && (int64_t)f->yt + f->dy >= Yj + c->p)) && khi[fid] <= klo[id])
                wl -= f->dir; /* in the sums: out */
            rast__few_one(c, ed, id, f, fid, elo, ehi, t0, t1, Yj, &wl, key, &nk);
        }
        rast__few_sort(key, nk);
        if (ed->rowx != j || ed->tx != t0) {
            rast__cov_x_at(ed, Yj, t0, c->h, &ed->x, &ed->r);
            ed->rowx = j;
            ed->tx = t0;
        }
        ed->sg = rast__cov_sign(rule, wl, ed->dir);
        for (k = 0; k < nk;) { /* its moments: the sign after each */
            const uint64_t tk = key[k] >> 1;
            for (; k < nk && key[k] >> 1 == tk; k++) wl += (key[k] & 1) ? 1 : -1;
            rast__cov_resign(c, ed, Yj, j, tk, rast__cov_sign(rule, wl, ed->dir));
        }
        rast__cov_x_end(ed, Yj, ed->tx, t1, c->h);
        if (ed->sg) rast__cells_piece(c, ed, Yj, ed->x, ed->tx, ed->xn, t1, ed->sg);
        rast__cov_x_keep(ed, j, t1);
    }
    return 1;
}
#endif

/* A group g[0..m) whose edges' lines all span the strip (the edges
 * themselves, or their lines: rast__grp_lines), whatever the winding
 * number w on its left (deep inside overlapping shapes, say).  Sorted by
 * their abscissae at the strip's top, then bottom, they fall into blocks:
 * a cut goes after position i when every edge left of it is, at the
 * bottom, left of every edge right of it (or level with it, their tops
 * apart): edges of two blocks are in order at the top and the bottom,
 * so they do not meet inside the row (straight lines), and the winding
 * number on a block's left is w plus the directions before it, all the
 * way down.  A block of one edge is what the sweep would make of it, no
 * event in the row: one piece, top to bottom, with the sign
 * rast__cov_sign gives from that winding (none where it is 0: under
 * non-zero, an edge between two non-zero windings bounds nothing), added
 * by the sweep's own cells; a block of several (edges that cross, or
 * coincide) is swept alone from its winding (only its edges can cross
 * each other).  So the sweep's work is where the crossings are, not the
 * group's.  Each edge's sg holds, until its block is done, the position
 * of the suffix's lowest bottom (the sweep sets sg afresh).
 *
 * lines: some edges start or end inside the strip (a group of no
 * horizontal run: rast__cov_row_groups), and the blocks are cut by the
 * edges' lines across the whole strip (rast__grp_lines).  Two blocks'
 * lines are still apart inside the strip, so their edges (parts of them)
 * do not meet, and a path between the blocks, top to bottom, crosses no
 * edge: the winding number along it is one number, the one just below
 * the top, w plus the directions of the edges before it that reach the
 * top (rast__grp_dir_top); the sweep of a block, and an edge alone, take
 * it as theirs.  Where many edges cross in a row, the group of its
 * columns is the whole row (their columns overlap) while most crossings
 * lie deep inside, in blocks that add nothing (on 2,000 canvas-spanning
 * triangles the sweep took 9 in 10 of them).  Out of line: inlined, it
 * crowds rast__cov_row_groups, whose own helpers then are not. */
static void rast__grp_blocks(rast__cells *c, rast__cedge *e, int32_t *g, int32_t m,
                                  rast__sweep *sw, int32_t j, rast_fill_rule rule, int32_t w, int lines)
{
    const int64_t Yj = (int64_t)j * c->p;
    /* the tops' abscissae' floors by position, for the sort (the sweep's
     * room, free until a block is swept): an inversion costs a step along
     * one array, not an edge's load (on 10,000 canvas-spanning triangles,
     * 30,000 edges, 10 MB, their rows' order changes by a row's crossings:
     * the loads were a third of "area"'s time; size-optimised builds,
     * firmware, -Os: through the edges, as before, 136 B less on
     * Cortex-M0) */
    int64_t *const ka = (int64_t *)(void *)sw->ct;
    int32_t k, b0, mx;
    int eq;
#if !defined(__OPTIMIZE_SIZE__)
    if (lines) rast__grp_lines(e, g, m, j, c);
#else
    (void)lines;
#endif
    for (k = 0; RAST__SHORTCUTS && k < m; k++) ka[k] = e[g[k]].qa;
    for (k = 1; k < m; k++) { /* by top, then bottom (insertion: few inversions) */
        const int32_t id = g[k];
        const int64_t x = RAST__SHORTCUTS ? ka[k] : 0;
        int32_t q = k;
        const rast__cedge *a = &e[id];
        while (q > 0 && (!RAST__SHORTCUTS || ka[q - 1] >= x)) {
            if (!RAST__SHORTCUTS || ka[q - 1] == x) { /* (the keys' floors equal: the exact order) */
                const rast__cedge *b = &e[g[q - 1]];
                int ct = rast__fast_cmpx(a->qa, a->qar, a, b->qa, b->qar, b);
                if (ct > 0 || (ct == 0 && rast__fast_cmpx(a->qb, a->qbr, a, b->qb, b->qbr, b) >= 0)) break;
            }
            g[q] = g[q - 1];
            if (RAST__SHORTCUTS) ka[q] = ka[q - 1];
            q--;
        }
        g[q] = id;
        if (RAST__SHORTCUTS) ka[q] = x;
    }
    e[g[m - 1]].sg = m - 1;
    for (k = m - 2; k >= 0; k--) { /* the lowest bottom from k on */
        const int32_t n1 = e[g[k + 1]].sg;
        e[g[k]].sg = rast__grp_below(&e[g[k]], &e[g[n1]], &eq) ? k : n1;
    }
    for (b0 = 0, mx = 0, k = 0; k < m; k++) {
        int cut = k + 1 == m;
        if (rast__grp_below(&e[g[mx]], &e[g[k]], &eq) || eq) mx = k; /* the block's highest bottom */
        if (!cut) {
            const rast__cedge *a = &e[g[mx]], *b = &e[g[e[g[k + 1]].sg]];
            cut = rast__grp_below(a, b, &eq) ||
                  (eq && rast__fast_cmpx(e[g[k]].qa, e[g[k]].qar, &e[g[k]], e[g[k + 1]].qa,
                                         e[g[k + 1]].qar, &e[g[k + 1]]) < 0);
        }
        if (!cut) continue;
        if (k == b0) {
            const int32_t dir = e[g[k]].dir, sg = rast__cov_sign(rule, w, dir);
            if (sg) rast__area_exact(c, e, g + k, 1, j, sg * dir); /* sign dir (sg dir) = sg */
            w += rast__grp_dir_top(&e[g[k]], Yj);
        } else {
            int32_t z, w1 = w;
            for (z = b0; z <= k; z++) w1 += rast__grp_dir_top(&e[g[z]], Yj);
            if (!rast__grp_none(e, g + b0, k + 1 - b0, rule, w)
#if !defined(__OPTIMIZE_SIZE__)
                && (k - b0 > 2 || !rast__area_small(c, e, g + b0, k + 1 - b0, j, rule, w)) /* (they span the row) */
#endif
            ) {
#if !defined(__OPTIMIZE_SIZE__)
                const int32_t mb = k + 1 - b0, nl = rast__grp_dead(c, e, g + b0, mb, sw, j, rule, w);
                if (nl != 0 && !(nl > 0 && nl * RAST__FEW_PER <= mb &&
                                 rast__grp_few(c, e, g + b0, mb, sw, j, rule, w, nl)))
#endif
                    rast__area_sweep(c, e, g + b0, k + 1 - b0, sw, j, rule, w, RAST__SHORTCUTS);
            }
            w = w1;
        }
        b0 = k + 1;
        mx = b0;
    }
}

/* A row that is not fast as a whole, group by group.  Its edges' quick
 * ranges [qlo, qhi) (by their columns), and the runs of horizontal edges strictly inside its
 * strip (fixed units, rs[0..nrun), sorted here by their left ends) and joined
 * where they overlap, make groups; between two groups no part and no run
 * meets the strip, so the winding number there is one number all the way
 * down the strip: the one just below the row's top, the sum of the
 * directions of the edges on its left that cross that line (top closed).
 * Each group alone is then fast (the tests of rast__cov_row_fast, with the
 * group's own ordinates where an edge starts or ends, the windings walked
 * from the one on its left), its parts added whole, or swept alone
 * (rast__cov_row_area from that winding number): the sweep's work is the
 * group's, not the row's.  All by the exact cells; the caller emits. */
/* Column of quick abscissa v, clamped to [x0 - 1, x1]: a key >= 0 from x0 - 1. */
static inline int32_t rast__grp_col(const rast__cells *c, int64_t v)
{
    const int64_t col = rast__q_col(v);
    return col < c->x0 ? 0 : col > c->x1 ? c->x1 - c->x0 + 1 : (int32_t)(col - c->x0) + 1;
}

/* rast__grp_col(c, a) <= rast__grp_col(c, b), without the keys: the
 * clamp to [x0 - 1, x1] is monotone, so it holds when a's column is not
 * past b's, or when the clamp makes them one (both left of x0, or both at
 * or past x1). */
static inline int rast__grp_col_le(const rast__cells *c, int64_t a, int64_t b)
{
#if RAST__SHORTCUTS
    const int64_t ca = rast__q_col(a), cb = rast__q_col(b);
    return ca <= cb || ca < c->x0 || cb >= c->x1;
#else /* (size-optimised builds: the two columns, as before; 200 B less on Cortex-M0) */
    return rast__grp_col(c, a) <= rast__grp_col(c, b);
#endif
}

/* The groups kept by rast__cov_row_groups (sw->h: where each starts in
 * row[]; sw->live: its edge count times 2, plus 1 for sign +1), added the
 * exact way. */
static void rast__grp_flush(rast__cells *c, rast__cedge *e, int32_t *row, const rast__sweep *sw,
                            int32_t nk, int32_t j)
{
    int32_t g;
    for (g = 0; g < nk; g++)
        rast__area_exact(c, e, row + sw->h[g], sw->live[g] >> 1, j, (sw->live[g] & 1) ? 1 : -1);
}

#if RAST__SHORTCUTS
/* ---- quick groups in a swept row
 *
 * Once a row sweeps a group, its cells are the exact ones (rast__cells):
 * the fast groups after it were added the exact way too (tri3k: a swept
 * group in nearly every row, 21,573 fast groups through rast__row_exact,
 * 11 M instructions of 67 M).  They go to the quick cells instead
 * (rast__q_piece, the same arrays: a quick cell's cover and area in
 * cover[].lo and cover[].hi), since no column holds both kinds: the
 * groups' columns lie apart (rast__cov_row_groups), and a group's cells,
 * quick or exact, lie in its parts' columns, from its least qlo's column to
 * its greatest qhi - 1's (the exact abscissa's column is its quick floor's;
 * a piece's abscissae lie between its part's ends).  rast__grp_emit walks
 * the row's cells once, with one cover so far (U): the exact cells' plus
 * the quick cells' times 2^30 (QT to T); each column the way its group was
 * added:
 *   - an exact column (and a run between cells): the exact way
 *     (rast__cells_a62).  The quick part of the cover is exact there: every
 *     quick part lies wholly left or right of such a column (a quick
 *     group's columns are all marked, rast__q_add), and a whole part's
 *     quick cover is its exact height (see the quick accumulation).
 *   - a quick column: the quick way (rast__q_run), from the cover over
 *     2^30, which is exact: the exact groups lie wholly left or right of
 *     the column, and each adds its whole height, a multiple of T (the
 *     winding number between groups is one number down the strip, so the
 *     cover there is T or 0 past the clip's carry, which the group of the
 *     clip's left end holds), the quick cells their own 2^-30 units.  The
 *     value then differs from the exact one by the quick group's error
 *     alone (under n 2^-28, n its parts: the bound of the quick
 *     accumulation, with the window of the most parts of a quick group).
 * Where a level is not certain, the quick groups are added again the exact
 * way (their quick cells are cleared by then; the exact ones are kept
 * until the row is done) and rast__cells_emit writes the row: the levels
 * are the exact way's either way. */
#define RAST__GRP_QUICK 128 /* quick groups a row at most (room on the stack); the others exact */
typedef struct rast__qgrp {
    int32_t k, ms;  /* its parts row[k .. k + ms / 2), sign +1 when ms is odd */
    int32_t lo, hi; /* its clip columns (indices from x0): [lo, hi] */
} rast__qgrp;

/* Group row[k .. k + m), sign s, into the quick cells; its record into *q. */
static void rast__grp_quick(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t k, int32_t m,
                            int32_t s, int32_t j, rast__qgrp *q)
{
    const int64_t Yj = (int64_t)j * c->p;
    int64_t lo = 0, hi = 0;
    int32_t z;
    for (z = k; z < k + m; z++) {
        rast__cedge *ed = &e[row[z]];
        rast__q_piece(c, ed, Yj, ed->qa, ed->qta, ed->qb, ed->qtb, ed->dir * s);
        if (z == k || ed->qlo < lo) lo = ed->qlo;
        if (z == k || ed->qhi > hi) hi = ed->qhi;
    }
    lo = rast__q_col(lo) - c->x0;
    hi = rast__q_col(hi - 1) - c->x0;
    q->k = k;
    q->ms = m * 2 + (s > 0);
    q->lo = lo < 0 ? 0 : lo > c->x1 - c->x0 ? c->x1 - c->x0 : (int32_t)lo;
    q->hi = hi < -1 ? -1 : hi > c->x1 - c->x0 ? c->x1 - c->x0 : (int32_t)hi;
}

/* Row y from the exact cells and the quick groups' cells q[0..nq) (by
 * column; most: the most parts one has), above: 1 when written (handed
 * on, every cell cleared), 0 when a level is not certain (the quick cells
 * and qcarry cleared, the exact ones kept). */
static int rast__grp_emit(rast__cells *c, int32_t y, const rast__qgrp *q, int32_t nq, int32_t most)
{
    const rast__cov_out *o = c->o;
    const rast_coverage_format f = o->format;
    const int u8 = f == RAST_COVERAGE_U8;
    const uint64_t win = ((uint64_t)most + 1) * c->quick << 24;
    const rast__i128 zero = rast__i128_u64(0);
    unsigned char *row = rast__cov_row(o, y);
    /* the cover so far (U): the exact cells' plus the quick ones' times 2^30 */
    rast__i128 acc = rast__i128_add(c->carry, rast__i128_shl(rast__i128_from((int64_t)c->qcarry), 30));
    uint64_t bad = 0;
    int32_t k = 0, wi, gi = 0;
    for (wi = c->wmin; wi <= c->wmax; wi++) {
        uint64_t b;
        for (b = c->bits[wi]; b; b &= b - 1) {
            const int32_t col = (wi << 6) + (int32_t)rast__ctz64(b);
            if (k < col) rast__cov_fill(f, row, k, col, rast__cov_level(f, rast__cells_a62(c, acc, zero, c->rule)));
            while (gi < nq && q[gi].hi < col) gi++;
            if (gi < nq && q[gi].lo <= col) { /* quick: acc a multiple of 2^30 (above) */
                acc = rast__i128_add(acc, rast__i128_shl(rast__i128_from((int64_t)c->cover[col].lo), 30));
                rast__q_run(c, row, col, col + 1, (rast__i128_sar(acc, 30).lo << 21) - c->cover[col].hi, win, u8,
                            &bad);
                c->cover[col].lo = c->cover[col].hi = 0;
            } else {
                acc = rast__i128_add(acc, c->cover[col]);
                rast__cov_store(f, row, col, rast__cov_level(f, rast__cells_a62(c, acc, c->area[col], c->rule)));
            }
            k = col + 1;
        }
    }
    if (k < c->x1 - c->x0)
        rast__cov_fill(f, row, k, c->x1 - c->x0, rast__cov_level(f, rast__cells_a62(c, acc, zero, c->rule)));
    c->qcarry = 0;
    if (bad) return 0;
    for (wi = c->wmin; wi <= c->wmax; wi++) {
        uint64_t b;
        for (b = c->bits[wi]; b; b &= b - 1) {
            const int32_t col = (wi << 6) + (int32_t)rast__ctz64(b);
            c->cover[col] = c->area[col] = zero;
        }
        c->bits[wi] = 0;
    }
    rast__cov_row_done(o, y);
    c->carry = zero;
    c->wmin = INT32_MAX;
    c->wmax = -1;
    c->emitted = 1;
    return 1;
}

/* row[0..n) by key (in [0, kmax]), stably: the order rast__cov_radix_sort
 * gives.  One counting pass by the key's top 7 bits into tmp (room for
 * n), then an insertion sort back into row, a few moves an edge (a row's
 * edges lie apart, a few in 8 columns at 512 wide); when the moves run
 * past that (many edges in a few columns), the radix sort finishes.  Both
 * steps are stable, so the order is the radix sort's whether it finishes
 * or not (a stable sort of one sequence by one key gives one order, and a
 * stable sort by a part of the key, or of a prefix, keeps the order of
 * equal keys).  Text: the radix sort's two passes of 256 counts a row
 * took 6% of "area" (issue 33).  Returns 1 when the radix sort finished. */
static int rast__grp_sort(int32_t *row, int32_t n, int32_t *tmp, const int32_t *key, int32_t kmax)
{
    uint32_t cnt[128], sum = 0, sh = 0;
    int32_t k, budget = 2 * n + 16;
    while ((kmax >> sh) >= 128) sh++;
    for (k = 0; k < 128; k++) cnt[k] = 0;
    for (k = 0; k < n; k++) cnt[key[row[k]] >> sh]++;
    for (k = 0; k < 128; k++) {
        const uint32_t c = cnt[k];
        cnt[k] = sum;
        sum += c;
    }
    for (k = 0; k < n; k++) tmp[cnt[key[row[k]] >> sh]++] = row[k];
    for (k = 0; k < n; k++) {
        const int32_t id = tmp[k], kx = key[id];
        int32_t q = k;
        for (; q > 0 && key[row[q - 1]] > kx; q--) row[q] = row[q - 1];
        row[q] = id;
        budget -= k - q;
        if (budget < 0) {
            for (q = k + 1; q < n; q++) row[q] = tmp[q];
            rast__cov_radix_sort(row, tmp, key, (uint32_t)n);
            return 1;
        }
    }
    return 0;
}

/* row[0..n) by key, stably, when row[0..nold) are the last row's edges
 * still in it, in the order it left them (by their keys then, which move
 * little from row to row), and row[nold..n) the new ones: an insertion of
 * each part, then one merge (tmp: room for n - nold).  Returns 0 when the
 * insertion of the old part runs past its budget or the new part is long
 * (nothing gained): then row[] is the same sequence but for some moves of
 * an edge past greater keys, so that any stable sort of it gives the order
 * a stable sort of the original gives (the same relative order of equal
 * keys), which the caller's sorts then give.  tri3k: the counting pass and
 * the insertion of rast__grp_sort were 5,000 instructions a row. */
static int rast__grp_merge(int32_t *row, int32_t n, int32_t nold, int32_t *tmp, const int32_t *key)
{
    int32_t k, q, budget = nold + 16, nn = n - nold, out;
    if (nn > 64) return 0;
    for (k = 1; k < nold; k++) {
        const int32_t id = row[k], kx = key[id];
        for (q = k; q > 0 && key[row[q - 1]] > kx; q--) row[q] = row[q - 1];
        row[q] = id;
        budget -= k - q;
        if (budget < 0) return 0;
    }
    for (k = 0; k < nn; k++) { /* the new part, by insertion into tmp */
        const int32_t id = row[nold + k], kx = key[id];
        for (q = k; q > 0 && key[tmp[q - 1]] > kx; q--) tmp[q] = tmp[q - 1];
        tmp[q] = id;
    }
    for (out = n - 1, k = nold - 1, q = nn - 1; q >= 0; out--) /* from the end: a new edge after an old one of its key */
        row[out] = k >= 0 && key[row[k]] > key[tmp[q]] ? row[k--] : tmp[q--];
    return 1;
}

/* row[0..n) by key (in [0, kmax]) in one stable counting pass (cnt: room
 * for kmax + 1 counts, tmp for n): again the order rast__cov_radix_sort
 * gives (one stable order by one key).  Where a row's parts are many for
 * its columns (one for every RAST__GRP_COUNT of them or more), this costs less
 * than the insertion above, whose moves grow with the parts a column, and
 * than the radix sort's two passes of 256 counts (keys past 255 at 512
 * wide): canvas-spanning triangles sorted 1,300 parts a row by insertion
 * at about 50,000 instructions a row. */
#define RAST__GRP_COUNT 3
static void rast__grp_count(int32_t *row, int32_t n, int32_t *tmp, uint32_t *cnt, const int32_t *key,
                            int32_t kmax)
{
    uint32_t sum = 0;
    int32_t k;
    for (k = 0; k <= kmax; k++) cnt[k] = 0;
    for (k = 0; k < n; k++) cnt[key[row[k]]]++;
    for (k = 0; k <= kmax; k++) {
        const uint32_t c = cnt[k];
        cnt[k] = sum;
        sum += c;
    }
    for (k = 0; k < n; k++) tmp[cnt[key[row[k]]]++] = row[k];
    memcpy(row, tmp, (size_t)n * sizeof *row);
}
#endif

static void rast__cov_row_groups(rast__cells *c, rast__cedge *e, int32_t *row, int32_t nrow,
                                 int32_t nold, rast__sweep *sw, int32_t j, rast_fill_rule rule,
                                 int32_t *rs, int32_t nrun, int acc)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t *const key = sw->wb; /* (the sweep's room: the sort's keys, not read after it) */
    /* swept: the exact cells for every group from then on; from the start
     * when the last row swept a group, which this one then likely does too */
    int32_t k, g, pz, r = 0, wl = 0, swept = sw->swept;
    /* the groups kept for the quick way, and the most parts one of them
     * has: every column is met by one group's parts at most (their columns
     * lie apart), so the quick values' error at a pixel is that group's,
     * not the row's (see the quick accumulation) */
    int32_t nk = 0, most = 0, ngrp = 0;
#if RAST__SHORTCUTS
    rast__qgrp qg[RAST__GRP_QUICK]; /* the quick groups once swept (above), and their most parts */
    int32_t nq = 0, qmost = 0;
#endif
    sw->swept = 0;
    for (k = 0; k < nrow; k++) { /* the parts' ranges, their first columns as keys */
        rast__cedge *ed = &e[row[k]];
        rast__fast_range(ed, j, c);
        key[row[k]] = rast__grp_col(c, ed->qlo);
    }
    if (nrow > 48) {
#if RAST__SHORTCUTS
        /* many parts for the columns: one counting pass (the keys' counts
         * in ct, free here: no group is being swept); else after a row
         * whose insertion ran past its budget (1 returned), the radix sort
         * alone (the same order) but every eighth row: on a stroke's dense
         * rows the insertion's moves, then the radix sort, took 2.3 M
         * instructions of 90 M */
        const int32_t kmax = c->x1 - c->x0 + 1;
        if ((int64_t)nrow * RAST__GRP_COUNT >= kmax && kmax < 2 * (int64_t)sw->room)
            rast__grp_count(row, nrow, sw->hidx, (uint32_t *)(void *)sw->ct, key, kmax);
        else if (!(sw->unsorted && (j & 7)) && rast__grp_merge(row, nrow, nold, sw->hidx, key))
            sw->unsorted = 0; /* (the last row's order, the new edges merged in) */
        else if (sw->unsorted && (j & 7))
            rast__cov_radix_sort(row, sw->hidx, key, (uint32_t)nrow);
        else
            sw->unsorted = rast__grp_sort(row, nrow, sw->hidx, key, c->x1 - c->x0 + 1);
#else
        (void)nold;
        rast__cov_radix_sort(row, sw->hidx, key, (uint32_t)nrow);
#endif
    } else {
        for (k = 1; k < nrow; k++) {
            int32_t id = row[k], q = k;
            while (q > 0 && key[id] < key[row[q - 1]]) {
                row[q] = row[q - 1];
                q--;
            }
            row[q] = id;
        }
    }
    for (k = 1; k < nrun; k++) { /* the runs by their left end (in place: no later row reads them) */
        int32_t id = rs[k], q = k;
        while (q > 0 && e[id].hx0 < e[rs[q - 1]].hx0) {
            rs[q] = rs[q - 1];
            q--;
        }
        rs[q] = id;
    }
    for (k = 0; k < nrow; k = g) {
        int32_t wr = wl, m, full = 1, s = wl, z, r0 = r;
        /* hq: the greatest qhi - 1 of the group's parts (and its runs' right
         * ends, quick units): its columns reach rast__grp_col(hq), the keys'
         * way; a part joins when its qlo's column is not past that one,
         * surely so when qlo <= hq (the columns, monotone), and only else
         * by the columns (no key, nor column, per joining part: a row of a
         * thousand triangles spanning the canvas, one group, took 15 M
         * instructions in them; and a sweep uses the keys' room) */
        int64_t hq = 0;
        for (g = k;; g++) { /* the group: row[k..g), the columns up to hq's; its windings */
            if (g < nrow && (g == k || e[row[g]].qlo <= hq || rast__grp_col_le(c, e[row[g]].qlo, hq))) {
                const int64_t q = e[row[g]].qhi - 1;
                if (g == k || q > hq) hq = q;
#if RAST__SHORTCUTS
                /* its windings as it joins (once: after a run joins, g is
                 * tried again), from its part's ends (rast__fast_range,
                 * above): the part starts at the row's top (qta 0) when the
                 * edge reaches it, and ends at the bottom (qtb QT) when it
                 * reaches that; every edge of the row ends below its top */
                {
                    const rast__cedge *ed = &e[row[g]];
                    if (ed->qta == 0) wr += ed->dir;
                    if (ed->qta != 0 || ed->qtb != QT) full = 0;
                }
#endif
                continue;
            }
            if (r < nrun && rast__grp_col_le(c, (int64_t)e[rs[r]].hx0 * ((int64_t)1 << (QF - (G - c->h))), hq)) {
                const int64_t q = (int64_t)e[rs[r]].hx1 * ((int64_t)1 << (QF - (G - c->h)));
                if (q > hq) hq = q; /* a run joins the group */
                r++;
                g--;
                continue;
            }
            break;
        }
        m = g - k;
        ngrp++;
#if !RAST__SHORTCUTS /* (size-optimised builds: the windings in a pass of their own, as before) */
        for (z = k; z < g; z++) {
            const rast__cedge *ed = &e[row[z]];
            if (ed->yt <= Yj && (int64_t)ed->yt + ed->dy > Yj) wr += ed->dir;
            if (ed->yt > Yj || (int64_t)ed->yt + ed->dy < Yj + c->p) full = 0;
        }
#endif
        if (s < -1 || s > 1) {
            s = 2; /* not fast */
        } else if (full) {
            int32_t ww = wl;
            if (RAST__SHORTCUTS && m == 1) { /* one edge, nothing to order: rast__fast_full's walk, inline */
                ww += e[row[k]].dir; /* (text: half its groups, a stroke's side alone in its columns) */
                if (!rast__fast_ok(ww, &s) || ww != wr) s = 2;
            } else if (!rast__fast_full(e, row + k, m, &ww, &s) || ww != wr) {
                s = 2;
            }
        } else if (RAST__SHORTCUTS && (z = rast__fast_chain(e, row + k, m, Yj, c->p, wl, wr, &s)) >= 0) {
            if (!z) s = 2;
        } else {
            uint64_t u[RAST__FAST_CUTS + 2];
            int32_t w[RAST__FAST_CUTS + 1], nu = 1, i;
            u[0] = 0;
            int32_t big = m > RAST__FAST_MIXED;
            for (z = k; z < g && s != 2 && !big; z++) /* the group's ordinates inside */
                big = !rast__fast_cuts(&e[row[z]], Yj, c, u, &nu);
            if (big) { /* (the sweep's room is free here: no group is being swept) */
                if (!rast__fast_sweep(e, row + k, m, Yj, c, wl, wr, &s, sw->hidx, sw->ct)) s = 2;
            } else if (s != 2) {
                u[nu++] = T;
                for (i = 0; i + 1 < nu; i++) w[i] = wl;
                if (!rast__fast_mixed(e, row + k, m, u, nu, Yj, c, w, &s)) s = 2;
                for (i = 0; i + 1 < nu && s != 2; i++)
                    if (w[i] != wr) s = 2;
            }
        }
        if (s == 2 && rast__grp_none(e, row + k, m, rule, wl)) s = 0; /* nothing to add */
        if (s == 2 && !swept) { /* the exact cells from here on: the groups kept so far first */
            rast__grp_flush(c, e, row, sw, nk, j);
            nk = 0;
            swept = 1;
        }
        if (s == 2 && (full || (r == r0 && m > RAST__GRP_LINES_MIN))) {
            rast__grp_blocks(c, e, row + k, m, sw, j, rule, wl, !full);
            sw->swept = 1;
            s = 0; /* done */
        }
        if (s == 2) {
            rast__area_sweep(c, e, row + k, m, sw, j, rule, wl, RAST__SHORTCUTS);
            sw->swept = 1;
        } else if (s != 0 && swept) {
#if RAST__SHORTCUTS
            if (nq < RAST__GRP_QUICK && rast__q_may(c, m > qmost ? m : qmost)) {
                rast__grp_quick(c, e, row, k, m, s, j, &qg[nq++]);
                if (m > qmost) qmost = m;
            } else
#endif
                rast__area_exact(c, e, row + k, m, j, s);
        } else if (s != 0) { /* kept: group nk starts at k, m edges, sign s */
            sw->h[nk] = k;
            sw->live[nk++] = m * 2 + (s > 0);
            if (m > most) most = m;
        }
        wl = wr;
    }
#if !RAST__SHORTCUTS
    (void)acc; /* (size-optimised builds: the quick cells, 0.5 KB less on Cortex-M0) */
    (void)ngrp;
#endif
    if (swept || !nk) {
#if RAST__SHORTCUTS
        if (nq && !rast__grp_emit(c, j, qg, nq, qmost)) /* not certain: the quick groups the exact way */
            for (g = 0; g < nq; g++)
                rast__area_exact(c, e, row + qg[g].k, qg[g].ms >> 1, j, (qg[g].ms & 1) ? 1 : -1);
#endif
        return;
#if RAST__SHORTCUTS
    } else if (acc && nk == ngrp) {
        /* every group fast, none added: each pixel's winding number takes
         * two values at most, 0 and its group's s, so the accumulation of
         * the parts with their directions, the rule applied (|v|), is its
         * coverage (the simple rows' engine, coverage_acc.c: 64-bit cells,
         * not this file's 128-bit ones) */
        if (rast__cov_acc_area_parts(e, row, nrow, most, j, G - c->h, rule, c->o, (uint64_t *)(void *)c->cover,
                                     c->bits, (uint32_t *)(void *)c->area)) {
            c->emitted = 1;
            return;
        }
#endif
    } else if (rast__q_may(c, most)) { /* no group swept: the row the quick way */
        for (g = 0; g < nk; g++) {
            const int32_t sg = (sw->live[g] & 1) ? 1 : -1, *gr = row + sw->h[g];
            for (pz = 0; pz < sw->live[g] >> 1; pz++) {
                rast__cedge *ed = &e[gr[pz]];
                rast__q_piece(c, ed, Yj, ed->qa, ed->qta, ed->qb, ed->qtb, ed->dir * sg);
            }
        }
        if (rast__q_emit(c, j, most)) return; /* emitted */
    }
    rast__grp_flush(c, e, row, sw, nk, j);
}

/* The row after a fast row, with the same edges, none of them starting or
 * ending inside it: its order at the top is the last row's at the bottom
 * (non-decreasing, row[] as the last row left it), so the windings between
 * neighbours are the last row's, all 0 or s, as long as the order holds to
 * the bottom.  Fast (1, its parts added) if every edge spans the row and
 * each is strictly right of its left neighbour at the top and not left of
 * it at the bottom (exact); else 0, nothing added, the caches valid. */
static int rast__cov_row_cont(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                              int32_t j, int32_t s)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    for (k = 0; k < nrow; k++) {
        rast__cedge *ed = &e[row[k]];
        if (ed->yt > Yj || (int64_t)ed->yt + ed->dy < Yj + c->p) return 0;
        rast__fast_range(ed, j, c);
        if (k > 0) {
            const rast__cedge *a = &e[row[k - 1]];
            if (rast__fast_cmpx(a->qa, a->qar, a, ed->qa, ed->qar, ed) >= 0 ||
                rast__fast_cmpx(a->qb, a->qbr, a, ed->qb, ed->qbr, ed) > 0)
                return 0;
        }
    }
    rast__fast_add(c, e, row, nrow, j, s);
    return 1;
}

/* The row's accumulation: every edge, whole, signed by its direction.
 * The quick way steps each edge's abscissa from row to row in 64 bits
 * (rast__q_top); only a row whose levels it cannot decide computes the
 * 128-bit ones and is added again the exact way. */
static void rast__cov_row_acc(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                              int32_t j)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    if (rast__q_may(c, nrow)) {
        for (k = 0; k < nrow; k++) {
            rast__cedge *ed = &e[row[k]];
            int64_t xa, xb;
            uint64_t ta, tb;
            rast__q_part(ed, j, c, &xa, &ta, &xb, &tb);
            rast__q_piece(c, ed, Yj, xa, ta, xb, tb, ed->dir);
        }
        if (rast__q_emit(c, j, nrow)) return;
    }
    rast__area_exact(c, e, row, nrow, j, 0);
}

#if RAST__SHORTCUTS
/* A row whose edges are all marked RAST__HZ_PLAIN (rast__cov_plain_parts:
 * edges of plain parts of the polygon, whose pixels each see one part's
 * winding numbers, 0 and its sign): the accumulation of its parts, the
 * rule applied, is its coverage, with no test (the simple rows' cells,
 * coverage_acc.c, every part whole with its direction; the window of the
 * row's nrow parts).  1 when done; 0 when those cells cannot decide a
 * level (nothing handed on: the row goes the usual way). */
static int rast__cov_row_plain(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow, int32_t j,
                               rast_fill_rule rule)
{
    int32_t k;
    for (k = 0; k < nrow; k++) {
        rast__cedge *ed = &e[row[k]];
        rast__q_part(ed, j, c, &ed->qa, &ed->qta, &ed->qb, &ed->qtb);
    }
    return rast__cov_acc_area_parts(e, row, nrow, nrow, j, G - c->h, rule, c->o, (uint64_t *)(void *)c->cover,
                                    c->bits, (uint32_t *)(void *)c->area);
}
#endif

/* Column of abscissa x (fixed units, P = 2^s a pixel): floor(x / P). */
static int64_t rast__cov_col_of(int64_t x, int32_t s)
{
    const int64_t p = (int64_t)1 << s;
    return x >= 0 ? x / p : -((-x + p - 1) / p);
}

/* A painter's output (o->paint: its rows handed on as runs of levels not
 * 0, rast__cov_row_done) narrowed to the columns the edges reach: left of
 * every edge and right of every edge the winding number is 0 (closed
 * rings), so those pixels are 0, which no painter is handed; the engines
 * then clear, keep and scan only the polygon's width, not the canvas's
 * (one small polygon a call on a wide canvas).  *on: o's copy, its clip's
 * x0 and x1 moved in (base, pixel (clip.x0, clip.y0), is the row's start
 * either way: the row is the engines' room). */
static void rast__cov_narrow(const rast__cedge *e, uint32_t n, int32_t s, rast__cov_out *on)
{
    int64_t lo = INT64_MAX, hi = INT64_MIN, c0, c1;
    uint32_t k;
    if (!on->paint || n == 0) return;
    for (k = 0; k < n; k++) {
        const int64_t a = e[k].xt, b = (int64_t)e[k].xt + e[k].dx;
        if (a < lo) lo = a;
        if (b < lo) lo = b;
        if (a > hi) hi = a;
        if (b > hi) hi = b;
        if (e[k].hz & RAST__HZ_RUN) {
            if (e[k].hx0 < lo) lo = e[k].hx0;
            if (e[k].hx1 > hi) hi = e[k].hx1;
        }
    }
    c0 = rast__cov_col_of(lo, s);
    c1 = rast__cov_col_of(hi, s) + 1;
    if (c0 >= on->clip.x1 || c1 <= on->clip.x0) return; /* none in the clip: as it is */
    if (c0 > on->clip.x0) on->clip.x0 = (int32_t)c0;
    if (c1 < on->clip.x1) on->clip.x1 = (int32_t)c1;
}

rast_status rast__cov_area(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                           int accumulate, const rast__cov_out *o0, rast__arena *arena)
{
    rast__cells c;
    rast__sweep sw;
    rast__cov_out on = *o0;
    const rast__cov_out *const o = &on;
    int32_t *order, *row, nrow = 0, j, ja, jb, k, width;
    uint32_t next = 0, nlive;
    int32_t fast = 0, same; /* the last row's s if it was a fast row; its edges kept */
    uint64_t *own; /* simple rows (rast__cov_acc_area_row): the columns' marks */
    int32_t *runs, nrun = 0, rnext = 0, rend; /* and the runs, by ordinate */
    /* the last row was not simple (or not tried): then a row of its edges
     * (same) is not tried, nor one that would go by groups (more than
     * RAST__FAST_CUTS edges) but every fourth: a paragraph of text failed
     * the test in most of its rows (3 M instructions of 55 M, issue 33),
     * and a grouped row whose groups are all fast ends in the simple rows'
     * cells anyway (rast__cov_acc_area_parts).  Either way the levels are
     * the exact ones: which way a row goes changes no level. */
    int32_t unsimple = 0;
    int64_t bottom = INT64_MAX; /* the least of the row edges' bottom ordinates */
    const int simple = !accumulate && rast__cov_acc_may(o, s);
    /* rows by groups (rast__cov_row_groups) on every output: its ranges are
     * quick units, which need S <= 16; its cells the exact ones where the
     * output has no quick way */
    const int grouped = !accumulate && s >= 0 && s <= 16;
    /* rows of marked edges only by the accumulation (rast__cov_row_plain):
     * plain, when the polygon's plain parts are marked; unplain, how many
     * of the row's edges are not */
    int plain = 0;
    int32_t unplain = 0;

    rast__cov_narrow(e, n, s, &on);
    width = on.clip.x1 - on.clip.x0;
    order = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    row = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    sw.live = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    sw.wb = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    sw.h = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    sw.hidx = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    sw.ct = (uint64_t *)rast__take(arena, (size_t)n * sizeof(uint64_t));
    sw.swept = sw.unsorted = 0;
#if RAST__SHORTCUTS
    sw.room = (int32_t)n; /* (rast__grp_few's only) */
#endif
    c.cover = (rast__i128 *)rast__take(arena, (size_t)width * sizeof(rast__i128));
    c.area = (rast__i128 *)rast__take(arena, (size_t)width * sizeof(rast__i128));
    c.bits = (uint64_t *)rast__take(arena, ((size_t)width + 63) / 64 * sizeof(uint64_t));
    own = (uint64_t *)rast__take(arena, (size_t)width * sizeof(uint64_t));
    runs = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    if ((n && (!order || !row || !sw.live || !sw.wb || !sw.h || !sw.hidx || !sw.ct || !runs)) ||
        !c.cover || !c.area || !c.bits || !own)
        return RAST_E_SCRATCH;
    for (k = 0; k < width; k++) c.cover[k] = c.area[k] = rast__i128_u64(0);
    for (k = 0; k < width; k++) own[k] = 0;
    for (k = 0; k < (width + 63) / 64; k++) c.bits[k] = 0;
    rast__cells_init(&c, s, rule, accumulate, o);

    if (n == 0) {
        rast__cov_zero_rows(o, o->clip.y0, o->clip.y1);
        return RAST_OK;
    }
    rast__cov_rows(e, n, c.p, order, o, &ja, &jb, RAST__SHORTCUTS); /* (the exact steps when needed: above) */
    for (k = 0; RAST__SHORTCUTS && k < (int32_t)n; k++) {
        e[k].xsr = -1;
        plain |= e[k].hz;
    }
    plain = RAST__SHORTCUTS && simple && (plain & RAST__HZ_PLAIN);
    rast__cov_sort_tops(order, row, sw.live, e, n); /* (row and live: room until the rows) */
    nlive = rast__cov_cancel(order, e, sw.live, n, row); /* (row: room until the rows; live: the tops' keys still) */
    if (grouped) { /* the runs, by ordinate (wb and h: room until the rows) */
        int32_t ymin = INT32_MAX;
        for (k = 0; k < (int32_t)n; k++)
            if (e[k].hz & RAST__HZ_RUN) {
                runs[nrun++] = k;
                if (rast__run_y(&e[k]) < ymin) ymin = rast__run_y(&e[k]);
            }
        for (k = 0; k < nrun; k++) sw.wb[runs[k]] = (int32_t)((uint32_t)rast__run_y(&e[runs[k]]) - (uint32_t)ymin);
        rast__cov_radix_sort(runs, sw.h, sw.wb, (uint32_t)nrun);
    }
    rast__cov_zero_rows(o, o->clip.y0, ja);
    for (j = ja; j < jb; j++) {
        const int64_t Yj = (int64_t)j * c.p;
        int32_t m, nold;
        /* Drop the edges that end above the row (when one does, bottom is
         * at or above the row's top); take those that start above its
         * bottom. */
        same = 1;
        if (bottom <= Yj) {
            bottom = INT64_MAX;
            unplain = 0;
            for (k = 0, m = 0; k < nrow; k++) {
                const int64_t yb = (int64_t)e[row[k]].yt + e[row[k]].dy;
                if (yb > Yj) {
                    row[m++] = row[k];
                    if (yb < bottom) bottom = yb;
                    if (plain) unplain += !(e[row[k]].hz & RAST__HZ_PLAIN);
                }
            }
            same = m == nrow;
            nrow = m;
        }
        nold = nrow; /* (the last row's edges, in its order: rast__grp_merge) */
        while (next < nlive && e[order[next]].yt < Yj + c.p) {
            const int64_t yb = (int64_t)e[order[next]].yt + e[order[next]].dy;
            if (yb > Yj) {
                row[nrow++] = order[next];
                if (yb < bottom) bottom = yb;
                same = 0;
                if (plain) unplain += !(e[order[next]].hz & RAST__HZ_PLAIN);
            }
            next++;
        }
        while (rnext < nrun && rast__run_y(&e[runs[rnext]]) <= Yj) rnext++; /* the row's runs */
        for (rend = rnext; rend < nrun && rast__run_y(&e[runs[rend]]) < Yj + c.p; rend++) {
        }
        if (nrow) {
            if (accumulate) {
                rast__cov_row_acc(&c, e, row, nrow, j);
#if RAST__SHORTCUTS
            } else if (plain && !unplain && rast__cov_row_plain(&c, e, row, nrow, j, rule)) {
                fast = 0;
                unsimple = 0;
                c.emitted = 1;
#else
                (void)unplain; /* (counted, read by the speed builds only) */
#endif
            } else if (fast && same && rast__cov_row_cont(&c, e, row, nrow, j, fast)) {
                /* done: the fast row's continuation, the cheapest test */
            } else if (simple && !(unsimple && (same || (RAST__SHORTCUTS && nrow > RAST__FAST_CUTS && (j & 3)))) &&
                       !(same && nrow <= 4) &&
                       rast__cov_acc_area_row(e, row, nrow, runs + rnext, rend - rnext, j, s, rule, o,
                                              (uint64_t *)(void *)c.cover, c.bits,
                                              (uint32_t *)(void *)c.area, own,
                                              (uint32_t)(j - ja) + 1)) {
                fast = 0;
                unsimple = 0;
                c.emitted = 1;
            } else {
                unsimple = simple;
                /* (a row of more edges than a fast row may have ends inside: by groups) */
                fast = grouped && nrow > RAST__FAST_CUTS ? 0 : rast__cov_row_fast(&c, e, row, nrow, j);
                if (!fast && grouped)
                    rast__cov_row_groups(&c, e, row, nrow, nold, &sw, j, rule, runs + rnext, rend - rnext,
                                         simple);
                else if (!fast)
                    rast__area_sweep(&c, e, row, nrow, &sw, j, rule, 0, 0);
            }
        } else {
            fast = 0;
        }
        if (!c.emitted) rast__cells_emit(&c, o, j, rule);
        c.emitted = 0;
    }
    rast__cov_zero_rows(o, jb, o->clip.y1);
    return RAST_OK;
}

#if RAST__SHORTCUTS
/* ---- bands of plain rows ------------------------------------------------
 *
 * A polygon the edges of whose parts that are not plain are marked
 * (rast__cov_parts_marked, RAST__HZ_BAD: all but a few plain, text with a
 * glyph or two whose rings touch) has rows that no marked edge reaches:
 * there the accumulation is the coverage (see rast__cov_row_plain), and rast__cov_acc's walk of those rows costs less
 * than "area"'s rows one at a time (text, 512 x 512: 17 M instructions
 * for the whole accumulation, 30 M for "area"'s rows).  So the rows go in
 * bands, each band with the edges that reach it: the bad bands (an
 * unmarked edge reaches them) by "area"'s rows, the plain ones by
 * rast__cov_acc.  A band ends only between two rows that no edge reaches
 * both of, so every edge lies in one band: none is handed from one band's
 * call to the next ("accumulate"'s call takes its edges' records for its
 * own compact ones, coverage_acc.c), and the bands are made once, in one
 * pass over the edges and one over the rows (the clip's).  Plain rows
 * fewer than RAST__BAND_GAP between two bad bands go with them.  The
 * levels are the same either way (exact); which way a row goes depends
 * only on the input. */
#define RAST__BANDS 64    /* bands at most (room on the stack), else one */
#define RAST__BAND_GAP 8  /* plain rows fewer than this between two bad: bad */

/* e[0..n)'s edges not marked RAST__HZ_BAD marked RAST__HZ_PLAIN, for
 * rast__cov_area's rows */
static void rast__band_mark(rast__cedge *e, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++)
        if (!(e[i].hz & RAST__HZ_BAD)) e[i].hz |= RAST__HZ_PLAIN;
}

/* Rows of o in bands (see above): 1 when done (*st the status), 0 when
 * the rows are not worth banding (nothing written, e[] as it was or
 * reordered).  arena: a copy, for this and each band's call, whose room
 * starts with rast__cov_parts_marked's table of the nr rings (their rows,
 * their edges in e[] ring by ring, which are not plain): the bands are
 * made from the rings', and the edges put in band order ring by ring,
 * no edge's record read (text: that pass over 31,000 records was 9% of
 * "area"'s time, a cache miss an edge); the records are moved only when
 * the rings do not come band by band. */
static int rast__cov_bands(rast__cedge *e, uint32_t n, uint32_t nr, int32_t s, rast_fill_rule rule,
                           const rast__cov_out *o, rast__arena arena, rast_status *st)
{
    int32_t y[RAST__BANDS + 1]; /* band t: rows [y[t], y[t + 1]) of the clip; bad when t is odd (band 0 may be empty) */
    uint32_t at[RAST__BANDS + 1]; /* band t's edges: e[at[t] .. at[t + 1]) */
    const int64_t y0 = o->clip.y0, h = (int64_t)o->clip.y1 - o->clip.y0;
    rast__arena room = arena;
    const int32_t *rows = (const int32_t *)rast__take(&room, RAST__COV_RING_ROWS(nr));
    int32_t *rkey = (int32_t *)rast__take(&room, (size_t)nr * sizeof(int32_t));
    /* per row r of the clip: span[r], the rings that reach rows r and r +
     * 1 (a difference, summed in the pass over the rows), then the band
     * of row r; bad[r], the rings not plain that reach row r (likewise) */
    int32_t *span = (int32_t *)rast__take(&room, (size_t)(h + 1) * sizeof(int32_t));
    int32_t *bad = (int32_t *)rast__take(&room, (size_t)(h + 1) * sizeof(int32_t));
    uint32_t i, m = 1, t, q, sum = 0;
    int32_t r, from = 0, sp = 0, bb = 0, segbad = 0, unsorted = 0, last = 0;
    int64_t plainrows = 0;
    if (!rows || !rkey || !span || !bad || n == 0 || h <= 0 || h >= INT32_MAX) return 0;
    for (r = 0; r <= (int32_t)h; r++) span[r] = bad[r] = 0;
    for (q = 0; q < nr; q++) { /* each ring's rows in the clip (by its first: rkey) */
        const int32_t c = rows[3 * q + 2], ne = c < 0 ? ~c : c;
        int64_t r0 = (int64_t)rows[3 * q] - y0, r1 = (int64_t)rows[3 * q + 1] - y0;
        sum += (uint32_t)ne;
        if (!ne || r1 < 0 || r0 >= h) { /* (none of its rows in the clip: with the first band or the last) */
            rkey[q] = ne && r0 >= h ? (int32_t)h - 1 : 0;
            continue;
        }
        r0 = r0 < 0 ? 0 : r0;
        r1 = r1 >= h ? h - 1 : r1;
        rkey[q] = (int32_t)r0;
        span[r0]++;
        span[r1]--;
        if (c < 0) {
            bad[r0]++;
            bad[r1 + 1]--;
        }
    }
    if (sum != n) return 0; /* (not rast__cov_parts_marked's edges) */
    y[0] = 0; /* the bands: rows [from, r + 1) a piece (no edge reaches across its ends), bad or plain */
    for (r = 0; r < (int32_t)h; r++) {
        bb += bad[r];
        sp += span[r];
        segbad |= bb > 0;
        if (sp != 0 && r + 1 < (int32_t)h) continue;
        if ((int32_t)((m - 1) & 1) != segbad) { /* a band of the other kind begins at from */
            if (segbad && m >= 3 && from - y[m - 1] < RAST__BAND_GAP) {
                m--; /* (a short plain band between two bad: bad) */
            } else {
                if (m + 1 > RAST__BANDS) return 0;
                y[m++] = from;
            }
        }
        from = r + 1;
        segbad = 0;
    }
    y[m] = (int32_t)h;
    for (t = 0; t < m; t += 2) plainrows += (int64_t)y[t + 1] - y[t];
    /* (plain rows a quarter of the clip's or more: else as one band) */
    if (plainrows * 4 < h) return 0;
    for (t = 0; t < m; t++) /* each row's band (span's room) */
        for (r = y[t]; r < y[t + 1]; r++) span[r] = (int32_t)t;
    for (t = 0; t <= m; t++) at[t] = 0;
    for (q = 0; q < nr; q++) { /* the rings' edges by band (a polygon's rings come in rows: often in order) */
        const int32_t c = rows[3 * q + 2], ne = c < 0 ? ~c : c, b = span[rkey[q]];
        unsorted |= ne && b < last;
        last = ne ? b : last;
        rkey[q] = b;
        at[b + 1] += (uint32_t)ne;
    }
    for (t = 0; t < m; t++) at[t + 1] += at[t];
    if (unsorted) { /* each edge's band (its ring's), then the records moved, stably */
        int32_t *tmp = (int32_t *)rast__take(&room, (size_t)n * sizeof(int32_t));
        int32_t *key = (int32_t *)rast__take(&room, (size_t)n * sizeof(int32_t));
        if (!tmp || !key) return 0;
        for (q = 0, i = 0; q < nr; q++) {
            const int32_t c = rows[3 * q + 2];
            uint32_t k;
            for (k = 0; k < (uint32_t)(c < 0 ? ~c : c); k++) key[i++] = rkey[q];
        }
        for (i = 0; i < n; i++) tmp[at[key[i]]++] = (int32_t)i; /* tmp[new place] = old place */
        for (t = m; t > 0; t--) at[t] = at[t - 1];
        at[0] = 0;
        for (i = 0; i < n; i++) { /* each cycle of the permutation, one copy an edge */
            if (tmp[i] < 0 || tmp[i] == (int32_t)i) continue;
            {
                const rast__cedge first = e[i];
                uint32_t p = i;
                while ((uint32_t)tmp[p] != i) {
                    const uint32_t src = (uint32_t)tmp[p];
                    e[p] = e[src];
                    tmp[p] = -1;
                    p = src;
                }
                e[p] = first;
                tmp[p] = -1;
            }
        }
    }
    for (t = 0; t < m; t++) { /* each band with its edges */
        rast__cov_out ob = *o;
        ob.clip.y0 = (int32_t)(y0 + y[t]);
        ob.clip.y1 = (int32_t)(y0 + y[t + 1]);
        ob.base = o->base + (ptrdiff_t)y[t] * o->stride;
        if (y[t] < y[t + 1]) {
            rast__arena a = arena;
            if (t & 1) rast__band_mark(e + at[t], at[t + 1] - at[t]);
            *st = t & 1 ? rast__cov_area(e + at[t], at[t + 1] - at[t], s, rule, 0, &ob, &a)
                        : rast__cov_acc(e + at[t], at[t + 1] - at[t], s, rule, &ob, &a);
            if (*st != RAST_OK) return 1;
        }
    }
    *st = RAST_OK;
    return 1;
}
#endif

#if RAST__SHORTCUTS
rast_status rast__cov_area_marked(rast__cedge *e, uint32_t n, uint32_t nrings, int32_t s, rast_fill_rule rule,
                                  const rast__cov_out *o, rast__arena *arena)
{
    rast_status st = RAST_OK;
    if (rast__cov_acc_may(o, s) && rast__cov_bands(e, n, nrings, s, rule, o, *arena, &st)) return st;
    rast__band_mark(e, n);
    return rast__cov_area(e, n, s, rule, 0, o, arena);
}
#endif

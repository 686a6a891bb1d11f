/*
 * cells.h - the exact cells of a coverage row (cells.c): 128-bit cover
 * and area per column, FreeType's way, each piece of an edge split at the
 * columns it crosses, a row emitted from them.  Shared by the exact sweep
 * of "area" (coverage_area.c) and the rows the 64-bit accumulation
 * cannot decide (coverage_acc.c, rast__cov_acc_exact_row).  Not installed.
 */
#ifndef RAST_COV_CELLS_H
#define RAST_COV_CELLS_H

#include "rows.h"

/* The row's cells: for clip column c (index c - x0), cover (sum of signed
 * heights, U) and area (sum of signed (f0 + f1) heights, U V; or, when
 * accumulating, that over 2^59 per piece, so that deep overlaps do not
 * wrap), and `carry`, the cover of everything left of the clip. */
typedef struct rast__cells {
    rast__i128 *cover, *area, carry;
    uint64_t *bits;             /* the columns touched, one bit each */
    int32_t x0, x1, wmin, wmax; /* clip columns; the words of bits touched */
    int32_t h;                  /* H = G - S */
    int32_t p;                  /* P = 2^S */
    int accumulate;
    /* the quick accumulation (below): its cells are cover[].lo (cover)
     * and cover[].hi (area), its carry qcarry; o and rule for its emit,
     * quick its level's M (0: not used), emitted set when it has written
     * the row */
    uint64_t qcarry;
    const rast__cov_out *o;
    rast_fill_rule rule;
    uint32_t quick;
    int emitted;
} rast__cells;

#define RAST__CELLS_T ((uint64_t)1 << RAST__COV_G)

/* a 2^62 from the running cover and a cell's area (see rast__cells),
 * the rule applied when accumulating, clamped to [0, 2^62]: for
 * rast__cells_emit and the swept rows' quick groups (coverage_area.c). */
static inline uint64_t rast__cells_a62(const rast__cells *c, rast__i128 acc, rast__i128 area,
                                       rast_fill_rule rule)
{
    const rast__i128 one = rast__i128_u64((uint64_t)1 << 62);
    rast__i128 v;
    if (!c->accumulate) { /* a 2^121 = 2^61 cover - area, then down to 2^62 */
        v = rast__i128_sar(rast__i128_sub(rast__i128_shl(acc, 61), area), 59);
        if (rast__i128_neg_p(v)) return 0;
        if (v.hi || v.lo > ((uint64_t)1 << 62)) return (uint64_t)1 << 62;
        return v.lo;
    } else { /* a 2^62 = 4 cover - area / 2^59 */
        v = rast__i128_sub(rast__i128_shl(acc, 2), area);
        /* |w| integrated, then the rule */
        if (rast__i128_neg_p(v)) v = rast__i128_neg(v);
        if (rule == RAST_RULE_NONZERO) {
            if (rast__i128_cmp(v, one) > 0) v = one;
        } else {
            uint64_t m = v.lo & (((uint64_t)1 << 63) - 1); /* mod 2 */
            v = rast__i128_u64(m > ((uint64_t)1 << 62) ? ((uint64_t)1 << 63) - m : m);
        }
    }
    if (rast__i128_neg_p(v)) return 0;
    if (rast__i128_cmp(v, one) > 0) return (uint64_t)1 << 62;
    return v.lo;
}

/* e's abscissa at ordinate t of the row whose top is Yj (rast__cov_x_at);
 * advanced by a whole row (rast__cov_x_row); at the end tn of a piece
 * that starts at t, into xn, rn (rast__cov_x_end), then kept as the
 * abscissa at tn of row j (rast__cov_x_keep).  See cells.c. */
void rast__cov_x_at(const rast__cedge *e, int64_t Yj, uint64_t t, int32_t h,
                           rast__i128 *x, int64_t *r);
void rast__cov_x_row(const rast__cedge *e, rast__i128 *x, int64_t *r);
void rast__cov_x_end(rast__cedge *e, int64_t Yj, uint64_t t, uint64_t tn, int32_t h);
void rast__cov_x_keep(rast__cedge *e, int32_t j, uint64_t tn);
/* c's fields but its arrays: nothing added yet. */
void rast__cells_init(rast__cells *c, int32_t s, rast_fill_rule rule, int accumulate,
                             const rast__cov_out *o);
/* The parts of row j's edges, whole, each with the sign dir * s (dir
 * alone for s = 0), the exact way. */
void rast__row_exact(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                            int32_t j, int32_t s);
/* Row y's values from the cells, which are then cleared; handed on. */
void rast__cells_emit(rast__cells *c, const rast__cov_out *o, int32_t y, rast_fill_rule rule);
/* The piece of edge e from (xa, ta) to (xb, tb), sign s, into the cells,
 * and its helpers: static inline, so that the sweep (coverage_area.c)
 * and the exact rows (cells.c) each call their own copy, as they did in one
 * file (GCC's -fipa-ra: a call into another file costs the caller its
 * registers; +3% instructions on 25 canvas-spanning triangles). */
/* The ordinates (U from the row's top at Yj) where e meets the verticals
 * x = X, X + 1, ... (dx > 0) or X, X - 1, ... (dx < 0) pixels, which lie
 * between its ends: floor(|X P - xt| dy 2^H / |dx|) - (Yj - yt) 2^H, the
 * first by a division, the next ones by adding e->ts, e->tsr (the step
 * dy 2^G / |dx|) with the remainder carried: exact, without a division per
 * column. */
typedef struct rast__tstep {
    rast__i128 t, off; /* t from the edge's top; off: the row's top from it */
    rast__cedge *e;
    uint32_t rem, adx;
    int64_t X;
} rast__tstep;

/* Start at vertical X: the edge's own stepper when it stands there (the
 * piece before ended in this column), else a division. */
static inline void rast__cov_t_first(rast__cedge *e, int64_t Yj, int64_t X, const rast__cells *c,
                              rast__tstep *s)
{
    s->e = e;
    s->X = X;
    s->adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    s->off = rast__i128_shl(rast__i128_from(Yj - e->yt), c->h);
    if (e->cX == X) {
        s->t = e->ct;
        s->rem = e->crem;
    } else {
        int64_t w = X * c->p - e->xt;
        if (w < 0) w = -w;
        s->t = rast__u128_div32(rast__i128_shl(rast__i128_mul(w, e->dy), c->h), s->adx, &s->rem);
    }
}

static inline void rast__cov_t_next(rast__tstep *s)
{
    const rast__cedge *e = s->e;
    s->t = rast__i128_add(s->t, e->ts);
    s->rem += e->tsr;
    if (s->rem >= s->adx) {
        s->rem -= s->adx;
        s->t = rast__i128_add(s->t, rast__i128_u64(1));
    }
    s->X += e->dx > 0 ? 1 : -1;
}

/* Leave the stepper with its edge for the next piece. */
static inline void rast__cov_t_keep(const rast__tstep *s)
{
    s->e->ct = s->t;
    s->e->crem = s->rem;
    s->e->cX = s->X;
}

/* The stepper's ordinate from the row's top, kept in [lo, hi]: the column
 * crossings of a piece are in its range (a floor of an exact value
 * between its ends); this only guards it. */
static inline uint64_t rast__cov_t_val(const rast__tstep *s, uint64_t lo, uint64_t hi)
{
    rast__i128 t = rast__i128_sub(s->t, s->off);
    if (rast__i128_neg_p(t) || (!t.hi && t.lo < lo)) return lo;
    if (t.hi || t.lo > hi) return hi;
    return t.lo;
}

/* One cell's share: from fraction f0 at t0 to f1 at t1 (V, 0..2^G) in
 * column col, sign s. */
static inline void rast__cells_add(rast__cells *c, int32_t col, uint64_t f0, uint64_t f1,
                            uint64_t t0, uint64_t t1, int32_t s)
{
    uint64_t dy = t1 - t0;
    rast__i128 cv, ar;
    if (dy == 0 || col >= c->x1) return;
    cv = rast__i128_from(s < 0 ? -(int64_t)dy : (int64_t)dy); /* dy <= 2^60 */
    if (col < c->x0) {
        c->carry = rast__i128_add(c->carry, cv);
        return;
    }
    if (c->accumulate) { /* rounded down, then signed */
        ar = rast__i128_sar(rast__i128_mul((int64_t)(f0 + f1), (int64_t)dy), 59);
        if (s < 0) ar = rast__i128_neg(ar);
    } else { /* f0 + f1 <= 2^61 */
        ar = rast__i128_mul(s < 0 ? -(int64_t)(f0 + f1) : (int64_t)(f0 + f1), (int64_t)dy);
    }
    col -= c->x0;
    c->cover[col] = rast__i128_add(c->cover[col], cv);
    c->area[col] = rast__i128_add(c->area[col], ar);
    c->bits[col >> 6] |= (uint64_t)1 << (col & 63);
    if ((col >> 6) < c->wmin) c->wmin = col >> 6;
    if ((col >> 6) > c->wmax) c->wmax = col >> 6;
}

/* The piece of edge e from (xa, ta) to (xb, tb) (V, U; ta < tb), sign s,
 * split at the pixel columns it crosses. */
static inline void rast__cells_piece(rast__cells *c, rast__cedge *e, int64_t Yj, rast__i128 xa,
                                     uint64_t ta, rast__i128 xb, uint64_t tb, int32_t s)
{
    const uint64_t fmask = RAST__CELLS_T - 1;
    /* the columns floor(x / 2^G): |column| < 2^28, so the low word of the
     * shifted value, read as two's complement, is it */
    int64_t ca = (int64_t)((xa.hi << (64 - RAST__COV_G)) | (xa.lo >> RAST__COV_G));
    int64_t cb = (int64_t)((xb.hi << (64 - RAST__COV_G)) | (xb.lo >> RAST__COV_G));
    uint64_t fa = xa.lo & fmask, fb = xb.lo & fmask, t = ta;
    int64_t col;
    rast__tstep st;
    if (ta >= tb) return;
    if (ca == cb) {
        rast__cells_add(c, (int32_t)ca, fa, fb, ta, tb, s);
        return;
    }
    if (ca < c->x0 && cb < c->x0) { /* all left of the clip: its cover */
        rast__cells_add(c, c->x0 - 1, 0, 0, ta, tb, s);
        return;
    }
    if (ca < cb) { /* going right: the verticals ca + 1, ..., cb */
        if (ca >= c->x1) return;
        col = ca;
        if (col < c->x0) { /* the part left of the clip: its cover */
            uint64_t tx;
            rast__cov_t_first(e, Yj, c->x0, c, &st);
            tx = rast__cov_t_val(&st, t, tb);
            rast__cells_add(c, c->x0 - 1, 0, 0, t, tx, s);
            t = tx;
            col = c->x0;
            fa = 0;
            rast__cov_t_next(&st);
        } else {
            rast__cov_t_first(e, Yj, col + 1, c, &st);
        }
        for (; col < cb; col++) {
            uint64_t tx;
            if (col >= c->x1) return;
            tx = rast__cov_t_val(&st, t, tb);
            rast__cells_add(c, (int32_t)col, fa, RAST__CELLS_T, t, tx, s);
            t = tx;
            fa = 0;
            rast__cov_t_next(&st);
        }
        rast__cov_t_keep(&st);
        rast__cells_add(c, (int32_t)cb, 0, fb, t, tb, s);
    } else { /* going left: the verticals ca, ..., cb + 1 */
        if (cb >= c->x1) return;
        col = ca;
        if (col >= c->x1) { /* the part right of the clip adds nothing */
            rast__cov_t_first(e, Yj, c->x1, c, &st);
            t = rast__cov_t_val(&st, t, tb);
            col = c->x1 - 1;
            fa = RAST__CELLS_T;
            rast__cov_t_next(&st);
        } else {
            rast__cov_t_first(e, Yj, col, c, &st);
        }
        for (; col > cb; col--) {
            uint64_t tx;
            if (col < c->x0) { /* the rest is left of the clip */
                rast__cells_add(c, c->x0 - 1, 0, 0, t, tb, s);
                return;
            }
            tx = rast__cov_t_val(&st, t, tb);
            rast__cells_add(c, (int32_t)col, fa, 0, t, tx, s);
            t = tx;
            fa = RAST__CELLS_T;
            rast__cov_t_next(&st);
        }
        rast__cov_t_keep(&st);
        rast__cells_add(c, (int32_t)cb, RAST__CELLS_T, fb, t, tb, s);
    }
}

/* Row j of "accumulate" the exact way: the edges row[0..nrow), whole,
 * into row j of o (handed on), with cleared cells cover[], area[] (clip
 * width each) and bits[] (a bit a column), left cleared; carry: the cover
 * of the parts left of o's clip that are not in row[] (the sum of their
 * dir (t1 - t0), t in units of 2^-G of the row's height; 0 when row[]
 * holds every part of the row). */
void rast__cov_acc_exact_row(rast__cedge *e, const int32_t *row, int32_t nrow, int32_t j,
                             int32_t s, rast_fill_rule rule, const rast__cov_out *o,
                             rast__i128 *cover, rast__i128 *area, uint64_t *bits, rast__i128 carry);

#endif /* RAST_COV_CELLS_H */

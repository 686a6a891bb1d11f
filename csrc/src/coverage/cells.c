/*
 * cells.c - the exact cells of a coverage row (cells.h; the units in
 * rows.h): moved here from coverage_area.c unchanged, so that the exact
 * sweep (coverage_area.c) and the accumulation's exact rows
 * (coverage_acc.c) call one layer below them instead of each other.
 */
#include "cells.h"
#include "../base/bits.h" /* rast__ctz64 */

#define G RAST__COV_G
#define T ((uint64_t)1 << G)

/* floor(y m / d), its remainder into *rem, for 0 <= y < 2^89 and
 * 0 < m, d < 2^32, where the compiler has a 128-bit type: the product and
 * one 128-bit division (two machine divisions at most), not rows.h's four
 * 64-bit divisions of 32-bit limbs (which firmware, with no 128-bit
 * divide, keeps).  rast__cov_x_at's division: on a stroke, its four
 * divisions a call were a tenth of "area"'s instructions. */
#if defined(__SIZEOF_INT128__) && !defined(RAST_NO_INT128)
#define RAST__COV_MULDIV 1
static inline rast__i128 rast__cov_muldiv(rast__i128 y, uint32_t m, uint32_t d, uint32_t *rem)
{
    __extension__ typedef unsigned __int128 rast__u128;
    const rast__u128 p = (((rast__u128)y.hi << 64) | y.lo) * m, q = p / d;
    rast__i128 r;
    *rem = (uint32_t)((uint64_t)p - (uint64_t)q * d);
    r.hi = (uint64_t)(q >> 64);
    r.lo = (uint64_t)q;
    return r;
}
#else
#define RAST__COV_MULDIV 0
#endif

/* x at ordinate t (U, from the top of the row whose top is Yj, fixed
 * units) of edge e, which must reach t: floor in V into *x, the rest r/dy
 * into *r. */
void rast__cov_x_at(const rast__cedge *e, int64_t Yj, uint64_t t, int32_t h,
                    rast__i128 *x, int64_t *r)
{
    rast__i128 base = rast__i128_shl(rast__i128_from(e->xt), h), y, q;
    uint32_t rem;
    if (e->dx == 0 || (!(t & (((uint64_t)1 << h) - 1)) && (int64_t)e->yt == Yj + (int64_t)(t >> h))) {
        /* vertical, or at its top */
        *x = base;
        *r = 0;
        return;
    }
    if (!(t & (((uint64_t)1 << h) - 1)) && (int64_t)e->yt + e->dy == Yj + (int64_t)(t >> h)) {
        *x = rast__i128_shl(rast__i128_from((int64_t)e->xt + e->dx), h); /* its bottom */
        *r = 0;
        return;
    }
    /* Y = height below the top, U units (>= 0, < 2^89). */
    y = rast__i128_add(rast__i128_shl(rast__i128_from(Yj - e->yt), h), rast__i128_u64(t));
#if RAST__COV_MULDIV
    q = rast__cov_muldiv(y, (uint32_t)(e->dx < 0 ? -e->dx : e->dx), (uint32_t)e->dy, &rem);
#else
    q = rast__u128_div32(rast__u128_mul32(y, (uint32_t)(e->dx < 0 ? -e->dx : e->dx)),
                         (uint32_t)e->dy, &rem);
#endif
    if (e->dx > 0) {
        *x = rast__i128_add(base, q);
        *r = rem;
    } else if (rem) {
        *x = rast__i128_sub(rast__i128_sub(base, q), rast__i128_from(1));
        *r = e->dy - (int64_t)rem;
    } else {
        *x = rast__i128_sub(base, q);
        *r = 0;
    }
}

/* Columns [k0, k1) of a clip row get value v. */
/* Row y's values from the cells, which are then cleared.  Only the cells
 * touched (their bits, in column order) add something; between them (inside
 * a span, or outside the shape) the value is the running cover's: one
 * computation and a fill per run.  A touched cell whose sums are 0 gives
 * the run's value too, so the bits only save the scan. */
void rast__cells_emit(rast__cells *c, const rast__cov_out *o, int32_t y, rast_fill_rule rule)
{
    unsigned char *row = rast__cov_row(o, y);
    const rast__i128 zero = rast__i128_u64(0);
    const rast_coverage_format f = o->format;
    rast__i128 acc = c->carry;
    int32_t k = 0, wi, w = c->x1 - c->x0;
    for (wi = c->wmin; wi <= c->wmax; wi++) {
        uint64_t b = c->bits[wi];
        c->bits[wi] = 0;
        while (b) {
            int32_t col = (wi << 6) + (int32_t)rast__ctz64(b);
            b &= b - 1;
            if (col > k)
                rast__cov_fill(f, row, k, col, rast__cov_level(f, rast__cells_a62(c, acc, zero, rule)));
            acc = rast__i128_add(acc, c->cover[col]);
            rast__cov_store(f, row, col, rast__cov_level(f, rast__cells_a62(c, acc, c->area[col], rule)));
            c->cover[col] = c->area[col] = zero;
            k = col + 1;
        }
    }
    if (k < w)
        rast__cov_fill(f, row, k, w, rast__cov_level(f, rast__cells_a62(c, acc, zero, rule)));
    rast__cov_row_done(o, y);
    c->carry = zero;
    c->wmin = INT32_MAX;
    c->wmax = -1;
}

/* x advanced by a whole row: from a row's top to the next (exact). */
void rast__cov_x_row(const rast__cedge *e, rast__i128 *x, int64_t *r)
{
    *x = rast__i128_add(*x, e->xs);
    *r += e->xsr;
    if (*r >= e->dy) {
        *r -= e->dy;
        *x = rast__i128_add(*x, rast__i128_u64(1));
    }
}

/* e's abscissa at the end tn of a piece that starts at t (where it is
 * cached) into xn, rn: a row's step when the piece is the whole row. */
void rast__cov_x_end(rast__cedge *e, int64_t Yj, uint64_t t, uint64_t tn, int32_t h)
{
    if (t == 0 && tn == T) {
        e->xn = e->x;
        e->rn = e->r;
        rast__cov_x_row(e, &e->xn, &e->rn);
    } else {
        rast__cov_x_at(e, Yj, tn, h, &e->xn, &e->rn);
    }
}

/* Cache xn, rn as the abscissa at tn of row j (the top of row j + 1 when
 * tn is the bottom). */
void rast__cov_x_keep(rast__cedge *e, int32_t j, uint64_t tn)
{
    e->x = e->xn;
    e->r = e->rn;
    e->rowx = tn == T ? j + 1 : j;
    e->tx = tn == T ? 0 : tn;
}

/* The parts of row j's edges, whole, each with the sign dir * s (dir
 * alone for s = 0), the exact way (128-bit abscissae). */
void rast__row_exact(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                     int32_t j, int32_t s)
{
    const int64_t Yj = (int64_t)j * c->p;
    int32_t k;
    for (k = 0; k < nrow; k++) {
        rast__cedge *ed = &e[row[k]];
        int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = (int64_t)ed->yt + ed->dy - Yj;
        uint64_t t0 = rel0 <= 0 ? 0 : (uint64_t)rel0 << c->h;
        uint64_t t1 = rel1 >= c->p ? T : (uint64_t)rel1 << c->h;
        if (ed->rowx != j || ed->tx != t0) {
            rast__cov_x_at(ed, Yj, t0, c->h, &ed->x, &ed->r);
            ed->rowx = j;
            ed->tx = t0;
        }
        rast__cov_x_end(ed, Yj, t0, t1, c->h);
        rast__cells_piece(c, ed, Yj, ed->x, t0, ed->xn, t1, s ? ed->dir * s : ed->dir);
        rast__cov_x_keep(ed, j, t1);
    }
}

/* c's fields but its arrays: nothing added yet; quick where the format has it. */
void rast__cells_init(rast__cells *c, int32_t s, rast_fill_rule rule, int accumulate,
                      const rast__cov_out *o)
{
    c->carry = rast__i128_u64(0);
    c->x0 = o->clip.x0;
    c->x1 = o->clip.x1;
    c->wmin = INT32_MAX;
    c->wmax = -1;
    c->h = G - s;
    c->p = (int32_t)1 << s;
    c->accumulate = accumulate;
    c->qcarry = 0;
    c->o = o;
    c->rule = rule;
    c->quick = o->format == RAST_COVERAGE_U8 ? 255 : o->format == RAST_COVERAGE_U16 ? 65535 : 0;
    c->emitted = 0;
}

void rast__cov_acc_exact_row(rast__cedge *e, const int32_t *row, int32_t nrow, int32_t j,
                             int32_t s, rast_fill_rule rule, const rast__cov_out *o,
                             rast__i128 *cover, rast__i128 *area, uint64_t *bits, rast__i128 carry)
{
    rast__cells c;
    c.cover = cover;
    c.area = area;
    c.bits = bits;
    rast__cells_init(&c, s, rule, 1, o);
    c.quick = 0;
    c.carry = carry;
    rast__row_exact(&c, e, row, nrow, j, 0);
    rast__cells_emit(&c, o, j, rule);
}

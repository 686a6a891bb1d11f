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
/* The piece of edge e from (xa, ta) to (xb, tb), sign s, into the cells. */
void rast__cells_piece(rast__cells *c, rast__cedge *e, int64_t Yj, rast__i128 xa,
                              uint64_t ta, rast__i128 xb, uint64_t tb, int32_t s);
/* The parts of row j's edges, whole, each with the sign dir * s (dir
 * alone for s = 0), the exact way. */
void rast__row_exact(rast__cells *c, rast__cedge *e, const int32_t *row, int32_t nrow,
                            int32_t j, int32_t s);
/* Row y's values from the cells, which are then cleared; handed on. */
void rast__cells_emit(rast__cells *c, const rast__cov_out *o, int32_t y, rast_fill_rule rule);
/* Row j of "accumulate" the exact way: the edges row[0..nrow), whole,
 * into row j of o (handed on), with cleared cells cover[], area[] (clip
 * width each) and bits[] (a bit a column), left cleared. */
void rast__cov_acc_exact_row(rast__cedge *e, const int32_t *row, int32_t nrow, int32_t j,
                             int32_t s, rast_fill_rule rule, const rast__cov_out *o,
                             rast__i128 *cover, rast__i128 *area, uint64_t *bits);

#endif /* RAST_COV_CELLS_H */

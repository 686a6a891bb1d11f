/*
 * coverage_acc_edge.tmpl.h - an edge's part in a row of "accumulate"'s cells
 * (coverage_acc.c; included there, not installed): its ends by the row
 * stepper (rast__acc_ends) and its pieces by the column stepper
 * (rast__acc_part), on a record of type RAST__ACC_E whose fields have
 * rast__cedge's names (rows.h), qX of type RAST__ACC_COL: the walk's
 * compact records (rast__aedge), and the edges' own for "area"'s rows
 * (rast__cov_acc_area_row), which coverage_acc.c has as two copies of
 * these functions, named by RAST__ACC_N (one source, not the same code
 * written twice).  RAST__ACC_FAT: the record is a rast__cedge, whose
 * steppers rows.h moves.
 */

/* rast__cov_qtop, rast__cov_qt_first with this engine's P and HQ */
#if RAST__ACC_FAT
static inline int64_t RAST__ACC_N(rast__acc_top)(RAST__ACC_E *e, int32_t j, const rast__acc *a)
{
    return rast__cov_qtop(e, j, a->p, a->hq);
}

static void RAST__ACC_N(rast__acc_t_first)(RAST__ACC_E *e, int64_t X, const rast__acc *a)
{
    rast__cov_qt_first(e, X, a->p, a->hq);
}
#else
/* (The walk's records get their quick steps when their steppers are first
 * stepped, not when they are made: an edge in one row, most of a line of
 * text's, steps neither from row to row nor, in one column, from column
 * to column, and its two divisions were a tenth of the paragraph's time;
 * one in two rows, set at the second row's top by rast__acc_top1, is not
 * stepped either.  qrow, qX INT32_MIN: the stepper never set; qxsr
 * RAST__ACC_UNMADE: the row step not made, rast__acc_qxs.) */
RAST__APART void RAST__ACC_N(rast__acc_top_set)(RAST__ACC_E *e, int32_t j, const rast__acc *a)
{
    RAST__ACC_QXS(e);
    rast__cov_qx_at(e->xt, e->yt, e->dx, e->dy, j, a->p, a->hq, &e->qx, &e->qxr);
    e->qrow = j;
}

static inline int64_t RAST__ACC_N(rast__acc_top)(RAST__ACC_E *e, int32_t j, const rast__acc *a)
{
    if (e->qrow == j - 1) {
        RAST__ACC_QXS(e);
        rast__cov_qstep(&e->qx, &e->qxr, e->qxs, e->qxsr, e->dy);
        e->qrow = j;
    } else if (e->qrow != j) {
        RAST__ACC_N(rast__acc_top_set)(e, j, a); /* (once an edge, out of line) */
    }
    return e->qx;
}

/* The column stepper at vertical X, its step made.  (The rows' walk sets
 * an edge's stepper at the first vertical it crosses without the step,
 * rast__acc_t_at: most of a line of text's edges cross one, and the
 * step's division was theirs.  Such a stepper, qX RAST__ACC_LAZYX, at
 * vertical lazyX, is stepped on to the next one here, in the one division
 * the step takes.) */
RAST__APART int RAST__ACC_N(rast__acc_t_next)(RAST__ACC_E *e, int64_t X)
{
    uint32_t qtr;
    rast__cov_qtstep(e->dx, e->dy, &e->qts, &e->qtsr);
    if (X != (int64_t)e->lazyX + (e->dx > 0 ? 1 : -1)) return 0;
    qtr = e->qtr + e->qtsr;
    e->qt += e->qts + rast__acc_carry(&qtr, (uint32_t)(e->dx < 0 ? -e->dx : e->dx));
    e->qtr = qtr;
    e->qX = (RAST__ACC_COL)X;
    return 1;
}

static void RAST__ACC_N(rast__acc_t_first)(RAST__ACC_E *e, int64_t X, const rast__acc *a)
{
    if (e->qX == INT32_MIN)
        rast__cov_qtstep(e->dx, e->dy, &e->qts, &e->qtsr);
    else if (e->qX == RAST__ACC_LAZYX && RAST__ACC_N(rast__acc_t_next)(e, X))
        return;
    rast__cov_qt_at(e->xt, e->dx, e->dy, X, a->p, a->hq, &e->qt, &e->qtr);
    e->qX = (RAST__ACC_COL)X;
}

/* The column stepper of an edge not set before at vertical X, without its
 * step (rast__acc_t_first's, in one division where it takes two): qX
 * RAST__ACC_LAZYX, which no vertical is, lazyX X */
static inline void RAST__ACC_N(rast__acc_t_at)(RAST__ACC_E *e, int64_t X, const rast__acc *a)
{
    rast__cov_qt_at(e->xt, e->dx, e->dy, X, a->p, a->hq, &e->qt, &e->qtr);
    e->qX = RAST__ACC_LAZYX;
    e->lazyX = (int32_t)X;
}
#endif

#if !defined(__OPTIMIZE_SIZE__)
/* rast__cov_qtop_set at the top of row j1 = e's first row + 1 (0 < d =
 * j1 P - yt <= P): floor(dx d 2^HQ / dy) by one unsigned division of
 * |dx| d 2^HQ <= 2^58, the floor of the negative quotient from it, inline
 * (a call and a signed division's tests an edge: 0.7 M instructions of
 * the text family's 20 M) */
static inline int64_t RAST__ACC_N(rast__acc_top1)(RAST__ACC_E *e, int32_t j1, const rast__acc *a, int lazy)
{
    const uint64_t d = (uint64_t)((int64_t)j1 * a->p - e->yt), dy = (uint64_t)e->dy;
    const uint64_t n = (uint64_t)(e->dx < 0 ? -(int64_t)e->dx : e->dx) * d << a->hq, q = n / dy, r = n % dy;
    const int64_t x = (int64_t)e->xt * ((int64_t)1 << a->hq);
#if !RAST__ACC_FAT
    /* (rast__acc_top_set's; a stepper not set has no step: qrow, a
     * register here, tells) */
    if (!lazy && e->qrow == INT32_MIN) rast__cov_qxstep(e->dx, e->dy, &e->qxs, &e->qxsr);
#else
    (void)lazy;
#endif
    if (e->dx >= 0) {
        e->qx = x + (int64_t)q;
        e->qxr = (uint32_t)r;
    } else {
        e->qx = x - (int64_t)q - (r != 0);
        e->qxr = (uint32_t)(r ? dy - r : 0);
    }
    e->qrow = j1;
    return e->qx;
}
#endif

/* e's part in row j (top Yj): from (*xa, *ta) to (*xb, *tb), Q units, t
 * from the row's top; its top rel0 = yt - Yj below the row's.  lazy (a
 * constant at each call): the row step is made when first stepped, not
 * when the stepper is set at e's second row (the rows' walk, whose edges
 * mostly end there; the bands' find theirs made, rast__acc_run_init). */
RAST__HOT void RAST__ACC_N(rast__acc_ends)(RAST__ACC_E *e, int32_t j, int64_t rel0, const rast__acc *a, int64_t *xa,
                              uint64_t *ta, int64_t *xb, uint64_t *tb, int lazy)
{
    const int64_t rel1 = rel0 + e->dy;
    if (rel0 > 0) {
        *ta = (uint64_t)rel0 << a->hq;
        *xa = (int64_t)e->xt * ((int64_t)1 << a->hq);
    } else {
        *ta = 0;
        *xa = RAST__ACC_N(rast__acc_top)(e, j, a);
    }
    if (rel1 < a->p) {
        *tb = (uint64_t)rel1 << a->hq;
        *xb = ((int64_t)e->xt + e->dx) * ((int64_t)1 << a->hq);
    } else {
        *tb = QT;
#if !defined(__OPTIMIZE_SIZE__)
        if (rel0 > 0 && e->qrow != j + 1) /* (e starts in row j) */
            *xb = RAST__ACC_N(rast__acc_top1)(e, j + 1, a, lazy);
        else
#endif
            *xb = RAST__ACC_N(rast__acc_top)(e, j + 1, a);
    }
    (void)lazy;
}

/* The part of e from (xa, ta) to (xb, tb) (Q units; t from the row's top,
 * whose top is off below e's top), sign s; cells sx apart; the parts
 * counted (a->cnt) when count. */
RAST__HOT void RAST__ACC_N(rast__acc_part)(rast__acc *a, RAST__ACC_E *e, int64_t off, int64_t xa, uint64_t ta,
                           int64_t xb, uint64_t tb, int32_t s, int32_t sx, int count)
{
    const uint64_t fm = QT - 1, neg = s < 0 ? ~(uint64_t)0 : 0;
    uint64_t *acc = a->acc;
    int64_t ca = rast__acc_col(xa), cb = rast__acc_col(xb), col, cend, step, lo, hi, qt;
    uint64_t f = (uint64_t)xa & fm, fb = (uint64_t)xb & fm, t = ta, fin, fout;
    uint32_t qtr, adx;
    if (ta >= tb) return;
    if (ca < a->x0 && cb < a->x0) { /* all left of the clip */
        acc[0] += (((tb - ta) << 21) ^ neg) - neg;
        rast__acc_touch(a, 0, 0, count);
        return;
    }
    if (ca == cb) {
        if (ca >= a->x1) return;
        lo = hi = ca - a->x0;
        rast__acc_put(acc, lo, f, fb, tb - ta, neg, sx);
        rast__acc_touch(a, (int32_t)lo, (int32_t)hi + 1, count);
        return;
    }
    adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    if (ca < cb) { /* right: the verticals ca + 1 .. cb */
        if (ca >= a->x1) return;
        step = 1;
        fin = 0;
        fout = QT;
        if (ca < a->x0) { /* to vertical x0 as cover left of the clip */
            if (e->qX != a->x0) RAST__ACC_N(rast__acc_t_first)(e, a->x0, a);
            qt = e->qt - off;
            t = qt < (int64_t)t ? t : qt > (int64_t)tb ? tb : (uint64_t)qt;
            acc[0] += (((t - ta) << 21) ^ neg) - neg;
            ca = a->x0;
            f = 0;
            e->qt += e->qts;
            e->qtr += e->qtsr;
            if (e->qtr >= adx) {
                e->qtr -= adx;
                e->qt++;
            }
            e->qX++;
        } else if (e->qX != ca + 1) {
            RAST__ACC_N(rast__acc_t_first)(e, ca + 1, a);
        }
        cend = cb < a->x1 ? cb : a->x1;
        lo = ca;
        hi = cend;
    } else { /* left: the verticals ca .. cb + 1 */
        if (cb >= a->x1) return;
        step = -1;
        fin = QT;
        fout = 0;
        if (ca >= a->x1) { /* from vertical x1 */
            if (e->qX != a->x1) RAST__ACC_N(rast__acc_t_first)(e, a->x1, a);
            qt = e->qt - off;
            t = qt < (int64_t)t ? t : qt > (int64_t)tb ? tb : (uint64_t)qt;
            ca = a->x1 - 1;
            f = QT;
            e->qt += e->qts;
            e->qtr += e->qtsr;
            if (e->qtr >= adx) {
                e->qtr -= adx;
                e->qt++;
            }
            e->qX--;
        } else if (e->qX != ca) {
            RAST__ACC_N(rast__acc_t_first)(e, ca, a);
        }
        cend = cb >= a->x0 ? cb : a->x0 - 1;
        lo = cend;
        hi = ca;
    }
    qt = e->qt - off;
    qtr = e->qtr;
    for (col = ca; col != cend; col += step) {
        uint64_t tx = qt < (int64_t)t ? t : qt > (int64_t)tb ? tb : (uint64_t)qt;
        rast__acc_put(acc, col - a->x0, f, fout, tx - t, neg, sx);
        t = tx;
        f = fin;
        qt += e->qts;
        qtr += e->qtsr;
        if (qtr >= adx) {
            qtr -= adx;
            qt++;
        }
    }
    e->qt = qt + off;
    e->qtr = qtr;
    e->qX = (RAST__ACC_COL)(e->qX + (col - ca));
    if (col == cb && col >= a->x0 && col < a->x1) { /* the last column, inside the clip */
        rast__acc_put(acc, col - a->x0, f, fb, tb - t, neg, sx);
    } else if (col < a->x0) { /* the rest is left of the clip */
        acc[0] += (((tb - t) << 21) ^ neg) - neg;
    } /* else the rest is right of the clip */
    lo = lo < a->x0 ? 0 : lo - a->x0;
    hi = (hi >= a->x1 ? a->x1 - 1 : hi) - a->x0 + 1;
    rast__acc_touch(a, (int32_t)lo, (int32_t)hi, count);
}


/*
 * coverage_acc.c - signed-area accumulation ("accumulate") into uint8 or
 * uint16 levels, a row of cells at a time, or a band of four for long
 * edges (DESIGN section 1a; the bound in rastrum.h).
 *
 * The edges (rast__cedge, their steps set by rast__cov_prep) are ordered
 * by the pixel row where they start with a radix sort (no heap, no
 * cancelling: the integral does not need it).  Row by row, each edge that
 * spans part of the row deposits that part into ONE array of 64-bit cells
 * acc[] (when the edges are long, each edge deposits its parts in the four
 * rows of a band, each row's into that row's cells, before the band's rows
 * are read out in order or together: rast__acc_by_bands; the sums are the
 * same; with AVX2 a band's cells of a column lie side by side,
 * RAST__ACC_SX):
 * for the piece of the part in column k, from fraction f0 to f1 of
 * the pixel (Q = 2^-30 pixel units) over the height dy (Q units),
 * acc[k] += s (dy 2^21 - ar) and acc[k + 1] += s ar, ar = floor((f0 + f1)
 * dy / 2^10), s the edge's direction (a piece left of the clip adds s dy
 * 2^21 to acc[0], one right of it nothing).  The running sum of acc[] at
 * column k is then v = 2^21 cover - area of the cells coverage_area.c
 * describes (its quick accumulation): the same sums, split between two
 * cells, so v 2^-51 is within n (2 Q + 2^-51) < (n + 1) 2^-29 of the exact
 * integral a of the winding number over the pixel, n < RAST__ACC_MAXN
 * the row's parts: a part meets a pixel at two points at most (where it enters and
 * leaves the column), each rounded to the grid of Q (its end's abscissa or
 * its column crossing's ordinate, both floored exactly by integer
 * steppers: abscissae from row to row, ordinates from column to column,
 * quotient and remainder, no division per row or column), which moves the
 * pixel's share by less than Q (the pixel's value moves by at most 2^21
 * units of 2^-51 for one unit of Q in an ordinate or abscissa); the floor
 * of ar adds less than 2^-51.  The level floor(a' M + 1/2) (a' the rule
 * applied: non-zero min(|a|, 1), even-odd |a| folded mod 2, both moving a
 * value by no more than they move a) is decided unless a' M + 1/2 is
 * within (n + 1) M 2^-29 of an integer (rast__acc_win); any such pixel
 * sends the whole row to the exact sweep (rast__cov_acc_exact_row), which
 * writes it again.  The sums are modular in 64 bits: |a| <= n / 2 <
 * 2^11 (n < RAST__ACC_MAXN = 4096), so v fits, and so does v + 2^62 in
 * the dense rows' first pass (rast__acc_sum24).  (The bound was n < 512
 * until a paragraph of text, 700 parts a row, sent nearly every row to
 * the exact sweep.)  The bands' walk takes rows of more parts too, by a
 * bound on |a| from the band's edges (speed builds: "Deep rows", below).
 *
 * The cells are cleared by the pass that reads them, which runs over the
 * columns touched only; the pixels left of them are 0, those right of
 * them all take the last sum's level (one fill).
 */
#include "coverage.h"
#include "cells.h"
#include "../base/bits.h" /* rast__ctz64 */
#if defined(__SSE2__) && !defined(RAST_NO_SIMD)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__ACC_SSE2 1
/* and AVX2 (GCC, clang on x86-64), where the processor has it, asked at
 * run time (__builtin_cpu_supports: the compiler's runtime keeps the
 * answer); -DRAST_NO_AVX2 leaves it out */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(RAST_NO_AVX2)
#include <immintrin.h>
#define RAST__ACC_AVX2 1
#endif
#endif

/* The walk's edge records.  An edge's part in a row reads its row
 * stepper, its column stepper and its ends: in a rast__cedge (rows.h,
 * 336 bytes, made for every engine) those fields are two cache lines of
 * a record chosen through the row's list of indices, and a line of text
 * of 31,000 edges (10 MB) waited on memory for them (16% of the walk's
 * time on one load, issue 33).  So the walk has its own record of just
 * those fields, 80 bytes, made once (rast__acc_sorted, from the 20-byte
 * rast__acc_thin records that "accumulate" reads straight from the
 * vertices, rast__cov_acc_points) into the edges' room in the order the
 * rows take the edges (by first row): the walk reads them in order, a
 * stream.  The exact rows, rare, rebuild the
 * rast__cedge records of their edges (rast__acc_exact).  Size-optimised
 * builds keep the edges' records: rast__aedge is rast__cedge there (the
 * same field names: the same code reads either). */
#if !defined(__OPTIMIZE_SIZE__)
#define RAST__ACC_COMPACT 1
typedef struct rast__aedge {
    int64_t qx, qxs;              /* the quick row stepper (rast__cedge's) */
    int64_t qt, qts;              /* the quick column stepper */
    uint32_t qxr, qxsr, qtr, qtsr;
    int32_t xt, yt, dx, dy;       /* the edge, top end first */
    int32_t qrow, qX, dir, lazyX; /* qrow, qX: INT32_MIN, not set; qX
                                   * RAST__ACC_LAZYX: set at vertical lazyX,
                                   * its step not made (rast__acc_t_at) */
} rast__aedge;
typedef int32_t rast__acc_col_t; /* (the type of qX) */
/* An edge as the walk's records are made from it: 20 bytes (a
 * rast__cedge's first lines were written for every edge, 336 bytes
 * apart, then read again: a tenth of the paragraph's time, issue 34).
 * "accumulate" writes these straight from the vertices
 * (rast__cov_acc_points); the edges' records other engines hand over
 * become these in place (rast__acc_thin_of). */
typedef struct rast__acc_thin {
    int32_t xt, yt, dx, dy, dir;
} rast__acc_thin;
typedef rast__acc_thin rast__acc_in; /* (the records the call's first passes read) */
#else
#define RAST__ACC_COMPACT 0
typedef rast__cedge rast__aedge;
typedef rast__cedge rast__acc_in;
typedef int64_t rast__acc_col_t;
#endif

#define QF 30
#define QT ((uint64_t)1 << QF)
#define QONE ((int64_t)1 << 51)
#define RAST__ACC_DENSE 16
/* The parts of a row the accumulation takes (the bound above: |a| <
 * 2^11); a row with more goes to the exact sweep, but in the bands' walk
 * of speed builds (rast__acc_deep_fits). */
#define RAST__ACC_MAXN 4096
/* A row of this many parts or more counts them per 16 columns for its
 * window (rast__acc_count); fewer make a window narrow enough.  (256
 * until the text family's rows of 100 to 255 parts sent 6 of its 460
 * rows to the exact sweep by the window of all their parts, at ~130,000
 * instructions each; at 64, 16 to 128 alike, only its rows with a pixel
 * at an exact tie go there: 10.) */
#define RAST__ACC_FEW 64
/* (a band's rows are read whole sooner: where all four are, its long
 * edges mark no cell, rast__acc_dband_r) */
#define RAST__ACC_DENSE_BAND 32
/* Edges of this many rows or more on the mean go the band walk (32 until
 * a mesh of 12 px cells, 11 rows an edge, walked row by row: 8 takes it
 * 16.6% fewer instructions, the circle 1.0%; 4 costs the holed disc and
 * the loop family 1%, 1 the text family 24%: callgrind, families.py seed
 * 0, 512 x 512) */
#define RAST__ACC_LONG 8
/* Dense uint8 non-zero rows of 256 parts or more summed the quick way too
 * (rast__acc_sum24's big), but in size-optimised builds, which keep the
 * smaller way (a cell at a time) */
#if defined(__OPTIMIZE_SIZE__)
#define RAST__ACC_BIG24 0
#else
#define RAST__ACC_BIG24 1
#endif
/* With AVX2, a band's cells of a column, one for each of its rows, are
 * next to each other (so that the rows are read out together, a column at
 * a time: rast__acc_quad): a band row's cells are RAST__ACC_SX words
 * apart; without, each row's cells are next to each other, as a lone
 * row's are (sx, a constant at each call: 1 or RAST__ACC_SX) */
#ifdef RAST__ACC_AVX2
#define RAST__ACC_SX RAST__ACC_BAND
#else
#define RAST__ACC_SX 1
#endif
#if defined(RAST__ACC_AVX2) && RAST__ACC_BAND != 4
#error "RAST__ACC_BAND: 4 (rast__acc_quad_avx2 holds a column's cells in one vector of four 64-bit lanes)"
#endif

/* A stepper's remainder r (< d, after adding a step's remainder below d)
 * brought below d again: returns the carry, 1 or 0, with no branch (it is
 * taken about as often as not, in no pattern: a mispredicted branch costs
 * more than these instructions). */
static inline int64_t rast__acc_carry(uint32_t *r, uint32_t d)
{
    const uint32_t c = (uint32_t)(*r >= d);
    *r -= d & (0u - c);
    return (int64_t)c;
}

/* The same, the remainder chosen by a conditional move (GCC 12 -O2: a
 * cmov, 5 instructions where the mask takes 8), for the column stepper of
 * the band walk's long rows (rast__acc_cols_in); in the row stepper
 * (rast__acc_run_row) and the short edges' loop (rast__acc_parts) the
 * mask's form took fewer instructions in all (callgrind: the spanning
 * triangles, tri10k, text) */
static inline int64_t rast__acc_carry_sel(uint32_t *r, uint32_t d)
{
    const uint32_t t = *r - d;
    const int c = *r >= d;
    *r = c ? t : *r;
    return (int64_t)c;
}

/* The window of a row of n parts, in 2^-51 levels of M = m: (n + 1) M
 * 2^-29, the bound above (< 2^47 for (n + 1) M < 2^25) */
static inline uint64_t rast__acc_win(uint64_t n, uint32_t m)
{
    return (n + 1) * m << 22;
}

/* floor(v / 2^QF) for |v| < 2^62 (no >> of a negative value) */
static inline int64_t rast__acc_col(int64_t v)
{
    return (int64_t)(((uint64_t)v + ((uint64_t)1 << 62)) >> QF) - ((int64_t)1 << 32);
}

typedef struct rast__acc {
    uint64_t *acc;     /* clip width + 1 cells */
    int32_t x0, x1;    /* clip columns */
    int32_t last;      /* x1 - x0 - 1: the last cell with a bit (of a column of the clip) */
    uint64_t *blk;     /* a bit for each cell touched (the last, width, not: never read) */
    uint32_t *z;       /* width words: a dense row's sums, cleared as they are read */
    int32_t lo, hi;    /* cells touched this row: [lo, hi] (lo > hi: none) */
    int32_t p, hq;     /* P = 2^S; HQ = 30 - S */
    int dense;         /* this row: no bits, every cell in [lo, hi] read */
#if !defined(__OPTIMIZE_SIZE__)
    int spread;        /* the counted parts did not all move lo, hi
                        * (rast__acc_parts: rast__acc_spread) */
#endif
    uint32_t *cnt;     /* NULL, or for each 16 columns the parts that touch
                        * them this row (rast__acc_count; rast__acc_part
                        * counts when asked) */
} rast__acc;

/* rast__acc_row's keep, from rast__acc_emit's (the sums kept on a tie:
 * rast__acc_ties_z); size-optimised builds have no such pass, and their
 * readouts of uint8 rows no such argument */
#if defined(__OPTIMIZE_SIZE__)
#define RAST__ACC_SPREAD(a) 0
#define RAST__ACC_KEEP_PARAM
#define RAST__ACC_KEEP_ARG(k)
#define RAST__ACC_KEEP_IN 0
#else
#define RAST__ACC_SPREAD(a) ((a)->spread)
#define RAST__ACC_KEEP_PARAM , int keep
#define RAST__ACC_KEEP_ARG(k) , (k) != NULL
#define RAST__ACC_KEEP_IN keep
#endif

/* A row's sums z[lo, hi) kept on a tie (rast__acc_emit's keep; hi < 0:
 * none), and their window: for rast__acc_ties_z */
typedef struct rast__acc_kept {
    int32_t lo, hi;
    uint64_t win;
} rast__acc_kept;

/* a's fields for the clip of o, S = s, cells acc[] and bits[] (cleared),
 * sums z[], nothing touched; dense rows as nrow says (RAST__ACC_DENSE). */
static void rast__acc_init(rast__acc *a, uint64_t *acc, uint64_t *bits, uint32_t *z, const rast__cov_out *o,
                           int32_t s, int32_t nrow)
{
    a->acc = acc;
    a->blk = bits; /* (a bit for each of the first w cells: ceil(w / 64) words) */
    a->z = z;
    a->x0 = o->clip.x0;
    a->x1 = o->clip.x1;
    a->last = a->x1 - a->x0 - 1;
    a->lo = INT32_MAX;
    a->hi = -1;
    a->p = (int32_t)1 << s;
    a->hq = QF - s;
    a->dense = (int64_t)nrow * RAST__ACC_DENSE >= a->x1 - a->x0;
    a->cnt = NULL;
#if !defined(__OPTIMIZE_SIZE__)
    a->spread = 0;
#endif
}

/* A part touches cells [lo, hi]: one more part for each 16 columns of
 * them in the clip.  A pixel's sum is off the exact integral only by the
 * parts that touch its column (the bound above, per part): one that lies
 * left of it has put its whole height's cover in the cells up to it (the
 * ordinates where it crosses the verticals between cancel, from its top
 * to its bottom, which are exact), one right of it nothing.  So the most
 * parts touching any 16 columns bound every pixel's error in the row
 * (rast__acc_emit's window): a few for a paragraph of glyphs, whose rows
 * hold hundreds of parts. */
static void rast__acc_count(rast__acc *a, int32_t lo, int32_t hi)
{
    if (hi > a->last) hi = a->last;
    for (lo >>= 4; lo <= hi >> 4; lo++) a->cnt[lo]++;
}

/* Cells [lo, hi] touched: their bits set unless the row is dense. */
RAST__HOT void rast__acc_mark(rast__acc *a, int32_t lo, int32_t hi)
{
    int32_t w0, w1;
    a->lo = lo < a->lo ? lo : a->lo; /* (no branch: at random per part) */
    a->hi = hi > a->hi ? hi : a->hi;
    if (a->dense) return;
    if (hi > a->last) hi = a->last;
    if (lo > hi) return;
    w0 = lo >> 6;
    w1 = hi >> 6;
    if (w0 == w1) {
        a->blk[w0] |= (~(uint64_t)0 << (lo & 63)) & (~(uint64_t)0 >> (63 - (hi & 63)));
        return;
    }
    a->blk[w0] |= ~(uint64_t)0 << (lo & 63);
    for (w0++; w0 < w1; w0++) a->blk[w0] = ~(uint64_t)0;
    a->blk[w1] |= ~(uint64_t)0 >> (63 - (hi & 63));
}

/* One column's piece: fractions f0 .. f1, height dy, signed by neg (0 or
 * all ones); column k of the clip (0 <= k < width), cells sx apart. */
RAST__HOT void rast__acc_put(uint64_t *acc, int64_t k, uint64_t f0, uint64_t f1, uint64_t dy,
                                 uint64_t neg, int32_t sx)
{
    uint64_t ar = ((f0 + f1) * dy) >> 10;
    acc[k * sx] += (((dy << 21) - ar) ^ neg) - neg;
    acc[(k + 1) * sx] += (ar ^ neg) - neg;
}

/* rast__acc_mark, and rast__acc_count when count (a constant at each
 * call: nothing added where it is 0) */
RAST__HOT void rast__acc_touch(rast__acc *a, int32_t lo, int32_t hi, int count)
{
    rast__acc_mark(a, lo, hi);
    /* (the column after the last, hi, gets the part's whole height: exact;
     * size-optimised builds count it too, one instruction fewer) */
#if defined(__OPTIMIZE_SIZE__)
    if (count) rast__acc_count(a, lo, hi);
#else
    if (count) rast__acc_count(a, lo, hi - 1);
#endif
}

/* A row step not made (the walk's records' qxsr: a remainder is < dy <
 * 2^28); rast__acc_qxs makes it (its records only: the edges' own have
 * theirs, rows.c) */
#if RAST__ACC_COMPACT
#define RAST__ACC_UNMADE UINT32_MAX
/* a column stepper set without its step (rast__acc_t_at): no vertical's
 * qX (|X| <= 2^28) */
#define RAST__ACC_LAZYX (INT32_MIN + 1)
static inline void rast__acc_qxs(rast__aedge *e)
{
    if (e->qxsr == RAST__ACC_UNMADE) rast__cov_qxstep(e->dx, e->dy, &e->qxs, &e->qxsr);
}
#endif

/* The walk's functions of an edge's part (coverage_acc_edge.tmpl.h), on its
 * records; in builds with compact ones, a copy on the edges' own records
 * too, named ..._fat, for "area"'s rows. */
#define RAST__ACC_E rast__aedge
#define RAST__ACC_N(f) f
#define RAST__ACC_COL rast__acc_col_t
#define RAST__ACC_FAT (!RAST__ACC_COMPACT)
#if RAST__ACC_COMPACT
#define RAST__ACC_QXS(e) rast__acc_qxs(e)
#else
#define RAST__ACC_QXS(e) ((void)0)
#endif
#include "coverage_acc_edge.tmpl.h"
#undef RAST__ACC_E
#undef RAST__ACC_N
#undef RAST__ACC_COL
#undef RAST__ACC_FAT
#if RAST__ACC_COMPACT
#define RAST__ACC_E rast__cedge
#define RAST__ACC_N(f) f##_fat
#define RAST__ACC_COL int64_t
#define RAST__ACC_FAT 1
#undef RAST__ACC_QXS
#define RAST__ACC_QXS(e) ((void)0)
#include "coverage_acc_edge.tmpl.h"
#undef RAST__ACC_E
#undef RAST__ACC_N
#undef RAST__ACC_COL
#undef RAST__ACC_FAT
#define RAST__ACC_FATN(f) f##_fat
#else
#define RAST__ACC_FATN(f) f
#endif

#if !defined(__OPTIMIZE_SIZE__) /* (only the speed builds' tie passes read it) */
/* The tie passes' end of e's part in row j (its bottom rel1 = yt + dy -
 * Yj below the row's top): (x, *tb) in Q units, t from the row's top, as
 * rast__acc_ends finds it (P = p, HQ = hq: the pass's copies of a's);
 * *exact cleared when the abscissa at the row's
 * bottom was floored (the stepper's remainder, read after the step). */
static inline int64_t rast__acc_bottom(rast__aedge *e, int32_t j, int64_t rel1, int32_t p, int32_t hq,
                                       const rast__acc *a, uint64_t *tb, int *exact)
{
    int64_t x;
    if (rel1 < p) {
        *tb = (uint64_t)rel1 << hq;
        return ((int64_t)e->xt + e->dx) * ((int64_t)1 << hq);
    }
    *tb = QT;
    x = rast__acc_top(e, j + 1, a);
    *exact &= e->qxr == 0;
    return x;
}
#endif

/* floor(x / P) for |x| < 2^62, by a shift (a division takes tens of
 * cycles, and this runs a few times an edge) */
static int64_t rast__acc_floorp(int64_t x, const rast__acc *a)
{
    const int32_t sh = QF - a->hq;
    return (int64_t)(((uint64_t)x + ((uint64_t)1 << 62)) >> sh) - ((int64_t)1 << (62 - sh));
}

/* The last row that e runs through, whole, if e lies in the columns of
 * the clip; INT32_MIN if not (rast__acc_edge's thru). */
static int32_t rast__acc_thru(const rast__aedge *e, const rast__acc *a)
{
    const int64_t xlo = (int64_t)e->xt + (e->dx < 0 ? e->dx : 0), xhi = (int64_t)e->xt + (e->dx < 0 ? 0 : e->dx);
    if (rast__acc_floorp(xlo, a) < a->x0 || rast__acc_floorp(xhi, a) >= a->x1) return INT32_MIN;
    return (int32_t)(rast__acc_floorp((int64_t)e->yt + e->dy, a) - 1);
}

/* e's part in row j (rel0 = e's top - the row's): rast__acc_ends, then
 * rast__acc_part; inline in both walks but in size-optimised builds
 * (out of line in the bands', as the rare way, it was a quarter of the
 * instructions of 10,000 small triangles, two parts an edge: a call and
 * its registers ~35 of the ~220 of a part) */
RAST__HOT void rast__acc_row_part_in(rast__acc *a, rast__aedge *e, int32_t j, int64_t rel0, int32_t sx, int count)
{
    int64_t xa, xb;
    uint64_t ta, tb;
    rast__acc_ends(e, j, rel0, a, &xa, &ta, &xb, &tb, 0);
    rast__acc_part(a, e, -rel0 * ((int64_t)1 << a->hq), xa, ta, xb, tb, e->dir, sx, count);
}

#if defined(__OPTIMIZE_SIZE__) /* (there one copy, out of line) */
RAST__APART void rast__acc_row_part(rast__acc *a, rast__aedge *e, int32_t j, int64_t rel0)
{
    rast__acc_row_part_in(a, e, j, rel0, RAST__ACC_SX, 0);
}
#define RAST__ACC_ROW_PART(a, e, j, rel0) rast__acc_row_part(a, e, j, rel0)
#else
#define RAST__ACC_ROW_PART(a, e, j, rel0) rast__acc_row_part_in(a, e, j, rel0, RAST__ACC_SX, 0)
#endif

/* A whole column's piece in rast__acc_cols_in: the column stepper's
 * remainder r moved a column (qtsr), the column's height qts or qts + 1
 * (the carry) in 2^-30 units, d = its height 2^20 with the edge's sign:
 * d0 or d1 (modulo 2^64), added to the cell with the share that the last
 * piece left for it (*prev); *sum += d (from which the caller has the
 * stepper's qt after the loop: fewer instructions a column than qt's own
 * step and difference). */
static inline void rast__acc_col_step(uint64_t *cell, uint32_t *r, uint32_t qtsr, uint32_t adx, uint64_t d0,
                                      uint64_t d1, uint64_t *prev, uint64_t *sum)
{
    uint64_t d;
    *r += qtsr;
    d = rast__acc_carry_sel(r, adx) ? d1 : d0;
    *cell += d + *prev;
    *prev = d;
    *sum += d;
}

/* The part of e through a whole row from xa (its top) to xb (its bottom)
 * in columns ca != cb of the clip (relative), its column stepper at the
 * next vertical it crosses (as the part in the row above leaves it) or
 * set there; off as rast__acc_part's; right: e goes right (ca < cb), a
 * constant at each call.  The verticals between are crossed at ordinates
 * in [0, QT] (floors of values in it) in order: no clamping.  The cells
 * touched, from the lesser of ca and cb to the greater + 1, are the
 * caller's to mark (rast__acc_run_row: not in a dense band, whose span
 * covers them). */
RAST__HOT void rast__acc_cols_in(rast__acc *a, rast__aedge *e, int64_t off, int64_t xa, int64_t xb,
                                 int64_t ca, int64_t cb, int right)
{
    const uint64_t fm = QT - 1, neg = e->dir < 0 ? ~(uint64_t)0 : 0;
    const uint32_t adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    const int64_t x0 = a->x0, X = ca + (int64_t)right + x0; /* the first vertical crossed */
    uint64_t *acc = a->acc, f = (uint64_t)xa & fm, t, prev = 0, sum = 0, d0, d1;
    int64_t qt, col, qts;
    uint32_t qtr, qtsr;
    if (e->qX != X) rast__acc_t_first(e, X, a); /* (the column step with it, the first time) */
    qtsr = e->qtsr;
    qts = e->qts;
    d0 = (((uint64_t)qts << 20) ^ neg) - neg;
    d1 = d0 + ((((uint64_t)1 << 20) ^ neg) - neg);
    qt = e->qt - off;
    qtr = e->qtr;
    /* the first column's piece, to the first vertical; then each whole
     * column's, of height d / 2^20 between two verticals, adds d to its
     * cell and the next (rast__acc_put with f0 + f1 = QT), which the loop
     * carries: prev, the last piece's share for the next cell */
    rast__acc_put(acc, ca, f, right ? QT : 0, (uint64_t)qt, neg, RAST__ACC_SX);
    if (right) {
        for (col = ca + 1; col != cb; col++)
            rast__acc_col_step(&acc[col * RAST__ACC_SX], &qtr, qtsr, adx, d0, d1, &prev, &sum);
        acc[cb * RAST__ACC_SX] += prev;
        f = 0;
    } else {
        for (col = ca - 1; col != cb; col--)
            rast__acc_col_step(&acc[(col + 1) * RAST__ACC_SX], &qtr, qtsr, adx, d0, d1, &prev, &sum);
        acc[(cb + 1) * RAST__ACC_SX] += prev;
        f = QT;
    }
    /* the last vertical's ordinate: the first's and the columns' heights
     * between (sum: their total, at most QT, times 2^20 with the sign) */
    qt += (int64_t)((((sum ^ neg) - neg)) >> 20);
    t = (uint64_t)qt;
    qt += qts; /* the stepper to the vertical after this part's last */
    qtr += qtsr;
    qt += rast__acc_carry_sel(&qtr, adx);
    rast__acc_put(acc, cb, f, (uint64_t)xb & fm, QT - t, neg, RAST__ACC_SX);
    e->qt = qt + off;
    e->qtr = qtr;
    e->qX = (rast__acc_col_t)(e->qX + (cb - ca));
}

/* Out of line, one for each direction, so that the rows' loop keeps its
 * registers and each direction's branches their own history (the edges of
 * a shape alternate: under cachegrind's branch simulation, one function's
 * branch on the direction made a fifth of the star's mispredictions). */
RAST__APART void rast__acc_cols_r(rast__acc *a, rast__aedge *e, int64_t off, int64_t xa, int64_t xb,
                                  int64_t ca, int64_t cb)
{
    rast__acc_cols_in(a, e, off, xa, xb, ca, cb, 1);
}

RAST__APART void rast__acc_cols_l(rast__acc *a, rast__aedge *e, int64_t off, int64_t xa, int64_t xb,
                                  int64_t ca, int64_t cb)
{
    rast__acc_cols_in(a, e, off, xa, xb, ca, cb, 0);
}

/* The row stepper of an edge that runs through rows, in locals. */
typedef struct rast__acc_run {
    int64_t qx, qxs, bias, ca; /* qx from the clip's left side (bias: its abscissa), >= 0; ca its column */
    uint64_t neg;
    uint32_t qxr, qxsr, dy, adx; /* (adx = |dx|, but in size-optimised builds) */
} rast__acc_run;

/* e's part in the row of cells a that it runs through, whole, at the
 * stepper u (at the row's top; moved to its bottom), off as
 * rast__acc_part's; right as rast__acc_cols_in's; marks: the cells
 * touched marked (0: the caller marks them, the row being dense). */
RAST__HOT void rast__acc_run_row(rast__acc *a, rast__aedge *e, rast__acc_run *u, int64_t off, int right,
                                 int marks)
{
    const uint64_t fm = QT - 1;
    const int64_t ca = u->ca;
    int64_t xb = u->qx + u->qxs, cb;
    u->qxr += u->qxsr;
    xb += rast__acc_carry(&u->qxr, u->dy);
    /* its column of the clip (e lies in it: no clip tests) */
    cb = (int64_t)((uint64_t)xb >> QF);
    if (ca == cb) {
        rast__acc_put(a->acc, ca, (uint64_t)u->qx & fm, (uint64_t)xb & fm, QT, u->neg, RAST__ACC_SX);
        if (marks) rast__acc_mark(a, (int32_t)ca, (int32_t)ca + 1);
    } else if (cb == ca + (right ? 1 : -1) && e->qX == ca + (int64_t)right + a->x0) {
        /* one vertical crossed, the column stepper there (as the last
         * crossing left it): the two columns' pieces here, with no call */
        const uint64_t t = (uint64_t)(e->qt - off);
#if defined(__OPTIMIZE_SIZE__)
        const uint32_t adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
#else
        const uint32_t adx = u->adx; /* (once a band: 1% of the spanning triangles' instructions) */
#endif
        uint32_t qtr = e->qtr + e->qtsr;
        rast__acc_put(a->acc, ca, (uint64_t)u->qx & fm, right ? QT : 0, t, u->neg, RAST__ACC_SX);
        rast__acc_put(a->acc, cb, right ? 0 : QT, (uint64_t)xb & fm, QT - t, u->neg, RAST__ACC_SX);
        e->qt += e->qts + rast__acc_carry(&qtr, adx);
        e->qtr = qtr;
        e->qX += right ? 1 : -1;
    } else if (right) {
        rast__acc_cols_r(a, e, off, u->qx, xb, ca, cb);
    } else {
        rast__acc_cols_l(a, e, off, u->qx, xb, ca, cb);
    }
    if (marks && ca != cb && right) /* (the columns crossed: a dense band's span has them) */
        rast__acc_mark(a, (int32_t)ca, (int32_t)cb + 1);
    else if (marks && ca != cb)
        rast__acc_mark(a, (int32_t)cb, (int32_t)ca + 1);
    u->qx = xb;
    u->ca = cb;
}

#if RAST__ACC_BAND % 4 != 0
#error "RAST__ACC_BAND: a multiple of 4 (rast__acc_run_band takes a whole band four rows at a time)"
#endif

/* u: e's row stepper, from the cells' clip v */
RAST__HOT void rast__acc_run_init(rast__acc_run *u, const rast__acc *v, const rast__aedge *e)
{
    u->qx = e->qx;
    u->qxr = e->qxr;
    u->qxs = e->qxs;
    u->qxsr = e->qxsr;
    u->dy = (uint32_t)e->dy;
#if !defined(__OPTIMIZE_SIZE__)
    u->adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
#endif
    u->neg = e->dir < 0 ? ~(uint64_t)0 : 0;
    u->bias = (int64_t)v->x0 * (int64_t)QT;
    u->qx -= u->bias;
    u->ca = (int64_t)((uint64_t)u->qx >> QF);
}

/* Rows r .. rend of the band (cells v[r]; ok[r] each), which e runs
 * through, from the row stepper's row r (off from e's top to row r's);
 * returns the first row not walked (past rend, or one whose ok is 0). */
RAST__HOT int32_t rast__acc_run_rows(rast__acc *v, const unsigned char *ok, rast__aedge *e, int32_t r,
                                     int32_t rend, int64_t off, int right)
{
    rast__acc_run u;
    rast__acc_run_init(&u, v, e);
    for (; r <= rend && ok[r]; r++, off += (int64_t)QT) rast__acc_run_row(&v[r], e, &u, off, right, 1);
    e->qx = u.qx + u.bias;
    e->qxr = u.qxr;
    return r;
}

/* The whole band, every row ok, from its top (off from e's top), four
 * rows at a time with no test between them (a loop's exit mispredicted
 * about once an edge and band): the band's loop sends its common case
 * here, past rast__acc_edge's tests; one function for each direction. */
RAST__HOT void rast__acc_run_band(rast__acc *v, rast__aedge *e, int64_t off, int right, int64_t *span)
{
    const int marks = !span;
    rast__acc_run u;
    int32_t r;
    rast__acc_run_init(&u, v, e);
    if (span && right) /* (its column at the top: the least if e goes right, else the greatest) */
        span[0] = u.ca < span[0] ? u.ca : span[0];
    else if (span)
        span[1] = u.ca > span[1] ? u.ca : span[1];
    for (r = 0; r < RAST__ACC_BAND; r += 4, off += 4 * (int64_t)QT) {
        rast__acc_run_row(&v[r], e, &u, off, right, marks);
        rast__acc_run_row(&v[r + 1], e, &u, off + (int64_t)QT, right, marks);
        rast__acc_run_row(&v[r + 2], e, &u, off + 2 * (int64_t)QT, right, marks);
        rast__acc_run_row(&v[r + 3], e, &u, off + 3 * (int64_t)QT, right, marks);
    }
    e->qx = u.qx + u.bias;
    e->qxr = u.qxr;
    if (span && right)
        span[1] = u.ca > span[1] ? u.ca : span[1];
    else if (span)
        span[0] = u.ca < span[0] ? u.ca : span[0];
}

RAST__APART void rast__acc_band_r(rast__acc *v, rast__aedge *e, int64_t off)
{
    rast__acc_run_band(v, e, off, 1, NULL);
}

RAST__APART void rast__acc_band_l(rast__acc *v, rast__aedge *e, int64_t off)
{
    rast__acc_run_band(v, e, off, 0, NULL);
}

/* The same for a band whose rows are all dense: the cells touched not
 * marked, but the columns that e's abscissae span (from its top's to its
 * bottom's, of the clip) added to span[0] .. span[1] */
RAST__APART void rast__acc_dband_r(rast__acc *v, rast__aedge *e, int64_t off, int64_t *span)
{
    rast__acc_run_band(v, e, off, 1, span);
}

RAST__APART void rast__acc_dband_l(rast__acc *v, rast__aedge *e, int64_t off, int64_t *span)
{
    rast__acc_run_band(v, e, off, 0, span);
}

#if !defined(__OPTIMIZE_SIZE__)
/* e's parts in rows j0 + r .. j0 + r1 (two or more) of a band whose rows
 * are all ok, e in the columns of the clip (rast__acc_thru not
 * INT32_MIN), in one loop, both steppers in registers from row to row and
 * column to column (a small triangle's edge meets a band in one to four
 * rows, its first or last among them: rast__acc_edge's rows, each partial
 * one by rast__acc_row_part_in with its tests of the clip and the
 * steppers in the record, took ~500 instructions a band of 10,000 small
 * triangles, ~210 a row).  A part's pieces are rast__acc_part's: its
 * first column's to the first vertical, each whole column's between two
 * (rast__acc_cols_in's way: its height d / 2^20 added to its cell and the
 * next, carried as prev), its last column's from the last vertical; the
 * verticals' ordinates, floors of values within [ta, tb], need no clamp
 * (rast__acc_cols_in's argument for [0, QT]), so the cells get the same
 * sums (docs/coverage.md, the accumulation's bound per part).  span:
 * NULL, or (the band's rows all dense) the columns that e's abscissae
 * span added to span[0] .. span[1], as rast__acc_dband_r's, no cell
 * marked.  right: e goes right, a constant at each call. */
RAST__HOT void rast__acc_short_in(rast__acc *v, rast__aedge *e, int32_t j0, int32_t r, int32_t r1, int64_t *span,
                                  int right)
{
    const int32_t p = v->p, hq = v->hq;
    const int64_t bias = (int64_t)v->x0 * (int64_t)QT, rel0 = (int64_t)e->yt - (int64_t)(j0 + r) * p;
    const int64_t rel1 = rel0 + e->dy - (int64_t)(r1 - r) * p; /* (row r1's bottom end) */
    const int32_t rl = rel1 < p ? r1 : r1 + 1; /* the row whose part ends at e's end (if in the band) */
    const uint64_t fm = QT - 1, neg = e->dir < 0 ? ~(uint64_t)0 : 0;
    const uint32_t dy = (uint32_t)e->dy, adx = (uint32_t)(e->dx < 0 ? -e->dx : e->dx);
    const int32_t r0 = r;
    int64_t xa, xb = 0, qxs = 0, qt = 0, qts = 0, c0;
    uint64_t ta, tb, d0 = 0, d1 = 0;
    uint32_t qxr = 0, qxsr = 0, qtr = 0, qtsr = 0;
    int cols = 0; /* the column stepper in registers: qt from the row's top */
    if (rel0 > 0) { /* (e starts in row j0 + r) */
        ta = (uint64_t)rel0 << hq;
        xa = (int64_t)e->xt * ((int64_t)1 << hq) - bias;
    } else {
        ta = 0;
        xa = rast__acc_top(e, j0 + r, &v[r]) - bias;
    }
    if (r < rl) { /* the row stepper at the next row's top (rast__acc_ends' way), then in registers */
        const int32_t j1 = j0 + r + 1;
        xb = (rel0 > 0 && e->qrow != j1 ? rast__acc_top1(e, j1, &v[r], 0) : rast__acc_top(e, j1, &v[r])) - bias;
        rast__acc_qxs(e);
        qxr = e->qxr;
        qxs = e->qxs;
        qxsr = e->qxsr;
    }
    c0 = (int64_t)((uint64_t)xa >> QF);
    for (;;) {
        uint64_t *const acc = v[r].acc;
        int64_t ca, cb;
        if (r == rl) {
            tb = (uint64_t)rel1 << hq;
            xb = ((int64_t)e->xt + e->dx) * ((int64_t)1 << hq) - bias;
        } else {
            tb = QT;
        }
        ca = (int64_t)((uint64_t)xa >> QF);
        cb = (int64_t)((uint64_t)xb >> QF);
        if (ca == cb) {
            rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)xb & fm, tb - ta, neg, RAST__ACC_SX);
            if (!span) rast__acc_mark(&v[r], (int32_t)ca, (int32_t)ca + 1);
        } else {
            uint64_t t, prev = 0, sum = 0;
            int64_t col;
            if (!cols) { /* the column stepper, once a call */
                const int64_t X = ca + right + v->x0;
                if (e->qX != X) rast__acc_t_first(e, X, &v[r]);
                qt = e->qt - (int64_t)(r - r0) * (int64_t)QT + rel0 * ((int64_t)1 << hq);
                qtr = e->qtr;
                qtsr = e->qtsr;
                qts = e->qts;
                d0 = (((uint64_t)qts << 20) ^ neg) - neg;
                d1 = d0 + ((((uint64_t)1 << 20) ^ neg) - neg);
                cols = 1;
            }
            t = (uint64_t)qt;
            rast__acc_put(acc, ca, (uint64_t)xa & fm, right ? QT : 0, t - ta, neg, RAST__ACC_SX);
            if (right) {
                for (col = ca + 1; col != cb; col++)
                    rast__acc_col_step(&acc[col * RAST__ACC_SX], &qtr, qtsr, adx, d0, d1, &prev, &sum);
                acc[cb * RAST__ACC_SX] += prev;
            } else {
                for (col = ca - 1; col != cb; col--)
                    rast__acc_col_step(&acc[(col + 1) * RAST__ACC_SX], &qtr, qtsr, adx, d0, d1, &prev, &sum);
                acc[(cb + 1) * RAST__ACC_SX] += prev;
            }
            t += (((sum ^ neg) - neg)) >> 20; /* (the last vertical's ordinate) */
            rast__acc_put(acc, cb, right ? 0 : QT, (uint64_t)xb & fm, tb - t, neg, RAST__ACC_SX);
            qtr += qtsr; /* the stepper to the vertical after the last */
            qt = (int64_t)t + qts + rast__acc_carry(&qtr, adx);
            if (!span && right)
                rast__acc_mark(&v[r], (int32_t)ca, (int32_t)cb + 1);
            else if (!span)
                rast__acc_mark(&v[r], (int32_t)cb, (int32_t)ca + 1);
        }
        if (r == r1) break;
        r++; /* the next row, from this one's bottom */
        xa = xb;
        ta = 0;
        qt -= (int64_t)QT;
        if (r != rl) {
            xb += qxs;
            qxr += qxsr;
            xb += rast__acc_carry(&qxr, dy);
        }
    }
    /* e's steppers, where e goes on below the band, as the other ways
     * leave them: the row stepper at the next row's top, the column
     * stepper at the vertical after the last crossed (where e ends here,
     * its records keep the steppers as rast__acc_ends and
     * rast__acc_t_first set them: at a row and a vertical of e, as the
     * tie passes take them) */
    if (r < rl) {
        e->qx = xb + bias;
        e->qxr = qxr;
        e->qrow = j0 + r + 1;
    }
    if (cols && r < rl) {
        e->qt = qt + (int64_t)(r - r0) * (int64_t)QT - rel0 * ((int64_t)1 << hq);
        e->qtr = qtr;
        e->qX = (rast__acc_col_t)((int64_t)((uint64_t)xb >> QF) + right + v->x0);
    }
    if (span) {
        const int64_t c1 = (int64_t)((uint64_t)xb >> QF), lo = right ? c0 : c1, hi = right ? c1 : c0;
        span[0] = lo < span[0] ? lo : span[0];
        span[1] = hi > span[1] ? hi : span[1];
    }
}

RAST__APART void rast__acc_short_r(rast__acc *v, rast__aedge *e, int32_t j0, int32_t r0, int32_t r1, int64_t *span)
{
    rast__acc_short_in(v, e, j0, r0, r1, span, 1);
}

RAST__APART void rast__acc_short_l(rast__acc *v, rast__aedge *e, int32_t j0, int32_t r0, int32_t r1, int64_t *span)
{
    rast__acc_short_in(v, e, j0, r0, r1, span, 0);
}
#endif

/* e's parts in rows j0 + r, r = r0 .. r1, of a band whose row r has the
 * cells v[r] (v[r].p, .hq, .x0, .x1 alike), skipping the rows whose ok[r]
 * is 0; thru the last row that e runs through, whole, if e lies in the
 * clip (rast__acc_thru), else below any.  The rows that it runs through,
 * with its row stepper at the row's top (qrow; as the part in the row
 * above leaves it) go the quick way (rast__acc_run_rows); every other
 * row's part goes to rast__acc_row_part_in (a small triangle's edges:
 * their first and last rows; RAST__ACC_ROW_PART). */
RAST__APART void rast__acc_edge(rast__acc *v, const unsigned char *ok, rast__aedge *e, int32_t j0,
                                int32_t r0, int32_t r1, int32_t thru)
{
    const int32_t p = v->p, hq = v->hq;
    const int64_t rthru = (int64_t)thru - j0; /* (of the band) */
    int32_t r = r0;
    while (r <= r1) {
        const int32_t j = j0 + r;
        const int64_t rel0 = (int64_t)e->yt - (int64_t)j * p;
        if (!ok[r]) {
            r++;
        } else if (rel0 <= 0 && r <= rthru && e->qrow == j) {
            const int32_t rend = rthru < r1 ? (int32_t)rthru : r1;
            const int64_t off = -rel0 * ((int64_t)1 << hq);
            r = e->dx > 0 ? rast__acc_run_rows(v, ok, e, r, rend, off, 1)
                          : rast__acc_run_rows(v, ok, e, r, rend, off, 0);
            e->qrow = j0 + r;
        } else {
            RAST__ACC_ROW_PART(&v[r], e, j, rel0);
            r++;
        }
    }
}

/* 2^51 a' for the running sum v = 2^51 a (modulo 2^64): the rule applied,
 * non-zero min(|a|, 1), even-odd |a| folded mod 2 (v mod 2^52 folded: for
 * v < 0 that is |v| mod 2^52 folded, as -v = 2^52 - (v mod 2^52) mod 2^52
 * and the fold maps u and 2^52 - u alike). */
RAST__HOT uint64_t rast__acc_apply(uint64_t v, rast_fill_rule rule)
{
    const uint64_t one = (uint64_t)QONE;
    uint64_t x;
    if (rule == RAST_RULE_NONZERO) {
        x = (int64_t)v < 0 ? 0 - v : v;
        return x > one ? one : x;
    }
    x = v & (2 * one - 1);
    return x > one ? 2 * one - x : x;
}

/* The level of the running sum v (2^51 = one pixel) under the rule, M =
 * m; *bad set when a tie is within win / 2^51 of it. */
RAST__HOT uint64_t rast__acc_level(int64_t v, rast_fill_rule rule, uint32_t m, uint64_t win,
                                       uint64_t *bad)
{
    uint64_t x = rast__acc_apply((uint64_t)v, rule);
    if (m == 255) {
        x = x * 255 + ((uint64_t)1 << 50);
    } else { /* x 65535 < 2^67: by halves */
        uint64_t hi = (x >> 32) * 65535, lo = (x & 0xFFFFFFFFu) * 65535 + ((uint64_t)1 << 50);
        uint64_t lev = (hi >> 19) + ((((hi & 0x7FFFF) << 32) + lo) >> 51), fr = ((hi << 32) + lo) & ((uint64_t)QONE - 1);
        *bad |= (uint64_t)(fr - win > (uint64_t)QONE - 2 * win);
        return lev;
    }
    *bad |= (uint64_t)((x & ((uint64_t)QONE - 1)) - win > (uint64_t)QONE - 2 * win);
    return x >> 51;
}

/* A dense row's z for the running sum v (from 2^62, or from 0 when big:
 * see rast__acc_sum24); big is a constant at each call. */
RAST__HOT uint32_t rast__acc_z(uint64_t v, int big)
{
    return (uint32_t)((big ? rast__acc_apply(v, RAST_RULE_NONZERO) : v) >> 27);
}

#ifdef RAST__ACC_AVX2
/* rast__acc_apply's non-zero rule on 4 lanes of running sums (from 0) */
__attribute__((target("avx2"), always_inline)) static inline __m256i rast__acc_nz4(__m256i v)
{
    const __m256i one = _mm256_set1_epi64x(QONE), neg = _mm256_cmpgt_epi64(_mm256_setzero_si256(), v);
    v = _mm256_sub_epi64(_mm256_xor_si256(v, neg), neg);
    return _mm256_blendv_epi8(v, one, _mm256_cmpgt_epi64(v, one));
}

/* rast__acc_sum24's way on the first 8 floor(n / 8) cells at c (a lone
 * row's: next to each other), 8 at a time, the running sum from v: each
 * vector of four cells summed in place by two shifts and adds, the sum so
 * far added and carried on from its last lane; z from each sum as
 * rast__acc_z makes it (big: rast__acc_nz4 first).  The cells cleared;
 * returns the running sum after them.  (The same sums modulo 2^64 in
 * another order of additions: the same z.) */
__attribute__((target("avx2"))) static uint64_t rast__acc_sum24_avx2(uint64_t *restrict c, uint32_t *restrict z,
                                                                    size_t n, uint64_t v, int big, int keep)
{
    const __m256i zero = _mm256_setzero_si256();
    __m256i s = _mm256_set1_epi64x((int64_t)v), a, b, x;
    for (; n >= 8; n -= 8, c += 8, z += 8) {
        a = _mm256_loadu_si256((const __m256i *)(const void *)c);
        b = _mm256_loadu_si256((const __m256i *)(const void *)(c + 4));
        if (!keep) {
            _mm256_storeu_si256((__m256i *)(void *)c, zero);
            _mm256_storeu_si256((__m256i *)(void *)(c + 4), zero);
        }
        /* [a0 a1 a2 a3] + [0 a0 a1 a2], then + [0 0 s0 s1] */
        a = _mm256_add_epi64(a, _mm256_blend_epi32(_mm256_permute4x64_epi64(a, 0x90), zero, 0x03));
        b = _mm256_add_epi64(b, _mm256_blend_epi32(_mm256_permute4x64_epi64(b, 0x90), zero, 0x03));
        a = _mm256_add_epi64(a, _mm256_permute2x128_si256(a, a, 0x08));
        b = _mm256_add_epi64(b, _mm256_permute2x128_si256(b, b, 0x08));
        a = _mm256_add_epi64(a, s);
        s = _mm256_permute4x64_epi64(a, 0xFF);
        b = _mm256_add_epi64(b, s);
        s = _mm256_permute4x64_epi64(b, 0xFF);
        if (big) {
            a = rast__acc_nz4(a);
            b = rast__acc_nz4(b);
        }
        a = _mm256_srli_epi64(a, 27);
        b = _mm256_srli_epi64(b, 27);
        /* each lane's low word, in order: [a0 a1 b0 b1 | a2 a3 b2 b3], its
         * 64-bit pairs put back in order */
        x = _mm256_castps_si256(_mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), 0x88));
        _mm256_storeu_si256((__m256i *)(void *)z, _mm256_permute4x64_epi64(x, 0xD8));
    }
    return (uint64_t)_mm_cvtsi128_si64(_mm256_castsi256_si128(s));
}
#endif

/* Dense uint8 rows in two passes, the second of which a compiler can run
 * on 16 cells at a time.  The first sums cells [lo, hi) and leaves in each
 * z = floor(v / 2^27) modulo 2^32 (v = 2^51 a, the running sum: |a| <= n /
 * 2, n the row's parts), nothing else, so that the rule is applied in the
 * second pass, on 32 bits: z is v / 2^27 exactly as a signed 32-bit value
 * when |a| < 2^7 (n < 256: the caller's condition for non-zero), and its
 * low 25 bits are (v mod 2^52) / 2^27 floored whatever n (even-odd).  For
 * non-zero with more parts (big, a constant at each call), z is
 * min(|v|, 2^51) / 2^27 floored, the rule applied on 64 bits
 * (rast__acc_apply): 0 <= z <= 2^24, which the second pass's non-zero
 * rule leaves as it is, within one unit of 2^24 a' as before (a paragraph
 * of text or a thousand triangles on a row: their rows were summed a cell
 * at a time, twice the instructions).  The cells are cleared, but where
 * keep (a constant at each call): the ties' pass reads them again
 * (rast__acc_ties_z), or rast__acc_unkeep clears them. */
RAST__HOT void rast__acc_sum24(uint64_t *restrict acc, uint32_t *restrict z, int32_t lo, int32_t hi, int32_t step,
                               int big, int keep)
{
    /* from 2^62: no >> of a negative value; it adds 2^35 to the floor,
     * which leaves the low 32 bits as they were; the cells step words
     * apart */
    const size_t sx = (size_t)step;
    uint64_t v = big ? 0 : (uint64_t)1 << 62, *c = acc + (size_t)lo * sx;
    size_t n = (size_t)(hi - lo), i;
    z += lo;
#ifdef RAST__ACC_AVX2
    if (sx == 1 && n >= 32 && __builtin_cpu_supports("avx2")) { /* (a lone row's cells: 8 at a time) */
        if (keep)
            v = big ? rast__acc_sum24_avx2(c, z, n, v, 1, 1) : rast__acc_sum24_avx2(c, z, n, v, 0, 1);
        else
            v = big ? rast__acc_sum24_avx2(c, z, n, v, 1, 0) : rast__acc_sum24_avx2(c, z, n, v, 0, 0);
        c += n & ~(size_t)7;
        z += n & ~(size_t)7;
        n &= 7;
    }
#endif
    for (; n >= 4; n -= 4, c += 4 * sx, z += 4) { /* (4 a turn, written out: -O2 does not unroll) */
        const uint64_t v0 = v + c[0], v1 = v0 + c[sx], v2 = v1 + c[2 * sx];
        v = v2 + c[3 * sx];
        z[0] = rast__acc_z(v0, big);
        z[1] = rast__acc_z(v1, big);
        z[2] = rast__acc_z(v2, big);
        z[3] = rast__acc_z(v, big);
        if (!keep) c[0] = c[sx] = c[2 * sx] = c[3 * sx] = 0;
    }
    for (i = 0; i < n; i++) {
        v += c[i * sx];
        if (!keep) c[i * sx] = 0;
        z[i] = rast__acc_z(v, big);
    }
}

/* The second pass: z' = 2^24 a' floored (within one unit: the floor of a
 * negative value is one off the floor of its magnitude), the rule applied
 * on the 32-bit z (rast__acc_apply's, at this scale), 0 <= z' <= 2^24; y =
 * 255 z' + 2^23 < 2^32, level y / 2^24, the cells cleared.  |x - 2^51 a'|
 * < (n + 1) 2^22 (the bound above) and |z' 2^27 - x| < 2^27 put y / 2^24
 * within (n + 1) 255 / 2^29 + 255 / 2^24 of a' 255 + 1/2, so the level is
 * certain when y's fraction is at least that far (w, in 2^-24 levels: the
 * caller's win, (n + 1) 255 2^22, over 2^27, + 256) from 0 and from 1, lim
 * = 2^24 - 2 w;
 * returns nonzero when it is not.  rule is a constant at each call.  (z
 * is left as it is, but in size-optimised builds: rast__acc_levels24
 * clears it, or the row's are kept for the ties' pass, rast__acc_ties_z.) */
RAST__HOT uint32_t rast__acc_level24(uint32_t *c, unsigned char *out, uint32_t w, uint32_t lim,
                                     rast_fill_rule rule)
{
    const uint32_t one = (uint32_t)1 << 24, z = *c;
    uint32_t x, y;
    if (rule == RAST_RULE_NONZERO) {
        const uint32_t neg = 0 - (z >> 31);
        x = (z ^ neg) - neg; /* |z| as a signed value: at most 2^31 */
        x = x > one ? one : x;
    } else {
        x = z & (2 * one - 1);
        x = x > one ? 2 * one - x : x;
    }
    y = (x << 8) - x + ((uint32_t)1 << 23);
#if defined(__OPTIMIZE_SIZE__)
    *c = 0; /* (there no pass keeps them: cleared here, the smaller way) */
#endif
    *out = (unsigned char)(y >> 24);
    return (uint32_t)(((y & 0xFFFFFFu) - w) > lim);
}

#ifdef RAST__ACC_SSE2
/* rast__acc_level24 on the 4 lanes at z: the levels, in the low
 * byte of each lane; the tie test's d = frac - w ORed into *below (d < 0:
 * its sign) and d > lim into *above, signed.  z fits a signed lane (the
 * caller's condition for non-zero), and so do x and y >> 24. */
RAST__HOT __m128i rast__acc_lanes(uint32_t *z, __m128i vw, __m128i vlim, __m128i *below, __m128i *above,
                                  rast_fill_rule rule)
{
    const __m128i one = _mm_set1_epi32(1 << 24);
    __m128i *p = (__m128i *)(void *)z, x = _mm_loadu_si128(p), c, d;
    if (rule == RAST_RULE_NONZERO) { /* min(|z|, 2^24) */
        c = _mm_srai_epi32(x, 31);
        x = _mm_sub_epi32(_mm_xor_si128(x, c), c);
        c = _mm_cmpgt_epi32(x, one);
        x = _mm_or_si128(_mm_and_si128(c, one), _mm_andnot_si128(c, x));
    } else { /* z mod 2^25, folded at 2^24 */
        x = _mm_and_si128(x, _mm_set1_epi32((2 << 24) - 1));
        c = _mm_cmpgt_epi32(x, one);
        x = _mm_or_si128(_mm_and_si128(c, _mm_sub_epi32(_mm_set1_epi32(2 << 24), x)), _mm_andnot_si128(c, x));
    }
    x = _mm_add_epi32(_mm_sub_epi32(_mm_slli_epi32(x, 8), x), _mm_set1_epi32(1 << 23)); /* y */
    d = _mm_sub_epi32(_mm_and_si128(x, _mm_set1_epi32((1 << 24) - 1)), vw);
    *below = _mm_or_si128(*below, d);
    *above = _mm_or_si128(*above, _mm_cmpgt_epi32(d, vlim));
    return _mm_srli_epi32(x, 24);
}
#endif

#ifdef RAST__ACC_AVX2
/* rast__acc_lanes on 8 lanes, with AVX2's absolute value and unsigned
 * minimum (for the same values: min(|z|, 2^24), |z| <= 2^31 read as
 * unsigned; even-odd min(x, 2^25 - x) for x < 2^25) */
__attribute__((target("avx2"), always_inline)) static inline __m256i
rast__acc_x8(__m256i x, __m256i vw, __m256i vlim, __m256i *below, __m256i *above, rast_fill_rule rule)
{
    const __m256i one = _mm256_set1_epi32(1 << 24);
    __m256i d;
    if (rule == RAST_RULE_NONZERO) {
        x = _mm256_min_epu32(_mm256_abs_epi32(x), one);
    } else {
        x = _mm256_and_si256(x, _mm256_set1_epi32((2 << 24) - 1));
        x = _mm256_min_epu32(x, _mm256_sub_epi32(_mm256_set1_epi32(2 << 24), x));
    }
    x = _mm256_add_epi32(_mm256_sub_epi32(_mm256_slli_epi32(x, 8), x), _mm256_set1_epi32(1 << 23)); /* y */
    d = _mm256_sub_epi32(_mm256_and_si256(x, _mm256_set1_epi32((1 << 24) - 1)), vw);
    *below = _mm256_or_si256(*below, d);
    *above = _mm256_or_si256(*above, _mm256_cmpgt_epi32(d, vlim));
    return _mm256_srli_epi32(x, 24);
}

/* the same on the 8 words at z */
__attribute__((target("avx2"), always_inline)) static inline __m256i
rast__acc_lanes8(uint32_t *z, __m256i vw, __m256i vlim, __m256i *below, __m256i *above, rast_fill_rule rule)
{
    const __m256i x = _mm256_loadu_si256((const __m256i *)(const void *)z);
    return rast__acc_x8(x, vw, vlim, below, above, rule);
}

/* Two columns' levels in the 4 rows of a band: the running sums s (of
 * the columns so far, one lane a row) plus the cells at c, then at c + 4
 * (cleared): [k0 k1 l0 l1 | k2 k3 l2 l3], k and l the columns, 0..3 the
 * rows (vw, vlim in that order); big as rast__acc_sum24's (s from 0) */
__attribute__((target("avx2"), always_inline)) static inline __m256i
rast__acc_pair8(uint64_t *c, __m256i *s, __m256i vw, __m256i vlim, __m256i *below, __m256i *above,
                rast_fill_rule rule, int big)
{
    __m256i *p = (__m256i *)(void *)c, a, b;
    a = *s = _mm256_add_epi64(*s, _mm256_loadu_si256(p));
    b = *s = _mm256_add_epi64(*s, _mm256_loadu_si256(p + 1));
    _mm256_storeu_si256(p, _mm256_setzero_si256());
    _mm256_storeu_si256(p + 1, _mm256_setzero_si256());
    if (big) {
        a = rast__acc_nz4(a);
        b = rast__acc_nz4(b);
    }
    a = _mm256_srli_epi64(a, 27); /* (z, as rast__acc_sum24's, in each low word) */
    b = _mm256_srli_epi64(b, 27);
    return rast__acc_x8(_mm256_castps_si256(_mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), 0x88)),
                        vw, vlim, below, above, rule);
}

/* The levels of the 4 rows of a band, out[r] each, from the cells of
 * columns [lo, hi) (cleared), 8 columns at a time, the rest one at a time
 * as rast__acc_sum24 and rast__acc_level24 do (a row's z from its lane);
 * w[r]: row r's window as rast__acc_levels24's; big as rast__acc_sum24's
 * (a constant at each call).  Returns the rows' tie flags, bit r for row
 * r. */
__attribute__((target("avx2"), always_inline)) static inline uint32_t
rast__acc_quad_in(uint64_t *restrict cells, int32_t lo, int32_t hi, unsigned char *const *out, const uint32_t *w,
                  rast_fill_rule rule, int big)
{
    const uint32_t one = (uint32_t)1 << 24;
    const __m256i vw = _mm256_setr_epi32((int32_t)w[0], (int32_t)w[1], (int32_t)w[0], (int32_t)w[1],
                                         (int32_t)w[2], (int32_t)w[3], (int32_t)w[2], (int32_t)w[3]);
    const __m256i vlim = _mm256_sub_epi32(_mm256_set1_epi32((int32_t)one), _mm256_add_epi32(vw, vw));
    /* a lane's bytes, the 8 columns of its first row, then of its second */
    const __m256i order = _mm256_setr_epi8(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15, 0, 2, 4, 6, 8,
                                           10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15);
    __m256i below = _mm256_setzero_si256(), above = below, s = _mm256_set1_epi64x(big ? 0 : (int64_t)1 << 62), y0,
            y1, y2, y3;
    uint64_t *c = cells + (size_t)lo * RAST__ACC_SX, v[4];
    uint32_t bad = 0, m, z;
    int32_t k = lo, r;
    for (; hi - k >= 8; k += 8, c += 8 * RAST__ACC_SX) {
        __m128i q0, q1;
        y0 = rast__acc_pair8(c, &s, vw, vlim, &below, &above, rule, big);
        y1 = rast__acc_pair8(c + 2 * RAST__ACC_SX, &s, vw, vlim, &below, &above, rule, big);
        y2 = rast__acc_pair8(c + 4 * RAST__ACC_SX, &s, vw, vlim, &below, &above, rule, big);
        y3 = rast__acc_pair8(c + 6 * RAST__ACC_SX, &s, vw, vlim, &below, &above, rule, big);
        y0 = _mm256_shuffle_epi8(_mm256_packus_epi16(_mm256_packs_epi32(y0, y1), _mm256_packs_epi32(y2, y3)), order);
        q0 = _mm256_castsi256_si128(y0);
        q1 = _mm256_extracti128_si256(y0, 1);
        _mm_storel_epi64((__m128i *)(void *)(out[0] + k), q0);
        _mm_storel_epi64((__m128i *)(void *)(out[1] + k), _mm_srli_si128(q0, 8));
        _mm_storel_epi64((__m128i *)(void *)(out[2] + k), q1);
        _mm_storel_epi64((__m128i *)(void *)(out[3] + k), _mm_srli_si128(q1, 8));
    }
    m = (uint32_t)_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_srai_epi32(below, 31), above)));
    bad = ((m | m >> 2) & 3) | ((m >> 2 | m >> 4) & 12);
    _mm256_storeu_si256((__m256i *)(void *)v, s);
    for (; k < hi; k++, c += RAST__ACC_SX)
        for (r = 0; r < 4; r++) {
            v[r] += c[r];
            c[r] = 0;
            z = rast__acc_z(v[r], big);
            bad |= rast__acc_level24(&z, out[r] + k, w[r], one - 2 * w[r], rule) << r;
        }
    return bad;
}

/* (one for each big: its test out of the loops) */
__attribute__((target("avx2"))) static uint32_t rast__acc_quad_avx2(uint64_t *restrict cells, int32_t lo,
                                                                   int32_t hi, unsigned char *const *out,
                                                                   const uint32_t *w, rast_fill_rule rule, int big)
{
    return big ? rast__acc_quad_in(cells, lo, hi, out, w, rule, 1) : rast__acc_quad_in(cells, lo, hi, out, w, rule, 0);
}

/* rast__acc_levels24's first 32 n cells and levels, 32 at a time (the
 * cells cleared when clear): its tie flag (nonzero: not certain) */
__attribute__((target("avx2"))) static uint32_t rast__acc_levels24_avx2(uint32_t *restrict z,
                                                                       unsigned char *restrict row, size_t n,
                                                                       uint32_t w, uint32_t lim,
                                                                       rast_fill_rule rule, int clear)
{
    __m256i below = _mm256_setzero_si256(), above = below, y0, y1, y2, y3, p;
    const __m256i vw = _mm256_set1_epi32((int32_t)w), vlim = _mm256_set1_epi32((int32_t)lim);
    const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
    for (; n >= 32; n -= 32, z += 32, row += 32) {
        y0 = rast__acc_lanes8(z, vw, vlim, &below, &above, rule);
        y1 = rast__acc_lanes8(z + 8, vw, vlim, &below, &above, rule);
        y2 = rast__acc_lanes8(z + 16, vw, vlim, &below, &above, rule);
        y3 = rast__acc_lanes8(z + 24, vw, vlim, &below, &above, rule);
        if (clear) {
            _mm256_storeu_si256((__m256i *)(void *)z, _mm256_setzero_si256());
            _mm256_storeu_si256((__m256i *)(void *)(z + 8), _mm256_setzero_si256());
            _mm256_storeu_si256((__m256i *)(void *)(z + 16), _mm256_setzero_si256());
            _mm256_storeu_si256((__m256i *)(void *)(z + 24), _mm256_setzero_si256());
        }
        /* (the packs work within each half: the words put back in order) */
        p = _mm256_packus_epi16(_mm256_packs_epi32(y0, y1), _mm256_packs_epi32(y2, y3));
        _mm256_storeu_si256((__m256i *)(void *)row, _mm256_permutevar8x32_epi32(p, order));
    }
    return (uint32_t)_mm256_movemask_epi8(_mm256_or_si256(_mm256_srai_epi32(below, 31), above));
}
#endif

/* z's word x cleared, when clear (size-optimised builds: rast__acc_level24
 * clears it) */
#if defined(__OPTIMIZE_SIZE__)
#define RAST__ACC_CLEAR(clear, x) (void)(clear)
#else
#define RAST__ACC_CLEAR(clear, x) \
    do {                          \
        if (clear) (x) = 0;       \
    } while (0)
#endif

RAST__HOT uint32_t rast__acc_levels24(uint32_t *restrict z, unsigned char *restrict row, int32_t lo,
                                      int32_t hi, uint32_t w, rast_fill_rule rule, int clear)
{
    const uint32_t lim = ((uint32_t)1 << 24) - 2 * w;
    uint32_t bad = 0;
    size_t n = (size_t)(hi - lo), i;
    /* pointers and size_t, not int indices: with -fwrapv (Python's flags)
     * an int index may wrap, and the compiler would not vectorise */
    z += lo;
    row += lo;
#ifdef RAST__ACC_AVX2
    if (n >= 32 && __builtin_cpu_supports("avx2")) {
        bad = rast__acc_levels24_avx2(z, row, n, w, lim, rule, clear);
        z += n & ~(size_t)31;
        row += n & ~(size_t)31;
        n &= 31;
    }
#endif
#ifdef RAST__ACC_SSE2
    {
        /* rast__acc_level24 written out on 4 x 4 lanes (rast__acc_lanes):
         * half the instructions of the compiler's own vectors of the loop
         * below, which packed the bytes by shuffles and gathered the tie
         * flag every turn */
        __m128i below = _mm_setzero_si128(), above = below, y0, y1, y2, y3;
        const __m128i vw = _mm_set1_epi32((int32_t)w), vlim = _mm_set1_epi32((int32_t)lim);
        for (; n >= 16; n -= 16, z += 16, row += 16) {
            y0 = rast__acc_lanes(z, vw, vlim, &below, &above, rule);
            y1 = rast__acc_lanes(z + 4, vw, vlim, &below, &above, rule);
            y2 = rast__acc_lanes(z + 8, vw, vlim, &below, &above, rule);
            y3 = rast__acc_lanes(z + 12, vw, vlim, &below, &above, rule);
            if (clear) {
                _mm_storeu_si128((__m128i *)(void *)z, _mm_setzero_si128());
                _mm_storeu_si128((__m128i *)(void *)(z + 4), _mm_setzero_si128());
                _mm_storeu_si128((__m128i *)(void *)(z + 8), _mm_setzero_si128());
                _mm_storeu_si128((__m128i *)(void *)(z + 12), _mm_setzero_si128());
            }
            _mm_storeu_si128((__m128i *)(void *)row, _mm_packus_epi16(_mm_packs_epi32(y0, y1), _mm_packs_epi32(y2, y3)));
        }
        /* (then 4 at a time: the rows of a small shape, 7 pixels on the
         * mean in the loop family, had all theirs one at a time, ~20
         * instructions each) */
        for (; n >= 4; n -= 4, z += 4, row += 4) {
            const int32_t b4 = _mm_cvtsi128_si32(_mm_packus_epi16(
                _mm_packs_epi32(rast__acc_lanes(z, vw, vlim, &below, &above, rule), _mm_setzero_si128()),
                _mm_setzero_si128()));
            if (clear) _mm_storeu_si128((__m128i *)(void *)z, _mm_setzero_si128());
            memcpy(row, &b4, 4);
        }
        bad |= (uint32_t)_mm_movemask_epi8(_mm_or_si128(_mm_srai_epi32(below, 31), above));
    }
#else
    for (; n >= 16; n -= 16, z += 16, row += 16) /* 16 at a time: no tail loop to add */
        for (i = 0; i < 16; i++) {
            bad |= rast__acc_level24(z + i, row + i, w, lim, rule);
            RAST__ACC_CLEAR(clear, z[i]);
        }
#endif
    for (i = 0; i < n; i++) {
        bad |= rast__acc_level24(z + i, row + i, w, lim, rule);
        RAST__ACC_CLEAR(clear, z[i]);
    }
    return bad;
}

/* Does a row read [lo, hi) by its sums z (rast__acc_sum24,
 * rast__acc_levels24)?  dense and m (255: uint8) as rast__acc_row's, win
 * its window. */
static inline int rast__acc_zpath(int dense, uint32_t m, int32_t lo, int32_t hi, rast_fill_rule rule, uint64_t win)
{
#if RAST__ACC_BIG24
    (void)rule;
    (void)win;
    return dense && m == 255 && lo < hi;
#else
    /* (non-zero: n < 256; dense 2: every cell read, but not this way) */
    return dense == 1 && m == 255 && lo < hi && (rule == RAST_RULE_EVENODD || win <= rast__acc_win(255, 255));
#endif
}

#ifdef RAST__ACC_AVX2
/* cells c[lo, hi) cleared 8 at a time: returns where the rest starts */
__attribute__((target("avx2"))) static int32_t rast__acc_zero_avx2(uint64_t *c, int32_t lo, int32_t hi)
{
    for (; lo + 8 <= hi; lo += 8) {
        _mm256_storeu_si256((__m256i *)(void *)(c + lo), _mm256_setzero_si256());
        _mm256_storeu_si256((__m256i *)(void *)(c + lo + 4), _mm256_setzero_si256());
    }
    return lo;
}
#endif

/* A kept row's sums z[lo, hi) and cells (sx words apart) cleared: no
 * tie, or none the ties' pass takes (rast__acc_sum24's keep) */
static void rast__acc_unkeep(uint64_t *acc, int32_t sx, uint32_t *z, int32_t lo, int32_t hi)
{
    int32_t k = lo;
    memset(z + lo, 0, (size_t)(hi - lo) * sizeof(uint32_t));
#ifdef RAST__ACC_AVX2
    if (sx == 1 && __builtin_cpu_supports("avx2")) k = rast__acc_zero_avx2(acc, lo, hi);
#endif
#ifdef RAST__ACC_SSE2
    /* (a lone row's cells, 4 a turn: a ~4 KB memset, rep stosb, counted a
     * byte an instruction by callgrind, was 6% of the text family's) */
    if (sx == 1)
        for (; k + 4 <= hi; k += 4) {
            _mm_storeu_si128((__m128i *)(void *)(acc + k), _mm_setzero_si128());
            _mm_storeu_si128((__m128i *)(void *)(acc + k + 2), _mm_setzero_si128());
        }
#endif
    for (; k < hi; k++) acc[k * sx] = 0;
}

/* Row y's levels from the cells in [lo, hi) (dense: all read; else those
 * whose bits are set in blk, the others holding 0), which are cleared with
 * their bits; the pixels left of lo get 0, those from hi on the last sum's
 * level.  rule and m are constants at each call (one loop each).  Returns
 * a tie's flag (rast__acc_level's). */
RAST__HOT uint64_t rast__acc_row(uint64_t *acc, int32_t sx, uint64_t *blk, uint32_t *z, unsigned char *row,
                                 int32_t lo, int32_t hi, int32_t w, int dense, rast_fill_rule rule, uint32_t m,
                                 uint64_t win, int keep)
{
    const rast_coverage_format f = m == 255 ? RAST_COVERAGE_U8 : RAST_COVERAGE_U16;
    uint64_t bad = 0, lev = 0, v = 0;
    uint16_t *r16 = (uint16_t *)(void *)row;
    int32_t k = lo, wi;
#if defined(__OPTIMIZE_SIZE__)
    keep = 0; /* (no pass reads them again there: rast__acc_ties_z is not built) */
#endif
    rast__cov_fill(f, row, 0, lo, 0);
    if (rast__acc_zpath(dense, m, lo, hi, rule, win)) {
#if RAST__ACC_BIG24
        /* (non-zero: big past n = 256, dense 2, or a window that wide;
         * w < 2^23 for n < RAST__ACC_MAXN) */
        if (rule == RAST_RULE_NONZERO && (dense == 2 || win > rast__acc_win(255, 255)))
            rast__acc_sum24(acc, z, lo, hi, sx, 1, keep);
        else
            rast__acc_sum24(acc, z, lo, hi, sx, 0, keep);
#else
        rast__acc_sum24(acc, z, lo, hi, sx, 0, 0);
#endif
        /* (z cleared as read, but kept on a tie when asked: rast__acc_ties_z) */
        if (!keep) {
            bad = rast__acc_levels24(z, row, lo, hi, (uint32_t)(win >> 27) + 256, rule, 1);
        } else {
            bad = rast__acc_levels24(z, row, lo, hi, (uint32_t)(win >> 27) + 256, rule, 0);
            if (!bad) rast__acc_unkeep(acc, sx, z, lo, hi);
        }
        lev = row[hi - 1];
        k = hi;
    } else if (dense) { /* no branch on the cell: half of them are 0, at random */
        for (; k < hi; k++) {
            v += acc[k * sx];
            acc[k * sx] = 0;
            lev = rast__acc_level((int64_t)v, rule, m, win, &bad);
            if (m == 255)
                row[k] = (unsigned char)lev;
            else
                r16[k] = (uint16_t)lev;
        }
    } else if (lo < hi) {
        for (wi = lo >> 6; wi <= (hi - 1) >> 6; wi++) {
            uint64_t b = blk[wi];
            blk[wi] = 0;
            for (; b; b &= b - 1) {
                int32_t col = (wi << 6) + (int32_t)rast__ctz64(b);
                uint64_t d = acc[col * sx];
                if (col > k) rast__cov_fill(f, row, k, col, lev);
                if (d) {
                    acc[col * sx] = 0;
                    v += d;
                    lev = rast__acc_level((int64_t)v, rule, m, win, &bad);
                }
                if (m == 255)
                    row[col] = (unsigned char)lev;
                else
                    r16[col] = (uint16_t)lev;
                k = col + 1;
            }
        }
    }
    rast__cov_fill(f, row, k, w, lev);
    return bad;
}

/* rast__acc_row for uint8, one for each rule and spacing of the cells (a
 * lone row's, a band row's) */
static uint64_t rast__acc_row_u8nz(uint64_t *acc, uint64_t *blk, uint32_t *z, unsigned char *row, int32_t lo,
                                   int32_t hi, int32_t w, int dense, uint64_t win RAST__ACC_KEEP_PARAM)
{
    return rast__acc_row(acc, 1, blk, z, row, lo, hi, w, dense, RAST_RULE_NONZERO, 255, win, RAST__ACC_KEEP_IN);
}

static uint64_t rast__acc_row_u8eo(uint64_t *acc, uint64_t *blk, uint32_t *z, unsigned char *row, int32_t lo,
                                   int32_t hi, int32_t w, int dense, uint64_t win RAST__ACC_KEEP_PARAM)
{
    return rast__acc_row(acc, 1, blk, z, row, lo, hi, w, dense, RAST_RULE_EVENODD, 255, win, RAST__ACC_KEEP_IN);
}

static uint64_t rast__acc_brow_u8nz(uint64_t *acc, uint64_t *blk, uint32_t *z, unsigned char *row, int32_t lo,
                                    int32_t hi, int32_t w, int dense, uint64_t win RAST__ACC_KEEP_PARAM)
{
    return rast__acc_row(acc, RAST__ACC_SX, blk, z, row, lo, hi, w, dense, RAST_RULE_NONZERO, 255, win, RAST__ACC_KEEP_IN);
}

static uint64_t rast__acc_brow_u8eo(uint64_t *acc, uint64_t *blk, uint32_t *z, unsigned char *row, int32_t lo,
                                    int32_t hi, int32_t w, int dense, uint64_t win RAST__ACC_KEEP_PARAM)
{
    return rast__acc_row(acc, RAST__ACC_SX, blk, z, row, lo, hi, w, dense, RAST_RULE_EVENODD, 255, win, RAST__ACC_KEEP_IN);
}

/* Are the edges ix[0..n) all vertical?  Then the sums of a row of their
 * parts are exact: no crossing, no abscissa stepped, and each ar = 2 f dy
 * / 2^10 with f and dy multiples of 2^HQ (HQ >= 14); so the levels are,
 * ties too (an axis-aligned box on half pixels: a tie along each side).
 * The edges are the walk's records e[] or, where e is NULL, the edges'
 * records fe[] ("area"'s rows). */
static int rast__acc_vertical(const rast__aedge *e, const rast__cedge *fe, const int32_t *ix, int32_t n)
{
    int32_t k;
    if (e) {
        for (k = 0; k < n; k++)
            if (e[ix[k]].dx) return 0;
    } else {
        for (k = 0; k < n; k++)
            if (fe[ix[k]].dx) return 0;
    }
    return 1;
}

/* Row y, written, its tie flag bad: 1 when done (handed on), 0 when a
 * level is not certain (nothing handed on) unless the row's edges
 * ix[0..n) are all vertical (rast__acc_vertical; it is asked only then). */
static int rast__acc_done(const rast__cov_out *o, int32_t y, uint64_t bad, const rast__aedge *e,
                          const rast__cedge *fe, const int32_t *ix, int32_t n)
{
    if (bad && !rast__acc_vertical(e, fe, ix, n)) return 0;
    rast__cov_row_done(o, y);
    return 1;
}

#if !defined(__OPTIMIZE_SIZE__)
/* The most parts in any 16 columns of a row of width w whose parts
 * rast__acc_parts counted (a->spread), every count read and cleared; the
 * cells [*lo, *hi) to read widened to those the counted parts touched.
 * The parts that it puts in one column or two are counted but leave lo
 * and hi as they are (8 instructions a part, a twentieth of the text
 * family's), so the counts say which cells they touched: from the first
 * counted 16 columns to the last's and the cell after (a part counted in
 * the columns of c touches c + 1 at most).  The cells read past those
 * touched hold 0: the same levels.  (Out of line: inline, the bands'
 * walk, which does not take it, lost registers to it.) */
RAST__APART uint32_t rast__acc_spread(rast__acc *a, int32_t w, int32_t *lo, int32_t *hi)
{
    const int32_t nb = (w - 1) >> 4;
    uint32_t most = 0, c;
    int32_t b, b0 = -1, b1 = -1;
    for (b = 0; b <= nb; b++) {
        c = a->cnt[b];
        if (c) {
            b0 = b0 < 0 ? b : b0;
            b1 = b;
            most = c > most ? c : most;
            a->cnt[b] = 0;
        }
    }
    if (b0 >= 0) {
        *lo = b0 * 16 < *lo ? b0 * 16 : *lo;
        *hi = b1 * 16 + 17 > *hi ? b1 * 16 + 17 : *hi;
        *hi = *hi < w ? *hi : w;
    }
    return most;
}
#endif

/* Row y from the cells touched, which are cleared: rast__acc_done's.
 * win: the window of the row's n parts, or, where a counts the parts per
 * 16 columns, that of the most of them (the counts cleared). */
RAST__HOT int rast__acc_emit(rast__acc *a, int32_t sx, const rast__cov_out *o, int32_t y, rast_fill_rule rule,
                          uint32_t m, uint64_t win, const rast__aedge *e, const rast__cedge *fe, const int32_t *ix, int32_t n,
                             rast__acc_kept *keep)
{
    unsigned char *row = rast__cov_row(o, y);
    const int32_t w = a->x1 - a->x0;
    const int dense = a->dense;
    uint64_t bad;
    int32_t lo = a->lo, hi = a->hi < w ? a->hi + 1 : w; /* [lo, hi) */
#if defined(__OPTIMIZE_SIZE__)
    (void)keep; /* (no sums kept there: rast__acc_ties_z is not built) */
#endif
#if !defined(__OPTIMIZE_SIZE__)
    if (a->cnt && a->spread) {
        win = rast__acc_win(rast__acc_spread(a, w, &lo, &hi), m);
        /* (the quick way's 32-bit sums need |a| < 2^7: n < 256) */
        if (dense && rule == RAST_RULE_NONZERO && n >= 256) a->dense = 2;
    }
#endif
    if (lo >= hi) lo = hi = 0;
    if (a->cnt && !RAST__ACC_SPREAD(a)) {
        uint32_t most = 0;
        int32_t b;
        for (b = lo >> 4; lo < hi && b <= (hi - 1) >> 4; b++) {
            most = a->cnt[b] > most ? a->cnt[b] : most;
            a->cnt[b] = 0;
        }
        win = rast__acc_win(most, m);
        /* (the quick way's 32-bit sums need |a| < 2^7: n < 256) */
        if (dense && rule == RAST_RULE_NONZERO && n >= 256) a->dense = 2;
    }
    if (o->format != RAST_COVERAGE_U8)
        bad = rast__acc_row(a->acc, sx, a->blk, a->z, row, lo, hi, w, a->dense, rule, m, win, 0);
    else if (rule == RAST_RULE_NONZERO)
        bad = (sx == 1 ? rast__acc_row_u8nz : rast__acc_brow_u8nz)(a->acc, a->blk, a->z, row, lo, hi, w, a->dense,
                                                                    win RAST__ACC_KEEP_ARG(keep));
    else
        bad = (sx == 1 ? rast__acc_row_u8eo : rast__acc_brow_u8eo)(a->acc, a->blk, a->z, row, lo, hi, w, a->dense,
                                                                    win RAST__ACC_KEEP_ARG(keep));
    a->acc[w * sx] = 0;
    a->lo = INT32_MAX;
    a->hi = -1;
#if !defined(__OPTIMIZE_SIZE__)
    /* z[lo, hi) kept (rast__acc_row): where, and the window */
    if (keep) keep->hi = -1;
    if (bad && keep && rast__acc_zpath(a->dense, m, lo, hi, rule, win)) {
        if (rast__acc_done(o, y, bad, e, fe, ix, n)) { /* (all vertical: done, z and the cells cleared) */
            rast__acc_unkeep(a->acc, sx, a->z, lo, hi);
            a->dense = dense;
            return 1;
        }
        keep->lo = lo;
        keep->hi = hi;
        keep->win = win;
        a->dense = dense;
        return 0;
    }
#endif
    a->dense = dense;
    return rast__acc_done(o, y, bad, e, fe, ix, n);
}

#ifdef RAST__ACC_AVX2
/* The 4 rows of the band j0 .. j0 + 3 (cells v[r], all dense, uint8, each
 * as rast__acc_row reads its quickly: cnt[r] parts, rule; non-zero rows of
 * 256 parts or more as rast__acc_sum24's big), read out together
 * (rast__acc_quad_avx2) into o, an array; the cells cleared.
 * Returns 1 with the rows' tie flags in *bad (bit r: row r), or 0 (no
 * cell touched: nothing done). */
static int rast__acc_quad(rast__acc *v, const rast__cov_out *o, int32_t j0, const int32_t *cnt,
                          rast_fill_rule rule, uint32_t *bad)
{
    const int32_t w = v->x1 - v->x0;
    unsigned char *out[4];
    uint32_t win[4];
    int32_t lo = INT32_MAX, hi = -1, r;
    for (r = 0; r < 4; r++) {
        lo = v[r].lo < lo ? v[r].lo : lo;
        hi = v[r].hi > hi ? v[r].hi : hi;
    }
    hi = hi < w ? hi + 1 : w;
    if (lo >= hi) return 0;
    for (r = 0; r < 4; r++) {
        out[r] = rast__cov_row(o, j0 + r);
        win[r] = (uint32_t)(rast__acc_win((uint64_t)cnt[r], 255) >> 27) + 256;
        rast__cov_fill(RAST_COVERAGE_U8, out[r], 0, lo, 0);
    }
    *bad = rast__acc_quad_avx2(v->acc, lo, hi, out, win, rule,
                               rule == RAST_RULE_NONZERO && (cnt[0] >= 256 || cnt[1] >= 256 || cnt[2] >= 256 ||
                                                             cnt[3] >= 256));
    for (r = 0; r < 4; r++) {
        rast__cov_fill(RAST_COVERAGE_U8, out[r], hi, w, out[r][hi - 1]);
        v->acc[w * RAST__ACC_SX + r] = 0;
        v[r].lo = INT32_MAX;
        v[r].hi = -1;
    }
    return 1;
}
#endif

/* ---- "area" rows by the accumulation ------------------------------------
 *
 * The accumulation gives each pixel the integral of the winding number w
 * over it, and the rule turns that into the pixel's coverage exactly when
 * w takes, on the pixel, values in one interval [i, i + 1]: both rules are
 * linear between consecutive integers.  Row j is "simple", and "area" takes
 * it this way (rast__cov_acc_area_row), when each column of the clip is
 * met by (the x range of) at most one "piece", or by two that a ring joins
 * there.  The pieces are the edges' parts in the strip and the runs of a
 * ring's horizontal edges strictly inside it; two pieces are joined when
 *   - they are parts that share an end (anywhere) in one of the shapes a
 *     ring makes: a chain (one ends where the other starts; the same
 *     direction) or a cusp (both start, or both end, there; opposite
 *     directions); or
 *   - they are a run and a part that ends at one of the run's ends, in the
 *     pixel's column.
 * Why: where two edges of a ring meet at a vertex inside the strip, and the
 * ring goes on along no horizontal edge there, it arrives once and leaves
 * once, by edges that add the same directions above the vertex as below
 * it; a run moves that balance along its length.  So w just left of column
 * c changes over the strip only where a piece crosses or touches column c.
 * One piece splits a pixel into two sides a step apart.  A chain's parts
 * are never at one height together and step w the same way; a cusp's do
 * not cross, and w steps up by one between them and back (collinear, they
 * cancel where both run); a part and a run joined in the pixel's column
 * are one path through it, or meet on its left side at a vertex that no
 * other edge reaches (one would be a third piece in the column), so that
 * the sides above and below them join round it: two values each time.
 * Anything else (three pieces in a pixel, two side by side with one
 * direction or that may cross, two runs) goes to the sweep.
 *
 * The runs come from a list of the edges that each run follows in its ring
 * (those edges may have cancelled: see rast__cov_cancel), not from the
 * row's parts.  own[] holds, for each column, the stamp of the row that last met it
 * (high word) and what met it (low word): the index in row[] of a part, or
 * RAST__OWN_RUN for a run; RAST__OWN_PAIR once two did. */
#define RAST__OWN_PAIR 0x80000000u
#define RAST__OWN_RUN 0x40000000u

/* Edges a and b, whose parts meet one column: a chain or a cusp? */
static int rast__acc_partners(const rast__cedge *a, const rast__cedge *b)
{
    const int32_t axb = a->xt + a->dx, ayb = a->yt + a->dy, bxb = b->xt + b->dx, byb = b->yt + b->dy;
    if ((axb == b->xt && ayb == b->yt) || (bxb == a->xt && byb == a->yt)) return a->dir == b->dir;
    if ((a->xt == b->xt && a->yt == b->yt) || (axb == bxb && ayb == byb)) return a->dir != b->dir;
    return 0;
}

/* Does edge e end at a run inside the strip of the row whose top is Yj,
 * in column c? */
static int rast__acc_joined(const rast__cedge *e, int64_t Yj, int32_t p, int64_t c)
{
    const int32_t xb = e->xt + e->dx;
    if ((e->hz & RAST__HZ_TOP) && e->yt > Yj && rast__floordiv(e->xt, p) == c) return 1;
    if ((e->hz & RAST__HZ_BOTTOM) && (int64_t)e->yt + e->dy < Yj + p && rast__floordiv(xb, p) == c)
        return 1;
    return 0;
}

/* Column c (of the clip) met by a piece, own[c]'s stamp tag: 1 if the
 * column stays simple.  `part` is its index in row[] (or RAST__OWN_RUN). */
RAST__HOT int rast__acc_meet(uint64_t *own, int32_t c, uint64_t tag, uint32_t part, const rast__cedge *e,
                             const int32_t *row, int64_t Yj, int32_t p, int32_t x0)
{
    const uint64_t v = own[c];
    uint32_t was;
    if ((v & ~(uint64_t)0xFFFFFFFFu) != tag) {
        own[c] = tag | part;
        return 1;
    }
    was = (uint32_t)v;
    if (was & RAST__OWN_PAIR) return 0;
    if (was == RAST__OWN_RUN) {
        if (part == RAST__OWN_RUN || !rast__acc_joined(&e[row[part]], Yj, p, (int64_t)c + x0)) return 0;
    } else if (part == RAST__OWN_RUN) {
        if (!rast__acc_joined(&e[row[was]], Yj, p, (int64_t)c + x0)) return 0;
    } else if (!rast__acc_partners(&e[row[was]], &e[row[part]])) {
        return 0;
    }
    own[c] = v | RAST__OWN_PAIR;
    return 1;
}

#if RAST__ACC_COMPACT
/* The walk's record of the edge f (rast__aedge: its fields; its qX
 * INT32_MIN where f's is INT64_MIN, not set). */
static void rast__acc_load(rast__aedge *c, const rast__cedge *f)
{
    c->qx = f->qx;
    c->qxs = f->qxs;
    c->qt = f->qt;
    c->qts = f->qts;
    c->qxr = f->qxr;
    c->qxsr = f->qxsr;
    c->qtr = f->qtr;
    c->qtsr = f->qtsr;
    c->xt = f->xt;
    c->yt = f->yt;
    c->dx = f->dx;
    c->dy = f->dy;
    c->qrow = f->qrow;
    /* (INT64_MIN: not set; a stepper set without its step, set again) */
    c->qX = f->qX < INT32_MIN || f->qX > INT32_MAX || f->qX == RAST__ACC_LAZYX ? INT32_MIN : (int32_t)f->qX;
    c->dir = f->dir;
    c->lazyX = 0;
}

#endif

/* Does row j of nrow parts fit "area" by the accumulation (its window)? */
static int rast__acc_area_fits(const rast__cov_out *o, int32_t nrow)
{
    const uint32_t m = o->format == RAST_COVERAGE_U8 ? 255 : 65535;
    return nrow < 512 && ((uint64_t)nrow + 1) * m < ((uint64_t)1 << 25);
}

/* The parts row[0..nrow) of row j (their ends in qa, qta, qb, qtb), each
 * whole with its direction, into a's cells, then the row's levels:
 * rast__acc_emit's answer, its window that of `most` parts (no column is
 * touched by more). */
static int rast__acc_area_add(rast__acc *a, rast__cedge *e, const int32_t *row, int32_t nrow, int32_t most,
                              int32_t j, rast_fill_rule rule, const rast__cov_out *o)
{
    const uint32_t m = o->format == RAST_COVERAGE_U8 ? 255 : 65535;
    const int64_t Yj = (int64_t)j * a->p;
    int32_t k;
    for (k = 0; k < nrow; k++) {
        rast__cedge *ed = &e[row[k]];
        RAST__ACC_FATN(rast__acc_part)(a, ed, -((int64_t)ed->yt - Yj) * ((int64_t)1 << a->hq), ed->qa, ed->qta,
                                       ed->qb, ed->qtb, ed->dir, 1, 0);
    }
    return rast__acc_emit(a, 1, o, j, rule, m, rast__acc_win((uint64_t)most, m), NULL, e, row, nrow, NULL);
}

int rast__cov_acc_area_row(rast__cedge *e, const int32_t *row, int32_t nrow, const int32_t *runs,
                           int32_t nrun, int32_t j, int32_t s, rast_fill_rule rule,
                           const rast__cov_out *o, uint64_t *acc, uint64_t *bits, uint32_t *z,
                           uint64_t *own, uint32_t stamp)
{
    const uint64_t tag = (uint64_t)stamp << 32;
    const int32_t w = o->clip.x1 - o->clip.x0;
    rast__acc a;
    int64_t Yj;
    int32_t k, c;
    if (!rast__acc_area_fits(o, nrow)) return 0;
    rast__acc_init(&a, acc, bits, z, o, s, nrow);
    Yj = (int64_t)j * a.p;
    for (k = 0; k < nrow; k++) { /* the parts, and the test */
        rast__cedge *ed = &e[row[k]];
        int64_t lo, hi;
        RAST__ACC_FATN(rast__acc_ends)(ed, j, (int64_t)ed->yt - Yj, &a, &ed->qa, &ed->qta, &ed->qb, &ed->qtb, 0);
        lo = rast__acc_col(ed->qa < ed->qb ? ed->qa : ed->qb) - a.x0;
        hi = rast__acc_col(ed->qa < ed->qb ? ed->qb : ed->qa) - a.x0;
        if (lo < 0) lo = 0;
        if (hi >= w) hi = w - 1;
        for (c = (int32_t)lo; c <= hi; c++)
            if (!rast__acc_meet(own, c, tag, (uint32_t)k, e, row, Yj, a.p, a.x0)) return 0;
    }
    for (k = 0; k < nrun; k++) { /* the runs' columns */
        const rast__cedge *ed = &e[runs[k]];
        int64_t lo = rast__floordiv(ed->hx0, a.p) - a.x0, hi = rast__floordiv(ed->hx1, a.p) - a.x0;
        if (lo < 0) lo = 0;
        if (hi >= w) hi = w - 1;
        for (c = (int32_t)lo; c <= hi; c++)
            if (!rast__acc_meet(own, c, tag, RAST__OWN_RUN, e, row, Yj, a.p, a.x0)) return 0;
    }
    return rast__acc_area_add(&a, e, row, nrow, nrow, j, rule, o);
}

#if !defined(__OPTIMIZE_SIZE__) /* (its one caller: not in size-optimised builds) */
int rast__cov_acc_area_parts(rast__cedge *e, const int32_t *row, int32_t nrow, int32_t most, int32_t j, int32_t s,
                             rast_fill_rule rule, const rast__cov_out *o, uint64_t *acc, uint64_t *bits,
                             uint32_t *z)
{
    rast__acc a;
    if (!rast__acc_area_fits(o, most)) return 0;
    rast__acc_init(&a, acc, bits, z, o, s, nrow);
    return rast__acc_area_add(&a, e, row, nrow, most, j, rule, o);
}
#endif

int rast__cov_acc_may(const rast__cov_out *o, int32_t s)
{
    return (o->format == RAST_COVERAGE_U8 || o->format == RAST_COVERAGE_U16) && s >= 0 && s <= 16;
}

/* What both walks share (rast__cov_acc sets it up): the edges e[0..n),
 * their order by top row, the rows' edges row[0..nrow), tmp[] (room for
 * n), each edge's first row key[] + ja, last row last[] and last row run
 * through (rast__acc_thru) thru[]; the exact rows' cells. */
typedef struct rast__acc_walk {
    rast__aedge *e;
    uint32_t n, m;
    int32_t s, ja, jb, width, nw;
    rast_fill_rule rule;
    const rast__cov_out *o;
    int32_t *order, *row, *tmp, *key, *last, *thru;
    rast__i128 *cover, *area;
    uint64_t *bits;
    unsigned char *exact; /* each edge's: its exact steps set (cleared at the first exact row) */
#if RAST__ACC_COMPACT
    /* the edges' room (n rast__cedge), whose first cap records' room is
     * free (e[] lies past it): for an exact row's (rast__acc_exact) */
    rast__cedge *fat;
    uint32_t cap;
#endif
} rast__acc_walk;

#if RAST__ACC_COMPACT
/* The edge record f of the walk's record c (for the exact rows: its
 * exact steps not set; no runs, "area"'s). */
static void rast__acc_unpack(rast__cedge *f, const rast__aedge *c)
{
    f->xt = c->xt;
    f->yt = c->yt;
    f->dx = c->dx;
    f->dy = c->dy;
    f->dir = c->dir;
    f->hz = 0;
    f->hx0 = f->hx1 = 0;
    f->qx = c->qx;
    f->qxs = c->qxs;
    f->qxr = c->qxr;
    f->qxsr = c->qxsr;
    f->qrow = c->qrow;
    f->qt = c->qt;
    f->qts = c->qts;
    f->qtr = c->qtr;
    f->qtsr = c->qtsr;
    f->qX = c->qX == INT32_MIN ? INT64_MIN : c->qX;
}

/* Row j the exact way (rast__cov_acc_exact_row), its edges the walk's
 * records ix[0..n): their rast__cedge records rebuilt in the free room
 * (w->fat[0..n), indices 0..n-1 in w->exact's room), their exact steps
 * set.  A row of more edges than the room takes (more than three in four
 * of the call's) has every record rebuilt in place (w->fat[i] from
 * w->e[i], in order: a record i's room meets only walk records <= i),
 * then the walk's records again from them, from the last (a walk record
 * i's room meets only edge records >= i): the steppers as they were. */
static void rast__acc_exact(const rast__acc_walk *w, const int32_t *ix, int32_t n, int32_t j)
{
    rast__cedge *const f = w->fat;
    rast__aedge c;
    uint32_t i;
    int32_t k;
    if ((uint32_t)n <= w->cap) {
        int32_t *const idx = (int32_t *)(void *)w->exact;
        for (k = 0; k < n; k++) {
            rast__acc_unpack(&f[k], &w->e[ix[k]]);
            idx[k] = k;
        }
        rast__cov_exact_steps(f, (uint32_t)n);
        rast__cov_acc_exact_row(f, idx, n, j, w->s, w->rule, w->o, w->cover, w->area, w->bits, rast__i128_u64(0));
        return;
    }
    for (i = 0; i < w->n; i++) { /* (memcpy: the rooms overlap, whatever the types) */
        memcpy(&c, &w->e[i], sizeof c);
        rast__acc_unpack(&f[i], &c);
    }
    memset(w->exact, 0, w->n);
    rast__cov_exact_steps_of(f, ix, n, w->exact);
    rast__cov_acc_exact_row(f, ix, n, j, w->s, w->rule, w->o, w->cover, w->area, w->bits, rast__i128_u64(0));
    for (i = w->n; i-- > 0;) {
        rast__acc_load(&c, &f[i]);
        memcpy(&w->e[i], &c, sizeof c);
    }
}
#else
static void rast__acc_exact(const rast__acc_walk *w, const int32_t *ix, int32_t n, int32_t j)
{
    rast__cov_exact_steps_of(w->e, ix, n, w->exact);
    rast__cov_acc_exact_row(w->e, ix, n, j, w->s, w->rule, w->o, w->cover, w->area, w->bits, rast__i128_u64(0));
}
#endif

#if defined(__OPTIMIZE_SIZE__) /* (speed builds: rast__acc_band_edges) */
/* The edges of rows j0 .. j1 - 1 in row[]: of its nrow (returns the new
 * count), those that end above j0 dropped (when one does: *drop, the least
 * last row among them, is above j0), those that start above row j1 taken
 * from order[*next] on. */
static int32_t rast__acc_edges_of(const rast__acc_walk *w, int32_t nrow, uint32_t *next, int32_t *drop,
                                  int32_t j0, int32_t j1)
{
    int32_t *const row = w->row, *const last = w->last, *const order = w->order, k, q;
    if (j0 > *drop) {
        *drop = INT32_MAX;
        for (k = 0, q = 0; k < nrow; k++)
            if (last[row[k]] >= j0) {
                row[q++] = row[k];
                if (last[row[k]] < *drop) *drop = last[row[k]];
            }
        nrow = q;
    }
    /* (an edge's first row: key[] + ja, not its record's yt, read later) */
    while (*next < w->n && w->key[order[*next]] + w->ja < j1) {
        if (last[order[*next]] >= j0) {
            row[nrow++] = order[*next];
            if (last[order[*next]] < *drop) *drop = last[order[*next]];
        }
        ++*next;
    }
    return nrow;
}
#endif

#if !defined(__OPTIMIZE_SIZE__)
/* rast__acc_edges_of for the band of rows j0 .. j1 - 1 (j1 - j0 <=
 * RAST__ACC_BAND), its rows' parts counted in the same pass: cnt[r]
 * (cleared here) + cnt[0 .. r - 1] is row j0 + r's (an edge from its
 * first row in the band on, less from the row after its last).  An edge
 * kept from the bands above starts above j0.  (Two passes over the band's
 * edges, each reading last[], were a fifth of the band walk's own
 * instructions on 10,000 small triangles.) */
static int32_t rast__acc_band_edges(const rast__acc_walk *w, int32_t nrow, uint32_t *next, int32_t *drop, int32_t j0,
                                    int32_t j1, int32_t *cnt)
{
    int32_t *const row = w->row, *const last = w->last, *const order = w->order, *const key = w->key;
    int32_t k, q, r, l, low = *drop;
    for (r = 0; r <= j1 - j0; r++) cnt[r] = 0;
    if (j0 > low) {
        low = INT32_MAX;
        for (k = 0, q = 0; k < nrow; k++) {
            l = last[row[k]];
            if (l >= j0) {
                row[q++] = row[k];
                low = l < low ? l : low;
                if (l < j1 - 1) cnt[l - j0 + 1]--;
            }
        }
        nrow = q;
    } else {
        for (k = 0; k < nrow; k++) {
            l = last[row[k]];
            if (l < j1 - 1) cnt[l - j0 + 1]--;
        }
    }
    cnt[0] += nrow;
    for (; *next < w->n && key[order[*next]] + w->ja < j1; ++*next) {
        const int32_t ek = order[*next], f = key[ek] + w->ja;
        l = last[ek];
        if (l >= j0) {
            row[nrow++] = ek;
            low = l < low ? l : low;
            cnt[f > j0 ? f - j0 : 0]++;
            if (l < j1 - 1) cnt[l - j0 + 1]--;
        }
    }
    *drop = low;
    return nrow;
}
#endif

#if defined(__OPTIMIZE_SIZE__)
/* Row ja to jb one at a time, each edge's part deposited as it comes, into
 * the cells of a (the short edges' walk). */
static void rast__acc_by_rows(const rast__acc_walk *w, rast__acc *a)
{
    rast__aedge *const e = w->e;
    const rast__cov_out *const o = w->o;
    const uint32_t m = w->m;
    int32_t *const row = w->row;
    int32_t nrow = 0, j, k, drop = INT32_MAX;
    uint32_t next = 0, *const cnt = a->z + w->width; /* (in area[], after z[]: cleared) */
    int exact = 0; /* w->exact[] cleared */
    for (j = w->ja; j < w->jb; j++) {
        const int64_t Yj = (int64_t)j * a->p;
        nrow = rast__acc_edges_of(w, nrow, &next, &drop, j, j + 1);
        if (nrow < RAST__ACC_MAXN && ((uint64_t)nrow + 1) * m < ((uint64_t)1 << 25)) {
            /* Bits for the cells touched, so that the scan skips the
             * others, unless the row's parts are many for its width
             * (a part or more for every RAST__ACC_DENSE columns): then every
             * cell from the first touched to the last is read. */
            a->dense = (int64_t)nrow * RAST__ACC_DENSE >= w->width;
            a->cnt = nrow >= RAST__ACC_FEW ? cnt : NULL;
            if (a->cnt) /* (two loops: the count costs nothing where not asked) */
                for (k = 0; k < nrow; k++) rast__acc_row_part_in(a, &e[row[k]], j, (int64_t)e[row[k]].yt - Yj, 1, 1);
            else
                for (k = 0; k < nrow; k++) rast__acc_row_part_in(a, &e[row[k]], j, (int64_t)e[row[k]].yt - Yj, 1, 0);
            if (rast__acc_emit(a, 1, o, j, w->rule, m, rast__acc_win((uint64_t)nrow, m), e, NULL, row, nrow, NULL)) continue;
        }
        if (!exact) { /* the first exact row (rare) */
            memset(w->exact, 0, w->n);
            exact = 1;
        }
        rast__acc_exact(w, row, nrow, j);
    }
}
#else
/* e's part in row j (rel0 = e's top - the row's; from (xa, ta) to (xb,
 * tb), rast__acc_ends') into the cells a (sx 1), the row's bounds in *lo,
 * *hi (locals of the caller: registers), the cells' fields given (a's,
 * read once by the caller: a store to a cell may alias them).  A part in
 * one column of the clip (four in five of a line of text's) is put here,
 * lo and hi not moved when count (rast__acc_spread), its two cells marked
 * and counted as rast__acc_touch would (the column and the next, the last
 * of the clip at most); one crossing one vertical inside the clip too;
 * any other goes to rast__acc_part.  count as rast__acc_part's, dense
 * a->dense (constants at each call: no test of either a part). */
RAST__HOT void rast__acc_deposit(rast__acc *a, uint64_t *acc, uint64_t *blk, uint32_t *cnt, int32_t last, int64_t x0,
                                 uint64_t w, rast__aedge *ed, int64_t rel0, int64_t xa, uint64_t ta, int64_t xb,
                                 uint64_t tb, int32_t *lo, int32_t *hi, int count, int dense)
{
    const uint64_t fm = QT - 1;
    const int32_t hq = a->hq;
    const int64_t ca = rast__acc_col(xa) - x0, cb = rast__acc_col(xb) - x0;
    if (ca == cb && (uint64_t)ca < w) {
        const int32_t c0 = (int32_t)ca, c1 = c0 < last ? c0 + 1 : c0;
        rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)xb & fm, tb - ta, ed->dir < 0 ? ~(uint64_t)0 : 0, 1);
        if (!count) { /* (counted: the counts have them, rast__acc_emit) */
            *lo = c0 < *lo ? c0 : *lo;
            *hi = c0 + 1 > *hi ? c0 + 1 : *hi;
        }
        if (!dense) {
            blk[c0 >> 6] |= (uint64_t)1 << (c0 & 63);
            blk[c1 >> 6] |= (uint64_t)1 << (c1 & 63);
        }
        if (count) cnt[c0 >> 4]++;
    } else if ((cb - ca == 1 || ca - cb == 1) && (uint64_t)ca < w && (uint64_t)cb < w) {
        /* one vertical crossed, inside the clip (most of the rest):
         * rast__acc_part's two pieces, the column stepper there */
        const int right = cb > ca;
        const int32_t c0 = (int32_t)(right ? ca : cb), c1 = c0 + 1, c2 = c1 < last ? c1 + 1 : c1;
        const uint64_t neg = ed->dir < 0 ? ~(uint64_t)0 : 0;
        const uint32_t adx = (uint32_t)(ed->dx < 0 ? -ed->dx : ed->dx);
        uint32_t qtr;
        int64_t qt;
        uint64_t tx;
        /* (the first vertical an edge crosses: its stepper there, not
         * the step, nor stepped on: rast__acc_t_at) */
        const int first = ed->qX == INT32_MIN;
        if (first)
            rast__acc_t_at(ed, c1 + x0, a);
        else if (ed->qX != c1 + x0)
            rast__acc_t_first(ed, c1 + x0, a);
        qt = ed->qt + rel0 * ((int64_t)1 << hq);
        tx = qt < (int64_t)ta ? ta : qt > (int64_t)tb ? tb : (uint64_t)qt;
        rast__acc_put(acc, ca, (uint64_t)xa & fm, right ? QT : 0, tx - ta, neg, 1);
        rast__acc_put(acc, cb, right ? 0 : QT, (uint64_t)xb & fm, tb - tx, neg, 1);
        if (!first) {
            qtr = ed->qtr + ed->qtsr;
            ed->qt += ed->qts + rast__acc_carry(&qtr, adx);
            ed->qtr = qtr;
            ed->qX += right ? 1 : -1;
        }
        if (!count) {
            *lo = c0 < *lo ? c0 : *lo;
            *hi = c1 + 1 > *hi ? c1 + 1 : *hi;
        }
        if (!dense) {
            blk[c0 >> 6] |= (uint64_t)1 << (c0 & 63);
            blk[c1 >> 6] |= (uint64_t)1 << (c1 & 63);
            blk[c2 >> 6] |= (uint64_t)1 << (c2 & 63);
        }
        if (count) {
            cnt[c0 >> 4]++;
            cnt[c1 >> 4] += (uint32_t)((c1 >> 4) != (c0 >> 4));
        }
    } else {
        a->lo = *lo;
        a->hi = *hi;
        rast__acc_part(a, ed, -rel0 * ((int64_t)1 << hq), xa, ta, xb, tb, ed->dir, 1, count);
        *lo = a->lo;
        *hi = a->hi;
    }
}

/* Row j's parts of the edges ix[0..n) into the cells of a (sx 1)
 * (rast__acc_deposit), and the edges that go on below row j copied to
 * nx[], in order (returns how many).  count as rast__acc_part's, dense
 * a->dense (constants at each call).  (From 79 instructions a part to ~50
 * on the text family: the struct's fields reloaded after each store,
 * which may alias them, the clip tests of the general way, the calls.) */
RAST__HOT int32_t rast__acc_parts(rast__acc *a, rast__aedge *e, const int32_t *ix, int32_t n, int32_t *nx,
                                  int32_t j, int count, int dense)
{
    const int32_t p = a->p, last = a->last;
    const int64_t Yj = (int64_t)j * p, x0 = a->x0;
    const uint64_t w = (uint64_t)(a->x1 - a->x0);
    uint64_t *const acc = a->acc, *const blk = a->blk;
    uint32_t *const cnt = a->cnt;
    int32_t lo = a->lo, hi = a->hi, k, q = 0;
    for (k = 0; k < n; k++) {
        rast__aedge *const ed = &e[ix[k]];
        const int64_t rel0 = (int64_t)ed->yt - Yj;
        int64_t xa, xb;
        uint64_t ta, tb;
        nx[q] = ix[k];
        q += rel0 + ed->dy > p; /* (it ends below row j) */
        rast__acc_ends(ed, j, rel0, a, &xa, &ta, &xb, &tb, 1);
        rast__acc_deposit(a, acc, blk, cnt, last, x0, w, ed, rel0, xa, ta, xb, tb, &lo, &hi, count, dense);
    }
    a->lo = lo;
    a->hi = hi;
    return q;
}

/* Row j's parts of the edges ix[0..n) whose first and last row is j
 * (rast__acc_by_rows' one[]), as rast__acc_parts puts them: none goes on
 * below the row, so no list of those that do; and an edge whose ends lie
 * strictly inside the row (rel0 > 0, rel1 < P) has them from its vertices,
 * as rast__acc_ends makes them there, without its tests.  count, dense as
 * rast__acc_parts' (constants at each call). */
RAST__HOT void rast__acc_ones(rast__acc *a, rast__aedge *e, const int32_t *ix, int32_t n, int32_t j, int count,
                              int dense)
{
    const int32_t p = a->p, last = a->last, hq = a->hq;
    const int64_t Yj = (int64_t)j * p, x0 = a->x0;
    const uint64_t w = (uint64_t)(a->x1 - a->x0);
    uint64_t *const acc = a->acc, *const blk = a->blk;
    uint32_t *const cnt = a->cnt;
    int32_t lo = a->lo, hi = a->hi, k;
    for (k = 0; k < n; k++) {
        rast__aedge *const ed = &e[ix[k]];
        const int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = rel0 + ed->dy;
        int64_t xa, xb;
        uint64_t ta, tb;
        if (rel0 > 0 && rel1 < p) {
            ta = (uint64_t)rel0 << hq;
            tb = (uint64_t)rel1 << hq;
            xa = (int64_t)ed->xt * ((int64_t)1 << hq);
            xb = ((int64_t)ed->xt + ed->dx) * ((int64_t)1 << hq);
        } else {
            rast__acc_ends(ed, j, rel0, a, &xa, &ta, &xb, &tb, 1);
        }
        rast__acc_deposit(a, acc, blk, cnt, last, x0, w, ed, rel0, xa, ta, xb, tb, &lo, &hi, count, dense);
    }
    a->lo = lo;
    a->hi = hi;
}

/* Columns [c0, c1] of the clip (clamped to it) in the bits b. */
static void rast__acc_cols_mark(uint64_t *b, int64_t c0, int64_t c1, int32_t last)
{
    c0 = c0 < 0 ? 0 : c0;
    c1 = c1 > last ? last : c1;
    for (; c0 <= c1; c0++) b[c0 >> 6] |= (uint64_t)1 << (c0 & 63);
}

/* Row j again, when a level of its quick sums was near a tie (most often
 * a pixel at an exact tie: half covered by a bar on a half pixel, which no
 * window can decide): its parts ix[0..n) put again into the cleared cells
 * of a (sx 1), as rast__acc_parts puts them, and each pixel's level
 * decided with the window of the row's parts (per 16 columns where they
 * are many) unless no part that may move it (rast__acc_count's) has a
 * rounded value: then its sum is exact, and so is its level, ties too.
 * A part's values are exact where its ends' abscissae are (a vertex, or
 * a row's top or bottom where the row stepper's remainder is 0), it
 * crosses no vertical, and the floor of ar drops nothing (its low 10 bits
 * 0); the columns of any other part are marked in a->blk (w->bits,
 * cleared, and left so).  Returns rast__acc_done's: 1 when written and
 * handed on, else 0 (the exact sweep's).  The steppers are left as the
 * first pass left them (the row's bottom). */
static int rast__acc_ties(rast__acc *a, const rast__acc_walk *w, rast__aedge *e, const int32_t *ix, int32_t n,
                          int32_t j)
{
    const int32_t p = a->p, hq = a->hq, last = a->last, wd = w->width;
    const int64_t Yj = (int64_t)j * p, x0 = a->x0;
    const uint64_t fm = QT - 1;
    const uint32_t m = w->m;
    const rast_coverage_format f = m == 255 ? RAST_COVERAGE_U8 : RAST_COVERAGE_U16;
    uint64_t *const acc = a->acc, *const ib = a->blk, win, bad = 0, lev = 0, v = 0;
    uint32_t *const cnt = n >= RAST__ACC_FEW ? a->z + wd : NULL, most = 0;
    unsigned char *const row = rast__cov_row(w->o, j);
    int32_t k, lo, hi;
    a->dense = 1; /* (rast__acc_part marks no bit: ib[] is this pass's) */
    a->cnt = cnt;
    for (k = 0; k < n; k++) {
        rast__aedge *const ed = &e[ix[k]];
        const int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = rel0 + ed->dy;
        int64_t xa, xb, ca, cb;
        uint64_t ta, tb;
        int exact = 1;
        if (rel0 > 0) {
            ta = (uint64_t)rel0 << hq;
            xa = (int64_t)ed->xt * ((int64_t)1 << hq);
        } else {
            ta = 0;
            xa = rast__acc_top(ed, j, a);
            exact = ed->qxr == 0;
        }
        xb = rast__acc_bottom(ed, j, rel1, p, hq, a, &tb, &exact);
        ca = rast__acc_col(xa) - x0;
        cb = rast__acc_col(xb) - x0;
        if (ca == cb && ca >= 0 && ca < wd) {
            const uint64_t fs = ((uint64_t)xa & fm) + ((uint64_t)xb & fm);
            rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)xb & fm, tb - ta, ed->dir < 0 ? ~(uint64_t)0 : 0, 1);
            a->lo = ca < a->lo ? (int32_t)ca : a->lo;
            a->hi = ca + 1 > a->hi ? (int32_t)ca + 1 : a->hi;
            if (cnt) cnt[ca >> 4]++;
            if (!exact || ((fs * (tb - ta)) & 1023)) ib[ca >> 6] |= (uint64_t)1 << (ca & 63);
        } else {
            rast__acc_part(a, ed, -rel0 * ((int64_t)1 << hq), xa, ta, xb, tb, ed->dir, 1, cnt != NULL);
            rast__acc_cols_mark(ib, ca < cb ? ca : cb, ca < cb ? cb : ca, last);
        }
    }
    lo = a->lo;
    hi = a->hi < wd ? a->hi + 1 : wd;
    if (lo >= hi) lo = hi = 0;
    if (cnt) {
        for (k = 0; k <= last >> 4; k++) {
            most = cnt[k] > most ? cnt[k] : most;
            cnt[k] = 0;
        }
        win = rast__acc_win(most, m);
    } else {
        win = rast__acc_win((uint64_t)n, m);
    }
    rast__cov_fill(f, row, 0, lo, 0);
    for (k = lo; k < hi; k++) {
        v += acc[k];
        acc[k] = 0;
        lev = rast__acc_level((int64_t)v, w->rule, m, (ib[k >> 6] >> (k & 63)) & 1 ? win : 0, &bad);
        rast__cov_store(f, row, k, lev);
    }
    rast__cov_fill(f, row, hi, wd, lev);
    acc[wd] = 0;
    for (k = 0; k <= last >> 6; k++) ib[k] = 0;
    a->lo = INT32_MAX;
    a->hi = -1;
    a->cnt = NULL;
    if (bad) return 0;
    rast__cov_row_done(w->o, j);
    return 1;
}

/* e's abscissa at the top of row j, which it starts above, as
 * rast__acc_parts leaves its row stepper (at row j, or at row j + 1 if e
 * goes on below): there one step back (the remainder's borrow), no
 * division; *rem its remainder (0: exact). */
static inline int64_t rast__acc_top_back(rast__aedge *e, int32_t j, const rast__acc *a, uint32_t *rem)
{
    int64_t x;
    if (e->qrow == j + 1) {
        uint32_t borrow;
        rast__acc_qxs(e);
        borrow = e->qxr < e->qxsr;
        x = e->qx - e->qxs - (int64_t)borrow;
        *rem = e->qxr - e->qxsr + ((uint32_t)e->dy & (0u - borrow));
        return x;
    }
    x = rast__acc_top(e, j, a);
    *rem = e->qxr;
    return x;
}

/* Do any of the blocks of 16 columns b0 .. b1 hold a pixel not certain
 * (flag[b] not 0)? */
static inline int rast__acc_flagged(const uint32_t *flag, int32_t b0, int32_t b1)
{
    if (b1 - b0 <= 1) return (flag[b0] | flag[b1]) != 0; /* (most parts: one block or two) */
    for (; b0 <= b1; b0++)
        if (flag[b0]) return 1;
    return 0;
}

/* rast__acc_ties_z's part from (xa, ta) to (xb, tb) (Q units), in a
 * flagged block: counted in a->cnt for each 16 of its columns c0 .. c1
 * (those of the clip), which are marked in a->blk when not exact (ex: its
 * ends are; a part of one column, its ar's floor drops nothing), as
 * rast__acc_ties has them.  Its cells are the first pass's, kept.
 * (Out of line: the loop keeps its registers for the other parts.) */
RAST__APART void rast__acc_tie_part(rast__acc *a, int64_t xa, uint64_t ta, int64_t xb, uint64_t tb, int64_t c0,
                                    int64_t c1, int ex)
{
    const uint64_t fm = QT - 1;
    int64_t b;
    for (b = c0 >> 4; b <= c1 >> 4; b++) a->cnt[b]++; /* (rast__acc_count's) */
    if (rast__acc_col(xa) == rast__acc_col(xb)) { /* (then c0 = c1 is its column, inside the clip) */
        const uint64_t fs = ((uint64_t)xa & fm) + ((uint64_t)xb & fm);
        if (!ex || ((fs * (tb - ta)) & 1023)) a->blk[c0 >> 6] |= (uint64_t)1 << (c0 & 63);
    } else {
        rast__acc_cols_mark(a->blk, c0, c1, a->last);
    }
}

/* rast__acc_ties for a uint8 row read by its sums z (rast__acc_zpath),
 * which rast__acc_emit kept (kept, its keep): only the
 * pixels of the blocks of 16 columns where a level was not certain are
 * decided again.  Their blocks come from z (the same test); z is cleared
 * on the way and the blocks' flags put in z[b] (b <= the column read).
 * The cells are the first pass's, kept (rast__acc_sum24's keep): their
 * running sums, from the row's first cell, give the flagged blocks'
 * pixels again (and the fill right of the last, if its block is flagged),
 * the others left as the first pass wrote them; so no part is put again.
 * Only the windows need the parts: each that touches a flagged block is
 * counted there, its columns marked when not exact (rast__acc_tie_part).
 * A part lies in its edge's columns, so an edge whose columns lie left
 * of the first flagged block or right of the last is passed by its two
 * ends, without its part's (a glyph's edges span a few columns; a row's
 * flagged blocks are one or two of its 32); the others' ends from where the first pass left the
 * steppers (no division, rast__acc_top_back).  (A paragraph of text: 27
 * rows of 120 with a pixel at an exact tie, a stem's side on a half
 * pixel; every part of them put again, ends and cells, cost 16% of its
 * instructions, ~55,000 a row.) */
static int rast__acc_ties_z(rast__acc *a, const rast__acc_walk *w, rast__aedge *e, const int32_t *ix, int32_t n,
                            int32_t j, rast__acc_kept *kept)
{
    const int32_t p = a->p, hq = a->hq, last = a->last, wd = w->width, lo = kept->lo, hi = kept->hi;
    const int64_t Yj = (int64_t)j * p, x0 = a->x0;
    const uint32_t w24 = (uint32_t)(kept->win >> 27) + 256, lim = ((uint32_t)1 << 24) - 2 * w24;
    uint32_t *const flag = a->z;
    uint64_t *const acc = a->acc, *const ib = a->blk, bad = 0, lev = 0, v = 0;
    unsigned char *const row = rast__cov_row(w->o, j);
    int32_t k, kk, b0 = INT32_MAX, b1 = -1;
    int64_t xlo, xhi;
    unsigned char out;
    for (k = lo; k < hi; k++) { /* (flag[k >> 4], k >> 4 <= k: read already) */
        uint32_t zk = flag[k];
        const uint32_t t = rast__acc_level24(&zk, &out, w24, lim, w->rule);
        flag[k] = 0;
        flag[k >> 4] |= t;
        if (t) { /* (the first and last flagged blocks) */
            b0 = b0 < (k >> 4) ? b0 : k >> 4;
            b1 = k >> 4;
        }
    }
    /* their columns' span, in the vertices' units: [xlo, xhi) (none
     * flagged: block 0's, whose parts find no flag) */
    if (b1 < 0) b0 = b1 = 0;
    xlo = (x0 + 16 * (int64_t)b0) * p;
    xhi = (x0 + 16 * (int64_t)b1 + 16) * p;
    kept->hi = -1;
    a->cnt = a->z + wd; /* (rast__acc_tie_part counts: cleared, as the first pass left them) */
    for (kk = 0; kk < n; kk++) {
        rast__aedge *const ed = &e[ix[kk]];
        const int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = rel0 + ed->dy;
        int64_t xa, xb, c0, c1;
        uint64_t ta, tb;
        uint32_t rem = 0;
        int exact = 1;
        /* the edge's columns, and so its part's: past the flagged span? */
        if ((int64_t)ed->xt + (ed->dx < 0 ? 0 : ed->dx) < xlo || (int64_t)ed->xt + (ed->dx < 0 ? ed->dx : 0) >= xhi)
            continue;
        if (rel0 > 0) {
            ta = (uint64_t)rel0 << hq;
            xa = (int64_t)ed->xt * ((int64_t)1 << hq);
        } else {
            ta = 0;
            xa = rast__acc_top_back(ed, j, a, &rem);
            exact = rem == 0;
        }
        xb = rast__acc_bottom(ed, j, rel1, p, hq, a, &tb, &exact);
        c0 = rast__acc_col(xa < xb ? xa : xb) - x0;
        c1 = rast__acc_col(xa < xb ? xb : xa) - x0;
        if (c0 >= wd) continue; /* (right of the clip: nothing) */
        c0 = c0 < 0 ? 0 : c0;
        c1 = c1 > last ? last : c1;
        if (c1 >= 0 && rast__acc_flagged(flag, (int32_t)c0 >> 4, (int32_t)c1 >> 4))
            rast__acc_tie_part(a, xa, ta, xb, tb, c0, c1, exact);
    }
    for (k = lo; k < hi; k++) {
        v += acc[k];
        acc[k] = 0;
        if (flag[k >> 4]) {
            uint64_t bk = 0;
            lev = rast__acc_level((int64_t)v, w->rule, 255,
                                  (ib[k >> 6] >> (k & 63)) & 1 ? rast__acc_win(a->cnt[k >> 4], 255) : 0, &bk);
            row[k] = (unsigned char)lev;
            if (bk) { /* (the span of the pixels not decided: kept's) */
                kept->lo = bad ? kept->lo : k;
                kept->hi = k + 1;
                bad = 1;
            }
        }
    }
    if (flag[(hi - 1) >> 4]) {
        rast__cov_fill(RAST_COVERAGE_U8, row, hi, wd, lev);
        if (kept->hi == hi) kept->hi = wd; /* (the fill's level not decided either) */
    }
    acc[wd] = 0;
    for (k = 0; k <= (hi - 1) >> 4; k++) flag[k] = 0;
    for (k = 0; k <= last >> 4; k++) a->cnt[k] = 0;
    a->cnt = NULL;
    for (k = 0; k <= last >> 6; k++) ib[k] = 0;
    a->lo = INT32_MAX;
    a->hi = -1;
    if (bad) return 0; /* (kept: the columns [lo, hi) to decide the exact way) */
    rast__cov_row_done(w->o, j);
    return 1;
}

/* Row j the exact way, as rast__acc_exact, but only its columns [c0, c1)
 * of the clip (the span of the pixels rast__acc_ties_z left undecided; the
 * others' levels, which it and the first pass decided, are those the exact
 * way gives, so they stay): only the edges ix[0..n) whose columns meet
 * [c0, c1) go, those wholly left of it as the cover they carry (each
 * piece left of the clip adds its height to the cells' carry, exactly:
 * the sum of its pieces' heights, dir (t1 - t0)), those wholly right
 * not at all (docs/coverage.md: the row is added again the 128-bit
 * way).  (A paragraph of text: 2 rows of ~700 parts sent to the exact
 * sweep for a pixel or two, 1.2 M instructions each.)  With more such
 * edges than the free room holds, the whole row, rast__acc_exact. */
static void rast__acc_exact_cols(const rast__acc_walk *w, const int32_t *ix, int32_t n, int32_t j, int32_t c0,
                                 int32_t c1)
{
    const rast__cov_out *const o = w->o;
    const int32_t s = w->s, p = (int32_t)1 << s, h = RAST__COV_G - s;
    const int64_t X0 = (int64_t)o->clip.x0 + c0, X1 = (int64_t)o->clip.x0 + c1, Yj = (int64_t)j * p;
    const uint64_t T = (uint64_t)1 << RAST__COV_G;
    rast__cedge *const f = w->fat;
    int32_t *const idx = (int32_t *)(void *)w->exact;
    rast__i128 carry = rast__i128_u64(0);
    rast__cov_out on = *o;
    int32_t k, q = 0;
    for (k = 0; k < n; k++) {
        const rast__aedge *const ed = &w->e[ix[k]];
        const int64_t xl = (int64_t)ed->xt + (ed->dx < 0 ? ed->dx : 0), xr = (int64_t)ed->xt + (ed->dx < 0 ? 0 : ed->dx);
        if (rast__floordiv(xl, p) >= X1) continue; /* (right of the columns: nothing) */
        if (rast__floordiv(xr, p) < X0) { /* left of them: its cover */
            const int64_t rel0 = (int64_t)ed->yt - Yj, rel1 = rel0 + ed->dy;
            const uint64_t t0 = rel0 <= 0 ? 0 : (uint64_t)rel0 << h, t1 = rel1 >= p ? T : (uint64_t)rel1 << h;
            carry = rast__i128_add(carry, rast__i128_from(ed->dir < 0 ? -(int64_t)(t1 - t0) : (int64_t)(t1 - t0)));
            continue;
        }
        if ((uint32_t)q >= w->cap) {
            rast__acc_exact(w, ix, n, j);
            return;
        }
        rast__acc_unpack(&f[q], ed);
        idx[q] = q;
        q++;
    }
    rast__cov_exact_steps(f, (uint32_t)q);
    on.clip.x0 = (int32_t)X0;
    on.clip.x1 = (int32_t)X1;
    on.base = o->base + (ptrdiff_t)c0 * (o->format == RAST_COVERAGE_U16 ? 2 : 1);
    on.paint = NULL; /* (the whole row handed on below) */
    rast__cov_acc_exact_row(f, idx, q, j, s, w->rule, &on, w->cover, w->area, w->bits, carry);
    rast__cov_row_done(o, j);
}

/* Row ja to jb one at a time, each edge's part deposited as it comes, into
 * the cells of a (the short edges' walk).  The row's edges are in cur[]
 * (w->row); those that go on below it are copied to nxt[] (w->tmp) as the
 * parts are put, and the two swap: no pass over the list to drop the
 * edges that end (rast__acc_edges_of's, a tenth of the text family's
 * instructions with it); the edges that start in the row come from
 * order[] by key[].  (Inline in its one caller: GCC 12 left it out of
 * line once the rows kept their cells, 0.1 M more instructions on text
 * and the stroke.) */
RAST__HOT void rast__acc_by_rows(const rast__acc_walk *w, rast__acc *a)
{
    rast__aedge *const e = w->e;
    const rast__cov_out *const o = w->o;
    const uint32_t m = w->m;
    const int32_t *const key = w->key, *const last = w->last, ja = w->ja;
    int32_t *cur = w->row, *nxt = w->tmp, *t, *const one = w->thru; /* (thru[]: the bands' walk's) */
    int32_t nrow = 0, none, j, k, q;
    uint32_t next = 0, *const cnt = a->z + w->width; /* (in area[], after z[]: cleared) */
    const uint32_t ne = w->n; /* (locals: the stores to cur[] may alias w's fields) */
    int exact = 0, done, zcols = 0; /* w->exact[] cleared */
    rast__acc_kept kept; /* (a tie's row of many parts: rast__acc_ties_z) */
    for (j = w->ja; j < w->jb; j++) {
        /* (the records are in the rows' order, rast__acc_sorted: edge
         * next is the next to start) */
        /* (those that end in the row too, one[], apart: rast__acc_ones) */
        for (none = 0; next < ne && key[next] + ja <= j; next++)
            if (last[next] == j)
                one[none++] = (int32_t)next;
            else if (last[next] > j)
                cur[nrow++] = (int32_t)next;
        done = 0;
        if (nrow + none < RAST__ACC_MAXN && ((uint64_t)nrow + none + 1) * m < ((uint64_t)1 << 25)) {
            /* Bits for the cells touched, so that the scan skips the
             * others, unless the row's parts are many for its width
             * (a part or more for every RAST__ACC_DENSE columns): then every
             * cell from the first touched to the last is read. */
            a->dense = (int64_t)(nrow + none) * RAST__ACC_DENSE >= w->width;
            a->cnt = nrow + none >= RAST__ACC_FEW ? cnt : NULL;
            /* (two calls: the count costs nothing where not asked) */
            /* (and two for dense rows: no test a part) */
            if (a->cnt) {
                if (a->dense) {
                    q = rast__acc_parts(a, e, cur, nrow, nxt, j, 1, 1);
                    rast__acc_ones(a, e, one, none, j, 1, 1);
                } else {
                    q = rast__acc_parts(a, e, cur, nrow, nxt, j, 1, 0);
                    rast__acc_ones(a, e, one, none, j, 1, 0);
                }
            } else if (a->dense) {
                q = rast__acc_parts(a, e, cur, nrow, nxt, j, 0, 1);
                rast__acc_ones(a, e, one, none, j, 0, 1);
            } else {
                q = rast__acc_parts(a, e, cur, nrow, nxt, j, 0, 0);
                rast__acc_ones(a, e, one, none, j, 0, 0);
            }
            /* (the row's edges all in cur[] again: the readout's and the
             * tie passes' list) */
            for (k = 0; k < none; k++) cur[nrow + k] = one[k];
            nrow += none;
            a->spread = a->cnt != NULL;
            kept.hi = -1;
            done = rast__acc_emit(a, 1, o, j, w->rule, m, rast__acc_win((uint64_t)nrow, m), e, NULL, cur, nrow,
                                  a->cnt ? &kept : NULL);
            if (!done && a->cnt && kept.hi >= 0) {
                done = rast__acc_ties_z(a, w, e, cur, nrow, j, &kept);
                zcols = !done && kept.hi > kept.lo; /* (kept: the columns left to decide) */
            } else if (!done) {
                done = rast__acc_ties(a, w, e, cur, nrow, j);
            }
        } else {
            for (k = 0, q = 0; k < nrow; k++)
                if (last[cur[k]] > j) nxt[q++] = cur[k];
            for (k = 0; k < none; k++) cur[nrow + k] = one[k];
            nrow += none;
        }
        if (!done) {
            if (!exact) { /* the first exact row (rare) */
                memset(w->exact, 0, w->n);
                exact = 1;
            }
            if (zcols)
                rast__acc_exact_cols(w, cur, nrow, j, kept.lo, kept.hi);
            else
                rast__acc_exact(w, cur, nrow, j);
        }
        zcols = 0;
        t = cur;
        cur = nxt;
        nxt = t;
        nrow = q;
    }
}

#endif

#if !defined(__OPTIMIZE_SIZE__)
/* A band's row j with a level near a tie by the window of all its parts
 * (rast__acc_win of the row's count): its q parts w->tmp[0..q) deposited
 * again into its cells a (cleared), a row at a time as rast__acc_by_rows
 * does, counted per 16 columns, so that each pixel's window is that of the
 * parts that touch its columns, not of the row's (a thousand parts on a
 * row of a thousand small triangles, twenty or so in any 16 columns: one
 * row in thirty went to the exact sweep, at ~470 instructions a part, where
 * this takes ~100).  Returns rast__acc_emit's: 1 when done.  The edges'
 * steppers are left at this row (the next band finds them by their tags);
 * the counts' room, after z[] in area[] as the rows' walk has it, cleared
 * as the walk's (the caller clears area[] before the first time). */
static int rast__acc_again(rast__acc *a, const rast__acc_walk *w, int32_t j, int32_t q)
{
    rast__aedge *const e = w->e;
    const int64_t Yj = (int64_t)j * a->p;
    int32_t k, done;
    a->dense = (int64_t)q * RAST__ACC_DENSE >= w->width;
    a->cnt = a->z + w->width;
    for (k = 0; k < q; k++)
        rast__acc_row_part_in(a, &e[w->tmp[k]], j, (int64_t)e[w->tmp[k]].yt - Yj, RAST__ACC_SX, 1);
    done = rast__acc_emit(a, RAST__ACC_SX, w->o, j, w->rule, w->m, 0, e, NULL, w->tmp, q, NULL);
    a->cnt = NULL;
    return done;
}

/* ---- Deep rows in the bands' walk (speed builds) -------------------------
 *
 * A band's row of n >= RAST__ACC_MAXN parts whose window still holds,
 * (n + 1) M < 2^25 (uint8: n < 131,586), is accumulated all the same:
 * its sums' bound per part (the top of this file) does not depend on n,
 * and modulo 2^64 each cell is right whatever n; what needs n < 2^12 is
 * only that the running sum v = 2^51 a + err (|err| < (n + 1) 2^22 <
 * 2^39) be read as a signed 64-bit value, which the non-zero rule does
 * (|v|, rast__acc_apply, rast__acc_nz4).  Even-odd reads v mod 2^52 only
 * (2^64 is a multiple of 2^52): any n.  Non-zero needs |a| <= 4095 at
 * each pixel of the row (then |v| <= 4095 2^51 + 2^39 < 2^63), which the
 * bound below gives from the band's edges, or the row goes to the exact
 * sweep as before (its cells cleared, rast__acc_drop).
 *
 * The bound.  A part of edge i (direction d = +-1: rast__cov_edge_of's,
 * the cancelled gone) in a row adds to pixel k's integral a_k its
 * c = d times the share of the pixel right of it within the part's
 * height h <= 1: with its abscissae in [xl, xr] and l = floor(xl), r =
 * floor(xr) (columns of the clip, as the cells take a part: left of the
 * clip whole, right of it nothing), c = 0 for k < l (the pixel lies left
 * of the part: k + 1 <= xl), c = d h for k > r (right of it: k >= r + 1
 * > xr), and d c in [0, h] between.  So for each row of the band
 *   a_k <= U_k = #{i : d = +1, l_i <= k} - #{i : d = -1, full, r_i < k},
 *   a_k >= L_k = #{i : d = +1, full, r_i < k} - #{i : d = -1, l_i <= k},
 * over the band's edges i, "full" those through every row of the band (h
 * = 1 in each; any other edge adds c in [0, 1] or [-1, 0] by its sign,
 * and none in a row it does not reach), with any [l_i, r_i] that holds
 * the edge's abscissae in the band: an edge walked through the whole band
 * (rast__acc_run_band) from its row stepper's abscissae at the band's top
 * and bottom (floors of the exact ones in 2^-30 px: the same columns), any
 * other from its ends.  U and L are two difference arrays over columns 0
 * .. w, h[0 .. w] and h[w + 1 .. 2 w + 1] (rast__acc_deep_add, a few
 * instructions an edge and band), summed once a band (rast__acc_deep_fits:
 * w columns).  10,000 canvas-spanning triangles all one way round
 * (bench/bench_crossings.py, 512 x 512: rows of ~15,000 parts, the
 * winding up to about a quarter of the count at the middle) have the
 * bound at 2,750 at most: every band passes. */
#define RAST__ACC_MAXA 4095

/* An edge of direction dir in columns l <= r1 - 1 (of the clip, 0 <= l <
 * r1 <= w) into U and L (h, above): +-1 at l in one, and at r1 in the
 * other when full (1 when the edge runs through every row of the band,
 * else 0).  (No branch on dir: the sides of a shape alternate.) */
static inline void rast__acc_deep_add(int32_t *h, int32_t w, int32_t l, int32_t r1, int32_t dir, int32_t full)
{
    const int32_t up = dir > 0, o = up ? 0 : w + 1, g = up ? 1 : -1;
    h[l + o] += g;
    h[r1 + (w + 1 - o)] += full ? g : 0;
}

/* The same for an edge not walked through the whole band (top and bot:
 * its rows' bounds in subpixels): its columns from its abscissae where it
 * enters and leaves the band (floors of the exact ones, whose columns they
 * are: two divisions, for these few), clamped to the clip */
static void rast__acc_deep_edge(int32_t *h, const rast__acc *a, const rast__aedge *e, int64_t top, int64_t bot)
{
    const int64_t yb = (int64_t)e->yt + e->dy, y0 = e->yt > top ? e->yt : top, y1 = yb < bot ? yb : bot;
    const int64_t w = a->x1 - a->x0;
    int64_t c[2], n, q;
    int i;
    if (e->dy <= 0 || y0 >= y1) return; /* (no part in the band) */
    for (i = 0; i < 2; i++) {
        n = (int64_t)e->dx * ((i ? y1 : y0) - e->yt); /* |n| < 2^62 */
        q = n / e->dy;
        q -= n < 0 && q * e->dy != n; /* floor */
        c[i] = rast__acc_floorp((int64_t)e->xt + q, a) - a->x0;
    }
    if (c[0] > c[1]) {
        q = c[0];
        c[0] = c[1];
        c[1] = q;
    }
    c[0] = c[0] < 0 ? 0 : c[0] > w ? w : c[0];
    c[1] = c[1] < 0 ? 0 : c[1] >= w ? w : c[1] + 1;
    rast__acc_deep_add(h, (int32_t)w, (int32_t)c[0], (int32_t)c[1], e->dir, y0 == top && y1 == bot);
}

/* U and L summed over columns 0 .. w - 1 (h cleared, all 2 w + 2):
 * 1 when -RAST__ACC_MAXA <= L_k and U_k <= RAST__ACC_MAXA at each */
static int rast__acc_deep_fits(int32_t *h, int32_t w)
{
    int64_t u = 0, l = 0, most = 0, least = 0;
    int32_t k;
    for (k = 0; k < w; k++) {
        u += h[k];
        l += h[w + 1 + k];
        h[k] = h[w + 1 + k] = 0;
        most = u > most ? u : most;
        least = l < least ? l : least;
    }
    h[w] = h[2 * w + 1] = 0;
    return most <= RAST__ACC_MAXA && least >= -RAST__ACC_MAXA;
}

/* A band row's cells and bits cleared, nothing read (its bound failed:
 * the row goes to the exact sweep); cells [lo, hi] of w as
 * rast__acc_emit reads them, and the one after the last */
static void rast__acc_drop(rast__acc *a, int32_t w)
{
    const int32_t hi = a->hi < w ? a->hi : w - 1;
    int32_t k;
    for (k = a->lo; k <= hi; k++) a->acc[k * RAST__ACC_SX] = 0;
    a->acc[w * RAST__ACC_SX] = 0;
    if (!a->dense && a->lo <= hi)
        for (k = a->lo >> 6; k <= hi >> 6; k++) a->blk[k] = 0;
    a->lo = INT32_MAX;
    a->hi = -1;
}
#endif

/* The band j0 .. j1 - 1's edges row[0..nrow) walked into the cells v[r]
 * (rast__acc_by_bands' loop: ok[], dense and span its); deep: NULL, or
 * the deep rows' U and L, each edge added (a constant at each call: the
 * copy without it is the walk as it was). */
RAST__HOT void rast__acc_band_walk(const rast__acc_walk *w, rast__acc *v, const unsigned char *ok, int32_t nrow,
                                   int32_t j0, int32_t j1, int dense, int64_t *span, int32_t *deep)
{
    rast__aedge *const e = w->e;
    const int32_t ja = w->ja, *const row = w->row, *const last = w->last, *const key = w->key;
    const int64_t top = (int64_t)j0 * v->p;
    int32_t k;
#if defined(__OPTIMIZE_SIZE__)
    (void)deep;
#endif
    for (k = 0; k < nrow; k++) {
        const int32_t ek = row[k], f = key[ek] + ja;
        rast__aedge *const ed = &e[ek];
        /* through the whole band, from its top, the row stepper there */
        if (ok[RAST__ACC_BAND] && w->thru[ek] >= j1 - 1 && ed->qrow == j0 && (int64_t)ed->yt <= top) {
            const int64_t off = (top - ed->yt) * ((int64_t)1 << v->hq);
#if !defined(__OPTIMIZE_SIZE__)
            const int64_t xtop = ed->qx; /* (at the band's top: the deep rows' bound) */
#endif
            if (dense && ed->dx > 0)
                rast__acc_dband_r(v, ed, off, span);
            else if (dense)
                rast__acc_dband_l(v, ed, off, span);
            else if (ed->dx > 0)
                rast__acc_band_r(v, ed, off);
            else
                rast__acc_band_l(v, ed, off);
            ed->qrow = j1;
#if !defined(__OPTIMIZE_SIZE__)
            if (deep) { /* (through the band, in the clip: from its abscissae at the top and the bottom) */
                const int32_t c0 = (int32_t)(rast__acc_col(xtop) - v->x0), c1 = (int32_t)(rast__acc_col(ed->qx) - v->x0);
                rast__acc_deep_add(deep, w->width, c0 < c1 ? c0 : c1, (c0 < c1 ? c1 : c0) + 1, ed->dir, 1);
            }
#endif
        } else {
            const int32_t r0 = f > j0 ? f - j0 : 0, r1 = (last[ek] < j1 - 1 ? last[ek] : j1 - 1) - j0;
#if !defined(__OPTIMIZE_SIZE__)
            if (deep) rast__acc_deep_edge(deep, v, ed, top, top + (int64_t)(j1 - j0) * v->p); /* (any other) */
            /* (two rows or more, in the clip: one loop; a row alone
             * costs less by rast__acc_edge, its set-up being less) */
            if (ok[RAST__ACC_BAND] && w->thru[ek] != INT32_MIN && r0 < r1) {
                if (ed->dx > 0)
                    rast__acc_short_r(v, ed, j0, r0, r1, dense ? span : NULL);
                else
                    rast__acc_short_l(v, ed, j0, r0, r1, dense ? span : NULL);
                continue;
            }
#endif
            rast__acc_edge(v, ok, ed, j0, r0, r1, w->thru[ek]);
        }
    }
}

/* Rows ja to jb a band of RAST__ACC_BAND at a time, into the cells v[r] of
 * the band's row r, each edge walked over the band's rows at once
 * (rast__acc_edge; the long edges' walk); the exact rows' cells cleared
 * when the first is needed. */
#if defined(__OPTIMIZE_SIZE__)
static void rast__acc_by_bands(const rast__acc_walk *w, rast__acc *v)
#else
/* (out of line: inline, the rows' walk in the same function had fewer
 * registers, ~1% of the text family's instructions) */
RAST__APART void rast__acc_by_bands(const rast__acc_walk *w, rast__acc *v)
#endif
{
    rast__aedge *const e = w->e;
    const rast__cov_out *const o = w->o;
    const uint32_t m = w->m;
    const int32_t ja = w->ja;
    int32_t *const row = w->row, *const last = w->last, *const key = w->key;
    unsigned char ok[RAST__ACC_BAND + 1]; /* each row's, then all rows' */
    int32_t cnt[RAST__ACC_BAND + 1], nrow = 0, j0, j1, k, q, r, drop = INT32_MAX;
    int64_t span[2]; /* the columns of the band's dense walks */
    int dense, quad; /* every row of the band dense; its rows read out together */
    uint32_t qbad = 0; /* (their tie flags) */
    uint32_t next = 0;
    int clean = 0; /* cover[], area[], bits[] and w->exact[] cleared */
#if !defined(__OPTIMIZE_SIZE__)
    /* a band's non-zero deep rows' bound: U and L in cover[] (free in this
     * walk but for the exact rows, which find it cleared as it is left) */
    int32_t *const hist = (int32_t *)(void *)w->cover, *deep;
    int hz = 0; /* hist[] cleared */
#endif
    for (j0 = ja; j0 < w->jb; j0 = j1) {
        j1 = w->jb - j0 > RAST__ACC_BAND ? j0 + RAST__ACC_BAND : w->jb;
        /* each row's parts: how many, and whether they are few enough to
         * accumulate (their bound) and many enough to read every cell
         * (a part or more for every RAST__ACC_DENSE_BAND columns: no bits) */
#if !defined(__OPTIMIZE_SIZE__)
        nrow = rast__acc_band_edges(w, nrow, &next, &drop, j0, j1, cnt);
#else
        nrow = rast__acc_edges_of(w, nrow, &next, &drop, j0, j1);
        for (r = 0; r <= j1 - j0; r++) cnt[r] = 0;
        for (k = 0; k < nrow; k++) {
            const int32_t f = key[row[k]] + ja;
            cnt[f > j0 ? f - j0 : 0]++;
            if (last[row[k]] < j1 - 1) cnt[last[row[k]] - j0 + 1]--;
        }
#endif
#if !defined(__OPTIMIZE_SIZE__)
        deep = NULL;
#endif
        for (r = 0; r < j1 - j0; r++) {
            if (r) cnt[r] += cnt[r - 1];
            ok[r] = (unsigned char)(cnt[r] < RAST__ACC_MAXN && ((uint64_t)cnt[r] + 1) * m < ((uint64_t)1 << 25));
#if !defined(__OPTIMIZE_SIZE__)
            if (!ok[r] && ((uint64_t)cnt[r] + 1) * m < ((uint64_t)1 << 25)) { /* deep (above): non-zero's bound below */
                ok[r] = 1;
                deep = w->rule == RAST_RULE_NONZERO ? hist : NULL;
            }
#endif
            v[r].dense = (int64_t)cnt[r] * RAST__ACC_DENSE_BAND >= w->width;
        }
#if !defined(__OPTIMIZE_SIZE__)
        if (deep && !hz) {
            for (k = 0; k < 2 * w->width + 2; k++) hist[k] = 0;
            hz = 1;
        }
#endif
        for (r = 0, ok[RAST__ACC_BAND] = j1 - j0 == RAST__ACC_BAND, dense = 1; r < j1 - j0; r++) {
            ok[RAST__ACC_BAND] &= ok[r];
            dense &= v[r].dense;
        }
        span[0] = INT64_MAX;
        span[1] = -1;
#if !defined(__OPTIMIZE_SIZE__)
        if (deep) /* (a copy with the bound's adds: none in the other) */
            rast__acc_band_walk(w, v, ok, nrow, j0, j1, dense, span, deep);
        else
#endif
            rast__acc_band_walk(w, v, ok, nrow, j0, j1, dense, span, NULL);
        if (span[1] >= 0) /* (dense: the cells of the walks above) */
            for (r = 0; r < RAST__ACC_BAND; r++) {
                const int32_t lo = (int32_t)span[0], hi = (int32_t)span[1] + 1;
                v[r].lo = lo < v[r].lo ? lo : v[r].lo;
                v[r].hi = hi > v[r].hi ? hi : v[r].hi;
            }
#if !defined(__OPTIMIZE_SIZE__)
        if (deep && !rast__acc_deep_fits(deep, w->width)) { /* (its deep rows to the exact sweep) */
            for (r = 0; r < j1 - j0; r++)
                if (cnt[r] >= RAST__ACC_MAXN && ok[r]) {
                    ok[r] = 0;
                    rast__acc_drop(&v[r], w->width);
                }
            ok[RAST__ACC_BAND] = 0;
        }
#endif
        quad = 0;
#ifdef RAST__ACC_AVX2
        /* the four rows read out together, when each would be read the
         * quick way (rast__acc_row) into an array */
        if (ok[RAST__ACC_BAND] && dense && m == 255 && !o->paint && __builtin_cpu_supports("avx2"))
            quad = rast__acc_quad(v, o, j0, cnt, w->rule, &qbad);
#endif
        for (r = 0; r < j1 - j0; r++) {
            const int32_t j = j0 + r;
            /* (on a tie, the band's edges all vertical will do) */
            if (ok[r] && (quad ? rast__acc_done(o, j, (qbad >> r) & 1, e, NULL, row, nrow)
                               : rast__acc_emit(&v[r], RAST__ACC_SX, o, j, w->rule, m,
                                                rast__acc_win((uint64_t)cnt[r], m), e, NULL, row, nrow, NULL)))
                continue;
            for (k = 0, q = 0; k < nrow; k++) /* the row's edges */
                if (key[row[k]] + ja <= j && last[row[k]] >= j) w->tmp[q++] = row[k];
            if (!clean) { /* the first exact row (rare): the cells cleared (the sums
                           * leave z[] as they find it) */
                memset(w->exact, 0, w->n);
                for (k = 0; k < w->width; k++) w->cover[k] = w->area[k] = rast__i128_u64(0);
                for (k = 0; k < w->nw; k++) w->bits[k] = 0;
                clean = 1;
            }
#if !defined(__OPTIMIZE_SIZE__)
            /* (the parts counted per 16 columns first, when there are
             * enough of them for it to narrow the window) */
            if (ok[r] && q >= RAST__ACC_FEW && rast__acc_again(&v[r], w, j, q)) continue;
#endif
            rast__acc_exact(w, w->tmp, q, j);
        }
    }
}

#if RAST__ACC_COMPACT
/* The piles' walk (speed builds): a batch of small triangles (every edge
 * within RAST__ACC_PILE rows, the rows dense on the mean) is walked an
 * edge at a time, each edge whole, into a ring of RAST__ACC_RING rows of
 * cells, instead of a band of four rows at a time (where a small
 * triangle's edge, 8 rows on the mean among 10,000, met 2.75 bands, at a
 * set-up of ~150 instructions a visit and the band's lists besides:
 * docs/coverage.md).  Rows are read out RAST__ACC_RING - RAST__ACC_PILE at
 * a time, once every edge that starts above them has been walked. */
#define RAST__ACC_RING 64
#define RAST__ACC_PILE 32
/* ...and only where the edges' rows are at least one for every
 * RAST__ACC_PILE_DENSE columns of the rows they span, on the mean: the
 * ring's rows are read whole, which a map's 289 rings of short edges (an
 * edge-row per ~20 columns) paid 14% more for than the bands' walk */
#define RAST__ACC_PILE_DENSE 4

/* floor(a / b) (pos) or floor(-a / b) (not pos) and its remainder, a >= 0,
 * b > 0: one unsigned division (pos a constant at each call) */
static inline int64_t rast__acc_sdiv(int64_t a, int64_t b, uint32_t *r, int pos)
{
    const uint64_t q = (uint64_t)a / (uint64_t)b, m = (uint64_t)a % (uint64_t)b;
    if (pos) {
        *r = (uint32_t)m;
        return (int64_t)q;
    }
    *r = (uint32_t)(m ? (uint64_t)b - m : 0);
    return -(int64_t)q - (m != 0);
}

/* A part of rast__acc_whole_in's edge: from (xa, ta) to (xb, tb) in row
 * cells acc (Q units, t from the row's top), the column stepper at the
 * next vertical after xa's column (*qt from the row's top, *qtr; its step
 * qts, qtsr; d0: qts 2^20 signed), moved past the part's last vertical */
RAST__HOT void rast__acc_whole_part(uint64_t *acc, int64_t xa, int64_t xb, uint64_t ta, uint64_t tb, int64_t *qt,
                                    uint32_t *qtr, int64_t qts, uint32_t qtsr, uint32_t adx, uint64_t d0, int right,
                                    uint64_t neg)
{
    const uint64_t fm = QT - 1;
    const int64_t ca = (int64_t)((uint64_t)xa >> QF), cb = (int64_t)((uint64_t)xb >> QF);
    if (ca == cb) {
        rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)xb & fm, tb - ta, neg, 1);
    } else {
        const uint64_t d1 = d0 + ((((uint64_t)1 << 20) ^ neg) - neg);
        uint64_t t = (uint64_t)*qt, prev = 0, sum = 0;
        uint32_t r = *qtr;
        int64_t col;
        rast__acc_put(acc, ca, (uint64_t)xa & fm, right ? QT : 0, t - ta, neg, 1);
        if (right) {
            for (col = ca + 1; col != cb; col++) rast__acc_col_step(&acc[col], &r, qtsr, adx, d0, d1, &prev, &sum);
            acc[cb] += prev;
        } else {
            for (col = ca - 1; col != cb; col--)
                rast__acc_col_step(&acc[col + 1], &r, qtsr, adx, d0, d1, &prev, &sum);
            acc[cb + 1] += prev;
        }
        t += (((sum ^ neg) - neg)) >> 20; /* (the last vertical's ordinate) */
        rast__acc_put(acc, cb, right ? 0 : QT, (uint64_t)xb & fm, tb - t, neg, 1);
        r += qtsr; /* the stepper to the vertical after the last */
        *qt = (int64_t)t + qts + rast__acc_carry_sel(&r, adx);
        *qtr = r;
    }
}

/* Edge e (within the clip's columns and rows, |dx| < 2^24, dy at most
 * RAST__ACC_PILE rows) whole into the ring's rows (ring: row j's cells at
 * ring + (j mod RAST__ACC_RING) stride; bias: the clip's left side in
 * 2^-30 px).  Each row's part is put as rast__acc_part puts it (a piece
 * in its one column; or its first column's to the first vertical, the
 * whole columns' between, as rast__acc_cols_in adds them, the last
 * column's from the last vertical), the abscissae at the rows' tops and
 * the ordinates at the verticals the floors of the exact values on the
 * grid of 2^-30 px, by steppers set here (one division each, as
 * rast__acc_top and rast__acc_t_first set them): the same pieces, so the
 * same cells (docs/coverage.md, the accumulation's bound per part).
 * right: e goes right; neg: its sign (0, or all ones: e->dir < 0); both
 * constants at each call, so that a put is two adds or two subtractions.
 * An edge whose ends lie in one column crosses no vertical: a piece a
 * row, and no column stepper; the others have theirs set at the first
 * vertical they cross, from the first row's top (the same ordinates as
 * when set at the row that crosses it: QT a row apart).  The first row
 * (from the edge's top) and the last (to its bottom end) apart from the
 * rows between, whole rows (from 0 to QT: constants there). */
RAST__HOT void rast__acc_whole_in(uint64_t *ring, size_t stride, const rast__aedge *e, int32_t s, int64_t bias,
                                  int right, uint64_t neg)
{
    const int32_t p = (int32_t)1 << s, hq = QF - s;
    const uint64_t fm = QT - 1;
    const int64_t xt = e->xt, yt = e->yt, dx = e->dx, dy = e->dy, adx = dx < 0 ? -dx : dx;
    const int32_t j0 = (int32_t)(yt >> s), jl = (int32_t)((yt + dy - 1) >> s); /* (yt >= 0 here: the clip's rows) */
    const int64_t xe = (xt + dx) * ((int64_t)1 << hq) - bias; /* the bottom end */
    const uint64_t te = (uint64_t)((yt + dy - (int64_t)jl * p) * ((int64_t)1 << hq));
    int64_t xa = xt * ((int64_t)1 << hq) - bias, qx = 0, qxs = 0, qt, qts;
    const int64_t ca = (int64_t)((uint64_t)xa >> QF);
    uint64_t ta = (uint64_t)((yt - (int64_t)j0 * p) * ((int64_t)1 << hq)), d0;
    uint32_t qxr = 0, qxsr = 0, qtr, qtsr;
    int32_t n = jl - j0; /* the rows before the last */
    uint64_t *acc = ring + (size_t)(j0 & (RAST__ACC_RING - 1)) * stride, *const end = ring + RAST__ACC_RING * stride;
    if (n) { /* (dx's sign is right's: the floors of quotients of one sign) */
        qx = xa + rast__acc_sdiv(adx * (((int64_t)j0 + 1) * p - yt) * ((int64_t)1 << hq), dy, &qxr, right);
        qxs = rast__acc_sdiv(adx * ((int64_t)1 << QF), dy, &qxsr, right);
    }
    if (ca == (int64_t)((uint64_t)xe >> QF)) { /* one column: a piece a row */
        for (; n; n--) {
            rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)qx & fm, QT - ta, neg, 1);
            xa = qx;
            ta = 0;
            acc += stride;
            acc = acc == end ? ring : acc;
            qx += qxs;
            qxr += qxsr;
            qx += rast__acc_carry_sel(&qxr, (uint32_t)dy);
        }
        rast__acc_put(acc, ca, (uint64_t)xa & fm, (uint64_t)xe & fm, te - ta, neg, 1);
        return;
    }
    { /* the column stepper at the first vertical crossed, from row j0's top */
        const int64_t X = (ca + right) * p + bias / ((int64_t)1 << hq), u = right ? X - xt : xt - X;
        qt = rast__acc_sdiv(u * dy * ((int64_t)1 << hq), adx, &qtr, 1) + (int64_t)ta;
        qts = rast__acc_sdiv(dy * ((int64_t)1 << QF), adx, &qtsr, 1);
        d0 = (((uint64_t)qts << 20) ^ neg) - neg;
    }
    if (n) {
        /* the first row, from the edge's top; then the whole rows */
        rast__acc_whole_part(acc, xa, qx, ta, QT, &qt, &qtr, qts, qtsr, (uint32_t)adx, d0, right, neg);
        for (;;) {
            xa = qx;
            qt -= (int64_t)QT;
            acc += stride;
            acc = acc == end ? ring : acc;
            if (!--n) break;
            qx += qxs;
            qxr += qxsr;
            qx += rast__acc_carry_sel(&qxr, (uint32_t)dy);
            rast__acc_whole_part(acc, xa, qx, 0, QT, &qt, &qtr, qts, qtsr, (uint32_t)adx, d0, right, neg);
        }
        ta = 0;
    }
    rast__acc_whole_part(acc, xa, xe, ta, te, &qt, &qtr, qts, qtsr, (uint32_t)adx, d0, right, neg);
}

/* Out of line, one for each direction and sign (rast__acc_cols_r's
 * reasons) */
RAST__APART void rast__acc_whole_rp(uint64_t *ring, size_t stride, const rast__aedge *e, int32_t s, int64_t bias)
{
    rast__acc_whole_in(ring, stride, e, s, bias, 1, 0);
}

RAST__APART void rast__acc_whole_rn(uint64_t *ring, size_t stride, const rast__aedge *e, int32_t s, int64_t bias)
{
    rast__acc_whole_in(ring, stride, e, s, bias, 1, ~(uint64_t)0);
}

RAST__APART void rast__acc_whole_lp(uint64_t *ring, size_t stride, const rast__aedge *e, int32_t s, int64_t bias)
{
    rast__acc_whole_in(ring, stride, e, s, bias, 0, 0);
}

RAST__APART void rast__acc_whole_ln(uint64_t *ring, size_t stride, const rast__aedge *e, int32_t s, int64_t bias)
{
    rast__acc_whole_in(ring, stride, e, s, bias, 0, ~(uint64_t)0);
}

/* Rows ja to jb by the piles' walk, if it fits: returns 0 (nothing done)
 * where an edge is taller than RAST__ACC_PILE rows or wider than 2^24
 * subpixels, the rows are not dense on the mean, or the edges' free room
 * (w->fat, below the records) cannot hold the ring and the exact rows'
 * records too.  Edges that leave the clip go row by row the general way
 * (rast__acc_row_part_in).  Every row is read whole (dense); a row with a
 * level near a tie, or too many parts, goes to the exact sweep
 * (rast__acc_exact), as in the bands' walk.  all: the edges' rows as
 * rast__acc_sorted sums them (each edge's, not cut to the clip's rows):
 * rows not dense even by that sum are turned away before the pass over
 * the edges (a map's rings: 0.2 M instructions).  (An edge wholly above
 * the clip adds less than nothing to it: such a scene may be turned away
 * where the pass would take it, the same levels by the bands' walk.) */
static int rast__acc_by_piles(const rast__acc_walk *w, rast__acc *v, uint64_t all)
{
    rast__aedge *const e = w->e;
    const int32_t ja = w->ja, jb = w->jb, s = w->s, p = (int32_t)1 << s, wd = w->width;
    const int32_t *const key = w->key, *const last = w->last;
    const size_t stride = (size_t)wd + 1, ringsz = RAST__ACC_RING * stride * sizeof(uint64_t);
    const size_t room = (size_t)((unsigned char *)(void *)e - (unsigned char *)(void *)w->fat);
    const int64_t bias = (int64_t)v->x0 * (int64_t)QT;
    rast__acc_walk ww = *w;
    rast__acc ra = v[0];
    uint64_t *ring, rows = 0;
    int32_t *dif, hmax = 0, most = 0, cur, j, jw, jh, hgt, k, q;
    int32_t nv = -1; /* an edge not vertical (the exact rows' test: rast__acc_emit's) */
    uint32_t i, i0, inext;
    int clean = 0;
    if (ja < 0 || ringsz + RAST__ACC_RING * sizeof(int32_t) > room || (size_t)(jb - ja + 1) * sizeof(int32_t) > ringsz ||
        (int64_t)all < 0 || all * RAST__ACC_PILE_DENSE < (uint64_t)(jb - ja) * (uint64_t)wd)
        return 0;
    ring = (uint64_t *)(void *)((unsigned char *)(void *)e - ringsz - RAST__ACC_RING * sizeof(int32_t));
    dif = (int32_t *)(void *)ring; /* (first the rows' counts, to decide) */
    for (j = 0; j <= jb - ja; j++) dif[j] = 0;
    for (i = 0; i < w->n; i++) {
        const int32_t f = key[i] + ja, l = last[i] < jb - 1 ? last[i] : jb - 1;
        if (l - f + 1 > RAST__ACC_PILE || (i && key[i] < key[i - 1]) || e[i].dx >= (1 << 24) || e[i].dx <= -(1 << 24))
            return 0;
        if (l < f) continue;
        hmax = l - f + 1 > hmax ? l - f + 1 : hmax;
        rows += (uint64_t)(l - f + 1);
        dif[f - ja]++;
        dif[l + 1 - ja]--;
        if (e[i].dx && nv < 0) nv = (int32_t)i;
    }
    if (nv < 0 || rows * RAST__ACC_PILE_DENSE < (uint64_t)(jb - ja) * (uint64_t)wd) return 0;
    for (j = 0, cur = 0; j < jb - ja; j++) {
        cur += dif[j];
        most = cur > most ? cur : most;
    }
    ww.cap = (uint32_t)((room - ringsz - RAST__ACC_RING * sizeof(int32_t)) / sizeof(rast__cedge));
    if ((uint32_t)most > ww.cap) return 0;
    /* the walk: the ring and its rows' count changes cleared */
    dif = (int32_t *)(void *)(ring + RAST__ACC_RING * stride);
    for (k = 0; k < RAST__ACC_RING; k++) dif[k] = 0;
    for (i = 0; i < RAST__ACC_RING * stride; i++) ring[i] = 0;
    ra.dense = 1;
    ra.cnt = NULL;
    ra.lo = 0;
    ra.hi = wd - 1;
    hgt = RAST__ACC_RING - hmax; /* (rows a window: an edge that starts in it ends RAST__ACC_RING - 1 rows below its top at most) */
    for (jw = ja, inext = 0, i0 = 0, cur = 0; jw < jb; jw = jh) {
        jh = jb - jw > hgt ? jw + hgt : jb;
        for (; inext < w->n && key[inext] + ja < jh; inext++) { /* every edge that starts above row jh */
            rast__aedge *const ed = &e[inext];
            const int32_t f = key[inext] + ja, l = last[inext] < jb - 1 ? last[inext] : jb - 1;
            if (l < f) continue;
            dif[f & (RAST__ACC_RING - 1)]++;
            dif[(l + 1) & (RAST__ACC_RING - 1)]--;
            if (w->thru[inext] != INT32_MIN && (int64_t)ed->yt >= (int64_t)ja * p && last[inext] <= jb - 1) {
                if (ed->dx > 0) {
                    if (ed->dir < 0)
                        rast__acc_whole_rn(ring, stride, ed, s, bias);
                    else
                        rast__acc_whole_rp(ring, stride, ed, s, bias);
                } else if (ed->dir < 0) {
                    rast__acc_whole_ln(ring, stride, ed, s, bias);
                } else {
                    rast__acc_whole_lp(ring, stride, ed, s, bias);
                }
            } else {
                for (j = f; j <= l; j++) { /* (the general way, a row at a time) */
                    ra.acc = ring + (size_t)(j & (RAST__ACC_RING - 1)) * stride;
                    rast__acc_row_part_in(&ra, ed, j, (int64_t)ed->yt - (int64_t)j * p, 1, 0);
                }
            }
        }
        for (j = jw; j < jh; j++) {
            const int32_t at = j & (RAST__ACC_RING - 1);
            ra.acc = ring + (size_t)at * stride;
            cur += dif[at];
            dif[at] = 0;
            ra.lo = 0;
            ra.hi = wd - 1;
            /* (on a tie, the exact row: one edge not vertical given as
             * the row's, so that rast__acc_emit does not take the sums) */
            if (cur < RAST__ACC_MAXN && ((uint64_t)cur + 1) * w->m < ((uint64_t)1 << 25)) {
                if (rast__acc_emit(&ra, 1, w->o, j, w->rule, w->m, rast__acc_win((uint64_t)cur, w->m), e, NULL, &nv,
                                   1, NULL))
                    continue;
            } else {
                for (k = 0; k <= wd; k++) ra.acc[k] = 0;
            }
            for (; i0 < inext && key[i0] + ja + hmax <= j; i0++) {
            }
            for (i = i0, q = 0; i < inext; i++) /* the row's edges */
                if (key[i] + ja <= j && last[i] >= j) ww.tmp[q++] = (int32_t)i;
            if (!clean) { /* the first exact row (rare): the cells cleared */
                memset(w->exact, 0, w->n);
                for (k = 0; k < wd; k++) w->cover[k] = w->area[k] = rast__i128_u64(0);
                for (k = 0; k < w->nw; k++) w->bits[k] = 0;
                clean = 1;
            }
            /* (the parts counted per 16 columns first, when there are
             * enough of them for it to narrow the window: the band's cells
             * v[0], unused here and cleared) */
            if (cur < RAST__ACC_MAXN && ((uint64_t)cur + 1) * w->m < ((uint64_t)1 << 25) && q >= RAST__ACC_FEW &&
                rast__acc_again(&v[0], &ww, j, q))
                continue;
            rast__acc_exact(&ww, ww.tmp, q, j);
        }
    }
    return 1;
}
#endif

/* The columns that can hold a value not 0: those the edges' abscissae
 * reach, [*c0, *c1) (of any clip).  Left of every edge the winding
 * number is 0, and right of them too: each ring is closed, so the
 * directions of the edges that a line from there to the right crosses
 * sum to 0. */
static void rast__acc_cols_reached(const rast__acc_in *e, uint32_t n, int32_t p, int64_t *c0, int64_t *c1)
{
    int64_t lo = e[0].xt, hi = e[0].xt;
    uint32_t i;
    for (i = 0; i < n; i++) {
        const int64_t xa = e[i].xt, xb = (int64_t)e[i].xt + e[i].dx;
        lo = xa < lo ? xa : lo;
        lo = xb < lo ? xb : lo;
        hi = xa > hi ? xa : hi;
        hi = xb > hi ? xb : hi;
    }
    *c0 = rast__floordiv(lo, p);
    *c1 = rast__floordiv(hi, p) + 1;
}

/* The accumulation into o narrowed to the columns [x0, x1) (of its clip,
 * not empty) that the edges reach: the cells, the rows' fills and their
 * scans (a painter's runs) cost those columns, not the clip's width (400
 * tiny polygons drawn one call each on a 512-wide canvas spent two
 * thirds of their instructions reading out rows of 0).  An array's other
 * columns get 0 in the rows [ja, jb) the edges reach, here; a painter is
 * handed the same runs (the columns left out hold 0: no run crosses
 * them). */
static rast_status rast__acc_narrow(rast__acc_in *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                    const rast__cov_out *o, rast__arena *arena, int32_t x0, int32_t x1);
/* The accumulation of the n > 0 edges into o, every column of its clip;
 * e[] at the start of the edges' room (n rast__cedge). */
static rast_status rast__acc_walk_all(rast__acc_in *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                      const rast__cov_out *o, rast__arena *arena);

/* rast__cov_acc of the edges e[] (rast__acc_in: at the start of the
 * edges' room, n rast__cedge). */
static rast_status rast__acc_go(rast__acc_in *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                const rast__cov_out *o, rast__arena *arena);

/* The probes a hash lookup takes at most (rast__acc_cancel): past them
 * an edge is neither cancelled nor kept for another to cancel, so that no
 * input, however its hashes collide, costs more than this per edge. */
#define RAST__ACC_PROBES 32

/* The equal edges (xt, yt, dx, dy) of opposite directions among the
 * edges e[i], i < n, looked at: every one (step 1), or a sample, each
 * next one 1 to 2 step - 1 further on, pseudo-randomly (a hash of i: so
 * that the two edges of a pair are both looked at about once in step^2
 * however the rings' sizes fall, which a fixed stride's multiples would
 * not be on a grid of rings of one size), in the hash table
 * slot[0..size) (a power of 2, at least twice the edges looked at, open
 * addressing, all -1 on the way in): each edge looks for one not yet
 * matched, and either matches it (both have their dir set to 0 when
 * `mark`) or is added.  (xt, yt) and (dx, dy) are read as two 64-bit
 * words: the hash in two products, the match in two compares, where four
 * of each were ~13 and ~8 instructions an edge on the map.  Returns how many edges matched (twice the
 * pairs).  Size-optimised builds read the four fields as they are, and
 * hash them with 32-bit products (RAST__ACC_WORDS, RAST__ACC_HASH,
 * RAST__ACC_SAME): there a 64-bit product is a library call, and so is a
 * memcpy (-ffreestanding; the Cortex-M0 has no unaligned loads).  Any
 * hash will do for the sums: a match compares the four fields, and an
 * edge past the probes is only not cancelled (the same levels,
 * rast__acc_cancel). */
#if defined(__OPTIMIZE_SIZE__)
/* (uint32_t products wrap, mod 2^32, whatever int's width) */
#define RAST__ACC_WORDS(x, top, d) ((void)(top), (void)(d))
#define RAST__ACC_HASH(x, top, d)                                                                                \
    rast__acc_mix((uint32_t)(x)->xt * 0x9E3779B1u + (uint32_t)(x)->yt * 0x85EBCA77u +                              \
                  (uint32_t)(x)->dx * 0xC2B2AE3Du + (uint32_t)(x)->dy * 0x27D4EB2Fu)
#define RAST__ACC_SAME(k, x, top, d) ((k)->xt == (x)->xt && (k)->yt == (x)->yt && (k)->dx == (x)->dx && (k)->dy == (x)->dy)
static uint32_t rast__acc_mix(uint32_t h)
{
    return h ^ (h >> 15);
}
#else
/* (xt, yt) and (dx, dy) as two 64-bit words (adjacent fields) */
#define RAST__ACC_WORDS(x, top, d) (memcpy(&(top), &(x)->xt, sizeof(top)), memcpy(&(d), &(x)->dx, sizeof(d)))
#define RAST__ACC_HASH(x, top, d) \
    ((uint32_t)((((top) * UINT64_C(0x9E3779B97F4A7C15)) ^ (d)) * UINT64_C(0xC2B2AE3D27D4EB4F) >> 32))
#define RAST__ACC_SAME(k, x, top, d) rast__acc_same(k, top, d)
static inline int rast__acc_same(const rast__acc_in *k, uint64_t top, uint64_t d)
{
    uint64_t ktop, kd;
    memcpy(&ktop, &k->xt, sizeof ktop);
    memcpy(&kd, &k->dx, sizeof kd);
    return ktop == top && kd == d;
}
#endif
RAST__HOT uint32_t rast__acc_pairs(rast__acc_in *e, uint32_t n, uint32_t step, int mark, int32_t *slot,
                                uint32_t size)
{
    uint32_t i, h, probe, gone = 0;
    int32_t k;
    for (i = 0; i < n;
         i += step == 1 ? 1 : 1 + (uint32_t)(((uint64_t)((i + 1) * 0x9E3779B1u) * (2 * step - 1)) >> 32)) {
        rast__acc_in *x = &e[i];
        uint64_t top = 0, d = 0; /* (speed builds: (xt, yt) and (dx, dy)) */
        RAST__ACC_WORDS(x, top, d);
        h = RAST__ACC_HASH(x, top, d);
        for (probe = 0; probe < RAST__ACC_PROBES; probe++, h++) {
            k = slot[h & (size - 1)];
            if (k == -1) {
                slot[h & (size - 1)] = (int32_t)i;
                break;
            }
            if (k < 0) continue;
            if (RAST__ACC_SAME(&e[k], x, top, d) && e[k].dir == -x->dir) {
                slot[h & (size - 1)] = -2; /* (matched: not again) */
                if (mark) e[k].dir = x->dir = 0;
                gone += 2;
                break;
            }
        }
    }
    return gone;
}

/* Coincident edges of opposite directions (a mesh's inner edges, two
 * triangles of a batch sharing a side, two countries' border) change no
 * winding number on either side: their parts put the same values in the
 * same cells with opposite signs (rast__acc_put's are exact negations
 * modulo 2^64), so the sums, and every level, are the same without them.
 * Each edge looks for an equal one (xt, yt, dx, dy) of the other
 * direction not yet cancelled, in a hash table of edge indices
 * (rast__acc_pairs, at least 2 n slots, in room taken from a copy of the
 * arena: the walk's after); if it finds one, both go (their dir set to
 * 0), else it is added.  The edges left are moved down in their order
 * (one pass: any order would do, the sums are the same in any order);
 * returns how many are left.  With no room for the table nothing goes. */
static uint32_t rast__acc_cancel(rast__acc_in *e, uint32_t n, rast__arena room)
{
    uint32_t size = 16, i, q;
    int32_t *slot;
    while (size < 2 * n) size <<= 1;
    slot = (int32_t *)rast__take(&room, (size_t)size * sizeof(int32_t));
    if (n < 2 || !slot) return n;
    for (i = 0; i < size; i++) slot[i] = -1; /* (-1 empty, -2 cancelled) */
    if (!rast__acc_pairs(e, n, 1, 1, slot, size)) return n;
    for (i = 0, q = 0; i < n; i++) /* (the rest moved down, in order) */
        if (e[i].dir) e[q++] = e[i];
    return q;
}

#if RAST__ACC_COMPACT
/* The edges e[0..n) as the call's first passes read them: rast__acc_thin
 * records, made in place at the start of their room (record i's 20 bytes
 * meet only the rast__cedge records <= i, read before it). */
static rast__acc_in *rast__acc_thin_of(rast__cedge *e, uint32_t n)
{
    unsigned char *const room = (unsigned char *)(void *)e;
    uint32_t i;
    for (i = 0; i < n; i++) {
        rast__acc_thin t;
        t.xt = e[i].xt;
        t.yt = e[i].yt;
        t.dx = e[i].dx;
        t.dy = e[i].dy;
        t.dir = e[i].dir;
        memcpy(room + (size_t)i * sizeof t, &t, sizeof t); /* (memcpy: the rooms overlap) */
    }
    return (rast__acc_in *)(void *)e;
}

/* The edges of the ring pt[0..size) that are not horizontal, in
 * rast__cov_edges_polygon's order, into t[]; returns how many. */
static uint32_t rast__acc_thin_ring(const rast_point *pt, uint32_t size, rast__acc_thin *t)
{
    uint32_t i, n = 0;
    rast_point a, b;
    if (!size) return 0;
    a = pt[0];
    for (i = 0; i < size; i++) {
        b = pt[i + 1 < size ? i + 1 : 0];
        if (a.y != b.y) {
            t[n].dir = rast__cov_edge_of(a, b, &t[n].xt, &t[n].yt, &t[n].dx, &t[n].dy);
            n++;
        }
        a = b;
    }
    return n;
}

/* Would rast__acc_cancel drop an eighth or more of the n edges t[] (a
 * map's countries share about half of theirs)?  Asked of a polygon of 2
 * rings or more that is not a mesh's (rast__cov_acc_points' `shared`
 * RAST__ACC_LOOK): the cancelling costs ~48 instructions an edge and
 * saves ~670 an edge cancelled on the map (its 10,237 edges, 5,242
 * cancelled: 9.47 M -> 6.0 M), but a text's edges never cancel (31,354
 * edges: +1.36 M, 9%, if all were looked for).  So about one edge in s is
 * looked at (rast__acc_pairs' sample), s = max(4, floor(sqrt(n / 64))):
 * both edges of a pair are in that sample about once in s^2, so g edges
 * matched there stand for ~g s^2 cancelled: yes when 8 g s^2 >= n.  With
 * n / s^2 >= 64, an eighth cancelled matches g >= 8 on the mean, the
 * threshold; the map's half, ~36 (threshold 9).  The sample (text: 1,425
 * edges looked at, a table of 4,096 slots) costs text ~0.5%.  Below
 * RAST__ACC_LOOK_MIN edges, no. */
#define RAST__ACC_LOOK_MIN 1024
static int rast__acc_many_pairs(rast__acc_in *t, uint32_t n, rast__arena room)
{
    uint32_t s = 4, m, size = 16, i;
    int32_t *slot;
    if (n < RAST__ACC_LOOK_MIN) return 0;
    while ((uint64_t)(s + 1) * (s + 1) * 64 <= n) s++;
    m = n / s + 1; /* (the sample's size, on the mean) */
    while (size < 2 * m) size <<= 1;
    slot = (int32_t *)rast__take(&room, (size_t)size * sizeof(int32_t));
    if (!slot) return 0;
    for (i = 0; i < size; i++) slot[i] = -1;
    return (uint64_t)rast__acc_pairs(t, n, s, 0, slot, size) * 8 * s * s >= n;
}

/* rast__acc_cancel, when `shared` is RAST__ACC_LOOK only if
 * rast__acc_many_pairs (else n) */
RAST__APART uint32_t rast__acc_cancel_some(rast__acc_in *t, uint32_t n, int shared, rast__arena room)
{
    return shared != RAST__ACC_LOOK || rast__acc_many_pairs(t, n, room) ? rast__acc_cancel(t, n, room) : n;
}

rast_status rast__cov_acc_points(const rast_polygon *poly, const uint32_t *skip, uint32_t nskip,
                                 const rast_point *tris, uint32_t ntris, int shared, int32_t s, rast_fill_rule rule,
                                 const rast__cov_out *o, rast__cedge *room, rast__arena *arena)
{
    rast__acc_thin *const t = (rast__acc_thin *)(void *)room;
    uint32_t n = 0, k, base, q = 0;
    if (tris) { /* (rast__cov_edges_triangles' edges) */
        for (k = 0; k < ntris; k++) {
            rast_point v[3];
            if (rast__cov_tri(&tris[3 * k], v)) n += rast__acc_thin_ring(v, 3, t + n);
        }
    } else {
        for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++)
            if (q < nskip && skip[q] == k)
                q++;
            else
                n += rast__acc_thin_ring(poly->points + base, poly->ring_sizes[k], t + n);
    }
    return rast__acc_go(t, shared ? rast__acc_cancel_some(t, n, shared, *arena) : n, s, rule, o, arena);
}
#else
#define rast__acc_thin_of(e, n) (e)
#endif

rast_status rast__cov_acc_shared(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                 const rast__cov_out *o, rast__arena *arena)
{
    rast__acc_in *const in = rast__acc_thin_of(e, n);
    return rast__acc_go(in, rast__acc_cancel(in, n, *arena), s, rule, o, arena);
}

rast_status rast__cov_acc(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                          const rast__cov_out *o, rast__arena *arena)
{
    return rast__acc_go(rast__acc_thin_of(e, n), n, s, rule, o, arena);
}

static rast_status rast__acc_go(rast__acc_in *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                const rast__cov_out *o, rast__arena *arena)
{
    int64_t c0, c1;
    if (n == 0) {
        rast__cov_zero_rows(o, o->clip.y0, o->clip.y1);
        return RAST_OK;
    }
    /* (an array: its rows are written whole either way, and the side
     * columns' fills cost more calls than they save: 4% more
     * instructions on the 64-gon circle) */
    if (!o->paint) return rast__acc_walk_all(e, n, s, rule, o, arena);
    rast__acc_cols_reached(e, n, (int32_t)1 << s, &c0, &c1);
    if (c0 <= o->clip.x0 && c1 >= o->clip.x1) return rast__acc_walk_all(e, n, s, rule, o, arena);
    c0 = c0 > o->clip.x0 ? c0 : o->clip.x0;
    c1 = c1 < o->clip.x1 ? c1 : o->clip.x1;
    if (c0 >= c1) { /* (all left or right of the clip: 0 everywhere) */
        rast__cov_zero_rows(o, o->clip.y0, o->clip.y1);
        return RAST_OK;
    }
    return rast__acc_narrow(e, n, s, rule, o, arena, (int32_t)c0, (int32_t)c1);
}

static rast_status rast__acc_narrow(rast__acc_in *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                    const rast__cov_out *o, rast__arena *arena, int32_t x0, int32_t x1)
{
    static const int32_t size[3] = {1, 2, 8};
    const int32_t sz = size[o->format];
    rast__cov_out sub = *o;
    rast_status st;
    int32_t j;
    sub.clip.x0 = x0;
    sub.clip.x1 = x1;
    if (!o->paint) sub.base = o->base + (ptrdiff_t)(x0 - o->clip.x0) * sz;
    st = rast__acc_walk_all(e, n, s, rule, &sub, arena);
    if (st != RAST_OK || o->paint) return st;
    for (j = o->clip.y0; j < o->clip.y1; j++) { /* (every row: the columns the walk left) */
        unsigned char *row = rast__cov_row(o, (int32_t)j);
        memset(row, 0, (size_t)(x0 - o->clip.x0) * (size_t)sz);
        memset(row + (ptrdiff_t)(x1 - o->clip.x0) * sz, 0, (size_t)(o->clip.x1 - x1) * (size_t)sz);
    }
    return RAST_OK;
}

#if RAST__ACC_COMPACT
/* (the walk's records go at the end of the edges' room, past its first
 * n rast__acc_thin, and leave room for as many rast__cedge before them
 * as they are: rast__acc_exact's) */
typedef char rast__acc_rooms[sizeof(rast__cedge) >= 2 * sizeof(rast__aedge) &&
                                     sizeof(rast__cedge) - sizeof(rast__aedge) >= sizeof(rast__acc_thin)
                                 ? 1
                                 : -1];

/* One pass over the edges t[0..n) (w->n, rast__acc_thin, 20 bytes each,
 * in a stream): the rows [ja, jb) the edges reach
 * (rast__cov_rows_reached); each edge's first row from ja, key[] (0 above
 * ja), plus the value returned (0, or ja when no key needs the clamp: its
 * readers take it off), its last row last[]; *nkeys the greatest key + 1
 * (from ja).  floor(y / P) by rast__acc_floorp's shift, S = s.  (The
 * records, their divisions, and the sum of the rows are
 * rast__acc_sorted's; order[] rast__acc_walk_all's, for a radix sort.) */
RAST__APART int32_t rast__acc_prep(rast__acc_walk *w, const rast__acc_thin *t, uint32_t *nkeys)
{
    const uint32_t n = w->n;
    const int32_t s = w->s;
    const int64_t bias = (int64_t)1 << (62 - s);
    int32_t *const key = w->key, *const last = w->last;
    int64_t ymin = t[0].yt, ymax = (int64_t)t[0].yt + t[0].dy, ytop = ymin, ja, kmin;
    uint32_t i, nk = 0;
    for (i = 0; i < n; i++) {
        const int64_t yt = t[i].yt, yb = yt + t[i].dy;
        const int32_t k = (int32_t)((int64_t)(((uint64_t)yt + ((uint64_t)1 << 62)) >> s) - bias);
        const int32_t l = (int32_t)(-((int64_t)(((uint64_t)-yb + ((uint64_t)1 << 62)) >> s) - bias) - 1);
        ymin = yt < ymin ? yt : ymin;
        ymax = yb > ymax ? yb : ymax;
        ytop = yt > ytop ? yt : ytop;
        key[i] = k;
        last[i] = l;
    }
    rast__cov_rows_reached(ymin, ymax, (int32_t)1 << s, w->o, &w->ja, &w->jb);
    ja = w->ja;
    kmin = (int64_t)(((uint64_t)ymin + ((uint64_t)1 << 62)) >> s) - bias; /* (the least key) */
    if (kmin >= ja) {
        /* No edge starts above row ja (the clip's top cuts no edge): no key
         * to clamp, the greatest the greatest top's; the keys are left
         * from row 0, and their reader takes ja off (returned:
         * rast__acc_sorted, which sums the rows too).  (A pass to take it
         * off here and sum the rows was 11 instructions an edge, ~0.35 M
         * of a line of text's.) */
        *nkeys = (uint32_t)((int64_t)(((uint64_t)ytop + ((uint64_t)1 << 62)) >> s) - bias - ja) + 1;
        return (int32_t)ja;
    }
    for (i = 0; i < n; i++) { /* (the keys from ja) */
        const int64_t r0 = (int64_t)key[i] - ja;
        const int32_t kk = r0 < 0 ? 0 : (int32_t)r0;
        key[i] = kk;
        nk = (uint32_t)kk >= nk ? (uint32_t)kk + 1 : nk;
    }
    *nkeys = nk;
    return 0;
}

/* The walk's record of the edge t, its steppers not set, nor their steps
 * (made when the steppers are first set: rast__acc_top_set, rast__acc_top1,
 * rast__acc_t_first). */
static inline void rast__acc_make(rast__aedge *c, const rast__acc_thin *t)
{
    const int32_t xt = t->xt, yt = t->yt, dx = t->dx, dy = t->dy, dir = t->dir;
    c->qx = c->qt = c->qxs = c->qts = 0;
    c->qxr = c->qtr = c->qtsr = 0;
    c->qxsr = RAST__ACC_UNMADE;
    c->xt = xt;
    c->yt = yt;
    c->dx = dx;
    c->dy = dy;
    c->qrow = c->qX = INT32_MIN;
    c->dir = dir;
    c->lazyX = 0;
}

/* The walk's records (rast__aedge, rast__acc_make's) of the edges t[]
 * (rast__acc_prep's, at the start of the edges' room e) in the rows'
 * order (by first row, stably), at the end of the room (past the first n
 * rast__aedge: no overlap with t[]); key[] and last[] put in that order
 * too (the walk's arrays swapped: no copy); order[] is left free (the
 * rows' walk reads the records in order, the bands' walk has 0 .. n - 1
 * put there: rast__acc_walk_all).  With counts (cnt[0..nkeys + d), room,
 * when the rows are few for the edges: see rast__acc_walk_all; the keys
 * key[] d more than the walk's, which it takes off as it puts them in
 * order), t[] is read in a stream and each record
 * written to its row's next slot, a counting sort's placing pass (the
 * records read through order[] at random, then written in order, took a
 * fifth of the paragraph's time, issue 34); else by w->order (a radix
 * sort's).  *rows: the edges' rows in all.  Returns the records; w->cap: how many rast__cedge the room
 * before them takes (rast__acc_exact's). */
static rast__aedge *rast__acc_sorted(rast__acc_walk *w, rast__cedge *e, const rast__acc_thin *t, uint32_t *cnt,
                                     uint32_t nkeys, int32_t d, uint64_t *rows)
{
    int64_t rs = 0; /* (the sum of last - key from ja, each edge's rows less one) */
    const uint32_t n = w->n;
    const size_t off = (size_t)n * (sizeof(rast__cedge) - sizeof(rast__aedge));
    rast__aedge *const ce = (rast__aedge *)(void *)((unsigned char *)(void *)e + off);
    int32_t *const order = w->order, *const key = w->key, *const last = w->last, *const ks = w->tmp;
    uint32_t i;
    (void)sizeof(rast__acc_rooms);
    if (cnt) {
        /* (the keys as rast__acc_prep left them, d more than the walk's:
         * d counts more, none of them used, where a pass over the edges
         * would take d off) */
        rast__cov_count_starts(cnt, key, n, nkeys + (uint32_t)d);
        for (i = 0; i < n; i++) { /* (order[] is free: the last rows go there) */
            const int32_t k = key[i];
            const uint32_t at = cnt[k]++;
            const int32_t l = last[i];
            rast__acc_make(&ce[at], &t[i]);
            ks[at] = k - d;
            order[at] = l;
            rs += (int64_t)l - k;
        }
    } else {
        for (i = 0; i < n; i++) {
            const int32_t k = order[i];
            rast__acc_make(&ce[i], &t[k]);
            ks[i] = key[k];
            order[i] = last[k];
            rs += (int64_t)last[k] - key[k];
        }
    }
    /* (the rows: last - (key - d + ja) + 1 an edge; d 0 without counts) */
    *rows = (uint64_t)(rs + (int64_t)n * ((int64_t)d - w->ja + 1));
    w->tmp = key;
    w->key = ks;
    w->order = last;
    w->last = order;
    w->cap = (uint32_t)(off / sizeof(rast__cedge));
    return ce;
}
#endif

static rast_status rast__acc_walk_all(rast__acc_in *in, uint32_t n, int32_t s, rast_fill_rule rule,
                                      const rast__cov_out *o, rast__arena *arena)
{
#if RAST__ACC_COMPACT
    rast__cedge *const e = (rast__cedge *)(void *)in; /* (the edges' room) */
#else
    rast__cedge *const e = in;
#endif
    rast__acc_walk w;
    rast__acc v[RAST__ACC_BAND];
    uint64_t *cells, *bandbits, rows = 0; /* (the edges' rows, in all) */
    uint32_t i, nkeys = 0; /* (the greatest key + 1) */
    int32_t r, k, band;
#if RAST__ACC_COMPACT
    int32_t d; /* (rast__acc_prep's: what its keys lack of ja) */
#endif
    int counted; /* (the order by counts of the rows, not a radix sort) */
    w.n = n;
    w.s = s;
#if RAST__ACC_COMPACT
    w.fat = e;
#endif
    w.rule = rule;
    w.o = o;
    w.width = o->clip.x1 - o->clip.x0;
    w.nw = (w.width + 63) / 64;
    w.m = o->format == RAST_COVERAGE_U8 ? 255 : 65535;
    /* the same blocks as rast__cov_area's (its scratch bound); the short
     * edges' walk has its cells acc[] (width + 1 words) in cover[] (width
     * pairs of words), which the exact row finds cleared as it leaves it */
    w.order = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.row = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.tmp = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.key = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.last = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.thru = (int32_t *)rast__take(arena, (size_t)n * sizeof(int32_t));
    w.exact = (unsigned char *)rast__take(arena, (size_t)n * sizeof(uint64_t));
    w.cover = (rast__i128 *)rast__take(arena, (size_t)w.width * sizeof(rast__i128));
    w.area = (rast__i128 *)rast__take(arena, (size_t)w.width * sizeof(rast__i128));
    w.bits = (uint64_t *)rast__take(arena, (size_t)w.nw * sizeof(uint64_t));
    /* the band's cells and bits (rast__cov_area_scratch counts them) */
    cells = (uint64_t *)rast__take(arena, (size_t)RAST__ACC_BAND * ((size_t)w.width + 1) * sizeof(uint64_t));
    bandbits = (uint64_t *)rast__take(arena, (size_t)RAST__ACC_BAND * (size_t)w.nw * sizeof(uint64_t));
    if ((n && (!w.order || !w.row || !w.tmp || !w.key || !w.last || !w.thru || !w.exact)) || !w.cover || !w.area ||
        !w.bits || !cells || !bandbits)
        return RAST_E_SCRATCH;
    /* (the dense rows' sums go to z[], in area[]: not read here but by the
     * exact rows, which find it cleared as the sums leave it) */
    rast__acc_init(&v[0], (uint64_t *)(void *)w.cover, w.bits, (uint32_t *)(void *)w.area, o, s, 0);
    if (n == 0) {
        rast__cov_zero_rows(o, o->clip.y0, o->clip.y1);
        return RAST_OK;
    }
#if RAST__ACC_COMPACT
    d = rast__acc_prep(&w, in, &nkeys);
#else
    rast__cov_rows(e, n, v[0].p, w.order, o, &w.ja, &w.jb, 1); /* (the exact steps when needed) */
    {
        /* the row where each starts, from ja; its last row.  (In locals:
         * the stores to key[] and last[] may alias any int32_t, and would
         * have every one of them read again an edge.)  floor(y / P) by
         * rast__acc_floorp's shift, S = s. */
        const int64_t ja = w.ja, bias = (int64_t)1 << (62 - s);
        int32_t *const key = w.key, *const last = w.last;
        for (i = 0; i < n; i++) {
            const int64_t yt = e[i].yt, yb = yt + e[i].dy;
            const int64_t r0 = (int64_t)(((uint64_t)yt + ((uint64_t)1 << 62)) >> s) - bias - ja;
            const int64_t l = -((int64_t)(((uint64_t)-yb + ((uint64_t)1 << 62)) >> s) - bias) - 1;
            const int32_t kk = r0 < 0 ? 0 : (int32_t)r0;
            key[i] = kk;
            last[i] = (int32_t)l;
            nkeys = (uint32_t)kk >= nkeys ? (uint32_t)kk + 1 : nkeys;
            rows += (uint64_t)(l - (kk + ja) + 1);
        }
    }
#endif
    /* By counts of the rows when the rows are few for the edges (a radix
     * sort takes two passes over the edges past 256 rows, and clears and
     * sums 256 counts a pass): the counts in cover[], free until the walk
     * (4 width of them), the same order either way (both stable). */
    counted = n >= 24 && nkeys < n + 512 && nkeys <= 4 * (uint32_t)w.width;
#if RAST__ACC_COMPACT
    if (!counted || nkeys + (uint32_t)d > 4 * (uint32_t)w.width) { /* (the keys from ja) */
        for (i = 0; i < n; i++) w.key[i] -= d;
        d = 0;
    }
    if (!counted) {
        for (i = 0; i < n; i++) w.order[i] = (int32_t)i;
        rast__cov_radix_sort(w.order, w.tmp, w.key, n);
    }
    w.e = rast__acc_sorted(&w, e, in, counted ? (uint32_t *)(void *)w.cover : NULL, nkeys, d, &rows);
#else
    if (counted)
        rast__cov_count_sort(w.order, (uint32_t *)(void *)w.cover, w.key, n, nkeys);
    else
        rast__cov_radix_sort(w.order, w.tmp, w.key, n);
    w.e = e;
#endif
    rast__cov_zero_rows(o, o->clip.y0, w.ja);
    /* Long edges (RAST__ACC_LONG rows each or more, on the mean) are walked
     * a band at a time, each edge's steppers in registers from row to row;
     * short ones row by row: over a band they would be walked a row or two
     * at a time, at a call and a setup each (the 64-gon circle and the
     * holed disc took 13% more time that way, at 1 row). */
    band = rows >= (uint64_t)RAST__ACC_LONG * n ? RAST__ACC_BAND : 1;
    if (band == 1) {
        for (k = 0; k < w.width; k++) w.cover[k] = w.area[k] = rast__i128_u64(0);
        for (k = 0; k < w.nw; k++) w.bits[k] = 0;
        rast__acc_by_rows(&w, &v[0]);
    } else {
        for (i = 0; i < n; i++) {
            w.thru[i] = rast__acc_thru(&w.e[i], &v[0]);
#if RAST__ACC_COMPACT
            w.order[i] = (int32_t)i; /* (the records' order: the rows' walk does without) */
#endif
        }
        for (k = 0; k < RAST__ACC_BAND * (w.width + 1); k++) cells[k] = 0;
        for (r = 0; r < RAST__ACC_BAND; r++) {
            uint64_t *b = bandbits + (size_t)r * (size_t)w.nw;
            for (k = 0; k < w.nw; k++) b[k] = 0;
            /* (row r's first cell: side by side with the others' or after them) */
            rast__acc_init(&v[r], cells + (RAST__ACC_SX == 1 ? (size_t)r * ((size_t)w.width + 1) : (size_t)r), b,
                           (uint32_t *)(void *)w.area, o, s, 0);
        }
#if RAST__ACC_COMPACT
        if (!rast__acc_by_piles(&w, v, rows))
#endif
            rast__acc_by_bands(&w, v);
    }
    rast__cov_zero_rows(o, w.jb, o->clip.y1);
    return RAST_OK;
}

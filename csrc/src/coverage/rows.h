/*
 * rows.h - the row machinery every coverage engine shares (rows.c): the
 * units of the area sweep, 128-bit helpers, the edges with their row and
 * column steppers, the rows the edges reach, and where a row's values go
 * (rast__cov_out: an array, or a painter handed each row's runs).  Below
 * the engines (cells.c, coverage_acc.c, coverage_area.c, coverage_ss.c,
 * coverage_plain.c), which call it and never each other upwards
 * (docs/architecture.md).  Not installed.
 *
 * Units of the area sweep.  Vertices are in fixed units of 1/P pixel,
 * P = 2^S.  Inside a pixel row j (the strip j <= y < j + 1 pixels), an
 * ordinate is t, in units U = 2^-G pixel from the row's top (0 <= t <= T =
 * 2^G); an abscissa is in units V = 2^-G pixel from x = 0, a signed 128-bit
 * integer (|x| < 2^88).  G = 60, so that a product of a fraction of a
 * pixel in V (< 2^61 for a sum of two) and a height in U (<= 2^60) fits
 * 128 bits.  Fixed units become U and V by a shift of H = G - S bits.
 */
#ifndef RAST_COV_ROWS_H
#define RAST_COV_ROWS_H

#include "../base/internal.h"
#include "../base/wide.h"

#define RAST__COV_G 60

/* ---- 128-bit helpers (on wide.h's two's-complement rast__i128) --------- */

#if !defined(__SIZEOF_INT128__) || defined(RAST_NO_INT128) /* (rast__cov_x_at's, cells.c, there) */
/* a * b for a >= 0 (the caller keeps it below 2^127) and b < 2^32. */
static inline rast__i128 rast__u128_mul32(rast__i128 a, uint32_t b)
{
    const uint64_t m = 0xFFFFFFFFu;
    uint64_t p0 = (a.lo & m) * b, p1 = (a.lo >> 32) * b + (p0 >> 32);
    rast__i128 r;
    r.lo = (p0 & m) | (p1 << 32);
    r.hi = a.hi * b + (p1 >> 32);
    return r;
}
#endif

/* floor(a / d) for a >= 0 and 0 < d < 2^32; *rem = a mod d.  Four 64-bit
 * divisions of 32-bit limbs (no 128-bit divide: firmware has none). */
static inline rast__i128 rast__u128_div32(rast__i128 a, uint32_t d, uint32_t *rem)
{
    const uint64_t m = 0xFFFFFFFFu;
    uint64_t limb[4], q[4], r = 0;
    int k;
    rast__i128 out;
    limb[0] = a.hi >> 32;
    limb[1] = a.hi & m;
    limb[2] = a.lo >> 32;
    limb[3] = a.lo & m;
    for (k = 0; k < 4; k++) {
        uint64_t cur = (r << 32) | limb[k];
        q[k] = cur / d;
        r = cur % d;
    }
    out.hi = (q[0] << 32) | q[1];
    out.lo = (q[2] << 32) | q[3];
    *rem = (uint32_t)r;
    return out;
}

static inline rast__i128 rast__i128_u64(uint64_t v)
{
    rast__i128 r;
    r.hi = 0;
    r.lo = v;
    return r;
}

/* ---- edges -------------------------------------------------------------- */

/* A non-horizontal edge, top end first (dy > 0), fixed units; `dir` the
 * direction of the original edge (+1 down).  The sweep caches the edge's
 * abscissa at the ordinate t it is at (x, r: the exact abscissa is
 * x + r/dy in V units, 0 <= r < dy) and at the end of the current piece
 * (xn, rn). */
typedef struct rast__cedge {
    /* what every row reads, together (the first three cache lines) */
    rast__i128 x, xn;
    int64_t r, rn;
    uint64_t tx;  /* the t of x, r in row `rowx` */
    int32_t rowx; /* see tx; INT32_MIN: not cached */
    int32_t xt, yt, dx, dy, dir;
    /* RAST__HZ_TOP, RAST__HZ_BOTTOM: that end is also an end of a
     * horizontal (or empty) edge of its ring; RAST__HZ_RUN: the ring's
     * horizontal edges right after this edge (its original end) span the
     * abscissae [hx0, hx1] (simple rows, coverage_acc.c) */
    int32_t hz, hx0, hx1;
    /* the quick column stepper (coverage_area.c, 2^-30 pixel units): at
     * vertical qX, t from the top = qt + qtr/|dx|; per column qts + qtsr/|dx| */
    int64_t qt, qX, qts;
    uint32_t qtr, qtsr;
    /* the quick row stepper (coverage_area.c, 2^-30 pixel units): the
     * exact abscissa at the top of row qrow is qx + qxr/dy; it grows by
     * qxs + qxsr/dy from a row's top to the next */
    int64_t qx, qxs;
    uint32_t qxr, qxsr;
    int32_t qrow; /* INT32_MIN: not set */
    /* a fast row's part, quick units: from qa + qar/dy at ordinate qta to
     * qb + qbr/dy at qtb (2^-30 pixel from the row's top); its abscissae
     * in [qlo, qhi) */
    int64_t qa, qb, qlo, qhi;
    uint64_t qta, qtb;
    uint32_t qar, qbr;
    rast__i128 xs; /* x grows by xs + xsr/dy from a row's top to the next */
    int64_t xsr;
    /* the column stepper (cells) */
    rast__i128 ts; /* t grows by ts + tsr/|dx| from a column to the next */
    rast__i128 ct; /* the column stepper left at vertical cX: t (U from the
                      top) = ct + crem/|dx|; see coverage_area.c */
    int64_t cX;
    uint32_t crem, tsr;
    /* the sweep's */
    rast__i128 xT; /* the edge's line at the bottom of the row (xT + rT/dy) */
    int64_t rT;
    int32_t sg;    /* the sign of its current piece (+1 enters, -1 leaves the inside, 0 neither) */
    int32_t cn, crow;
    int32_t pos;    /* its slot in the sweep's order when last put there (a hint,
                     * coverage_area.c's rast__cov_find; in the padding before ctime) */
    uint64_t ctime; /* its crossing time with edge cn in row crow (a cache) */
} rast__cedge;

#define RAST__HZ_TOP 1
#define RAST__HZ_BOTTOM 2
#define RAST__HZ_RUN 4

/* The ordinate of the run after e (RAST__HZ_RUN): that of e's original end. */
static inline int32_t rast__run_y(const rast__cedge *e)
{
    return e->dir > 0 ? e->yt + e->dy : e->yt;
}

/* The edge from vertex a to vertex b (a.y != b.y), top end first: from
 * (*xt, *yt) by (*dx, *dy > 0); returns its direction, +1 when a is its
 * top (rast__cov_edges_polygon's, and "accumulate"'s own records,
 * coverage_acc.c). */
static inline int32_t rast__cov_edge_of(rast_point a, rast_point b, int32_t *xt, int32_t *yt, int32_t *dx,
                                        int32_t *dy)
{
    const int down = a.y < b.y;
    const rast_point ta = down ? a : b, tb = down ? b : a;
    *xt = ta.x;
    *yt = ta.y;
    *dx = tb.x - ta.x;
    *dy = tb.y - ta.y;
    return down ? 1 : -1;
}

/* The edges of a polygon's rings (rule: the caller's) or of a triangle
 * batch (each triangle turned to one orientation, so that the non-zero
 * rule gives the union) into e[] (room for every vertex); returns how many
 * are not horizontal. */
uint32_t rast__cov_edges_polygon(const rast_polygon *poly, rast__cedge *e);
uint32_t rast__cov_edges_triangles(const rast_point *tris, uint32_t ntris, rast__cedge *e);

void rast__cov_qtop_set(rast__cedge *e, int32_t j, int32_t p, int32_t hq);
/* The quick row step of the edge by (dx, dy > 0): dx 2^30 / dy (|dx| <=
 * 2^28), floored, *qxs + *qxsr/dy. */
static inline void rast__cov_qxstep(int32_t dx, int32_t dy, int64_t *qxs, uint32_t *qxsr)
{
    int64_t qq, rr;
    rast__floordivmod((int64_t)dx * ((int64_t)1 << 30), dy, &qq, &rr);
    *qxs = qq;
    *qxsr = (uint32_t)rr;
}

/* The quick column step of the edge by (dx, dy > 0): dy 2^30 / |dx| (by
 * one division; 0 for a vertical edge), *qts + *qtsr/|dx|. */
static inline void rast__cov_qtstep(int32_t dx, int32_t dy, int64_t *qts, uint32_t *qtsr)
{
    const uint64_t adx = (uint64_t)(dx < 0 ? -(int64_t)dx : dx);
    const uint64_t a = (uint64_t)dy << 30;
    *qts = (int64_t)(adx ? a / adx : 0);
    *qtsr = (uint32_t)(adx ? a % adx : 0);
}

/* Both quick steps of the edge by (dx, dy > 0): rast__cov_qtstep's per
 * column, rast__cov_qxstep's per row (rast__cov_rows' quick way). */
static inline void rast__cov_qsteps(int32_t dx, int32_t dy, int64_t *qts, uint32_t *qtsr, int64_t *qxs,
                                    uint32_t *qxsr)
{
    rast__cov_qtstep(dx, dy, qts, qtsr);
    rast__cov_qxstep(dx, dy, qxs, qxsr);
}
/* The quick row stepper's step from a row's top to the next: qx + qxr/dy
 * grows by qxs + qxsr/dy (the fields of any record that has them: the
 * edges here, "accumulate"'s compact ones, coverage_acc.c). */
static inline void rast__cov_qstep(int64_t *qx, uint32_t *qxr, int64_t qxs, uint32_t qxsr, int32_t dy)
{
    *qx += qxs;
    *qxr += qxsr;
    if (*qxr >= (uint32_t)dy) {
        *qxr -= (uint32_t)dy;
        ++*qx;
    }
}

/* The quick steppers (units Q = 2^-30 pixel; HQ = 30 - S, P = 2^S).  e's
 * exact abscissa at the top of row j (which e spans: yt <= j P < yt + dy)
 * is qx + qxr/dy: stepped from the row above by qxs + qxsr/dy, else set
 * by rast__cov_qtop_set (out of line: once an edge), in one division at
 * the edge's first row top (dx (jP - yt) 2^HQ <= 2^58), two elsewhere
 * (dx (jP - yt) < 2^56; the remainder times 2^HQ < 2^58): rast__cov_qx_at. */
static inline int64_t rast__cov_qtop(rast__cedge *e, int32_t j, int32_t p, int32_t hq)
{
    if (e->qrow == j - 1) {
        rast__cov_qstep(&e->qx, &e->qxr, e->qxs, e->qxsr, e->dy);
        e->qrow = j;
    } else if (e->qrow != j) {
        rast__cov_qtop_set(e, j, p, hq); /* (once an edge, out of line) */
    }
    return e->qx;
}

/* The edge from (xt, yt) by (dx, dy > 0): its abscissa at the top of row
 * j, floor(xt 2^HQ + dx (j P - yt) 2^HQ / dy) into *qx, the remainder
 * (over dy) into *qxr (rast__cov_qtop_set's). */
static inline void rast__cov_qx_at(int32_t xt, int32_t yt, int32_t dx, int32_t dy, int32_t j, int32_t p,
                                   int32_t hq, int64_t *qx, uint32_t *qxr)
{
    const int64_t d = (int64_t)j * p - yt;
    int64_t q, r, q2, r2;
    if (d >= 0 && d <= p) { /* (an edge's first row top: |dx d 2^HQ| <= 2^58, one division) */
        rast__floordivmod((int64_t)dx * d * ((int64_t)1 << hq), dy, &q2, &r2);
        *qx = (int64_t)xt * ((int64_t)1 << hq) + q2;
    } else {
        rast__floordivmod((int64_t)dx * d, dy, &q, &r);
        rast__floordivmod(r * ((int64_t)1 << hq), dy, &q2, &r2);
        *qx = ((int64_t)xt + q) * ((int64_t)1 << hq) + q2;
    }
    *qxr = (uint32_t)r2;
}

/* The column stepper of the edge from (xt, .) by (dx, dy) at vertical X
 * (which its x range reaches: |X P - xt| <= |dx|): t = floor(|X P - xt|
 * dy 2^HQ / |dx|) from its top, *qt + *qtr/|dx|, in two 64-bit divisions
 * (|X P - xt| dy < 2^56, the remainder times 2^HQ < 2^58), or one when
 * |X P - xt| <= P (the product times 2^HQ <= 2^58). */
static inline void rast__cov_qt_at(int32_t xt, int32_t dx, int32_t dy, int64_t X, int32_t p, int32_t hq,
                                   int64_t *qt, uint32_t *qtr)
{
    uint64_t adx = (uint64_t)(dx < 0 ? -(int64_t)dx : dx);
    int64_t w = X * p - xt;
    uint64_t m = (uint64_t)(w < 0 ? -w : w) * (uint64_t)dy, r;
    if (w >= -p && w <= p) { /* (the first vertical: m 2^HQ <= 2^58, one division) */
        *qt = (int64_t)((m << hq) / adx);
        *qtr = (uint32_t)((m << hq) % adx);
    } else {
        r = (m % adx) << hq;
        *qt = (int64_t)(((m / adx) << hq) + r / adx);
        *qtr = (uint32_t)(r % adx);
    }
}

/* e's column stepper at vertical X: rast__cov_qt_at, qX = X. */
static inline void rast__cov_qt_first(rast__cedge *e, int64_t X, int32_t p, int32_t hq)
{
    rast__cov_qt_at(e->xt, e->dx, e->dy, X, p, hq, &e->qt, &e->qtr);
    e->qX = X;
}

/* ---- where the values go ----------------------------------------------- */

typedef struct rast__cov_out {
    unsigned char *base; /* pixel (clip.x0, clip.y0) */
    ptrdiff_t stride;
    rast_coverage_format format;
    rast_rect clip;
    /* a painter (rast__cov_paint: the span entry points, the anti-aliased
     * fills): base is one row of U8 levels (stride 0), handed on by
     * rast__cov_row_done as levels runs; NULL for an array */
    const rast__painter *paint;
} rast__cov_out;

/* A stretch of level 255 at least this long goes to a painter's full
 * entry (a fill: a memset for one-byte pixels) instead of its levels
 * entry (a blend per pixel); shorter ones stay in their levels run, where
 * a blend of a few pixels costs less than another call.  The pixels are
 * the same either way: a blend at 255 writes what a fill writes.  (Here
 * for coverage_small.c too, which hands a row of fewer straight on.) */
#define RAST__COV_FULL_MIN 16

/* Row y is complete: hand its runs of values not 0 to the painter, if
 * there is one: to its levels entry, except that a stretch of 255 at
 * least RAST__COV_FULL_MIN long goes to its full entry when it has one
 * (the same pixels: a blend at 255 writes what a fill writes). */
void rast__cov_row_done(const rast__cov_out *o, int32_t y);

/* The value stored for coverage a62 / 2^62 (0 <= a62 <= 2^62): a62 itself
 * (FIX62), or floor((a62 M + 2^61) / 2^62), in 128 bits (a62 M < 2^78). */
static inline uint64_t rast__cov_level(rast_coverage_format f, uint64_t a62)
{
    rast__i128 p;
    if (f == RAST_COVERAGE_FIX62) return a62;
    p = rast__i128_mul((int64_t)a62, f == RAST_COVERAGE_U8 ? 255 : 65535);
    p = rast__i128_add(p, rast__i128_u64((uint64_t)1 << 61));
    return rast__i128_sar(p, 62).lo;
}

/* Column k of a clip row gets value v (rast__cov_level's). */
static inline void rast__cov_store(rast_coverage_format f, unsigned char *row, int32_t k,
                                   uint64_t v)
{
    if (f == RAST_COVERAGE_U8)
        row[k] = (unsigned char)v;
    else if (f == RAST_COVERAGE_U16)
        ((uint16_t *)(void *)row)[k] = (uint16_t)v;
    else
        ((uint64_t *)(void *)row)[k] = v;
}

/* Columns [k0, k1) of a clip row get value v: a memset for uint8 (byte
 * stores for a run of 8 or fewer, shorter than the call). */
static inline void rast__cov_fill(rast_coverage_format f, unsigned char *row, int32_t k0, int32_t k1,
                                  uint64_t v)
{
    if (f == RAST_COVERAGE_U8 && k1 - k0 > 8)
        memset(row + k0, (int)v, (size_t)(k1 - k0));
    else
        for (; k0 < k1; k0++) rast__cov_store(f, row, k0, v);
}

static inline unsigned char *rast__cov_row(const rast__cov_out *o, int32_t y)
{
    return o->base + (ptrdiff_t)(y - o->clip.y0) * o->stride;
}

/* Every pixel of rows [y0, y1) of the clip gets 0. */
void rast__cov_zero_rows(const rast__cov_out *o, int32_t y0, int32_t y1);

/* ---- the rows the edges reach (rows.c) ---------------------------------- */

/* Triangle t[0..2] with its vertices in the order that makes its signed
 * area positive into v[0..2]; 0 when it is degenerate (its edges would
 * cancel). */
int rast__cov_tri(const rast_point *t, rast_point *v);
/* Stable radix sort (8 bits a pass, as many passes as the largest key
 * needs; an insertion sort for a few) of the indices ix[0..n) by
 * key[ix[i]], each key's bits read as unsigned; tmp[0..n) is room.  The
 * result is in ix. */
void rast__cov_radix_sort(int32_t *ix, int32_t *tmp, const int32_t *key, uint32_t n);
/* cnt[k] = how many of key[0..n) are below k, for k in [0, nkeys): where
 * a counting sort's placing pass puts the first key k (cnt: nkeys counts
 * of room, not cleared). */
static inline void rast__cov_count_starts(uint32_t *cnt, const int32_t *key, uint32_t n, uint32_t nkeys)
{
    uint32_t i, sum = 0;
    for (i = 0; i < nkeys; i++) cnt[i] = 0;
    for (i = 0; i < n; i++) cnt[key[i]]++;
    for (i = 0; i < nkeys; i++) {
        const uint32_t c = cnt[i];
        cnt[i] = sum;
        sum += c;
    }
}
/* ix[0..n) = 0 .. n - 1 ordered by key[i] in [0, nkeys), stably (what
 * rast__cov_radix_sort makes of ix[i] = i): one counting pass, one pass
 * over the nkeys counts cnt[0..nkeys) (room, not cleared), one placing
 * pass; for keys that are rows, where there are far fewer than edges. */
void rast__cov_count_sort(int32_t *ix, uint32_t *cnt, const int32_t *key, uint32_t n, uint32_t nkeys);
/* Each edge's steps set (when quick, those of the quick way only: then
 * rast__cov_exact_steps before an exact row), order[i] = i, and the rows
 * [*ja, *jb) of the clip the edges' strips reach (n > 0). */
void rast__cov_rows(rast__cedge *e, uint32_t n, int32_t p, int32_t *order, const rast__cov_out *o,
                    int32_t *ja, int32_t *jb, int quick);
/* The rows [*ja, *jb) of the clip of o that the strips of ordinates
 * [ymin, ymax] reach (rast__cov_rows'). */
void rast__cov_rows_reached(int64_t ymin, int64_t ymax, int32_t p, const rast__cov_out *o, int32_t *ja,
                            int32_t *jb);
void rast__cov_exact_steps(rast__cedge *e, uint32_t n);
/* The exact steps of the edges e[ix[k]], k < n, whose done[] is 0 (then
 * 1): an exact row's edges, not every edge of the call. */
void rast__cov_exact_steps_of(rast__cedge *e, const int32_t *ix, int32_t n, unsigned char *done);

#endif /* RAST_COV_ROWS_H */

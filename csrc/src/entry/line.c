/*
 * line.c - lines, polylines and outlines (seed 002), and the list of a
 * line's pixels.
 *
 * The pixels a line owns are defined in rastrum.h ("lines").  In internal
 * units (coordinates doubled, one pixel = U = 2^(S+1), sample offset O, see
 * internal.h) and along the line's major axis (x when |dx| >= |dy|, else y),
 * walking from a towards b:
 *
 *   major pixel  p_k = p_0 + sm*k,  k = 0, 1, ..., n-1   (sm = +-1)
 *   minor pixel  q_k = floor((N_0 + k*D) / Q),           Q > 0, |D| <= Q
 *
 * Bresenham (exact): with adx = |major difference| (1 if it is 0) and
 * u_0 = (p_0*U + O - a_major)*sm the distance from a to the first sample,
 *   Q = U*adx,  D = U*dmin,  N_0 = (a_minor - O + U/2)*adx + u_0*dmin,
 * which is floor(y(p + o) - o + 1/2) of the header, written over one
 * denominator.  The loop keeps e = (N_0 + k*D) mod Q and only adds and
 * compares (at most one carry per step since |D| <= Q).
 *
 * DDA (the textbook's, made integer): the minor coordinate is a fixed-point
 * number y with 16 fraction bits of a pixel.  It starts at the exact value
 * of the line at the first sample rounded to 1/2^16 (half up), the slope
 * m = dmin/dmaj is rounded to 1/2^16 (half up), and every step does
 * y += m; the pixel is floor(y - o + 1/2) taken on that rounded y (the
 * textbook's round(y)).  That is the same form with
 *   Q = 2^16,  D = m,  N_0 = y_0 - o*2^16 + 2^15.
 * Only the slope's rounding makes it differ from the exact line: after k
 * steps y is off by at most (k + 1)/2^17 pixel, so a line shorter than
 * 2^16 steps is never more than one pixel away from the exact one.
 *
 * Clipping is exact and never walks off-clip steps: the steps whose major
 * pixel is inside the clip are an interval of k, and since q_k is monotonic
 * so are the steps whose minor pixel is; both are found by division, and the
 * walk starts at the first step inside.  A line a million pixels long
 * crossing a small target costs what its visible part costs.
 *
 * Bounds (|input| <= 2^27 - 1, so |internal| < 2^28, differences < 2^29,
 * U <= 2^17) are written beside every product below.
 */
#include "../painters/paint.h"

/* A line set up for walking: the steps [0, n) that are inside the clip,
 * renumbered so that step 0 is the first pixel drawn. */
typedef struct rast__lwalk {
    int64_t p;     /* major pixel of the current step */
    int64_t q;     /* minor pixel of the current step */
    int64_t e;     /* Bresenham: the error term, in [0, qden) */
    int64_t d;     /* Bresenham: |D|, in [0, qden]; DDA: m */
    int64_t qden;  /* Bresenham: Q */
    int64_t y;     /* DDA: N_0 + k*m (y with 16 fraction bits, shifted) */
    int64_t n;     /* steps inside the clip */
    int32_t sm;    /* major step: +1 or -1 */
    int32_t dq;    /* Bresenham: minor step on a carry, +1 or -1 */
    int32_t ymajor;
    int32_t dda;
} rast__lwalk;

#define RAST__DDA_BITS 16
/* Makes a DDA value non-negative before a shift: |y| < 2^44 (pixels below
 * 2^27 + 3, times 2^16), so y + 2^45 > 0 and floor(y / 2^16) is a shift of
 * an unsigned number, well defined in C99 whatever the sign of y. */
#define RAST__DDA_BIAS ((int64_t)1 << 45)

static int64_t rast__dda_pixel(int64_t y)
{
    return (int64_t)((uint64_t)(y + RAST__DDA_BIAS) >> RAST__DDA_BITS) -
           (RAST__DDA_BIAS >> RAST__DDA_BITS);
}

static int64_t rast__min64(int64_t a, int64_t b) { return a < b ? a : b; }
static int64_t rast__max64(int64_t a, int64_t b) { return a > b ? a : b; }

/* Set up the walk of a -> b inside the pixel rectangle clip (any int32
 * coordinates; empty if x1 <= x0 or y1 <= y0).  w->n = 0 when no pixel of
 * the line is inside.  a and b must be in range; g from rast__grid_init. */
static void rast__lwalk_init(rast__lwalk *w, rast_point a, rast_point b, const rast__grid *g,
                             int dda, const rast_rect *clip)
{
    const int64_t U = g->unit, O = g->off;
    int64_t amaj, amin, bmaj, bmin, dmaj, dmin, adx, lo, hi, p0, n, u0;
    int64_t n0, dn, qd, kb, ke, m0, m1, c0, c1, qa, qb;
    int32_t sm;

    w->n = 0;
    w->dda = dda;
    {   /* Doubled: |.| <= 2^28 - 2; differences <= 2^29 - 4. */
        int64_t ax = 2 * (int64_t)a.x, ay = 2 * (int64_t)a.y;
        int64_t bx = 2 * (int64_t)b.x, by = 2 * (int64_t)b.y;
        int64_t adxx = bx > ax ? bx - ax : ax - bx, adyy = by > ay ? by - ay : ay - by;
        w->ymajor = adyy > adxx;
        if (w->ymajor) {
            amaj = ay; amin = ax; bmaj = by; bmin = bx;
            m0 = clip->y0; m1 = clip->y1; c0 = clip->x0; c1 = clip->x1;
        } else {
            amaj = ax; amin = ay; bmaj = bx; bmin = by;
            m0 = clip->x0; m1 = clip->x1; c0 = clip->y0; c1 = clip->y1;
        }
    }
    if (m0 >= m1 || c0 >= c1) return;
    dmaj = bmaj - amaj;
    dmin = bmin - amin;
    sm = dmaj >= 0 ? 1 : -1;
    adx = dmaj >= 0 ? dmaj : -dmaj;

    /* The major pixels whose sample lies on the segment: lo..hi
     * (|lo|, |hi| <= 2^27 + 1). */
    lo = rast__ceildiv(rast__min64(amaj, bmaj) - O, U);
    hi = rast__floordiv(rast__max64(amaj, bmaj) - O, U);
    if (lo > hi) return;
    n = hi - lo + 1;
    p0 = sm > 0 ? lo : hi;
    u0 = (p0 * U + O - amaj) * sm; /* 0 <= u0 <= adx < 2^29 */
    if (adx == 0) adx = 1;         /* a = b: dmin = 0 too, q = floor((a - O + U/2) / U) */

    if (!dda) {
        qd = U * adx;                             /* < 2^17 * 2^29 = 2^46 */
        dn = U * dmin;                            /* |dn| <= qd */
        n0 = (amin - O + U / 2) * adx + u0 * dmin; /* < 2^29 * 2^29 + 2^29 * 2^29 = 2^59 */
    } else {
        /* y_0 = the line's minor coordinate at the first sample, in pixels
         * with 16 fraction bits, rounded half up:
         * 2^16 * (amin*adx + u0*dmin) / (U*adx), through quotient and
         * remainder so that nothing exceeds 2^62. */
        int64_t t = amin * adx + u0 * dmin; /* < 2^28 * 2^29 + 2^29 * 2^29 < 2^59 */
        int64_t qq = U * adx;               /* < 2^46, even */
        int64_t f = rast__floordiv(t, qq);  /* the pixel part, |f| <= 2^27 + 1 */
        int64_t r = t - f * qq;             /* [0, qq) */
        int64_t y0 = f * ((int64_t)1 << RAST__DDA_BITS) +
                     rast__floordiv(r * ((int64_t)1 << RAST__DDA_BITS) + qq / 2, qq); /* r*2^16 < 2^62 */
        /* m = round(2^16 * dmin / adx) half up: |dmin| * 2^17 < 2^46; |m| <= 2^16 */
        int64_t m = rast__floordiv(dmin * ((int64_t)2 << RAST__DDA_BITS) + adx, 2 * adx);
        int64_t o16 = O ? (int64_t)1 << (RAST__DDA_BITS - 1) : 0;
        qd = (int64_t)1 << RAST__DDA_BITS;
        dn = m;
        n0 = y0 - o16 + ((int64_t)1 << (RAST__DDA_BITS - 1)); /* |n0| < 2^44 */
    }
    /* From here q_k = floor((n0 + k*dn) / qd) for both algorithms, with
     * |k*dn| <= (adx/U + 1) * U*|dmin| < (2^29 + 2^17) * 2^29 < 2^59
     * (Bresenham) or 2^29 * 2^16 (DDA). */

    /* Steps whose major pixel p0 + sm*k is in [m0, m1). */
    if (sm > 0) {
        kb = m0 - p0;
        ke = m1 - p0;
    } else {
        kb = p0 - m1 + 1;
        ke = p0 - m0 + 1;
    }
    kb = rast__max64(kb, 0);
    ke = rast__min64(ke, n);
    if (kb >= ke) return;

    /* Steps whose minor pixel is in [c0, c1).  q_k is monotonic, so first
     * cut [c0, c1) to the pixels the line has between kb and ke - 1: that
     * keeps |c| <= 2^27 + 2 and every c*qd below 2^58 (|c*U| < 2^28 + 2^19,
     * times adx < 2^29; DDA: 2^28 * 2^16). */
    qa = rast__floordiv(n0 + kb * dn, qd);
    qb = rast__floordiv(n0 + (ke - 1) * dn, qd);
    c0 = rast__max64(c0, rast__min64(qa, qb));
    c1 = rast__min64(c1, rast__max64(qa, qb) + 1);
    if (c0 >= c1) return;
    if (dn > 0) { /* q grows: q_k >= c  <=>  n0 + k*dn >= c*qd */
        kb = rast__max64(kb, rast__ceildiv(c0 * qd - n0, dn));
        ke = rast__min64(ke, rast__ceildiv(c1 * qd - n0, dn));
    } else if (dn < 0) { /* q shrinks: q_k >= c  <=>  k <= (n0 - c*qd) / |dn| */
        kb = rast__max64(kb, rast__floordiv(n0 - c1 * qd, -dn) + 1);
        ke = rast__min64(ke, rast__floordiv(n0 - c0 * qd, -dn) + 1);
    } /* dn == 0: q is constant and inside [c0, c1) after the cut */
    if (kb >= ke) return;

    /* Start at step kb. */
    w->n = ke - kb;
    w->sm = sm;
    w->p = p0 + sm * kb;
    if (!dda) {
        int64_t nk = n0 + kb * dn;
        w->q = rast__floordiv(nk, qd);
        w->e = nk - w->q * qd; /* [0, qd) */
        w->qden = qd;
        if (dn >= 0) {
            w->d = dn;
            w->dq = 1;
        } else { /* count the error from the other end: e' = qd - 1 - e */
            w->d = -dn;
            w->dq = -1;
            w->e = qd - 1 - w->e;
        }
    } else {
        w->y = n0 + kb * dn;
        w->d = dn;
        w->q = rast__dda_pixel(w->y);
    }
}

/* Advance to the next step: add and compare only. */
static inline void rast__lwalk_next(rast__lwalk *w)
{
    w->p += w->sm;
    if (w->dda) {
        w->y += w->d;
        w->q = rast__dda_pixel(w->y);
    } else {
        w->e += w->d;
        if (w->e >= w->qden) {
            w->e -= w->qden;
            w->q += w->dq;
        }
    }
}

/* The DDA walk, when the options ask for it and the build keeps it (the
 * check refused it otherwise): a constant 0 when left out, so that its
 * code goes. */
#define RAST__LINE_DDA(o) \
    (RAST__HAS(RAST_CONFIG_LINE_ALGORITHMS, RAST_LINE_DDA) && (o)->algorithm == RAST_LINE_DDA)

static rast_status rast__line_check(const rast_line_opts *opts, rast__grid *g)
{
    if (!opts) return RAST_E_NULL;
    if ((unsigned)opts->algorithm >= RAST_LINE_COUNT_ ||
        !RAST__HAS(RAST_CONFIG_LINE_ALGORITHMS, opts->algorithm))
        return RAST_E_ALGORITHM;
    return rast__grid_init(g, opts->subpixel_bits, opts->sample, RAST_ROUND_EXACT,
                           RAST_BOUNDARY_EXACT);
}

static int rast__in_range(rast_point p)
{
    return p.x >= -RAST_COORD_MAX && p.x <= RAST_COORD_MAX && p.y >= -RAST_COORD_MAX &&
           p.y <= RAST_COORD_MAX;
}

/* Hand the line's pixels inside clip to a painter, one span per run of
 * pixels in a row (x-major lines) or per pixel (y-major ones). */
static void rast__line_paint(rast_point a, rast_point b, const rast__grid *g, int dda,
                             const rast_rect *clip, const rast__painter *p)
{
    const rast__row_fn fn = p->full;
    void *const user = p->user;
    rast__lwalk w;
    int64_t k, row, left, right;
    int32_t xs[2];

    rast__lwalk_init(&w, a, b, g, dda, clip);
    if (w.n == 0) return;
    if (w.ymajor) {
        for (k = 0;; k++) {
            xs[0] = (int32_t)w.q;
            xs[1] = (int32_t)w.q + 1;
            fn(user, (int32_t)w.p, xs, 1);
            if (k + 1 == w.n) break;
            rast__lwalk_next(&w);
        }
        return;
    }
    row = w.q;
    left = right = w.p;
    for (k = 1; k < w.n; k++) {
        rast__lwalk_next(&w);
        if (w.q != row) {
            xs[0] = (int32_t)left;
            xs[1] = (int32_t)right + 1;
            fn(user, (int32_t)row, xs, 1);
            row = w.q;
            left = right = w.p;
        } else if (w.p < left) {
            left = w.p;
        } else {
            right = w.p;
        }
    }
    xs[0] = (int32_t)left;
    xs[1] = (int32_t)right + 1;
    fn(user, (int32_t)row, xs, 1);
}

/* Check the options, the target and the pixel; set up the painter. */
static rast_status rast__line_begin(const rast_target *target, const rast_line_opts *opts,
                                    const void *pixel, rast__grid *g, rast_rect *clip,
                                    rast__solid *solid, rast__painter *p)
{
    rast_status st = rast__line_check(opts, g);
    if (st != RAST_OK) return st;
    st = rast__target_check(target, clip);
    if (st != RAST_OK) return st;
    return rast__solid_init(solid, target, clip, pixel, NULL, p);
}

rast_status rast_draw_line(const rast_target *target, rast_point a, rast_point b,
                           const rast_line_opts *opts, const void *pixel)
{
    rast__grid g;
    rast_rect clip;
    rast__solid solid;
    rast__painter p;
    rast_status st = rast__line_begin(target, opts, pixel, &g, &clip, &solid, &p);
    if (st != RAST_OK) return st;
    if (!rast__in_range(a) || !rast__in_range(b)) return RAST_E_RANGE;
    rast__line_paint(a, b, &g, RAST__LINE_DDA(opts), &clip, &p);
    return RAST_OK;
}

/* Check the points, then hand every segment's pixels inside clip to
 * painter p (the options are checked). */
static rast_status rast__polyline(const rast_point *points, uint32_t npoints, int closed,
                                  const rast__grid *g, const rast_line_opts *opts,
                                  const rast_rect *clip, const rast__painter *p)
{
    uint32_t k;
    int dda = RAST__LINE_DDA(opts);
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    if (npoints > 0 && !points) return RAST_E_NULL;
    for (k = 0; k < npoints; k++)
        if (!rast__in_range(points[k])) return RAST_E_RANGE;
    for (k = 0; k + 1 < npoints; k++)
        rast__line_paint(points[k], points[k + 1], g, dda, clip, p);
    if (closed && npoints > 0)
        rast__line_paint(points[npoints - 1], points[0], g, dda, clip, p);
    return RAST_OK;
}

rast_status rast_draw_polyline(const rast_target *target, const rast_point *points,
                               uint32_t npoints, int closed, const rast_line_opts *opts,
                               const void *pixel)
{
    rast__grid g;
    rast_rect clip;
    rast__solid solid;
    rast__painter p;
    rast_status st = rast__line_begin(target, opts, pixel, &g, &clip, &solid, &p);
    if (st != RAST_OK) return st;
    return rast__polyline(points, npoints, closed, &g, opts, &clip, &p);
}

rast_status rast_draw_polyline_spans(const rast_point *points, uint32_t npoints, int closed,
                                     const rast_line_opts *opts, const rast_rect *clip,
                                     rast_span_fn span, void *user)
{
    rast__grid g;
    rast__user_spans u;
    rast__painter p;
    rast_rect c;
    rast_status st = rast__line_check(opts, &g);
    if (st != RAST_OK) return st;
    if (!clip || !span) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    rast__user_painter(&u, span, NULL, user, &p);
    return rast__polyline(points, npoints, closed, &g, opts, &c, &p);
}

rast_status rast_line_pixels(rast_point a, rast_point b, const rast_line_opts *opts,
                             const rast_rect *clip, int32_t *xy, size_t capacity, size_t *count)
{
    rast__grid g;
    rast__lwalk w;
    rast_rect c;
    int64_t k;
    rast_status st = rast__line_check(opts, &g);
    if (st != RAST_OK) return st;
    if (!clip || !count || (capacity > 0 && !xy)) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    if (!rast__in_range(a) || !rast__in_range(b)) return RAST_E_RANGE;
    rast__lwalk_init(&w, a, b, &g, RAST__LINE_DDA(opts), &c);
    *count = (size_t)w.n; /* <= 2^28 + 1 */
    if ((size_t)w.n > capacity) return RAST_E_SCRATCH;
    for (k = 0; k < w.n; k++) {
        if (k) rast__lwalk_next(&w);
        xy[2 * k] = (int32_t)(w.ymajor ? w.q : w.p);
        xy[2 * k + 1] = (int32_t)(w.ymajor ? w.p : w.q);
    }
    return RAST_OK;
}

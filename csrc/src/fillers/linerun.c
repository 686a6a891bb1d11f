/*
 * linerun.c - the library's line (rastrum.h, "lines") by formula, row by
 * row.  line.c walks the same pixels incrementally (Bresenham); this file
 * answers "which columns does the line have in row j" directly, for the
 * boundary modes, which add edges row by row beside a filler.
 *
 * In internal units (doubled; unit U, sample offset O, half pixel H = U/2)
 * name the line's axes major u and minor v: u = x, v = y when
 * |dx| >= |dy|, else the other way round.  With the endpoints ordered so
 * that du >= 0, the line has one pixel at each major index k whose sample
 * kU + O lies in [ua, ub], at minor index
 *     m(k) = floor((v(kU + O) - O + H) / U),
 *     v(u) = va + (u - ua) dv / du          (va when du = 0).
 */
#include "../base/internal.h"

typedef struct rast__axes {
    int64_t ua, va, du, dv; /* du >= 0, |dv| <= du */
    int xmajor;
} rast__axes;

static rast__axes rast__line_axes(rast_point a, rast_point b)
{
    rast__axes l;
    int64_t ax = 2 * (int64_t)a.x, ay = 2 * (int64_t)a.y;
    int64_t bx = 2 * (int64_t)b.x, by = 2 * (int64_t)b.y;
    int64_t adx = bx > ax ? bx - ax : ax - bx, ady = by > ay ? by - ay : ay - by;
    l.xmajor = adx >= ady;
    if (!l.xmajor) { /* swap the axes */
        int64_t t = ax; ax = ay; ay = t;
        t = bx; bx = by; by = t;
    }
    if (bx < ax) { /* order along the major axis */
        int64_t t = ax; ax = bx; bx = t;
        t = ay; ay = by; by = t;
    }
    l.ua = ax;
    l.va = ay;
    l.du = bx - ax;
    l.dv = by - ay;
    return l;
}

/* floor(n / d) for any d != 0. */
static int64_t rast__fdiv(int64_t n, int64_t d)
{
    return d < 0 ? rast__floordiv(-n, -d) : rast__floordiv(n, d);
}

/* Minor index of major index k (k in the line's major range, so that
 * kU + O - ua lies in [0, du]).  |va * du| < 2^57, the middle product is
 * at most du * |dv| < 2^58, the last < 2^46: the sum fits. */
static int64_t rast__minor(const rast__axes *l, const rast__grid *g, int64_t k)
{
    int64_t h = g->unit / 2;
    if (l->du == 0) return rast__floordiv(l->va - g->off + h, g->unit);
    return rast__floordiv(l->va * l->du + (k * g->unit + g->off - l->ua) * l->dv +
                              (h - g->off) * l->du,
                          (int64_t)g->unit * l->du);
}

/* The major indices [*k0, *k1) whose samples lie on the segment. */
static void rast__major(const rast__axes *l, const rast__grid *g, int64_t *k0, int64_t *k1)
{
    *k0 = rast__ceildiv(l->ua - g->off, g->unit);
    *k1 = rast__floordiv(l->ua + l->du - g->off, g->unit) + 1;
    if (*k1 < *k0) *k1 = *k0;
}

void rast__line_rows(rast_point a, rast_point b, const rast__grid *g,
                     int64_t *r0, int64_t *r1)
{
    rast__axes l = rast__line_axes(a, b);
    int64_t k0, k1, m0, m1;
    rast__major(&l, g, &k0, &k1);
    if (!l.xmajor || k0 == k1) {
        *r0 = k0;
        *r1 = k1;
        return;
    }
    m0 = rast__minor(&l, g, k0);
    m1 = rast__minor(&l, g, k1 - 1);
    *r0 = m0 < m1 ? m0 : m1;
    *r1 = (m0 < m1 ? m1 : m0) + 1;
}

void rast__line_run(rast_point a, rast_point b, const rast__grid *g,
                    int64_t row, int64_t *x0, int64_t *x1)
{
    rast__axes l = rast__line_axes(a, b);
    int64_t k0, k1, lo, hi, p, nj, nj1, u = g->unit, h = g->unit / 2;
    rast__major(&l, g, &k0, &k1);
    if (!l.xmajor) { /* one pixel per row */
        *x0 = rast__minor(&l, g, row);
        *x1 = *x0 + 1;
        return;
    }
    if (l.dv == 0) { /* horizontal (or a point): the whole major range */
        *x0 = k0;
        *x1 = k1;
        return;
    }
    /* m(k) >= j  <=>  k * p >= N(j), with p = U dv and
     * N(j) = jU du - va du - (O - ua) dv - (H - O) du.  The row is within
     * the line's rows, so |jU - va| <= du + U and every product < 2^59. */
    p = u * l.dv;
    nj = (row * u - l.va) * l.du - (g->off - l.ua) * l.dv - (h - g->off) * l.du;
    nj1 = nj + u * l.du;
    if (p > 0) { /* k in [ceil(N(j)/p), ceil(N(j+1)/p)) */
        lo = rast__ceildiv(nj, p);
        hi = rast__ceildiv(nj1, p);
    } else { /* k in [floor(N(j+1)/p) + 1, floor(N(j)/p)] */
        lo = rast__fdiv(nj1, p) + 1;
        hi = rast__fdiv(nj, p) + 1;
    }
    *x0 = lo > k0 ? lo : k0;
    *x1 = hi < k1 ? hi : k1;
}

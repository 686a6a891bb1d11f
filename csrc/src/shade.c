/*
 * shade.c - the Gouraud painter (seed 001 3.3.5; seeds 002-004): colours
 * and depth interpolated from each triangle's plane equations over the
 * spans any triangle filler emits.  The filler decides which samples; this
 * file only decides what each one gets.
 *
 * A quantity with values c0, c1, c2 at the vertices (internal units, see
 * internal.h: doubled, so that every sample is an integer point) is
 *     c(p) = c0 + N(p) / A,   N(p) = (px - x0) gx + (py - y0) gy,
 *     gx = d1 (y2 - y0) - d2 (y1 - y0),  gy = d2 (x1 - x0) - d1 (x2 - x0),
 * with d1 = c1 - c0, d2 = c2 - c0 and A = (x1 - x0)(y2 - y0) -
 * (y1 - y0)(x2 - x0) (signs turned so that A > 0).  This is the
 * barycentric sum of the header, regrouped around vertex 0.
 *
 * Exact: the rounded value is c0 + floor(R / D) with R = 2 N + A, D = 2 A.
 * At a span's first pixel R / D is divided out (quotient q, remainder r in
 * [0, D)); from one pixel to the next R grows by 2 gx unit = sx D + tx, so
 * q += sx, r += tx, and a carry when r reaches D: adds and a compare, no
 * division, exact.  Magnitudes: |d| < 2^33 (depth), coordinate differences
 * < 2^30, so gx, gy < 2^63; A < 2^60.  N itself needs 128 bits in general
 * (a big triangle, a full-range depth); per triangle the painter checks
 * whether every product fits int64_t and otherwise divides with wide.h.
 *
 * Fixed: the value at the box corner (ri, rj) and the steps per column and
 * row, each rounded to 1/2^F, then v = base + (i - ri) fgx + (j - rj) fgy
 * by additions; a pixel is floor(v / 2^F + 1/2).
 */
#include <string.h>

#include "paint.h"
#include "wide.h"

#define RAST__SHADE_RUN 64 /* pixels gathered before a format's put */
#define RAST__CH_Z 4       /* channel index of the depth */

typedef struct rast__chan {
    int64_t c0;              /* value at vertex 0 */
    int64_t gx, gy;          /* N = (px - x0) gx + (py - y0) gy */
    int64_t sx, tx;          /* exact: R's step per column = sx D + tx */
    int64_t fbase, fgx, fgy; /* fixed: c - c0 at (ri, rj), steps; 1/2^F */
    int64_t lo, hi;          /* the channel's range */
} rast__chan;

typedef struct rast__shade {
    unsigned char *base;
    ptrdiff_t stride;
    const rast__format *fmt;
    int32_t *zbuf;
    ptrdiff_t zstride;       /* target width */
    const uint8_t *colors;
    const int32_t *z;
    rast_precision prec;
    int32_t F;
    int32_t nch;             /* colour channels interpolated */
    int32_t unit, off;       /* of the grid */
    /* the current triangle */
    int64_t A, D;
    int64_t x0, y0;          /* vertex 0, internal units */
    int32_t imin, imax, jmin, jmax; /* pixels its spans may reach */
    int32_t narrow;          /* every N in the box fits int64_t */
    int32_t step;            /* every sx fits: stepping is exact */
    int32_t fixed;           /* fixed steps fit (else: exact) */
    rast__chan ch[5];        /* R, G, B, A, depth */
    /* flat without depth: a solid painter */
    int32_t flat;
    rast__solid solid;
    rast__row_fn solid_fn;
} rast__shade;

static int32_t rast__bitlen(int64_t v)
{
    uint64_t u = v < 0 ? 0 - (uint64_t)v : (uint64_t)v;
    int32_t n = 0;
    while (u) {
        n++;
        u >>= 1;
    }
    return n;
}

static int64_t rast__clamp(int64_t v, const rast__chan *c)
{
    return v < c->lo ? c->lo : v > c->hi ? c->hi : v;
}

/* c - c0 at pixel (i, j), rounded half up, exactly: q and the remainder r
 * of R over D.  Returns 0 when the value is saturated (far outside the
 * triangle): stepping from it would be wrong. */
static int rast__exact_at(const rast__shade *s, const rast__chan *c, int32_t i, int32_t j,
                          int64_t *q, int64_t *r)
{
    int64_t dx = (int64_t)i * s->unit + s->off - s->x0;
    int64_t dy = (int64_t)j * s->unit + s->off - s->y0;
    if (s->narrow && i >= s->imin && i <= s->imax && j >= s->jmin && j <= s->jmax) {
        int64_t R = 2 * (dx * c->gx + dy * c->gy) + s->A;
        int64_t qq = R / s->D, rr = R % s->D;
        if (rr < 0) {
            qq--;
            rr += s->D;
        }
        *q = qq;
        *r = rr;
        return 1;
    } else {
        rast__i128 R = rast__i128_add(rast__i128_mul(dx, c->gx), rast__i128_mul(dy, c->gy));
        R = rast__i128_add(rast__i128_shl(R, 1), rast__i128_from(s->A));
        return rast__i128_floordiv(R, s->D, q, r);
    }
}

/* floor(v / 2^F + 1/2) for |v| < 2^62, by a shift of the biased value
 * (a right shift of a negative number is implementation-defined in C). */
static int64_t rast__fixed_round(int64_t v, int32_t F)
{
    const int64_t bias = (int64_t)1 << 62;
    return (int64_t)((uint64_t)(v + bias + ((int64_t)1 << (F - 1))) >> F) - (bias >> F);
}

/* Hand the gathered run [x, x + n) to the format. */
static void rast__shade_flush(const rast__shade *s, unsigned char *row, int32_t x, int32_t *n,
                              const unsigned char *buf)
{
    if (*n) s->fmt->put(row, x, *n, buf);
    *n = 0;
}

static void rast__shade_span(rast__shade *s, int32_t y, int32_t xa, int32_t xb)
{
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t *zrow = s->zbuf ? s->zbuf + (ptrdiff_t)y * s->zstride : NULL;
    unsigned char buf[4 * RAST__SHADE_RUN];
    int64_t q[5], r[5];
    int32_t nch = s->nch, c, x, run = 0, runx = xa;
    int32_t last = zrow ? RAST__CH_Z : nch - 1;
    int fixed = s->fixed && s->prec == RAST_PRECISION_FIXED && xa >= s->imin &&
                xb - 1 <= s->imax && y >= s->jmin && y <= s->jmax;
    int fresh = 0;

    /* The first pixel's values: q (and r) per channel. */
    for (c = 0; c <= last; c++) {
        const rast__chan *ch = &s->ch[c];
        if (c >= nch && c != RAST__CH_Z) continue;
        if (fixed) {
            q[c] = ch->fbase + (int64_t)(xa - s->imin) * ch->fgx + (int64_t)(y - s->jmin) * ch->fgy;
        } else if (!rast__exact_at(s, ch, xa, y, &q[c], &r[c]) || !s->step) {
            fresh = 1;
        }
    }
    for (x = xa; x < xb; x++) {
        int64_t val[5];
        if (fresh && x > xa)
            for (c = 0; c <= last; c++)
                if (c < nch || c == RAST__CH_Z) (void)rast__exact_at(s, &s->ch[c], x, y, &q[c], &r[c]);
        for (c = 0; c <= last; c++) {
            const rast__chan *ch = &s->ch[c];
            if (c >= nch && c != RAST__CH_Z) continue;
            val[c] = rast__clamp(ch->c0 + (fixed ? rast__fixed_round(q[c], s->F) : q[c]), ch);
            if (fixed) {
                q[c] += ch->fgx;
            } else if (!fresh) {
                int64_t rr = r[c] + ch->tx, carry = rr >= s->D;
                q[c] += ch->sx + carry;
                r[c] = rr - (s->D & -carry);
            }
        }
        if (zrow) {
            int32_t zv = (int32_t)val[RAST__CH_Z];
            if (!(zv < zrow[x])) { /* hidden: the run ends here */
                rast__shade_flush(s, row, runx, &run, buf);
                continue;
            }
            zrow[x] = zv;
        }
        if (run == 0) runx = x;
        for (c = 0; c < nch; c++) buf[4 * run + c] = (unsigned char)val[c];
        if (++run == RAST__SHADE_RUN) rast__shade_flush(s, row, runx, &run, buf);
    }
    rast__shade_flush(s, row, runx, &run, buf);
}

static void rast__shade_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__shade *s = (rast__shade *)user;
    int32_t k;
    if (s->flat) {
        s->solid_fn(&s->solid, y, xs, n);
        return;
    }
    for (k = 0; k < n; k++) rast__shade_span(s, y, xs[2 * k], xs[2 * k + 1]);
}

/* The pixels a triangle's spans may reach, one axis: its vertices' extent
 * with two pixels to spare (textbook rounding and the boundary modes reach
 * at most one pixel past the triangle), cut to the clip. */
static void rast__shade_extent(int64_t a, int64_t b, int64_t c, const rast__shade *s,
                               int32_t lo, int32_t hi, int32_t *mn, int32_t *mx)
{
    int64_t min = a < b ? (a < c ? a : c) : (b < c ? b : c);
    int64_t max = a > b ? (a > c ? a : c) : (b > c ? b : c);
    int64_t i0 = rast__floordiv(min - s->off, s->unit) - 2;
    int64_t i1 = rast__floordiv(max - s->off, s->unit) + 2;
    if (i0 < lo) i0 = lo;
    if (i1 > hi - 1) i1 = hi - 1;
    if (i1 < i0) i1 = i0; /* nothing to paint: any one pixel */
    *mn = (int32_t)i0;
    *mx = (int32_t)i1;
}

/* Set up channel c of the current triangle from its vertex values. */
static void rast__chan_setup(rast__shade *s, rast__chan *ch, int64_t c0, int64_t c1, int64_t c2,
                             int64_t ex1, int64_t ey1, int64_t ex2, int64_t ey2, int neg)
{
    int64_t d1 = c1 - c0, d2 = c2 - c0;
    int64_t dxr, dyr, t;
    ch->c0 = c0;
    ch->gx = d1 * ey2 - d2 * ey1;
    ch->gy = d2 * ex1 - d1 * ex2;
    if (neg) {
        ch->gx = -ch->gx;
        ch->gy = -ch->gy;
    }
    /* Exact stepping: 2 gx unit = sx D + tx. */
    if (!rast__i128_floordiv(rast__i128_mul(ch->gx, 2 * (int64_t)s->unit), s->D, &ch->sx, &ch->tx))
        s->step = 0;
    /* N fits int64_t over the box? */
    dxr = (int64_t)(s->imax - s->imin + 1) * s->unit + s->unit;
    dyr = (int64_t)(s->jmax - s->jmin + 1) * s->unit + s->unit;
    {
        int64_t ax = s->x0 - ((int64_t)s->imin * s->unit + s->off);
        int64_t ay = s->y0 - ((int64_t)s->jmin * s->unit + s->off);
        if (ax < 0) ax = -ax;
        if (ay < 0) ay = -ay;
        dxr += ax;
        dyr += ay;
    }
    if (rast__bitlen(ch->gx) + rast__bitlen(dxr) > 60 || rast__bitlen(ch->gy) + rast__bitlen(dyr) > 60)
        s->narrow = 0;
    if (s->prec == RAST_PRECISION_FIXED) {
        /* base: (2 N 2^F + A) / D at the corner; steps: (2 g unit 2^F + A) / D */
        int64_t dx = (int64_t)s->imin * s->unit + s->off - s->x0;
        int64_t dy = (int64_t)s->jmin * s->unit + s->off - s->y0;
        rast__i128 N = rast__i128_add(rast__i128_mul(dx, ch->gx), rast__i128_mul(dy, ch->gy));
        rast__i128 a = rast__i128_from(s->A);
        int ok = rast__i128_floordiv(rast__i128_add(rast__i128_shl(N, s->F + 1), a), s->D,
                                     &ch->fbase, &t);
        ok &= rast__i128_floordiv(
            rast__i128_add(rast__i128_shl(rast__i128_mul(ch->gx, s->unit), s->F + 1), a), s->D,
            &ch->fgx, &t);
        ok &= rast__i128_floordiv(
            rast__i128_add(rast__i128_shl(rast__i128_mul(ch->gy, s->unit), s->F + 1), a), s->D,
            &ch->fgy, &t);
        /* base + 2^29 steps of each kind stays below 2^62 */
        if (!ok || ch->fbase > ((int64_t)1 << 60) || ch->fbase < -((int64_t)1 << 60) ||
            rast__bitlen(ch->fgx) > 31 || rast__bitlen(ch->fgy) > 31)
            s->fixed = 0;
    }
}

static int rast__shade_begin(void *user, const rast_point *t, uint32_t k, const rast__grid *g)
{
    rast__shade *s = (rast__shade *)user;
    const uint8_t *col = s->colors + 12 * (size_t)k;
    int64_t x0 = 2 * (int64_t)t[0].x, y0 = 2 * (int64_t)t[0].y;
    int64_t ex1 = 2 * (int64_t)t[1].x - x0, ey1 = 2 * (int64_t)t[1].y - y0;
    int64_t ex2 = 2 * (int64_t)t[2].x - x0, ey2 = 2 * (int64_t)t[2].y - y0;
    int64_t A = ex1 * ey2 - ey1 * ex2;
    int32_t c, neg = A < 0;

    s->unit = g->unit;
    s->off = g->off;

    if (s->flat) {
        s->fmt->pack(col, s->solid.value);
        return 1;
    }
    if (A == 0) { /* no plane: vertex 0's values (boundary modes only) */
        ex1 = ey1 = ex2 = ey2 = 0;
        A = 1;
    }
    s->A = neg ? -A : A;
    s->D = 2 * s->A;
    s->x0 = x0;
    s->y0 = y0;
    rast__shade_extent(x0, x0 + ex1, x0 + ex2, s, s->solid.clip.x0, s->solid.clip.x1, &s->imin,
                       &s->imax);
    rast__shade_extent(y0, y0 + ey1, y0 + ey2, s, s->solid.clip.y0, s->solid.clip.y1, &s->jmin,
                       &s->jmax);
    s->narrow = 1;
    s->step = 1;
    /* fixed: (i - imin) fgx + (j - jmin) fgy + base stays below 2^61 */
    s->fixed = s->imax - s->imin < ((int32_t)1 << 28) && s->jmax - s->jmin < ((int32_t)1 << 28);
    for (c = 0; c < s->nch; c++) {
        int flat = s->prec == RAST_PRECISION_FLAT;
        rast__chan_setup(s, &s->ch[c], col[c], flat ? col[c] : col[4 + c],
                         flat ? col[c] : col[8 + c], ex1, ey1, ex2, ey2, neg);
    }
    if (s->z) {
        const int32_t *z = s->z + 3 * (size_t)k;
        rast__chan_setup(s, &s->ch[RAST__CH_Z], z[0], z[1], z[2], ex1, ey1, ex2, ey2, neg);
    }
    return 1;
}

rast_status rast_fill_triangles_shaded(const rast_target *target, const rast_point *tris,
                                       uint32_t ntris, const uint8_t *colors, const int32_t *z,
                                       int32_t *zbuf, const rast_tri_opts *opts,
                                       const rast_shade_opts *shade, void *scratch,
                                       size_t scratch_bytes)
{
    rast__shade s;
    rast_rect clip;
    rast_status st;
    int32_t c;

    if (!target || !opts || !shade || (ntris > 0 && (!tris || !colors))) return RAST_E_NULL;
    if (!z != !zbuf) return RAST_E_NULL;
    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    if ((unsigned)shade->precision > RAST_PRECISION_FLAT) return RAST_E_ARG;
    if (shade->precision == RAST_PRECISION_FIXED &&
        (shade->fraction_bits < 1 || shade->fraction_bits > 16))
        return RAST_E_ARG;
    memset(&s, 0, sizeof s);
    s.fmt = &rast__formats[target->format];
    if (!s.fmt->put) return RAST_E_FORMAT;
    s.base = (unsigned char *)target->pixels;
    s.stride = target->stride;
    s.zbuf = zbuf;
    s.zstride = target->width;
    s.colors = colors;
    s.z = z;
    s.prec = shade->precision;
    s.F = shade->fraction_bits;
    s.nch = s.fmt->channels;
    for (c = 0; c < 4; c++) {
        s.ch[c].lo = 0;
        s.ch[c].hi = 255;
    }
    s.ch[RAST__CH_Z].lo = INT32_MIN;
    s.ch[RAST__CH_Z].hi = INT32_MAX;
    /* The solid painter: the flat colour without depth, and the clip. */
    {
        static const unsigned char zero[4] = {0, 0, 0, 0};
        st = rast__solid_init(&s.solid, target, &clip, zero, NULL, &s.solid_fn);
        if (st != RAST_OK) return st;
    }
    s.flat = s.prec == RAST_PRECISION_FLAT && !z;
    return rast__tri_fill(tris, ntris, opts, &clip, rast__shade_row, &s, rast__shade_begin,
                          scratch, scratch_bytes);
}

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
 *
 * Packed (the common case: RGBA8888 on a little-endian machine, no depth,
 * exact rounding and boundary, a small triangle): the same values, all
 * four channels of a pixel stepped together and written by one 32-bit
 * store, without clamping.  Every sample such a fill writes lies in the
 * closed triangle, where the exact value is within the vertex values
 * (0..255), so:
 *  - exact: each level is in 0..255; the four levels q live in bytes of
 *    one word (a step adds every channel's sx and its carry: no byte ever
 *    carries into the next), the remainders in [0, D) shifted so that a
 *    carry is a sign bit (no branch): two to a 64-bit word as 32-bit lanes
 *    when D < 2^31, else one to a register;
 *  - fixed: the base and each step are off by at most 1/2 of 1/2^F, so with
 *    1 + W + H < 2^F (W, H: the box's columns and rows) v is less than half
 *    a level off and v + 1/2 lies in (0, 256).  Two channels share a
 *    64-bit word (R and B; G and A times 256) as 32-bit lanes holding
 *    (v + 1/2) 2^16, in [0, 2^24) (times 256: [0, 2^32)), so the lanes
 *    never carry into each other and every level sits at a fixed bit:
 *    two adds, two masks, two shifts and a store a pixel.
 * Both setups divide by D with the triangle's reciprocal (wide.h).
 */
#include <string.h>

#include "paint.h"
#include "../base/wide.h"

#define RAST__SHADE_RUN 64 /* pixels gathered before a format's put */
#define RAST__CH_Z 4       /* channel index of the depth */

typedef struct rast__chan {
    int64_t c0;              /* value at vertex 0 */
    int64_t gx, gy;          /* N = (px - x0) gx + (py - y0) gy */
    int64_t sx, tx;          /* exact: R's step per column = sx D + tx */
    int64_t fbase, fgx, fgy; /* fixed: c - c0 at (ri, rj), steps; 1/2^F */
    int64_t fc;              /* fixed: c at pixel (0, 0) of the plane, 1/2^F */
    int64_t lo, hi;          /* the channel's range */
} rast__chan;

typedef struct rast__shade {
    unsigned char *base;
    ptrdiff_t stride;
    int32_t ox, oy;          /* the pixel at base: (0, 0) for a target, a
                                band's corner for rast__shade_band; the
                                packed rows take (0, 0) (packable) */
    const rast__format *fmt;
    int32_t *zbuf;
    ptrdiff_t zstride;       /* target width */
    const uint8_t *colors;
    const int32_t *z;
    rast_precision prec;
    int32_t F;
    int32_t nch;             /* colour channels interpolated */
    int32_t unit, off, shift; /* of the grid: unit = 2^shift */
    /* the current triangle */
    int64_t A, D;
    rast__recip rd;          /* division by D */
    int64_t x0, y0;          /* vertex 0, internal units */
    int32_t imin, imax, jmin, jmax; /* pixels its spans may reach */
    int32_t blx, bly;        /* bits of the largest |px - x0|, |py - y0| in the box */
    int32_t narrow;          /* every N in the box fits int64_t */
    int32_t step;            /* every sx fits: stepping is exact */
    int32_t have_steps;      /* sx, tx computed (fixed point needs none) */
    int32_t fixed;           /* fixed steps fit (else: exact) */
    rast__chan ch[5];        /* R, G, B, A, depth */
    /* fixed, packed (see the top): 32-bit lanes (R, B) and 256 (G, A), each
     * (v + 1/2) 2^16, at pixel (0, 0) of the plane and their steps per
     * column and row; the sums are taken modulo 2^64 */
    int32_t packable;        /* the call may pack: RGBA8888, little-endian, no depth, exact boundary */
    int32_t packed;          /* the current triangle is packed: 1 fixed, 2 exact */
    uint64_t pk0[2], pkx[2], pky[2];
    /* exact, packed: per channel R at the box corner, its steps per column
     * and row (R's, and 2 gx unit = sx D + tx) */
    int64_t ek[4], egx[4], egy[4], esx[4], etx[4];
    /* flat without depth: a solid painter */
    int32_t flat;
    int32_t cull;            /* skip triangles whose rows miss the clip (bands) */
    rast__solid solid;
    rast__painter solid_p;   /* its full entry (user: &solid) */
    rast__rgba_put_fn bput;  /* NULL, or the blend in place of the put (blend.c) */
    const void *bctx;
} rast__shade;

/* Bits of |v| (0 for 0): the compiler's count-leading-zeros, or (other
 * compilers, -DRAST_NO_BUILTIN_CTZ) halving. */
static int32_t rast__bitlen(int64_t v)
{
    uint64_t u = v < 0 ? 0 - (uint64_t)v : (uint64_t)v;
#if (defined(__GNUC__) || defined(__clang__)) && !defined(RAST_NO_BUILTIN_CTZ)
    return u ? 64 - __builtin_clzll(u) : 0;
#else
    int32_t n = 0;
    if (u >> 32) { n += 32; u >>= 32; }
    if (u >> 16) { n += 16; u >>= 16; }
    if (u >> 8) { n += 8; u >>= 8; }
    if (u >> 4) { n += 4; u >>= 4; }
    if (u >> 2) { n += 2; u >>= 2; }
    if (u >> 1) { n += 1; u >>= 1; }
    return n + (int32_t)u;
#endif
}

/* *q = floor((a b 2^sh + c) / d), *r the remainder, for 0 < d < 2^62,
 * |c| < 2^61, 0 <= sh < 64: natively when the product fits in 61 bits
 * (the common case), else in 128 bits; 0 if the quotient saturated (see
 * rast__i128_floordiv). */
static int rast__prod_div(int64_t a, int64_t b, int32_t sh, int64_t c, const rast__recip *d,
                          int64_t *q, int64_t *r)
{
    if (rast__bitlen(a) + rast__bitlen(b) + sh <= 61) {
        *q = rast__recip_floordiv(d, a * b * ((int64_t)1 << sh) + c, r);
        return 1;
    }
    return rast__i128_floordiv(rast__i128_add(rast__i128_shl(rast__i128_mul(a, b), sh),
                                              rast__i128_from(c)), (int64_t)d->d, q, r);
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
        *q = rast__recip_floordiv(&s->rd, R, r);
        return 1;
    } else {
        rast__i128 R = rast__i128_add(rast__i128_mul(dx, c->gx), rast__i128_mul(dy, c->gy));
        R = rast__i128_add(rast__i128_shl(R, 1), rast__i128_from(s->A));
        return rast__i128_floordiv(R, s->D, q, r);
    }
}

/* One channel of a chunk of n pixels, channel-major so that each loop is
 * a tight run of adds: the values start at *q (exact: with remainder *r)
 * and go into out[stride k] (clamped to the channel's range); *q and *r
 * are left at pixel n. */
static void rast__exact_run(const rast__shade *s, const rast__chan *ch, int64_t *q, int64_t *r,
                            int32_t n, int64_t *out)
{
    int64_t qq = *q, rr = *r, D = s->D, sx = ch->sx, tx = ch->tx, lo = ch->lo, hi = ch->hi;
    int32_t k;
    for (k = 0; k < n; k++) {
        int64_t v = qq, carry;
        out[k] = v < lo ? lo : v > hi ? hi : v;
        rr += tx;
        carry = rr >= D;
        qq += sx + carry;
        rr -= D & -carry;
    }
    *q = qq;
    *r = rr;
}

static void rast__fixed_run(const rast__shade *s, const rast__chan *ch, int64_t *q, int32_t n,
                            int64_t *out)
{
    /* floor(v / 2^F + 1/2) by a shift of v biased non-negative (a right
     * shift of a negative number is implementation-defined in C) */
    const int64_t bias = (int64_t)1 << 62;
    int64_t v = *q + bias + ((int64_t)1 << (s->F - 1)), g = ch->fgx, lo = ch->lo, hi = ch->hi;
    int64_t unbias = bias >> s->F;
    int32_t k, F = s->F;
    for (k = 0; k < n; k++) {
        int64_t x = (int64_t)((uint64_t)v >> F) - unbias;
        out[k] = x < lo ? lo : x > hi ? hi : x;
        v += g;
    }
    *q = v - bias - ((int64_t)1 << (s->F - 1));
}

/* The colour channels of n pixels in fixed point, pixel-major into the
 * RGBA buffer: the common fast case, one loop per channel count. */
static void rast__fixed_colours(const rast__shade *s, int64_t *q, int32_t nch, int32_t n,
                                unsigned char *buf)
{
    const int64_t bias = ((int64_t)1 << 62) + ((int64_t)1 << (s->F - 1));
    const int64_t unbias = ((int64_t)1 << 62) >> s->F;
    const int32_t F = s->F;
    int64_t v[4] = {0, 0, 0, 0}, g[4] = {0, 0, 0, 0};
    int32_t c, k;
#define RAST__LEVEL(c)                                                         \
    do {                                                                       \
        int64_t l = (int64_t)((uint64_t)v[c] >> F) - unbias;                   \
        buf[4 * k + (c)] = (unsigned char)(l < 0 ? 0 : l > 255 ? 255 : l);     \
        v[c] += g[c];                                                          \
    } while (0)
    for (c = 0; c < nch; c++) {
        v[c] = q[c] + bias;
        g[c] = s->ch[c].fgx;
    }
    if (nch == 1) {
        for (k = 0; k < n; k++) RAST__LEVEL(0);
    } else if (nch == 3) {
        for (k = 0; k < n; k++) {
            RAST__LEVEL(0);
            RAST__LEVEL(1);
            RAST__LEVEL(2);
        }
    } else {
        for (k = 0; k < n; k++) {
            RAST__LEVEL(0);
            RAST__LEVEL(1);
            RAST__LEVEL(2);
            RAST__LEVEL(3);
        }
    }
#undef RAST__LEVEL
    for (c = 0; c < nch; c++) q[c] = v[c] - bias;
}

/* Exactly, one pixel at a time (a saturated start: far outside a sliver,
 * where stepping would be wrong). */
static void rast__fresh_run(const rast__shade *s, const rast__chan *ch, int32_t x, int32_t y,
                            int32_t n, int64_t *out)
{
    int32_t k;
    for (k = 0; k < n; k++) {
        int64_t q, r;
        (void)rast__exact_at(s, ch, x + k, y, &q, &r);
        q += ch->c0;
        out[k] = q < ch->lo ? ch->lo : q > ch->hi ? ch->hi : q;
    }
}

/* The start of channel c at pixel (x, y): *q (value, c0 included) and *r;
 * returns 0 when the pixels must be computed one by one. */
static int rast__chan_start(const rast__shade *s, const rast__chan *ch, int fixed, int32_t x,
                            int32_t y, int64_t *q, int64_t *r)
{
    if (fixed) {
        *q = ch->fc + (int64_t)x * ch->fgx + (int64_t)y * ch->fgy;
        return 1;
    }
    if (!rast__exact_at(s, ch, x, y, q, r)) return 0;
    *q += ch->c0;
    return s->step && s->have_steps;
}

static void rast__shade_span(rast__shade *s, int32_t y, int32_t xa, int32_t xb)
{
    unsigned char *row = s->base + (ptrdiff_t)(y - s->oy) * s->stride;
    int32_t *zrow = s->zbuf ? s->zbuf + (ptrdiff_t)y * s->zstride : NULL;
    unsigned char buf[4 * RAST__SHADE_RUN];
    int64_t val[RAST__SHADE_RUN];
    int64_t q[5], r[5];
    int step[5];
    int32_t nch = s->nch, c, x, k;
    int fixed = s->fixed && s->prec == RAST_PRECISION_FIXED && xa >= s->imin &&
                xb - 1 <= s->imax && y >= s->jmin && y <= s->jmax;

    if (fixed && !zrow) { /* the fast common case */
        for (c = 0; c < nch; c++)
            q[c] = s->ch[c].fc + (int64_t)xa * s->ch[c].fgx + (int64_t)y * s->ch[c].fgy;
        for (x = xa; x < xb; x += RAST__SHADE_RUN) {
            int32_t n = xb - x < RAST__SHADE_RUN ? xb - x : RAST__SHADE_RUN;
            rast__fixed_colours(s, q, nch, n, buf);
            if (s->bput) s->bput(s->bctx, row, x - s->ox, n, buf, NULL);
            else s->fmt->put(row, x - s->ox, n, buf);
        }
        return;
    }
    for (c = 0; c < nch; c++) step[c] = rast__chan_start(s, &s->ch[c], fixed, xa, y, &q[c], &r[c]);
    if (zrow)
        step[RAST__CH_Z] = rast__chan_start(s, &s->ch[RAST__CH_Z], fixed, xa, y, &q[RAST__CH_Z],
                                            &r[RAST__CH_Z]);
    for (x = xa; x < xb; x += RAST__SHADE_RUN) {
        int32_t n = xb - x < RAST__SHADE_RUN ? xb - x : RAST__SHADE_RUN;
        unsigned char pass[RAST__SHADE_RUN];
        if (fixed) rast__fixed_colours(s, q, nch, n, buf);
        else for (c = 0; c < nch; c++) {
            const rast__chan *ch = &s->ch[c];
            if (!step[c]) rast__fresh_run(s, ch, x, y, n, val);
            else if (fixed) rast__fixed_run(s, ch, &q[c], n, val);
            else rast__exact_run(s, ch, &q[c], &r[c], n, val);
            for (k = 0; k < n; k++) buf[4 * k + c] = (unsigned char)val[k];
        }
        if (!zrow) {
            if (s->bput) s->bput(s->bctx, row, x - s->ox, n, buf, NULL);
            else s->fmt->put(row, x - s->ox, n, buf);
            continue;
        }
        c = RAST__CH_Z;
        if (!step[c]) rast__fresh_run(s, &s->ch[c], x, y, n, val);
        else if (fixed) rast__fixed_run(s, &s->ch[c], &q[c], n, val);
        else rast__exact_run(s, &s->ch[c], &q[c], &r[c], n, val);
        for (k = 0; k < n; k++) {
            int32_t zv = (int32_t)val[k];
            pass[k] = zv < zrow[x + k];
            if (pass[k]) zrow[x + k] = zv;
        }
        /* the runs of visible pixels */
        for (k = 0; k < n;) {
            int32_t e;
            if (!pass[k]) {
                k++;
                continue;
            }
            for (e = k + 1; e < n && pass[e]; e++) {}
            if (s->bput) s->bput(s->bctx, row, x + k - s->ox, e - k, buf + 4 * k, NULL);
            else s->fmt->put(row, x + k - s->ox, e - k, buf + 4 * k);
            k = e;
        }
    }
}

/* The spans of row y of a packed triangle: the levels of R and B at bits
 * 16.. and 48.. of one word, of G and A at bits 24.. and 56.. of the other
 * (no clamping, see the top), stored as R, G, B, A bytes in one
 * little-endian 32-bit word. */
static void rast__packed_row(const rast__shade *s, int32_t y, const int32_t *xs, int32_t n)
{
    const uint64_t m0 = 0x00FF000000FF0000u, m1 = 0xFF000000FF000000u;
    const uint64_t sx0 = s->pkx[0], sx1 = s->pkx[1];
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    uint64_t r0 = s->pk0[0] + (uint64_t)(int64_t)y * s->pky[0];
    uint64_t r1 = s->pk0[1] + (uint64_t)(int64_t)y * s->pky[1];
    int32_t k;
    for (k = 0; k < n; k++) {
        int32_t x = xs[2 * k], xb = xs[2 * k + 1];
        uint64_t p0 = r0 + (uint64_t)(int64_t)x * sx0, p1 = r1 + (uint64_t)(int64_t)x * sx1;
        unsigned char *o = row + (ptrdiff_t)x * 4;
        for (; x < xb; x++, o += 4) {
            uint64_t w = (p0 & m0) | (p1 & m1);
            uint32_t px = (uint32_t)(w >> 16) | (uint32_t)(w >> 32);
            memcpy(o, &px, 4);
            p0 += sx0;
            p1 += sx1;
        }
    }
}

/* The spans of row y of an exact packed triangle: each channel's value
 * q + r / D stepped exactly (a carry when r reaches D), the four levels in
 * bytes of one word (no clamping: every sample lies in the triangle, so
 * every level is in 0..255 and no byte carries into the next), stored as
 * R, G, B, A by one 32-bit store on a little-endian machine. */
static void rast__exact_packed_row(const rast__shade *s, int32_t y, const int32_t *xs, int32_t n)
{
    const int64_t D = s->D;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    uint32_t sxp = 0;
    int64_t rowk[4];
    int32_t c, k;
    for (c = 0; c < 4; c++) {
        rowk[c] = s->ek[c] + (int64_t)(y - s->jmin) * s->egy[c];
        sxp += (uint32_t)s->esx[c] << (8 * c);
    }
    for (k = 0; k < n; k++) {
        int32_t x = xs[2 * k], xb = xs[2 * k + 1];
        int64_t r[4];
        uint32_t qp = 0;
        unsigned char *o = row + (ptrdiff_t)x * 4;
        for (c = 0; c < 4; c++) {
            int64_t q = rast__recip_floordiv(&s->rd, rowk[c] + (int64_t)(x - s->imin) * s->egx[c],
                                             &r[c]);
            qp += (uint32_t)(q + s->ch[c].c0) << (8 * c);
        }
        if (D < ((int64_t)1 << 31)) {
            /* r - D + 2^31 in [2^31 - D, 2^31) as 32-bit lanes, (R, B) and
             * (G, A): a carry sets the lane's bit 31, never bit 32 (r + t
             * < 2D < 2^32), and one product takes D off both lanes */
            const uint64_t bias = ((uint64_t)1 << 31) - (uint64_t)D, lanes = 0x100000001u;
            const uint64_t d = (uint64_t)D;
            const uint64_t t0 = (uint64_t)s->etx[0] | (uint64_t)s->etx[2] << 32;
            const uint64_t t1 = (uint64_t)s->etx[1] | (uint64_t)s->etx[3] << 32;
            uint64_t p0 = ((uint64_t)r[0] + bias) | ((uint64_t)r[2] + bias) << 32;
            uint64_t p1 = ((uint64_t)r[1] + bias) | ((uint64_t)r[3] + bias) << 32;
            /* the levels R, G at bits 0, 8 and B, A at 32, 40, where the
             * carries land */
            uint64_t q = (qp & 0xFFFFu) | (uint64_t)(qp >> 16) << 32;
            const uint64_t sq = (uint64_t)s->esx[0] + ((uint64_t)s->esx[1] << 8) +
                                ((uint64_t)s->esx[2] << 32) + ((uint64_t)s->esx[3] << 40);
            for (; x < xb; x++, o += 4) {
                uint64_t c0, c1;
                uint32_t px = (uint32_t)(q | q >> 16);
                memcpy(o, &px, 4);
                p0 += t0;
                p1 += t1;
                c0 = (p0 >> 31) & lanes; /* R's carry at bit 0, B's at bit 32 */
                c1 = (p1 >> 31) & lanes;
                q += sq + c0 + (c1 << 8);
                p0 -= c0 * d;
                p1 -= c1 * d;
            }
        } else {
            int64_t r0 = r[0], r1 = r[1], r2 = r[2], r3 = r[3];
            const int64_t t0 = s->etx[0], t1 = s->etx[1], t2 = s->etx[2], t3 = s->etx[3];
            /* r - D kept in [-D, 0): a carry when it reaches 0 */
            r0 -= D;
            r1 -= D;
            r2 -= D;
            r3 -= D;
            for (; x < xb; x++, o += 4) {
                int64_t m0, m1, m2, m3; /* -1 where r - D reached 0: a carry */
                memcpy(o, &qp, 4);
                r0 += t0;
                r1 += t1;
                r2 += t2;
                r3 += t3;
                m0 = (int64_t)((uint64_t)r0 >> 63) - 1;
                m1 = (int64_t)((uint64_t)r1 >> 63) - 1;
                m2 = (int64_t)((uint64_t)r2 >> 63) - 1;
                m3 = (int64_t)((uint64_t)r3 >> 63) - 1;
                r0 -= D & m0;
                r1 -= D & m1;
                r2 -= D & m2;
                r3 -= D & m3;
                qp += sxp + (((uint32_t)m0 & 0x1u) | ((uint32_t)m1 & 0x100u) |
                             ((uint32_t)m2 & 0x10000u) | ((uint32_t)m3 & 0x1000000u));
            }
        }
    }
}

static void rast__shade_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__shade *s = (rast__shade *)user;
    int32_t k;
    if (s->flat) {
        s->solid_p.full(&s->solid, y, xs, n);
        return;
    }
    if (s->packed == 1) {
        rast__packed_row(s, y, xs, n);
        return;
    }
    if (s->packed == 2) {
        rast__exact_packed_row(s, y, xs, n);
        return;
    }
    for (k = 0; k < n; k++) rast__shade_span(s, y, xs[2 * k], xs[2 * k + 1]);
}

/* The Gouraud painter *p of s: full runs only (the triangle fillers'
 * spans); its user s, which rast__shade_begin sets up per triangle. */
static const rast__painter *rast__shade_painter(rast__shade *s, rast__painter *p)
{
    memset(p, 0, sizeof *p);
    p->full = rast__shade_row;
    p->user = s;
    return p;
}

/* The pixels a triangle's spans may reach, one axis: its vertices' extent
 * with two pixels to spare (textbook rounding and the boundary modes reach
 * at most one pixel past the triangle), cut to the clip. */
static void rast__shade_extent(int64_t a, int64_t b, int64_t c, const rast__shade *s,
                               int32_t lo, int32_t hi, int32_t *mn, int32_t *mx)
{
    int64_t min = a < b ? (a < c ? a : c) : (b < c ? b : c);
    int64_t max = a > b ? (a > c ? a : c) : (b > c ? b : c);
    /* floor((v - off) / unit) by a shift of the value made non-negative
     * (|v| < 2^29, unit = 2^shift) */
    const int64_t bias = (int64_t)1 << 40;
    int64_t i0 = (int64_t)((uint64_t)(min - s->off + bias) >> s->shift) - (bias >> s->shift) - 2;
    int64_t i1 = (int64_t)((uint64_t)(max - s->off + bias) >> s->shift) - (bias >> s->shift) + 2;
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
    int64_t d1 = c1 - c0, d2 = c2 - c0, t;
    ch->c0 = c0;
    ch->gx = d1 * ey2 - d2 * ey1;
    ch->gy = d2 * ex1 - d1 * ex2;
    if (neg) {
        ch->gx = -ch->gx;
        ch->gy = -ch->gy;
    }
    /* N fits int64_t over the box: each product below 2^60 */
    if (rast__bitlen(ch->gx) + s->blx > 60 || rast__bitlen(ch->gy) + s->bly > 60) s->narrow = 0;
    if (s->prec == RAST_PRECISION_FIXED) {
        /* base: (2 N 2^F + A) / D at the corner; steps: (2 g unit 2^F + A) / D */
        int64_t dx = (int64_t)s->imin * s->unit + s->off - s->x0;
        int64_t dy = (int64_t)s->jmin * s->unit + s->off - s->y0;
        int ok;
        if (s->narrow) {
            ok = rast__prod_div(dx * ch->gx + dy * ch->gy, 1, s->F + 1, s->A, &s->rd, &ch->fbase, &t);
        } else {
            rast__i128 N = rast__i128_add(rast__i128_mul(dx, ch->gx), rast__i128_mul(dy, ch->gy));
            ok = rast__i128_floordiv(rast__i128_add(rast__i128_shl(N, s->F + 1),
                                                    rast__i128_from(s->A)), s->D, &ch->fbase, &t);
        }
        ok &= rast__prod_div(ch->gx, s->unit, s->F + 1, s->A, &s->rd, &ch->fgx, &t);
        ok &= rast__prod_div(ch->gy, s->unit, s->F + 1, s->A, &s->rd, &ch->fgy, &t);
        /* base + 2^28 steps of each kind stays below 2^61; with the
         * columns and rows before the box (|imin|, |jmin| < 2^30), fc
         * stays below 5 * 2^60 */
        if (!ok || ch->fbase > ((int64_t)1 << 60) || ch->fbase < -((int64_t)1 << 60) ||
            rast__bitlen(ch->fgx) > 31 || rast__bitlen(ch->fgy) > 31)
            s->fixed = 0;
        else
            ch->fc = ch->c0 * ((int64_t)1 << s->F) + ch->fbase - (int64_t)s->imin * ch->fgx -
                     (int64_t)s->jmin * ch->fgy;
    }
}

/* Set up the packed fixed-point path for the current triangle (box and
 * reciprocal done, exact rounding): 0 when it does not apply (a big box for
 * F, magnitudes past the bounds below, steps the general path would reject),
 * then the general setup runs. */
static int rast__packed_setup(rast__shade *s, const uint8_t *col, int64_t ex1, int64_t ey1,
                              int64_t ex2, int64_t ey2, int neg)
{
    const int32_t F = s->F;
    const int64_t A = s->A, lim = (int64_t)1 << 60;
    int64_t dx = (int64_t)s->imin * s->unit + s->off - s->x0;
    int64_t dy = (int64_t)s->jmin * s->unit + s->off - s->y0;
    uint64_t v0[4], vx[4], vy[4];
    int32_t b, c;
    /* no lane carries (see the top) */
    if ((int64_t)(s->imax - s->imin) + (s->jmax - s->jmin) + 1 >= ((int64_t)1 << F)) return 0;
    /* b: |ex|, |ey|, |dx|, |dy| < 2^b, unit <= 2^(b - 2); so |gx|, |gy| <
     * 2^(b+9), |N| < 2^(2b+10) and the numerators below < 2^62 */
    b = rast__bitlen((ex1 < 0 ? -ex1 : ex1) | (ey1 < 0 ? -ey1 : ey1) | (ex2 < 0 ? -ex2 : ex2) |
                     (ey2 < 0 ? -ey2 : ey2) | (dx < 0 ? -dx : dx) | (dy < 0 ? -dy : dy) |
                     (4 * (int64_t)s->unit));
    if (2 * b + F + 12 > 62 || b + s->shift + F + 11 > 62) return 0;
    for (c = 0; c < 4; c++) {
        int64_t c0 = col[c], d1 = col[4 + c] - c0, d2 = col[8 + c] - c0;
        int64_t fb = 0, fx = 0, fy = 0, r;
        if (d1 | d2) { /* as rast__chan_setup, with the same roundings */
            int64_t gx = d1 * ey2 - d2 * ey1, gy = d2 * ex1 - d1 * ex2;
            if (neg) {
                gx = -gx;
                gy = -gy;
            }
            fb = rast__recip_floordiv(&s->rd, (dx * gx + dy * gy) * ((int64_t)1 << (F + 1)) + A, &r);
            fx = rast__recip_floordiv(&s->rd, gx * ((int64_t)1 << (s->shift + F + 1)) + A, &r);
            fy = rast__recip_floordiv(&s->rd, gy * ((int64_t)1 << (s->shift + F + 1)) + A, &r);
            if (fb > lim || fb < -lim || rast__bitlen(fx) > 31 || rast__bitlen(fy) > 31) return 0;
        }
        /* c 2^F + fbase - imin fgx - jmin fgy + 2^(F-1), modulo 2^64 */
        v0[c] = ((uint64_t)c0 << F) + (uint64_t)fb - (uint64_t)(int64_t)s->imin * (uint64_t)fx -
                (uint64_t)(int64_t)s->jmin * (uint64_t)fy + ((uint64_t)1 << (F - 1));
        vx[c] = (uint64_t)fx;
        vy[c] = (uint64_t)fy;
    }
    /* in units of 2^-16 level (2^-8 for G and A), so that every F has its
     * levels at the same bits */
    s->pk0[0] = (v0[0] + (v0[2] << 32)) << (16 - F);
    s->pk0[1] = (v0[1] + (v0[3] << 32)) << (24 - F);
    s->pkx[0] = (vx[0] + (vx[2] << 32)) << (16 - F);
    s->pkx[1] = (vx[1] + (vx[3] << 32)) << (24 - F);
    s->pky[0] = (vy[0] + (vy[2] << 32)) << (16 - F);
    s->pky[1] = (vy[1] + (vy[3] << 32)) << (24 - F);
    return 1;
}

/* Set up the exact packed path for the current triangle (box and
 * reciprocal done, exact rounding): 0 when it does not apply. */
static int rast__exact_packed_setup(rast__shade *s, const uint8_t *col, int64_t ex1,
                                    int64_t ey1, int64_t ex2, int64_t ey2, int neg)
{
    int64_t dx = (int64_t)s->imin * s->unit + s->off - s->x0;
    int64_t dy = (int64_t)s->jmin * s->unit + s->off - s->y0;
    int32_t b, c;
    /* b: |ex|, |ey|, |dx|, |dy| at the corner < 2^b, unit <= 2^(b - 2); over
     * the box |dx|, |dy| < 2^(b+3), |gx|, |gy| < 2^(b+9), so |R| < 2^(2b+15) */
    b = rast__bitlen((ex1 < 0 ? -ex1 : ex1) | (ey1 < 0 ? -ey1 : ey1) | (ex2 < 0 ? -ex2 : ex2) |
                     (ey2 < 0 ? -ey2 : ey2) | (dx < 0 ? -dx : dx) | (dy < 0 ? -dy : dy) |
                     (4 * (int64_t)s->unit));
    if (2 * b + 15 > 62) return 0;
    for (c = 0; c < 4; c++) {
        int64_t c0 = col[c], d1 = col[4 + c] - c0, d2 = col[8 + c] - c0;
        int64_t gx = d1 * ey2 - d2 * ey1, gy = d2 * ex1 - d1 * ex2;
        if (neg) {
            gx = -gx;
            gy = -gy;
        }
        s->ch[c].c0 = c0;
        s->ek[c] = 2 * (dx * gx + dy * gy) + s->A;
        s->egx[c] = gx * ((int64_t)2 << s->shift);
        s->egy[c] = gy * ((int64_t)2 << s->shift);
        s->esx[c] = rast__recip_floordiv(&s->rd, s->egx[c], &s->etx[c]);
    }
    return 1;
}

static int rast__shade_begin(void *user, const rast_point *t, uint32_t k, const rast__grid *g)
{
    rast__shade *s = (rast__shade *)user;
    const uint8_t *col = s->colors + 12 * (size_t)k;
    int64_t x0 = 2 * (int64_t)t[0].x, y0 = 2 * (int64_t)t[0].y;
    int64_t ex1 = 2 * (int64_t)t[1].x - x0, ey1 = 2 * (int64_t)t[1].y - y0;
    int64_t ex2 = 2 * (int64_t)t[2].x - x0, ey2 = 2 * (int64_t)t[2].y - y0;
    int64_t A = ex1 * ey2 - ey1 * ex2;
    int32_t c, neg = A < 0, plane;

    s->unit = g->unit;
    s->shift = g->shift;
    s->off = g->off;
    if (s->cull) { /* a band: a triangle whose rows (and a pixel to spare) miss it */
        int64_t y1 = y0 + ey1, y2 = y0 + ey2;
        int64_t lo = y0 < y1 ? (y0 < y2 ? y0 : y2) : (y1 < y2 ? y1 : y2);
        int64_t hi = y0 > y1 ? (y0 > y2 ? y0 : y2) : (y1 > y2 ? y1 : y2);
        if (hi < ((int64_t)s->solid.clip.y0 - 1) * s->unit ||
            lo > ((int64_t)s->solid.clip.y1 + 1) * s->unit)
            return 0;
    }

    if (s->flat) {
        s->fmt->pack(col, s->solid.value);
        return 1;
    }
    s->packed = 0;
    plane = A != 0;
    if (A == 0) { /* no plane: vertex 0's values (boundary modes only) */
        ex1 = ey1 = ex2 = ey2 = 0;
        A = 1;
    }
    s->A = neg ? -A : A;
    s->D = 2 * s->A;
    rast__recip_init(&s->rd, s->D);
    s->x0 = x0;
    s->y0 = y0;
    rast__shade_extent(x0, x0 + ex1, x0 + ex2, s, s->solid.clip.x0, s->solid.clip.x1, &s->imin,
                       &s->imax);
    rast__shade_extent(y0, y0 + ey1, y0 + ey2, s, s->solid.clip.y0, s->solid.clip.y1, &s->jmin,
                       &s->jmax);
    if (s->packable && !g->textbook && plane) {
        if (s->prec == RAST_PRECISION_FIXED && rast__packed_setup(s, col, ex1, ey1, ex2, ey2, neg))
            s->packed = 1;
        else if (s->prec == RAST_PRECISION_EXACT &&
                 rast__exact_packed_setup(s, col, ex1, ey1, ex2, ey2, neg))
            s->packed = 2;
        if (s->packed) return 1;
    }
    /* bits of the largest |px - x0|, |py - y0| over the box */
    {
        int64_t ax = s->x0 - ((int64_t)s->imin * s->unit + s->off);
        int64_t ay = s->y0 - ((int64_t)s->jmin * s->unit + s->off);
        s->blx = rast__bitlen((ax < 0 ? -ax : ax) + (int64_t)(s->imax - s->imin + 2) * s->unit);
        s->bly = rast__bitlen((ay < 0 ? -ay : ay) + (int64_t)(s->jmax - s->jmin + 2) * s->unit);
    }
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
    /* Exact stepping, 2 gx unit = sx D + tx, unless fixed point does it all */
    s->have_steps = s->prec != RAST_PRECISION_FIXED || !s->fixed;
    if (s->have_steps)
        for (c = 0; c <= RAST__CH_Z; c++)
            if ((c < s->nch || (c == RAST__CH_Z && s->z)) &&
                !rast__prod_div(s->ch[c].gx, s->unit, 1, 0, &s->rd, &s->ch[c].sx, &s->ch[c].tx))
                s->step = 0;
    return 1;
}

/* The painter for a checked format with colour, pixels at base (stride
 * bytes a row) holding pixel (ox, oy) of the target's plane, clip `clip`. */
static rast_status rast__shade_setup(rast__shade *s, rast_format format, unsigned char *base,
                                     ptrdiff_t stride, int32_t ox, int32_t oy,
                                     const rast_rect *clip, const uint8_t *colors,
                                     const int32_t *z, int32_t *zbuf, int32_t zstride,
                                     const rast_tri_opts *opts, const rast_shade_opts *shade)
{
    int32_t c;
    if ((unsigned)shade->precision > RAST_PRECISION_FLAT) return RAST_E_ARG;
    if (shade->precision == RAST_PRECISION_FIXED &&
        (shade->fraction_bits < 1 || shade->fraction_bits > 16))
        return RAST_E_ARG;
    memset(s, 0, sizeof *s);
    s->fmt = &rast__formats[format];
    if (!s->fmt->put) return RAST_E_FORMAT;
    s->base = base;
    s->stride = stride;
    s->ox = ox;
    s->oy = oy;
    s->zbuf = zbuf;
    s->zstride = zstride;
    s->colors = colors;
    s->z = z;
    s->prec = shade->precision;
    s->F = shade->fraction_bits;
    s->nch = s->fmt->channels;
    for (c = 0; c < 4; c++) {
        s->ch[c].lo = 0;
        s->ch[c].hi = 255;
    }
    s->ch[RAST__CH_Z].lo = INT32_MIN;
    s->ch[RAST__CH_Z].hi = INT32_MAX;
    /* the clip (the flat painter's too) */
    s->solid.clip = *clip;
    {
        const uint32_t one = 1;
        unsigned char low;
        memcpy(&low, &one, 1);
        s->packable = low == 1 && format == RAST_FORMAT_RGBA8888 && ox == 0 && oy == 0 &&
                      s->prec != RAST_PRECISION_FLAT && !z && opts->boundary == RAST_BOUNDARY_EXACT;
    }
    return RAST_OK;
}

rast_status rast_fill_triangles_shaded(const rast_target *target, const rast_point *tris,
                                       uint32_t ntris, const uint8_t *colors, const int32_t *z,
                                       int32_t *zbuf, const rast_tri_opts *opts,
                                       const rast_shade_opts *shade, void *scratch,
                                       size_t scratch_bytes)
{
    return rast__fill_shaded(target, tris, ntris, colors, z, zbuf, opts, shade, NULL, NULL,
                             scratch, scratch_bytes);
}

rast_status rast__fill_shaded(const rast_target *target, const rast_point *tris, uint32_t ntris,
                              const uint8_t *colors, const int32_t *z, int32_t *zbuf,
                              const rast_tri_opts *opts, const rast_shade_opts *shade,
                              rast__rgba_put_fn bput, const void *bctx, void *scratch,
                              size_t scratch_bytes)
{
    rast__shade s;
    rast__painter p;
    rast_rect clip;
    rast_status st;

    if (!target || !opts || !shade || (ntris > 0 && (!tris || !colors))) return RAST_E_NULL;
    if (!z != !zbuf) return RAST_E_NULL;
    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    st = rast__shade_setup(&s, target->format, (unsigned char *)target->pixels, target->stride,
                           0, 0, &clip, colors, z, zbuf, target->width, opts, shade);
    if (st != RAST_OK) return st;
    /* The solid painter: the flat colour without depth, and the clip. */
    {
        static const unsigned char zero[4] = {0, 0, 0, 0};
        st = rast__solid_init(&s.solid, target, &clip, zero, NULL, &s.solid_p);
        if (st != RAST_OK) return st;
    }
    s.flat = s.prec == RAST_PRECISION_FLAT && !z && !bput;
    if (bput) { /* every channel (alpha is the source's), through bput: not packed */
        s.bput = bput;
        s.bctx = bctx;
        s.nch = 4;
        s.packable = 0;
    }
    return rast__tri_fill(tris, ntris, opts, &clip, rast__shade_painter(&s, &p), rast__shade_begin,
                          scratch, scratch_bytes);
}

rast_status rast__shade_band(unsigned char *rgba, ptrdiff_t stride, const rast_rect *band,
                             const rast_point *tris, uint32_t ntris, const uint8_t *colors,
                             const rast_tri_opts *opts, const rast__grid *g,
                             const rast_shade_opts *shade, rast__tri_filler_fn filler,
                             void *scratch, size_t scratch_bytes)
{
    rast__shade s;
    rast__painter p;
    rast_status st = rast__shade_setup(&s, RAST_FORMAT_RGBA8888, rgba, stride, band->x0,
                                       band->y0, band, colors, NULL, NULL, 0, opts, shade);
    if (st != RAST_OK) return st;
    s.cull = 1;
    return filler(tris, ntris, opts, g, band, rast__shade_painter(&s, &p), rast__shade_begin,
                  scratch, scratch_bytes);
}

/* ref.h - the C tests' brute-force reference: DESIGN section 1, one sample
 * at a time, by cross-multiplication instead of division.  Coordinates are
 * doubled (unit = 2^(S+1) per pixel) so that a half-pixel sample is an
 * integer.  For a downward edge (y0 < y1 after swapping) crossing row yc,
 * the crossing X counts for the sample xc iff X <= xc (exact rounding), or
 * iff X < xc + 1/2 pixel (textbook rounding): iff
 * (xc - x0)(y1 - y0) >= (yc - y0)(x1 - x0), resp. with xc + unit/2 and >. */
#ifndef RAST_TEST_REF_H
#define RAST_TEST_REF_H

#include <stdint.h>

#include "rastrum.h"

/* Winding number of sample (i, j); *crossings (if not NULL) gets the number
 * of crossings counted, whose parity is the even-odd answer. */
static inline int ref_winding(const rast_point *pts, const uint32_t *sizes, uint32_t nrings, int s,
                       int center, int textbook, int64_t i, int64_t j, int *crossings)
{
    int64_t unit = (int64_t)2 << s, off = center ? ((int64_t)1 << s) : 0;
    int64_t xc = i * unit + off + (textbook ? unit / 2 : 0), yc = j * unit + off;
    uint32_t k, v, base = 0;
    int w = 0, n = 0;
    for (k = 0; k < nrings; base += sizes[k], k++) {
        for (v = 0; v < sizes[k]; v++) {
            rast_point a = pts[base + v], b = pts[base + (v + 1) % sizes[k]];
            int64_t x0 = 2 * (int64_t)a.x, y0 = 2 * (int64_t)a.y;
            int64_t x1 = 2 * (int64_t)b.x, y1 = 2 * (int64_t)b.y, lhs, rhs;
            int dir = 1;
            if (y0 == y1) continue;
            if (y0 > y1) {
                int64_t t;
                t = x0; x0 = x1; x1 = t;
                t = y0; y0 = y1; y1 = t;
                dir = -1;
            }
            if (!(y0 <= yc && yc < y1)) continue;
            lhs = (xc - x0) * (y1 - y0);
            rhs = (yc - y0) * (x1 - x0);
            if (textbook ? lhs > rhs : lhs >= rhs) {
                w += dir;
                n++;
            }
        }
    }
    if (crossings) *crossings = n;
    return w;
}

static inline int64_t ref_floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b < 0) ? q - 1 : q;
}

/* ---- the line, straight from the header (rast_draw_line) -----------------
 * Doubled coordinates (one pixel = U = 2^(s+1), sample offset O).  Major
 * pixel p is on the line iff its sample p*U + O lies between the endpoints;
 * its minor pixel *q is floor((y(p*U + O) - O + U/2) / U) with y the line
 * through the endpoints, as one fraction with a positive denominator.
 * Returns 0 when column (x-major) or row (y-major) p holds no pixel. */
static inline int ref_line_minor(rast_point a, rast_point b, int s, int center, int64_t p, int64_t *q)
{
    int64_t U = (int64_t)2 << s, O = center ? (int64_t)1 << s : 0;
    int64_t ax = 2 * (int64_t)a.x, ay = 2 * (int64_t)a.y, bx = 2 * (int64_t)b.x, by = 2 * (int64_t)b.y;
    int64_t adx = bx > ax ? bx - ax : ax - bx, ady = by > ay ? by - ay : ay - by, t;
    int64_t xs = p * U + O;
    if (ady > adx) { /* y-major: swap the axes */
        t = ax; ax = ay; ay = t;
        t = bx; bx = by; by = t;
    }
    if (bx < ax) { /* left to right */
        t = ax; ax = bx; bx = t;
        t = ay; ay = by; by = t;
    }
    if (xs < ax || xs > bx) return 0;
    if (bx == ax) {
        *q = ref_floor_div(ay - O + U / 2, U);
    } else {
        *q = ref_floor_div((ay - O + U / 2) * (bx - ax) + (xs - ax) * (by - ay), U * (bx - ax));
    }
    return 1;
}

/* Is pixel (i, j) one of the line a -> b's? */
static inline int ref_line_has(rast_point a, rast_point b, int s, int center, int64_t i, int64_t j)
{
    int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y, q = 0;
    if (dx < 0) dx = -dx;
    if (dy < 0) dy = -dy;
    if (dy > dx) return ref_line_minor(a, b, s, center, j, &q) && q == i;
    return ref_line_minor(a, b, s, center, i, &q) && q == j;
}

/* ---- 64-bit vertices (rast_polygon64) ------------------------------------------
 * The same rule with products of two int64_t compared exactly: each
 * product as a sign and a 128-bit magnitude, schoolbook on 32-bit halves
 * (no __int128: the 32-bit hosts of make cross-check have none). */
typedef struct ref_wide {
    int neg;         /* the product is negative (and not 0) */
    uint64_t hi, lo; /* its magnitude */
} ref_wide;

static inline ref_wide ref_mul(int64_t a, int64_t b)
{
    uint64_t ua = a < 0 ? 0 - (uint64_t)a : (uint64_t)a, ub = b < 0 ? 0 - (uint64_t)b : (uint64_t)b;
    uint64_t a0 = ua & 0xFFFFFFFFu, a1 = ua >> 32, b0 = ub & 0xFFFFFFFFu, b1 = ub >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1, mid, carry;
    ref_wide r;
    mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    carry = mid >> 32;
    r.lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + carry;
    r.neg = ((a < 0) != (b < 0)) && (r.hi | r.lo);
    return r;
}

/* -1, 0, 1 as x <, ==, > y. */
static inline int ref_cmp(ref_wide x, ref_wide y)
{
    int m;
    if (x.neg != y.neg) return x.neg ? -1 : 1;
    m = x.hi != y.hi ? (x.hi < y.hi ? -1 : 1) : x.lo != y.lo ? (x.lo < y.lo ? -1 : 1) : 0;
    return x.neg ? -m : m;
}

/* Winding number of sample (i, j) (|i|, |j| < 2^28) of 64-bit rings at S
 * (0..32), vertices within +-(2^(S+28) - 1): doubled coordinates and the
 * sample below 2^62, so every difference fits int64_t. */
static inline int ref_winding64(const rast_point64 *pts, const uint32_t *sizes, uint32_t nrings,
                                int s, int center, int64_t i, int64_t j)
{
    int64_t unit = (int64_t)2 << s, off = center ? ((int64_t)1 << s) : 0;
    int64_t xc = i * unit + off, yc = j * unit + off;
    uint32_t k, v, base = 0;
    int w = 0;
    for (k = 0; k < nrings; base += sizes[k], k++) {
        for (v = 0; v < sizes[k]; v++) {
            rast_point64 a = pts[base + v], b = pts[base + (v + 1) % sizes[k]];
            int64_t x0 = 2 * a.x, y0 = 2 * a.y, x1 = 2 * b.x, y1 = 2 * b.y, t;
            int dir = 1;
            if (y0 == y1) continue;
            if (y0 > y1) {
                t = x0; x0 = x1; x1 = t;
                t = y0; y0 = y1; y1 = t;
                dir = -1;
            }
            if (!(y0 <= yc && yc < y1)) continue;
            if (ref_cmp(ref_mul(xc - x0, y1 - y0), ref_mul(yc - y0, x1 - x0)) >= 0) w += dir;
        }
    }
    return w;
}

/* Does the closed segment a-b (units 1/2^s pixel, 64-bit) meet the open
 * square (i, i+1) x (j, j+1)?  The t in [0, 1] inside each open slab form
 * an interval; intersect the two, comparing fractions exactly. */
static inline int ref_touches64(rast_point64 a, rast_point64 b, int s, int64_t i, int64_t j)
{
    int64_t lo_n = 0, lo_d = 1, hi_n = 1, hi_d = 1;
    int lo_open = 0, hi_open = 0, axis, c;
    for (axis = 0; axis < 2; axis++) {
        int64_t p0 = axis ? a.y : a.x, d = (axis ? b.y : b.x) - p0, kk = axis ? j : i;
        int64_t L = kk * ((int64_t)1 << s), H = (kk + 1) * ((int64_t)1 << s), n0, n1;
        if (d == 0) {
            if (!(L < p0 && p0 < H)) return 0;
            continue;
        }
        if (d > 0) {
            n0 = L - p0;
            n1 = H - p0;
        } else {
            d = -d;
            n0 = p0 - H;
            n1 = p0 - L;
        }
        if (ref_cmp(ref_mul(n0, lo_d), ref_mul(lo_n, d)) >= 0) {
            lo_n = n0;
            lo_d = d;
            lo_open = 1;
        }
        if (ref_cmp(ref_mul(n1, hi_d), ref_mul(hi_n, d)) <= 0) {
            hi_n = n1;
            hi_d = d;
            hi_open = 1;
        }
    }
    c = ref_cmp(ref_mul(lo_n, hi_d), ref_mul(hi_n, lo_d));
    return c < 0 || (c == 0 && !lo_open && !hi_open);
}

/* Is pixel (i, j) in the 64-bit fill with options o (exact or
 * conservative boundary, exact rounding)? */
static inline int ref_polygon64(const rast_polygon64 *pg, const rast_fill_opts *o, int64_t i,
                                int64_t j)
{
    int s = o->subpixel_bits, w;
    uint32_t k, v, base = 0;
    w = ref_winding64(pg->points, pg->ring_sizes, pg->nrings, s, o->sample == RAST_SAMPLE_CENTER,
                      i, j);
    if (o->rule == RAST_RULE_EVENODD ? (w & 1) != 0 : w != 0) return 1;
    if (o->boundary != RAST_BOUNDARY_CONSERVATIVE) return 0;
    for (k = 0; k < pg->nrings; base += pg->ring_sizes[k], k++)
        for (v = 0; v < pg->ring_sizes[k]; v++)
            if (ref_touches64(pg->points[base + v], pg->points[base + (v + 1) % pg->ring_sizes[k]],
                              s, i, j))
                return 1;
    return 0;
}

#endif

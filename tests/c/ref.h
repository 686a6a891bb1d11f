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

#endif

/*
 * curve_ref.h - the curve references the flattener's checks share
 * (tests/c/test_path.c, tests/fuzz/fuzz_path.c), written apart from the
 * library: floor(sqrt) by bisection, the edge count of rastrum.h's
 * formula written out again, a Bezier point in long double, and the
 * squared distance from a point to a segment.  No libm: the tests link
 * none.
 */
#ifndef RAST_TEST_CURVE_REF_H
#define RAST_TEST_CURVE_REF_H

#include "rastrum.h"

/* floor(sqrt(v)) for v < 2^62, by bisection. */
static uint64_t ref_isqrt(uint64_t v)
{
    uint64_t lo = 0, hi = 1u << 31;
    while (lo < hi) {
        uint64_t mid = (lo + hi + 1) / 2;
        if (mid * mid <= v) lo = mid; else hi = mid - 1;
    }
    return lo;
}

/* The edge count of rastrum.h's formula for the curve q[0..d] (d = 2, 3)
 * at tolerance tol. */
static uint32_t ref_edges(const rast_point *q, int d, int32_t tol)
{
    uint64_t dd = 0, m, need, qq = 4 * (uint64_t)tol - 3, n;
    int k;
    for (k = 0; k + 2 <= d; k++) {
        int64_t dx = (int64_t)q[k].x - 2 * (int64_t)q[k + 1].x + q[k + 2].x;
        int64_t dy = (int64_t)q[k].y - 2 * (int64_t)q[k + 1].y + q[k + 2].y;
        uint64_t s = (uint64_t)(dx * dx + dy * dy);
        if (s > dd) dd = s;
    }
    m = ref_isqrt(dd);
    if (m * m < dd) m++;
    need = ((d == 3 ? 3 : 1) * m + qq - 1) / qq;
    n = ref_isqrt(need);
    if (n * n < need) n++;
    return n ? (uint32_t)n : 1;
}

/* The point of the Bezier curve q[0..d] at parameter t. */
static void ref_bezier(const rast_point *q, int d, long double t, long double *x, long double *y)
{
    long double s = 1 - t;
    if (d == 2) {
        *x = s * s * q[0].x + 2 * s * t * q[1].x + t * t * q[2].x;
        *y = s * s * q[0].y + 2 * s * t * q[1].y + t * t * q[2].y;
    } else {
        *x = s * s * s * q[0].x + 3 * s * s * t * q[1].x + 3 * s * t * t * q[2].x + t * t * t * q[3].x;
        *y = s * s * s * q[0].y + 3 * s * s * t * q[1].y + 3 * s * t * t * q[2].y + t * t * t * q[3].y;
    }
}

/* The squared distance from (px, py) to the segment ab. */
static long double ref_seg_d2(long double px, long double py, rast_point a, rast_point b)
{
    long double dx = (long double)b.x - a.x, dy = (long double)b.y - a.y;
    long double l2 = dx * dx + dy * dy, t = 0;
    if (l2 > 0) t = ((px - a.x) * dx + (py - a.y) * dy) / l2;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    dx = a.x + t * dx - px;
    dy = a.y + t * dy - py;
    return dx * dx + dy * dy;
}

#endif

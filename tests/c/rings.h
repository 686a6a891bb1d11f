/*
 * rings.h - random sets of small rings for the fill tests (test_delta.c,
 * test_delta_bytes.c): points on sample points, on sample rows or
 * anywhere, within a margin of 4 pixels around a W x H target; rings of
 * 3..6 vertices around a point, either way round, sometimes with a vertex
 * halfway along an edge (collinear), a repeated vertex, or one ring drawn
 * across the whole target.  Include after check.h (rng()) with the enum
 * constants W and H defined.
 */
#ifndef RAST_TEST_RINGS_H
#define RAST_TEST_RINGS_H

#include <string.h>

/* v rounded down to a multiple of 2^s. */
static int32_t floor_to(int32_t v, int s)
{
    const int32_t one = (int32_t)1 << s;
    int32_t m = v % one;
    return v - (m < 0 ? m + one : m);
}

/* A random point: on a sample point, on a sample row, or anywhere, within
 * a margin around the target (so that rings cross the clip's sides). */
static rast_point point(int s, int center)
{
    const int32_t one = (int32_t)1 << s, half = center ? one / 2 : 0;
    rast_point q;
    int kind = (int)(rng() % 3);
    q.x = (int32_t)(rng() % (uint32_t)((W + 8) * one)) - 4 * one;
    q.y = (int32_t)(rng() % (uint32_t)((H + 8) * one)) - 4 * one;
    if (kind == 0) { /* a sample point */
        q.x = floor_to(q.x, s) + half;
        q.y = floor_to(q.y, s) + half;
    } else if (kind == 1) { /* on a sample row */
        q.y = floor_to(q.y, s) + half;
    }
    return q;
}

/* Up to nrings small rings into pts[] (room for maxp points) and sizes[]:
 * returns the rings made, their points' count in *np. */
static uint32_t small_rings(rast_point *pts, uint32_t *sizes, uint32_t maxp, uint32_t nrings, int s,
                            int center, uint32_t *np)
{
    uint32_t k, v, n = 0;
    for (k = 0; k < nrings && n + 8 <= maxp; k++) {
        uint32_t m = 3 + rng() % 4, first = n;
        rast_point c0 = point(s, center);
        const int32_t r = (int32_t)(1 + rng() % 6) << s;
        for (v = 0; v < m; v++) {
            rast_point q = point(s, center);
            q.x = c0.x + (q.x % r);
            q.y = c0.y + (q.y % r);
            pts[n++] = q;
        }
        if (rng() % 4 == 0) { /* a collinear vertex between the first two */
            rast_point mid;
            mid.x = pts[first].x + (pts[first + 1].x - pts[first].x) / 2;
            mid.y = pts[first].y + (pts[first + 1].y - pts[first].y) / 2;
            if ((int64_t)(mid.x - pts[first].x) * (pts[first + 1].y - pts[first].y) ==
                (int64_t)(mid.y - pts[first].y) * (pts[first + 1].x - pts[first].x)) {
                memmove(&pts[first + 2], &pts[first + 1], (n - first - 1) * sizeof *pts);
                pts[first + 1] = mid;
                n++;
                m++;
            }
        }
        if (rng() % 8 == 0) pts[first + 2] = pts[first + 1]; /* a repeated vertex */
        if (rng() % 8 == 0) { /* one big ring across the target, the hole of its rings */
            pts[first].x = -(2 << s);
            pts[first].y = (int32_t)(rng() % H) << s;
            pts[first + 1].x = (W + 2) << s;
            pts[first + 1].y = pts[first].y + (int32_t)(rng() % 3);
        }
        sizes[k] = m;
    }
    *np = n;
    return k;
}

/* A triangle walked round n / 3 times (n points, a multiple of 3): the
 * winding number n / 3 inside it, past the byte counters' reach for the
 * larger counts. */
static void wound_triangle(rast_point *pts, uint32_t n)
{
    uint32_t v;
    for (v = 0; v < n; v += 3) {
        pts[v].x = 2 << 4;
        pts[v].y = 1 << 4;
        pts[v + 1].x = (W - 3) << 4;
        pts[v + 1].y = (H / 2) << 4;
        pts[v + 2].x = 5 << 4;
        pts[v + 2].y = (H - 2) << 4;
    }
}

#endif

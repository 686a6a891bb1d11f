/*
 * stroke_check.h - the bound of rastrum.h's "strokes", checked from its
 * definition at sample points (tests/c/test_stroke.c, tests/fuzz/
 * fuzz_stroke.c): the winding number of the outline at a point (exact,
 * 64-bit, the point off the grid), its distance to the flattened path
 * (squared, long double; no libm).  With h = width / 2, E the stated
 * error (round parts max(tolerance, 2), vertices sqrt(2)/2, a miter's
 * tip miter_limit + 1, all in units) plus a margin of 1:
 *   - the winding number is never negative (the pieces' winding numbers
 *     summed: path/stroke.c);
 *   - a point it covers is within R of the path: h + E with round joins
 *     and caps, h sqrt(2) + E with square caps or bevels, max(L, sqrt(2))
 *     h + E with miters (the tip's distance h / sin(theta/2) <= L h);
 *   - solid strokes: a point within h - E of a segment, its foot on the
 *     segment at least h + E from both ends, is covered; with round joins
 *     and caps (the Minkowski sum of the path and the disc of radius h) a
 *     point within h - E of the path is covered, whatever the foot.
 */
#ifndef RAST_STROKE_CHECK_H
#define RAST_STROKE_CHECK_H

#include "rastrum.h"

#include <string.h>

/* A stroke style of width w (grid units), the join and the cap, the
 * default miter limit (4) and the finest tolerance (one grid step). */
static inline rast_stroke_style sc_style(int32_t w, int join, int cap)
{
    rast_stroke_style s;
    memset(&s, 0, sizeof s);
    s.width = w;
    s.join = join;
    s.cap = cap;
    s.miter_limit = 4 * 65536;
    s.tolerance = 1;
    return s;
}

/* The winding number of the outline at (x + 1/4, y + 1/8) units. */
static int sc_winding(const rast_point *pts, const uint32_t *sizes, uint32_t nrings, int32_t x, int32_t y)
{
    int64_t px = 8 * (int64_t)x + 2, py = 8 * (int64_t)y + 1;
    uint32_t r, k, base = 0;
    int w = 0;
    for (r = 0; r < nrings; r++) {
        uint32_t n = sizes[r];
        for (k = 0; k < n; k++) {
            rast_point a = pts[base + k], b = pts[base + (k + 1) % n];
            int64_t ax = 8 * (int64_t)a.x, ay = 8 * (int64_t)a.y, bx = 8 * (int64_t)b.x, by = 8 * (int64_t)b.y;
            /* cross of (b - a) and (p - a) in long double: exact enough, the
             * point is never on an edge (it is off the 1/8 grid in y) */
            long double c = (long double)(bx - ax) * (long double)(py - ay) -
                            (long double)(by - ay) * (long double)(px - ax);
            if (ay <= py && py < by && c > 0) w++;
            else if (by <= py && py < ay && c < 0) w--;
        }
        base += n;
    }
    return w;
}

/* Squared distance from p to segment ab, and the foot's parameter. */
static long double sc_seg(long double px, long double py, rast_point a, rast_point b, long double *t_out,
                          long double *len2)
{
    long double dx = (long double)b.x - a.x, dy = (long double)b.y - a.y;
    long double l2 = dx * dx + dy * dy, t = 0;
    if (l2 > 0) t = ((px - a.x) * dx + (py - a.y) * dy) / l2;
    *t_out = t;
    *len2 = l2;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    dx = a.x + t * dx - px;
    dy = a.y + t * dy - py;
    return dx * dx + dy * dy;
}

typedef struct sc_path {
    const rast_point *pts; /* the flattened path (rast_path_flatten) */
    const uint32_t *sizes;
    uint32_t nrings;
} sc_path;

/* Check the bound at the point (x + 1/4, y + 1/8); 0: it fails. */
static int sc_check_point(const sc_path *fp, const rast_point *out, const uint32_t *osizes, uint32_t onrings,
                          const rast_stroke_style *st, int32_t x, int32_t y)
{
    long double px = x + 0.25L, py = y + 0.125L, h = st->width / 2.0L, best = -1, bin = -1, e, rout, lim;
    long double tol = st->tolerance > 2 ? st->tolerance : 2;
    int w = sc_winding(out, osizes, onrings, x, y), inner = 0, dashed = st->dash && st->ndash;
    uint32_t r, k, base = 0;
    lim = st->miter_limit / 65536.0L;
    e = 1 + (st->join == RAST_JOIN_ROUND || st->cap == RAST_CAP_ROUND ? tol : 1);
    if (st->join == RAST_JOIN_MITER) e += lim + 1;
    if (w < 0) return 0;
    for (r = 0; r < fp->nrings; r++) {
        uint32_t n = fp->sizes[r];
        for (k = 0; k < n; k++) {
            long double t, l2, d2;
            rast_point a = fp->pts[base + k], b = fp->pts[base + (k + 1 < n ? k + 1 : k)];
            if (k + 1 >= n) b = fp->pts[base]; /* the closing segment: counted for R only */
            d2 = sc_seg(px, py, a, b, &t, &l2);
            if (best < 0 || d2 < best) best = d2;
            if (k + 1 < n) /* not the closing segment (nor a lone point): stroked for sure */
                if (bin < 0 || d2 < bin) bin = d2;
            if (k + 1 < n && l2 > 0 && d2 < (h - e) * (h - e) && h > e) {
                /* the foot at least h + e from both ends: t l >= h + e */
                long double m = h + e;
                if (t >= 0 && t <= 1 && t * t * l2 >= m * m && (1 - t) * (1 - t) * l2 >= m * m) inner = 1;
            }
        }
        base += n;
    }
    if (best < 0) return w == 0; /* no path: no outline */
    if (st->join == RAST_JOIN_ROUND && st->cap == RAST_CAP_ROUND)
        rout = h + e;
    else if (st->join == RAST_JOIN_MITER)
        rout = (lim > 1.4143L ? lim : 1.4143L) * h + e;
    else
        rout = 1.4143L * h + e;
    if (w != 0 && best > rout * rout) return 0;
    if (!dashed && inner && w == 0) return 0;
    if (!dashed && st->join == RAST_JOIN_ROUND && st->cap == RAST_CAP_ROUND && h > e &&
        bin >= 0 && bin < (h - e) * (h - e) && w == 0)
        return 0;
    return 1;
}

/* The rings' total shoelace area is >= 0: the outline is the pieces'
 * chain plus cancelling edges (path/stroke.c), so its area is theirs, a
 * sum of non-negative areas.  (A closed subpath's inner ring turns
 * clockwise, so single rings may be negative.) */
static int sc_area_nonneg(const rast_point *out, const uint32_t *osizes, uint32_t onrings)
{
    uint32_t r, k, base = 0;
    long double s = 0;
    for (r = 0; r < onrings; r++) {
        uint32_t n = osizes[r];
        for (k = 0; k < n; k++) {
            rast_point a = out[base + k], b = out[base + (k + 1) % n];
            s += (long double)a.x * b.y - (long double)b.x * a.y;
        }
        base += n;
    }
    return s >= 0;
}

#endif

/*
 * flatten.c - a path's curves turned into edges, within a stated tolerance
 * (rast_path_flatten; the contract is in rastrum.h under "Paths", the
 * user's page docs/paths.md).
 *
 * The bound, proven.  Let B(t), 0 <= t <= 1, be a Bezier curve of degree
 * d (2 or 3) with control points P_0 .. P_d (integers, units u = 1/2^S
 * pixel), and n >= 1 the number of edges.  Its vertices are V_i = B(i/n)
 * exactly and W_i = V_i rounded per coordinate (floor(v + 1/2)); W_0 =
 * P_0 and W_n = P_d are integers already.
 *
 * 1. The second derivative.  B''(t) = d (d-1) sum_k D_k b_k(t), with D_k =
 *    P_k - 2 P_k+1 + P_k+2 (k = 0 .. d-2) and b_k the Bernstein
 *    polynomials of degree d-2, which are >= 0 and sum to 1; so B''(t) is
 *    d (d-1) times a convex combination of the D_k and |B''(t)| <= d (d-1)
 *    M, M = max_k |D_k| (Euclidean norm).
 * 2. One edge.  On [a, b] = [i/n, (i+1)/n], h = 1/n, let L(t) be the
 *    point of the chord V_i V_i+1 with the same fraction s = (t - a)/h.
 *    Taylor's formula with the integral remainder gives B(t) - L(t) =
 *    -integral of G(t, x) B''(x) dx over [a, b], with Green's function
 *    G >= 0 of integral (t - a)(b - t)/2 <= h^2/8; so
 *    |B(t) - L(t)| <= h^2/8 max |B''| <= d (d-1) M / (8 n^2) =: E.
 *    Every point B(t) of the curve is within E of the polyline (of L(t)),
 *    and every point L(t) of the polyline within E of the curve (of B(t)):
 *    the Hausdorff distance of curve and exact polyline is <= E.
 * 3. Rounding.  |W_i - V_i| <= sqrt(2)/2 u < 3/4 u.  The point (1-s) W_i +
 *    s W_i+1 of a rounded edge is within max(|W_i - V_i|, |W_i+1 - V_i+1|)
 *    of the point (1-s) V_i + s V_i+1 (the triangle inequality on the
 *    convex combination), and conversely; so rounded and exact polylines
 *    are within 3/4 u of each other both ways, and by the triangle
 *    inequality the curve and the rounded polyline are within E + 3/4 u.
 * 4. The count.  E + 3/4 <= T (T = tolerance, in u) iff
 *    d (d-1) M / (8 n^2) <= (4T - 3)/4 iff d (d-1) M <= 2 n^2 (4T - 3),
 *    that is c M <= n^2 (4T - 3) with c = 3 for a cubic (d (d-1) = 6)
 *    and c = 1 for a quadratic (d (d-1) = 2).  With m = ceil(sqrt(dd)) >=
 *    M (dd = max_k |D_k|^2, an exact integer) it suffices that
 *    n^2 >= ceil(c m / (4T - 3)); this file takes the smallest such n,
 *    n = ceil(sqrt(ceil(c m / (4T - 3)))), at least 1: Wang's formula.
 *    (T >= 1, so 4T - 3 >= 1.)
 * The vertices W_i are in the convex hull of the control points' pixel
 * boxes, so in range whenever the control points are.
 *
 * Ranges.  |coordinate| <= 2^27 - 1: |D_k| components <= 2^29, dd <=
 * 2^59, m <= 759,250,125 < 2^30, c m < 2^32, n <= ceil(sqrt(3 m)) =
 * 47,726 < 2^16.  Evaluation: V_i = P_0 + N/n^d with
 * N = sum of Bernstein numerators times (P_k - P_0), |P_k - P_0| < 2^28
 * and the numerators summing to n^d, so |N| < n^d 2^28: a quadratic's
 * |2N + n^2| < 2^61 and a cubic's with n <= 1024 < 2^59 in int64_t; a
 * cubic with n > 1024 (|N| < 2^75) in 128 bits (base/wide.h; the quotient,
 * a coordinate difference, is far inside rast__wide_floordiv's +-2^62).  Counts:
 * the total of flattened vertices is checked against RAST_MAX_POINTS as
 * it is summed (in 64 bits, each curve adding < 2^16).
 */
#include "path.h"
#include "../base/wide.h"

/* floor(sqrt(v)), bit by bit (no division, no float).  The first bit,
 * the highest power of 4 <= v (0 for v = 0), is found by halves: the
 * largest even shift S <= 62 with 2^62 >> S > v, binary digit by digit
 * (32, 16, .., 2: the test is monotone in S), then one step more; a build for size
 * steps down one power at a time. */
uint32_t rast__isqrt_floor(uint64_t v)
{
    uint64_t r = 0, bit = (uint64_t)1 << 62;
#ifdef __OPTIMIZE_SIZE__
    while (bit > v) bit >>= 2;
#else
    if (bit >> 32 > v) bit >>= 32;
    if (bit >> 16 > v) bit >>= 16;
    if (bit >> 8 > v) bit >>= 8;
    if (bit >> 4 > v) bit >>= 4;
    if (bit >> 2 > v) bit >>= 2;
    if (bit > v) bit >>= 2;
    /* each step taken or not by a mask, not a branch: the bits of a root
     * are as good as random, and half the steps' branches mispredicted
     * cost more than the step */
    while (bit) {
        uint64_t t = r + bit, take = (uint64_t)0 - (uint64_t)(v >= t);
        v -= t & take;
        r = (r >> 1) + (bit & take);
        bit >>= 2;
    }
    return (uint32_t)r;
#endif
    while (bit) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)r;
}

uint32_t rast__isqrt_ceil(uint64_t v)
{
    uint32_t r = rast__isqrt_floor(v);
    return (uint64_t)r * r < v ? r + 1 : r;
}

/* dd = max_k |D_k|^2, the largest squared second difference (step 4). */
static uint64_t curve_dd(const rast_point *p, int d)
{
    uint64_t dd = 0;
    int k;
    for (k = 0; k + 2 <= d; k++) {
        int64_t dx = (int64_t)p[k].x - 2 * (int64_t)p[k + 1].x + p[k + 2].x;
        int64_t dy = (int64_t)p[k].y - 2 * (int64_t)p[k + 1].y + p[k + 2].y;
        uint64_t s = (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
        if (s > dd) dd = s;
    }
    return dd;
}

#if !defined(__OPTIMIZE_SIZE__)
/* Whether n edges are enough (step 4 above, without a square root):
 * n^2 >= ceil(c m / q) iff n^2 q >= c m iff K = floor(n^2 q / c) >= m
 * (m an integer) iff K >= sqrt(dd) iff K^2 >= dd (K >= 0).  n <= 2^16, q
 * < 2^29: n^2 q < 2^61; K >= 2^30 is enough (dd <= 2^59). */
static int enough_edges(uint64_t n, uint64_t dd, uint64_t q, int d)
{
    uint64_t k = n * n * q;
    if (d == 3) k /= 3;
    return k >= ((uint64_t)1 << 30) || k * k >= dd;
}

/* The number of edges of a curve of degree d (2 or 3) with control points
 * p[0 .. d] at tolerance tol (step 4 above): the smallest n >= 1 that is
 * enough (enough_edges), by doubling from 1 and then halving the last
 * step, so ~2 log2(n) tests (a flat curve: one) and no square root (two
 * bit-by-bit roots cost ~330 instructions a curve); the same n as n =
 * ceil(sqrt(ceil(c m / (4T - 3)))), which a build for size computes so
 * (the smaller code). */
uint32_t rast__curve_edges(const rast_point *p, int d, int32_t tol)
{
    uint64_t dd = curve_dd(p, d), q = (uint64_t)4 * (uint64_t)tol - 3;
    uint32_t lo, hi, mid;
    /* enough(hi), not enough(lo) (lo = 0: below any count); hi <= 2^16 */
    for (lo = 0, hi = 1; !enough_edges(hi, dd, q, d); hi *= 2) lo = hi;
    while (hi - lo > 1) {
        mid = lo + (hi - lo) / 2;
        if (enough_edges(mid, dd, q, d))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}
#else
uint32_t rast__curve_edges(const rast_point *p, int d, int32_t tol)
{
    uint64_t m = rast__isqrt_ceil(curve_dd(p, d)), q = (uint64_t)4 * (uint64_t)tol - 3;
    uint32_t n = rast__isqrt_ceil(((d == 3 ? 3 : 1) * m + q - 1) / q);
    return n ? n : 1;
}
#endif

/* floor(num / den + 1/2) for den > 0, |2 num + den| < 2^62. */
static int32_t round_div(int64_t num, int64_t den)
{
    return (int32_t)rast__floordiv(2 * num + den, 2 * den);
}

/* One coordinate of B(i/n) rounded: c0 the start, c1.. the control
 * coordinates (d of them after c0), as in the file's comment. */
static int32_t eval_coord(const int32_t *c, int d, uint32_t i, uint32_t n)
{
    int64_t a = (int64_t)(n - i), b = (int64_t)i;
    if (d == 2) {
        int64_t num = 2 * a * b * ((int64_t)c[1] - c[0]) + b * b * ((int64_t)c[2] - c[0]);
        return c[0] + round_div(num, (int64_t)n * n);
    }
    if (n <= 1024) {
        int64_t num = 3 * a * a * b * ((int64_t)c[1] - c[0]) + 3 * a * b * b * ((int64_t)c[2] - c[0]) +
                      b * b * b * ((int64_t)c[3] - c[0]);
        return c[0] + round_div(num, (int64_t)n * n * n);
    } else {
        int64_t den = (int64_t)n * n * n, q, r;
        rast__i128 num = rast__i128_add(rast__i128_mul(3 * a * a * b, (int64_t)c[1] - c[0]),
                                        rast__i128_mul(3 * a * b * b, (int64_t)c[2] - c[0]));
        num = rast__i128_add(num, rast__i128_mul(b * b * b, (int64_t)c[3] - c[0]));
        num = rast__i128_add(rast__i128_shl(num, 1), rast__i128_from(den));
        rast__wide_floordiv(num, 2 * den, &q, &r);
        return c[0] + (int32_t)q;
    }
}

rast_point rast__curve_point(const rast_point *p, int d, uint32_t i, uint32_t n)
{
    int32_t xs[4], ys[4];
    rast_point w;
    int j;
    for (j = 0; j <= d; j++) {
        xs[j] = p[j].x;
        ys[j] = p[j].y;
    }
    w.x = eval_coord(xs, d, i, n);
    w.y = eval_coord(ys, d, i, n);
    return w;
}

#if !defined(__OPTIMIZE_SIZE__)
/* The points of a curve by forward differences (not in a build for size:
 * there each point is eval_coord's, the same points in less code).  Per
 * coordinate, with e_k = c_k - c_0, B(t) - c_0 = a t + b t^2 + g t^3: a
 * = 3 e1, b = 3 (e2 - 2 e1), g = e3 - 3 e2 + 3 e1 (cubic); a = 2 e1, b =
 * e2 - 2 e1, g = 0 (quadratic).  eval_coord's rounded value is c_0 +
 * floor(X(i) / D), X(i) = 2 n^3 (B(i/n) - c_0) + n^3 = 2 (a n^2 i + b n
 * i^2 + g i^3) + n^3, D = 2 n^3 (a quadratic's numerator and denominator
 * there times n: the same quotient).  X is a cubic in i: X(0) = n^3, its
 * differences X(1) - X(0) = 2 (a n^2 + b n + g), the second 2 (2 b n + 6
 * g), the third 12 g; each of the four is kept as q D + r, 0 <= r < D, and
 * a step adds them pairwise (a carry when a remainder reaches D): exact,
 * no division but three per coordinate at the start (two for a
 * quadratic).  Ranges: |e_k| < 2^28, so |a| < 3 2^28, |b| < 9 2^28, |g| <
 * 8 2^28; n <= 47,726 (a quadratic's <= 27,555), so |a n^2| < 2^61 and the
 * first difference is < 2^62, the others far less; D < 2^48, r + dr <
 * 2^49.  The quotients: X/D - 1/2 = B(t) - c_0 with t = j/n <= 2 (the last
 * step makes a second difference that reaches X(n + 1), never used), so
 * |X/D| < (6 + 36 + 64) 2^28 + 1 < 2^35, and a difference of up to four
 * such values is < 2^37: far inside int64_t. */
typedef struct flat_fd {
    int64_t q0, r0, q1, r1, q2, r2, q3, r3;
} flat_fd;

static void fd_part(int64_t v, int64_t den, int64_t *q, int64_t *r)
{
    *q = rast__floordiv(v, den);
    *r = v - *q * den;
}

static void fd_start(flat_fd *s, const int32_t *c, int d, int64_t n)
{
    int64_t e1 = (int64_t)c[1] - c[0], e2 = (int64_t)c[2] - c[0], a, b, g, den = 2 * n * n * n;
    if (d == 3) {
        a = 3 * e1;
        b = 3 * (e2 - 2 * e1);
        g = (int64_t)c[3] - c[0] - 3 * e2 + 3 * e1;
    } else {
        a = 2 * e1;
        b = e2 - 2 * e1;
        g = 0;
    }
    s->q0 = 0;
    s->r0 = n * n * n;
    fd_part(2 * (a * n * n + b * n + g), den, &s->q1, &s->r1);
    fd_part(2 * (2 * b * n + 6 * g), den, &s->q2, &s->r2);
    if (d == 3) fd_part(12 * g, den, &s->q3, &s->r3); /* a quadratic's is 0, not used */
}

/* (q, r) += (dq, dr), r kept in [0, den). */
RAST__HOT void fd_add(int64_t *q, int64_t *r, int64_t dq, int64_t dr, int64_t den)
{
    *q += dq;
    *r += dr;
    if (*r >= den) {
        *r -= den;
        *q += 1;
    }
}

/* One step, i to i + 1 (the third difference is constant). */
RAST__HOT void fd_step(flat_fd *s, int cubic, int64_t den)
{
    fd_add(&s->q0, &s->r0, s->q1, s->r1, den);
    fd_add(&s->q1, &s->r1, s->q2, s->r2, den);
    if (cubic) fd_add(&s->q2, &s->r2, s->q3, s->r3, den);
}

/* The points i = 1 .. n - 1 of the curve q[0 .. d] into out[0 .. n - 1),
 * each eval_coord's (n >= 2). */
RAST__HOT void fd_points(rast_point *out, const rast_point *q, int cubic, uint32_t n)
{
    int32_t xs[4], ys[4];
    flat_fd fx, fy;
    int64_t den = 2 * (int64_t)n * n * n;
    uint32_t i;
    int j, d = cubic ? 3 : 2;
    for (j = 0; j <= d; j++) {
        xs[j] = q[j].x;
        ys[j] = q[j].y;
    }
    fd_start(&fx, xs, d, n);
    fd_start(&fy, ys, d, n);
    for (i = 1; i < n; i++) {
        fd_step(&fx, cubic, den);
        fd_step(&fy, cubic, den);
        out[i - 1].x = xs[0] + (int32_t)fx.q0;
        out[i - 1].y = ys[0] + (int32_t)fy.q0;
    }
}

/* The curve's points i = 1 .. n - 1 into out (n >= 2). */
static void curve_points(rast_point *out, const rast_point *q, int d, uint32_t n)
{
    if (d == 3)
        fd_points(out, q, 1, n);
    else
        fd_points(out, q, 0, n);
}
#endif

static int in_range(rast_point p)
{
    return p.x >= -RAST_COORD_MAX && p.x <= RAST_COORD_MAX && p.y >= -RAST_COORD_MAX &&
           p.y <= RAST_COORD_MAX;
}

static void put(rast__flat *f, rast_point p)
{
    if (f->points) {
        f->points[f->npoints] = p;
        f->ring_sizes[f->nrings - 1]++;
    }
    f->npoints++;
}

static void open_ring(rast__flat *f, rast_point p)
{
    if (f->points) {
        f->ring_sizes[f->nrings] = 0;
        if (f->closed) f->closed[f->nrings] = 0;
    }
    f->nrings++;
    put(f, p);
}

/* Check the path: verbs, the point count, the range, the tolerance. */
static rast_status check_path(const rast_path *path, int32_t tolerance)
{
    static const uint8_t takes[RAST_PATH_VERB_COUNT_] = {1, 1, 2, 3, 0};
    uint64_t need = 0;
    uint32_t k;
    if (!path) return RAST_E_NULL;
    if ((path->nverbs && !path->verbs) || (path->npoints && !path->points)) return RAST_E_NULL;
    if (tolerance < 1 || tolerance > RAST_COORD_MAX) return RAST_E_ARG;
    for (k = 0; k < path->nverbs; k++) {
        if (path->verbs[k] >= RAST_PATH_VERB_COUNT_) return RAST_E_ARG;
        need += takes[path->verbs[k]];
    }
    if (path->nverbs && path->verbs[0] != RAST_PATH_MOVE) return RAST_E_ARG;
    if (need != path->npoints) return RAST_E_ARG;
    for (k = 0; k < path->npoints; k++)
        if (!in_range(path->points[k])) return RAST_E_RANGE;
    return RAST_OK;
}

rast_status rast__path_flatten(const rast_path *path, int32_t tolerance, rast__flat *f)
{
    rast_status st = check_path(path, tolerance);
    const rast_point *p;
    rast_point cur = {0, 0}, start = {0, 0};
    int open = 0;
    uint64_t total = 0, room = UINT64_MAX; /* total: f->npoints; room: the vertices f can take */
    uint32_t k, rings = UINT32_MAX;        /* rings: the subpaths f can take */
    if (st != RAST_OK) return st;
    if (f->points && f->max_points && f->max_rings) { /* (path.h: a room given, not a count) */
        room = f->max_points;
        rings = f->max_rings;
    }
    p = path->points;
    for (k = 0; k < path->nverbs; k++) {
        int v = path->verbs[k];
        if (v == RAST_PATH_MOVE) {
            cur = start = *p++;
            if (f->nrings >= rings || total >= room) return RAST_E_SCRATCH;
            open_ring(f, cur);
            open = 1;
            total++;
        } else if (v == RAST_PATH_CLOSE) {
            if (open && f->points && f->closed) f->closed[f->nrings - 1] = 1;
            open = 0;
            cur = start;
        } else {
            if (!open) { /* SVG: a new subpath at the closed one's start */
                if (f->nrings >= rings || total >= room) return RAST_E_SCRATCH;
                open_ring(f, start);
                open = 1;
                total++;
            }
            if (v == RAST_PATH_LINE) {
                cur = *p++;
                if (total >= room) return RAST_E_SCRATCH;
                put(f, cur);
                total++;
            } else {
                int d = v; /* RAST_PATH_QUAD = 2, RAST_PATH_CUBIC = 3: the degree */
                rast_point q[4];
                uint32_t n;
                int j;
                q[0] = cur;
                for (j = 1; j <= d; j++) q[j] = *p++;
                n = rast__curve_edges(q, d, tolerance);
                total += n;
                if (total > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
                if (total > room) return RAST_E_SCRATCH;
#if !defined(__OPTIMIZE_SIZE__)
                if (f->points) {
                    if (n > 1) curve_points(f->points + f->npoints, q, d, n);
                    f->points[f->npoints + n - 1] = q[d];
                    f->ring_sizes[f->nrings - 1] += n;
                }
                f->npoints += n;
#else /* a build for size: each point eval_coord's (the smaller code) */
                if (f->points) {
                    int32_t xs[4], ys[4];
                    uint32_t i;
                    for (j = 0; j <= d; j++) {
                        xs[j] = q[j].x;
                        ys[j] = q[j].y;
                    }
                    for (i = 1; i < n; i++) {
                        rast_point w;
                        w.x = eval_coord(xs, d, i, n);
                        w.y = eval_coord(ys, d, i, n);
                        put(f, w);
                    }
                    put(f, q[d]);
                } else {
                    f->npoints += n;
                }
#endif
                cur = q[d];
            }
        }
        if (total > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    return RAST_OK;
}

rast_status rast_path_flatten_size(const rast_path *path, int32_t tolerance, uint32_t *npoints,
                                   uint32_t *nrings)
{
    rast__flat f;
    rast_status st;
    if (!npoints || !nrings) return RAST_E_NULL;
    memset(&f, 0, sizeof f);
    st = rast__path_flatten(path, tolerance, &f);
    if (st != RAST_OK) return st;
    *npoints = f.npoints;
    *nrings = f.nrings;
    return RAST_OK;
}

rast_status rast_path_flatten(const rast_path *path, int32_t tolerance, rast_point *points,
                              uint32_t max_points, uint32_t *ring_sizes, uint32_t max_rings,
                              rast_polygon *polygon)
{
    rast__flat f;
    uint32_t np, nr;
    rast_status st = rast_path_flatten_size(path, tolerance, &np, &nr);
    if (st != RAST_OK) return st;
    if (!points || !ring_sizes || !polygon) return RAST_E_NULL;
    if (np > max_points || nr > max_rings) return RAST_E_SCRATCH;
    memset(&f, 0, sizeof f);
    f.points = points;
    f.ring_sizes = ring_sizes;
    st = rast__path_flatten(path, tolerance, &f);
    if (st != RAST_OK) return st;
    polygon->points = points;
    polygon->ring_sizes = ring_sizes;
    polygon->nrings = nr;
    return RAST_OK;
}

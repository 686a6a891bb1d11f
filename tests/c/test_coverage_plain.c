/*
 * test_coverage_plain.c - rast__cov_plain, the test that lets "area" take
 * a polygon by the accumulation, against a brute force written apart from
 * it: every pair of edges tested, and the winding number sampled on a grid
 * finer than the vertices' (no sweep, no sort).  Small random rings on a
 * grid of a few points (vertices shared, on edges, collinear, crossing),
 * rings sorted around a point (mostly simple), nested and side by side,
 * coordinates at the range's ends; and named cases.
 */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "coverage/coverage.h"

static uint64_t scratch[1 << 12];

typedef struct { int64_t x, y; } pt;

static int64_t orient(pt a, pt b, pt c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

/* c on the closed segment [a, b] */
static int on_seg(pt a, pt b, pt c)
{
    if (orient(a, b, c) != 0) return 0;
    return (c.x - a.x) * (c.x - b.x) <= 0 && (c.y - a.y) * (c.y - b.y) <= 0;
}

static int sgn(int64_t v) { return (v > 0) - (v < 0); }

/* the closed segments [p, q] and [r, t] share a point */
static int meet(pt p, pt q, pt r, pt t)
{
    if (sgn(orient(p, q, r)) * sgn(orient(p, q, t)) < 0 && sgn(orient(r, t, p)) * sgn(orient(r, t, q)) < 0)
        return 1;
    return on_seg(p, q, r) || on_seg(p, q, t) || on_seg(r, t, p) || on_seg(r, t, q);
}

#define MAXV 64

/* The rings with their edges of length 0 dropped: v[k], ring of each. */
static int compact(const rast_point *p, const uint32_t *sizes, uint32_t nrings, pt *v, int *ring, int *start,
                   int *count)
{
    uint32_t r, i, base = 0;
    int n = 0;
    for (r = 0; r < nrings; base += sizes[r], r++) {
        start[r] = n;
        for (i = 0; i < sizes[r]; i++) {
            rast_point a = p[base + i], b = p[base + (i + 1) % sizes[r]];
            if (a.x == b.x && a.y == b.y) continue;
            v[n].x = a.x;
            v[n].y = a.y;
            ring[n++] = (int)r;
        }
        count[r] = n - start[r];
        if (count[r] < 3) return -1;
    }
    return n;
}

static int brute_plain(const rast_point *p, const uint32_t *sizes, uint32_t nrings)
{
    pt v[MAXV], lo, hi;
    int ring[MAXV], start[8], count[8], n, i, j, pos = 0, neg = 0;
    int64_t X, Y;
    n = compact(p, sizes, nrings, v, ring, start, count);
    if (n < 0) return 0;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (v[i].x == v[j].x && v[i].y == v[j].y) return 0;
    for (i = 0; i < n; i++) {
        int ni = start[ring[i]] + (i - start[ring[i]] + 1) % count[ring[i]];
        for (j = i + 1; j < n; j++) {
            int nj = start[ring[j]] + (j - start[ring[j]] + 1) % count[ring[j]];
            if (ni == j) { /* i then j, at v[j]: no other common point */
                if (on_seg(v[j], v[nj], v[i]) || on_seg(v[i], v[j], v[nj])) return 0;
            } else if (nj == i) {
                if (on_seg(v[i], v[ni], v[j]) || on_seg(v[j], v[i], v[ni])) return 0;
            } else if (meet(v[i], v[ni], v[j], v[nj])) {
                return 0;
            }
        }
    }
    /* the faces: the winding number at points between the vertices' grid
     * (times 8, at odd coordinates, off the edges) */
    lo = hi = v[0];
    for (i = 1; i < n; i++) {
        if (v[i].x < lo.x) lo.x = v[i].x;
        if (v[i].y < lo.y) lo.y = v[i].y;
        if (v[i].x > hi.x) hi.x = v[i].x;
        if (v[i].y > hi.y) hi.y = v[i].y;
    }
    for (Y = 8 * lo.y - 1; Y <= 8 * hi.y + 1; Y += 2)
        for (X = 8 * lo.x - 1; X <= 8 * hi.x + 1; X += 2) {
            pt q;
            int w = 0, on = 0;
            q.x = X;
            q.y = Y;
            for (i = 0; i < n; i++) {
                int ni = start[ring[i]] + (i - start[ring[i]] + 1) % count[ring[i]];
                pt a, b;
                a.x = 8 * v[i].x;
                a.y = 8 * v[i].y;
                b.x = 8 * v[ni].x;
                b.y = 8 * v[ni].y;
                if (on_seg(a, b, q)) on = 1;
                /* a ray to the right: edges going up cross it +1, down -1 */
                if ((a.y <= Y) != (b.y <= Y)) {
                    int64_t o = orient(a, b, q);
                    if (a.y <= Y && o > 0) w++;
                    if (b.y <= Y && o < 0) w--;
                }
            }
            if (on) continue;
            if (w > 1 || w < -1) return 0;
            pos |= w == 1;
            neg |= w == -1;
        }
    return !(pos && neg);
}

/* a disagreement, on stderr */
static void show(const rast_point *p, const uint32_t *sizes, uint32_t nrings, int got, int want)
{
    uint32_t r, i, base = 0;
    fprintf(stderr, "rast__cov_plain %d, brute force %d:", got, want);
    for (r = 0; r < nrings; base += sizes[r], r++) {
        fprintf(stderr, " [");
        for (i = 0; i < sizes[r]; i++) fprintf(stderr, " (%d, %d)", (int)p[base + i].x, (int)p[base + i].y);
        fprintf(stderr, " ]");
    }
    fprintf(stderr, "\n");
    CHECK(got == want);
}

static int plain(const rast_point *p, const uint32_t *sizes, uint32_t nrings)
{
    rast_polygon poly;
    uint32_t k, np = 0;
    for (k = 0; k < nrings; k++) np += sizes[k];
    poly.points = p;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    return rast__cov_plain(&poly, np, rast__arena_of(scratch, sizeof scratch));
}

/* A ring of n points sorted by angle round (cx, cy) (by quadrant and
 * cross products: no floating point). */
static void star_ring(rast_point *p, uint32_t n, int32_t cx, int32_t cy, int32_t r)
{
    uint32_t i, j;
    for (i = 0; i < n; i++) {
        p[i].x = cx + (int32_t)(rng() % (uint32_t)(2 * r + 1)) - r;
        p[i].y = cy + (int32_t)(rng() % (uint32_t)(2 * r + 1)) - r;
    }
    for (i = 1; i < n; i++) /* insertion sort by angle */
        for (j = i; j > 0; j--) {
            pt a, b, c;
            int ha, hb;
            a.x = p[j - 1].x - cx;
            a.y = p[j - 1].y - cy;
            b.x = p[j].x - cx;
            b.y = p[j].y - cy;
            ha = a.y < 0 || (a.y == 0 && a.x < 0);
            hb = b.y < 0 || (b.y == 0 && b.x < 0);
            c.x = c.y = 0;
            if (ha < hb || (ha == hb && orient(c, a, b) >= 0)) break;
            {
                rast_point t = p[j - 1];
                p[j - 1] = p[j];
                p[j] = t;
            }
        }
}

static void reverse(rast_point *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n / 2; i++) {
        rast_point t = p[i];
        p[i] = p[n - 1 - i];
        p[n - 1 - i] = t;
    }
}

static void named(void)
{
    static const rast_point sq[4] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}};
    rast_point p[16];
    uint32_t s[3] = {4, 4, 4};
    CHECK(plain(sq, s, 1) == 1);
    /* a hole the other way round: plain; the same way: w = 2 inside */
    memcpy(p, sq, sizeof sq);
    p[4].x = 2, p[4].y = 2, p[5].x = 2, p[5].y = 6, p[6].x = 6, p[6].y = 6, p[7].x = 6, p[7].y = 2;
    CHECK(plain(p, s, 2) == 1);
    reverse(p + 4, 4);
    CHECK(plain(p, s, 2) == 0);
    /* side by side, one way: plain; opposite ways: -1 and 1 */
    p[4].x = 10, p[4].y = 0, p[5].x = 14, p[5].y = 0, p[6].x = 14, p[6].y = 4, p[7].x = 10, p[7].y = 4;
    CHECK(plain(p, s, 2) == 1);
    reverse(p + 4, 4);
    CHECK(plain(p, s, 2) == 0);
    /* touching at a corner, at a vertex on an edge, along an edge */
    p[4].x = 8, p[4].y = 8, p[5].x = 12, p[5].y = 8, p[6].x = 12, p[6].y = 12, p[7].x = 8, p[7].y = 12;
    CHECK(plain(p, s, 2) == 0);
    p[4].x = 8, p[4].y = 4, p[5].x = 12, p[5].y = 2, p[6].x = 12, p[6].y = 6, p[7].x = 10, p[7].y = 6;
    CHECK(plain(p, s, 2) == 0);
    p[4].x = 8, p[4].y = 2, p[5].x = 12, p[5].y = 2, p[6].x = 12, p[6].y = 6, p[7].x = 8, p[7].y = 6;
    CHECK(plain(p, s, 2) == 0);
    /* a bow tie; a spike back along an edge; a vertex visited twice */
    {
        static const rast_point bow[4] = {{0, 0}, {8, 8}, {8, 0}, {0, 8}};
        static const rast_point spike[5] = {{0, 0}, {8, 0}, {4, 0}, {4, 8}, {0, 8}};
        static const rast_point twice[6] = {{0, 0}, {4, 4}, {8, 0}, {8, 8}, {4, 4}, {0, 8}};
        static const rast_point flat[4] = {{0, 0}, {4, 0}, {8, 0}, {2, 0}};
        static const rast_point dup[6] = {{0, 0}, {0, 0}, {8, 0}, {8, 8}, {8, 8}, {0, 8}};
        static const rast_point vert[5] = {{0, 0}, {0, 8}, {0, 4}, {4, 4}, {4, 0}};
        uint32_t n4 = 4, n5 = 5, n6 = 6;
        CHECK(plain(bow, &n4, 1) == 0);
        CHECK(plain(spike, &n5, 1) == 0);
        CHECK(plain(twice, &n6, 1) == 0);
        CHECK(plain(flat, &n4, 1) == 0);
        CHECK(plain(dup, &n6, 1) == 1); /* repeated points are edges of length 0 */
        CHECK(plain(vert, &n5, 1) == 0);
    }
}

int main(void)
{
    rast_point p[MAXV];
    uint32_t sizes[4];
    int t, agree = 0, yes = 0, scaled = 0, n = check_count(200000);
    named();
    for (t = 0; t < n; t++) {
        uint32_t nr = 1 + rng() % 3, r, k = 0, kind = rng() % 4;
        int32_t scale = rng() % 8 == 0 ? (int32_t)(RAST_COORD_MAX / 6 - rng() % 1000) : 1;
        for (r = 0; r < nr; r++) {
            sizes[r] = 3 + rng() % 6;
            if (kind == 0) { /* anything on a 5 x 5 grid */
                uint32_t i;
                for (i = 0; i < sizes[r]; i++) {
                    p[k + i].x = (int32_t)(rng() % 5);
                    p[k + i].y = (int32_t)(rng() % 5);
                }
            } else { /* round a point: side by side (1), nested (2), anywhere (3) */
                int32_t c = kind == 1 ? 8 * (int32_t)r : 6, rad = kind == 2 ? 6 - 2 * (int32_t)r : 3;
                star_ring(p + k, sizes[r], c, kind == 3 ? (int32_t)(rng() % 9) : 6, rad < 1 ? 1 : rad);
                if (rng() % 2) reverse(p + k, sizes[r]);
            }
            k += sizes[r];
        }
        {
            /* scaled by up to (2^27 - 1) / 6 round (6, 6), the coordinates
             * reach the range's ends; a plane's scaling (by a positive
             * factor) keeps the answer */
            int want = brute_plain(p, sizes, nr), got;
            scaled += scale > 1;
            uint32_t i;
            for (i = 0; i < k; i++) /* (only shapes within 6 of (6, 6)) */
                if (p[i].x < 0 || p[i].x > 12 || p[i].y < 0 || p[i].y > 12) scale = 1;
            if (scale > 1) {
                for (i = 0; i < k; i++) {
                    p[i].x = (p[i].x - 6) * scale;
                    p[i].y = (p[i].y - 6) * scale;
                }
            }
            got = plain(p, sizes, nr);
            if (got == want)
                agree++;
            else
                show(p, sizes, nr, got, want);
            yes += got;
        }
    }
    CHECK(agree == n);
    CHECK(yes > n / 20);   /* the plain case is not rare */
    CHECK(scaled > n / 20); /* nor the range's ends */
    printf("test_coverage_plain: %d cases, %d plain\n", n, yes);
    return check_report("test_coverage_plain");
}

/*
 * test_coverage_chains.c - the plain test of a part (coverage_plain.c:
 * rast__pl_chains, the sweep of x-monotone chains, and the sweep by edges
 * where it gives up) against a brute-force oracle of its three conditions
 * written here: every pair of edges tested for a common point, the
 * winding number of every other ring by crossings.  Random parts of 2 to 4
 * rings inside one pixel (S = 8: coordinates 0 .. 255, so the rings are
 * one part and rast__cov_plain_parts's answer is the part's), on coarse
 * grids where vertices coincide, edges overlap, touch and cross, rings
 * nest either way, and edges of length 0 and vertical edges are common;
 * the answer must be the oracle's, yes and no.  Plain parts are found by
 * the accumulation ("area"'s rows), so a wrong yes is a wrong level
 * (issue 34).
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 34u
#include "check.h"
#include "coverage/coverage.h"

static uint64_t scratch[1 << 14];
static rast__cedge edges[64];

#define MAXV 12

typedef struct {
    rast_point p[MAXV];
    uint32_t n;
} ring;

static int64_t cross(rast_point a, rast_point b, rast_point c)
{
    return ((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

static int same(rast_point a, rast_point b)
{
    return a.x == b.x && a.y == b.y;
}

/* c on segment ab, given the three on one line */
static int within(rast_point a, rast_point b, rast_point c)
{
    return (a.x < b.x ? a.x : b.x) <= c.x && c.x <= (a.x < b.x ? b.x : a.x) && (a.y < b.y ? a.y : b.y) <= c.y &&
           c.y <= (a.y < b.y ? b.y : a.y);
}

/* do segments pq and rt have a point in common? */
static int meet(rast_point p, rast_point q, rast_point r, rast_point t)
{
    const int64_t d1 = cross(r, t, p), d2 = cross(r, t, q), d3 = cross(p, q, r), d4 = cross(p, q, t);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 1;
    return (d1 == 0 && within(r, t, p)) || (d2 == 0 && within(r, t, q)) || (d3 == 0 && within(p, q, r)) ||
           (d4 == 0 && within(p, q, t));
}

/* winding number of ring g at p (not on it) */
static int winding(const ring *g, rast_point p)
{
    int w = 0;
    uint32_t k;
    for (k = 0; k < g->n; k++) {
        const rast_point a = g->p[k], b = g->p[(k + 1) % g->n];
        if (a.y <= p.y && p.y < b.y && cross(a, b, p) > 0) w++;
        if (b.y <= p.y && p.y < a.y && cross(a, b, p) < 0) w--;
    }
    return w;
}

/* the three conditions (coverage_plain.c's top), by brute force */
static int oracle(const ring *in, uint32_t nr)
{
    ring g[4];
    uint32_t r, q, i, j;
    int pos = 0, neg = 0;
    for (r = 0; r < nr; r++) { /* edges of length 0 dropped */
        g[r].n = 0;
        for (i = 0; i < in[r].n; i++)
            if (!same(in[r].p[i], in[r].p[(i + 1) % in[r].n])) g[r].p[g[r].n++] = in[r].p[i];
        if (g[r].n < 3) return 0;
    }
    for (r = 0; r < nr; r++) /* 1: no point twice */
        for (i = 0; i < g[r].n; i++)
            for (q = r; q < nr; q++)
                for (j = q == r ? i + 1 : 0; j < g[q].n; j++)
                    if (same(g[r].p[i], g[q].p[j])) return 0;
    for (r = 0; r < nr; r++) /* 2: edges meet only where a ring turns, and there not folded back */
        for (i = 0; i < g[r].n; i++)
            for (q = r; q < nr; q++)
                for (j = q == r ? i + 1 : 0; j < g[q].n; j++) {
                    const rast_point a = g[r].p[i], b = g[r].p[(i + 1) % g[r].n];
                    const rast_point c = g[q].p[j], d = g[q].p[(j + 1) % g[q].n];
                    if (q == r && (j == (i + 1) % g[r].n || i == (j + 1) % g[r].n)) {
                        const rast_point u = j == (i + 1) % g[r].n ? a : c, v = j == (i + 1) % g[r].n ? b : a,
                                         w = j == (i + 1) % g[r].n ? d : b;
                        if (cross(u, v, w) == 0 &&
                            ((int64_t)u.x - v.x) * ((int64_t)w.x - v.x) + ((int64_t)u.y - v.y) * ((int64_t)w.y - v.y) > 0)
                            return 0;
                        continue;
                    }
                    if (meet(a, b, c, d)) return 0;
                }
    for (r = 0; r < nr; r++) { /* 3: each ring's two sides */
        int64_t area = 0;
        int w0 = 0, w1;
        for (q = 0; q < nr; q++)
            if (q != r) w0 += winding(&g[q], g[r].p[0]);
        for (i = 0; i < g[r].n; i++) area += cross(g[r].p[0], g[r].p[i], g[r].p[(i + 1) % g[r].n]);
        w1 = w0 + (area > 0 ? 1 : -1);
        if (w0 < -1 || w0 > 1 || w1 < -1 || w1 > 1) return 0;
        pos |= w0 == 1 || w1 == 1;
        neg |= w0 == -1 || w1 == -1;
    }
    return !(pos && neg);
}

static int32_t coord(uint32_t grid, uint32_t scale)
{
    return (int32_t)(rng() % grid * scale);
}

/* a ring round (cx, cy) of radius rad (or a random one: rad 0), turned
 * round when cw: n
 * vertices at increasing angles (kind 0: less than a turn, a star-shaped
 * ring; kind 1: maybe more), snapped to the grid; kind 2: anywhere */
static void make(ring *g, uint32_t grid, uint32_t scale, int kind, int32_t cx, int32_t cy, int32_t rad, int cw)
{
    uint32_t i;
    g->n = 3 + rng() % (kind == 2 ? 4 : 8);
    if (kind == 2) {
        for (i = 0; i < g->n; i++) g->p[i].x = coord(grid, scale), g->p[i].y = coord(grid, scale);
        return;
    }
    {
        static const int32_t ux[16] = {100, 92, 71, 38, 0, -38, -71, -92, -100, -92, -71, -38, 0, 38, 71, 92};
        static const int32_t uy[16] = {0, 38, 71, 92, 100, 92, 71, 38, 0, -38, -71, -92, -100, -92, -71, -38};
        uint32_t a = rng() % 16, left = 16;
        if (!rad) rad = (int32_t)(1 + rng() % (grid / 2 + 1)) * (int32_t)scale;
        for (i = 0; i < g->n; i++) {
            int32_t x, y;
            const uint32_t step = kind == 0 ? 1 + rng() % (left - (g->n - i) + 1 < 3 ? left - (g->n - i) + 1 : 3)
                                            : 1 + rng() % 3; /* (kind 1: past a whole turn the ring winds twice) */
            left -= step;
            a = (a + step) % 16;
            x = cx + ux[a] * rad / 100;
            y = cy + uy[a] * rad / 100;
            x = x / (int32_t)scale * (int32_t)scale;
            y = y / (int32_t)scale * (int32_t)scale;
            g->p[i].x = x < 0 ? 0 : x > 255 ? 255 : x;
            g->p[i].y = y < 0 ? 0 : y > 255 ? 255 : y;
        }
    }
    if (cw) { /* the other way round */
        for (i = 0; i < g->n / 2; i++) {
            const rast_point t = g->p[i];
            g->p[i] = g->p[g->n - 1 - i];
            g->p[g->n - 1 - i] = t;
        }
    }
}

int main(void)
{
    static const uint32_t grids[][2] = {{4, 60}, {6, 40}, {9, 28}, {16, 16}, {32, 8}, {256, 1}};
    int t, yes = 0, no = 0;
    const int cases = check_count(40000);
    for (t = 0; t < cases; t++) {
        ring g[4];
        rast_point pts[4 * MAXV];
        uint32_t sizes[4], nr = 2 + rng() % 3, r, np = 0, n, gi = rng() % 6;
        rast_polygon poly;
        int want, got;
        /* 0: rings round one centre near the middle, each inside the last
         * (or not quite); 1: anywhere; 2: apart */
        const int mode = (int)(rng() % 3);
        const int32_t cx = 96 + (int32_t)(rng() % 64), cy = 96 + (int32_t)(rng() % 64);
        for (r = 0; r < nr; r++) {
            const int cw = rng() % 4 ? (int)(r & 1) : (int)(rng() & 1); /* (mostly each the other way) */
            if (mode == 0)
                make(&g[r], grids[gi][0], grids[gi][1], rng() % 8 ? 0 : 1, cx, cy, (int32_t)(110 * (nr - r) / nr), cw);
            else if (mode == 1)
                make(&g[r], grids[gi][0], grids[gi][1], (int)(rng() % 3), coord(grids[gi][0], grids[gi][1]),
                     coord(grids[gi][0], grids[gi][1]), 0, (int)(rng() & 1));
            else /* (apart: a ring in its own quarter of the pixel, mostly all one way) */
                make(&g[r], grids[gi][0], grids[gi][1], 0, (int32_t)(64 + 128 * (r & 1)), (int32_t)(64 + 128 * (r >> 1)),
                     (int32_t)(20 + rng() % 50), rng() % 4 ? 0 : (int)(rng() & 1));
            if (r > 0 && rng() % 6 == 0) g[r].p[rng() % g[r].n] = g[rng() % r].p[0]; /* a vertex shared */
            if (rng() % 8 == 0) g[r].p[1] = g[r].p[0]; /* an edge of length 0 */
            memcpy(pts + np, g[r].p, g[r].n * sizeof(rast_point));
            sizes[r] = g[r].n;
            np += g[r].n;
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nr;
        n = rast__cov_edges_polygon(&poly, edges);
        want = oracle(g, nr);
        got = rast__cov_plain_parts(&poly, np, rast__arena_of(scratch, sizeof scratch), 8, edges, n);
        yes += want;
        no += !want;
        if (got != want) {
            fprintf(stderr, "case %d: plain %d, the oracle %d:", t, got, want);
            for (r = 0; r < nr; r++) {
                uint32_t i;
                fprintf(stderr, " [");
                for (i = 0; i < g[r].n; i++) fprintf(stderr, "(%d,%d)", g[r].p[i].x, g[r].p[i].y);
                fprintf(stderr, "]");
            }
            fprintf(stderr, "\n");
        }
        CHECK(got == want);
    }
    CHECK(yes > cases / 20 && no > cases / 20); /* (both answers, often) */
    printf("test_coverage_chains: %d parts, %d plain\n", cases, yes);
    return check_report("test_coverage_chains");
}

/*
 * test_coverage_parts_lanes.c - rast__cov_parts_test's per-ring passes
 * (coverage_plain.c), which x86 builds run four coordinates a step
 * (SSE2): each ring's box and its count of edges not horizontal, read
 * back from the table it leaves (rows, count as ~ when not plain,
 * columns: coverage.h) and held to plain loops over the points here; and
 * rast__pl_same's comparison of a part with a moved copy of it, by a
 * part made not plain by one vertex moved at each place of its first
 * ring (each lane of the four-point step and the points after it).
 * Rings of 1 to 37 points (the step's pairs, an odd point left, and the
 * scalar rings of fewer than 4), many with repeated ordinates
 * (horizontal edges, an edge of length 0), the edge into the first point
 * among them, anywhere up to RAST_COORD_MAX, at S = 0, 4, 8.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 19u
#include "check.h"
#include "coverage/coverage.h"

static uint64_t scratch[1 << 16];
static rast_point pts[1024];
static uint32_t sizes[40];

#define PX 256

static int64_t floordiv(int64_t a, int64_t p)
{
    return a >= 0 ? a / p : -((-a + p - 1) / p);
}

/* A rectangle (x0, y0) - (x1, y1) into p (4 points), one way round or
 * the other */
static void rect(rast_point *p, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int ccw)
{
    rast_point r[4];
    int i;
    r[0].x = x0, r[0].y = y0;
    r[1].x = x1, r[1].y = y0;
    r[2].x = x1, r[2].y = y1;
    r[3].x = x0, r[3].y = y1;
    for (i = 0; i < 4; i++) p[i] = r[ccw ? i : 3 - i];
}

/* The table against each ring's points: its rows, columns and edges not
 * horizontal.  0 when a check failed. */
static int table_ok(const rast_polygon *poly, int32_t sb)
{
    const int64_t P = (int64_t)1 << sb;
    const int32_t *rows = (const int32_t *)(const void *)scratch, *cols = rows + 3 * poly->nrings;
    uint32_t r, i, base;
    int ok = 1;
    for (r = 0, base = 0; r < poly->nrings; base += poly->ring_sizes[r], r++) {
        const rast_point *p = poly->points + base;
        const uint32_t n = poly->ring_sizes[r];
        int64_t x0 = p[0].x, y0 = p[0].y, x1 = p[0].x, y1 = p[0].y;
        int32_t ne = 0, c = rows[3 * r + 2];
        for (i = 0; i < n; i++) {
            if (p[i].x < x0) x0 = p[i].x;
            if (p[i].x > x1) x1 = p[i].x;
            if (p[i].y < y0) y0 = p[i].y;
            if (p[i].y > y1) y1 = p[i].y;
            if (p[i].y != p[i ? i - 1 : n - 1].y) ne++;
        }
        ok &= rows[3 * r] == floordiv(y0, P);
        ok &= rows[3 * r + 1] == -floordiv(-y1, P) - 1;
        ok &= (c < 0 ? ~c : c) == ne;
        ok &= cols[2 * r] == floordiv(x0, P);
        ok &= cols[2 * r + 1] == -floordiv(-x1, P) - 1;
    }
    return ok;
}

/* Random rings, each in its own cell of 12 pixels (no two parts meet),
 * after a plain square and two squares one way round that overlap (one
 * part plain, one not: the table is written) */
static void tables(int trials)
{
    int t;
    for (t = 0; t < trials; t++) {
        const int32_t sb = (int32_t)(rng() % 3) * 4, unit = (int32_t)1 << sb;
        const uint32_t nr = 3 + rng() % 10;
        const int far = rng() % 4 == 0;
        /* the scene's corner: near either end of the range at times */
        const int32_t ox = far ? (rng() & 1 ? RAST_COORD_MAX - 200 * unit * 12 : -RAST_COORD_MAX) : -(int32_t)(rng() % 64) * unit;
        const int32_t oy = far ? (rng() & 1 ? RAST_COORD_MAX - 20 * unit * 12 : -RAST_COORD_MAX) : (int32_t)(rng() % 64) * unit;
        uint32_t r, i, np = 12;
        rast_polygon poly;
        int got;
        rect(pts, ox + unit, oy + unit, ox + 4 * unit, oy + 4 * unit, 1);
        rect(pts + 4, ox + 13 * unit, oy + unit, ox + 16 * unit, oy + 4 * unit, 1);
        rect(pts + 8, ox + 14 * unit, oy + 2 * unit, ox + 18 * unit, oy + 6 * unit, 1);
        sizes[0] = sizes[1] = sizes[2] = 4;
        for (r = 3; r < nr; r++) {
            const uint32_t n = 1 + rng() % 37;
            const int32_t cx = ox + (int32_t)(r % 16) * 12 * unit, cy = oy + (int32_t)(1 + r / 16) * 12 * unit;
            const int flat = rng() % 3; /* (0: any ordinates; else few, many horizontal edges) */
            for (i = 0; i < n; i++) {
                pts[np + i].x = cx + (int32_t)(rng() % (uint32_t)(8 * unit));
                pts[np + i].y = cy + (flat ? (int32_t)(rng() % 3) * 3 * unit : (int32_t)(rng() % (uint32_t)(8 * unit)));
            }
            if (rng() % 4 == 0 && n > 1) pts[np + n - 1] = pts[np + rng() % (n - 1)]; /* (a point again) */
            if (rng() % 3 == 0) pts[np].y = pts[np + n - 1].y; /* (the edge into the first point horizontal) */
            sizes[r] = n;
            np += n;
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nr;
        got = rast__cov_parts_test(&poly, np, rast__arena_of(scratch, sizeof scratch), sb);
        CHECK(got == -1);
        if (got == -1) {
            const int32_t *rows = (const int32_t *)(const void *)scratch;
            CHECK(table_ok(&poly, sb));
            CHECK(rows[2] >= 0 && rows[5] < 0 && rows[8] < 0); /* (the square plain, the pair not) */
        }
    }
}

/* A "C" open to the right (11 points, half pixels; its point 5 at place k) and a square
 * in its mouth, wound the same way: one part, plain; set at four places
 * 8 pixels apart, the third with the C's point (1, 2) moved to (2, 2),
 * into the square (winding 2 there; the boxes, sizes and so the hash of
 * the part as before).  That copy alone is not plain. */
static void copies(void)
{
    static const int32_t c[11][2] = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 3}, {2, 4}, {2, 5}, {2, 6}, {6, 6}, {6, 8}, {0, 8}};
    uint32_t k, q, i;
    for (k = 0; k < 11; k++) {
        rast_polygon poly;
        uint32_t np = 0;
        int got;
        for (q = 0; q < 4; q++) {
            const int32_t x0 = (int32_t)q * 8 * PX + 100, y0 = 300;
            for (i = 0; i < 11; i++) { /* (c's point i at place (i - 5 + k) mod 11: its point 5, (1, 2), at k) */
                const uint32_t at = (i + 11 + k - 5) % 11;
                pts[np + at].x = x0 + c[i][0] * PX / 2;
                pts[np + at].y = y0 + c[i][1] * PX / 2;
                if (q == 2 && i == 5) pts[np + at].x = x0 + 2 * PX;
            }
            /* the square, the C's way round: (0, 0) (3, 0) (3, 1) turns
             * one way on screen, so does the square from (1.5, 1.5) to
             * (2.5, 1.5) to (2.5, 2.5) */
            rect(pts + np + 11, x0 + 3 * PX / 2, y0 + 3 * PX / 2, x0 + 5 * PX / 2, y0 + 5 * PX / 2, 1);
            sizes[2 * q] = 11;
            sizes[2 * q + 1] = 4;
            np += 15;
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = 8;
        got = rast__cov_parts_test(&poly, np, rast__arena_of(scratch, sizeof scratch), 8);
        CHECK(got == -1);
        if (got == -1) {
            const int32_t *rows = (const int32_t *)(const void *)scratch;
            for (q = 0; q < 8; q++) CHECK((rows[3 * q + 2] < 0) == (q / 2 == 2));
            CHECK(table_ok(&poly, 8));
        }
        /* and unspoilt: every part plain (the copies by the first's answer) */
        pts[30 + k].x = 16 * PX + 100 + PX;
        CHECK(rast__cov_parts_test(&poly, np, rast__arena_of(scratch, sizeof scratch), 8) == 1);
    }
}

int main(void)
{
    tables(check_count(4000));
    copies();
    return check_report("test_coverage_parts_lanes");
}

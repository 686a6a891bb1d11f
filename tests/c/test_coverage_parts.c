/*
 * test_coverage_parts.c - rast__cov_plain_parts (coverage_plain.c): the
 * plain test part by part, where a part is the rings whose pixel boxes
 * share pixels.  Named scenes at S = 8 (a pixel is 256 units): which
 * edges it marks RAST__HZ_PLAIN, and when it answers 1 (every part plain,
 * even parts wound opposite ways, which rast__cov_plain refuses as a
 * whole).  The levels themselves are held to the exact oracle by
 * tests/test_coverage_plain_parts.py.
 */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "coverage/coverage.h"

static uint64_t scratch[1 << 14];
static rast__cedge edges[64];

#define PX 256

/* A rectangle (x0, y0) - (x1, y1), units of 1/256 px, into p (4 points),
 * counter-clockwise on screen when ccw (else reversed). */
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

/* rast__cov_plain_parts on rings of 4 points each; marked[r]: whether
 * ring r's two vertical edges (its only ones) are marked, both the same */
static int parts(const rast_point *p, uint32_t nrings, int *marked, int *whole)
{
    uint32_t sizes[8], r, n;
    rast_polygon poly;
    for (r = 0; r < nrings; r++) sizes[r] = 4;
    poly.points = p;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    n = rast__cov_edges_polygon(&poly, edges);
    CHECK(n >= 2 * nrings); /* (a ring's first two edges at 2 r: the rings before have two each) */
    *whole = rast__cov_plain(&poly, 4 * nrings, rast__arena_of(scratch, sizeof scratch));
    {
        const int got = rast__cov_plain_parts(&poly, 4 * nrings, rast__arena_of(scratch, sizeof scratch), 8, edges, n);
        for (r = 0; r < nrings; r++) {
            const int a = (edges[2 * r].hz & RAST__HZ_PLAIN) != 0, b = (edges[2 * r + 1].hz & RAST__HZ_PLAIN) != 0;
            CHECK(a == b);
            CHECK(!got || !a); /* (1: nothing marked, the whole goes by the accumulation) */
            marked[r] = a;
        }
        return got;
    }
}

int main(void)
{
    rast_point p[32];
    int m[8], whole;

    /* two rings far apart, wound opposite ways: plain part by part, not
     * as a whole (one sign) */
    rect(p, 1 * PX + 10, 1 * PX + 10, 3 * PX, 9 * PX, 1);
    rect(p + 4, 6 * PX + 10, 1 * PX + 10, 8 * PX, 9 * PX, 0);
    CHECK(parts(p, 2, m, &whole) == 1);
    CHECK(whole == 0);

    /* the same, and two rings wound one way that overlap (winding 2):
     * the far ones marked, the pair not */
    rect(p + 8, 12 * PX, 1 * PX, 15 * PX, 6 * PX, 1);
    rect(p + 12, 13 * PX, 3 * PX, 16 * PX, 8 * PX, 1);
    CHECK(parts(p, 4, m, &whole) == 0);
    CHECK(m[0] && m[1] && !m[2] && !m[3]);

    /* apart by less than a pixel, in one pixel column, wound opposite
     * ways (+1 and -1 in column 20): one part, not plain; the far ring
     * alone marked */
    rect(p, 19 * PX + 10, 1 * PX, 20 * PX + 100, 9 * PX, 1);
    rect(p + 4, 20 * PX + 150, 1 * PX, 22 * PX, 9 * PX, 0);
    rect(p + 8, 30 * PX, 1 * PX, 32 * PX, 9 * PX, 1);
    CHECK(parts(p, 3, m, &whole) == 0);
    CHECK(!m[0] && !m[1] && m[2]);

    /* the same two one way round: one part, plain (0 and 1 in the
     * column), and so the whole (one sign) */
    rect(p + 4, 20 * PX + 150, 1 * PX, 22 * PX, 9 * PX, 1);
    CHECK(parts(p, 3, m, &whole) == 1);
    CHECK(whole == 1);

    /* boxes that meet at a pixel corner only (column 5, row 5): one part;
     * wound opposite ways, not plain; the third ring, apart, marked */
    rect(p, 1 * PX, 1 * PX, 5 * PX + 100, 5 * PX + 100, 1);
    rect(p + 4, 5 * PX + 150, 5 * PX + 150, 9 * PX, 9 * PX, 0);
    rect(p + 8, 1 * PX, 12 * PX, 4 * PX, 14 * PX, 0);
    CHECK(parts(p, 3, m, &whole) == 0);
    CHECK(!m[0] && !m[1] && m[2]);

    /* a hole wound the other way inside a ring (0, 1, 0), and a ring
     * wound the first's way inside the hole (1 again): one part, plain;
     * a ring the same way inside the first without a hole (2): not */
    rect(p, 1 * PX, 1 * PX, 9 * PX, 9 * PX, 1);
    rect(p + 4, 2 * PX, 2 * PX, 8 * PX, 8 * PX, 0);
    rect(p + 8, 3 * PX, 3 * PX, 7 * PX, 7 * PX, 1);
    rect(p + 12, 20 * PX, 1 * PX, 22 * PX, 3 * PX, 0);
    CHECK(parts(p, 4, m, &whole) == 1);
    rect(p + 4, 2 * PX, 2 * PX, 8 * PX, 8 * PX, 1);
    CHECK(parts(p, 4, m, &whole) == 0);
    CHECK(!m[0] && !m[1] && !m[2] && m[3]);

    /* a ring of no area (back and forth on one line, a vertex visited
     * twice: its edges cancel) is not plain; the ring apart is */
    rect(p, 1 * PX, 1 * PX, 3 * PX, 3 * PX, 1);
    p[4].x = p[5].x = p[6].x = p[7].x = 10 * PX;
    p[4].y = 1 * PX, p[5].y = 2 * PX, p[6].y = 3 * PX, p[7].y = 2 * PX;
    CHECK(parts(p, 2, m, &whole) == 0);
    CHECK(m[0] && !m[1]);

    printf("test_coverage_parts: named scenes\n");
    return check_report("test_coverage_parts");
}

/* test_aet_rule.c - the AET filler's own choices (fillers/aet.c, the way
 * rast__aet_fill takes, RAST__AET_BY_RULE) against the AET's sweep of
 * every edge (RAST__AET_BY_SWEEP) and the reference winding number (ref.h,
 * straight from DESIGN), bit for bit:
 *  - shared edges cancelled first (rast__segs_cancel, base/edge.c): a
 *    polygon of many small rings whose edges cancel in pairs (a mesh's
 *    cells) filled from what is left.  Random meshes: jittered grids of
 *    cells, each a quad or two triangles (either diagonal), some cells
 *    turned the other way (a hole where they are), some given twice (the
 *    same way: winding 2 under non-zero, 0 under even-odd), vertices on
 *    sample points and rows, meshes crossing the clip's sides; and
 *    polygons whose edges do not cancel (given up: the arena as it was);
 *  - the winding deltas added as the edges are set up (rast__aet_delta_now):
 *    rings.h's many small rings on a clip of few rows (the rule's counts,
 *    checked here, take them), and a triangle wound round 170 to 400
 *    times (past 510 crossings a row the counters are left unread and the
 *    sweep fills);
 * both rules, both samples, several subpixel precisions, exact and
 * textbook rounding. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/aet.h"
#include "rastrum.h"

enum { W = 40, H = 28, MAXP = 1200 };

#include "rings.h"
#include "row_canvas.h"
#include "wound_check.h"

/* A random mesh of nx x ny cells into pts[] and sizes[]: returns the rings. */
static uint32_t mesh(rast_point *pts, uint32_t *sizes, int s, int center, uint32_t *np)
{
    static rast_point grid[9][9];
    const int32_t one = (int32_t)1 << s, half = center ? one / 2 : 0;
    const int32_t nx = 1 + (int32_t)(rng() % 8), ny = 1 + (int32_t)(rng() % 8);
    const int32_t cw = 1 + (int32_t)(rng() % 6), ch = 1 + (int32_t)(rng() % 5);
    const int32_t x0 = (int32_t)(rng() % 12) - 6, y0 = (int32_t)(rng() % 10) - 5;
    const int on = (int)(rng() % 3); /* 0: sample points, 1: sample rows, 2: anywhere */
    uint32_t k = 0, n = 0;
    int32_t r, q;
    for (r = 0; r <= ny; r++)
        for (q = 0; q <= nx; q++) {
            rast_point p;
            p.x = (x0 + q * cw) * one + half;
            p.y = (y0 + r * ch) * one + half;
            if (r > 0 && r < ny && q > 0 && q < nx && rng() % 2) { /* jitter inner vertices */
                int32_t jx = (int32_t)(rng() % (uint32_t)one) - one / 2;
                int32_t jy = (int32_t)(rng() % (uint32_t)one) - one / 2;
                if (on == 0) jx = jy = 0;
                if (on == 1) jy = 0;
                p.x += jx + (int32_t)(rng() % 3) - 1;
                p.y += jy;
            }
            grid[r][q] = p;
        }
    for (r = 0; r < ny; r++)
        for (q = 0; q < nx; q++) {
            const rast_point a = grid[r][q], b = grid[r][q + 1], d = grid[r + 1][q + 1],
                             e = grid[r + 1][q];
            const int flip = rng() % 8 == 0, twice = rng() % 10 == 0, kind = (int)(rng() % 3);
            int t, copy;
            for (copy = 0; copy <= twice; copy++) {
                rast_point ring[2][4];
                uint32_t len[2], nr, v;
                if (kind == 0) { /* a quad */
                    ring[0][0] = a, ring[0][1] = b, ring[0][2] = d, ring[0][3] = e;
                    len[0] = 4, nr = 1;
                } else if (kind == 1) { /* two triangles, diagonal a-d */
                    ring[0][0] = a, ring[0][1] = b, ring[0][2] = d;
                    ring[1][0] = a, ring[1][1] = d, ring[1][2] = e;
                    len[0] = len[1] = 3, nr = 2;
                } else { /* two triangles, diagonal b-e */
                    ring[0][0] = a, ring[0][1] = b, ring[0][2] = e;
                    ring[1][0] = b, ring[1][1] = d, ring[1][2] = e;
                    len[0] = len[1] = 3, nr = 2;
                }
                for (t = 0; t < (int)nr; t++) {
                    for (v = 0; v < len[t]; v++)
                        pts[n + v] = ring[t][flip ? len[t] - 1 - v : v];
                    n += len[t];
                    sizes[k++] = len[t];
                }
            }
        }
    *np = n;
    return k;
}

/* Non-zero past the byte counters' reach: a triangle walked round `turns`
 * times (rings.h), 3 x turns vertices on a clip of 4 rows: the deltas are
 * walked as the edges go, and up to 510 crossings a row read; past that
 * the sweep fills. */
static void test_wound(void)
{
    static const uint32_t turns[] = {170, 200, 255, 256, 300, 400};
    const rast_rect clip = {0, H / 2 - 2, W, H / 2 + 2};
    wound_check(turns, sizeof turns / sizeof turns[0], &clip, RAST__AET_BY_RULE);
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    static canvas a, b;
    static unsigned char scratch[1 << 20];
    int iter, n = check_count(3000), cancelled = 0, now = 0;
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 5), center = (int)(rng() & 1), textbook = (int)(rng() % 4 == 0);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        uint32_t nrings, np = 0;
        rast__grid g;
        rast_polygon poly;
        rast_rect clip;
        size_t need;
        int32_t i;
        rast__arena ar;
        rast__seg *seg;
        uint32_t copies;

        CHECK(rast__grid_init(&g, s, center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER,
                              textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT,
                              RAST_BOUNDARY_EXACT) == RAST_OK);
        if (iter % 4 == 2) { /* many small rings on few rows: the deltas as the edges go */
            nrings = small_rings(pts, sizes, MAXP, 8 + rng() % 120, s, center, &np);
        } else if (iter % 4 == 3) { /* rings that share no edge: the cancelling given up */
            uint32_t v;
            nrings = 2 + rng() % 40;
            for (i = 0; i < (int32_t)nrings; i++) {
                sizes[i] = 3 + rng() % 4;
                for (v = 0; v < sizes[i]; v++) {
                    pts[np].x = (int32_t)(rng() % ((W + 8) << s)) - (4 << s);
                    pts[np].y = (int32_t)(rng() % ((H + 8) << s)) - (4 << s);
                    np++;
                }
            }
        } else {
            nrings = mesh(pts, sizes, s, center, &np);
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nrings;
        clip.x0 = (int32_t)(rng() % 6);
        clip.y0 = (int32_t)(rng() % 6);
        clip.x1 = W - (int32_t)(rng() % 6);
        clip.y1 = H - (int32_t)(rng() % 6);
        if (iter % 4 == 2) { /* a few rows, so that the rule takes the deltas */
            clip.y0 = (int32_t)(rng() % (H - 3));
            clip.y1 = clip.y0 + 1 + (int32_t)(rng() % 3);
        }
        /* the rule's counts (fillers/aet.c): 8 vertices a clip row, the
         * counters of its rows in the room of the vertices' edge records,
         * at most 8 words of them a vertex */
        if (np >= 8 * (uint32_t)(clip.y1 - clip.y0) &&
            (clip.y1 - clip.y0) * ((clip.x1 - clip.x0 + 8) & ~7) <= (int32_t)np * 48 &&
            (clip.y1 - clip.y0) * ((clip.x1 - clip.x0 + 8) / 8) <= 8 * (int32_t)np)
            now++;
        /* exactly the AET's scratch */
        need = rast__aet_scratch(np, W, H);
        CHECK(need <= sizeof scratch);
        ar = rast__arena_of(scratch, need);
#if !defined(__OPTIMIZE_SIZE__)
        if (rast__segs_cancel(poly.points, poly.ring_sizes, np, rule == RAST_RULE_EVENODD, &ar, &seg,
                              &copies) >= 0) {
            CHECK(2 * copies <= np);
            cancelled++;
        } else {
            CHECK(ar.p == scratch && ar.left == need); /* given back */
        }
#else
        (void)seg, (void)copies, (void)ar;
#endif
        CHECK(canvas_fill(&a, &poly, np, &g, rule, &clip, scratch, need, RAST__AET_BY_SWEEP) == RAST_OK);
        CHECK(canvas_fill(&b, &poly, np, &g, rule, &clip, scratch, need, RAST__AET_BY_RULE) == RAST_OK);
        CHECK(!a.bad && !b.bad);
        CHECK(memcmp(a.px, b.px, sizeof a.px) == 0);
        CHECK(canvas_matches_ref(&b, pts, sizes, nrings, s, center, textbook, rule, &clip, iter));
    }
#if !defined(__OPTIMIZE_SIZE__)
    CHECK(cancelled > n / 3); /* the meshes do take the cancelling */
#endif
    CHECK(now > n / 8); /* and the small rings the deltas */
    test_wound();
    return check_report("test_aet_rule");
}

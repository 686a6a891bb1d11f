/* test_delta.c - the AET filler's two ways (fillers/aet.c): the sweep of
 * the active edge table and the winding deltas summed along each row give
 * the same runs, bit for bit, and both the pixels of the reference
 * winding number (ref.h, straight from DESIGN: a pixel is inside when its
 * sample is, by the rule).  Random corpora of what breaks fillers: many
 * small rings overlapping, holes (rings turned the other way), vertices
 * on sample points and on sample rows, collinear vertices, horizontal
 * edges, rings crossing the clip's sides, both rules, both samples,
 * several subpixel precisions, and clips cut small so that the deltas go
 * in bands.  (A build for size has the sweep only: the two then agree
 * trivially.) */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "rastrum.h"

enum { W = 48, H = 24, MAXP = 400 };

#include "rings.h"
#include "row_canvas.h"
#include "wound_check.h"

/* Non-zero past the byte counters' reach: a triangle walked round `turns`
 * times (3 x turns edges, 2 x turns crossings on a row through it, the
 * winding number `turns` inside).  Up to 510 crossings a row the deltas
 * are exact and taken; past that the sweep fills (the buckets, which the
 * deltas' count of crossings borrows, given back as they were). */
static void test_wound(void)
{
    static const uint32_t turns[] = {85, 127, 128, 200, 255, 256, 300, 400};
    const rast_rect clip = {0, 0, W, H};
    wound_check(turns, sizeof turns / sizeof turns[0], &clip, RAST__AET_BY_DELTA);
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    static canvas a, b;
    static unsigned char scratch[1 << 20];
    int iter, n = check_count(3000);
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 5), center = (int)(rng() & 1), textbook = (int)(rng() % 4 == 0);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        uint32_t nrings = 1 + rng() % 60, np = 0;
        rast__grid g;
        rast_polygon poly;
        rast_rect clip;
        size_t need;

        CHECK(rast__grid_init(&g, s, center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER,
                              textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT,
                              RAST_BOUNDARY_EXACT) == RAST_OK);
        nrings = small_rings(pts, sizes, MAXP, nrings, s, center, &np);
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nrings;
        clip.x0 = (int32_t)(rng() % 6);
        clip.y0 = (int32_t)(rng() % 6);
        clip.x1 = W - (int32_t)(rng() % 6);
        clip.y1 = H - (int32_t)(rng() % 6);
        /* exactly the AET's scratch: the counters' rows (at most 56
         * bytes) always fit the room of 3 or more edge records, and a
         * polygon of few vertices holds only a few rows of them, so they
         * go in bands; with at most MAXP < 512 edges non-zero is exact,
         * so RAST__AET_BY_DELTA always takes the deltas */
        need = rast__aet_scratch(np, W, H);
        CHECK(need <= sizeof scratch);
        CHECK(canvas_fill(&a, &poly, np, &g, rule, &clip, scratch, need, RAST__AET_BY_SWEEP) == RAST_OK);
        CHECK(canvas_fill(&b, &poly, np, &g, rule, &clip, scratch, need, RAST__AET_BY_DELTA) == RAST_OK);
        CHECK(!a.bad && !b.bad);
        CHECK(memcmp(a.px, b.px, sizeof a.px) == 0);
        CHECK(canvas_matches_ref(&b, pts, sizes, nrings, s, center, textbook, rule, &clip, iter));
    }
    test_wound();
    return check_report("test_delta");
}

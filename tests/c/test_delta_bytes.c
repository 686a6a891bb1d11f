/* test_delta_bytes.c - the AET filler's winding deltas written straight
 * to one-byte pixels, a word of eight columns at a time (fillers/aet.c,
 * rast__delta_bytes: a gray8 fill's fast kind, and polygon_mask's opaque
 * gray8 painter), against the AET's sweep through the same painter and
 * against the reference winding number (ref.h, straight from DESIGN: a
 * pixel is inside when its sample is, by the rule).  Bit for bit, the
 * whole buffer: inside the clip the value (or, opaque, the background
 * outside the polygon), outside the clip nothing touched.  Random corpora
 * as test_delta.c's (many small rings overlapping, holes, vertices on
 * sample points and rows, collinear and repeated vertices, rings across
 * the clip's sides, both rules, samples and roundings), on a target whose
 * width is no multiple of 8, with clips cut at random or not at all and
 * polygons inside the target or across its sides (so the polygon's box
 * is cut by the clip or inside it, and its last word partial), small
 * scratch (the counters in bands), and windings up to 255 and past it
 * (the lanes' sums modulo 2^8).  (A build for size has the sweep only:
 * the two then agree trivially.) */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "painters/paint.h"
#include "rastrum.h"

enum { W = 53, H = 21, STRIDE = W + 11, MAXP = 400 };

#include "rings.h"
static const unsigned char SENTINEL = 0xA5, VALUE = 200, BACKGROUND = 7;
#include "byte_canvas.h"

/* Both ways into both painters, the same bytes; the deltas' against the
 * reference. */
static void check_scene(int iter, const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                        uint32_t np, int s, int center, int textbook, rast_fill_rule rule,
                        const rast_rect *clip, size_t need)
{
    static unsigned char pre[STRIDE * H], a[STRIDE * H], b[STRIDE * H];
    static unsigned char scratch[1 << 20];
    rast__grid g;
    rast_polygon poly;
    int opaque;
    int32_t k;
    CHECK(need <= sizeof scratch);
    CHECK(rast__grid_init(&g, s, center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER,
                          textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT,
                          RAST_BOUNDARY_EXACT) == RAST_OK);
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    for (k = 0; k < STRIDE * H; k++) pre[k] = (k & 1) ? SENTINEL : (unsigned char)rng();
    for (opaque = 0; opaque < 2; opaque++) {
        CHECK(bytes_fill(a, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_SWEEP) ==
              RAST_OK);
        CHECK(bytes_fill(b, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_DELTA) ==
              RAST_OK);
        CHECK(memcmp(a, b, sizeof a) == 0);
        CHECK(bytes_match_ref(b, pre, pts, sizes, nrings, s, center, textbook, rule, clip, opaque, iter));
    }
}

/* Non-zero with windings up to 400: a triangle walked round `turns`
 * times (the deltas exact up to 510 crossings a row, the sweep past). */
static void test_wound(void)
{
    static rast_point pts[3 * 400];
    static const uint32_t turns[] = {1, 127, 128, 255, 256, 257, 400};
    size_t t;
    for (t = 0; t < sizeof turns / sizeof turns[0]; t++) {
        uint32_t n = 3 * turns[t];
        rast_rect clip = {1, 0, W - 2, H};
        wound_triangle(pts, n);
        check_scene(-1, pts, &n, 1, n, 4, 1, 0, RAST_RULE_NONZERO, &clip,
                    rast__aet_scratch(n, W, H));
    }
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    int iter, n = check_count(1500);
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 5), center = (int)(rng() & 1), textbook = (int)(rng() % 4 == 0);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        uint32_t nrings = 1 + rng() % 60, np = 0, v;
        rast_rect clip;
        nrings = small_rings(pts, sizes, MAXP, nrings, s, center, &np);
        if (rng() % 3 == 0) { /* all inside the target: the box not cut by the clip */
            for (v = 0; v < np; v++) {
                pts[v].x = pts[v].x < 0 ? 0 : pts[v].x > (W << s) ? W << s : pts[v].x;
                pts[v].y = pts[v].y < 0 ? 0 : pts[v].y > (H << s) ? H << s : pts[v].y;
            }
        }
        /* a clip cut at random, or the whole target (the polygon's box then
         * mostly the clip's) */
        clip.x0 = clip.y0 = 0;
        clip.x1 = W;
        clip.y1 = H;
        if (rng() % 3) {
            clip.x0 = (int32_t)(rng() % 12);
            clip.y0 = (int32_t)(rng() % 6);
            clip.x1 = W - (int32_t)(rng() % 12);
            clip.y1 = H - (int32_t)(rng() % 6);
        }
        /* the AET's scratch (the counters in bands for few vertices), or
         * room for them all */
        check_scene(iter, pts, sizes, nrings, np, s, center, textbook, rule, &clip,
                    rng() % 2 ? rast__aet_scratch(np, W, H) : rast__aet_scratch(np + 200, W, H));
    }
    test_wound();
    return check_report("test_delta_bytes");
}

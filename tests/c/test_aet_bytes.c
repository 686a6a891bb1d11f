/* test_aet_bytes.c - the AET's sweep writing an outline's rows straight to
 * one-byte pixels from its row hook (fillers/aet.c, rast__aet_sweep_bytes:
 * a gray8 fill's fast kind, and polygon_mask's opaque gray8 painter: each
 * pixel once, the background between the runs), which rast__aet_fill
 * takes where the sweep fills (few edges for the rows: a circle, a glyph,
 * a star), against the sweep's runs through the sink and the same painter
 * (RAST__AET_BY_SWEEP) and against the reference winding number (ref.h,
 * straight from DESIGN: a pixel is inside when its sample is, by the
 * rule).  Bit for bit, the whole buffer: inside the clip the value (or,
 * opaque, the background outside the polygon), outside the clip nothing
 * touched.  Scenes: one to three small rings (rings.h: vertices on
 * sample points and rows, collinear and repeated ones, rings across the
 * clip's sides), random stars of up to 40 vertices across the target (many
 * runs a row, crossing edges), and two rings far apart in y (rows of no
 * crossing between them, which the hook writes as background); both
 * rules, samples and roundings, clips cut at random or the whole target,
 * on a target whose width is no multiple of 8; and a triangle wound up to
 * 400 times (non-zero).  (A build for size has the sweep through the sink
 * only: the two then agree trivially.) */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "painters/paint.h"
#include "rastrum.h"

enum { W = 45, H = 37, STRIDE = W + 7, MAXP = 1200 };

#include "rings.h"
static const unsigned char VALUE = 9, BACKGROUND = 250;
#include "byte_canvas.h"

/* Fill by `how` (byte_canvas.h), with this file's scratch. */
static void fill(unsigned char *px, const unsigned char *pre, const rast_polygon *poly, uint32_t np,
                 const rast__grid *g, rast_fill_rule rule, const rast_rect *clip, int opaque, int how)
{
    static unsigned char scratch[1 << 18];
    CHECK(rast__aet_scratch(np, W, H) <= sizeof scratch);
    CHECK(bytes_fill(px, pre, poly, np, g, rule, clip, scratch, rast__aet_scratch(np, W, H), opaque, how) ==
          RAST_OK);
}

static void check_scene(int iter, const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                        uint32_t np, int s, int center, int textbook, rast_fill_rule rule,
                        const rast_rect *clip)
{
    static unsigned char pre[STRIDE * H], a[STRIDE * H], b[STRIDE * H];
    rast__grid g;
    rast_polygon poly;
    int opaque, k;
    CHECK(rast__grid_init(&g, s, center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER,
                          textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT,
                          RAST_BOUNDARY_EXACT) == RAST_OK);
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    for (k = 0; k < STRIDE * H; k++) pre[k] = (unsigned char)(rng() | 1); /* never 0: no byte a fill writes by chance */
    for (opaque = 0; opaque < 2; opaque++) {
        fill(a, pre, &poly, np, &g, rule, clip, opaque, RAST__AET_BY_SWEEP);
        fill(b, pre, &poly, np, &g, rule, clip, opaque, RAST__AET_BY_RULE);
        CHECK(memcmp(a, b, sizeof a) == 0);
        CHECK(bytes_match_ref(b, pre, pts, sizes, nrings, s, center, textbook, rule, clip, opaque, iter));
    }
}

/* A star of m vertices round a random centre, radii at random, across
 * (and past) the target: pts[0 .. m). */
static void star(rast_point *pts, uint32_t m, int s)
{
    const int32_t cx = (int32_t)(rng() % W) << s, cy = (int32_t)(rng() % H) << s;
    uint32_t v;
    for (v = 0; v < m; v++) {
        /* a direction of 16 round the circle (by table: no libm), scaled */
        static const int8_t dx[16] = {8, 7, 6, 3, 0, -3, -6, -7, -8, -7, -6, -3, 0, 3, 6, 7};
        static const int8_t dy[16] = {0, 3, 6, 7, 8, 7, 6, 3, 0, -3, -6, -7, -8, -7, -6, -3};
        const int32_t r = (int32_t)(1 + rng() % 40), d = (int32_t)((v * 16) / m);
        pts[v].x = cx + dx[d] * r * ((int32_t)1 << s) / 8 + (int32_t)(rng() % (1u << s));
        pts[v].y = cy + dy[d] * r * ((int32_t)1 << s) / 8 + (int32_t)(rng() % (1u << s));
    }
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    int iter, n = check_count(1500);
    static const uint32_t turns[] = {1, 127, 128, 255, 256, 257, 400};
    size_t t;
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 5), center = (int)(rng() & 1), textbook = (int)(rng() % 4 == 0);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        uint32_t nrings, np = 0;
        rast_rect clip = {0, 0, W, H};
        const int kind = (int)(rng() % 3);
        if (kind == 0) {
            nrings = small_rings(pts, sizes, MAXP, 1 + rng() % 3, s, center, &np);
        } else if (kind == 1) {
            np = sizes[0] = 3 + rng() % 38;
            star(pts, np, s);
            nrings = 1;
        } else { /* two rings, one near the top and one near the bottom */
            uint32_t v;
            sizes[0] = 3 + rng() % 10;
            sizes[1] = 3 + rng() % 10;
            star(pts, sizes[0], s);
            star(pts + sizes[0], sizes[1], s);
            for (v = 0; v < sizes[0]; v++) pts[v].y = pts[v].y % (8 << s);
            for (v = sizes[0]; v < sizes[0] + sizes[1]; v++) pts[v].y = ((H - 8) << s) + pts[v].y % (8 << s);
            np = sizes[0] + sizes[1];
            nrings = 2;
        }
        if (rng() % 3) {
            clip.x0 = (int32_t)(rng() % 12);
            clip.y0 = (int32_t)(rng() % 8);
            clip.x1 = W - (int32_t)(rng() % 12);
            clip.y1 = H - (int32_t)(rng() % 8);
        }
        check_scene(iter, pts, sizes, nrings, np, s, center, textbook, rule, &clip);
    }
    for (t = 0; t < sizeof turns / sizeof turns[0]; t++) {
        uint32_t np = 3 * turns[t];
        rast_rect clip = {1, 2, W - 2, H - 1};
        wound_triangle(pts, np);
        check_scene(-1, pts, &np, 1, np, 4, 1, 0, RAST_RULE_NONZERO, &clip);
    }
    return check_report("test_aet_bytes");
}

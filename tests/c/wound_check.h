/*
 * wound_check.h - non-zero past the byte counters' reach, for the AET
 * filler's tests (test_delta.c, test_aet_rule.c): a triangle walked round
 * `turns` times (rings.h's wound_triangle: 3 x turns edges, 2 x turns
 * crossings on a row through it, the winding number `turns` inside),
 * filled by the AET's sweep of every edge (RAST__AET_BY_SWEEP) and by the
 * way `how` under test, on `clip`: the two the same bit for bit, and the
 * pixels of the reference winding number (ref.h) inside the clip, none
 * outside.  Include after rings.h and row_canvas.h (canvas_fill).
 */
#ifndef RAST_TEST_WOUND_CHECK_H
#define RAST_TEST_WOUND_CHECK_H

static void wound_check(const uint32_t *turns, size_t nturns, const rast_rect *clip, int how)
{
    static rast_point pts[3 * 400];
    static unsigned char scratch[1 << 20];
    static canvas a, b;
    rast__grid g;
    size_t t;
    CHECK(rast__grid_init(&g, 4, RAST_SAMPLE_CENTER, RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT) == RAST_OK);
    for (t = 0; t < nturns; t++) {
        uint32_t n = 3 * turns[t];
        rast_polygon poly;
        int32_t i, j, ok = 1, inside = 0;
        wound_triangle(pts, n);
        poly.points = pts;
        poly.ring_sizes = &n;
        poly.nrings = 1;
        CHECK(canvas_fill(&a, &poly, n, &g, RAST_RULE_NONZERO, clip, scratch, rast__aet_scratch(n, W, H),
                   RAST__AET_BY_SWEEP) == RAST_OK);
        CHECK(canvas_fill(&b, &poly, n, &g, RAST_RULE_NONZERO, clip, scratch, rast__aet_scratch(n, W, H), how) ==
              RAST_OK);
        CHECK(!a.bad && !b.bad);
        CHECK(memcmp(a.px, b.px, sizeof a.px) == 0);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                int in = j >= clip->y0 && j < clip->y1 && ref_winding(pts, &n, 1, 4, 1, 0, i, j, NULL) != 0;
                if (b.px[j][i] != in) ok = 0;
                inside += in;
            }
        CHECK(ok && inside > 0);
    }
}

#endif

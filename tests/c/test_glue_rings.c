/*
 * test_glue_rings.c - the binding's glue (python/glue, compiled in as
 * setup.py builds it) refuses ring sizes that do not sum to the point
 * count (rastpy_check_rings): the core reads sum(ring_sizes) points, the
 * glue's buffer holds npoints, so a sum past it would read past the
 * buffer.  Every glue call taking ring sizes returns RAST_E_ARG for sizes
 * one short, one past, far past, and summing to npoints only modulo 2^32,
 * and writes nothing (the target, a mask or a coverage array, with guard
 * bytes around it); the same calls with sizes that sum right (rings of
 * size 0 among them: the core allows rings of fewer than 3 points) draw.
 * ASan (make asan-c) would also catch a read past the points.
 */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#define RAST_STATIC_LINKING_ONLY
#include "../../python/glue/fill.c"
#include "../../python/glue/wide.c"
#include "../../python/glue/blend.c"
#include "../../python/glue/coverage.c"

/* fill.c's test hook calls into CPython; no interpreter here */
int PyGILState_Check(void) { return 0; }

#define W 16
#define H 12
#define GUARD 32
#define NPTS 7

static unsigned char mem[GUARD + W * H * 8 + GUARD], orig[sizeof mem];
/* two rings: a triangle and a square (then one past: never read) */
static const double xy[2 * (NPTS + 1)] = {1.5, 1.5, 9.25, 2.0, 4.0, 8.5,
                                          10.0, 3.0, 14.0, 3.0, 14.0, 9.0, 10.0, 9.0};

static void fresh(void)
{
    size_t i;
    for (i = 0; i < sizeof mem; i++) mem[i] = (unsigned char)(i * 37u + 11u);
    memcpy(orig, mem, sizeof mem);
}

/* Each glue call taking ring sizes, on `sizes` (nrings of them); the
 * target, mask or array at mem + GUARD.  Returns how many calls did not
 * return `want`, or wrote memory when they must not have. */
static int run(const uint32_t *sizes, uint32_t nrings, long want)
{
    static const uint8_t rgba[4] = {200, 100, 50, 160};
    static const unsigned char pixel[4] = {77, 78, 79, 80};
    rast_target t;
    rast_fill_opts fo;
    rast_coverage_opts co;
    rast_blend_opts bo;
    int bad = 0, k;
    memset(&fo, 0, sizeof fo);
    fo.algorithm = RAST_ALGO_AET;
    fo.rule = RAST_RULE_EVENODD;
    fo.subpixel_bits = 8;
    fo.sample = RAST_SAMPLE_CENTER;
    memset(&co, 0, sizeof co);
    co.method = RAST_AA_AREA;
    co.rule = RAST_RULE_EVENODD;
    co.subpixel_bits = 8;
    co.sample = RAST_SAMPLE_CENTER;
    bo.opacity = 200;
    bo.premultiplied = 0;
    for (k = 0; k < 11; k++) {
        long got = 0;
        fresh();
        CHECK(rast_target_init(&t, mem + GUARD, W, H, W * 3, RAST_FORMAT_RGB888) == RAST_OK);
        switch (k) {
        case 0: got = rastpy_fill_polygon(&t, xy, NPTS, sizes, nrings, &fo, pixel, NULL); break;
        case 1: got = rastpy_fill_polygon(&t, xy, NPTS, sizes, nrings, &fo, pixel, pixel); break;
        case 2: got = rastpy_mask_polygon(mem + GUARD, H, W, xy, NPTS, sizes, nrings, &fo); break;
        case 3: got = rastpy_blend_polygon(&t, xy, NPTS, sizes, nrings, &fo, rgba, &bo, NULL); break;
        case 4: got = rastpy_blend_polygon_coverage(&t, xy, NPTS, sizes, nrings, &co, rgba, &bo, NULL, NULL); break;
        case 5: got = rastpy_fill_polygon_aa(&t, xy, NPTS, sizes, nrings, &co, pixel, NULL); break;
        case 6: got = rastpy_polygon_coverage(mem + GUARD, H, W, 0, xy, NPTS, sizes, nrings, &co, NULL); break;
        case 7: got = rastpy_fill_polygon64(&t, xy, NPTS, sizes, nrings, &fo, pixel, NULL); break;
        case 8: got = rastpy_mask_polygon64(mem + GUARD, H, W, xy, NPTS, sizes, nrings, &fo); break;
        case 9: got = rastpy_polygon_coverage64(mem + GUARD, H, W, 0, xy, NPTS, sizes, nrings, &co); break;
        default: got = rastpy_blend_polygon64(&t, xy, NPTS, sizes, nrings, &fo, rgba, &bo, NULL); break;
        }
        if (got != want) {
            printf("call %d: %ld, not %ld\n", k, got, want);
            bad++;
        }
        if (want != RAST_OK && memcmp(mem, orig, sizeof mem) != 0) {
            printf("call %d: wrote memory on an error\n", k);
            bad++;
        }
        if (want == RAST_OK && (memcmp(mem, orig, GUARD) != 0 ||
                                memcmp(mem + GUARD + W * H * 3, orig + GUARD + W * H * 3, GUARD) != 0)) {
            printf("call %d: wrote past the target\n", k);
            bad++;
        }
        if (want == RAST_OK && memcmp(mem, orig, sizeof mem) == 0) {
            printf("call %d: drew nothing\n", k);
            bad++;
        }
    }
    return bad;
}

int main(void)
{
    static const uint32_t good[2] = {3, 4}, good0[4] = {0, 3, 0, 4}, one_ring[1] = {NPTS},
                          short1[2] = {3, 3}, past1[2] = {3, 5}, far[2] = {3, 1000000},
                          huge[1] = {0xFFFFFFFFu}, wrap[3] = {0xFFFFFFFFu, 4, 4}, /* 32-bit sum: 7 */
                          wrap2[2] = {0x80000000u, 0x80000007u};                  /* 32-bit sum: 7 */
    CHECK(run(good, 2, RAST_OK) == 0);
    CHECK(run(good0, 4, RAST_OK) == 0);
    CHECK(run(one_ring, 1, RAST_OK) == 0);
    CHECK(run(NULL, 1, RAST_OK) == 0);
    CHECK(run(short1, 2, RAST_E_ARG) == 0);
    CHECK(run(past1, 2, RAST_E_ARG) == 0);
    CHECK(run(far, 2, RAST_E_ARG) == 0);
    CHECK(run(huge, 1, RAST_E_ARG) == 0);
    CHECK(run(wrap, 3, RAST_E_ARG) == 0);
    CHECK(run(wrap2, 2, RAST_E_ARG) == 0);
    CHECK(run(good, 0, RAST_E_ARG) == 0); /* no rings: a sum of 0 */
    CHECK(rastpy_check_rings(0, good, 0) == RAST_OK);
    CHECK(rastpy_check_rings(7, good, 2) == RAST_OK);
    CHECK(rastpy_check_rings(7, wrap, 3) == RAST_E_ARG);
    CHECK(rastpy_check_rings(7, NULL, 5) == RAST_OK);
    return check_report("test_glue_rings");
}

/*
 * test_harden2.c - issue 18 in the core.
 *
 *  - rast_render_bands_spans accepts every clip the per-primitive span
 *    entry points accept: the widest, {-RAST_MAX_DIM, 0, RAST_MAX_DIM, 16},
 *    was RAST_E_SIZE (its width went to rast_scratch_size, which caps it)
 *    and gives the spans of rast_fill_polygon_spans / _triangles_spans /
 *    rast_draw_polyline_spans there.
 *  - rast_seed_fill_limited: with enough stack the work is the region's
 *    pixel count, the pixels those of rast_flood_fill; a limit below it
 *    stops with RAST_E_WORK, having written only region pixels and at
 *    most the limit; 0 work on an error and for a no-op fill.  With no
 *    stack (the fixed-memory fallback) the same pixels, the work counted.
 * The racing writer itself is tests/race/test_race.c (make race-check).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_RNG_SEED 18u
#include "check.h"
#include "rastrum.h"

/* Spans recorded as (y, x0, x1) triples. */
typedef struct {
    int32_t v[3 * 4096];
    int n;
} span_log;

static void log_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_log *s = (span_log *)user;
    if (s->n + 3 <= (int)(sizeof s->v / sizeof s->v[0])) {
        s->v[s->n++] = y;
        s->v[s->n++] = x0;
        s->v[s->n++] = x1;
    }
}

static void log_prim_span(void *user, const rast_prim *p, int32_t y, int32_t x0, int32_t x1)
{
    (void)p;
    log_span(user, y, x0, x1);
}

static uint64_t scratch_mem[(1 << 16) / 8];
static span_log a, b;

static void test_bands_wide_clip(void)
{
    static const rast_point pts[4] = {{-300 * 256, 1 * 256}, {500 * 256, 2 * 256},
                                      {400 * 256, 14 * 256}, {-200 * 256, 12 * 256}};
    static const rast_point tri[3] = {{-100 * 256, 0}, {300 * 256, 4 * 256}, {0, 15 * 256}};
    static const uint32_t ring[1] = {4};
    rast_fill_opts fo;
    rast_tri_opts to;
    rast_line_opts lo;
    rast_prim p[3];
    rast_rect clip = {-RAST_MAX_DIM, 0, RAST_MAX_DIM, 16};
    unsigned char px = 1;
    int k;

    memset(&fo, 0, sizeof fo);
    fo.algorithm = RAST_ALGO_AET;
    fo.subpixel_bits = 8;
    memset(&to, 0, sizeof to);
    to.subpixel_bits = 8;
    memset(&lo, 0, sizeof lo);
    lo.subpixel_bits = 8;
    memset(p, 0, sizeof p);
    p[0].kind = RAST_PRIM_POLYGON;
    p[0].polygon.points = pts;
    p[0].polygon.ring_sizes = ring;
    p[0].polygon.nrings = 1;
    p[0].fill = &fo;
    p[0].pixel = &px;
    p[1].kind = RAST_PRIM_TRIANGLES;
    p[1].points = tri;
    p[1].count = 1;
    p[1].tri = &to;
    p[1].pixel = &px;
    p[2].kind = RAST_PRIM_POLYLINE;
    p[2].points = pts;
    p[2].count = 4;
    p[2].closed = 1;
    p[2].line = &lo;
    p[2].pixel = &px;
    for (k = 0; k < 3; k++) {
        rast_status s1, s2;
        a.n = b.n = 0;
        if (k == 0)
            s1 = rast_fill_polygon_spans(&p[0].polygon, &fo, &clip, log_span, &a, scratch_mem,
                                         sizeof scratch_mem);
        else if (k == 1)
            s1 = rast_fill_triangles_spans(tri, 1, &to, &clip, log_span, &a, scratch_mem,
                                           sizeof scratch_mem);
        else
            s1 = rast_draw_polyline_spans(pts, 4, 1, &lo, &clip, log_span, &a);
        s2 = rast_render_bands_spans(&p[k], 1, &clip, 16, log_prim_span, &b, scratch_mem,
                                     sizeof scratch_mem, NULL);
        CHECK(s1 == RAST_OK);
        CHECK(s2 == RAST_OK);
        CHECK(a.n > 0 && a.n == b.n && memcmp(a.v, b.v, (size_t)a.n * sizeof a.v[0]) == 0);
    }
    /* Past +-RAST_MAX_DIM: refused by all alike. */
    clip.x0 = -RAST_MAX_DIM - 1;
    CHECK(rast_fill_polygon_spans(&p[0].polygon, &fo, &clip, log_span, &a, scratch_mem,
                                  sizeof scratch_mem) == RAST_E_SIZE);
    CHECK(rast_render_bands_spans(p, 3, &clip, 16, log_prim_span, &b, scratch_mem,
                                  sizeof scratch_mem, NULL) == RAST_E_SIZE);
}

#define SW 40
#define SH 30

static unsigned char img[SH][SW], img2[SH][SW], orig[SH][SW];
static uint64_t stack_mem[(1 << 15) / 8];

/* A picture: 0 background, walls of 5 with gaps (one region of 0s with
 * thin corridors, and some closed pockets). */
static void picture(void)
{
    int x, y;
    for (y = 0; y < SH; y++)
        for (x = 0; x < SW; x++)
            orig[y][x] = (unsigned char)(((y % 3 == 2 && x % 9 != 4) || (x % 4 == 3 && y % 7 != 0))
                                         ? 5 : 0);
}

static void test_limited(void)
{
    rast_target t, t2;
    unsigned char v = 7;
    uint64_t work = 99, region = 0;
    int x, y, stack;
    picture();
    rast_target_init(&t, img, SW, SH, SW, RAST_FORMAT_GRAY8);
    rast_target_init(&t2, img2, SW, SH, SW, RAST_FORMAT_GRAY8);
    for (stack = 0; stack < 2; stack++) {
        size_t bytes = stack ? sizeof stack_mem : 0;
        memcpy(img, orig, sizeof img);
        memcpy(img2, orig, sizeof img);
        CHECK(rast_flood_fill(&t2, 1, 1, &v, 4, stack_mem, bytes) == RAST_OK);
        CHECK(rast_seed_fill_limited(&t, 1, 1, &v, NULL, 4, stack_mem, bytes, UINT64_MAX,
                                     &work) == RAST_OK);
        CHECK(memcmp(img, img2, sizeof img) == 0);
        region = 0;
        for (y = 0; y < SH; y++)
            for (x = 0; x < SW; x++) region += img2[y][x] != orig[y][x];
        CHECK(region > 100);
        if (stack) CHECK(work == region);   /* one unit per pixel */
        else CHECK(work >= region);         /* and the fallback's steps */
        /* A limit below the work: RAST_E_WORK, only region pixels written,
         * at most `limit` of them. */
        {
            uint64_t limit = region / 3, n = 0, w2 = 0;
            int outside = 0;
            memcpy(img, orig, sizeof img);
            CHECK(rast_seed_fill_limited(&t, 1, 1, &v, NULL, 4, stack_mem, bytes, limit, &w2) ==
                  RAST_E_WORK);
            for (y = 0; y < SH; y++)
                for (x = 0; x < SW; x++)
                    if (img[y][x] != orig[y][x]) {
                        n++;
                        outside += img2[y][x] != 7 || img[y][x] != 7;
                    }
            CHECK(outside == 0);
            CHECK(n > 0 && n <= limit);
            CHECK(w2 <= limit);
        }
    }
    /* Boundary fill through the same call. */
    memcpy(img, orig, sizeof img);
    memcpy(img2, orig, sizeof img);
    {
        unsigned char edge = 5;
        CHECK(rast_boundary_fill(&t2, 1, 1, &v, &edge, 8, stack_mem, sizeof stack_mem) == RAST_OK);
        CHECK(rast_seed_fill_limited(&t, 1, 1, &v, &edge, 8, NULL, 0, UINT64_MAX, NULL) == RAST_OK);
        CHECK(memcmp(img, img2, sizeof img) == 0);
    }
    /* Errors and no-ops: work 0, nothing written. */
    memcpy(img, orig, sizeof img);
    work = 5;
    CHECK(rast_seed_fill_limited(&t, SW, 0, &v, NULL, 4, NULL, 0, 10, &work) == RAST_E_ARG);
    CHECK(work == 5); /* untouched on an argument error */
    memcpy(img, orig, sizeof img);
    v = 0;
    CHECK(rast_seed_fill_limited(&t, 1, 1, &v, NULL, 4, NULL, 0, 0, &work) == RAST_OK);
    CHECK(work == 0 && memcmp(img, orig, sizeof img) == 0); /* value == seed: nothing */
    CHECK(rast_seed_fill_limited(NULL, 1, 1, &v, NULL, 4, NULL, 0, 0, &work) == RAST_E_NULL);
    CHECK(rast_status_str(RAST_E_WORK)[0] != 'u'); /* has a message */
}

int main(void)
{
    test_bands_wide_clip();
    test_limited();
    return check_report("test_harden2");
}

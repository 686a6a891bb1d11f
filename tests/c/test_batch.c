/* test_batch.c - rast_fill_polygons_spans: a batch of polygons gives, in
 * order, exactly the spans each polygon gives on its own (rast_fill_polygon_spans
 * over the whole clip), in any band; every error comes before the first span
 * and names the polygon; the scratch is the largest polygon's own need and
 * nothing past it is touched. */
#define CHECK_RNG_SEED 13u
#include "check.h"

#include <string.h>

#include "rastrum.h"

static uint64_t scratch_mem[1 << 15];
#define GUARD 0xA5
#include "scratch.h"

#define W 61
#define H 47
#define NPOLY 12
#define MAXPTS 16

/* Images painted by spans: one byte a pixel, the polygon's index + 1 (a
 * later polygon over an earlier one, as a burn in order does). */
static unsigned char img_batch[H][W], img_each[H][W];
static int spans_seen, bad_span;

static void paint_batch(void *user, uint32_t index, int32_t y, int32_t x0, int32_t x1)
{
    const rast_rect *clip = (const rast_rect *)user;
    int32_t x;
    spans_seen++;
    if (y < clip->y0 || y >= clip->y1 || x0 < clip->x0 || x1 > clip->x1 || x0 >= x1 || index >= NPOLY) {
        bad_span++;
        return;
    }
    for (x = x0; x < x1; x++) img_batch[y][x] = (unsigned char)(index + 1);
}

static uint32_t each_index;
static void paint_each(void *user, int32_t y, int32_t x0, int32_t x1)
{
    int32_t x;
    (void)user;
    for (x = x0; x < x1; x++) img_each[y][x] = (unsigned char)(each_index + 1);
}

static rast_point pts[NPOLY][MAXPTS];
static uint32_t sizes[NPOLY][2];
static rast_polygon polys[NPOLY];

/* NPOLY random polygons (one or two rings, vertices a bit past the clip),
 * S = 4. */
static void make_batch(void)
{
    int k, i;
    for (k = 0; k < NPOLY; k++) {
        int n0 = 3 + (int)(rng() % 6), n1 = (rng() % 3 == 0) ? 3 + (int)(rng() % 5) : 0;
        for (i = 0; i < n0 + n1; i++) {
            pts[k][i].x = (int32_t)(rng() % ((W + 8) * 16)) - 4 * 16;
            pts[k][i].y = (int32_t)(rng() % ((H + 8) * 16)) - 4 * 16;
        }
        sizes[k][0] = (uint32_t)n0;
        sizes[k][1] = (uint32_t)n1;
        polys[k].points = pts[k];
        polys[k].ring_sizes = sizes[k];
        polys[k].nrings = n1 ? 2 : 1;
    }
}

static void test_same_as_each(rast_algorithm algo, rast_fill_rule rule, rast_boundary boundary)
{
    rast_fill_opts o;
    rast_rect whole = {0, 0, W, H};
    size_t need, each_need;
    unsigned char *s;
    uint32_t k, failed = 777;
    int32_t band;
    memset(&o, 0, sizeof o);
    o.algorithm = algo;
    o.rule = rule;
    o.subpixel_bits = 4;
    o.sample = RAST_SAMPLE_CENTER;
    o.boundary = boundary;
    make_batch();

    /* Each polygon on its own, over the whole clip, in order. */
    memset(img_each, 0, sizeof img_each);
    for (k = 0; k < NPOLY; k++) {
        uint32_t n = sizes[k][0] + sizes[k][1];
        CHECK(rast_scratch_size(&o, n, W, H, &each_need) == RAST_OK);
        s = scratch_for(each_need);
        each_index = k;
        CHECK(rast_fill_polygon_spans(&polys[k], &o, &whole, paint_each, NULL, s, each_need) == RAST_OK);
    }

    {   /* the scene is not empty (else the comparison below proves little) */
        size_t i, on = 0;
        for (i = 0; i < sizeof img_each; i++) on += ((unsigned char *)img_each)[i] != 0;
        CHECK(on > 0);
    }

    /* The batch, whole and band by band (bands of 1, 5 and 16 rows). */
    CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &whole, &need, &failed) == RAST_OK);
    CHECK(failed == 777);
    for (band = 0; band <= 16; band = band ? band * 3 + 1 : 1) {
        rast_rect clip = whole;
        int32_t y;
        memset(img_batch, 0, sizeof img_batch);
        bad_span = 0;
        for (y = 0; y < H; y += band ? band : H) {
            size_t band_need;
            clip.y0 = y;
            clip.y1 = band && y + band < H ? y + band : H;
            CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &clip, &band_need, NULL) == RAST_OK);
            CHECK(band_need <= need);
            s = scratch_for(band_need);
            CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &clip, paint_batch, &clip, s, band_need,
                                           NULL) == RAST_OK);
            CHECK(scratch_guard_ok(s, band_need));
        }
        CHECK(bad_span == 0);
        CHECK(memcmp(img_batch, img_each, sizeof img_each) == 0);
    }
}

static void test_errors(void)
{
    rast_fill_opts o;
    rast_rect whole = {0, 0, W, H};
    size_t need;
    unsigned char *s;
    uint32_t failed;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    make_batch();
    CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &whole, &need, NULL) == RAST_OK);

    /* A vertex out of range in polygon 7: nothing drawn, 7 named. */
    pts[7][1].x = RAST_COORD_MAX + 1;
    s = scratch_for(need);
    spans_seen = 0;
    failed = 0;
    CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &whole, paint_batch, &whole, s, need, &failed) ==
          RAST_E_RANGE);
    CHECK(failed == 7 && spans_seen == 0);
    failed = 0;
    CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &whole, &need, &failed) == RAST_E_RANGE);
    CHECK(failed == 7);
    make_batch();

    /* Too little scratch: the first polygon that does not fit is named. */
    CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &whole, &need, NULL) == RAST_OK);
    if (need > 0) {
        uint32_t k;
        size_t each;
        s = scratch_for(need - 1);
        spans_seen = 0;
        CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &whole, paint_batch, &whole, s, need - 1,
                                       &failed) == RAST_E_SCRATCH);
        CHECK(spans_seen == 0 && failed < NPOLY);
        for (k = 0; k < failed; k++) {
            rast_rect b;
            CHECK(rast_fill_bounds(&o, &polys[k], &whole, &b) == RAST_OK);
            CHECK(rast_scratch_size(&o, sizes[k][0] + sizes[k][1], b.x1 - b.x0, b.y1 - b.y0, &each) ==
                  RAST_OK);
            CHECK(each <= need - 1);
        }
        /* Misaligned scratch. */
        CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &whole, paint_batch, &whole,
                                       (unsigned char *)scratch_mem + 1, need, NULL) == RAST_E_ALIGN);
    }
    /* Bad options are the batch's, not a polygon's: *failed untouched. */
    o.subpixel_bits = 99;
    failed = 12345;
    CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &whole, paint_batch, &whole, s, need, &failed) ==
          RAST_E_SUBPIXEL);
    CHECK(failed == 12345);
    o.subpixel_bits = 4;
    /* NULLs, a bad clip, an empty batch. */
    CHECK(rast_fill_polygons_spans(NULL, 1, &o, &whole, paint_batch, &whole, s, need, NULL) == RAST_E_NULL);
    CHECK(rast_fill_polygons_spans(polys, NPOLY, NULL, &whole, paint_batch, &whole, s, need, NULL) ==
          RAST_E_NULL);
    CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, NULL, paint_batch, &whole, s, need, NULL) ==
          RAST_E_NULL);
    CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &whole, NULL, &whole, s, need, NULL) == RAST_E_NULL);
    CHECK(rast_polygons_scratch_size(polys, NPOLY, &o, &whole, NULL, NULL) == RAST_E_NULL);
    {
        rast_rect huge = {0, 0, RAST_MAX_DIM, 2};
        huge.x1 = RAST_MAX_DIM;
        huge.x0 = -RAST_MAX_DIM - 1;
        spans_seen = 0;
        CHECK(rast_fill_polygons_spans(polys, NPOLY, &o, &huge, paint_batch, &whole, s, need, NULL) ==
              RAST_E_SIZE);
        CHECK(spans_seen == 0);
    }
    CHECK(rast_polygons_scratch_size(NULL, 0, &o, &whole, &need, NULL) == RAST_OK && need == 0);
    CHECK(rast_fill_polygons_spans(NULL, 0, &o, &whole, paint_batch, &whole, NULL, 0, NULL) == RAST_OK);
}

int main(void)
{
    int round;
    for (round = 0; round < check_count(40); round++) {
        test_same_as_each(RAST_ALGO_AET, RAST_RULE_EVENODD, RAST_BOUNDARY_EXACT);
        test_same_as_each(RAST_ALGO_AET, RAST_RULE_NONZERO, RAST_BOUNDARY_EXACT);
        test_same_as_each(RAST_ALGO_EDGEFLAG, RAST_RULE_EVENODD, RAST_BOUNDARY_EXACT);
        test_same_as_each(RAST_ALGO_XSCAN, RAST_RULE_NONZERO, RAST_BOUNDARY_CONSERVATIVE);
        test_same_as_each(RAST_ALGO_EDGEFILL, RAST_RULE_EVENODD, RAST_BOUNDARY_CLOSED);
    }
    test_errors();
    return check_report("test_batch");
}

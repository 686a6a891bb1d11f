/*
 * test_modes.c - textbook rounding and the boundary modes through the C API:
 * the book's Figure 3-19 row, the span order every mode keeps, painting
 * equal to spans, and the scratch the modes ask for.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 777u
#include "check.h"
#include "rastrum.h"

static uint64_t scratch[1 << 15];

/* Spans as painted into a mask, with their order checked on the way. */
typedef struct span_log {
    unsigned char *img;
    int w, h;
    int32_t y, x1; /* last span */
    int started, ordered, inside;
} span_log;

static void log_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_log *l = (span_log *)user;
    int32_t x;
    if (l->started && (y < l->y || (y == l->y && x0 <= l->x1))) l->ordered = 0;
    if (x0 >= x1 || y < 0 || y >= l->h || x0 < 0 || x1 > l->w) {
        l->inside = 0;
        return;
    }
    for (x = x0; x < x1; x++) l->img[y * l->w + x] = 1;
    l->started = 1;
    l->y = y;
    l->x1 = x1;
}

static void test_textbook_figure_3_19(void)
{
    static const rast_point fig[] = {{7, 8}, {3, 12}, {1, 7}, {3, 1}, {6, 5}, {8, 1}, {12, 9}};
    static const uint32_t n = 7;
    static const int want[14] = {0, 0, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0};
    rast_polygon poly = {fig, &n, 1};
    rast_fill_opts o;
    unsigned char img[14 * 14];
    rast_target t;
    static const unsigned char one = 1;
    int i, same = 1;
    memset(&o, 0, sizeof o);
    o.rounding = RAST_ROUND_TEXTBOOK; /* S = 0, samples on the corners */
    memset(img, 0, sizeof img);
    CHECK(rast_target_init(&t, img, 14, 14, 14, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) == RAST_OK);
    for (i = 0; i < 14; i++) same &= img[3 * 14 + i] == want[i];
    CHECK(same); /* [2, 4] and [7, 8], as the book fills row 3 */
    o.rounding = (rast_rounding)2;
    CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.rounding = RAST_ROUND_EXACT;
    o.boundary = (rast_boundary)3;
    CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
}

/* Random polygons in every mode: spans ordered and inside the clip, and the
 * same pixels as rast_fill_polygon paints. */
static void test_spans_every_mode(void)
{
    enum { W = 48, H = 40 };
    static unsigned char a[W * H], b[W * H];
    static const unsigned char one = 1;
    rast_point pts[24];
    uint32_t sizes[2];
    int iter, ordered = 1, inside = 1, same = 1;
    for (iter = 0; iter < 3000; iter++) {
        rast_fill_opts o;
        rast_polygon poly;
        rast_target t;
        rast_rect clip;
        span_log l;
        int k, s = (int)(rng() % 9);
        uint32_t np;
        memset(&o, 0, sizeof o);
        o.subpixel_bits = s;
        o.sample = (rast_sample)(rng() % 2);
        o.rule = (rast_fill_rule)(rng() % 2);
        o.rounding = (rast_rounding)(rng() % 2);
        o.boundary = (rast_boundary)(rng() % 3);
        sizes[0] = 3 + rng() % 10;
        sizes[1] = rng() % 2 ? 3 + rng() % 10 : 0;
        np = sizes[0] + sizes[1];
        for (k = 0; k < (int)np; k++) {
            pts[k].x = (int32_t)(rng() % ((W + 8) << s)) - (4 << s);
            pts[k].y = (int32_t)(rng() % ((H + 8) << s)) - (4 << s);
            if (rng() % 4 == 0) pts[k].x &= ~((1 << s) - 1); /* on grid lines */
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = sizes[1] ? 2 : 1;
        memset(a, 0, sizeof a);
        memset(b, 0, sizeof b);
        rast_target_init(&t, a, W, H, W, RAST_FORMAT_GRAY8);
        if (rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) != RAST_OK) {
            CHECK(0);
            return;
        }
        l.img = b;
        l.w = W;
        l.h = H;
        l.started = 0;
        l.ordered = 1;
        l.inside = 1;
        clip.x0 = 0;
        clip.y0 = 0;
        clip.x1 = W;
        clip.y1 = H;
        if (rast_fill_polygon_spans(&poly, &o, &clip, log_span, &l, scratch, sizeof scratch) != RAST_OK) {
            CHECK(0);
            return;
        }
        ordered &= l.ordered;
        inside &= l.inside;
        same &= memcmp(a, b, sizeof a) == 0;
    }
    CHECK(ordered);
    CHECK(inside);
    CHECK(same);
}

static void test_scratch(void)
{
    rast_fill_opts o;
    size_t exact, closed, cons;
    memset(&o, 0, sizeof o);
    CHECK(rast_scratch_size(&o, 100, 640, 480, &exact) == RAST_OK);
    o.boundary = RAST_BOUNDARY_CLOSED;
    CHECK(rast_scratch_size(&o, 100, 640, 480, &closed) == RAST_OK);
    o.boundary = RAST_BOUNDARY_CONSERVATIVE;
    CHECK(rast_scratch_size(&o, 100, 640, 480, &cons) == RAST_OK);
    CHECK(closed > exact && cons == closed);
    {   /* one byte short: refused, target untouched */
        static const rast_point tri[] = {{0, 0}, {9, 1}, {3, 8}};
        static const uint32_t n = 3;
        rast_polygon poly = {tri, &n, 1};
        unsigned char img[100];
        static const unsigned char one = 1;
        rast_target t;
        size_t need;
        int k, clean = 1;
        memset(img, 0, sizeof img);
        rast_target_init(&t, img, 10, 10, 10, RAST_FORMAT_GRAY8);
        CHECK(rast_scratch_size(&o, 3, 10, 10, &need) == RAST_OK);
        CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, need - 1) == RAST_E_SCRATCH);
        for (k = 0; k < 100; k++) clean &= img[k] == 0;
        CHECK(clean);
        CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, need) == RAST_OK);
    }
}

int main(void)
{
    test_textbook_figure_3_19();
    test_spans_every_mode();
    test_scratch();
    return check_report("test_modes");
}

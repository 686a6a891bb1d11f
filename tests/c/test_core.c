/*
 * test_core.c - the C core against hand-worked rows and a brute-force
 * reference, with guard bytes around every target.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 12345u
#include "check.h"
#include "ref.h"
#include "rastrum.h"

#define GUARD 0xA5
#define PAD 16

/* ---- the brute-force reference (ref.h) ----------------------------------- */
static int ref_inside(const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                      int s, int center, int rule, int64_t i, int64_t j)
{
    int crossings, w = ref_winding(pts, sizes, nrings, s, center, 0, i, j, &crossings);
    return rule == RAST_RULE_EVENODD ? (crossings & 1) : (w != 0);
}

static uint64_t scratch[1 << 16];

/* The sample coordinate (fixed point) of the pixel holding v. */
static int32_t on_sample(int32_t v, int s, int center)
{
    int32_t one = (int32_t)1 << s, q = v / one;
    if (v % one < 0) q--;
    return q * one + (center ? one / 2 : 0);
}

static int guarded_equals_ref(const unsigned char *buf, int stride, const rast_point *pts,
                              const uint32_t *sizes, uint32_t nrings, int s, int center,
                              int rule, int w, int h);

/* Fill into a guarded gray8 buffer and compare every pixel with ref_inside,
 * with the solid painter over zeros and the opaque one over garbage. */
static int fill_and_compare(const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                            int s, int center, int rule, int w, int h)
{
    static unsigned char buf[(64 + 2 * PAD) * (64 + 2 * PAD)];
    int stride = w + 2 * PAD, i, j, ok = 1;
    rast_target t;
    rast_polygon p;
    rast_fill_opts o;
    unsigned char one = 1;
    memset(buf, GUARD, sizeof buf);
    for (j = 0; j < h; j++) memset(buf + (j + PAD) * stride + PAD, 0, (size_t)w);
    if (rast_target_init(&t, buf + PAD * stride + PAD, w, h, stride, RAST_FORMAT_GRAY8) != RAST_OK) return 0;
    p.points = pts;
    p.ring_sizes = sizes;
    p.nrings = nrings;
    memset(&o, 0, sizeof o);
    o.algorithm = RAST_ALGO_AET;
    o.rule = (rast_fill_rule)rule;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    if (rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) != RAST_OK) return 0;
    ok &= guarded_equals_ref(buf, stride, pts, sizes, nrings, s, center, rule, w, h);

    /* Opaque: the same pixels over garbage, with background 0; and with the
     * clip narrowed, nothing outside it touched. */
    {
        unsigned char zero = 0;
        for (j = 0; j < h; j++) memset(buf + (j + PAD) * stride + PAD, 0x77, (size_t)w);
        if (rast_fill_polygon_opaque(&t, &p, &o, &one, &zero, scratch, sizeof scratch) != RAST_OK) return 0;
        ok &= guarded_equals_ref(buf, stride, pts, sizes, nrings, s, center, rule, w, h);
        t.clip.x0 = w / 3;
        t.clip.y0 = h / 4;
        t.clip.x1 = w - w / 5;
        t.clip.y1 = h - h / 3;
        for (j = 0; j < h; j++) memset(buf + (j + PAD) * stride + PAD, 0x77, (size_t)w);
        if (rast_fill_polygon_opaque(&t, &p, &o, &one, &zero, scratch, sizeof scratch) != RAST_OK) return 0;
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++) {
                unsigned char got = buf[(j + PAD) * stride + i + PAD];
                int in_clip = i >= t.clip.x0 && i < t.clip.x1 && j >= t.clip.y0 && j < t.clip.y1;
                if (!in_clip && got != 0x77) ok = 0;
                if (in_clip && got != ref_inside(pts, sizes, nrings, s, center, rule, i, j)) ok = 0;
            }
    }
    return ok;
}

/* Every pixel of the w x h target inside the guarded buffer equals the
 * reference, and every guard byte is intact. */
static int guarded_equals_ref(const unsigned char *buf, int stride, const rast_point *pts,
                              const uint32_t *sizes, uint32_t nrings, int s, int center,
                              int rule, int w, int h)
{
    int i, j, ok = 1;
    for (j = -PAD; j < h + PAD; j++)
        for (i = -PAD; i < w + PAD; i++) {
            unsigned char got = buf[(j + PAD) * stride + i + PAD];
            if (i < 0 || j < 0 || i >= w || j >= h) {
                if (got != GUARD) ok = 0;
            } else if (got != ref_inside(pts, sizes, nrings, s, center, rule, i, j)) {
                ok = 0;
            }
        }
    return ok;
}

/* ---- Figure 3-19 of seed 001, worked by hand -------------------------------
 * P0(7,8) P1(3,12) P2(1,7) P3(3,1) P4(6,5) P5(8,1) P6(12,9), samples at
 * integer points, S = 0.  Row 3 crosses at 2 1/3, 4 1/2, 7, 9: pixels 3-4
 * and 7-8 (the book rounds 2 1/3 to 2).  Row 1 crosses at 3, 3, 8, 8 (the
 * local minima P3 and P5 counted twice): nothing.  Row 8 crosses at 1.4, 7,
 * 7, 11.5: pixels 2-11.  Rows 12 and 13: nothing (bottom open). */
static void test_figure_3_19(void)
{
    static const rast_point fig[] = {{7, 8}, {3, 12}, {1, 7}, {3, 1}, {6, 5}, {8, 1}, {12, 9}};
    static const uint32_t n = 7;
    /* first and last+1 pixel of each span, per row; -1 ends a row */
    static const int rows[14][5] = {
        {-1}, {-1}, {3, 4, 8, 9, -1}, {3, 5, 7, 9, -1}, {2, 6, 7, 10, -1},
        {2, 10, -1}, {2, 11, -1}, {1, 11, -1}, {2, 12, -1}, {2, 6, -1},
        {3, 5, -1}, {3, 4, -1}, {-1}, {-1},
    };
    unsigned char img[14][14];
    unsigned char one = 1;
    rast_target t;
    rast_polygon p;
    rast_fill_opts o;
    int i, j, k;

    memset(img, 0, sizeof img);
    CHECK(rast_target_init(&t, img, 14, 14, 14, RAST_FORMAT_GRAY8) == RAST_OK);
    p.points = fig;
    p.ring_sizes = &n;
    p.nrings = 1;
    memset(&o, 0, sizeof o);
    for (k = 0; k < 2; k++) {
        o.rule = k ? RAST_RULE_NONZERO : RAST_RULE_EVENODD; /* simple: rules agree */
        memset(img, 0, sizeof img);
        CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_OK);
        for (j = 0; j < 14; j++) {
            unsigned char want[14];
            memset(want, 0, sizeof want);
            for (i = 0; rows[j][i] >= 0; i += 2) memset(want + rows[j][i], 1, (size_t)(rows[j][i + 1] - rows[j][i]));
            CHECK(memcmp(img[j], want, 14) == 0);
        }
    }
}

/* ---- spans: order, merging, clipping ------------------------------------- */
typedef struct {
    int n, bad;
    int32_t y, x1;
    long area;
} span_log;

static void log_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_log *l = (span_log *)user;
    if (x0 >= x1) l->bad++;
    if (l->n && (y < l->y || (y == l->y && x0 <= l->x1))) l->bad++; /* order, no touching */
    l->n++;
    l->y = y;
    l->x1 = x1;
    l->area += x1 - x0;
}

static void test_spans(void)
{
    /* Two squares side by side sharing an edge: one span per row, merged. */
    static const rast_point sq[] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {4, 0}, {8, 0}, {8, 4}, {4, 4}};
    static const uint32_t sizes[] = {4, 4};
    rast_polygon p = {sq, sizes, 2};
    rast_fill_opts o;
    rast_rect clip = {-5, -5, 100, 100}, small = {2, 1, 6, 3}, none = {3, 3, 3, 9};
    span_log l;
    memset(&o, 0, sizeof o);
    o.rule = RAST_RULE_NONZERO;
    o.sample = RAST_SAMPLE_CENTER;
    memset(&l, 0, sizeof l);
    CHECK(rast_fill_polygon_spans(&p, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_OK);
    CHECK(l.n == 4 && l.bad == 0 && l.area == 32);
    memset(&l, 0, sizeof l);
    CHECK(rast_fill_polygon_spans(&p, &o, &small, log_span, &l, scratch, sizeof scratch) == RAST_OK);
    CHECK(l.n == 2 && l.bad == 0 && l.area == 8);
    memset(&l, 0, sizeof l);
    CHECK(rast_fill_polygon_spans(&p, &o, &none, log_span, &l, scratch, sizeof scratch) == RAST_OK);
    CHECK(l.n == 0);
    /* Even-odd: the shared edge is crossed twice, still one merged span. */
    o.rule = RAST_RULE_EVENODD;
    memset(&l, 0, sizeof l);
    CHECK(rast_fill_polygon_spans(&p, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_OK);
    CHECK(l.n == 4 && l.bad == 0 && l.area == 32);
}

/* ---- errors: a status, and the target untouched ----------------------------- */
static void test_errors(void)
{
    rast_point tri[3] = {{1, 1}, {30, 2}, {10, 30}};
    uint32_t n = 3;
    rast_polygon p = {tri, &n, 1};
    rast_fill_opts o;
    rast_target t;
    unsigned char img[32 * 32], before[32 * 32], one = 1;
    size_t need = 0;
    int32_t bpp = 0;
    memset(&o, 0, sizeof o);
    memset(img, 7, sizeof img);
    memcpy(before, img, sizeof img);
    CHECK(rast_target_init(&t, img, 32, 32, 32, RAST_FORMAT_GRAY8) == RAST_OK);

    CHECK(rast_target_init(&t, img, 32, 32, 31, RAST_FORMAT_GRAY8) == RAST_E_SIZE);
    CHECK(rast_target_init(&t, img, -1, 32, 32, RAST_FORMAT_GRAY8) == RAST_E_SIZE);
    CHECK(rast_target_init(&t, img, 32, 32, 32, (rast_format)9) == RAST_E_FORMAT);
    CHECK(rast_target_init(&t, NULL, 32, 32, 32, RAST_FORMAT_GRAY8) == RAST_E_NULL);
    CHECK(rast_target_init(&t, img, 32, 32, 32, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_format_bytes(RAST_FORMAT_RGB888, &bpp) == RAST_OK && bpp == 3);

    CHECK(rast_scratch_size(&o, 3, 32, 32, &need) == RAST_OK);
    CHECK(need <= RAST_AET_SCRATCH_BOUND(3, 32));
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, need - 1) == RAST_E_SCRATCH);
    CHECK(rast_fill_polygon(&t, &p, &o, &one, (char *)scratch + 4, need) == RAST_E_ALIGN);
    tri[1].x = RAST_COORD_MAX + 1;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_RANGE);
    tri[1].x = -RAST_COORD_MAX - 1;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_RANGE);
    tri[1].x = 30;
    o.subpixel_bits = RAST_MAX_SUBPIXEL_BITS + 1;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_SUBPIXEL);
    o.subpixel_bits = -1;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_SUBPIXEL);
    o.subpixel_bits = 0;
    o.algorithm = RAST_ALGO_COUNT_;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_ALGORITHM);
    o.algorithm = RAST_ALGO_AET;
    o.rule = (rast_fill_rule)5;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.rule = RAST_RULE_EVENODD;
    o.sample = (rast_sample)3;
    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.sample = RAST_SAMPLE_CORNER;
    CHECK(rast_fill_polygon(&t, &p, &o, NULL, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_polygon(NULL, &p, &o, &one, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_polygon(&t, NULL, &o, &one, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(memcmp(img, before, sizeof img) == 0);

    CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch, need) == RAST_OK);
    CHECK(memcmp(img, before, sizeof img) != 0);

    CHECK(strcmp(rast_status_str(RAST_OK), "ok") == 0);
    CHECK(strcmp(rast_status_str((rast_status)-999), "unknown status") == 0);
    CHECK(strcmp(rast_status_str(RAST_E_RANGE), rast_status_str(RAST_E_SCRATCH)) != 0);
    CHECK(rast_version_number() == RAST_VERSION_NUMBER);
}

/* ---- random polygons against the reference, guard bytes intact ------------- */
static void test_random(void)
{
    rast_point pts[24];
    uint32_t sizes[3];
    int iter, bad = 0, runs = 0;
    for (iter = 0; iter < 3000; iter++) {
        int s = (int)(rng() % 9), center = (int)(rng() & 1), rule = (int)(rng() & 1);
        int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 40);
        uint32_t nrings = 1 + rng() % 3, k, v, total = 0;
        int32_t span = (int32_t)((w > h ? w : h) + 8) << s;
        for (k = 0; k < nrings; k++) {
            sizes[k] = 3 + rng() % 6;
            for (v = 0; v < sizes[k]; v++, total++) {
                /* a quarter of the vertices on the sample grid */
                pts[total].x = (int32_t)(rng() % (uint32_t)span) - (4 << s);
                pts[total].y = (int32_t)(rng() % (uint32_t)span) - (4 << s);
                if (rng() % 4 == 0) {
                    pts[total].x = on_sample(pts[total].x, s, center);
                    pts[total].y = on_sample(pts[total].y, s, center);
                }
            }
        }
        bad += !fill_and_compare(pts, sizes, nrings, s, center, rule, w, h);
        runs++;
    }
    CHECK(runs == 3000);
    CHECK(bad == 0);
}

/* ---- coordinates at the limit: huge polygons seen through a small window --- */
static void test_limits(void)
{
    int s, bad = 0;
    for (s = 0; s <= RAST_MAX_SUBPIXEL_BITS; s++) {
        const int32_t M = RAST_COORD_MAX;
        /* A thin wedge from one corner of the range to the other, passing
         * near the origin, and a triangle with vertices on the extremes. */
        rast_point a[3] = {{-M, -M}, {M, M - 1}, {M, M}};
        rast_point b[3] = {{-M, 0}, {M, -M}, {M, M}};
        uint32_t n = 3;
        int c;
        for (c = 0; c < 2; c++) {
            bad += !fill_and_compare(a, &n, 1, s, c, RAST_RULE_EVENODD, 40, 40);
            bad += !fill_and_compare(b, &n, 1, s, c, RAST_RULE_NONZERO, 40, 40);
        }
    }
    CHECK(bad == 0);
}

/* A comb of 100 teeth: rows of 100 spans reach the painter in parts. */
static void test_comb(void)
{
    static rast_point comb[404];
    uint32_t n = 0, k;
    int bad = 0, rule;
    for (k = 0; k < 100; k++) {
        comb[n].x = (int32_t)(4 * k) << 4; comb[n++].y = 2 << 4;
        comb[n].x = (int32_t)(4 * k + 2) << 4; comb[n++].y = 2 << 4;
        comb[n].x = (int32_t)(4 * k + 2) << 4; comb[n++].y = 30 << 4;
        comb[n].x = (int32_t)(4 * k + 4) << 4; comb[n++].y = 30 << 4;
    }
    /* close along the bottom, beyond row 40 */
    comb[n - 1].y = 50 << 4;
    comb[n].x = 0; comb[n++].y = 50 << 4;
    for (rule = 0; rule < 2; rule++) {
        /* view columns 0..63 of the comb, then a window further right */
        bad += !fill_and_compare(comb, &n, 1, 4, 1, rule, 64, 64);
    }
    {
        static unsigned char img[40 * 400];
        unsigned char one = 1, zero = 0;
        rast_target t;
        rast_polygon p = {comb, &n, 1};
        rast_fill_opts o;
        int i, j;
        memset(&o, 0, sizeof o);
        o.subpixel_bits = 4;
        o.sample = RAST_SAMPLE_CENTER;
        memset(img, 0x77, sizeof img);
        CHECK(rast_target_init(&t, img, 400, 40, 400, RAST_FORMAT_GRAY8) == RAST_OK);
        CHECK(rast_fill_polygon_opaque(&t, &p, &o, &one, &zero, scratch, sizeof scratch) == RAST_OK);
        for (j = 0; j < 40; j++)
            for (i = 0; i < 400; i++)
                bad += img[j * 400 + i] != ref_inside(comb, &n, 1, 4, 1, 0, i, j);
    }
    CHECK(bad == 0);
}

int main(void)
{
    test_figure_3_19();
    test_spans();
    test_errors();
    test_random();
    test_limits();
    test_comb();
    return check_report("test_core");
}

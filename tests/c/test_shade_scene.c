/* test_shade_scene.c - Gouraud rectangles and colour polygons from C:
 * guard bytes around every buffer (nothing written outside the clip), the
 * pixel set equal to the plain fill's (two backgrounds), a hand-computed
 * value, errors before any write.  The exact colours are held against a
 * Fraction oracle in tests/test_shading.py. */
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "rastrum.h"

#define W 23
#define H 17
#define GUARD 64

/* A union so that a 16-bit target over mem + GUARD is aligned. */
static union {
    unsigned char b[GUARD + W * H * 4 + GUARD];
    uint64_t align;
} mem_u;
#define mem (mem_u.b)
static unsigned char plain[W * H * 4];
static uint64_t scratch[8192];

static uint32_t rnd_state = 12345u;
static int32_t rnd(int32_t lo, int32_t hi) /* [lo, hi] */
{
    rnd_state = rnd_state * 1103515245u + 12345u;
    return lo + (int32_t)((rnd_state >> 8) % (uint32_t)(hi - lo + 1));
}

static int guards_ok(void)
{
    int k;
    for (k = 0; k < GUARD; k++)
        if (mem[k] != 0xA5 || mem[GUARD + W * H * 4 + k] != 0xA5) return 0;
    return 1;
}

/* A target over mem with `bg` everywhere and a clip inside. */
static void target(rast_target *t, rast_format f, int32_t bpp, unsigned char bg, const rast_rect *clip)
{
    memset(mem, 0xA5, sizeof mem);
    memset(mem + GUARD, bg, (size_t)W * H * (size_t)bpp);
    rast_target_init(t, mem + GUARD, W, H, W * bpp, f);
    if (clip) t->clip = *clip;
}

static void test_rect(void)
{
    rast_tri_opts o;
    rast_shade_opts sh;
    rast_target t;
    uint8_t cols[16];
    int it, k;
    memset(&o, 0, sizeof o);
    memset(&sh, 0, sizeof sh);
    /* A 4 x 1 gray ramp 0 -> 80 at S = 0, centres: 10, 30, 50, 70. */
    {
        static const uint8_t ramp[16] = {0, 0, 0, 0, 80, 0, 0, 0, 80, 0, 0, 0, 0, 0, 0, 0};
        rast_point p0 = {0, 0}, p1 = {4, 1};
        o.sample = RAST_SAMPLE_CENTER;
        target(&t, RAST_FORMAT_GRAY8, 1, 0, NULL);
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, ramp, &o, &sh) == RAST_OK);
        CHECK(mem[GUARD] == 10 && mem[GUARD + 1] == 30 && mem[GUARD + 2] == 50 && mem[GUARD + 3] == 70);
        CHECK(mem[GUARD + 4] == 0 && mem[GUARD + W] == 0);
    }
    for (it = 0; it < 400; it++) {
        rast_point p0, p1, ring[4];
        rast_polygon poly;
        rast_fill_opts fo;
        rast_rect clip;
        uint32_t four = 4;
        unsigned char one = 1;
        int same = 1;
        o.subpixel_bits = rnd(0, 4);
        o.sample = rnd(0, 1) ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        o.rounding = rnd(0, 3) == 0 ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
        sh.precision = (rast_precision)rnd(0, 2);
        sh.fraction_bits = rnd(1, 16);
        p0.x = rnd(-40, (W + 5) << o.subpixel_bits);
        p0.y = rnd(-40, (H + 5) << o.subpixel_bits);
        p1.x = rnd(-40, (W + 5) << o.subpixel_bits);
        p1.y = rnd(-40, (H + 5) << o.subpixel_bits);
        clip.x0 = rnd(-2, 8);
        clip.y0 = rnd(-2, 8);
        clip.x1 = rnd(6, W + 3);
        clip.y1 = rnd(6, H + 3);
        for (k = 0; k < 16; k++) cols[k] = (uint8_t)rnd(1, 255); /* never 0 */
        /* The plain fill of the ring, same options, same clip. */
        ring[0] = p0;
        ring[1].x = p1.x;
        ring[1].y = p0.y;
        ring[2] = p1;
        ring[3].x = p0.x;
        ring[3].y = p1.y;
        poly.points = ring;
        poly.ring_sizes = &four;
        poly.nrings = 1;
        memset(&fo, 0, sizeof fo);
        fo.subpixel_bits = o.subpixel_bits;
        fo.sample = o.sample;
        fo.rounding = o.rounding;
        target(&t, RAST_FORMAT_GRAY8, 1, 0, &clip);
        CHECK(rast_fill_polygon(&t, &poly, &fo, &one, scratch, sizeof scratch) == RAST_OK);
        memcpy(plain, mem + GUARD, W * H);
        target(&t, RAST_FORMAT_RGBA8888, 4, 0, &clip);
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_OK);
        CHECK(guards_ok());
        for (k = 0; k < W * H; k++) same &= (plain[k] != 0) == (mem[GUARD + 4 * k] != 0);
        CHECK(same);
    }
    /* Errors: nothing written. */
    {
        rast_point p0 = {0, 0}, p1 = {8, 8}, far = {RAST_COORD_MAX + 1, 0};
        rast_point big = {RAST_GOURAUD_RECT_MAX_SIZE + 1, 8};
        memset(&o, 0, sizeof o);
        memset(&sh, 0, sizeof sh);
        target(&t, RAST_FORMAT_RGB888, 3, 7, NULL);
        CHECK(rast_fill_rect_gouraud(NULL, p0, p1, cols, &o, &sh) == RAST_E_NULL);
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, NULL, &o, &sh) == RAST_E_NULL);
        CHECK(rast_fill_rect_gouraud(&t, p0, far, cols, &o, &sh) == RAST_E_RANGE);
        CHECK(rast_fill_rect_gouraud(&t, p0, big, cols, &o, &sh) == RAST_E_RANGE);
        sh.precision = RAST_PRECISION_FIXED;
        sh.fraction_bits = 0;
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_E_ARG);
        sh.precision = (rast_precision)9;
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_E_ARG);
        sh.precision = RAST_PRECISION_EXACT;
        o.boundary = RAST_BOUNDARY_CLOSED;
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_E_ARG);
        o.boundary = RAST_BOUNDARY_EXACT;
        o.subpixel_bits = 17;
        CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_E_SUBPIXEL);
        for (k = 0; k < W * H * 3; k++)
            if (mem[GUARD + k] != 7) break;
        CHECK(k == W * H * 3 && guards_ok());
    }
}

static void test_polygon(void)
{
    rast_fill_opts o;
    rast_shade_opts sh;
    rast_target t;
    rast_point pts[12];
    uint8_t cols[12 * 4];
    uint32_t sizes[3];
    rast_polygon poly;
    size_t need;
    int it, k;
    memset(&sh, 0, sizeof sh);
    for (it = 0; it < 400; it++) {
        rast_rect clip;
        unsigned char one = 1;
        uint32_t n = 0, r;
        int same = 1;
        memset(&o, 0, sizeof o);
        o.subpixel_bits = rnd(0, 6);
        o.sample = rnd(0, 1) ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        o.rule = rnd(0, 1) ? RAST_RULE_NONZERO : RAST_RULE_EVENODD;
        sh.precision = rnd(0, 3) ? RAST_PRECISION_EXACT : RAST_PRECISION_FLAT;
        poly.nrings = (uint32_t)rnd(1, 3);
        for (r = 0; r < poly.nrings; r++) {
            sizes[r] = (uint32_t)rnd(3, 4);
            for (k = 0; k < (int)sizes[r]; k++, n++) {
                pts[n].x = rnd(-30, (W + 4) << o.subpixel_bits);
                pts[n].y = rnd(-30, (H + 4) << o.subpixel_bits);
            }
        }
        for (k = 0; k < (int)n * 4; k++) cols[k] = (uint8_t)rnd(1, 255);
        poly.points = pts;
        poly.ring_sizes = sizes;
        clip.x0 = rnd(-2, 8);
        clip.y0 = rnd(-2, 8);
        clip.x1 = rnd(6, W + 3);
        clip.y1 = rnd(6, H + 3);
        target(&t, RAST_FORMAT_GRAY8, 1, 0, &clip);
        CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) == RAST_OK);
        memcpy(plain, mem + GUARD, W * H);
        target(&t, RAST_FORMAT_RGB888, 3, 0, &clip);
        CHECK(rast_polygon_gouraud_scratch_size(n, W, H, &need) == RAST_OK);
        CHECK(need <= sizeof scratch);
        CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need) == RAST_OK);
        CHECK(guards_ok());
        for (k = 0; k < W * H; k++) same &= (plain[k] != 0) == (mem[GUARD + 3 * k] != 0);
        CHECK(same);
    }
    /* Errors before any write. */
    target(&t, RAST_FORMAT_RGB888, 3, 7, NULL);
    memset(&o, 0, sizeof o);
    memset(&sh, 0, sizeof sh);
    sizes[0] = 3;
    poly.nrings = 1;
    CHECK(rast_polygon_gouraud_scratch_size(3, W, H, &need) == RAST_OK);
    CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need - 1) == RAST_E_SCRATCH);
    CHECK(rast_fill_polygon_gouraud(&t, &poly, NULL, &o, &sh, scratch, need) == RAST_E_NULL);
    o.algorithm = RAST_ALGO_XSCAN;
    CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need) == RAST_E_ALGORITHM);
    o.algorithm = RAST_ALGO_AET;
    sh.precision = RAST_PRECISION_FIXED;
    sh.fraction_bits = 8;
    CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need) == RAST_E_ARG);
    sh.precision = RAST_PRECISION_EXACT;
    pts[1].x = RAST_COORD_MAX + 1;
    CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need) == RAST_E_RANGE);
    pts[1].x = 0;
    {
        rast_target c16;
        CHECK(rast_target_init(&c16, mem + GUARD, W, H / 2, W * 2, RAST_FORMAT_COUNT16) == RAST_OK);
        CHECK(rast_fill_polygon_gouraud(&c16, &poly, cols, &o, &sh, scratch, need) == RAST_E_FORMAT);
    }
    for (k = 0; k < W * H * 3; k++)
        if (mem[GUARD + k] != 7) break;
    CHECK(k == W * H * 3 && guards_ok());
}

/* Textbook rounding owns a sample up to half a pixel left of the run's
 * left crossing, where the edge-to-edge line is extrapolated: the value
 * there is the plane's, clamped to 0..255 (found by fuzz_shade: pixel
 * (10, 1) of this triangle, plane value -784/617, was stored as 255, and a
 * tiny run could overflow the quotient). */
static void test_polygon_textbook_clamp(void)
{
    static rast_point pts[3] = {{48, -5}, {15, -8}, {-8, 46}};
    static const uint8_t cols[12] = {96, 243, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    static const uint32_t three = 3;
    static uint8_t img[48 * 48];
    rast_polygon poly;
    rast_fill_opts o;
    rast_shade_opts sh;
    rast_target t;
    size_t need = 0;
    poly.points = pts;
    poly.ring_sizes = &three;
    poly.nrings = 1;
    memset(&o, 0, sizeof o);
    memset(&sh, 0, sizeof sh);
    o.algorithm = RAST_ALGO_AET;
    o.sample = RAST_SAMPLE_CENTER;
    o.rounding = RAST_ROUND_TEXTBOOK;
    memset(img, 7, sizeof img);
    CHECK(rast_target_init(&t, img, 48, 48, 48, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_polygon_gouraud_scratch_size(3, 48, 48, &need) == RAST_OK);
    CHECK(need <= sizeof scratch);
    CHECK(rast_fill_polygon_gouraud(&t, &poly, cols, &o, &sh, scratch, need) == RAST_OK);
    CHECK(img[1 * 48 + 10] == 0);
}

/* The same for rectangles (found by fuzz_shade): textbook rounding owns
 * column 11 of this rectangle, x from 11.9375 to 16, whose sample 11.5 is
 * left of it; its red, extrapolated to a little below 0, was stored as 255,
 * and the truncating division put every later pixel of the row one level
 * too high. */
static void test_rect_textbook_clamp(void)
{
    static const uint8_t cols[16] = {89, 255, 255, 0, 0, 192, 170, 250, 34, 95, 85, 0, 0, 51, 253, 253};
    static uint8_t img[20 * 20 * 3];
    rast_point p0 = {256, 204}, p1 = {191, -128};
    rast_tri_opts o;
    rast_shade_opts sh;
    rast_target t;
    memset(&o, 0, sizeof o);
    memset(&sh, 0, sizeof sh);
    o.subpixel_bits = 4;
    o.sample = RAST_SAMPLE_CENTER;
    o.rounding = RAST_ROUND_TEXTBOOK;
    memset(img, 7, sizeof img);
    CHECK(rast_target_init(&t, img, 20, 20, 60, RAST_FORMAT_RGB888) == RAST_OK);
    CHECK(rast_fill_rect_gouraud(&t, p0, p1, cols, &o, &sh) == RAST_OK);
    CHECK(img[(9 * 20 + 11) * 3] == 0);  /* extrapolated below 0: clamped */
    CHECK(img[(9 * 20 + 12) * 3] == 15); /* Fraction reference: floor(c + 1/2) */
    CHECK(img[(9 * 20 + 15) * 3] == 66);
    CHECK(img[(9 * 20 + 11) * 3 + 1] == 172);
}

int main(void)
{
    test_rect();
    test_polygon();
    test_polygon_textbook_clamp();
    test_rect_textbook_clamp();
    return check_report("test_shade_scene");
}

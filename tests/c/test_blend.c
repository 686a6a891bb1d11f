/*
 * test_blend.c - opacity (rastrum.h, "opacity: source-over"):
 *  - rast_fill_polygon_aa_blend / rast_fill_triangles_aa_blend paint
 *    exactly what rast_blend_coverage paints through the uint8 coverage
 *    rast_polygon_coverage / rast_triangles_coverage give for the target's
 *    clip, and rast_fill_polygon_blend what it paints through
 *    rast_fill_polygon's mask (255 inside): every format of the four,
 *    straight and premultiplied, random alpha, opacity, clip, method and
 *    rings; nothing outside the clip is touched (the whole buffer is
 *    compared, guard rows and row padding included).  The blend itself is
 *    held against the exact rational oracle in tests/test_opacity.py.
 *  - alpha 255 and opacity 255: rast_fill_polygon_aa_blend writes what
 *    rast_fill_polygon_aa writes with the packed colour (GRAY8, RGB888,
 *    RGB565, premultiplied RGBA8888), and rast_fill_polygon_blend what
 *    rast_fill_polygon writes: the opaque fills' bytes.
 *  - errors before anything is written.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 3434u
#include "check.h"
#include "rastrum.h"

#define GUARD 0x5A
static uint64_t scratch_mem[1 << 16];
#include "scratch.h"

#define W 13
#define H 11
#define PAD 2
#define STRIDE (W * 4 + 2 * PAD)
#define SIZE ((H + 2 * PAD) * STRIDE)

static uint64_t mem[3][SIZE / 8 + 1];
#define before ((unsigned char *)mem[0])
#define got ((unsigned char *)mem[1])
#define want ((unsigned char *)mem[2])

static const rast_format formats[4] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888, RAST_FORMAT_RGB565,
                                       RAST_FORMAT_RGBA8888};

static void target(rast_target *t, unsigned char *buf, rast_format f, const rast_rect *clip)
{
    CHECK(rast_target_init(t, buf + PAD * STRIDE, W, H, STRIDE, f) == RAST_OK);
    t->clip = *clip;
}

static size_t cov_scratch(const rast_coverage_opts *o, uint32_t np, const rast_rect *c)
{
    size_t need = 0;
    CHECK(rast_coverage_scratch_size(o, np, c->x1 - c->x0, c->y1 - c->y0, &need) == RAST_OK);
    return need;
}

static void test_random(void)
{
    int iter, n = check_count(800);
    for (iter = 0; iter < n; iter++) {
        rast_format f = formats[iter % 4];
        rast_point pts[12];
        uint32_t sizes[3], nr = 1 + rng() % 3, k, np = 0;
        rast_polygon poly;
        rast_coverage_opts o;
        rast_fill_opts fo;
        rast_blend_opts b;
        rast_target t;
        rast_rect clip, cut;
        uint8_t cov[H * W], rgba[4];
        unsigned char *s;
        size_t need, i;
        int kind = iter % 3; /* 0 polygon aa, 1 triangles aa, 2 polygon binary */
        memset(&o, 0, sizeof o);
        memset(&fo, 0, sizeof fo);
        o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
        o.rule = (rast_fill_rule)(rng() % 2);
        o.subpixel_bits = (int32_t)(rng() % 5);
        fo.rule = o.rule;
        fo.subpixel_bits = o.subpixel_bits;
        if (kind == 1) nr = 1 + rng() % 2;
        for (k = 0; k < nr; k++) {
            uint32_t m = kind == 1 ? 3 : 3 + rng() % 2, j;
            sizes[k] = m;
            for (j = 0; j < m; j++, np++) {
                pts[np].x = (int32_t)(rng() % (uint32_t)((W + 4) << o.subpixel_bits)) - (2 << o.subpixel_bits);
                pts[np].y = (int32_t)(rng() % (uint32_t)((H + 4) << o.subpixel_bits)) - (2 << o.subpixel_bits);
            }
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nr;
        for (k = 0; k < 4; k++) rgba[k] = (uint8_t)rng();
        if (iter % 5 == 0) rgba[3] = 255;
        b.opacity = iter % 7 == 0 ? 255 : (int32_t)(rng() % 256);
        b.premultiplied = f == RAST_FORMAT_RGBA8888 ? (int32_t)(rng() % 2) : (int32_t)(rng() % 2);
        clip.x0 = (int32_t)(rng() % 5) - 1;
        clip.y0 = (int32_t)(rng() % 5) - 1;
        clip.x1 = W + 1 - (int32_t)(rng() % 6);
        clip.y1 = H + 1 - (int32_t)(rng() % 6);
        cut = clip;
        if (cut.x0 < 0) cut.x0 = 0;
        if (cut.y0 < 0) cut.y0 = 0;
        if (cut.x1 > W) cut.x1 = W;
        if (cut.y1 > H) cut.y1 = H;
        for (i = 0; i < SIZE; i++) before[i] = (unsigned char)rng();
        if (f == RAST_FORMAT_RGBA8888 && b.premultiplied) /* a premultiplied image */
            for (i = 0; i + 3 < SIZE; i += 4) {
                for (k = 0; k < 3; k++)
                    if (before[i + k] > before[i + 3]) before[i + k] = before[i + 3];
            }
        memcpy(got, before, SIZE);
        memcpy(want, before, SIZE);
        /* the image rast_blend_coverage reads: coverage, or the binary mask */
        memset(cov, 0, sizeof cov);
        if (kind == 2) {
            rast_target m;
            uint8_t on = 255;
            CHECK(rast_target_init(&m, cov, cut.x1 - cut.x0, cut.y1 - cut.y0, W, RAST_FORMAT_GRAY8) ==
                  RAST_OK);
            CHECK(rast_scratch_size(&fo, np, W, H, &need) == RAST_OK);
            s = scratch_for(need);
            {
                rast_point moved[12];
                rast_polygon mp = poly;
                for (k = 0; k < np; k++) {
                    moved[k].x = pts[k].x - (cut.x0 << fo.subpixel_bits);
                    moved[k].y = pts[k].y - (cut.y0 << fo.subpixel_bits);
                }
                mp.points = moved;
                CHECK(rast_fill_polygon(&m, &mp, &fo, &on, s, need) == RAST_OK);
            }
            target(&t, got, f, &clip);
            CHECK(rast_fill_polygon_blend(&t, &poly, &fo, rgba, &b, s, need) == RAST_OK);
        } else {
            need = cov_scratch(&o, np, &cut);
            s = scratch_for(need);
            CHECK((kind == 0 ? rast_polygon_coverage(&poly, &o, &cut, RAST_COVERAGE_U8, cov, W, s, need)
                             : rast_triangles_coverage(pts, np / 3, &o, &cut, RAST_COVERAGE_U8, cov, W, s,
                                                       need)) == RAST_OK);
            target(&t, got, f, &clip);
            CHECK((kind == 0 ? rast_fill_polygon_aa_blend(&t, &poly, &o, rgba, &b, s, need)
                             : rast_fill_triangles_aa_blend(&t, pts, np / 3, &o, rgba, &b, s, need)) ==
                  RAST_OK);
            CHECK(scratch_guard_ok(s, need));
        }
        target(&t, want, f, &clip);
        CHECK(rast_blend_coverage(&t, cov, RAST_COVERAGE_U8, W, rgba, &b) == RAST_OK);
        CHECK(memcmp(got, want, SIZE) == 0);
        /* opaque: the value fills' bytes */
        if (rgba[3] == 255 && b.opacity == 255 &&
            (f != RAST_FORMAT_RGBA8888 || b.premultiplied) && kind != 1) {
            unsigned char value[4];
            CHECK(rast_pack_color(f, rgba, value) == RAST_OK);
            memcpy(want, before, SIZE);
            target(&t, want, f, &clip);
            if (kind == 0) {
                CHECK(rast_fill_polygon_aa(&t, &poly, &o, value, s, need) == RAST_OK);
            } else {
                CHECK(rast_scratch_size(&fo, np, W, H, &need) == RAST_OK);
                s = scratch_for(need);
                CHECK(rast_fill_polygon(&t, &poly, &fo, value, s, need) == RAST_OK);
            }
            CHECK(memcmp(got, want, SIZE) == 0);
        }
    }
}

static void test_errors(void)
{
    static const rast_point tri[3] = {{0, 0}, {W << 8, 0}, {0, H << 8}};
    static const uint32_t three = 3;
    rast_polygon poly;
    rast_coverage_opts o;
    rast_fill_opts fo;
    rast_blend_opts b;
    rast_target t;
    rast_rect all = {0, 0, W, H};
    uint8_t rgba[4] = {10, 20, 30, 40};
    unsigned char *s;
    size_t need;
    int f;
    poly.points = tri;
    poly.ring_sizes = &three;
    poly.nrings = 1;
    memset(&o, 0, sizeof o);
    memset(&fo, 0, sizeof fo);
    fo.subpixel_bits = 8;
    o.subpixel_bits = 8;
    CHECK(rast_coverage_scratch_size(&o, 3, W, H, &need) == RAST_OK);
    s = scratch_for(need);
    memset(before, 7, SIZE);
    memcpy(got, before, SIZE);
    b.premultiplied = 0;
    b.opacity = 256;
    target(&t, got, RAST_FORMAT_RGB888, &all);
    CHECK(rast_fill_polygon_aa_blend(&t, &poly, &o, rgba, &b, s, need) == RAST_E_ARG);
    CHECK(rast_fill_triangles_aa_blend(&t, tri, 1, &o, rgba, &b, s, need) == RAST_E_ARG);
    CHECK(rast_fill_polygon_blend(&t, &poly, &fo, rgba, &b, s, need) == RAST_E_ARG);
    b.opacity = 255;
    b.premultiplied = -1;
    CHECK(rast_fill_polygon_aa_blend(&t, &poly, &o, rgba, &b, s, need) == RAST_E_ARG);
    b.premultiplied = 0;
    CHECK(rast_fill_polygon_aa_blend(&t, &poly, &o, NULL, &b, s, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon_aa_blend(&t, NULL, &o, rgba, &b, s, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon_blend(&t, NULL, &fo, rgba, &b, s, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon_aa_blend(NULL, &poly, &o, rgba, &b, s, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon_aa_blend(&t, &poly, &o, rgba, &b, s, need - 1) == RAST_E_SCRATCH);
    o.method = RAST_AA_COUNT_;
    CHECK(rast_fill_triangles_aa_blend(&t, tri, 1, &o, rgba, NULL, s, need) == RAST_E_ARG);
    o.method = RAST_AA_AREA;
    for (f = 0; f < 2; f++) {
        rast_format fmt = f ? RAST_FORMAT_MONO1 : RAST_FORMAT_COUNT16;
        CHECK(rast_target_init(&t, got + PAD * STRIDE, W, H, STRIDE, fmt) == RAST_OK);
        CHECK(rast_fill_polygon_aa_blend(&t, &poly, &o, rgba, NULL, s, need) == RAST_E_FORMAT);
        CHECK(rast_fill_polygon_blend(&t, &poly, &fo, rgba, NULL, s, need) == RAST_E_FORMAT);
    }
    CHECK(memcmp(got, before, SIZE) == 0);
    /* opts NULL: opacity 255, straight */
    target(&t, got, RAST_FORMAT_GRAY8, &all);
    CHECK(rast_fill_triangles_aa_blend(&t, tri, 1, &o, rgba, NULL, s, need) == RAST_OK);
    CHECK(got[PAD * STRIDE] == (10 * 40 + 7 * 215 + 127) / 255);
}

/* rast_blend_coverage_linear (its rounding is held against the exact
 * oracle in tests/test_opacity_more.py): with the linear table
 * dec[k] = k 2^16 the nearest level to the mix is the stored-level mix of
 * rast_blend_coverage (never a tie: 255 is odd), for every format but
 * straight RGBA8888's colour, here over opaque pixels, where it is too;
 * errors (premultiplied = 1 on any format) before anything is written. */
static void test_linear(void)
{
    static rast_gamma g;
    static const rast_rect all = {0, 0, W, H};
    uint8_t cov[H * W], rgba[4];
    rast_blend_opts b;
    rast_target t;
    int iter, f;
    uint32_t k;
    for (k = 0; k < 256; k++) g.dec8[k] = k << 16;
    for (k = 0; k < 64; k++) g.dec6[k] = k << 18;
    for (k = 0; k < 32; k++) g.dec5[k] = k << 19;
    for (iter = 0; iter < check_count(200); iter++) {
        size_t i;
        f = iter % 4;
        for (i = 0; i < sizeof cov; i++) cov[i] = (uint8_t)rng();
        for (i = 0; i < 4; i++) rgba[i] = (uint8_t)rng();
        for (i = 0; i < SIZE; i++) before[i] = (unsigned char)rng();
        if (formats[f] == RAST_FORMAT_RGBA8888) {
            int y, x;
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++) before[(PAD + y) * STRIDE + x * 4 + 3] = 255;
        }
        memcpy(got, before, SIZE);
        memcpy(want, before, SIZE);
        b.opacity = (int32_t)(rng() % 256);
        b.premultiplied = 0;
        target(&t, got, formats[f], &all);
        CHECK(rast_blend_coverage_linear(&t, cov, RAST_COVERAGE_U8, W, rgba, &b, &g) == RAST_OK);
        target(&t, want, formats[f], &all);
        CHECK(rast_blend_coverage(&t, cov, RAST_COVERAGE_U8, W, rgba, &b) == RAST_OK);
        CHECK(memcmp(got, want, SIZE) == 0);
    }
    /* errors: nothing written */
    for (f = 0; f < 4; f++) {
        memset(got, 7, SIZE);
        memcpy(before, got, SIZE);
        memset(cov, 255, sizeof cov);
        rgba[0] = 200, rgba[1] = 100, rgba[2] = 50, rgba[3] = 255;
        target(&t, got, formats[f], &all);
        b.opacity = 255;
        b.premultiplied = 0;
        CHECK(rast_blend_coverage_linear(&t, cov, RAST_COVERAGE_U8, W, rgba, &b, NULL) == RAST_E_NULL);
        g.dec6[9] = g.dec6[8];
        CHECK(rast_blend_coverage_linear(&t, cov, RAST_COVERAGE_U8, W, rgba, &b, &g) == RAST_E_ARG);
        g.dec6[9] = 9u << 18;
        g.dec8[255] = (1u << 24) + 1;
        CHECK(rast_blend_coverage_linear(&t, cov, RAST_COVERAGE_U8, W, rgba, &b, &g) == RAST_E_ARG);
        g.dec8[255] = 255u << 16;
        b.premultiplied = 1;
        CHECK(rast_blend_coverage_linear(&t, cov, RAST_COVERAGE_U8, W, rgba, &b, &g) == RAST_E_ARG);
        CHECK(memcmp(got, before, SIZE) == 0);
    }
}

int main(void)
{
    test_random();
    test_errors();
    test_linear();
    return check_report("test_blend");
}

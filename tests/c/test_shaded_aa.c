/*
 * test_shaded_aa.c - anti-aliased Gouraud triangle batches
 * (rast_fill_triangles_shaded_aa, rast_shaded_aa_scratch_size):
 *  - a plane known in closed form: a mesh whose vertex colours all lie on
 *    R = 20 (x - 1), G = 20 (y - 1) (B, A fixed), samples at pixel
 *    centres, so that every pixel's documented colour, owned or on the
 *    silhouette (extrapolated, clamped to 0..255), is that formula at
 *    (i + 1/2, j + 1/2); the target equals that colour (packed by
 *    rast_pack_color) blended with the coverage levels
 *    rast_triangles_coverage gives by the documented rule (blend_ref.h),
 *    every colour format, every method; untouched where c = 0, in the
 *    row padding and the guard rows;
 *  - one colour at every vertex: the same bytes as rast_fill_triangles_aa
 *    with that colour (random batches, every format and method);
 *  - pixels of full coverage: the binary rast_fill_triangles_shaded's
 *    colour exactly (random meshes, RGBA8888; exact and flat);
 *  - clips and bands: a 40-row target (three bands of colour) drawn whole
 *    equals it drawn through clips of 1, 7 and 16 rows, and a window
 *    leaves the rest alone;
 *  - errors: every status before anything is written; the scratch's guard
 *    bytes are never touched.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 4242u
#include "blend_ref.h"
#include "check.h"
#include "rastrum.h"

#define GUARD 0x5A
static uint64_t scratch_mem[1 << 17];
#include "scratch.h"

#define W 19
#define H 40
#define PAD 3
#define MAXB 4
#define STRIDE (W * MAXB + 2 * PAD)
#define SIZE ((H + 2 * PAD) * STRIDE)

static uint64_t mem[3][SIZE / 8 + 1];
#define got ((unsigned char *)mem[0])
#define want ((unsigned char *)mem[1])
#define before ((unsigned char *)mem[2])

static const rast_format COLOUR_FORMATS[5] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888,
                                              RAST_FORMAT_RGBA8888, RAST_FORMAT_RGB565,
                                              RAST_FORMAT_MONO1};

static void target(rast_target *t, unsigned char *buf, rast_format f, int32_t h)
{
    CHECK(rast_target_init(t, buf + PAD * STRIDE, W, h, STRIDE, f) == RAST_OK);
}

static void randomise(unsigned char *buf)
{
    int32_t k;
    for (k = 0; k < SIZE; k++) buf[k] = (unsigned char)rng();
}

static rast_status shaded_aa(const rast_target *t, const rast_point *tris, uint32_t n,
                             const uint8_t *colors, const rast_coverage_opts *o,
                             const rast_shade_opts *sh)
{
    size_t need;
    unsigned char *s;
    rast_status st = rast_shaded_aa_scratch_size(o, n, t->clip.x1 - t->clip.x0,
                                                 t->clip.y1 - t->clip.y0, &need);
    if (st != RAST_OK) return st;
    s = scratch_for(need);
    st = rast_fill_triangles_shaded_aa(t, tris, n, colors, o, sh, s, need);
    CHECK(scratch_guard_ok(s, need));
    return st;
}

static void coverage(const rast_point *tris, uint32_t n, const rast_coverage_opts *o,
                     int32_t h, uint8_t *cov)
{
    size_t need;
    unsigned char *s;
    rast_rect clip = {0, 0, W, 0};
    clip.y1 = h;
    CHECK(rast_coverage_scratch_size(o, 3 * n, W, h, &need) == RAST_OK);
    s = scratch_for(need);
    CHECK(rast_triangles_coverage(tris, n, o, &clip, RAST_COVERAGE_U8, cov, W, s, need) ==
          RAST_OK);
}

static int clamp255(int32_t v) { return v < 0 ? 0 : v > 255 ? 255 : v; }

/* The batch's coverage at every pixel of an h-row target, and the target
 * painted by the documented rule: `colour`(i, j, rgba) gives each
 * pixel's colour, packed by rast_pack_color, blended with its level. */
typedef void (*colour_fn)(const void *user, int32_t i, int32_t j, uint8_t *rgba);

static void expect(const rast_target *t, unsigned char *buf, const uint8_t *cov, colour_fn colour,
                   const void *user)
{
    int32_t i, j;
    for (j = t->clip.y0; j < t->clip.y1; j++)
        for (i = t->clip.x0; i < t->clip.x1; i++) {
            uint8_t rgba[4];
            unsigned char v[4] = {0, 0, 0, 0};
            if (!cov[j * W + i]) continue;
            colour(user, i, j, rgba);
            CHECK(rast_pack_color(t->format, rgba, v) == RAST_OK);
            blend_ref(t->format, buf + PAD * STRIDE + j * STRIDE, i, cov[j * W + i], v);
        }
}

/* The plane: R = 8 (x - 7/4), G = 8 (y - 7/4), B = 262 - 4 y, A = 200, at
 * the pixel centre: 8 i - 10, 8 j - 10, 260 - 4 j, clamped (the left and
 * top silhouettes' samples lie outside, where R goes below 0 and B above
 * 255). */
static void plane_colour(const void *user, int32_t i, int32_t j, uint8_t *rgba)
{
    (void)user;
    rgba[0] = (uint8_t)clamp255(8 * i - 10);
    rgba[1] = (uint8_t)clamp255(8 * j - 10);
    rgba[2] = (uint8_t)clamp255(260 - 4 * j);
    rgba[3] = 200;
}

static void test_plane(void)
{
    /* a quad split in two, and a third triangle on its right edge (S = 2) */
    static const double xy[9][2] = {{1.75, 1.75}, {17.25, 1.75},  {1.75, 30.5},
                                    {17.25, 1.75}, {17.25, 30.5}, {1.75, 30.5},
                                    {17.25, 1.75}, {18.75, 15},   {17.25, 30.5}};
    rast_point tris[9];
    uint8_t colors[36], cov[W * H];
    int32_t k, m, f;
    for (k = 0; k < 9; k++) {
        tris[k].x = (int32_t)(xy[k][0] * 4);
        tris[k].y = (int32_t)(xy[k][1] * 4);
        colors[4 * k] = (uint8_t)(8 * (xy[k][0] - 1.75));
        colors[4 * k + 1] = (uint8_t)(8 * (xy[k][1] - 1.75));
        colors[4 * k + 2] = (uint8_t)(262 - 4 * xy[k][1]);
        colors[4 * k + 3] = 200;
    }
    for (m = 0; m < RAST_AA_COUNT_; m++)
        for (f = 0; f < 5; f++) {
            rast_coverage_opts o;
            rast_shade_opts sh;
            rast_target t, u;
            memset(&o, 0, sizeof o);
            memset(&sh, 0, sizeof sh);
            o.subpixel_bits = 2;
            o.sample = RAST_SAMPLE_CENTER;
            o.method = (rast_aa_method)m;
            coverage(tris, 3, &o, H, cov);
            randomise(got);
            memcpy(want, got, SIZE);
            target(&t, got, COLOUR_FORMATS[f], H);
            target(&u, want, COLOUR_FORMATS[f], H);
            CHECK(shaded_aa(&t, tris, 3, colors, &o, &sh) == RAST_OK);
            expect(&u, want, cov, plane_colour, NULL);
            CHECK(memcmp(got, want, SIZE) == 0);
        }
    /* the silhouettes are really there: column 1 gets R = 0 (-2 clamped),
     * row 1 B = 255 (256 clamped) */
    CHECK(cov[5 * W + 1] > 0 && cov[1 * W + 5] > 0);
}

/* One colour everywhere: the same bytes as the one-colour fill. */
static void test_one_colour(void)
{
    int32_t c, k;
    for (c = 0; c < check_count(300); c++) {
        rast_coverage_opts o;
        rast_shade_opts sh;
        rast_target t, u;
        rast_point tris[15];
        uint8_t colors[60], rgba[4];
        unsigned char v[4] = {0, 0, 0, 0};
        uint32_t n = 1 + rng() % 5;
        size_t need;
        rast_format f = COLOUR_FORMATS[rng() % 5];
        memset(&o, 0, sizeof o);
        memset(&sh, 0, sizeof sh);
        o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
        o.subpixel_bits = (int32_t)(rng() % 5);
        o.sample = rng() % 2 ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        sh.precision = rng() % 2 ? RAST_PRECISION_FLAT : RAST_PRECISION_EXACT;
        for (k = 0; k < 4; k++) rgba[k] = (uint8_t)rng();
        for (k = 0; k < (int32_t)(3 * n); k++) {
            tris[k].x = (int32_t)(rng() % (uint32_t)((W + 4) << o.subpixel_bits)) - (2 << o.subpixel_bits);
            tris[k].y = (int32_t)(rng() % (uint32_t)((24 + 4) << o.subpixel_bits)) - (2 << o.subpixel_bits);
            memcpy(colors + 4 * k, rgba, 4);
        }
        randomise(got);
        memcpy(want, got, SIZE);
        target(&t, got, f, 24);
        target(&u, want, f, 24);
        CHECK(shaded_aa(&t, tris, n, colors, &o, &sh) == RAST_OK);
        CHECK(rast_pack_color(f, rgba, v) == RAST_OK);
        CHECK(rast_coverage_scratch_size(&o, 3 * n, W, 24, &need) == RAST_OK);
        CHECK(rast_fill_triangles_aa(&u, tris, n, &o, v, scratch_for(need), need) == RAST_OK);
        CHECK(memcmp(got, want, SIZE) == 0);
    }
}

/* Random fans (a mesh) over black: every pixel the binary fill owns has
 * the binary shaded fill's colour blended with its coverage level (so,
 * with full coverage, that colour itself). */
static void test_full_is_binary(void)
{
    int32_t c, k, i, j;
    for (c = 0; c < check_count(200); c++) {
        rast_coverage_opts o;
        rast_shade_opts sh;
        rast_tri_opts to;
        rast_target t, u;
        rast_point tris[18], ring[6], centre;
        rast_target mt;
        uint8_t colors[72], vc[6][4], cc[4], cov[W * H], mask[W * H];
        const unsigned char one = 1;
        uint32_t n = 6;
        int32_t S = (int32_t)(rng() % 4);
        memset(&o, 0, sizeof o);
        memset(&sh, 0, sizeof sh);
        memset(&to, 0, sizeof to);
        o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
        o.subpixel_bits = to.subpixel_bits = S;
        o.sample = to.sample = rng() % 2 ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        sh.precision = rng() % 4 ? RAST_PRECISION_EXACT : RAST_PRECISION_FLAT;
        centre.x = (int32_t)(8 << S) + (int32_t)(rng() % (4u << S));
        centre.y = (int32_t)(12 << S) + (int32_t)(rng() % (4u << S));
        for (k = 0; k < 6; k++) { /* a star-shaped ring around the centre */
            static const int32_t dx[6] = {-1, 0, 1, 1, 0, -1}, dy[6] = {-1, -1, -1, 1, 1, 1};
            ring[k].x = centre.x + dx[k] * (int32_t)((2u << S) + rng() % (7u << S));
            ring[k].y = centre.y + dy[k] * (int32_t)((2u << S) + rng() % (10u << S));
            if (k == 1 || k == 4) ring[k].x = centre.x + (int32_t)(rng() % (3u << S)) - (int32_t)(1u << S);
            for (i = 0; i < 4; i++) vc[k][i] = (uint8_t)rng();
        }
        for (i = 0; i < 4; i++) cc[i] = (uint8_t)rng();
        for (k = 0; k < 6; k++) {
            tris[3 * k] = centre;
            tris[3 * k + 1] = ring[k];
            tris[3 * k + 2] = ring[(k + 1) % 6];
            memcpy(colors + 12 * k, cc, 4);
            memcpy(colors + 12 * k + 4, vc[k], 4);
            memcpy(colors + 12 * k + 8, vc[(k + 1) % 6], 4);
        }
        memset(got, 0, SIZE);
        memset(want, 0, SIZE);
        target(&t, got, RAST_FORMAT_RGBA8888, H);
        target(&u, want, RAST_FORMAT_RGBA8888, H);
        CHECK(shaded_aa(&t, tris, n, colors, &o, &sh) == RAST_OK);
        CHECK(rast_fill_triangles_shaded(&u, tris, n, colors, NULL, NULL, &to, &sh, NULL, 0) ==
              RAST_OK);
        coverage(tris, n, &o, H, cov);
        memset(mask, 0, sizeof mask);
        CHECK(rast_target_init(&mt, mask, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
        CHECK(rast_fill_triangles(&mt, tris, n, &to, &one, NULL, 0) == RAST_OK);
        k = 0;
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                const unsigned char *a = got + (PAD + j) * STRIDE + 4 * i;
                unsigned char b[4] = {0, 0, 0, 0}, v[4];
                memcpy(v, want + (PAD + j) * STRIDE + 4 * i, 4); /* the binary colour */
                if (!mask[j * W + i] || !cov[j * W + i]) continue;
                k += cov[j * W + i] == 255;
                blend_ref(RAST_FORMAT_RGBA8888, b, 0, cov[j * W + i], v); /* over black */
                CHECK(memcmp(a, b, 4) == 0);
            }
        CHECK(k > 0);
    }
}

/* Band and clip invariance: the whole target equals clips of 1, 7 and 16
 * rows drawn one after the other, and the whole drawn with a scratch that
 * holds taller bands (about 32 rows, or all 40); a window writes nothing
 * outside it. */
static void test_clips(void)
{
    static const int32_t rows[3] = {1, 7, 16};
    int32_t c, k, r;
    for (c = 0; c < check_count(60); c++) {
        rast_coverage_opts o;
        rast_shade_opts sh;
        rast_target t, u;
        rast_point tris[12];
        uint8_t colors[48];
        uint32_t n = 1 + rng() % 4;
        rast_format f = COLOUR_FORMATS[rng() % 5];
        memset(&o, 0, sizeof o);
        memset(&sh, 0, sizeof sh);
        o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
        o.subpixel_bits = 3;
        o.sample = RAST_SAMPLE_CENTER;
        for (k = 0; k < (int32_t)(3 * n); k++) {
            tris[k].x = (int32_t)(rng() % ((W + 6) << 3)) - (3 << 3);
            tris[k].y = (int32_t)(rng() % ((H + 6) << 3)) - (3 << 3);
        }
        for (k = 0; k < (int32_t)(12 * n); k++) colors[k] = (uint8_t)rng();
        randomise(got);
        memcpy(want, got, SIZE);
        memcpy(before, got, SIZE);
        target(&t, got, f, H);
        target(&u, want, f, H);
        CHECK(shaded_aa(&t, tris, n, colors, &o, &sh) == RAST_OK);
        for (r = 0; r < 2; r++) {
            size_t need;
            unsigned char *s;
            CHECK(rast_shaded_aa_scratch_size(&o, n, W, H, &need) == RAST_OK);
            need += r ? need + 4 * W * H : 4 * W * 16; /* room for 32 rows, or all */
            memcpy(want, before, SIZE);
            s = scratch_for(need);
            CHECK(rast_fill_triangles_shaded_aa(&u, tris, n, colors, &o, &sh, s, need) == RAST_OK);
            CHECK(scratch_guard_ok(s, need));
            CHECK(memcmp(got, want, SIZE) == 0);
        }
        for (r = 0; r < 3; r++) {
            int32_t y;
            memcpy(want, before, SIZE);
            for (y = 0; y < H; y += rows[r]) {
                u.clip.y0 = y;
                u.clip.y1 = y + rows[r] < H ? y + rows[r] : H;
                CHECK(shaded_aa(&u, tris, n, colors, &o, &sh) == RAST_OK);
            }
            CHECK(memcmp(got, want, SIZE) == 0);
        }
        /* a window: inside, the whole call's pixels; outside, untouched */
        memcpy(want, before, SIZE);
        target(&u, want, f, H);
        u.clip.x0 = 3;
        u.clip.x1 = 11;
        u.clip.y0 = 5;
        u.clip.y1 = 29;
        CHECK(shaded_aa(&u, tris, n, colors, &o, &sh) == RAST_OK);
        {
            int32_t j, bpp = f == RAST_FORMAT_GRAY8 ? 1 : f == RAST_FORMAT_RGB888 ? 3
                           : f == RAST_FORMAT_RGBA8888 ? 4 : 2;
            for (j = 0; j < H + 2 * PAD; j++) {
                int32_t y = j - PAD, in = y >= 5 && y < 29;
                const unsigned char *src = in ? got : before;
                if (f == RAST_FORMAT_MONO1) continue; /* bits: test_coverage_paint's business */
                if (!in) {
                    CHECK(memcmp(want + j * STRIDE, before + j * STRIDE, STRIDE) == 0);
                    continue;
                }
                CHECK(memcmp(want + j * STRIDE, before + j * STRIDE, (size_t)(3 * bpp)) == 0);
                CHECK(memcmp(want + j * STRIDE + 3 * bpp, src + j * STRIDE + 3 * bpp,
                             (size_t)(8 * bpp)) == 0);
                CHECK(memcmp(want + j * STRIDE + 11 * bpp, before + j * STRIDE + 11 * bpp,
                             (size_t)(STRIDE - 11 * bpp)) == 0);
            }
        }
    }
}

/* Every error before anything is written. */
static void test_errors(void)
{
    rast_coverage_opts o;
    rast_shade_opts sh;
    rast_target t;
    rast_point tris[3] = {{0, 0}, {40, 8}, {8, 40}};
    rast_point far[3] = {{0, 0}, {RAST_COORD_MAX + 1, 0}, {0, 8}};
    uint8_t colors[12] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    uint16_t cnt[W * H];
    size_t need, b;
    unsigned char *s;
    memset(&o, 0, sizeof o);
    memset(&sh, 0, sizeof sh);
    o.subpixel_bits = 2;
    randomise(got);
    memcpy(before, got, SIZE);
    target(&t, got, RAST_FORMAT_RGB888, H);
    CHECK(rast_shaded_aa_scratch_size(&o, 1, W, H, &need) == RAST_OK);
    s = scratch_for(need);
    CHECK(rast_fill_triangles_shaded_aa(NULL, tris, 1, colors, &o, &sh, s, need) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded_aa(&t, NULL, 1, colors, &o, &sh, s, need) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, NULL, &o, &sh, s, need) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, NULL, &sh, s, need) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, NULL, s, need) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need - 1) ==
          RAST_E_SCRATCH);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s + 1, need) ==
          RAST_E_ALIGN);
    CHECK(rast_fill_triangles_shaded_aa(&t, far, 1, colors, &o, &sh, s, need) == RAST_E_RANGE);
    sh.precision = RAST_PRECISION_FIXED;
    sh.fraction_bits = 8;
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need) == RAST_E_ARG);
    sh.precision = (rast_precision)7;
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need) == RAST_E_ARG);
    sh.precision = RAST_PRECISION_EXACT;
    o.method = RAST_AA_COUNT_;
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need) == RAST_E_ARG);
    CHECK(rast_shaded_aa_scratch_size(&o, 1, W, H, &b) == RAST_E_ARG);
    o.method = RAST_AA_AREA;
    o.subpixel_bits = 17;
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need) == RAST_E_SUBPIXEL);
    o.subpixel_bits = 2;
    CHECK(rast_shaded_aa_scratch_size(&o, 1, -1, H, &b) == RAST_E_SIZE);
    CHECK(rast_shaded_aa_scratch_size(&o, 1, W, H, NULL) == RAST_E_NULL);
    CHECK(rast_shaded_aa_scratch_size(NULL, 1, W, H, &b) == RAST_E_NULL);
    CHECK(rast_shaded_aa_scratch_size(&o, 0xFFFFFFFFu, W, H, &b) == RAST_E_TOO_MANY);
    CHECK(memcmp(got, before, SIZE) == 0);
    /* COUNT16 has no colour */
    memset(cnt, 0, sizeof cnt);
    CHECK(rast_target_init(&t, cnt, W, H, 2 * W, RAST_FORMAT_COUNT16) == RAST_OK);
    CHECK(rast_fill_triangles_shaded_aa(&t, tris, 1, colors, &o, &sh, s, need) == RAST_E_FORMAT);
    for (b = 0; b < W * H; b++) CHECK(cnt[b] == 0);
    /* the scratch: area and ss16, a band's worth, not the clip's rows */
    {
        size_t a1, a2;
        CHECK(rast_shaded_aa_scratch_size(&o, 10, 100, 16, &a1) == RAST_OK);
        CHECK(rast_shaded_aa_scratch_size(&o, 10, 100, 100000, &a2) == RAST_OK);
        CHECK(a1 == a2);
    }
    /* empty: nothing, and no error */
    target(&t, got, RAST_FORMAT_RGB888, H);
    CHECK(rast_fill_triangles_shaded_aa(&t, NULL, 0, NULL, &o, &sh, s, need) == RAST_OK);
    CHECK(memcmp(got, before, SIZE) == 0);
}

int main(void)
{
    test_plane();
    test_one_colour();
    test_full_is_binary();
    test_clips();
    test_errors();
    return check_report("test_shaded_aa");
}

/*
 * test_shade.c - pixel formats and shaded triangles in C: every format
 * through the fills with guard bytes around the target; mono1 spans at
 * every bit offset; rgb565 packing; a shaded call writes the pixels of the
 * unshaded one; exact depth and colour at the coordinate limit against an
 * int64 reference; errors before any write.  (The colour oracle proper is
 * the Python fraction oracle, tests/oracle_shade.py.)
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 77u
#include "check.h"
#include "ref.h"
#include "base/wide.h" /* rast__recip_floordiv, rast__i128_floordiv */

#define GUARD 0xA5
#define PAD 16
#define W 29
#define H 21

static uint64_t scratch[1 << 12];

static const rast_format formats[] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB888, RAST_FORMAT_RGBA8888,
                                      RAST_FORMAT_RGB565, RAST_FORMAT_MONO1};
#define NFORMATS 5

/* A guarded W x H target of format f in buf: PAD guard bytes before, after
 * and at the end of every row (the stride has PAD spare bytes). */
static int32_t make_bg(rast_target *t, unsigned char *buf, size_t size, rast_format f, int bg)
{
    int32_t row;
    CHECK(rast_format_stride(f, W, &row) == RAST_OK);
    memset(buf, bg, size);
    CHECK(rast_target_init(t, buf + PAD, W, H, row + PAD, f) == RAST_OK);
    return row + PAD;
}

static int32_t make(rast_target *t, unsigned char *buf, size_t size, rast_format f)
{
    return make_bg(t, buf, size, f, GUARD);
}

/* Pixel (i, j) the same in targets a and b (same format and layout)? */
static int same_pixel(const rast_target *a, const rast_target *b, int32_t i, int32_t j)
{
    const unsigned char *ra = (const unsigned char *)a->pixels + (ptrdiff_t)j * a->stride;
    const unsigned char *rb = (const unsigned char *)b->pixels + (ptrdiff_t)j * b->stride;
    int32_t n, k;
    if (a->format == RAST_FORMAT_MONO1) return !(((ra[i >> 3] ^ rb[i >> 3]) >> (7 - (i & 7))) & 1);
    rast_format_bytes(a->format, &n);
    for (k = 0; k < n; k++)
        if (ra[i * n + k] != rb[i * n + k]) return 0;
    return 1;
}

/* Every byte outside the pixels untouched: before, after, row padding,
 * and the padding bits of a mono1 row's last byte. */
static int guards_ok(const rast_target *t, const unsigned char *buf, size_t size)
{
    int32_t row, j, k;
    size_t end = PAD + (size_t)t->stride * H;
    rast_format_stride(t->format, W, &row);
    for (k = 0; k < PAD; k++)
        if (buf[k] != GUARD) return 0;
    for (k = (int32_t)end; k < (int32_t)size; k++)
        if (buf[k] != GUARD) return 0;
    for (j = 0; j < H; j++) {
        const unsigned char *r = (const unsigned char *)t->pixels + (ptrdiff_t)j * t->stride;
        for (k = row; k < t->stride; k++)
            if (r[k] != GUARD) return 0;
        if (t->format == RAST_FORMAT_MONO1 && W % 8 &&
            ((r[row - 1] ^ GUARD) & (0xFFu >> (W % 8))))
            return 0;
    }
    return 1;
}

static rast_point rpt(int s)
{
    rast_point p;
    p.x = (int32_t)(rng() % (uint32_t)((W + 8) << s)) - (4 << s);
    p.y = (int32_t)(rng() % (uint32_t)((H + 8) << s)) - (4 << s);
    return p;
}

/* Unshaded and shaded batches write exactly the reference's pixels, in
 * every format, algorithm and precision, and nothing outside: the same
 * call on two backgrounds that differ in every bit leaves a pixel equal in
 * both iff it wrote it. */
static void test_pixel_sets(void)
{
    static unsigned char buf[2][PAD + (W * 4 + PAD) * H + PAD];
    int round, fi, algo, prec;
    for (round = 0; round < 40; round++) {
        int s = (int)(rng() % 9), center = (int)(rng() & 1);
        rast_point tri[3];
        uint8_t colors[12];
        int32_t i, j, k;
        for (k = 0; k < 3; k++) tri[k] = rpt(s);
        for (k = 0; k < 12; k++) colors[k] = (uint8_t)rng();
        for (fi = 0; fi < NFORMATS; fi++)
            for (algo = 0; algo < RAST_TRI_COUNT_; algo++)
                for (prec = -1; prec <= RAST_PRECISION_FLAT; prec++) {
                    rast_target t[2];
                    rast_tri_opts o;
                    rast_shade_opts so;
                    static const unsigned char pixel[4] = {1, 2, 3, 4};
                    int bad = 0, b;
                    memset(&o, 0, sizeof o);
                    o.algorithm = (rast_tri_algorithm)algo;
                    o.subpixel_bits = s;
                    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
                    so.precision = (rast_precision)(prec < 0 ? 0 : prec);
                    so.fraction_bits = 1 + (int32_t)(rng() % 16);
                    for (b = 0; b < 2; b++) {
                        make_bg(&t[b], buf[b], sizeof buf[b], formats[fi], b ? 0x5A : GUARD);
                        if (prec < 0)
                            CHECK(rast_fill_triangles(&t[b], tri, 1, &o, pixel, scratch, sizeof scratch) == RAST_OK);
                        else
                            CHECK(rast_fill_triangles_shaded(&t[b], tri, 1, colors, NULL, NULL, &o, &so,
                                                             scratch, sizeof scratch) == RAST_OK);
                    }
                    for (j = 0; j < H; j++)
                        for (i = 0; i < W; i++) {
                            static const uint32_t three = 3;
                            int in = ref_winding(tri, &three, 1, s, center, 0, i, j, NULL) != 0;
                            if (same_pixel(&t[0], &t[1], i, j) != in) bad++;
                        }
                    CHECK(bad == 0);
                    CHECK(guards_ok(&t[0], buf[0], sizeof buf[0]));
                }
    }
}

/* The packed RGBA8888 paths (fixed and exact; little-endian hosts, exact
 * rounding and boundary, no depth) against the general per-channel path:
 * R, G, B equal those of RGB888, A the level of GRAY8 filled with A as its
 * R; nothing written outside the target. */
static void test_packed_paths(void)
{
    static unsigned char buf[3][PAD + (W * 4 + PAD) * H + PAD];
    static const rast_format fmts[3] = {RAST_FORMAT_RGBA8888, RAST_FORMAT_RGB888, RAST_FORMAT_GRAY8};
    int round, bad = 0, guards = 1;
    for (round = 0; round < 400; round++) {
        int s = (int)(rng() % 9), n = 1 + (int)(rng() % 4), f, k;
        rast_point tri[12];
        uint8_t colors[48], alpha[48];
        rast_target t[3];
        rast_tri_opts o;
        rast_shade_opts so;
        int32_t i, j;
        for (k = 0; k < 3 * n; k++) tri[k] = rpt(s);
        for (k = 0; k < 12 * n; k++) {
            uint32_t r = rng();
            colors[k] = (uint8_t)(r & 8 ? (r >> 4) & 1 ? 255 : 0 : r >> 8);
        }
        for (k = 0; k < 3 * n; k++) alpha[4 * k] = colors[4 * k + 3];
        memset(&o, 0, sizeof o);
        o.algorithm = (rast_tri_algorithm)(rng() % RAST_TRI_COUNT_);
        o.subpixel_bits = s;
        o.sample = rng() & 1 ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        so.precision = rng() & 1 ? RAST_PRECISION_EXACT : RAST_PRECISION_FIXED;
        so.fraction_bits = 1 + (int32_t)(rng() % 16);
        for (f = 0; f < 3; f++) {
            make(&t[f], buf[f], sizeof buf[f], fmts[f]);
            CHECK(rast_fill_triangles_shaded(&t[f], tri, (uint32_t)n, f == 2 ? alpha : colors, NULL,
                                             NULL, &o, &so, scratch, sizeof scratch) == RAST_OK);
            guards &= guards_ok(&t[f], buf[f], sizeof buf[f]);
        }
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                const unsigned char *a = (const unsigned char *)t[0].pixels + j * t[0].stride + 4 * i;
                const unsigned char *b = (const unsigned char *)t[1].pixels + j * t[1].stride + 3 * i;
                const unsigned char *c = (const unsigned char *)t[2].pixels + j * t[2].stride + i;
                if (memcmp(a, b, 3) != 0 || a[3] != c[0]) bad++;
            }
    }
    CHECK(bad == 0);
    CHECK(guards);
}

/* mono1 spans at every start and end bit: exactly those bits change. */
static void test_mono1_spans(void)
{
    static unsigned char buf[4 * 8];
    int32_t x0, x1, v, i;
    for (v = 0; v < 2; v++)
        for (x0 = 0; x0 < 24; x0++)
            for (x1 = x0 + 1; x1 <= 24; x1++) {
                rast_target t;
                rast_point tri[6];
                rast_tri_opts o;
                unsigned char value = (unsigned char)v;
                int ok = 1;
                memset(buf, v ? 0x00 : 0xFF, sizeof buf);
                CHECK(rast_target_init(&t, buf, 24, 1, 3, RAST_FORMAT_MONO1) == RAST_OK);
                memset(&o, 0, sizeof o); /* S = 0, corners: the rectangle [x0, x1) x [0, 1) */
                tri[0].x = x0; tri[0].y = 0; tri[1].x = x1; tri[1].y = 0; tri[2].x = x1; tri[2].y = 1;
                tri[3].x = x0; tri[3].y = 0; tri[4].x = x1; tri[4].y = 1; tri[5].x = x0; tri[5].y = 1;
                CHECK(rast_fill_triangles(&t, tri, 2, &o, &value, scratch, sizeof scratch) == RAST_OK);
                for (i = 0; i < 24; i++) {
                    int bit = (buf[i >> 3] >> (7 - (i & 7))) & 1;
                    int want = (i >= x0 && i < x1) ? v : !v;
                    if (bit != want) ok = 0;
                }
                for (i = 3; i < 32; i++)
                    if (buf[i] != (v ? 0x00 : 0xFF)) ok = 0;
                CHECK(ok);
            }
}

static void test_formats(void)
{
    static const uint8_t rgba[4] = {0xF8, 0xFC, 0xF8, 9}, low[4] = {7, 3, 7, 0};
    uint16_t p;
    unsigned char m;
    int32_t b;
    CHECK(rast_pack_color(RAST_FORMAT_RGB565, rgba, &p) == RAST_OK && p == 0xFFFF);
    CHECK(rast_pack_color(RAST_FORMAT_RGB565, low, &p) == RAST_OK && p == 0);
    CHECK(rast_pack_color(RAST_FORMAT_MONO1, rgba, &m) == RAST_OK && m == 1);
    CHECK(rast_pack_color(RAST_FORMAT_MONO1, low, &m) == RAST_OK && m == 0);
    CHECK(rast_pack_color(RAST_FORMAT_COUNT16, rgba, &p) == RAST_E_FORMAT);
    CHECK(rast_pack_color(RAST_FORMAT_COUNT_, rgba, &p) == RAST_E_FORMAT);
    CHECK(rast_format_bytes(RAST_FORMAT_RGB565, &b) == RAST_OK && b == 2);
    CHECK(rast_format_bytes(RAST_FORMAT_MONO1, &b) == RAST_OK && b == 1);
    CHECK(rast_format_stride(RAST_FORMAT_MONO1, 9, &b) == RAST_OK && b == 2);
    CHECK(rast_format_stride(RAST_FORMAT_MONO1, 0, &b) == RAST_OK && b == 0);
    CHECK(rast_format_stride(RAST_FORMAT_RGB888, 5, &b) == RAST_OK && b == 15);
    CHECK(rast_format_stride(RAST_FORMAT_MONO1, -1, &b) == RAST_E_SIZE);
    {
        static uint16_t img[4 * 4];
        rast_target t;
        CHECK(rast_target_init(&t, (unsigned char *)img + 1, 4, 4, 8, RAST_FORMAT_RGB565) == RAST_E_SIZE);
        CHECK(rast_target_init(&t, img, 4, 4, 7, RAST_FORMAT_RGB565) == RAST_E_SIZE);
        CHECK(rast_target_init(&t, img, 9, 4, 1, RAST_FORMAT_MONO1) == RAST_E_SIZE);
        CHECK(rast_target_init(&t, img, 9, 4, 2, RAST_FORMAT_MONO1) == RAST_OK);
    }
}

/* A polygon, opaque, into mono1 and rgb565: every pixel written once. */
static void test_opaque(void)
{
    static unsigned char buf[PAD + (W * 4 + PAD) * H + PAD];
    static const rast_point sq[4] = {{3, 2}, {20, 2}, {20, 15}, {3, 15}};
    static const uint32_t n = 4;
    const rast_polygon poly = {sq, &n, 1};
    rast_fill_opts o;
    int fi;
    memset(&o, 0, sizeof o);
    for (fi = 3; fi < NFORMATS; fi++) {
        static const unsigned char on[2] = {0xFF, 0xFF}, off[2] = {0, 0};
        rast_target t;
        int32_t i, j, ok = 1;
        make(&t, buf, sizeof buf, formats[fi]);
        CHECK(rast_fill_polygon_opaque(&t, &poly, &o, on, off, scratch, sizeof scratch) == RAST_OK);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                const unsigned char *r = (const unsigned char *)t.pixels + (ptrdiff_t)j * t.stride;
                int in = i >= 3 && i < 20 && j >= 2 && j < 15;
                int got = formats[fi] == RAST_FORMAT_MONO1 ? (r[i >> 3] >> (7 - (i & 7))) & 1
                                                           : r[2 * i] == 0xFF && r[2 * i + 1] == 0xFF;
                if (got != in) ok = 0;
                if (formats[fi] == RAST_FORMAT_RGB565 && !in && (r[2 * i] || r[2 * i + 1])) ok = 0;
            }
        CHECK(ok);
        CHECK(guards_ok(&t, buf, sizeof buf));
    }
}

/* At the coordinate limit: v0 = (-M, 0), v1 = (M, 0), v2 = (-M, M), a
 * right angle at v0 with legs 2M and M, so that in doubled units the value
 * at sample p is c0 + ((px - x0) d1 + 2 (py - y0) d2) / 4M exactly: an
 * int64 reference for depths spanning all of int32_t. */
static void test_limit_exact(void)
{
    static int32_t zbuf[16 * 16];
    static uint8_t img[16 * 16];
    const int32_t M = RAST_COORD_MAX;
    rast_point tri[3];
    const int32_t z[3] = {INT32_MIN, INT32_MAX, 0};
    uint8_t colors[12] = {0, 0, 0, 0, 255, 0, 0, 0, 100, 0, 0, 0};
    rast_target t;
    rast_tri_opts o;
    rast_shade_opts so;
    int32_t i, j, k, okz = 1, okc = 1;
    tri[0].x = -M; tri[0].y = 0; tri[1].x = M; tri[1].y = 0; tri[2].x = -M; tri[2].y = M;
    memset(&o, 0, sizeof o);
    o.sample = RAST_SAMPLE_CENTER; /* S = 0: sample 2i + 1 in doubled units */
    for (k = 0; k < 16 * 16; k++) zbuf[k] = INT32_MAX;
    memset(&so, 0, sizeof so);
    CHECK(rast_target_init(&t, img, 16, 16, 16, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, z, zbuf, &o, &so, scratch, sizeof scratch) == RAST_OK);
    for (j = 0; j < 16; j++)
        for (i = 0; i < 16; i++) {
            int64_t L = 4 * (int64_t)M;
            int64_t px = 2 * i + 1 + 2 * (int64_t)M, py = 2 * j + 1;
            int64_t d1 = (int64_t)z[1] - z[0], d2 = (int64_t)z[2] - z[0];
            int64_t nz = px * d1 + 2 * py * d2; /* < 2^61 */
            int64_t want = z[0] + ref_floor_div(2 * nz + L, 2 * L);
            int64_t nc = px * 255 + 2 * py * 100;
            int64_t wc = ref_floor_div(2 * nc + L, 2 * L);
            if (zbuf[j * 16 + i] != want) okz = 0;
            if (img[j * 16 + i] != wc) okc = 0;
        }
    CHECK(okz);
    CHECK(okc);
}

static void test_depth_and_errors(void)
{
    static uint8_t img[8 * 8];
    static int32_t zbuf[8 * 8];
    static uint16_t counts[8 * 8];
    static const rast_point tri[3] = {{0, 0}, {8, 0}, {0, 8}};
    static const uint8_t colors[12] = {10, 0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0};
    const int32_t z[3] = {3, 3, 3};
    rast_target t, tc;
    rast_tri_opts o;
    rast_shade_opts so;
    int k, same = 1;
    memset(&o, 0, sizeof o);
    memset(&so, 0, sizeof so);
    CHECK(rast_target_init(&t, img, 8, 8, 8, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_target_init(&tc, counts, 8, 8, 16, RAST_FORMAT_COUNT16) == RAST_OK);
    CHECK(rast_fill_triangles_shaded(&tc, tri, 1, colors, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_FORMAT);
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, z, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, zbuf, &o, &so, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, NULL, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, NULL, &o, NULL, scratch, sizeof scratch) == RAST_E_NULL);
    so.precision = (rast_precision)3;
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_ARG);
    so.precision = RAST_PRECISION_FIXED;
    so.fraction_bits = 0;
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_ARG);
    so.fraction_bits = 17;
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_ARG);
    o.subpixel_bits = 17;
    so.fraction_bits = 8;
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, NULL, NULL, &o, &so, scratch, sizeof scratch) == RAST_E_SUBPIXEL);
    for (k = 0; k < 64; k++) same &= img[k] == 0;
    CHECK(same); /* nothing written by a refused call */
    /* depth: equal fails, nearer passes; the clip bounds the buffer too */
    o.subpixel_bits = 0;
    so.precision = RAST_PRECISION_EXACT;
    for (k = 0; k < 64; k++) zbuf[k] = k == 0 ? 3 : k == 1 ? 4 : INT32_MAX;
    t.clip.x1 = 4;
    CHECK(rast_fill_triangles_shaded(&t, tri, 1, colors, z, zbuf, &o, &so, scratch, sizeof scratch) == RAST_OK);
    CHECK(img[0] == 0 && zbuf[0] == 3);  /* 3 < 3 fails */
    CHECK(img[1] == 10 && zbuf[1] == 3); /* 3 < 4 passes */
    CHECK(img[5] == 0 && zbuf[5] == INT32_MAX); /* outside the clip */
}

static uint64_t rng64(void)
{
    return ((uint64_t)rng() << 40) ^ ((uint64_t)rng() << 16) ^ rng();
}

/* The division helpers against the compiler's division: random and
 * extreme numerators, divisors up to 2^62 - 1. */
static void test_division(void)
{
    static const int64_t ns[] = {0, 1, -1, INT64_MAX, INT64_MIN + 1, INT64_MIN, 12345, -12345};
    int k, ok = 1, okw = 1;
    for (k = 0; k < 200000; k++) {
        int64_t d = (int64_t)(rng64() >> (1 + rng() % 62)) % (((int64_t)1 << 62) - 1) + 1;
        int64_t n = k < 8 ? ns[k] : (int64_t)(rng64() >> (1 + rng() % 63)) * ((rng() & 1) ? 1 : -1);
        int64_t want = ref_floor_div(n, d), q, r;
        rast__recip rc;
        if (n == INT64_MIN && d == 1) continue; /* ref_floor_div overflows */
        rast__recip_init(&rc, d);
        q = rast__recip_floordiv(&rc, n, &r);
        /* q d + r == n, in unsigned (modular) arithmetic: q d may pass
         * INT64_MIN on the way */
        if (q != want || (uint64_t)q * (uint64_t)d + (uint64_t)r != (uint64_t)n || r < 0 || r >= d)
            ok = 0;
        /* 128-bit: (n * 2^s) / d for small s compared when it fits */
        if (n > -((int64_t)1 << 60) && n < ((int64_t)1 << 60)) {
            int64_t q2, r2;
            int fits = rast__i128_floordiv(rast__i128_from(n), d, &q2, &r2);
            if (!fits || q2 != want || r2 != r) okw = 0;
        }
    }
    CHECK(ok);
    CHECK(okw);
    { /* a product past int64_t: (2^62 + 3)(2^40 + 1) over 2^41 + 1, checked
       * by multiplying back: q d + r == n with 0 <= r < d */
        int64_t q, r;
        rast__i128 n = rast__i128_mul(((int64_t)1 << 62) + 3, ((int64_t)1 << 40) + 1);
        CHECK(rast__i128_floordiv(n, ((int64_t)1 << 41) + 1, &q, &r) == 1);
        {
            rast__i128 back = rast__i128_add(rast__i128_mul(q, ((int64_t)1 << 41) + 1),
                                             rast__i128_from(r));
            CHECK(back.hi == n.hi && back.lo == n.lo && r >= 0 && r < ((int64_t)1 << 41) + 1);
        }
        n = rast__i128_neg(n);
        CHECK(rast__i128_floordiv(n, ((int64_t)1 << 41) + 1, &q, &r) == 1);
        {
            rast__i128 back = rast__i128_add(rast__i128_mul(q, ((int64_t)1 << 41) + 1),
                                             rast__i128_from(r));
            CHECK(back.hi == n.hi && back.lo == n.lo && r >= 0 && r < ((int64_t)1 << 41) + 1);
        }
        /* a quotient past 2^62 saturates */
        CHECK(rast__i128_floordiv(n, 3, &q, &r) == 0 && q == -((int64_t)1 << 62));
    }
}

int main(void)
{
    test_division();
    test_formats();
    test_mono1_spans();
    test_pixel_sets();
    test_packed_paths();
    test_opaque();
    test_limit_exact();
    test_depth_and_errors();
    return check_report("test_shade");
}

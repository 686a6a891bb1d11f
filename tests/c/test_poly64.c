/*
 * test_poly64.c - the 64-bit vertex path (rast_polygon64, issue 13).
 *
 *  - against a brute-force reference of DESIGN section 1 with 128-bit
 *    cross-multiplication (ref.h, ref_polygon64), at S = 20 .. 32 and
 *    at the ends of the range (+-RAST_COORD64_MAX(S)): random polygons in
 *    windows around the origin and around the corners of the range,
 *    slivers thinner than 2^-S pixel, vertices on sample points, collinear
 *    points, both rules, both sample offsets;
 *  - against the 32-bit path on the same vertices (S <= 16), every rule,
 *    offset and the exact and conservative boundary modes: same bytes;
 *  - scaling: vertices v at S and v * 2^k at S + k give the same pixels
 *    (so the conservative mode at S = 32 is held against the 32-bit one);
 *  - errors (S = 33, one unit past the range, other algorithms, textbook
 *    rounding, the closed boundary, small or misaligned scratch), each
 *    leaving the target untouched;
 *  - the band renderer with RAST_PRIM_POLYGON64 against the direct fill,
 *    and a scratch need that does not grow with the coordinates.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_RNG_SEED 13u
#include "check.h"
#include "ref.h"
#include "rastrum.h"

#define W 48
#define H 40
#define MAXP 64

static int64_t rnd64(int64_t lo, int64_t hi)
{
    uint64_t span = (uint64_t)(hi - lo) + 1, v;
    v = ((uint64_t)rng() << 40) ^ ((uint64_t)rng() << 20) ^ rng();
    if (span == 0) return (int64_t)v;
    return lo + (int64_t)(v % span);
}

static unsigned char img_a[H][W], img_b[H][W], img_c[H][W];
static long inside_seen, outside_seen; /* the reference cases are not all empty */

static rast_fill_opts opts_of(int s, int rule, int center, int boundary)
{
    rast_fill_opts o;
    memset(&o, 0, sizeof o);
    o.algorithm = RAST_ALGO_AET;
    o.rule = (rast_fill_rule)rule;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    o.boundary = (rast_boundary)boundary;
    return o;
}

static uint64_t scratch_mem[1 << 14];

/* Fill the 64-bit polygon into img (W x H gray8, cleared), through a
 * target whose pixel (0, 0) stands for pixel (ox, oy) of the plane: the
 * polygon is translated by whole pixels (which translates the pixels). */
static rast_status fill64(unsigned char img[H][W], const rast_point64 *pts, const uint32_t *sizes,
                          uint32_t nrings, const rast_fill_opts *o)
{
    rast_polygon64 p;
    rast_target t;
    static const unsigned char one = 1;
    size_t need;
    rast_status st;
    memset(img, 0, (size_t)W * H);
    p.points = pts;
    p.ring_sizes = sizes;
    p.nrings = nrings;
    CHECK(rast_target_init(&t, img, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
    st = rast_scratch_size64(o, 0, W, H, &need);
    if (st != RAST_OK) return st;
    return rast_fill_polygon64(&t, &p, o, &one, scratch_mem, sizeof scratch_mem);
}

/* Random polygon: nrings rings of 3..8 points in the box [lo, hi]^2 of
 * fixed-point units; returns the point count. */
static uint32_t random_poly(rast_point64 *pts, uint32_t *sizes, uint32_t *nrings, int64_t xlo,
                            int64_t xhi, int64_t ylo, int64_t yhi)
{
    uint32_t r, k, n = 0;
    *nrings = 1 + rng() % 3;
    for (r = 0; r < *nrings; r++) {
        sizes[r] = 3 + rng() % 6;
        for (k = 0; k < sizes[r]; k++, n++) {
            pts[n].x = rnd64(xlo, xhi);
            pts[n].y = rnd64(ylo, yhi);
        }
    }
    return n;
}

/* Compare the fill with the reference (ref.h) over the W x H window whose
 * pixel (0, 0) is pixel (0, 0) of the plane; returns the pixels that
 * differ. */
static int diff_ref_mode(const rast_point64 *pts, const uint32_t *sizes, uint32_t nrings, int s,
                         int rule, int center, int boundary)
{
    rast_fill_opts o = opts_of(s, rule, center, boundary);
    rast_polygon64 pg;
    int i, j, bad = 0;
    pg.points = pts;
    pg.ring_sizes = sizes;
    pg.nrings = nrings;
    if (fill64(img_a, pts, sizes, nrings, &o) != RAST_OK) return -1;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            int in = ref_polygon64(&pg, &o, i, j);
            bad += in != img_a[j][i];
            if (in) inside_seen++; else outside_seen++;
        }
    return bad;
}

static int diff_ref(const rast_point64 *pts, const uint32_t *sizes, uint32_t nrings, int s,
                    int rule, int center)
{
    return diff_ref_mode(pts, sizes, nrings, s, rule, center, RAST_BOUNDARY_EXACT) |
           diff_ref_mode(pts, sizes, nrings, s, rule, center, RAST_BOUNDARY_CONSERVATIVE);
}

/* v rounded down to a multiple of m > 0 (no shift of a negative value). */
static int64_t down(int64_t v, int64_t m)
{
    int64_t r = v % m;
    return v - (r < 0 ? r + m : r);
}

/* Random polygons near the window, at precision s, with vertices up to
 * `reach` pixels from it (so edges come from far away). */
static void test_reference(int s, int cases)
{
    rast_point64 pts[MAXP];
    uint32_t sizes[4], nrings;
    int c, bad = 0;
    const int64_t px = (int64_t)1 << s;
    for (c = 0; c < cases; c++) {
        int64_t reach = c % 3 == 0 ? 4 : c % 3 == 1 ? 200 : ((int64_t)1 << 27);
        uint32_t n = random_poly(pts, sizes, &nrings, -reach * px, (W + reach) * px,
                                 -reach * px, (H + reach) * px), k;
        if (c % 5 == 4) /* vertices on sample points (centres and corners) */
            for (k = 0; k < n; k++) {
                pts[k].x = down(pts[k].x, (int64_t)1 << (s - 1));
                pts[k].y = down(pts[k].y, (int64_t)1 << (s - 1));
            }
        if (c % 7 == 6 && n >= 3) { /* a collinear point mid-edge */
            pts[1].x = pts[0].x + (pts[2].x - pts[0].x) / 2;
            pts[1].y = pts[0].y + (pts[2].y - pts[0].y) / 2;
        }
        bad += diff_ref(pts, sizes, nrings, s, c & 1, (c >> 1) & 1) != 0;
    }
    CHECK(bad == 0);
}

/* Slivers: triangles one unit (2^-S pixel) thin, or thinner in places,
 * crossing the window at random slopes. */
static void test_slivers(int s)
{
    rast_point64 pts[3];
    uint32_t sizes[1] = {3};
    int c, bad = 0;
    const int64_t px = (int64_t)1 << s;
    for (c = 0; c < 60; c++) {
        pts[0].x = rnd64(-8 * px, (W + 8) * px);
        pts[0].y = rnd64(-8 * px, 0);
        pts[1].x = rnd64(-8 * px, (W + 8) * px);
        pts[1].y = rnd64(H * px, (H + 8) * px);
        pts[2].x = pts[1].x + (c & 1 ? 1 : -1);
        pts[2].y = pts[1].y + (c & 2 ? 1 : 0);
        bad += diff_ref(pts, sizes, 1, s, c & 1, (c >> 2) & 1) != 0;
    }
    CHECK(bad == 0);
}

/* The ends of the range: polygons with vertices at +-RAST_COORD64_MAX(s),
 * seen through windows at the origin and next to the range's corners (a
 * window far away is the same fill translated: vertices shifted by whole
 * pixels). */
static void test_limits(int s)
{
    const int64_t lim = RAST_COORD64_MAX(s), px = (int64_t)1 << s;
    rast_point64 pts[MAXP];
    uint32_t sizes[4], nrings;
    int c, bad = 0;
    for (c = 0; c < 40; c++) {
        uint32_t n, k;
        int64_t sx = (c & 1) ? 1 : -1, sy = (c & 2) ? 1 : -1;
        /* the window's pixel (0, 0) is plane pixel (ox, oy) */
        int64_t ox = c % 8 < 4 ? 0 : sx * ((lim >> s) - (sx > 0 ? W : 0));
        int64_t oy = c % 8 < 4 ? 0 : sy * ((lim >> s) - (sy > 0 ? H : 0));
        n = random_poly(pts, sizes, &nrings, -lim, lim, -lim, lim);
        for (k = 0; k < n; k++) { /* some vertices exactly at the limits */
            if (rng() % 3 == 0) pts[k].x = rng() & 1 ? lim : -lim;
            if (rng() % 3 == 0) pts[k].y = rng() & 1 ? lim : -lim;
        }
        /* Translate by (-ox, -oy) pixels, which keeps the vertices in range
         * only where they stay inside: clamp those that would not (still a
         * polygon, still at the limit). */
        for (k = 0; k < n; k++) {
            int64_t x = pts[k].x - ox * px, y = pts[k].y - oy * px;
            pts[k].x = x > lim ? lim : x < -lim ? -lim : x;
            pts[k].y = y > lim ? lim : y < -lim ? -lim : y;
        }
        bad += diff_ref(pts, sizes, nrings, s, c & 1, (c >> 3) & 1) != 0;
    }
    CHECK(bad == 0);
}

/* Same vertices through the 32-bit path (S <= 16): same bytes, exact and
 * conservative; then scaled by 2^k to S + k through the 64-bit path. */
static void test_vs32(int cases)
{
    rast_point p32[MAXP];
    rast_point64 p64[MAXP];
    uint32_t sizes[4], nrings, k;
    int c, same = 0, scaled = 0, total = 0;
    for (c = 0; c < cases; c++) {
        int s = (int)(rng() % 17), rule = c & 1, center = (c >> 1) & 1;
        int boundary = (c >> 2) & 1 ? RAST_BOUNDARY_CONSERVATIVE : RAST_BOUNDARY_EXACT;
        int64_t px = (int64_t)1 << s, reach = c % 3 == 0 ? 3 : 60;
        int64_t lo = -reach * px, hi = (W + reach) * px;
        rast_fill_opts o = opts_of(s, rule, center, boundary), o2;
        rast_polygon p;
        rast_target t;
        static const unsigned char one = 1;
        uint32_t n;
        int kk;
        if (hi > RAST_COORD_MAX) hi = RAST_COORD_MAX;
        if (lo < -RAST_COORD_MAX) lo = -RAST_COORD_MAX;
        n = random_poly(p64, sizes, &nrings, lo, hi, lo, hi);
        for (k = 0; k < n; k++) {
            p32[k].x = (int32_t)p64[k].x;
            p32[k].y = (int32_t)p64[k].y;
        }
        p.points = p32;
        p.ring_sizes = sizes;
        p.nrings = nrings;
        memset(img_b, 0, sizeof img_b);
        CHECK(rast_target_init(&t, img_b, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
        CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_OK);
        CHECK(fill64(img_a, p64, sizes, nrings, &o) == RAST_OK);
        same += memcmp(img_a, img_b, sizeof img_a) == 0;
        /* scaled: S + kk, every vertex times 2^kk */
        kk = 1 + (int)(rng() % (uint32_t)(RAST_MAX_SUBPIXEL_BITS64 - s));
        for (k = 0; k < n; k++) {
            p64[k].x *= (int64_t)1 << kk;
            p64[k].y *= (int64_t)1 << kk;
        }
        o2 = opts_of(s + kk, rule, center, boundary);
        CHECK(fill64(img_a, p64, sizes, nrings, &o2) == RAST_OK);
        scaled += memcmp(img_a, img_b, sizeof img_a) == 0;
        total++;
    }
    CHECK(same == total);
    CHECK(scaled == total);
}

/* Every error before any write. */
static void test_errors(void)
{
    const int s = 24;
    const int64_t lim = RAST_COORD64_MAX(s);
    rast_point64 pts[3] = {{0, 0}, {0, 0}, {0, 0}};
    uint32_t sizes[1] = {3};
    rast_polygon64 p;
    rast_target t;
    rast_fill_opts o = opts_of(s, 0, 1, 0);
    static const unsigned char one = 1;
    unsigned char before[H][W];
    size_t need;
    int k;
    p.points = pts;
    p.ring_sizes = sizes;
    p.nrings = 1;
    pts[1].x = lim;
    pts[2].y = lim;
    memset(img_a, 7, sizeof img_a);
    memcpy(before, img_a, sizeof before);
    CHECK(rast_target_init(&t, img_a, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_OK);
    CHECK(memcmp(before, img_a, sizeof before) != 0); /* at the limit: fine, and draws */
    memcpy(img_a, before, sizeof before);
    for (k = 0; k < 4; k++) { /* one unit past the range, each sign and axis */
        rast_point64 keep = pts[1];
        if (k == 0) pts[1].x = lim + 1;
        if (k == 1) pts[1].x = -lim - 1;
        if (k == 2) pts[1].y = lim + 1;
        if (k == 3) pts[1].y = -lim - 1;
        CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_RANGE);
        pts[1] = keep;
    }
    pts[1].x = INT64_MAX;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_RANGE);
    pts[1].x = INT64_MIN;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_RANGE);
    pts[1].x = lim;
    o.subpixel_bits = 33;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_SUBPIXEL);
    CHECK(rast_scratch_size64(&o, 3, W, H, &need) == RAST_E_SUBPIXEL);
    o.subpixel_bits = -1;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_SUBPIXEL);
    o = opts_of(s, 0, 1, 0);
    for (k = 1; k < RAST_ALGO_COUNT_; k++) {
        o.algorithm = (rast_algorithm)k;
        o.rule = RAST_RULE_EVENODD;
        CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_WIDE);
        CHECK(rast_scratch_size64(&o, 3, W, H, &need) == RAST_E_WIDE);
    }
    o.algorithm = (rast_algorithm)RAST_ALGO_COUNT_;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_ALGORITHM);
    o = opts_of(s, 0, 1, 0);
    o.rounding = RAST_ROUND_TEXTBOOK;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_WIDE);
    o = opts_of(s, 0, 1, RAST_BOUNDARY_CLOSED);
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_WIDE);
    o = opts_of(s, 0, 1, 0);
    o.sample = (rast_sample)5;
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_ARG);
    o = opts_of(s, 0, 1, 0);
    CHECK(rast_scratch_size64(&o, 3, W, H, &need) == RAST_OK);
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, scratch_mem, need - 1) == RAST_E_SCRATCH);
    CHECK(rast_fill_polygon64(&t, &p, &o, &one, (unsigned char *)scratch_mem + 1, need) == RAST_E_ALIGN);
    CHECK(rast_fill_polygon64(&t, NULL, &o, &one, scratch_mem, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon64(&t, &p, NULL, &one, scratch_mem, need) == RAST_E_NULL);
    CHECK(rast_fill_polygon64_spans(&p, &o, NULL, NULL, NULL, scratch_mem, need) == RAST_E_NULL);
    CHECK(rast_scratch_size64(&o, 3, -1, H, &need) == RAST_E_SIZE);
    CHECK(rast_scratch_size64(&o, RAST_MAX_POINTS + 1u, W, H, &need) == RAST_E_TOO_MANY);
    CHECK(memcmp(before, img_a, sizeof before) == 0);
    CHECK(strstr(rast_status_str(RAST_E_WIDE), "64-bit") != NULL);
    /* memory grows with the vertices and rows, never with the coordinates */
    {
        size_t a, b;
        rast_fill_opts o0 = opts_of(0, 0, 1, RAST_BOUNDARY_CONSERVATIVE);
        rast_fill_opts o32 = opts_of(32, 0, 1, RAST_BOUNDARY_CONSERVATIVE);
        CHECK(rast_scratch_size64(&o0, 100, W, H, &a) == RAST_OK);
        CHECK(rast_scratch_size64(&o32, 100, W, H, &b) == RAST_OK);
        CHECK(a == b);
    }
}

/* The band renderer: a scene of 64-bit polygons (both rules, both
 * boundary modes) against the direct fills, band heights 1, 3, 40; and
 * the spans call against the target call. */
static uint32_t span_count;
static void span_paint(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    unsigned char (*img)[W] = (unsigned char (*)[W])user;
    memset(&img[y][x0], *(const unsigned char *)prim->pixel, (size_t)(x1 - x0));
    span_count++;
}

static void test_bands(void)
{
    static rast_point64 pts[4][MAXP];
    static uint32_t sizes[4][4];
    rast_prim prims[4];
    rast_fill_opts fo[4];
    unsigned char px[4] = {11, 22, 33, 44};
    rast_target t;
    int rep, i, rows[3] = {1, 3, 40}, r;
    for (rep = 0; rep < 20; rep++) {
        int s = 20 + (int)(rng() % 13);
        int64_t unit = (int64_t)1 << s;
        for (i = 0; i < 4; i++) {
            uint32_t nr;
            memset(&prims[i], 0, sizeof prims[i]);
            random_poly(pts[i], sizes[i], &nr, -5 * unit, (W + 5) * unit, -5 * unit, (H + 5) * unit);
            fo[i] = opts_of(s, i & 1, (rep >> 1) & 1, i >= 2 ? RAST_BOUNDARY_CONSERVATIVE : 0);
            prims[i].kind = RAST_PRIM_POLYGON64;
            prims[i].polygon64.points = pts[i];
            prims[i].polygon64.ring_sizes = sizes[i];
            prims[i].polygon64.nrings = nr;
            prims[i].fill = &fo[i];
            prims[i].pixel = &px[i];
        }
        memset(img_b, 0, sizeof img_b);
        CHECK(rast_target_init(&t, img_b, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
        for (i = 0; i < 4; i++)
            CHECK(rast_fill_polygon64(&t, &prims[i].polygon64, &fo[i], &px[i], scratch_mem,
                                      sizeof scratch_mem) == RAST_OK);
        for (r = 0; r < 3; r++) {
            size_t one;
            memset(img_a, 0, sizeof img_a);
            memset(img_c, 0, sizeof img_c);
            CHECK(rast_target_init(&t, img_a, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
            CHECK(rast_scene_scratch_size(prims, 4, 1, W, &one) == RAST_OK);
            CHECK(rast_render_bands(&t, prims, 4, rows[r], scratch_mem, sizeof scratch_mem, NULL) == RAST_OK);
            CHECK(memcmp(img_a, img_b, sizeof img_a) == 0);
            {
                rast_rect clip = {0, 0, W, H};
                CHECK(rast_render_bands_spans(prims, 4, &clip, rows[r], span_paint, img_c,
                                              scratch_mem, one, NULL) == RAST_OK);
                CHECK(memcmp(img_c, img_b, sizeof img_c) == 0);
            }
        }
    }
    /* a bad 64-bit primitive last: nothing drawn */
    {
        rast_band_stats st;
        memset(img_a, 0, sizeof img_a);
        pts[3][0].x = RAST_COORD64_MAX(fo[3].subpixel_bits) + 1;
        CHECK(rast_render_bands(&t, prims, 4, 8, scratch_mem, sizeof scratch_mem, &st) == RAST_E_RANGE);
        {
            int i2, j2, zero = 1;
            for (j2 = 0; j2 < H; j2++)
                for (i2 = 0; i2 < W; i2++) zero &= img_a[j2][i2] == 0;
            CHECK(zero);
        }
    }
    CHECK(span_count > 0);
}

/* The batch: rast_fill_polygons64_spans equals each polygon's own spans
 * call, in order; rast_fill_bounds64 holds every pixel of its polygon; a
 * bad polygon is named by *failed before any span. */
typedef struct {
    unsigned char (*img)[W];
    uint32_t spans;
} batch_user;

static void batch_span(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    batch_user *u = (batch_user *)user;
    memset(&u->img[y][x0], (int)(k + 1), (size_t)(x1 - x0));
    u->spans++;
}

static unsigned char (*one_img)[W];
static uint32_t one_k;
static void one_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    (void)user;
    memset(&one_img[y][x0], (int)(one_k + 1), (size_t)(x1 - x0));
}

static void test_batch64(void)
{
    static rast_point64 pts[8][MAXP];
    static uint32_t sizes[8][4];
    rast_polygon64 polys[8];
    rast_rect clip = {0, 0, W, H}, b;
    int rep, outside = 0, same = 0;
    uint32_t k, failed;
    for (rep = 0; rep < 40; rep++) {
        int s = (int)(rng() % 33);
        int64_t unit = (int64_t)1 << s;
        rast_fill_opts o = opts_of(s, rep & 1, 1, (rep >> 1) & 1 ? RAST_BOUNDARY_CONSERVATIVE : 0);
        batch_user u;
        size_t need;
        for (k = 0; k < 8; k++) {
            uint32_t nr;
            random_poly(pts[k], sizes[k], &nr, -3 * unit, (W + 3) * unit, -3 * unit, (H + 3) * unit);
            polys[k].points = pts[k];
            polys[k].ring_sizes = sizes[k];
            polys[k].nrings = nr;
        }
        CHECK(rast_polygons64_scratch_size(polys, 8, &o, &clip, &need, &failed) == RAST_OK);
        memset(img_a, 0, sizeof img_a);
        u.img = img_a;
        u.spans = 0;
        CHECK(rast_fill_polygons64_spans(polys, 8, &o, &clip, batch_span, &u, scratch_mem, need,
                                         &failed) == RAST_OK);
        memset(img_b, 0, sizeof img_b);
        one_img = img_b;
        for (k = 0; k < 8; k++) {
            int i, j;
            one_k = k;
            CHECK(rast_fill_polygon64_spans(&polys[k], &o, &clip, one_span, NULL, scratch_mem,
                                            sizeof scratch_mem) == RAST_OK);
            /* the bounds hold this polygon's pixels */
            memset(img_c, 0, sizeof img_c);
            one_img = img_c;
            CHECK(rast_fill_polygon64_spans(&polys[k], &o, &clip, one_span, NULL, scratch_mem,
                                            sizeof scratch_mem) == RAST_OK);
            one_img = img_b;
            CHECK(rast_fill_bounds64(&o, &polys[k], &clip, &b) == RAST_OK);
            for (j = 0; j < H; j++)
                for (i = 0; i < W; i++)
                    if (img_c[j][i] && (i < b.x0 || i >= b.x1 || j < b.y0 || j >= b.y1)) outside++;
        }
        same += memcmp(img_a, img_b, sizeof img_a) == 0;
        /* polygon 5 out of range: named, nothing drawn */
        pts[5][0].x = RAST_COORD64_MAX(s) + 1;
        memset(img_a, 0, sizeof img_a);
        failed = 99;
        u.spans = 0;
        CHECK(rast_fill_polygons64_spans(polys, 8, &o, &clip, batch_span, &u, scratch_mem,
                                         sizeof scratch_mem, &failed) == RAST_E_RANGE);
        CHECK(failed == 5 && u.spans == 0);
        CHECK(rast_fill_bounds64(&o, &polys[5], &clip, &b) == RAST_E_RANGE);
    }
    CHECK(same == 40);
    CHECK(outside == 0);
    {
        rast_fill_opts o = opts_of(24, 0, 1, 0);
        o.algorithm = RAST_ALGO_XSCAN;
        CHECK(rast_fill_polygons64_spans(polys, 8, &o, &clip, batch_span, NULL, scratch_mem,
                                         sizeof scratch_mem, &failed) == RAST_E_WIDE);
    }
}

int main(void)
{
    int s;
    int n = check_count(60);
    for (s = 20; s <= 32; s += 4) test_reference(s, n);
    test_reference(1, n);
    test_reference(8, n);
    test_slivers(32);
    test_slivers(24);
    test_limits(32);
    test_limits(24);
    test_limits(0);
    CHECK(inside_seen > 10000 && outside_seen > 10000);
    test_vs32(check_count(400));
    test_errors();
    test_bands();
    test_batch64();
    return check_report("test_poly64");
}

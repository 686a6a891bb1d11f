/*
 * test_lines.c - lines and predicates: the seed's Bresenham (002) worked
 * by hand, all eight octants, symmetry, exact clipping of huge lines, guard
 * bytes, errors that leave the target untouched, and the four predicates
 * on a triangle's boundary.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 4242u
#include "check.h"
#include "ref.h"
#include "base/internal.h" /* rast__line_rows, rast__line_run: the line by formula */
#include "rastrum.h"

#define GUARD 0xA5

static const rast_rect everything = {-RAST_MAX_DIM, -RAST_MAX_DIM, RAST_MAX_DIM, RAST_MAX_DIM};

/* The pixels of a -> b, at most cap, into xy; returns the count or -1. */
static long pixels(rast_point a, rast_point b, int s, int center, int dda, const rast_rect *clip,
                   int32_t *xy, size_t cap)
{
    rast_line_opts o;
    size_t n = 0;
    o.algorithm = dda ? RAST_LINE_DDA : RAST_LINE_BRESENHAM;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    if (rast_line_pixels(a, b, &o, clip ? clip : &everything, xy, cap, &n) != RAST_OK) return -1;
    return (long)n;
}

/* The listed pixels are exactly ref_minor's, in order from a. */
static int equals_ref(rast_point a, rast_point b, int s, int center, const int32_t *xy, long n)
{
    int ymajor = (int64_t)(b.y > a.y ? b.y - a.y : a.y - b.y) > (int64_t)(b.x > a.x ? b.x - a.x : a.x - b.x);
    int64_t U = (int64_t)1 << s, O2 = center ? 1 : 0; /* in input units: pixel 2^s, offset 2^s/2 */
    int64_t amaj = ymajor ? a.y : a.x, bmaj = ymajor ? b.y : b.x, lo, hi, p, q;
    int sm = bmaj >= amaj ? 1 : -1;
    long k = 0;
    /* samples p*2^s + o*2^s in [min, max]: in doubled units to keep o = 1/2 whole */
    lo = -ref_floor_div(-(2 * (amaj < bmaj ? amaj : bmaj) - O2 * U), 2 * U);
    hi = ref_floor_div(2 * (amaj > bmaj ? amaj : bmaj) - O2 * U, 2 * U);
    if ((lo > hi ? 0 : hi - lo + 1) != n) return 0;
    for (p = sm > 0 ? lo : hi; k < n; p += sm, k++) {
        int32_t x = ymajor ? xy[2 * k + 1] : xy[2 * k], y = ymajor ? xy[2 * k] : xy[2 * k + 1];
        if (!ref_line_minor(a, b, s, center, p, &q)) return 0;
        if (x != p || y != q) return 0;
    }
    return 1;
}

/* ---- seed 002's line(), transcribed --------------------------------------------
 * Integer endpoints, pixels at integer points (S = 0, o = 0). */
static int seed_line(int x0, int y0, int x1, int y1, int32_t *xy)
{
    int steep = 0, n = 0, t, dx, dx2, dy, derror, error, x, y;
    if ((x0 > x1 ? x0 - x1 : x1 - x0) < (y0 > y1 ? y0 - y1 : y1 - y0)) {
        t = x0; x0 = y0; y0 = t;
        t = x1; x1 = y1; y1 = t;
        steep = 1;
    }
    if (x0 > x1) {
        t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
    }
    dx = x1 - x0;
    dx2 = dx * 2;
    dy = y1 - y0;
    derror = (dy < 0 ? -dy : dy) * 2;
    error = 0;
    y = y0;
    for (x = x0; x <= x1; x++) {
        xy[2 * n] = steep ? y : x;
        xy[2 * n + 1] = steep ? x : y;
        n++;
        error += derror;
        if (error > dx) { /* "more than .5": a tie (error == dx) stays */
            y += (y1 > y0 ? 1 : -1);
            error -= dx2;
        }
    }
    return n;
}

/* Seed 002 by hand: (0,0) -> (8,3) with the seed's code.  error runs
 * 0 6 12>8:-4 2 8 14>8:-2 4 10>8:-6 0, so its rows are
 *   x: 0 1 2 3 4 5 6 7 8
 *   y: 0 0 1 1 1 2 2 3 3
 * The library's y(x) = 3x/8 is 1.5 at x = 4, a tie: the seed keeps the row
 * it is on (error == dx is not "more than .5"), which is the row above for
 * a line going down; the library goes down, to row 2.  Every other pixel
 * agrees.  (0,3) -> (8,0) climbs instead, and there the seed's "stay" is
 * the row below: it agrees with the library everywhere. */
static void test_seed_002_by_hand(void)
{
    static const int32_t seed_down[9] = {0, 0, 1, 1, 1, 2, 2, 3, 3};
    static const int32_t lib_down[9] = {0, 0, 1, 1, 2, 2, 2, 3, 3};
    static const int32_t both_up[9] = {3, 3, 2, 2, 2, 1, 1, 0, 0};
    int32_t xy[64], ref[64];
    rast_point a = {0, 0}, b = {8, 3}, c = {0, 3}, d = {8, 0};
    int k, n;

    n = seed_line(0, 0, 8, 3, ref);
    CHECK(n == 9);
    for (k = 0; k < 9; k++) CHECK(ref[2 * k] == k && ref[2 * k + 1] == seed_down[k]);
    CHECK(pixels(a, b, 0, 0, 0, NULL, xy, 32) == 9);
    for (k = 0; k < 9; k++) CHECK(xy[2 * k] == k && xy[2 * k + 1] == lib_down[k]);
    /* the seed draws b -> a left to right too: the same pixels, same tie */
    n = seed_line(8, 3, 0, 0, ref);
    CHECK(n == 9 && ref[2 * 4 + 1] == 1);
    CHECK(pixels(b, a, 0, 0, 0, NULL, xy, 32) == 9);
    for (k = 0; k < 9; k++) CHECK(xy[2 * k] == 8 - k && xy[2 * k + 1] == lib_down[8 - k]);

    n = seed_line(0, 3, 8, 0, ref);
    CHECK(n == 9);
    for (k = 0; k < 9; k++) CHECK(ref[2 * k] == k && ref[2 * k + 1] == both_up[k]);
    CHECK(pixels(c, d, 0, 0, 0, NULL, xy, 32) == 9);
    for (k = 0; k < 9; k++) CHECK(xy[2 * k] == k && xy[2 * k + 1] == both_up[k]);
}

/* The seed's line on random integer lines (S = 0, o = 0): the same major
 * pixels, the same minor pixel except at exact ties, where the library's
 * is one further down (x-major) or right (y-major) than the seed's; that
 * happens only on lines whose minor coordinate grows with the major one
 * (there the seed's "stay" is up or left). */
static void test_seed_002_random(void)
{
    static int32_t xy[2 * 200], ref[2 * 200];
    int iter, bad = 0, ties = 0;
    for (iter = 0; iter < 20000; iter++) {
        rast_point a, b;
        long n;
        int m, k;
        a.x = (int32_t)(rng() % 61) - 30;
        a.y = (int32_t)(rng() % 61) - 30;
        b.x = (int32_t)(rng() % 61) - 30;
        b.y = (int32_t)(rng() % 61) - 30;
        if (rng() % 3 == 0) b.y = a.y + (b.x - a.x) / 2; /* slope 1/2: ties */
        m = seed_line(a.x, a.y, b.x, b.y, ref);
        n = pixels(a, b, 0, 0, 0, NULL, xy, 200);
        if (n != m) {
            bad++;
            continue;
        }
        /* compare as sets along the major axis: the seed walks left to right */
        for (k = 0; k < m; k++) {
            int j, found = 0;
            for (j = 0; j < m; j++) {
                int ymajor = (b.y > a.y ? b.y - a.y : a.y - b.y) > (b.x > a.x ? b.x - a.x : a.x - b.x);
                int maj = ymajor ? 1 : 0;
                if (xy[2 * j + maj] != ref[2 * k + maj]) continue;
                found = 1;
                if (xy[2 * j + 1 - maj] == ref[2 * k + 1 - maj]) break;
                /* a tie: the library one further down / right */
                if (xy[2 * j + 1 - maj] == ref[2 * k + 1 - maj] + 1 &&
                    (maj ? ((int64_t)b.y - a.y) * ((int64_t)b.x - a.x) > 0
                         : ((int64_t)b.x - a.x) * ((int64_t)b.y - a.y) > 0))
                    ties++;
                else
                    bad++;
                break;
            }
            if (!found) bad++;
        }
    }
    CHECK(bad == 0);
    CHECK(ties > 0); /* the slope-1/2 lines do meet ties */
}

/* ---- eight octants, worked by hand (S = 0, o = 0, from (0,0)) -------------
 * Slope 2/5 has no tie: y = 2x/5 is 0, .4, .8, 1.2, 1.6, 2 -> rows 0 0 1 1 2 2.
 * Slope 1/2 ties at odd x: y = .5 goes down to 1, y = -.5 goes "down" to 0,
 * so the same line reflected is not the reflected pixels: the tie rule
 * depends on the axis, not on the direction of travel. */
static void test_octants(void)
{
    struct {
        rast_point b;
        int n;
        int32_t xy[12];
    } v[] = {
        {{5, 2}, 6, {0, 0, 1, 0, 2, 1, 3, 1, 4, 2, 5, 2}},
        {{2, 5}, 6, {0, 0, 0, 1, 1, 2, 1, 3, 2, 4, 2, 5}},
        {{-2, 5}, 6, {0, 0, 0, 1, -1, 2, -1, 3, -2, 4, -2, 5}},
        {{-5, 2}, 6, {0, 0, -1, 0, -2, 1, -3, 1, -4, 2, -5, 2}},
        {{-5, -2}, 6, {0, 0, -1, 0, -2, -1, -3, -1, -4, -2, -5, -2}},
        {{-2, -5}, 6, {0, 0, 0, -1, -1, -2, -1, -3, -2, -4, -2, -5}},
        {{2, -5}, 6, {0, 0, 0, -1, 1, -2, 1, -3, 2, -4, 2, -5}},
        {{5, -2}, 6, {0, 0, 1, 0, 2, -1, 3, -1, 4, -2, 5, -2}},
        /* ties */
        {{4, 2}, 5, {0, 0, 1, 1, 2, 1, 3, 2, 4, 2}},
        {{4, -2}, 5, {0, 0, 1, 0, 2, -1, 3, -1, 4, -2}},
        {{-4, 2}, 5, {0, 0, -1, 1, -2, 1, -3, 2, -4, 2}},
        {{-4, -2}, 5, {0, 0, -1, 0, -2, -1, -3, -1, -4, -2}},
        {{2, 4}, 5, {0, 0, 1, 1, 1, 2, 2, 3, 2, 4}},
        {{-2, 4}, 5, {0, 0, 0, 1, -1, 2, -1, 3, -2, 4}},
        {{2, -4}, 5, {0, 0, 1, -1, 1, -2, 2, -3, 2, -4}},
        {{-2, -4}, 5, {0, 0, 0, -1, -1, -2, -1, -3, -2, -4}},
        /* diagonals and axes */
        {{3, 3}, 4, {0, 0, 1, 1, 2, 2, 3, 3}},
        {{-3, 3}, 4, {0, 0, -1, 1, -2, 2, -3, 3}},
        {{0, -3}, 4, {0, 0, 0, -1, 0, -2, 0, -3}},
        {{-3, 0}, 4, {0, 0, -1, 0, -2, 0, -3, 0}},
        {{0, 0}, 1, {0, 0}},
    };
    rast_point o = {0, 0};
    int32_t xy[32];
    size_t i;
    int k;
    for (i = 0; i < sizeof v / sizeof v[0]; i++) {
        int ok = pixels(o, v[i].b, 0, 0, 0, NULL, xy, 16) == v[i].n;
        for (k = 0; ok && k < 2 * v[i].n; k++) ok = xy[k] == v[i].xy[k];
        if (!ok) fprintf(stderr, "octant vector %d\n", (int)i);
        CHECK(ok);
        /* b -> a: the same pixels, in the reverse order */
        ok = pixels(v[i].b, o, 0, 0, 0, NULL, xy, 16) == v[i].n;
        for (k = 0; ok && k < v[i].n; k++)
            ok = xy[2 * k] == v[i].xy[2 * (v[i].n - 1 - k)] && xy[2 * k + 1] == v[i].xy[2 * (v[i].n - 1 - k) + 1];
        CHECK(ok);
        /* o = 1/2, S = 1, endpoints on pixel centres: the same pixels */
        {
            rast_point a2 = {1, 1}, b2;
            b2.x = 2 * v[i].b.x + 1;
            b2.y = 2 * v[i].b.y + 1;
            ok = pixels(a2, b2, 1, 1, 0, NULL, xy, 16) == v[i].n;
            for (k = 0; ok && k < 2 * v[i].n; k++) ok = xy[k] == v[i].xy[k];
            CHECK(ok);
        }
    }
}

/* ---- random lines against the reference, symmetric, clipped ---------------- */
static int32_t rand_coord(int s, int32_t span)
{
    int32_t v = (int32_t)(rng() % (uint32_t)(2 * span + 1)) - span;
    if (rng() % 4 == 0) v &= ~(((int32_t)1 << s) - 1); /* on the pixel grid */
    return v;
}

static void test_random(void)
{
    static int32_t xy[2 * 2100], back[2 * 2100], cl[2 * 2100];
    int iter, bad = 0, asym = 0, clipbad = 0;
    for (iter = 0; iter < 20000; iter++) {
        int s = (int)(rng() % 9), center = (int)(rng() & 1);
        int32_t span = (int32_t)((rng() % 3 == 0) ? 1000 : 20) << s;
        rast_point a, b;
        rast_rect clip;
        long n, m, c, k, j;
        a.x = rand_coord(s, span);
        a.y = rand_coord(s, span);
        b.x = rand_coord(s, span);
        b.y = rand_coord(s, span);
        if (rng() % 8 == 0) b = a;
        n = pixels(a, b, s, center, 0, NULL, xy, 2100);
        m = pixels(b, a, s, center, 0, NULL, back, 2100);
        if (n < 0 || !equals_ref(a, b, s, center, xy, n)) bad++;
        if (m != n) {
            asym++;
            continue;
        }
        for (k = 0; k < n; k++)
            if (xy[2 * k] != back[2 * (n - 1 - k)] || xy[2 * k + 1] != back[2 * (n - 1 - k) + 1]) asym++;
        /* a random clip: exactly the pixels inside, in the same order */
        clip.x0 = (int32_t)(rng() % 60) - 30;
        clip.y0 = (int32_t)(rng() % 60) - 30;
        clip.x1 = clip.x0 + (int32_t)(rng() % 40);
        clip.y1 = clip.y0 + (int32_t)(rng() % 40);
        c = pixels(a, b, s, center, 0, &clip, cl, 2100);
        for (k = 0, j = 0; k < n; k++) {
            if (xy[2 * k] < clip.x0 || xy[2 * k] >= clip.x1 || xy[2 * k + 1] < clip.y0 || xy[2 * k + 1] >= clip.y1)
                continue;
            if (j >= c || cl[2 * j] != xy[2 * k] || cl[2 * j + 1] != xy[2 * k + 1]) clipbad++;
            j++;
        }
        if (j != c) clipbad++;
    }
    CHECK(bad == 0);
    CHECK(asym == 0);
    CHECK(clipbad == 0);
}

/* ---- huge lines through a small window: exact, guarded, and quick ----------
 * Endpoints at +-RAST_COORD_MAX for every S: with S = 0 the lines are 2^28
 * pixels long; walking them step by step would take seconds, the clip jump
 * takes nothing.  Every pixel drawn is the reference's. */
static void test_huge(void)
{
    enum { W = 37, H = 29, PAD = 8, STRIDE = W + 2 * PAD };
    static unsigned char buf[(H + 2 * PAD) * STRIDE];
    const int32_t M = RAST_COORD_MAX;
    int s, iter, bad = 0, guard = 0, drawn = 0;
    for (iter = 0; iter < 2000; iter++) {
        rast_target t;
        rast_line_opts o;
        rast_point a, b;
        unsigned char one = 1;
        int i, j, center = (int)(rng() & 1);
        s = (int)(rng() % (RAST_MAX_SUBPIXEL_BITS + 1));
        /* one endpoint at an extreme, the other anywhere: through the
         * window often enough (the window is near the origin) */
        a.x = (rng() & 1) ? M : -M;
        a.y = (int32_t)(rng() % (2u * (uint32_t)M + 1u)) - M;
        if (rng() & 1) { int32_t tt = a.x; a.x = a.y; a.y = tt; }
        b.x = (int32_t)(rng() % (uint32_t)(W << s)) * ((rng() & 1) ? 1 : -1);
        b.y = (int32_t)(rng() % (uint32_t)(H << s));
        if (iter % 3 == 0) { /* through the middle */
            b.x = -a.x;
            b.y = -a.y + (int32_t)(rng() % 64) - 32;
            if (b.y > M) b.y = M;
            if (b.y < -M) b.y = -M;
        }
        memset(buf, GUARD, sizeof buf);
        for (j = 0; j < H; j++) memset(buf + (PAD + j) * STRIDE + PAD, 0, W);
        CHECK(rast_target_init(&t, buf + PAD * STRIDE + PAD, W, H, STRIDE, RAST_FORMAT_GRAY8) == RAST_OK);
        o.algorithm = RAST_LINE_BRESENHAM;
        o.subpixel_bits = s;
        o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        if (rast_draw_line(&t, a, b, &o, &one) != RAST_OK) bad++;
        for (j = -PAD; j < H + PAD; j++)
            for (i = -PAD; i < W + PAD; i++) {
                unsigned char v = buf[(PAD + j) * STRIDE + PAD + i];
                if (i < 0 || j < 0 || i >= W || j >= H) {
                    guard += v != GUARD;
                } else {
                    int want = ref_line_has(a, b, s, center, i, j);
                    bad += v != want;
                    drawn += v;
                }
            }
    }
    CHECK(bad == 0);
    CHECK(guard == 0);
    CHECK(drawn > 1000); /* the lines did cross the window */
}

/* ---- polylines and outlines ------------------------------------------------- */
static void test_polyline(void)
{
    static unsigned char img[24 * 24], want[24 * 24];
    rast_point tri[3] = {{3 << 4, 2 << 4}, {20 << 4, 9 << 4}, {6 << 4, 21 << 4}};
    int32_t xy[2 * 64];
    rast_target t;
    rast_line_opts o;
    unsigned char one = 1;
    int k;
    long n, i;
    o.algorithm = RAST_LINE_BRESENHAM;
    o.subpixel_bits = 4;
    o.sample = RAST_SAMPLE_CENTER;
    memset(img, 0, sizeof img);
    memset(want, 0, sizeof want);
    CHECK(rast_target_init(&t, img, 24, 24, 24, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_draw_polyline(&t, tri, 3, 1, &o, &one) == RAST_OK);
    for (k = 0; k < 3; k++) { /* seed 002: three lines make a triangle */
        n = pixels(tri[k], tri[(k + 1) % 3], 4, 1, 0, NULL, xy, 64);
        for (i = 0; i < n; i++) want[xy[2 * i + 1] * 24 + xy[2 * i]] = 1;
    }
    CHECK(memcmp(img, want, sizeof img) == 0);
    /* open: without the closing edge */
    memset(img, 0, sizeof img);
    memset(want, 0, sizeof want);
    CHECK(rast_draw_polyline(&t, tri, 3, 0, &o, &one) == RAST_OK);
    for (k = 0; k < 2; k++) {
        n = pixels(tri[k], tri[k + 1], 4, 1, 0, NULL, xy, 64);
        for (i = 0; i < n; i++) want[xy[2 * i + 1] * 24 + xy[2 * i]] = 1;
    }
    CHECK(memcmp(img, want, sizeof img) == 0);
    CHECK(rast_draw_polyline(&t, tri, 0, 1, &o, &one) == RAST_OK);
    CHECK(rast_draw_polyline(&t, NULL, 0, 1, &o, &one) == RAST_OK);
}

/* ---- rgb and a narrowed clip: whole pixels, nothing outside the clip -------- */
static void test_rgb_clip(void)
{
    static unsigned char img[20 * 20 * 3], want[20 * 20 * 3];
    const unsigned char red[3] = {255, 1, 2};
    rast_point a = {-50, 3}, b = {70, 17};
    int32_t xy[2 * 200];
    rast_target t;
    rast_line_opts o;
    long n, i;
    o.algorithm = RAST_LINE_BRESENHAM;
    o.subpixel_bits = 0;
    o.sample = RAST_SAMPLE_CENTER;
    memset(img, 9, sizeof img);
    memcpy(want, img, sizeof img);
    CHECK(rast_target_init(&t, img, 20, 20, 60, RAST_FORMAT_RGB888) == RAST_OK);
    t.clip.x0 = 4; t.clip.y0 = 5; t.clip.x1 = 15; t.clip.y1 = 11;
    CHECK(rast_draw_line(&t, a, b, &o, red) == RAST_OK);
    n = pixels(a, b, 0, 1, 0, &t.clip, xy, 200);
    CHECK(n > 3);
    for (i = 0; i < n; i++) memcpy(want + xy[2 * i + 1] * 60 + xy[2 * i] * 3, red, 3);
    CHECK(memcmp(img, want, sizeof img) == 0);
}

/* ---- the DDA: one pixel per major step, never more than one off ------------ */
static void test_dda(void)
{
    static int32_t xy[2 * 2100], ex[2 * 2100];
    int iter, bad = 0, differ = 0;
    for (iter = 0; iter < 20000; iter++) {
        int s = (int)(rng() % 9), center = (int)(rng() & 1);
        int32_t span = (int32_t)1000 << s;
        rast_point a, b;
        long n, m, k;
        a.x = rand_coord(s, span);
        a.y = rand_coord(s, span);
        b.x = rand_coord(s, span);
        b.y = rand_coord(s, span);
        n = pixels(a, b, s, center, 1, NULL, xy, 2100);
        m = pixels(a, b, s, center, 0, NULL, ex, 2100);
        if (n != m) {
            bad++;
            continue;
        }
        for (k = 0; k < 2 * n; k++) {
            int32_t d = xy[k] - ex[k];
            if (d < -1 || d > 1) bad++;
            if (d) differ = 1;
        }
    }
    CHECK(bad == 0);
    CHECK(differ); /* it is not the exact line */
}

/* ---- errors: a status, and the target untouched ------------------------------ */
static void test_errors(void)
{
    static unsigned char img[16 * 16], before[16 * 16];
    rast_point a = {1, 1}, b = {14, 9}, pts[3] = {{1, 1}, {14, 9}, {3, 12}};
    rast_line_opts o;
    rast_target t;
    rast_rect clip = {0, 0, 16, 16};
    unsigned char one = 1;
    int32_t xy[64];
    size_t n = 99;
    int in = 7;
    rast_point far = {RAST_COORD_MAX + 1, 0};
    memset(img, 7, sizeof img);
    memcpy(before, img, sizeof img);
    CHECK(rast_target_init(&t, img, 16, 16, 16, RAST_FORMAT_GRAY8) == RAST_OK);
    memset(&o, 0, sizeof o);

    CHECK(rast_draw_line(NULL, a, b, &o, &one) == RAST_E_NULL);
    CHECK(rast_draw_line(&t, a, b, NULL, &one) == RAST_E_NULL);
    CHECK(rast_draw_line(&t, a, b, &o, NULL) == RAST_E_NULL);
    CHECK(rast_draw_line(&t, far, b, &o, &one) == RAST_E_RANGE);
    CHECK(rast_draw_line(&t, a, far, &o, &one) == RAST_E_RANGE);
    far.x = 0; far.y = -RAST_COORD_MAX - 1;
    CHECK(rast_draw_line(&t, a, far, &o, &one) == RAST_E_RANGE);
    o.subpixel_bits = 17;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_SUBPIXEL);
    o.subpixel_bits = -1;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_SUBPIXEL);
    o.subpixel_bits = 0;
    o.algorithm = RAST_LINE_COUNT_;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_ALGORITHM);
    o.algorithm = RAST_LINE_BRESENHAM;
    o.sample = (rast_sample)2;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_ARG);
    o.sample = RAST_SAMPLE_CORNER;
    t.format = (rast_format)77;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_FORMAT);
    t.format = RAST_FORMAT_GRAY8;
    t.stride = 3;
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_E_SIZE);
    t.stride = 16;
    CHECK(rast_draw_polyline(&t, NULL, 3, 0, &o, &one) == RAST_E_NULL);
    CHECK(rast_draw_polyline(&t, pts, (uint32_t)RAST_MAX_POINTS + 1, 0, &o, &one) == RAST_E_TOO_MANY);
    pts[2].x = RAST_COORD_MAX + 1; /* the last point bad: the first segments not drawn either */
    CHECK(rast_draw_polyline(&t, pts, 3, 1, &o, &one) == RAST_E_RANGE);
    pts[2].x = 3;
    o.algorithm = (rast_line_algorithm)9;
    CHECK(rast_draw_polyline(&t, pts, 3, 1, &o, &one) == RAST_E_ALGORITHM);
    o.algorithm = RAST_LINE_BRESENHAM;
    CHECK(memcmp(img, before, sizeof img) == 0);

    /* rast_line_pixels */
    CHECK(rast_line_pixels(a, b, &o, &clip, xy, 3, &n) == RAST_E_SCRATCH && n == 14);
    CHECK(rast_line_pixels(a, b, &o, &clip, NULL, 0, &n) == RAST_E_SCRATCH && n == 14);
    CHECK(rast_line_pixels(a, b, &o, &clip, NULL, 5, &n) == RAST_E_NULL);
    CHECK(rast_line_pixels(a, b, &o, NULL, xy, 32, &n) == RAST_E_NULL);
    CHECK(rast_line_pixels(a, b, &o, &clip, xy, 32, NULL) == RAST_E_NULL);
    CHECK(rast_line_pixels(a, b, NULL, &clip, xy, 32, &n) == RAST_E_NULL);
    clip.x1 = RAST_MAX_DIM + 1;
    CHECK(rast_line_pixels(a, b, &o, &clip, xy, 32, &n) == RAST_E_SIZE);
    clip.x1 = 16;
    CHECK(rast_line_pixels(a, b, &o, &clip, xy, 32, &n) == RAST_OK && n == 14);
    clip.x1 = 0; /* empty */
    CHECK(rast_line_pixels(a, b, &o, &clip, NULL, 0, &n) == RAST_OK && n == 0);

    /* predicates */
    CHECK(rast_point_in_triangle(a, NULL, RAST_PRED_OWNER, &in) == RAST_E_NULL);
    CHECK(rast_point_in_triangle(a, pts, RAST_PRED_OWNER, NULL) == RAST_E_NULL);
    CHECK(rast_point_in_triangle(a, pts, RAST_PRED_COUNT_, &in) == RAST_E_ARG && in == 7);
    far.x = -RAST_COORD_MAX - 1; far.y = 0;
    CHECK(rast_point_in_triangle(far, pts, RAST_PRED_AREA, &in) == RAST_E_RANGE && in == 7);

    /* finally a good call writes */
    CHECK(rast_draw_line(&t, a, b, &o, &one) == RAST_OK);
    CHECK(memcmp(img, before, sizeof img) != 0);
}

/* ---- predicates on a triangle's boundary ---------------------------------------
 * t = (0,0), (6,0), (0,6).  Closed tests: every point of the three edges is
 * in.  OWNER: the left edge x = 0 and the top edge y = 0 are in (except the
 * top edge's right end (6,0): right of the hypotenuse's crossing), the
 * hypotenuse and the bottom vertex (0,6) out. */
static void test_predicates(void)
{
    const rast_point t[3] = {{0, 0}, {6, 0}, {0, 6}};
    const rast_point deg[3] = {{0, 0}, {3, 3}, {6, 6}};
    struct {
        rast_point p;
        int closed, owner;
    } v[] = {
        {{2, 2}, 1, 1}, {{0, 0}, 1, 1}, {{3, 0}, 1, 1}, {{0, 3}, 1, 1},
        {{6, 0}, 1, 0}, {{0, 6}, 1, 0}, {{3, 3}, 1, 0}, {{5, 1}, 1, 0},
        {{4, 1}, 1, 1}, {{-1, 2}, 0, 0}, {{4, 3}, 0, 0}, {{2, -1}, 0, 0},
        {{7, 0}, 0, 0}, {{0, 7}, 0, 0},
    };
    size_t i;
    int m, in;
    for (i = 0; i < sizeof v / sizeof v[0]; i++) {
        for (m = 0; m < RAST_PRED_COUNT_; m++) {
            rast_point r[3] = {t[2], t[1], t[0]}; /* the other winding */
            int want = m == RAST_PRED_OWNER ? v[i].owner : v[i].closed;
            CHECK(rast_point_in_triangle(v[i].p, t, (rast_predicate)m, &in) == RAST_OK && in == want);
            CHECK(rast_point_in_triangle(v[i].p, r, (rast_predicate)m, &in) == RAST_OK && in == want);
        }
    }
    /* degenerate: nothing inside, not even on the segment */
    for (m = 0; m < RAST_PRED_COUNT_; m++) {
        rast_point on = {2, 2}, off = {2, 3};
        CHECK(rast_point_in_triangle(on, deg, (rast_predicate)m, &in) == RAST_OK && in == 0);
        CHECK(rast_point_in_triangle(off, deg, (rast_predicate)m, &in) == RAST_OK && in == 0);
    }
    /* the range limit: the largest triangle, a point just inside each edge */
    {
        const int32_t M = RAST_COORD_MAX;
        const rast_point big[3] = {{-M, -M}, {M, -M}, {-M, M}};
        rast_point p1 = {-M, -M}, p2 = {0, -1}, p3 = {0, 1}, p4 = {M, M};
        for (m = 0; m < RAST_PRED_COUNT_; m++) {
            CHECK(rast_point_in_triangle(p2, big, (rast_predicate)m, &in) == RAST_OK && in == 1);
            CHECK(rast_point_in_triangle(p3, big, (rast_predicate)m, &in) == RAST_OK && in == 0);
            CHECK(rast_point_in_triangle(p4, big, (rast_predicate)m, &in) == RAST_OK && in == 0);
            CHECK(rast_point_in_triangle(p1, big, (rast_predicate)m, &in) == RAST_OK && in == 1);
        }
    }
}

/* ---- the walk equals the formula (linerun.c), pixel for pixel ---------------
 * rast__line_rows / rast__line_run give the same line row by row by exact
 * division; Bresenham's incremental walk must list exactly those pixels.
 * Small lines are compared whole; lines up to the range limit through a
 * window around a point of theirs. */
static void test_linerun(void)
{
    enum { WMAX = 64 };
    static int32_t xy[2 * 4 * WMAX * WMAX];
    int iter, bad = 0, rows_seen = 0;
    for (iter = 0; iter < 20000; iter++) {
        int s = (int)(rng() % (RAST_MAX_SUBPIXEL_BITS + 1)), center = (int)(rng() & 1);
        int huge = rng() % 4 == 0;
        int32_t span = huge ? RAST_COORD_MAX : (int32_t)(30 << (s > 8 ? 8 : s));
        rast__grid g;
        rast_point a, b;
        rast_rect win;
        int64_t r0, r1, j;
        long n, k;
        a.x = (int32_t)(rng() % (2u * (uint32_t)span + 1u)) - span;
        a.y = (int32_t)(rng() % (2u * (uint32_t)span + 1u)) - span;
        b.x = (int32_t)(rng() % (2u * (uint32_t)span + 1u)) - span;
        b.y = (int32_t)(rng() % (2u * (uint32_t)span + 1u)) - span;
        if (rng() % 5 == 0) b.y = a.y + (b.x - a.x) / 2 / ((rng() & 1) ? 1 : -1); /* ties */
        if (b.y > RAST_COORD_MAX || b.y < -RAST_COORD_MAX) b.y = a.y;
        if (rng() % 10 == 0) b = a;
        if (rast__grid_init(&g, s, center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER, RAST_ROUND_EXACT,
                            RAST_BOUNDARY_EXACT) != RAST_OK) {
            bad++;
            continue;
        }
        if (huge) { /* a window around the point halfway */
            int32_t cx = (int32_t)(((int64_t)a.x + b.x) / 2 >> s), cy = (int32_t)(((int64_t)a.y + b.y) / 2 >> s);
            win.x0 = cx - (int32_t)(rng() % WMAX);
            win.y0 = cy - (int32_t)(rng() % WMAX);
        } else {
            win.x0 = -40;
            win.y0 = -40;
        }
        win.x1 = win.x0 + WMAX + 16;
        win.y1 = win.y0 + WMAX + 16;
        n = pixels(a, b, s, center, 0, &win, xy, sizeof xy / sizeof xy[0] / 2);
        if (n < 0) {
            bad++;
            continue;
        }
        rast__line_rows(a, b, &g, &r0, &r1);
        for (j = win.y0; j < win.y1; j++) {
            int64_t x0 = 0, x1 = 0, lo = INT64_MAX, hi = INT64_MIN, cnt = 0;
            if (j >= r0 && j < r1) {
                rast__line_run(a, b, &g, j, &x0, &x1);
                if (x0 >= x1) bad++; /* never empty inside [r0, r1) */
                if (x0 < win.x0) x0 = win.x0;
                if (x1 > win.x1) x1 = win.x1;
                if (x1 < x0) x1 = x0;
            }
            for (k = 0; k < n; k++) {
                if (xy[2 * k + 1] != j) continue;
                cnt++;
                if (xy[2 * k] < lo) lo = xy[2 * k];
                if (xy[2 * k] > hi) hi = xy[2 * k];
            }
            if (cnt != x1 - x0 || (cnt && (lo != x0 || hi != x1 - 1))) bad++;
            rows_seen += cnt > 0;
        }
    }
    CHECK(bad == 0);
    CHECK(rows_seen > 10000);
}

int main(void)
{
    test_seed_002_by_hand();
    test_seed_002_random();
    test_octants();
    test_random();
    test_huge();
    test_polyline();
    test_rgb_clip();
    test_dda();
    test_errors();
    test_predicates();
    test_linerun();
    return check_report("test_lines");
}

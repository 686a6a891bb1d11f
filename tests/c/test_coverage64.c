/*
 * test_coverage64.c - rast_polygon_coverage64 (exact-area coverage on
 * 64-bit vertices, S up to 32, +-2^28 pixels).
 *
 * Oracle: overlapping axis-aligned rectangles, each turned either way, at
 * S = 32 (and lower) near +-2^28 pixels.  Each cell's exact area under the
 * rule is computed here by brute force in integers: the cell is cut at
 * every rectangle side that crosses it, each sub-box gets the winding
 * number of the rectangles holding it, and the boxes inside under the rule
 * add up their areas (units 2^-2S pixel^2, 128 bits).  The C value must be
 * within the bound of rastrum.h, (n + m + 1) 2^-50, and, rectangles having
 * no slanted edges, it is in fact exact to the 2^-62 rounding, which is
 * checked too.  Plus hand-computed slanted cases (a triangle, a bow tie, a
 * ring twice, a hole), the errors with nothing written, and the scratch.
 */
#include <stdio.h>
#include <string.h>

#include "rastrum.h"
#include "check.h"

/* The oracle's sums: 128-bit unsigned numbers as two halves, so that the
 * test runs where the compiler has no __int128 (32-bit ARM and MIPS in
 * make cross-check). */
typedef struct u128 { uint64_t hi, lo; } u128;

static u128 u128_add(u128 a, u128 b)
{
    u128 r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo);
    return r;
}

/* a b exactly, from four 32 x 32-bit products */
static u128 u128_mul(uint64_t a, uint64_t b)
{
    const uint64_t m = 0xffffffffu;
    uint64_t p00 = (a & m) * (b & m), p01 = (a & m) * (b >> 32);
    uint64_t p10 = (a >> 32) * (b & m), p11 = (a >> 32) * (b >> 32);
    uint64_t mid = (p00 >> 32) + (p01 & m) + (p10 & m);
    u128 r;
    r.lo = (mid << 32) | (p00 & m);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

/* floor((a + 2^(sh - 1)) / 2^sh), its low 64 bits, 1 <= sh <= 63 */
static uint64_t u128_round_shr(u128 a, int sh)
{
    u128 half;
    half.hi = 0;
    half.lo = (uint64_t)1 << (sh - 1);
    a = u128_add(a, half);
    return (a.lo >> sh) | (a.hi << (64 - sh));
}

#define W 6
#define H 5
#define NR 4

static uint64_t out[H][W];
static uint64_t scratch_mem[1 << 14];

typedef struct {
    int64_t x0, y0, x1, y1; /* vertex units, x0 < x1, y0 < y1 */
    int dir;                /* +1 or -1: the ring's turn */
} rect;

static rast_status run(const rast_point64 *pts, const uint32_t *sizes, uint32_t nrings, int s,
                       rast_fill_rule rule, rast_rect clip, rast_coverage_format f, void *o,
                       ptrdiff_t stride)
{
    rast_polygon64 poly;
    rast_coverage_opts opts;
    size_t need;
    memset(&opts, 0, sizeof opts);
    opts.method = RAST_AA_AREA;
    opts.rule = rule;
    opts.subpixel_bits = s;
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    if (rast_coverage64_scratch_size(&opts, 64, clip.x1 - clip.x0, clip.y1 - clip.y0, &need) !=
        RAST_OK)
        return RAST_E_ARG;
    if (need > sizeof scratch_mem) return RAST_E_SCRATCH;
    return rast_polygon_coverage64(&poly, &opts, &clip, f, o, stride, scratch_mem, need);
}

static int inside(rast_fill_rule rule, int w)
{
    return rule == RAST_RULE_EVENODD ? (w & 1) != 0 : w != 0;
}

/* The exact area of cell (cx, cy) (pixels) under `rule`, in 2^-2s units. */
static u128 cell_area(const rect *r, int n, int64_t cx, int64_t cy, int s,
                                   rast_fill_rule rule)
{
    const int64_t u = (int64_t)1 << s;
    int64_t xs[2 * NR + 2], ys[2 * NR + 2];
    int nx = 0, ny = 0, i, j, k;
    u128 sum = {0, 0};
    int64_t X0 = cx * u, X1 = X0 + u, Y0 = cy * u, Y1 = Y0 + u;
    xs[nx++] = X0;
    xs[nx++] = X1;
    ys[ny++] = Y0;
    ys[ny++] = Y1;
    for (k = 0; k < n; k++) {
        if (r[k].x0 > X0 && r[k].x0 < X1) xs[nx++] = r[k].x0;
        if (r[k].x1 > X0 && r[k].x1 < X1) xs[nx++] = r[k].x1;
        if (r[k].y0 > Y0 && r[k].y0 < Y1) ys[ny++] = r[k].y0;
        if (r[k].y1 > Y0 && r[k].y1 < Y1) ys[ny++] = r[k].y1;
    }
    /* sort (insertion) */
    for (i = 1; i < nx; i++)
        for (j = i; j > 0 && xs[j - 1] > xs[j]; j--) {
            int64_t t = xs[j];
            xs[j] = xs[j - 1];
            xs[j - 1] = t;
        }
    for (i = 1; i < ny; i++)
        for (j = i; j > 0 && ys[j - 1] > ys[j]; j--) {
            int64_t t = ys[j];
            ys[j] = ys[j - 1];
            ys[j - 1] = t;
        }
    for (i = 0; i + 1 < nx; i++)
        for (j = 0; j + 1 < ny; j++) {
            int w = 0;
            if (xs[i] == xs[i + 1] || ys[j] == ys[j + 1]) continue;
            for (k = 0; k < n; k++) /* the sub-box lies wholly in or out of each */
                if (r[k].x0 <= xs[i] && xs[i + 1] <= r[k].x1 && r[k].y0 <= ys[j] &&
                    ys[j + 1] <= r[k].y1)
                    w += r[k].dir;
            if (inside(rule, w))
                sum = u128_add(sum, u128_mul((uint64_t)(xs[i + 1] - xs[i]),
                                             (uint64_t)(ys[j + 1] - ys[j])));
        }
    return sum;
}

static void test_rectangles(int s, int64_t ox, int64_t oy, int cases)
{
    const int64_t u = (int64_t)1 << s;
    int c;
    for (c = 0; c < cases; c++) {
        rect r[NR];
        rast_point64 pts[4 * NR];
        uint32_t sizes[NR];
        int n = 1 + (int)(rng() % NR), k, i, j;
        rast_fill_rule rule = (rng() & 1) ? RAST_RULE_NONZERO : RAST_RULE_EVENODD;
        rast_rect clip;
        for (k = 0; k < n; k++) {
            int64_t a, b;
            /* sides on pixel corners, at 2^-s, or anywhere; -1 .. W + 1 px */
            a = (ox - 1) * u + (int64_t)(rng() % (uint32_t)((W + 2) * 4)) * (u / 4 ? u / 4 : 1);
            b = (ox - 1) * u + (int64_t)(rng() % (uint32_t)((W + 2) * 4)) * (u / 4 ? u / 4 : 1);
            if (rng() & 1) a += (int64_t)(rng() % 5) - 2;
            if (a == b) b += 1;
            r[k].x0 = a < b ? a : b;
            r[k].x1 = a < b ? b : a;
            a = (oy - 1) * u + (int64_t)(rng() % (uint32_t)((H + 2) * 4)) * (u / 4 ? u / 4 : 1);
            b = (oy - 1) * u + (int64_t)(rng() % (uint32_t)((H + 2) * 4)) * (u / 4 ? u / 4 : 1);
            if (rng() & 1) b += (int64_t)(rng() % 5) - 2;
            if (a == b) b += 1;
            r[k].y0 = a < b ? a : b;
            r[k].y1 = a < b ? b : a;
            r[k].dir = (rng() & 1) ? 1 : -1;
            sizes[k] = 4;
            /* y down: (x0,y0) (x1,y0) (x1,y1) (x0,y1) goes clockwise on
             * screen; the edge x1 goes down (+1), so w = +1 inside */
            if (r[k].dir > 0) {
                pts[4 * k + 0].x = r[k].x0, pts[4 * k + 0].y = r[k].y0;
                pts[4 * k + 1].x = r[k].x1, pts[4 * k + 1].y = r[k].y0;
                pts[4 * k + 2].x = r[k].x1, pts[4 * k + 2].y = r[k].y1;
                pts[4 * k + 3].x = r[k].x0, pts[4 * k + 3].y = r[k].y1;
            } else {
                pts[4 * k + 0].x = r[k].x0, pts[4 * k + 0].y = r[k].y0;
                pts[4 * k + 1].x = r[k].x0, pts[4 * k + 1].y = r[k].y1;
                pts[4 * k + 2].x = r[k].x1, pts[4 * k + 2].y = r[k].y1;
                pts[4 * k + 3].x = r[k].x1, pts[4 * k + 3].y = r[k].y0;
            }
        }
        clip.x0 = (int32_t)ox;
        clip.y0 = (int32_t)oy;
        clip.x1 = (int32_t)ox + W;
        clip.y1 = (int32_t)oy + H;
        CHECK(run(pts, sizes, (uint32_t)n, s, rule, clip, RAST_COVERAGE_FIX62, out, sizeof out[0]) ==
              RAST_OK);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                /* exact: area / 2^2s pixels; FIX62 = area 2^(62 - 2s), rounded */
                u128 a = cell_area(r, n, ox + i, oy + j, s, rule);
                uint64_t got = out[j][i], want;
                if (2 * s <= 62)
                    want = a.lo << (62 - 2 * s); /* a <= 2^2s: the product fits */
                else
                    want = u128_round_shr(a, 2 * s - 62);
                CHECK(got + 1 >= want && got <= want + 1);
            }
    }
}

static void test_known(void)
{
    const int64_t o = ((int64_t)1 << 28) - 4, u = (int64_t)1 << 32;
    rast_rect c1 = {0, 0, 0, 0};
    uint64_t v[1][3];
    rast_point64 tri[3], bow[4], sq[8], outer[8];
    uint32_t n3 = 3, n4 = 4, two[2] = {4, 4};
    int32_t b = (int32_t)o;
    c1.x0 = b;
    c1.y0 = b;
    c1.x1 = b + 1;
    c1.y1 = b + 1;
    tri[0].x = o * u, tri[0].y = o * u;
    tri[1].x = (o + 1) * u, tri[1].y = o * u;
    tri[2].x = o * u, tri[2].y = (o + 1) * u;
    CHECK(run(tri, &n3, 1, 32, RAST_RULE_EVENODD, c1, RAST_COVERAGE_FIX62, v, 8) == RAST_OK);
    CHECK(v[0][0] == (uint64_t)1 << 61);
    bow[0].x = o * u, bow[0].y = o * u;
    bow[1].x = (o + 1) * u, bow[1].y = (o + 1) * u;
    bow[2].x = (o + 1) * u, bow[2].y = o * u;
    bow[3].x = o * u, bow[3].y = (o + 1) * u;
    CHECK(run(bow, &n4, 1, 32, RAST_RULE_NONZERO, c1, RAST_COVERAGE_FIX62, v, 8) == RAST_OK);
    CHECK(v[0][0] == (uint64_t)1 << 61);
    CHECK(run(bow, &n4, 1, 32, RAST_RULE_EVENODD, c1, RAST_COVERAGE_U8, v, 1) == RAST_OK);
    CHECK(((uint8_t *)v)[0] == 128);
    /* a ring twice, from x = o + 1/4 to o + 2: non-zero 3/4 and 1, even-odd 0 */
    {
        rast_rect c2 = c1;
        c2.x1 = b + 2;
        sq[0].x = o * u + u / 4, sq[0].y = o * u;
        sq[1].x = (o + 2) * u, sq[1].y = o * u;
        sq[2].x = (o + 2) * u, sq[2].y = (o + 1) * u;
        sq[3].x = o * u + u / 4, sq[3].y = (o + 1) * u;
        memcpy(sq + 4, sq, 4 * sizeof sq[0]);
        CHECK(run(sq, two, 2, 32, RAST_RULE_NONZERO, c2, RAST_COVERAGE_FIX62, v, 24) == RAST_OK);
        CHECK(v[0][0] == (uint64_t)3 << 60 && v[0][1] == (uint64_t)1 << 62);
        CHECK(run(sq, two, 2, 32, RAST_RULE_EVENODD, c2, RAST_COVERAGE_FIX62, v, 24) == RAST_OK);
        CHECK(v[0][0] == 0 && v[0][1] == 0);
    }
    /* 3 x 3 with a hole turned the other way (non-zero) */
    {
        rast_rect c3;
        uint8_t m[3][3];
        int i, j;
        c3.x0 = b, c3.y0 = b, c3.x1 = b + 3, c3.y1 = b + 3;
        outer[0].x = o * u, outer[0].y = o * u;
        outer[1].x = (o + 3) * u, outer[1].y = o * u;
        outer[2].x = (o + 3) * u, outer[2].y = (o + 3) * u;
        outer[3].x = o * u, outer[3].y = (o + 3) * u;
        outer[4].x = (o + 1) * u, outer[4].y = (o + 1) * u;
        outer[5].x = (o + 1) * u, outer[5].y = (o + 2) * u;
        outer[6].x = (o + 2) * u, outer[6].y = (o + 2) * u;
        outer[7].x = (o + 2) * u, outer[7].y = (o + 1) * u;
        CHECK(run(outer, two, 2, 32, RAST_RULE_NONZERO, c3, RAST_COVERAGE_U8, m, 3) == RAST_OK);
        for (j = 0; j < 3; j++)
            for (i = 0; i < 3; i++) CHECK(m[j][i] == ((i == 1 && j == 1) ? 0 : 255));
    }
}

static void test_errors(void)
{
    rast_point64 p[3];
    uint32_t n = 3;
    rast_polygon64 poly;
    rast_coverage_opts o;
    rast_rect c = {0, 0, 2, 2};
    uint8_t img[2][2];
    size_t need;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 32;
    p[0].x = 0, p[0].y = 0;
    p[1].x = (int64_t)1 << 33, p[1].y = 0;
    p[2].x = 0, p[2].y = (int64_t)1 << 33;
    poly.points = p;
    poly.ring_sizes = &n;
    poly.nrings = 1;
    CHECK(rast_coverage64_scratch_size(&o, 3, 2, 2, &need) == RAST_OK);
    CHECK(need <= sizeof scratch_mem);
    memset(img, 7, sizeof img);
    o.method = RAST_AA_SS4;
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need) ==
          RAST_E_WIDE);
    o.method = RAST_AA_AREA;
    o.subpixel_bits = 33;
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need) ==
          RAST_E_SUBPIXEL);
    o.subpixel_bits = 32;
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need - 1) ==
          RAST_E_SCRATCH);
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 1, scratch_mem, need) ==
          RAST_E_ARG);
    CHECK(rast_polygon_coverage64(&poly, &o, &c, (rast_coverage_format)3, img, 2, scratch_mem,
                                  need) == RAST_E_ARG);
    CHECK(rast_polygon_coverage64(NULL, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need) ==
          RAST_E_NULL);
    p[1].x = RAST_COORD64_MAX(32) + 1;
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need) ==
          RAST_E_RANGE);
    CHECK(img[0][0] == 7 && img[0][1] == 7 && img[1][0] == 7 && img[1][1] == 7);
    p[1].x = (int64_t)1 << 33;
    CHECK(rast_polygon_coverage64(&poly, &o, &c, RAST_COVERAGE_U8, img, 2, scratch_mem, need) ==
          RAST_OK);
    CHECK(img[0][0] == 255 && img[0][1] == 128 && img[1][0] == 128 && img[1][1] == 0);
}

int main(void)
{
    int n = check_count(300);
    test_known();
    test_errors();
    test_rectangles(32, ((int64_t)1 << 28) - W - 2, ((int64_t)1 << 28) - H - 2, n);
    test_rectangles(32, -((int64_t)1 << 28) + 2, 5, n);
    test_rectangles(24, 123456, -654321, n);
    test_rectangles(17, 0, 0, n);
    test_rectangles(2, 0, 0, n);
    test_rectangles(0, 0, 0, n);
    return check_report("test_coverage64");
}

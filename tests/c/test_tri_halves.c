/*
 * test_tri_halves.c - the "edge" triangle filler's rows on a gray8 target
 * whose clip holds every column the triangle can reach (the uncut way:
 * rast__rows_direct_uncut), against the brute-force reference of ref.h,
 * one sample at a time.  There the filler walks the triangle in two
 * halves, above and from its middle vertex's row down, two bounds each,
 * in batches of rows (tri_edge.c, rast__fe_half).  The triangles here:
 * tall ones (halves of hundreds of rows: several batches), middle
 * vertices on sample rows and just off them, flat tops and bottoms,
 * slivers, every order of the vertices, both orientations, both samples
 * and roundings, S from 0 to 16.  Pixels outside the triangle's box must
 * stay untouched.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 1818u
#include "check.h"
#include "ref.h"

#define W 160
#define H 400

static unsigned char img[H * W];
static uint64_t scratch[64];

static int ref_in(const rast_point *t, int s, int center, int textbook, int64_t i, int64_t j)
{
    static const uint32_t three = 3;
    return ref_winding(t, &three, 1, s, center, textbook, i, j, NULL) != 0;
}

/* The fixed-point coordinate of sample row (or column) v, moved by d. */
static int32_t at_sample(int32_t v, int s, int center, int32_t d)
{
    return (v << s) + (center ? (1 << s) / 2 : 0) + d;
}

/* A random vertex in [margin, size - margin) pixels. */
static int32_t coord(int32_t size, int s)
{
    const int32_t margin = 3;
    return (int32_t)((margin << s) + (int32_t)(rng() % (uint32_t)((size - 2 * margin) << s)));
}

/* Fill triangle t (its vertices in any order) and compare every pixel of
 * the target with the reference: 0 outside, 255 inside. */
static int tri_equals_ref(const rast_point *t, int s, int center, int textbook)
{
    rast_tri_opts o;
    rast_target tg;
    const unsigned char one = 255;
    int i, j, k, ok = 1;
    int32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    memset(&o, 0, sizeof o);
    o.algorithm = RAST_TRI_EDGE;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    o.rounding = textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
    memset(img, 0, sizeof img);
    if (rast_target_init(&tg, img, W, H, W, RAST_FORMAT_GRAY8) != RAST_OK) return 0;
    if (rast_fill_triangles(&tg, t, 1, &o, &one, scratch, sizeof scratch) != RAST_OK) return 0;
    /* the reference within the box (pixels) of the vertices, one more
     * each way; 0 outside it */
    for (k = 0; k < 3; k++) {
        x0 = k == 0 || t[k].x < x0 ? t[k].x : x0;
        x1 = k == 0 || t[k].x > x1 ? t[k].x : x1;
        y0 = k == 0 || t[k].y < y0 ? t[k].y : y0;
        y1 = k == 0 || t[k].y > y1 ? t[k].y : y1;
    }
    x0 = (x0 >> s) - 1;
    x1 = (x1 >> s) + 1;
    y0 = (y0 >> s) - 1;
    y1 = (y1 >> s) + 1;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            int want = 0;
            if (i >= x0 && i <= x1 && j >= y0 && j <= y1 && ref_in(t, s, center, textbook, i, j)) want = 255;
            ok &= img[j * W + i] == want;
        }
    return ok;
}

/* The triangle in all six orders of its vertices (both orientations). */
static int all_orders(const rast_point *t, int s, int center, int textbook)
{
    static const int ord[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    int k, ok = 1;
    for (k = 0; k < 6; k++) {
        rast_point u[3];
        u[0] = t[ord[k][0]];
        u[1] = t[ord[k][1]];
        u[2] = t[ord[k][2]];
        ok &= tri_equals_ref(u, s, center, textbook);
    }
    return ok;
}

static void test_halves(void)
{
    static const int ss[6] = {0, 1, 3, 4, 8, 16};
    int iter, bad = 0, n = check_count(600);
    for (iter = 0; iter < n; iter++) {
        int s = ss[iter % 6], center = (int)(rng() & 1), textbook = (int)(rng() & 1);
        int kind = (int)(rng() % 6), k;
        int32_t w = s == 16 ? 40 : W, h = s == 16 ? 40 : H; /* S = 16: coordinates below 2^22 */
        rast_point t[3];
        for (k = 0; k < 3; k++) {
            t[k].x = coord(w, s);
            t[k].y = coord(h, s);
        }
        if (kind == 0) { /* tall: top near the first row, bottom near the last */
            t[0].y = coord(8, s);
            t[2].y = ((h - 8) << s) + coord(8, s) - (3 << s);
        } else if (kind == 1) { /* the middle vertex on a sample row, or one unit off it */
            int32_t lo = t[0].y < t[1].y ? t[0].y : t[1].y, hi = t[0].y ^ t[1].y ^ lo;
            int32_t row = ((lo + hi) / 2) >> s;
            t[2].y = at_sample(row, s, center, (int32_t)(rng() % 3) - 1);
            if (rng() & 1) t[2].x = at_sample(t[2].x >> s, s, center, 0);
        } else if (kind == 2) { /* a flat top or bottom */
            t[1].y = t[0].y;
        } else if (kind == 3) { /* flat, on a sample row */
            t[0].y = t[1].y = at_sample(t[0].y >> s, s, center, 0);
        } else if (kind == 4) { /* a sliver: the middle vertex within a unit of the long edge */
            t[2].x = (t[0].x + t[1].x) / 2 + (int32_t)(rng() % 3) - 1;
            t[2].y = (t[0].y + t[1].y) / 2 + (int32_t)(rng() % 3) - 1;
        } /* kind 5: as drawn */
        bad += !all_orders(t, s, center, textbook);
    }
    CHECK(bad == 0);
}

int main(void)
{
    test_halves();
    return check_report("test_tri_halves");
}

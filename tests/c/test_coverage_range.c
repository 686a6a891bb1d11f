/* test_coverage_range.c - every vertex's range checked by the coverage
 * calls, wherever it lies in the polygon or the triangle batch
 * (entry/coverage.c, rast__cov_check_points: speed builds test four
 * points a step with SSE2, the last 0-3 one by one).  The documented
 * range (rastrum.h, "anti-aliased coverage"): |v| <= RAST_COORD_MAX, and
 * for "ssK" |v| 2^max(0, log2 K - S) <= RAST_COORD_MAX too.  Polygons of
 * n points (n = 3 .. 13, one ring or three) and batches of n / 3
 * triangles, with one coordinate just past the bound (or past minus it)
 * at each place in turn, x or y: RAST_E_RANGE and no value written
 * (docs/bad-input.md: every error is found before a pixel is written);
 * on the bound itself the call goes ahead (RAST_OK: the range is
 * inclusive). */
#include <string.h>

#include "check.h"
#include "rastrum.h"
#include "range_rings.h"

#define W 16
#define H 12

static unsigned char out[H][W];
static unsigned char scratch[1 << 18] __attribute__((aligned(64)));

/* The bound of |v| for method m at S = s, from the documented rule:
 * the greatest v with v 2^max(0, log2 K - S) <= RAST_COORD_MAX. */
static int32_t bound(rast_aa_method m, int32_t s)
{
    int32_t kb = (m >= RAST_AA_SS2 && m <= RAST_AA_SS16) ? (int32_t)(m - RAST_AA_SS2) + 1 : 0;
    int32_t sh = kb > s ? kb - s : 0;
    return (int32_t)(RAST_COORD_MAX / ((int64_t)1 << sh));
}

/* tris: a batch of n / 3 triangles, else a polygon (rings 1 or 3) */
static rast_status cover(const rast_point *p, uint32_t n, int rings, int tris, rast_aa_method m, int32_t s)
{
    uint32_t sizes[3];
    rast_polygon poly;
    rast_coverage_opts o;
    rast_rect clip = {0, 0, W, H};
    size_t need = 0;
    o.method = m;
    o.rule = RAST_RULE_NONZERO;
    o.subpixel_bits = s;
    o.sample = RAST_SAMPLE_CENTER;
    CHECK(rast_coverage_scratch_size(&o, n, W, H, &need) == RAST_OK && need <= sizeof scratch);
    if (tris)
        return rast_triangles_coverage(p, n / 3, &o, &clip, RAST_COVERAGE_U8, out, W, scratch, sizeof scratch);
    range_polygon(&poly, p, n, rings, sizes);
    return rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, out, W, scratch, sizeof scratch);
}

static int untouched(void)
{
    uint32_t i;
    for (i = 0; i < sizeof out; i++)
        if (((unsigned char *)out)[i] != 99) return 0;
    return 1;
}

static void test_each_place(void)
{
    static const struct {
        rast_aa_method m;
        int32_t s;
    } runs[] = {{RAST_AA_ACCUMULATE, 4}, {RAST_AA_AREA, 8}, {RAST_AA_SS4, 1}, {RAST_AA_SS16, 0}, {RAST_AA_SS16, 4}};
    rast_point p[13];
    uint32_t n, k, u;
    int c, sg, rings, tris;
    for (u = 0; u < sizeof runs / sizeof runs[0]; u++) {
        const rast_aa_method m = runs[u].m;
        const int32_t s = runs[u].s, lim = bound(m, s);
        for (tris = 0; tris < 2; tris++)
            for (n = 3; n <= 13; n++) {
                if (tris && n % 3) continue;
                for (k = 0; k < n; k++)
                    for (c = 0; c < 2; c++)         /* x or y */
                        for (sg = 0; sg < 2; sg++)  /* past the top or the bottom of the range */
                            for (rings = 1; rings <= (tris ? 1 : 3); rings += 2) {
                                int32_t *v;
                                range_zigzag(p, n, s);
                                v = c ? &p[k].y : &p[k].x;
                                /* just past the bound: refused, nothing written */
                                *v = sg ? -lim - 1 : lim + 1;
                                memset(out, 99, sizeof out);
                                CHECK(cover(p, n, rings, tris, m, s) == RAST_E_RANGE);
                                CHECK(untouched());
                                /* on it: done */
                                *v = sg ? -lim : lim;
                                CHECK(cover(p, n, rings, tris, m, s) == RAST_OK);
                                /* and the far side of the other coordinate */
                                v = c ? &p[k].x : &p[k].y;
                                *v = sg ? lim + 1 : -lim - 1;
                                memset(out, 99, sizeof out);
                                CHECK(cover(p, n, rings, tris, m, s) == RAST_E_RANGE);
                                CHECK(untouched());
                            }
            }
    }
}

int main(void)
{
    test_each_place();
    return check_report("test_coverage_range");
}

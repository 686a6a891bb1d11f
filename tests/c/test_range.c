/* test_range.c - every vertex's range checked, wherever it lies in the
 * polygon (entry/fill.c, rast__check_polygon: speed builds test four
 * points a step with SSE2, the last 0-3 one by one).  A polygon of n
 * points (n = 3 .. 13, one ring or three) with one coordinate just past
 * RAST_COORD_MAX (or -RAST_COORD_MAX) at each place in turn, x or y:
 * rast_fill_polygon and rast_fill_polygon_opaque return RAST_E_RANGE
 * and write no pixel (docs/bad-input.md: every error is found before a
 * pixel is written); at exactly +-RAST_COORD_MAX the fill goes ahead,
 * and the pixels are those of the same polygon with that point moved
 * there by hand (the range is inclusive). */
#include <string.h>

#include "check.h"
#include "rastrum.h"
#include "range_rings.h"

#define W 16
#define H 12

static unsigned char px[H][W], ref[H][W];
static unsigned char scratch[1 << 16] __attribute__((aligned(64)));

static rast_status fill(const rast_point *p, uint32_t n, int rings, int opaque)
{
    const unsigned char one = 200, zero = 7;
    uint32_t sizes[3];
    rast_polygon poly;
    rast_target t;
    rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_NONZERO, 4, RAST_SAMPLE_CENTER, 0, 0};
    rast_target_init(&t, px, W, H, W, RAST_FORMAT_GRAY8);
    range_polygon(&poly, p, n, rings, sizes);
    return opaque ? rast_fill_polygon_opaque(&t, &poly, &o, &one, &zero, scratch, sizeof scratch)
                  : rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch);
}

static void test_each_place(void)
{
    rast_point p[13], q[13];
    uint32_t n, k;
    int c, s, rings, opaque;
    for (n = 3; n <= 13; n++)
        for (k = 0; k < n; k++)
            for (c = 0; c < 2; c++)         /* x or y */
                for (s = 0; s < 2; s++)     /* past the top or the bottom of the range */
                    for (rings = 1; rings <= 3; rings += 2)
                        for (opaque = 0; opaque < 2; opaque++) {
                            int32_t *v;
                            const int32_t edge = s ? -RAST_COORD_MAX : RAST_COORD_MAX;
                            range_zigzag(p, n, 4);
                            memcpy(q, p, sizeof p);
                            v = c ? &p[k].y : &p[k].x;
                            /* just past the range: refused, nothing written */
                            *v = s ? edge - 1 : edge + 1;
                            memset(px, 99, sizeof px);
                            CHECK(fill(p, n, rings, opaque) == RAST_E_RANGE);
                            CHECK(px[0][0] == 99 && !memcmp(px[0], px[H - 1], W) &&
                                  memchr(px, 200, sizeof px) == NULL && memchr(px, 7, sizeof px) == NULL);
                            /* on its end: filled, as the same polygon given so */
                            *v = edge;
                            memset(px, 99, sizeof px);
                            CHECK(fill(p, n, rings, opaque) == RAST_OK);
                            memcpy(ref, px, sizeof px);
                            if (c) q[k].y = edge;
                            else q[k].x = edge;
                            memset(px, 99, sizeof px);
                            CHECK(fill(q, n, rings, opaque) == RAST_OK);
                            CHECK(!memcmp(ref, px, sizeof px));
                            /* and the far side of the other coordinate too */
                            v = c ? &p[k].x : &p[k].y;
                            *v = s ? RAST_COORD_MAX + 1 : -RAST_COORD_MAX - 1;
                            CHECK(fill(p, n, rings, opaque) == RAST_E_RANGE);
                        }
}

int main(void)
{
    test_each_place();
    return check_report("test_range");
}

/* cbench_paint.c - what painting coverage costs over computing it: ten calls
 * on a 200-spike star (400 vertices, radii 100 and 250 px, S = 8, non-zero)
 * at 512x512, as
 *   0: rast_polygon_coverage into a uint8 array,
 *   1: rast_fill_polygon_aa into a GRAY8 target,
 *   2: rast_fill_polygon_aa into an RGB888 target,
 *   3: rast_fill_polygon_aa_blend into an RGB888 target, the colour at
 *      alpha 128 (the opacity path, docs/opacity.md),
 *   4: rast_fill_polygon (binary) into an RGB888 target,
 *   5: rast_fill_polygon_blend (binary) into an RGB888 target, alpha 128,
 * with method argv[2] (a rast_aa_method: 0 area, 2 ss4, 5 accumulate).
 * Meant for instruction counts (repeatable on a shared machine):
 *   cc -O2 -std=c11 -Icsrc/include bench/cbench_paint.c build/librastrum.a -lm -o cbench_paint
 *   valgrind --tool=callgrind ./cbench_paint WHICH METHOD */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrum.h"

#define N 400

static uint64_t scratch[1 << 16];
static unsigned char img[512 * 512 * 3];

int main(int argc, char **argv)
{
    static rast_point p[N];
    uint32_t n = N;
    int i, which = argc > 1 ? atoi(argv[1]) : 0, m = argc > 2 ? atoi(argv[2]) : 0;
    rast_polygon poly = {p, &n, 1};
    rast_coverage_opts o;
    rast_fill_opts fo;
    rast_rect clip = {0, 0, 512, 512};
    rast_target t;
    size_t need;
    unsigned char v[3] = {200, 100, 50};
    for (i = 0; i < N; i++) {
        double a = 6.283185307179586 * i / N, r = (i % 2) ? 250 : 100;
        p[i].x = (int32_t)((256 + r * cos(a - 1.5707963267948966)) * 256);
        p[i].y = (int32_t)((256 + r * cos(a)) * 256);
    }
    memset(&fo, 0, sizeof fo);
    fo.rule = RAST_RULE_NONZERO;
    fo.subpixel_bits = 8;
    memset(&o, 0, sizeof o);
    o.method = (rast_aa_method)m;
    o.rule = RAST_RULE_NONZERO;
    o.subpixel_bits = 8;
    o.sample = RAST_SAMPLE_CENTER;
    if (rast_coverage_scratch_size(&o, N, 512, 512, &need) != RAST_OK || need > sizeof scratch) {
        fprintf(stderr, "cbench_paint: bad method or scratch\n");
        return 1;
    }
    rast_target_init(&t, img, 512, 512, which == 1 ? 512 : 3 * 512,
                     which == 1 ? RAST_FORMAT_GRAY8 : RAST_FORMAT_RGB888);
    for (i = 0; i < 10; i++) {
        static const uint8_t half[4] = {200, 100, 50, 128};
        rast_status st = which == 0
                             ? rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, img, 512,
                                                     scratch, need)
                         : which == 4 ? rast_fill_polygon(&t, &poly, &fo, v, scratch, sizeof scratch)
#ifndef CBENCH_NO_BLEND /* (a library older than the blend calls) */
                         : which == 3 ? rast_fill_polygon_aa_blend(&t, &poly, &o, half, NULL, scratch, need)
                         : which == 5 ? rast_fill_polygon_blend(&t, &poly, &fo, half, NULL, scratch,
                                                                sizeof scratch)
#endif
                                      : rast_fill_polygon_aa(&t, &poly, &o, v, scratch, need);
        if (st != RAST_OK) return 1;
    }
    printf("pixel (10, 256): %d\n", img[512 * 256 + 10]);
    return 0;
}

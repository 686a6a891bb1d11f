/* cbench.c - the C core alone, no Python: median time of rast_fill_polygon on
 * random self-intersecting polygons and a 200-spike star (used to tune the
 * filler; `make cbench`). */
#define _POSIX_C_SOURCE 199309L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cbench_time.h"
#include "rastrum.h"

static uint64_t scratch[1 << 18];

static double run(rast_point *pts, uint32_t n, int w, int h, int reps)
{
    static double t[64];
    unsigned char *img = malloc((size_t)w * h), one = 1;
    rast_target tg;
    rast_polygon p = {pts, &n, 1};
    rast_fill_opts o;
    int r;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 8;
    memset(img, 0, (size_t)w * h);
    rast_target_init(&tg, img, w, h, w, RAST_FORMAT_GRAY8);
    for (r = 0; r < reps && r < 64; r++) {
        double t0 = now();
        int k;
        for (k = 0; k < 20; k++) rast_fill_polygon(&tg, &p, &o, &one, scratch, sizeof scratch);
        t[r] = (now() - t0) / 20;
    }
    qsort(t, (size_t)r, sizeof t[0], cmp);
    free(img);
    return t[r / 2];
}

int main(void)
{
    static rast_point pts[400];
    uint32_t i, k;
    double total = 0;
    srand(1);
    for (k = 0; k < 100; k++) {
        uint32_t n = 20 + (uint32_t)(rand() % 41);
        for (i = 0; i < n; i++) {
            pts[i].x = rand() % (640 * 256);
            pts[i].y = rand() % (480 * 256);
        }
        total += run(pts, n, 640, 480, 5);
    }
    printf("random 20-60 gons 640x480: %.1f us per polygon\n", total / 100 * 1e6);
    for (i = 0; i < 400; i++) {
        /* star: integer approximation of cos/sin is not needed: a zigzag
         * fan of 200 spikes around the centre, radii 300 and 1000 px */
        int32_t r = (i % 2) ? 300 : 1000;
        int32_t q = (int32_t)i % 100, side = (int32_t)i / 100;
        int32_t u = (q * 2000) / 100 - 1000;
        int32_t x = side == 0 ? u : side == 1 ? 1000 : side == 2 ? -u : -1000;
        int32_t y = side == 0 ? -1000 : side == 1 ? u : side == 2 ? 1000 : -u;
        pts[i].x = (1024 + x * r / 1000) * 256;
        pts[i].y = (1024 + y * r / 1000) * 256;
    }
    printf("400-vertex zigzag star 2048x2048: %.1f us\n", run(pts, 400, 2048, 2048, 15) * 1e6);
    return 0;
}

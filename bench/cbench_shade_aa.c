/* cbench_shade_aa.c - what Gouraud colour times coverage costs beside the
 * binary shaded fill and the one-colour anti-aliased fill, one call at
 * 512x512 into an RGBA8888 target, on
 *   scene 0: a 64-triangle fan (a 64-gon of radius 200 px),
 *   scene 1: a 32x32-cell grid mesh of 2048 triangles over 400x400 px,
 * vertices at S = 8 (jittered off the pixel grid), colours per vertex, as
 *   which 0: rast_fill_triangles_shaded (binary, exact),
 *   which 1: rast_fill_triangles_aa (one colour),
 *   which 2: rast_fill_triangles_shaded_aa (exact),
 * with coverage method argv[3] (a rast_aa_method: 0 area, 2 ss4), and
 * for 1 and 2 the scratch they ask for (argv[4] 0: for 2, a band of 16
 * rows) or 2 MiB (argv[4] 1: for 2, bands as tall as that holds).
 * Meant for instruction counts (repeatable on a shared machine):
 *   cc -O2 -std=c11 -Icsrc/include bench/cbench_shade_aa.c build/librastrum.a -lm -o cbench_shade_aa
 *   valgrind --tool=callgrind ./cbench_shade_aa SCENE WHICH METHOD */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrum.h"

#define MAXT 2048

static uint64_t scratch[1 << 18];
static unsigned char img[512 * 512 * 4];
static rast_point tris[3 * MAXT];
static uint8_t colors[12 * MAXT];

static rast_point pt(double x, double y)
{
    rast_point p;
    p.x = (int32_t)(x * 256);
    p.y = (int32_t)(y * 256);
    return p;
}

static void colour(uint32_t k, double x, double y)
{
    colors[4 * k] = (uint8_t)((int)x & 255);
    colors[4 * k + 1] = (uint8_t)((int)y & 255);
    colors[4 * k + 2] = (uint8_t)((int)(x + y) & 255);
    colors[4 * k + 3] = 255;
}

static uint32_t scene(int which)
{
    uint32_t n = 0, i, j, k;
    if (which == 0) {
        for (i = 0; i < 64; i++) {
            double a0 = 6.283185307179586 * i / 64, a1 = 6.283185307179586 * (i + 1) / 64;
            double v[3][2] = {{256.3, 256.7},
                              {256.3 + 200 * cos(a0), 256.7 + 200 * sin(a0)},
                              {256.3 + 200 * cos(a1), 256.7 + 200 * sin(a1)}};
            for (k = 0; k < 3; k++) {
                tris[3 * n + k] = pt(v[k][0], v[k][1]);
                colour(3 * n + k, v[k][0], v[k][1]);
            }
            n++;
        }
        return n;
    }
    for (j = 0; j < 32; j++)
        for (i = 0; i < 32; i++) {
            double x0 = 56.37 + 12.5 * i, y0 = 56.61 + 12.5 * j, x1 = x0 + 12.5, y1 = y0 + 12.5;
            double v[6][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}};
            for (k = 0; k < 6; k++) {
                tris[3 * n + k] = pt(v[k][0], v[k][1]);
                colour(3 * n + k, v[k][0], v[k][1]);
            }
            n += 2;
        }
    return n;
}

int main(int argc, char **argv)
{
    int sc = argc > 1 ? atoi(argv[1]) : 0, which = argc > 2 ? atoi(argv[2]) : 0;
    int m = argc > 3 ? atoi(argv[3]) : 0, big = argc > 4 ? atoi(argv[4]) : 0;
    uint32_t n = scene(sc);
    rast_coverage_opts o;
    rast_tri_opts to;
    rast_shade_opts sh;
    rast_target t;
    size_t need = 0;
    const unsigned char v[4] = {200, 100, 50, 255};
    rast_status st;
    memset(&o, 0, sizeof o);
    memset(&to, 0, sizeof to);
    memset(&sh, 0, sizeof sh);
    o.method = (rast_aa_method)m;
    o.subpixel_bits = to.subpixel_bits = 8;
    o.sample = to.sample = RAST_SAMPLE_CENTER;
    rast_target_init(&t, img, 512, 512, 512 * 4, RAST_FORMAT_RGBA8888);
    if (which == 0) {
        st = rast_fill_triangles_shaded(&t, tris, n, colors, NULL, NULL, &to, &sh, NULL, 0);
    } else if (which == 1) {
        rast_coverage_scratch_size(&o, 3 * n, 512, 512, &need);
        st = rast_fill_triangles_aa(&t, tris, n, &o, v, scratch, big ? sizeof scratch : need);
    } else {
        rast_shaded_aa_scratch_size(&o, n, 512, 512, &need);
        st = rast_fill_triangles_shaded_aa(&t, tris, n, colors, &o, &sh, scratch,
                                           big ? sizeof scratch : need);
    }
    printf("scene %d which %d method %d: %s (scratch %zu bytes), pixel (256, 100) %u %u %u\n", sc,
           which, m, rast_status_str(st), need, img[(100 * 512 + 256) * 4],
           img[(100 * 512 + 256) * 4 + 1], img[(100 * 512 + 256) * 4 + 2]);
    return st != RAST_OK;
}

/* cbench_tri.c - the binary fills alone, for instruction counts of the
 * pipeline (filler -> sink -> painter) on a shared machine:
 *   which 0..2: rast_fill_triangles into a 512x512 GRAY8 target with
 *               algorithm 0 edge, 1 sweep, 2 edgeflag, a 64x64-cell
 *               grid mesh (8192 small triangles) and 2000 random
 *               triangles (up to 40 px), S = 8, every vertex inside;
 *   which 3:    the same batch, algorithm edge, through a clip that
 *               cuts most triangles (the sink's clipped path);
 *   which 4:    the same batch into an RGB888 target (the generic solid
 *               painter);
 *   which 5:    the same batch to a span callback;
 *   which 6:    100 random 20..60-gons into the GRAY8 target
 *               (rast_fill_polygon, AET);
 *   which 7, 8: those polygons with a colour per vertex
 *               (rast_fill_polygon_gouraud, 7 exact, 8 flat) into an
 *               RGB888 target;
 *   which 9, 10: 400 random rectangles (up to 120 px) shaded bilinearly
 *               (rast_fill_rect_gouraud, 9 exact, 10 fixed, F = 12) into
 *               an RGB888 target.
 *   cc -O2 -std=c11 -Icsrc/include bench/cbench_tri.c build/librastrum.a -o cbench_tri
 *   valgrind --tool=callgrind ./cbench_tri WHICH */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrum.h"

#define GRID 64
#define NRAND 2000
#define NT (2 * GRID * GRID + NRAND)

static uint64_t scratch[1 << 16];
static unsigned char img[512 * 512 * 3];
static rast_point tris[3 * NT];
static uint32_t lcg = 7;

static int32_t rnd(int32_t n)
{
    lcg = lcg * 1103515245u + 12345u;
    return (int32_t)((lcg >> 8) % (uint32_t)n);
}

static rast_point at(int32_t x, int32_t y)
{
    rast_point p;
    p.x = x;
    p.y = y;
    return p;
}

static unsigned long sum;

static void span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    (void)user;
    sum += (unsigned long)(y + x1 - x0);
}

int main(int argc, char **argv)
{
    int which = argc > 1 ? atoi(argv[1]) : 0;
    uint32_t n = 0, i, j;
    const int32_t cell = 500 * 256 / GRID;
    rast_target t;
    rast_tri_opts o;
    unsigned char v[3] = {200, 100, 50};
    rast_status st = RAST_OK;

    for (j = 0; j < GRID; j++)
        for (i = 0; i < GRID; i++) {
            int32_t x = 1000 + (int32_t)i * cell + rnd(64), y = 1000 + (int32_t)j * cell + rnd(64);
            tris[n++] = at(x, y);
            tris[n++] = at(x + cell, y + rnd(64));
            tris[n++] = at(x + rnd(64), y + cell);
            tris[n++] = at(x + cell, y + rnd(64));
            tris[n++] = at(x + cell + rnd(64), y + cell);
            tris[n++] = at(x + rnd(64), y + cell);
        }
    for (i = 0; i < NRAND; i++) {
        int32_t x = 256 * 10 + rnd(256 * 460), y = 256 * 10 + rnd(256 * 460);
        tris[n++] = at(x, y);
        tris[n++] = at(x + rnd(256 * 40), y + rnd(256 * 40));
        tris[n++] = at(x + rnd(256 * 40) - 256 * 20, y + rnd(256 * 40));
    }
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 8;
    o.algorithm = which <= 2 ? (rast_tri_algorithm)which : RAST_TRI_EDGE;
    rast_target_init(&t, img, 512, 512, which == 4 || which >= 7 ? 512 * 3 : 512,
                     which == 4 || which >= 7 ? RAST_FORMAT_RGB888 : RAST_FORMAT_GRAY8);
    if (which == 3) {
        t.clip.x0 = 3;
        t.clip.x1 = 509;
        t.clip.y0 = 5;
        t.clip.y1 = 500;
    }
    if (which <= 4) {
        st = rast_fill_triangles(&t, tris, NT, &o, v, scratch, sizeof scratch);
    } else if (which == 5) {
        rast_rect clip = {0, 0, 512, 512};
        st = rast_fill_triangles_spans(tris, NT, &o, &clip, span, NULL, scratch, sizeof scratch);
    } else if (which >= 9) {
        rast_shade_opts so;
        uint8_t col[16];
        uint32_t k;
        memset(&so, 0, sizeof so);
        so.precision = which == 9 ? RAST_PRECISION_EXACT : RAST_PRECISION_FIXED;
        so.fraction_bits = 12;
        for (k = 0; k < 400 && st == RAST_OK; k++) {
            rast_point p0 = at(rnd(400 * 256), rnd(400 * 256));
            rast_point p1 = at(p0.x + rnd(120 * 256), p0.y + rnd(120 * 256));
            for (i = 0; i < 16; i++) col[i] = (uint8_t)rnd(256);
            st = rast_fill_rect_gouraud(&t, p0, p1, col, &o, &so);
        }
    } else {
        rast_fill_opts fo;
        rast_shade_opts so;
        static uint8_t col[4 * 60];
        static rast_point pts[60];
        uint32_t k;
        memset(&fo, 0, sizeof fo);
        fo.subpixel_bits = 8;
        memset(&so, 0, sizeof so);
        so.precision = which == 8 ? RAST_PRECISION_FLAT : RAST_PRECISION_EXACT;
        for (k = 0; k < 100 && st == RAST_OK; k++) {
            uint32_t m = 20 + (uint32_t)rnd(41);
            rast_polygon p;
            for (i = 0; i < m; i++) pts[i] = at(rnd(512 * 256), rnd(512 * 256));
            for (i = 0; i < 4 * m; i++) col[i] = (uint8_t)rnd(256);
            p.points = pts;
            p.ring_sizes = &m;
            p.nrings = 1;
            if (which == 6)
                st = rast_fill_polygon(&t, &p, &fo, v, scratch, sizeof scratch);
            else
                st = rast_fill_polygon_gouraud(&t, &p, col, &fo, &so, scratch, sizeof scratch);
        }
    }
    for (i = 0; i < sizeof img; i++) sum += img[i] * (i % 251);
    printf("status %d checksum %lu\n", (int)st, sum);
    return st != RAST_OK;
}

/* bench_precision.c - the cost of the 64-bit vertex path (issue 13), C core
 * alone: the same polygons through rast_fill_polygon (int32 vertices,
 * S = 8) and rast_fill_polygon64 (int64 vertices at S = 8, 24 and 32: the
 * same shapes, vertices scaled by 2^(S-8)), side by side in one run.  Each
 * round times every path once, in turn, so that the machine's noise falls
 * on all of them alike; the figures are medians over the rounds, and the
 * ratio is each 64-bit path's median over the 32-bit one's.
 *
 * Scenes (the polygon benchmark of cbench.c, plus a GIS-like batch):
 *  - "random": 100 random self-intersecting 20-60-gons in 640x480 (cbench);
 *  - "star": the 400-vertex zigzag star in 2048x2048 (cbench);
 *  - "small": 20,000 small polygons (8-gons, radius 2-12 px) into
 *    4096x4096 through the batch call (rast_fill_polygons_spans and its
 *    64-bit twin), spans counted.
 *
 *   make bench-precision      (prints the table; ROUNDS=n to change)
 * Also run under callgrind by `make bench-precision-callgrind`: the
 * instruction counts of one round, which do not depend on the noise. */
#define _POSIX_C_SOURCE 199309L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cbench_time.h"
#include "rastrum.h"

#define NPATHS 4
static const int path_s[NPATHS] = {8, 8, 24, 32}; /* path 0: 32-bit; 1..3: 64-bit */
static const char *const path_name[NPATHS] = {"int32 S=8", "int64 S=8", "int64 S=24",
                                              "int64 S=32"};

static uint64_t scratch[1 << 19];

/* A scene: polygons of one ring each, vertices in 1/256 pixel. */
typedef struct {
    rast_point *pts;
    rast_point64 *pts64[NPATHS];
    uint32_t *sizes;
    uint32_t npolys, npts;
    int w, h;
} scene;

static void scene_wide(scene *sc)
{
    int p;
    uint32_t i;
    for (p = 1; p < NPATHS; p++) {
        int64_t m = (int64_t)1 << (path_s[p] - 8);
        free(sc->pts64[p]);
        sc->pts64[p] = malloc(sc->npts * sizeof(rast_point64));
        for (i = 0; i < sc->npts; i++) {
            sc->pts64[p][i].x = sc->pts[i].x * m;
            sc->pts64[p][i].y = sc->pts[i].y * m;
        }
    }
}

static unsigned char *img;
static uint64_t spans_seen;

static void count_span(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    (void)user;
    (void)k;
    (void)y;
    spans_seen += (uint64_t)(x1 - x0);
}

/* Draw the whole scene once through path p (the image must be clear). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static uint64_t draw(const scene *sc, int p, int batch)
{
    rast_fill_opts o;
    rast_target t;
    static const unsigned char one = 1;
    uint32_t k, at = 0;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = path_s[p];
    o.sample = RAST_SAMPLE_CENTER;
    if (batch) {
        static rast_polygon polys[20000];
        static rast_polygon64 polys64[20000];
        rast_rect clip;
        uint32_t failed;
        clip.x0 = clip.y0 = 0;
        clip.x1 = sc->w;
        clip.y1 = sc->h;
        for (k = 0; k < sc->npolys; at += sc->sizes[k], k++) {
            polys[k].points = sc->pts + at;
            polys[k].ring_sizes = &sc->sizes[k];
            polys[k].nrings = 1;
            if (p) {
                polys64[k].points = sc->pts64[p] + at;
                polys64[k].ring_sizes = &sc->sizes[k];
                polys64[k].nrings = 1;
            }
        }
        if (p == 0)
            rast_fill_polygons_spans(polys, sc->npolys, &o, &clip, count_span, NULL, scratch,
                                     sizeof scratch, &failed);
        else
            rast_fill_polygons64_spans(polys64, sc->npolys, &o, &clip, count_span, NULL,
                                       scratch, sizeof scratch, &failed);
        return spans_seen;
    }
    rast_target_init(&t, img, sc->w, sc->h, sc->w, RAST_FORMAT_GRAY8);
    for (k = 0; k < sc->npolys; at += sc->sizes[k], k++) {
        if (p == 0) {
            rast_polygon poly;
            poly.points = sc->pts + at;
            poly.ring_sizes = &sc->sizes[k];
            poly.nrings = 1;
            rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch);
        } else {
            rast_polygon64 poly;
            poly.points = sc->pts64[p] + at;
            poly.ring_sizes = &sc->sizes[k];
            poly.nrings = 1;
            rast_fill_polygon64(&t, &poly, &o, &one, scratch, sizeof scratch);
        }
    }
    return 0;
}

/* The image's checksum after draw(), then cleared (outside the timing and
 * outside callgrind's count: a pass over the whole image would dilute the
 * ratio). */
static uint64_t take_sum(const scene *sc, int batch)
{
    uint64_t sum = 0;
    int32_t i;
    if (batch) {
        sum = spans_seen;
        spans_seen = 0;
        return sum;
    }
    for (i = 0; i < sc->w * sc->h; i++) sum += img[i];
    memset(img, 0, (size_t)sc->w * sc->h);
    return sum;
}

static void bench(const char *name, const scene *sc, int batch, int rounds)
{
    static double t[NPATHS][201];
    uint64_t check[NPATHS];
    double med[NPATHS];
    int r, p;
    if (rounds > 201) rounds = 201;
    for (r = 0; r < rounds; r++)
        for (p = 0; p < NPATHS; p++) {
            double t0 = now();
            draw(sc, p, batch);
            t[p][r] = now() - t0;
            check[p] = take_sum(sc, batch);
        }
    printf("%-8s", name);
    for (p = 0; p < NPATHS; p++) {
        qsort(t[p], (size_t)rounds, sizeof(double), cmp);
        med[p] = t[p][rounds / 2];
        printf("  %9.3f ms", med[p] * 1e3);
    }
    printf("  |");
    for (p = 1; p < NPATHS; p++) printf("  %.3fx", med[p] / med[0]);
    for (p = 1; p < NPATHS; p++)
        if (check[p] != check[0]) printf("  MISMATCH(%s)", path_name[p]);
    printf("\n");
}

static rast_point pts[20000 * 8 + 6000];
static uint32_t sizes[20000];

/* Scene i (0 random, 1 star, 2 small) into *sc; returns whether it is a batch. */
static int make_scene(int which, scene *sc)
{
    uint32_t i, k, n;
    sc->pts = pts;
    sc->sizes = sizes;
    if (which == 0) { /* random 20-60-gons, 640x480 (cbench's) */
        srand(1);
        for (k = 0, n = 0; k < 100; k++) {
            sizes[k] = 20 + (uint32_t)(rand() % 41);
            for (i = 0; i < sizes[k]; i++, n++) {
                pts[n].x = rand() % (640 * 256);
                pts[n].y = rand() % (480 * 256);
            }
        }
        sc->npolys = 100;
        sc->npts = n;
        sc->w = 640;
        sc->h = 480;
    } else if (which == 1) { /* the zigzag star, 2048x2048 (cbench's) */
        for (i = 0; i < 400; i++) {
            int32_t r = (i % 2) ? 300 : 1000;
            int32_t q = (int32_t)i % 100, side = (int32_t)i / 100;
            int32_t u = (q * 2000) / 100 - 1000;
            int32_t x = side == 0 ? u : side == 1 ? 1000 : side == 2 ? -u : -1000;
            int32_t y = side == 0 ? -1000 : side == 1 ? u : side == 2 ? 1000 : -u;
            pts[i].x = (1024 + x * r / 1000) * 256;
            pts[i].y = (1024 + y * r / 1000) * 256;
        }
        sizes[0] = 400;
        sc->npolys = 1;
        sc->npts = 400;
        sc->w = sc->h = 2048;
    } else { /* 20,000 small 8-gons into 4096x4096, batched (GIS-like) */
        static const int32_t c8[8][2] = {{1000, 0}, {707, 707}, {0, 1000}, {-707, 707},
                                         {-1000, 0}, {-707, -707}, {0, -1000}, {707, -707}};
        srand(2);
        for (k = 0, n = 0; k < 20000; k++) {
            int32_t cx = rand() % (4096 * 256), cy = rand() % (4096 * 256);
            int32_t rad = (2 + rand() % 11) * 256;
            sizes[k] = 8;
            for (i = 0; i < 8; i++, n++) {
                pts[n].x = cx + c8[i][0] * rad / 1000 + rand() % 97;
                pts[n].y = cy + c8[i][1] * rad / 1000 + rand() % 89;
            }
        }
        sc->npolys = 20000;
        sc->npts = n;
        sc->w = sc->h = 4096;
    }
    scene_wide(sc);
    return which == 2;
}

static const char *const scene_name[3] = {"random", "star", "small"};

int main(int argc, char **argv)
{
    int rounds = 31, p, which;
    scene sc;
    memset(&sc, 0, sizeof sc);
    img = calloc((size_t)4096 * 4096, 1);
    if (argc == 4 && strcmp(argv[1], "one") == 0) {
        /* one scene through one path, once (for callgrind: the counts of
         * draw() alone are the path's cost) */
        which = atoi(argv[2]);
        p = atoi(argv[3]);
        if (which < 0 || which > 2 || p < 0 || p >= NPATHS) return 2;
        int batch = make_scene(which, &sc);
        draw(&sc, p, batch);
        printf("%s %s: %llu\n", scene_name[which], path_name[p],
               (unsigned long long)take_sum(&sc, batch));
    } else {
        if (argc > 1) rounds = atoi(argv[1]);
        if (rounds < 1) rounds = 1;
        printf("%-8s", "scene");
        for (p = 0; p < NPATHS; p++) printf("  %12s", path_name[p]);
        printf("  |  64-bit / 32-bit (medians of %d rounds)\n", rounds);
        for (which = 0; which < 3; which++) {
            int batch = make_scene(which, &sc);
            bench(scene_name[which], &sc, batch, batch && rounds > 11 ? 11 : rounds);
        }
    }
    for (p = 1; p < NPATHS; p++) free(sc.pts64[p]);
    free(img);
    return 0;
}

/* bench_ss.c - supersampled coverage ("ssK") against the binary fill of the
 * same scene, the C core alone, at 512x512, vertices snapped to 2^-8 pixel:
 * the scenes of bench/bench_coverage.py (a 64-gon circle, a 400-vertex
 * star, a disc with 6 holes, 10,000 random triangles in one batch, a 32x32
 * mesh in one batch), each the median of REPS runs, end to end (binary: a
 * memset of the image then the fill; ssK writes every pixel itself).
 *
 *   cc -O2 -std=c99 -Icsrc/include bench/bench_ss.c build/librastrum.a -lm -o build/bench_ss
 *   build/bench_ss                  every scene, binary and ss2..ss16, ratios to binary
 *   build/bench_ss star ss4 1       one scene and mode (bin, ss2, ss4, ss8, ss16) once:
 *   valgrind --tool=callgrind build/bench_ss star ss4 1   instruction counts
 *
 * (Under callgrind, subtract the run of `build/bench_ss star none 1`: the
 * scene's set-up and the output hash.) */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rastrum.h"

#define N 512
#define PI 3.14159265358979323846

static rast_point pts[30000];
static uint32_t ring[16], nring, npts;
static int batch; /* the points are triangles */
static unsigned char img[N * N];
static uint64_t scratch[1 << 20];
static uint64_t lcg = 12;

static double rnd(void)
{
    lcg = lcg * 6364136223846793005u + 1442695040888963407u;
    return (double)(lcg >> 11) / 9007199254740992.0;
}

static rast_point at(double x, double y)
{
    rast_point p;
    p.x = (int32_t)lround(x * 256);
    p.y = (int32_t)lround(y * 256);
    return p;
}

/* An n-gon (or, with r2 > 0, a star alternating radii r and r2). */
static void ngon(double cx, double cy, double r, double r2, int n, int reverse)
{
    int i;
    for (i = 0; i < n; i++) {
        double t = 2 * PI * (reverse ? n - i : i) / n, rr = (r2 > 0 && (i & 1)) ? r2 : r;
        pts[npts++] = at(cx + rr * cos(t), cy + rr * sin(t));
    }
    ring[nring++] = (uint32_t)n;
}

static int scene(const char *s)
{
    const double c = N / 2.0;
    int i, j;
    npts = nring = 0;
    batch = 0;
    lcg = 12;
    if (!strcmp(s, "circle")) {
        ngon(c, c, 0.4 * N, 0, 64, 0);
    } else if (!strcmp(s, "star")) {
        ngon(c, c, 0.47 * N, 0.2 * N, 400, 0);
    } else if (!strcmp(s, "holes")) {
        ngon(c, c, 0.45 * N, 0, 128, 0);
        for (i = 0; i < 6; i++)
            ngon(c + 0.25 * N * cos(2 * PI * i / 6), c + 0.25 * N * sin(2 * PI * i / 6), 0.08 * N, 0,
                 32, 1);
    } else if (!strcmp(s, "triangles")) {
        batch = 1;
        for (i = 0; i < 30000; i++) {
            double x = 0.05 * N + 0.9 * N * rnd(), y = 0.05 * N + 0.9 * N * rnd();
            pts[npts++] = at(x, y);
        }
    } else if (!strcmp(s, "mesh")) {
        static double g[33][33][2];
        batch = 1;
        for (i = 0; i < 33; i++)
            for (j = 0; j < 33; j++) {
                int inner = i > 0 && i < 32 && j > 0 && j < 32;
                g[i][j][0] = 0.1 * N + 0.8 * N * j / 32 + (inner ? rnd() * 6 - 3 : 0);
                g[i][j][1] = 0.1 * N + 0.8 * N * i / 32 + (inner ? rnd() * 6 - 3 : 0);
            }
        for (i = 0; i < 32; i++)
            for (j = 0; j < 32; j++) {
                static const int q[6][2] = {{0, 0}, {0, 1}, {1, 1}, {0, 0}, {1, 1}, {1, 0}};
                int k;
                for (k = 0; k < 6; k++)
                    pts[npts++] = at(g[i + q[k][0]][j + q[k][1]][0], g[i + q[k][0]][j + q[k][1]][1]);
            }
    } else {
        return 0;
    }
    return 1;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One run of `mode` on the current scene; its status. */
static rast_status draw(const char *mode)
{
    rast_polygon poly = {pts, ring, nring};
    static const char *const names[] = {"ss2", "ss4", "ss8", "ss16"};
    rast_rect clip = {0, 0, N, N};
    size_t need = 0;
    int k;
    if (!strcmp(mode, "bin")) {
        rast_target t;
        unsigned char v = 255;
        rast_target_init(&t, img, N, N, N, RAST_FORMAT_GRAY8);
        memset(img, 0, sizeof img);
        if (batch) {
            rast_tri_opts o;
            memset(&o, 0, sizeof o);
            o.subpixel_bits = 8;
            o.sample = RAST_SAMPLE_CENTER;
            rast_tri_scratch_size(&o, N, N, &need);
            return rast_fill_triangles(&t, pts, npts / 3, &o, &v, scratch, sizeof scratch);
        } else {
            rast_fill_opts o;
            memset(&o, 0, sizeof o);
            o.subpixel_bits = 8;
            o.rule = RAST_RULE_NONZERO;
            o.sample = RAST_SAMPLE_CENTER;
            return rast_fill_polygon(&t, &poly, &o, &v, scratch, sizeof scratch);
        }
    }
    for (k = 0; k < 4; k++)
        if (!strcmp(mode, names[k])) {
            rast_coverage_opts o;
            memset(&o, 0, sizeof o);
            o.method = (rast_aa_method)(RAST_AA_SS2 + k);
            o.rule = RAST_RULE_NONZERO;
            o.subpixel_bits = 8;
            o.sample = RAST_SAMPLE_CENTER;
            rast_coverage_scratch_size(&o, npts, N, N, &need);
            if (need > sizeof scratch) return RAST_E_SCRATCH;
            return batch ? rast_triangles_coverage(pts, npts / 3, &o, &clip, RAST_COVERAGE_U8, img,
                                                   N, scratch, need)
                         : rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, img, N,
                                                 scratch, need);
        }
    return RAST_OK; /* "none": the set-up alone */
}

static double median(const char *mode, int reps)
{
    static double t[1001];
    int r;
    if (reps > 1001) reps = 1001;
    for (r = 0; r < reps; r++) {
        double t0 = now();
        if (draw(mode) != RAST_OK) return -1;
        t[r] = now() - t0;
    }
    qsort(t, (size_t)reps, sizeof t[0], cmp);
    return t[reps / 2];
}

int main(int argc, char **argv)
{
    static const char *const scenes[] = {"circle", "star", "holes", "triangles", "mesh"};
    static const char *const modes[] = {"ss2", "ss4", "ss8", "ss16"};
    int s, m;
    if (argc == 4) {
        uint64_t h = 0;
        size_t k;
        if (!scene(argv[1])) return 2;
        printf("%s %s: median %.4f ms", argv[1], argv[2], median(argv[2], atoi(argv[3])));
        for (k = 0; k < sizeof img; k++) h = h * 31 + img[k];
        printf(", output hash %016llx\n", (unsigned long long)h);
        return 0;
    }
    printf("median ms at %dx%d (ratio to the binary fill of the same scene, same run)\n", N, N);
    printf("%-10s %9s", "scene", "binary");
    for (m = 0; m < 4; m++) printf(" %16s", modes[m]);
    printf("\n");
    for (s = 0; s < 5; s++) {
        int big;
        double b;
        scene(scenes[s]);
        big = !strcmp(scenes[s], "triangles");
        b = median("bin", big ? 7 : 51);
        printf("%-10s %9.4f", scenes[s], b);
        for (m = 0; m < 4; m++) {
            double t = median(modes[m], big ? 5 : 51);
            printf(" %9.4f (%4.1fx)", t, t / b);
        }
        printf("\n");
    }
    return 0;
}

/* cbench_coverage.c - the coverage core alone, no Python: median time of
 * rast_polygon_coverage ("area" and "accumulate", uint8) on the scenes of
 * bench/bench_coverage.py at 512x512 (circle, star, holed disc, a mesh of
 * triangles, random overlapping triangles).  Used to tune coverage_area.c:
 *   make cbench-coverage              (wall clock, medians)
 *   valgrind --tool=callgrind build/cbench_coverage 1 SCENE METHOD
 * counts instructions of one call of one scene (SCENE: one of the names
 * below, trisN for N random triangles, or a file of rings: its count, then
 * each ring's size and vertices in 1/256 pixel; "t:FILE", the same file
 * drawn as a triangle batch, rast_triangles_coverage, its rings of 3).
 * Add --toggle-collect=draw to count the call alone, not the file's
 * reading. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cbench_time.h"
#include "rastrum.h"

#define SIZE 512
#define PI 3.14159265358979323846
#define MAXP 200000

static rast_point pts[MAXP];
static uint32_t sizes[MAXP];
static unsigned char img[SIZE * SIZE];

static rast_point P(double x, double y)
{
    rast_point p;
    p.x = (int32_t)lround(x * 256);
    p.y = (int32_t)lround(y * 256);
    return p;
}

/* n-gon at (cx, cy), radius r, appended; reversed when rev. */
static uint32_t ngon(uint32_t at, double cx, double cy, double r, uint32_t n, int rev)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        double t = 2 * PI * (rev ? n - i : i) / n;
        pts[at + i] = P(cx + r * cos(t), cy + r * sin(t));
    }
    return n;
}

static double lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* The scene's rings; *tris: a triangle batch (npoints / 3 triangles). */
static uint32_t scene(const char *name, uint32_t *nrings, int *tris)
{
    const double c = SIZE / 2.0;
    uint32_t n = 0, k;
    *tris = 0;
    if (!strcmp(name, "circle")) {
        sizes[0] = ngon(0, c, c, 0.4 * SIZE, 64, 0);
        *nrings = 1;
        return sizes[0];
    }
    if (!strcmp(name, "star")) {
        for (k = 0; k < 400; k++) {
            double r = (k % 2 ? 0.2 : 0.47) * SIZE, t = 2 * PI * k / 400;
            pts[k] = P(c + r * cos(t), c + r * sin(t));
        }
        sizes[0] = 400;
        *nrings = 1;
        return 400;
    }
    if (!strcmp(name, "holes")) {
        sizes[0] = ngon(0, c, c, 0.45 * SIZE, 128, 0);
        n = 128;
        for (k = 0; k < 6; k++) {
            double a = 2 * PI * k / 6;
            sizes[k + 1] = ngon(n, c + 0.25 * SIZE * cos(a), c + 0.25 * SIZE * sin(a), 0.08 * SIZE, 32, 1);
            n += 32;
        }
        *nrings = 7;
        return n;
    }
    if (!strcmp(name, "twice")) {
        for (k = 0; k < 2; k++) {
            pts[4 * k] = P(0.2 * SIZE + .3, 0.2 * SIZE + .3);
            pts[4 * k + 1] = P(0.8 * SIZE + .3, 0.2 * SIZE + .3);
            pts[4 * k + 2] = P(0.8 * SIZE + .3, 0.8 * SIZE + .3);
            pts[4 * k + 3] = P(0.2 * SIZE + .3, 0.8 * SIZE + .3);
            sizes[k] = 4;
        }
        *nrings = 2;
        return 8;
    }
    if (!strcmp(name, "mesh")) {
        uint64_t s = 12;
        static double gx[33 * 33], gy[33 * 33];
        uint32_t r, q;
        for (k = 0; k < 33 * 33; k++) {
            int inner = k % 33 > 0 && k % 33 < 32 && k / 33 > 0 && k / 33 < 32;
            gx[k] = (0.1 + 0.8 * (k % 33) / 32) * SIZE + (inner ? 6 * lcg(&s) - 3 : 0);
            gy[k] = (0.1 + 0.8 * (k / 33) / 32) * SIZE + (inner ? 6 * lcg(&s) - 3 : 0);
        }
        for (r = 0; r < 32; r++)
            for (q = 0; q < 32; q++) {
                uint32_t a = r * 33 + q, b = a + 1, d = a + 34, e = a + 33;
                pts[n++] = P(gx[a], gy[a]);
                pts[n++] = P(gx[b], gy[b]);
                pts[n++] = P(gx[d], gy[d]);
                pts[n++] = P(gx[a], gy[a]);
                pts[n++] = P(gx[d], gy[d]);
                pts[n++] = P(gx[e], gy[e]);
            }
        *tris = 1;
        return n;
    }
    if (!strncmp(name, "tris", 4)) { /* "tris1000": random overlapping triangles */
        uint64_t s = 12;
        uint32_t m = (uint32_t)atoi(name + 4);
        for (k = 0; k < 3 * m && k < MAXP; k++)
            pts[k] = P((0.05 + 0.9 * lcg(&s)) * SIZE, (0.05 + 0.9 * lcg(&s)) * SIZE);
        *tris = 1;
        return k;
    }
    { /* a file: the ring count, then each ring's size and its vertices (fixed, S = 8) */
        FILE *f;
        if (!strncmp(name, "t:", 2)) { /* as a triangle batch */
            name += 2;
            *tris = 1;
        }
        f = fopen(name, "r");
        uint32_t r, i;
        if (f && fscanf(f, "%u", nrings) == 1) {
            for (r = 0; r < *nrings && r < MAXP; r++) {
                if (fscanf(f, "%u", &sizes[r]) != 1) break;
                for (i = 0; i < sizes[r] && n < MAXP; i++, n++)
                    if (fscanf(f, "%d %d", &pts[n].x, &pts[n].y) != 2) break;
            }
            fclose(f);
            return n;
        }
    }
    fprintf(stderr, "unknown scene %s\n", name);
    exit(2);
}

/* FNV-1a of the image: runs compared across builds must be bit-identical. */
static unsigned long long hash(void)
{
    unsigned long long h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < sizeof img; i++) h = (h ^ img[i]) * 1099511628211ull;
    return h;
}

static void *scratch;
static size_t scratch_bytes;

static rast_status draw(uint32_t npoints, uint32_t nrings, int tris, rast_aa_method m)
{
    rast_coverage_opts o = {m, RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER};
    rast_rect clip = {0, 0, SIZE, SIZE};
    rast_polygon poly;
    size_t need;
    rast_coverage_scratch_size(&o, npoints, SIZE, SIZE, &need);
    if (need > scratch_bytes) {
        free(scratch);
        scratch = malloc(need);
        scratch_bytes = need;
    }
    if (tris)
        return rast_triangles_coverage(pts, npoints / 3, &o, &clip, RAST_COVERAGE_U8, img, SIZE,
                                       scratch, scratch_bytes);
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    return rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, img, SIZE, scratch,
                                 scratch_bytes);
}

int main(int argc, char **argv)
{
    /* the scenes run by default; trisN and files only when named */
    static const char *const all[] = {"circle", "star", "holes", "twice", "mesh", "named"};
    static const char *const mname[] = {"area", "accumulate"};
    static const rast_aa_method meth[] = {RAST_AA_AREA, RAST_AA_ACCUMULATE};
    int reps = argc > 1 ? atoi(argv[1]) : 15, s, mi;
    for (s = 0; s < 6; s++) {
        uint32_t nrings = 1, n;
        int tris;
        if (argc > 2 ? strcmp(argv[2], all[s]) && s + 1 < 6 : s + 1 == 6) continue;
        n = scene(argc > 2 ? argv[2] : all[s], &nrings, &tris);
        for (mi = 0; mi < 2; mi++) {
            double t[64];
            int r;
            if (argc > 3 && strcmp(argv[3], mname[mi])) continue;
            for (r = 0; r < reps && r < 64; r++) {
                double t0 = now();
                if (draw(n, nrings, tris, meth[mi]) != RAST_OK) return 1;
                t[r] = now() - t0;
            }
            qsort(t, (size_t)r, sizeof t[0], cmp);
            printf("%-10s %-10s %9.3f ms  (median of %d; image hash %016llx)\n",
                   argc > 2 ? argv[2] : all[s], mname[mi], t[r / 2] * 1e3, r, hash());
        }
        if (argc > 2) break;
    }
    return 0;
}

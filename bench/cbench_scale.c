/* cbench_scale.c - does each method's cost grow with the work?  Scene
 * families drawn from a seeded generator at a size N, doubled step by
 * step (issue 33): the cost of one call, in instructions under callgrind
 * (repeatable where timings are not), per family, size and method.
 *   build/cbench_scale FAMILY N METHOD [REPS]   one configuration (the
 *       call is the function `draw`: valgrind --tool=callgrind
 *       --toggle-collect=draw counts it alone), prints the median time
 *       and an image hash
 *   tools/callgrind-scale.sh build/cbench_scale   the whole series, with
 *       each method's growth exponent log2(cost(2N) / cost(N))
 * Families (canvas 1024 x 1024, non-zero rule, S = 8):
 *   text N       N glyph-like shapes in lines (an "o" with its hole and a
 *                slanted bar: 3 rings, 52 vertices), 14 px tall, none
 *                overlapping: rings x 2
 *   smalltris N  N random triangles about 12 px across, one call: edges and
 *                overlap depth x 2
 *   bigtris N    N random triangles spanning the canvas: edges x 2,
 *                crossings x 4
 *   meshrings N  a mesh of N cells (40 across, 12 px), each cell two
 *                triangles given as two rings of one polygon: rings x 2
 *   @FILE        a scene bench/dump_scene.py wrote (a family of
 *                bench/families.py at a seed and size <= 1024; N is not
 *                read): a polygon in one call, a triangle batch in one call
 *                (rast_triangles_coverage; binary: rast_fill_triangles), or
 *                the "loop" family's call a ring (rast_fill_polygon_aa into
 *                a gray8 canvas; binary: rast_fill_polygon), its rule
 * Methods: area, accumulate, ss4 (rast_polygon_coverage, uint8), binary
 * (rast_fill_polygon, AET, gray8); the triangle families also as a batch:
 * tarea, taccumulate, tss4 (rast_triangles_coverage), tbinary
 * (rast_fill_triangles, "edge"); mask, a one-polygon scene file only:
 * polygon_mask's call (rast_fill_polygon_opaque, background 0: every
 * pixel written once, nothing cleared first). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cbench_time.h"
#include "rastrum.h"

#define SIZE 1024
#define PI 3.14159265358979323846

static rast_point *pts;
static uint32_t *sizes;
/* a scene file's: 0 polygon, 1 triangles, 2 a call a ring (-1: a family
 * of this file); its rule and canvas size */
static int fkind = -1;
static rast_fill_rule frule = RAST_RULE_NONZERO;
static int32_t fsize = SIZE;
static unsigned char img[SIZE * SIZE];
static void *scratch;
static size_t scratch_bytes;

static rast_point P(double x, double y)
{
    rast_point p;
    p.x = (int32_t)lround(x * 256);
    p.y = (int32_t)lround(y * 256);
    return p;
}

static double lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* An ellipse of n vertices at (cx, cy), radii rx, ry, appended at *at;
 * clockwise on screen when cw (y down). */
static void ellipse(uint32_t *at, uint32_t *nr, double cx, double cy, double rx, double ry,
                    uint32_t n, int cw)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        double t = 2 * PI * (cw ? i : n - i) / n;
        pts[*at + i] = P(cx + rx * cos(t), cy + ry * sin(t));
    }
    *at += n;
    sizes[(*nr)++] = n;
}

static uint32_t u32(FILE *f)
{
    unsigned char b[4];
    if (fread(b, 1, 4, f) != 4) {
        fprintf(stderr, "short scene file\n");
        exit(2);
    }
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* A scene file (bench/dump_scene.py) into pts, sizes, fkind, frule, fsize. */
static void scene_file(const char *path, uint32_t *npoints, uint32_t *nrings)
{
    FILE *f = fopen(path, "rb");
    char magic[4];
    uint32_t i, nr, np;
    if (!f || fread(magic, 1, 4, f) != 4 || memcmp(magic, "RSC1", 4)) {
        fprintf(stderr, "%s: not a scene file\n", path);
        exit(2);
    }
    fkind = (int)u32(f);
    frule = u32(f) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
    fsize = (int32_t)u32(f);
    nr = u32(f);
    np = u32(f);
    if (fsize <= 0 || fsize > SIZE || fkind < 0 || fkind > 2) {
        fprintf(stderr, "%s: size %d or kind %d not taken\n", path, (int)fsize, fkind);
        exit(2);
    }
    pts = (rast_point *)malloc((np + 1) * sizeof *pts);
    sizes = (uint32_t *)malloc((nr + 1) * sizeof *sizes);
    for (i = 0; i < nr; i++) sizes[i] = u32(f);
    for (i = 0; i < np; i++) {
        pts[i].x = (int32_t)u32(f);
        pts[i].y = (int32_t)u32(f);
    }
    fclose(f);
    *npoints = np;
    *nrings = nr;
}

/* The family's geometry: *npoints vertices, *nrings rings (a triangle
 * family: 3 a ring). */
static void scene(const char *fam, uint32_t n, uint32_t *npoints, uint32_t *nrings)
{
    uint64_t s = 12;
    uint32_t k, at = 0, nr = 0, cap = 60 * n + 16;
    pts = (rast_point *)malloc(cap * sizeof *pts);
    sizes = (uint32_t *)malloc(cap * sizeof *sizes);
    if (!strcmp(fam, "text")) { /* 11 px pitch, 20 px lines, a slight jitter */
        for (k = 0; k < n; k++) {
            double x = 4 + 11.0 * (k % 92) + lcg(&s), y = 10 + 20.0 * (k / 92) + lcg(&s);
            uint32_t b = at;
            ellipse(&at, &nr, x + 4, y + 7, 4.2, 5, 24, 1); /* the "o", clockwise */
            ellipse(&at, &nr, x + 4, y + 7, 2.4, 3.3, 24, 0); /* its hole */
            pts[at++] = P(x + 8.6, y);        /* the bar, clockwise */
            pts[at++] = P(x + 10.0, y);
            pts[at++] = P(x + 9.6, y + 12.2);
            pts[at++] = P(x + 8.2, y + 12.2);
            sizes[nr++] = 4;
            (void)b;
        }
    } else if (!strcmp(fam, "smalltris") || !strcmp(fam, "bigtris")) {
        const int big = fam[0] == 'b';
        for (k = 0; k < n; k++) {
            double cx = 8 + (SIZE - 16) * lcg(&s), cy = 8 + (SIZE - 16) * lcg(&s);
            uint32_t v;
            for (v = 0; v < 3; v++)
                pts[at++] = big ? P(SIZE * lcg(&s), SIZE * lcg(&s))
                                : P(cx + 12 * lcg(&s) - 6, cy + 12 * lcg(&s) - 6);
            sizes[nr++] = 3;
        }
    } else if (!strcmp(fam, "meshrings")) { /* 40 cells across, jittered inner vertices */
        const uint32_t cols = 40, rows = (n + cols - 1) / cols;
        double *gx = (double *)malloc((cols + 1) * (rows + 1) * sizeof(double));
        double *gy = (double *)malloc((cols + 1) * (rows + 1) * sizeof(double));
        uint32_t r, q;
        for (r = 0; r <= rows; r++)
            for (q = 0; q <= cols; q++) {
                int inner = r > 0 && r < rows && q > 0 && q < cols;
                gx[r * (cols + 1) + q] = 20 + 12.0 * q + (inner ? 5 * lcg(&s) - 2.5 : 0);
                gy[r * (cols + 1) + q] = 20 + 12.0 * r + (inner ? 5 * lcg(&s) - 2.5 : 0);
            }
        for (k = 0; k < n; k++) {
            uint32_t a = (k / cols) * (cols + 1) + k % cols, b = a + 1, d = a + cols + 2, e = a + cols + 1;
            pts[at++] = P(gx[a], gy[a]);
            pts[at++] = P(gx[b], gy[b]);
            pts[at++] = P(gx[d], gy[d]);
            pts[at++] = P(gx[a], gy[a]);
            pts[at++] = P(gx[d], gy[d]);
            pts[at++] = P(gx[e], gy[e]);
            sizes[nr++] = 3;
            sizes[nr++] = 3;
        }
        free(gx);
        free(gy);
    } else {
        fprintf(stderr, "unknown family %s\n", fam);
        exit(2);
    }
    *npoints = at;
    *nrings = nr;
}

static const char *const mnames[] = {"area", "accumulate", "ss4", "binary",
                                     "tarea", "taccumulate", "tss4", "tbinary", "mask"};
static const rast_aa_method aa[] = {RAST_AA_AREA, RAST_AA_ACCUMULATE, RAST_AA_SS4};

/* The scratch grown to `need` bytes (before the call: its size is read
 * as an argument too). */
static void room(size_t need)
{
    if (need > scratch_bytes) {
        free(scratch);
        scratch = malloc(need);
        scratch_bytes = need;
    }
}

/* A scene file's call(s) of method m (0 .. 3), into img (fsize x fsize) */
static rast_status draw_file(int m, uint32_t npoints, uint32_t nrings)
{
    rast_rect clip;
    rast_target t;
    rast_polygon poly;
    size_t need = 0;
    const unsigned char one = 255;
    uint32_t k, at = 0;
    rast_status st = RAST_OK;
    clip.x0 = clip.y0 = 0;
    clip.x1 = clip.y1 = fsize;
    if (m == 8) { /* polygon_mask's call: every pixel written once, no clearing first */
        const unsigned char zero = 0;
        rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER, 0, 0};
        o.rule = frule;
        rast_target_init(&t, img, fsize, fsize, fsize, RAST_FORMAT_GRAY8);
        rast_scratch_size(&o, npoints, fsize, fsize, &need);
        room(need);
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nrings;
        return rast_fill_polygon_opaque(&t, &poly, &o, &one, &zero, scratch, scratch_bytes);
    }
    memset(img, 0, sizeof img);
    rast_target_init(&t, img, fsize, fsize, fsize, RAST_FORMAT_GRAY8);
    if (m == 3) {
        rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER, 0, 0};
        o.rule = frule;
        rast_scratch_size(&o, npoints, fsize, fsize, &need);
        room(need);
        if (fkind == 1) {
            rast_tri_opts to = {RAST_TRI_EDGE, 8, RAST_SAMPLE_CENTER, 0, 0};
            rast_tri_scratch_size(&to, fsize, fsize, &need);
            room(need ? need : 16);
            return rast_fill_triangles(&t, pts, npoints / 3, &to, &one, scratch, scratch_bytes);
        }
        for (k = 0; k < (fkind == 2 ? nrings : 1) && st == RAST_OK; k++) {
            poly.points = pts + at;
            poly.ring_sizes = fkind == 2 ? sizes + k : sizes;
            poly.nrings = fkind == 2 ? 1 : nrings;
            at += fkind == 2 ? sizes[k] : 0;
            st = rast_fill_polygon(&t, &poly, &o, &one, scratch, scratch_bytes);
        }
        return st;
    } else {
        rast_coverage_opts o = {aa[m & 3], RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER};
        o.rule = frule;
        rast_coverage_scratch_size(&o, npoints, fsize, fsize, &need);
        room(need);
        if (fkind == 1)
            return rast_triangles_coverage(pts, npoints / 3, &o, &clip, RAST_COVERAGE_U8, img, (size_t)fsize,
                                           scratch, scratch_bytes);
        if (fkind == 0) {
            poly.points = pts;
            poly.ring_sizes = sizes;
            poly.nrings = nrings;
            return rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, img, (size_t)fsize, scratch,
                                         scratch_bytes);
        }
        for (k = 0; k < nrings && st == RAST_OK; k++) {
            poly.points = pts + at;
            poly.ring_sizes = sizes + k;
            poly.nrings = 1;
            at += sizes[k];
            st = rast_fill_polygon_aa(&t, &poly, &o, &one, scratch, scratch_bytes);
        }
        return st;
    }
}

/* One call of method m on the scene (the function callgrind counts). */
__attribute__((noinline)) static rast_status draw(int m, uint32_t npoints, uint32_t nrings)
{
    rast_rect clip = {0, 0, SIZE, SIZE};
    rast_polygon poly;
    size_t need = 0;
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    if (fkind >= 0) return draw_file(m, npoints, nrings);
    if (m == 3 || m == 7) {
        rast_target t;
        const unsigned char one = 255;
        memset(img, 0, sizeof img);
        rast_target_init(&t, img, SIZE, SIZE, SIZE, RAST_FORMAT_GRAY8);
        if (m == 3) {
            rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER, 0, 0};
            rast_scratch_size(&o, npoints, SIZE, SIZE, &need);
            room(need);
            return rast_fill_polygon(&t, &poly, &o, &one, scratch, scratch_bytes);
        } else {
            rast_tri_opts o = {RAST_TRI_EDGE, 8, RAST_SAMPLE_CENTER, 0, 0};
            rast_tri_scratch_size(&o, SIZE, SIZE, &need);
            room(need ? need : 16);
            return rast_fill_triangles(&t, pts, npoints / 3, &o, &one, scratch, scratch_bytes);
        }
    } else {
        rast_coverage_opts o = {aa[m & 3], RAST_RULE_NONZERO, 8, RAST_SAMPLE_CENTER};
        rast_coverage_scratch_size(&o, npoints, SIZE, SIZE, &need);
        room(need);
        if (m < 4)
            return rast_polygon_coverage(&poly, &o, &clip, RAST_COVERAGE_U8, img, SIZE, scratch,
                                         scratch_bytes);
        return rast_triangles_coverage(pts, npoints / 3, &o, &clip, RAST_COVERAGE_U8, img, SIZE,
                                       scratch, scratch_bytes);
    }
}

static unsigned long long hash(void)
{
    unsigned long long h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < sizeof img; i++) h = (h ^ img[i]) * 1099511628211ull;
    return h;
}

int main(int argc, char **argv)
{
    uint32_t n, npoints, nrings;
    int m, reps, r;
    double t[64];
    if (argc < 4) {
        fprintf(stderr, "usage: %s FAMILY N METHOD [REPS]\n", argv[0]);
        return 2;
    }
    n = (uint32_t)atoi(argv[2]);
    for (m = 0; m < 9 && strcmp(argv[3], mnames[m]); m++) {
    }
    if (m == 9 || (m == 8 && argv[1][0] != '@')) {
        fprintf(stderr, "unknown method %s\n", argv[3]);
        return 2;
    }
    reps = argc > 4 ? atoi(argv[4]) : 1;
    if (argv[1][0] == '@')
        scene_file(argv[1] + 1, &npoints, &nrings);
    else
        scene(argv[1], n, &npoints, &nrings);
    if (m == 8 && fkind != 0) {
        fprintf(stderr, "mask: a one-polygon scene file only\n");
        return 2;
    }
    if (m >= 4 && m < 8 && (fkind >= 0 || strstr(argv[1], "tris") == NULL)) {
        fprintf(stderr, "%s: a triangle family only\n", argv[3]);
        return 2;
    }
    for (r = 0; r < reps && r < 64; r++) {
        double t0 = now();
        rast_status st = draw(m, npoints, nrings);
        if (st != RAST_OK) {
            fprintf(stderr, "%s\n", rast_status_str(st));
            return 1;
        }
        t[r] = now() - t0;
    }
    qsort(t, (size_t)r, sizeof t[0], cmp);
    printf("%-10s %6u %-12s %10.3f ms  (%u rings, %u vertices; median of %d; image hash %016llx)\n",
           argv[1], n, argv[3], t[r / 2] * 1e3, nrings, npoints, r, hash());
    free(scratch);
    free(pts);
    free(sizes);
    return 0;
}

/*
 * fuzz_cocopoly.c - the binding's windowed pycocotools polygon rule
 * (python/glue/coco.c, rastpy_coco_fr_polys; core rast_coco_ring_toggles_in):
 * each ring's toggles taken `budget` at a time, so that memory follows the
 * RLE, not vertices x width.  Small budgets (1..64) force many windows.
 * Oracle, written apart from coco.c: a plain transcription of pycocotools'
 * rleFrPoly (maskApi.c): upsample by 5, walk every edge densely, keep the
 * x-steps that land on a column centre, collect ALL toggles, sort them,
 * take differences and drop zero runs; then pycocotools' rleToString.
 * The glue's bytes for each polygon must equal the oracle's string.
 */
#include "glue.h"
#include "fuzz.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CP_MAXV 12   /* vertices a ring */
#define CP_MAXP 3    /* rings a call */
#define CP_MAXDIM 48 /* height, width */

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

static int iabs(int v) { return v < 0 ? -v : v; }

/* pycocotools' rleFrPoly: the counts of ring xy (k points) in h x w. */
static size_t ref_fr_poly(const double *xy, size_t k, uint32_t h, uint32_t w, uint32_t *cnts)
{
    const double scale = 5;
    int x[CP_MAXV + 1], y[CP_MAXV + 1];
    static int u[CP_MAXV * 2000], v[CP_MAXV * 2000];
    static uint32_t a[CP_MAXV * 2000 + 1];
    size_t j, m = 0, n = 0, na;
    for (j = 0; j < k; j++) x[j] = (int)(scale * xy[2 * j] + .5);
    x[k] = x[0];
    for (j = 0; j < k; j++) y[j] = (int)(scale * xy[2 * j + 1] + .5);
    y[k] = y[0];
    for (j = 0; j < k; j++) {
        int xs = x[j], xe = x[j + 1], ys = y[j], ye = y[j + 1], dx, dy, t, d, flip;
        double s;
        dx = iabs(xe - xs);
        dy = iabs(ys - ye);
        flip = (dx >= dy && xs > xe) || (dx < dy && ys > ye);
        if (flip) {
            t = xs; xs = xe; xe = t;
            t = ys; ys = ye; ye = t;
        }
        /* a zero-length edge: pycocotools divides 0 by 0 (NaN, then an
         * undefined int conversion); its one point never starts an x-step
         * (its u equals its neighbours'), so its v is never read: 0 here */
        s = dx == 0 && dy == 0 ? 0.0 : dx >= dy ? (double)(ye - ys) / dx : (double)(xe - xs) / dy;
        if (dx >= dy)
            for (d = 0; d <= dx; d++) {
                t = flip ? dx - d : d;
                u[m] = t + xs;
                v[m] = (int)(ys + s * t + .5);
                m++;
            }
        else
            for (d = 0; d <= dy; d++) {
                t = flip ? dy - d : d;
                v[m] = t + ys;
                u[m] = (int)(xs + s * t + .5);
                m++;
            }
    }
    /* the y-boundary points, downsampled */
    na = 0;
    for (j = 1; j < m; j++)
        if (u[j] != u[j - 1]) {
            double xd = (double)(u[j] < u[j - 1] ? u[j] : u[j] - 1), yd;
            xd = (xd + .5) / scale - .5;
            if (floor(xd) != xd || xd < 0 || xd > (double)w - 1) continue;
            yd = (double)(v[j] < v[j - 1] ? v[j] : v[j - 1]);
            yd = (yd + .5) / scale - .5;
            if (yd < 0) yd = 0;
            else if (yd > h) yd = h;
            yd = ceil(yd);
            a[na++] = (uint32_t)((int)xd * (int)h + (int)yd);
        }
    a[na++] = h * w;
    qsort(a, na, sizeof a[0], cmp_u32);
    {
        uint32_t p = 0, t;
        for (j = 0; j < na; j++) {
            t = a[j];
            a[j] -= p;
            p = t;
        }
    }
    j = 0;
    cnts[n++] = a[j++];
    while (j < na) {
        if (a[j] > 0) cnts[n++] = a[j++];
        else {
            j++;
            if (j < na) cnts[n - 1] += a[j++];
        }
    }
    return n;
}

/* pycocotools' rleToString */
static size_t ref_to_string(const uint32_t *cnts, size_t m, char *s)
{
    size_t i, p = 0;
    for (i = 0; i < m; i++) {
        long x = (long)cnts[i];
        int more = 1;
        if (i > 2) x -= (long)cnts[i - 2];
        while (more) {
            char c = (char)(x & 0x1f);
            x >>= 5;
            more = (c & 0x10) ? x != -1 : x != 0;
            if (more) c |= 0x20;
            c += 48;
            s[p++] = c;
        }
    }
    return p;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    double xy[CP_MAXP * CP_MAXV * 2];
    uint32_t npts[CP_MAXP], h, w, npolys, k, at = 0;
    static uint32_t cnts[CP_MAXV * 2000 + 2];
    static char want[(CP_MAXV * 2000 + 2) * 7];
    size_t budget, offsets[CP_MAXP + 1];
    char *got = NULL;
    long st;
    h = 1 + (uint32_t)fz_below(&in, CP_MAXDIM);
    w = 1 + (uint32_t)fz_below(&in, CP_MAXDIM);
    budget = 1 + (size_t)fz_below(&in, 64);
    npolys = 1 + (uint32_t)fz_below(&in, CP_MAXP);
    for (k = 0; k < npolys; k++) {
        uint32_t i;
        npts[k] = 1 + (uint32_t)fz_below(&in, CP_MAXV);
        for (i = 0; i < 2 * npts[k]; i++) {
            /* quarter pixels in [-8, 56), sometimes a tenth (5x + 0.5 near .5 ties) */
            int32_t q = fz_below(&in, 64 * 4) - 32;
            double c = q / 4.0;
            if (fz_u8(&in) < 32) c += fz_below(&in, 10) / 10.0;
            xy[2 * at + i] = c;
        }
        at += npts[k];
    }
    st = rastpy_coco_fr_polys(xy, npts, npolys, h, w, budget, &got, offsets);
    FZ_ASSERT(st == 0);
    at = 0;
    for (k = 0; k < npolys; k++) {
        size_t m = ref_fr_poly(xy + 2 * at, npts[k], h, w, cnts);
        size_t n = ref_to_string(cnts, m, want);
        FZ_ASSERT(offsets[k + 1] - offsets[k] == n);
        FZ_ASSERT(memcmp(got + offsets[k], want, n) == 0);
        at += npts[k];
    }
    rastpy_free(got);
    return 0;
}

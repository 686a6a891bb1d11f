/* test_coco.c - pycocotools' polygon rule in the core (rast_coco_ring_toggles,
 * rast_coco_rle) against a reference that walks every edge in doubles, one
 * step at a time, as pycocotools' rleFrPoly does (written here from its
 * description; test code may use double).  Small coordinates make the
 * doubles tie often; larger ones check the exact rounding elsewhere. */
#define CHECK_RNG_SEED 14u
#define RAST_STATIC_LINKING_ONLY /* pycocotools' rule */
#include <string.h>
#include "check.h"
#include "rastrum.h"

#define MAXPTS 12
#define MAXSTEPS 400000
#define MAXTOG 100000

static int walk_u[MAXSTEPS], walk_v[MAXSTEPS];
static uint32_t ref_tog[MAXTOG], got_tog[MAXTOG], work[MAXTOG];
static uint32_t ref_cnt[MAXTOG + 2], got_cnt[MAXTOG + 2];

/* floor and ceil of doubles of moderate size, without libm (the C tests
 * link none) */
static double floor_d(double v)
{
    double t = (double)(long long)v;
    return t > v ? t - 1 : t;
}

static double ceil_d(double v)
{
    double t = (double)(long long)v;
    return t < v ? t + 1 : t;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x > y ? 1 : x < y ? -1 : 0;
}

/* The walk and the toggles; returns the number of toggles or -1 (too many). */
static long reference(const rast_point *p, int k, int h, int w, uint32_t *tog)
{
    long m = 0, n = 0, j;
    for (j = 0; j < k; j++) {
        int xs = p[j].x, ys = p[j].y, xe = p[(j + 1) % k].x, ye = p[(j + 1) % k].y, t, d;
        int dx = abs(xe - xs), dy = abs(ys - ye);
        int flip = (dx >= dy && xs > xe) || (dx < dy && ys > ye);
        double s;
        if (flip) {
            t = xs; xs = xe; xe = t;
            t = ys; ys = ye; ye = t;
        }
        if (dx >= dy && dx == 0) { /* pycocotools' 0/0: one point whose v never counts */
            if (m >= MAXSTEPS) return -1;
            walk_u[m] = xs;
            walk_v[m++] = ys;
            continue;
        }
        s = dx >= dy ? (double)(ye - ys) / dx : (double)(xe - xs) / dy;
        if (m + (dx > dy ? dx : dy) + 1 > MAXSTEPS) return -1;
        if (dx >= dy)
            for (d = 0; d <= dx; d++) {
                t = flip ? dx - d : d;
                walk_u[m] = t + xs;
                walk_v[m++] = (int)(ys + s * t + .5);
            }
        else
            for (d = 0; d <= dy; d++) {
                t = flip ? dy - d : d;
                walk_v[m] = t + ys;
                walk_u[m++] = (int)(xs + s * t + .5);
            }
    }
    for (j = 1; j < m; j++)
        if (walk_u[j] != walk_u[j - 1]) {
            double xd = (double)(walk_u[j] < walk_u[j - 1] ? walk_u[j] : walk_u[j] - 1), yd;
            xd = (xd + .5) / 5 - .5;
            if (floor_d(xd) != xd || xd < 0 || (w && xd > w - 1)) continue;
            yd = (double)(walk_v[j] < walk_v[j - 1] ? walk_v[j] : walk_v[j - 1]);
            yd = (yd + .5) / 5 - .5;
            if (yd < 0) yd = 0;
            else if (yd > h) yd = h;
            yd = ceil_d(yd);
            if (n >= MAXTOG) return -1;
            tog[n++] = (uint32_t)(int)xd * (uint32_t)h + (uint32_t)(int)yd;
        }
    return n;
}

/* pycocotools' counts from toggles: sorted with h*w, differences, a 0
 * joining its neighbours. */
static size_t reference_rle(uint32_t *tog, size_t n, uint32_t total, uint32_t *cnt)
{
    size_t j, k = n + 1, m = 0;
    uint32_t p = 0;
    tog[n] = total;
    qsort(tog, k, sizeof *tog, cmp_u32);
    for (j = 0; j < k; j++) {
        uint32_t t = tog[j];
        tog[j] -= p;
        p = t;
    }
    j = 0;
    cnt[m++] = tog[j++];
    while (j < k)
        if (tog[j] > 0) cnt[m++] = tog[j++];
        else {
            j++;
            if (j < k) cnt[m - 1] += tog[j++];
        }
    return m;
}

/* rast_coco_ring_toggles_in over random windows that tile the positions:
 * each window's count exact (a capacity one short is refused, nothing
 * written), every toggle inside its window, and the windows together the
 * whole call's toggles (got_tog[0..n), as sorted multisets). */
static uint32_t win_tog[MAXTOG], all_tog[MAXTOG];

static void windows(const rast_point *p, int k, int h, int w, size_t n)
{
    uint64_t first = 0, top = (uint64_t)h * (uint64_t)(w ? w : 300) + (uint64_t)h + 1;
    size_t at = 0, got, i;
    while (first < top) {
        uint64_t end = first + 1 + rng() % (rng() % 2 ? 3u : (uint32_t)(top / 4 + 1));
        if (rng() % 16 == 0) end = first + ((uint64_t)1 << 40); /* a huge window */
        got = 0;
        CHECK(rast_coco_ring_toggles_in(p, (uint32_t)k, h, w, first, end, win_tog, MAXTOG, &got) == RAST_OK);
        if (got) {
            size_t again = 0;
            win_tog[got - 1] = 0xDEADBEEFu;
            CHECK(rast_coco_ring_toggles_in(p, (uint32_t)k, h, w, first, end, win_tog, got - 1, &again) ==
                      RAST_E_SCRATCH &&
                  again == got && win_tog[got - 1] == 0xDEADBEEFu);
            CHECK(rast_coco_ring_toggles_in(p, (uint32_t)k, h, w, first, end, win_tog, got, &again) == RAST_OK);
        }
        for (i = 0; i < got && at < MAXTOG; i++) {
            /* positions are below 2^32 here: no wrap to undo */
            CHECK(win_tog[i] >= first && win_tog[i] < end);
            all_tog[at++] = win_tog[i];
        }
        first = end;
    }
    CHECK(rast_coco_ring_toggles_in(p, (uint32_t)k, h, w, 5, 5, NULL, 0, &got) == RAST_OK && got == 0);
    CHECK(at == n);
    if (at != n) return;
    memcpy(win_tog, got_tog, n * sizeof *win_tog);
    qsort(win_tog, n, sizeof *win_tog, cmp_u32);
    qsort(all_tog, n, sizeof *all_tog, cmp_u32);
    CHECK(memcmp(win_tog, all_tog, n * sizeof *win_tog) == 0);
}

static void one_ring(int range, int h, int w)
{
    rast_point p[MAXPTS];
    int k = 1 + (int)(rng() % MAXPTS), i;
    long nref;
    size_t ngot = 0, mref, mgot = 0;
    for (i = 0; i < k; i++) {
        p[i].x = (int32_t)(rng() % (uint32_t)(2 * range + 1)) - range + 5 * w / 2;
        p[i].y = (int32_t)(rng() % (uint32_t)(2 * range + 1)) - range + 5 * h / 2;
        if (i && rng() % 8 == 0) p[i] = p[i - 1]; /* repeated points */
    }
    nref = reference(p, k, h, w, ref_tog);
    if (nref < 0) return;
    CHECK(rast_coco_ring_toggles(p, (uint32_t)k, h, w, got_tog, MAXTOG, &ngot) == RAST_OK);
    CHECK(ngot == (size_t)nref);
    if (ngot != (size_t)nref) return;
    windows(p, k, h, w, ngot);
    mref = reference_rle(ref_tog, ngot, (uint32_t)(h * w), ref_cnt);
    CHECK(rast_coco_rle(got_tog, ngot, (uint32_t)(h * w), work, got_cnt, &mgot) == RAST_OK);
    CHECK(mgot == mref && memcmp(got_cnt, ref_cnt, mref * sizeof *ref_cnt) == 0);
}

static void test_errors(void)
{
    rast_point p[3] = {{0, 0}, {50, 0}, {0, 50}};
    size_t n = 99;
    uint32_t t[4];
    CHECK(rast_coco_ring_toggles(p, 3, 10, 10, t, 0, &n) == RAST_E_SCRATCH && n == 20);
    CHECK(rast_coco_ring_toggles(p, 3, 10, 10, NULL, 0, NULL) == RAST_E_NULL);
    CHECK(rast_coco_ring_toggles(NULL, 3, 10, 10, NULL, 0, &n) == RAST_E_NULL);
    CHECK(rast_coco_ring_toggles(p, 3, -1, 10, NULL, 0, &n) == RAST_E_SIZE);
    CHECK(rast_coco_ring_toggles(p, 3, 70000, 70000, NULL, 0, &n) == RAST_E_SIZE);
    p[1].x = RAST_COCO_COORD_MAX + 1;
    CHECK(rast_coco_ring_toggles(p, 3, 10, 10, NULL, 0, &n) == RAST_E_RANGE);
    p[1].x = -RAST_COCO_COORD_MAX;
    CHECK(rast_coco_ring_toggles(p, 3, 10, 10, NULL, 0, &n) == RAST_OK);
    CHECK(rast_coco_ring_toggles(p, 0, 10, 10, NULL, 0, &n) == RAST_OK && n == 0);
    CHECK(rast_coco_rle(NULL, 0, 100, NULL, t, &n) == RAST_OK && n == 1 && t[0] == 100);
    CHECK(rast_coco_rle(NULL, 1, 100, work, t, &n) == RAST_E_NULL);
}

int main(void)
{
    int i;
    for (i = 0; i < check_count(3000); i++) one_ring(12, 4, 5);            /* dense ties */
    for (i = 0; i < check_count(3000); i++) one_ring(60, 13, 11);
    for (i = 0; i < check_count(1000); i++) one_ring(400, 1 + (int)(rng() % 90), 1 + (int)(rng() % 90));
    for (i = 0; i < check_count(200); i++) one_ring(40000, 50, 60);       /* far past the edges */
    for (i = 0; i < check_count(200); i++) one_ring(30, 7, 0);             /* width 0, as pycocotools */
    test_errors();
    return check_report("test_coco");
}

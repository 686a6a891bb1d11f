/*
 * test_path.c - rast_path_flatten: bad input refused with nothing written,
 * the edge count of rastrum.h's formula (and no fewer edges would keep
 * the bound), the bound itself on random quadratics and cubics (the curve
 * sampled densely against the polyline, both ways), the range limits
 * (128-bit evaluation), subpaths and CLOSE, and a flattened circle filled
 * by the polygon fillers.  The exact check in rational arithmetic is
 * tests/test_path.py; here long double squared distances with a margin
 * of 1e-9 of a unit squared, far below the rounding the bound accounts
 * for (no libm: the tests link none).
 */
#include <string.h>

#include "check.h"
#include "curve_ref.h"
#include "rastrum.h"

#define MAXP 200000
static rast_point pts[MAXP];
static uint32_t rings[1024];

/* Flatten one curve from q[0]; check the bound by sampling both ways. */
static void check_curve(const rast_point *q, int d, int32_t tol, int samples)
{
    uint8_t verbs[2] = {RAST_PATH_MOVE, (uint8_t)d};
    rast_path path;
    rast_polygon poly;
    uint32_t np = 0, nr = 0, i, j;
    long double worst = 0;
    path.verbs = verbs;
    path.nverbs = 2;
    path.points = q;
    path.npoints = (uint32_t)d + 1;
    CHECK(rast_path_flatten_size(&path, tol, &np, &nr) == RAST_OK);
    CHECK(nr == 1 && np == 1 + ref_edges(q, d, tol));
    if (np > MAXP) return;
    CHECK(rast_path_flatten(&path, tol, pts, MAXP, rings, 1024, &poly) == RAST_OK);
    CHECK(poly.nrings == 1 && rings[0] == np && poly.points == pts);
    CHECK(pts[0].x == q[0].x && pts[0].y == q[0].y && pts[np - 1].x == q[d].x && pts[np - 1].y == q[d].y);
    /* curve -> polyline: each sample near the edge of its parameter span */
    for (j = 0; j <= (uint32_t)samples; j++) {
        long double t = (long double)j / samples, x, y, best;
        uint32_t e = (uint32_t)(t * (np - 1));
        if (e >= np - 1) e = np - 2;
        ref_bezier(q, d, t, &x, &y);
        best = ref_seg_d2(x, y, pts[e], pts[e + 1]);
        if (best > worst) worst = best;
    }
    /* polyline -> curve: each vertex and edge midpoint near the curve at
     * its own parameter (the proof's correspondence) */
    for (i = 0; i + 1 < np; i++) {
        long double t = ((long double)i + 0.5L) / (np - 1), x, y, mx, my, dist;
        ref_bezier(q, d, t, &x, &y);
        mx = ((long double)pts[i].x + pts[i + 1].x) / 2;
        my = ((long double)pts[i].y + pts[i + 1].y) / 2;
        dist = (x - mx) * (x - mx) + (y - my) * (y - my);
        if (dist > worst) worst = dist;
    }
    CHECK(worst <= (long double)tol * tol + 1e-9L);
    if (!(worst <= (long double)tol * tol + 1e-9L))
        fprintf(stderr, "  d=%d tol=%d edges=%u worst^2=%Lg\n", d, (int)tol, np - 1, worst);
}

static int32_t rnd_coord(int32_t lim) { return (int32_t)(rng() % (2u * (uint32_t)lim + 1)) - lim; }

static void test_bad_input(void)
{
    uint8_t verbs[4] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_CUBIC, RAST_PATH_CLOSE};
    rast_point q[5] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {50, 50}};
    rast_path p = {verbs, 4, q, 5};
    rast_polygon poly = {NULL, NULL, 77};
    uint32_t np = 7, nr = 7, before = 0xdeadbeef;
    CHECK(rast_path_flatten_size(NULL, 4, &np, &nr) == RAST_E_NULL);
    CHECK(rast_path_flatten_size(&p, 4, NULL, &nr) == RAST_E_NULL);
    CHECK(rast_path_flatten_size(&p, 0, &np, &nr) == RAST_E_ARG);
    CHECK(rast_path_flatten_size(&p, -1, &np, &nr) == RAST_E_ARG);
    CHECK(rast_path_flatten_size(&p, RAST_COORD_MAX + 1, &np, &nr) == RAST_E_ARG);
    p.npoints = 4;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_ARG);
    p.npoints = 6;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_ARG);
    p.npoints = 5;
    verbs[0] = RAST_PATH_LINE;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_ARG);
    verbs[0] = RAST_PATH_MOVE;
    verbs[3] = RAST_PATH_VERB_COUNT_;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_ARG);
    verbs[3] = RAST_PATH_CLOSE;
    q[3].x = RAST_COORD_MAX + 1;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_RANGE);
    q[3].x = -RAST_COORD_MAX - 1;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_E_RANGE);
    CHECK(np == 7 && nr == 7);
    q[3].x = 0;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_OK);
    CHECK(nr == 1 && np > 3);
    /* too small: nothing written */
    pts[0].x = 12345;
    rings[0] = before;
    CHECK(rast_path_flatten(&p, 4, pts, np - 1, rings, 1, &poly) == RAST_E_SCRATCH);
    CHECK(rast_path_flatten(&p, 4, pts, np, rings, 0, &poly) == RAST_E_SCRATCH);
    CHECK(rast_path_flatten(&p, 4, NULL, np, rings, 1, &poly) == RAST_E_NULL);
    CHECK(rast_path_flatten(&p, 4, pts, np, rings, 1, NULL) == RAST_E_NULL);
    CHECK(pts[0].x == 12345 && rings[0] == before && poly.nrings == 77);
    CHECK(rast_path_flatten(&p, 4, pts, np, rings, 1, &poly) == RAST_OK);
    CHECK(poly.nrings == 1 && rings[0] == np);
    /* the empty path */
    p.nverbs = 0;
    p.npoints = 0;
    p.points = NULL;
    CHECK(rast_path_flatten_size(&p, 4, &np, &nr) == RAST_OK && np == 0 && nr == 0);
    CHECK(rast_path_flatten(&p, 4, pts, 0, rings, 0, &poly) == RAST_OK && poly.nrings == 0);
}

static void test_subpaths(void)
{
    /* M L L Z L L Z M Q: the L after Z starts at the first start */
    uint8_t verbs[9] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE, RAST_PATH_CLOSE,
                        RAST_PATH_LINE, RAST_PATH_LINE, RAST_PATH_CLOSE, RAST_PATH_MOVE,
                        RAST_PATH_QUAD};
    rast_point q[8] = {{10, 10}, {20, 10}, {20, 20}, {0, 10}, {0, 0}, {5, 5}, {8, 5}, {11, 5}};
    rast_path p = {verbs, 9, q, 8};
    rast_polygon poly;
    uint32_t np, nr;
    CHECK(rast_path_flatten_size(&p, 1, &np, &nr) == RAST_OK);
    CHECK(nr == 3 && np == 3 + 3 + 2);
    CHECK(rast_path_flatten(&p, 1, pts, MAXP, rings, 1024, &poly) == RAST_OK);
    CHECK(rings[0] == 3 && rings[1] == 3 && rings[2] == 2);
    CHECK(pts[3].x == 10 && pts[3].y == 10 && pts[4].x == 0 && pts[4].y == 10);
    CHECK(pts[7].x == 11 && pts[7].y == 5); /* a straight quadratic: one edge */
}

static void test_random_bound(void)
{
    int k, count = check_count(400);
    for (k = 0; k < count; k++) {
        rast_point q[4];
        int d = 2 + (int)(rng() % 2), j;
        int32_t lim = (int32_t[]){64, 4096, 1 << 20, RAST_COORD_MAX}[rng() % 4];
        int32_t tol = (int32_t[]){1, 2, 3, 16, 64, 256, 1000}[rng() % 7];
        for (j = 0; j <= d; j++) {
            q[j].x = rnd_coord(lim);
            q[j].y = rnd_coord(lim);
        }
        switch (rng() % 6) {
        case 0: q[1] = q[0]; break;          /* coincident control points */
        case 1: q[d] = q[0]; break;          /* closed loop */
        case 2: q[1] = q[d - 1] = q[d]; break;
        case 3: /* cusp-like: controls crossed */
            if (d == 3) { rast_point t = q[1]; q[1] = q[3]; q[3] = t; }
            break;
        default: break;
        }
        if (lim == RAST_COORD_MAX && tol < 64) tol = 64; /* keep the sampled cases quick */
        check_curve(q, d, tol, 4000);
    }
}

static void test_limits(void)
{
    /* The largest second differences at tolerance 1: 128-bit evaluation;
     * the count must stay under 47,727 (rastrum.h) and the vertices in
     * range and on the curve. */
    const int32_t M = RAST_COORD_MAX;
    rast_point c1[4] = {{-M, -M}, {M, M}, {-M, -M}, {M, M}};
    rast_point c2[4] = {{-M, M}, {M, -M}, {-M, M}, {M, -M}};
    rast_point qd[3] = {{-M, -M}, {M, M}, {-M, -M}};
    rast_point tiny[4] = {{M, M}, {M, M}, {M, M}, {M, M}};
    uint8_t verbs[2] = {RAST_PATH_MOVE, RAST_PATH_CUBIC};
    rast_path p = {verbs, 2, c1, 4};
    uint32_t np, nr, i;
    CHECK(rast_path_flatten_size(&p, 1, &np, &nr) == RAST_OK);
    CHECK(np - 1 <= 47726 && np - 1 > 1024);
    check_curve(c1, 3, 1, 200000);
    check_curve(c2, 3, 1, 200000);
    check_curve(qd, 2, 1, 200000);
    check_curve(tiny, 3, 1, 10);
    p.points = c2;
    CHECK(rast_path_flatten(&p, 1, pts, MAXP, rings, 1, NULL) == RAST_E_NULL);
    for (i = 0; i < np && i < MAXP; i++)
        CHECK(pts[i].x >= -M && pts[i].x <= M && pts[i].y >= -M && pts[i].y <= M);
    /* each cubic count just around the int64/128-bit switch */
    for (i = 0; i < 60; i++) {
        rast_point q[4] = {{0, 0}, {0, 0}, {0, 0}, {0, 0}};
        q[1].x = (int32_t)(200000 + 3000 * i);
        q[2].y = (int32_t)(100000 + 7 * i);
        q[3].x = 5;
        check_curve(q, 3, 1, 20000);
    }
}

/* No smaller count keeps step 4's condition c M <= n^2 (4T - 3) with the
 * exact M: the formula gives the least n, up to the ceil of sqrt(dd). */
static void test_minimal(void)
{
    int k;
    for (k = 0; k < check_count(2000); k++) {
        rast_point q[4];
        int d = 2 + (int)(rng() % 2), j;
        int32_t tol = 1 + (int32_t)(rng() % 300);
        uint32_t n;
        long double dd = 0, c = d == 3 ? 3 : 1, rhs;
        for (j = 0; j <= d; j++) {
            q[j].x = rnd_coord(100000);
            q[j].y = rnd_coord(100000);
        }
        n = ref_edges(q, d, tol);
        for (j = 0; j + 2 <= d; j++) {
            long double dx = (long double)q[j].x - 2.0L * q[j + 1].x + q[j + 2].x;
            long double dy = (long double)q[j].y - 2.0L * q[j + 1].y + q[j + 2].y;
            long double s = dx * dx + dy * dy;
            if (s > dd) dd = s;
        }
        /* c^2 M^2 <= (n^2 (4T - 3))^2, both sides exact in long double */
        rhs = (long double)n * n * (4.0L * tol - 3);
        CHECK(c * c * dd <= rhs * rhs);
        /* n - 1 fails even with M rounded up to the next integer, m + 1 */
        if (n > 1) {
            long double m1 = (long double)ref_isqrt((uint64_t)dd) + 1;
            rhs = (long double)(n - 1) * (n - 1) * (4.0L * tol - 3);
            CHECK(c * m1 > rhs);
        }
    }
}

/* A circle of radius r from four cubics (kappa 0.5523), filled: its area
 * within the bound's band of pi r^2. */
static void test_circle_fill(void)
{
    const int32_t r = 200 * 16, cx = 256 * 16, cy = 256 * 16, kk = (int32_t)(0.5522847498 * r);
    rast_point q[13] = {{cx + r, cy},      {cx + r, cy + kk}, {cx + kk, cy + r}, {cx, cy + r},
                        {cx - kk, cy + r}, {cx - r, cy + kk}, {cx - r, cy},      {cx - r, cy - kk},
                        {cx - kk, cy - r}, {cx, cy - r},      {cx + kk, cy - r}, {cx + r, cy - kk},
                        {cx + r, cy}};
    uint8_t verbs[6] = {RAST_PATH_MOVE, RAST_PATH_CUBIC, RAST_PATH_CUBIC, RAST_PATH_CUBIC,
                        RAST_PATH_CUBIC, RAST_PATH_CLOSE};
    rast_path p = {verbs, 6, q, 13};
    rast_polygon poly;
    static uint8_t img[512 * 512];
    static uint64_t scratch[1 << 16];
    rast_target t;
    rast_fill_opts o;
    uint8_t one = 1;
    long area = 0, i;
    int32_t tol = 4; /* 1/4 pixel at S = 4 */
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    o.sample = RAST_SAMPLE_CENTER;
    o.rule = RAST_RULE_NONZERO;
    CHECK(rast_path_flatten(&p, tol, pts, MAXP, rings, 1024, &poly) == RAST_OK);
    CHECK(rast_target_init(&t, img, 512, 512, 512, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_fill_polygon(&t, &poly, &o, &one, scratch, sizeof scratch) == RAST_OK);
    for (i = 0; i < 512 * 512; i++) area += img[i];
    /* inside r - 1/4 - curve error of the kappa fit (0.03%) and the
     * samples' granularity: a generous ring of 2 pixels each side */
    {
        double diff = (double)area - 3.14159265 * 200 * 200;
        CHECK(diff < 2 * 3.1416 * 200 * 2 && diff > -2 * 3.1416 * 200 * 2);
    }
}

int main(void)
{
    test_bad_input();
    test_subpaths();
    test_minimal();
    test_random_bound();
    test_limits();
    test_circle_fill();
    return check_report("test_path");
}

/*
 * test_stroke.c - rast_path_stroke: bad input refused with nothing
 * written; a segment's parallelogram, square caps and a right angle's
 * miter exactly; the miter limit at SVG's ratio; the offsets rounded to
 * nearest (checked against the integer definition); dashes on a straight
 * line exactly, and a dash over a vertex keeping its join; zero-length
 * subpaths; round joins and caps point by point against a scan of the
 * whole circle; and on random polylines and curves, every join x cap, solid
 * and dashed, rastrum.h's bound at sample points (tests/c/stroke_check.h).
 * The pixel-exact check against an independent referee is
 * tests/test_stroke.py.
 */
#include <string.h>

#include "check.h"
#include "rastrum.h"
#include "stroke_check.h"
#include "stroke_pieces.h"

#define GUARD 0xA5
static uint64_t scratch_mem[1 << 18];
#include "scratch.h"

#define MAXP 100000
static rast_point out[MAXP], flat[MAXP], pout[MAXP];
static uint32_t rings[MAXP / 3], frings[64], prings[MAXP / 3];

static rast_status run(const uint8_t *verbs, uint32_t nv, const rast_point *pts, uint32_t np,
                       const rast_stroke_style *s, uint32_t *onp, uint32_t *onr)
{
    rast_path path;
    rast_polygon poly;
    rast_status st;
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = pts;
    path.npoints = np;
    st = rast_path_stroke_size(&path, s, onp, onr);
    if (st != RAST_OK) return st;
    if (*onp > MAXP || *onr > MAXP / 3) return RAST_E_SCRATCH;
    st = rast_path_stroke(&path, s, out, MAXP, rings, MAXP / 3, &poly);
    if (st == RAST_OK) CHECK(poly.nrings == *onr && poly.points == out);
    return st;
}

static void test_bad_input(void)
{
    static const uint8_t v[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
    static const rast_point p[2] = {{0, 0}, {100, 0}};
    int32_t dneg[2] = {5, -1}, dzero[2] = {0, 0};
    rast_path path = {v, 2, p, 2};
    rast_stroke_style s = sc_style(10, RAST_JOIN_MITER, RAST_CAP_BUTT), b;
    rast_polygon poly = {NULL, NULL, 777};
    uint32_t np = 99, nr = 99;
    CHECK(rast_path_stroke_size(NULL, &s, &np, &nr) == RAST_E_NULL);
    CHECK(rast_path_stroke_size(&path, NULL, &np, &nr) == RAST_E_NULL);
    CHECK(rast_path_stroke_size(&path, &s, NULL, &nr) == RAST_E_NULL);
    b = s; b.width = 0;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.width = RAST_COORD_MAX + 1;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.tolerance = 0;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.join = 3;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.cap = -1;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.miter_limit = 65535;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b = s; b.ndash = 2; b.dash = NULL;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_NULL);
    b.dash = dneg;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    b.dash = dzero;
    CHECK(rast_path_stroke_size(&path, &b, &np, &nr) == RAST_E_ARG);
    CHECK(np == 99 && nr == 99);
    {
        rast_point far[2] = {{RAST_COORD_MAX - 100, 0}, {RAST_COORD_MAX, 0}};
        rast_path fpath = {v, 2, far, 2};
        b = s; b.cap = RAST_CAP_SQUARE; /* the outline leaves the range */
        CHECK(rast_path_stroke_size(&fpath, &b, &np, &nr) == RAST_E_RANGE);
        CHECK(rast_path_stroke(&fpath, &b, out, MAXP, rings, 100, &poly) == RAST_E_RANGE);
        b.cap = RAST_CAP_BUTT;
        CHECK(rast_path_stroke_size(&fpath, &b, &np, &nr) == RAST_OK);
    }
    CHECK(rast_path_stroke_size(&path, &s, &np, &nr) == RAST_OK && np == 4 && nr == 1);
    CHECK(rast_path_stroke(&path, &s, out, 3, rings, 1, &poly) == RAST_E_SCRATCH);
    CHECK(rast_path_stroke(&path, &s, out, 4, rings, 0, &poly) == RAST_E_SCRATCH);
    CHECK(rast_path_stroke(&path, &s, NULL, 4, rings, 1, &poly) == RAST_E_NULL);
    CHECK(poly.nrings == 777);
    path.npoints = 1; /* the path's own errors */
    CHECK(rast_path_stroke_size(&path, &s, &np, &nr) == RAST_E_ARG);
}

static int ring_is(uint32_t base, const int32_t *xy, uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++)
        if (out[base + k].x != xy[2 * k] || out[base + k].y != xy[2 * k + 1]) return 0;
    return 1;
}

static void test_exact_rings(void)
{
    static const uint8_t v2[2] = {RAST_PATH_MOVE, RAST_PATH_LINE}, v3[3] = {0, 1, 1};
    static const rast_point seg[2] = {{0, 0}, {160, 0}}, ell[3] = {{0, 0}, {160, 0}, {160, 160}};
    static const int32_t rect[8] = {0, -16, 160, -16, 160, 16, 0, 16};
    /* right side forward, the end's cap, left side back, the start's cap */
    static const int32_t squared[16] = {0, -16, 160, -16, 176, -16, 176, 16, 160, 16, 0, 16, -16, 16, -16, -16};
    /* a left turn: the miter's tip on the right (outer) side, the pivot
     * (160, 0) on the left (inner) one */
    static const int32_t mitred[20] = {0, -16, 160, -16, 176, -16, 176, 0, 176, 160,
                                       144, 160, 144, 0, 160, 0, 160, 16, 0, 16};
    static const int32_t bevelled[18] = {0, -16, 160, -16, 176, 0, 176, 160,
                                         144, 160, 144, 0, 160, 0, 160, 16, 0, 16};
    rast_stroke_style s = sc_style(32, RAST_JOIN_MITER, RAST_CAP_BUTT);
    uint32_t np, nr;
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 1 && np == 4 && ring_is(0, rect, 4));
    s.cap = RAST_CAP_SQUARE;
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 1 && np == 8 && ring_is(0, squared, 8));
    s.cap = RAST_CAP_BUTT;
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np == 10 && ring_is(0, mitred, 10));
    s.miter_limit = 92680; /* 1.41419 < sqrt(2) = 1.41421: bevelled */
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np == 9 && ring_is(0, bevelled, 9));
    s.miter_limit = 92682; /* 1.41422 */
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np == 10 && ring_is(0, mitred, 10));
    s.join = RAST_JOIN_BEVEL;
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np == 9 && ring_is(0, bevelled, 9));
    s.join = RAST_JOIN_ROUND;
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np > 10);
}

/* The offset of a segment (0,0)-(dx,dy) at width w against its definition:
 * |o.x| = c with (2c - 1)^2 L2 <= w^2 dy^2 < (2c + 1)^2 L2 (rounded to
 * nearest, halves up), integers only. */
static void test_offsets_rounded(void)
{
    static const uint8_t v2[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
    int i;
    for (i = 0; i < check_count(3000); i++) {
        rast_point p[2];
        rast_stroke_style s = sc_style(1 + (int32_t)(rng() % 4000), RAST_JOIN_MITER, RAST_CAP_BUTT);
        uint32_t np, nr;
        int64_t dx = (int64_t)(rng() % 20001) - 10000, dy = (int64_t)(rng() % 20001) - 10000, l2, w, ox, oy, a;
        if (!dx && !dy) continue;
        p[0].x = p[0].y = 0;
        p[1].x = (int32_t)dx;
        p[1].y = (int32_t)dy;
        CHECK(run(v2, 2, p, 2, &s, &np, &nr) == RAST_OK && nr == 1 && np == 4);
        /* ring: a - o first */
        ox = -out[0].x;
        oy = -out[0].y;
        l2 = dx * dx + dy * dy;
        w = s.width;
        a = ox < 0 ? -ox : ox;
        CHECK((2 * a - 1) * (2 * a - 1) * l2 <= w * w * dy * dy || a == 0);
        CHECK(w * w * dy * dy < (2 * a + 1) * (2 * a + 1) * l2);
        a = oy < 0 ? -oy : oy;
        CHECK((2 * a - 1) * (2 * a - 1) * l2 <= w * w * dx * dx || a == 0);
        CHECK(w * w * dx * dx < (2 * a + 1) * (2 * a + 1) * l2);
        CHECK((ox == 0 || (ox < 0) == (-dy < 0)) && (oy == 0 || (oy < 0) == (dx < 0)));
    }
}

static void test_dashes_exact(void)
{
    static const uint8_t v2[2] = {RAST_PATH_MOVE, RAST_PATH_LINE}, v3[3] = {0, 1, 1};
    static const rast_point seg[2] = {{0, 0}, {1000, 0}}, ell[3] = {{0, 0}, {160, 0}, {160, 160}};
    int32_t d[2] = {100, 50}, one[1] = {40}, dots[2] = {0, 250};
    rast_stroke_style s = sc_style(20, RAST_JOIN_MITER, RAST_CAP_BUTT);
    uint32_t np, nr, k;
    s.dash = d;
    s.ndash = 2;
    s.dash_offset = 30; /* on 70, off 50, on 100, ... */
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 7);
    CHECK(out[0].x == 0 && out[1].x == 70 && out[4].x == 120 && out[5].x == 220);
    CHECK(out[4 * 6].x == 870 && out[4 * 6 + 1].x == 970); /* then off from 970 past the end */
    s.ndash = 1; /* odd: {40} is {40, 40} */
    s.dash = one;
    s.dash_offset = 0;
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 13);
    s.dash = d; /* one dash over the corner: the join kept, as solid */
    s.ndash = 2;
    d[0] = 400;
    d[1] = 10;
    s.dash_offset = 0;
    CHECK(run(v3, 3, ell, 3, &s, &np, &nr) == RAST_OK && nr == 1 && np == 10); /* the solid L's ring */
    s.cap = RAST_CAP_ROUND; /* zero-length dashes: dots every 250 */
    s.dash = dots;
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 5);
    for (k = 0; k < nr; k++) CHECK(rings[k] > 8);
    s.cap = RAST_CAP_BUTT; /* and nothing with butt caps */
    CHECK(run(v2, 2, seg, 2, &s, &np, &nr) == RAST_OK && nr == 0);
}

static void test_zero_length(void)
{
    static const uint8_t mz[2] = {RAST_PATH_MOVE, RAST_PATH_CLOSE}, mm[2] = {0, 0}, ml[2] = {0, 1};
    static const rast_point p[2] = {{50, 50}, {50, 50}};
    rast_stroke_style s = sc_style(40, RAST_JOIN_MITER, RAST_CAP_ROUND);
    uint32_t np, nr;
    CHECK(run(mz, 2, p, 1, &s, &np, &nr) == RAST_OK && nr == 1 && np > 8);
    CHECK(run(ml, 2, p, 2, &s, &np, &nr) == RAST_OK && nr == 1 && np > 8);
    CHECK(run(mm, 2, p, 2, &s, &np, &nr) == RAST_OK && nr == 0); /* MOVE alone: nothing */
    s.cap = RAST_CAP_SQUARE;
    CHECK(run(ml, 2, p, 2, &s, &np, &nr) == RAST_OK && nr == 1 && np == 4 && out[0].x == 30 && out[0].y == 30);
    s.cap = RAST_CAP_BUTT;
    CHECK(run(ml, 2, p, 2, &s, &np, &nr) == RAST_OK && nr == 0);
}

/* Random polylines with turns, crossings, tiny and zero-length segments,
 * curves and closes: the bound at sample points, every join x cap. */
static void test_random_bound(void)
{
    int i;
    for (i = 0; i < check_count(600); i++) {
        uint8_t verbs[8];
        rast_point pts[24];
        int32_t dash[3];
        uint32_t nv = 2 + rng() % 6, np = 0, k, onp, onr, fnp, fnr;
        rast_stroke_style s = sc_style(1 + (int32_t)(rng() % 200), (int)(rng() % 3), (int)(rng() % 3));
        rast_path path;
        rast_polygon fpoly;
        sc_path fp;
        s.tolerance = 1 + (int32_t)(rng() % 8);
        s.miter_limit = 65536 + (int32_t)(rng() % (6 * 65536));
        if (rng() % 2) {
            s.ndash = 1 + rng() % 3;
            for (k = 0; k < s.ndash; k++) dash[k] = (int32_t)(rng() % 300);
            dash[0] += 1;
            s.dash = dash;
            s.dash_offset = (int32_t)(rng() % 600) - 300;
        }
        verbs[0] = RAST_PATH_MOVE;
        pts[np].x = (int32_t)(rng() % 800);
        pts[np++].y = (int32_t)(rng() % 800);
        for (k = 1; k < nv; k++) {
            uint32_t r = rng() % 16, j, take;
            verbs[k] = r < 9 ? RAST_PATH_LINE : r < 11 ? RAST_PATH_QUAD : r < 13 ? RAST_PATH_CUBIC
                       : r < 15 ? RAST_PATH_CLOSE : RAST_PATH_MOVE;
            take = verbs[k] == RAST_PATH_CLOSE ? 0 : verbs[k] == RAST_PATH_MOVE ? 1 : verbs[k];
            for (j = 0; j < take; j++) {
                if (rng() % 8 == 0) { /* tiny or zero */
                    pts[np].x = pts[np - 1].x + (int32_t)(rng() % 3) - 1;
                    pts[np].y = pts[np - 1].y + (int32_t)(rng() % 3) - 1;
                } else {
                    pts[np].x = (int32_t)(rng() % 800);
                    pts[np].y = (int32_t)(rng() % 800);
                }
                np++;
            }
        }
        CHECK(run(verbs, nv, pts, np, &s, &onp, &onr) == RAST_OK);
        CHECK(sc_area_nonneg(out, rings, onr));
        path.verbs = verbs;
        path.nverbs = nv;
        path.points = pts;
        path.npoints = np;
        CHECK(rast_path_flatten(&path, s.tolerance, flat, MAXP, frings, 64, &fpoly) == RAST_OK);
        CHECK(rast_path_flatten_size(&path, s.tolerance, &fnp, &fnr) == RAST_OK);
        fp.pts = flat;
        fp.sizes = frings;
        fp.nrings = fnr;
        for (k = 0; k < 40; k++) {
            rast_point c = flat[rng() % fnp];
            int32_t reach = s.width * 3 + 4;
            int32_t x = c.x + (int32_t)(rng() % (uint32_t)(2 * reach + 1)) - reach;
            int32_t y = c.y + (int32_t)(rng() % (uint32_t)(2 * reach + 1)) - reach;
            CHECK(sc_check_point(&fp, out, rings, onr, &s, x, y));
        }
    }
}

/* Round joins and caps: the arc points are exactly the circle's points
 * (stroke.c's definition, scanned all round here: m from the width and
 * tolerance, h ((m^2 - k^2), 2 k m) / (m^2 + k^2) rounded to nearest and
 * its quarter turns) strictly inside the sweep from s to e, each
 * advancing in angle, in counter-clockwise order. */
static int64_t rp_div(int64_t num, int64_t den) /* floor(num / den + 1/2), den > 0 */
{
    int64_t n = 2 * num + den, d = 2 * den;
    return n >= 0 ? n / d : -((-n + d - 1) / d);
}

static int64_t rp_cross(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    return ax * by - ay * bx;
}

static void rp_point(int64_t w, int64_t m, int64_t j, int64_t *x, int64_t *y)
{
    int64_t k = j % m, den = 2 * (m * m + k * k);
    int64_t px = rp_div(w * (m * m - k * k), den), py = rp_div(w * 2 * k * m, den);
    switch ((j / m) & 3) {
    case 0: *x = px; *y = py; break;
    case 1: *x = -py; *y = px; break;
    case 2: *x = -px; *y = -py; break;
    default: *x = py; *y = -px; break;
    }
}

/* The ring's points from *at on: the scan's points strictly inside the
 * sweep from s to e about (cx, cy), counter-clockwise, each advancing in
 * angle (the scan starting after a point outside the sweep). */
static int rp_arc(uint32_t *at, uint32_t end, int64_t cx, int64_t cy, int64_t sx, int64_t sy, int64_t ex,
                  int64_t ey, int64_t w, int64_t m)
{
    int64_t j, j0 = -1, lx = sx, ly = sy;
    for (j = 0; j < 4 * m && j0 < 0; j++) {
        int64_t x, y;
        rp_point(w, m, j, &x, &y);
        if (!(rp_cross(sx, sy, x, y) > 0 && rp_cross(x, y, ex, ey) > 0)) j0 = j;
    }
    for (j = 1; j <= 4 * m; j++) {
        int64_t x, y;
        rp_point(w, m, (j0 + j) % (4 * m), &x, &y);
        if (rp_cross(sx, sy, x, y) > 0 && rp_cross(x, y, ex, ey) > 0 && rp_cross(lx, ly, x, y) > 0) {
            if (*at >= end || out[*at].x != cx + x || out[*at].y != cy + y) return 0;
            (*at)++;
            lx = x;
            ly = y;
        }
    }
    return 1;
}

static int rp_pt(uint32_t *at, uint32_t end, int64_t x, int64_t y)
{
    if (*at >= end || out[*at].x != x || out[*at].y != y) return 0;
    (*at)++;
    return 1;
}

/* The offset o = N(b - a): a - o is the first point of a segment's ring. */
static void rp_offset(rast_point a, rast_point b, const rast_stroke_style *s0, int64_t *ox, int64_t *oy)
{
    static const uint8_t v2[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
    rast_point p[2];
    rast_stroke_style s = *s0;
    uint32_t np, nr;
    p[0] = a;
    p[1] = b;
    s.cap = RAST_CAP_BUTT;
    CHECK(run(v2, 2, p, 2, &s, &np, &nr) == RAST_OK && np == 4);
    *ox = a.x - out[0].x;
    *oy = a.y - out[0].y;
}

/* Three points, round joins and caps: one ring, right side forward, the
 * end's cap, left side back, the start's cap; the join's arc on the outer
 * side, the pivot on the inner one; every arc exactly the circle's points
 * in its sweep. */
static void test_round_points(void)
{
    static const uint8_t v3[3] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE};
    int i;
    for (i = 0; i < check_count(3000); i++) {
        rast_point p[3];
        rast_stroke_style s = sc_style(1 + (int32_t)(rng() % 5000), RAST_JOIN_ROUND, RAST_CAP_ROUND);
        int64_t w = s.width, m, need, o1x, o1y, o2x, o2y, t, dot, vx, vy;
        uint32_t np, nr, at = 0;
        int turn_back = rng() % 4 == 0, pivot_r = 0, pivot_l = 0;
        s.tolerance = 1 + (int32_t)(rng() % (rng() % 2 ? 4 : 300));
        need = (w + 4 * (int64_t)s.tolerance - 4) / (4 * (int64_t)s.tolerance - 3);
        for (m = 1; m * m < need; m++) continue;
        if (m > w / 4) m = w / 4;
        if (m < 1) m = 1;
        for (at = 0; at < 3; at++) {
            p[at].x = 10000 + (int32_t)(rng() % 8000);
            p[at].y = 10000 + (int32_t)(rng() % 8000);
        }
        at = 0;
        if (turn_back) { /* straight back along the segment: a half disc */
            p[2].x = p[1].x - (p[1].x - p[0].x) / 2;
            p[2].y = p[1].y - (p[1].y - p[0].y) / 2;
        }
        if ((p[0].x == p[1].x && p[0].y == p[1].y) || (p[1].x == p[2].x && p[1].y == p[2].y)) continue;
        rp_offset(p[0], p[1], &s, &o1x, &o1y);
        rp_offset(p[1], p[2], &s, &o2x, &o2y);
        if ((!o1x && !o1y) || (!o2x && !o2y)) continue;
        vx = p[1].x;
        vy = p[1].y;
        t = rp_cross(p[1].x - p[0].x, p[1].y - p[0].y, p[2].x - p[1].x, p[2].y - p[1].y);
        dot = (int64_t)(p[1].x - p[0].x) * (p[2].x - p[1].x) + (int64_t)(p[1].y - p[0].y) * (p[2].y - p[1].y);
        if (t > 0 && rp_cross(-o1x, -o1y, -o2x, -o2y) <= 0 && dot >= 0) pivot_r = 1; /* offsets crossed */
        if (t < 0 && rp_cross(o2x, o2y, o1x, o1y) <= 0 && dot >= 0) pivot_l = 1;
        CHECK(run(v3, 3, p, 3, &s, &np, &nr) == RAST_OK && nr == 1 && rings[0] == np);
        CHECK(rp_pt(&at, np, p[0].x - o1x, p[0].y - o1y) && rp_pt(&at, np, vx - o1x, vy - o1y));
        if (t > 0 && !pivot_r)
            CHECK(rp_arc(&at, np, vx, vy, -o1x, -o1y, -o2x, -o2y, w, m));
        else if (t == 0)
            CHECK(rp_arc(&at, np, vx, vy, -o1x, -o1y, o1x, o1y, w, m));
        else
            CHECK(rp_pt(&at, np, vx, vy));
        CHECK(rp_pt(&at, np, vx - o2x, vy - o2y) && rp_pt(&at, np, p[2].x - o2x, p[2].y - o2y));
        CHECK(rp_arc(&at, np, p[2].x, p[2].y, -o2x, -o2y, o2x, o2y, w, m));
        CHECK(rp_pt(&at, np, p[2].x + o2x, p[2].y + o2y) && rp_pt(&at, np, vx + o2x, vy + o2y));
        if (t < 0 && !pivot_l)
            CHECK(rp_arc(&at, np, vx, vy, o2x, o2y, o1x, o1y, w, m));
        else
            CHECK(rp_pt(&at, np, vx, vy));
        CHECK(rp_pt(&at, np, vx + o1x, vy + o1y) && rp_pt(&at, np, p[0].x + o1x, p[0].y + o1y));
        CHECK(rp_arc(&at, np, p[0].x, p[0].y, o1x, o1y, -o1x, -o1y, w, m));
        CHECK(at == np);
    }
}

/* The coverage of an outline (non-zero, 64 x 64 pixels, S = 4). */
static void rq_cover(const rast_polygon *poly, uint32_t np, rast_aa_method method, rast_coverage_format f,
                     void *cov, ptrdiff_t stride)
{
    rast_coverage_opts o;
    rast_rect clip = {0, 0, 64, 64};
    size_t need;
    unsigned char *sc;
    memset(&o, 0, sizeof o);
    o.method = method;
    o.rule = RAST_RULE_NONZERO;
    o.subpixel_bits = 4;
    CHECK(rast_coverage_scratch_size(&o, np, 64, 64, &need) == RAST_OK);
    sc = scratch_for(need);
    CHECK(sc != NULL);
    if (!sc) return;
    CHECK(rast_polygon_coverage(poly, &o, &clip, f, cov, stride, sc, need) == RAST_OK);
    CHECK(scratch_guard_ok(sc, need));
}

/* One ring per subpath (and dash) against the pieces it replaced
 * (tests/c/stroke_pieces.h, the stroker before): on random polylines with
 * self-crossings, tiny segments, exact and near U-turns, straight runs,
 * closes, curves and dashes, every join x cap, the non-zero region is the
 * same: "ss4" and "accumulate" give the same levels bit for bit (the
 * winding numbers are equal everywhere off the cancelling edges,
 * path/stroke.c), "area" the same FIX62 values to 2^-42 (it rounds its
 * crossings to 2^-60, rastrum.h) and so the same levels except where a
 * tie lies between the two (seen in 2 pixels of 2 million). */
static void test_rings_equal_pieces(void)
{
    static uint64_t ca[64 * 64], cb[64 * 64];
    static uint16_t ua[64 * 64], ub[64 * 64];
    uint32_t ties = 0;
    int i;
    for (i = 0; i < check_count(500); i++) {
        uint8_t verbs[16];
        rast_point pts[48];
        int32_t dash[3];
        uint32_t nv = 2 + rng() % 14, np = 0, k, onp = 0, onr = 0, pnp = 0, pnr = 0;
        rast_stroke_style s = sc_style(1 + (int32_t)(rng() % 160), (int)(rng() % 3), (int)(rng() % 3));
        rast_path path;
        rast_polygon ppoly, opoly;
        s.tolerance = 1 + (int32_t)(rng() % 8);
        s.miter_limit = 65536 + (int32_t)(rng() % (6 * 65536));
        if (rng() % 3 == 0) {
            s.ndash = 1 + rng() % 3;
            for (k = 0; k < s.ndash; k++) dash[k] = (int32_t)(rng() % 200);
            dash[0] += 1;
            s.dash = dash;
            s.dash_offset = (int32_t)(rng() % 400) - 200;
        }
        verbs[0] = RAST_PATH_MOVE;
        pts[np].x = 200 + (int32_t)(rng() % 624);
        pts[np++].y = 200 + (int32_t)(rng() % 624);
        for (k = 1; k < nv; k++) {
            uint32_t r = rng() % 20, j, take;
            verbs[k] = r < 14 ? RAST_PATH_LINE : r < 16 ? RAST_PATH_QUAD : r < 17 ? RAST_PATH_CUBIC
                       : r < 19 ? RAST_PATH_CLOSE : RAST_PATH_MOVE;
            take = verbs[k] == RAST_PATH_CLOSE ? 0 : verbs[k] == RAST_PATH_MOVE ? 1 : verbs[k];
            for (j = 0; j < take; j++) {
                rast_point a = pts[np - 1], b = np >= 2 ? pts[np - 2] : pts[np - 1];
                uint32_t how = rng() % 9;
                if (how == 0) { /* tiny or zero */
                    pts[np].x = a.x + (int32_t)(rng() % 3) - 1;
                    pts[np].y = a.y + (int32_t)(rng() % 3) - 1;
                } else if (how == 1) { /* an exact U-turn, back past the previous point or to it */
                    int32_t f = (int32_t)(rng() % 3);
                    pts[np].x = f == 0 ? b.x : a.x + (b.x - a.x) * f / 2;
                    pts[np].y = f == 0 ? b.y : a.y + (b.y - a.y) * f / 2;
                } else if (how == 2) { /* nearly one */
                    pts[np].x = b.x + (int32_t)(rng() % 5) - 2;
                    pts[np].y = b.y + (int32_t)(rng() % 5) - 2;
                } else if (how == 3) { /* straight on */
                    pts[np].x = a.x + (a.x - b.x) / 2;
                    pts[np].y = a.y + (a.y - b.y) / 2;
                } else if (how == 4) { /* nearly: the rounded offsets may cross */
                    pts[np].x = a.x + (a.x - b.x) / 2 + (int32_t)(rng() % 3) - 1;
                    pts[np].y = a.y + (a.y - b.y) / 2 + (int32_t)(rng() % 3) - 1;
                } else {
                    pts[np].x = 200 + (int32_t)(rng() % 624);
                    pts[np].y = 200 + (int32_t)(rng() % 624);
                }
                if (pts[np].x < 180 || pts[np].x > 844) pts[np].x = 512;
                if (pts[np].y < 180 || pts[np].y > 844) pts[np].y = 512;
                np++;
            }
        }
        path.verbs = verbs;
        path.nverbs = nv;
        path.points = pts;
        path.npoints = np;
        CHECK(run(verbs, nv, pts, np, &s, &onp, &onr) == RAST_OK);
        CHECK(sp_path_stroke_size(&path, &s, &pnp, &pnr) == RAST_OK && pnp <= MAXP && pnr <= MAXP / 3);
        CHECK(sp_path_stroke(&path, &s, pout, MAXP, prings, MAXP / 3, &ppoly) == RAST_OK);
        opoly.points = out;
        opoly.ring_sizes = rings;
        opoly.nrings = onr;
        CHECK(onr <= pnr);
        rq_cover(&opoly, onp, RAST_AA_AREA, RAST_COVERAGE_FIX62, ca, 64 * 8);
        rq_cover(&ppoly, pnp, RAST_AA_AREA, RAST_COVERAGE_FIX62, cb, 64 * 8);
        rq_cover(&opoly, onp, RAST_AA_AREA, RAST_COVERAGE_U16, ua, 64 * 2);
        rq_cover(&ppoly, pnp, RAST_AA_AREA, RAST_COVERAGE_U16, ub, 64 * 2);
        for (k = 0; k < 64 * 64; k++) {
            /* "area" rounds its crossings to 2^-60 (rastrum.h): the same
             * region through other edges may differ in the last bits of
             * FIX62, and a level where a tie lies between the two */
            uint64_t d = ca[k] > cb[k] ? ca[k] - cb[k] : cb[k] - ca[k];
            CHECK(d <= ((uint64_t)1 << 20));
            CHECK(ua[k] == ub[k] || ua[k] + 1 == ub[k] || ub[k] + 1 == ua[k]);
            if (ua[k] != ub[k]) ties++;
        }
        rq_cover(&opoly, onp, RAST_AA_SS4, RAST_COVERAGE_U16, ua, 64 * 2);
        rq_cover(&ppoly, pnp, RAST_AA_SS4, RAST_COVERAGE_U16, ub, 64 * 2);
        CHECK(memcmp(ua, ub, sizeof ua) == 0);
        rq_cover(&opoly, onp, RAST_AA_ACCUMULATE, RAST_COVERAGE_U16, ua, 64 * 2);
        rq_cover(&ppoly, pnp, RAST_AA_ACCUMULATE, RAST_COVERAGE_U16, ub, 64 * 2);
        CHECK(memcmp(ua, ub, sizeof ua) == 0);
    }
    CHECK(ties <= 8); /* a handful of the 2 million pixels */
}

int main(void)
{
    test_bad_input();
    test_exact_rings();
    test_offsets_rounded();
    test_dashes_exact();
    test_zero_length();
    test_random_bound();
    test_round_points();
    test_rings_equal_pieces();
    return check_report("test_stroke");
}

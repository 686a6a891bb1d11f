/*
 * test_stroke_compact.c - rastrum.stroke(outline="compact")'s outline
 * (rast__path_stroke_run's flags, path/path.h).  Round parts straddling
 * the circle (RAST__STROKE_ARCS; path/stroke.c, "Round parts straddling
 * the circle"): a whole dot's points one by one within max(tolerance, 2)
 * units of the circle both ways (each vertex, each chord's line), with no
 * more points than the exact circle's.  The inner joins through the
 * meeting point (RAST__STROKE_MEET, "Inner joins"): a right angle's rings
 * exactly, the
 * meeting point on the grid, with a miter, a bevel and round joins; the
 * same at the range limits (offsets of 2^26 - 1, the outline touching
 * +-RAST_COORD_MAX: no overflow, the exact point); the pivot kept where a
 * segment is shorter than the corner's reach (the same outline as without
 * the flag); and on random polylines the count pass equal to the storing
 * pass, never more points than the pivot's outline, and rastrum.h's bound
 * at sample points (tests/c/stroke_check.h).  Pixel by pixel against an
 * independent referee: tests/test_stroke_compact.py.
 */
#include <string.h>

#include "check.h"
#include "path/path.h"
#include "rastrum.h"
#include "stroke_check.h"

#define MAXP 100000
static rast_point out[MAXP], piv[MAXP], flat[MAXP];
static uint32_t rings[MAXP / 3], prings[MAXP / 3], frings[64];

/* The outline with `flags` into o/r: counted, then stored into exactly
 * that room (which must give the same sizes). */
static rast_status run(const uint8_t *verbs, uint32_t nv, const rast_point *pts, uint32_t np, unsigned flags,
                       const rast_stroke_style *s, rast_point *o, uint32_t *r, uint32_t *onp, uint32_t *onr)
{
    rast_path path;
    uint32_t n2 = 0, r2 = 0;
    rast_status st;
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = pts;
    path.npoints = np;
    st = rast__path_stroke_run(&path, s, flags, NULL, 0, NULL, 0, onp, onr);
    if (st != RAST_OK) return st;
    if (*onp > MAXP || *onr > MAXP / 3) return RAST_E_SCRATCH;
    st = rast__path_stroke_run(&path, s, flags, o, *onp, r, *onr, &n2, &r2);
    CHECK(st != RAST_OK || (n2 == *onp && r2 == *onr));
    return st;
}

static int ring_is(const int32_t *xy, uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++)
        if (out[k].x != xy[2 * k] || out[k].y != xy[2 * k + 1]) return 0;
    return 1;
}

static void test_right_angle(void)
{
    static const uint8_t v3[3] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE};
    static const rast_point ell[3] = {{0, 0}, {160, 0}, {160, 160}};
    /* a left turn: the miter's tip on the right (outer) side; the left
     * (inner) side through the offsets' meeting point (144, 16), not
     * through 144,0, 160,0, 160,16 (tests/c/test_stroke.c: "mitred") */
    static const int32_t mitred[16] = {0, -16, 160, -16, 176, -16, 176, 0, 176, 160, 144, 160, 144, 16, 0, 16};
    static const int32_t bevelled[14] = {0, -16, 160, -16, 176, 0, 176, 160, 144, 160, 144, 16, 0, 16};
    rast_stroke_style s = sc_style(32, RAST_JOIN_MITER, RAST_CAP_BUTT);
    uint32_t np, nr, k;
    CHECK(run(v3, 3, ell, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK && nr == 1 && np == 8 &&
          ring_is(mitred, 8));
    s.join = RAST_JOIN_BEVEL;
    CHECK(run(v3, 3, ell, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK && nr == 1 && np == 7 &&
          ring_is(bevelled, 7));
    s.join = RAST_JOIN_ROUND;
    CHECK(run(v3, 3, ell, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK && nr == 1 && np > 8);
    for (k = 0; k < np; k++) /* the inner side: (144, 16) only, no point at the vertex */
        CHECK(!(out[k].x == 160 && out[k].y == 0) && !(out[k].x == 144 && out[k].y == 0));
    CHECK(np > 2 && out[np - 2].x == 144 && out[np - 2].y == 16);
}

/* The same right angle at the range limits: v = (2^26, -2^26), h = 2^26 -
 * 1, so the outline reaches -RAST_COORD_MAX and the meeting point is (1,
 * -1) exactly (64-bit cross products near 2^56, a 128-bit quotient). */
static void test_range_limits(void)
{
    static const uint8_t v3[3] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE};
    const int32_t a = 1 << 26, h = a - 1;
    rast_point ell[3];
    rast_stroke_style s = sc_style(2 * h, RAST_JOIN_MITER, RAST_CAP_BUTT);
    uint32_t np, nr;
    int32_t want[16];
    ell[0].x = -a;
    ell[0].y = -a;
    ell[1].x = a;
    ell[1].y = -a;
    ell[2].x = a;
    ell[2].y = a;
    want[0] = -a, want[1] = -a - h, want[2] = a, want[3] = -a - h, want[4] = a + h, want[5] = -a - h;
    want[6] = a + h, want[7] = -a, want[8] = a + h, want[9] = a, want[10] = a - h, want[11] = a;
    want[12] = 1, want[13] = -1, want[14] = -a, want[15] = -a + h;
    CHECK(-a - h == -RAST_COORD_MAX);
    CHECK(run(v3, 3, ell, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK && nr == 1 && np == 8 &&
          ring_is(want, 8));
}

/* Where a segment is shorter than the corner's reach (h tan(phi/2) at a
 * right angle: h), or the turn nearly back, the pivot stays: the same
 * outline as without the flag. */
static void test_pivot_kept(void)
{
    static const uint8_t v4[4] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE, RAST_PATH_LINE};
    static const rast_point zig[4] = {{0, 0}, {160, 0}, {160, 15}, {0, 15}}; /* middle 15 < h = 16 */
    static const rast_point back[3] = {{0, 0}, {160, 0}, {0, 4}};           /* a turn of 178.6 degrees */
    /* a turn of 60 degrees at h = 100 after a segment of 70: the lines meet
     * 100 tan(30) = 58 from the corner, within it, but the leaving
     * segment's parallelogram reaches 100 sin(60) = 87 back, past its start
     * (and the same reversed: the leaving segment short) */
    static const rast_point short1[3] = {{1000, 1000}, {1070, 1000}, {1570, 1866}};
    static const rast_point short2[3] = {{570, 134}, {1070, 1000}, {1140, 1000}};
    int join;
    for (join = 0; join < 3; join++) {
        rast_stroke_style s = sc_style(32, join, RAST_CAP_SQUARE);
        uint32_t np, nr, pn, pr;
        CHECK(run(v4, 4, zig, 4, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK);
        CHECK(run(v4, 4, zig, 4, 0, &s, piv, prings, &pn, &pr) == RAST_OK);
        CHECK(np == pn && nr == pr && memcmp(out, piv, np * sizeof *out) == 0);
        CHECK(run(v4, 3, back, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK);
        CHECK(run(v4, 3, back, 3, 0, &s, piv, prings, &pn, &pr) == RAST_OK);
        CHECK(np == pn && nr == pr && memcmp(out, piv, np * sizeof *out) == 0);
        s.width = 200;
        CHECK(run(v4, 3, short1, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK);
        CHECK(run(v4, 3, short1, 3, 0, &s, piv, prings, &pn, &pr) == RAST_OK);
        CHECK(np == pn && nr == pr && memcmp(out, piv, np * sizeof *out) == 0);
        CHECK(run(v4, 3, short2, 3, RAST__STROKE_MEET, &s, out, rings, &np, &nr) == RAST_OK);
        CHECK(run(v4, 3, short2, 3, 0, &s, piv, prings, &pn, &pr) == RAST_OK);
        CHECK(np == pn && nr == pr && memcmp(out, piv, np * sizeof *out) == 0);
    }
}

/* Is (x + 1/4, y + 1/8) within 1 unit of an edge of the outline? */
static int near_edge(const rast_point *o, const uint32_t *sizes, uint32_t nrings, int32_t x, int32_t y)
{
    uint32_t r, k, base = 0;
    for (r = 0; r < nrings; r++) {
        for (k = 0; k < sizes[r]; k++) {
            long double t, l2;
            if (sc_seg(x + 0.25L, y + 0.125L, o[base + k], o[base + (k + 1) % sizes[r]], &t, &l2) <= 1) return 1;
        }
        base += sizes[r];
    }
    return 0;
}

/* Random polylines (closed ones, curves, dashes, tiny segments, near
 * turns back): counted = stored, as many rings as the pivot's outline and
 * no more points, and the bound at sample points near the path; and the
 * region the pivot's (the pieces' union exactly, tests/c/test_stroke.c)
 * but within sqrt(2)/2 unit of the rounded meeting points' edges: a
 * sample point near the path's vertices (where the corners are) that one
 * outline covers and the other not is within 1 unit of an edge of this
 * one. */
static void test_random_bound(void)
{
    int i;
    uint32_t meets = 0, differ = 0;
    for (i = 0; i < check_count(2000); i++) {
        uint8_t verbs[12];
        rast_point pts[36];
        int32_t dash[2];
        uint32_t nv = 2 + rng() % 10, np = 0, k, onp, onr, pn, pr, fnp, fnr;
        int32_t w0 = 1 + (int32_t)(rng() % 300);
        int join = (int)(rng() % 3), cap = (int)(rng() % 3); /* (one call a statement: the same cases on every compiler) */
        rast_stroke_style s = sc_style(w0, join, cap);
        rast_path path;
        rast_polygon fpoly;
        sc_path fp;
        s.tolerance = 1 + (int32_t)(rng() % 8);
        if (rng() % 4 == 0) {
            s.ndash = 2;
            dash[0] = 1 + (int32_t)(rng() % 300);
            dash[1] = (int32_t)(rng() % 100);
            s.dash = dash;
        }
        verbs[0] = RAST_PATH_MOVE;
        pts[np].x = 2000 + (int32_t)(rng() % 2000);
        pts[np++].y = 2000 + (int32_t)(rng() % 2000);
        for (k = 1; k < nv; k++) {
            uint32_t r = rng() % 20, j, take;
            verbs[k] = r < 15 ? RAST_PATH_LINE : r < 17 ? RAST_PATH_QUAD : r < 19 ? RAST_PATH_CLOSE : RAST_PATH_MOVE;
            take = verbs[k] == RAST_PATH_CLOSE ? 0 : verbs[k] == RAST_PATH_MOVE ? 1 : verbs[k];
            for (j = 0; j < take; j++) {
                rast_point a = pts[np - 1];
                uint32_t how = rng() % 4, span = how == 0 ? 9 : how == 1 ? (uint32_t)s.width + 1 : how == 2 ? 200 : 2000;
                pts[np].x = a.x + (int32_t)(rng() % span) - (int32_t)span / 2;
                pts[np].y = a.y + (int32_t)(rng() % span) - (int32_t)span / 2;
                np++;
            }
        }
        path.verbs = verbs;
        path.nverbs = nv;
        path.points = pts;
        path.npoints = np;
        CHECK(run(verbs, nv, pts, np, RAST__STROKE_MEET, &s, out, rings, &onp, &onr) == RAST_OK);
        CHECK(run(verbs, nv, pts, np, 0, &s, piv, prings, &pn, &pr) == RAST_OK);
        CHECK(onr == pr && onp <= pn);
        meets += pn - onp;
        CHECK(sc_area_nonneg(out, rings, onr));
        CHECK(rast_path_flatten_size(&path, s.tolerance, &fnp, &fnr) == RAST_OK && fnp <= MAXP && fnr <= 64);
        CHECK(rast_path_flatten(&path, s.tolerance, flat, MAXP, frings, 64, &fpoly) == RAST_OK);
        fp.pts = flat;
        fp.sizes = frings;
        fp.nrings = fnr;
        for (k = 0; k < 40 && fnp; k++) {
            rast_point c = flat[rng() % fnp];
            int32_t reach = s.width + 8;
            int32_t x = c.x + (int32_t)(rng() % (2 * (uint32_t)reach + 1)) - reach;
            int32_t y = c.y + (int32_t)(rng() % (2 * (uint32_t)reach + 1)) - reach;
            int in_m = sc_winding(out, rings, onr, x, y) != 0, in_p = sc_winding(piv, prings, pr, x, y) != 0;
            CHECK(sc_check_point(&fp, out, rings, onr, &s, x, y));
            CHECK(in_m == in_p || near_edge(out, rings, onr, x, y));
            if (in_m != in_p) differ++;
        }
    }
    CHECK(meets > (uint32_t)check_count(2000)); /* the meeting points were taken */
    CHECK(differ < (uint32_t)check_count(2000)); /* slivers only: rarely hit */
}

/* A dot of width w at tolerance T: its ring, each vertex p (about the
 * centre) with h - T' <= |p| <= h + T' and each chord's line at least h -
 * T' from the centre, T' = max(T, 2) (rastrum.h's bound), exactly in
 * integers (w <= 5000: products below 2^50; wider, the count only).
 * Returns the point count. */
static uint32_t dot_within(int32_t w, int32_t tol, unsigned flags)
{
    static const uint8_t v2[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
    const rast_point c = {3000, 3000}, p2[2] = {{3000, 3000}, {3000, 3000}};
    rast_stroke_style s = sc_style(w, RAST_JOIN_ROUND, RAST_CAP_ROUND);
    uint32_t np = 0, nr = 0, k;
    int64_t t2 = 2 * (int64_t)(tol > 2 ? tol : 2), lo = w - t2 > 0 ? (w - t2) * (w - t2) : 0, hi = (w + t2) * (w + t2);
    s.tolerance = tol;
    CHECK(run(v2, 2, p2, 2, flags, &s, out, rings, &np, &nr) == RAST_OK && nr == 1 && np >= 3);
    for (k = 0; k < np && w <= 5000; k++) {
        int64_t px = out[k].x - c.x, py = out[k].y - c.y, qx = out[(k + 1) % np].x - c.x,
                qy = out[(k + 1) % np].y - c.y, cr = px * qy - py * qx, dx = qx - px, dy = qy - py;
        CHECK(4 * (px * px + py * py) <= hi && 4 * (px * px + py * py) >= lo);
        CHECK(cr > 0 && 4 * cr * cr >= lo * (dx * dx + dy * dy));
    }
    return np;
}

static void test_round_parts(void)
{
    int i;
    uint64_t exact = 0, wide = 0;
    for (i = 0; i < check_count(3000); i++) {
        int32_t w = 1 + (int32_t)(rng() % 5000), coarse = rng() % 2 == 0, tol = 1 + (int32_t)(rng() % (coarse ? 300 : 4));
        uint32_t ne = dot_within(w, tol, 0), nw = dot_within(w, tol, RAST__STROKE_ARCS);
        CHECK(nw <= ne);
        exact += ne;
        wide += nw;
    }
    CHECK(wide * 10 < exact * 8); /* fewer by about 1/sqrt(2) */
    /* 3 px on the 2^-16 px grid at 1/256 px: m = 14, 10 */
    CHECK(dot_within(196608, 256, 0) == 56 && dot_within(196608, 256, RAST__STROKE_ARCS) == 40);
}

int main(void)
{
    test_round_parts();
    test_right_angle();
    test_range_limits();
    test_pivot_kept();
    test_random_bound();
    return check_report("test_stroke_compact");
}

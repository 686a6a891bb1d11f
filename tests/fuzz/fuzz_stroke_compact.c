/*
 * fuzz_stroke_compact.c - rastrum.stroke(outline="compact")'s outline:
 * rast__path_stroke_run with RAST__STROKE_MEET (inner joins through the
 * meeting point), RAST__STROKE_ARCS (round parts straddling the circle)
 * or both (path/path.h, path/stroke.c), near a small target and at
 * the range limits (points anywhere in +-RAST_COORD_MAX, widths to
 * RAST_COORD_MAX: the integer arithmetic's range, under the sanitizers).
 * Oracle: the count pass gives what the storing pass stores (room one
 * point short: RAST_E_SCRATCH); where the vertex-pivot outline (flags 0)
 * is made, this one is too (but a wider circle may leave the range),
 * with as many rings (with RAST__STROKE_MEET alone, no more points); the
 * rings' total area >= 0; and rastrum.h's bound at sample points near the
 * path (tests/c/stroke_check.h: winding never negative, covered points
 * within the stated reach, points well inside a segment's band covered),
 * which holds for the meeting point's outline (within sqrt(2)/2 unit of
 * the pieces' union: path/stroke.c, "Inner joins") with its margin, and
 * for the wider circle's points (within the tolerance, as before).
 */
#include "fuzz.h"
#include "stroke_check.h"
#include "path/path.h"

#define FM_MAXV 10
#define FM_MAXOUT 60000
#define FM_MAXR 4000

static rast_point out[FM_MAXOUT], piv[FM_MAXOUT], flat[FM_MAXOUT];
static uint32_t rings[FM_MAXR], prings[FM_MAXR], frings[FM_MAXV + 1];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t takes[5] = {1, 1, 2, 3, 0};
    fz_in in = {data, size, 0};
    uint8_t verbs[FM_MAXV];
    rast_point pts[3 * FM_MAXV];
    int32_t dash[3];
    uint32_t nv = 1 + fz_below(&in, FM_MAXV), np = 0, k, n1, r1, n2, r2, pn, pr, fnp, fnr;
    uint32_t mode = fz_u8(&in);
    unsigned flags = 1 + (mode >> 2) % 3; /* MEET, ARCS, both */
    int big = mode & 2; /* the range limits */
    int32_t extent = 4 + fz_below(&in, 64), unit = 16;
    rast_stroke_style st;
    rast_path path;
    rast_polygon fpoly;
    rast_status s, sp;
    sc_path fp;

    for (k = 0; k < nv; k++) {
        uint32_t v = fz_u8(&in), j;
        verbs[k] = k == 0 ? RAST_PATH_MOVE : (uint8_t)(v % 5);
        for (j = 0; j < takes[verbs[k]]; j++) {
            if (big) {
                pts[np].x = (int32_t)(fz_u32(&in) % (2u * RAST_COORD_MAX + 1)) - RAST_COORD_MAX;
                pts[np].y = (int32_t)(fz_u32(&in) % (2u * RAST_COORD_MAX + 1)) - RAST_COORD_MAX;
                if (fz_u8(&in) < 64) pts[np].x = fz_coord(&in, 0, 64) % (RAST_COORD_MAX + 1);
            } else {
                pts[np].x = fz_below(&in, extent * unit);
                pts[np].y = fz_below(&in, extent * unit);
            }
            if (np && fz_u8(&in) < 40) pts[np] = pts[np - 1]; /* a repeated point: zero length */
            if (np && fz_u8(&in) < 40) { /* a short step from the last point: a short segment */
                pts[np].x = pts[np - 1].x + fz_below(&in, 9) - 4;
                pts[np].y = pts[np - 1].y + fz_below(&in, 9) - 4;
                if (pts[np].x > RAST_COORD_MAX || pts[np].x < -RAST_COORD_MAX) pts[np].x = pts[np - 1].x;
                if (pts[np].y > RAST_COORD_MAX || pts[np].y < -RAST_COORD_MAX) pts[np].y = pts[np - 1].y;
            }
            np++;
        }
    }
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = pts;
    path.npoints = np;
    st.width = big ? 1 + (int32_t)(fz_u32(&in) % RAST_COORD_MAX) : 1 + fz_below(&in, 8 * unit);
    if (big && fz_u8(&in) < 128) st.width = 1 + (st.width & 0xFFFF);
    st.join = fz_below(&in, 3);
    st.cap = fz_below(&in, 3);
    st.miter_limit = 65536 + (int32_t)fz_below(&in, 8 * 65536);
    st.tolerance = 1 + fz_below(&in, unit);
    if (big && fz_u8(&in) < 192) st.tolerance <<= 12; /* fewer points on wide circles and long curves */
    st.dash = NULL;
    st.ndash = 0;
    st.dash_offset = 0;
    if (mode & 1) {
        st.ndash = 1 + fz_below(&in, 3);
        for (k = 0; k < st.ndash; k++) dash[k] = (1 + fz_below(&in, 4 * unit)) << (big ? 20 : 0);
        st.dash = dash;
        st.dash_offset = (int32_t)fz_below(&in, 16 * unit) - 8 * unit; /* (big: dashes of 2^20 units and more) */
    }
    s = rast__path_stroke_run(&path, &st, flags, NULL, 0, NULL, 0, &n1, &r1);
    sp = rast__path_stroke_run(&path, &st, 0, NULL, 0, NULL, 0, &pn, &pr);
    /* (the wider circle reaches h / (4 m^2) further: past the range where
     * the other did not, RAST_E_RANGE) */
    if (sp == RAST_OK)
        FZ_ASSERT((s == RAST_OK && r1 == pr && (flags != RAST__STROKE_MEET || n1 <= pn)) ||
                  (s == RAST_E_RANGE && (flags & RAST__STROKE_ARCS)));
    if (s != RAST_OK || n1 > FM_MAXOUT || r1 > FM_MAXR) return 0;
    if (n1) FZ_ASSERT(rast__path_stroke_run(&path, &st, flags, out, n1 - 1, rings, FM_MAXR, &n2,
                                            &r2) == RAST_E_SCRATCH);
    FZ_ASSERT(rast__path_stroke_run(&path, &st, flags, out, n1, rings, FM_MAXR, &n2, &r2) == RAST_OK);
    FZ_ASSERT(n2 == n1 && r2 == r1);
    {
        uint64_t sum = 0;
        for (k = 0; k < r1; k++) sum += rings[k];
        FZ_ASSERT(sum == n1);
    }
    FZ_ASSERT(sc_area_nonneg(out, rings, r1));
    if (sp == RAST_OK && pn <= FM_MAXOUT && pr <= FM_MAXR) /* the pivot's outline, stored: the same rings */
        FZ_ASSERT(rast__path_stroke_run(&path, &st, 0, piv, pn, prings, FM_MAXR, &n2, &r2) == RAST_OK);
    FZ_ASSERT(rast_path_flatten_size(&path, st.tolerance, &fnp, &fnr) == RAST_OK);
    if (fnp > FM_MAXOUT || !fnp) return 0;
    FZ_ASSERT(rast_path_flatten(&path, st.tolerance, flat, FM_MAXOUT, frings, FM_MAXV + 1, &fpoly) == RAST_OK);
    fp.pts = flat;
    fp.sizes = frings;
    fp.nrings = fnr;
    /* sample points near the path's points (within 4 widths), where the
     * inner corners are */
    for (k = 0; k < 24; k++) {
        rast_point c = flat[fz_below(&in, (int32_t)fnp)];
        int64_t reach = (int64_t)st.width * 4 + 8, x, y;
        x = c.x + (int64_t)(fz_u32(&in) % (uint32_t)(2 * reach + 1)) - reach;
        y = c.y + (int64_t)(fz_u32(&in) % (uint32_t)(2 * reach + 1)) - reach;
        if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX || y < -RAST_COORD_MAX || y > RAST_COORD_MAX) continue;
        FZ_ASSERT(sc_check_point(&fp, out, rings, r1, &st, (int32_t)x, (int32_t)y));
    }
    return 0;
}

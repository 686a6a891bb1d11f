/*
 * fuzz_stroke.c - rast_path_stroke.  Oracle: a bad style (width,
 * tolerance, join, cap or miter limit out of range, a negative dash, all
 * dashes 0) or a bad path gets its status with nothing written; a good one
 * gives the sizes rast_path_stroke_size gives, the rings' total area >= 0,
 * and rastrum.h's bound checked at sample
 * points near the path (tests/c/stroke_check.h: the winding number never
 * negative; covered points within the stated reach of the flattened path;
 * points well inside a segment's band covered; with round joins and caps
 * exactly the band of half the width, up to the stated error).
 */
#include "fuzz.h"
#include "stroke_check.h"

#define FS_MAXV 10
#define FS_MAXOUT 60000
#define FS_MAXR 4000

static rast_point out[FS_MAXOUT], flat[FS_MAXOUT];
static uint32_t rings[FS_MAXR], frings[FS_MAXV + 1];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t takes[5] = {1, 1, 2, 3, 0};
    fz_in in = {data, size, 0};
    uint8_t verbs[FS_MAXV];
    rast_point pts[3 * FS_MAXV];
    int32_t dash[4];
    uint32_t nv = 1 + fz_below(&in, FS_MAXV), np = 0, k, got_np = 0xFFFFFFFF, got_nr = 0xFFFFFFFF;
    uint32_t fnp, fnr, mode = fz_u8(&in);
    int32_t extent = 4 + fz_below(&in, 64), unit = 16;
    rast_stroke_style st;
    rast_path path;
    rast_polygon poly = {NULL, NULL, 12345}, fpoly;
    rast_status s, want = RAST_OK;
    sc_path fp;

    for (k = 0; k < nv; k++) {
        uint32_t v = fz_u8(&in), j;
        verbs[k] = k == 0 ? RAST_PATH_MOVE : (uint8_t)(v % 5);
        for (j = 0; j < takes[verbs[k]]; j++) {
            pts[np].x = (int32_t)fz_below(&in, extent * unit);
            pts[np].y = (int32_t)fz_below(&in, extent * unit);
            if (np && fz_u8(&in) < 40) pts[np] = pts[np - 1]; /* a repeated point: zero length */
            np++;
        }
    }
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = pts;
    path.npoints = np;
    st.width = 1 + fz_below(&in, 8 * unit);
    st.join = fz_below(&in, 3);
    st.cap = fz_below(&in, 3);
    st.miter_limit = 65536 + (int32_t)fz_below(&in, 8 * 65536);
    st.tolerance = 1 + fz_below(&in, unit);
    st.dash = NULL;
    st.ndash = 0;
    st.dash_offset = 0;
    if (mode & 1) {
        st.ndash = 1 + fz_below(&in, 4);
        for (k = 0; k < st.ndash; k++) dash[k] = fz_below(&in, 4 * unit);
        if (fz_u8(&in) < 20) dash[0] = 0;
        st.dash = dash;
        st.dash_offset = (int32_t)fz_below(&in, 16 * unit) - 8 * unit;
        want = RAST_E_ARG;
        for (k = 0; k < st.ndash; k++)
            if (dash[k]) want = RAST_OK;
    }
    if (mode & 2) { /* a bad style */
        switch (fz_below(&in, 7)) {
        case 0: st.width = 0; break;
        case 1: st.tolerance = 0; break;
        case 2: st.join = 3; break;
        case 3: st.cap = -1; break;
        case 4: st.miter_limit = 65535; break;
        case 5: st.width = RAST_COORD_MAX + 1; break;
        default: if (st.ndash) dash[0] = -1; else st.tolerance = -5; break;
        }
        want = RAST_E_ARG;
    }
    s = rast_path_stroke_size(&path, &st, &got_np, &got_nr);
    if (want != RAST_OK) {
        FZ_ASSERT(s == want && got_np == 0xFFFFFFFF && got_nr == 0xFFFFFFFF);
        FZ_ASSERT(rast_path_stroke(&path, &st, out, FS_MAXOUT, rings, FS_MAXR, &poly) == want);
        FZ_ASSERT(poly.nrings == 12345);
        return 0;
    }
    FZ_ASSERT(s == RAST_OK || s == RAST_E_TOO_MANY);
    if (s != RAST_OK || got_np > FS_MAXOUT || got_nr > FS_MAXR) return 0;
    if (got_np) FZ_ASSERT(rast_path_stroke(&path, &st, out, got_np - 1, rings, FS_MAXR, &poly) == RAST_E_SCRATCH);
    FZ_ASSERT(poly.nrings == 12345);
    FZ_ASSERT(rast_path_stroke(&path, &st, out, FS_MAXOUT, rings, FS_MAXR, &poly) == RAST_OK);
    FZ_ASSERT(poly.nrings == got_nr && poly.points == out && poly.ring_sizes == rings);
    {
        uint64_t sum = 0;
        for (k = 0; k < got_nr; k++) sum += rings[k];
        FZ_ASSERT(sum == got_np);
    }
    FZ_ASSERT(sc_area_nonneg(out, rings, got_nr));
    /* the flattened path, as the stroker flattens it */
    FZ_ASSERT(rast_path_flatten_size(&path, st.tolerance, &fnp, &fnr) == RAST_OK);
    if (fnp > FS_MAXOUT) return 0;
    FZ_ASSERT(rast_path_flatten(&path, st.tolerance, flat, FS_MAXOUT, frings, FS_MAXV + 1, &fpoly) == RAST_OK);
    fp.pts = flat;
    fp.sizes = frings;
    fp.nrings = fnr;
    /* sample points: near the path's points, and where the input says */
    for (k = 0; k < 24; k++) {
        rast_point c = flat[fz_below(&in, (int32_t)fnp)];
        int32_t reach = st.width * 4 + 8;
        int32_t x = c.x + fz_below(&in, 2 * reach + 1) - reach, y = c.y + fz_below(&in, 2 * reach + 1) - reach;
#ifdef FS_DEBUG
        if (!sc_check_point(&fp, out, rings, got_nr, &st, x, y)) {
            uint32_t j;
            fprintf(stderr, "w=%d join=%d cap=%d lim=%d tol=%d ndash=%u point %d %d wind %d\n", st.width, st.join,
                    st.cap, st.miter_limit, st.tolerance, st.ndash, x, y, sc_winding(out, rings, got_nr, x, y));
            for (j = 0; j < nv; j++) fprintf(stderr, "v%d ", verbs[j]);
            for (j = 0; j < np; j++) fprintf(stderr, "(%d,%d) ", pts[j].x, pts[j].y);
            fprintf(stderr, "\n");
            for (j = 0; j < st.ndash; j++) fprintf(stderr, "dash %d ", dash[j]);
            fprintf(stderr, "off %d\n", st.dash_offset);
        }
#endif
        FZ_ASSERT(sc_check_point(&fp, out, rings, got_nr, &st, x, y));
    }
    return 0;
}

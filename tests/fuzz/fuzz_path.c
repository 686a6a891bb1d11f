/*
 * fuzz_path.c - rast_path_flatten.  Oracle: bad paths (unknown verbs, a
 * first verb other than MOVE, a point count off, points out of range, a
 * tolerance outside 1..RAST_COORD_MAX) get their status with nothing
 * written; a good one gives the sizes rast_path_flatten_size gives, one
 * ring per subpath, each LINE's end and each curve's end exactly, each
 * curve cut into the count of rastrum.h's formula (written again here),
 * and the bound of rastrum.h checked inside: every flattened vertex within
 * sqrt(2)/2 unit of the curve point at its parameter (the rounding), and
 * curve points sampled along every edge within `tolerance` of that edge
 * (squared distances in long double, margin 1e-6 unit^2; the exact check
 * in rational arithmetic is tests/test_path.py).
 */
#include "fuzz.h"
#include "curve_ref.h"

#define FP_MAXV 12
#define FP_MAXOUT 30000

static rast_point out[FP_MAXOUT];
static uint32_t rings[FP_MAXV + 1];

/* The curve q[0..d] flattened into w[0..n] at tolerance tol: the bound. */
static void check_curve(const rast_point *q, int d, const rast_point *w, uint32_t n, int32_t tol)
{
    uint32_t i, step = n > 1024 ? n / 1024 : 1;
    long double t2 = (long double)tol * tol + 1e-6L;
    FZ_ASSERT(w[0].x == q[0].x && w[0].y == q[0].y && w[n].x == q[d].x && w[n].y == q[d].y);
    for (i = 0; i < n; i += step) {
        long double x, y;
        int j;
        ref_bezier(q, d, (long double)i / n, &x, &y);
        FZ_ASSERT((x - w[i].x) * (x - w[i].x) + (y - w[i].y) * (y - w[i].y) <= 0.5L + 1e-6L);
        for (j = 0; j <= 8; j++) {
            ref_bezier(q, d, ((long double)i + j / 8.0L) / n, &x, &y);
            FZ_ASSERT(ref_seg_d2(x, y, w[i], w[i + 1]) <= t2);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t takes[5] = {1, 1, 2, 3, 0};
    fz_in in = {data, size, 0};
    uint8_t verbs[FP_MAXV];
    rast_point pts[3 * FP_MAXV];
    uint32_t nv = fz_below(&in, FP_MAXV + 1), np = 0, k, want_np = 0, want_nr = 0;
    uint32_t got_np = 0xFFFFFFFF, got_nr = 0xFFFFFFFF;
    int s = fz_below(&in, 9), bad_verb = 0, open = 0;
    int32_t extent = 1 + fz_below(&in, 256), tol;
    uint32_t tmode = fz_u8(&in);
    rast_path path;
    rast_polygon poly = {NULL, NULL, 12345};
    rast_status st, want;
    rast_point cur = {0, 0}, start = {0, 0};

    if (tmode < 8) tol = (int32_t[]){0, -1, RAST_COORD_MAX + 1, RAST_COORD_MAX, 1, 1, 2, 3}[tmode];
    else tol = 1 + fz_below(&in, tmode < 128 ? 4 : 1 << (s + 2));
    for (k = 0; k < nv; k++) {
        uint32_t v = fz_u8(&in), j;
        if (v == 255) { verbs[k] = 5 + fz_below(&in, 10); bad_verb = 1; continue; }
        verbs[k] = k == 0 && v < 200 ? RAST_PATH_MOVE : (uint8_t)(v % 5);
        for (j = 0; j < takes[verbs[k]]; j++) pts[np++] = fz_point(&in, s, extent);
    }
    if (fz_u8(&in) == 7 && np) np--; /* a count off by one */
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = np ? pts : NULL;
    path.npoints = np;

    /* the expected status */
    want = RAST_OK;
    {
        uint32_t need = 0;
        for (k = 0; k < nv; k++) need += verbs[k] < 5 ? takes[verbs[k]] : 0;
        if (tol < 1 || tol > RAST_COORD_MAX || bad_verb || (nv && verbs[0] != RAST_PATH_MOVE) ||
            need != np)
            want = RAST_E_ARG;
        else if (in.out_of_range) {
            for (k = 0; k < np; k++)
                if (!fz_in_range(pts[k])) want = RAST_E_RANGE;
        }
    }
    st = rast_path_flatten_size(&path, tol, &got_np, &got_nr);
    if (want != RAST_OK) {
        FZ_ASSERT(st == want && got_np == 0xFFFFFFFF && got_nr == 0xFFFFFFFF);
        FZ_ASSERT(rast_path_flatten(&path, tol, out, FP_MAXOUT, rings, FP_MAXV + 1, &poly) == want);
        FZ_ASSERT(poly.nrings == 12345);
        return 0;
    }
    FZ_ASSERT(st == RAST_OK || st == RAST_E_TOO_MANY);
    if (st != RAST_OK) return 0;
    /* the sizes, walked again */
    {
        const rast_point *p = pts;
        for (k = 0; k < nv; k++) {
            int v = verbs[k];
            if (v == RAST_PATH_MOVE) { want_nr++; want_np++; open = 1; cur = start = *p++; }
            else if (v == RAST_PATH_CLOSE) { open = 0; cur = start; }
            else {
                rast_point q[4];
                int j;
                if (!open) { want_nr++; want_np++; open = 1; }
                q[0] = cur;
                for (j = 1; j <= (v == RAST_PATH_LINE ? 1 : v); j++) q[j] = *p++;
                want_np += v == RAST_PATH_LINE ? 1 : ref_edges(q, v, tol);
                cur = q[v == RAST_PATH_LINE ? 1 : v];
            }
        }
    }
    FZ_ASSERT(got_np == want_np && got_nr == want_nr);
    if (got_np > FP_MAXOUT) return 0;
    if (got_np) {
        FZ_ASSERT(rast_path_flatten(&path, tol, out, got_np - 1, rings, FP_MAXV + 1, &poly) == RAST_E_SCRATCH);
        FZ_ASSERT(poly.nrings == 12345);
    }
    FZ_ASSERT(rast_path_flatten(&path, tol, out, FP_MAXOUT, rings, FP_MAXV + 1, &poly) == RAST_OK);
    FZ_ASSERT(poly.nrings == want_nr && poly.points == out && poly.ring_sizes == rings);
    /* walk once more along the output: ring sizes, ends, the bound */
    {
        const rast_point *p = pts;
        uint32_t o = 0, r = 0, ring_start = 0;
        open = 0;
        for (k = 0; k < nv; k++) {
            int v = verbs[k];
            if (v == RAST_PATH_MOVE) {
                if (r) FZ_ASSERT(rings[r - 1] == o - ring_start);
                ring_start = o;
                r++;
                cur = start = *p++;
                FZ_ASSERT(out[o].x == cur.x && out[o].y == cur.y);
                o++;
                open = 1;
            } else if (v == RAST_PATH_CLOSE) {
                open = 0;
                cur = start;
            } else {
                rast_point q[4];
                int j, d = v == RAST_PATH_LINE ? 1 : v;
                if (!open) {
                    if (r) FZ_ASSERT(rings[r - 1] == o - ring_start);
                    ring_start = o;
                    r++;
                    FZ_ASSERT(out[o].x == start.x && out[o].y == start.y);
                    o++;
                    open = 1;
                }
                q[0] = cur;
                for (j = 1; j <= d; j++) q[j] = *p++;
                if (d == 1) {
                    FZ_ASSERT(out[o].x == q[1].x && out[o].y == q[1].y);
                    o++;
                } else {
                    uint32_t n = ref_edges(q, d, tol);
                    check_curve(q, d, out + o - 1, n, tol);
                    o += n;
                }
                cur = q[d];
            }
        }
        if (r) FZ_ASSERT(rings[r - 1] == o - ring_start);
        FZ_ASSERT(o == got_np && r == want_nr);
    }
    return 0;
}

/*
 * fuzz_predicate.c - rast_point_in_triangle, every method.  Oracle: the
 * four closed-triangle methods give the closed triangle (exact
 * orientation tests, no area for a degenerate one); OWNER gives the fill's
 * rule at a sample placed at p (ref.h's winding number, S = 0, corner
 * samples); out-of-range input and unknown methods are errors.
 */
#include "fuzz.h"

static int sign(int64_t v) { return (v > 0) - (v < 0); }

static int64_t orient(rast_point a, rast_point b, rast_point p)
{
    return ((int64_t)b.x - a.x) * ((int64_t)p.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)p.x - a.x);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point p, t[3];
    int method, inside = -1, k, want;
    int64_t area;
    rast_status st;
    int32_t extent = 1 + fz_below(&in, 64);
    static const uint32_t three = 3;

    method = fz_u8(&in) == 255 ? RAST_PRED_COUNT_ + fz_below(&in, 3) : fz_below(&in, RAST_PRED_COUNT_);
    p = fz_point(&in, 0, extent);
    for (k = 0; k < 3; k++) t[k] = fz_point(&in, 0, extent);
    if (fz_u8(&in) < 64) p = t[fz_below(&in, 3)]; /* on a vertex */
    if (fz_u8(&in) < 64) { /* on an edge's lattice point, when it has one */
        int e = fz_below(&in, 3);
        rast_point a = t[e], b = t[(e + 1) % 3];
        if (!in.out_of_range && ((int64_t)b.x - a.x) % 2 == 0 && ((int64_t)b.y - a.y) % 2 == 0) {
            p.x = (int32_t)(((int64_t)a.x + b.x) / 2);
            p.y = (int32_t)(((int64_t)a.y + b.y) / 2);
        }
    }
    /* the vertex and edge choices may have replaced a bad point */
    in.out_of_range = !fz_in_range(p) || !fz_in_range(t[0]) || !fz_in_range(t[1]) ||
                      !fz_in_range(t[2]);
    st = rast_point_in_triangle(p, t, (rast_predicate)method, &inside);
    if (method >= RAST_PRED_COUNT_ || in.out_of_range) {
        FZ_ASSERT(st == (in.out_of_range ? RAST_E_RANGE : RAST_E_ARG) ||
                  (in.out_of_range && method >= RAST_PRED_COUNT_ && st == RAST_E_ARG));
        FZ_ASSERT(inside == -1);
        return 0;
    }
    FZ_ASSERT(st == RAST_OK);
    area = orient(t[0], t[1], t[2]);
    if (method == RAST_PRED_OWNER) {
        want = ref_winding(t, &three, 1, 0, 0, 0, p.x, p.y, NULL) != 0;
    } else {
        want = area != 0;
        for (k = 0; k < 3 && want; k++) {
            int o = sign(orient(t[k], t[(k + 1) % 3], p));
            if (o != 0 && o != sign(area)) want = 0;
        }
    }
    FZ_ASSERT(inside == want);
    return 0;
}

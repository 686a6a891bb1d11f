/*
 * predicate.c - is a point inside a triangle?  The four tests of seeds 003
 * and 004 (same side, cross product, area sum, barycentric) in exact
 * integers, and the fill's own rule.
 *
 * Coordinates are within +-(2^27 - 1), so a difference is below 2^28, a
 * cross product of two differences below 2^57 and a sum of three cross
 * products below 2^59: every value here fits int64_t.  Where a seed
 * multiplies two cross products (same side: a dot product of the two
 * normals), only their signs are multiplied.
 *
 * The four closed tests answer the same question, "is p in the closed
 * triangle?", and give the same answer for every p and t.  A triangle of
 * zero area contains no point for any of them: each checks the area first.
 * Taken literally, the seeds' formulas would not agree there: same side
 * (v1 . v2 >= 0 with v1 = 0) accepts every point of the plane, cross
 * product and area sum accept the whole line through a collinear triangle
 * (the plane, when the three vertices coincide); only the seed's
 * barycentric code refuses it (its `abs(u.z) < 1` branch).
 */
#include "../base/internal.h"

static int rast__sign(int64_t v)
{
    return (v > 0) - (v < 0);
}

static int64_t rast__abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* Seed 003: p and c on the same side of the line ab (or p on it). */
static int rast__same_side(rast_point a, rast_point b, rast_point c, rast_point p)
{
    return rast__sign(rast__cross3(a, b, c)) * rast__sign(rast__cross3(a, b, p)) >= 0;
}

/* DESIGN section 1 at a sample placed at p: the winding number of the
 * triangle's ring around p, counting a crossing of row py at X iff X <= px,
 * rows top closed and bottom open.  For a downward edge (y0 < y1) crossing
 * the row, X <= px iff (px - x0)(y1 - y0) >= (py - y0)(x1 - x0). */
static int rast__owner(rast_point p, const rast_point *t)
{
    int k, wind = 0;
    for (k = 0; k < 3; k++) {
        rast_point a = t[k], b = t[(k + 1) % 3];
        int dir = 1;
        if (a.y == b.y) continue; /* horizontal edges never cross */
        if (a.y > b.y) {
            rast_point s = a;
            a = b;
            b = s;
            dir = -1;
        }
        if (p.y < a.y || p.y >= b.y) continue;
        /* < 2^28 * 2^28 each */
        if (((int64_t)p.x - a.x) * ((int64_t)b.y - a.y) >= ((int64_t)p.y - a.y) * ((int64_t)b.x - a.x))
            wind += dir;
    }
    return wind != 0; /* a triangle winds 0 or +-1: either fill rule */
}

rast_status rast_point_in_triangle(rast_point p, const rast_point *t, rast_predicate method,
                                   int *inside)
{
    int64_t area;
    int k;
    if (!t || !inside) return RAST_E_NULL;
    if ((unsigned)method >= RAST_PRED_COUNT_) return RAST_E_ARG;
    if (p.x < -RAST_COORD_MAX || p.x > RAST_COORD_MAX || p.y < -RAST_COORD_MAX ||
        p.y > RAST_COORD_MAX)
        return RAST_E_RANGE;
    for (k = 0; k < 3; k++)
        if (t[k].x < -RAST_COORD_MAX || t[k].x > RAST_COORD_MAX || t[k].y < -RAST_COORD_MAX ||
            t[k].y > RAST_COORD_MAX)
            return RAST_E_RANGE;

    if (method == RAST_PRED_OWNER) {
        *inside = rast__owner(p, t);
        return RAST_OK;
    }
    area = rast__cross3(t[0], t[1], t[2]);
    if (area == 0) { /* degenerate: no point inside (see the top of the file) */
        *inside = 0;
        return RAST_OK;
    }
    switch (method) {
    case RAST_PRED_SAMESIDE:
        *inside = rast__same_side(t[0], t[1], t[2], p) && rast__same_side(t[1], t[2], t[0], p) &&
                  rast__same_side(t[2], t[0], t[1], p);
        break;
    case RAST_PRED_CROSS: { /* P0P1 x P0Q, P1P2 x P1Q, P2P0 x P2Q: one sign */
        int64_t c0 = rast__cross3(t[0], t[1], p);
        int64_t c1 = rast__cross3(t[1], t[2], p);
        int64_t c2 = rast__cross3(t[2], t[0], p);
        *inside = (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
        break;
    }
    case RAST_PRED_AREA: /* S(pab) + S(pbc) + S(pca) == S(abc); < 3 * 2^57 */
        *inside = rast__abs64(rast__cross3(p, t[0], t[1])) + rast__abs64(rast__cross3(p, t[1], t[2])) +
                      rast__abs64(rast__cross3(p, t[2], t[0])) ==
                  rast__abs64(area);
        break;
    default: { /* RAST_PRED_BARYCENTRIC: p = a + beta (b - a) + gamma (c - a),
                * beta = db / area, gamma = dc / area, alpha = 1 - beta - gamma;
                * all >= 0, compared without dividing. */
        int64_t db = rast__cross3(t[0], p, t[2]);
        int64_t dc = rast__cross3(t[0], t[1], p);
        int64_t da = area - db - dc; /* < 3 * 2^57 */
        if (area < 0) {
            da = -da;
            db = -db;
            dc = -dc;
        }
        *inside = da >= 0 && db >= 0 && dc >= 0;
        break;
    }
    }
    return RAST_OK;
}

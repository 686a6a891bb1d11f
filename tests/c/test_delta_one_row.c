/* test_delta_one_row.c - the winding deltas' edges of one sample row whose
 * ends' columns are one apart (fillers/aet.c, rast__delta_rc_walk and
 * rast__one_row_side: the crossing's column is the first of the two whose
 * sample is not left of the crossing, found by one comparison of products,
 * not by rast__one_row_col's division), against the reference winding
 * number (ref.h, straight from DESIGN) and the AET's sweep, bit for bit.
 * Rings of short edges, half of them through a sample point exactly (the
 * crossing on the sample: it counts for that column, exact rounding),
 * either way round, with steps of less than a pixel across and down, so
 * that the two columns are one apart; the rest random steps of up to a
 * pixel and a half; rings round points near and past the canvas's sides
 * (the columns cut to the clip: the first of the two is 0 or the last is
 * the clip's width); S = 0 to 16, both samples, both roundings (textbook
 * takes the division), both rules, non-zero past 511 vertices (the
 * pieces' count); the clip the whole width and opaque (the counters in
 * the mask itself, the last row in a row of its own) or anywhere on the
 * canvas (a buffer of rows). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "painters/paint.h"
#include "rastrum.h"

enum { W = 61, H = 19, STRIDE = W, MAXP = 1400 };
static const unsigned char VALUE = 1, BACKGROUND = 0;
#include "byte_canvas.h"

/* A ring of `n` vertices (n even, >= 4) from pixel (cx, cy): pairs of
 * vertices a short edge apart, through a sample point (qx, qy) near the
 * last vertex when `tie` (top = Q - a u, bottom = Q + b u, |a u|, |b u|
 * under a pixel each way), else two random steps of up to 1.5 pixels
 * across and 1.25 down or up.  Returns the vertices written. */
static uint32_t short_ring(rast_point *pts, uint32_t n, int32_t cx, int32_t cy, int s, int center)
{
    const int64_t one = (int64_t)1 << s;
    /* the sample's offset in fixed units; at S = 0 a centre sample is not
     * on the grid: no vertex can pass through it */
    const int ties = !(center && s == 0);
    const int64_t half = center ? one / 2 : 0;
    int64_t x = cx * one, y = cy * one;
    uint32_t v;
    for (v = 0; v + 2 <= n; v += 2) {
        if (ties && rng() % 2) {
            const int64_t qx = (x >> s) + (int64_t)(rng() % 5) - 2, qy = (y >> s) + (int64_t)(rng() % 5) - 2;
            const int64_t lim = one > 1 ? one - 1 : 1;
            int64_t ux = 1 + (int64_t)(rng() % (uint32_t)lim), uy = 1 + (int64_t)(rng() % (uint32_t)lim);
            int64_t a = 1, b = 1, X = qx * one + half, Y = qy * one + half;
            if (rng() & 1) ux = -ux;
            if (rng() % 4 == 0) ux = 0; /* (one column: the walk's other branch) */
            if (one >= 4 && (rng() & 1)) { /* unequal parts, still under a pixel */
                ux /= 2;
                uy = uy / 2 + 1;
                a = 1 + (int64_t)(rng() & 1);
            }
            if (rng() & 1) { /* top first, or bottom first: both directions */
                pts[v].x = (int32_t)(X - a * ux);
                pts[v].y = (int32_t)(Y - a * uy);
                pts[v + 1].x = (int32_t)(X + b * ux);
                pts[v + 1].y = (int32_t)(Y + b * uy);
            } else {
                pts[v].x = (int32_t)(X + b * ux);
                pts[v].y = (int32_t)(Y + b * uy);
                pts[v + 1].x = (int32_t)(X - a * ux);
                pts[v + 1].y = (int32_t)(Y - a * uy);
            }
        } else {
            int k;
            for (k = 0; k < 2; k++) {
                x += (int64_t)(rng() % (uint32_t)(3 * one + 1)) - 3 * one / 2;
                y += (int64_t)(rng() % (uint32_t)(5 * one / 2 + 1)) - 5 * one / 4;
                pts[v + k].x = (int32_t)x;
                pts[v + k].y = (int32_t)y;
            }
        }
        x = pts[v + 1].x;
        y = pts[v + 1].y;
    }
    return v;
}

/* A scene: rings of short edges (bytes_rings_near). */
static uint32_t short_rings(int iter, int s, int center, rast_point *pts, uint32_t *sizes, uint32_t *np)
{
    return bytes_rings_near(iter, s, center, short_ring, pts, sizes, np);
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    bytes_scenes(8, 0, short_rings, pts, sizes);
    return check_report("test_delta_one_row");
}

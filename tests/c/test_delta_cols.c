/* test_delta_cols.c - the winding deltas' edges whose ends lie in
 * different columns, over one row or many (fillers/aet.c, rast__rc_edge:
 * the column on each row found from the top's column by the sign of
 * F(c) = c q - n, no division, where neither end's column is cut to the
 * clip, exact rounding; the rest by rast__delta_rc_other as before), and
 * the rings walked a monotone chain at a time (rast__delta_rc_walk: the
 * sentinel row past the ring, the pieces counted once a chain), against
 * the reference winding number (ref.h, straight from DESIGN) and the
 * AET's sweep, bit for bit.  Rings of slanted edges: half of them along a
 * line through sample points a whole number of pixels apart across and
 * down (the crossing exactly on a sample on several rows: it counts for
 * that column), either way round, their ends a fraction of the step past
 * those samples; the rest random steps of up to 24 pixels across and 3.5
 * down or up (steep, shallow, one row or several); chains of several
 * edges one way (a zig-zag or a staircase) as well as turns at every
 * vertex; rings round points near and past the canvas's sides (the
 * columns cut: the other path), S = 0 to 16, both samples, both roundings
 * (textbook: the other path), both rules, non-zero past 511 vertices (the
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

/* A ring of `n` vertices (n even, >= 4) from pixel (cx, cy), two at a
 * time: along a line through a sample point Q (near the last vertex) and
 * Q + (a, b) pixels (|a| <= 5, 1 <= b <= 3), from Q - ka (a, b) / 4 to
 * Q + (1 + kb / 4) (a, b) (either way round) when `tie`, else two random
 * steps; `stair`: the random steps all down (or all up) for the ring's
 * first half, so that chains run over several edges.  Returns the
 * vertices written. */
static uint32_t slant_ring(rast_point *pts, uint32_t n, int32_t cx, int32_t cy, int s, int center)
{
    const int64_t one = (int64_t)1 << s;
    const int ties = !(center && s == 0); /* (a centre is on no vertex grid at S = 0) */
    const int64_t half = center ? one / 2 : 0, q4 = one >= 4 ? one / 4 : 0;
    const int stair = (int)(rng() % 3), sdir = (rng() & 1) ? 1 : -1;
    int64_t x = cx * one, y = cy * one;
    uint32_t v;
    for (v = 0; v + 2 <= n; v += 2) {
        if (ties && rng() % 2) {
            const int64_t qx = (x >> s) + (int64_t)(rng() % 5) - 2, qy = (y >> s) + (int64_t)(rng() % 5) - 2;
            const int64_t a = (int64_t)(rng() % 11) - 5, b = 1 + (int64_t)(rng() % 3);
            const int64_t ka = (int64_t)(rng() % 4), kb = (int64_t)(rng() % 4);
            const int64_t X = qx * one + half, Y = qy * one + half;
            const int64_t x0 = X - ka * q4 * a, y0 = Y - ka * q4 * b;
            const int64_t x1 = X + (one + kb * q4) * a, y1 = Y + (one + kb * q4) * b;
            const int k = (int)(rng() & 1);
            pts[v + k].x = (int32_t)x0;
            pts[v + k].y = (int32_t)y0;
            pts[v + 1 - k].x = (int32_t)x1;
            pts[v + 1 - k].y = (int32_t)y1;
        } else {
            int k;
            for (k = 0; k < 2; k++) {
                const int64_t wide = 1 + (int64_t)(rng() % 24);
                int64_t dy = (int64_t)(rng() % (uint32_t)(7 * one / 2 + 1));
                x += (int64_t)(rng() % (uint32_t)(2 * wide * one + 1)) - wide * one;
                if (stair && v < n / 2) dy *= sdir;
                else dy -= 7 * one / 4;
                y += dy;
                pts[v + k].x = (int32_t)x;
                pts[v + k].y = (int32_t)y;
            }
        }
        x = pts[v + 1].x;
        y = pts[v + 1].y;
        /* (kept near the canvas: a far walk would leave it) */
        if (x < -4 * one || x > (W + 4) * one) x = (int64_t)(rng() % W) * one;
        if (y < -4 * one || y > (H + 4) * one) y = (int64_t)(rng() % H) * one;
    }
    return v;
}

/* A scene: slanted rings (bytes_rings_near). */
static uint32_t scene_rings(int iter, int s, int center, rast_point *pts, uint32_t *sizes, uint32_t *np)
{
    return bytes_rings_near(iter, s, center, slant_ring, pts, sizes, np);
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    bytes_scenes(8, 0, scene_rings, pts, sizes);
    return check_report("test_delta_cols");
}

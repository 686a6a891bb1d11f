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

static void check_scene(int iter, const rast_point *pts, const uint32_t *sizes, uint32_t nrings, uint32_t np,
                        int s, int center, int textbook, rast_fill_rule rule, const rast_rect *clip, int opaque)
{
    static unsigned char pre[STRIDE * H], a[STRIDE * H], b[STRIDE * H];
    static unsigned char scratch[1 << 20];
    const size_t need = rast__aet_scratch(np, W, H);
    const rast_polygon poly = {pts, sizes, nrings};
    const rast_sample at = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    rast__grid g;
    int32_t k;
    CHECK(need <= sizeof scratch);
    CHECK(rast__grid_init(&g, s, at, textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT) ==
          RAST_OK);
    for (k = 0; k < STRIDE * H; k++) pre[k] = (unsigned char)rng(); /* garbage: the clip's part written */
    CHECK(bytes_fill(a, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_SWEEP) == RAST_OK);
    CHECK(bytes_fill(b, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_RULE) == RAST_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK(bytes_match_ref(b, pre, pts, sizes, nrings, s, center, textbook, rule, clip, opaque, iter));
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    int iter, n = check_count(1500), taken = 0;
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 17), center = (int)(rng() & 1);
        const int textbook = (int)(rng() % 8 == 0), opaque = (int)(rng() & 1);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        /* one scene in 8 past 511 vertices (non-zero: the pieces counted) */
        const uint32_t want = iter % 8 == 5 ? 600 + rng() % 700 : 16 + rng() % 300;
        uint32_t np = 0, nrings = 0;
        rast_rect clip;
        int32_t rows;
        while (np + 4 <= want) {
            uint32_t m = 4 + 2 * (rng() % 12);
            /* round a point near the canvas, one ring in 6 near a side or past it */
            const int32_t cx = rng() % 6 ? (int32_t)(rng() % W) : (rng() & 1) ? -2 : W + 1;
            const int32_t cy = (int32_t)(rng() % (H + 4)) - 2;
            if (np + m > want) m = (want - np) & ~1u;
            sizes[nrings++] = slant_ring(pts + np, m, cx, cy, s, center);
            np += m;
        }
        /* rows for at least 8 vertices each (the rule's count), from 1 up */
        rows = (int32_t)(np / 8) < H ? (int32_t)(np / 8) : H;
        rows = 1 + (int32_t)(rng() % (uint32_t)rows);
        clip.y0 = (int32_t)(rng() % (uint32_t)(H - rows + 1));
        clip.y1 = clip.y0 + rows;
        if (opaque && (rng() & 3)) { /* the whole width: the counters in the mask itself */
            clip.x0 = 0;
            clip.x1 = W;
        } else {
            clip.x0 = (int32_t)(rng() % 20);
            clip.x1 = W - (int32_t)(rng() % 20);
        }
        if (np >= 8 * (uint32_t)rows && rows * ((clip.x1 - clip.x0 + 8) & ~7) <= (int32_t)np * 48 &&
            rows * ((clip.x1 - clip.x0 + 8) / 8) <= 8 * (int32_t)np)
            taken++;
        check_scene(iter, pts, sizes, nrings, np, s, center, textbook, rule, &clip, opaque);
    }
    CHECK(taken > n / 2);
    return check_report("test_delta_cols");
}

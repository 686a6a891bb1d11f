/* test_delta_far.c - the winding deltas' vertices cut to the clip first
 * (fillers/aet.c, rast__delta_rc and rast__delta_rc_walk: every vertex's
 * row and column relative to the clip, cut to [0, rows] x [0, bits], as
 * 16-bit numbers, SSE2 four vertices a step and the last 0 to 3 one at a
 * time), against the reference winding number (ref.h, straight from
 * DESIGN) and the AET's sweep, bit for bit.  Rings of 3 to 13 vertices
 * round a point near the canvas, some of their vertices far past one side
 * or two (up to +-RAST_COORD_MAX, where the relative rows and columns do
 * not fit 16 bits and saturate before the cut), so that edges cross the
 * clip from far away, are cut at its top and bottom, lie wholly left or
 * right of it (counted at its first column or past its last), or cross no
 * row of it; S = 0 to 16, both samples, both roundings, both rules, non-zero
 * past 511 vertices (the pieces' count); the clip the whole width and
 * opaque (the counters in the mask itself, the last row in a row of its
 * own) or anywhere on the canvas (a buffer of rows).  Then clips 32,766 to
 * 32,768 columns wide (the walk takes up to 32,767; past it the other
 * walk), two rows, through rast_fill_polygon_opaque. */
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

/* A coordinate (fixed units at S = s) near pixel c (within 3 pixels), or,
 * one time in `far`, far past it either way: 2^k pixels and a random part
 * of that for k up to what fits, or exactly +-RAST_COORD_MAX. */
static int32_t coord(int32_t c, int s, uint32_t far)
{
    const int64_t one = (int64_t)1 << s;
    int64_t v;
    if (rng() % far) {
        v = c * one + (int64_t)(rng() % (uint32_t)(6 * one + 1)) - 3 * one;
    } else if (rng() % 4 == 0) {
        v = (rng() & 1) ? RAST_COORD_MAX : -RAST_COORD_MAX;
    } else {
        const int k = 3 + (int)(rng() % (uint32_t)(27 - s - 2)); /* 2^k pixels: 2^(k+s) < 2^27 */
        v = ((int64_t)1 << (k + s)) + (int64_t)(rng() % ((uint32_t)1 << (k + s)));
        if (v > RAST_COORD_MAX) v = RAST_COORD_MAX;
        v = (rng() & 1) ? c * one + v : c * one - v;
    }
    if (v > RAST_COORD_MAX) v = RAST_COORD_MAX;
    if (v < -RAST_COORD_MAX) v = -RAST_COORD_MAX;
    return (int32_t)v;
}

/* `nr` rings of 3 to 13 vertices (or `big` each: 3 + rng() % big) round
 * points near a w x h canvas; the vertices' count into *np. */
static uint32_t far_rings(rast_point *pts, uint32_t *sizes, uint32_t nr, uint32_t big, int s, int32_t w,
                          int32_t h, uint32_t *np)
{
    uint32_t k, v, n = 0;
    const uint32_t far = 2 + rng() % 8;
    for (k = 0; k < nr; k++) {
        const int32_t cx = (int32_t)(rng() % (uint32_t)(w + 6)) - 3, cy = (int32_t)(rng() % (uint32_t)(h + 6)) - 3;
        sizes[k] = 3 + rng() % big;
        if (n + sizes[k] > MAXP) break;
        for (v = 0; v < sizes[k]; v++) {
            pts[n].x = coord(cx, s, far);
            pts[n].y = coord(cy, s, far);
            n++;
        }
    }
    *np = n;
    return k;
}

/* Two rows of `w` columns (32,766 to 32,768), opaque, through the public
 * call: every pixel against the reference. */
static void check_wide(int32_t w, int s, rast_fill_rule rule)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    static unsigned char px[2 * 32768];
    static union { /* RAST_SCRATCH_ALIGN (8): a char array alone is 1-aligned on 32-bit ARM */
        uint64_t align;
        unsigned char b[1 << 21];
    } sbuf;
    unsigned char *const scratch = sbuf.b;
    const unsigned char one = 1, zero = 0;
    rast_fill_opts o = {RAST_ALGO_AET, RAST_RULE_NONZERO, 0, RAST_SAMPLE_CENTER, RAST_ROUND_EXACT, 0};
    rast_polygon poly;
    rast_target t;
    uint32_t np = 0, nrings;
    size_t need = 0;
    int32_t i, j, bad = 0;
    o.rule = rule;
    o.subpixel_bits = s;
    /* 1,400 vertices: the rule's counts take the deltas for two rows of
     * 32,776 counters (at most 48 bytes and 8 words a vertex) */
    nrings = far_rings(pts, sizes, MAXP, 5, s, w, 2, &np);
    while (np < MAXP && nrings < MAXP) { /* the rest as one ring of what is left */
        uint32_t v;
        sizes[nrings] = MAXP - np;
        if (sizes[nrings] < 3) break;
        for (v = 0; v < sizes[nrings]; v++) {
            pts[np].x = coord((int32_t)(rng() % (uint32_t)w), s, 4);
            pts[np].y = coord((int32_t)(rng() % 4) - 1, s, 4);
            np++;
        }
        nrings++;
    }
    CHECK(np >= 1366);
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    CHECK(rast_target_init(&t, px, w, 2, w, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast_scratch_size(&o, np, w, 2, &need) == RAST_OK);
    CHECK(need <= sizeof sbuf.b);
    memset(px, 77, sizeof px);
    CHECK(rast_fill_polygon_opaque(&t, &poly, &o, &one, &zero, scratch, need) == RAST_OK);
    for (j = 0; j < 2 && !bad; j++)
        for (i = 0; i < w; i++) {
            int cr, wn = ref_winding(pts, sizes, nrings, s, 1, 0, i, j, &cr);
            const int in = rule == RAST_RULE_EVENODD ? (cr & 1) : wn != 0;
            if (px[j * w + i] != (in ? 1 : 0)) {
                fprintf(stderr, "wide %d S=%d: byte (%d, %d) is %d, the reference %d\n", (int)w, s, (int)i,
                        (int)j, px[j * w + i], in);
                bad = 1;
                break;
            }
        }
    CHECK(!bad);
}

/* A scene: 8 to 57 far rings, one scene in 8 200 (past 511 vertices:
 * non-zero's pieces counted). */
static uint32_t scene_rings(int iter, int s, int center, rast_point *pts, uint32_t *sizes, uint32_t *np)
{
    (void)center;
    return far_rings(pts, sizes, iter % 8 == 5 ? 200 : 8 + rng() % 50, 11, s, W, H, np);
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    bytes_scenes(4, 16, scene_rings, pts, sizes);
    check_wide(32766, 8, RAST_RULE_NONZERO);
    check_wide(32767, 4, RAST_RULE_EVENODD);
    check_wide(32767, 16, RAST_RULE_NONZERO);
    check_wide(32768, 8, RAST_RULE_NONZERO);
    check_wide(32768, 0, RAST_RULE_EVENODD);
    return check_report("test_delta_far");
}

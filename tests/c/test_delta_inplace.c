/* test_delta_inplace.c - the winding deltas counted in the mask itself
 * (fillers/aet.c, rast__delta_inplace: polygon_mask's opaque gray8 mask,
 * rows of the clip's width end to end), against the AET's sweep through
 * the same painter and against the reference winding number (ref.h,
 * straight from DESIGN).  The target's rows are packed (stride = width,
 * 53: no multiple of 8 or 16, so the sweep's last columns are a tail),
 * the clip the whole width and some or all of the rows, so that every
 * vertex count of at least 8 a row takes the deltas the rule picks
 * (RAST__AET_BY_RULE).  Rings across the target's left and right sides:
 * crossings right of a row spill onto the next row's first column, and
 * those of the last row go to a row of their own.  The mask starts as
 * random bytes (every one must be written).  Non-zero wound past 510
 * crossings a row: the deltas give up after counting into the mask, and
 * the sweep must still write every byte.  (A build for size has the
 * sweep only: the two then agree trivially.) */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "painters/paint.h"
#include "rastrum.h"

enum { W = 53, H = 21, STRIDE = W, MAXP = 600 };

#include "rings.h"
static const unsigned char VALUE = 1, BACKGROUND = 0;
#include "byte_canvas.h"

/* Non-zero with windings up to 400 over every row (the deltas exact up
 * to 510 crossings a row, given up past it). */
static void test_wound(void)
{
    static rast_point pts[3 * 400];
    static const uint32_t turns[] = {60, 128, 255, 256, 257, 400};
    size_t t;
    for (t = 0; t < sizeof turns / sizeof turns[0]; t++) {
        uint32_t n = 3 * turns[t];
        rast_rect clip = {0, 0, W, H};
        wound_triangle(pts, n);
        bytes_check_scene(-1, pts, &n, 1, n, 4, 1, 0, RAST_RULE_NONZERO, &clip, 1);
    }
}

int main(void)
{
    static rast_point pts[MAXP];
    static uint32_t sizes[MAXP];
    int iter, n = check_count(600);
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 5), center = (int)(rng() & 1);
        uint32_t np = 0, nrings = small_rings(pts, sizes, MAXP, 40 + rng() % 110, s, center, &np);
        const int textbook = (int)(rng() % 4 == 0);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        rast_rect clip;
        int32_t rows;
        /* the whole width; as many rows as the vertices take the deltas
         * for (8 a row), from 2 (one in the mask, the last in its own
         * row) up, somewhere */
        rows = (int32_t)(np / 8) < H ? (int32_t)(np / 8) : H;
        if (rows < 2) continue;
        if (rng() & 1) rows = 2 + (int32_t)(rng() % (uint32_t)(rows - 1));
        clip.x0 = 0;
        clip.x1 = W;
        clip.y0 = (int32_t)(rng() % (uint32_t)(H - rows + 1));
        clip.y1 = clip.y0 + rows;
        bytes_check_scene(iter, pts, sizes, nrings, np, s, center, textbook, rule, &clip, 1);
    }
    test_wound();
    return check_report("test_delta_inplace");
}

/*
 * fence.c - the fence filler (Dunlavey 1983; seed 001, section 3.5 and
 * Figure 3-37; seed 003): edge fill with a fence, a vertical line through
 * a vertex.  A crossing left of the fence complements the pixels from the
 * crossing to the fence; one right of it, the pixels from the fence to the
 * crossing.  Even-odd only, as edge fill.
 *
 * Why it is still exact: with the fence at column f and a crossing whose
 * first counting column is c, a sample i < f is complemented iff c <= i
 * (it lies in [c, f)), the same as edge fill; a sample i >= f is
 * complemented iff i < c (it lies in [f, c)), i.e. iff the crossing does
 * NOT count for it.  A row has an even number of crossings, so the number
 * that do not count has the parity of the number that do.
 *
 * The fence is the column of the vertex nearest the middle of the
 * polygon's box (cut to the clip): each complement then covers at most
 * about half the box instead of all of it right of the crossing.
 *
 * Scratch: the same one-bit-per-pixel mask as edgefill.c, for the same
 * reasons (height x ceil(width / 64) x 8 bytes).
 */
#include "poly.h"

/* The fence, relative to the box: the column (first counting column) of
 * the vertex nearest the box's middle, clamped to [0, bits]. */
static int32_t rast__fence_col(const rast_polygon *poly, uint32_t npoints,
                               const rast__grid *g, const rast__mask *m)
{
    int64_t mid = (int64_t)m->bits / 2, best = mid, dist = -1;
    uint32_t i;
    for (i = 0; i < npoints; i++) {
        int64_t c = rast__cross_col(2 * (int64_t)poly->points[i].x, 1, g) - m->box.col0;
        int64_t d;
        if (c < 0) c = 0;
        if (c > m->bits) c = m->bits;
        d = c > mid ? c - mid : mid - c;
        if (dist < 0 || d < dist) {
            dist = d;
            best = c;
        }
    }
    return (int32_t)best;
}

rast_status rast__fence_fill(const rast_polygon *poly, uint32_t npoints,
                             const rast__grid *g, rast_fill_rule rule,
                             const rast_rect *clip, rast__sink *sink,
                             rast__arena *arena)
{
    (void)rule; /* even-odd: the registry refuses non-zero */
    return rast__complement_fill(poly, npoints, g, clip, sink, arena, rast__fence_col);
}

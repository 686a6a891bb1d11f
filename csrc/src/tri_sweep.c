/*
 * tri_sweep.c - the sweep-line triangle filler (seeds 000, 002).
 *
 * Sort the vertices by y: a (top), b (middle), c (bottom).  The long edge
 * a->c crosses every row the triangle covers; the short edges a->b and b->c
 * share them out between the middle vertex's row and the rest.  Both ends of
 * each row's span come from the exact integer DDA of edge.c (quotient and
 * remainder, never a float), so a row's pixels are exactly
 * [first column counting the left crossing, first column counting the right
 * one): what the polygon rule gives a ring with two crossings per row.
 *
 * Scratch: none.
 */
#include "internal.h"

size_t rast__tri_sweep_scratch(int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return 0;
}

rast_status rast__tri_sweep_fill(const rast_point *t, const rast__grid *g,
                                 const rast_rect *clip, rast__sink *sink,
                                 rast__arena *arena)
{
    rast_point a = t[0], b = t[1], c = t[2], s;
    rast__edge e0, lng, sh;
    rast__rows o;
    int64_t side, r;
    int32_t ra, rb, rc, j;
    (void)arena;

    if (b.y < a.y) { s = a; a = b; b = s; }
    if (c.y < b.y) { s = b; b = c; c = s; }
    if (b.y < a.y) { s = a; a = b; b = s; }

    /* The long edge a->c goes down; b is right of it iff side > 0 (the
     * edge function of a->c at b; input units: products below 2^56). */
    side = (int64_t)(b.x - a.x) * (c.y - a.y) - (int64_t)(b.y - a.y) * (c.x - a.x);
    if (side == 0) return RAST_OK; /* degenerate: both crossings coincide */

    /* Each vertex's first row at or below it, once: the long edge walks
     * [ra, rc), the short ones [ra, rb) and [rb, rc), all cut to the clip. */
    r = rast__row_at_or_after(2 * (int64_t)a.y, g);
    ra = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)c.y, g);
    rc = r < clip->y1 ? (int32_t)r : clip->y1;
    if (ra >= rc) return RAST_OK;
    r = rast__row_at_or_after(2 * (int64_t)b.y, g);
    rb = r < ra ? ra : (r > rc ? rc : (int32_t)r);

    /* The walks run on local copies (sh, lng): the pixel stores of the
     * sink's inline path may alias anything whose address was taken, and
     * would make the compiler reload the edges from memory every row. */
    rast__edge_start(&e0, a, c, 1, ra, rc, g);
    lng = e0;
    o = rast__rows_of(sink);
    if (ra < rb) {
        rast__edge_start(&e0, a, b, 1, ra, rb, g);
        sh = e0;
        for (j = ra; j < rb; j++) {
            rast__rows_put(&o, j, side > 0 ? lng.x : sh.x, side > 0 ? sh.x : lng.x);
            rast__edge_step(&lng);
            rast__edge_step(&sh);
        }
    }
    if (rb < rc) {
        rast__edge_start(&e0, b, c, 1, rb, rc, g);
        sh = e0;
        for (j = rb; j < rc; j++) {
            rast__rows_put(&o, j, side > 0 ? lng.x : sh.x, side > 0 ? sh.x : lng.x);
            rast__edge_step(&lng);
            rast__edge_step(&sh);
        }
    }
    return RAST_OK;
}

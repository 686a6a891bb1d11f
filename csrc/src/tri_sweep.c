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
    rast__edge lng, sh;
    int64_t side;
    int k;
    (void)arena;

    if (b.y < a.y) { s = a; a = b; b = s; }
    if (c.y < b.y) { s = b; b = c; c = s; }
    if (b.y < a.y) { s = a; a = b; b = s; }

    /* The long edge a->c goes down; b is right of it iff side > 0 (the
     * edge function of a->c at b; input units: products below 2^56). */
    side = (int64_t)(b.x - a.x) * (c.y - a.y) - (int64_t)(b.y - a.y) * (c.x - a.x);
    if (side == 0) return RAST_OK; /* degenerate: both crossings coincide */
    if (!rast__edge_setup(&lng, a, c, g, clip->y0, clip->y1)) return RAST_OK;

    /* The short edges' visible rows follow each other and together are the
     * long edge's, so the long edge is always at the short edge's row. */
    for (k = 0; k < 2; k++) {
        int32_t j;
        if (!rast__edge_setup(&sh, k ? b : a, k ? c : b, g, clip->y0, clip->y1)) continue;
        if (side > 0) {
            for (j = sh.row; j < sh.end; j++) {
                rast__sink_span(sink, j, lng.x, sh.x);
                rast__edge_step(&lng);
                rast__edge_step(&sh);
            }
        } else {
            for (j = sh.row; j < sh.end; j++) {
                rast__sink_span(sink, j, sh.x, lng.x);
                rast__edge_step(&lng);
                rast__edge_step(&sh);
            }
        }
    }
    rast__sink_flush(sink);
    return RAST_OK;
}

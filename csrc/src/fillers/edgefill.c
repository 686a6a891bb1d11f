/*
 * edgefill.c - the edge fill filler (seed 001, section 3.5; seed 003):
 * for every crossing of every edge with a row, complement every pixel of
 * the row to the right of the crossing.  A sample ends up complemented
 * once per crossing at or left of it, so it is set iff that number is odd:
 * the even-odd rule, and only it (a complement has no direction).
 *
 * The edges are taken in the order given, each walked down its rows with
 * the exact DDA (rast__edge): the order does not matter, which is the
 * algorithm's point - it needs no edge table and no sorting, only a frame
 * buffer.  As the book suggests, the complement is restricted to the
 * polygon's bounding box (here cut to the clip): right of the box every
 * sample is complemented an even number of times anyway.  After the last
 * edge, the mask rows are read out as spans and painted.
 *
 * Scratch: the mask, ONE BIT per pixel of the clip, in 64-bit words
 * (height x ceil(width / 64) x 8 bytes; 512 KiB for 2048 x 2048).  A bit
 * because a pixel's whole state is one parity, and because complementing a
 * run of bits is a few word XORs (64 pixels each) where bytes would be 64
 * times as many writes.  Only the box's part is cleared and used.
 */
#include "poly.h"

rast_status rast__edgefill_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    (void)rule; /* even-odd: the registry refuses non-zero */
    /* Edge fill is the complement walk with its "fence" at the box's right
     * side: every run goes from the crossing to there. */
    return rast__complement_fill(poly, npoints, g, clip, sink, arena, NULL);
}

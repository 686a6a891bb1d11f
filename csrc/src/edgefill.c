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

size_t rast__edgefill_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)npoints;
    return rast__mask_scratch(width, height);
}

rast_status rast__edgefill_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    const rast_point *pts = poly->points;
    rast__mask m;
    uint32_t k, i, base;
    rast_status st;

    (void)rule; /* even-odd: the registry refuses non-zero */
    st = rast__mask_begin(&m, poly, npoints, g, clip, arena);
    if (st != RAST_OK || m.bits == 0) return st;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            rast__edge ed;
            int32_t j;
            if (!rast__edge_setup(&ed, pts[base + i], pts[base + (i + 1 == n ? 0 : i + 1)], g,
                                  m.box.row0, m.box.row1))
                continue;
            for (j = ed.row; j < ed.end; j++, rast__edge_step(&ed)) {
                /* Samples i >= ed.x count the crossing: complement them,
                 * from the box's left side when the crossing is left of it. */
                int32_t c = ed.x - m.box.col0;
                if (c < 0) c = 0;
                if (c < m.bits) rast__bits_flip(rast__mask_row(&m, j), c, m.bits);
            }
        }
    }
    rast__mask_spans(&m, sink);
    return RAST_OK;
}

/*
 * crossing.c - point by point, by crossing number (seed 003,
 * FillPolygonPbyP with a ray-crossing IsInside): for every sample, count
 * the edges that cross the leftward ray from it, and fill the sample iff
 * the count is odd.  Even-odd only: a count has no direction.
 *
 * The per-sample test is the rule of DESIGN section 1 itself, without a
 * division.  With an edge's upper end (x0, y0), dx = x1 - x0 and
 * dy = y1 - y0 > 0 (internal units), it crosses sample row yc iff
 * y0 <= yc < y1 (top closed, bottom open; the textbook's "vertex counted
 * twice, once or not at all" cases follow from it), and its crossing
 * X = x0 + (yc - y0) dx / dy counts for the sample at xc iff X <= xc, that
 * is iff the cross product
 *     d = dx (yc - y0) - dy (xc - x0) <= 0
 * (the sample is on or to the left of the edge walked downwards).
 * Textbook rounding counts it iff X < xc + unit/2: d < 0 at xc + unit/2.
 * |d| < 2^58 + 2^58 + 2^47 (poly.h): no overflow.
 *
 * It is the slow, teaching algorithm: every sample is tested on its own
 * against every edge.  Two restrictions keep it usable without changing a
 * pixel: only samples of the polygon's bounding box (cut to the clip) are
 * tested, and for each row only the edges that cross that row (collected
 * once per row, by testing every edge, as xscan.c does).
 *
 * Scratch: one rast__line (32 bytes) per vertex, twice: all the edges, and
 * the ones crossing the current row.
 */
#include "poly.h"

rast_status rast__crossing_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    rast__box box;
    rast__line *lines, *row;
    int32_t nlines, nrow, i, j, e;
    rast_status st;
    const int64_t half = g->textbook ? g->unit / 2 : 0, strict = g->textbook;

    (void)rule; /* even-odd: the registry refuses non-zero */
    st = rast__pointwise_begin(poly, npoints, g, clip, arena, &box, &lines, &row, &nlines);
    if (st != RAST_OK || nlines < 0) return st;

    for (j = box.row0; j < box.row1; j++) {
        const int64_t yc = (int64_t)j * g->unit + g->off;
        for (e = 0, nrow = 0; e < nlines; e++)
            if (lines[e].row <= j && j < lines[e].end) row[nrow++] = lines[e];
        for (i = box.col0; i < box.col1; i++) {
            const int64_t xc = (int64_t)i * g->unit + g->off + half;
            int32_t crossings = 0;
            for (e = 0; e < nrow; e++) {
                const rast__line *l = &row[e];
                int64_t d = (int64_t)l->dx * (yc - l->y0) - (int64_t)l->dy * (xc - l->x0);
                crossings += d + strict <= 0;
            }
            if (crossings & 1) rast__sink_span(sink, j, i, i + 1);
        }
    }
    rast__sink_flush(sink);
    return RAST_OK;
}

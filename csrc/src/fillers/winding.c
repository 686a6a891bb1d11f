/*
 * winding.c - point by point, by winding number (seed 003,
 * FillPolygonPbyP with the angle-sum IsInside): for every sample, the
 * number of times the polygon's boundary winds around it; inside iff it is
 * not 0 (non-zero) or odd (even-odd: the parity of the winding number is
 * the parity of the crossing number).
 *
 * The winding number is the exact integer form of the angle-sum method.
 * Seed 003 sums the signed angles theta_i that the edges subtend at the
 * sample: the sum is 2 pi w, 0 outside and +-2 pi inside a simple polygon,
 * and w in general.  Computing it with angles needs trigonometry and
 * rounding; but w is also the number of times the boundary sweeps past
 * any one direction from the sample, counted with sign.  Take the
 * direction "left" (the ray from the sample towards -x): an edge sweeps
 * past it exactly when it crosses the ray, clockwise or anticlockwise as
 * it goes down or up.  So
 *     w = sum over edges crossing the ray of their direction (+1 down, -1 up),
 * the same integer as the angle sum, found with integer comparisons only,
 * and, with DESIGN section 1's choice of which crossings are "on the ray"
 * (row top closed bottom open, X <= xc), defined on the boundary too.
 *
 * Each test is a cross-product sign, with the edge as given, a -> b:
 *     c = (bx - ax)(yc - ay) - (by - ay)(xc - ax),
 * the side of the edge the sample is on.  A downward edge (by > ay) that
 * crosses row yc adds +1 iff c <= 0, an upward one adds -1 iff c >= 0 (both
 * say "the crossing is at or left of the sample", X <= xc).  Textbook
 * rounding (X < xc + unit/2) tests at xc + unit/2 with strict signs.
 * |c| < 2^59 (poly.h).
 *
 * Slow by design, restricted as crossing.c is (samples of the bounding box
 * cut to the clip, and per row the edges crossing that row); same scratch:
 * one rast__line per vertex, twice.
 */
#include "poly.h"

rast_status rast__winding_fill(const rast_polygon *poly, uint32_t npoints,
                               const rast__grid *g, rast_fill_rule rule,
                               const rast_rect *clip, rast__sink *sink,
                               rast__arena *arena)
{
    rast__box box;
    rast__line *lines, *row;
    int32_t nlines, nrow, i, j, e;
    rast_status st;
    const int64_t half = g->textbook ? g->unit / 2 : 0, strict = g->textbook;

    st = rast__pointwise_begin(poly, npoints, g, clip, arena, &box, &lines, &row, &nlines);
    if (st != RAST_OK || nlines < 0) return st;

    for (j = box.row0; j < box.row1; j++) {
        const int64_t yc = (int64_t)j * g->unit + g->off;
        /* The edges crossing this row, turned back to their given
         * direction a -> b (rast__line keeps the upper end first). */
        for (e = 0, nrow = 0; e < nlines; e++) {
            rast__line l = lines[e];
            if (j < l.row || j >= l.end) continue;
            if (l.dir < 0) {
                l.x0 += l.dx;
                l.y0 += l.dy;
                l.dx = -l.dx;
                l.dy = -l.dy;
            }
            row[nrow++] = l;
        }
        for (i = box.col0; i < box.col1; i++) {
            const int64_t xc = (int64_t)i * g->unit + g->off + half;
            int32_t w = 0;
            for (e = 0; e < nrow; e++) {
                const rast__line *l = &row[e];
                int64_t c = (int64_t)l->dx * (yc - l->y0) - (int64_t)l->dy * (xc - l->x0);
                if (l->dy > 0 ? c + strict <= 0 : c - strict >= 0) w += l->dir;
            }
            if (rule == RAST_RULE_EVENODD ? (w & 1) : w != 0) rast__sink_span(sink, j, i, i + 1);
        }
    }
    rast__sink_flush(sink);
    return RAST_OK;
}

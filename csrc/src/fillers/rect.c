/*
 * rect.c - the rectangle filler: an axis-aligned rectangle's pixels,
 * exactly those of its polygon fill (left and top sides in, right and
 * bottom sides out), without an edge table: one column range for every
 * row.  It feeds the bilinear Gouraud painter (shade_rect.c).
 *
 * Scratch: none.
 */
#include "../base/internal.h"

void rast__rect_fill(int64_t x0, int64_t y0, int64_t w, int64_t h, const rast__grid *g,
                     const rast_rect *clip, const rast__painter *p)
{
    /* Columns counting the left side's crossing but not the right one's,
     * rows from the top side (closed) to the bottom side (open). */
    int64_t col0 = rast__cross_col(x0, 1, g), col1 = rast__cross_col(x0 + w, 1, g);
    int64_t row0 = rast__row_at_or_after(y0, g), row1 = rast__row_at_or_after(y0 + h, g);
    int64_t j;
    int32_t xs[2];
    if (col0 < clip->x0) col0 = clip->x0;
    if (col1 > clip->x1) col1 = clip->x1;
    if (col0 >= col1) return;
    if (row0 < clip->y0) row0 = clip->y0;
    if (row1 > clip->y1) row1 = clip->y1;
    xs[0] = (int32_t)col0;
    xs[1] = (int32_t)col1;
    for (j = row0; j < row1; j++) p->full(p->user, (int32_t)j, xs, 1);
}

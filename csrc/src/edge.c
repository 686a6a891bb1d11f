/*
 * edge.c - exact edge setup: where an edge first crosses a sample row, and
 * the integer DDA that walks it down (see rast__edge in internal.h).
 */
#include "internal.h"

int rast__edge_setup(rast__edge *ed, rast_point a, rast_point b,
                     const rast__grid *g, int32_t row_lo, int32_t row_hi)
{
    int64_t xa, ya, xb, yb, dx, dy, first, end, yc, q, n, r, step;
    int32_t dir = 1;

    if (a.y == b.y) return 0; /* horizontal edges never cross */
    if (a.y > b.y) {
        rast_point t = a;
        a = b;
        b = t;
        dir = -1;
    }
    xa = 2 * (int64_t)a.x;
    ya = 2 * (int64_t)a.y;
    xb = 2 * (int64_t)b.x;
    yb = 2 * (int64_t)b.y;

    /* Rows j with ya <= j*unit + off < yb, cut to [row_lo, row_hi). */
    first = rast__row_at_or_after(ya, g);
    end = rast__row_at_or_after(yb, g);
    if (first < row_lo) first = row_lo;
    if (end > row_hi) end = row_hi;
    if (first >= end) return 0;

    /* |dx|, dy < 2^29; |xa - off|, yc - ya < 2^29: n < 2^59, q < 2^46. */
    dx = xb - xa;
    dy = yb - ya;
    yc = first * g->unit + g->off;
    q = dy * g->unit;
    n = (xa - g->off) * dy + (yc - ya) * dx;
    /* Textbook rounding: the first column is floor((n + h*dy) / q) with
     * h = unit/2, which is ceil((n + h*dy - q + 1) / q); from then on the
     * walk is the same (rast__cross_col says this once for other users). */
    if (g->textbook) n += (int64_t)(g->unit / 2) * dy - q + 1;

    /* x = ceil(n / q) and e = x*q - n, without forming x*q (it may not fit). */
    r = n % q;
    if (r < 0) r += q;
    ed->x = (int32_t)((n - r) / q + (r != 0));
    ed->e = r ? q - r : 0;
    ed->q = q;

    step = rast__floordiv(dx, dy);
    ed->step = (int32_t)step;
    ed->dr = (dx - step * dy) * g->unit;
    ed->row = (int32_t)first;
    ed->end = (int32_t)end;
    ed->dir = dir;
    ed->next = -1;
    return 1;
}

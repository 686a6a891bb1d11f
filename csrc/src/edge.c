/*
 * edge.c - exact edge setup: where an edge first crosses a sample row, and
 * the integer DDA that walks it down (see rast__edge in internal.h).
 *
 * Setup is most of the cost of a small primitive (a triangle of a mesh has
 * three edges and a handful of rows), and its cost is divisions.  Those by
 * the unit (a power of two) are shifts; the whole columns per row always
 * fit 32 bits; the first crossing is split into a whole column at the upper
 * vertex plus a remainder that fits 32 bits unless the edge is very long or
 * starts far above the first row, and a 32-bit division is several times
 * faster than a 64-bit one on common CPUs.
 */
#include "internal.h"

/* floor(a / 2^shift) for |a| < 2^30, by a shift of a + 2^30 >= 0. */
static int32_t rast__floorshift32(int32_t a, int32_t shift)
{
    const uint32_t bias = (uint32_t)1 << 30;
    return (int32_t)(((uint32_t)a + bias) >> shift) - (int32_t)(bias >> shift);
}

void rast__edge_start(rast__edge *ed, rast_point top, rast_point bottom,
                      int32_t dir, int32_t first, int32_t end, const rast__grid *g)
{
    /* Internal units: |coordinate| < 2^28, differences < 2^29. */
    int32_t xa = 2 * top.x, ya = 2 * top.y;
    int32_t dx = 2 * bottom.x - xa, dy = 2 * bottom.y - ya;
    int32_t base, xr, step;
    int64_t q = (int64_t)dy * g->unit; /* < 2^46 */
    int64_t n, t, r;

    /* The first column x = ceil(n / q), n = (xa - off)*dy + (yc - ya)*dx
     * with yc = first*unit + off.  With xa - off = base*unit + xr
     * (0 <= xr < unit), n / q is base plus n' / q, n' = xr*dy + (yc - ya)*dx,
     * small unless the edge is long or starts far above row `first`;
     * |n'| < 2^59 in any case. */
    base = rast__floorshift32(xa - g->off, g->shift);
    xr = xa - g->off - base * g->unit;
    n = (int64_t)xr * dy + ((int64_t)first * g->unit + g->off - ya) * dx;
    /* Textbook rounding: the first column is floor((n + h*dy) / q) with
     * h = unit/2, which is ceil((n + h*dy - q + 1) / q); from then on the
     * walk is the same (rast__cross_col says this once for other users). */
    if (g->textbook) n += (int64_t)(g->unit / 2) * dy - q + 1;

    /* x = ceil(n / q) and e = x*q - n, without forming x*q (it may not fit),
     * from one truncating division: n = t*q + r with r of n's sign; the
     * ceiling is t + 1 when r > 0, else t. */
    if (q <= INT32_MAX && n >= -INT32_MAX && n <= INT32_MAX) {
        t = (int32_t)n / (int32_t)q;
        r = (int32_t)n % (int32_t)q;
    } else {
        t = n / q;
        r = n % q;
    }
    ed->x = (int32_t)(base + t + (r > 0));
    ed->e = r > 0 ? q - r : -r;
    ed->q = q;

    /* Whole columns per row, floor(dx / dy), and the remainder's growth. */
    step = dx / dy;
    step -= dx % dy < 0;
    ed->step = step;
    ed->dr = (int64_t)(dx - step * dy) * g->unit;
    ed->row = first;
    ed->end = end;
    ed->dir = dir;
    ed->next = -1;
}

int rast__edge_setup(rast__edge *ed, rast_point a, rast_point b,
                     const rast__grid *g, int32_t row_lo, int32_t row_hi)
{
    int64_t first, end;
    int32_t dir = 1;

    if (a.y == b.y) return 0; /* horizontal edges never cross */
    if (a.y > b.y) {
        rast_point s = a;
        a = b;
        b = s;
        dir = -1;
    }
    /* Rows j with ya <= j*unit + off < yb, cut to [row_lo, row_hi). */
    first = rast__row_at_or_after(2 * (int64_t)a.y, g);
    end = rast__row_at_or_after(2 * (int64_t)b.y, g);
    if (first < row_lo) first = row_lo;
    if (end > row_hi) end = row_hi;
    if (first >= end) return 0;
    rast__edge_start(ed, a, b, dir, (int32_t)first, (int32_t)end, g);
    return 1;
}

/*
 * edge.c - exact edge setup: where an edge first crosses a sample row, and
 * the integer DDA that walks it down (see rast__edge in internal.h).  The
 * bodies are inline functions in internal.h, which the triangle fillers
 * use directly; these are the out-of-line copies the polygon fillers
 * call.
 */
#include "internal.h"

void rast__edge_start(rast__edge *ed, rast_point top, rast_point bottom,
                      int32_t dir, int32_t first, int32_t end, const rast__grid *g)
{
    rast__edge_start_inline(ed, top, bottom, dir, first, end, g);
}

int rast__edge_setup(rast__edge *ed, rast_point a, rast_point b,
                     const rast__grid *g, int32_t row_lo, int32_t row_hi)
{
    return rast__edge_setup_inline(ed, a, b, g, row_lo, row_hi);
}

/*
 * aet.c - the active edge table filler (seed 001, section 3.4); the walk
 * itself is in base/aet.h.
 *
 * (How the walk works, and how a row's new edges join the AET in
 * O(k log k + n): aet.h.)
 *
 * Scratch: the edge table and the AET (an edge record each) and one bucket
 * per visible row (where its run of the table ends).
 */
#include "../base/aet.h"

/* The edge record's size is part of the scratch contract in rastrum.h. */
typedef char rast__aet_edge_size_check[sizeof(rast__edge) == RAST_AET_EDGE_BYTES ? 1 : -1];

size_t rast__aet_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    return rast__size_add(
        rast__size_mul(2, rast__align(rast__size_mul(npoints, sizeof(rast__edge)))),
        rast__align(rast__size_mul((size_t)height + 1, sizeof(int32_t))));
}

static inline void rast__aet_span(void *user, int32_t row, const rast__edge *l, const rast__edge *r)
{
    rast__sink_span((rast__sink *)user, row, l->x, r->x);
}

rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena)
{
    rast_status st = rast__aet_walk(poly, npoints, g, rule, clip, arena, rast__aet_span, NULL, sink, NULL);
    rast__sink_flush(sink);
    return st;
}

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
#include "../base/internal.h"

size_t rast__tri_sweep_scratch(int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return 0;
}

/* Put p and q in order of y (q.y < p.y: swapped), without a branch. */
static inline void rast__sort2(rast_point *p, rast_point *q)
{
    int32_t sw = q->y < p->y, px = p->x, py = p->y, qx = q->x, qy = q->y;
    p->x = sw ? qx : px;
    p->y = sw ? qy : py;
    q->x = sw ? px : qx;
    q->y = sw ? py : qy;
}

/* Rows [j0, j1) between the long edge and a short one (long_left: the
 * long one is the left bound).  `direct` (a constant, so this is two
 * loops): the sink writes inline and no run needs cutting, so each row is
 * one memset down a row pointer.  The walks run on the caller's locals:
 * the pixel stores may alias anything whose address escaped, and would
 * make the compiler reload the edges from memory every row. */
RAST__HOT void rast__sweep_rows(const rast__rows *o, int32_t j0, int32_t j1, rast__edge *lng,
                                    rast__edge *sh, int long_left, int direct)
{
    unsigned char *p = rast__rows_at(o, j0, direct);
    int32_t j;
    for (j = j0; j < j1; j++) {
        rast__rows_emit(o, &p, j, long_left ? lng->x : sh->x, long_left ? sh->x : lng->x, direct);
        rast__edge_step(lng);
        rast__edge_step(sh);
    }
}

/* Both halves: [ra, rb) between a->c and a->b, [rb, rc) between a->c and
 * b->c. */
RAST__HOT void rast__sweep_halves(const rast__rows *o, rast_point a, rast_point b,
                                      rast_point c, int32_t ra, int32_t rb, int32_t rc,
                                      int long_left, const rast__grid *g, int direct)
{
    rast__edge e, lng, sh;
    rast__edge_start_tri(&e, a, c, 1, ra, rc, g);
    lng = e;
    if (ra < rb) {
        rast__edge_start_tri(&e, a, b, 1, ra, rb, g);
        sh = e;
        rast__sweep_rows(o, ra, rb, &lng, &sh, long_left, direct);
    }
    if (rb < rc) {
        rast__edge_start_tri(&e, b, c, 1, rb, rc, g);
        sh = e;
        rast__sweep_rows(o, rb, rc, &lng, &sh, long_left, direct);
    }
}

rast_status rast__tri_sweep_fill(const rast_point *t, const rast__grid *g,
                                 const rast_rect *clip, rast__sink *sink,
                                 rast__arena *arena)
{
    rast_point a = t[0], b = t[1], c = t[2];
    rast__rows o;
    int64_t side, r, xmin, xmax;
    int32_t ra, rb, rc;
    (void)arena;

    /* Sorted by y with compare-and-swaps that compile to conditional
     * moves: the order of a triangle's vertices is a coin toss a branch
     * would mispredict. */
    rast__sort2(&a, &b);
    rast__sort2(&b, &c);
    rast__sort2(&a, &b);

    /* The long edge a->c goes down; b is right of it iff side > 0 (the
     * edge function of a->c at b; input units: products below 2^56). */
    side = (int64_t)(b.x - a.x) * (c.y - a.y) - (int64_t)(b.y - a.y) * (c.x - a.x);
    if (side == 0) return RAST_OK; /* degenerate: both crossings coincide */

    /* Each vertex's first row at or below it, once: the long edge walks
     * [ra, rc), the short ones [ra, rb) and [rb, rc), all cut to the clip. */
    r = rast__row_at_or_after(2 * (int64_t)a.y, g);
    ra = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)c.y, g);
    rc = r < clip->y1 ? (int32_t)r : clip->y1;
    if (ra >= rc) return RAST_OK;
    r = rast__row_at_or_after(2 * (int64_t)b.y, g);
    rb = r < ra ? ra : (r > rc ? rc : (int32_t)r);

    /* Every crossing lies between the vertices' abscissae. */
    xmin = a.x < b.x ? a.x : b.x;
    xmin = xmin < c.x ? xmin : c.x;
    xmax = a.x > b.x ? a.x : b.x;
    xmax = xmax > c.x ? xmax : c.x;
    o = rast__rows_of(sink);
    if (rast__rows_direct_uncut(&o, 2 * xmin, 2 * xmax, g))
        rast__sweep_halves(&o, a, b, c, ra, rb, rc, side > 0, g, 1);
    else
        rast__sweep_halves(&o, a, b, c, ra, rb, rc, side > 0, g, 0);
    return RAST_OK;
}

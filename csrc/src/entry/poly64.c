/*
 * poly64.c - the polygon fills on 64-bit vertices (rast_polygon64): the
 * precision path for S up to 32 (issue 13).
 *
 * Ranges.  A vertex coordinate v satisfies |v| <= 2^(S+28) - 1 (fixed
 * point, S <= 32), so the doubled internal coordinates satisfy |X| < 2^61
 * and every edge difference |dx|, |dy| < 2^62; the unit is 2^(S+1) <=
 * 2^33.  A sample row inside an edge's rows has |j unit| < 2^61.
 *
 * The edge.  The 32-bit edge (internal.h) keeps x and the remainder
 * e = x q - n in [0, q) for q = dy unit, which at S = 32 and dy near 2^62
 * would need 96 bits.  But from row to row n grows by dx unit, a multiple
 * of the unit, so e mod unit never changes, and whether e - dr wraps
 * below 0 depends on floor(e / unit) alone.  This path keeps
 *     E = floor(e / unit) in [0, dy),  dr = dx mod dy,  q = dy,
 * and steps exactly as rast__edge_step does: the same record, the same
 * walk (aet.h's rast__aet_sweep), with 64-bit numbers throughout.  Only
 * the first crossing needs more: with xa - off = base unit + xr
 * (0 <= xr < unit) and w = yc - ya (the first row's sample below the upper
 * vertex, 0 <= w < dy), the column is
 *     x = base + x',  x' = ceil(m / dy),  m = ceil(n' / unit),
 *     n' = xr dy + w dx                    (|n'| < 2^125: 128 bits),
 * and E = x' dy - m.  (ceil(ceil(a / b) / c) = ceil(a / (b c)) for
 * positive b, c.)  m fits 64 bits unless the edge starts far above the
 * clip (w < unit bounds |n'| by unit (dy + |dx|)); then it is a 128-bit
 * division (wide.h).
 *
 * Why the walk's int32 fields suffice: a column x at a row the edge
 * crosses lies within a pixel of the edge's x extent, |x| <= 2^28 + 1; an
 * edge crossing two rows or more has dy > unit, so |step| = |floor(dx/dy)|
 * < 2^30 / 2 = 2^29 (|dx| < 2^(S+30)); after its last row the walk steps it
 * once more (then drops it): |x + step + 1| < 2^30.  An edge with one
 * visible row never steps into another, and its step and dr are set to 0.
 */
#include "../base/aet.h"
#include "../painters/paint.h"
#include "../base/wide.h"

/* The fill's options, checked, and the grid: RAST_E_NULL, RAST_E_ALGORITHM,
 * RAST_E_ARG, RAST_E_RULE, RAST_E_SUBPIXEL, RAST_E_WIDE. */
static rast_status rast__check_opts64(const rast_fill_opts *o, rast__grid64 *g)
{
    rast_status st;
    uint32_t rules;
    if (!o) return RAST_E_NULL;
    if (!RAST_CONFIG_POLYGON64) return RAST_E_WIDE; /* left out (base/config.h) */
    st = rast_algorithm_info(o->algorithm, NULL, &rules);
    if (st != RAST_OK) return st;
    if ((unsigned)o->rule > RAST_RULE_NONZERO) return RAST_E_ARG;
    if (!(rules & (1u << o->rule))) return RAST_E_RULE;
    if (o->subpixel_bits < 0 || o->subpixel_bits > RAST_MAX_SUBPIXEL_BITS64)
        return RAST_E_SUBPIXEL;
    if (o->sample != RAST_SAMPLE_CORNER && o->sample != RAST_SAMPLE_CENTER) return RAST_E_ARG;
    if ((unsigned)o->rounding > RAST_ROUND_TEXTBOOK) return RAST_E_ARG;
    if ((unsigned)o->boundary > RAST_BOUNDARY_CONSERVATIVE || !RAST__BOUNDARY_KEPT(o->boundary))
        return RAST_E_ARG;
    if (o->algorithm != RAST_ALGO_AET || o->rounding != RAST_ROUND_EXACT ||
        o->boundary == RAST_BOUNDARY_CLOSED)
        return RAST_E_WIDE;
    g->shift = o->subpixel_bits + 1;
    g->unit = (int64_t)1 << g->shift;
    g->off = o->sample == RAST_SAMPLE_CENTER ? (int64_t)1 << o->subpixel_bits : 0;
    return RAST_OK;
}

/* Count the vertices (checking the pointers). */
static rast_status rast__count_polygon64(const rast_polygon64 *p, uint32_t *npoints)
{
    uint64_t n = 0;
    uint32_t k;
    if (!p) return RAST_E_NULL;
    if (p->nrings > 0 && !p->ring_sizes) return RAST_E_NULL;
    for (k = 0; k < p->nrings; k++) {
        n += p->ring_sizes[k];
        if (n > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    if (n > 0 && !p->points) return RAST_E_NULL;
    *npoints = (uint32_t)n;
    return RAST_OK;
}

/* Count the vertices and check that every one is in range. */
static rast_status rast__check_polygon64(const rast_polygon64 *p, int32_t s, uint32_t *npoints)
{
    const int64_t lim = RAST_COORD64_MAX(s);
    uint32_t n = 0, i;
    rast_status st = rast__count_polygon64(p, &n);
    if (st != RAST_OK) return st;
    for (i = 0; i < n; i++) {
        int64_t x = p->points[i].x, y = p->points[i].y;
        if (x < -lim || x > lim || y < -lim || y > lim) return RAST_E_RANGE;
    }
    *npoints = n;
    return RAST_OK;
}

static size_t rast__scratch64(const rast_fill_opts *o, uint32_t npoints, int32_t height)
{
    size_t need = rast__aet_scratch(npoints, 0, height);
    if (RAST__BOUNDARY_MODES && o->boundary != RAST_BOUNDARY_EXACT)
        need = rast__size_add(need, rast__bound_scratch64(npoints, height));
    return need;
}

rast_status rast_scratch_size64(const rast_fill_opts *opts, uint32_t npoints, int32_t width,
                                int32_t height, size_t *bytes)
{
    rast__grid64 g;
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__check_opts64(opts, &g);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__scratch64(opts, npoints, height);
    return RAST_OK;
}

/* The first row whose sample is at or below internal ordinate y (|y| <
 * 2^61): ceil((y - off) / unit), as a shift of the value made
 * non-negative by a bias. */
static inline int64_t rast__row64(int64_t y, const rast__grid64 *g)
{
    const int64_t bias = (int64_t)1 << 62;
    return (int64_t)((uint64_t)(y - g->off + g->unit - 1 + bias) >> g->shift) -
           (bias >> g->shift);
}

/* rast__edge_setup for a 64-bit edge (see the top of this file). */
static inline int rast__edge_setup64(rast__edge *ed, rast_point64 a, rast_point64 b,
                                     const rast__grid64 *g, int32_t row_lo, int32_t row_hi)
{
    const int64_t bias = (int64_t)1 << 62;
    int64_t first, end, xa, ya, dx, dy, base, xr, w, xq, e, step;
    int32_t dir = 1;
    rast__i128 n;

    if (a.y == b.y) return 0; /* horizontal edges never cross */
    if (a.y > b.y) {
        rast_point64 t = a;
        a = b;
        b = t;
        dir = -1;
    }
    first = rast__row64(2 * a.y, g);
    end = rast__row64(2 * b.y, g);
    if (first < row_lo) first = row_lo;
    if (end > row_hi) end = row_hi;
    if (first >= end) return 0;

    xa = 2 * a.x;
    ya = 2 * a.y;
    dx = 2 * b.x - xa;
    dy = 2 * b.y - ya;
    /* xa - off = base * unit + xr, 0 <= xr < unit (|xa - off| < 2^62) */
    base = (int64_t)((uint64_t)(xa - g->off + bias) >> g->shift) - (bias >> g->shift);
    xr = xa - g->off - base * g->unit;
    w = first * g->unit + g->off - ya;
    n = rast__i128_add(rast__i128_mul(xr, dy), rast__i128_mul(w, dx));
    n = rast__i128_ceilshift(n, g->shift); /* m = ceil(n' / unit) */
    if (rast__i128_is64(n)) /* m = xq dy + e, 0 <= e < dy */
        rast__floordivmod((int64_t)n.lo, dy, &xq, &e);
    else
        rast__wide_floordiv(n, dy, &xq, &e);
    /* x' = ceil(m / dy), E = x' dy - m */
    if (e > 0) {
        xq += 1;
        e = dy - e;
    }
    ed->x = (int32_t)(base + xq);
    ed->e = e;
    ed->q = dy;
    if (end - first > 1) {
        rast__floordivmod(dx, dy, &step, &ed->dr);
        ed->step = (int32_t)step;
    } else {
        ed->step = 0;
        ed->dr = 0;
    }
    ed->row = (int32_t)first;
    ed->end = (int32_t)end;
    ed->dir = dir;
    ed->next = -1;
    return 1;
}

static inline void rast__aet64_span(void *user, int32_t row, const rast__edge *l,
                                    const rast__edge *r)
{
    rast__sink_span((rast__sink *)user, row, l->x, r->x);
}

/* The AET walk of aet.h with the 64-bit setup. */
static rast_status rast__aet64_fill(const rast_polygon64 *poly, uint32_t npoints,
                                    const rast__grid64 *g, rast_fill_rule rule,
                                    const rast_rect *clip, rast__sink *sink,
                                    rast__arena *arena)
{
    const rast_point64 *pts = poly->points;
    rast__edge *edges, *aet;
    int32_t *bucket;
    int64_t miny, maxy, r;
    int32_t row0, row1, nedges = 0;
    uint32_t i, k, base;

    if (npoints == 0) return RAST_OK;
    miny = maxy = pts[0].y;
    for (i = 1; i < npoints; i++) {
        if (pts[i].y < miny) miny = pts[i].y;
        if (pts[i].y > maxy) maxy = pts[i].y;
    }
    r = rast__row64(2 * miny, g);
    row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row64(2 * maxy, g);
    row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    if (row0 >= row1) return RAST_OK;

    if (!rast__aet_tables(arena, npoints, row0, row1, &edges, &aet, &bucket))
        return RAST_E_SCRATCH;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            rast__edge *ed = &aet[nedges];
            if (rast__edge_setup64(ed, pts[base + i], pts[base + (i + 1 == n ? 0 : i + 1)], g,
                                   row0, row1)) {
                ed->next = nedges++;
                bucket[ed->row - row0 + 1]++;
            }
        }
    }
    rast__aet_sweep(edges, aet, bucket, nedges, row0, row1, rule, rast__aet64_span, NULL, sink);
    return RAST_OK;
}

rast_status rast__fill64_prepare(const rast_fill_opts *opts, rast__grid64 *g)
{
    return rast__check_opts64(opts, g);
}

size_t rast__fill64_scratch(const rast_fill_opts *opts, uint32_t npoints, int32_t height)
{
    return rast__scratch64(opts, npoints, height);
}

rast_status rast__fill64_checked(const rast_polygon64 *poly, uint32_t npoints,
                                 const rast_fill_opts *opts, const rast__grid64 *g,
                                 const rast_rect *clip, const rast__painter *p, void *scratch,
                                 size_t scratch_bytes)
{
    rast__sink sink;
    rast__arena arena = rast__arena_of(scratch, scratch_bytes);
    rast_status st;

    rast__sink_init(&sink, p, clip);
    if (!RAST__BOUNDARY_MODES || opts->boundary == RAST_BOUNDARY_EXACT) {
        st = rast__aet64_fill(poly, npoints, g, opts->rule, clip, &sink, &arena);
        rast__sink_flush(&sink);
        return st;
    }
    {
        rast__bound b;
        st = rast__bound_begin64(&b, poly, npoints, g, clip, &sink, &arena);
        if (st == RAST_OK) st = rast__aet64_fill(poly, npoints, g, opts->rule, clip, &b.in, &arena);
        if (st == RAST_OK) rast__bound_end(&b);
        return st;
    }
}

/* Check the polygon, options and scratch for a clip; run the filler. */
static rast_status rast__fill64(const void *polygon, const rast_fill_opts *opts,
                                const rast_rect *clip, const rast__painter *p,
                                void *scratch, size_t scratch_bytes)
{
    const rast_polygon64 *poly = (const rast_polygon64 *)polygon;
    rast__grid64 g;
    uint32_t npoints;
    rast_status st;

    st = rast__check_opts64(opts, &g);
    if (st != RAST_OK) return st;
    st = rast__check_polygon64(poly, opts->subpixel_bits, &npoints);
    if (st != RAST_OK) return st;
    st = rast__scratch_check(scratch, scratch_bytes,
                             rast__scratch64(opts, npoints, clip->y1 - clip->y0));
    if (st != RAST_OK) return st;
    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK;
    return rast__fill64_checked(poly, npoints, opts, &g, clip, p, scratch, scratch_bytes);
}

rast_status rast_fill_polygon64(const rast_target *target, const rast_polygon64 *polygon,
                                const rast_fill_opts *opts, const void *pixel, void *scratch,
                                size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, NULL, 0, rast__fill64, scratch,
                             scratch_bytes);
}

rast_status rast_fill_polygon64_opaque(const rast_target *target, const rast_polygon64 *polygon,
                                       const rast_fill_opts *opts, const void *pixel,
                                       const void *background, void *scratch,
                                       size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, background, 1, rast__fill64, scratch,
                             scratch_bytes);
}

rast_status rast_fill_polygon64_spans(const rast_polygon64 *polygon, const rast_fill_opts *opts,
                                      const rast_rect *clip, rast_span_fn span, void *user,
                                      void *scratch, size_t scratch_bytes)
{
    return rast__fill_spans(polygon, opts, clip, span, user, rast__fill64, scratch,
                            scratch_bytes);
}

rast_status rast_fill_bounds64(const rast_fill_opts *opts, const rast_polygon64 *polygon,
                               const rast_rect *clip, rast_rect *bounds)
{
    rast__grid64 g;
    uint32_t npoints;
    rast_status st;

    if (!clip || !bounds) return RAST_E_NULL;
    st = rast__check_opts64(opts, &g);
    if (st != RAST_OK) return st;
    return rast__fill64_measure(opts, &g, polygon, clip, &npoints, bounds);
}

rast_status rast__fill64_measure(const rast_fill_opts *opts, const rast__grid64 *gp,
                                 const rast_polygon64 *polygon, const rast_rect *clip,
                                 uint32_t *npoints, rast_rect *bounds)
{
    const int64_t bias = (int64_t)1 << 62;
    const rast__grid64 g = *gp;
    rast_rect c, out;
    uint32_t i;
    int64_t lo[2], hi[2], x0, x1, y0, y1;
    rast_status st;

    /* rast__check_polygon64's checks, in its order, the range on the
     * extent (one pass over the vertices) */
    st = rast__count_polygon64(polygon, npoints);
    if (st != RAST_OK) return st;
    lo[0] = hi[0] = lo[1] = hi[1] = 0;
    if (*npoints > 0) {
        const rast_point64 *pts = polygon->points;
        const int64_t lim = RAST_COORD64_MAX(opts->subpixel_bits);
        lo[0] = hi[0] = pts[0].x;
        lo[1] = hi[1] = pts[0].y;
        for (i = 1; i < *npoints; i++) {
            if (pts[i].x < lo[0]) lo[0] = pts[i].x;
            if (pts[i].x > hi[0]) hi[0] = pts[i].x;
            if (pts[i].y < lo[1]) lo[1] = pts[i].y;
            if (pts[i].y > hi[1]) hi[1] = pts[i].y;
        }
        if (lo[0] < -lim || hi[0] > lim || lo[1] < -lim || hi[1] > lim) return RAST_E_RANGE;
    }
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    out.x0 = out.x1 = c.x0; /* empty unless something below says otherwise */
    out.y0 = out.y1 = c.y0;
    if (*npoints > 0) {
        if (opts->boundary == RAST_BOUNDARY_EXACT) {
            /* The AET's rows; columns from the first column counting a
             * crossing at min x to the one counting max x (poly.h). */
            x0 = rast__row64(2 * lo[0], &g);
            x1 = rast__row64(2 * hi[0], &g);
            y0 = rast__row64(2 * lo[1], &g);
            y1 = rast__row64(2 * hi[1], &g);
        } else {
            /* The vertices' pixel hull, one more pixel each side (as
             * rast_fill_bounds). */
            const int32_t s = opts->subpixel_bits;
            x0 = (int64_t)((uint64_t)(lo[0] + bias) >> s) - (bias >> s) - 1;
            x1 = (int64_t)((uint64_t)(hi[0] + bias) >> s) - (bias >> s) + 2;
            y0 = (int64_t)((uint64_t)(lo[1] + bias) >> s) - (bias >> s) - 1;
            y1 = (int64_t)((uint64_t)(hi[1] + bias) >> s) - (bias >> s) + 2;
        }
        rast__rect_cut64(&out, &c, x0, x1, y0, y1);
    }
    *bounds = out;
    return RAST_OK;
}

/*
 * shade_poly.c - polygons with a colour per vertex, through the active edge
 * table (seed 001: "the two ends of every span are known before it is
 * filled, so the span can be shaded smoothly"): edge, then span.
 *
 * The pixels are the AET's (aet.h), so exactly the polygon fill's.  The
 * colour of a sample (xs, yc) of a run bounded by edges l and r (rastrum.h
 * says which) is, per channel, in internal units:
 *   - each bounding edge, from its upper end (xt, yt, ct) to its lower end
 *     (xb, yb, cb), dy = yb - yt > 0, crosses the row at X = Q / dy with
 *     Q = xt dy + (yc - yt)(xb - xt), with the colour P / dy,
 *     P = ct dy + (yc - yt)(cb - ct): exact rationals;
 *   - along the run, c = cl + (xs - Xl) (cr - cl) / (Xr - Xl), which over
 *     the common denominator D = dl G, G = Qr dl - Ql dr > 0, is
 *     c = (Pl G + (xs dl - Ql) E) / D with E = Pr dl - Pl dr;
 *   - the pixel gets floor(c + 1/2).
 * Magnitudes (poly.h's ranges: |coordinates| < 2^28, dy < 2^29):
 * |Q| < 2^59, P < 2^37, G < 2^89, |E| < 2^67, D < 2^118, and since c is a
 * convex combination of the corners for xs in [Xl, Xr) (a textbook
 * sample left of Xl is clamped apart, see rast__gpoly_span),
 * 0 <= c D <= 255 D < 2^126: all inside
 * the signed 128-bit integers of wide.h.  From one sample to the next the
 * numerator grows by T = unit dl E (|T| < 2^113), less than 256 D: the
 * quotient and remainder (in [0, D)) are stepped, as the rectangle's.
 */
#include "../base/aet.h"
#include "shade_run.h"
#include "../base/wide.h"

/* ---- 128-bit helpers beyond wide.h ------------------------------------------- */

static int rast__i128_lt(rast__i128 a, rast__i128 b)
{
    if (a.hi != b.hi) return (int64_t)a.hi < (int64_t)b.hi;
    return a.lo < b.lo;
}

static rast__i128 rast__sp_i128_sub(rast__i128 a, rast__i128 b)
{
    return rast__i128_add(a, rast__i128_neg(b));
}

/* a * b for a product known to fit 128 bits (sign and magnitude: |a|'s
 * halves times |b|). */
static rast__i128 rast__i128_mul_wide(rast__i128 a, int64_t b)
{
    int neg = (int64_t)a.hi < 0, nb = b < 0;
    uint64_t ub = nb ? 0 - (uint64_t)b : (uint64_t)b;
    rast__i128 r, lo;
    if (neg) a = rast__i128_neg(a);
    /* |a|.lo * ub: split the low half so that rast__i128_mul's signed
     * operands stay below 2^63. */
    lo = rast__i128_add(rast__i128_mul((int64_t)(a.lo >> 1), (int64_t)ub),
                        rast__i128_mul((int64_t)(a.lo >> 1), (int64_t)ub));
    if (a.lo & 1u) lo = rast__i128_add(lo, rast__i128_from((int64_t)ub));
    r.lo = lo.lo;
    r.hi = lo.hi + a.hi * ub;
    return neg != nb ? rast__i128_neg(r) : r;
}

/* floor(n / d) and the remainder in [0, d), for d > 0 and a quotient of
 * magnitude below 2^10 (restoring division over ten quotient bits). */
static int32_t rast__i128_small_div(rast__i128 n, rast__i128 d, rast__i128 *rem)
{
    int neg = (int64_t)n.hi < 0;
    int32_t q = 0, b;
    if (neg) n = rast__i128_neg(n);
    for (b = 9; b >= 0; b--) {
        rast__i128 s = rast__i128_shl(d, b);
        if (!rast__i128_lt(n, s)) {
            n = rast__sp_i128_sub(n, s);
            q += (int32_t)1 << b;
        }
    }
    if (neg && (n.hi | n.lo)) {
        q = -q - 1;
        n = rast__sp_i128_sub(d, n);
    } else if (neg) {
        q = -q;
    }
    *rem = n;
    return q;
}

/* ---- the painter ------------------------------------------------------------------- */

/* The polygon's Gouraud painter: rast__gpoly_span colours columns of the
 * current run, whose bounding edges rast__gpoly_begin was given. */
typedef struct rast__shade_poly {
    unsigned char *base;   /* pixel (x, y) of the destination: row y - oy of */
    ptrdiff_t stride;      /* base, column x - ox (a target: ox = oy = 0) */
    int32_t ox, oy;
    rast__rgba_out out;    /* stored, or blended (rast_fill_polygon_gouraud_blend) */
    int flat;              /* FLAT through the blend: vertex 0's colour */
    const rast_point *pts;
    const uint8_t *colors; /* 4 per vertex */
    const int32_t *src;    /* edge k: from vertex src[2k] to src[2k+1] */
    const rast__grid *g;
    int32_t l, r;          /* the current run's bounding edges */
    int32_t cx0, cx1;      /* the filler's clip columns */
} rast__shade_poly;

/* An edge at sample ordinate yc: X = Q / dy, colour P[ch] / dy. */
typedef struct rast__edge_at {
    int64_t Q, dy, P[4];
} rast__edge_at;

static void rast__edge_at_row(const rast__shade_poly *s, int32_t k, int64_t yc, rast__edge_at *e)
{
    int32_t ia = s->src[2 * k], ib = s->src[2 * k + 1], ch;
    rast_point a = s->pts[ia], b = s->pts[ib];
    int64_t xt, yt, xb, t;
    if (a.y > b.y) {
        int32_t ti = ia;
        rast_point tp = a;
        a = b;
        b = tp;
        ia = ib;
        ib = ti;
    }
    xt = 2 * (int64_t)a.x;
    yt = 2 * (int64_t)a.y;
    xb = 2 * (int64_t)b.x;
    e->dy = 2 * ((int64_t)b.y - a.y);
    t = yc - yt;
    e->Q = xt * e->dy + t * (xb - xt);
    for (ch = 0; ch < 4; ch++) {
        int64_t ct = s->colors[4 * ia + ch], cb = s->colors[4 * ib + ch];
        e->P[ch] = ct * e->dy + t * (cb - ct);
    }
}

/* The run about to be painted: bounded by edges l and r (indices into the
 * edge table, see src). */
static inline void rast__gpoly_begin(rast__shade_poly *s, int32_t l, int32_t r)
{
    s->l = l;
    s->r = r;
}

/* Columns [x0, x1) (x0 < x1) of row `row` of the current run. */
static void rast__gpoly_span(const rast__shade_poly *s, int32_t row, int32_t x0, int32_t x1)
{
    const rast__grid *g = s->g;
    unsigned char run[4 * RAST__SHADE_RUN];
    unsigned char *p = s->base + (ptrdiff_t)(row - s->oy) * s->stride;
    int32_t i, n, ch, fill = 0, x;
    rast__i128 D, R[4], SR[4];
    int32_t q[4], sq[4];

    n = x1 - x0;
    x = x0 - s->ox;
    {
        int64_t yc = (int64_t)row * g->unit + g->off;
        int64_t xs = (int64_t)x0 * g->unit + g->off; /* |xs| < 2^28 */
        rast__edge_at el, er;
        rast__i128 G;
        int64_t A;
        rast__edge_at_row(s, s->l, yc, &el);
        rast__edge_at_row(s, s->r, yc, &er);
        G = rast__sp_i128_sub(rast__i128_mul(er.Q, el.dy), rast__i128_mul(el.Q, er.dy));
        D = rast__i128_mul_wide(G, el.dy);
        A = xs * el.dy - el.Q;
        /* Textbook rounding owns a sample up to half a pixel left of Xl
         * (A < 0; never more than the run's first one): the line's value
         * there is extrapolated, so it may lie outside 0..255, by any
         * amount when Xr - Xl is tiny.  It is clamped (as the triangles
         * clamp the plane), and the run goes on from the next sample,
         * which is inside [Xl, Xr). */
        if (A < 0) {
            for (ch = 0; ch < 4; ch++) {
                rast__i128 E = rast__sp_i128_sub(rast__i128_mul(er.P[ch], el.dy), rast__i128_mul(el.P[ch], er.dy));
                rast__i128 N = rast__i128_add(rast__i128_mul_wide(G, el.P[ch]), rast__i128_mul_wide(E, A));
                rast__i128 rem;
                N = rast__i128_add(N, rast__i128_mul_wide(G, el.dy / 2));
                run[ch] = (int64_t)N.hi < 0 ? 0
                          : !rast__i128_lt(N, rast__i128_shl(D, 8))
                              ? 255
                              : (unsigned char)rast__i128_small_div(N, D, &rem);
            }
            fill = 1;
            if (n == 1) {
                rast__put_rgba(&s->out, p, x, fill, run);
                return;
            }
            xs += g->unit;
            A += (int64_t)g->unit * el.dy;
        }
        for (ch = 0; ch < 4; ch++) {
            rast__i128 E = rast__sp_i128_sub(rast__i128_mul(er.P[ch], el.dy), rast__i128_mul(el.P[ch], er.dy));
            rast__i128 N = rast__i128_add(rast__i128_mul_wide(G, el.P[ch]), rast__i128_mul_wide(E, A));
            /* + D/2: D = dl G with dl even */
            N = rast__i128_add(N, rast__i128_mul_wide(G, el.dy / 2));
            q[ch] = rast__i128_small_div(N, D, &R[ch]);
            sq[ch] = 0;
            SR[ch] = rast__i128_from(0);
            if (n > 1)
                sq[ch] = rast__i128_small_div(rast__i128_mul_wide(E, (int64_t)g->unit * el.dy), D, &SR[ch]);
        }
    }
    for (i = fill; i < n; i++) {
        for (ch = 0; ch < 4; ch++) {
            run[4 * fill + ch] = (unsigned char)q[ch];
            q[ch] += sq[ch];
            R[ch] = rast__i128_add(R[ch], SR[ch]);
            if (!rast__i128_lt(R[ch], D)) {
                R[ch] = rast__sp_i128_sub(R[ch], D);
                q[ch]++;
            }
        }
        if (++fill == RAST__SHADE_RUN || i + 1 == n) {
            rast__put_rgba(&s->out, p, x, fill, run);
            x += fill;
            fill = 0;
        }
    }
}

/* ---- the filler ---------------------------------------------------------------------- */

/* The AET filler (aet.h's walk, static inline) instantiated with this
 * painter: each run cut to the clip's columns, its bounding edges told to
 * the painter (rast__gpoly_begin), its columns painted by the painter's
 * span function, all inlined into the walk's loop.  (Through the
 * painter's entries by pointer, a call or two per run cost 2-4% of the
 * whole fill.) */
static void rast__gpoly_run(void *user, int32_t row, const rast__edge *l, const rast__edge *r)
{
    rast__shade_poly *s = (rast__shade_poly *)user;
    int32_t x0 = l->x > s->cx0 ? l->x : s->cx0, x1 = r->x < s->cx1 ? r->x : s->cx1;
    if (x0 >= x1) return;
    if (s->flat) {
        rast__put_rgba_flat(&s->out, s->base + (ptrdiff_t)(row - s->oy) * s->stride, x0 - s->ox,
                            x1 - x0, s->colors);
        return;
    }
    rast__gpoly_begin(s, l->next, r->next);
    rast__gpoly_span(s, row, x0, x1);
}

/* Edges of equal column in exact order: by crossing abscissa, then by
 * the index of the edge's first vertex (so that which edges bound a run,
 * and so its colour, is defined; the pixels do not change). */
static int rast__shade_before(const rast__shade_poly *s, int64_t yc, const rast__edge *a,
                              const rast__edge *b)
{
    rast__edge_at ea, eb;
    rast__i128 l, r;
    rast__edge_at_row(s, a->next, yc, &ea);
    rast__edge_at_row(s, b->next, yc, &eb);
    l = rast__i128_mul(ea.Q, eb.dy);
    r = rast__i128_mul(eb.Q, ea.dy);
    if (rast__i128_lt(l, r)) return 1;
    if (rast__i128_lt(r, l)) return 0;
    return s->src[2 * a->next] < s->src[2 * b->next];
}

static void rast__shade_order(void *user, int32_t row, rast__edge *aet, int32_t n)
{
    const rast__shade_poly *s = (const rast__shade_poly *)user;
    int64_t yc = (int64_t)row * s->g->unit + s->g->off;
    int32_t i, k;
    for (i = 1; i < n; i++) {
        if (aet[i - 1].x != aet[i].x) continue;
        /* insertion within the group of equal columns */
        for (k = i; k > 0 && aet[k - 1].x == aet[k].x && rast__shade_before(s, yc, &aet[k], &aet[k - 1]); k--) {
            rast__edge t = aet[k];
            aet[k] = aet[k - 1];
            aet[k - 1] = t;
        }
    }
}

rast_status rast_polygon_gouraud_scratch_size(uint32_t npoints, int32_t width, int32_t height,
                                              size_t *bytes)
{
    if (!bytes) return RAST_E_NULL;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__size_add(rast__aet_scratch(npoints, width, height),
                            rast__align(rast__size_mul(npoints, 2 * sizeof(int32_t))));
    return RAST_OK;
}

rast_status rast__poly_shade_check(const rast_polygon *polygon, const uint8_t *colors,
                                   uint32_t *npoints)
{
    uint64_t total = 0;
    uint32_t k, i;
    if (!polygon) return RAST_E_NULL;
    if (polygon->nrings > 0 && !polygon->ring_sizes) return RAST_E_NULL;
    for (k = 0; k < polygon->nrings; k++) {
        total += polygon->ring_sizes[k];
        if (total > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    *npoints = (uint32_t)total;
    if (total > 0 && (!polygon->points || !colors)) return RAST_E_NULL;
    for (i = 0; i < *npoints; i++) {
        int32_t x = polygon->points[i].x, y = polygon->points[i].y;
        if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX || y < -RAST_COORD_MAX || y > RAST_COORD_MAX)
            return RAST_E_RANGE;
    }
    return RAST_OK;
}

/* The walk of a checked polygon into the painter s (its destination and
 * out set), its runs cut to `clip`, with scratch of
 * rast_polygon_gouraud_scratch_size for the clip. */
static rast_status rast__gpoly_walk(rast__shade_poly *s, const rast_polygon *polygon,
                                    uint32_t npoints, const uint8_t *colors, const rast__grid *g,
                                    rast_fill_rule rule, int flat, const rast_rect *clip,
                                    void *scratch, size_t scratch_bytes)
{
    rast__arena arena;
    int32_t *src;
    arena.p = (unsigned char *)scratch;
    arena.left = scratch_bytes;
    src = (int32_t *)rast__take(&arena, (size_t)npoints * 2 * sizeof(int32_t));
    if (!src) return RAST_E_SCRATCH;
    s->flat = flat;
    s->pts = polygon->points;
    s->colors = colors;
    s->src = src;
    s->g = g;
    s->cx0 = clip->x0;
    s->cx1 = clip->x1;
    return rast__aet_walk(polygon, npoints, g, rule, clip, &arena, rast__gpoly_run,
                          rast__shade_order, s, src);
}

rast_status rast__poly_shade_band(unsigned char *rgba, ptrdiff_t stride, const rast_rect *band,
                                  const rast_polygon *polygon, uint32_t npoints,
                                  const uint8_t *colors, const rast__grid *g, rast_fill_rule rule,
                                  int flat, void *scratch, size_t scratch_bytes)
{
    rast__shade_poly s;
    s.base = rgba;
    s.stride = stride;
    s.ox = band->x0;
    s.oy = band->y0;
    s.out.put = rast__formats[RAST_FORMAT_RGBA8888].put;
    s.out.bput = NULL;
    s.out.bctx = NULL;
    if (band->x0 >= band->x1 || band->y0 >= band->y1 || npoints == 0) return RAST_OK;
    return rast__gpoly_walk(&s, polygon, npoints, colors, g, rule, flat, band, scratch,
                            scratch_bytes);
}

/* rast_fill_polygon_gouraud with each run's colours to bput (NULL:
 * stored), as paint.h says. */
rast_status rast__fill_polygon_shaded(const rast_target *target, const rast_polygon *polygon,
                                      const uint8_t *colors, const rast_fill_opts *opts,
                                      const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                      const void *bctx, void *scratch, size_t scratch_bytes)
{
    rast__shade_poly s;
    rast__grid g;
    rast_rect clip;
    uint32_t npoints;
    size_t need;
    rast_status st;

    if (!target || !polygon || !opts || !shade) return RAST_E_NULL;
    if (opts->algorithm != RAST_ALGO_AET) return RAST_E_ALGORITHM;
    if ((unsigned)opts->rule > RAST_RULE_NONZERO) return RAST_E_ARG;
    st = rast__grid_init(&g, opts->subpixel_bits, opts->sample, opts->rounding, opts->boundary);
    if (st != RAST_OK) return st;
    if (opts->boundary != RAST_BOUNDARY_EXACT) return RAST_E_ARG;
    if (shade->precision != RAST_PRECISION_EXACT && shade->precision != RAST_PRECISION_FLAT)
        return RAST_E_ARG;
    st = rast__poly_shade_check(polygon, colors, &npoints);
    if (st != RAST_OK) return st;
    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    st = rast__shade_format(target);
    if (st != RAST_OK) return st;
    st = rast_polygon_gouraud_scratch_size(npoints, clip.x1 - clip.x0, clip.y1 - clip.y0, &need);
    if (st != RAST_OK) return st;
    st = rast__scratch_check(scratch, scratch_bytes, need);
    if (st != RAST_OK) return st;
    if (clip.x0 >= clip.x1 || clip.y0 >= clip.y1 || npoints == 0) return RAST_OK;

    if (shade->precision == RAST_PRECISION_FLAT && !bput) {
        /* One colour, vertex 0's: the solid painter of its value (a
         * format's fill of pack(c) writes what its put of c writes), fed by
         * the AET filler, which owns the same pixels as the walk below. */
        rast__solid solid;
        rast__painter paint;
        rast__sink sink;
        rast__arena arena;
        unsigned char value[4] = {0, 0, 0, 0};
        arena.p = (unsigned char *)scratch;
        arena.left = scratch_bytes;
        if (!rast__take(&arena, (size_t)npoints * 2 * sizeof(int32_t))) return RAST_E_SCRATCH;
        rast__formats[target->format].pack(colors, value);
        st = rast__solid_init(&solid, target, &clip, value, NULL, &paint);
        if (st != RAST_OK) return st;
        rast__sink_init(&sink, &paint, &clip);
        return rast__aet_fill(polygon, npoints, &g, opts->rule, &clip, &sink, &arena);
    }
    s.base = (unsigned char *)target->pixels;
    s.stride = target->stride;
    s.ox = s.oy = 0;
    rast__rgba_out_init(&s.out, target, bput, bctx);
    /* FLAT through the blend: the walk's pixels, one colour */
    return rast__gpoly_walk(&s, polygon, npoints, colors, &g, opts->rule,
                            shade->precision == RAST_PRECISION_FLAT, &clip, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_gouraud(const rast_target *target, const rast_polygon *polygon,
                                      const uint8_t *colors, const rast_fill_opts *opts,
                                      const rast_shade_opts *shade, void *scratch,
                                      size_t scratch_bytes)
{
    return rast__fill_polygon_shaded(target, polygon, colors, opts, shade, NULL, NULL, scratch,
                                     scratch_bytes);
}

/*
 * fill.c - the polygon entry points: check everything, then hand the
 * polygon to the chosen filler with the chosen painter as its sink.
 * Every error is found here, before a filler runs and before any pixel is
 * written.
 */
#include "paint.h"
#include "registry.h"

static rast_status rast__check_opts(const rast_fill_opts *o, rast__grid *g,
                                    const rast__algo **algo)
{
    const rast__algo *al;
    if (!o) return RAST_E_NULL;
    al = rast__algo_get(o->algorithm);
    if (!al) return RAST_E_ALGORITHM;
    if ((unsigned)o->rule > RAST_RULE_NONZERO) return RAST_E_ARG;
    if (!(al->rules & (1u << o->rule))) return RAST_E_RULE;
    *algo = al;
    return rast__grid_init(g, o->subpixel_bits, o->sample, o->rounding, o->boundary);
}

/* Count the vertices and check that every one is in range. */
static rast_status rast__check_polygon(const rast_polygon *p, uint32_t *npoints)
{
    uint64_t n = 0;
    uint32_t k, i;
    if (!p) return RAST_E_NULL;
    if (p->nrings > 0 && !p->ring_sizes) return RAST_E_NULL;
    for (k = 0; k < p->nrings; k++) {
        n += p->ring_sizes[k];
        if (n > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    if (n > 0 && !p->points) return RAST_E_NULL;
    for (i = 0; i < (uint32_t)n; i++) {
        int32_t x = p->points[i].x, y = p->points[i].y;
        if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX ||
            y < -RAST_COORD_MAX || y > RAST_COORD_MAX)
            return RAST_E_RANGE;
    }
    *npoints = (uint32_t)n;
    return RAST_OK;
}

rast_status rast_scratch_size(const rast_fill_opts *opts, uint32_t npoints,
                              int32_t width, int32_t height, size_t *bytes)
{
    const rast__algo *al;
    rast__grid g;
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__check_opts(opts, &g, &al);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = al->scratch(npoints, width, height);
    if (opts->boundary != RAST_BOUNDARY_EXACT)
        *bytes = rast__size_add(*bytes, rast__bound_scratch(npoints, height));
    return RAST_OK;
}

/* Check the polygon, options and scratch for a clip; run the filler. */
static rast_status rast__fill(const rast_polygon *poly, const rast_fill_opts *opts,
                              const rast_rect *clip, rast__row_fn fn, void *user,
                              void *scratch, size_t scratch_bytes)
{
    const rast__algo *al;
    rast__grid g;
    rast__sink sink;
    rast__arena arena;
    uint32_t npoints;
    size_t need;
    rast_status st;

    st = rast__check_opts(opts, &g, &al);
    if (st != RAST_OK) return st;
    st = rast__check_polygon(poly, &npoints);
    if (st != RAST_OK) return st;
    need = al->scratch(npoints, clip->x1 - clip->x0, clip->y1 - clip->y0);
    if (opts->boundary != RAST_BOUNDARY_EXACT)
        need = rast__size_add(need, rast__bound_scratch(npoints, clip->y1 - clip->y0));
    st = rast__scratch_check(scratch, scratch_bytes, need);
    if (st != RAST_OK) return st;
    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK;

    rast__sink_init(&sink, fn, user, clip);
    arena.p = (unsigned char *)scratch;
    arena.left = scratch_bytes;
    if (opts->boundary == RAST_BOUNDARY_EXACT)
        return al->fill(poly, npoints, &g, opts->rule, clip, &sink, &arena);
    {
        rast__bound b;
        st = rast__bound_begin(&b, poly, npoints, &g, opts->boundary, clip, &sink, &arena);
        if (st == RAST_OK) st = al->fill(poly, npoints, &g, opts->rule, clip, &b.in, &arena);
        if (st == RAST_OK) rast__bound_end(&b);
        return st;
    }
}

static rast_status rast__fill_target(const rast_target *target, const rast_polygon *polygon,
                                     const rast_fill_opts *opts, const void *pixel,
                                     const void *background, int opaque,
                                     void *scratch, size_t scratch_bytes)
{
    rast__solid solid;
    rast__row_fn fn;
    rast_rect clip;
    rast_status st;

    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    if (opaque && !background) return RAST_E_NULL;
    st = rast__solid_init(&solid, target, &clip, pixel, background, &fn);
    if (st != RAST_OK) return st;
    st = rast__fill(polygon, opts, &clip, fn, &solid, scratch, scratch_bytes);
    if (st == RAST_OK && opaque && clip.x0 < clip.x1) rast__opaque_finish(&solid);
    return st;
}

rast_status rast_fill_polygon(const rast_target *target, const rast_polygon *polygon,
                              const rast_fill_opts *opts, const void *pixel,
                              void *scratch, size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, NULL, 0, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_opaque(const rast_target *target, const rast_polygon *polygon,
                                     const rast_fill_opts *opts, const void *pixel,
                                     const void *background, void *scratch,
                                     size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, background, 1, scratch, scratch_bytes);
}

rast_status rast_fill_polygon_spans(const rast_polygon *polygon,
                                    const rast_fill_opts *opts,
                                    const rast_rect *clip, rast_span_fn span,
                                    void *user, void *scratch,
                                    size_t scratch_bytes)
{
    rast__user_spans u;
    rast_rect c;
    rast_status st;
    if (!clip || !span) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    u.fn = span;
    u.user = user;
    return rast__fill(polygon, opts, &c, rast__user_row, &u, scratch, scratch_bytes);
}

/*
 * trifill.c - the triangle entry points: check the whole batch, then hand
 * each triangle to the chosen filler with the chosen painter as its sink.
 * Every error is found here, before a filler runs and before any pixel is
 * written.  Adding a triangle algorithm adds one row to rast__tri_algos
 * (and its file).
 */
#include "../painters/paint.h"

typedef struct rast__tri_algo {
    char name[10]; /* in the row: see rast__algo (registry.h) */
    rast__tri_scratch_fn scratch;
    rast__tri_fill_fn fill;
} rast__tri_algo;

/* Algorithm a's row, or an empty one (no filler: "unknown") when the
 * build's configuration leaves a out (base/config.h). */
#define RAST__TRI_ROW(a, name, scratch, fill)                                  \
    {name, RAST__HAS(RAST_CONFIG_TRI_ALGORITHMS, a) ? scratch : NULL,          \
     RAST__HAS(RAST_CONFIG_TRI_ALGORITHMS, a) ? fill : NULL}

static const rast__tri_algo rast__tri_algos[RAST_TRI_COUNT_] = {
    RAST__TRI_ROW(RAST_TRI_EDGE, "edge", rast__tri_edge_scratch, rast__tri_edge_fill),
    RAST__TRI_ROW(RAST_TRI_SWEEP, "sweep", rast__tri_sweep_scratch, rast__tri_sweep_fill),
    RAST__TRI_ROW(RAST_TRI_EDGEFLAG, "edgeflag", rast__tri_edgeflag_scratch,
                  rast__tri_edgeflag_fill),
};

rast_status rast_tri_algorithm_info(rast_tri_algorithm algorithm, const char **name)
{
    if ((unsigned)algorithm >= RAST_TRI_COUNT_ || !RAST__HAS(RAST_CONFIG_TRI_ALGORITHMS, algorithm))
        return RAST_E_ALGORITHM;
    if (name) *name = rast__tri_algos[algorithm].name;
    return RAST_OK;
}

/* The options: grid (S, sample, rounding, boundary), then the algorithm. */
static rast_status rast__tri_check_opts(const rast_tri_opts *o, rast__grid *g,
                                        const rast__tri_algo **algo)
{
    rast_status st = rast__grid_init(g, o->subpixel_bits, o->sample, o->rounding, o->boundary);
    /* A build without triangles always fails below: set *algo anyway, or
     * the compiler warns that the callers use it unset. */
    if (RAST_CONFIG_TRI_ALGORITHMS == 0) *algo = NULL;
    if (st != RAST_OK) return st;
    if ((unsigned)o->algorithm >= RAST_TRI_COUNT_ ||
        !RAST__HAS(RAST_CONFIG_TRI_ALGORITHMS, o->algorithm))
        return RAST_E_ALGORITHM;
    *algo = &rast__tri_algos[o->algorithm];
    return RAST_OK;
}

static size_t rast__tri_need(const rast__tri_algo *al, const rast_tri_opts *o,
                             int32_t width, int32_t height)
{
    size_t need = al->scratch(width, height);
    if (RAST__BOUNDARY_MODES && o->boundary != RAST_BOUNDARY_EXACT) need = rast__size_add(need, rast__bound_scratch(3, height));
    return need;
}

rast_status rast_tri_scratch_size(const rast_tri_opts *opts, int32_t width, int32_t height,
                                  size_t *bytes)
{
    const rast__tri_algo *al;
    rast__grid g;
    rast_status st;
    if (!opts || !bytes) return RAST_E_NULL;
    st = rast__tri_check_opts(opts, &g, &al);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    return rast__tri_fill_need(opts, width, height, bytes);
}

rast_status rast__tri_fill_need(const rast_tri_opts *opts, int32_t width, int32_t height,
                                size_t *bytes)
{
    const rast__tri_algo *al;
    rast__grid g;
    rast_status st;
    if (!opts) return RAST_E_NULL;
    st = rast__tri_check_opts(opts, &g, &al);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0) return RAST_E_SIZE;
    *bytes = rast__tri_need(al, opts, width, height);
    return RAST_OK;
}

/* Every vertex of the batch in range (3 * ntris may pass 2^32: count in
 * 64 bits). */
static rast_status rast__tri_check_range(const rast_point *tris, uint32_t ntris)
{
    uint64_t i, n = 3 * (uint64_t)ntris;
    for (i = 0; i < n; i++) {
        int32_t x = tris[i].x, y = tris[i].y;
        if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX || y < -RAST_COORD_MAX ||
            y > RAST_COORD_MAX)
            return RAST_E_RANGE;
    }
    return RAST_OK;
}

rast_status rast__tri_check(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                            const rast_rect *clip, rast__grid *g, void *scratch,
                            size_t scratch_bytes)
{
    const rast__tri_algo *al;
    rast_status st = rast__tri_check_range(tris, ntris);
    if (st != RAST_OK) return st;
    st = rast__tri_check_opts(opts, g, &al);
    if (st != RAST_OK) return st;
    return rast__scratch_check(scratch, scratch_bytes,
                               rast__tri_need(al, opts, clip->x1 - clip->x0, clip->y1 - clip->y0));
}

rast_status rast__tri_fill(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                           const rast_rect *clip, const rast__painter *p,
                           rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes)
{
    rast__grid g;
    rast_status st = rast__tri_check(tris, ntris, opts, clip, &g, scratch, scratch_bytes);
    if (st != RAST_OK) return st;
    return rast__tri_fill_checked(tris, ntris, opts, &g, clip, p, begin, scratch, scratch_bytes);
}

rast_status rast__tri_fill_checked(const rast_point *tris, uint32_t ntris,
                                   const rast_tri_opts *opts, const rast__grid *gp,
                                   const rast_rect *clip, const rast__painter *p,
                                   rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes)
{
    const rast__tri_algo *al = &rast__tri_algos[opts->algorithm];
    const rast__grid g = *gp;
    rast__sink sink;
    rast__arena arena;
    uint32_t k;
    rast_status st;

    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK;

    rast__sink_init(&sink, p, clip);
    for (k = 0; k < ntris; k++) {
        const rast_point *t = tris + 3 * (size_t)k;
        if (begin && !begin(p->user, t, k, &g)) continue;
        /* Fillers leave the sink empty (rast__rows_put, or a flush), so one
         * triangle's spans never merge with the next one's: COUNT16 counts
         * both. */
        arena.p = (unsigned char *)scratch;
        arena.left = scratch_bytes;
        if (!RAST__BOUNDARY_MODES || opts->boundary == RAST_BOUNDARY_EXACT) {
            st = al->fill(t, &g, clip, &sink, &arena);
        } else {
            static const uint32_t three = 3;
            rast_polygon poly;
            rast__bound b;
            poly.points = t;
            poly.ring_sizes = &three;
            poly.nrings = 1;
            st = rast__bound_begin(&b, &poly, 3, &g, opts->boundary, clip, &sink, &arena);
            if (st == RAST_OK) st = al->fill(t, &g, clip, &b.in, &arena);
            if (st == RAST_OK) rast__bound_end(&b);
        }
        if (st != RAST_OK) return st; /* not reached: the scratch was checked */
    }
    return RAST_OK;
}

rast_status rast_fill_triangles(const rast_target *target, const rast_point *tris, uint32_t ntris,
                                const rast_tri_opts *opts, const void *pixel, void *scratch,
                                size_t scratch_bytes)
{
    rast__solid solid;
    rast__painter p;
    rast_rect clip;
    rast_status st;

    if (!target || !opts || (ntris > 0 && !tris)) return RAST_E_NULL;
    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    st = rast__solid_init(&solid, target, &clip, pixel, NULL, &p);
    if (st != RAST_OK) return st;
    return rast__tri_fill(tris, ntris, opts, &clip, &p, NULL, scratch, scratch_bytes);
}

rast_status rast_fill_triangles_spans(const rast_point *tris, uint32_t ntris,
                                      const rast_tri_opts *opts, const rast_rect *clip,
                                      rast_span_fn span, void *user, void *scratch,
                                      size_t scratch_bytes)
{
    rast__user_spans u;
    rast__painter p;
    rast_rect c;
    rast_status st;
    if (!opts || !clip || !span || (ntris > 0 && !tris)) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    rast__user_painter(&u, span, NULL, user, &p);
    return rast__tri_fill(tris, ntris, opts, &c, &p, NULL, scratch, scratch_bytes);
}

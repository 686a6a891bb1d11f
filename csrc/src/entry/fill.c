/*
 * fill.c - the polygon entry points: check everything, then hand the
 * polygon to the chosen filler with the chosen painter as its sink.
 * Every error is found here, before a filler runs and before any pixel is
 * written.
 */
#include "../painters/paint.h"
#include "../fillers/poly.h"
#include "../fillers/registry.h"
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__RANGE_SSE2 1
#endif

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

/* Count the vertices and, with range set, check that every one is in
 * range (rast__fill_snapped's callers have checked them already). */
static rast_status rast__check_polygon(const rast_polygon *p, uint32_t *npoints, int range)
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
    i = 0;
#if defined(RAST__RANGE_SSE2)
    /* Four points (eight coordinates) a step, the comparisons' results
     * gathered and tested once at the end: 11 instructions a vertex were
     * ~380 K of a paragraph of text's rast_fill_polygon (a third of what
     * the fill's own walk of its vertices costs). */
    if (range) {
        const __m128i hi = _mm_set1_epi32(RAST_COORD_MAX), lo = _mm_set1_epi32(-RAST_COORD_MAX);
        __m128i bad = _mm_setzero_si128();
        const rast_point *q = p->points;
        for (; i + 4 <= (uint32_t)n; i += 4) {
            const __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(q + i));
            const __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(q + i + 2));
            bad = _mm_or_si128(bad, _mm_or_si128(_mm_cmpgt_epi32(a, hi), _mm_cmplt_epi32(a, lo)));
            bad = _mm_or_si128(bad, _mm_or_si128(_mm_cmpgt_epi32(b, hi), _mm_cmplt_epi32(b, lo)));
        }
        if (_mm_movemask_epi8(bad)) return RAST_E_RANGE;
    }
#endif
    for (; range && i < (uint32_t)n; i++) {
        int32_t x = p->points[i].x, y = p->points[i].y;
        if (x < -RAST_COORD_MAX || x > RAST_COORD_MAX ||
            y < -RAST_COORD_MAX || y > RAST_COORD_MAX)
            return RAST_E_RANGE;
    }
    *npoints = (uint32_t)n;
    return RAST_OK;
}

/* The scratch a fill needs for a clip of width x height: one formula for
 * every entry point. */
static size_t rast__need(const rast__algo *al, const rast_fill_opts *opts, uint32_t npoints,
                         int32_t width, int32_t height)
{
    size_t need = al->scratch(npoints, width, height);
    if (RAST__BOUNDARY_MODES && opts->boundary != RAST_BOUNDARY_EXACT)
        need = rast__size_add(need, rast__bound_scratch(npoints, height));
    return need;
}

rast_status rast__fill_need(const rast_fill_opts *opts, uint32_t npoints, int32_t width,
                            int32_t height, size_t *bytes)
{
    const rast__algo *al;
    rast__grid g;
    rast_status st = rast__check_opts(opts, &g, &al);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0) return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__need(al, opts, npoints, width, height);
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
#if defined(__OPTIMIZE_SIZE__)
    return rast__fill_need(opts, npoints, width, height, bytes); /* (18 bytes less code) */
#else
    /* rast__fill_need's remaining check and formula: its own check of the
     * options again was a tenth of the glue's work before a tiny
     * polygon's fill (Canvas.fill_polygon in a loop) */
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__need(al, opts, npoints, width, height);
    return RAST_OK;
#endif
}

rast_status rast__fill_prepare(const rast_fill_opts *opts, rast__fill_setup *f)
{
    f->opts = opts;
    return rast__check_opts(opts, &f->g, &f->al);
}

size_t rast__fill_scratch(const rast__fill_setup *f, uint32_t npoints, int32_t width,
                          int32_t height)
{
    return rast__need(f->al, f->opts, npoints, width, height);
}

rast_status rast__fill_checked(const rast__fill_setup *f, const rast_polygon *poly,
                               uint32_t npoints, const rast_rect *clip, const rast__painter *p,
                               void *scratch, size_t scratch_bytes)
{
    rast__sink sink;
    rast__arena arena = rast__arena_of(scratch, scratch_bytes);
    rast_status st;

    rast__sink_init(&sink, p, clip);
    if (!RAST__BOUNDARY_MODES || f->opts->boundary == RAST_BOUNDARY_EXACT)
        return f->al->fill(poly, npoints, &f->g, f->opts->rule, clip, &sink, &arena);
    {
        rast__bound b;
        st = rast__bound_begin(&b, poly, npoints, &f->g, f->opts->boundary, clip, &sink, &arena);
        if (st == RAST_OK) st = f->al->fill(poly, npoints, &f->g, f->opts->rule, clip, &b.in, &arena);
        if (st == RAST_OK) rast__bound_end(&b);
        return st;
    }
}

/* Check the polygon (its points' range too when range is set), options and
 * scratch for a clip; run the filler. */
static rast_status rast__fill_by(const void *polygon, const rast_fill_opts *opts,
                                 const rast_rect *clip, const rast__painter *p,
                                 void *scratch, size_t scratch_bytes, int range)
{
    const rast_polygon *poly = (const rast_polygon *)polygon;
    rast__fill_setup f;
    uint32_t npoints;
    size_t need;
    rast_status st;

    st = rast__fill_prepare(opts, &f);
    if (st != RAST_OK) return st;
    st = rast__check_polygon(poly, &npoints, range);
    if (st != RAST_OK) return st;
    need = rast__need(f.al, opts, npoints, clip->x1 - clip->x0, clip->y1 - clip->y0);
    st = rast__scratch_check(scratch, scratch_bytes, need);
    if (st != RAST_OK) return st;
    if (clip->x0 >= clip->x1 || clip->y0 >= clip->y1) return RAST_OK;
    return rast__fill_checked(&f, poly, npoints, clip, p, scratch, scratch_bytes);
}

rast_status rast__fill(const void *polygon, const rast_fill_opts *opts,
                       const rast_rect *clip, const rast__painter *p,
                       void *scratch, size_t scratch_bytes)
{
    return rast__fill_by(polygon, opts, clip, p, scratch, scratch_bytes, 1);
}

#if !defined(__OPTIMIZE_SIZE__)
/* rast__fill without the pass over every vertex for its range: the
 * binding's snap (python/glue/fill.c, rastpy_snap) has refused any point
 * outside +-RAST_COORD_MAX already (11 instructions a vertex, ~380 K on a
 * paragraph of text).  Size-optimised builds (firmware, no binding) leave
 * it out: rast__fill's only caller then, the range check folded in. */
rast_status rast__fill_snapped(const void *polygon, const rast_fill_opts *opts,
                               const rast_rect *clip, const rast__painter *p,
                               void *scratch, size_t scratch_bytes)
{
    return rast__fill_by(polygon, opts, clip, p, scratch, scratch_bytes, 0);
}
#endif

rast_status rast__fill_target(const rast_target *target, const void *polygon,
                              const rast_fill_opts *opts, const void *pixel,
                              const void *background, int opaque, rast__fill_any_fn fill,
                              void *scratch, size_t scratch_bytes)
{
    rast__solid solid;
    rast__painter p;
    rast_rect clip;
    rast_status st;

    st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    if (opaque && !background) return RAST_E_NULL;
    st = rast__solid_init(&solid, target, &clip, pixel, background, &p);
    if (st != RAST_OK) return st;
    st = fill(polygon, opts, &clip, &p, scratch, scratch_bytes);
    if (st == RAST_OK && opaque && clip.x0 < clip.x1) rast__opaque_finish(&solid);
    return st;
}

rast_status rast__fill_spans(const void *polygon, const rast_fill_opts *opts,
                             const rast_rect *clip, rast_span_fn span, void *user,
                             rast__fill_any_fn fill, void *scratch, size_t scratch_bytes)
{
    rast__user_spans u;
    rast__painter p;
    rast_rect c;
    rast_status st;
    if (!clip || !span) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    rast__user_painter(&u, span, NULL, user, &p);
    return fill(polygon, opts, &c, &p, scratch, scratch_bytes);
}

rast_status rast_fill_polygon(const rast_target *target, const rast_polygon *polygon,
                              const rast_fill_opts *opts, const void *pixel,
                              void *scratch, size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, NULL, 0, rast__fill, scratch,
                             scratch_bytes);
}

rast_status rast_fill_polygon_opaque(const rast_target *target, const rast_polygon *polygon,
                                     const rast_fill_opts *opts, const void *pixel,
                                     const void *background, void *scratch,
                                     size_t scratch_bytes)
{
    return rast__fill_target(target, polygon, opts, pixel, background, 1, rast__fill, scratch,
                             scratch_bytes);
}

rast_status rast_fill_polygon_spans(const rast_polygon *polygon,
                                    const rast_fill_opts *opts,
                                    const rast_rect *clip, rast_span_fn span,
                                    void *user, void *scratch,
                                    size_t scratch_bytes)
{
    return rast__fill_spans(polygon, opts, clip, span, user, rast__fill, scratch, scratch_bytes);
}

/* floor(v / 2^s) for a fixed-point coordinate, in pixels. */
static int64_t rast__pixel_floor(int32_t v, int32_t s)
{
    return rast__floordiv(v, (int64_t)1 << s);
}

rast_status rast__fill_measure(const rast__fill_setup *f, const rast_polygon *polygon,
                               const rast_rect *clip, uint32_t *npoints, rast_rect *bounds)
{
    const rast_point *pts;
    rast_rect c, out;
    rast__box box;
    uint64_t n = 0;
    uint32_t k, i;
    int32_t minx, maxx, miny, maxy;
    rast_status st;

    /* rast__check_polygon's checks, in its order, the range on the extent */
    if (!polygon) return RAST_E_NULL;
    if (polygon->nrings > 0 && !polygon->ring_sizes) return RAST_E_NULL;
    for (k = 0; k < polygon->nrings; k++) {
        n += polygon->ring_sizes[k];
        if (n > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    if (n > 0 && !polygon->points) return RAST_E_NULL;
    pts = polygon->points;
    minx = maxx = miny = maxy = 0;
    if (n > 0) {
        minx = maxx = pts[0].x;
        miny = maxy = pts[0].y;
    }
    for (i = 1; i < (uint32_t)n; i++) {
        if (pts[i].x < minx) minx = pts[i].x;
        if (pts[i].x > maxx) maxx = pts[i].x;
        if (pts[i].y < miny) miny = pts[i].y;
        if (pts[i].y > maxy) maxy = pts[i].y;
    }
    if (minx < -RAST_COORD_MAX || maxx > RAST_COORD_MAX || miny < -RAST_COORD_MAX ||
        maxy > RAST_COORD_MAX)
        return RAST_E_RANGE;
    *npoints = (uint32_t)n;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    out.x0 = out.x1 = c.x0; /* empty unless something below says otherwise */
    out.y0 = out.y1 = c.y0;
    if (f->opts->boundary == RAST_BOUNDARY_EXACT) {
        /* The box the fillers themselves work in (poly.h). */
        if (n > 0 && rast__box_of(minx, maxx, miny, maxy, &f->g, &c, &box)) {
            out.x0 = box.col0;
            out.x1 = box.col1;
            out.y0 = box.row0;
            out.y1 = box.row1;
        }
    } else if (n > 0) {
        /* The edges' pixels too: a pixel of the library's line, or one that
         * an edge passes through, lies within a pixel of the vertices'
         * pixel hull [floor(min), floor(max)]; and so does every sample the
         * fill owns under either rounding.  One more pixel each side. */
        int32_t s = f->opts->subpixel_bits;
        int64_t x0 = rast__pixel_floor(minx, s) - 1, x1 = rast__pixel_floor(maxx, s) + 2;
        int64_t y0 = rast__pixel_floor(miny, s) - 1, y1 = rast__pixel_floor(maxy, s) + 2;
        rast__rect_cut64(&out, &c, x0, x1, y0, y1);
    }
    *bounds = out;
    return RAST_OK;
}

rast_status rast_fill_bounds(const rast_fill_opts *opts, const rast_polygon *polygon,
                             const rast_rect *clip, rast_rect *bounds)
{
    rast__fill_setup f;
    uint32_t npoints;
    rast_status st;

    if (!clip || !bounds) return RAST_E_NULL;
    st = rast__fill_prepare(opts, &f);
    if (st != RAST_OK) return st;
    return rast__fill_measure(&f, polygon, clip, &npoints, bounds);
}

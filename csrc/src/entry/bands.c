/*
 * bands.c - a scene (an array of primitives) drawn band by band, into a
 * target or as spans, in a scratch buffer of fixed size (issue 5).
 *
 * A band is the clip narrowed to some rows.  Every filler clips exactly and
 * decides each row on its own, so drawing the primitives in order into each
 * band gives the pixels of drawing them in order into the whole clip; the
 * work memory is that of one primitive in one band.  A primitive whose
 * band needs more scratch than there is gets its band halved until it fits
 * (FreeType's gray_convert_glyph does the same); a one-row band that does
 * not fit is found before anything is drawn.
 *
 * Everything is checked once per call: each primitive goes once through
 * its own entry point with an empty clip, which checks everything and
 * draws nothing, before the first band is drawn; the bands then run the
 * fillers behind those entry points with nothing checked again (the
 * vertices are not re-read for their range band after band).
 */
#include "../painters/paint.h"

/* An anti-aliased primitive's scratch for a band (rast_coverage_scratch_size;
 * a span clip's width past RAST_MAX_DIM never gets here: the spans call
 * refuses aa). */
static rast_status rast__cov_need_band(const rast_coverage_opts *aa, uint64_t npoints,
                                       int32_t width, int32_t rows, size_t *need)
{
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    return rast_coverage_scratch_size(aa, (uint32_t)npoints, width, rows, need);
}

/* Scratch that primitive p needs for a band of `rows` rows and `width`
 * columns (also checks its kind and options). */
static rast_status rast__prim_need(const rast_prim *p, int32_t width, int32_t rows,
                                   size_t *need)
{
    uint64_t npoints = 0;
    uint32_t k;
    /* coverage is for 32-bit polygons and triangle batches */
    if (p->aa && p->kind != RAST_PRIM_POLYGON && p->kind != RAST_PRIM_TRIANGLES) return RAST_E_ARG;
    /* 64-bit polygons outside the switch: a switch of four cases makes
     * GCC's Thumb-1 code call a case-table helper (__gnu_thumb1_case_uqi)
     * that firmware-check does not allow. */
    if (p->kind == RAST_PRIM_POLYGON64) {
        if (p->polygon64.nrings > 0 && !p->polygon64.ring_sizes) return RAST_E_NULL;
        for (k = 0; k < p->polygon64.nrings; k++) {
            npoints += p->polygon64.ring_sizes[k];
            if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
        }
        /* Its scratch does not depend on the width; a span clip may be
         * wider than RAST_MAX_DIM (up to twice it), which the public size
         * function refuses. */
        return rast_scratch_size64(p->fill, (uint32_t)npoints, width > RAST_MAX_DIM ? RAST_MAX_DIM : width,
                                   rows, need);
    }
    switch (p->kind) {
    case RAST_PRIM_POLYGON:
        if (p->polygon.nrings > 0 && !p->polygon.ring_sizes) return RAST_E_NULL;
        for (k = 0; k < p->polygon.nrings; k++) {
            npoints += p->polygon.ring_sizes[k];
            if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
        }
        if (p->aa) return rast__cov_need_band(p->aa, npoints, width, rows, need);
        return rast__fill_need(p->fill, (uint32_t)npoints, width, rows, need);
    case RAST_PRIM_TRIANGLES:
        if (p->aa) return rast__cov_need_band(p->aa, 3 * (uint64_t)p->count, width, rows, need);
        return rast__tri_fill_need(p->tri, width, rows, need);
    case RAST_PRIM_POLYLINE:
        if (!p->line) return RAST_E_NULL;
        if ((unsigned)p->line->algorithm >= RAST_LINE_COUNT_ ||
            !RAST__HAS(RAST_CONFIG_LINE_ALGORITHMS, p->line->algorithm))
            return RAST_E_ALGORITHM;
        *need = 0;
        return RAST_OK;
    default:
        return RAST_E_ARG;
    }
}

rast_status rast_scene_scratch_size(const rast_prim *prims, uint32_t n, int32_t band_rows,
                                    int32_t width, size_t *bytes)
{
    size_t most = 0, need;
    uint32_t i;
    rast_status st;
    if (!bytes || (n > 0 && !prims)) return RAST_E_NULL;
    if (band_rows < 1) return RAST_E_ARG;
    if (width < 0 || width > RAST_MAX_DIM || band_rows > RAST_MAX_DIM) return RAST_E_SIZE;
    for (i = 0; i < n; i++) {
        st = rast__prim_need(&prims[i], width, band_rows, &need);
        if (st != RAST_OK) return st;
        if (need > most) most = need;
    }
    *bytes = most;
    return RAST_OK;
}

/* Where the primitives go: a target (target not NULL), a span callback
 * (span) or a coverage callback (cspan). */
typedef struct rast__scene {
    const rast_target *target;
    rast_prim_span_fn span;
    rast_prim_coverage_fn cspan;
    void *user;
    const rast_prim *prim; /* the primitive being drawn, for the callback */
    void *scratch;
    size_t bytes;
} rast__scene;

static void rast__scene_init(rast__scene *s, const rast_target *target, rast_prim_span_fn span,
                             rast_prim_coverage_fn cspan, void *user, void *scratch, size_t bytes)
{
    s->target = target;
    s->span = span;
    s->cspan = cspan;
    s->user = user;
    s->prim = NULL;
    s->scratch = scratch;
    s->bytes = bytes;
}

static void rast__scene_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    const rast__scene *s = (const rast__scene *)user;
    if (s->span) s->span(s->user, s->prim, y, x0, x1);
    else s->cspan(s->user, s->prim, y, x0, x1, NULL); /* binary: all of each pixel */
}

static void rast__scene_cov(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *values)
{
    const rast__scene *s = (const rast__scene *)user;
    s->cspan(s->user, s->prim, y, x0, x1, values);
}

/* Draw primitive p inside `band` (inside the clip) through its entry point. */
static rast_status rast__prim_draw(rast__scene *s, const rast_prim *p, const rast_rect *band)
{
    if (s->target) {
        rast_target t = *s->target;
        t.clip = *band;
        if (p->kind == RAST_PRIM_POLYGON64) /* (outside the switch: see rast__prim_need) */
            return rast_fill_polygon64(&t, &p->polygon64, p->fill, p->pixel, s->scratch,
                                       s->bytes);
        if (p->aa && p->kind == RAST_PRIM_POLYGON)
            return rast_fill_polygon_aa(&t, &p->polygon, p->aa, p->pixel, s->scratch, s->bytes);
        if (p->aa) /* RAST_PRIM_TRIANGLES: rast__prim_need refused the others */
            return rast_fill_triangles_aa(&t, p->points, p->count, p->aa, p->pixel, s->scratch,
                                          s->bytes);
        switch (p->kind) {
        case RAST_PRIM_POLYGON:
            return rast_fill_polygon(&t, &p->polygon, p->fill, p->pixel, s->scratch, s->bytes);
        case RAST_PRIM_TRIANGLES:
            return rast_fill_triangles(&t, p->points, p->count, p->tri, p->pixel, s->scratch,
                                       s->bytes);
        case RAST_PRIM_POLYLINE:
            return rast_draw_polyline(&t, p->points, p->count, p->closed, p->line, p->pixel);
        default:
            return RAST_E_ARG;
        }
    }
    s->prim = p;
    if (p->aa && !s->cspan) return RAST_E_ARG; /* a span has no coverage values */
    if (p->aa && p->kind == RAST_PRIM_POLYGON)
        return rast_polygon_coverage_spans(&p->polygon, p->aa, band, rast__scene_cov, s,
                                           s->scratch, s->bytes);
    if (p->aa) /* RAST_PRIM_TRIANGLES: rast__prim_need refused the others */
        return rast_triangles_coverage_spans(p->points, p->count, p->aa, band, rast__scene_cov, s,
                                             s->scratch, s->bytes);
    if (p->kind == RAST_PRIM_POLYGON64)
        return rast_fill_polygon64_spans(&p->polygon64, p->fill, band, rast__scene_span, s,
                                         s->scratch, s->bytes);
    switch (p->kind) {
    case RAST_PRIM_POLYGON:
        return rast_fill_polygon_spans(&p->polygon, p->fill, band, rast__scene_span, s,
                                       s->scratch, s->bytes);
    case RAST_PRIM_TRIANGLES:
        return rast_fill_triangles_spans(p->points, p->count, p->tri, band, rast__scene_span, s,
                                         s->scratch, s->bytes);
    case RAST_PRIM_POLYLINE:
        return rast_draw_polyline_spans(p->points, p->count, p->closed, p->line, band,
                                        rast__scene_span, s);
    default:
        return RAST_E_ARG;
    }
}

/* The vertex count of a polygon that rast__prim_need has counted. */
static uint32_t rast__ring_points(const uint32_t *sizes, uint32_t nrings)
{
    uint32_t k, n = 0;
    for (k = 0; k < nrings; k++) n += sizes[k];
    return n;
}

/* Draw primitive p, which rast__prim_draw has checked on the whole clip,
 * inside `band` (non-empty, inside that clip, with enough scratch): its
 * entry point's painter and filler with nothing checked again.  A
 * polyline's checks are its drawing: it goes through its entry point. */
static rast_status rast__prim_band(rast__scene *s, const rast_prim *p, const rast_rect *band)
{
    rast__solid solid;
    rast__user_spans u;
    rast__painter pt;
    const int aa = RAST_CONFIG_AA_METHODS != 0 && p->aa != NULL;
    rast_status st;

    if (p->kind == RAST_PRIM_POLYLINE) return rast__prim_draw(s, p, band);
    if (s->target) {
        st = rast__solid_init(&solid, s->target, band, p->pixel, NULL, &pt);
        if (st != RAST_OK) return st; /* not reached: checked with the scene */
    } else {
        s->prim = p;
        rast__user_painter(&u, aa ? NULL : rast__scene_span, aa ? rast__scene_cov : NULL, s, &pt);
    }
    if (aa && p->kind == RAST_PRIM_POLYGON)
        return rast__cov_paint_checked(&p->polygon, NULL, 0,
                                       rast__ring_points(p->polygon.ring_sizes, p->polygon.nrings),
                                       p->aa, band, &pt, s->scratch, s->bytes);
    if (aa) /* RAST_PRIM_TRIANGLES */
        return rast__cov_paint_checked(NULL, p->points, p->count, 3 * p->count, p->aa, band, &pt,
                                       s->scratch, s->bytes);
    if (RAST_CONFIG_POLYGON64 && p->kind == RAST_PRIM_POLYGON64) {
        rast__grid64 g;
        st = rast__fill64_prepare(p->fill, &g);
        if (st != RAST_OK) return st; /* not reached */
        return rast__fill64_checked(&p->polygon64,
                                    rast__ring_points(p->polygon64.ring_sizes, p->polygon64.nrings),
                                    p->fill, &g, band, &pt, s->scratch, s->bytes);
    }
    if (p->kind == RAST_PRIM_TRIANGLES) {
        rast__grid g;
        st = rast__grid_init(&g, p->tri->subpixel_bits, p->tri->sample, p->tri->rounding,
                             p->tri->boundary);
        if (st != RAST_OK) return st; /* not reached */
        return rast__tri_fill_checked(p->points, p->count, p->tri, &g, band, &pt, NULL, s->scratch,
                                      s->bytes);
    }
    {
        rast__fill_setup f;
        st = rast__fill_prepare(p->fill, &f);
        if (st != RAST_OK) return st; /* not reached */
        return rast__fill_checked(&f, &p->polygon,
                                  rast__ring_points(p->polygon.ring_sizes, p->polygon.nrings), band,
                                  &pt, s->scratch, s->bytes);
    }
}

/* Check the whole scene, then draw it band by band into `clip` (checked,
 * non-inverted). */
static rast_status rast__render(rast__scene *s, const rast_prim *prims, uint32_t n,
                                const rast_rect *clip, int32_t band_rows,
                                rast_band_stats *stats)
{
    const int32_t width = clip->x1 - clip->x0;
    rast_band_stats sum;
    rast_rect band;
    uint32_t i;
    int32_t y;
    size_t need;
    rast_status st;

    if (n > 0 && !prims) return RAST_E_NULL;
    if (band_rows < 1) return RAST_E_ARG;
    sum.bands = 0;
    sum.splits = 0;
    sum.peak_scratch = 0;

    /* Everything that can fail, before the first write: the one-row need,
     * then the primitive's own checks on an empty clip (which also check
     * the scratch pointer and its alignment). */
    band.x0 = band.x1 = clip->x0;
    band.y0 = band.y1 = clip->y0;
    for (i = 0; i < n; i++) {
        st = rast__prim_need(&prims[i], width, 1, &need);
        if (st != RAST_OK) return st;
        if (need > s->bytes) return RAST_E_SCRATCH;
        st = rast__prim_draw(s, &prims[i], &band);
        if (st != RAST_OK) return st;
    }

    for (y = clip->y0; y < clip->y1;) {
        /* clip->y1 - y fits int32_t: both lie in +-RAST_MAX_DIM. */
        const int32_t rows = clip->y1 - y < band_rows ? clip->y1 - y : band_rows;
        sum.bands++;
        for (i = 0; i < n; i++) {
            int32_t sub = rows, r;
            for (;;) {
                st = rast__prim_need(&prims[i], width, sub, &need);
                if (st != RAST_OK) return st; /* not reached: checked above */
                if (need <= s->bytes || sub == 1) break;
                sub = sub - sub / 2; /* halve, rounding up: two parts cover it */
                sum.splits++;
            }
            if (need > sum.peak_scratch) sum.peak_scratch = need;
            for (r = y; r < y + rows; r += sub) {
                band.x0 = clip->x0;
                band.x1 = clip->x1;
                band.y0 = r;
                band.y1 = y + rows - r < sub ? y + rows : r + sub;
                if (width == 0) continue; /* nothing to draw, as each entry point */
                st = rast__prim_band(s, &prims[i], &band);
                if (st != RAST_OK) return st; /* not reached: checked above */
            }
        }
        y += rows;
    }
    if (stats) *stats = sum;
    return RAST_OK;
}

rast_status rast_render_bands(const rast_target *target, const rast_prim *prims, uint32_t n,
                              int32_t band_rows, void *scratch, size_t scratch_bytes,
                              rast_band_stats *stats)
{
    rast__scene s;
    rast_rect clip;
    rast_status st = rast__target_check(target, &clip);
    if (st != RAST_OK) return st;
    rast__scene_init(&s, target, NULL, NULL, NULL, scratch, scratch_bytes);
    return rast__render(&s, prims, n, &clip, band_rows, stats);
}

/* The spans calls: a checked clip, the scene to `span` or `cspan`. */
static rast_status rast__render_to(const rast_prim *prims, uint32_t n, const rast_rect *clip,
                                   int32_t band_rows, rast_prim_span_fn span,
                                   rast_prim_coverage_fn cspan, void *user, void *scratch,
                                   size_t scratch_bytes, rast_band_stats *stats)
{
    rast__scene s;
    rast_rect c;
    rast_status st;
    if (!clip || (!span && !cspan)) return RAST_E_NULL;
    st = rast__span_clip(clip, &c);
    if (st != RAST_OK) return st;
    rast__scene_init(&s, NULL, span, cspan, user, scratch, scratch_bytes);
    return rast__render(&s, prims, n, &c, band_rows, stats);
}

rast_status rast_render_bands_spans(const rast_prim *prims, uint32_t n, const rast_rect *clip,
                                    int32_t band_rows, rast_prim_span_fn span, void *user,
                                    void *scratch, size_t scratch_bytes, rast_band_stats *stats)
{
    if (!span) return RAST_E_NULL;
    return rast__render_to(prims, n, clip, band_rows, span, NULL, user, scratch, scratch_bytes,
                           stats);
}

rast_status rast_render_bands_coverage(const rast_prim *prims, uint32_t n, const rast_rect *clip,
                                       int32_t band_rows, rast_prim_coverage_fn span, void *user,
                                       void *scratch, size_t scratch_bytes,
                                       rast_band_stats *stats)
{
    if (!span) return RAST_E_NULL;
    return rast__render_to(prims, n, clip, band_rows, NULL, span, user, scratch, scratch_bytes,
                           stats);
}

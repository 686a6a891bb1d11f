/*
 * paint.h - the pixel formats, the solid painter and the target checks
 * shared with the dispatchers.
 */
#ifndef RAST_PAINT_H
#define RAST_PAINT_H

#include "../base/internal.h"

/* A pixel format (formats.c has one row per rast_format).  Rows are
 * addressed by their first byte; x is a column.  A pixel VALUE is what the
 * `pixel` arguments hold: `value` bytes in the format's own encoding. */
typedef struct rast__format {
    int32_t bits;     /* bits of memory per pixel: 1, 8, 16, 24, 32 */
    int32_t value;    /* bytes of a pixel value; 0: the format takes none (COUNT16) */
    int32_t channels; /* RGBA channels a shaded fill interpolates (R, RGB, RGBA); 0: none */
    rast__row_fn row; /* a solid row painter of its own (user: rast__solid), or NULL
                         for the generic one calling `fill` per span */
    /* columns [x0, x1) of `row` set to the value v (COUNT16: plus 1) */
    void (*fill)(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v);
    /* an 8-bit RGBA colour as a pixel value; NULL if the format has none */
    void (*pack)(const unsigned char *rgba, unsigned char *v);
    /* columns [x, x + n) of `row` from n RGBA colours (4 bytes each) */
    void (*put)(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba);
    /* columns [x0, x1) of `row` painted with the value v weighted by the
     * coverage levels cov[0 .. x1 - x0) (uint8, floor(a 255 + 1/2)):
     * channels blended by rast__blend8, MONO1 thresholded, COUNT16 counted
     * (see rast_fill_polygon_aa) */
    void (*blend)(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                  const unsigned char *v);
} rast__format;

/* One channel of level s (the fill's) over level d (the pixel's) with
 * coverage level a (0..255): floor((s a + d (255 - a) + 127) / 255), the
 * nearest integer to the exact mix (s a + d (255 - a)) / 255, which is
 * never a tie (255 is odd).  a = 255 gives s, a = 0 gives d; levels up to
 * 255 (an 8-bit channel, or rgb565's 5- and 6-bit ones). */
static inline unsigned rast__blend8(unsigned s, unsigned d, unsigned a)
{
    return (s * a + d * (255u - a) + 127u) / 255u;
}

extern const rast__format rast__formats[RAST_FORMAT_COUNT_];

/* A known format that the build keeps (base/config.h). */
#define RAST__FORMAT_KEPT(f) \
    ((unsigned)(f) < RAST_FORMAT_COUNT_ && RAST__HAS(RAST_CONFIG_FORMATS, (f)))

typedef struct rast__solid {
    unsigned char *base;
    ptrdiff_t stride;
    const rast__format *fmt;
    unsigned char value[4];       /* inside */
    unsigned char background[4];  /* outside (opaque painter only) */
    rast_rect clip;
    int32_t row;                  /* opaque: the last row written */
} rast__solid;

/* A span callback's clip: coordinates within +-RAST_MAX_DIM (so that its
 * width and height fit int32_t) else RAST_E_SIZE; an inverted one is made
 * empty. */
rast_status rast__span_clip(const rast_rect *clip, rast_rect *c);

/* The scratch a polygon (triangle batch) fill needs for a clip of width x
 * height, any size rast__span_clip passes (up to 2 RAST_MAX_DIM): the
 * entry points' own formula, for rast_render_bands* too, so that a scene
 * accepts every clip its primitives' entry points accept.  Checks the
 * options; RAST_E_SIZE for a negative side. */
rast_status rast__fill_need(const rast_fill_opts *opts, uint32_t npoints, int32_t width,
                            int32_t height, size_t *bytes);
rast_status rast__tri_fill_need(const rast_tri_opts *opts, int32_t width, int32_t height,
                                size_t *bytes);

/* Check a target (as rast_target_init would) and cut its clip to it. */
rast_status rast__target_check(const rast_target *t, rast_rect *clip);

/* The painter of the user's callbacks: each full run to `fn` (the span
 * entry points, rast_fill_polygon_spans, ...), each levels run to `cov`
 * (the coverage span entry points, rast_polygon_coverage_spans, ...);
 * the entry of a NULL one is NULL.  *p is set up with *u as its user. */
typedef struct rast__user_spans {
    rast_span_fn fn;
    rast_coverage_span_fn cov;
    void *user;
} rast__user_spans;
void rast__user_painter(rast__user_spans *u, rast_span_fn fn, rast_coverage_span_fn cov,
                        void *user, rast__painter *p);

/* The solid painter: `pixel` (a value of the target's format) over the
 * runs of a checked target and clip, a full run written, a levels run
 * blended by the format's blend (formats.c): fills *s and the painter *p
 * (user s; with the fast kind for a one-byte format).  With a non-NULL
 * `background` it is the opaque painter (full runs only): every clip
 * pixel is written, and rast__opaque_finish must follow a successful
 * fill.  RAST_FORMAT_COUNT16 adds 1 per covered pixel instead (a levels
 * run: per pixel not 0) and ignores `pixel` (it may be NULL); it has no
 * opaque painter (RAST_E_FORMAT).  Otherwise RAST_E_NULL for a NULL
 * pixel. */
rast_status rast__solid_init(rast__solid *s, const rast_target *t, const rast_rect *clip,
                             const void *pixel, const void *background, rast__painter *p);
void rast__opaque_finish(rast__solid *s);

#if !defined(__OPTIMIZE_SIZE__)
/* A sink's painter seen as rows of one-byte pixels that a filler may
 * write itself, a word at a time (the winding-delta fill, fillers/aet.c):
 * the solid painter's fast kind (full runs set `value`, nothing else
 * written), or the opaque painter of a one-byte format (`opaque`: the
 * rows the filler takes are first claimed, rast__byte_rows_claim, then
 * each written whole, columns [x0, x1) (the clip's), `value` inside and
 * `background` outside).  Pixel (x, y) is base[y stride + x].  0 when
 * the sink's painter is neither, or the sink holds spans.  Not in a build
 * for size (which has no such filler). */
typedef struct rast__byte_rows {
    unsigned char *base;
    ptrdiff_t stride;
    unsigned char value, background;
    int opaque;
    int32_t x0, x1;
    rast__solid *solid; /* opaque: the painter */
} rast__byte_rows;
int rast__sink_byte_rows(const rast__sink *sink, rast__byte_rows *b);

/* Opaque: the rows before y0 that nothing wrote get the background; rows
 * [y0, y1) (y0 < y1, after any row written) are the caller's, to write
 * whole, the painter going on after them. */
void rast__byte_rows_claim(const rast__byte_rows *b, int32_t y0, int32_t y1);

/* The solid gray8 painter's fast kind, levels a box at a time
 * (formats.c): rows [y0, y1), columns [x0, x1) of base (a row every
 * stride bytes) blended toward value by the levels at lv (a row every
 * lstride bytes, the first row y0's from column x0). */
void rast__gray8_blend_rows(unsigned char *base, ptrdiff_t stride, unsigned char value, int32_t x0,
                            int32_t x1, int32_t y0, int32_t y1, const uint8_t *lv, ptrdiff_t lstride);

/* Bytes p[0 .. len) set to v, w its byte in all eight: a run of up to 32
 * by word stores that stay inside it (overlapping), a longer one by
 * memset.  A spiky outline's rows are many short runs, a memset call each
 * (~27 instructions a run on the 200-spike star).  The opaque gray8
 * painter's runs (paint.c) and the AET's own rows (fillers/aet.c). */
static inline void rast__run8(unsigned char *p, size_t len, unsigned char v, uint64_t w)
{
    if (len > 32) {
        memset(p, v, len);
    } else if (len >= 8) {
        memcpy(p, &w, 8);
        memcpy(p + len - 8, &w, 8);
        if (len > 16) {
            memcpy(p + 8, &w, 8);
            memcpy(p + len - 16, &w, 8);
        }
    } else if (len >= 4) {
        memcpy(p, &w, 4);
        memcpy(p + len - 4, &w, 4);
    } else if (len > 0) {
        p[0] = v;
        p[len / 2] = v;
        p[len - 1] = v;
    }
}
#endif

/* Called before triangle k (vertices t, grid g) is filled, with the
 * painter's `user`: set the painter up for it; 0 skips the triangle. */
typedef int (*rast__tri_begin_fn)(void *user, const rast_point *t, uint32_t k,
                                  const rast__grid *g);

/* The triangle batch behind every triangle entry point (trifill.c): check
 * the batch, options and scratch for `clip` (non-empty or empty, cut to the
 * target or a span clip), then run the filler on each triangle in turn,
 * calling `begin` (with the painter's user) first when it is not NULL, its
 * runs going to painter p. */
rast_status rast__tri_fill(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                           const rast_rect *clip, const rast__painter *p,
                           rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes);
/* The same in two steps: rast__tri_fill's checks (the grid into *g), and
 * the fill with nothing checked (a clip no larger than the checked one). */
rast_status rast__tri_check(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                            const rast_rect *clip, rast__grid *g, void *scratch,
                            size_t scratch_bytes);
rast_status rast__tri_fill_checked(const rast_point *tris, uint32_t ntris,
                                   const rast_tri_opts *opts, const rast__grid *g,
                                   const rast_rect *clip, const rast__painter *p,
                                   rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes);

/* A checked triangle filler as rast__tri_fill_checked (its signature):
 * rast__tri_fill_checked itself, or rast__tri_touching (shade_aa.c). */
typedef rast_status (*rast__tri_filler_fn)(const rast_point *tris, uint32_t ntris,
                                           const rast_tri_opts *opts, const rast__grid *g,
                                           const rast_rect *clip, const rast__painter *p,
                                           rast__tri_begin_fn begin, void *scratch,
                                           size_t scratch_bytes);

/* The pixels whose closed square [i, i+1] x [j, j+1] meets an edge (a
 * closed segment) of the triangle, for each non-degenerate triangle in
 * turn (rows top to bottom, a span per edge in the row, possibly
 * overlapping), cut to `clip`: the silhouette filler of the anti-aliased
 * shaded fill.  A checked filler (the batch and options passed
 * rast__tri_check; g their grid, given to `begin`); needs no scratch;
 * the painter's full entry only. */
rast_status rast__tri_touching(const rast_point *tris, uint32_t ntris, const rast_tri_opts *opts,
                               const rast__grid *g, const rast_rect *clip, const rast__painter *p,
                               rast__tri_begin_fn begin, void *scratch, size_t scratch_bytes);

/* The Gouraud painter (shade.c) fed by `filler`, into RGBA8888 colours:
 * pixel (band->x0 + i, band->y0 + j) at rgba + j stride + 4 i, every
 * pixel of `band` the filler gives written (clamped to 0..255).  The
 * batch and `opts` passed rast__tri_check (g their grid); `shade`'s
 * precision is checked (as rast_fill_triangles_shaded's, no depth). */
rast_status rast__shade_band(unsigned char *rgba, ptrdiff_t stride, const rast_rect *band,
                             const rast_point *tris, uint32_t ntris, const uint8_t *colors,
                             const rast_tri_opts *opts, const rast__grid *g,
                             const rast_shade_opts *shade, rast__tri_filler_fn filler,
                             void *scratch, size_t scratch_bytes);

/* The polygon entry points' common part (fill.c), for 32-bit polygons
 * (fill.c) and 64-bit ones (poly64.c): `fill` checks the polygon (a
 * rast_polygon or rast_polygon64), options and scratch for a clip and runs
 * the filler into the row painter.  rast__fill_target checks the target
 * and paints `pixel` (with `opaque`, `background` elsewhere in the clip);
 * rast__fill_spans hands the spans to a user callback. */
/* A polygon fill's options, checked once for many polygons (batch.c):
 * the algorithm and the grid. */
struct rast__algo;
typedef struct rast__fill_setup {
    const rast_fill_opts *opts;
    const struct rast__algo *al;
    rast__grid g;
} rast__fill_setup;
/* Check the options (the errors of rast_scratch_size's) into *f. */
rast_status rast__fill_prepare(const rast_fill_opts *opts, rast__fill_setup *f);
/* rast_fill_bounds with checked options: check the polygon (its vertex
 * count, then every vertex's range, from one pass over them) and the span
 * clip, and give its bounds there and its vertex count. */
rast_status rast__fill_measure(const rast__fill_setup *f, const rast_polygon *polygon,
                               const rast_rect *clip, uint32_t *npoints, rast_rect *bounds);
/* The scratch a fill of npoints vertices needs in a width x height clip. */
size_t rast__fill_scratch(const rast__fill_setup *f, uint32_t npoints, int32_t width,
                          int32_t height);
/* Fill a polygon that rast__fill_measure passed (npoints its count) in a
 * non-empty clip within its span clip, with aligned scratch of at least
 * rast__fill_scratch bytes for that clip: nothing is checked again. */
rast_status rast__fill_checked(const rast__fill_setup *f, const rast_polygon *polygon,
                               uint32_t npoints, const rast_rect *clip, const rast__painter *p,
                               void *scratch, size_t scratch_bytes);

/* The same for 64-bit polygons (poly64.c): the options checked once into
 * the grid; a polygon checked and measured (rast_fill_bounds64 with checked
 * options); its scratch; and its fill, nothing checked again. */
rast_status rast__fill64_prepare(const rast_fill_opts *opts, rast__grid64 *g);
rast_status rast__fill64_measure(const rast_fill_opts *opts, const rast__grid64 *g,
                                 const rast_polygon64 *polygon, const rast_rect *clip,
                                 uint32_t *npoints, rast_rect *bounds);
size_t rast__fill64_scratch(const rast_fill_opts *opts, uint32_t npoints, int32_t height);
rast_status rast__fill64_checked(const rast_polygon64 *poly, uint32_t npoints,
                                 const rast_fill_opts *opts, const rast__grid64 *g,
                                 const rast_rect *clip, const rast__painter *p, void *scratch,
                                 size_t scratch_bytes);

/* A rast_polygon's fill (fill.c; a rast__fill_any_fn): check the polygon,
 * options and scratch for `clip`, then run the filler into painter p. */
rast_status rast__fill(const void *polygon, const rast_fill_opts *opts, const rast_rect *clip,
                       const rast__painter *p, void *scratch, size_t scratch_bytes);
/* rast__fill for a polygon whose every point the caller has checked to lie
 * in +-RAST_COORD_MAX (the internal contract of the Python binding, whose
 * snap refuses any other before the call); every other check the same.
 * Not in size-optimised builds (__OPTIMIZE_SIZE__). */
rast_status rast__fill_snapped(const void *polygon, const rast_fill_opts *opts,
                               const rast_rect *clip, const rast__painter *p, void *scratch,
                               size_t scratch_bytes);
typedef rast_status (*rast__fill_any_fn)(const void *polygon, const rast_fill_opts *opts,
                                         const rast_rect *clip, const rast__painter *p,
                                         void *scratch, size_t scratch_bytes);
rast_status rast__fill_target(const rast_target *target, const void *polygon,
                              const rast_fill_opts *opts, const void *pixel,
                              const void *background, int opaque, rast__fill_any_fn fill,
                              void *scratch, size_t scratch_bytes);
rast_status rast__fill_spans(const void *polygon, const rast_fill_opts *opts,
                             const rast_rect *clip, rast_span_fn span, void *user,
                             rast__fill_any_fn fill, void *scratch, size_t scratch_bytes);

/* The coverage pipeline (coverage.c): a polygon (poly not NULL) or a
 * triangle batch's coverage inside `clip` (a span clip, cut to nothing
 * else) handed to painter p's levels entry, row by row, each run of
 * levels not 0.  Every check of rast_polygon_coverage_spans /
 * rast_triangles_coverage_spans (but the callback's) before the first
 * run. */
rast_status rast__cov_paint(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                            const rast_coverage_opts *opts, const rast_rect *clip,
                            const rast__painter *p, void *scratch, size_t scratch_bytes);
/* The same in two steps, for a caller painting the same geometry band by
 * band: every check, once, for the whole clip, with the scratch for a band
 * of `rows` rows (*npoints: the vertex count); then each band (rows of the
 * checked clip, at most `rows` of them) painted with nothing checked
 * again. */
rast_status rast__cov_paint_check(const rast_polygon *poly, const rast_point *tris,
                                  uint32_t ntris, const rast_coverage_opts *opts,
                                  const rast_rect *clip, int32_t rows, void *scratch,
                                  size_t scratch_bytes, uint32_t *npoints);
rast_status rast__cov_paint_checked(const rast_polygon *poly, const rast_point *tris,
                                    uint32_t ntris, uint32_t npoints,
                                    const rast_coverage_opts *opts, const rast_rect *clip,
                                    const rast__painter *p, void *scratch, size_t scratch_bytes);
#if !defined(__OPTIMIZE_SIZE__)
/* rast__cov_paint of a polygon (tris unused) for the Python binding's
 * anti-aliased fill, whose glue has made the checks of rast__cov_begin
 * and rast__cov_check_points before the call: the options, the clip's
 * size and the vertex count by rast_coverage_scratch_size for this
 * clip's size, the scratch that size (aligned), and every point snapped
 * into +-RAST_COORD_MAX (rastpy_snap); the clip the target's, checked.
 * Only a supersampling method's own checks (its fine grid's range) are
 * made.  Not in size-optimised builds. */
rast_status rast__cov_paint_snapped(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                                    const rast_coverage_opts *opts, const rast_rect *clip,
                                    const rast__painter *p, void *scratch, size_t scratch_bytes);
/* rast_fill_polygon_aa through rast__cov_paint_snapped (its contract). */
rast_status rast__fill_polygon_aa_snapped(const rast_target *target, const rast_polygon *polygon,
                                          const rast_coverage_opts *opts, const void *pixel,
                                          void *scratch, size_t scratch_bytes);
#endif

/* Source-over of a per-pixel source colour (blend.c, rastrum.h "shaded
 * fills with opacity"): n pixels from x of `row`, pixel k from the RGBA
 * colour rgba[4k .. 4k + 3] (its alpha times the opacity) at coverage
 * level cov[k] (cov NULL: 255), rounded as rast_blend_coverage rounds.
 * ctx is what blend.c set up for it.  The shaded fills call it in place
 * of the format's put (shade.c, shade_rect.c, shade_poly.c) or blend
 * (shade_aa.c). */
typedef void (*rast__rgba_put_fn)(const void *ctx, unsigned char *row, int32_t x, int32_t n,
                                  const unsigned char *rgba, const uint8_t *cov);

/* rast_fill_triangles_shaded (no depth) / rast_fill_triangles_shaded_aa
 * with each pixel's colour handed to bput (NULL: stored as they store it):
 * every channel, alpha too, interpolated whatever the format. */
rast_status rast__fill_shaded(const rast_target *target, const rast_point *tris, uint32_t ntris,
                              const uint8_t *colors, const int32_t *z, int32_t *zbuf,
                              const rast_tri_opts *opts, const rast_shade_opts *shade,
                              rast__rgba_put_fn bput, const void *bctx, void *scratch,
                              size_t scratch_bytes);
rast_status rast__fill_shaded_aa(const rast_target *target, const rast_point *tris,
                                 uint32_t ntris, const uint8_t *colors,
                                 const rast_coverage_opts *opts, const rast_shade_opts *shade,
                                 rast__rgba_put_fn bput, const void *bctx, void *scratch,
                                 size_t scratch_bytes);

/* rast_fill_rect_gouraud (shade_rect.c) and rast_fill_polygon_gouraud
 * (shade_poly.c) with each pixel's colour handed to bput (NULL: stored as
 * they store it): every channel, alpha too, interpolated whatever the
 * format; FLAT hands vertex (corner) 0's colour to the same pixels. */
rast_status rast__fill_rect_shaded(const rast_target *target, rast_point p0, rast_point p1,
                                   const uint8_t *colors, const rast_tri_opts *opts,
                                   const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                   const void *bctx);
rast_status rast__fill_polygon_shaded(const rast_target *target, const rast_polygon *polygon,
                                      const uint8_t *colors, const rast_fill_opts *opts,
                                      const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                      const void *bctx, void *scratch, size_t scratch_bytes);

/* The polygon of a shaded fill checked (shade_poly.c): ring sizes, their
 * total (*npoints), NULL pointers and every vertex's range, as
 * rast_fill_polygon_gouraud checks them. */
rast_status rast__poly_shade_check(const rast_polygon *polygon, const uint8_t *colors,
                                   uint32_t *npoints);
/* The binary Gouraud polygon (rast_fill_polygon_gouraud's walk, its
 * pixels and colours for `rule` on grid g; flat: vertex 0's colour) into
 * RGBA8888 colours: pixel (band->x0 + i, band->y0 + j) at
 * rgba + j stride + 4 i.  A polygon that passed rast__poly_shade_check
 * (npoints its count); scratch of rast_polygon_gouraud_scratch_size for
 * the band. */
rast_status rast__poly_shade_band(unsigned char *rgba, ptrdiff_t stride, const rast_rect *band,
                                  const rast_polygon *polygon, uint32_t npoints,
                                  const uint8_t *colors, const rast__grid *g, rast_fill_rule rule,
                                  int flat, void *scratch, size_t scratch_bytes);
/* rast_fill_polygon_gouraud_aa (shade_aa.c) with each pixel's colour
 * handed to bput (NULL: blended as the format blends a value). */
rast_status rast__fill_polygon_shaded_aa(const rast_target *target, const rast_polygon *polygon,
                                         const uint8_t *colors, const rast_coverage_opts *opts,
                                         const rast_shade_opts *shade, rast__rgba_put_fn bput,
                                         const void *bctx, void *scratch, size_t scratch_bytes);

#endif /* RAST_PAINT_H */

/*
 * coverage.c - the coverage entry points (rastrum.h, "anti-aliased
 * coverage"): check everything, build the edges (or the fine-grid
 * polygon), then run the method.  Every error is found here, before a
 * value is written.
 */
#include "../coverage/coverage.h"
#include "../painters/paint.h"
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__COV_RANGE_SSE2 1
#endif

static const char *const rast__aa_names[RAST_AA_COUNT_] = {"area", "ss2", "ss4",
                                                           "ss8", "ss16", "accumulate"};

rast_status rast_aa_method_info(rast_aa_method method, const char **name)
{
    if ((unsigned)method >= RAST_AA_COUNT_ || !RAST__HAS(RAST_CONFIG_AA_METHODS, method))
        return RAST_E_ARG;
    if (name) *name = rast__aa_names[method];
    return RAST_OK;
}

/* Some supersampling method is kept by the build's configuration (a
 * constant: where none is, rast__aa_kbits is 0 for every method the
 * checks let through, and the fine-grid path, rast__cov_ss and
 * rast__cov_ss_tris, is not linked: docs/c.md, "Pay for what you call").
 * The same for "accumulate" (whose own paths "area" does not take). */
#define RAST__SS_KEPT                                                          \
    (RAST__HAS(RAST_CONFIG_AA_METHODS, RAST_AA_SS2) ||                         \
     RAST__HAS(RAST_CONFIG_AA_METHODS, RAST_AA_SS4) ||                         \
     RAST__HAS(RAST_CONFIG_AA_METHODS, RAST_AA_SS8) ||                         \
     RAST__HAS(RAST_CONFIG_AA_METHODS, RAST_AA_SS16))
#define RAST__IS_ACC(m) (RAST__HAS(RAST_CONFIG_AA_METHODS, RAST_AA_ACCUMULATE) && (m) == RAST_AA_ACCUMULATE)

/* log2 of k for the supersampling methods, 0 for the others. */
static int32_t rast__aa_kbits(rast_aa_method m)
{
    return (RAST__SS_KEPT && m >= RAST_AA_SS2 && m <= RAST_AA_SS16) ? (int32_t)(m - RAST_AA_SS2) + 1 : 0;
}

static rast_status rast__cov_check_opts(const rast_coverage_opts *o)
{
    if (!o) return RAST_E_NULL;
    if ((unsigned)o->method >= RAST_AA_COUNT_ || !RAST__HAS(RAST_CONFIG_AA_METHODS, o->method))
        return RAST_E_ARG;
    if ((unsigned)o->rule > RAST_RULE_NONZERO) return RAST_E_ARG;
    if (o->subpixel_bits < 0 || o->subpixel_bits > RAST_MAX_SUBPIXEL_BITS) return RAST_E_SUBPIXEL;
    if (o->sample != RAST_SAMPLE_CORNER && o->sample != RAST_SAMPLE_CENTER) return RAST_E_ARG;
    return RAST_OK;
}

static size_t rast__cov_need(const rast_coverage_opts *o, uint32_t npoints, int32_t width,
                             int32_t height)
{
    int32_t kb = rast__aa_kbits(o->method);
    /* the spans call's row buffer first */
    size_t row = rast__align((size_t)width);
    if (!kb) return rast__size_add(row, rast__cov_area_scratch(npoints, width));
    /* the fine-grid copy of the vertices and ring sizes, then the count */
    return rast__size_add(row, rast__size_add(rast__align(rast__size_mul(npoints, sizeof(rast_point))),
                          rast__size_add(rast__align(rast__size_mul(npoints, sizeof(uint32_t))),
                                         rast__cov_ss_scratch(npoints, kb, width, height))));
}

rast_status rast_coverage_scratch_size(const rast_coverage_opts *opts, uint32_t npoints,
                                       int32_t width, int32_t height, size_t *bytes)
{
    rast_status st;
    if (!bytes) return RAST_E_NULL;
    st = rast__cov_check_opts(opts);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    *bytes = rast__cov_need(opts, npoints, width, height);
    return RAST_OK;
}

static rast_status rast__cov_check_points(const rast_point *p, uint32_t n, int32_t scale)
{
    const int32_t lim = RAST_COORD_MAX >> scale;
    uint32_t i = 0, i0;
#if defined(RAST__COV_RANGE_SSE2)
    /* Four points (eight coordinates) a step against +-lim (lim <=
     * RAST_COORD_MAX: both of the loops below in one), the comparisons
     * gathered and tested once at the end, as the binary fill's
     * (entry/fill.c, rast__check_polygon): 12 instructions a vertex were
     * ~370 K of a line of text's "accumulate" (its 31,354 vertices); the
     * last 0-3 points by the loops below, from i0. */
    {
        const __m128i hi = _mm_set1_epi32(lim), lo = _mm_set1_epi32(-lim);
        __m128i bad = _mm_setzero_si128();
        for (; i + 4 <= n; i += 4) {
            const __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(p + i));
            const __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(p + i + 2));
            bad = _mm_or_si128(bad, _mm_or_si128(_mm_cmpgt_epi32(a, hi), _mm_cmplt_epi32(a, lo)));
            bad = _mm_or_si128(bad, _mm_or_si128(_mm_cmpgt_epi32(b, hi), _mm_cmplt_epi32(b, lo)));
        }
        if (_mm_movemask_epi8(bad)) return RAST_E_RANGE;
    }
#endif
    for (i0 = i; i < n; i++)
        if (p[i].x < -RAST_COORD_MAX || p[i].x > RAST_COORD_MAX || p[i].y < -RAST_COORD_MAX ||
            p[i].y > RAST_COORD_MAX)
            return RAST_E_RANGE;
    if (scale)
        for (i = i0; i < n; i++)
            if (p[i].x < -lim || p[i].x > lim || p[i].y < -lim || p[i].y > lim)
                return RAST_E_RANGE;
    return RAST_OK;
}

/* Does the clip's fine grid (kb bits more a pixel) fit in +-RAST_MAX_DIM? */
static int rast__cov_fine_fits(const rast_rect *c, int32_t kb)
{
    const int32_t lim = RAST_MAX_DIM >> kb;
    return !kb || (c->x0 >= -lim && c->x1 <= lim && c->y0 >= -lim && c->y1 <= lim);
}

/* Everything but the geometry: options, output, clip, and (given the
 * vertex count) the scratch, for the clip's rows or, when fewer, `rows`
 * rows (a band of it).  *o is set up for the cut clip. */
static rast_status rast__cov_begin(const rast_coverage_opts *opts, const rast_rect *clip,
                                   rast_coverage_format format, void *out, ptrdiff_t stride,
                                   uint32_t npoints, void *scratch, size_t scratch_bytes,
                                   rast__cov_out *o, int spans, int32_t rows)
{
    static const int32_t size[3] = {1, 2, 8};
    rast_status st = rast__cov_check_opts(opts);
    int32_t kb, w, h;
    if (st != RAST_OK) return st;
    if (!clip) return RAST_E_NULL;
    if ((unsigned)format > RAST_COVERAGE_FIX62) return RAST_E_ARG;
    st = rast__span_clip(clip, &o->clip);
    if (st != RAST_OK) return st;
    kb = rast__aa_kbits(opts->method);
    if (!rast__cov_fine_fits(&o->clip, kb)) return RAST_E_SIZE;
    w = o->clip.x1 - o->clip.x0;
    h = o->clip.y1 - o->clip.y0;
    if (npoints > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    if (w > 0 && h > 0 && !spans) {
        if (!out) return RAST_E_NULL;
        if (stride % size[format] || (uintptr_t)out % (uintptr_t)size[format] ||
            stride < (ptrdiff_t)w * size[format])
            return RAST_E_ARG;
    }
    st = rast__scratch_check(scratch, scratch_bytes,
                             rast__cov_need(opts, npoints, w, h < rows ? h : rows));
    if (st != RAST_OK) return st;
    o->base = (unsigned char *)out;
    o->stride = stride;
    o->format = format;
    o->paint = NULL;
    return RAST_OK;
}

/* The fine-grid copy for supersampling: the vertices times 2^(kb - S)
 * when S < kb (else the same integers, read with S - kb bits). */
static void rast__cov_scale(const rast_point *p, uint32_t n, int32_t scale, rast_point *q)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        q[i].x = (int32_t)((uint32_t)p[i].x << scale);
        q[i].y = (int32_t)((uint32_t)p[i].y << scale);
    }
}

/* Does the test of rast__cov_plain pay?  It costs about what six rows of
 * an edge save ("area" over "accumulate": ~130 instructions a row, the
 * test ~500 to 1,100 a vertex on the bench's scenes), so only where the
 * edges' rows (the accumulation's parts) are 6 times the vertices.  The
 * edges' rows counted from the points (8 bytes a vertex), not from the
 * edges' records (336 bytes: a paragraph's 75,051 were 11% of "area"'s
 * time under perf, a cache miss an edge); the same count.  (Size-optimised
 * builds: from the edges, as before, 124 bytes less on Cortex-M0.) */
static int rast__cov_plain_pays(const rast_polygon *poly, const rast__cedge *e, uint32_t n, int32_t s,
                                uint32_t npoints)
{
    const int64_t off = (int64_t)1 << 27; /* |y| < 2^27: y + off > 0 */
    uint64_t rows = 0;
    uint32_t k;
#if !defined(__OPTIMIZE_SIZE__)
    uint32_t i, base;
    uint64_t ady = 0; /* the sum of |dy| over the edges */
    (void)e;
    (void)n;
    /* An edge's rows are at most |dy| / P + 2 (P = 2^s), so fewer than 6
     * a vertex in all when the sum of |dy| / P is below 4 a vertex (short
     * edges: text), found in a pass with no branch, the vertices in one
     * run (each ring's first edge mended after) */
    i = 1;
#if defined(RAST__COV_RANGE_SSE2)
    /* Two edges a step: the differences of points i, i + 1 and the ones
     * before them (|dy| < 2^28, checked: no lane overflows), their
     * absolute values' y lanes shifted down into two 64-bit sums; 11
     * instructions a vertex were ~370 K of a line of text's "area" */
    if (npoints >= 3) {
        __m128i sum = _mm_setzero_si128();
        uint64_t two[2];
        for (; i + 2 <= npoints; i += 2) {
            const __m128i a = _mm_loadu_si128((const __m128i *)(const void *)(poly->points + i));
            const __m128i b = _mm_loadu_si128((const __m128i *)(const void *)(poly->points + i - 1));
            const __m128i d = _mm_sub_epi32(a, b), sg = _mm_srai_epi32(d, 31);
            sum = _mm_add_epi64(sum, _mm_srli_epi64(_mm_sub_epi32(_mm_xor_si128(d, sg), sg), 32));
        }
        _mm_storeu_si128((__m128i *)(void *)two, sum);
        ady = two[0] + two[1];
    }
#endif
    for (; i < npoints; i++) {
        const int64_t d = (int64_t)poly->points[i].y - poly->points[i - 1].y;
        ady += (uint64_t)(d < 0 ? -d : d);
    }
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        const uint32_t size = poly->ring_sizes[k];
        const int64_t y = size ? poly->points[base].y : 0, d = size ? poly->points[base + size - 1].y - y : 0,
                      c = base ? poly->points[base - 1].y - y : 0;
        ady += (uint64_t)(d < 0 ? -d : d) - (uint64_t)(size ? (c < 0 ? -c : c) : 0);
    }
    if ((ady >> s) + 2 * (uint64_t)npoints < 6 * (uint64_t)npoints) return 0;
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        const rast_point *pt = poly->points + base;
        const uint32_t size = poly->ring_sizes[k];
        int64_t a = size ? pt[size - 1].y : 0;
        for (i = 0; i < size; i++) { /* the edge from the vertex before (an edge: two ordinates) */
            const int64_t b = pt[i].y, lo = a < b ? a : b, hi = a < b ? b : a;
            if (a != b) rows += (uint64_t)(((hi + off - 1) >> s) - ((lo + off) >> s) + 1);
            a = b;
        }
        if (rows >= 6 * (uint64_t)npoints) return 1; /* (enough: the rest need not be counted) */
    }
#else
    (void)poly;
    for (k = 0; k < n; k++)
        rows += (uint64_t)(((e[k].yt + off + e[k].dy - 1) >> s) - ((e[k].yt + off) >> s) + 1);
#endif
    return rows >= 6 * (uint64_t)npoints;
}

#if !defined(__OPTIMIZE_SIZE__)
/* Not 0 when the polygon is one ring that is convex: its edges of length 0
 * skipped, every two consecutive ones turn the same way or go straight on
 * (none turns back), and their direction goes round once (dx changes sign
 * exactly twice round the ring).  Each turn is then below a half turn, so
 * the direction turns monotonically through 2 pi times the number of
 * rounds, and passes the vertical, where dx changes sign, twice a round;
 * a closed polygon that turns one way through 2 pi is convex and simple.
 * Its winding number is 0 outside and +1 or -1 inside: it is plain
 * (coverage_plain.c), found in a few operations a vertex, and "area" may
 * take it by the accumulation at any size (the tiny polygons of a
 * call each, where rast__cov_plain_pays says no).  |coordinates| <=
 * RAST_COORD_MAX (checked): differences < 2^28, products < 2^57.  The
 * answer is the way it turns, the sign of px dy - py dx (+1 or -1), y
 * down: its accumulation's running sums inside, each edge's sign +1 down
 * and -1 up, are minus that times the area (coverage_small.c takes its
 * levels without |v| by it). */
static int rast__cov_convex(const rast_polygon *poly)
{
    const rast_point *p = poly->points;
    uint32_t n, i, j;
    int64_t px = 0, py = 0, dx, dy, c;
    int turn = 0, flips = 0, sx = 0;
    if (poly->nrings != 1 || (n = poly->ring_sizes[0]) < 3) return 0;
    /* the ring's last edge of length not 0, and the sign of the last dx
     * not 0: what comes before the first edge */
    for (i = n; i-- > 0 && !(sx && (px || py));) {
        j = i + 1 < n ? i + 1 : 0;
        dx = (int64_t)p[j].x - p[i].x;
        if (!px && !py) {
            px = dx;
            py = (int64_t)p[j].y - p[i].y;
        }
        if (!sx && dx) sx = dx > 0 ? 1 : -1;
    }
    if (!sx) return 0; /* every edge vertical or of length 0: no area */
    for (i = 0; i < n; i++) {
        j = i + 1 < n ? i + 1 : 0;
        dx = (int64_t)p[j].x - p[i].x;
        dy = (int64_t)p[j].y - p[i].y;
        if (!dx && !dy) continue;
        c = px * dy - py * dx;
        if (c == 0) {
            if (px * dx + py * dy < 0) return 0; /* turns back */
        } else {
            const int t = c > 0 ? 1 : -1;
            if (turn && t != turn) return 0;
            turn = t;
        }
        if (dx) {
            const int sd = dx > 0 ? 1 : -1;
            if (sd != sx && ++flips > 2) return 0;
            sx = sd;
        }
        px = dx;
        py = dy;
    }
    return flips == 2 ? turn : 0;
}
#endif

#if !defined(__OPTIMIZE_SIZE__)
/* "area" of a polygon some of whose parts are not plain (text with a
 * glyph or two whose rings touch; rast__cov_parts_test's table at the
 * start of arena's room) into an array, by its parts' boxes
 * (rast__cov_parts_boxes): the rings outside every box by their
 * accumulation, read from the points (coverage_acc.c), every row of the
 * clip written; then each box's pixels again, by rast__cov_area of its
 * rings' edges alone, the box its clip.  A ring's winding number is 0
 * outside the pixel box of its edges, so each pixel sees the rings of
 * one side only, and each side gives it its exact coverage
 * (docs/coverage.md: plain parts by the accumulation): the same levels
 * as rast__cov_area_marked's bands, without an edge record for the
 * rings outside the boxes, nor the exact rows for their edges.  1 when
 * done (*st the status), 0 when declined (nothing written; the table
 * kept).  A painter's rows go from the top, each once: there the boxes'
 * levels come first, into room of their own, and the accumulation's rows
 * go through rast__cov_merge_* (below), which hands the painter a row
 * that meets no box as it comes and a row that meets one with that box's
 * row put in (its pixels are 0 in the accumulation's), each row once, in
 * order.  The painter is handed what rast__cov_row_done makes of each
 * row of the array this function writes. */
#define RAST__COV_BOXES 32

/* A painter between the accumulation of the rings outside the boxes and
 * the real painter (rast__cov_by_boxes): rows that meet no box go straight
 * on; a row that meets one is gathered in rb (the clip's width, 0 outside
 * [lo, hi)), its boxes' levels put in, and handed on whole by
 * rast__cov_row_done; the boxes' rows the accumulation leaves empty are
 * handed on too, in their place. */
typedef struct rast__cov_merge {
    const rast__painter *real;
    rast__cov_out out; /* the real output (its clip, its painter) */
    unsigned char *rb; /* the gathered row, pixel out.clip.x0 first */
    const unsigned char *lv; /* the boxes' levels, box after box, row after row */
    const int32_t *bc; /* box k: x0, y0, x1, y1 (clipped), the offset of its levels in lv */
    int32_t nb, y0, y1; /* the boxes, the rows any meets: [y0, y1) */
    int32_t next, cur, pend, lo, hi; /* next row not handed on; last row seen; the row gathered (or INT32_MIN) */
} rast__cov_merge;

static int rast__cov_merge_meets(const rast__cov_merge *g, int32_t y)
{
    int32_t k;
    if (y < g->y0 || y >= g->y1) return 0;
    for (k = 0; k < g->nb; k++)
        if (y >= g->bc[5 * k + 1] && y < g->bc[5 * k + 3]) return 1;
    return 0;
}

/* Row y (gathered, or the boxes' alone) with its boxes' levels, on */
static void rast__cov_merge_row(rast__cov_merge *g, int32_t y)
{
    const int32_t cx = g->out.clip.x0;
    int32_t k;
    rast__cov_out t = g->out;
    for (k = 0; k < g->nb; k++) {
        const int32_t *b = g->bc + 5 * k, w = b[2] - b[0];
        if (y < b[1] || y >= b[3]) continue;
        memcpy(g->rb + (b[0] - cx), g->lv + b[4] + (ptrdiff_t)(y - b[1]) * w, (size_t)w);
        g->lo = b[0] < g->lo ? b[0] : g->lo;
        g->hi = b[2] > g->hi ? b[2] : g->hi;
    }
    if (g->lo >= g->hi) return;
    /* (0 outside [lo, hi): the same runs as the whole row's) */
    t.base = g->rb + (g->lo - cx);
    t.clip.x0 = g->lo;
    t.clip.x1 = g->hi;
    rast__cov_row_done(&t, y);
    memset(g->rb + (g->lo - cx), 0, (size_t)(g->hi - g->lo));
    g->lo = INT32_MAX;
    g->hi = INT32_MIN;
}

/* The rows before row y handed on (y: the next row the accumulation
 * hands, or the clip's end) */
static void rast__cov_merge_to(rast__cov_merge *g, int32_t y)
{
    int32_t r;
    if (g->pend != INT32_MIN) rast__cov_merge_row(g, g->pend);
    g->pend = INT32_MIN;
    for (r = g->next > g->y0 ? g->next : g->y0; r < y && r < g->y1; r++)
        if (rast__cov_merge_meets(g, r)) rast__cov_merge_row(g, r);
    g->next = y + 1;
}

/* Row y's first run from the accumulation */
static void rast__cov_merge_new(rast__cov_merge *g, int32_t y)
{
    g->cur = y;
    rast__cov_merge_to(g, y);
    g->pend = rast__cov_merge_meets(g, y) ? y : INT32_MIN;
}

/* A run of row y: 1 when the row is gathered */
static inline int rast__cov_merge_at(rast__cov_merge *g, int32_t y)
{
    if (y != g->cur) rast__cov_merge_new(g, y);
    return g->pend != INT32_MIN;
}

static void rast__cov_merge_levels(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    rast__cov_merge *g = (rast__cov_merge *)user;
    if (!rast__cov_merge_at(g, y)) {
        g->real->levels(g->real->user, y, x0, x1, cov);
        return;
    }
    memcpy(g->rb + (x0 - g->out.clip.x0), cov, (size_t)(x1 - x0));
    g->lo = x0 < g->lo ? x0 : g->lo;
    g->hi = x1 > g->hi ? x1 : g->hi;
}

static void rast__cov_merge_full(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__cov_merge *g = (rast__cov_merge *)user;
    int32_t i;
    if (!rast__cov_merge_at(g, y)) {
        g->real->full(g->real->user, y, xs, n);
        return;
    }
    for (i = 0; i < n; i++) {
        memset(g->rb + (xs[2 * i] - g->out.clip.x0), 255, (size_t)(xs[2 * i + 1] - xs[2 * i]));
        g->lo = xs[2 * i] < g->lo ? xs[2 * i] : g->lo;
        g->hi = xs[2 * i + 1] > g->hi ? xs[2 * i + 1] : g->hi;
    }
}

/* Box k's levels into ob (the box its clip), for both ways of
 * rast__cov_by_boxes: rast__cov_area of the edges of its rings alone
 * (box[i] == 1 + k of the m rings listed, ring[i] and first[i] their
 * numbers and first points), in the edges' room e.  A ring's winding
 * number is 0 outside its box, so the box's pixels see its rings only
 * (docs/coverage.md, the parts by boxes). */
static inline rast_status rast__cov_box_area(const rast_polygon *poly, const uint32_t *ring, const uint32_t *first,
                                             const unsigned char *box, uint32_t m, int32_t k, int32_t s,
                                             rast_fill_rule rule, const rast__cov_out *ob, rast__cedge *e,
                                             rast__arena a)
{
    uint32_t i, n = 0;
    for (i = 0; i < m; i++)
        if (box[i] == (unsigned char)(k + 1)) {
            rast_polygon one;
            one.points = poly->points + first[i];
            one.ring_sizes = poly->ring_sizes + ring[i];
            one.nrings = 1;
            n += rast__cov_edges_polygon(&one, e + n);
        }
    return rast__cov_area(e, n, s, rule, 0, ob, &a);
}

/* rast__cov_by_boxes into a painter: the rings in boxes (ring[0 .. m),
 * their first points first[], their boxes box[], 1 + k in box k) listed
 * at the end of the edges' room, the boxes bx[0 .. nb).  The boxes'
 * levels (U8, box after box) and a row of the clip's width go in the
 * edges' room below those lists, above both what the accumulation of the
 * other rings takes there (a rast__cedge a point of theirs) and what each
 * box's edges take while its levels are found (a rast__cedge a point of
 * its rings): 0 (declined, nothing handed on) when they do not fit. */
static int rast__cov_boxes_paint(const rast_polygon *poly, uint32_t npoints, int32_t s, rast_fill_rule rule,
                                 const rast__cov_out *o, rast__cedge *e, rast__arena arena, const uint32_t *ring,
                                 const uint32_t *first, const unsigned char *box, uint32_t m, const int32_t *bx,
                                 int32_t nb, rast_status *st)
{
    int32_t bc[5 * RAST__COV_BOXES], k;
    uint32_t i, pin = 0, pk[RAST__COV_BOXES], most;
    size_t lvn = 0, need;
    unsigned char *lv, *low;
    rast__cov_merge g;
    rast__painter wrap;
    rast__cov_out ow;
    rast__arena room;
    g.y0 = INT32_MAX;
    g.y1 = INT32_MIN;
    for (k = 0; k < nb; k++) { /* each box clipped, and its levels' place */
        int32_t *b = bc + 5 * k;
        b[0] = bx[4 * k] > o->clip.x0 ? bx[4 * k] : o->clip.x0;
        b[1] = bx[4 * k + 1] > o->clip.y0 ? bx[4 * k + 1] : o->clip.y0;
        b[2] = bx[4 * k + 2] < o->clip.x1 - 1 ? bx[4 * k + 2] + 1 : o->clip.x1;
        b[3] = bx[4 * k + 3] < o->clip.y1 - 1 ? bx[4 * k + 3] + 1 : o->clip.y1;
        if (b[0] >= b[2] || b[1] >= b[3]) { /* (empty: no row meets it) */
            b[2] = b[0];
            b[3] = b[1];
        }
        b[4] = (int32_t)lvn;
        lvn += (size_t)(b[2] - b[0]) * (size_t)(b[3] - b[1]);
        if (lvn > (size_t)INT32_MAX) return 0;
        if (b[1] < b[3]) {
            g.y0 = b[1] < g.y0 ? b[1] : g.y0;
            g.y1 = b[3] > g.y1 ? b[3] : g.y1;
        }
        pk[k] = 0;
    }
    for (i = 0; i < m; i++) { /* the points in boxes, and in each */
        const uint32_t size = poly->ring_sizes[ring[i]];
        pin += size;
        if (box[i] != RAST__PARTS_NONE) pk[box[i] - 1] += size;
    }
    most = npoints - pin;
    for (k = 0; k < nb; k++) most = pk[k] > most ? pk[k] : most;
    need = rast__align((size_t)(o->clip.x1 - o->clip.x0)) + rast__align(lvn);
    low = (unsigned char *)(void *)(e + most);
    if ((size_t)((const unsigned char *)(const void *)ring - low) < need) return 0;
    g.rb = (unsigned char *)(void *)ring - need; /* (ring: 8-byte aligned, need a multiple of it) */
    lv = g.rb + rast__align((size_t)(o->clip.x1 - o->clip.x0));
    memset(g.rb, 0, need);
    *st = RAST_OK;
    for (k = 0; k < nb && *st == RAST_OK; k++) { /* each box's levels: its rings' exact area */
        rast__cov_out ob = *o;
        const int32_t *b = bc + 5 * k;
        if (b[0] >= b[2]) continue;
        ob.clip.x0 = b[0];
        ob.clip.y0 = b[1];
        ob.clip.x1 = b[2];
        ob.clip.y1 = b[3];
        ob.base = lv + b[4];
        ob.stride = b[2] - b[0];
        ob.format = RAST_COVERAGE_U8;
        ob.paint = NULL;
        *st = rast__cov_box_area(poly, ring, first, box, m, k, s, rule, &ob, e, arena);
    }
    if (*st != RAST_OK) return 1;
    g.real = o->paint;
    g.out = *o;
    g.lv = lv;
    g.bc = bc;
    g.nb = nb;
    g.next = o->clip.y0;
    g.cur = INT32_MIN;
    g.pend = INT32_MIN;
    g.lo = INT32_MAX;
    g.hi = INT32_MIN;
    wrap.full = o->paint->full ? rast__cov_merge_full : NULL; /* (the same runs as the real painter's) */
    wrap.levels = rast__cov_merge_levels;
    wrap.user = &g;
    wrap.bytes = NULL;
    wrap.stride = 0;
    wrap.value = 0;
    ow = *o;
    ow.paint = &wrap;
    room = arena;
    *st = rast__cov_acc_points(poly, ring, m, NULL, 0, 0, s, rule, &ow, e, &room);
    if (*st == RAST_OK) rast__cov_merge_to(&g, o->clip.y1);
    return 1;
}

static int rast__cov_by_boxes(const rast_polygon *poly, uint32_t npoints, int32_t s, rast_fill_rule rule,
                              const rast__cov_out *o, rast__cedge *e, rast__arena arena, rast_status *st)
{
    static const int32_t size[3] = {1, 2, 8};
    const uint32_t nr = poly->nrings;
    int32_t bx[4 * RAST__COV_BOXES], nb, k;
    rast__arena room = arena;
    unsigned char *in;
    uint32_t *ring, *first, r, base, m = 0, i;
    unsigned char *box;
    if (!rast__take(&room, RAST__COV_RING_ROWS(nr))) return 0; /* (the table kept) */
    in = (unsigned char *)rast__take(&room, nr);
    if (!in || (nb = rast__cov_parts_boxes(arena, nr, in, bx, RAST__COV_BOXES)) < 0) return 0;
    /* the rings in boxes (and those with nothing to draw), in order: their
     * numbers, first points and boxes, at the end of the edges' room (a
     * rast__cedge a point), past what the accumulation of the others
     * takes (a rast__cedge an edge, and the rings in boxes hold as many
     * edges as it at most: rast__cov_parts_boxes) and the boxes' edges */
    for (r = 0; r < nr; r++) m += in[r] != 0;
    ring = (uint32_t *)(void *)((unsigned char *)(void *)(e + npoints) - (size_t)m * 2 * sizeof(uint32_t) -
                                (((size_t)m + 7) & ~(size_t)7));
    first = ring + m;
    box = (unsigned char *)(void *)(first + m);
    for (r = 0, base = 0, i = 0; r < nr; base += poly->ring_sizes[r], r++)
        if (in[r]) {
            ring[i] = r;
            first[i] = base;
            box[i++] = in[r];
        }
    if (o->paint) return rast__cov_boxes_paint(poly, npoints, s, rule, o, e, arena, ring, first, box, m, bx, nb, st);
    room = arena; /* (the table and in[] read: all the room the accumulation's) */
    *st = rast__cov_acc_points(poly, ring, m, NULL, 0, 0, s, rule, o, e, &room);
    for (k = 0; k < nb && *st == RAST_OK; k++) { /* each box: its rings' exact area, its pixels only */
        rast__cov_out ob = *o;
        ob.clip.x0 = bx[4 * k] > o->clip.x0 ? bx[4 * k] : o->clip.x0;
        ob.clip.y0 = bx[4 * k + 1] > o->clip.y0 ? bx[4 * k + 1] : o->clip.y0;
        ob.clip.x1 = bx[4 * k + 2] < o->clip.x1 - 1 ? bx[4 * k + 2] + 1 : o->clip.x1;
        ob.clip.y1 = bx[4 * k + 3] < o->clip.y1 - 1 ? bx[4 * k + 3] + 1 : o->clip.y1;
        if (ob.clip.x0 >= ob.clip.x1 || ob.clip.y0 >= ob.clip.y1) continue;
        ob.base = o->base + (ptrdiff_t)(ob.clip.y0 - o->clip.y0) * o->stride +
                  (ptrdiff_t)(ob.clip.x0 - o->clip.x0) * size[o->format];
        *st = rast__cov_box_area(poly, ring, first, box, m, k, s, rule, &ob, e, arena);
    }
    return 1;
}
#endif

/* Does "accumulate" drop the shared sides first (rast__cov_acc_shared)?
 * For a triangle batch, and a polygon of 16 rings or more of 8 vertices
 * or fewer on the mean (a mesh's). */
#define RAST__COV_SHARED(poly, tris, npoints) \
    ((tris) || ((poly)->nrings >= 16 && (uint64_t)(poly)->nrings * 8 >= (npoints)))

static rast_status rast__cov_run(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                                 uint32_t npoints, const rast_coverage_opts *opts,
                                 const rast__cov_out *o, void *scratch, size_t scratch_bytes)
{
    rast__arena arena;
    int32_t kb = rast__aa_kbits(opts->method), s = opts->subpixel_bits;
    rast_fill_rule rule = tris ? RAST_RULE_NONZERO : opts->rule;
    if (o->clip.x0 >= o->clip.x1 || o->clip.y0 >= o->clip.y1) return RAST_OK;
    arena.p = (unsigned char *)scratch;
    arena.left = scratch_bytes;
    if (!rast__take(&arena, (size_t)(o->clip.x1 - o->clip.x0))) return RAST_E_SCRATCH; /* the row */
    if (!kb) {
        rast__cedge *e = (rast__cedge *)rast__take(&arena, (size_t)npoints * sizeof(rast__cedge));
        uint32_t n;
#if !defined(__OPTIMIZE_SIZE__)
        int parts = 0; /* rast__cov_parts_test's answer, when asked */
        int convex = -1; /* rast__cov_convex's answer, when asked */
#endif
        if (npoints && !e) return RAST_E_SCRATCH;
#if !defined(__OPTIMIZE_SIZE__)
        /* one small convex ring painted (a tiny polygon a call): its
         * levels without the engines' setup (coverage_small.c), unless
         * one is too near a tie for its 64 bits */
        if (poly && o->paint) {
            rast_rect box;
            if (rast__cov_small_fits(poly, s, &box)) {
                const int turn = rast__cov_convex(poly);
                if (turn && rast__cov_small(poly, s, turn, o, &box)) return RAST_OK;
                convex = turn != 0;
            }
        }
        /* "accumulate": its walk's records straight from the vertices
         * (coverage_acc.c), the same edges and levels as below */
        if (RAST__IS_ACC(opts->method) && rast__cov_acc_may(o, s))
            return rast__cov_acc_points(poly, NULL, 0, tris, ntris,
                                        RAST__COV_SHARED(poly, tris, npoints) ? 1
                                        : poly->nrings >= 2 ? RAST__ACC_LOOK /* (a map's borders?) */
                                                            : 0,
                                        s, rule, o, e, &arena);
        /* "area" of a polygon that is plain (coverage_plain.c: there the
         * accumulation is the coverage), found from its points alone: its
         * accumulation, from them too; the test where the whole polygon's
         * does not pay (short edges: text, a row or two each), part by part
         * (coverage_plain.c), whose cost is about linear in the vertices:
         * -1 when only some parts are plain, whose edges are marked below
         * for rast__cov_area_marked's bands (a polygon of several rings) */
        if (!tris && rast__cov_acc_may(o, s) &&
            ((convex >= 0 ? convex : rast__cov_convex(poly)) ||
             (rast__cov_plain_pays(poly, e, 0, s, npoints) ? rast__cov_plain(poly, npoints, arena)
                                                    : poly->nrings >= 2 &&
                                                          (parts = rast__cov_parts_test(poly, npoints, arena, s)) > 0)))
            return rast__cov_acc_points(poly, NULL, 0, NULL, 0, 0, s, rule, o, e, &arena);
        /* some parts not plain: those parts' boxes apart (an array) */
        if (parts < 0) {
            rast_status st;
            if (rast__cov_by_boxes(poly, npoints, s, rule, o, e, arena, &st)) return st;
        }
        /* rings that share their borders (a map): the polygon without its
         * equal and opposite edges (the same winding number), when plain,
         * by its accumulation (coverage_plain.c, rast__cov_borders) */
        if (!tris && !parts && poly->nrings >= 2 && rast__cov_acc_may(o, s)) {
            rast__arena room = arena;
            rast_polygon kept;
            if (rast__cov_borders(poly, npoints, &room, &kept))
                return rast__cov_acc_points(&kept, NULL, 0, NULL, 0, 0, s, rule, o, e, &room);
        }
#endif
        n = tris ? rast__cov_edges_triangles(tris, ntris, e) : rast__cov_edges_polygon(poly, e);
#if !defined(__OPTIMIZE_SIZE__)
        /* (some parts plain, their edges marked: "area" only) */
        if (parts < 0 && rast__cov_parts_mark(arena, poly->nrings, e, n, RAST__HZ_BAD) < 0)
            return rast__cov_area_marked(e, n, poly->nrings, s, rule, o, &arena);
#else
        /* a triangle batch's shared edges cancel in rast__cov_area's sweep
         * before any row; a polygon's accumulation goes to rast__cov_acc,
         * and so does "area" of a plain polygon (coverage_plain.c: there
         * the accumulation is the coverage) */
        if (!tris && rast__cov_acc_may(o, s) &&
            (RAST__IS_ACC(opts->method) ||
             (rast__cov_plain_pays(poly, e, n, s, npoints) && rast__cov_plain(poly, npoints, arena))))
            /* (16 rings or more of 8 vertices or fewer on the mean: a
             * mesh's, whose shared sides cancel first) */
            return RAST__IS_ACC(opts->method) && RAST__COV_SHARED(poly, tris, npoints)
                       ? rast__cov_acc_shared(e, n, s, rule, o, &arena)
                       : rast__cov_acc(e, n, s, rule, o, &arena);
        /* a triangle batch's accumulation: its shared sides cancel first */
        if (tris && RAST__IS_ACC(opts->method) && rast__cov_acc_may(o, s))
            return rast__cov_acc_shared(e, n, s, rule, o, &arena);
#endif
        return rast__cov_area(e, n, s, rule, RAST__IS_ACC(opts->method), o, &arena);
    } else {
        int32_t scale = s < kb ? kb - s : 0;
#if !defined(__OPTIMIZE_SIZE__)
        /* "ss2", "ss4" of one small convex ring painted: its samples'
         * spans straight from the vertices (coverage_small.c) */
        rast_rect box;
        if (poly && o->paint && kb <= 2 && s > kb && rast__cov_small_fits(poly, s, &box) && rast__cov_convex(poly)) {
            rast__cov_small_ss(poly, s, kb, opts->sample, o, &box);
            return RAST_OK;
        }
#endif
        rast_point *q = (rast_point *)rast__take(&arena, (size_t)npoints * sizeof(rast_point));
        uint32_t *sizes = (uint32_t *)rast__take(&arena, (size_t)npoints * sizeof(uint32_t));
        rast_polygon fine;
        if (npoints && (!q || !sizes)) return RAST_E_SCRATCH;
        if (tris) {
            uint32_t k, m = 0;
            for (k = 0; k < ntris; k++)
                if (rast__cov_tri(&tris[3 * k], &q[3 * m])) m++;
            rast__cov_scale(q, 3 * m, scale, q);
            return rast__cov_ss_tris(q, m, s < kb ? 0 : s - kb, kb, opts->sample, o, &arena);
        } else {
            rast__cov_scale(poly->points, npoints, scale, q);
            fine.nrings = poly->nrings;
        }
        fine.points = q;
        fine.ring_sizes = tris ? sizes : poly->ring_sizes;
        return rast__cov_ss(&fine, npoints, s < kb ? 0 : s - kb, kb, rule, opts->sample, o, &arena);
    }
}

/* The polygon's vertices, counted and its pointers checked. */
static rast_status rast__cov_count(const rast_polygon *polygon, uint32_t *npoints)
{
    uint64_t n = 0;
    uint32_t k;
    if (polygon->nrings > 0 && !polygon->ring_sizes) return RAST_E_NULL;
    for (k = 0; k < polygon->nrings; k++) {
        n += polygon->ring_sizes[k];
        if (n > RAST_MAX_POINTS) return RAST_E_TOO_MANY;
    }
    if (n > 0 && !polygon->points) return RAST_E_NULL;
    *npoints = (uint32_t)n;
    return RAST_OK;
}

/* What every entry point does once its geometry is counted: options,
 * output and scratch checked (rast__cov_begin), the vertices checked,
 * then the method run.  `paint` not NULL: the levels go to it, row by
 * row, through a row buffer at the scratch's start (rast__cov_run skips
 * it). */
static rast_status rast__cov_check(const rast_polygon *poly, const rast_point *tris, uint32_t n,
                                   const rast_coverage_opts *opts, const rast_rect *clip,
                                   rast_coverage_format format, void *out, ptrdiff_t stride,
                                   int paint, void *scratch, size_t scratch_bytes,
                                   rast__cov_out *o, int32_t rows)
{
    int32_t kb;
    rast_status st = rast__cov_begin(opts, clip, paint ? RAST_COVERAGE_U8 : format, out, stride, n,
                                     scratch, scratch_bytes, o, paint, rows);
    if (st != RAST_OK) return st;
    kb = rast__aa_kbits(opts->method);
    return rast__cov_check_points(poly ? poly->points : tris, n,
                                  kb > opts->subpixel_bits ? kb - opts->subpixel_bits : 0);
}

/* The method run into *o (checked), or into painter `paint`. */
static rast_status rast__cov_go(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                                uint32_t n, const rast_coverage_opts *opts, rast__cov_out *o,
                                const rast__painter *paint, void *scratch, size_t scratch_bytes)
{
    static const rast_point none[3] = {{0, 0}, {0, 0}, {0, 0}};
    if (paint) {
        o->base = (unsigned char *)scratch;
        o->stride = 0;
        o->paint = paint;
    }
    if (!poly && !ntris) tris = none;
    return rast__cov_run(poly, tris, ntris, n, opts, o, scratch, scratch_bytes);
}

static rast_status rast__cov_entry(const rast_polygon *poly, const rast_point *tris,
                                   uint32_t ntris, uint32_t n, const rast_coverage_opts *opts,
                                   const rast_rect *clip, rast_coverage_format format, void *out,
                                   ptrdiff_t stride, const rast__painter *paint, void *scratch,
                                   size_t scratch_bytes)
{
    rast__cov_out o;
    rast_status st = rast__cov_check(poly, tris, n, opts, clip, format, out, stride, paint != NULL,
                                     scratch, scratch_bytes, &o, INT32_MAX);
    if (st != RAST_OK) return st;
    return rast__cov_go(poly, tris, ntris, n, opts, &o, paint, scratch, scratch_bytes);
}

rast_status rast_polygon_coverage(const rast_polygon *polygon, const rast_coverage_opts *opts,
                                  const rast_rect *clip, rast_coverage_format format, void *out,
                                  ptrdiff_t stride, void *scratch, size_t scratch_bytes)
{
    uint32_t n = 0;
    rast_status st;
    if (!polygon) return RAST_E_NULL;
    st = rast__cov_count(polygon, &n);
    if (st != RAST_OK) return st;
    return rast__cov_entry(polygon, NULL, 0, n, opts, clip, format, out, stride, NULL, scratch,
                           scratch_bytes);
}

rast_status rast_triangles_coverage(const rast_point *tris, uint32_t ntris,
                                    const rast_coverage_opts *opts, const rast_rect *clip,
                                    rast_coverage_format format, void *out, ptrdiff_t stride,
                                    void *scratch, size_t scratch_bytes)
{
    if (ntris > RAST_MAX_POINTS / 3) return RAST_E_TOO_MANY;
    if (ntris > 0 && !tris) return RAST_E_NULL;
    return rast__cov_entry(NULL, tris, ntris, 3 * ntris, opts, clip, format, out, stride, NULL,
                           scratch, scratch_bytes);
}

/* The checks of the painting entry points (geometry counted, then
 * rast__cov_check), *o set up for the clip. */
static rast_status rast__cov_paint_prepare(const rast_polygon *poly, const rast_point *tris,
                                           uint32_t ntris, const rast_coverage_opts *opts,
                                           const rast_rect *clip, int32_t rows, void *scratch,
                                           size_t scratch_bytes, uint32_t *npoints,
                                           rast__cov_out *o)
{
    rast_status st;
    if (poly) {
        st = rast__cov_count(poly, npoints);
        if (st != RAST_OK) return st;
    } else {
        if (ntris > RAST_MAX_POINTS / 3) return RAST_E_TOO_MANY;
        if (ntris > 0 && !tris) return RAST_E_NULL;
        *npoints = 3 * ntris;
    }
    return rast__cov_check(poly, tris, *npoints, opts, clip, RAST_COVERAGE_U8, NULL, 0, 1, scratch,
                           scratch_bytes, o, rows);
}

rast_status rast__cov_paint_check(const rast_polygon *poly, const rast_point *tris,
                                  uint32_t ntris, const rast_coverage_opts *opts,
                                  const rast_rect *clip, int32_t rows, void *scratch,
                                  size_t scratch_bytes, uint32_t *npoints)
{
    rast__cov_out o;
    return rast__cov_paint_prepare(poly, tris, ntris, opts, clip, rows, scratch, scratch_bytes,
                                   npoints, &o);
}

rast_status rast__cov_paint_checked(const rast_polygon *poly, const rast_point *tris,
                                    uint32_t ntris, uint32_t npoints,
                                    const rast_coverage_opts *opts, const rast_rect *clip,
                                    const rast__painter *p, void *scratch, size_t scratch_bytes)
{
    rast__cov_out o;
    o.clip = *clip;
    o.format = RAST_COVERAGE_U8;
    return rast__cov_go(poly, tris, ntris, npoints, opts, &o, p, scratch, scratch_bytes);
}

rast_status rast__cov_paint(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                            const rast_coverage_opts *opts, const rast_rect *clip,
                            const rast__painter *p, void *scratch, size_t scratch_bytes)
{
    rast__cov_out o;
    uint32_t n = 0;
    rast_status st = rast__cov_paint_prepare(poly, tris, ntris, opts, clip, INT32_MAX, scratch,
                                             scratch_bytes, &n, &o);
    if (st != RAST_OK) return st;
    return rast__cov_go(poly, tris, ntris, n, opts, &o, p, scratch, scratch_bytes);
}

#if !defined(__OPTIMIZE_SIZE__)
/* (painters/paint.h.)  The checks it skips were ~350 instructions of a
 * tiny polygon's "accumulate" call from Python, 2.4% (issue 33). */
rast_status rast__cov_paint_snapped(const rast_polygon *poly, const rast_point *tris, uint32_t ntris,
                                    const rast_coverage_opts *opts, const rast_rect *clip,
                                    const rast__painter *p, void *scratch, size_t scratch_bytes)
{
    const int32_t kb = rast__aa_kbits(opts->method);
    uint32_t n = 0;
    rast_status st;
    if (!poly) return rast__cov_paint(poly, tris, ntris, opts, clip, p, scratch, scratch_bytes);
    st = rast__cov_count(poly, &n);
    if (st != RAST_OK) return st;
    /* a supersampling method's own checks, in rast__cov_begin's and
     * rast__cov_check's order: its fine grid's clip, then its points'
     * narrower range */
    if (!rast__cov_fine_fits(clip, kb)) return RAST_E_SIZE;
    if (kb > opts->subpixel_bits && (st = rast__cov_check_points(poly->points, n, kb - opts->subpixel_bits)) != RAST_OK)
        return st;
    return rast__cov_paint_checked(poly, NULL, 0, n, opts, clip, p, scratch, scratch_bytes);
}
#endif

rast_status rast_polygon_coverage_spans(const rast_polygon *polygon,
                                        const rast_coverage_opts *opts, const rast_rect *clip,
                                        rast_coverage_span_fn span, void *user, void *scratch,
                                        size_t scratch_bytes)
{
    rast__user_spans u;
    rast__painter p;
    if (!polygon || !span || !clip) return RAST_E_NULL;
    rast__user_painter(&u, NULL, span, user, &p);
    return rast__cov_paint(polygon, NULL, 0, opts, clip, &p, scratch, scratch_bytes);
}

rast_status rast_triangles_coverage_spans(const rast_point *tris, uint32_t ntris,
                                          const rast_coverage_opts *opts, const rast_rect *clip,
                                          rast_coverage_span_fn span, void *user, void *scratch,
                                          size_t scratch_bytes)
{
    rast__user_spans u;
    rast__painter p;
    if (!span || !clip) return RAST_E_NULL;
    rast__user_painter(&u, NULL, span, user, &p);
    return rast__cov_paint(NULL, tris, ntris, opts, clip, &p, scratch, scratch_bytes);
}

/* batch.c - glue: burn npolys polygons into one array in one C call.
 *
 * Polygon k is poly_rings[k] consecutive rings of ring_sizes (and their
 * points, consecutive in xy).  Each pixel polygon k owns (the exact rule
 * with opts, rast_fill_polygons_spans) gets values[k] (of the array's
 * dtype; NULL: 1), replaced or added, in the order of the polygons.  The
 * pixel (y, x) of polygon k is at out + k * plane_stride + y * row_stride +
 * x * itemsize (plane_stride 0: all polygons into one plane; the size of a
 * plane: one mask per polygon).
 *
 * rastpy_burn_polygons64 is the same with the points snapped to int64
 * (rastpy_snap64, S up to 32, +-2^28 pixels) and drawn by
 * rast_fill_polygons64_spans (algorithm aet; exact or conservative
 * boundary; else RAST_E_WIDE).
 *
 * Returns 0; k + 1 when point k is bad (NaN, infinite or out of range
 * after snapping, see rastpy_snap); a negative rast_status, with *failed
 * the polygon it belongs to when it is one polygon's; RASTPY_E_NOMEM.
 * Nothing is written to out unless the call succeeds. */
#include <stdlib.h>
#include <string.h>
#include "batch.h"
#include "gdalline.h"
#include "wide.h"

typedef struct rastpy_burn {
    unsigned char *out;
    int64_t row_stride, plane_stride;
    int32_t x0, y0; /* the window's origin: span (y, x) is at out's row y - y0, column x - x0 */
    const unsigned char *values; /* NULL: 1 */
    void (*put)(const struct rastpy_burn *b, unsigned char *row, uint32_t k, int32_t x0,
                int32_t x1);
} rastpy_burn;

/* One span writer per element type and merge rule.  The value is read
 * with memcpy (values need not be aligned); the rows are aligned, as numpy
 * arrays of the type are.  Four elements a step through a pointer: the
 * compiler makes the four stores one vector store (with an int index,
 * -fwrapv, which Python's flags add, hides that x + 1 is the next
 * element). */
#define RASTPY_PUTS(NAME, T)                                                                 \
    static T rastpy_value_##NAME(const rastpy_burn *b, uint32_t k)                          \
    {                                                                                        \
        T v = (T)1;                                                                          \
        if (b->values) memcpy(&v, b->values + (size_t)k * sizeof(T), sizeof(T));             \
        return v;                                                                            \
    }                                                                                        \
    static inline void rastpy_replace_##NAME(const rastpy_burn *b, unsigned char *row, uint32_t k, \
                                      int32_t x0, int32_t x1)                                \
    {                                                                                        \
        T *p = (T *)(void *)row, v = rastpy_value_##NAME(b, k);                              \
        T *q = p + x0, *end = p + x1;                                                        \
        if (sizeof(T) == 1) { /* bytes: the library memset (see rast__sink's direct) */      \
            unsigned char c;                                                                 \
            memcpy(&c, &v, 1);                                                               \
            memset(q, c, (size_t)(end - q));                                                 \
            return;                                                                          \
        }                                                                                    \
        if (end - q < 4) {                                                                   \
            for (; q < end; q++) *q = v;                                                     \
            return;                                                                          \
        }                                                                                    \
        for (; end - q > 4; q += 4) {                                                        \
            q[0] = v;                                                                        \
            q[1] = v;                                                                        \
            q[2] = v;                                                                        \
            q[3] = v;                                                                        \
        }                                                                                    \
        /* the last 1..4 elements as one group of four, ending at `end`                   \
         * (overlapping the group before: a replace may write twice) */                     \
        q = end - 4;                                                                         \
        q[0] = v;                                                                            \
        q[1] = v;                                                                            \
        q[2] = v;                                                                            \
        q[3] = v;                                                                            \
    }                                                                                        \
    static inline void rastpy_add_##NAME(const rastpy_burn *b, unsigned char *row, uint32_t k, \
                                  int32_t x0, int32_t x1)                                    \
    {                                                                                        \
        T *p = (T *)(void *)row, v = rastpy_value_##NAME(b, k);                              \
        T *q = p + x0, *end = p + x1;                                                        \
        for (; end - q >= 4; q += 4) {                                                       \
            q[0] = RASTPY_ADD_##NAME(q[0], v);                                               \
            q[1] = RASTPY_ADD_##NAME(q[1], v);                                               \
            q[2] = RASTPY_ADD_##NAME(q[2], v);                                               \
            q[3] = RASTPY_ADD_##NAME(q[3], v);                                               \
        }                                                                                    \
        for (; q < end; q++) *q = RASTPY_ADD_##NAME(*q, v);                                  \
    }                                                                                        \
    static void rastpy_addsat_##NAME(const rastpy_burn *b, unsigned char *row, uint32_t k,   \
                                     int32_t x0, int32_t x1)                                 \
    {                                                                                        \
        T *p = (T *)(void *)row, v = rastpy_value_##NAME(b, k);                              \
        int32_t x;                                                                           \
        for (x = x0; x < x1; x++) p[x] = RASTPY_SAT_##NAME(p[x], v);                         \
    }                                                                                        \
    RASTPY_SPAN(replace, NAME)                                                               \
    RASTPY_SPAN(add, NAME)                                                                   \
    RASTPY_SPAN(addsat, NAME)

/* The batch's span callback for one writer: the row found and the writer
 * inlined, so that a span costs the core's one indirect call (through a
 * generic callback and then `put`, it cost two: a tenth of a labels batch
 * of 10,000 small instances). */
#define RASTPY_SPAN(MERGE, NAME)                                                             \
    static void rastpy_span_##MERGE##_##NAME(void *user, uint32_t k, int32_t y, int32_t x0,  \
                                             int32_t x1)                                     \
    {                                                                                        \
        const rastpy_burn *b = (const rastpy_burn *)user;                                    \
        rastpy_##MERGE##_##NAME(                                                             \
            b, b->out + (int64_t)k * b->plane_stride + (int64_t)(y - b->y0) * b->row_stride, \
            k, x0 - b->x0, x1 - b->x0);                                                      \
    }

/* Integer adds wrap (through the unsigned type of the same width, where
 * overflow is defined); float adds are IEEE. */
#define RASTPY_ADD_u8(a, b) (uint8_t)((a) + (b))
#define RASTPY_ADD_i8(a, b) (int8_t)(uint8_t)((uint8_t)(a) + (uint8_t)(b))
#define RASTPY_ADD_u16(a, b) (uint16_t)((a) + (b))
#define RASTPY_ADD_i16(a, b) (int16_t)(uint16_t)((uint16_t)(a) + (uint16_t)(b))
#define RASTPY_ADD_u32(a, b) (uint32_t)((a) + (b))
#define RASTPY_ADD_i32(a, b) (int32_t)((uint32_t)(a) + (uint32_t)(b))
#define RASTPY_ADD_i64(a, b) (int64_t)((uint64_t)(a) + (uint64_t)(b))
#define RASTPY_ADD_u64(a, b) (uint64_t)((a) + (b))
#define RASTPY_ADD_f32(a, b) (float)((a) + (b))
#define RASTPY_ADD_f64(a, b) ((a) + (b))

/* Saturating adds (RASTPY_MERGE_ADD_SAT): the exact sum clamped to the
 * type's range; types narrower than 64 bits sum in int64_t, the 64-bit
 * ones compare with the room left first. */
#define RASTPY_CLAMP(s, lo, hi) ((s) < (lo) ? (lo) : (s) > (hi) ? (hi) : (s))
#define RASTPY_SAT_u8(a, b) (uint8_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), 0, 255)
#define RASTPY_SAT_i8(a, b) (int8_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), -128, 127)
#define RASTPY_SAT_u16(a, b) (uint16_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), 0, 65535)
#define RASTPY_SAT_i16(a, b) (int16_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), -32768, 32767)
#define RASTPY_SAT_u32(a, b) (uint32_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), 0, (int64_t)UINT32_MAX)
#define RASTPY_SAT_i32(a, b) (int32_t)RASTPY_CLAMP((int64_t)(a) + (int64_t)(b), INT32_MIN, INT32_MAX)
#define RASTPY_SAT_i64(a, b)                                             \
    ((b) > 0 && (a) > INT64_MAX - (b)   ? INT64_MAX                      \
     : (b) < 0 && (a) < INT64_MIN - (b) ? INT64_MIN                      \
                                        : (a) + (b))
#define RASTPY_SAT_u64(a, b) ((uint64_t)((a) + (b)) < (a) ? UINT64_MAX : (uint64_t)((a) + (b)))
#define RASTPY_SAT_f32(a, b) (float)((a) + (b))
#define RASTPY_SAT_f64(a, b) ((a) + (b))

RASTPY_PUTS(u8, uint8_t)
RASTPY_PUTS(i8, int8_t)
RASTPY_PUTS(u16, uint16_t)
RASTPY_PUTS(i16, int16_t)
RASTPY_PUTS(u32, uint32_t)
RASTPY_PUTS(i32, int32_t)
RASTPY_PUTS(i64, int64_t)
RASTPY_PUTS(u64, uint64_t)
RASTPY_PUTS(f32, float)
RASTPY_PUTS(f64, double)

typedef void (*rastpy_put_fn)(const rastpy_burn *, unsigned char *, uint32_t, int32_t, int32_t);

/* RASTPY_MERGE_FRESH: the planes as one run of bytes, written up to `at`
 * (every byte before it is final).  A span past `at` clears the gap and
 * sets its own bytes; a span behind it (the spans come in order from the
 * fillers of the batch, but nothing here relies on it) sets its bytes,
 * which is what it would do to a cleared array. */
typedef struct rastpy_fresh {
    rastpy_burn b;
    size_t at;
} rastpy_fresh;

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
/* Clear n bytes at p: the whole 64-byte lines of a long gap with
 * non-temporal stores (SSE2), as the C library clears a large calloc'd
 * block: a mask's planes are far larger than the cache, and ordinary
 * stores would read every line before writing it. */
static void rastpy_clear(unsigned char *p, size_t n)
{
#if defined(__SSE2__)
    if (n >= 1024) {
        unsigned char *end = p + n;
        unsigned char *a = (unsigned char *)(((uintptr_t)p + 63) & ~(uintptr_t)63);
        unsigned char *b = (unsigned char *)((uintptr_t)end & ~(uintptr_t)63);
        const __m128i z = _mm_setzero_si128();
        memset(p, 0, (size_t)(a - p));
        for (; a < b; a += 64) {
            _mm_stream_si128((__m128i *)(void *)a, z);
            _mm_stream_si128((__m128i *)(void *)(a + 16), z);
            _mm_stream_si128((__m128i *)(void *)(a + 32), z);
            _mm_stream_si128((__m128i *)(void *)(a + 48), z);
        }
        memset(b, 0, (size_t)(end - b));
        return;
    }
#endif
    memset(p, 0, n);
}

static void rastpy_span_fresh(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    rastpy_fresh *f = (rastpy_fresh *)user;
    size_t start = (size_t)((int64_t)k * f->b.plane_stride + (int64_t)(y - f->b.y0) * f->b.row_stride +
                            (x0 - f->b.x0)),
           end = start + (size_t)(x1 - x0);
    if (start > f->at) rastpy_clear(f->b.out + f->at, start - f->at);
    memset(f->b.out + start, 1, end - start);
    if (end > f->at) f->at = end;
}

/* Indexed by RASTPY_DT_* - 1, then by merge rule. */
#define RASTPY_PUT_ROW(NAME) {rastpy_replace_##NAME, rastpy_add_##NAME, rastpy_addsat_##NAME}
static const rastpy_put_fn rastpy_puts[10][3] = {
    RASTPY_PUT_ROW(u8),  RASTPY_PUT_ROW(i8),  RASTPY_PUT_ROW(u16), RASTPY_PUT_ROW(i16),
    RASTPY_PUT_ROW(u32), RASTPY_PUT_ROW(i32), RASTPY_PUT_ROW(i64), RASTPY_PUT_ROW(u64),
    RASTPY_PUT_ROW(f32), RASTPY_PUT_ROW(f64),
};

/* The same table of span callbacks for the batch. */
#define RASTPY_SPAN_ROW(NAME) {rastpy_span_replace_##NAME, rastpy_span_add_##NAME, rastpy_span_addsat_##NAME}
static const rast_batch_span_fn rastpy_spans[10][3] = {
    RASTPY_SPAN_ROW(u8),  RASTPY_SPAN_ROW(i8),  RASTPY_SPAN_ROW(u16), RASTPY_SPAN_ROW(i16),
    RASTPY_SPAN_ROW(u32), RASTPY_SPAN_ROW(i32), RASTPY_SPAN_ROW(i64), RASTPY_SPAN_ROW(u64),
    RASTPY_SPAN_ROW(f32), RASTPY_SPAN_ROW(f64),
};

/* Snap xy (npoints points) to int32 (wide == 0) or int64 (wide == 1) into
 * a malloc'd *pts and lay npolys polygons (rast_polygon or rast_polygon64)
 * over it in a malloc'd *polys: polygon k is poly_rings[k] consecutive
 * rings of ring_sizes.  Returns 0 (the caller frees both), k + 1 when point
 * k is bad, RAST_E_ARG when the tables disagree, RASTPY_E_NOMEM (nothing
 * to free then). */
static long rastpy_table_any(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                             size_t nrings, const uint32_t *poly_rings, uint32_t npolys, int s,
                             int wide, void **polys_out, void **pts_out)
{
    unsigned char *polys =
        (unsigned char *)malloc((size_t)npolys * (wide ? sizeof(rast_polygon64) : sizeof(rast_polygon)) + 1);
    void *pts = malloc(npoints * (wide ? sizeof(rast_point64) : sizeof(rast_point)) + 1);
    size_t ring = 0, point = 0, r;
    uint32_t k;
    long bad;
    if (!polys || !pts) {
        free(polys);
        free(pts);
        return RASTPY_E_NOMEM;
    }
    bad = wide ? rastpy_snap64(xy, npoints, s, (int64_t *)pts) : rastpy_snap(xy, npoints, s, (int32_t *)pts);
    if (bad >= 0) {
        free(polys);
        free(pts);
        return bad + 1;
    }
    for (k = 0; k < npolys; k++) {
        size_t n = 0;
        if (wide) {
            rast_polygon64 *p = (rast_polygon64 *)(void *)polys + k;
            p->points = (const rast_point64 *)pts + point;
            p->ring_sizes = ring_sizes + ring;
            p->nrings = poly_rings[k];
        } else {
            rast_polygon *p = (rast_polygon *)(void *)polys + k;
            p->points = (const rast_point *)pts + point;
            p->ring_sizes = ring_sizes + ring;
            p->nrings = poly_rings[k];
        }
        if (poly_rings[k] > nrings - ring) break;
        for (r = 0; r < poly_rings[k]; r++) n += ring_sizes[ring + r];
        if (n > npoints - point) break;
        ring += poly_rings[k];
        point += n;
    }
    if (k < npolys || ring != nrings || point != npoints) { /* the tables disagree */
        free(polys);
        free(pts);
        return RAST_E_ARG;
    }
    *polys_out = polys;
    *pts_out = pts;
    return 0;
}

/* The 32-bit table, for the glue's other files (coco.c). */
long rastpy_polygon_table(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys, int s,
                          rast_polygon **polys_out, int32_t **pts_out)
{
    void *polys, *pts;
    long st = rastpy_table_any(xy, npoints, ring_sizes, nrings, poly_rings, npolys, s, 0, &polys, &pts);
    if (st == 0) {
        *polys_out = (rast_polygon *)polys;
        *pts_out = (int32_t *)pts;
    }
    return st;
}

/* Twice the signed area of snapped ring p[0..n), exactly where the
 * compiler has a 128-bit integer (products of coordinates below 2^27 reach
 * 2^55; their sum over 2^24 points 2^79), else in double. */
#if defined(__SIZEOF_INT128__)
__extension__ typedef __int128 rastpy_wide;
#else
typedef double rastpy_wide;
#endif
static int rastpy_ring_sign(const int32_t *p, size_t n)
{
    rastpy_wide a = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        size_t j = i + 1 < n ? i + 1 : 0;
        a += (rastpy_wide)((int64_t)p[2 * i] * p[2 * j + 1] - (int64_t)p[2 * j] * p[2 * i + 1]);
    }
    return a > 0 ? 1 : a < 0 ? -1 : 0;
}

/* Reverse the rings whose sign of area is not orient[r] (+1 or -1; 0:
 * leave it): after this, non-zero winding gives the union of the +1 rings
 * less the -1 rings (outer rings and their holes). */
static void rastpy_orient(int32_t *pts, const uint32_t *ring_sizes, size_t nrings,
                          const int8_t *orient)
{
    size_t r, at = 0;
    for (r = 0; r < nrings; at += ring_sizes[r], r++) {
        int32_t *p = pts + 2 * at;
        size_t n = ring_sizes[r], i;
        if (!orient[r] || rastpy_ring_sign(p, n) != -orient[r]) continue;
        for (i = 0; i < n / 2; i++) {
            int32_t x = p[2 * i], y = p[2 * i + 1];
            p[2 * i] = p[2 * (n - 1 - i)];
            p[2 * i + 1] = p[2 * (n - 1 - i) + 1];
            p[2 * (n - 1 - i)] = x;
            p[2 * (n - 1 - i) + 1] = y;
        }
    }
}

/* The exact scratch of a batch (rast_polygons_scratch_size and its 64-bit
 * twin). */
static rast_status rastpy_batch_need(const void *polys, uint32_t npolys, const rast_fill_opts *opts,
                                     const rast_rect *clip, int wide, size_t *need, uint32_t *failed)
{
    return wide ? rast_polygons64_scratch_size((const rast_polygon64 *)polys, npolys, opts, clip,
                                               need, failed)
                : rast_polygons_scratch_size((const rast_polygon *)polys, npolys, opts, clip, need,
                                             failed);
}

/* Every burn: the points snapped to int32 (rast_polygon, wide == 0) or to
 * int64 (rast_polygon64, wide == 1), the same tables, the same spans; with
 * `orient` (32-bit only), the rings turned first (rastpy_orient).  out is
 * the window of rows y0 .. y0 + height - 1, columns x0 .. x0 + width - 1
 * of the plane the points live in (the clip). */
static long rastpy_burn_any(void *out, int32_t y0, int32_t x0, int32_t height, int32_t width,
                            int64_t row_stride,
                            int64_t plane_stride, int dtype, int merge, const void *values,
                            const double *xy, size_t npoints, const uint32_t *ring_sizes,
                            size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                            const rast_fill_opts *opts, uint32_t *failed, int wide,
                            const int8_t *orient)
{
    void *polys, *pts, *scratch;
    rast_rect clip;
    rastpy_fresh f;
    rastpy_burn *b = &f.b;
    size_t need = 0;
    long bad;
    rast_status st;

    if (dtype < RASTPY_DT_U8 || dtype > RASTPY_DT_F64 || merge < RASTPY_MERGE_REPLACE ||
        merge > RASTPY_MERGE_FRESH || (orient && wide))
        return RAST_E_ARG;
    if (merge == RASTPY_MERGE_FRESH &&
        (dtype != RASTPY_DT_U8 || values || (height > 1 && row_stride != width) ||
         (npolys > 1 && plane_stride != (int64_t)height * width)))
        return RAST_E_ARG;
    if (height < 0 || width < 0 || y0 < -RAST_MAX_DIM || y0 > RAST_MAX_DIM - height ||
        x0 < -RAST_MAX_DIM || x0 > RAST_MAX_DIM - width)
        return RAST_E_SIZE;
    bad = rastpy_table_any(xy, npoints, ring_sizes, nrings, poly_rings, npolys,
                           opts ? opts->subpixel_bits : 0, wide, &polys, &pts);
    if (bad) return bad;
    if (orient) rastpy_orient((int32_t *)pts, ring_sizes, nrings, orient);
    clip.x0 = x0;
    clip.y0 = y0;
    clip.x1 = x0 + width;
    clip.y1 = y0 + height;
    if (!wide && opts && opts->algorithm == RAST_ALGO_AET && opts->boundary == RAST_BOUNDARY_EXACT) {
        /* The AET's published bound for the largest polygon and the
         * window's rows, instead of a pass that measures every polygon
         * (the fill checks them all anyway; should the bound ever fall
         * short, the fill says so before drawing and the exact size is
         * asked for below). */
        size_t most = 0, ring = 0;
        uint32_t k, r;
        for (k = 0; k < npolys; k++) {
            size_t n = 0;
            for (r = 0; r < poly_rings[k]; r++) n += ring_sizes[ring++];
            if (n > most) most = n;
        }
        need = RAST_AET_SCRATCH_BOUND(most, height);
        st = RAST_OK;
    } else {
        st = rastpy_batch_need(polys, npolys, opts, &clip, wide, &need, failed);
    }
    scratch = st == RAST_OK ? malloc(need + 1) : NULL;
    if (st == RAST_OK && !scratch) st = (rast_status)RASTPY_E_NOMEM;
    if (st == RAST_OK) {
        const rast_batch_span_fn span =
            merge == RASTPY_MERGE_FRESH ? rastpy_span_fresh : rastpy_spans[dtype - 1][merge];
        b->out = (unsigned char *)out;
        b->row_stride = merge == RASTPY_MERGE_FRESH ? width : row_stride;
        b->plane_stride = merge == RASTPY_MERGE_FRESH ? (int64_t)height * width : plane_stride;
        b->x0 = x0;
        b->y0 = y0;
        b->values = (const unsigned char *)values;
        b->put = merge == RASTPY_MERGE_FRESH ? NULL : rastpy_puts[dtype - 1][merge];
        f.at = 0;
        st = wide ? rast_fill_polygons64_spans((const rast_polygon64 *)polys, npolys, opts, &clip,
                                               span, b, scratch, need, failed)
                  : rast_fill_polygons_spans((const rast_polygon *)polys, npolys, opts, &clip, span,
                                             b, scratch, need, failed);
        if (st == RAST_E_SCRATCH) { /* (not reached while the bound holds) */
            free(scratch);
            st = rastpy_batch_need(polys, npolys, opts, &clip, wide, &need, failed);
            scratch = st == RAST_OK ? malloc(need + 1) : NULL;
            if (st == RAST_OK && !scratch) st = (rast_status)RASTPY_E_NOMEM;
            if (st == RAST_OK)
                st = rast_fill_polygons_spans((const rast_polygon *)polys, npolys, opts, &clip, span, b,
                                              scratch, need, failed);
        }
        /* the rest of the planes after the last span */
        if (st == RAST_OK && merge == RASTPY_MERGE_FRESH)
            rastpy_clear(f.b.out + f.at, (size_t)npolys * (size_t)height * (size_t)width - f.at);
#if defined(__SSE2__)
        if (merge == RASTPY_MERGE_FRESH) _mm_sfence(); /* the streamed stores before the return */
#endif
    }
    free(scratch);
    free(polys);
    free(pts);
    return st;
}

long rastpy_burn_polygons(void *out, int32_t height, int32_t width, int64_t row_stride,
                          int64_t plane_stride, int dtype, int merge, const void *values,
                          const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                          const rast_fill_opts *opts, uint32_t *failed)
{
    return rastpy_burn_any(out, 0, 0, height, width, row_stride, plane_stride, dtype, merge, values,
                           xy, npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, 0, NULL);
}

long rastpy_burn_polygons64(void *out, int32_t height, int32_t width, int64_t row_stride,
                            int64_t plane_stride, int dtype, int merge, const void *values,
                            const double *xy, size_t npoints, const uint32_t *ring_sizes,
                            size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                            const rast_fill_opts *opts, uint32_t *failed)
{
    return rastpy_burn_any(out, 0, 0, height, width, row_stride, plane_stride, dtype, merge, values,
                           xy, npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, 1, NULL);
}

long rastpy_burn_polygons64_at(void *out, int32_t y0, int32_t x0, int32_t height, int32_t width,
                               int64_t row_stride, int dtype, int merge, const void *values,
                               const double *xy, size_t npoints, const uint32_t *ring_sizes,
                               size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                               const rast_fill_opts *opts, uint32_t *failed)
{
    return rastpy_burn_any(out, y0, x0, height, width, row_stride, 0, dtype, merge, values, xy,
                           npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, 1, NULL);
}

long rastpy_burn_polygons_oriented(void *out, int32_t height, int32_t width, int64_t row_stride,
                                   int64_t plane_stride, int dtype, int merge, const void *values,
                                   const double *xy, size_t npoints, const uint32_t *ring_sizes,
                                   size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                                   const rast_fill_opts *opts, uint32_t *failed,
                                   const int8_t *orient)
{
    return rastpy_burn_any(out, 0, 0, height, width, row_stride, plane_stride, dtype, merge, values,
                           xy, npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, 0, orient);
}

typedef struct rastpy_line_burn {
    rastpy_burn b;
    const uint32_t *part;
    int64_t *buf, width; /* geometry by geometry: its pixels, row * width + col */
    size_t n;
} rastpy_line_burn;

static void rastpy_line_pixel(void *user, size_t k, int64_t row, int64_t col)
{
    const rastpy_line_burn *l = (const rastpy_line_burn *)user;
    l->b.put(&l->b, l->b.out + row * l->b.row_stride, l->part[k], (int32_t)col, (int32_t)col + 1);
}

static void rastpy_line_collect(void *user, size_t k, int64_t row, int64_t col)
{
    rastpy_line_burn *l = (rastpy_line_burn *)user;
    (void)k;
    l->buf[l->n++] = row * l->width + col;
}

static int rastpy_cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

long rastpy_burn_gdal_lines(void *out, int32_t height, int32_t width, int64_t row_stride, int dtype,
                            int merge, const void *values, const int64_t *ij, const int8_t *last,
                            const uint32_t *part, const uint32_t *geom, size_t npoints)
{
    rastpy_line_burn l;
    size_t s = 0, e, cap = 0, i;
    if (dtype < RASTPY_DT_U8 || dtype > RASTPY_DT_F64 || merge < RASTPY_MERGE_REPLACE ||
        merge > RASTPY_MERGE_ADD_SAT || !values)
        return RAST_E_ARG;
    l.b.out = (unsigned char *)out;
    l.b.row_stride = row_stride;
    l.b.plane_stride = 0;
    l.b.x0 = 0;
    l.b.y0 = 0;
    l.b.values = (const unsigned char *)values;
    l.b.put = rastpy_puts[dtype - 1][merge];
    l.part = part;
    l.buf = NULL;
    l.width = width;
    if (!geom) {
        rastpy_gdal_line_walk(ij, last, npoints, height, width, rastpy_line_pixel, &l);
        return 0;
    }
    /* Geometry by geometry: its pixels, sorted, each burnt once. */
    for (s = 0; s < npoints; s = e) {
        size_t need;
        for (e = s + 1; e < npoints && geom[e] == geom[s];) e++;
        need = rastpy_gdal_line_count(ij + 2 * s, last + s, e - s, height, width);
        if (need > cap) {
            int64_t *grown = (int64_t *)realloc(l.buf, need * sizeof *l.buf);
            if (!grown) {
                free(l.buf);
                return RASTPY_E_NOMEM;
            }
            l.buf = grown;
            cap = need;
        }
        l.n = 0;
        rastpy_gdal_line_walk(ij + 2 * s, last + s, e - s, height, width, rastpy_line_collect, &l);
        if (l.n > 1) qsort(l.buf, l.n, sizeof *l.buf, rastpy_cmp_i64); /* (l.buf is NULL while n is 0) */
        for (i = 0; i < l.n; i++)
            if (i == 0 || l.buf[i] != l.buf[i - 1])
                l.b.put(&l.b, l.b.out + l.buf[i] / width * row_stride, part[s],
                        (int32_t)(l.buf[i] % width), (int32_t)(l.buf[i] % width) + 1);
    }
    free(l.buf);
    return 0;
}

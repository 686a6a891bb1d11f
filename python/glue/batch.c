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
 * Returns 0; k + 1 when point k is bad (NaN, infinite or out of range
 * after snapping, see rastpy_snap); a negative rast_status, with *failed
 * the polygon it belongs to when it is one polygon's; RASTPY_E_NOMEM.
 * Nothing is written to out unless the call succeeds. */
#include <stdlib.h>
#include <string.h>
#include "batch.h"

typedef struct rastpy_burn {
    unsigned char *out;
    int64_t row_stride, plane_stride;
    const unsigned char *values; /* NULL: 1 */
    void (*put)(const struct rastpy_burn *b, unsigned char *row, uint32_t k, int32_t x0,
                int32_t x1);
} rastpy_burn;

/* One span writer per element type and merge rule.  The value is read
 * with memcpy (values need not be aligned); the rows are aligned, as numpy
 * arrays of the type are. */
#define RASTPY_PUTS(NAME, T)                                                                 \
    static T rastpy_value_##NAME(const rastpy_burn *b, uint32_t k)                          \
    {                                                                                        \
        T v = (T)1;                                                                          \
        if (b->values) memcpy(&v, b->values + (size_t)k * sizeof(T), sizeof(T));             \
        return v;                                                                            \
    }                                                                                        \
    static void rastpy_replace_##NAME(const rastpy_burn *b, unsigned char *row, uint32_t k,  \
                                      int32_t x0, int32_t x1)                                \
    {                                                                                        \
        T *p = (T *)(void *)row, v = rastpy_value_##NAME(b, k);                              \
        int32_t x;                                                                           \
        for (x = x0; x < x1; x++) p[x] = v;                                                  \
    }                                                                                        \
    static void rastpy_add_##NAME(const rastpy_burn *b, unsigned char *row, uint32_t k,      \
                                  int32_t x0, int32_t x1)                                    \
    {                                                                                        \
        T *p = (T *)(void *)row, v = rastpy_value_##NAME(b, k);                              \
        int32_t x;                                                                           \
        for (x = x0; x < x1; x++) p[x] = RASTPY_ADD_##NAME(p[x], v);                         \
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

/* Indexed by RASTPY_DT_* - 1, then by merge rule. */
static const rastpy_put_fn rastpy_puts[10][2] = {
    {rastpy_replace_u8, rastpy_add_u8},   {rastpy_replace_i8, rastpy_add_i8},
    {rastpy_replace_u16, rastpy_add_u16}, {rastpy_replace_i16, rastpy_add_i16},
    {rastpy_replace_u32, rastpy_add_u32}, {rastpy_replace_i32, rastpy_add_i32},
    {rastpy_replace_i64, rastpy_add_i64}, {rastpy_replace_u64, rastpy_add_u64},
    {rastpy_replace_f32, rastpy_add_f32}, {rastpy_replace_f64, rastpy_add_f64},
};

static void rastpy_burn_span(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    const rastpy_burn *b = (const rastpy_burn *)user;
    b->put(b, b->out + (int64_t)k * b->plane_stride + (int64_t)y * b->row_stride, k, x0, x1);
}

/* Snap xy (npoints points) into a malloc'd *pts and lay npolys polygons
 * over it in a malloc'd *polys: polygon k is poly_rings[k] consecutive
 * rings of ring_sizes.  Returns 0 (the caller frees both), k + 1 when point
 * k is bad, RAST_E_ARG when the tables disagree, RASTPY_E_NOMEM (nothing
 * to free then). */
long rastpy_polygon_table(const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys, int s,
                          rast_polygon **polys_out, int32_t **pts_out)
{
    rast_polygon *polys = (rast_polygon *)malloc((size_t)npolys * sizeof *polys + 1);
    int32_t *pts = (int32_t *)malloc(npoints * sizeof(rast_point) + 1);
    size_t ring = 0, point = 0, r;
    uint32_t k;
    long bad;
    if (!polys || !pts) {
        free(polys);
        free(pts);
        return RASTPY_E_NOMEM;
    }
    bad = rastpy_snap(xy, npoints, s, pts);
    if (bad >= 0) {
        free(polys);
        free(pts);
        return bad + 1;
    }
    for (k = 0; k < npolys; k++) {
        size_t n = 0;
        polys[k].points = (const rast_point *)(const void *)(pts + 2 * point);
        polys[k].ring_sizes = ring_sizes + ring;
        polys[k].nrings = poly_rings[k];
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

static long rastpy_burn_all(void *out, int32_t height, int32_t width, int64_t row_stride,
                        int64_t plane_stride, int dtype, int merge, const void *values,
                        const double *xy, size_t npoints, const uint32_t *ring_sizes,
                        size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                        const rast_fill_opts *opts, uint32_t *failed, const int8_t *orient);

long rastpy_burn_polygons(void *out, int32_t height, int32_t width, int64_t row_stride,
                          int64_t plane_stride, int dtype, int merge, const void *values,
                          const double *xy, size_t npoints, const uint32_t *ring_sizes,
                          size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                          const rast_fill_opts *opts, uint32_t *failed)
{
    return rastpy_burn_all(out, height, width, row_stride, plane_stride, dtype, merge, values, xy,
                       npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, NULL);
}

long rastpy_burn_polygons_oriented(void *out, int32_t height, int32_t width, int64_t row_stride,
                                   int64_t plane_stride, int dtype, int merge, const void *values,
                                   const double *xy, size_t npoints, const uint32_t *ring_sizes,
                                   size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                                   const rast_fill_opts *opts, uint32_t *failed,
                                   const int8_t *orient)
{
    return rastpy_burn_all(out, height, width, row_stride, plane_stride, dtype, merge, values, xy,
                       npoints, ring_sizes, nrings, poly_rings, npolys, opts, failed, orient);
}

static long rastpy_burn_all(void *out, int32_t height, int32_t width, int64_t row_stride,
                        int64_t plane_stride, int dtype, int merge, const void *values,
                        const double *xy, size_t npoints, const uint32_t *ring_sizes,
                        size_t nrings, const uint32_t *poly_rings, uint32_t npolys,
                        const rast_fill_opts *opts, uint32_t *failed, const int8_t *orient)
{
    rast_polygon *polys;
    rast_rect clip;
    rastpy_burn b;
    int32_t *pts;
    size_t need = 0;
    void *scratch;
    long bad;
    rast_status st;

    if (dtype < RASTPY_DT_U8 || dtype > RASTPY_DT_F64 || (merge != RASTPY_MERGE_REPLACE &&
                                                          merge != RASTPY_MERGE_ADD))
        return RAST_E_ARG;
    if (height < 0 || width < 0) return RAST_E_SIZE;
    bad = rastpy_polygon_table(xy, npoints, ring_sizes, nrings, poly_rings, npolys,
                               opts ? opts->subpixel_bits : 0, &polys, &pts);
    if (bad) return bad;
    if (orient) rastpy_orient(pts, ring_sizes, nrings, orient);
    clip.x0 = 0;
    clip.y0 = 0;
    clip.x1 = width;
    clip.y1 = height;
    st = rast_polygons_scratch_size(polys, npolys, opts, &clip, &need, failed);
    scratch = st == RAST_OK ? malloc(need + 1) : NULL;
    if (st == RAST_OK && !scratch) st = (rast_status)RASTPY_E_NOMEM;
    if (st == RAST_OK) {
        b.out = (unsigned char *)out;
        b.row_stride = row_stride;
        b.plane_stride = plane_stride;
        b.values = (const unsigned char *)values;
        b.put = rastpy_puts[dtype - 1][merge];
        st = rast_fill_polygons_spans(polys, npolys, opts, &clip, rastpy_burn_span, &b, scratch,
                                      need, failed);
    }
    free(scratch);
    free(polys);
    free(pts);
    return st;
}

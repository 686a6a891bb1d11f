/*
 * edgeflag.c - the edge flag filler (Ackland and Weste 1981; seed 001,
 * section 3.3, for polygons as in seed 003): first mark every crossing of
 * every edge with a row in a flag buffer, then sweep each row from left to
 * right, toggling "inside" at each flag and filling while inside.
 *
 * The flag of a pixel is not a single bit, because several crossings can
 * share a pixel (a vertex where two edges meet, two edges closer than a
 * pixel): under even-odd the flag counts the crossings whose first
 * counting column is that pixel and the sweep toggles on an odd count;
 * under non-zero it holds the sum of their directions and the sweep keeps
 * a running winding number, inside while it is not 0.  Crossings left of
 * the polygon's box (cut to the clip) are flagged on its first column, the
 * ones right of it are dropped: the sweep sees the same counts.
 *
 * The counts are kept modulo 2^(8 * sizeof flag), which is exact: |winding|
 * never exceeds the number of edges, so a winding number is 0 iff it is 0
 * modulo 2^8 when there are at most 255 vertices, 2^16 up to 65535 and
 * 2^32 beyond (RAST_MAX_POINTS = 2^24); and parity survives any modulus of
 * 2^k, so even-odd always uses one byte.
 *
 * Scratch: the flag buffer, one flag per pixel of the clip, each row padded
 * to 8 bytes: height x roundup8(width x F) bytes with F = 1 byte for up to
 * 255 vertices, 2 up to 65535, 4 beyond (the size non-zero needs; even-odd
 * uses the first byte of each).  Only the box's part is cleared and used.
 * The sweep skips 8 bytes of empty flags at a time.
 */
#include <string.h>

#include "poly.h"

static size_t rast__flag_bytes(uint32_t npoints)
{
    return npoints <= 0xFFu ? 1 : npoints <= 0xFFFFu ? 2 : 4;
}

/* Bytes of a row of `width` flags of `f` bytes, padded to 8. */
static size_t rast__flag_row(int32_t width, size_t f)
{
    size_t n = rast__size_mul((size_t)width, f);
    return n > (size_t)-1 - 7 ? (size_t)-1 : (n + 7) & ~(size_t)7;
}

size_t rast__edgeflag_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    return rast__size_mul((size_t)height, rast__flag_row(width, rast__flag_bytes(npoints)));
}

/* Mark and sweep for flags of type T (uint8_t, uint16_t or uint32_t):
 * `eo` selects even-odd (count crossings, inside on odd) over non-zero
 * (sum directions, inside on non-zero).  Unsigned T: the sums wrap. */
#define RAST__EDGEFLAG(T)                                                                   \
    static void rast__edgeflag_##T(const rast_polygon *poly, const rast__grid *g,          \
                                   const rast__box *box, int eo, unsigned char *buf,       \
                                   size_t row_bytes, rast__sink *sink)                     \
    {                                                                                       \
        const rast_point *pts = poly->points;                                               \
        const int32_t bits = box->col1 - box->col0;                                         \
        const int32_t per8 = (int32_t)(8 / sizeof(T));                                     \
        uint32_t k, i, base;                                                                \
        int32_t j;                                                                          \
        /* Mark. */                                                                         \
        for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {         \
            uint32_t n = poly->ring_sizes[k];                                               \
            for (i = 0; i < n; i++) {                                                       \
                rast__edge ed;                                                              \
                T inc;                                                                      \
                if (!rast__edge_setup(&ed, pts[base + i], pts[base + (i + 1 == n ? 0 : i + 1)], \
                                      g, box->row0, box->row1))                             \
                    continue;                                                               \
                inc = (T)(eo || ed.dir > 0 ? 1u : (T)-1);                                   \
                for (j = ed.row; j < ed.end; j++, rast__edge_step(&ed)) {                   \
                    int32_t c = ed.x - box->col0;                                           \
                    T *row = (T *)(void *)(buf + (size_t)(j - box->row0) * row_bytes);      \
                    if (c < 0) c = 0;                                                       \
                    if (c < bits) row[c] = (T)(row[c] + inc);                               \
                }                                                                           \
            }                                                                               \
        }                                                                                   \
        /* Sweep. */                                                                        \
        for (j = box->row0; j < box->row1; j++) {                                           \
            const unsigned char *bytes = buf + (size_t)(j - box->row0) * row_bytes;         \
            const T *row = (const T *)(const void *)bytes;                                  \
            T w = 0;                                                                        \
            int32_t x, start = 0, in = 0;                                                   \
            for (x = 0; x < bits;) {                                                        \
                if (row[x] == 0) {                                                          \
                    uint64_t v;                                                             \
                    if (x % per8 == 0 && x + per8 <= bits) {                                \
                        memcpy(&v, bytes + (size_t)x * sizeof(T), 8);                       \
                        if (v == 0) {                                                       \
                            x += per8;                                                      \
                            continue;                                                       \
                        }                                                                   \
                    }                                                                       \
                    x++;                                                                    \
                    continue;                                                               \
                }                                                                           \
                w = (T)(w + row[x]);                                                        \
                if (in != (eo ? (int)(w & 1u) : w != 0)) {                                  \
                    in = !in;                                                               \
                    if (in)                                                                 \
                        start = x;                                                          \
                    else                                                                    \
                        rast__sink_span(sink, j, box->col0 + start, box->col0 + x);         \
                }                                                                           \
                x++;                                                                        \
            }                                                                               \
            if (in) rast__sink_span(sink, j, box->col0 + start, box->col0 + bits);         \
        }                                                                                   \
        rast__sink_flush(sink);                                                             \
    }

RAST__EDGEFLAG(uint8_t)
RAST__EDGEFLAG(uint16_t)
RAST__EDGEFLAG(uint32_t)

rast_status rast__edgeflag_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    rast__box box;
    size_t f, row_bytes, n;
    unsigned char *buf;
    int eo = rule == RAST_RULE_EVENODD;

    if (!rast__poly_box(poly, npoints, g, clip, &box)) return RAST_OK;
    f = eo ? 1 : rast__flag_bytes(npoints);
    row_bytes = rast__flag_row(box.col1 - box.col0, f);
    n = (size_t)(box.row1 - box.row0) * row_bytes;
    buf = (unsigned char *)rast__take(arena, n);
    if (!buf) return RAST_E_SCRATCH;
    memset(buf, 0, n);
    if (f == 1)
        rast__edgeflag_uint8_t(poly, g, &box, eo, buf, row_bytes, sink);
    else if (f == 2)
        rast__edgeflag_uint16_t(poly, g, &box, eo, buf, row_bytes, sink);
    else
        rast__edgeflag_uint32_t(poly, g, &box, eo, buf, row_bytes, sink);
    return RAST_OK;
}

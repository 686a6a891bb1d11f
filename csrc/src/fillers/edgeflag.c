/*
 * edgeflag.c - the edge flag filler (Ackland and Weste 1981; seed 001,
 * section 3.3, for polygons as in seed 003): first mark every crossing of
 * every edge with a row in a flag buffer, then sweep each row from left to
 * right, toggling "inside" at each flag and filling while inside.
 *
 * Even-odd: the flag buffer is one bit per pixel, and marking a crossing
 * toggles the bit of its first counting column (two crossings on one pixel
 * cancel, as two toggles of "inside" would).  The sweep toggles "inside" at
 * each set bit; it finds them 64 pixels at a time (a word) with one
 * count-trailing-zeros per flag, so empty stretches of a row cost a word
 * test each.
 *
 * Non-zero: a pixel's flag must hold the sum of the directions of the
 * crossings on it, and the sweep keeps a running winding number, inside
 * while it is not 0.  The bits then say which pixels have a flag at all,
 * and a counter per pixel holds the sum; a counter is written when its bit
 * is first set, so only the bits are cleared beforehand and the sweep
 * still skips empty words.  The counters, and the running sum, are kept
 * modulo 2^(8F), which is exact: a row's crossings (at most one per edge,
 * so at most npoints) have directions summing to 0, so the winding number
 * of a sample, the sum over the crossings that count for it, is also minus
 * the sum over those that do not, and |winding| <= npoints / 2.  It is
 * therefore 0 iff it is 0 modulo 2^8 with at most 511 vertices (F = 1),
 * modulo 2^16 up to 131071 (F = 2), and modulo 2^32 beyond (F = 4;
 * RAST_MAX_POINTS is 2^24).
 *
 * Crossings left of the polygon's box (cut to the clip) are flagged on its
 * first column, the ones right of it are dropped: the sweep sees the same
 * counts.
 *
 * Scratch: the bits, height x ceil(width / 64) x 8 bytes, and the counters
 * non-zero needs, height x width x F bytes (rounded up to 8), for a clip of
 * width x height; F as above.  rast_scratch_size cannot see the rule, so it
 * always asks for both; even-odd uses the bits only.
 */
#include "poly.h"

static size_t rast__flag_bytes(uint32_t npoints)
{
    return npoints <= 511u ? 1 : npoints <= 131071u ? 2 : 4;
}

/* Bytes of the counters for a clip width x height, rounded up to 8. */
static size_t rast__counter_bytes(uint32_t npoints, int32_t width, int32_t height)
{
    size_t n = rast__size_mul(rast__size_mul((size_t)width, (size_t)height), rast__flag_bytes(npoints));
    return n > (size_t)-1 - 7 ? (size_t)-1 : (n + 7) & ~(size_t)7;
}

size_t rast__edgeflag_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    return rast__size_add(rast__mask_scratch(width, height),
                          rast__counter_bytes(npoints, width, height));
}

/* Walk every edge down its rows; hand each crossing's column, relative to
 * the box and clamped to it (or -1 right of it) to MARK(row, c, dir). */
#define RAST__EDGEFLAG_MARK(MARK)                                                           \
    do {                                                                                    \
        const rast_point *pts = poly->points;                                               \
        uint32_t k_, i_, base_;                                                             \
        for (k_ = 0, base_ = 0; k_ < poly->nrings; base_ += poly->ring_sizes[k_], k_++) {   \
            uint32_t n_ = poly->ring_sizes[k_];                                             \
            for (i_ = 0; i_ < n_; i_++) {                                                   \
                rast__edge ed;                                                              \
                int32_t j_;                                                                 \
                if (!rast__edge_setup(&ed, pts[base_ + i_], pts[base_ + (i_ + 1 == n_ ? 0 : i_ + 1)], \
                                      g, m.box.row0, m.box.row1))                           \
                    continue;                                                               \
                for (j_ = ed.row; j_ < ed.end; j_++, rast__edge_step(&ed)) {                \
                    int32_t c = ed.x - m.box.col0;                                          \
                    if (c < 0) c = 0;                                                       \
                    if (c < m.bits) MARK(j_, c, ed.dir);                                    \
                }                                                                           \
            }                                                                               \
        }                                                                                   \
    } while (0)

#define RAST__BIT(c) ((uint64_t)1 << ((c) % RAST__WORD_BITS))

/* Even-odd: toggle, then sweep. */
static void rast__edgeflag_evenodd(const rast_polygon *poly, const rast__grid *g,
                                   rast__mask m, rast__sink *sink)
{
    int32_t j;
#define RAST__TOGGLE(j, c, dir) \
    (rast__mask_row(&m, j)[(c) / RAST__WORD_BITS] ^= RAST__BIT(c))
    RAST__EDGEFLAG_MARK(RAST__TOGGLE);
#undef RAST__TOGGLE
    for (j = m.box.row0; j < m.box.row1; j++) {
        const uint64_t *row = rast__mask_row(&m, j);
        int32_t k, nw = (int32_t)m.words, start = 0, in = 0;
        for (k = 0; k < nw; k++) {
            uint64_t w = row[k];
            while (w) { /* each flag toggles "inside" */
                int32_t c = k * RAST__WORD_BITS + rast__ctz64(w);
                w &= w - 1;
                in = !in;
                if (in)
                    start = c;
                else
                    rast__sink_span(sink, j, m.box.col0 + start, m.box.col0 + c);
            }
        }
        if (in) rast__sink_span(sink, j, m.box.col0 + start, m.box.col0 + m.bits);
    }
    rast__sink_flush(sink);
}

/* Non-zero with counters of type T (uint8_t, uint16_t or uint32_t). */
#define RAST__EDGEFLAG_NONZERO(T)                                                           \
    static void rast__edgeflag_nonzero_##T(const rast_polygon *poly, const rast__grid *g,   \
                                           rast__mask m, T *count, rast__sink *sink)        \
    {                                                                                       \
        int32_t j;                                                                          \
        const size_t stride = (size_t)m.bits;                                               \
        /* the first crossing on a pixel sets its bit and writes its counter */             \
        RAST__EDGEFLAG_MARK(RAST__ADD_##T);                                                 \
        for (j = m.box.row0; j < m.box.row1; j++) {                                         \
            const uint64_t *row = rast__mask_row(&m, j);                                    \
            const T *cnt = count + (size_t)(j - m.box.row0) * stride;                       \
            int32_t k, nw = (int32_t)m.words, start = 0, in = 0;                            \
            T wind = 0;                                                                     \
            for (k = 0; k < nw; k++) {                                                      \
                uint64_t w = row[k];                                                        \
                while (w) {                                                                 \
                    int32_t c = k * RAST__WORD_BITS + rast__ctz64(w);                       \
                    w &= w - 1;                                                             \
                    wind = (T)(wind + cnt[c]);                                              \
                    if (in != (wind != 0)) {                                                \
                        in = !in;                                                           \
                        if (in)                                                             \
                            start = c;                                                      \
                        else                                                                \
                            rast__sink_span(sink, j, m.box.col0 + start, m.box.col0 + c);   \
                    }                                                                       \
                }                                                                           \
            }                                                                               \
            if (in) rast__sink_span(sink, j, m.box.col0 + start, m.box.col0 + m.bits);      \
        }                                                                                   \
        rast__sink_flush(sink);                                                             \
    }

#define RAST__ADD(T, j, c, dir)                                                             \
    do {                                                                                    \
        uint64_t *w_ = &rast__mask_row(&m, j)[(c) / RAST__WORD_BITS];                       \
        T *p_ = &count[(size_t)((j) - m.box.row0) * stride + (size_t)(c)];                  \
        T inc_ = (T)((dir) > 0 ? 1u : (T)-1);                                               \
        if (*w_ & RAST__BIT(c)) {                                                           \
            *p_ = (T)(*p_ + inc_);                                                          \
        } else {                                                                            \
            *w_ |= RAST__BIT(c);                                                            \
            *p_ = inc_;                                                                     \
        }                                                                                   \
    } while (0)
#define RAST__ADD_uint8_t(j, c, dir) RAST__ADD(uint8_t, j, c, dir)
#define RAST__ADD_uint16_t(j, c, dir) RAST__ADD(uint16_t, j, c, dir)
#define RAST__ADD_uint32_t(j, c, dir) RAST__ADD(uint32_t, j, c, dir)

RAST__EDGEFLAG_NONZERO(uint8_t)
RAST__EDGEFLAG_NONZERO(uint16_t)
RAST__EDGEFLAG_NONZERO(uint32_t)

rast_status rast__edgeflag_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena)
{
    rast__mask m;
    size_t f, n;
    void *count;
    rast_status st = rast__mask_begin(&m, poly, npoints, g, clip, arena);
    if (st != RAST_OK || m.bits == 0) return st;
    if (rule == RAST_RULE_EVENODD) {
        rast__edgeflag_evenodd(poly, g, m, sink);
        return RAST_OK;
    }
    f = rast__flag_bytes(npoints);
    n = (size_t)(m.box.row1 - m.box.row0) * (size_t)m.bits * f;
    count = rast__take(arena, n);
    if (!count) return RAST_E_SCRATCH;
    if (f == 1)
        rast__edgeflag_nonzero_uint8_t(poly, g, m, (uint8_t *)count, sink);
    else if (f == 2)
        rast__edgeflag_nonzero_uint16_t(poly, g, m, (uint16_t *)count, sink);
    else
        rast__edgeflag_nonzero_uint32_t(poly, g, m, (uint32_t *)count, sink);
    return RAST_OK;
}

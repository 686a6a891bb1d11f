/*
 * formats.c - the pixel formats: how a value is laid out in memory, how a
 * span of one value is written, how an 8-bit RGBA colour becomes a value,
 * how a run of shaded colours is stored, and how a run of anti-aliased
 * coverage paints the value.  Adding a format is one more
 * enumerator in rastrum.h and one more row of rast__formats here, with its
 * functions beside it; the painters (paint.c, shade.c) only read the table.
 */
#include <string.h>

#include "paint.h"

/* Fill n pixels of `bytes` bytes each with the pattern already written in
 * the first pixel, doubling the copied run each time: long spans become a
 * handful of large memcpy calls. */
static void rast__replicate(unsigned char *p, size_t bytes, size_t n)
{
    size_t done = bytes, total = bytes * n;
    while (done < total) {
        size_t c = done < total - done ? done : total - done;
        memcpy(p + done, p, c);
        done += c;
    }
}

/* Columns [x0, x1) of a row of `bytes`-byte pixels, all equal to value. */
static void rast__put(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *value,
                      int32_t bytes)
{
    unsigned char *p = row + (ptrdiff_t)x0 * bytes;
    if (x1 <= x0) return;
    memcpy(p, value, (size_t)bytes);
    rast__replicate(p, (size_t)bytes, (size_t)(x1 - x0));
}

/* Columns [x0, x1) of a row of `bytes`-byte pixels, each byte blended
 * toward the value's byte by the pixel's coverage (rast__blend8): every
 * byte a channel of 0..255, A included. */
static void rast__blend_bytes(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                              const unsigned char *v, int32_t bytes)
{
    unsigned char *p = row + (ptrdiff_t)x0 * bytes;
    int32_t k, c;
    for (k = 0; k < x1 - x0; k++, p += bytes)
        for (c = 0; c < bytes; c++) p[c] = (unsigned char)rast__blend8(v[c], p[c], cov[k]);
}

/* ---- gray8: one byte; shaded from R ---------------------------------------- */

/* Masks are the common case: a bare memset per span, no call per span. */
static void rast__gray8_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t k;
    for (k = 0; k < n; k++) memset(row + xs[2 * k], s->value[0], (size_t)(xs[2 * k + 1] - xs[2 * k]));
}

static void rast__gray8_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    if (x1 > x0) memset(row + x0, v[0], (size_t)(x1 - x0));
}

static void rast__gray8_pack(const unsigned char *rgba, unsigned char *v)
{
    v[0] = rgba[0];
}

static void rast__gray8_put(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba)
{
    int32_t k;
    for (k = 0; k < n; k++) row[x + k] = rgba[4 * k];
}

/* One byte a pixel; eight at a time where SSE2 is (a tiny polygon's rows
 * are a few pixels: -O2 did not vectorise the loop, 8% of the loop
 * family's "area" call under perf, issue 33).  In 16-bit lanes
 * x = s a + d (255 - a) + 127 <= 65152 exactly, and x / 255 is
 * (x + 1 + (x >> 8)) >> 8 for every x <= 65534 (checked for all of
 * them): rast__blend8's value. */
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__GRAY8_SSE2 1
#else
#define RAST__GRAY8_SSE2 0
#endif

#if RAST__GRAY8_SSE2
/* rast__blend8 of the 8 pixels d and levels a (each in the low 8 bytes,
 * the others 0) with fill s: the 8 bytes in the low half. */
static inline __m128i rast__gray8_mix8(__m128i d, __m128i a, __m128i sv)
{
    const __m128i z = _mm_setzero_si128(), m = _mm_set1_epi16(255);
    const __m128i half = _mm_set1_epi16(127), one = _mm_set1_epi16(1);
    const __m128i d16 = _mm_unpacklo_epi8(d, z), a16 = _mm_unpacklo_epi8(a, z);
    const __m128i x = _mm_add_epi16(_mm_add_epi16(_mm_mullo_epi16(sv, a16), _mm_mullo_epi16(d16, _mm_sub_epi16(m, a16))),
                                    half);
    return _mm_packus_epi16(_mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(x, one), _mm_srli_epi16(x, 8)), 8), z);
}

/* 4 bytes at p, as the low lane of a vector (memcpy: any alignment). */
static inline __m128i rast__gray8_load4(const unsigned char *p)
{
    int32_t v;
    memcpy(&v, p, 4);
    return _mm_cvtsi32_si128(v);
}

static inline void rast__gray8_store4(unsigned char *p, __m128i q)
{
    const int32_t v = _mm_cvtsi128_si32(q);
    memcpy(p, &v, 4);
}
#endif

/* Rows of 4 pixels or more take no pixel one at a time: the last 8 (or
 * 4) are blended as one more step that overlaps the steps before, its
 * pixels and levels read before any of the row is written, so a pixel in
 * both gets the same value from both (a tiny polygon's rows are 3 to 12
 * pixels: their last few, one at a time, were ~10 instructions each, a
 * quarter of the loop family's painting). */
RAST__HOT void rast__gray8_blend_in(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                                    const unsigned char *v)
{
    unsigned s = v[0];
    int32_t i = x0;
#if RAST__GRAY8_SSE2
    const __m128i sv = _mm_set1_epi16((short)s);
    if (x1 - x0 >= 8) {
        /* the last 8, from the pixels as they are before the steps */
        const __m128i last = rast__gray8_mix8(_mm_loadl_epi64((const __m128i *)(const void *)(row + x1 - 8)),
                                              _mm_loadl_epi64((const __m128i *)(const void *)(cov + (x1 - 8 - x0))),
                                              sv);
        for (; i + 8 <= x1; i += 8)
            _mm_storel_epi64((__m128i *)(void *)(row + i),
                             rast__gray8_mix8(_mm_loadl_epi64((const __m128i *)(const void *)(row + i)),
                                              _mm_loadl_epi64((const __m128i *)(const void *)(cov + (i - x0))), sv));
        if (i < x1) _mm_storel_epi64((__m128i *)(void *)(row + x1 - 8), last);
        return;
    }
    if (x1 - x0 >= 4) { /* the first 4 and the last 4 as one step of 8 */
        const __m128i q = rast__gray8_mix8(_mm_unpacklo_epi32(rast__gray8_load4(row + x0), rast__gray8_load4(row + x1 - 4)),
                                           _mm_unpacklo_epi32(rast__gray8_load4(cov), rast__gray8_load4(cov + (x1 - 4 - x0))),
                                           sv);
        rast__gray8_store4(row + x1 - 4, _mm_srli_si128(q, 4));
        rast__gray8_store4(row + x0, q);
        return;
    }
#endif
    for (; i < x1; i++) row[i] = (unsigned char)rast__blend8(s, row[i], cov[i - x0]);
}

/* (the format's entry; rast__gray8_blend_rows inlines the body) */
static void rast__gray8_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                              const unsigned char *v)
{
    rast__gray8_blend_in(row, x0, x1, cov, v);
}

#if !defined(__OPTIMIZE_SIZE__)
/* Rows [y0, y1) of the solid gray8 painter's pixels (the fast kind:
 * rast__painter::bytes, stride and value), columns [x0, x1), blended by
 * rows of levels lv (a row every lstride bytes, the first for row y0 and
 * column x0) as rast__gray8_blend blends each: a level 0 leaves its pixel
 * as it is and 255 sets the value (rast__blend8), so a tiny polygon's
 * box (coverage_small.c) goes here whole, its rows' runs not looked for
 * and no painter's call a row. */
void rast__gray8_blend_rows(unsigned char *base, ptrdiff_t stride, unsigned char value, int32_t x0,
                            int32_t x1, int32_t y0, int32_t y1, const uint8_t *lv, ptrdiff_t lstride)
{
    unsigned char *row = base + (ptrdiff_t)y0 * stride;
    for (; y0 < y1; y0++, row += stride, lv += lstride) rast__gray8_blend_in(row, x0, x1, lv, &value);
}
#endif

/* ---- rgb888: R, G, B bytes ------------------------------------------------- */

static void rast__rgb888_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    rast__put(row, x0, x1, v, 3);
}

static void rast__rgb888_pack(const unsigned char *rgba, unsigned char *v)
{
    memcpy(v, rgba, 3);
}

static void rast__rgb888_put(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba)
{
    unsigned char *p = row + (ptrdiff_t)x * 3;
    int32_t k;
    for (k = 0; k < n; k++) {
        p[3 * k] = rgba[4 * k];
        p[3 * k + 1] = rgba[4 * k + 1];
        p[3 * k + 2] = rgba[4 * k + 2];
    }
}

static void rast__rgb888_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                               const unsigned char *v)
{
    rast__blend_bytes(row, x0, x1, cov, v, 3);
}

/* ---- rgba8888: R, G, B, A bytes; shading stores the interpolated A -------- */

static void rast__rgba8888_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    rast__put(row, x0, x1, v, 4);
}

static void rast__rgba8888_pack(const unsigned char *rgba, unsigned char *v)
{
    memcpy(v, rgba, 4);
}

static void rast__rgba8888_put(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba)
{
    memcpy(row + (ptrdiff_t)x * 4, rgba, (size_t)n * 4);
}

static void rast__rgba8888_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                                 const unsigned char *v)
{
    rast__blend_bytes(row, x0, x1, cov, v, 4);
}

/* ---- count16: a native uint16_t; a fill adds 1 (saturating) ---------------- */

/* v + 1 - carry keeps the loop free of branches, so the compiler
 * vectorises it. */
static void rast__count16_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    uint16_t *p = (uint16_t *)(void *)row;
    int32_t i;
    (void)v;
    for (i = x0; i < x1; i++) {
        uint32_t c = (uint32_t)p[i] + 1u;
        p[i] = (uint16_t)(c - (c >> 16));
    }
}

/* A count adds 1 wherever the coverage is not 0. */
static void rast__count16_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                                const unsigned char *v)
{
    uint16_t *p = (uint16_t *)(void *)row;
    int32_t i;
    (void)v;
    for (i = x0; i < x1; i++) {
        uint32_t c = (uint32_t)p[i] + (cov[i - x0] != 0);
        p[i] = (uint16_t)(c - (c >> 16));
    }
}

/* ---- rgb565: a native uint16_t, R in bits 15-11, G 10-5, B 4-0 ------------- */

/* A pixel value is its two bytes in memory (a native uint16_t), so a span
 * is a plain 2-byte pattern. */
static void rast__rgb565_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    rast__put(row, x0, x1, v, 2);
}

/* The top 5, 6 and 5 bits of R, G and B (truncation, not rounding: 255
 * stays full scale and 0..7 of R all give 0). */
static uint16_t rast__rgb565(const unsigned char *rgba)
{
    return (uint16_t)(((unsigned)(rgba[0] >> 3) << 11) | ((unsigned)(rgba[1] >> 2) << 5) |
                      (unsigned)(rgba[2] >> 3));
}

static void rast__rgb565_pack(const unsigned char *rgba, unsigned char *v)
{
    uint16_t p = rast__rgb565(rgba);
    memcpy(v, &p, 2);
}

static void rast__rgb565_put(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba)
{
    uint16_t *p = (uint16_t *)(void *)row + x;
    int32_t k;
    for (k = 0; k < n; k++) p[k] = rast__rgb565(rgba + 4 * k);
}

/* Each of R, G and B blended in its own levels (0..31, 0..63, 0..31) by
 * rast__blend8, the value's bits over the pixel's. */
static void rast__rgb565_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                               const unsigned char *v)
{
    uint16_t *p = (uint16_t *)(void *)row;
    uint16_t s;
    unsigned sr, sg, sb;
    int32_t i;
    memcpy(&s, v, 2);
    sr = (unsigned)s >> 11;
    sg = ((unsigned)s >> 5) & 63u;
    sb = (unsigned)s & 31u;
    for (i = x0; i < x1; i++) {
        unsigned d = p[i], a = cov[i - x0];
        p[i] = (uint16_t)((rast__blend8(sr, d >> 11, a) << 11) |
                          (rast__blend8(sg, (d >> 5) & 63u, a) << 5) | rast__blend8(sb, d & 31u, a));
    }
}

/* ---- mono1: one bit, MSB first: pixel x is bit 7 - x%8 of byte x/8 --------- */

/* A value is one byte, "on" iff it is not 0.  The partial bytes at the
 * span's ends are masked; the bytes between are a memset. */
static void rast__mono1_fill(unsigned char *row, int32_t x0, int32_t x1, const unsigned char *v)
{
    int32_t b0 = x0 >> 3, b1 = (x1 - 1) >> 3;
    unsigned head = 0xFFu >> (x0 & 7), tail = (0xFF00u >> (((x1 - 1) & 7) + 1)) & 0xFFu;
    unsigned char on = v[0] ? 0xFF : 0x00;
    if (x1 <= x0) return;
    if (b0 == b1) {
        unsigned m = head & tail;
        row[b0] = (unsigned char)((row[b0] & ~m) | (on & m));
        return;
    }
    row[b0] = (unsigned char)((row[b0] & ~head) | (on & head));
    if (b1 > b0 + 1) memset(row + b0 + 1, on, (size_t)(b1 - b0 - 1));
    row[b1] = (unsigned char)((row[b1] & ~tail) | (on & tail));
}

/* A colour is on iff R >= 128: its top bit, as rgb565 takes top bits. */
static void rast__mono1_pack(const unsigned char *rgba, unsigned char *v)
{
    v[0] = (unsigned char)(rgba[0] >> 7);
}

static void rast__mono1_put(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba)
{
    int32_t k;
    for (k = 0; k < n; k++) {
        int32_t i = x + k;
        unsigned m = 0x80u >> (i & 7);
        row[i >> 3] = (unsigned char)((row[i >> 3] & ~m) | (rgba[4 * k] & 0x80u ? m : 0u));
    }
}

/* A threshold, not a blend: the pixels with coverage level >= 128 (more
 * than half the pixel: a > 127.5 / 255) get the value, the others are
 * left alone. */
static void rast__mono1_blend(unsigned char *row, int32_t x0, int32_t x1, const uint8_t *cov,
                              const unsigned char *v)
{
    int32_t i = x0;
    while (i < x1) {
        int32_t i0;
        while (i < x1 && cov[i - x0] < 128) i++;
        i0 = i;
        while (i < x1 && cov[i - x0] >= 128) i++;
        rast__mono1_fill(row, i0, i, v);
    }
}

/* ---- the table, in rast_format order ---------------------------------------- */

/* Format f's row as the build's configuration keeps it (base/config.h): all
 * zero when f is left out (RAST__FORMAT_KEPT refuses f before its row is
 * read); without shading no `put`, without anti-aliasing no `blend` (no
 * method is kept then, and every call that would blend refuses its
 * method first), so that the linker drops what nothing calls.  `pack` stays with the format:
 * rast_pack_color is how an application makes a pixel value.  A slot a
 * format has none of is a typed null (RAST__NO_*): `c ? NULL : NULL` would
 * be a void pointer, which ISO C does not let initialise a function
 * pointer. */
#define RAST__NO_ROW ((rast__row_fn)0)
#define RAST__NO_PACK ((void (*)(const unsigned char *, unsigned char *))0)
#define RAST__NO_PUT ((void (*)(unsigned char *, int32_t, int32_t, const unsigned char *))0)
/* The row of f is there: f is kept, or f is RGBA8888, the colours the
 * anti-aliased shaded triangles shade a band into (shade_aa.c), when they
 * are (the target format check still refuses a left-out RGBA8888). */
#define RAST__ROW_KEPT(f)                                                      \
    (RAST__HAS(RAST_CONFIG_FORMATS, f) ||                                      \
     ((f) == RAST_FORMAT_RGBA8888 && RAST_CONFIG_SHADING && RAST_CONFIG_AA_METHODS))
#define RAST__KEEP(f, x) (RAST__ROW_KEPT(f) ? (x) : 0)
#define RAST__FORMAT_ROW(f, bits, value, channels, row, fill, pack, put, blend) \
    {RAST__KEEP(f, bits), RAST__KEEP(f, value), RAST__KEEP(f, channels), \
     RAST__ROW_KEPT(f) ? row : NULL, \
     RAST__ROW_KEPT(f) ? fill : NULL, \
     RAST__ROW_KEPT(f) ? pack : NULL, \
     RAST__ROW_KEPT(f) && RAST_CONFIG_SHADING ? put : NULL, \
     RAST__ROW_KEPT(f) && RAST_CONFIG_AA_METHODS ? blend : NULL}

const rast__format rast__formats[RAST_FORMAT_COUNT_] = {
    /* format bits value channels row fill pack put blend */
    RAST__FORMAT_ROW(RAST_FORMAT_GRAY8, 8, 1, 1, rast__gray8_row, rast__gray8_fill,
                     rast__gray8_pack, rast__gray8_put, rast__gray8_blend),
    RAST__FORMAT_ROW(RAST_FORMAT_RGB888, 24, 3, 3, RAST__NO_ROW, rast__rgb888_fill,
                     rast__rgb888_pack, rast__rgb888_put, rast__rgb888_blend),
    RAST__FORMAT_ROW(RAST_FORMAT_RGBA8888, 32, 4, 4, RAST__NO_ROW, rast__rgba8888_fill,
                     rast__rgba8888_pack, rast__rgba8888_put, rast__rgba8888_blend),
    RAST__FORMAT_ROW(RAST_FORMAT_COUNT16, 16, 0, 0, RAST__NO_ROW, rast__count16_fill,
                     RAST__NO_PACK, RAST__NO_PUT, rast__count16_blend),
    RAST__FORMAT_ROW(RAST_FORMAT_RGB565, 16, 2, 3, RAST__NO_ROW, rast__rgb565_fill,
                     rast__rgb565_pack, rast__rgb565_put, rast__rgb565_blend),
    RAST__FORMAT_ROW(RAST_FORMAT_MONO1, 1, 1, 1, RAST__NO_ROW, rast__mono1_fill,
                     rast__mono1_pack, rast__mono1_put, rast__mono1_blend),
};

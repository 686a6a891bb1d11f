/*
 * fuzz.h - what the fuzz targets share: a decoder that turns the fuzzer's
 * bytes into bounded arguments (coordinates near a small target, at the
 * range limits, anywhere in range, or just out of it), a target with guard
 * bytes around it, and the slow references (tests/c/ref.h, DESIGN
 * section 1 one sample at a time, and the boundary modes from their
 * definitions in rastrum.h).
 *
 * Every target is a libFuzzer entry point, LLVMFuzzerTestOneInput; built
 * with clang -fsanitize=fuzzer it is a fuzzer, built with driver.c it runs
 * a corpus once (make fuzz-regress, make fuzz-check).  An oracle failure
 * aborts, which both report as a crash.
 */
#ifndef RAST_FUZZ_H
#define RAST_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrum.h"
#include "ref.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FZ_ASSERT(c)                                                              \
    do {                                                                          \
        if (!(c)) {                                                               \
            fprintf(stderr, "%s:%d: oracle failed: %s\n", __FILE__, __LINE__, #c); \
            abort();                                                              \
        }                                                                         \
    } while (0)

/* ---- decoding ----------------------------------------------------------------
 * Past the end of the input every read gives 0, so every input decodes. */
typedef struct fz_in {
    const uint8_t *p;
    size_t n;
    int out_of_range; /* a coordinate outside +-RAST_COORD_MAX was made */
} fz_in;

static inline uint32_t fz_u8(fz_in *in)
{
    if (!in->n) return 0;
    in->n--;
    return *in->p++;
}
static inline uint32_t fz_u16(fz_in *in) { return fz_u8(in) | fz_u8(in) << 8; }
static inline uint32_t fz_u32(fz_in *in) { return fz_u16(in) | fz_u16(in) << 16; }
static inline int32_t fz_below(fz_in *in, int32_t n) { return (int32_t)(fz_u16(in) % (uint32_t)n); }

/* A vertex coordinate in units of 1/2^s pixel: mostly a pixel in
 * [-8, extent + 8) with a subpixel part (none, exactly half, or any), else
 * one of the range limits, anything in range, or (rarely) just out of it. */
static inline int32_t fz_coord(fz_in *in, int s, int32_t extent)
{
    static const int32_t limits[8] = {RAST_COORD_MAX, -RAST_COORD_MAX, RAST_COORD_MAX - 1,
                                      -RAST_COORD_MAX + 1, 0, 1, -1, 1 << 26};
    uint32_t mode = fz_u8(in);
    int32_t px;
    uint32_t sub;
    if (mode == 255) {
        in->out_of_range = 1;
        return (fz_u8(in) & 1) ? RAST_COORD_MAX + 1 : INT32_MIN;
    }
    if (mode >= 240) return limits[mode % 8];
    if (mode >= 224) return (int32_t)(fz_u32(in) % (2u * RAST_COORD_MAX + 1)) - RAST_COORD_MAX;
    px = fz_below(in, extent + 16) - 8;
    sub = s ? fz_u16(in) & ((1u << s) - 1) : 0;
    if (mode % 4 == 1) sub = 0;
    if (mode % 4 == 2 && s) sub = 1u << (s - 1);
    return px * (1 << s) + (int32_t)sub;
}

static inline int fz_in_range(rast_point p)
{
    return p.x >= -RAST_COORD_MAX && p.x <= RAST_COORD_MAX && p.y >= -RAST_COORD_MAX &&
           p.y <= RAST_COORD_MAX;
}

static inline rast_point fz_point(fz_in *in, int s, int32_t extent)
{
    rast_point p;
    p.x = fz_coord(in, s, extent);
    p.y = fz_coord(in, s, extent);
    return p;
}

/* A clip around a w x h target: each side within 4 pixels of it, possibly
 * inverted or empty. */
static inline rast_rect fz_clip(fz_in *in, int32_t w, int32_t h)
{
    rast_rect c;
    if (fz_u8(in) < 128) { /* the whole target */
        c.x0 = c.y0 = 0;
        c.x1 = w;
        c.y1 = h;
        return c;
    }
    c.x0 = fz_below(in, w + 9) - 4;
    c.x1 = fz_below(in, w + 9) - 4;
    c.y0 = fz_below(in, h + 9) - 4;
    c.y1 = fz_below(in, h + 9) - 4;
    return c;
}

/* ---- a target with guard bytes ---------------------------------------------- */
#define FZ_MAXDIM 48
#define FZ_PAD 4
#define FZ_SPAN (FZ_MAXDIM + 2 * FZ_PAD)
#define FZ_GUARD 0xA5

typedef struct fz_target {
    unsigned char mem[FZ_SPAN * FZ_SPAN * 4];
    unsigned char before[FZ_SPAN * FZ_SPAN * 4];
    rast_target t;
    rast_rect cut; /* the clip cut to the target */
    int32_t w, h, bpp, stride;
} fz_target;

static const unsigned char fz_value[4] = {0x5A, 0xC3, 0x3C, 0x96};
static const unsigned char fz_background[4] = {0x11, 0x22, 0x33, 0x44};

static inline unsigned char *fz_px(fz_target *ft, int32_t x, int32_t y)
{
    return ft->mem + (ptrdiff_t)(y + FZ_PAD) * ft->stride + (ptrdiff_t)(x + FZ_PAD) * ft->bpp;
}

/* Guards around, zeros inside; ft->before keeps a copy. */
static inline void fz_target_init(fz_target *ft, int32_t w, int32_t h, rast_format f,
                                  const rast_rect *clip)
{
    int32_t y;
    rast_format_bytes(f, &ft->bpp);
    ft->w = w;
    ft->h = h;
    ft->stride = (w + 2 * FZ_PAD) * ft->bpp;
    memset(ft->mem, FZ_GUARD, sizeof ft->mem);
    for (y = 0; y < h; y++) memset(fz_px(ft, 0, y), 0, (size_t)(w * ft->bpp));
    FZ_ASSERT(rast_target_init(&ft->t, fz_px(ft, 0, 0), w, h, ft->stride, f) == RAST_OK);
    ft->t.clip = *clip;
    ft->cut = *clip;
    if (ft->cut.x0 < 0) ft->cut.x0 = 0;
    if (ft->cut.y0 < 0) ft->cut.y0 = 0;
    if (ft->cut.x1 > w) ft->cut.x1 = w;
    if (ft->cut.y1 > h) ft->cut.y1 = h;
    if (ft->cut.x1 < ft->cut.x0) ft->cut.x1 = ft->cut.x0;
    if (ft->cut.y1 < ft->cut.y0) ft->cut.y1 = ft->cut.y0;
    memcpy(ft->before, ft->mem, sizeof ft->mem);
}

static inline int fz_in_rect(const rast_rect *r, int32_t x, int32_t y)
{
    return x >= r->x0 && x < r->x1 && y >= r->y0 && y < r->y1;
}

static inline int fz_untouched(const fz_target *ft)
{
    return memcmp(ft->mem, ft->before, sizeof ft->mem) == 0;
}

/* RAST_FORMAT_MONO1 packs 8 pixels a byte, MSB first: pixel (x, y) of the
 * target (x >= 0) is bit 7 - x % 8 of byte x / 8 of its row, in `mem` (ft->mem
 * or a copy of it). */
static inline unsigned char *fz_mono_byte(const fz_target *ft, unsigned char *mem, int32_t x, int32_t y)
{
    return mem + (ptrdiff_t)(FZ_PAD + y) * ft->stride + FZ_PAD + x / 8;
}

/* Put a value (format bytes; MONO1: on iff byte 0 is not 0) at (x, y) of `mem`. */
static inline void fz_set(const fz_target *ft, unsigned char *mem, int32_t x, int32_t y,
                          const unsigned char *value)
{
    if (ft->t.format == RAST_FORMAT_MONO1) {
        unsigned char *b = fz_mono_byte(ft, mem, x, y), bit = (unsigned char)(0x80u >> (x % 8));
        *b = (unsigned char)(value[0] ? (*b | bit) : (*b & ~bit));
        return;
    }
    memcpy(mem + (fz_px((fz_target *)ft, x, y) - ft->mem), value, (size_t)ft->bpp);
}

/* The count a pixel holds: COUNT16 its value; other formats 1 if it holds
 * fz_value (MONO1: its bit is on), 0 if it holds what it held before
 * (anything else is an oracle failure). */
static inline int32_t fz_count(fz_target *ft, int32_t x, int32_t y)
{
    const unsigned char *p = fz_px(ft, x, y);
    if (ft->t.format == RAST_FORMAT_COUNT16) {
        uint16_t v;
        memcpy(&v, p, 2);
        return v;
    }
    if (ft->t.format == RAST_FORMAT_MONO1) {
        const unsigned char *b = fz_mono_byte(ft, ft->mem, x, y);
        unsigned char bit = (unsigned char)(0x80u >> (x % 8));
        if (*b & bit) return 1;
        FZ_ASSERT(!(ft->before[b - ft->mem] & bit));
        return 0;
    }
    if (memcmp(p, fz_value, (size_t)ft->bpp) == 0) return 1;
    FZ_ASSERT(memcmp(p, ft->before + (p - ft->mem), (size_t)ft->bpp) == 0);
    return 0;
}

/* Every byte of the memory (guards, the padding bits of MONO1 rows
 * included) as before, except the pixels of the cut clip: there the
 * counts are `want` (w x h, row major; COUNT16 holds it, the other formats
 * fz_value where want > 0). */
static unsigned char fz_expect[FZ_SPAN * FZ_SPAN * 4];
static inline void fz_check(fz_target *ft, const uint16_t *want)
{
    int32_t x, y;
    memcpy(fz_expect, ft->before, sizeof fz_expect);
    for (y = ft->cut.y0; y < ft->cut.y1; y++)
        for (x = ft->cut.x0; x < ft->cut.x1; x++) {
            int32_t w = want[y * ft->w + x];
            if (ft->t.format == RAST_FORMAT_COUNT16) {
                uint16_t v = (uint16_t)w;
                memcpy(fz_expect + (fz_px(ft, x, y) - ft->mem), &v, 2);
            } else if (w > 0) {
                fz_set(ft, fz_expect, x, y, fz_value);
            }
        }
    FZ_ASSERT(memcmp(fz_expect, ft->mem, sizeof fz_expect) == 0);
}

/* ---- scratch with guard bytes after it ----------------------------------------- */
#define FZ_SCRATCH_MAX (1 << 20)
#define FZ_SCRATCH_GUARD 64
typedef struct fz_scratch {
    uint64_t mem[(FZ_SCRATCH_MAX + FZ_SCRATCH_GUARD) / 8];
    size_t bytes;
} fz_scratch;

static inline void *fz_scratch_init(fz_scratch *s, size_t bytes)
{
    FZ_ASSERT(bytes <= FZ_SCRATCH_MAX);
    s->bytes = bytes;
    memset((unsigned char *)s->mem + bytes, FZ_GUARD, FZ_SCRATCH_GUARD);
    return s->mem;
}

static inline void fz_scratch_check(const fz_scratch *s)
{
    const unsigned char *g = (const unsigned char *)s->mem + s->bytes;
    int i;
    for (i = 0; i < FZ_SCRATCH_GUARD; i++) FZ_ASSERT(g[i] == FZ_GUARD);
}

/* ---- references ---------------------------------------------------------------- */

/* Does the closed segment a-b (units 1/2^s pixel) meet the open square
 * (i, i+1) x (j, j+1) of pixel (i, j)?  The parameters t in [0, 1] with
 * the point inside each open slab form an interval; intersect the two,
 * as fractions with positive denominators (|numerators|, denominators
 * < 2^29: the products fit int64_t). */
static inline int fz_ref_touches(rast_point a, rast_point b, int s, int64_t i, int64_t j)
{
    rast_point64 a64, b64;
    a64.x = a.x;
    a64.y = a.y;
    b64.x = b.x;
    b64.y = b.y;
    return ref_touches64(a64, b64, s, i, j); /* ref.h: the same test, in 128 bits */
}

/* Is pixel (i, j) in the fill of polygon pg with options o (any rule,
 * rounding, sample, boundary)?  DESIGN section 1 plus the boundary modes
 * as rastrum.h defines them. */
static inline int fz_ref_polygon(const rast_polygon *pg, const rast_fill_opts *o, int64_t i,
                                 int64_t j)
{
    int s = o->subpixel_bits, center = o->sample == RAST_SAMPLE_CENTER, cr;
    int w = ref_winding(pg->points, pg->ring_sizes, pg->nrings, s, center,
                        o->rounding == RAST_ROUND_TEXTBOOK, i, j, &cr);
    uint32_t k, v, base = 0;
    if (o->rule == RAST_RULE_EVENODD ? (cr & 1) : (w != 0)) return 1;
    if (o->boundary == RAST_BOUNDARY_EXACT) return 0;
    for (k = 0; k < pg->nrings; base += pg->ring_sizes[k], k++)
        for (v = 0; v < pg->ring_sizes[k]; v++) {
            rast_point a = pg->points[base + v], b = pg->points[base + (v + 1) % pg->ring_sizes[k]];
            if (o->boundary == RAST_BOUNDARY_CLOSED ? ref_line_has(a, b, s, center, i, j)
                                                    : fz_ref_touches(a, b, s, i, j))
                return 1;
        }
    return 0;
}

/* ---- spans into a coverage grid over the padded window --------------------------- */
typedef struct fz_spans {
    uint16_t count[FZ_SPAN * FZ_SPAN]; /* (x + FZ_PAD, y + FZ_PAD) */
    rast_rect clip;
    int32_t last_y, last_x1, ordered; /* ordered: check polygon span order */
} fz_spans;

static inline void fz_spans_init(fz_spans *s, const rast_rect *clip, int ordered)
{
    memset(s->count, 0, sizeof s->count);
    s->clip = *clip;
    s->last_y = INT32_MIN;
    s->last_x1 = INT32_MIN;
    s->ordered = ordered;
}

static inline void fz_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    fz_spans *s = (fz_spans *)user;
    int32_t x;
    FZ_ASSERT(x0 < x1);
    FZ_ASSERT(fz_in_rect(&s->clip, x0, y) && x1 <= s->clip.x1);
    if (s->ordered) { /* rows top to bottom, spans left to right, not touching */
        FZ_ASSERT(y >= s->last_y);
        if (y == s->last_y) FZ_ASSERT(x0 > s->last_x1);
        s->last_y = y;
        s->last_x1 = x1;
    }
    for (x = x0; x < x1; x++) s->count[(y + FZ_PAD) * FZ_SPAN + x + FZ_PAD]++;
}

static inline uint16_t fz_spans_at(const fz_spans *s, int32_t x, int32_t y)
{
    return s->count[(y + FZ_PAD) * FZ_SPAN + x + FZ_PAD];
}

/* Decode fill options; *valid is 0 when they hold an error on purpose. */
static inline rast_fill_opts fz_fill_opts(fz_in *in)
{
    rast_fill_opts o;
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_algorithm)fz_below(in, RAST_ALGO_COUNT_);
    o.rule = (rast_fill_rule)fz_below(in, 2);
    o.subpixel_bits = fz_below(in, RAST_MAX_SUBPIXEL_BITS + 1);
    o.sample = (rast_sample)fz_below(in, 2);
    o.rounding = (rast_rounding)fz_below(in, 2);
    o.boundary = (rast_boundary)fz_below(in, 3);
    return o;
}

/* Every format, RGB565 and MONO1 included (and any added later). */
static inline rast_format fz_format(fz_in *in)
{
    return (rast_format)fz_below(in, RAST_FORMAT_COUNT_);
}

#endif

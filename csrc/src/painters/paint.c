/*
 * paint.c - targets and painters: WHAT a run writes.  A painter
 * (rast__painter, internal.h) takes a row's full runs at once (one call
 * per row, not per span) and a levels run at a time.  The solid painter
 * writes one value over full runs and blends it by a levels run's
 * coverage (the format's blend); the opaque painter also writes the
 * background between full runs, so that every clip pixel is written once;
 * the user painters hand runs to the caller's callbacks.
 *
 * The pixel formats themselves are rows of rast__formats (formats.c);
 * nothing here depends on a particular one.
 */
#include <string.h>

#include "paint.h"

/* Any format's solid row: its span function over each span. */
static void rast__solid_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t k;
    for (k = 0; k < n; k++) s->fmt->fill(row, xs[2 * k], xs[2 * k + 1], s->value);
}

/* Any format's levels run: its blend (formats.c). */
static void rast__solid_levels(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__solid *s = (const rast__solid *)user;
    s->fmt->blend(s->base + (ptrdiff_t)y * s->stride, x0, x1, cov, s->value);
}

/* ---- opaque: every clip pixel written once, value or background --------- */

/* Whole background rows after the last row written, up to (not including)
 * row `to`.  A row with spans is cleared whole too and its spans written
 * over it: the row is in L1 by then, so the second write is nearly free,
 * and it takes one memset per row instead of one per gap. */
static void rast__opaque_rows(rast__solid *s, int32_t to)
{
#if !defined(__OPTIMIZE_SIZE__)
    /* One byte a pixel (gray8, as rast__opaque_row8 takes it) and the
     * clip's rows back to back (the whole stride): one memset for them
     * all, not one a row through the format's entry (the rows above and
     * below a glyph were a twelfth of polygon_mask's fill of it). */
    if (s->row + 1 < to && s->fmt->bits == 8 && s->fmt->value == 1 && s->fmt->row &&
        s->stride == s->clip.x1 - s->clip.x0) {
        /* (glibc stores a block this long by `rep stosb`, which callgrind
         * counts a byte an instruction: a glyph's call is counted 225 K ->
         * 403 K instructions, though 14.0 -> 13.2 us; in pieces of 2 KB,
         * below that threshold, both stay as they were) */
        memset(s->base + (ptrdiff_t)(s->row + 1) * s->stride + s->clip.x0, s->background[0],
               (size_t)(to - s->row - 1) * (size_t)s->stride);
        s->row = to;
        return;
    }
#endif
    for (s->row++; s->row < to; s->row++)
        s->fmt->fill(s->base + (ptrdiff_t)s->row * s->stride, s->clip.x0, s->clip.x1,
                     s->background);
}

static void rast__opaque_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__solid *s = (rast__solid *)user;
    if (y != s->row) { /* a new row (a long row may come in parts) */
        rast__opaque_rows(s, y + 1);
        s->row = y;
    }
    if (s->fmt->row) s->fmt->row(user, y, xs, n);
    else rast__solid_row(user, y, xs, n);
}

#if !defined(__OPTIMIZE_SIZE__)
/* The same for one byte a pixel and a value (gray8): memsets, without the
 * format's entries in between (on a circle's rows those calls were a
 * tenth of the fill).  Not in a build for size: rast__opaque_row does it. */
static void rast__opaque_row8(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__solid *s = (rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    const unsigned char v = s->value[0];
    const uint64_t w = v * (uint64_t)0x0101010101010101u;
    int32_t k;
    if (y != s->row) {
        rast__opaque_rows(s, y);
        s->row = y;
        memset(row + s->clip.x0, s->background[0], (size_t)(s->clip.x1 - s->clip.x0));
    }
    for (k = 0; k < n; k++) rast__run8(row + xs[2 * k], (size_t)(xs[2 * k + 1] - xs[2 * k]), v, w);
}
#endif

void rast__opaque_finish(rast__solid *s)
{
    rast__opaque_rows(s, s->clip.y1);
}

#if !defined(__OPTIMIZE_SIZE__)
int rast__sink_byte_rows(const rast__sink *sink, rast__byte_rows *b)
{
    if (sink->n) return 0;
    if (sink->direct) { /* the solid painter's fast kind (rast__solid_init) */
        b->base = sink->direct;
        b->stride = sink->stride;
        b->value = (unsigned char)sink->value;
        b->background = 0;
        b->opaque = 0;
        b->x0 = sink->cx0;
        b->x1 = sink->cx1;
        b->solid = NULL;
        return 1;
    }
    if (sink->fn == rast__opaque_row || sink->fn == rast__opaque_row8) {
        rast__solid *s = (rast__solid *)sink->user;
        /* one byte a pixel and a value (gray8), the sink's columns the
         * painter's (what rast__opaque_row writes: the clip's row, then
         * the runs) */
        if (s->fmt->bits != 8 || s->fmt->value != 1 || s->fmt->row == NULL ||
            sink->cx0 != s->clip.x0 || sink->cx1 != s->clip.x1)
            return 0;
        b->base = s->base;
        b->stride = s->stride;
        b->value = s->value[0];
        b->background = s->background[0];
        b->opaque = 1;
        b->x0 = s->clip.x0;
        b->x1 = s->clip.x1;
        b->solid = s;
        return 1;
    }
    return 0;
}

void rast__byte_rows_claim(const rast__byte_rows *b, int32_t y0, int32_t y1)
{
    rast__solid *s = b->solid;
    rast__opaque_rows(s, y0);
    s->row = y1 - 1; /* the last row written */
}
#endif

rast_status rast_format_bytes(rast_format format, int32_t *bytes)
{
    if (!bytes) return RAST_E_NULL;
    if (!RAST__FORMAT_KEPT(format)) return RAST_E_FORMAT;
    *bytes = rast__formats[format].value ? rast__formats[format].value
                                         : rast__formats[format].bits / 8;
    return RAST_OK;
}

rast_status rast_format_stride(rast_format format, int32_t width, int32_t *bytes)
{
    int64_t b;
    if (!bytes) return RAST_E_NULL;
    if (!RAST__FORMAT_KEPT(format)) return RAST_E_FORMAT;
    if (width < 0 || width > RAST_MAX_DIM) return RAST_E_SIZE;
    b = ((int64_t)width * rast__formats[format].bits + 7) / 8;
    if (b > INT32_MAX) return RAST_E_SIZE;
    *bytes = (int32_t)b;
    return RAST_OK;
}

rast_status rast_pack_color(rast_format format, const uint8_t *rgba, void *pixel)
{
    if (!rgba || !pixel) return RAST_E_NULL;
    if (!RAST__FORMAT_KEPT(format) || !rast__formats[format].pack)
        return RAST_E_FORMAT;
    rast__formats[format].pack(rgba, (unsigned char *)pixel);
    return RAST_OK;
}

rast_status rast_target_init(rast_target *t, void *pixels, int32_t width,
                             int32_t height, int32_t stride, rast_format format)
{
    rast_target v;
    int32_t row;
    rast_status st;

    if (!t) return RAST_E_NULL;
    if (!RAST__FORMAT_KEPT(format)) return RAST_E_FORMAT;
    if (height < 0 || height > RAST_MAX_DIM) return RAST_E_SIZE;
    st = rast_format_stride(format, width, &row);
    if (st != RAST_OK) return st;
    if (stride < 0 || stride < row) return RAST_E_SIZE;
    if ((uint64_t)stride * (uint64_t)height > (uint64_t)PTRDIFF_MAX) return RAST_E_SIZE;
    if (!pixels && width > 0 && height > 0) return RAST_E_NULL;
    /* 16-bit pixels (COUNT16, RGB565) are uint16_t: every row must start
     * 2-byte aligned. */
    if (rast__formats[format].bits == 16 &&
        (stride % 2 != 0 || (uintptr_t)pixels % sizeof(uint16_t) != 0))
        return RAST_E_SIZE;
    v.pixels = pixels;
    v.width = width;
    v.height = height;
    v.stride = stride;
    v.format = format;
    v.clip.x0 = 0;
    v.clip.y0 = 0;
    v.clip.x1 = width;
    v.clip.y1 = height;
    *t = v;
    return RAST_OK;
}

rast_status rast__span_clip(const rast_rect *clip, rast_rect *out)
{
    rast_rect c = *clip;
    if (c.x0 < -RAST_MAX_DIM || c.x0 > RAST_MAX_DIM || c.x1 < -RAST_MAX_DIM ||
        c.x1 > RAST_MAX_DIM || c.y0 < -RAST_MAX_DIM || c.y0 > RAST_MAX_DIM ||
        c.y1 < -RAST_MAX_DIM || c.y1 > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (c.x1 < c.x0) c.x1 = c.x0;
    if (c.y1 < c.y0) c.y1 = c.y0;
    *out = c;
    return RAST_OK;
}

rast_status rast__target_check(const rast_target *t, rast_rect *clip)
{
    rast_target v;
    rast_status st;
    rast_rect c;

    if (!t) return RAST_E_NULL;
    /* Re-validate through the one constructor: a hand-filled struct gets
     * exactly the checks an initialised one did. */
    st = rast_target_init(&v, t->pixels, t->width, t->height, t->stride, t->format);
    if (st != RAST_OK) return st;
    c = t->clip;
    if (c.x0 < 0) c.x0 = 0;
    if (c.y0 < 0) c.y0 = 0;
    if (c.x1 > t->width) c.x1 = t->width;
    if (c.y1 > t->height) c.y1 = t->height;
    if (c.x1 < c.x0) c.x1 = c.x0;
    if (c.y1 < c.y0) c.y1 = c.y0;
    *clip = c;
    return RAST_OK;
}

rast_status rast__solid_init(rast__solid *s, const rast_target *t, const rast_rect *clip,
                             const void *pixel, const void *background, rast__painter *p)
{
    const rast__format *f = &rast__formats[t->format];
    /* A count has no value to write and no background to restore. */
    if (!f->value && background) return RAST_E_FORMAT;
    if (f->value && !pixel) return RAST_E_NULL;
    memset(s, 0, sizeof *s);
    s->base = (unsigned char *)t->pixels;
    s->stride = t->stride;
    s->fmt = f;
    s->clip = *clip;
    if (f->value) memcpy(s->value, pixel, (size_t)f->value);
    memset(p, 0, sizeof *p);
    p->user = s;
    if (background) {
        memcpy(s->background, background, (size_t)f->value);
        s->row = clip->y0 - 1; /* the last row written */
#if defined(__OPTIMIZE_SIZE__)
        p->full = rast__opaque_row;
#else
        p->full = f->bits == 8 && f->value == 1 && f->row ? rast__opaque_row8 : rast__opaque_row;
#endif
    } else {
        p->full = f->row ? f->row : rast__solid_row;
        p->levels = rast__solid_levels;
        /* One byte a pixel, one byte a value: a full run is a memset. */
        if (f->bits == 8 && f->value == 1) {
            p->bytes = s->base;
            p->stride = s->stride;
            p->value = s->value[0];
        }
    }
    return RAST_OK;
}

static void rast__user_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__user_spans *u = (const rast__user_spans *)user;
    int32_t k;
    for (k = 0; k < n; k++) u->fn(u->user, y, xs[2 * k], xs[2 * k + 1]);
}

static void rast__user_levels(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__user_spans *u = (const rast__user_spans *)user;
    u->cov(u->user, y, x0, x1, cov);
}

void rast__user_painter(rast__user_spans *u, rast_span_fn fn, rast_coverage_span_fn cov,
                        void *user, rast__painter *p)
{
    memset(p, 0, sizeof *p);
    u->fn = fn;
    u->cov = cov;
    u->user = user;
    if (fn) p->full = rast__user_row;
    if (cov) p->levels = rast__user_levels;
    p->user = u;
}

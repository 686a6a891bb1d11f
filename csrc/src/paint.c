/*
 * paint.c - targets and painters: WHAT a span writes.  Painters take a
 * row's spans at once (one call per row, not per span).  The solid painter
 * writes one value over the spans; the opaque painter also writes the
 * background between them, so that every clip pixel is written once.
 *
 * Adding a pixel format means one more row in rast__formats and, when its
 * pixels are not plain byte patterns, one more span function.
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

/* Bytes per pixel, by format.  GRAY8, RGB888 and RGBA8888 are plain byte
 * patterns, which the solid painter writes; COUNT16 has its own painter
 * (rast__count_row), as a packed format (rgb565, mono1) would. */
static const int32_t rast__format_bytes[RAST_FORMAT_COUNT_] = {
    1, /* RAST_FORMAT_GRAY8 */
    3, /* RAST_FORMAT_RGB888 */
    4, /* RAST_FORMAT_RGBA8888 */
    2, /* RAST_FORMAT_COUNT16 */
};

/* Write n pixels of `bytes` bytes each, all equal to `value`, at p. */
static void rast__put(unsigned char *p, const unsigned char *value, int32_t bytes, int32_t n)
{
    if (n <= 0) return;
    if (bytes == 1) {
        memset(p, value[0], (size_t)n);
    } else {
        memcpy(p, value, (size_t)bytes);
        rast__replicate(p, (size_t)bytes, (size_t)n);
    }
}

static void rast__solid_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t k, bpp = s->bytes;
    if (bpp == 1) { /* masks: the common case, kept to a bare memset */
        for (k = 0; k < n; k++) memset(row + xs[2 * k], s->value[0], (size_t)(xs[2 * k + 1] - xs[2 * k]));
        return;
    }
    for (k = 0; k < n; k++)
        rast__put(row + (ptrdiff_t)xs[2 * k] * bpp, s->value, bpp, xs[2 * k + 1] - xs[2 * k]);
}

/* COUNT16: add 1 to every covered pixel, saturating at 65535.  v + 1 - carry
 * keeps the loop free of branches, so the compiler vectorises it. */
static void rast__count_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    uint16_t *row = (uint16_t *)(void *)(s->base + (ptrdiff_t)y * s->stride);
    int32_t k, i;
    for (k = 0; k < n; k++) {
        uint16_t *p = row + xs[2 * k];
        int32_t len = xs[2 * k + 1] - xs[2 * k];
        for (i = 0; i < len; i++) {
            uint32_t v = (uint32_t)p[i] + 1u;
            p[i] = (uint16_t)(v - (v >> 16));
        }
    }
}

/* ---- opaque: every clip pixel written once, value or background --------- */

/* Whole background rows after the last row written, up to (not including)
 * row `to`.  A row with spans is cleared whole too and its spans written
 * over it: the row is in L1 by then, so the second write is nearly free,
 * and it takes one memset per row instead of one per gap. */
static void rast__opaque_rows(rast__solid *s, int32_t to)
{
    int32_t bpp = s->bytes;
    for (s->row++; s->row < to; s->row++)
        rast__put(s->base + (ptrdiff_t)s->row * s->stride + (ptrdiff_t)s->clip.x0 * bpp,
                  s->background, bpp, s->clip.x1 - s->clip.x0);
}

static void rast__opaque_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    rast__solid *s = (rast__solid *)user;
    if (y != s->row) { /* a new row (a long row may come in parts) */
        rast__opaque_rows(s, y + 1);
        s->row = y;
    }
    rast__solid_row(user, y, xs, n);
}

void rast__opaque_finish(rast__solid *s)
{
    rast__opaque_rows(s, s->clip.y1);
}

rast_status rast_format_bytes(rast_format format, int32_t *bytes)
{
    if (!bytes) return RAST_E_NULL;
    if ((unsigned)format >= RAST_FORMAT_COUNT_) return RAST_E_FORMAT;
    *bytes = rast__format_bytes[format];
    return RAST_OK;
}

rast_status rast_target_init(rast_target *t, void *pixels, int32_t width,
                             int32_t height, int32_t stride, rast_format format)
{
    rast_target v;
    int32_t bpp;
    rast_status st;

    if (!t) return RAST_E_NULL;
    st = rast_format_bytes(format, &bpp);
    if (st != RAST_OK) return st;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    if (stride < 0 || (int64_t)stride < (int64_t)width * bpp) return RAST_E_SIZE;
    if ((uint64_t)stride * (uint64_t)height > (uint64_t)PTRDIFF_MAX) return RAST_E_SIZE;
    if (!pixels && width > 0 && height > 0) return RAST_E_NULL;
    /* COUNT16 pixels are uint16_t: every row must start 2-byte aligned. */
    if (format == RAST_FORMAT_COUNT16 &&
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
                             const void *pixel, const void *background, rast__row_fn *fn)
{
    int32_t bpp = rast__format_bytes[t->format];
    if (t->format == RAST_FORMAT_COUNT16) {
        /* A count has no value to write and no background to restore. */
        if (background) return RAST_E_FORMAT;
        memset(s, 0, sizeof *s);
        s->base = (unsigned char *)t->pixels;
        s->stride = t->stride;
        s->bytes = bpp;
        s->clip = *clip;
        *fn = rast__count_row;
        return RAST_OK;
    }
    if (!pixel) return RAST_E_NULL;
    memset(s, 0, sizeof *s);
    s->base = (unsigned char *)t->pixels;
    s->stride = t->stride;
    s->bytes = bpp;
    s->clip = *clip;
    memcpy(s->value, pixel, (size_t)bpp);
    if (background) {
        memcpy(s->background, background, (size_t)bpp);
        s->row = clip->y0 - 1; /* the last row written */
        *fn = rast__opaque_row;
    } else {
        *fn = rast__solid_row;
    }
    return RAST_OK;
}

void rast__user_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__user_spans *u = (const rast__user_spans *)user;
    int32_t k;
    for (k = 0; k < n; k++) u->fn(u->user, y, xs[2 * k], xs[2 * k + 1]);
}

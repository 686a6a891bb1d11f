/*
 * paint.c - targets and solid painters: WHAT a span writes.  Painters take a
 * row's spans at once (one call per row, not per span).
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

static void rast__solid_row1(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride, v = s->value[0];
    int32_t k;
    for (k = 0; k < n; k++) memset(row + xs[2 * k], v, (size_t)(xs[2 * k + 1] - xs[2 * k]));
}

static void rast__solid_row3(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t k;
    for (k = 0; k < n; k++) {
        unsigned char *p = row + (ptrdiff_t)xs[2 * k] * 3;
        memcpy(p, s->value, 3);
        rast__replicate(p, 3, (size_t)(xs[2 * k + 1] - xs[2 * k]));
    }
}

static void rast__solid_row4(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__solid *s = (const rast__solid *)user;
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    int32_t k;
    for (k = 0; k < n; k++) {
        unsigned char *p = row + (ptrdiff_t)xs[2 * k] * 4;
        memcpy(p, s->value, 4);
        rast__replicate(p, 4, (size_t)(xs[2 * k + 1] - xs[2 * k]));
    }
}

static const struct {
    int32_t bytes;
    rast__row_fn solid;
} rast__formats[RAST_FORMAT_COUNT_] = {
    {1, rast__solid_row1}, /* RAST_FORMAT_GRAY8 */
    {3, rast__solid_row3}, /* RAST_FORMAT_RGB888 */
    {4, rast__solid_row4}, /* RAST_FORMAT_RGBA8888 */
};

rast_status rast_format_bytes(rast_format format, int32_t *bytes)
{
    if (!bytes) return RAST_E_NULL;
    if ((unsigned)format >= RAST_FORMAT_COUNT_) return RAST_E_FORMAT;
    *bytes = rast__formats[format].bytes;
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

rast_status rast__solid_init(rast__solid *s, const rast_target *t,
                             const void *pixel, rast__row_fn *fn)
{
    int32_t bpp = rast__formats[t->format].bytes;
    if (!pixel) return RAST_E_NULL;
    s->base = (unsigned char *)t->pixels;
    s->stride = t->stride;
    memset(s->value, 0, sizeof s->value);
    memcpy(s->value, pixel, (size_t)bpp);
    *fn = rast__formats[t->format].solid;
    return RAST_OK;
}

void rast__user_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    const rast__user_spans *u = (const rast__user_spans *)user;
    int32_t k;
    for (k = 0; k < n; k++) u->fn(u->user, y, xs[2 * k], xs[2 * k + 1]);
}

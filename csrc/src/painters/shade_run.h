/*
 * shade_run.h - storing runs of shaded RGBA colours, for the fills that
 * gather a row's colours before writing them (shade_rect.c,
 * shade_poly.c): the format table's `put` (formats.c) does the packing,
 * or, for their blended entries (blend.c), the blend hook does the
 * source-over.  Not installed.
 */
#ifndef RAST_SHADE_RUN_H
#define RAST_SHADE_RUN_H

#include <string.h>

#include "paint.h"

/* Pixels a row's colours are gathered in before they are stored. */
#define RAST__SHADE_RUN 64

/* Where a run of colours goes: stored by the target format's put, or
 * (bput not NULL) handed to bput with bctx (rast__rgba_put_fn, cov NULL:
 * a binary fill's pixels, level 255). */
typedef struct rast__rgba_out {
    void (*put)(unsigned char *row, int32_t x, int32_t n, const unsigned char *rgba);
    rast__rgba_put_fn bput;
    const void *bctx;
} rast__rgba_out;

/* *o for a checked target t whose format has a put (rast__shade_format)
 * or for the blend bput (NULL: stored). */
static inline void rast__rgba_out_init(rast__rgba_out *o, const rast_target *t,
                                       rast__rgba_put_fn bput, const void *bctx)
{
    o->put = rast__formats[t->format].put;
    o->bput = bput;
    o->bctx = bctx;
}

/* Columns [x, x + n) of `row` (the first byte of a row of the target)
 * from n RGBA colours (4 bytes each). */
static inline void rast__put_rgba(const rast__rgba_out *o, unsigned char *row, int32_t x, int32_t n,
                                  const unsigned char *rgba)
{
    if (o->bput)
        o->bput(o->bctx, row, x, n, rgba, NULL);
    else
        o->put(row, x, n, rgba);
}

/* Columns [x, x + n) of `row` all in the one RGBA colour c (4 bytes),
 * a run of RAST__SHADE_RUN at a time. */
static inline void rast__put_rgba_flat(const rast__rgba_out *o, unsigned char *row, int32_t x,
                                       int32_t n, const unsigned char *c)
{
    unsigned char run[4 * RAST__SHADE_RUN];
    int32_t k, m;
    for (k = 0; k < RAST__SHADE_RUN && k < n; k++) memcpy(run + 4 * k, c, 4);
    for (; n > 0; x += m, n -= m) {
        m = n < RAST__SHADE_RUN ? n : RAST__SHADE_RUN;
        rast__put_rgba(o, row, x, m, run);
    }
}

/* RAST_E_FORMAT for a checked target whose format has no colour (COUNT16). */
static inline rast_status rast__shade_format(const rast_target *t)
{
    return rast__formats[t->format].put ? RAST_OK : RAST_E_FORMAT;
}

#endif /* RAST_SHADE_RUN_H */

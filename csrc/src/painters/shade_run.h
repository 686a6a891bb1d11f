/*
 * shade_run.h - storing runs of shaded RGBA colours, for the fills that
 * gather a row's colours before writing them (shade_rect.c,
 * shade_poly.c): the format table's `put` (formats.c) does the packing.
 * Not installed.
 */
#ifndef RAST_SHADE_RUN_H
#define RAST_SHADE_RUN_H

#include "paint.h"

/* Pixels a row's colours are gathered in before they are stored. */
#define RAST__SHADE_RUN 64

/* Columns [x, x + n) of `row` (the first byte of a row of t) from n RGBA
 * colours (4 bytes each).  t's format has a put (checked by the caller:
 * rast__shade_format). */
static inline void rast__put_rgba(const rast_target *t, unsigned char *row, int32_t x, int32_t n,
                                  const unsigned char *rgba)
{
    rast__formats[t->format].put(row, x, n, rgba);
}

/* RAST_E_FORMAT for a checked target whose format has no colour (COUNT16). */
static inline rast_status rast__shade_format(const rast_target *t)
{
    return rast__formats[t->format].put ? RAST_OK : RAST_E_FORMAT;
}

#endif /* RAST_SHADE_RUN_H */

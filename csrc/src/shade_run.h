/*
 * shade_run.h - storing a run of shaded RGBA colours into a target row.
 * Not installed.  (Until branch shade's format table is merged: the first
 * 1, 3 or 4 channels of each colour, as the byte formats hold them.)
 */
#ifndef RAST_SHADE_RUN_H
#define RAST_SHADE_RUN_H

#include "internal.h"

/* Pixels a row's colours are gathered in before they are stored. */
#define RAST__SHADE_RUN 64

/* Columns [x, x + n) of `row` from n RGBA colours (4 bytes each). */
static inline void rast__put_rgba(const rast_target *t, unsigned char *row, int32_t x, int32_t n,
                                  const unsigned char *rgba)
{
    int32_t i, k, bytes = t->format == RAST_FORMAT_GRAY8 ? 1 : t->format == RAST_FORMAT_RGB888 ? 3 : 4;
    for (i = 0; i < n; i++)
        for (k = 0; k < bytes; k++) row[(ptrdiff_t)(x + i) * bytes + k] = rgba[4 * i + k];
}

#endif /* RAST_SHADE_RUN_H */

/*
 * paint.h - the solid painter and target checks shared with the dispatcher.
 */
#ifndef RAST_PAINT_H
#define RAST_PAINT_H

#include "internal.h"

typedef struct rast__solid {
    unsigned char *base;
    ptrdiff_t stride;
    unsigned char value[4];
} rast__solid;

/* Check a target (as rast_target_init would) and cut its clip to it. */
rast_status rast__target_check(const rast_target *t, rast_rect *clip);

/* A painter writing `pixel` (target format bytes) over spans of a checked
 * target: fills *s and the row function to pass it to. */
/* The painter for rast_fill_polygon_spans: hands each span of a row to
 * the user's rast_span_fn. */
typedef struct rast__user_spans {
    rast_span_fn fn;
    void *user;
} rast__user_spans;
void rast__user_row(void *user, int32_t y, const int32_t *xs, int32_t n);

rast_status rast__solid_init(rast__solid *s, const rast_target *t,
                             const void *pixel, rast__row_fn *fn);

#endif /* RAST_PAINT_H */

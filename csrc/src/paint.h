/*
 * paint.h - the solid painter and target checks shared with the dispatcher.
 */
#ifndef RAST_PAINT_H
#define RAST_PAINT_H

#include "internal.h"

typedef struct rast__solid {
    unsigned char *base;
    ptrdiff_t stride;
    int32_t bytes;                /* per pixel */
    unsigned char value[4];       /* inside */
    unsigned char background[4];  /* outside (opaque painter only) */
    rast_rect clip;
    int32_t row;                  /* opaque: the last row written */
} rast__solid;

/* A span callback's clip: coordinates within +-RAST_MAX_DIM (so that its
 * width and height fit int32_t) else RAST_E_SIZE; an inverted one is made
 * empty. */
rast_status rast__span_clip(const rast_rect *clip, rast_rect *c);

/* Check a target (as rast_target_init would) and cut its clip to it. */
rast_status rast__target_check(const rast_target *t, rast_rect *clip);

/* The painter for rast_fill_polygon_spans: hands each span of a row to
 * the user's rast_span_fn. */
typedef struct rast__user_spans {
    rast_span_fn fn;
    void *user;
} rast__user_spans;
void rast__user_row(void *user, int32_t y, const int32_t *xs, int32_t n);

/* A painter writing `pixel` (target format bytes) over spans of a checked
 * target and clip: fills *s and the row function to pass it to.  With a
 * non-NULL `background` it is the opaque painter: every clip pixel is
 * written, and rast__opaque_finish must follow a successful fill.
 * RAST_FORMAT_COUNT16 adds 1 per covered pixel instead and ignores `pixel`
 * (it may be NULL); it has no opaque painter (RAST_E_FORMAT).  Otherwise
 * RAST_E_NULL for a NULL pixel. */
rast_status rast__solid_init(rast__solid *s, const rast_target *t, const rast_rect *clip,
                             const void *pixel, const void *background, rast__row_fn *fn);
void rast__opaque_finish(rast__solid *s);

#endif /* RAST_PAINT_H */

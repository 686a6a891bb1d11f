/*
 * row_canvas.h - a W x H canvas of per-pixel counts that a fill's rows of
 * runs are added into, for the C tests that compare fills pixel for pixel
 * (test_delta.c, test_aet_rule.c), and the check of such a canvas against
 * the brute-force reference (ref.h).  The includer defines W and H first.
 * A run out of the clip, empty or out of order, or a row before the last,
 * marks the canvas bad instead of being drawn.
 */
#ifndef RAST_TEST_ROW_CANVAS_H
#define RAST_TEST_ROW_CANVAS_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "ref.h"
#include "base/internal.h"
#include "rastrum.h"

typedef struct canvas {
    unsigned char px[H][W];
    int bad; /* a run out of the clip, empty, or out of order */
    int32_t last_y;
} canvas;

static void put_row(void *user, int32_t y, const int32_t *xs, int32_t n)
{
    canvas *c = (canvas *)user;
    int32_t k, x;
    if (y < c->last_y || y < 0 || y >= H) {
        c->bad = 1;
        return;
    }
    c->last_y = y;
    for (k = 0; k < n; k++) {
        if (xs[2 * k] >= xs[2 * k + 1] || xs[2 * k] < 0 || xs[2 * k + 1] > W) {
            c->bad = 1;
            return;
        }
        for (x = xs[2 * k]; x < xs[2 * k + 1]; x++) c->px[y][x]++;
    }
}

/* The AET filler's runs of poly by `how` (RAST__AET_BY_RULE, _SWEEP or
 * _DELTA: rast__aet_fill_by) into c, cleared first; the status. */
static rast_status canvas_fill(canvas *c, const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                               rast_fill_rule rule, const rast_rect *clip, void *scratch, size_t bytes, int how)
{
    rast__arena arena = rast__arena_of(scratch, bytes);
    rast__painter p;
    rast__sink sink;
    memset(c, 0, sizeof *c);
    c->last_y = -1;
    memset(&p, 0, sizeof p);
    p.full = put_row;
    p.user = c;
    rast__sink_init(&sink, &p, clip);
    return rast__aet_fill_by(poly, npoints, g, rule, clip, &sink, &arena, how);
}

/* Each pixel of c once against the reference: inside the clip and inside
 * the rings by the rule (even-odd: an odd count of crossings, non-zero: a
 * winding other than 0), else outside.  The first pixel that differs is
 * printed (iter names the case) and 0 returned; 1 when all agree. */
static int canvas_matches_ref(const canvas *c, const rast_point *pts, const uint32_t *sizes,
                              uint32_t nrings, int s, int center, int textbook, rast_fill_rule rule,
                              const rast_rect *clip, int iter)
{
    int32_t i, j;
    for (j = 0; j < H; j++) {
        for (i = 0; i < W; i++) {
            int cr, w = ref_winding(pts, sizes, nrings, s, center, textbook, i, j, &cr);
            int in = i >= clip->x0 && i < clip->x1 && j >= clip->y0 && j < clip->y1 &&
                     (rule == RAST_RULE_EVENODD ? (cr & 1) : w != 0);
            if (c->px[j][i] != in) {
                fprintf(stderr, "iter %d: pixel (%d, %d) is %d, the reference %d\n", iter, (int)i,
                        (int)j, c->px[j][i], in);
                return 0;
            }
        }
    }
    return 1;
}

#endif

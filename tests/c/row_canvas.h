/*
 * row_canvas.h - a W x H canvas of per-pixel counts that a fill's rows of
 * runs are added into, for the C tests that compare fills pixel for pixel
 * (test_delta.c, test_aet_rule.c).  The includer defines W and H first.
 * A run out of the clip, empty or out of order, or a row before the last,
 * marks the canvas bad instead of being drawn.
 */
#ifndef RAST_TEST_ROW_CANVAS_H
#define RAST_TEST_ROW_CANVAS_H

#include <stdint.h>

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

#endif

/*
 * firmware_lines.c - lines on firmware: a graph of 40 samples as one
 * polyline and a frame around it as a closed one, Bresenham's exact lines
 * with endpoints in 1/16 pixel, into the 320 x 64 RGB565 picture of
 * firmware_band.h, band by band, through rast_draw_polyline (no scratch).
 * Built with its configuration header firmware_lines_conf.h:
 *
 *     cc -DRAST_CONFIG_HEADER='"firmware_lines_conf.h"' -Iexamples \
 *        -Ibuild/single examples/firmware_lines.c build/single/rastrum.c
 */
#include "firmware_band.h"

#define S 4
#define SAMPLES 40

static int draw_band(const rast_target *t, int32_t y0)
{
    static const rast_line_opts opts = {RAST_LINE_BRESENHAM, S, RAST_SAMPLE_CENTER};
    static const uint16_t green = 0x07E0, grey = 0x8410;
    rast_point graph[SAMPLES], frame[4];
    uint32_t v = 12345;
    int32_t k, dy = y0 << S;
    for (k = 0; k < SAMPLES; k++) { /* a random walk from an LCG */
        v = v * 1664525u + 1013904223u;
        graph[k].x = (8 + 7 * k) << S;
        graph[k].y = (int32_t)(120 + (v >> 23) + (k & 3) * 60) - dy;
    }
    frame[0].x = 4 << S, frame[0].y = (2 << S) - dy;
    frame[1].x = 315 << S, frame[1].y = (2 << S) - dy;
    frame[2].x = 315 << S, frame[2].y = (61 << S) - dy;
    frame[3].x = 4 << S, frame[3].y = (61 << S) - dy;
    return (rast_draw_polyline(t, frame, 4, 1, &opts, &grey) != RAST_OK) |
           (rast_draw_polyline(t, graph, SAMPLES, 0, &opts, &green) != RAST_OK);
}

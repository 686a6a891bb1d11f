/*
 * firmware_min.c - the smallest useful rastrum firmware: a polygon with a
 * hole, filled with the AET once under even-odd and once under non-zero,
 * into a 320 x 64 RGB565 picture drawn as four bands of 16 rows
 * (firmware_band.h), through rast_fill_polygon_opaque and
 * rast_fill_polygon.
 *
 * The library is compiled with the example's own configuration header,
 * firmware_min_conf.h (the AET, RGB565, nothing else):
 *
 *     cc -DRAST_CONFIG_HEADER='"firmware_min_conf.h"' -Iexamples \
 *        -Ibuild/single examples/firmware_min.c build/single/rastrum.c
 *
 * and make firmware-check prints the code it links for a Cortex-M0.
 * Integer only, no heap, no stdio.
 */
#include "firmware_band.h"

#define S 4 /* vertices in 1/16 pixel */

/* Outer ring and hole, both clockwise on screen (y down): even-odd leaves
 * the hole empty, non-zero fills it (the winding number there is 2). */
static const rast_point shape[8] = {
    {10 << S, 4 << S},  {150 << S, 8 << S},  {140 << S, 60 << S}, {20 << S, 56 << S},
    {50 << S, 20 << S}, {110 << S, 22 << S}, {104 << S, 44 << S}, {56 << S, 40 << S}};
static const uint32_t rings[2] = {4, 4};

/* 8 vertices in a band of 16 rows, sized at compile time */
static uint64_t scratch[(RAST_AET_SCRATCH_BOUND(8, FIRMWARE_BAND) + 7) / 8];

/* The shape moved right by dx pixels and up by the band's first row (whole
 * pixels: its pixels move with it exactly), filled under `rule`; with
 * `paper`, every other pixel of the band is cleared to it. */
static int fill(const rast_target *t, rast_fill_rule rule, int32_t dx, int32_t y0,
                const uint16_t *ink, const uint16_t *paper)
{
    rast_fill_opts opts = {RAST_ALGO_AET, RAST_RULE_EVENODD, S, RAST_SAMPLE_CENTER,
                           RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT};
    rast_point p[8];
    rast_polygon poly;
    int k;
    for (k = 0; k < 8; k++) {
        p[k].x = shape[k].x + (dx << S);
        p[k].y = shape[k].y - (y0 << S);
    }
    poly.points = p;
    poly.ring_sizes = rings;
    poly.nrings = 2;
    opts.rule = rule;
    if (paper)
        return rast_fill_polygon_opaque(t, &poly, &opts, ink, paper, scratch, sizeof scratch) !=
               RAST_OK;
    return rast_fill_polygon(t, &poly, &opts, ink, scratch, sizeof scratch) != RAST_OK;
}

static int draw_band(const rast_target *t, int32_t y0)
{
    static const uint16_t red = 0xF800, blue = 0x001F, white = 0xFFFF;
    return fill(t, RAST_RULE_EVENODD, 0, y0, &red, &white) | /* left, on white */
           fill(t, RAST_RULE_NONZERO, 160, y0, &blue, NULL); /* right */
}

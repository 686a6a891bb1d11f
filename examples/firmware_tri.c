/*
 * firmware_tri.c - a triangle batch on firmware: a strip of a sine-like
 * height field as 2 x 15 triangles sharing their edges (no pixel drawn
 * twice, none missed), each column of quads in its own colour, filled with
 * the sweep algorithm into the 320 x 64 RGB565 picture of firmware_band.h,
 * band by band, through rast_fill_triangles (no scratch: the sweep needs
 * none).  Built with its configuration header firmware_tri_conf.h:
 *
 *     cc -DRAST_CONFIG_HEADER='"firmware_tri_conf.h"' -Iexamples \
 *        -Ibuild/single examples/firmware_tri.c build/single/rastrum.c
 */
#include "firmware_band.h"

#define S 4
#define QUADS 15

/* Heights of the strip's top edge, in 1/16 pixel. */
static const int32_t top[QUADS + 1] = {130, 260, 410, 300, 150, 90,  200, 380,
                                       460, 350, 180, 60,  140, 330, 420, 250};

static int draw_band(const rast_target *t, int32_t y0)
{
    static const rast_tri_opts opts = {RAST_TRI_SWEEP, S, RAST_SAMPLE_CENTER, RAST_ROUND_EXACT,
                                       RAST_BOUNDARY_EXACT};
    rast_point tri[6];
    uint16_t ink;
    int32_t q, x0, x1, bottom = (60 - y0) << S;
    int bad = 0;
    for (q = 0; q < QUADS; q++) {
        x0 = (10 + 20 * q) << S;
        x1 = (30 + 20 * q) << S;
        /* the quad (x0, top q) (x1, top q+1) (x1, bottom) (x0, bottom) as
         * two triangles sharing its diagonal */
        tri[0].x = x0, tri[0].y = top[q] + 123 - (y0 << S);
        tri[1].x = x1, tri[1].y = top[q + 1] + 123 - (y0 << S);
        tri[2].x = x1, tri[2].y = bottom;
        tri[3] = tri[0];
        tri[4] = tri[2];
        tri[5].x = x0, tri[5].y = bottom;
        ink = (uint16_t)(0x0841u * (uint16_t)(q + 1));
        bad |= rast_fill_triangles(t, tri, 2, &opts, &ink, NULL, 0) != RAST_OK;
    }
    return bad;
}

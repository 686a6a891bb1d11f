/*
 * firmware_gauge.c - an anti-aliased gauge on firmware: a stroked arc of
 * cubic Beziers (the track, butt caps), its first 126 degrees stroked
 * again with round caps (the value) and a needle, each outline built by
 * rast_path_stroke in static memory (no heap, no float) and drawn with
 * exact area coverage (rast_fill_polygon_aa, non-zero) into the
 * 320 x 64 RGB565 picture of firmware_band.h, band by band.  Points in
 * 1/16 pixel.  Built with its configuration header firmware_gauge_conf.h:
 *
 *     cc -DRAST_CONFIG_HEADER='"firmware_gauge_conf.h"' -Iexamples \
 *        -Ibuild/single examples/firmware_gauge.c build/single/rastrum.c
 */
#include "firmware_band.h"

#define S 4
#define MAXPTS 1400
#define MAXRINGS 400
#define SCRATCH (600u * 1024u)

static rast_point outline[MAXPTS];
static uint32_t rings[MAXRINGS];
static uint64_t scratch[SCRATCH / 8];

/* Stroke `n` verbs of `verbs` over pts (shifted up by dy units) and fill
 * the outline anti-aliased with `color`; 0 on success. */
static int stroke_fill(const rast_target *t, const uint8_t *verbs, uint32_t nv, const rast_point *pts,
                       uint32_t np, int32_t dy, const rast_stroke_style *st, uint16_t color)
{
    static const rast_coverage_opts opts = {RAST_AA_AREA, RAST_RULE_NONZERO, S, RAST_SAMPLE_CENTER};
    rast_point moved[8];
    rast_path path;
    rast_polygon poly;
    uint32_t k, onp, onr;
    size_t need;
    for (k = 0; k < np; k++) {
        moved[k].x = pts[k].x;
        moved[k].y = pts[k].y - dy;
    }
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = moved;
    path.npoints = np;
    if (rast_path_stroke_size(&path, st, &onp, &onr) != RAST_OK || onp > MAXPTS || onr > MAXRINGS) return 1;
    if (rast_path_stroke(&path, st, outline, MAXPTS, rings, MAXRINGS, &poly) != RAST_OK) return 1;
    if (rast_coverage_scratch_size(&opts, onp, FIRMWARE_W, FIRMWARE_BAND, &need) != RAST_OK || need > SCRATCH)
        return 1;
    return rast_fill_polygon_aa(t, &poly, &opts, &color, scratch, SCRATCH) != RAST_OK;
}

static int draw_band(const rast_target *t, int32_t y0)
{
    /* centre (160, 58) px, radius 44 px: two quarter circles as cubics */
    static const uint8_t arc[3] = {RAST_PATH_MOVE, RAST_PATH_CUBIC, RAST_PATH_CUBIC};
    static const rast_point track[7] = {{1856, 928}, {1856, 539}, {2171, 224}, {2560, 224},
                                        {2949, 224}, {3264, 539}, {3264, 928}};
    static const rast_point value[7] = {{1856, 928}, {1856, 539}, {2171, 224}, {2560, 224},
                                        {2785, 224}, {2997, 332}, {3130, 514}};
    static const uint8_t line[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
    static const rast_point needle[2] = {{2560, 928}, {2974, 627}};
    /* 8 px wide, bevel joins (the arc's turns are tiny), tolerance 1/8 px */
    static const rast_stroke_style track_st = {8 << S, RAST_JOIN_BEVEL, RAST_CAP_BUTT, 4 << 16, 2, NULL, 0, 0};
    static const rast_stroke_style value_st = {8 << S, RAST_JOIN_BEVEL, RAST_CAP_ROUND, 4 << 16, 2, NULL, 0, 0};
    static const rast_stroke_style needle_st = {2 << S, RAST_JOIN_ROUND, RAST_CAP_ROUND, 4 << 16, 2, NULL, 0, 0};
    int32_t dy = y0 << S;
    return stroke_fill(t, arc, 3, track, 7, dy, &track_st, 0x4208) |   /* dark grey */
           stroke_fill(t, arc, 3, value, 7, dy, &value_st, 0x07E0) |   /* green */
           stroke_fill(t, line, 2, needle, 2, dy, &needle_st, 0xFFFF); /* white */
}

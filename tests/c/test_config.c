/* test_config.c - a build configuration (csrc/src/base/config.h) cuts
 * features cleanly and changes nothing else.
 *
 * Built as every test (the default configuration: everything kept), it
 * checks that each call of the list below succeeds.  Built with
 * -DRAST_CONFIG_HEADER='"config_cut.h"' against the one-file library
 * compiled the same way (make test-config), it checks that the calls
 * naming a feature config_cut.h leaves out return the status an unknown
 * value gets and leave the target untouched.  Both builds print a hash of
 * the pixels of every kept feature's scene; make test-config requires the
 * two lists to be equal, so a kept feature draws what the full library
 * draws. */
#include <string.h>

#include "check.h"
#include "rastrum.h"

#ifdef RAST_CONFIG_HEADER
#define CUT 1
#else
#define CUT 0
#endif

#define W 48
#define H 40

static uint64_t scratch[1 << 15];
static uint32_t pix[H][W]; /* 4 bytes a pixel: room for every format */
static uint32_t before[H][W];

static uint32_t hash_pixels(void)
{
    uint32_t h = 2166136261u;
    const unsigned char *p = (const unsigned char *)pix;
    size_t i;
    for (i = 0; i < sizeof pix; i++) h = (h ^ p[i]) * 16777619u;
    return h;
}

/* A random picture to draw over: untouched means equal to it. */
static void noise(void)
{
    int x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) pix[y][x] = rng() ^ (rng() << 8);
    memcpy(before, pix, sizeof pix);
}

static int untouched(void)
{
    return memcmp(before, pix, sizeof pix) == 0;
}

/* A target over pix in `format` (hand-filled: a cut format cannot be
 * initialised, and the fill must refuse it itself). */
static rast_target target(rast_format format)
{
    rast_target t;
    t.pixels = pix;
    t.width = W;
    t.height = H;
    t.stride = (int32_t)sizeof pix[0];
    t.format = format;
    t.clip.x0 = 0;
    t.clip.y0 = 0;
    t.clip.x1 = W;
    t.clip.y1 = H;
    return t;
}

/* A polygon with a hole, in 1/16 pixel: both rings the same way round. */
static const rast_point shape[8] = {{3 * 16 + 5, 2 * 16},   {44 * 16, 5 * 16 + 9},
                                    {40 * 16 + 3, 37 * 16}, {5 * 16, 33 * 16 + 7},
                                    {12 * 16, 10 * 16},     {30 * 16 + 8, 12 * 16},
                                    {28 * 16, 26 * 16 + 3}, {14 * 16 + 1, 24 * 16}};
static const uint32_t rings[2] = {4, 4};
static const rast_polygon poly = {shape, rings, 2};
static const rast_point tris[6] = {{2 * 16, 3 * 16}, {45 * 16 + 7, 9 * 16}, {20 * 16, 38 * 16},
                                   {40 * 16, 1 * 16}, {47 * 16, 30 * 16}, {30 * 16 + 5, 20 * 16}};

static void scene(const char *name, rast_status st)
{
    CHECK(st == RAST_OK);
    printf("scene %s %08lx\n", name, (unsigned long)hash_pixels());
}

/* ---- kept by config_cut.h: drawn in both builds, hashes compared ------- */
static void kept(void)
{
    static const uint16_t ink = 0xA5C3;
    static const rast_algorithm algos[2] = {RAST_ALGO_AET, RAST_ALGO_EDGEFLAG};
    rast_fill_opts o;
    rast_tri_opts to;
    rast_line_opts lo;
    rast_coverage_opts co;
    rast_target t, g;
    char name[64];
    int a, r, b;

    for (a = 0; a < 2; a++)
        for (r = 0; r < 2; r++)
            for (b = 0; b < 2; b++) {
                memset(&o, 0, sizeof o);
                o.algorithm = algos[a];
                o.rule = (rast_fill_rule)r;
                o.subpixel_bits = 4;
                o.sample = RAST_SAMPLE_CENTER;
                o.boundary = b ? RAST_BOUNDARY_CLOSED : RAST_BOUNDARY_EXACT;
                memset(pix, 0, sizeof pix);
                t = target(RAST_FORMAT_RGB565);
                sprintf(name, "polygon-%d-%d-%d", a, r, b);
                scene(name, rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch));
            }
    /* GRAY8 in the first half of the rows' bytes, opaque */
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    memset(pix, 0, sizeof pix);
    CHECK(rast_target_init(&g, pix, W, H, (int32_t)sizeof pix[0], RAST_FORMAT_GRAY8) == RAST_OK);
    {
        static const unsigned char on = 200, off = 7;
        scene("gray8-opaque",
              rast_fill_polygon_opaque(&g, &poly, &o, &on, &off, scratch, sizeof scratch));
    }
    memset(&to, 0, sizeof to);
    to.subpixel_bits = 4;
    memset(pix, 0, sizeof pix);
    t = target(RAST_FORMAT_RGB565);
    scene("triangles-edge", rast_fill_triangles(&t, tris, 2, &to, &ink, scratch, sizeof scratch));
    memset(&lo, 0, sizeof lo);
    lo.subpixel_bits = 4;
    memset(pix, 0, sizeof pix);
    scene("polyline", rast_draw_polyline(&t, shape, 4, 1, &lo, &ink));
    memset(&co, 0, sizeof co);
    co.subpixel_bits = 4;
    co.rule = RAST_RULE_NONZERO;
    memset(pix, 0, sizeof pix);
    scene("aa-area", rast_fill_polygon_aa(&t, &poly, &co, &ink, scratch, sizeof scratch));
}

/* ---- left out by config_cut.h: refused there, drawn here ---------------- */

/* `st` is what the call returned: with the cut, `cut_status` and the
 * pixels untouched; in the full build, RAST_OK. */
static void expect(rast_status st, rast_status cut_status)
{
    if (CUT) {
        CHECK(st == cut_status);
        CHECK(untouched());
    } else {
        CHECK(st == RAST_OK);
    }
}

static void left_out(void)
{
    static const uint16_t ink = 0x1234;
    static const uint8_t colors[6 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                          9, 9, 9, 9,   99, 9, 9, 9, 9,   99, 9, 9};
    static const rast_point64 shape64[3] = {{0, 0}, {40 << 4, 3 << 4}, {7 << 4, 30 << 4}};
    static const uint32_t three = 3;
    const rast_polygon64 poly64 = {shape64, &three, 1};
    rast_fill_opts o;
    rast_tri_opts to;
    rast_line_opts lo;
    rast_coverage_opts co;
    rast_shade_opts so;
    rast_target t, t2;
    rast_prim prim;
    const char *name;
    uint32_t rules;
    int32_t bytes;
    size_t need;
    int a;

    t = target(RAST_FORMAT_RGB565);
    /* polygon algorithms */
    for (a = 0; a < RAST_ALGO_COUNT_; a++) {
        if (a == RAST_ALGO_AET || a == RAST_ALGO_EDGEFLAG) continue;
        memset(&o, 0, sizeof o);
        o.algorithm = (rast_algorithm)a;
        o.subpixel_bits = 4;
        noise();
        expect(rast_algorithm_info(o.algorithm, &name, &rules), RAST_E_ALGORITHM);
        expect(rast_scratch_size(&o, 8, W, H, &need), RAST_E_ALGORITHM);
        expect(rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch), RAST_E_ALGORITHM);
    }
    /* boundary modes */
    memset(&o, 0, sizeof o);
    o.boundary = RAST_BOUNDARY_CONSERVATIVE;
    noise();
    expect(rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch), RAST_E_ARG);
    /* formats */
    for (a = 0; a < RAST_FORMAT_COUNT_; a++) {
        static const uint8_t rgba[4] = {1, 2, 3, 4};
        uint32_t px = 0;
        if (a == RAST_FORMAT_GRAY8 || a == RAST_FORMAT_RGB565) continue;
        memset(&o, 0, sizeof o);
        noise();
        expect(rast_format_bytes((rast_format)a, &bytes), RAST_E_FORMAT);
        expect(rast_format_stride((rast_format)a, W, &bytes), RAST_E_FORMAT);
        if (a != RAST_FORMAT_COUNT16)
            expect(rast_pack_color((rast_format)a, rgba, &px), RAST_E_FORMAT);
        expect(rast_target_init(&t2, pix, W, H, (int32_t)sizeof pix[0], (rast_format)a),
               RAST_E_FORMAT);
        t2 = target((rast_format)a);
        expect(rast_fill_polygon(&t2, &poly, &o, &ink, scratch, sizeof scratch), RAST_E_FORMAT);
    }
    /* triangle algorithms */
    memset(&to, 0, sizeof to);
    for (a = RAST_TRI_SWEEP; a < RAST_TRI_COUNT_; a++) {
        to.algorithm = (rast_tri_algorithm)a;
        noise();
        expect(rast_tri_algorithm_info(to.algorithm, &name), RAST_E_ALGORITHM);
        expect(rast_tri_scratch_size(&to, W, H, &need), RAST_E_ALGORITHM);
        expect(rast_fill_triangles(&t, tris, 2, &to, &ink, scratch, sizeof scratch),
               RAST_E_ALGORITHM);
    }
    /* line algorithms, alone and in a scene */
    memset(&lo, 0, sizeof lo);
    lo.algorithm = RAST_LINE_DDA;
    noise();
    expect(rast_draw_line(&t, shape[0], shape[2], &lo, &ink), RAST_E_ALGORITHM);
    memset(&prim, 0, sizeof prim);
    prim.kind = RAST_PRIM_POLYLINE;
    prim.points = shape;
    prim.count = 4;
    prim.line = &lo;
    prim.pixel = &ink;
    expect(rast_render_bands(&t, &prim, 1, 8, scratch, sizeof scratch, NULL), RAST_E_ALGORITHM);
    /* anti-aliasing methods */
    memset(&co, 0, sizeof co);
    co.method = RAST_AA_SS4;
    noise();
    expect(rast_aa_method_info(co.method, &name), RAST_E_ARG);
    expect(rast_fill_polygon_aa(&t, &poly, &co, &ink, scratch, sizeof scratch), RAST_E_ARG);
    /* shading */
    memset(&to, 0, sizeof to);
    memset(&so, 0, sizeof so);
    noise();
    expect(rast_fill_triangles_shaded(&t, tris, 2, colors, NULL, NULL, &to, &so, scratch,
                                      sizeof scratch),
           RAST_E_FORMAT);
    /* 64-bit vertices */
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    noise();
    expect(rast_scratch_size64(&o, 3, W, H, &need), RAST_E_WIDE);
    expect(rast_fill_polygon64(&t, &poly64, &o, &ink, scratch, sizeof scratch), RAST_E_WIDE);
}

int main(void)
{
    kept();
    left_out();
    return check_report(CUT ? "test_config (cut: config_cut.h)" : "test_config");
}

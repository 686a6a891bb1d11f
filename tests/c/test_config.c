/* test_config.c - a build configuration (csrc/src/base/config.h) cuts
 * features cleanly and changes nothing else.
 *
 * What the build keeps is read from the same macros the library reads
 * (base/config.h, with the RAST_CONFIG_HEADER the build was given, if
 * any).  For every value of every configurable argument the test makes the
 * calls that name it: a kept value must work, a left-out one must get the
 * status an unknown value gets and leave the target untouched.  Built as
 * every test (the default configuration) everything must work; make
 * test-config builds it against the one-file library compiled with
 * tests/c/config_cut.h and with examples/firmware_min_conf.h.  Every build prints
 * a hash of the pixels of each scene it keeps; make test-config requires
 * the cut builds' lines to be among the full build's, so a kept feature
 * draws what the full library draws. */
#include <string.h>

#include "check.h"
#include "rastrum.h"
#include "base/config.h" /* the build's RAST_CONFIG_* and RAST__HAS */

#define W 48
#define H 40

static uint64_t scratch[1 << 15];
static uint32_t pix[H][W]; /* 4 bytes a pixel: room for every format */
static uint32_t before[H][W];
static const uint32_t ink = 0xA5C3E1F0u; /* any format's value: its first bytes */

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

/* A clear picture to draw on (scenes hash it). */
static void blank(void)
{
    memset(pix, 0, sizeof pix);
    memcpy(before, pix, sizeof pix);
}

static int untouched(void)
{
    return memcmp(before, pix, sizeof pix) == 0;
}

/* A target over pix in `format`, hand-filled (a left-out format cannot be
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

/* The first kept value below n in mask m, or -1. */
static int first_kept(unsigned long m, int n)
{
    int v;
    for (v = 0; v < n; v++)
        if (RAST__HAS(m, v)) return v;
    return -1;
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
static const uint8_t colors[6 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                      9, 9, 9, 9,   99, 9, 9, 9, 9,   99, 9, 9};

/* A call's status `st` for a value that is `kept` or not: RAST_OK, or
 * `cut_status` with the pixels untouched.  A kept value's picture is
 * printed as a scene line (name) when `name` is not NULL. */
static void expect(rast_status st, int kept, rast_status cut_status, const char *name)
{
    if (kept) {
        if (st != RAST_OK) fprintf(stderr, "%s: status %d\n", name ? name : "(a query)", (int)st);
        CHECK(st == RAST_OK);
        if (name) printf("scene %s %08lx\n", name, (unsigned long)hash_pixels());
    } else {
        CHECK(st == cut_status);
        CHECK(untouched());
    }
}

static void polygons(int fmt)
{
    int a, r, b, algo = first_kept(RAST_CONFIG_ALGORITHMS, RAST_ALGO_COUNT_);
    char name[64];
    const char *s;
    uint32_t rules;
    size_t need;
    rast_fill_opts o;
    rast_target t = target((rast_format)fmt);

    for (a = 0; a < RAST_ALGO_COUNT_; a++) {
        int kept = RAST__HAS(RAST_CONFIG_ALGORITHMS, a);
        memset(&o, 0, sizeof o);
        o.algorithm = (rast_algorithm)a;
        o.subpixel_bits = 4;
        o.sample = RAST_SAMPLE_CENTER;
        noise();
        expect(rast_algorithm_info(o.algorithm, &s, &rules), kept, RAST_E_ALGORITHM, NULL);
        expect(rast_scratch_size(&o, 8, W, H, &need), kept, RAST_E_ALGORITHM, NULL);
        if (fmt < 0) continue;
        for (r = 0; r < 2; r++) {
            o.rule = (rast_fill_rule)r;
            if (kept && rast_algorithm_info(o.algorithm, NULL, &rules) == RAST_OK &&
                !(rules & (1u << r)))
                continue; /* even-odd only */
            blank();
            sprintf(name, "polygon-%d-%d-format%d", a, r, fmt);
            expect(rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch), kept,
                   RAST_E_ALGORITHM, name);
        }
    }
    if (algo < 0 || fmt < 0) return;
    for (b = RAST_BOUNDARY_CLOSED; b <= RAST_BOUNDARY_CONSERVATIVE; b++) {
        memset(&o, 0, sizeof o);
        o.algorithm = (rast_algorithm)algo;
        o.subpixel_bits = 4;
        o.boundary = (rast_boundary)b;
        blank();
        sprintf(name, "boundary-%d-%d-format%d", b, algo, fmt);
        expect(rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch),
               RAST__HAS(RAST_CONFIG_BOUNDARIES, b), RAST_E_ARG, name);
    }
    /* 64-bit vertices (the AET only) */
    if (RAST__HAS(RAST_CONFIG_ALGORITHMS, RAST_ALGO_AET)) {
        static const rast_point64 shape64[3] = {{0, 0}, {40 << 4, 3 << 4}, {7 << 4, 30 << 4}};
        static const uint32_t three = 3;
        const rast_polygon64 poly64 = {shape64, &three, 1};
        memset(&o, 0, sizeof o);
        o.subpixel_bits = 4;
        noise();
        expect(rast_scratch_size64(&o, 3, W, H, &need), RAST_CONFIG_POLYGON64, RAST_E_WIDE, NULL);
        blank();
        sprintf(name, "polygon64-format%d", fmt);
        expect(rast_fill_polygon64(&t, &poly64, &o, &ink, scratch, sizeof scratch),
               RAST_CONFIG_POLYGON64, RAST_E_WIDE, name);
    }
}

static void formats(void)
{
    static const uint8_t rgba[4] = {1, 2, 3, 200};
    int f, algo = first_kept(RAST_CONFIG_ALGORITHMS, RAST_ALGO_COUNT_);
    char name[64];
    int32_t bytes;
    uint32_t px;
    rast_fill_opts o;
    rast_target t;
    for (f = 0; f < RAST_FORMAT_COUNT_; f++) {
        int kept = RAST__HAS(RAST_CONFIG_FORMATS, f);
        noise();
        expect(rast_format_bytes((rast_format)f, &bytes), kept, RAST_E_FORMAT, NULL);
        expect(rast_format_stride((rast_format)f, W, &bytes), kept, RAST_E_FORMAT, NULL);
        if (f != RAST_FORMAT_COUNT16)
            expect(rast_pack_color((rast_format)f, rgba, &px), kept, RAST_E_FORMAT, NULL);
        expect(rast_target_init(&t, pix, W, H, (int32_t)sizeof pix[0], (rast_format)f), kept,
               RAST_E_FORMAT, NULL);
        if (algo < 0) continue;
        memset(&o, 0, sizeof o);
        o.algorithm = (rast_algorithm)algo;
        o.subpixel_bits = 4;
        t = target((rast_format)f);
        blank();
        sprintf(name, "format-%d-%d", f, algo);
        expect(rast_fill_polygon(&t, &poly, &o, &ink, scratch, sizeof scratch), kept,
               RAST_E_FORMAT, name);
    }
}

static void triangles(int fmt)
{
    int a, tri = first_kept(RAST_CONFIG_TRI_ALGORITHMS, RAST_TRI_COUNT_);
    char name[64];
    const char *s;
    size_t need;
    rast_tri_opts to;
    rast_shade_opts so;
    rast_target t = target((rast_format)fmt);
    for (a = 0; a < RAST_TRI_COUNT_; a++) {
        int kept = RAST__HAS(RAST_CONFIG_TRI_ALGORITHMS, a);
        memset(&to, 0, sizeof to);
        to.algorithm = (rast_tri_algorithm)a;
        to.subpixel_bits = 4;
        noise();
        expect(rast_tri_algorithm_info(to.algorithm, &s), kept, RAST_E_ALGORITHM, NULL);
        expect(rast_tri_scratch_size(&to, W, H, &need), kept, RAST_E_ALGORITHM, NULL);
        if (fmt < 0) continue;
        blank();
        sprintf(name, "triangles-%d-format%d", a, fmt);
        expect(rast_fill_triangles(&t, tris, 2, &to, &ink, scratch, sizeof scratch), kept,
               RAST_E_ALGORITHM, name);
    }
    if (tri < 0 || fmt < 0) return;
    memset(&to, 0, sizeof to);
    to.algorithm = (rast_tri_algorithm)tri;
    to.subpixel_bits = 4;
    memset(&so, 0, sizeof so);
    blank();
    sprintf(name, "shaded-%d-format%d", tri, fmt);
    expect(rast_fill_triangles_shaded(&t, tris, 2, colors, NULL, NULL, &to, &so, scratch,
                                      sizeof scratch),
           RAST_CONFIG_SHADING, RAST_E_FORMAT, name);
}

static void lines(int fmt)
{
    int a;
    char name[64];
    rast_line_opts lo;
    rast_prim prim;
    rast_target t = target((rast_format)fmt);
    if (fmt < 0) return;
    for (a = 0; a < RAST_LINE_COUNT_; a++) {
        int kept = RAST__HAS(RAST_CONFIG_LINE_ALGORITHMS, a);
        memset(&lo, 0, sizeof lo);
        lo.algorithm = (rast_line_algorithm)a;
        lo.subpixel_bits = 4;
        blank();
        sprintf(name, "polyline-%d-format%d", a, fmt);
        expect(rast_draw_polyline(&t, shape, 4, 1, &lo, &ink), kept, RAST_E_ALGORITHM, name);
        memset(&prim, 0, sizeof prim);
        prim.kind = RAST_PRIM_POLYLINE;
        prim.points = shape;
        prim.count = 4;
        prim.line = &lo;
        prim.pixel = &ink;
        blank();
        sprintf(name, "bands-polyline-%d-format%d", a, fmt);
        expect(rast_render_bands(&t, &prim, 1, 8, scratch, sizeof scratch, NULL), kept,
               RAST_E_ALGORITHM, name);
    }
}

static void coverage(int fmt)
{
    int m;
    char name[64];
    const char *s;
    rast_coverage_opts co;
    rast_shade_opts so;
    rast_target t = target((rast_format)fmt);
    for (m = 0; m < RAST_AA_COUNT_; m++) {
        int kept = RAST__HAS(RAST_CONFIG_AA_METHODS, m);
        memset(&co, 0, sizeof co);
        co.method = (rast_aa_method)m;
        co.subpixel_bits = 4;
        co.rule = RAST_RULE_NONZERO;
        noise();
        expect(rast_aa_method_info(co.method, &s), kept, RAST_E_ARG, NULL);
        if (fmt < 0) continue;
        blank();
        sprintf(name, "aa-%d-format%d", m, fmt);
        expect(rast_fill_polygon_aa(&t, &poly, &co, &ink, scratch, sizeof scratch), kept,
               RAST_E_ARG, name);
        blank();
        sprintf(name, "aa-triangles-%d-format%d", m, fmt);
        expect(rast_fill_triangles_aa(&t, tris, 2, &co, &ink, scratch, sizeof scratch), kept,
               RAST_E_ARG, name);
        memset(&so, 0, sizeof so);
        blank();
        sprintf(name, "aa-shaded-%d-format%d", m, fmt);
        /* Gouraud and anti-aliased: the method first, then the shading */
        expect(rast_fill_triangles_shaded_aa(&t, tris, 2, colors, &co, &so, scratch,
                                             sizeof scratch),
               kept && RAST_CONFIG_SHADING, kept ? RAST_E_FORMAT : RAST_E_ARG, name);
    }
}

/* The calls that test something else than formats draw into GRAY8 and
 * RGB565 targets, those of the two the build keeps (the full build's
 * scenes then include every configured build's); with neither, only the
 * queries run (fmt -1). */
int main(void)
{
    static const int fmts[2] = {RAST_FORMAT_GRAY8, RAST_FORMAT_RGB565};
    int k, drawn = 0;
    for (k = 0; k < 2 || !drawn; k++) {
        int fmt = k < 2 ? fmts[k] : -1;
        if (fmt >= 0 && !RAST__HAS(RAST_CONFIG_FORMATS, fmt)) continue;
        drawn = 1;
        polygons(fmt);
        triangles(fmt);
        lines(fmt);
        coverage(fmt);
    }
    formats();
#ifdef RAST_CONFIG_HEADER
    return check_report("test_config (" RAST_CONFIG_HEADER ")");
#else
    return check_report("test_config");
#endif
}

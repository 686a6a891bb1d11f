/*
 * display_rgb565.c - what firmware with a 320x240 RGB565 display and a few
 * KB of RAM does: describe a scene once, then let rastrum hand it to the
 * display driver as spans, band by band, in one fixed static arena.
 *
 * The "display" is a uint16_t framebuffer behind push_span(y, x0, x1,
 * colour), the one call a display controller driver offers, and
 * push_run(y, x0, x1, colour, levels), which blends a run of coverage
 * levels into it (an anti-aliased gauge: a stroked arc of cubics with
 * round caps and a needle, each outline built once by rast_path_stroke in
 * static memory).  The program prints the scratch it used and the bands,
 * checks that the picture equals the same scene drawn in one band of 240
 * rows, and the library's own painting of it into a whole-frame target
 * (rast_render_bands), and writes a PPM.
 *
 *     make display-example        (builds and runs it)
 *     build/display_rgb565 [out.ppm]
 *     make display-qemu           (the same on an emulated Cortex-M,
 *                                  compared with the PC's frame hash)
 *
 * Integer only, no heap, no libm: it builds for a microcontroller as is
 * (minus the PPM writer).
 */
#define RAST_STATIC_LINKING_ONLY /* RAST_EDGEFLAG_SCRATCH_BOUND (built with the library) */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "rastrum.h"

#define DISPLAY_W 320
#define DISPLAY_H 240
#define BAND_ROWS 16
#define S 4 /* vertices in 1/16 pixel */

/* ---- the "display" -------------------------------------------------------- */
static uint16_t framebuffer[DISPLAY_H][DISPLAY_W];
static unsigned long spans_pushed;

static void push_span(int32_t y, int32_t x0, int32_t x1, uint16_t colour)
{
    int32_t x;
    for (x = x0; x < x1; x++) framebuffer[y][x] = colour;
    spans_pushed++;
}

/* One field (0..max) of the source s over the pixel's d at coverage level
 * c (0..255): floor((s c + d (255 - c) + 127) / 255), the nearest level
 * to the exact mix, as rastrum blends coverage into RGB565 (rastrum.h,
 * rast_fill_polygon_aa). */
static uint32_t mix(uint32_t s, uint32_t d, uint32_t c)
{
    return (s * c + d * (255u - c) + 127u) / 255u;
}

/* The anti-aliased counterpart of push_span: level values[i] (1..255) of
 * colour over pixel x0 + i, each of R, G and B in its own levels. */
static void push_run(int32_t y, int32_t x0, int32_t x1, uint16_t colour, const uint8_t *values)
{
    int32_t x;
    for (x = x0; x < x1; x++) {
        uint32_t d = framebuffer[y][x], c = values[x - x0];
        framebuffer[y][x] = (uint16_t)(mix(colour >> 11, d >> 11, c) << 11 |
                                       mix((colour >> 5) & 63u, (d >> 5) & 63u, c) << 5 |
                                       mix(colour & 31u, d & 31u, c));
    }
    spans_pushed++;
}

/* rastrum's span callback: the primitive's pixel is its RGB565 colour;
 * values is NULL for a binary primitive's span, the coverage levels of an
 * anti-aliased one's run. */
static void on_span(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1,
                    const uint8_t *values)
{
    uint16_t colour;
    (void)user;
    memcpy(&colour, prim->pixel, sizeof colour);
    if (values)
        push_run(y, x0, x1, colour, values);
    else
        push_span(y, x0, x1, colour);
}

#define RGB565(r, g, b) (uint16_t)((((r) >> 3) << 11) | (((g) >> 2) << 5) | ((b) >> 3))

/* ---- the scene ------------------------------------------------------------- */
/* sin(k * 2 pi / 64) * 32767 for k = 0..16: a quarter of a 64-gon. */
static const int32_t quarter_sine[17] = {0,     3212,  6393,  9512,  12539, 15446,
                                         18204, 20787, 23170, 25329, 27245, 28898,
                                         30273, 31356, 32137, 32609, 32767};

static int32_t sine64(int k) /* sin(k * 2 pi / 64) * 32767 */
{
    k &= 63;
    if (k <= 16) return quarter_sine[k];
    if (k <= 32) return quarter_sine[32 - k];
    if (k <= 48) return -quarter_sine[k - 32];
    return -quarter_sine[64 - k];
}

/* n points on a circle of radius r pixels around (cx, cy), point k at the
 * 64-gon's vertex k * step * 64 / n (step > 1: a star polygon), in 1/2^S
 * pixel. */
static void circle(rast_point *p, int n, int step, int32_t cx, int32_t cy, int32_t r)
{
    int k;
    for (k = 0; k < n; k++) {
        int a = (k * step * 64 / n) % 64;
        p[k].x = (cx << S) + (int32_t)((int64_t)sine64(a + 16) * (r << S) / 32767);
        p[k].y = (cy << S) + (int32_t)((int64_t)sine64(a) * (r << S) / 32767);
    }
}

static rast_point sky[4], sun[64], star[5], hill[4], mesh[3 * 2 * 12], graph[20], ray[3];
static const uint32_t four = 4, sixty_four = 64, five = 5, three = 3;
static const uint16_t c_sky = RGB565(30, 40, 90), c_sun = RGB565(250, 200, 40),
                      c_star = RGB565(240, 240, 255), c_hill = RGB565(40, 120, 50),
                      c_mesh = RGB565(90, 170, 80), c_graph = RGB565(255, 60, 60),
                      c_ray = RGB565(250, 230, 140), c_ring = RGB565(255, 255, 255);

/* ---- the gauge: anti-aliased strokes ----------------------------------------
 * Centre (160, 178) px, radius 44 px: the track a 270-degree arc from the
 * 64-gon's vertex 24 (135 degrees, bottom left) clockwise over the top to
 * vertex 72 (45 degrees), 10 px wide with butt caps; the value its first
 * 157.5 degrees with round caps; a needle with round caps and a hub (a
 * zero-length subpath with round caps: a disc).  Each arc is cubics of
 * 22.5 degrees (4 vertices of the 64-gon), control points at
 * 4/3 tan(22.5 / 4 degrees) = 4303 / 32767 of the radius along the
 * tangents (such a cubic is within 10^-5 px of the circle at this radius;
 * its points, cut to the 1/16 px grid, move it by less than 1/16 px). */
#define GAUGE_CX 160
#define GAUGE_CY 178
#define GAUGE_R 44
#define GAUGE_START 24 /* the 64-gon's vertex */
#define GAUGE_STEPS 12 /* cubics of the track */
#define VALUE_STEPS 7  /* cubics of the value */
#define ARC_K 4303
#define OUTLINE_MAX 1200 /* outline vertices of the four strokes (checked) */
#define RINGS_MAX 160

static uint8_t track_verbs[1 + GAUGE_STEPS];
static rast_point track_pts[1 + 3 * GAUGE_STEPS];
static const uint8_t needle_verbs[2] = {RAST_PATH_MOVE, RAST_PATH_LINE};
static rast_point needle_pts[2], hub_pts[2];
static rast_point outline[OUTLINE_MAX];
static uint32_t outline_rings[RINGS_MAX];
static const rast_coverage_opts aa_opts = {RAST_AA_AREA, RAST_RULE_NONZERO, S, RAST_SAMPLE_CENTER};
static const uint16_t c_track = RGB565(70, 70, 80), c_value = RGB565(255, 150, 30),
                      c_needle = RGB565(255, 255, 255);

/* The point at the 64-gon's vertex a on the circle of radius r (1/2^S
 * pixel) around the gauge's centre, plus t times the unit tangent (the
 * direction of increasing a) times ARC_K / 32767 of r. */
static rast_point gauge_point(int a, int32_t r, int t)
{
    rast_point p;
    int64_t kr = (int64_t)r * ARC_K / 32767 * t;
    p.x = (GAUGE_CX << S) + (int32_t)(((int64_t)sine64(a + 16) * r - sine64(a) * kr) / 32767);
    p.y = (GAUGE_CY << S) + (int32_t)(((int64_t)sine64(a) * r + sine64(a + 16) * kr) / 32767);
    return p;
}

/* Stroke a path of nv verbs over pts with `style` into the free part of
 * outline[] and make *prim an anti-aliased polygon of it; 0 on success. */
static int stroke_prim(rast_prim *prim, const uint8_t *verbs, uint32_t nv, const rast_point *pts,
                       uint32_t np, const rast_stroke_style *style, const uint16_t *colour)
{
    static uint32_t used_pts, used_rings;
    rast_path path;
    uint32_t npts, nrings;
    path.verbs = verbs, path.nverbs = nv, path.points = pts, path.npoints = np;
    if (rast_path_stroke_size(&path, style, &npts, &nrings) != RAST_OK ||
        npts > OUTLINE_MAX - used_pts || nrings > RINGS_MAX - used_rings ||
        rast_path_stroke(&path, style, outline + used_pts, OUTLINE_MAX - used_pts,
                         outline_rings + used_rings, RINGS_MAX - used_rings,
                         &prim->polygon) != RAST_OK)
        return 1;
    used_pts += npts, used_rings += nrings;
    prim->kind = RAST_PRIM_POLYGON;
    prim->aa = &aa_opts;
    prim->pixel = colour;
    return 0;
}

static int build_gauge(rast_prim *prims)
{
    /* tolerance 2 units (1/8 px) for the round caps */
    static const rast_stroke_style track_st = {10 << S, RAST_JOIN_BEVEL, RAST_CAP_BUTT, 4 << 16, 2, NULL, 0, 0};
    static const rast_stroke_style value_st = {10 << S, RAST_JOIN_BEVEL, RAST_CAP_ROUND, 4 << 16, 2, NULL, 0, 0};
    static const rast_stroke_style needle_st = {3 << S, RAST_JOIN_ROUND, RAST_CAP_ROUND, 4 << 16, 2, NULL, 0, 0};
    static const rast_stroke_style hub_st = {10 << S, RAST_JOIN_ROUND, RAST_CAP_ROUND, 4 << 16, 2, NULL, 0, 0};
    const int32_t r = GAUGE_R << S;
    int i;
    track_verbs[0] = RAST_PATH_MOVE;
    track_pts[0] = gauge_point(GAUGE_START, r, 0);
    for (i = 0; i < GAUGE_STEPS; i++) {
        int a = GAUGE_START + 4 * i;
        track_verbs[1 + i] = RAST_PATH_CUBIC;
        track_pts[1 + 3 * i] = gauge_point(a, r, 1);
        track_pts[2 + 3 * i] = gauge_point(a + 4, r, -1);
        track_pts[3 + 3 * i] = gauge_point(a + 4, r, 0);
    }
    needle_pts[0].x = hub_pts[0].x = hub_pts[1].x = GAUGE_CX << S;
    needle_pts[0].y = hub_pts[0].y = hub_pts[1].y = GAUGE_CY << S;
    needle_pts[1] = gauge_point(GAUGE_START + 4 * VALUE_STEPS, r - (12 << S), 0);
    return stroke_prim(&prims[0], track_verbs, 1 + GAUGE_STEPS, track_pts, 1 + 3 * GAUGE_STEPS,
                       &track_st, &c_track) |
           stroke_prim(&prims[1], track_verbs, 1 + VALUE_STEPS, track_pts, 1 + 3 * VALUE_STEPS,
                       &value_st, &c_value) |
           stroke_prim(&prims[2], needle_verbs, 2, needle_pts, 2, &needle_st, &c_needle) |
           stroke_prim(&prims[3], needle_verbs, 2, hub_pts, 2, &hub_st, &c_needle);
}

static rast_prim scene[12];
static rast_fill_opts aet_opts, star_opts, ray_opts;
static rast_tri_opts tri_opts;
static rast_line_opts line_opts;

static int build_scene(void)
{
    int i;
    memset(scene, 0, sizeof scene);
    aet_opts.algorithm = RAST_ALGO_AET;
    aet_opts.rule = RAST_RULE_NONZERO;
    aet_opts.subpixel_bits = S;
    aet_opts.sample = RAST_SAMPLE_CENTER;
    star_opts = aet_opts;
    star_opts.algorithm = RAST_ALGO_EDGEFLAG; /* one bit and one counter per band pixel */
    ray_opts = aet_opts;
    ray_opts.algorithm = RAST_ALGO_XSCAN;
    tri_opts.algorithm = RAST_TRI_EDGE;
    tri_opts.subpixel_bits = S;
    tri_opts.sample = RAST_SAMPLE_CENTER;
    line_opts.algorithm = RAST_LINE_BRESENHAM;
    line_opts.subpixel_bits = S;
    line_opts.sample = RAST_SAMPLE_CENTER;

    /* 0: the sky, the whole screen */
    sky[0].x = 0, sky[0].y = 0;
    sky[1].x = DISPLAY_W << S, sky[1].y = 0;
    sky[2].x = DISPLAY_W << S, sky[2].y = DISPLAY_H << S;
    sky[3].x = 0, sky[3].y = DISPLAY_H << S;
    /* 1: a sun beam reaching far off screen (y = -2^27 .. 2^27): the memory
     *    it needs is that of its 3 edges in a band, not of its size */
    ray[0].x = 250 << S, ray[0].y = 60 << S;
    ray[1].x = -RAST_COORD_MAX, ray[1].y = RAST_COORD_MAX;
    ray[2].x = -RAST_COORD_MAX + (RAST_COORD_MAX / 3), ray[2].y = RAST_COORD_MAX;
    /* 2: the sun, a 64-gon; 3: its outline */
    circle(sun, 64, 1, 250, 60, 38);
    /* 4: a star {5/2}, filled under non-zero */
    circle(star, 5, 2, 70, 55, 35);
    /* 5: a hill; 6: a triangle mesh on it */
    hill[0].x = 0, hill[0].y = 170 << S;
    hill[1].x = DISPLAY_W << S, hill[1].y = 140 << S;
    hill[2].x = DISPLAY_W << S, hill[2].y = DISPLAY_H << S;
    hill[3].x = 0, hill[3].y = DISPLAY_H << S;
    for (i = 0; i < 12; i++) {
        rast_point *t = mesh + 6 * i;
        int32_t x0 = (i * 320 / 12) << S, x1 = ((i + 1) * 320 / 12) << S;
        int32_t top0 = (200 - 8 * (i % 3)) << S, top1 = (200 - 8 * ((i + 1) % 3)) << S;
        t[0].x = x0, t[0].y = top0;
        t[1].x = x1, t[1].y = top1;
        t[2].x = x1, t[2].y = DISPLAY_H << S;
        t[3].x = x0, t[3].y = top0;
        t[4].x = x1, t[4].y = DISPLAY_H << S;
        t[5].x = x0, t[5].y = DISPLAY_H << S;
    }
    /* 7: a graph, an open polyline */
    for (i = 0; i < 20; i++) {
        graph[i].x = (10 + 16 * i) << S;
        graph[i].y = (120 + sine64(i * 7) / 1200) << S;
    }

    scene[0].kind = RAST_PRIM_POLYGON;
    scene[0].polygon.points = sky, scene[0].polygon.ring_sizes = &four, scene[0].polygon.nrings = 1;
    scene[0].fill = &aet_opts, scene[0].pixel = &c_sky;
    scene[1].kind = RAST_PRIM_POLYGON;
    scene[1].polygon.points = ray, scene[1].polygon.ring_sizes = &three, scene[1].polygon.nrings = 1;
    scene[1].fill = &ray_opts, scene[1].pixel = &c_ray;
    scene[2].kind = RAST_PRIM_POLYGON;
    scene[2].polygon.points = sun, scene[2].polygon.ring_sizes = &sixty_four, scene[2].polygon.nrings = 1;
    scene[2].fill = &aet_opts, scene[2].pixel = &c_sun;
    scene[3].kind = RAST_PRIM_POLYLINE;
    scene[3].points = sun, scene[3].count = 64, scene[3].closed = 1;
    scene[3].line = &line_opts, scene[3].pixel = &c_ring;
    scene[4].kind = RAST_PRIM_POLYGON;
    scene[4].polygon.points = star, scene[4].polygon.ring_sizes = &five, scene[4].polygon.nrings = 1;
    scene[4].fill = &star_opts, scene[4].pixel = &c_star;
    scene[5].kind = RAST_PRIM_POLYGON;
    scene[5].polygon.points = hill, scene[5].polygon.ring_sizes = &four, scene[5].polygon.nrings = 1;
    scene[5].fill = &aet_opts, scene[5].pixel = &c_hill;
    scene[6].kind = RAST_PRIM_TRIANGLES;
    scene[6].points = mesh, scene[6].count = 2 * 12;
    scene[6].tri = &tri_opts, scene[6].pixel = &c_mesh;
    scene[7].kind = RAST_PRIM_POLYLINE;
    scene[7].points = graph, scene[7].count = 20, scene[7].closed = 0;
    scene[7].line = &line_opts, scene[7].pixel = &c_graph;
    /* 8-11: the gauge's track, value, needle and hub, anti-aliased */
    return build_gauge(scene + 8);
}
#define NPRIMS 12

/* The one work buffer, sized at compile time for a band of BAND_ROWS rows:
 * for the binary primitives by the bound macros of rastrum.h (the sun, 64
 * edges under the AET, and the star under edgeflag: a bit and a counter
 * per band pixel); for the anti-aliased gauge by the figure
 * rast_scene_scratch_size gives for its largest outline, the track's
 * (one ring: "area" coverage keeps about 370 bytes per edge and 23 KB of
 * row buffers for the display's width, whatever the band's height), which
 * the program prints.  A scene that outgrew it would be refused
 * (RAST_E_SCRATCH) with nothing drawn. */
#define SUN_BYTES RAST_AET_SCRATCH_BOUND(64, BAND_ROWS)
#define STAR_BYTES RAST_EDGEFLAG_SCRATCH_BOUND(5, DISPLAY_W, BAND_ROWS)
#define GAUGE_BYTES 112528u
#define MAX2(a, b) ((a) > (b) ? (a) : (b))
#define ARENA_BYTES MAX2(MAX2(SUN_BYTES, STAR_BYTES), GAUGE_BYTES)
static uint64_t arena[(ARENA_BYTES + 7) / 8];

/* FNV-1a over the frame's pixel values (each as its low byte, then its
 * high byte: the same number on little- and big-endian machines), so that
 * a run on a microcontroller can be compared with one on a PC. */
static uint32_t frame_hash(void)
{
    uint32_t h = 2166136261u;
    int x, y;
    for (y = 0; y < DISPLAY_H; y++)
        for (x = 0; x < DISPLAY_W; x++) {
            h = (h ^ (framebuffer[y][x] & 0xFFu)) * 16777619u;
            h = (h ^ (uint32_t)(framebuffer[y][x] >> 8)) * 16777619u;
        }
    return h;
}

static int write_ppm(const char *path)
{
    FILE *f = fopen(path, "wb");
    int x, y;
    if (!f) return 1;
    fprintf(f, "P6\n%d %d\n255\n", DISPLAY_W, DISPLAY_H);
    for (y = 0; y < DISPLAY_H; y++)
        for (x = 0; x < DISPLAY_W; x++) {
            uint16_t c = framebuffer[y][x];
            unsigned char rgb[3];
            rgb[0] = (unsigned char)(((c >> 11) & 31) * 255 / 31);
            rgb[1] = (unsigned char)(((c >> 5) & 63) * 255 / 63);
            rgb[2] = (unsigned char)((c & 31) * 255 / 31);
            fwrite(rgb, 1, 3, f);
        }
    return fclose(f) != 0;
}

int main(int argc, char **argv)
{
    static uint16_t banded[DISPLAY_H][DISPLAY_W];
    static uint64_t big[1 << 16]; /* 512 KiB: enough for one 240-row band */
    const rast_rect screen = {0, 0, DISPLAY_W, DISPLAY_H};
    rast_band_stats stats;
    rast_target whole;
    size_t need_band = 0, need_row = 0, need_frame = 0;
    rast_status st;

    if (build_scene() != 0) {
        fprintf(stderr, "the gauge's outlines do not fit their buffers\n");
        return 1;
    }
    rast_scene_scratch_size(scene, NPRIMS, BAND_ROWS, DISPLAY_W, &need_band);
    rast_scene_scratch_size(scene, NPRIMS, 1, DISPLAY_W, &need_row);
    rast_scene_scratch_size(scene, NPRIMS, DISPLAY_H, DISPLAY_W, &need_frame);

    st = rast_render_bands_coverage(scene, NPRIMS, &screen, BAND_ROWS, on_span, NULL, arena,
                                    sizeof arena, &stats);
    if (st != RAST_OK) {
        fprintf(stderr, "render: %s\n", rast_status_str(st));
        return 1;
    }
    printf("display 320x240 rgb565, %d primitives (4 anti-aliased), bands of %d rows\n", NPRIMS,
           BAND_ROWS);
    printf("static arena: %lu bytes; peak scratch used: %lu bytes; bands: %lu; halvings: %lu\n",
           (unsigned long)sizeof arena, (unsigned long)stats.peak_scratch,
           (unsigned long)stats.bands, (unsigned long)stats.splits);
    printf("scene needs: %lu bytes per 1-row band, %lu per %d-row band, %lu for the whole frame\n",
           (unsigned long)need_row, (unsigned long)need_band, BAND_ROWS,
           (unsigned long)need_frame);
    printf("spans and runs pushed: %lu\n", spans_pushed);
    printf("frame hash: %08lx\n", (unsigned long)frame_hash());

    /* The same scene in one band of the whole screen: the same picture. */
    memcpy(banded, framebuffer, sizeof banded);
    memset(framebuffer, 0, sizeof framebuffer);
    st = rast_render_bands_coverage(scene, NPRIMS, &screen, DISPLAY_H, on_span, NULL, big,
                                    sizeof big, NULL);
    if (st != RAST_OK || memcmp(banded, framebuffer, sizeof banded) != 0) {
        fprintf(stderr, "banded picture differs from the one-band picture\n");
        return 1;
    }
    printf("identical to the one-band render: yes\n");

    /* And rastrum painting the whole frame itself (its own RGB565 blend of
     * the coverage, rast_render_bands into a target): the same picture. */
    memset(framebuffer, 0, sizeof framebuffer);
    if (rast_target_init(&whole, framebuffer, DISPLAY_W, DISPLAY_H, (int32_t)sizeof framebuffer[0],
                         RAST_FORMAT_RGB565) != RAST_OK ||
        rast_render_bands(&whole, scene, NPRIMS, DISPLAY_H, big, sizeof big, NULL) != RAST_OK ||
        memcmp(banded, framebuffer, sizeof banded) != 0) {
        fprintf(stderr, "banded picture differs from rastrum's whole-frame painting\n");
        return 1;
    }
    printf("identical to rastrum's whole-frame painting: yes\n");

    /* An arena too small for a single row: an error, and no span pushed. */
    spans_pushed = 0;
    st = rast_render_bands_coverage(scene, NPRIMS, &screen, BAND_ROWS, on_span, NULL, arena,
                                    need_row - 8, NULL);
    if (st != RAST_E_SCRATCH || spans_pushed != 0) {
        fprintf(stderr, "a too small arena drew something\n");
        return 1;
    }
    printf("arena of %lu bytes: \"%s\", nothing drawn\n", (unsigned long)(need_row - 8),
           rast_status_str(st));

#ifndef DISPLAY_NO_FILES /* a microcontroller has no files */
    memcpy(framebuffer, banded, sizeof banded);
    if (write_ppm(argc > 1 ? argv[1] : "display_rgb565.ppm")) {
        fprintf(stderr, "cannot write the PPM\n");
        return 1;
    }
#else
    (void)argc;
    (void)argv;
    (void)write_ppm;
#endif
    return 0;
}

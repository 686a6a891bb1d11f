/*
 * display_rgb565.c - what firmware with a 320x240 RGB565 display and a few
 * KB of RAM does: describe a scene once, then let rastrum hand it to the
 * display driver as spans, band by band, in one fixed static arena.
 *
 * The "display" is a uint16_t framebuffer behind push_span(y, x0, x1,
 * colour), the one call a display controller driver offers.  The program
 * prints the scratch it used and the bands, checks that the picture equals
 * the same scene drawn in one band of 240 rows, and writes a PPM.
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

/* rastrum's span callback: the primitive's pixel is its RGB565 colour. */
static void on_span(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    uint16_t colour;
    (void)user;
    memcpy(&colour, prim->pixel, sizeof colour);
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

static rast_prim scene[9];
static rast_fill_opts aet_opts, star_opts, ray_opts;
static rast_tri_opts tri_opts;
static rast_line_opts line_opts;

static void build_scene(void)
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
}
#define NPRIMS 8

/* The one work buffer, sized at compile time for a band of BAND_ROWS rows
 * by the bound macros of rastrum.h for the two largest primitives: the sun,
 * 64 edges under the AET, and the star under edgeflag (a bit and a counter
 * per band pixel).  rast_scene_scratch_size gives the exact figure. */
#define SUN_BYTES RAST_AET_SCRATCH_BOUND(64, BAND_ROWS)
#define STAR_BYTES RAST_EDGEFLAG_SCRATCH_BOUND(5, DISPLAY_W, BAND_ROWS)
#define ARENA_BYTES (SUN_BYTES > STAR_BYTES ? SUN_BYTES : STAR_BYTES)
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
    size_t need_band = 0, need_row = 0, need_frame = 0;
    rast_status st;

    build_scene();
    rast_scene_scratch_size(scene, NPRIMS, BAND_ROWS, DISPLAY_W, &need_band);
    rast_scene_scratch_size(scene, NPRIMS, 1, DISPLAY_W, &need_row);
    rast_scene_scratch_size(scene, NPRIMS, DISPLAY_H, DISPLAY_W, &need_frame);

    st = rast_render_bands_spans(scene, NPRIMS, &screen, BAND_ROWS, on_span, NULL, arena,
                                 sizeof arena, &stats);
    if (st != RAST_OK) {
        fprintf(stderr, "render: %s\n", rast_status_str(st));
        return 1;
    }
    printf("display 320x240 rgb565, %d primitives, bands of %d rows\n", NPRIMS, BAND_ROWS);
    printf("static arena: %lu bytes; peak scratch used: %lu bytes; bands: %lu; halvings: %lu\n",
           (unsigned long)sizeof arena, (unsigned long)stats.peak_scratch,
           (unsigned long)stats.bands, (unsigned long)stats.splits);
    printf("scene needs: %lu bytes per 1-row band, %lu per %d-row band, %lu for the whole frame\n",
           (unsigned long)need_row, (unsigned long)need_band, BAND_ROWS,
           (unsigned long)need_frame);
    printf("spans pushed: %lu\n", spans_pushed);
    printf("frame hash: %08lx\n", (unsigned long)frame_hash());

    /* The same scene in one band of the whole screen: the same picture. */
    memcpy(banded, framebuffer, sizeof banded);
    memset(framebuffer, 0, sizeof framebuffer);
    st = rast_render_bands_spans(scene, NPRIMS, &screen, DISPLAY_H, on_span, NULL, big,
                                 sizeof big, NULL);
    if (st != RAST_OK || memcmp(banded, framebuffer, sizeof banded) != 0) {
        fprintf(stderr, "banded picture differs from the one-band picture\n");
        return 1;
    }
    printf("identical to the one-band render: yes\n");

    /* An arena too small for a single row: an error, and no span pushed. */
    spans_pushed = 0;
    st = rast_render_bands_spans(scene, NPRIMS, &screen, BAND_ROWS, on_span, NULL, arena,
                                 need_row - 8, NULL);
    if (st != RAST_E_SCRATCH || spans_pushed != 0) {
        fprintf(stderr, "a too small arena drew something\n");
        return 1;
    }
    printf("arena of %lu bytes: \"%s\", nothing drawn\n", (unsigned long)(need_row - 8),
           rast_status_str(st));

#ifndef DISPLAY_NO_FILES /* a microcontroller has no files */
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

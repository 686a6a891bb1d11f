/*
 * draw_ppm.c - rastrum from C: fill the textbook polygon of Figure 3-19 and a
 * ring with a hole into an RGB image and write it as a PPM file.
 *
 *   make install PREFIX=$HOME/.local
 *   cc -std=c99 draw_ppm.c $(pkg-config --cflags --libs rastrum) -o draw_ppm
 *   ./draw_ppm out.ppm
 *
 * Memory: the image and the scratch are static arrays; rastrum allocates
 * nothing.  The scratch is sized at compile time with RAST_AET_SCRATCH_BOUND.
 */
#include <stdint.h>
#include <stdio.h>

#include <rastrum.h>

#define W 320
#define H 240
#define S 4 /* subpixel bits: vertices in 1/16 pixel */

static unsigned char image[H][W][3];
static uint64_t scratch[RAST_AET_SCRATCH_BOUND(16, H) / 8 + 1];

static rast_status fill(const rast_target *t, const rast_point *pts, const uint32_t *sizes,
                        uint32_t nrings, rast_fill_rule rule, const unsigned char rgb[3])
{
    rast_polygon poly;
    rast_fill_opts opts = {.algorithm = RAST_ALGO_AET, .rule = RAST_RULE_EVENODD,
                           .subpixel_bits = S, .sample = RAST_SAMPLE_CENTER};
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    opts.rule = rule;
    return rast_fill_polygon(t, &poly, &opts, rgb, scratch, sizeof scratch);
}

int main(int argc, char **argv)
{
    /* Figure 3-19 (seed 001), scaled by 16 pixels and moved right. */
    static const int fig[7][2] = {{7, 8}, {3, 12}, {1, 7}, {3, 1}, {6, 5}, {8, 1}, {12, 9}};
    /* A square ring with a square hole; the hole runs the other way round,
     * so both rules leave it empty. */
    static const rast_point ring[8] = {
        {200 << S, 40 << S}, {300 << S, 40 << S}, {300 << S, 140 << S}, {200 << S, 140 << S},
        {225 << S, 65 << S}, {225 << S, 115 << S}, {275 << S, 115 << S}, {275 << S, 65 << S},
    };
    static const uint32_t ring_sizes[2] = {4, 4};
    static const unsigned char orange[3] = {240, 140, 30}, teal[3] = {20, 150, 160};
    rast_point poly[7];
    uint32_t n = 7;
    rast_target t;
    rast_status st;
    FILE *f;
    int i;
    const char *path = argc > 1 ? argv[1] : "draw_ppm.ppm";

    st = rast_target_init(&t, image, W, H, W * 3, RAST_FORMAT_RGB888);
    for (i = 0; i < 7 && st == RAST_OK; i++) {
        poly[i].x = (fig[i][0] * 16 - 8) << S;
        poly[i].y = (fig[i][1] * 16 + 20) << S;
    }
    if (st == RAST_OK) st = fill(&t, poly, &n, 1, RAST_RULE_EVENODD, orange);
    if (st == RAST_OK) st = fill(&t, ring, ring_sizes, 2, RAST_RULE_NONZERO, teal);
    if (st != RAST_OK) {
        fprintf(stderr, "draw_ppm: %s\n", rast_status_str(st));
        return 1;
    }
    f = fopen(path, "wb");
    if (!f || fprintf(f, "P6\n%d %d\n255\n", W, H) < 0 || fwrite(image, sizeof image, 1, f) != 1) {
        fprintf(stderr, "draw_ppm: cannot write %s\n", path);
        return 1;
    }
    fclose(f);
    printf("draw_ppm: wrote %s (%dx%d), rastrum %d\n", path, W, H, rast_version_number());
    return 0;
}

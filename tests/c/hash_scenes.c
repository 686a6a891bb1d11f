/*
 * hash_scenes.c - render a fixed set of scenes with every algorithm and mode
 * and print one FNV-1a hash per scene.  `make cross-check` runs it natively,
 * on 32-bit ARM and on big-endian MIPS (qemu-user) and compares the lines:
 * the pixels must not depend on int size, alignment or byte order.
 * COUNT16 buffers are hashed by value (low byte first), not by memory
 * bytes, which do depend on byte order.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "rastrum.h"

enum { W = 96, H = 80, NPTS = 64 };

static uint64_t scratch[1 << 14];
static unsigned char img[W * H * 4];
static uint16_t counts[W * H];

static uint32_t rng_state;
static uint32_t rng(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return rng_state >> 8;
}

static uint64_t fnv(uint64_t h, const unsigned char *p, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        h ^= p[k];
        h *= 1099511628211ull;
    }
    return h;
}

static uint64_t hash_counts(void)
{
    uint64_t h = 14695981039346656037ull;
    int k;
    for (k = 0; k < W * H; k++) {
        unsigned char b[2];
        b[0] = (unsigned char)(counts[k] & 0xff);
        b[1] = (unsigned char)(counts[k] >> 8);
        h = fnv(h, b, 2);
    }
    return h;
}

/* A scene: a few rings of random vertices, some on sample points, some
 * far outside, with S bits. */
static uint32_t make_points(rast_point *pts, uint32_t *sizes, int s, uint32_t seed)
{
    uint32_t k, n = 0, r;
    rng_state = seed;
    for (r = 0; r < 3; r++) {
        sizes[r] = 3 + rng() % 12;
        for (k = 0; k < sizes[r]; k++, n++) {
            pts[n].x = (int32_t)(rng() % ((W + 20) << s)) - (10 << s);
            pts[n].y = (int32_t)(rng() % ((H + 20) << s)) - (10 << s);
            if (rng() % 5 == 0) pts[n].x = (pts[n].x >> s) << s;
            if (rng() % 9 == 0) pts[n].y = RAST_COORD_MAX - (int32_t)(rng() % 1000);
        }
    }
    return n;
}

int main(void)
{
    static const unsigned char rgb[3] = {200, 17, 99};
    rast_point pts[NPTS];
    uint32_t sizes[3], npts;
    rast_target t;
    int a, s, o, rule, rnd, bnd, seed;
    const char *name;
    rast_status st;

    for (seed = 1; seed <= 6; seed++) {
        for (s = 0; s <= 8; s += 4) {
            npts = make_points(pts, sizes, s, (uint32_t)seed * 7919u);
            for (a = 0; a < RAST_ALGO_COUNT_; a++) {
                uint32_t rules;
                if (rast_algorithm_info((rast_algorithm)a, &name, &rules) != RAST_OK) continue;
                for (rule = 0; rule < 2; rule++) {
                    if (!(rules >> rule & 1)) continue;
                    for (o = 0; o < 2; o++)
                        for (rnd = 0; rnd < 2; rnd++)
                            for (bnd = 0; bnd < 3; bnd++) {
                                rast_fill_opts f;
                                rast_polygon p;
                                memset(&f, 0, sizeof f);
                                f.algorithm = (rast_algorithm)a;
                                f.rule = (rast_fill_rule)rule;
                                f.subpixel_bits = s;
                                f.sample = (rast_sample)o;
                                f.rounding = (rast_rounding)rnd;
                                f.boundary = (rast_boundary)bnd;
                                p.points = pts;
                                p.ring_sizes = sizes;
                                p.nrings = 3;
                                memset(img, 7, sizeof img);
                                rast_target_init(&t, img, W, H, W * 3, RAST_FORMAT_RGB888);
                                st = rast_fill_polygon(&t, &p, &f, rgb, scratch, sizeof scratch);
                                printf("poly %s seed=%d S=%d rule=%d o=%d round=%d bound=%d: %d %016llx\n",
                                       name, seed, s, rule, o, rnd, bnd, (int)st,
                                       (unsigned long long)fnv(14695981039346656037ull, img, W * H * 3));
                            }
                }
            }
            for (a = 0; a < RAST_TRI_COUNT_; a++) {
                rast_tri_opts f;
                if (rast_tri_algorithm_info((rast_tri_algorithm)a, &name) != RAST_OK) continue;
                for (o = 0; o < 2; o++) {
                    memset(&f, 0, sizeof f);
                    f.algorithm = (rast_tri_algorithm)a;
                    f.subpixel_bits = s;
                    f.sample = (rast_sample)o;
                    memset(counts, 0, sizeof counts);
                    rast_target_init(&t, counts, W, H, W * 2, RAST_FORMAT_COUNT16);
                    st = rast_fill_triangles(&t, pts, npts / 3, &f, NULL, scratch, sizeof scratch);
                    printf("tris %s seed=%d S=%d o=%d: %d %016llx\n", name, seed, s, o, (int)st,
                           (unsigned long long)hash_counts());
                }
            }
            for (a = 0; a < RAST_LINE_COUNT_; a++) {
                for (o = 0; o < 2; o++) {
                    rast_line_opts f;
                    memset(&f, 0, sizeof f);
                    f.algorithm = (rast_line_algorithm)a;
                    f.subpixel_bits = s;
                    f.sample = (rast_sample)o;
                    memset(img, 0, sizeof img);
                    rast_target_init(&t, img, W, H, W, RAST_FORMAT_GRAY8);
                    st = rast_draw_polyline(&t, pts, sizes[0] + sizes[1], 1, &f, rgb);
                    printf("line %d seed=%d S=%d o=%d: %d %016llx\n", a, seed, s, o, (int)st,
                           (unsigned long long)fnv(14695981039346656037ull, img, W * H));
                }
            }
        }
    }
    return 0;
}

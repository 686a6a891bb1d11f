/*
 * hash_scenes.c - render a fixed set of scenes with every algorithm and mode
 * and print one FNV-1a hash per scene.  `make cross-check` runs it natively,
 * on 32-bit ARM and on big-endian MIPS (qemu-user) and compares the lines:
 * the pixels must not depend on int size, alignment or byte order.
 * COUNT16 and RGB565 buffers are hashed by value (low byte first), not by
 * memory bytes, which do depend on byte order; depth buffers likewise.
 * Beyond the solid fills: shaded triangles (every precision, with and
 * without depth), Gouraud rectangles and colour polygons, rgb565 and mono1
 * targets, band rendering and the region fills (with a tiny stack too, so
 * the fixed-memory fallback runs on every machine).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "rastrum.h"

enum { W = 96, H = 80, NPTS = 64 };

static uint64_t scratch[1 << 14];
static unsigned char img[W * H * 4];
static uint16_t counts[W * H];
static int32_t zbuf[W * H];
static uint8_t colors[NPTS * 4];

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

static uint64_t hash_u16(const uint16_t *v, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    size_t k;
    for (k = 0; k < n; k++) {
        unsigned char b[2];
        b[0] = (unsigned char)(v[k] & 0xff);
        b[1] = (unsigned char)(v[k] >> 8);
        h = fnv(h, b, 2);
    }
    return h;
}

static uint64_t hash_i32(uint64_t h, const int32_t *v, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        uint32_t u = (uint32_t)v[k];
        unsigned char b[4];
        b[0] = (unsigned char)u;
        b[1] = (unsigned char)(u >> 8);
        b[2] = (unsigned char)(u >> 16);
        b[3] = (unsigned char)(u >> 24);
        h = fnv(h, b, 4);
    }
    return h;
}

/* The paths added with shading, formats, bands and region fill, on the
 * scene's points (npts of them, in 3 rings of `sizes`). */
static void hash_more(const rast_point *pts, const uint32_t *sizes, uint32_t npts, int seed, int s)
{
    static const unsigned char one = 1, two = 2;
    static const uint16_t px565 = 0x11c8;
    static int32_t z[NPTS];
    static unsigned char stack[64];
    rast_target t;
    rast_status st;
    rast_polygon p;
    rast_tri_opts to;
    rast_fill_opts fo;
    rast_shade_opts sh;
    rast_prim prims[2];
    uint32_t k;
    int prec, dep, o, conn;

    for (k = 0; k < NPTS * 4; k++) colors[k] = (uint8_t)(rng() & 0xff);
    for (k = 0; k < NPTS; k++) z[k] = (int32_t)(rng() % 2000001u) - 1000000;
    p.points = pts;
    p.ring_sizes = sizes;
    p.nrings = 3;
    for (o = 0; o < 2; o++) {
        memset(&to, 0, sizeof to);
        to.subpixel_bits = s;
        to.sample = (rast_sample)o;
        memset(&fo, 0, sizeof fo);
        fo.subpixel_bits = s;
        fo.sample = (rast_sample)o;
        for (prec = 0; prec < 3; prec++)
            for (dep = 0; dep < 2; dep++) {
                sh.precision = (rast_precision)prec;
                sh.fraction_bits = 12;
                memset(img, 7, sizeof img);
                for (k = 0; k < W * H; k++) zbuf[k] = INT32_MAX;
                rast_target_init(&t, img, W, H, W * 4, RAST_FORMAT_RGBA8888);
                st = rast_fill_triangles_shaded(&t, pts, npts / 3, colors, dep ? z : NULL,
                                                dep ? zbuf : NULL, &to, &sh, scratch, sizeof scratch);
                printf("shade seed=%d S=%d o=%d prec=%d depth=%d: %d %016llx\n", seed, s, o, prec,
                       dep, (int)st,
                       (unsigned long long)hash_i32(fnv(14695981039346656037ull, img, W * H * 4),
                                                    zbuf, W * H));
            }
        for (prec = 0; prec < 3; prec++) {
            rast_point a = pts[0], b = pts[1];
            sh.precision = (rast_precision)prec;
            sh.fraction_bits = 8;
            a.y = a.y % (H << s);
            b.y = b.y % (H << s);
            memset(img, 7, sizeof img);
            rast_target_init(&t, img, W, H, W * 3, RAST_FORMAT_RGB888);
            st = rast_fill_rect_gouraud(&t, a, b, colors, &to, &sh);
            printf("rect seed=%d S=%d o=%d prec=%d: %d %016llx\n", seed, s, o, prec, (int)st,
                   (unsigned long long)fnv(14695981039346656037ull, img, W * H * 3));
            if (prec == RAST_PRECISION_FIXED) continue;
            memset(img, 7, sizeof img);
            st = rast_fill_polygon_gouraud(&t, &p, colors, &fo, &sh, scratch, sizeof scratch);
            printf("cpoly seed=%d S=%d o=%d prec=%d: %d %016llx\n", seed, s, o, prec, (int)st,
                   (unsigned long long)fnv(14695981039346656037ull, img, W * H * 3));
        }
        /* rgb565 (hashed by value) and mono1 through a polygon and triangles;
         * an rgb565 pixel is a native uint16_t, so the value is given as
         * one (the bytes {200, 17} meant 0x11c8 on little-endian hosts and
         * 0xc811 on big-endian ones: every rgb565 hash differed on MIPS) */
        memset(counts, 0x5a, sizeof counts);
        rast_target_init(&t, counts, W, H, W * 2, RAST_FORMAT_RGB565);
        st = rast_fill_polygon(&t, &p, &fo, &px565, scratch, sizeof scratch);
        printf("rgb565 seed=%d S=%d o=%d: %d %016llx\n", seed, s, o, (int)st,
               (unsigned long long)hash_u16(counts, W * H));
        memset(img, 0x5a, sizeof img);
        rast_target_init(&t, img, W, H, (W + 7) / 8, RAST_FORMAT_MONO1);
        st = rast_fill_triangles(&t, pts, npts / 3, &to, &one, scratch, sizeof scratch);
        printf("mono1 seed=%d S=%d o=%d: %d %016llx\n", seed, s, o, (int)st,
               (unsigned long long)fnv(14695981039346656037ull, img, (size_t)H * ((W + 7) / 8)));
    }
    /* a scene of a polygon, triangles and a polyline, band by band */
    memset(prims, 0, sizeof prims);
    fo.sample = RAST_SAMPLE_CENTER;
    to.sample = RAST_SAMPLE_CENTER;
    prims[0].kind = RAST_PRIM_POLYGON;
    prims[0].polygon = p;
    prims[0].fill = &fo;
    prims[0].pixel = &one;
    prims[1].kind = RAST_PRIM_TRIANGLES;
    prims[1].points = pts + 3;
    prims[1].count = (npts - 3) / 3;
    prims[1].tri = &to;
    prims[1].pixel = &two;
    for (k = 1; k <= 16; k *= 4) {
        rast_band_stats stats;
        memset(img, 0, sizeof img);
        rast_target_init(&t, img, W, H, W, RAST_FORMAT_GRAY8);
        st = rast_render_bands(&t, prims, 2, (int32_t)k, scratch, sizeof scratch, &stats);
        printf("bands seed=%d S=%d rows=%u: %d %016llx\n", seed, s, (unsigned)k, (int)st,
               (unsigned long long)fnv(14695981039346656037ull, img, W * H));
    }
    /* region fills on that picture, with room to spare and with 64 bytes */
    for (conn = 4; conn <= 8; conn += 4)
        for (k = 0; k < 2; k++) {
            static unsigned char pic[W * H];
            static uint64_t big[W * H];
            const unsigned char v = 9;
            memcpy(pic, img, sizeof pic);
            rast_target_init(&t, pic, W, H, W, RAST_FORMAT_GRAY8);
            st = rast_flood_fill(&t, W / 2, H / 2, &v, conn, k ? (void *)stack : (void *)big,
                                 k ? sizeof stack : sizeof big);
            if (st == RAST_OK) st = rast_boundary_fill(&t, 3, 3, &v, &two, conn,
                                                        k ? (void *)stack : (void *)big,
                                                        k ? sizeof stack : sizeof big);
            printf("seedfill seed=%d S=%d conn=%d tiny=%u: %d %016llx\n", seed, s, conn,
                   (unsigned)k, (int)st, (unsigned long long)fnv(14695981039346656037ull, pic, W * H));
        }
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
            hash_more(pts, sizes, npts, seed, s);
        }
    }
    return 0;
}

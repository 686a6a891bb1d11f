/*
 * test_bands.c - scenes drawn band by band (rast_render_bands and
 * rast_render_bands_spans) against the same primitives drawn one after the
 * other into the whole clip with their own entry points: byte for byte, for
 * band heights 1, 2, 7, 16 and 240, every polygon algorithm and rule, every
 * boundary mode, three formats, demo-like scenes (circle, star, holes, a
 * triangle mesh, polylines) and random ones.  Also: guard bytes around the
 * target and after the scratch; a scratch too small for one row (and a bad
 * primitive at the end of a scene) leave the target untouched; a scratch
 * between the one-row and the full-band need halves bands and still gives
 * the same pixels; the need does not grow with the coordinate range.
 * The polygon pixels themselves are held against ref.h (DESIGN section 1)
 * on one scene, so the comparison is not only of the library with itself.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_RNG_SEED 5u
#include "check.h"
#include "ref.h"
#include "rastrum.h"

#define W 160
#define H 240
#define PAD 24
#define BPP_MAX 4
#define STRIDE ((W + 2 * PAD) * BPP_MAX)
#define ROWS (H + 2 * PAD)
#define GUARD 0xA5
#define MAXPRIMS 16
#define MAXPTS 4096
#define SCRATCH_BYTES (1 << 20)

static int32_t rnd(int32_t lo, int32_t hi) { return lo + (int32_t)(rng() % (uint32_t)(hi - lo + 1)); }

/* ---- scenes ------------------------------------------------------------------ */
typedef struct {
    rast_prim prims[MAXPRIMS];
    uint32_t n;
    rast_point pts[MAXPTS];
    uint32_t npts;
    uint32_t rings[64];
    uint32_t nrings;
    rast_fill_opts fill[MAXPRIMS];
    rast_tri_opts tri[MAXPRIMS];
    rast_line_opts line[MAXPRIMS];
    unsigned char pixel[MAXPRIMS][4];
} scene;

/* cos and sin without libm: Taylor series, |x| <= 2 pi. */
static double my_cos(double x)
{
    double term = 1, sum = 1;
    int k;
    for (k = 1; k < 30; k++) {
        term *= -x * x / ((2 * k - 1) * (2 * k));
        sum += term;
    }
    return sum;
}
static double my_sin(double x) { return my_cos(x - 1.5707963267948966); }

static rast_point *take_pts(scene *sc, uint32_t n)
{
    rast_point *p = sc->pts + sc->npts;
    sc->npts += n;
    return p;
}

static rast_prim *add_prim(scene *sc, rast_prim_kind kind, int s)
{
    uint32_t i = sc->n++;
    rast_prim *p = &sc->prims[i];
    memset(p, 0, sizeof *p);
    p->kind = kind;
    memset(&sc->fill[i], 0, sizeof sc->fill[i]);
    memset(&sc->tri[i], 0, sizeof sc->tri[i]);
    memset(&sc->line[i], 0, sizeof sc->line[i]);
    sc->fill[i].subpixel_bits = s;
    sc->fill[i].sample = RAST_SAMPLE_CENTER;
    sc->tri[i].subpixel_bits = s;
    sc->tri[i].sample = RAST_SAMPLE_CENTER;
    sc->line[i].subpixel_bits = s;
    sc->line[i].sample = RAST_SAMPLE_CENTER;
    p->fill = &sc->fill[i];
    p->tri = &sc->tri[i];
    p->line = &sc->line[i];
    sc->pixel[i][0] = (unsigned char)(40 + 37 * i);
    sc->pixel[i][1] = (unsigned char)(200 - 23 * i);
    sc->pixel[i][2] = (unsigned char)(i * 61);
    sc->pixel[i][3] = 255;
    p->pixel = sc->pixel[i];
    return p;
}

/* A ring of n points on a circle (every `step`-th point: a star polygon). */
static void ring_circle(rast_point *p, int n, int step, double cx, double cy, double r, int s)
{
    int k;
    for (k = 0; k < n; k++) {
        double a = 6.283185307179586 * (double)((k * step) % n) / n;
        p[k].x = (int32_t)((cx + r * my_cos(a > 3.14159 ? a - 6.283185307179586 : a)) * (1 << s));
        p[k].y = (int32_t)((cy + r * my_sin(a > 3.14159 ? a - 6.283185307179586 : a)) * (1 << s));
    }
}

static void add_polygon_rings(scene *sc, rast_prim *p, uint32_t first_ring, uint32_t first_pt)
{
    p->polygon.points = sc->pts + first_pt;
    p->polygon.ring_sizes = sc->rings + first_ring;
    p->polygon.nrings = sc->nrings - first_ring;
}

/* Demo-like scenes: 0 circle, 1 star {200/67}, 2 ring with holes, 3 a
 * triangle mesh, 4 polylines; 5 all of them at once. */
static void demo_scene(scene *sc, int which, int s)
{
    uint32_t r0, p0;
    rast_prim *p;
    sc->n = sc->npts = sc->nrings = 0;
    if (which == 0 || which == 5) {
        r0 = sc->nrings, p0 = sc->npts;
        p = add_prim(sc, RAST_PRIM_POLYGON, s);
        ring_circle(take_pts(sc, 90), 90, 1, 80.3, 120.2, 70.7, s);
        sc->rings[sc->nrings++] = 90;
        add_polygon_rings(sc, p, r0, p0);
    }
    if (which == 1 || which == 5) {
        r0 = sc->nrings, p0 = sc->npts;
        p = add_prim(sc, RAST_PRIM_POLYGON, s);
        ring_circle(take_pts(sc, 200), 200, 67, 75.5, 110.25, 90.0, s);
        sc->rings[sc->nrings++] = 200;
        add_polygon_rings(sc, p, r0, p0);
    }
    if (which == 2 || which == 5) {
        int h;
        r0 = sc->nrings, p0 = sc->npts;
        p = add_prim(sc, RAST_PRIM_POLYGON, s);
        ring_circle(take_pts(sc, 64), 64, 1, 80, 120, 75, s);
        sc->rings[sc->nrings++] = 64;
        for (h = 0; h < 6; h++) { /* holes, the other way round */
            double a = 6.283185307179586 * h / 6 - 3.14159;
            ring_circle(take_pts(sc, 24), 24, 23, 80 + 40 * my_cos(a), 120 + 40 * my_sin(a), 17, s);
            sc->rings[sc->nrings++] = 24;
        }
        add_polygon_rings(sc, p, r0, p0);
    }
    if (which == 3 || which == 5) {
        /* a 6 x 8 grid of jittered vertices, two triangles per cell */
        rast_point grid[7][9];
        int i, j;
        rast_point *t;
        for (j = 0; j < 9; j++)
            for (i = 0; i < 7; i++) {
                grid[i][j].x = (int32_t)((i * 30 - 20) * (1 << s) + rnd(-5 * (1 << s), 5 << s));
                grid[i][j].y = (int32_t)((j * 32 - 20) * (1 << s) + rnd(-5 * (1 << s), 5 << s));
            }
        p = add_prim(sc, RAST_PRIM_TRIANGLES, s);
        t = take_pts(sc, 6 * 6 * 8);
        p->points = t;
        p->count = 2 * 6 * 8;
        for (j = 0; j < 8; j++)
            for (i = 0; i < 6; i++) {
                rast_point *c = t + 6 * (j * 6 + i);
                c[0] = grid[i][j]; c[1] = grid[i + 1][j]; c[2] = grid[i + 1][j + 1];
                c[3] = grid[i][j]; c[4] = grid[i + 1][j + 1]; c[5] = grid[i][j + 1];
            }
    }
    if (which == 4 || which == 5) {
        int k;
        for (k = 0; k < 2; k++) {
            rast_point *q;
            int i;
            p = add_prim(sc, RAST_PRIM_POLYLINE, s);
            q = take_pts(sc, 12);
            for (i = 0; i < 12; i++) {
                q[i].x = (int32_t)(rnd(-20, W + 20) * (1 << s)) + rnd(0, (1 << s) - 1);
                q[i].y = (int32_t)(rnd(-20, H + 20) * (1 << s)) + rnd(0, (1 << s) - 1);
            }
            p->points = q;
            p->count = 12;
            p->closed = k;
            sc->line[sc->n - 1].algorithm = (rast_line_algorithm)k;
        }
    }
}

/* A random scene: polygons (self-intersecting, several rings, some huge),
 * triangle batches and polylines, random options. */
static void random_scene(scene *sc)
{
    uint32_t n = (uint32_t)rnd(1, 8), k;
    sc->n = sc->npts = sc->nrings = 0;
    for (k = 0; k < n; k++) {
        int s = rnd(0, 4) == 0 ? 0 : rnd(0, 8);
        int kind = rnd(0, 2);
        int32_t span = rnd(0, 9) == 0 ? RAST_COORD_MAX : (int32_t)((W + 80) << s);
        rast_prim *p = add_prim(sc, (rast_prim_kind)kind, s);
        rast_point *q;
        uint32_t i, m;
        sc->fill[k].sample = (rast_sample)rnd(0, 1);
        sc->fill[k].rounding = (rast_rounding)(rnd(0, 3) == 0);
        sc->fill[k].boundary = (rast_boundary)(rnd(0, 3) == 0 ? rnd(1, 2) : 0);
        sc->fill[k].rule = (rast_fill_rule)rnd(0, 1);
        sc->tri[k].sample = sc->fill[k].sample;
        sc->tri[k].rounding = sc->fill[k].rounding;
        sc->tri[k].boundary = sc->fill[k].boundary;
        sc->tri[k].algorithm = (rast_tri_algorithm)rnd(0, RAST_TRI_COUNT_ - 1);
        sc->line[k].sample = sc->fill[k].sample;
        sc->line[k].algorithm = (rast_line_algorithm)rnd(0, 1);
        m = kind == RAST_PRIM_TRIANGLES ? 3 * (uint32_t)rnd(0, 12) : (uint32_t)rnd(0, 30);
        q = take_pts(sc, m);
        for (i = 0; i < m; i++) {
            int64_t x = (int64_t)rnd(-40 * (1 << s), (W + 40) << s);
            int64_t y = (int64_t)rnd(-40 * (1 << s), (H + 40) << s);
            if (span == RAST_COORD_MAX && rnd(0, 2) == 0) {
                x = rnd(0, 1) ? RAST_COORD_MAX : -RAST_COORD_MAX;
                y = rnd(0, 1) ? RAST_COORD_MAX : -RAST_COORD_MAX;
            }
            q[i].x = (int32_t)x;
            q[i].y = (int32_t)y;
        }
        if (kind == RAST_PRIM_POLYGON) {
            uint32_t r0 = sc->nrings, left = m;
            while (left > 0) {
                uint32_t sz = (uint32_t)rnd(1, (int32_t)left);
                sc->rings[sc->nrings++] = sz;
                left -= sz;
            }
            p->polygon.points = q;
            p->polygon.ring_sizes = sc->rings + r0;
            p->polygon.nrings = sc->nrings - r0;
        } else {
            p->points = q;
            p->count = kind == RAST_PRIM_TRIANGLES ? m / 3 : m;
            p->closed = rnd(0, 1);
        }
    }
}

/* ---- drawing -------------------------------------------------------------------- */
static unsigned char full_mem[ROWS * STRIDE], band_mem[ROWS * STRIDE], span_mem[ROWS * STRIDE];
static uint64_t scratch_mem[SCRATCH_BYTES / 8 + 8];

static int bpp_of(rast_format f)
{
    int32_t b = 0;
    rast_format_bytes(f, &b);
    return b;
}

static rast_target make_target(unsigned char *mem, rast_format f, const rast_rect *clip)
{
    rast_target t;
    memset(mem, GUARD, sizeof full_mem);
    rast_target_init(&t, mem + PAD * STRIDE + PAD * BPP_MAX, W, H, STRIDE, f);
    if (f == RAST_FORMAT_COUNT16) { /* counts start at 0 inside the target */
        int y;
        for (y = 0; y < H; y++) memset(mem + (PAD + y) * STRIDE + PAD * BPP_MAX, 0, W * 2);
    }
    t.clip = *clip;
    return t;
}

/* The whole-clip render: each primitive through its own entry point. */
static rast_status draw_full(const rast_target *t, const scene *sc)
{
    uint32_t i;
    for (i = 0; i < sc->n; i++) {
        const rast_prim *p = &sc->prims[i];
        rast_status st;
        if (p->kind == RAST_PRIM_POLYGON)
            st = rast_fill_polygon(t, &p->polygon, p->fill, p->pixel, scratch_mem, SCRATCH_BYTES);
        else if (p->kind == RAST_PRIM_TRIANGLES)
            st = rast_fill_triangles(t, p->points, p->count, p->tri, p->pixel, scratch_mem,
                                     SCRATCH_BYTES);
        else
            st = rast_draw_polyline(t, p->points, p->count, p->closed, p->line, p->pixel);
        if (st != RAST_OK) return st;
    }
    return RAST_OK;
}

typedef struct {
    const rast_target *t;
    const scene *sc;
    rast_rect clip;
    int bad; /* spans outside the clip, empty, or of another scene */
} span_ctx;

static void paint_span(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    span_ctx *c = (span_ctx *)user;
    int bpp = bpp_of(c->t->format);
    unsigned char *row = (unsigned char *)c->t->pixels + (ptrdiff_t)y * c->t->stride;
    int32_t x;
    if (prim < c->sc->prims || prim >= c->sc->prims + c->sc->n || x0 >= x1 || x0 < c->clip.x0 ||
        x1 > c->clip.x1 || y < c->clip.y0 || y >= c->clip.y1) {
        c->bad++;
        return;
    }
    for (x = x0; x < x1; x++) {
        if (c->t->format == RAST_FORMAT_COUNT16) {
            uint16_t *v = (uint16_t *)(void *)(row + 2 * x);
            if (*v < 65535) (*v)++;
        } else {
            memcpy(row + x * bpp, prim->pixel, (size_t)bpp);
        }
    }
}

static int bands_fails;
/* Full render, band render and span render of one scene with one clip
 * format and band height: all three equal, guards intact. */
static void compare(const scene *sc, rast_format f, const rast_rect *clip, int32_t k,
                    size_t scratch_bytes)
{
    rast_target tf = make_target(full_mem, f, clip);
    rast_target tb = make_target(band_mem, f, clip);
    rast_target ts = make_target(span_mem, f, clip);
    rast_band_stats stats;
    span_ctx c;
    rast_rect cut = *clip;
    rast_status s1, s2, s3;
    unsigned char *tail = (unsigned char *)scratch_mem + scratch_bytes;
    if (cut.x0 < 0) cut.x0 = 0;
    if (cut.y0 < 0) cut.y0 = 0;
    if (cut.x1 > W) cut.x1 = W;
    if (cut.y1 > H) cut.y1 = H;
    s1 = draw_full(&tf, sc);
    memset(tail, GUARD, 64);
    s2 = rast_render_bands(&tb, sc->prims, sc->n, k, scratch_mem, scratch_bytes, &stats);
    c.t = &ts;
    c.sc = sc;
    c.clip = cut;
    c.bad = 0;
    s3 = rast_render_bands_spans(sc->prims, sc->n, &cut, k, paint_span, &c, scratch_mem,
                                 scratch_bytes, NULL);
    CHECK(s1 == RAST_OK);
    CHECK(s2 == RAST_OK);
    CHECK(s3 == RAST_OK);
    CHECK(c.bad == 0);
    CHECK(stats.peak_scratch <= scratch_bytes);
    if (memcmp(full_mem, band_mem, sizeof full_mem) != 0 || memcmp(full_mem, span_mem, sizeof full_mem) != 0) {
        if (bands_fails++ < 5)
            fprintf(stderr, "band render differs: format %d k %d clip %d,%d,%d,%d bytes %lu\n", (int)f,
                    (int)k, clip->x0, clip->y0, clip->x1, clip->y1, (unsigned long)scratch_bytes);
        CHECK(0);
    } else {
        CHECK(1);
    }
    {
        int i, ok = 1;
        for (i = 0; i < 64; i++) ok &= tail[i] == GUARD;
        CHECK(ok);
    }
}

static const int32_t band_heights[] = {1, 2, 7, 16, 240};
#define NK (int)(sizeof band_heights / sizeof band_heights[0])

static void test_demo_scenes(void)
{
    static scene sc;
    const rast_rect whole = {0, 0, W, H}, window = {13, 29, 141, 203};
    int which, algo, rule, boundary, k, s;
    for (which = 0; which <= 5; which++) {
        for (s = 0; s <= 5; s += 5) {
            demo_scene(&sc, which, s);
            for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
                uint32_t rules = 0;
                rast_algorithm_info((rast_algorithm)algo, NULL, &rules);
                for (rule = 0; rule <= 1; rule++) {
                    uint32_t i;
                    if (!(rules & (1u << rule))) continue;
                    boundary = (algo + rule + s) % 3;
                    for (i = 0; i < sc.n; i++) {
                        sc.fill[i].algorithm = (rast_algorithm)algo;
                        sc.fill[i].rule = (rast_fill_rule)rule;
                        sc.fill[i].boundary = (rast_boundary)boundary;
                        sc.tri[i].algorithm = (rast_tri_algorithm)(algo % RAST_TRI_COUNT_);
                        sc.tri[i].boundary = (rast_boundary)boundary;
                    }
                    for (k = 0; k < NK; k++) {
                        /* the quick run (valgrind, qemu): one band height
                         * of the first four in turn, and the whole clip */
                        if (check_count(5) < 5 && k != NK - 1 && k != (which + s + algo + rule) % (NK - 1))
                            continue;
                        compare(&sc, RAST_FORMAT_RGB888, &whole, band_heights[k], SCRATCH_BYTES);
                        compare(&sc, RAST_FORMAT_COUNT16, &window, band_heights[k], SCRATCH_BYTES);
                    }
                }
            }
        }
    }
}

static void test_random_scenes(void)
{
    static scene sc;
    int n, k;
    for (n = 0; n < check_count(100); n++) {
        rast_rect clip;
        rast_format f = (rast_format)rnd(0, RAST_FORMAT_COUNT16);
        uint32_t i;
        random_scene(&sc);
        for (i = 0; i < sc.n; i++) sc.fill[i].algorithm = (rast_algorithm)rnd(0, RAST_ALGO_COUNT_ - 1);
        for (i = 0; i < sc.n; i++) { /* a rule the algorithm supports */
            uint32_t rules = 0;
            rast_algorithm_info(sc.fill[i].algorithm, NULL, &rules);
            if (!(rules & (1u << sc.fill[i].rule))) sc.fill[i].rule = RAST_RULE_EVENODD;
        }
        clip.x0 = rnd(-10, W / 2);
        clip.y0 = rnd(-10, H / 2);
        clip.x1 = rnd(clip.x0, W + 10);
        clip.y1 = rnd(clip.y0, H + 10);
        for (k = 0; k < NK; k++) compare(&sc, f, &clip, band_heights[k], SCRATCH_BYTES);
        compare(&sc, f, &clip, rnd(1, 300), SCRATCH_BYTES);
    }
}

/* Scratch between the one-row need and the full-band need: bands are
 * halved, the pixels do not change; below the one-row need: RAST_E_SCRATCH
 * and not one byte of the target written. */
static void test_small_scratch(void)
{
    static scene sc;
    const rast_rect whole = {0, 0, W, H};
    size_t one = 0, full = 0;
    rast_band_stats stats;
    rast_target t;
    int algo;
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
        uint32_t i;
        demo_scene(&sc, 5, 4);
        for (i = 0; i < sc.n; i++) {
            sc.fill[i].algorithm = (rast_algorithm)algo;
            sc.tri[i].algorithm = RAST_TRI_EDGEFLAG; /* needs rows */
        }
        CHECK(rast_scene_scratch_size(sc.prims, sc.n, 1, W, &one) == RAST_OK);
        CHECK(rast_scene_scratch_size(sc.prims, sc.n, H, W, &full) == RAST_OK);
        CHECK(one <= full);
        /* halving: the pixels of the full render, in the bytes of a few rows */
        if (full > one) {
            size_t mid = one + (full - one) / 3;
            mid -= mid % 8;
            if (mid < one) mid = one;
            compare(&sc, RAST_FORMAT_RGBA8888, &whole, H, mid);
            compare(&sc, RAST_FORMAT_GRAY8, &whole, 64, one);
            t = make_target(band_mem, RAST_FORMAT_GRAY8, &whole);
            CHECK(rast_render_bands(&t, sc.prims, sc.n, H, scratch_mem, mid, &stats) == RAST_OK);
            CHECK(stats.splits > 0 && stats.bands == 1 && stats.peak_scratch <= mid);
        }
        /* too small: nothing written, neither to the target nor to spans */
        if (one >= 8) {
            span_ctx c;
            unsigned char *copy = span_mem;
            t = make_target(band_mem, RAST_FORMAT_RGB888, &whole);
            memcpy(copy, band_mem, sizeof band_mem);
            CHECK(rast_render_bands(&t, sc.prims, sc.n, 16, scratch_mem, one - 8, NULL) ==
                  RAST_E_SCRATCH);
            CHECK(memcmp(copy, band_mem, sizeof band_mem) == 0);
            c.t = &t;
            c.sc = &sc;
            c.clip = whole;
            c.bad = 0;
            CHECK(rast_render_bands_spans(sc.prims, sc.n, &whole, 16, paint_span, &c, scratch_mem,
                                          one - 8, NULL) == RAST_E_SCRATCH);
            CHECK(memcmp(copy, band_mem, sizeof band_mem) == 0);
        }
    }
}

/* A line first (no scratch), then a mask algorithm whose one-row need is
 * more than the scratch but whose empty-clip need is not: still nothing
 * drawn (the one-row need is checked for the whole scene first). */
static void test_small_scratch_after_line(void)
{
    static scene sc;
    const rast_rect whole = {0, 0, W, H};
    rast_target t;
    size_t one = 0;
    int algo;
    for (algo = RAST_ALGO_EDGEFILL; algo <= RAST_ALGO_EDGEFLAG; algo++) {
        demo_scene(&sc, 5, 4); /* circle, star, holes, mesh, line, line */
        sc.fill[0].algorithm = (rast_algorithm)algo;
        sc.prims[1] = sc.prims[0];
        sc.prims[0] = sc.prims[4];
        sc.n = 2; /* a line, the circle */
        CHECK(sc.prims[0].kind == RAST_PRIM_POLYLINE);
        CHECK(rast_scene_scratch_size(sc.prims, sc.n, 1, W, &one) == RAST_OK);
        CHECK(one >= 8);
        t = make_target(band_mem, RAST_FORMAT_GRAY8, &whole);
        memcpy(span_mem, band_mem, sizeof band_mem);
        CHECK(rast_render_bands(&t, sc.prims, sc.n, 16, scratch_mem, one - 8, NULL) ==
              RAST_E_SCRATCH);
        CHECK(memcmp(span_mem, band_mem, sizeof band_mem) == 0);
    }
}

/* A bad primitive last: the scene is checked whole before anything is drawn. */
static void test_bad_last(void)
{
    static scene sc;
    const rast_rect whole = {0, 0, W, H};
    rast_target t;
    static const rast_point far_pt[3] = {{0, 0}, {RAST_COORD_MAX + 1, 5}, {3, 90}};
    static const rast_point near_pt[3] = {{0, 0}, {100, 5}, {3, 90}};
    static const uint32_t three = 3;
    rast_prim *p;
    int kind;
    /* a vertex out of range in each kind; a bad rule; a bad kind; no pixel */
    for (kind = 0; kind < 6; kind++) {
        demo_scene(&sc, 5, 4);
        p = add_prim(&sc, kind < 3 ? (rast_prim_kind)kind : RAST_PRIM_POLYGON, 0);
        p->points = kind < 3 ? far_pt : near_pt;
        p->count = kind == RAST_PRIM_POLYLINE ? 3 : 1;
        p->polygon.points = p->points;
        p->polygon.ring_sizes = &three;
        p->polygon.nrings = 1;
        if (kind == 3) sc.fill[sc.n - 1].rule = (rast_fill_rule)7;
        if (kind == 4) p->kind = (rast_prim_kind)9;
        if (kind == 5) p->pixel = NULL;
        t = make_target(band_mem, RAST_FORMAT_RGB888, &whole);
        memcpy(span_mem, band_mem, sizeof band_mem);
        CHECK(rast_render_bands(&t, sc.prims, sc.n, 16, scratch_mem, SCRATCH_BYTES, NULL) != RAST_OK);
        CHECK(memcmp(span_mem, band_mem, sizeof band_mem) == 0);
    }
    CHECK(rast_render_bands(&t, sc.prims, 1, 0, scratch_mem, SCRATCH_BYTES, NULL) == RAST_E_ARG);
    CHECK(rast_render_bands(&t, NULL, 1, 4, scratch_mem, SCRATCH_BYTES, NULL) == RAST_E_NULL);
    CHECK(rast_render_bands(NULL, sc.prims, 1, 4, scratch_mem, SCRATCH_BYTES, NULL) == RAST_E_NULL);
    CHECK(rast_render_bands_spans(sc.prims, 1, NULL, 4, paint_span, NULL, scratch_mem,
                                  SCRATCH_BYTES, NULL) == RAST_E_NULL);
    CHECK(rast_render_bands_spans(sc.prims, 1, &whole, 4, NULL, NULL, scratch_mem,
                                  SCRATCH_BYTES, NULL) == RAST_E_NULL);
    CHECK(rast_render_bands(&t, NULL, 0, 4, NULL, 0, NULL) == RAST_OK);
    CHECK(rast_scene_scratch_size(sc.prims, 1, 0, W, &(size_t){0}) == RAST_E_ARG);
    CHECK(rast_scene_scratch_size(sc.prims, 1, 4, -1, &(size_t){0}) == RAST_E_SIZE);
    CHECK(rast_scene_scratch_size(sc.prims, 1, 4, W, NULL) == RAST_E_NULL);
}

/* The need is a function of the edges and the band: the same polygon
 * stretched to y = +-2^27 (and x) needs the same bytes for every algorithm,
 * and draws its band with them. */
static void test_coordinate_range(void)
{
    static const rast_point small[4] = {{10, 10}, {150, 20}, {140, 230}, {5, 200}};
    static const rast_point huge[4] = {{-RAST_COORD_MAX, -RAST_COORD_MAX},
                                       {RAST_COORD_MAX, -RAST_COORD_MAX + 7},
                                       {RAST_COORD_MAX - 3, RAST_COORD_MAX},
                                       {-RAST_COORD_MAX + 1, RAST_COORD_MAX - 1}};
    static const uint32_t four = 4;
    rast_fill_opts o;
    rast_prim p;
    int algo;
    memset(&o, 0, sizeof o);
    memset(&p, 0, sizeof p);
    p.kind = RAST_PRIM_POLYGON;
    p.polygon.ring_sizes = &four;
    p.polygon.nrings = 1;
    p.fill = &o;
    p.pixel = "\x7f";
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
        size_t a = 0, b = 1;
        rast_target t;
        const rast_rect whole = {0, 0, W, H};
        int y, ok = 1;
        o.algorithm = (rast_algorithm)algo;
        p.polygon.points = small;
        CHECK(rast_scene_scratch_size(&p, 1, 8, W, &a) == RAST_OK);
        p.polygon.points = huge;
        CHECK(rast_scene_scratch_size(&p, 1, 8, W, &b) == RAST_OK);
        CHECK(a == b);
        t = make_target(band_mem, RAST_FORMAT_GRAY8, &whole);
        CHECK(rast_render_bands(&t, &p, 1, 8, scratch_mem, b, NULL) == RAST_OK);
        for (y = 0; y < H; y++) /* the huge quad covers the whole target */
            ok &= memchr(band_mem + (PAD + y) * STRIDE + PAD * BPP_MAX, GUARD, W) == NULL;
        CHECK(ok);
    }
}

/* One scene's polygons against ref.h, through the band renderer (COUNT16
 * gives how many polygons own each sample). */
static void test_against_reference(void)
{
    static scene sc;
    const rast_rect whole = {0, 0, W, H};
    rast_target t;
    int algo, x, y, bad = 0;
    demo_scene(&sc, 5, 4);
    sc.n = 3; /* circle, star, holes */
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
        uint32_t i;
        for (i = 0; i < sc.n; i++) {
            sc.fill[i].algorithm = (rast_algorithm)algo;
            uint32_t rules = 0;
            rast_algorithm_info((rast_algorithm)algo, NULL, &rules);
            sc.fill[i].rule = (rules & (1u << RAST_RULE_NONZERO)) ? RAST_RULE_NONZERO
                                                                   : RAST_RULE_EVENODD;
        }
        t = make_target(band_mem, RAST_FORMAT_COUNT16, &whole);
        CHECK(rast_render_bands(&t, sc.prims, sc.n, 7, scratch_mem, SCRATCH_BYTES, NULL) == RAST_OK);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int want = 0;
                uint16_t got;
                for (i = 0; i < sc.n; i++) {
                    const rast_polygon *pg = &sc.prims[i].polygon;
                    int cr, w = ref_winding(pg->points, pg->ring_sizes, pg->nrings, 4, 1, 0, x, y, &cr);
                    want += sc.fill[i].rule == RAST_RULE_EVENODD ? (cr & 1) : (w != 0);
                }
                memcpy(&got, band_mem + (PAD + y) * STRIDE + PAD * BPP_MAX + 2 * x, 2);
                bad += got != want;
            }
    }
    CHECK(bad == 0);
}

int main(void)
{
    test_demo_scenes();
    test_random_scenes();
    test_small_scratch();
    test_small_scratch_after_line();
    test_bad_last();
    test_coordinate_range();
    test_against_reference();
    return check_report("test_bands");
}

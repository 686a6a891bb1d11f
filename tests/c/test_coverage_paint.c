/*
 * test_coverage_paint.c - anti-aliased fills (rast_fill_polygon_aa,
 * rast_fill_triangles_aa) and rast_triangles_coverage_spans:
 *  - every format: the painted target equals the documented rule applied
 *    (blend_ref.h, written from the docs) to the coverage levels that
 *    rast_polygon_coverage / rast_triangles_coverage give for the same
 *    clip (checked against exact references in test_coverage.c): channels
 *    floor((s c + d (255 - c) + 127) / 255) (rgb565 per 5/6/5 field),
 *    mono1 set iff c >= 128, count16 + 1 iff c > 0; pixels with c = 0,
 *    outside the clip, in the row padding and in guard rows are untouched
 *    (mono1: to the bit);
 *  - every method, both rules, random overlapping rings;
 *  - rast_triangles_coverage_spans: the image's values in ordered runs;
 *  - scenes with anti-aliased primitives (rast_prim.aa) drawn band by band
 *    (rows of 1, 5, 16 and all, and a scratch that forces halving): the
 *    same bytes as each primitive's own entry point into the whole target,
 *    in order; the scratch a function of the edges and the band, not of
 *    the coordinates; the spans call refuses them, and
 *    rast_render_bands_coverage hands on their values (and NULL for the
 *    binary ones) so that painting them by the rule gives the same bytes;
 *  - errors: every status before anything is written.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 1213u
#include "blend_ref.h"
#include "check.h"
#include "rastrum.h"

#define GUARD 0x5A
static uint64_t scratch_mem[1 << 17];
#include "scratch.h"

#define W 13
#define H 11
#define PAD 3   /* guard rows above and below, guard bytes after each row */
#define MAXB 4  /* bytes of the widest pixel */
#define STRIDE (W * MAXB + 2 * PAD) /* even: 16-bit rows stay aligned */
#define SIZE ((H + 2 * PAD) * STRIDE)

/* 8-byte aligned (16-bit formats need 2) */
static uint64_t mem[3][SIZE / 8 + 1];
#define before ((unsigned char *)mem[0])
#define got ((unsigned char *)mem[1])
#define want ((unsigned char *)mem[2])

static rast_status paint(const rast_target *t, const rast_polygon *p, const rast_point *tris,
                         uint32_t ntris, const rast_coverage_opts *o, const void *pixel)
{
    size_t need;
    unsigned char *s;
    uint32_t np = p ? 0 : 3 * ntris, k;
    rast_status st;
    if (p)
        for (k = 0; k < p->nrings; k++) np += p->ring_sizes[k];
    st = rast_coverage_scratch_size(o, np, t->clip.x1 - t->clip.x0, t->clip.y1 - t->clip.y0, &need);
    if (st != RAST_OK) return st;
    s = scratch_for(need);
    st = p ? rast_fill_polygon_aa(t, p, o, pixel, s, need)
           : rast_fill_triangles_aa(t, tris, ntris, o, pixel, s, need);
    CHECK(scratch_guard_ok(s, need));
    return st;
}

static void coverage(const rast_polygon *p, const rast_point *tris, uint32_t ntris,
                     const rast_coverage_opts *o, const rast_rect *clip, uint8_t *cov)
{
    size_t need;
    unsigned char *s;
    uint32_t np = p ? 0 : 3 * ntris, k;
    if (p)
        for (k = 0; k < p->nrings; k++) np += p->ring_sizes[k];
    CHECK(rast_coverage_scratch_size(o, np, clip->x1 - clip->x0, clip->y1 - clip->y0, &need) ==
          RAST_OK);
    s = scratch_for(need);
    CHECK((p ? rast_polygon_coverage(p, o, clip, RAST_COVERAGE_U8, cov, W, s, need)
             : rast_triangles_coverage(tris, ntris, o, clip, RAST_COVERAGE_U8, cov, W, s, need)) ==
          RAST_OK);
}

static void random_opts(rast_coverage_opts *o)
{
    memset(o, 0, sizeof *o);
    o->method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
    o->rule = (rast_fill_rule)(rng() % 2);
    o->subpixel_bits = (int32_t)(rng() % 5);
    o->sample = (rast_sample)(rng() % 2);
}

static void test_formats(void)
{
    int iter, n = check_count(600);
    for (iter = 0; iter < n; iter++) {
        rast_format f = (rast_format)(iter % RAST_FORMAT_COUNT_);
        rast_point pts[12];
        uint32_t sizes[3], nr = 1 + rng() % 3, k, np = 0;
        rast_polygon poly;
        rast_coverage_opts o;
        rast_target t;
        rast_rect clip;
        uint8_t cov[H * W];
        unsigned char value[MAXB];
        int tri = iter % 7 == 3, x, y;
        size_t i;
        random_opts(&o);
        for (k = 0; k < nr; k++) {
            uint32_t m = 3 + rng() % 2, j;
            sizes[k] = m;
            for (j = 0; j < m; j++, np++) {
                pts[np].x = (int32_t)(rng() % (uint32_t)((W + 4) << o.subpixel_bits)) -
                            (2 << o.subpixel_bits);
                pts[np].y = (int32_t)(rng() % (uint32_t)((H + 4) << o.subpixel_bits)) -
                            (2 << o.subpixel_bits);
            }
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = nr;
        for (i = 0; i < SIZE; i++) before[i] = (unsigned char)rng();
        for (k = 0; k < MAXB; k++) value[k] = (unsigned char)rng();
        if (iter % 5 == 0) memset(value, 255, sizeof value); /* opaque white */
        CHECK(rast_target_init(&t, before + PAD * STRIDE, W, H, STRIDE, f) == RAST_OK);
        /* a clip inside the target, often the whole */
        if (rng() % 2) {
            t.clip.x0 = (int32_t)(rng() % 5);
            t.clip.y0 = (int32_t)(rng() % 4);
            t.clip.x1 = W - (int32_t)(rng() % 5);
            t.clip.y1 = H - (int32_t)(rng() % 4);
        }
        clip = t.clip;
        memset(cov, 0, sizeof cov);
        coverage(tri ? NULL : &poly, pts, np / 3, &o, &clip, cov);
        memcpy(want, before, SIZE);
        for (y = clip.y0; y < clip.y1; y++)
            for (x = clip.x0; x < clip.x1; x++)
                blend_ref(f, want + (y + PAD) * STRIDE, x, cov[(y - clip.y0) * W + (x - clip.x0)],
                          value);
        memcpy(got, before, SIZE);
        t.pixels = got + PAD * STRIDE;
        CHECK(paint(&t, tri ? NULL : &poly, pts, np / 3, &o, value) == RAST_OK);
        CHECK(memcmp(got, want, SIZE) == 0);
    }
}

/* A coverage of 0 and 255 everywhere: a triangulated square paints its
 * pixels with exactly the value (no seam blended twice) and leaves the rest. */
static void test_square(void)
{
    static const rast_point sq[6] = {{16, 16}, {144, 16}, {144, 112}, {16, 16}, {144, 112}, {16, 112}};
    rast_coverage_opts o;
    rast_target t;
    unsigned char v[3] = {10, 200, 30};
    int x, y, m, ok = 1;
    for (m = 0; m < RAST_AA_COUNT_; m++) {
        memset(&o, 0, sizeof o);
        o.method = (rast_aa_method)m;
        o.subpixel_bits = 4;
        memset(got, 77, SIZE);
        CHECK(rast_target_init(&t, got + PAD * STRIDE, W, H, STRIDE, RAST_FORMAT_RGB888) == RAST_OK);
        CHECK(paint(&t, NULL, sq, 2, &o, v) == RAST_OK);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                const unsigned char *p = got + (y + PAD) * STRIDE + 3 * x;
                int in = x >= 1 && x < 9 && y >= 1 && y < 7;
                if (in ? memcmp(p, v, 3) != 0 : (p[0] != 77 || p[1] != 77 || p[2] != 77)) ok = 0;
            }
    }
    CHECK(ok);
}

/* ---- rast_triangles_coverage_spans ------------------------------------------------ */

typedef struct runs {
    uint8_t img[H * W];
    int32_t last_y, last_x1, bad;
    rast_rect clip;
} runs;

static void on_run(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *v)
{
    runs *r = (runs *)user;
    int32_t x;
    if (y < r->last_y || (y == r->last_y && x0 <= r->last_x1) || x0 >= x1 || x0 < r->clip.x0 ||
        x1 > r->clip.x1 || y < r->clip.y0 || y >= r->clip.y1)
        r->bad = 1;
    r->last_y = y;
    r->last_x1 = x1;
    for (x = x0; x < x1 && !r->bad; x++) {
        if (!v[x - x0]) r->bad = 1;
        r->img[(y - r->clip.y0) * W + (x - r->clip.x0)] = v[x - x0];
    }
}

static void test_spans(void)
{
    int iter, n = check_count(100);
    for (iter = 0; iter < n; iter++) {
        rast_point tris[12];
        rast_coverage_opts o;
        rast_rect clip = {-2, 1, W - 2, H};
        uint8_t cov[H * W];
        runs r;
        size_t need;
        unsigned char *s;
        uint32_t nt = 1 + rng() % 4, k;
        random_opts(&o);
        for (k = 0; k < 3 * nt; k++) {
            tris[k].x = (int32_t)(rng() % (uint32_t)((W + 2) << o.subpixel_bits)) - (3 << o.subpixel_bits);
            tris[k].y = (int32_t)(rng() % (uint32_t)((H + 2) << o.subpixel_bits));
        }
        memset(cov, 0, sizeof cov);
        coverage(NULL, tris, nt, &o, &clip, cov);
        memset(&r, 0, sizeof r);
        r.last_y = clip.y0 - 1;
        r.clip = clip;
        CHECK(rast_coverage_scratch_size(&o, 3 * nt, W, H - 1, &need) == RAST_OK);
        s = scratch_for(need);
        CHECK(rast_triangles_coverage_spans(tris, nt, &o, &clip, on_run, &r, s, need) == RAST_OK);
        CHECK(scratch_guard_ok(s, need));
        CHECK(!r.bad);
        CHECK(memcmp(r.img, cov, sizeof cov) == 0);
    }
}

/* ---- errors: nothing written ------------------------------------------------------- */

static void no_run(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *v)
{
    (void)y, (void)x0, (void)x1, (void)v;
    *(int *)user = 1;
}

static void test_errors(void)
{
    static const rast_point tri[3] = {{0, 0}, {64, 0}, {0, 64}};
    const uint32_t three = 3;
    rast_polygon p = {tri, &three, 1};
    rast_coverage_opts o;
    rast_target t;
    rast_rect clip = {0, 0, 4, 4};
    size_t need;
    unsigned char *s, v = 200;
    int called = 0;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    CHECK(rast_coverage_scratch_size(&o, 3, W, H, &need) == RAST_OK);
    s = scratch_for(need);
    memset(before, 0xAB, SIZE);
    memcpy(got, before, SIZE);
    CHECK(rast_target_init(&t, got + PAD * STRIDE, W, H, STRIDE, RAST_FORMAT_GRAY8) == RAST_OK);
#define REFUSED(call, status) CHECK((call) == (status) && memcmp(got, before, SIZE) == 0)
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s, need - 1), RAST_E_SCRATCH);
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s + 1, need), RAST_E_ALIGN);
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, NULL, s, need), RAST_E_NULL);
    REFUSED(rast_fill_polygon_aa(NULL, &p, &o, &v, s, need), RAST_E_NULL);
    REFUSED(rast_fill_polygon_aa(&t, NULL, &o, &v, s, need), RAST_E_NULL);
    REFUSED(rast_fill_polygon_aa(&t, &p, NULL, &v, s, need), RAST_E_NULL);
    REFUSED(rast_fill_triangles_aa(&t, NULL, 1, &o, &v, s, need), RAST_E_NULL);
    REFUSED(rast_fill_triangles_aa(&t, tri, RAST_MAX_POINTS, &o, &v, s, need), RAST_E_TOO_MANY);
    o.method = RAST_AA_COUNT_;
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s, need), RAST_E_ARG);
    o.method = RAST_AA_AREA;
    o.rule = (rast_fill_rule)2;
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s, need), RAST_E_ARG);
    o.rule = RAST_RULE_EVENODD;
    o.subpixel_bits = 17;
    REFUSED(rast_fill_triangles_aa(&t, tri, 1, &o, &v, s, need), RAST_E_SUBPIXEL);
    o.subpixel_bits = 4;
    {
        rast_point far[3] = {{0, 0}, {RAST_COORD_MAX + 1, 0}, {0, 64}};
        rast_polygon pf = {far, &three, 1};
        REFUSED(rast_fill_polygon_aa(&t, &pf, &o, &v, s, need), RAST_E_RANGE);
        REFUSED(rast_fill_triangles_aa(&t, far, 1, &o, &v, s, need), RAST_E_RANGE);
    }
    t.format = (rast_format)RAST_FORMAT_COUNT_;
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s, need), RAST_E_FORMAT);
    t.format = RAST_FORMAT_GRAY8;
    t.stride = W - 1;
    REFUSED(rast_fill_polygon_aa(&t, &p, &o, &v, s, need), RAST_E_SIZE);
    t.stride = STRIDE;
    /* COUNT16 takes no value */
    CHECK(rast_target_init(&t, got + PAD * STRIDE, W, H, STRIDE, RAST_FORMAT_COUNT16) == RAST_OK);
    CHECK(rast_fill_polygon_aa(&t, &p, &o, NULL, s, need) == RAST_OK);
    CHECK(memcmp(got, before, SIZE) != 0);
    /* the spans call: errors before the first run */
    CHECK(rast_triangles_coverage_spans(tri, 1, &o, &clip, NULL, &called, s, need) == RAST_E_NULL);
    CHECK(rast_triangles_coverage_spans(tri, 1, &o, NULL, no_run, &called, s, need) == RAST_E_NULL);
    CHECK(rast_triangles_coverage_spans(tri, 1, &o, &clip, no_run, &called, s, 0) == RAST_E_SCRATCH);
    CHECK(!called);
    CHECK(rast_triangles_coverage_spans(tri, 1, &o, &clip, no_run, &called, s, need) == RAST_OK);
    CHECK(called);
}

/* ---- scenes band by band ----------------------------------------------------------- */

#define BW 40
#define BH 37
#define BSTRIDE (BW * 3 + 4)
static unsigned char band_full[BH * BSTRIDE], band_got[BH * BSTRIDE];
static uint64_t band_scratch[1 << 15];

typedef struct bscene {
    rast_prim prims[6];
    rast_point pts[6][12];
    uint32_t sizes[6][2];
    rast_coverage_opts aa[6];
    rast_fill_opts fill[6];
    unsigned char pixel[6][3];
    uint32_t n;
} bscene;

static void band_scene(bscene *sc, int32_t far)
{
    uint32_t i, k;
    memset(sc, 0, sizeof *sc);
    sc->n = 6;
    for (i = 0; i < sc->n; i++) {
        rast_prim *p = &sc->prims[i];
        int tri = i % 3 == 2;
        random_opts(&sc->aa[i]);
        sc->aa[i].subpixel_bits = 4;
        for (k = 0; k < 12; k++) {
            sc->pts[i][k].x = (int32_t)(rng() % ((BW + 8) << 4)) - (4 << 4);
            sc->pts[i][k].y = (int32_t)(rng() % ((BH + 8) << 4)) - (4 << 4);
        }
        if (far && i == 1) sc->pts[i][3].y = RAST_COORD_MAX >> 4 << 4; /* reaching far down */
        for (k = 0; k < 3; k++) sc->pixel[i][k] = (unsigned char)rng();
        p->pixel = sc->pixel[i];
        if (tri) {
            p->kind = RAST_PRIM_TRIANGLES;
            p->points = sc->pts[i];
            p->count = 4;
            p->aa = &sc->aa[i];
        } else {
            sc->sizes[i][0] = 5;
            sc->sizes[i][1] = 7;
            p->kind = RAST_PRIM_POLYGON;
            p->polygon.points = sc->pts[i];
            p->polygon.ring_sizes = sc->sizes[i];
            p->polygon.nrings = 2;
            sc->fill[i].subpixel_bits = 4;
            sc->fill[i].rule = sc->aa[i].rule;
            p->fill = &sc->fill[i];
            p->aa = i == 3 ? NULL : &sc->aa[i]; /* one binary polygon among them */
        }
    }
}

/* rast_render_bands_coverage painted by blend_ref into band_got (NULL
 * values: a binary span, every pixel level 255). */
typedef struct cov_painter {
    const rast_prim *prims;
    uint32_t n;
    int bad;
} cov_painter;

static void cov_paint(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1,
                      const uint8_t *values)
{
    cov_painter *c = (cov_painter *)user;
    int32_t x;
    if (prim < c->prims || prim >= c->prims + c->n || x0 >= x1 || x0 < 0 || x1 > BW || y < 0 ||
        y >= BH || (values == NULL) != (prim->aa == NULL)) {
        c->bad = 1;
        return;
    }
    for (x = x0; x < x1; x++) {
        if (values && !values[x - x0]) c->bad = 1;
        blend_ref(RAST_FORMAT_RGB888, band_got + y * BSTRIDE, x, values ? values[x - x0] : 255,
                  (const unsigned char *)prim->pixel);
    }
}

static void test_bands(void)
{
    int iter, n = check_count(40);
    for (iter = 0; iter < n; iter++) {
        static const int32_t rows[5] = {1, 5, 16, BH, 3};
        bscene sc;
        rast_target t;
        size_t need, bytes;
        uint32_t i;
        int r;
        band_scene(&sc, 0);
        /* the primitives one after the other into the whole target */
        memset(band_full, 90, sizeof band_full);
        CHECK(rast_target_init(&t, band_full, BW, BH, BSTRIDE, RAST_FORMAT_RGB888) == RAST_OK);
        for (i = 0; i < sc.n; i++) {
            const rast_prim *p = &sc.prims[i];
            uint32_t np = p->kind == RAST_PRIM_TRIANGLES ? 3 * p->count : 12;
            unsigned char *s = (unsigned char *)band_scratch;
            if (p->aa) {
                CHECK(rast_coverage_scratch_size(p->aa, np, BW, BH, &need) == RAST_OK);
                CHECK(need <= sizeof band_scratch);
                CHECK((p->kind == RAST_PRIM_POLYGON
                           ? rast_fill_polygon_aa(&t, &p->polygon, p->aa, p->pixel, s, need)
                           : rast_fill_triangles_aa(&t, p->points, p->count, p->aa, p->pixel, s,
                                                    need)) == RAST_OK);
            } else {
                CHECK(rast_scratch_size(p->fill, np, BW, BH, &need) == RAST_OK);
                CHECK(rast_fill_polygon(&t, &p->polygon, p->fill, p->pixel, s, need) == RAST_OK);
            }
        }
        for (r = 0; r < 5; r++) {
            rast_band_stats stats;
            CHECK(rast_scene_scratch_size(sc.prims, sc.n, rows[r], BW, &need) == RAST_OK);
            bytes = need;
            if (r == 4) { /* between one row's need and the band's: halved bands */
                CHECK(rast_scene_scratch_size(sc.prims, sc.n, 1, BW, &bytes) == RAST_OK);
                CHECK(rast_scene_scratch_size(sc.prims, sc.n, 32, BW, &need) == RAST_OK);
                bytes = (bytes + need) / 2 / RAST_SCRATCH_ALIGN * RAST_SCRATCH_ALIGN;
            }
            memset(band_got, 90, sizeof band_got);
            t.pixels = band_got;
            CHECK(rast_render_bands(&t, sc.prims, sc.n, r == 4 ? 32 : rows[r], band_scratch, bytes,
                                    &stats) == RAST_OK);
            CHECK(stats.peak_scratch <= bytes);
            CHECK(memcmp(band_got, band_full, sizeof band_got) == 0);
            /* the same scene's coverage runs, painted by the documented rule */
            {
                cov_painter c = {sc.prims, 0, 0};
                rast_rect clip = {0, 0, BW, BH};
                c.n = sc.n;
                memset(band_got, 90, sizeof band_got);
                CHECK(rast_render_bands_coverage(sc.prims, sc.n, &clip, r == 4 ? 32 : rows[r], cov_paint,
                                                 &c, band_scratch, bytes, NULL) == RAST_OK);
                CHECK(!c.bad);
                CHECK(memcmp(band_got, band_full, sizeof band_got) == 0);
            }
        }
        /* the need grows with the edges and the band, not the coordinates */
        {
            bscene far;
            size_t near_need, far_need;
            rng_state ^= 0x9E3779B9u;
            band_scene(&far, 1);
            CHECK(rast_scene_scratch_size(far.prims, far.n, 5, BW, &far_need) == RAST_OK);
            far.pts[1][3].y = 3;
            CHECK(rast_scene_scratch_size(far.prims, far.n, 5, BW, &near_need) == RAST_OK);
            CHECK(far_need == near_need);
        }
    }
}

static void prim_span(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    (void)prim, (void)y, (void)x0, (void)x1;
    *(int *)user = 1;
}

static void test_band_errors(void)
{
    bscene sc;
    rast_target t;
    rast_rect clip = {0, 0, BW, BH};
    size_t need;
    int called = 0;
    band_scene(&sc, 0);
    CHECK(rast_scene_scratch_size(sc.prims, sc.n, 4, BW, &need) == RAST_OK);
    /* the spans call has no coverage to hand on */
    CHECK(rast_render_bands_spans(sc.prims, sc.n, &clip, 4, prim_span, &called, band_scratch, need,
                                  NULL) == RAST_E_ARG);
    CHECK(!called);
    CHECK(rast_render_bands_coverage(sc.prims, sc.n, &clip, 4, NULL, &called, band_scratch, need,
                                     NULL) == RAST_E_NULL);
    CHECK(rast_render_bands_coverage(sc.prims, sc.n, NULL, 4, cov_paint, &called, band_scratch,
                                     need, NULL) == RAST_E_NULL);
    {
        /* an anti-aliased primitive in a clip wider than RAST_MAX_DIM */
        rast_rect wide = {-RAST_MAX_DIM, 0, RAST_MAX_DIM, 4};
        CHECK(rast_render_bands_coverage(sc.prims, sc.n, &wide, 4, cov_paint, &called,
                                         band_scratch, sizeof band_scratch, NULL) == RAST_E_SIZE);
    }
    CHECK(!called);
    /* aa on a polyline; a bad method at the end: nothing written */
    memset(band_full, 90, sizeof band_full);
    memcpy(band_got, band_full, sizeof band_got);
    CHECK(rast_target_init(&t, band_got, BW, BH, BSTRIDE, RAST_FORMAT_RGB888) == RAST_OK);
    sc.aa[4].method = RAST_AA_COUNT_;
    CHECK(rast_render_bands(&t, sc.prims, sc.n, 4, band_scratch, need, NULL) == RAST_E_ARG);
    CHECK(rast_scene_scratch_size(sc.prims, sc.n, 4, BW, &need) == RAST_E_ARG);
    sc.aa[4].method = RAST_AA_SS4;
    sc.prims[5].kind = RAST_PRIM_POLYLINE;
    sc.prims[5].count = 3;
    {
        rast_line_opts lo;
        memset(&lo, 0, sizeof lo);
        sc.prims[5].line = &lo;
        CHECK(rast_scene_scratch_size(sc.prims, sc.n, 4, BW, &need) == RAST_E_ARG);
        CHECK(rast_render_bands(&t, sc.prims, sc.n, 4, band_scratch, sizeof band_scratch, NULL) ==
              RAST_E_ARG);
        sc.prims[5].aa = NULL; /* a binary polyline is fine */
        CHECK(rast_scene_scratch_size(sc.prims, sc.n, 4, BW, &need) == RAST_OK);
    }
    CHECK(memcmp(band_got, band_full, sizeof band_got) == 0);
}

int main(void)
{
    test_formats();
    test_square();
    test_spans();
    test_errors();
    test_bands();
    test_band_errors();
    return check_report("test_coverage_paint");
}

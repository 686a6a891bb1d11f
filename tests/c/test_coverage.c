/*
 * test_coverage.c - anti-aliased coverage through the C API, each method
 * against an exact reference that does not share its code:
 *  - area (and accumulate for one rectangle): unions of axis-aligned
 *    rectangles on the 2^-S grid, overlapping, coincident, in either
 *    orientation, under both rules; the exact area is a count of the
 *    2^-S cells inside, so every level must be floor(a M + 1/2);
 *  - ssK: the binary fill ("xscan", not the AET the method uses) of the
 *    vertices scaled by k into a count16 target k times finer;
 *  - triangle batches: a triangulated square is covered fully, seamlessly;
 *  - area: translation by whole pixels translates the values exactly;
 *  - errors: every status, nothing written, scratch exact and its guard
 *    bytes intact;
 *  - rast_polygon_coverage_spans and rast_triangles_coverage_spans, every
 *    method: the same values as the image, in ordered runs of values not 0
 *    inside the clip.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 1212u
#include "check.h"
#include "rastrum.h"

#define GUARD 0x5A
static uint64_t scratch_mem[1 << 17];
#include "scratch.h"

#define W 12
#define H 10

static rast_status cover(const rast_polygon *p, const rast_point *tris, uint32_t ntris,
                         const rast_coverage_opts *o, const rast_rect *clip,
                         rast_coverage_format f, void *out, ptrdiff_t stride)
{
    size_t need;
    unsigned char *s;
    uint32_t np = p ? 0 : 3 * ntris;
    rast_status st;
    uint32_t k;
    if (p)
        for (k = 0; k < p->nrings; k++) np += p->ring_sizes[k];
    st = rast_coverage_scratch_size(o, np, clip->x1 - clip->x0, clip->y1 - clip->y0, &need);
    if (st != RAST_OK) return st;
    s = scratch_for(need);
    if (!s) return RAST_E_SCRATCH;
    st = p ? rast_polygon_coverage(p, o, clip, f, out, stride, s, need)
           : rast_triangles_coverage(tris, ntris, o, clip, f, out, stride, s, need);
    CHECK(scratch_guard_ok(s, need));
    return st;
}

static uint32_t level(uint64_t num, uint64_t den, uint32_t M)
{
    return (uint32_t)((2 * num * M + den) / (2 * den)); /* floor(num M / den + 1/2) */
}

/* ---- rectangles: the exact area by cells ----------------------------------- */

/* The options of one random case (rule, grid, method) and a clip a few
 * pixels inside the W x H image on each side. */
static void opts_and_clip(rast_coverage_opts *o, rast_rect *clip, int rule, int32_t s, rast_aa_method m)
{
    memset(o, 0, sizeof *o);
    o->rule = (rast_fill_rule)rule;
    o->subpixel_bits = s;
    o->method = m;
    clip->x0 = (int32_t)(rng() % 3);
    clip->y0 = (int32_t)(rng() % 3);
    clip->x1 = W - (int32_t)(rng() % 3);
    clip->y1 = H - (int32_t)(rng() % 3);
}

static void test_rectangles(void)
{
    int iter, n = check_count(300);
    for (iter = 0; iter < n; iter++) {
        int32_t s = (int32_t)(rng() % 4), g = 1 << s, nr = 1 + (int)(rng() % 5), r, i, j;
        rast_point pts[4 * 5];
        uint32_t sizes[5];
        int32_t rx0[5], ry0[5], rx1[5], ry1[5], sg[5];
        rast_polygon poly;
        rast_coverage_opts o;
        rast_rect clip;
        uint16_t out[H][W];
        int rule = (int)(rng() % 2);
        for (r = 0; r < nr; r++) {
            int32_t a = (int32_t)(rng() % (uint32_t)((W + 2) * g)) - g;
            int32_t b = (int32_t)(rng() % (uint32_t)((W + 2) * g)) - g;
            int32_t c = (int32_t)(rng() % (uint32_t)((H + 2) * g)) - g;
            int32_t d = (int32_t)(rng() % (uint32_t)((H + 2) * g)) - g;
            if (r > 0 && rng() % 3 == 0) { /* share an edge or the whole rectangle */
                a = rx0[r - 1];
                if (rng() % 2) b = rx1[r - 1];
            }
            rx0[r] = a < b ? a : b;
            rx1[r] = a < b ? b : a;
            ry0[r] = c < d ? c : d;
            ry1[r] = c < d ? d : c;
            sg[r] = (rng() % 2) ? 1 : -1;
            /* (x0,y0) (x1,y0) (x1,y1) (x0,y1) has winding -1 inside */
            pts[4 * r].x = rx0[r];
            pts[4 * r].y = ry0[r];
            pts[4 * r + 1].x = sg[r] < 0 ? rx1[r] : rx0[r];
            pts[4 * r + 1].y = sg[r] < 0 ? ry0[r] : ry1[r];
            pts[4 * r + 2].x = rx1[r];
            pts[4 * r + 2].y = ry1[r];
            pts[4 * r + 3].x = sg[r] < 0 ? rx0[r] : rx1[r];
            pts[4 * r + 3].y = sg[r] < 0 ? ry1[r] : ry0[r];
            sizes[r] = 4;
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = (uint32_t)nr;
        opts_and_clip(&o, &clip, rule, s, (nr == 1 && rng() % 2) ? RAST_AA_ACCUMULATE : RAST_AA_AREA);
        CHECK(cover(&poly, NULL, 0, &o, &clip, RAST_COVERAGE_U16, &out[0][0], W * 2) == RAST_OK);
        for (j = clip.y0; j < clip.y1; j++)
            for (i = clip.x0; i < clip.x1; i++) {
                uint32_t cells = 0;
                int32_t u, v;
                for (v = j * g; v < (j + 1) * g; v++)
                    for (u = i * g; u < (i + 1) * g; u++) {
                        int w = 0;
                        for (r = 0; r < nr; r++)
                            if (u >= rx0[r] && u < rx1[r] && v >= ry0[r] && v < ry1[r]) w += sg[r];
                        cells += rule == RAST_RULE_EVENODD ? (uint32_t)(w & 1) : (w != 0);
                    }
                CHECK(out[j - clip.y0][i - clip.x0] == level(cells, (uint64_t)g * g, 65535));
            }
    }
}

/* ---- accumulate: many rectangles, exact --------------------------------------------
 * 12 to 24 rectangles on the 2^-S grid (24 edges or more: the rows'
 * counting sort), their corners on a coarse grid so that sides coincide,
 * of both directions; as rings of one polygon (16 rings or more: the
 * shared sides cancel first) or, two triangles each, as a batch (a
 * shared diagonal).  The accumulation's value is the integral a of the
 * winding number over the pixel, a count of 2^-S cells here, the rule
 * applied (non-zero min(|a|, 1), even-odd |a| folded mod 2: rastrum.h),
 * and every level must be floor(a' M + 1/2): no bound wider than that. */
static void test_acc_many(void)
{
    int iter, n = check_count(150);
    for (iter = 0; iter < n; iter++) {
        int32_t s = (int32_t)(rng() % 3), g = 1 << s, nr = 12 + (int)(rng() % 13), r, i, j;
        rast_point pts[4 * 24], tris[6 * 24];
        uint32_t sizes[24], M;
        int32_t rx0[24], ry0[24], rx1[24], ry1[24], sg[24];
        rast_polygon poly;
        rast_coverage_opts o;
        rast_rect clip;
        uint16_t out[H][W];
        const int batch = (int)(rng() % 2), rule = batch ? RAST_RULE_NONZERO : (int)(rng() % 2);
        const rast_coverage_format f = rng() % 2 ? RAST_COVERAGE_U8 : RAST_COVERAGE_U16;
        for (r = 0; r < nr; r++) {
            int32_t a, b, c, d;
            do { /* (corners on the grid of half pixels, or whole ones) */
                a = (int32_t)(rng() % (2 * (W + 2))) * g / 2 - g;
                b = (int32_t)(rng() % (2 * (W + 2))) * g / 2 - g;
                c = (int32_t)(rng() % (2 * (H + 2))) * g / 2 - g;
                d = (int32_t)(rng() % (2 * (H + 2))) * g / 2 - g;
            } while (a == b || c == d);
            if (r > 0 && rng() % 2) { /* a side of the last one's, either way */
                a = rng() % 2 ? rx0[r - 1] : rx1[r - 1];
                if (a == b) b = a + 1;
            }
            rx0[r] = a < b ? a : b;
            rx1[r] = a < b ? b : a;
            ry0[r] = c < d ? c : d;
            ry1[r] = c < d ? d : c;
            sg[r] = batch || rng() % 2 ? 1 : -1;
            pts[4 * r].x = rx0[r]; /* (x0,y0) (x0,y1) (x1,y1) (x1,y0): +1 inside, y down */
            pts[4 * r].y = ry0[r];
            pts[4 * r + 1].x = sg[r] > 0 ? rx0[r] : rx1[r];
            pts[4 * r + 1].y = sg[r] > 0 ? ry1[r] : ry0[r];
            pts[4 * r + 2].x = rx1[r];
            pts[4 * r + 2].y = ry1[r];
            pts[4 * r + 3].x = sg[r] > 0 ? rx1[r] : rx0[r];
            pts[4 * r + 3].y = sg[r] > 0 ? ry0[r] : ry1[r];
            sizes[r] = 4;
            /* two triangles, one of them turned the other way (a batch
             * orients each) */
            tris[6 * r] = pts[4 * r];
            tris[6 * r + 1] = pts[4 * r + 1];
            tris[6 * r + 2] = pts[4 * r + 2];
            tris[6 * r + 3] = pts[4 * r];
            tris[6 * r + 4] = pts[4 * r + 2];
            tris[6 * r + 5] = pts[4 * r + 3];
            if (rng() % 2) {
                tris[6 * r + 4] = pts[4 * r + 3];
                tris[6 * r + 5] = pts[4 * r + 2];
            }
        }
        poly.points = pts;
        poly.ring_sizes = sizes;
        poly.nrings = (uint32_t)nr;
        opts_and_clip(&o, &clip, rule, s, RAST_AA_ACCUMULATE);
        M = f == RAST_COVERAGE_U8 ? 255 : 65535;
        CHECK(cover(batch ? NULL : &poly, batch ? tris : NULL, batch ? 2 * (uint32_t)nr : 0, &o, &clip, f,
                    &out[0][0], W * 2) == RAST_OK);
        for (j = clip.y0; j < clip.y1; j++)
            for (i = clip.x0; i < clip.x1; i++) {
                const uint64_t one = (uint64_t)g * (uint64_t)g;
                const unsigned char *row = (const unsigned char *)&out[j - clip.y0][0];
                int64_t sum = 0;
                uint64_t x;
                int32_t u, v;
                for (v = j * g; v < (j + 1) * g; v++)
                    for (u = i * g; u < (i + 1) * g; u++)
                        for (r = 0; r < nr; r++)
                            if (u >= rx0[r] && u < rx1[r] && v >= ry0[r] && v < ry1[r]) sum += sg[r];
                x = (uint64_t)(sum < 0 ? -sum : sum); /* |a| one^-1 */
                if (rule == RAST_RULE_NONZERO) {
                    x = x > one ? one : x;
                } else {
                    x %= 2 * one;
                    x = x > one ? 2 * one - x : x;
                }
                CHECK((f == RAST_COVERAGE_U8 ? row[i - clip.x0] : out[j - clip.y0][i - clip.x0]) ==
                      level(x, one, M));
            }
    }
}

/* ---- supersampling: the binary fill k times finer ------------------------------ */

static void test_ss(void)
{
    int iter, n = check_count(200);
    static uint16_t fine[16 * H][16 * W];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 4), K = 1 << kb, s = (int32_t)(rng() % 6), i, j;
        int32_t np = 3 + (int32_t)(rng() % 8), g = 1 << s, w = K == 16 ? 5 : W, h = K == 16 ? 4 : H;
        rast_point pts[10], big[10];
        uint32_t size = (uint32_t)np;
        rast_polygon poly = {pts, &size, 1}, bigp = {big, &size, 1};
        rast_coverage_opts o;
        rast_fill_opts fo;
        rast_rect clip = {0, 0, 0, 0};
        rast_target t;
        uint8_t out[H][W];
        size_t need;
        unsigned char *sc;
        for (i = 0; i < np; i++) {
            pts[i].x = (int32_t)(rng() % (uint32_t)((w + 4) * g)) - 2 * g;
            pts[i].y = (int32_t)(rng() % (uint32_t)((h + 4) * g)) - 2 * g;
            /* the same point on the fine grid, with S' = max(S - kb, 0) */
            big[i].x = s >= kb ? pts[i].x : pts[i].x * (K >> s);
            big[i].y = s >= kb ? pts[i].y : pts[i].y * (K >> s);
        }
        memset(&o, 0, sizeof o);
        o.method = (rast_aa_method)(RAST_AA_SS2 + kb - 1);
        o.rule = (rast_fill_rule)(rng() % 2);
        o.subpixel_bits = s;
        o.sample = (rast_sample)(rng() % 2);
        clip.x1 = w;
        clip.y1 = h;
        CHECK(cover(&poly, NULL, 0, &o, &clip, RAST_COVERAGE_U8, &out[0][0], W) == RAST_OK);
        memset(fine, 0, sizeof fine);
        CHECK(rast_target_init(&t, fine, w * K, h * K, (int32_t)sizeof fine[0], RAST_FORMAT_COUNT16) ==
              RAST_OK);
        memset(&fo, 0, sizeof fo);
        fo.algorithm = RAST_ALGO_XSCAN;
        fo.rule = o.rule;
        fo.subpixel_bits = s >= kb ? s - kb : 0;
        fo.sample = o.sample;
        CHECK(rast_scratch_size(&fo, size, w * K, h * K, &need) == RAST_OK);
        sc = scratch_for(need);
        CHECK(rast_fill_polygon(&t, &bigp, &fo, NULL, sc, need) == RAST_OK);
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++) {
                uint32_t c = 0;
                int32_t u, v;
                for (v = 0; v < K; v++)
                    for (u = 0; u < K; u++) c += fine[j * K + v][i * K + u];
                CHECK(out[j][i] == level(c, (uint64_t)K * K, 255));
            }
    }
}

/* Random ssK options for k = 2^kb and S = s (either rule and sample
 * offset) in *o, and in *fo the reference's: "xscan" on the vertices
 * scaled by k, read with S' = max(S - kb, 0) bits. */
static void ss_opts(int32_t kb, int32_t s, rast_coverage_opts *o, rast_fill_opts *fo)
{
    memset(o, 0, sizeof *o);
    o->method = (rast_aa_method)(RAST_AA_SS2 + kb - 1);
    o->rule = (rast_fill_rule)(rng() % 2);
    o->subpixel_bits = s;
    o->sample = (rast_sample)(rng() % 2);
    memset(fo, 0, sizeof *fo);
    fo->algorithm = RAST_ALGO_XSCAN;
    fo->rule = o->rule;
    fo->subpixel_bits = s >= kb ? s - kb : 0;
    fo->sample = o->sample;
}

/* Each value of an ssK image `out` (w x h clip pixels, rows of `ow`
 * uint64_t words, format f) against the sub-samples counted in `fine` (the
 * clip k = 2^kb times finer, rows of `fs` bytes of uint16_t counts, or of
 * uint8_t 0/1 when `bytes`). */
static void check_ss_image(const uint64_t *out, int32_t ow, int32_t w, int32_t h,
                           rast_coverage_format f, int32_t kb, const void *fine, size_t fs,
                           int bytes)
{
    const int32_t K = 1 << kb;
    int32_t i, j, u, v;
    for (j = 0; j < h; j++) {
        const unsigned char *row = (const unsigned char *)(out + (ptrdiff_t)j * ow);
        for (i = 0; i < w; i++) {
            uint64_t c = 0, got;
            for (v = 0; v < K; v++)
                for (u = 0; u < K; u++) {
                    const unsigned char *fr = (const unsigned char *)fine + (size_t)(j * K + v) * fs;
                    c += bytes ? fr[i * K + u] : ((const uint16_t *)(const void *)fr)[i * K + u];
                }
            got = f == RAST_COVERAGE_U8    ? row[i]
                  : f == RAST_COVERAGE_U16 ? ((const uint16_t *)(const void *)row)[i]
                                           : out[(ptrdiff_t)j * ow + i];
            CHECK(got == (f == RAST_COVERAGE_FIX62
                              ? c << (62 - 2 * kb)
                              : level(c, (uint64_t)K * K, f == RAST_COVERAGE_U8 ? 255 : 65535)));
        }
    }
}

/* The reference for a polygon's ssK image `out` (w x h, rows of ow
 * words, format f): bigp (npts vertices, clip-relative, scaled by k =
 * 2^kb) filled by fo into `fine` (cleared first; w k x h k counts, rows of
 * fs bytes), then every value checked (check_ss_image). */
static void check_ss_polygon(const rast_polygon *bigp, uint32_t npts, const rast_fill_opts *fo,
                             const uint64_t *out, int32_t ow, int32_t w, int32_t h,
                             rast_coverage_format f, int32_t kb, uint16_t *fine, size_t fs)
{
    const int32_t K = 1 << kb;
    rast_target t;
    size_t need;
    unsigned char *sc;
    memset(fine, 0, fs * (size_t)(h * K));
    CHECK(rast_target_init(&t, fine, w * K, h * K, (int32_t)fs, RAST_FORMAT_COUNT16) == RAST_OK);
    CHECK(rast_scratch_size(fo, npts, w * K, h * K, &need) == RAST_OK);
    sc = scratch_for(need);
    CHECK(rast_fill_polygon(&t, bigp, fo, NULL, sc, need) == RAST_OK);
    check_ss_image(out, ow, w, h, f, kb, fine, fs, 0);
}

/* The same on a clip wider than 64 columns (the flush walks a bit per
 * column, 64 to a word) and away from the origin, in every format: the
 * runs between marked columns, their ends at the clip's edges and the
 * values of each format. */
#define WW 150
static void test_ss_wide(void)
{
    int iter, n = check_count(60);
    static uint16_t fine[4 * 3][4 * WW];
    static uint64_t out[3][WW];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 2), K = 1 << kb, s = (int32_t)(rng() % 3), g = 1 << s;
        int32_t np = 3 + (int32_t)(rng() % 8), i, j, h = 3;
        rast_coverage_format f = (rast_coverage_format)(rng() % 3);
        static const int32_t fsize[3] = {1, 2, 8};
        rast_point pts[10], big[10];
        uint32_t size = (uint32_t)np;
        rast_polygon poly = {pts, &size, 1}, bigp = {big, &size, 1};
        rast_coverage_opts o;
        rast_fill_opts fo;
        rast_rect clip;
        clip.x0 = (int32_t)(rng() % 140) - 100;
        clip.y0 = (int32_t)(rng() % 9) - 4;
        clip.x1 = clip.x0 + WW;
        clip.y1 = clip.y0 + h;
        for (i = 0; i < np; i++) {
            /* x beyond the clip on either side now and then; the reference
             * gets the polygon moved by whole pixels to the clip's origin */
            int32_t x = (int32_t)(rng() % (uint32_t)((WW + 20) * g)) - 10 * g + clip.x0 * g;
            int32_t y = (int32_t)(rng() % (uint32_t)((h + 4) * g)) - 2 * g + clip.y0 * g;
            pts[i].x = x;
            pts[i].y = y;
            x -= clip.x0 * g;
            y -= clip.y0 * g;
            big[i].x = s >= kb ? x : x * (K >> s);
            big[i].y = s >= kb ? y : y * (K >> s);
        }
        ss_opts(kb, s, &o, &fo);
        memset(out, 0xA5, sizeof out);
        CHECK(cover(&poly, NULL, 0, &o, &clip, f, &out[0][0], (ptrdiff_t)sizeof out[0]) == RAST_OK);
        check_ss_polygon(&bigp, size, &fo, &out[0][0], WW, WW, h, f, kb, &fine[0][0],
                         sizeof fine[0]);
        for (j = 0; j < h; j++) /* nothing written after the clip's last column */
            for (i = WW * fsize[f]; i < (int32_t)sizeof out[0]; i++)
                CHECK(((const unsigned char *)out[j])[i] == 0xA5);
    }
}
#undef WW

/* Rows with many runs' ends (one a column in 8 or more: the uint8_t flush
 * then sums every column of each 64 with a mark, and fills those without
 * one at their count) on clips of 65 to 264 columns: a comb of teeth in
 * the first 64 columns, one tooth inside column 63 from a fraction of it
 * (its ends there change the count of column 64, in a word of 64 with no
 * mark) to a column far right, or to the clip's right edge; both rules,
 * every k, each format. */
#define DW 264
static void test_ss_dense(void)
{
    int iter, n = check_count(150);
    static uint16_t fine[16 * 2][16 * DW];
    static uint64_t out[2][DW];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 4), K = 1 << kb, s = 1 + (int32_t)(rng() % 3), g = 1 << s;
        int32_t w = 65 + (int32_t)(rng() % (DW - 65)), h = 2, nq = 8 + (int32_t)(rng() % 12), q, i;
        rast_coverage_format f = (rast_coverage_format)(rng() % 4 == 0 ? rng() % 3 : 0);
        rast_point pts[4 * 21], big[4 * 21];
        uint32_t sizes[21];
        rast_polygon poly = {pts, sizes, 0}, bigp = {big, sizes, 0};
        rast_coverage_opts o;
        rast_fill_opts fo;
        rast_rect clip = {0, 0, 0, 0};
        clip.x1 = w;
        clip.y1 = h;
        for (q = 0; q <= nq; q++) {
            int32_t x0, x1, y0 = -(int32_t)(rng() % (uint32_t)g), y1 = h * g + (int32_t)(rng() % (uint32_t)g);
            if (q < nq) { /* a tooth in the first 64 columns */
                x0 = (int32_t)(rng() % (uint32_t)(64 * g));
                x1 = x0 + 1 + (int32_t)(rng() % (uint32_t)(2 * g));
            } else { /* inside column 63 to far right, or to the edge */
                x0 = 63 * g + 1 + (int32_t)(rng() % (uint32_t)(g - 1));
                x1 = rng() % 2 ? w * g + (int32_t)(rng() % (uint32_t)(3 * g))
                               : x0 + 64 * g + (int32_t)(rng() % (uint32_t)(64 * g));
            }
            if (rng() % 2) { /* either orientation */
                int32_t x = x0;
                x0 = x1;
                x1 = x;
            }
            pts[4 * q].x = x0;
            pts[4 * q].y = y0;
            pts[4 * q + 1].x = x1;
            pts[4 * q + 1].y = y0;
            pts[4 * q + 2].x = x1;
            pts[4 * q + 2].y = y1;
            pts[4 * q + 3].x = x0 + (int32_t)(rng() % 3) - 1; /* not always straight */
            pts[4 * q + 3].y = y1;
            sizes[q] = 4;
        }
        poly.nrings = bigp.nrings = (uint32_t)nq + 1;
        for (i = 0; i < 4 * (nq + 1); i++) {
            big[i].x = s >= kb ? pts[i].x : pts[i].x * (K >> s);
            big[i].y = s >= kb ? pts[i].y : pts[i].y * (K >> s);
        }
        ss_opts(kb, s, &o, &fo);
        memset(out, 0xA5, sizeof out);
        CHECK(cover(&poly, NULL, 0, &o, &clip, f, &out[0][0], (ptrdiff_t)sizeof out[0]) == RAST_OK);
        check_ss_polygon(&bigp, 4 * ((uint32_t)nq + 1), &fo, &out[0][0], DW, w, h, f, kb,
                         &fine[0][0], sizeof fine[0]);
    }
}
#undef DW

/* A triangle batch big[0 .. 3 nt) (clip-relative, S = s) by ssK (k =
 * 2^kb) into out (the clip, rows of ow words, format f; tris[] holds the
 * batch moved to the clip) against the union of its triangles, each filled
 * on its own ("xscan" on the vertices scaled by k, overwriting a byte
 * target: a union, whatever overlaps) into fine (rows of fs bytes), big[]
 * scaled by k on the way. */
static void check_ss_batch(rast_point *big, rast_point *tris, int32_t nt, int32_t kb, int32_t s,
                           rast_coverage_format f, const rast_rect *clip, uint64_t *out,
                           int32_t ow, uint8_t *fine, size_t fs)
{
    const int32_t K = 1 << kb, g = 1 << s, w = clip->x1 - clip->x0, h = clip->y1 - clip->y0;
    rast_coverage_opts o;
    rast_fill_opts fo;
    rast_target t;
    uint8_t one = 1;
    int32_t i;
    for (i = 0; i < 3 * nt; i++) {
        tris[i].x = big[i].x + clip->x0 * g;
        tris[i].y = big[i].y + clip->y0 * g;
        big[i].x = s >= kb ? big[i].x : big[i].x * (K >> s);
        big[i].y = s >= kb ? big[i].y : big[i].y * (K >> s);
    }
    ss_opts(kb, s, &o, &fo); /* o.rule: ignored */
    fo.rule = RAST_RULE_EVENODD; /* one triangle: either */
    memset(out, 0xA5, (size_t)h * (size_t)ow * 8);
    CHECK(cover(NULL, nt ? tris : NULL, (uint32_t)nt, &o, clip, f, out, (ptrdiff_t)ow * 8) ==
          RAST_OK);
    memset(fine, 0, (size_t)(h * K) * fs);
    CHECK(rast_target_init(&t, fine, w * K, h * K, (int32_t)fs, RAST_FORMAT_GRAY8) == RAST_OK);
    for (i = 0; i < nt; i++) {
        uint32_t three = 3;
        rast_polygon p = {&big[3 * i], &three, 1};
        size_t need;
        unsigned char *sc;
        CHECK(rast_scratch_size(&fo, 3, w * K, h * K, &need) == RAST_OK);
        sc = scratch_for(need);
        CHECK(rast_fill_polygon(&t, &p, &fo, &one, sc, need) == RAST_OK);
    }
    check_ss_image(out, ow, w, h, f, kb, fine, fs, 1);
}

/* Triangle batches by supersampling against the union of the triangles
 * (check_ss_batch).  Overlapping,
 * repeated in the other orientation, degenerate, with horizontal edges,
 * reaching past the clip, on a clip off the origin wider than a word of
 * bits, in every format. */
#define WT 140
static void test_ss_triangles(void)
{
    int iter, n = check_count(80);
    static uint8_t fine[8 * 4][8 * WT];
    static uint64_t out[4][WT];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 3), s = (int32_t)(rng() % 4), g = 1 << s;
        int32_t nt = (int32_t)(rng() % 7), i, h = 4;
        rast_coverage_format f = (rast_coverage_format)(rng() % 3);
        rast_point tris[3 * 6], big[3 * 6];
        rast_rect clip;
        clip.x0 = (int32_t)(rng() % 100) - 60;
        clip.y0 = (int32_t)(rng() % 9) - 4;
        clip.x1 = clip.x0 + WT;
        clip.y1 = clip.y0 + h;
        for (i = 0; i < 3 * nt; i++) {
            int32_t x = (int32_t)(rng() % (uint32_t)((WT + 20) * g)) - 10 * g;
            int32_t y = (int32_t)(rng() % (uint32_t)((h + 4) * g)) - 2 * g;
            if (i % 3 && rng() % 4 == 0) y = big[i - 1].y; /* a horizontal edge */
            big[i].x = x;
            big[i].y = y;
        }
        if (nt > 1 && rng() % 2) { /* a triangle twice, the other way round */
            big[3] = big[0];
            big[4] = big[2];
            big[5] = big[1];
        }
        if (nt > 2 && rng() % 3 == 0) big[8] = big[7]; /* degenerate */
        check_ss_batch(big, tris, nt, kb, s, f, &clip, &out[0][0], WT, &fine[0][0], sizeof fine[0]);
    }
}
#undef WT

/* Meshes in one batch (a jittered grid of nx x ny cells, each cut by one
 * of its diagonals, every triangle's vertices in a random order): their
 * inner edges, given once each way, cancel, and what is left (the
 * outline, at most half the edges) is walked as one polygon.  Jitter
 * large enough to fold cells over their neighbours (overlaps), now and
 * then a triangle repeated (either way round), a degenerate one or a
 * stray one across the mesh, vertices on sample points (S = 0) or not,
 * meshes past the clip's edges, against the union (check_ss_batch). */
#define WG 140
#define HG 6
static void test_ss_mesh(void)
{
    int iter, n = check_count(150);
    static uint8_t fine[8 * HG][8 * WG];
    static uint64_t out[HG][WG];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 3), s = (int32_t)(rng() % 4), g = 1 << s;
        int32_t nx = 1 + (int32_t)(rng() % 6), ny = 1 + (int32_t)(rng() % 6), i, j, k, nt = 0;
        int32_t cw = 2 + (int32_t)(rng() % 24), ch = 1 + (int32_t)(rng() % 3);
        int32_t jit = (int32_t)(rng() % 3) * g / 2, x0, y0, h = 1 + (int32_t)(rng() % HG);
        rast_coverage_format f = (rast_coverage_format)(rng() % 4 == 0 ? rng() % 3 : 0);
        rast_point grid[7][7], tris[3 * 76], big[3 * 76];
        rast_rect clip;
        clip.x0 = (int32_t)(rng() % 40) - 20;
        clip.y0 = (int32_t)(rng() % 9) - 4;
        clip.x1 = clip.x0 + WG;
        clip.y1 = clip.y0 + h;
        x0 = (int32_t)(rng() % (uint32_t)(40 * g)) - 20 * g;
        y0 = (int32_t)(rng() % (uint32_t)(4 * g)) - 2 * g;
        for (i = 0; i <= ny; i++)
            for (j = 0; j <= nx; j++) {
                grid[i][j].x = x0 + j * cw * g + (jit ? (int32_t)(rng() % (uint32_t)(2 * jit + 1)) - jit : 0);
                grid[i][j].y = y0 + i * ch * g + (jit ? (int32_t)(rng() % (uint32_t)(2 * jit + 1)) - jit : 0);
            }
        for (i = 0; i < ny; i++)
            for (j = 0; j < nx; j++) {
                const rast_point a = grid[i][j], b = grid[i][j + 1], c = grid[i + 1][j + 1],
                                 d = grid[i + 1][j];
                rast_point q[6];
                if (rng() % 2) {
                    q[0] = a, q[1] = b, q[2] = c, q[3] = a, q[4] = c, q[5] = d;
                } else {
                    q[0] = a, q[1] = b, q[2] = d, q[3] = b, q[4] = c, q[5] = d;
                }
                for (k = 0; k < 2; k++) { /* its vertices in a random order */
                    const int32_t r = (int32_t)(rng() % 3), sw = (int32_t)(rng() % 2);
                    big[3 * nt] = q[3 * k + r];
                    big[3 * nt + 1] = q[3 * k + (r + 1 + sw) % 3];
                    big[3 * nt + 2] = q[3 * k + (r + 2 - sw) % 3];
                    nt++;
                }
            }
        if (rng() % 3 == 0) { /* a triangle again, either way round */
            big[3 * nt] = big[0];
            big[3 * nt + 1] = big[rng() % 2 ? 1 : 2];
            big[3 * nt + 2] = big[3 * nt + 1].x == big[1].x && big[3 * nt + 1].y == big[1].y ? big[2] : big[1];
            nt++;
        }
        if (rng() % 3 == 0) { /* a degenerate one on a mesh vertex */
            big[3 * nt] = grid[0][0];
            big[3 * nt + 1] = grid[ny][nx];
            big[3 * nt + 2] = grid[0][0];
            nt++;
        }
        if (rng() % 4 == 0) { /* a stray one across the mesh */
            for (k = 0; k < 3; k++) {
                big[3 * nt + k].x = x0 + (int32_t)(rng() % (uint32_t)((nx * cw + 1) * g));
                big[3 * nt + k].y = y0 + (int32_t)(rng() % (uint32_t)((ny * ch + 1) * g));
            }
            nt++;
        }
        check_ss_batch(big, tris, nt, kb, s, f, &clip, &out[0][0], WG, &fine[0][0], sizeof fine[0]);
    }
}
#undef WG
#undef HG

/* Batches of many triangles (more than 256 on an output row: the walk then
 * keeps columns covered on all k fine rows and skips triangles inside them):
 * a few wide ones across the clip's rows, many inside them (about: some
 * reach out), slivers across their edges and elsewhere, repeats the other
 * way round, degenerate ones and horizontal edges, vertices inside output
 * rows, some reaching past the clip, against the same reference as
 * above. */
#define WM 90
#define HM 6
static void test_ss_many_triangles(void)
{
    int iter, n = check_count(40);
    static uint8_t fine[16 * HM][16 * WM];
    static uint64_t out[HM][WM];
    static rast_point tris[3 * 600], big[3 * 600];
    for (iter = 0; iter < n; iter++) {
        int32_t kb = 1 + (int32_t)(rng() % 4), s = (int32_t)(rng() % 3), g = 1 << s;
        int32_t nt = 300 + (int32_t)(rng() % 300), i, hosts = 1 + (int32_t)(rng() % 3);
        rast_coverage_format f = (rast_coverage_format)(rng() % 3);
        rast_rect clip;
        clip.x0 = (int32_t)(rng() % 40) - 20;
        clip.y0 = (int32_t)(rng() % 9) - 4;
        clip.x1 = clip.x0 + WM;
        clip.y1 = clip.y0 + HM;
        for (i = 0; i < nt; i++) {
            rast_point *v = &big[3 * i];
            int32_t k, kind = (int32_t)(rng() % 10);
            if (i < hosts) { /* a few wide ones, across the clip's rows */
                int32_t x0 = (int32_t)(rng() % (uint32_t)(WM * g)) - 10 * g;
                v[0].x = x0 + (int32_t)(rng() % (uint32_t)(40 * g));
                v[0].y = -2 * g - (int32_t)(rng() % (uint32_t)(2 * g));
                v[1].x = x0;
                v[1].y = (HM + 2) * g + (int32_t)(rng() % (uint32_t)(2 * g));
                v[2].x = x0 + 15 * g + (int32_t)(rng() % (uint32_t)(30 * g));
                v[2].y = (int32_t)(rng() % (uint32_t)((HM + 4) * g)) - 2 * g;
                if (rng() % 2) v[0].x = v[1].x; /* a vertical edge */
            } else if (kind < 4) { /* inside (about) one of the wide ones */
                const rast_point *h = &big[3 * (int32_t)(rng() % (uint32_t)hosts)];
                int32_t cx = (h[0].x + h[1].x + h[2].x) / 3, cy = (h[0].y + h[1].y + h[2].y) / 3;
                int32_t num = 1 + (int32_t)(rng() % 7); /* 1/8 .. 7/8 of the way out */
                for (k = 0; k < 3; k++) {
                    v[k].x = cx + (h[k].x - cx) * num / 8 + (int32_t)(rng() % 3) - 1;
                    v[k].y = cy + (h[k].y - cy) * num / 8 + (int32_t)(rng() % 3) - 1;
                }
            } else if (kind < 8) { /* a sliver, tall or short, anywhere */
                int32_t cx = (int32_t)(rng() % (uint32_t)((WM + 10) * g)) - 5 * g;
                int32_t w = 1 + (int32_t)(rng() % (uint32_t)(2 * g + 1));
                int32_t tall = rng() % 3 ? (HM + 4) * g : 3 * g;
                for (k = 0; k < 3; k++) {
                    v[k].x = cx + (int32_t)(rng() % (uint32_t)(2 * w + 1)) - w + (k == 2 ? 3 * w : 0);
                    v[k].y = (int32_t)(rng() % (uint32_t)(tall + 1)) - 2 * g;
                }
                v[2].x += (int32_t)(rng() % (uint32_t)(12 * g + 1)) - 6 * g; /* sloping */
            } else if (kind < 6) { /* one of the wide ones, grown a little */
                const rast_point *h = &big[3 * (int32_t)(rng() % (uint32_t)hosts)];
                for (k = 0; k < 3; k++) v[k] = h[k];
                v[rng() % 3].x += (int32_t)(rng() % 3) - 1;
            } else if (i > 0 && kind == 8) { /* the one before, the other way round */
                v[0] = big[3 * i - 3];
                v[1] = big[3 * i - 1];
                v[2] = big[3 * i - 2];
            } else { /* degenerate, or a horizontal edge */
                for (k = 0; k < 3; k++) {
                    v[k].x = (int32_t)(rng() % (uint32_t)((WM + 10) * g)) - 5 * g;
                    v[k].y = (int32_t)(rng() % (uint32_t)((HM + 4) * g)) - 2 * g;
                }
                v[2] = rng() % 2 ? v[1] : v[2];
                v[1].y = v[0].y;
            }
        }
        check_ss_batch(big, tris, nt, kb, s, f, &clip, &out[0][0], WM, &fine[0][0], sizeof fine[0]);
    }
}
#undef WM
#undef HM

/* ---- triangle batches ------------------------------------------------------------ */

static void test_mesh(void)
{
    /* a 4 x 4 grid of quads over [1, 9] x [1, 9], inner vertices jittered,
     * each quad two triangles in alternating orientations */
    rast_point v[25], tris[32 * 3];
    uint8_t out[H][W];
    rast_coverage_opts o;
    rast_rect clip = {0, 0, W, H};
    int r, c, k = 0, m;
    for (r = 0; r < 5; r++)
        for (c = 0; c < 5; c++) {
            int inner = r > 0 && r < 4 && c > 0 && c < 4;
            v[r * 5 + c].x = (1 + 2 * c) * 16 + (inner ? (int32_t)(rng() % 13) - 6 : 0);
            v[r * 5 + c].y = (1 + 2 * r) * 16 + (inner ? (int32_t)(rng() % 13) - 6 : 0);
        }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            rast_point a = v[r * 5 + c], b = v[r * 5 + c + 1], d = v[r * 5 + c + 6],
                       e = v[r * 5 + c + 5];
            tris[k++] = a, tris[k++] = b, tris[k++] = d;
            tris[k++] = a, tris[k++] = (r + c) % 2 ? e : d, tris[k++] = (r + c) % 2 ? d : e;
        }
    for (m = 0; m < 3; m++) {
        int i, j, ok = 1;
        memset(&o, 0, sizeof o);
        o.method = m == 0 ? RAST_AA_AREA : m == 1 ? RAST_AA_SS4 : RAST_AA_ACCUMULATE;
        o.subpixel_bits = 4;
        CHECK(cover(NULL, tris, 32, &o, &clip, RAST_COVERAGE_U8, &out[0][0], W) == RAST_OK);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                int in = i >= 1 && i < 9 && j >= 1 && j < 9;
                if (out[j][i] != (in ? 255 : 0)) ok = 0;
            }
        CHECK(ok);
    }
}

/* ---- area: translation by whole pixels ---------------------------------------------- */

static void test_translation(void)
{
    int iter, n = check_count(100);
    for (iter = 0; iter < n; iter++) {
        rast_point a[9], b[9];
        uint32_t size = 9;
        rast_polygon pa = {a, &size, 1}, pb = {b, &size, 1};
        rast_coverage_opts o;
        int32_t s = (int32_t)(rng() % 9), dx = (int32_t)(rng() % 200) - 100,
                dy = (int32_t)(rng() % 200) - 100, i;
        rast_rect ca = {0, 0, W, H}, cb;
        uint64_t oa[H][W], ob[H][W];
        for (i = 0; i < 9; i++) {
            a[i].x = (int32_t)(rng() % (uint32_t)((W + 2) << s)) - (1 << s);
            a[i].y = (int32_t)(rng() % (uint32_t)((H + 2) << s)) - (1 << s);
            b[i].x = a[i].x + dx * (1 << s);
            b[i].y = a[i].y + dy * (1 << s);
        }
        cb.x0 = dx;
        cb.y0 = dy;
        cb.x1 = dx + W;
        cb.y1 = dy + H;
        memset(&o, 0, sizeof o);
        o.rule = (rast_fill_rule)(rng() % 2);
        o.subpixel_bits = s;
        CHECK(cover(&pa, NULL, 0, &o, &ca, RAST_COVERAGE_FIX62, &oa[0][0], W * 8) == RAST_OK);
        CHECK(cover(&pb, NULL, 0, &o, &cb, RAST_COVERAGE_FIX62, &ob[0][0], W * 8) == RAST_OK);
        CHECK(memcmp(oa, ob, sizeof oa) == 0);
    }
}

/* ---- errors ---------------------------------------------------------------------- */

static int untouched(const uint8_t *p, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (p[k] != 0xAB) return 0;
    return 1;
}

static void test_errors(void)
{
    static const rast_point tri[3] = {{0, 0}, {64, 0}, {0, 64}};
    const uint32_t three = 3;
    rast_polygon p = {tri, &three, 1};
    rast_coverage_opts o;
    rast_rect clip = {0, 0, 4, 4};
    uint8_t out[4 * 8 + 8];
    size_t need;
    unsigned char *s;
    const char *name;
    memset(&o, 0, sizeof o);
    o.subpixel_bits = 4;
    CHECK(rast_coverage_scratch_size(&o, 3, 4, 4, &need) == RAST_OK);
    s = scratch_for(need);
    memset(out, 0xAB, sizeof out);
#define REFUSED(call, status) CHECK((call) == (status) && untouched(out, sizeof out))
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need - 1),
            RAST_E_SCRATCH);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s + 1, need),
            RAST_E_ALIGN);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 3, s, need), RAST_E_ARG);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U16, out + 1, 8, s, need),
            RAST_E_ARG);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, (rast_coverage_format)3, out, 4, s, need),
            RAST_E_ARG);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, NULL, 4, s, need), RAST_E_NULL);
    REFUSED(rast_polygon_coverage(NULL, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_NULL);
    REFUSED(rast_polygon_coverage(&p, NULL, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_NULL);
    REFUSED(rast_polygon_coverage(&p, &o, NULL, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_NULL);
    REFUSED(rast_triangles_coverage(NULL, 1, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need),
            RAST_E_NULL);
    o.method = RAST_AA_COUNT_;
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_ARG);
    o.method = RAST_AA_AREA;
    o.rule = (rast_fill_rule)2;
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_ARG);
    o.rule = RAST_RULE_EVENODD;
    o.sample = (rast_sample)2;
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_E_ARG);
    o.sample = RAST_SAMPLE_CENTER;
    o.subpixel_bits = 17;
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need),
            RAST_E_SUBPIXEL);
    o.subpixel_bits = 4;
    {
        rast_point far[3] = {{0, 0}, {RAST_COORD_MAX + 1, 0}, {0, 64}};
        rast_polygon pf = {far, &three, 1};
        REFUSED(rast_polygon_coverage(&pf, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need),
                RAST_E_RANGE);
        far[1].x = RAST_COORD_MAX; /* in range, but not times 16 with S = 0 */
        o.method = RAST_AA_SS16;
        o.subpixel_bits = 0;
        CHECK(rast_coverage_scratch_size(&o, 3, 4, 4, &need) == RAST_OK);
        s = scratch_for(need);
        REFUSED(rast_polygon_coverage(&pf, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need),
                RAST_E_RANGE);
        clip.x1 = RAST_MAX_DIM / 8;
        REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need),
                RAST_E_SIZE);
        clip.x1 = 4;
    }
    {
        rast_rect huge = {-RAST_MAX_DIM - 1, 0, 4, 4};
        o.method = RAST_AA_AREA;
        REFUSED(rast_polygon_coverage(&p, &o, &huge, RAST_COVERAGE_U8, out, 4, s, need),
                RAST_E_SIZE);
    }
    CHECK(rast_coverage_scratch_size(&o, RAST_MAX_POINTS + 1, 4, 4, &need) == RAST_E_TOO_MANY);
    CHECK(rast_coverage_scratch_size(&o, 3, -1, 4, &need) == RAST_E_SIZE);
    CHECK(rast_coverage_scratch_size(&o, 3, 4, 4, NULL) == RAST_E_NULL);
    CHECK(rast_aa_method_info(RAST_AA_SS8, &name) == RAST_OK && strcmp(name, "ss8") == 0);
    CHECK(rast_aa_method_info(RAST_AA_COUNT_, &name) == RAST_E_ARG);
    /* an empty clip writes nothing and is not an error */
    clip.x1 = 0;
    o.subpixel_bits = 4;
    CHECK(rast_coverage_scratch_size(&o, 3, 0, 4, &need) == RAST_OK);
    s = scratch_for(need);
    REFUSED(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 4, s, need), RAST_OK);
#undef REFUSED
}

/* ---- spans with coverage values ---------------------------------------------------- */

/* A run handed to a spans callback, into img (row stride w, the clip's
 * pixel (clip->x0, clip->y0) first): *ok cleared unless it lies in the
 * clip, after the last run (*y, *x1), and holds no 0. */
static void take_run(uint8_t *img, int32_t w, const rast_rect *clip, int32_t *py, int32_t *px1, int32_t *ok,
                     int32_t y, int32_t x0, int32_t x1, const uint8_t *v)
{
    int32_t x;
    if (x0 >= x1 || y < clip->y0 || y >= clip->y1 || x0 < clip->x0 || x1 > clip->x1 ||
        (y == *py && x0 <= *px1) || y < *py) {
        *ok = 0;
        return;
    }
    for (x = x0; x < x1; x++) {
        if (!v[x - x0]) *ok = 0;
        img[(size_t)(y - clip->y0) * (size_t)w + (size_t)(x - clip->x0)] = v[x - x0];
    }
    *py = y;
    *px1 = x1;
}

typedef struct span_img {
    uint8_t img[H][W];
    rast_rect clip;
    int32_t y, x1, calls, ok;
} span_img;

static void take_span(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *v)
{
    span_img *s = (span_img *)user;
    s->calls++;
    take_run(&s->img[0][0], W, &s->clip, &s->y, &s->x1, &s->ok, y, x0, x1, v);
}

/* Both spans calls (a polygon of 9 vertices, or the batch of 3 triangles
 * they make), every method, against the image rast_polygon_coverage or
 * rast_triangles_coverage writes. */
static void test_spans(void)
{
    int iter, n = check_count(300);
    for (iter = 0; iter < n; iter++) {
        rast_point pts[9];
        uint32_t size = 9;
        rast_polygon p = {pts, &size, 1};
        rast_coverage_opts o;
        rast_rect clip;
        uint8_t want[H][W];
        span_img s;
        size_t need;
        unsigned char *sc;
        int32_t i, tri = (int32_t)(rng() % 2);
        rast_polygon *pp = tri ? NULL : &p;
        for (i = 0; i < 9; i++) {
            pts[i].x = (int32_t)(rng() % ((W + 4) * 16)) - 32;
            pts[i].y = (int32_t)(rng() % ((H + 4) * 16)) - 32;
        }
        memset(&o, 0, sizeof o);
        o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
        o.rule = (rast_fill_rule)(rng() % 2);
        o.subpixel_bits = 4;
        o.sample = (rast_sample)(rng() % 2);
        clip.x0 = (int32_t)(rng() % 3) - 1;
        clip.y0 = (int32_t)(rng() % 3) - 1;
        clip.x1 = clip.x0 + W - 2;
        clip.y1 = clip.y0 + H - 2;
        CHECK(cover(pp, pts, 3, &o, &clip, RAST_COVERAGE_U8, &want[0][0], W) == RAST_OK);
        memset(&s, 0, sizeof s);
        s.clip = clip;
        s.y = INT32_MIN;
        s.ok = 1;
        CHECK(rast_coverage_scratch_size(&o, 9, W - 2, H - 2, &need) == RAST_OK);
        sc = scratch_for(need);
        CHECK((tri ? rast_triangles_coverage_spans(pts, 3, &o, &clip, take_span, &s, sc, need)
                   : rast_polygon_coverage_spans(&p, &o, &clip, take_span, &s, sc, need)) ==
              RAST_OK);
        CHECK(scratch_guard_ok(sc, need));
        CHECK(s.ok);
        for (i = 0; i < H - 2; i++) CHECK(memcmp(s.img[i], want[i], W - 2) == 0);
        /* errors: nothing handed on */
        s.calls = 0;
        if (tri) {
            CHECK(rast_triangles_coverage_spans(pts, 3, &o, &clip, NULL, &s, sc, need) ==
                  RAST_E_NULL);
            CHECK(rast_triangles_coverage_spans(pts, 3, &o, NULL, take_span, &s, sc, need) ==
                  RAST_E_NULL);
            CHECK(rast_triangles_coverage_spans(NULL, 3, &o, &clip, take_span, &s, sc, need) ==
                  RAST_E_NULL);
            CHECK(rast_triangles_coverage_spans(pts, 3, &o, &clip, take_span, &s, sc, need - 1) ==
                  RAST_E_SCRATCH);
            CHECK(rast_triangles_coverage_spans(pts, RAST_MAX_POINTS / 3 + 1, &o, &clip, take_span,
                                                &s, sc, need) == RAST_E_TOO_MANY);
            /* none: nothing to hand on, and no error */
            CHECK(rast_triangles_coverage_spans(NULL, 0, &o, &clip, take_span, &s, sc, need) ==
                  RAST_OK);
            pts[4].x = RAST_COORD_MAX + 1;
            CHECK(rast_triangles_coverage_spans(pts, 3, &o, &clip, take_span, &s, sc, need) ==
                  RAST_E_RANGE);
            o.rule = (rast_fill_rule)5;
            CHECK(rast_triangles_coverage_spans(pts, 3, &o, &clip, take_span, &s, sc, need) ==
                  RAST_E_ARG);
        } else {
            CHECK(rast_polygon_coverage_spans(&p, &o, &clip, NULL, &s, sc, need) == RAST_E_NULL);
            CHECK(rast_polygon_coverage_spans(&p, &o, &clip, take_span, &s, sc, need - 1) ==
                  RAST_E_SCRATCH);
            o.rule = (rast_fill_rule)5;
            CHECK(rast_polygon_coverage_spans(&p, &o, &clip, take_span, &s, sc, need) ==
                  RAST_E_ARG);
        }
        CHECK(s.calls == 0);
    }
}

/* One small convex ring a call, as Canvas.fill_polygon(aa=...) draws the
 * loop family's (coverage_small.c, which hands a row that is one run
 * straight to the levels entry and any other through
 * rast__cov_row_done): its spans, every method and sample, a clip cutting
 * it or not, against rast_polygon_coverage's array (the engines' levels),
 * no level 0 in a span.  Slivers (points at S = 8) whose supersampled
 * rows have a 0 between levels not 0, and random triangles up to 24
 * pixels across. */
#define WS 30
#define HS 24
/* An image of ROWS x COLS levels with its clip and run state, and the
 * spans callback TAKE that fills it through take_run. */
#define RUN_IMG(T, ROWS, COLS, TAKE)                                                         \
    typedef struct T {                                                                     \
        uint8_t img[ROWS][COLS];                                                           \
        rast_rect clip;                                                                    \
        int32_t y, x1, ok;                                                                 \
    } T;                                                                                   \
    static void TAKE(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *v)      \
    {                                                                                      \
        T *s = (T *)user;                                                                  \
        take_run(&s->img[0][0], COLS, &s->clip, &s->y, &s->x1, &s->ok, y, x0, x1, v);      \
    }

RUN_IMG(small_img, HS, WS, take_small)

static void test_spans_small(void)
{
    static const rast_point slivers[2][4] = {{{333, 1285}, {5811, 2639}, {5811, 2647}, {333, 1293}},
                                             {{333, 1306}, {5811, 2022}, {5811, 2030}, {333, 1313}}};
    int iter, n = check_count(400);
    for (iter = 0; iter < n; iter++) {
        rast_point pts[4];
        uint32_t size = iter < 2 * 2 * RAST_AA_COUNT_ ? 4 : 3;
        rast_polygon p = {pts, &size, 1};
        rast_coverage_opts o;
        rast_rect clip;
        uint8_t want[HS][WS];
        small_img s;
        size_t need;
        unsigned char *sc;
        int32_t i, y;
        memset(&o, 0, sizeof o);
        o.subpixel_bits = 8;
        o.rule = (rast_fill_rule)(rng() % 2);
        if (size == 4) { /* each sliver, each method, both samples */
            memcpy(pts, slivers[iter % 2], sizeof pts);
            o.method = (rast_aa_method)(iter / 2 % RAST_AA_COUNT_);
            o.sample = (rast_sample)(iter / (2 * RAST_AA_COUNT_) % 2);
        } else {
            const int32_t x = (int32_t)(rng() % (WS * 256)) - 512, y0 = (int32_t)(rng() % (HS * 256)) - 512;
            for (i = 0; i < 3; i++) {
                pts[i].x = x + (int32_t)(rng() % (24 * 256));
                pts[i].y = y0 + (int32_t)(rng() % (24 * 256));
            }
            o.method = (rast_aa_method)(rng() % RAST_AA_COUNT_);
            o.sample = (rast_sample)(rng() % 2);
        }
        clip.x0 = (int32_t)(rng() % 4);
        clip.y0 = (int32_t)(rng() % 4);
        clip.x1 = WS - (int32_t)(rng() % 4);
        clip.y1 = HS - (int32_t)(rng() % 4);
        memset(want, 0, sizeof want);
        CHECK(rast_coverage_scratch_size(&o, size, WS, HS, &need) == RAST_OK);
        sc = scratch_for(need);
        CHECK(rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, &want[0][0], WS, sc, need) ==
              RAST_OK);
        memset(&s, 0, sizeof s);
        s.clip = clip;
        s.y = INT32_MIN;
        s.ok = 1;
        CHECK(rast_polygon_coverage_spans(&p, &o, &clip, take_small, &s, sc, need) == RAST_OK);
        CHECK(s.ok);
        for (y = 0; y < HS; y++) CHECK(memcmp(s.img[y], want[y], WS) == 0);
    }
}

/* ---- what the scratch held before: nothing may depend on it ----------------- */

/* A staircase (horizontal runs at 12 heights over 36 rows, keys past one
 * byte of a radix pass), a ring across it and a triangle batch with
 * shared sides, each drawn "area" with the scratch filled four ways
 * before the call: the same bytes. */
static void test_scratch_content(void)
{
    static const unsigned char fills[4] = {0x00, 0xFF, 0x5A, 0xA5};
    rast_point pts[32];
    uint32_t sizes[2], n = 0, k, fi;
    rast_polygon p;
    rast_rect clip = {0, 0, 40, 40};
    static unsigned char first[40 * 40], out[40 * 40];
    rast_point tris[12] = {{256, 256}, {2560, 1408}, {256, 1408}, {2560, 1408}, {256, 256}, {2816, 256},
                           {768, 512}, {9000, 8000}, {1000, 8000}, {300, 9000}, {2000, 3000}, {9500, 9800}};
    int shape, rule;
    for (k = 0; k < 12; k++) { /* the staircase: down 3 pixels (+ 0.4), right 3, 12 times */
        pts[n].x = (int32_t)(k * 3 * 256 + 128);
        pts[n++].y = (int32_t)(k * 3 * 256 + 100);
        pts[n].x = (int32_t)((k + 1) * 3 * 256 + 128);
        pts[n++].y = (int32_t)(k * 3 * 256 + 100);
    }
    pts[n].x = 128, pts[n++].y = 36 * 256 + 100;
    sizes[0] = n;
    pts[n].x = 20 * 256, pts[n++].y = 50; /* a ring across it */
    pts[n].x = 38 * 256, pts[n++].y = 30 * 256;
    pts[n].x = 2 * 256, pts[n++].y = 38 * 256 + 77;
    sizes[1] = 3;
    p.points = pts;
    p.ring_sizes = sizes;
    for (shape = 0; shape < 2; shape++)
        for (rule = 0; rule < 2; rule++) {
            rast_coverage_opts o = {RAST_AA_AREA, rule ? RAST_RULE_NONZERO : RAST_RULE_EVENODD, 8,
                                    RAST_SAMPLE_CENTER};
            size_t need;
            unsigned char *s;
            p.nrings = 2;
            CHECK(rast_coverage_scratch_size(&o, shape ? 12 : n, 40, 40, &need) == RAST_OK);
            s = scratch_for(need);
            CHECK(s != NULL);
            if (!s) return;
            for (fi = 0; fi < 4; fi++) {
                memset(s, fills[fi], need);
                CHECK((shape ? rast_triangles_coverage(tris, 4, &o, &clip, RAST_COVERAGE_U8, out, 40, s, need)
                             : rast_polygon_coverage(&p, &o, &clip, RAST_COVERAGE_U8, out, 40, s, need)) ==
                      RAST_OK);
                if (fi == 0)
                    memcpy(first, out, sizeof out);
                else
                    CHECK(memcmp(first, out, sizeof out) == 0);
            }
        }
}


/* ---- long edges: the walk a band of rows at a time ------------------------- */

/* Polygons whose edges cross 32 rows or more each on the mean are walked a
 * band of rows at a time.  Random rings of 3 to 5 tall, steep edges over a
 * clip 120 rows high (some past its sides and ends, some vertices on half
 * pixels: rows to the exact sweep inside a band), clips from -1, 0 or 1,
 * "area" and "accumulate",
 * both rules, U8 and U16: the spans call hands on what the array call
 * writes, the scratch's guard holds, and the same image comes whatever the
 * scratch held before (filled four ways). */
#define WL 16
#define HL 120
/* take_span's, for the long edges' clip (WL x HL) */
RUN_IMG(long_img, HL, WL, take_long_span)

static void test_long_edges(void)
{
    static const unsigned char fills[4] = {0x00, 0xFF, 0x5A, 0xA5};
    static uint16_t first[HL][WL], out[HL][WL];
    int iter, n = check_count(60);
    for (iter = 0; iter < n; iter++) {
        rast_point pts[10];
        uint32_t sizes[2], k, np = 0, fi;
        rast_polygon p = {pts, sizes, 0};
        rast_coverage_opts o;
        rast_rect clip;
        rast_coverage_format f = rng() % 2 ? RAST_COVERAGE_U16 : RAST_COVERAGE_U8;
        size_t need, bpp = f == RAST_COVERAGE_U16 ? 2 : 1;
        unsigned char *sc;
        static long_img s;
        int32_t y;
        for (k = 0; k < 2; k++) {
            uint32_t m = 3 + rng() % 3, v;
            int32_t cx = (int32_t)(rng() % (WL * 256)), cy = 40 * 256 + (int32_t)(rng() % (40 * 256));
            for (v = 0; v < m; v++) { /* round (cx, cy), 7 to 9 pixels across, 40 to 60 down */
                int32_t dx = (int32_t)(rng() % (18 * 256)) - 9 * 256, dy = (int32_t)(rng() % (20 * 256)) + 40 * 256;
                pts[np].x = cx + (v % 2 ? dx : -dx / 2);
                pts[np].y = cy + (v < m / 2 ? -dy : dy) - (int32_t)v * 256;
                if (rng() % 3 == 0) pts[np].x &= ~127, pts[np].y &= ~127; /* half pixels */
                np++;
            }
            sizes[k] = m;
        }
        p.nrings = 2;
        clip.x0 = (int32_t)(rng() % 3) - 1; /* (a clip from x = -1: no shift of a negative) */
        clip.y0 = (int32_t)(rng() % 3) - 1;
        clip.x1 = clip.x0 + WL;
        clip.y1 = clip.y0 + HL;
        memset(&o, 0, sizeof o);
        o.method = rng() % 2 ? RAST_AA_AREA : RAST_AA_ACCUMULATE;
        o.rule = (rast_fill_rule)(rng() % 2);
        o.subpixel_bits = 8;
        o.sample = RAST_SAMPLE_CENTER;
        CHECK(rast_coverage_scratch_size(&o, np, WL, HL, &need) == RAST_OK);
        sc = scratch_for(need);
        CHECK(sc != NULL);
        if (!sc) return;
        for (fi = 0; fi < 4; fi++) {
            memset(sc, fills[fi], need);
            CHECK(rast_polygon_coverage(&p, &o, &clip, f, out, (ptrdiff_t)(WL * bpp), sc, need) == RAST_OK);
            CHECK(scratch_guard_ok(sc, need));
            if (fi == 0)
                memcpy(first, out, sizeof out);
            else
                CHECK(memcmp(first, out, (size_t)HL * WL * bpp) == 0);
        }
        if (f == RAST_COVERAGE_U8) { /* the spans: the same levels */
            memset(&s, 0, sizeof s);
            s.clip = clip;
            s.y = INT32_MIN;
            s.ok = 1;
            CHECK(rast_polygon_coverage_spans(&p, &o, &clip, take_long_span, &s, sc, need) == RAST_OK);
            CHECK(s.ok);
            for (y = 0; y < HL; y++)
                CHECK(memcmp(s.img[y], (const unsigned char *)first + (size_t)y * WL, WL) == 0);
        }
    }
}

int main(void)
{
    test_rectangles();
    test_acc_many();
    test_ss();
    test_ss_wide();
    test_ss_dense();
    test_ss_triangles();
    test_ss_mesh();
    test_ss_many_triangles();
    test_mesh();
    test_translation();
    test_errors();
    test_spans();
    test_spans_small();
    test_scratch_content();
    test_long_edges();
    return check_report("test_coverage");
}

/*
 * test_harden.c - issue 5's paths in the core: the AET with thousands of
 * edges starting on one row (a comb) against the per-sample reference, and
 * rast_fill_bounds: a fill cut to the bounds it gives paints the same
 * pixels as one over the whole clip, with scratch sized by the bounds
 * (exactly that much, guard bytes after it), for every algorithm, rule,
 * boundary mode, sample offset and rounding; a small polygon in the
 * largest clip needs a few hundred bytes where the clip would need more
 * than memory holds.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_RNG_SEED 55u
#include "check.h"
#include "ref.h"
#include "rastrum.h"

#define GUARD 0xA5
#define W 128
#define H 64

static uint64_t scratch_mem[(1 << 22) / 8];
#include "scratch.h"

/* Spans into a W x H image (pixels counted) whose (0, 0) is (ox, oy);
 * bad counts spans outside `clip`, out of order, or off the image. */
typedef struct {
    unsigned char img[W * H];
    rast_rect clip;
    int32_t ox, oy;
    int bad;
} span_img;

static void to_img(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_img *s = (span_img *)user;
    int32_t x;
    if (x0 >= x1 || y < s->clip.y0 || y >= s->clip.y1 || x0 < s->clip.x0 || x1 > s->clip.x1 ||
        y < s->oy || y >= s->oy + H || x0 < s->ox || x1 > s->ox + W) {
        s->bad++;
        return;
    }
    for (x = x0; x < x1; x++) s->img[(y - s->oy) * W + (x - s->ox)]++;
}

/* Fill through the span API into *si with exactly the scratch
 * rast_scratch_size asks for `clip`; RAST_OK and intact guards, or not. */
static rast_status fill_spans(const rast_polygon *p, const rast_fill_opts *o, const rast_rect *clip,
                              span_img *si, int32_t ox, int32_t oy)
{
    size_t need;
    unsigned char *scr;
    rast_status st;
    uint32_t k, n = 0;
    for (k = 0; k < p->nrings; k++) n += p->ring_sizes[k];
    memset(si, 0, sizeof *si);
    si->clip = *clip;
    si->ox = ox;
    si->oy = oy;
    st = rast_scratch_size(o, n, clip->x1 - clip->x0, clip->y1 - clip->y0, &need);
    if (st != RAST_OK) return st;
    scr = scratch_for(need);
    if (!scr) return RAST_E_SCRATCH;
    st = rast_fill_polygon_spans(p, o, clip, to_img, si, scr, need);
    if (st == RAST_OK && !scratch_guard_ok(scr, need)) st = RAST_E_ARG;
    return st;
}

static rast_fill_opts make_opts(int algo, int rule, int s, int center, int textbook, int boundary)
{
    rast_fill_opts o;
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_algorithm)algo;
    o.rule = (rast_fill_rule)rule;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    o.rounding = textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
    o.boundary = (rast_boundary)boundary;
    return o;
}

static int supports(int algo, int rule)
{
    uint32_t rules = 0;
    return rast_algorithm_info((rast_algorithm)algo, NULL, &rules) == RAST_OK && (rules >> rule & 1);
}

/* ---- a comb: thousands of edges joining the AET on one row ------------------- */

static rast_point comb[2 * 1500 + 3];

/* `teeth` teeth across the W px, hanging from row y0 (S = s), closed along
 * the row above: 2 x teeth edges start on one row. */
static uint32_t make_comb(uint32_t teeth, int s, int reverse)
{
    uint32_t k, n = 2 * teeth + 3;
    for (k = 0; k < teeth; k++) {
        int32_t x0 = (int32_t)(((int64_t)k * (W - 8) << s) / teeth) + (4 << s);
        int32_t x1 = (int32_t)(((int64_t)(k + 1) * (W - 8) << s) / teeth) + (4 << s);
        comb[2 * k].x = x0;
        comb[2 * k].y = 3 << s;
        comb[2 * k + 1].x = (x0 + x1) / 2 + (int32_t)(rng() % 3) - 1; /* some teeth lean */
        comb[2 * k + 1].y = ((H - 4) << s) - (int32_t)(rng() % (20u << s));
    }
    comb[2 * teeth].x = (W - 4) << s;
    comb[2 * teeth].y = 3 << s;
    comb[2 * teeth + 1].x = (W - 4) << s;
    comb[2 * teeth + 1].y = 1 << s;
    comb[2 * teeth + 2].x = 4 << s;
    comb[2 * teeth + 2].y = 1 << s;
    if (reverse)
        for (k = 0; k < n / 2; k++) {
            rast_point t = comb[k];
            comb[k] = comb[n - 1 - k];
            comb[n - 1 - k] = t;
        }
    return n;
}

static void test_comb(void)
{
    static const uint32_t teeth[] = {3, 40, 1500};
    static const int grids[][3] = {{8, 1, 0}, {0, 0, 0}, {4, 0, 1}};
    size_t a, gi;
    int bad = 0, filled = 0, rev;
    for (a = 0; a < sizeof teeth / sizeof teeth[0]; a++)
        for (gi = 0; gi < sizeof grids / sizeof grids[0]; gi++)
            for (rev = 0; rev < 2; rev++) {
                int s = grids[gi][0], center = grids[gi][1], textbook = grids[gi][2], rule;
                uint32_t n = make_comb(teeth[a], s, rev);
                rast_polygon p = {comb, &n, 1};
                rast_rect clip = {0, 0, W, H};
                /* the quick run (valgrind, qemu): the 1,500-tooth comb on
                 * one grid, one direction */
                if (check_count(5) < 5 && a == 2 && (gi != 0 || rev != 0)) continue;
                for (rule = 0; rule < 2; rule++) {
                    /* the reference once, then every algorithm against it */
                    static unsigned char ref[W * H];
                    int algo, i, j;
                    for (j = 0; j < H; j++)
                        for (i = 0; i < W; i++) {
                            int cr, w = ref_winding(comb, &n, 1, s, center, textbook, i, j, &cr);
                            ref[j * W + i] = (unsigned char)(rule ? w != 0 : cr & 1);
                        }
                    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
                        static span_img si;
                        rast_fill_opts o = make_opts(algo, rule, s, center, textbook, 0);
                        if (!supports(algo, rule)) continue;
                        if (fill_spans(&p, &o, &clip, &si, 0, 0) != RAST_OK || si.bad) bad++;
                        else if (memcmp(si.img, ref, sizeof ref) != 0) {
                            bad++;
                            fprintf(stderr, "  comb %u teeth: algorithm %d rule %d grid %d differs\n",
                                    teeth[a], algo, rule, (int)gi);
                        }
                    }
                    for (i = 0; i < W * H; i++) filled += ref[i];
                }
            }
    CHECK(bad == 0);
    CHECK(filled > 0);
}

/* ---- rast_fill_bounds -------------------------------------------------------- */

static rast_point poly_pts[64];

static void test_bounds_random(void)
{
    int trial, bad = 0, outside = 0, smaller = 0;
    for (trial = 0; trial < 60; trial++) {
        uint32_t sizes[2], n, k;
        rast_polygon p;
        int s = trial % 3 == 0 ? 0 : 4, algo, rule, boundary, c, t;
        int32_t span = trial % 4 == 0 ? 12 : 90; /* small shapes and ones over the edge */
        int32_t off = trial % 4 == 0 ? (int32_t)(rng() % 100) : -20;
        sizes[0] = 3 + rng() % 9;
        sizes[1] = trial % 5 == 0 ? 3 + rng() % 4 : 0;
        n = sizes[0] + sizes[1];
        for (k = 0; k < n; k++) {
            int32_t one = (int32_t)1 << s;
            poly_pts[k].x = (int32_t)(rng() % (uint32_t)(span * one)) + off * one;
            poly_pts[k].y = (int32_t)(rng() % (uint32_t)(span / 2 * one)) + off / 2 * one;
        }
        if (trial % 7 == 3) poly_pts[2] = poly_pts[0]; /* a spike: zero-area part */
        p.points = poly_pts;
        p.ring_sizes = sizes;
        p.nrings = sizes[1] ? 2 : 1;
        for (algo = 0; algo < RAST_ALGO_COUNT_; algo++)
            for (rule = 0; rule < 2; rule++)
                for (boundary = 0; boundary < 3; boundary++)
                    for (c = 0; c < 2; c++)
                        for (t = 0; t < 2; t++) {
                            static span_img whole, cut;
                            rast_fill_opts o = make_opts(algo, rule, s, c, t, boundary);
                            rast_rect clip = {0, 0, W, H}, b;
                            size_t need_clip, need_cut;
                            int i, j;
                            if (!supports(algo, rule)) continue;
                            if (rast_fill_bounds(&o, &p, &clip, &b) != RAST_OK) { bad++; continue; }
                            if (b.x0 < clip.x0 || b.x1 > clip.x1 || b.y0 < clip.y0 || b.y1 > clip.y1 ||
                                b.x0 > b.x1 || b.y0 > b.y1) { bad++; continue; }
                            if (fill_spans(&p, &o, &clip, &whole, 0, 0) != RAST_OK || whole.bad) bad++;
                            if (fill_spans(&p, &o, &b, &cut, 0, 0) != RAST_OK || cut.bad) bad++;
                            if (memcmp(whole.img, cut.img, sizeof whole.img) != 0) bad++;
                            for (j = 0; j < H; j++)
                                for (i = 0; i < W; i++)
                                    if (whole.img[j * W + i] && (i < b.x0 || i >= b.x1 || j < b.y0 || j >= b.y1))
                                        outside++;
                            rast_scratch_size(&o, n, W, H, &need_clip);
                            rast_scratch_size(&o, n, b.x1 - b.x0, b.y1 - b.y0, &need_cut);
                            if (need_cut > need_clip) bad++;
                            smaller += need_cut < need_clip;
                        }
    }
    CHECK(bad == 0);
    CHECK(outside == 0);
    CHECK(smaller > 0);
}

/* A 5-pixel triangle in the largest span clip: the mask algorithms would
 * need 2^57 bytes for the clip (or SIZE_MAX), a few hundred for the
 * bounds; the fill cut to them equals the reference. */
static void test_small_in_huge(void)
{
    rast_point tri[3] = {{-3 * 16, 2 * 16}, {2 * 16 + 5, -16}, {0, 5 * 16 + 3}};
    uint32_t n = 3;
    rast_polygon p = {tri, &n, 1};
    const rast_rect huge = {-RAST_MAX_DIM, -RAST_MAX_DIM, RAST_MAX_DIM, RAST_MAX_DIM};
    int algo, rule, bad = 0, filled = 0;
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++)
        for (rule = 0; rule < 2; rule++) {
            static span_img si;
            rast_fill_opts o = make_opts(algo, rule, 4, 1, 0, 0);
            rast_rect b;
            size_t big = 0, small = 0;
            int i, j;
            if (!supports(algo, rule)) continue;
            CHECK(rast_fill_bounds(&o, &p, &huge, &b) == RAST_OK);
            CHECK(b.x0 >= -4 && b.x1 <= 3 && b.y0 >= -2 && b.y1 <= 6);
            CHECK(rast_scratch_size(&o, n, b.x1 - b.x0, b.y1 - b.y0, &small) == RAST_OK);
            CHECK(small <= 512);
            CHECK(rast_scratch_size(&o, n, huge.x1 - huge.x0 > RAST_MAX_DIM ? RAST_MAX_DIM : huge.x1 - huge.x0,
                                    RAST_MAX_DIM, &big) == RAST_OK);
            if (algo == RAST_ALGO_EDGEFILL || algo == RAST_ALGO_FENCE || algo == RAST_ALGO_EDGEFLAG)
                CHECK(big > ((size_t)1 << 30) || big == (size_t)-1);
            /* the clip's contract is unchanged: the huge clip with the
             * small scratch is refused, whatever the polygon */
            if (big > small)
                CHECK(rast_fill_polygon_spans(&p, &o, &huge, to_img, &si, scratch_mem, small) == RAST_E_SCRATCH);
            if (fill_spans(&p, &o, &b, &si, -W / 2, -H / 2) != RAST_OK || si.bad) bad++;
            for (j = -H / 2; j < H / 2; j++)
                for (i = -W / 2; i < W / 2; i++) {
                    int cr, w = ref_winding(tri, &n, 1, 4, 1, 0, i, j, &cr);
                    int want = rule ? w != 0 : cr & 1;
                    if (si.img[(j + H / 2) * W + i + W / 2] != want) bad++;
                    filled += want;
                }
        }
    CHECK(bad == 0);
    CHECK(filled > 0);
}

static void test_bounds_errors(void)
{
    rast_point tri[3] = {{0, 0}, {10, 0}, {0, 10}};
    uint32_t n = 3;
    rast_polygon p = {tri, &n, 1};
    rast_fill_opts o = make_opts(RAST_ALGO_AET, 0, 0, 1, 0, 0);
    rast_rect clip = {0, 0, 8, 8}, b = {7, 7, 7, 7}, bad_clip = {0, 0, RAST_MAX_DIM + 1, 8};
    CHECK(rast_fill_bounds(NULL, &p, &clip, &b) == RAST_E_NULL);
    CHECK(rast_fill_bounds(&o, NULL, &clip, &b) == RAST_E_NULL);
    CHECK(rast_fill_bounds(&o, &p, NULL, &b) == RAST_E_NULL);
    CHECK(rast_fill_bounds(&o, &p, &clip, NULL) == RAST_E_NULL);
    CHECK(rast_fill_bounds(&o, &p, &bad_clip, &b) == RAST_E_SIZE);
    tri[1].x = RAST_COORD_MAX + 1;
    CHECK(rast_fill_bounds(&o, &p, &clip, &b) == RAST_E_RANGE);
    tri[1].x = 10;
    o.algorithm = RAST_ALGO_COUNT_;
    CHECK(rast_fill_bounds(&o, &p, &clip, &b) == RAST_E_ALGORITHM);
    CHECK(b.x0 == 7 && b.y0 == 7 && b.x1 == 7 && b.y1 == 7); /* untouched on error */
    o.algorithm = RAST_ALGO_AET;
    /* no points, or nothing inside the clip: an empty rectangle */
    n = 0;
    CHECK(rast_fill_bounds(&o, &p, &clip, &b) == RAST_OK);
    CHECK(b.x0 == b.x1 && b.y0 == b.y1);
    n = 3;
    clip.x0 = 20;
    clip.x1 = 30;
    CHECK(rast_fill_bounds(&o, &p, &clip, &b) == RAST_OK);
    CHECK(b.x0 == b.x1 && b.y0 == b.y1);
}

int main(void)
{
    test_bounds_errors();
    test_comb();
    test_bounds_random();
    test_small_in_huge();
    return check_report("test_harden");
}

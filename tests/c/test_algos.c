/*
 * test_algos.c - every polygon algorithm of the registry against a
 * brute-force per-sample reference and against the AET: random polygons
 * (self-intersecting, holes, collinear and repeated points, vertices on
 * samples, axis-parallel edges), S in {0, 1, 4, 8, 16}, both sample
 * offsets, both roundings, every supported rule; guard bytes around the
 * target and after a scratch buffer of exactly the size asked for;
 * coordinates at +-RAST_COORD_MAX; thousands of vertices; errors.
 */
#define RAST_STATIC_LINKING_ONLY /* the other algorithms' scratch bounds */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_RNG_SEED 2024u
#include "check.h"
#include "ref.h"
#include "rastrum.h"

#define GUARD 0xA5
#define PAD 16
#define MAXW 300
#define STRIDE (MAXW + 2 * PAD)

/* ---- the reference: ref.h, DESIGN section 1 one sample at a time ---------- */
typedef struct {
    int s, center, textbook;
} grid;

static int parity_bad; /* the parity of w is the parity of the count */
static int ref_inside(const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                      const grid *gr, int rule, int64_t i, int64_t j)
{
    int n, w = ref_winding(pts, sizes, nrings, gr->s, gr->center, gr->textbook, i, j, &n);
    if (rule == RAST_RULE_EVENODD) {
        parity_bad += (n & 1) != (w & 1);
        return n & 1;
    }
    return w != 0;
}

/* ---- filling with guards ------------------------------------------------------ */

static uint64_t scratch_mem[(1 << 25) / 8]; /* 32 MiB: the AET of 196608 vertices */
#include "scratch.h"
static const char *algo_name(int a)
{
    const char *name = "?";
    rast_algorithm_info((rast_algorithm)a, &name, NULL);
    return name;
}

static rast_fill_opts make_opts(int algo, int rule, const grid *gr)
{
    rast_fill_opts o;
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_algorithm)algo;
    o.rule = (rast_fill_rule)rule;
    o.subpixel_bits = gr->s;
    o.sample = gr->center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    o.rounding = gr->textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
    return o;
}

/* Fill into a guarded w x h gray8 buffer over `background` (solid painter
 * over zeros, or opaque over garbage with clip `clip` or the whole target),
 * with exactly the scratch rast_scratch_size asks for.  1 when the call
 * succeeded and every guard byte (around the target and after the
 * scratch) is intact. */
static int guarded_fill(unsigned char *buf, const rast_polygon *p, const rast_fill_opts *o,
                        int w, int h, int opaque, const rast_rect *clip)
{
    int stride = STRIDE, i, j, ok = 1;
    rast_target t;
    unsigned char one = 1, zero = 0, *scr;
    size_t need;
    memset(buf, GUARD, (size_t)STRIDE * (MAXW + 2 * PAD));
    for (j = 0; j < h; j++) memset(buf + (j + PAD) * stride + PAD, opaque ? 0x77 : 0, (size_t)w);
    if (rast_target_init(&t, buf + PAD * stride + PAD, w, h, stride, RAST_FORMAT_GRAY8) != RAST_OK) return 0;
    if (clip) t.clip = *clip;
    {
        uint32_t k, n = 0;
        for (k = 0; k < p->nrings; k++) n += p->ring_sizes[k];
        if (rast_scratch_size(o, n, t.clip.x1 - t.clip.x0, t.clip.y1 - t.clip.y0, &need) != RAST_OK)
            return 0;
    }
    scr = scratch_for(need);
    if (!scr) return 0;
    if (opaque) {
        if (rast_fill_polygon_opaque(&t, p, o, &one, &zero, scr, need) != RAST_OK) ok = 0;
    } else {
        if (rast_fill_polygon(&t, p, o, &one, scr, need) != RAST_OK) ok = 0;
    }
    ok &= scratch_guard_ok(scr, need);
    for (j = -PAD; j < h + PAD; j++)
        for (i = -PAD; i < w + PAD; i++)
            if ((i < 0 || j < 0 || i >= w || j >= h) && buf[(j + PAD) * stride + i + PAD] != GUARD) ok = 0;
    return ok;
}

static int px(const unsigned char *buf, int i, int j)
{
    return buf[(j + PAD) * STRIDE + i + PAD];
}

/* One case: every algorithm and supported rule against the reference and
 * against the AET; solid and opaque painters; a narrowed clip.  The mask
 * fillers hold a row in 64-bit words: widths past 128 give runs with whole
 * words in the middle, widths of 64k runs that end with a word.  Returns
 * the number of failing (algorithm, rule) runs, and prints the first. */
static int failures_printed;
static int check_case(const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                      const grid *gr, int w, int h)
{
    static unsigned char buf[STRIDE * (MAXW + 2 * PAD)], aet[STRIDE * (MAXW + 2 * PAD)];
    static unsigned char ref[2][MAXW * MAXW];
    rast_polygon p;
    rast_rect narrow;
    int algo, rule, i, j, bad = 0;
    p.points = pts;
    p.ring_sizes = sizes;
    p.nrings = nrings;
    narrow.x0 = w / 3;
    narrow.y0 = h / 4;
    narrow.x1 = w - w / 5;
    narrow.y1 = h - h / 3;
    for (rule = 0; rule < 2; rule++)
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++) ref[rule][j * w + i] = (unsigned char)ref_inside(pts, sizes, nrings, gr, rule, i, j);
    for (rule = 0; rule < 2; rule++) {
        rast_fill_opts o = make_opts(RAST_ALGO_AET, rule, gr);
        if (!guarded_fill(aet, &p, &o, w, h, 0, NULL)) bad++;
        for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
            uint32_t rules = 0;
            int ok = 1, pass;
            if (rast_algorithm_info((rast_algorithm)algo, NULL, &rules) != RAST_OK) continue;
            if (!(rules >> rule & 1)) continue;
            o = make_opts(algo, rule, gr);
            for (pass = 0; pass < 3; pass++) {
                int opaque = pass > 0;
                const rast_rect *clip = pass == 2 ? &narrow : NULL;
                if (!guarded_fill(buf, &p, &o, w, h, opaque, clip)) ok = 0;
                for (j = 0; j < h; j++)
                    for (i = 0; i < w; i++) {
                        int got = px(buf, i, j);
                        int in_clip = !clip || (i >= clip->x0 && i < clip->x1 && j >= clip->y0 && j < clip->y1);
                        int want = in_clip ? ref[rule][j * w + i] : (opaque ? 0x77 : 0);
                        if (got != want) ok = 0;
                        if (!clip && got != px(aet, i, j)) ok = 0;
                    }
            }
            if (!ok) {
                bad++;
                if (failures_printed++ < 5)
                    fprintf(stderr, "  mismatch: %s rule %d S %d center %d textbook %d %dx%d, %u ring(s)\n",
                            algo_name(algo), rule, gr->s, gr->center, gr->textbook, w, h, nrings);
            }
        }
    }
    return bad;
}

/* ---- random polygons ----------------------------------------------------------- */

static const int S_VALUES[] = {0, 1, 4, 8, 16};

/* The fixed-point coordinate of the sample of the pixel holding v. */
static int32_t on_sample(int32_t v, const grid *gr)
{
    int32_t one = (int32_t)1 << gr->s, q = v / one;
    if (v % one < 0) q--;
    return q * one + (gr->center ? one / 2 : 0);
}

static void test_random(void)
{
    static rast_point pts[64];
    uint32_t sizes[4];
    int iter, bad = 0;
    for (iter = 0; iter < 1500; iter++) {
        grid gr;
        int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 40), kind = (int)(rng() % 4);
        /* one case in four wider than a mask word, some exactly 64 or 128
         * (a run reaching the end of the last word) */
        if (iter % 4 == 3) {
            static const int wide[4] = {64, 128, 192, 256};
            w = iter % 8 == 3 ? wide[(iter / 8) % 4] : 41 + (int)(rng() % 250);
            h = 1 + (int)(rng() % 24);
        }
        uint32_t nrings = 1, k, v, total = 0;
        int32_t one, span;
        gr.s = S_VALUES[rng() % 5];
        gr.center = (int)(rng() & 1);
        gr.textbook = (int)(rng() % 3 == 0);
        one = (int32_t)1 << gr.s;
        span = (int32_t)((w > h ? w : h) + 8);
        if (kind == 0) {
            /* random vertex lists: self-intersecting, 1-3 rings */
            nrings = 1 + rng() % 3;
            for (k = 0; k < nrings; k++) {
                sizes[k] = 3 + rng() % 8;
                for (v = 0; v < sizes[k]; v++, total++) {
                    pts[total].x = (int32_t)(rng() % (uint32_t)(span * one)) - 4 * one;
                    pts[total].y = (int32_t)(rng() % (uint32_t)(span * one)) - 4 * one;
                }
            }
        } else if (kind == 1) {
            /* a box with a hole running the other way (or, one case in
             * two, the same way: non-zero then fills the hole) */
            int32_t x0 = (int32_t)(rng() % (uint32_t)(w * one + 1)) - 2 * one;
            int32_t y0 = (int32_t)(rng() % (uint32_t)(h * one + 1)) - 2 * one;
            int32_t bw = 3 * one + (int32_t)(rng() % (uint32_t)(w * one + 1));
            int32_t bh = 3 * one + (int32_t)(rng() % (uint32_t)(h * one + 1));
            int32_t ix = x0 + bw / 4, iy = y0 + bh / 3, iw = bw / 2, ih = bh / 3;
            int same = (int)(rng() & 1);
            nrings = 2;
            sizes[0] = 4;
            pts[0].x = x0; pts[0].y = y0;
            pts[1].x = x0 + bw; pts[1].y = y0;
            pts[2].x = x0 + bw; pts[2].y = y0 + bh;
            pts[3].x = x0; pts[3].y = y0 + bh;
            sizes[1] = 4;
            pts[4].x = ix; pts[4].y = iy;
            pts[5].x = same ? ix + iw : ix; pts[5].y = same ? iy : iy + ih;
            pts[6].x = ix + iw; pts[6].y = iy + ih;
            pts[7].x = same ? ix : ix + iw; pts[7].y = same ? iy + ih : iy;
            total = 8;
        } else if (kind == 2) {
            /* collinear and repeated points: a random ring with midpoints
             * (exact when the difference is even) and doubled vertices */
            uint32_t n = 3 + rng() % 6;
            rast_point base_pts[8];
            for (v = 0; v < n; v++) {
                base_pts[v].x = 2 * ((int32_t)(rng() % (uint32_t)(span * one)) / 2) - 4 * one;
                base_pts[v].y = 2 * ((int32_t)(rng() % (uint32_t)(span * one)) / 2) - 4 * one;
            }
            for (v = 0; v < n; v++) {
                rast_point a = base_pts[v], b = base_pts[(v + 1) % n];
                pts[total++] = a;
                if (rng() & 1) pts[total++] = a;
                pts[total].x = (a.x + b.x) / 2;
                pts[total].y = (a.y + b.y) / 2;
                total++;
            }
            sizes[0] = total;
        } else {
            /* vertices on samples, with axis-parallel runs */
            uint32_t n = 3 + rng() % 10;
            for (v = 0; v < n; v++, total++) {
                pts[total].x = on_sample((int32_t)(rng() % (uint32_t)(span * one)) - 4 * one, &gr);
                pts[total].y = on_sample((int32_t)(rng() % (uint32_t)(span * one)) - 4 * one, &gr);
                if (v > 0 && rng() % 3 == 0) pts[total].x = pts[total - 1].x;
                if (v > 0 && rng() % 3 == 0) pts[total].y = pts[total - 1].y;
            }
            sizes[0] = total;
        }
        bad += check_case(pts, sizes, nrings, &gr, w, h);
    }
    CHECK(bad == 0);
}

/* ---- coordinates at the limit ------------------------------------------------------ */
static void test_limits(void)
{
    const int32_t M = RAST_COORD_MAX;
    int s, c, t, bad = 0;
    for (s = 0; s <= RAST_MAX_SUBPIXEL_BITS; s++)
        for (c = 0; c < 2; c++)
            for (t = 0; t < 2; t++) {
                grid gr;
                rast_point a[3] = {{-M, -M}, {M, M - 1}, {M, M}};
                rast_point b[3] = {{-M, 0}, {M, -M}, {M, M}};
                rast_point sq[4] = {{-M, -M}, {M, -M}, {M, M}, {-M, M}};
                rast_point thin[4] = {{-M, 1}, {M, 2}, {M, 40 << s < M ? 40 << s : M}, {-M, 30}};
                uint32_t n3 = 3, n4 = 4;
                gr.s = s;
                gr.center = c;
                gr.textbook = t;
                bad += check_case(a, &n3, 1, &gr, 40, 40);
                bad += check_case(b, &n3, 1, &gr, 40, 40);
                bad += check_case(sq, &n4, 1, &gr, 17, 9);
                bad += check_case(thin, &n4, 1, &gr, 33, 40);
            }
    CHECK(bad == 0);
}

/* Far from the origin: a clip of the span API at column and row ~2^27
 * (S = 0), where the polygon's vertices sit at the coordinate limit. */
typedef struct {
    rast_rect clip;
    unsigned char img[40 * 40];
    int bad;
    int32_t last_y, last_x1;
} span_img;

static void to_img(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_img *s = (span_img *)user;
    int32_t x;
    if (x0 >= x1 || y < s->clip.y0 || y >= s->clip.y1 || x0 < s->clip.x0 || x1 > s->clip.x1) {
        s->bad++;
        return;
    }
    if (y < s->last_y || (y == s->last_y && x0 <= s->last_x1)) s->bad++; /* order, not touching */
    s->last_y = y;
    s->last_x1 = x1;
    for (x = x0; x < x1; x++) s->img[(y - s->clip.y0) * 40 + (x - s->clip.x0)]++;
}

static void test_far_clip(void)
{
    const int32_t M = RAST_COORD_MAX;
    rast_point tri[3];
    uint32_t n = 3;
    rast_polygon p = {tri, &n, 1};
    int algo, rule, c, t, side, bad = 0;
    long filled[2] = {0, 0};
    /* side 0 near (M, M), side 1 the mirror image near (-M, -M): negative
     * columns and rows in the span API */
    for (side = 0; side < 2; side++)
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++)
        for (rule = 0; rule < 2; rule++)
            for (c = 0; c < 2; c++)
                for (t = 0; t < 2; t++) {
                    static span_img si;
                    grid gr;
                    rast_fill_opts o;
                    uint32_t rules = 0;
                    size_t need = 0;
                    int i, j;
                    unsigned char *scr;
                    gr.s = 0;
                    gr.center = c;
                    gr.textbook = t;
                    rast_algorithm_info((rast_algorithm)algo, NULL, &rules);
                    if (!(rules >> rule & 1)) continue;
                    o = make_opts(algo, rule, &gr);
                    memset(&si, 0, sizeof si);
                    tri[0].x = M; tri[0].y = M;
                    tri[1].x = -M; tri[1].y = M - 7;
                    tri[2].x = M - 25; tri[2].y = -M;
                    si.clip.x0 = M - 30;
                    si.clip.y0 = M - 35;
                    si.clip.x1 = M + 10;
                    si.clip.y1 = M + 5;
                    if (side) {
                        int v;
                        for (v = 0; v < 3; v++) {
                            tri[v].x = -tri[v].x;
                            tri[v].y = -tri[v].y;
                        }
                        si.clip.x0 = -M - 10;
                        si.clip.y0 = -M - 5;
                        si.clip.x1 = -M + 30;
                        si.clip.y1 = -M + 35;
                    }
                    si.last_y = si.clip.y0 - 1;
                    CHECK(rast_scratch_size(&o, n, 40, 40, &need) == RAST_OK);
                    scr = scratch_for(need);
                    CHECK(rast_fill_polygon_spans(&p, &o, &si.clip, to_img, &si, scr, need) == RAST_OK);
                    CHECK(scratch_guard_ok(scr, need));
                    bad += si.bad;
                    for (j = 0; j < 40; j++)
                        for (i = 0; i < 40; i++) {
                            bad += si.img[j * 40 + i] !=
                                   ref_inside(tri, &n, 1, &gr, rule, si.clip.x0 + i, si.clip.y0 + j);
                            filled[side] += si.img[j * 40 + i];
                        }
                }
    CHECK(bad == 0);
    CHECK(filled[0] > 0 && filled[1] > 0); /* the windows do see the polygon */
}

/* ---- thousands of vertices ------------------------------------------------------------- */

static rast_point big[3 * 65536 + 16];

static void test_many_vertices(void)
{
    uint32_t k, n;
    int bad = 0;
    grid gr = {4, 1, 0};
    /* a 3000-vertex star, and a 5000-vertex random walk partly outside */
    n = 3000;
    for (k = 0; k < n; k++) {
        /* radii alternate 18 and 9 px about (20, 20), S = 4, angles in
         * integer steps of a rough circle (no floating point needed) */
        int32_t r = (k & 1 ? 9 : 18) << 4;
        int32_t q = (int32_t)(k % 750), x, y;
        /* walk the square's perimeter as the "circle": 4 sides of 750/4 */
        int32_t side = q / 188, tpos = (q % 188) * 2 * r / 188 - r;
        x = side == 0 ? r : side == 1 ? -tpos : side == 2 ? -r : tpos;
        y = side == 0 ? tpos : side == 1 ? r : side == 2 ? -tpos : -r;
        big[k].x = (20 << 4) + x;
        big[k].y = (20 << 4) + y;
    }
    bad += check_case(big, &n, 1, &gr, 40, 40);
    n = 5000;
    for (k = 0; k < n; k++) {
        big[k].x = (int32_t)(rng() % (60u << 4)) - (10 << 4);
        big[k].y = (int32_t)(rng() % (60u << 4)) - (10 << 4);
    }
    gr.textbook = 1;
    bad += check_case(big, &n, 1, &gr, 40, 40);
    CHECK(bad == 0);
}

/* Windings of 256 and 65536 at the centre: the same triangle walked round
 * that many times (768 and 196608 vertices).  Exact only if the flag
 * counters of edgeflag do not wrap to 0: they have 16 resp. 32 bits for
 * that many vertices (8 bits serve up to 511 vertices, |winding| <= 255).
 * 131072 edges join the AET on one row: sorted, then merged (aet.c), where
 * inserting them one by one once cost ~2^32 moves and made this test skip
 * the AET. */
static void test_deep_winding(void)
{
    static const uint32_t turns[2] = {256, 65536};
    int t, bad = 0;
    grid gr = {0, 1, 0};
    for (t = 0; t < 2; t++) {
        uint32_t k, n = 3 * turns[t];
        for (k = 0; k < turns[t]; k++) {
            big[3 * k].x = 1; big[3 * k].y = 1;
            big[3 * k + 1].x = 7; big[3 * k + 1].y = 2;
            big[3 * k + 2].x = 3; big[3 * k + 2].y = 7;
        }
        bad += check_case(big, &n, 1, &gr, 8, 8);
    }
    CHECK(bad == 0);
}

/* ---- errors -------------------------------------------------------------------------- */
static void test_errors(void)
{
    static unsigned char img[24 * 24], before[24 * 24];
    rast_point tri[3] = {{1, 1}, {20, 2}, {9, 21}};
    uint32_t n = 3;
    rast_polygon p = {tri, &n, 1};
    rast_target t;
    unsigned char one = 1;
    int algo, rule;
    CHECK(rast_target_init(&t, img, 24, 24, 24, RAST_FORMAT_GRAY8) == RAST_OK);
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
        uint32_t rules = 0;
        const char *name = NULL;
        CHECK(rast_algorithm_info((rast_algorithm)algo, &name, &rules) == RAST_OK);
        CHECK(name != NULL && (rules & 1u)); /* every algorithm does even-odd */
        for (rule = 0; rule < 2; rule++) {
            grid gr = {0, 0, 0};
            rast_fill_opts o = make_opts(algo, rule, &gr);
            size_t need = 0;
            unsigned char *scr;
            memset(img, 7, sizeof img);
            memcpy(before, img, sizeof img);
            if (!(rules >> rule & 1)) {
                CHECK(rast_scratch_size(&o, n, 24, 24, &need) == RAST_E_RULE);
                CHECK(rast_fill_polygon(&t, &p, &o, &one, scratch_mem, sizeof scratch_mem) == RAST_E_RULE);
                CHECK(memcmp(img, before, sizeof img) == 0);
                continue;
            }
            CHECK(rast_scratch_size(&o, n, 24, 24, &need) == RAST_OK);
            CHECK(need > 0);
            scr = scratch_for(need);
            /* one byte short: refused before anything is written */
            CHECK(rast_fill_polygon(&t, &p, &o, &one, scr + 8, need - 1) == RAST_E_SCRATCH);
            CHECK(rast_fill_polygon_opaque(&t, &p, &o, &one, &one, scr + 8, need - 1) == RAST_E_SCRATCH);
            CHECK(memcmp(img, before, sizeof img) == 0);
            /* exactly enough: fills */
            CHECK(rast_fill_polygon(&t, &p, &o, &one, scr, need) == RAST_OK);
            CHECK(scratch_guard_ok(scr, need));
            CHECK(memcmp(img, before, sizeof img) != 0);
        }
    }
    /* The compile-time bounds of rastrum.h are never less than
     * rast_scratch_size. */
    {
        static const uint32_t ns[] = {0, 1, 3, 64, 511, 512, 131071, 131072, 1u << 24};
        static const int32_t ds[] = {0, 1, 63, 64, 65, 640, 2048, 100000};
        size_t k, a, b;
        int fits = 1;
        for (k = 0; k < sizeof ns / sizeof ns[0]; k++)
            for (a = 0; a < sizeof ds / sizeof ds[0]; a++)
                for (b = 0; b < sizeof ds / sizeof ds[0]; b++) {
                    uint32_t np = ns[k];
                    int32_t w = ds[a], h = ds[b];
                    size_t need[RAST_ALGO_COUNT_], bound[RAST_ALGO_COUNT_];
                    grid gr = {0, 0, 0};
                    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
                        rast_fill_opts o = make_opts(algo, 0, &gr);
                        if (rast_scratch_size(&o, np, w, h, &need[algo]) != RAST_OK) fits = 0;
                    }
                    bound[RAST_ALGO_AET] = RAST_AET_SCRATCH_BOUND(np, h);
                    bound[RAST_ALGO_XSCAN] = RAST_XSCAN_SCRATCH_BOUND(np);
                    bound[RAST_ALGO_EDGEFILL] = RAST_EDGEFILL_SCRATCH_BOUND(w, h);
                    bound[RAST_ALGO_FENCE] = RAST_FENCE_SCRATCH_BOUND(w, h);
                    bound[RAST_ALGO_EDGEFLAG] = RAST_EDGEFLAG_SCRATCH_BOUND(np, w, h);
                    bound[RAST_ALGO_CROSSING] = RAST_POINTWISE_SCRATCH_BOUND(np);
                    bound[RAST_ALGO_WINDING] = RAST_POINTWISE_SCRATCH_BOUND(np);
                    /* a need of SIZE_MAX (32-bit size_t) is "more than
                     * memory can hold": no buffer passes, whatever a
                     * wrapped bound says */
                    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++)
                        fits &= need[algo] == (size_t)-1 || need[algo] <= bound[algo];
                }
        CHECK(fits);
    }
    /* Scratch sizes never wrap: the largest clip gives a huge size (or
     * SIZE_MAX), not a small one. */
    for (algo = 0; algo < RAST_ALGO_COUNT_; algo++) {
        grid gr = {0, 0, 0};
        rast_fill_opts o = make_opts(algo, 0, &gr);
        size_t small = 0, large = 0;
        CHECK(rast_scratch_size(&o, 3, 24, 24, &small) == RAST_OK);
        CHECK(rast_scratch_size(&o, 3, RAST_MAX_DIM, RAST_MAX_DIM, &large) == RAST_OK);
        CHECK(large >= small);
    }
}

int main(void)
{
    test_errors();
    test_random();
    test_limits();
    test_far_clip();
    test_many_vertices();
    test_deep_winding();
    CHECK(parity_bad == 0);
    return check_report("test_algos");
}

/*
 * test_tri.c - the triangle fillers against Example 3-1 of seed 001 worked
 * by hand, and against a brute-force per-sample reference with guard bytes
 * around every target; COUNT16; errors; coordinates at the limit.
 */
#include <stdint.h>
#include <string.h>

#define CHECK_RNG_SEED 2024u
#include "check.h"
#include "ref.h"
#include "base/internal.h" /* rast__tri_span_flags, rast__grid_init */

#define GUARD 0xA5
#define PAD 8
#define MAXW 48

static uint64_t scratch[1 << 12];

/* ---- the reference: DESIGN section 1 for the ring t0 t1 t2, one sample at a
 * time, by cross-multiplication (no division).  Coordinates doubled, so the
 * sample (i + o, j + o) and half a pixel are integers.  A crossing X of a
 * downward edge counts for the sample iff X <= xc (exact), or
 * X < xc + 1/2 pixel (textbook). */
static int ref_inside(const rast_point *t, int s, int center, int textbook, int64_t i, int64_t j)
{
    static const uint32_t three = 3;
    return ref_winding(t, &three, 1, s, center, textbook, i, j, NULL) != 0;
}

static rast_tri_opts topts(int algo, int s, int center, int textbook)
{
    rast_tri_opts o;
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_tri_algorithm)algo;
    o.subpixel_bits = s;
    o.sample = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    o.rounding = textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
    return o;
}

/* ---- Example 3-1 of seed 001 -------------------------------------------------
 * P0(1,1) P1(5,3) P2(4,7), samples at integer points, S = 0.  The book's
 * SpanLeft/SpanRight table, rows 1..6 (the last row, 7, is open):
 * (1,1)(1,1) / (2,2)(3,2) / (2,3)(5,3) / (3,4)(5,4) / (3,5)(5,5) / (4,6)(4,6).
 * It rounds each crossing to the nearest column: RAST_ROUND_TEXTBOOK.
 * Left edge P0P2: X = 1 + (y-1)/2 = 1, 1.5, 2, 2.5, 3, 3.5 -> 1 2 2 3 3 4.
 * Right: P0P1 X = 1, 3; P1P2 X = 5, 4.75, 4.5, 4.25 -> 1 3 5 5 5 4.
 * Exact (a crossing counts for column i iff X <= i): left 1 2 2 3 3 4,
 * right 1 3 5 5 5 5: row 6 gains pixel 4 (sample (4,6) is left of 4.25). */
static void test_example_3_1(void)
{
    static const rast_point tri[3] = {{1, 1}, {5, 3}, {4, 7}};
    static const int32_t book_left[6] = {1, 2, 2, 3, 3, 4};
    static const int32_t book_right[6] = {1, 3, 5, 5, 5, 4};
    static const int32_t exact_right[6] = {1, 3, 5, 5, 5, 5};
    int32_t left[10], right[10], r0 = -1, r1 = -1;
    rast__grid g;
    int j, i, a, perm, textbook;

    CHECK(rast__grid_init(&g, 0, RAST_SAMPLE_CORNER, RAST_ROUND_TEXTBOOK, RAST_BOUNDARY_EXACT) == RAST_OK);
    CHECK(rast__tri_span_flags(tri, &g, 0, 10, left, right, &r0, &r1) == 1);
    CHECK(r0 == 1 && r1 == 7);
    for (j = 0; j < 6; j++) {
        CHECK(left[j + 1] == book_left[j]);
        CHECK(right[j + 1] == book_right[j]);
    }
    /* a clip band of rows 3..4 gets exactly those rows */
    CHECK(rast__tri_span_flags(tri, &g, 3, 5, left, right, &r0, &r1) == 1);
    CHECK(r0 == 3 && r1 == 5 && left[0] == 2 && right[0] == 5 && left[1] == 3 && right[1] == 5);
    CHECK(rast__grid_init(&g, 0, RAST_SAMPLE_CORNER, RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT) == RAST_OK);
    CHECK(rast__tri_span_flags(tri, &g, 0, 10, left, right, &r0, &r1) == 1);
    for (j = 0; j < 6; j++) {
        CHECK(left[j + 1] == book_left[j]);
        CHECK(right[j + 1] == exact_right[j]);
    }

    /* The filled pixels, [SpanLeft, SpanRight) per row, from every
     * algorithm and every order of the vertices. */
    for (textbook = 0; textbook < 2; textbook++)
        for (a = 0; a < RAST_TRI_COUNT_; a++)
            for (perm = 0; perm < 6; perm++) {
                static const int p[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
                rast_point t[3];
                unsigned char img[10][10], one = 1;
                rast_target tg;
                rast_tri_opts o = topts(a, 0, 0, textbook);
                int ok = 1;
                for (i = 0; i < 3; i++) t[i] = tri[p[perm][i]];
                memset(img, 0, sizeof img);
                CHECK(rast_target_init(&tg, img, 10, 10, 10, RAST_FORMAT_GRAY8) == RAST_OK);
                CHECK(rast_fill_triangles(&tg, t, 1, &o, &one, scratch, sizeof scratch) == RAST_OK);
                for (j = 0; j < 10; j++)
                    for (i = 0; i < 10; i++) {
                        int want = 0;
                        if (j >= 1 && j <= 6)
                            want = i >= book_left[j - 1] && i < (textbook ? book_right[j - 1] : exact_right[j - 1]);
                        ok &= img[j][i] == want;
                    }
                CHECK(ok);
            }
}

/* ---- random batches against the reference --------------------------------- */

/* The sample coordinate (fixed point) of the pixel holding v. */
static int32_t on_sample(int32_t v, int s, int center)
{
    int32_t one = (int32_t)1 << s, q = v / one;
    if (v % one < 0) q--;
    return q * one + (center ? one / 2 : 0);
}

static void random_triangle(rast_point *t, int s, int center, int w, int h)
{
    int32_t span = (int32_t)((w > h ? w : h) + 8) << s;
    int k, kind = (int)(rng() % 8);
    for (k = 0; k < 3; k++) {
        t[k].x = (int32_t)(rng() % (uint32_t)span) - (4 << s);
        t[k].y = (int32_t)(rng() % (uint32_t)span) - (4 << s);
        if (rng() % 4 == 0) { /* vertices on sample points */
            t[k].x = on_sample(t[k].x, s, center);
            t[k].y = on_sample(t[k].y, s, center);
        }
    }
    if (kind == 0) { /* a sliver: the third vertex within a grid step of the first edge's middle */
        t[2].x = (t[0].x + t[1].x) / 2 + (int32_t)(rng() % 3) - 1;
        t[2].y = (t[0].y + t[1].y) / 2 + (int32_t)(rng() % 3) - 1;
    } else if (kind == 1) { /* degenerate: collinear or repeated */
        t[2].x = 2 * t[1].x - t[0].x;
        t[2].y = 2 * t[1].y - t[0].y;
        if (rng() & 1) t[1] = t[0];
    } else if (kind == 2) { /* a horizontal edge */
        t[1].y = t[0].y;
    } else if (kind == 3) { /* huge, mostly off-screen */
        t[0].x = -(int32_t)(rng() % 100000) * (1 << (s > 8 ? 8 : s));
        t[1].y = (int32_t)(rng() % 100000) * (1 << (s > 8 ? 8 : s));
    }
}

/* Fill `n` triangles into a guarded target (gray8 over zeros, or count16
 * over zeros) and compare each pixel with the reference (the count with the
 * number of triangles owning it); the guard and, for gray8, the clip
 * outside must be untouched. */
static int batch_equals_ref(const rast_point *tris, int n, const rast_tri_opts *o, int count16,
                            int w, int h, const rast_rect *clip)
{
    static unsigned char buf[(MAXW + 2 * PAD) * (MAXW + 2 * PAD) * 2];
    int bpp = count16 ? 2 : 1, stride = (w + 2 * PAD) * bpp, i, j, k, ok = 1;
    int center = o->sample == RAST_SAMPLE_CENTER, textbook = o->rounding == RAST_ROUND_TEXTBOOK;
    rast_target t;
    unsigned char one = 1, *base = buf + PAD * stride + PAD * bpp;
    memset(buf, GUARD, sizeof buf);
    for (j = 0; j < h; j++) memset(base + j * stride, 0, (size_t)(w * bpp));
    if (rast_target_init(&t, base, w, h, stride, count16 ? RAST_FORMAT_COUNT16 : RAST_FORMAT_GRAY8) != RAST_OK)
        return 0;
    if (clip) t.clip = *clip;
    if (rast_fill_triangles(&t, tris, (uint32_t)n, o, count16 ? NULL : &one, scratch, sizeof scratch) != RAST_OK)
        return 0;
    for (j = -PAD; j < h + PAD; j++)
        for (i = -PAD; i < w + PAD; i++) {
            const unsigned char *p = base + j * stride + i * bpp;
            int got, want = 0;
            if (i < 0 || j < 0 || i >= w || j >= h) {
                ok &= p[0] == GUARD && p[bpp - 1] == GUARD;
                continue;
            }
            if (i >= t.clip.x0 && i < t.clip.x1 && j >= t.clip.y0 && j < t.clip.y1)
                for (k = 0; k < n; k++) want += ref_inside(tris + 3 * k, o->subpixel_bits, center, textbook, i, j);
            if (count16) {
                uint16_t v;
                memcpy(&v, p, 2);
                got = v;
            } else {
                got = p[0];
                if (want > 1) want = 1;
            }
            ok &= got == want;
        }
    return ok;
}

static void test_random(void)
{
    static const int ss[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 16};
    rast_point tris[3 * 6];
    int iter, bad = 0, runs = 0;
    for (iter = 0; iter < 4000; iter++) {
        int s = ss[iter % 10], center = (int)(rng() & 1), textbook = (int)(rng() & 1);
        int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 40), n = 1 + (int)(rng() % 6), k, a;
        rast_rect clip;
        for (k = 0; k < n; k++) random_triangle(tris + 3 * k, s, center, w, h);
        clip.x0 = (int32_t)(rng() % (uint32_t)(w + 1)) - 2;
        clip.y0 = (int32_t)(rng() % (uint32_t)(h + 1)) - 2;
        clip.x1 = clip.x0 + (int32_t)(rng() % (uint32_t)(w + 4));
        clip.y1 = clip.y0 + (int32_t)(rng() % (uint32_t)(h + 4));
        for (a = 0; a < RAST_TRI_COUNT_; a++) {
            rast_tri_opts o = topts(a, s, center, textbook);
            bad += !batch_equals_ref(tris, n, &o, 1, w, h, NULL);
            bad += !batch_equals_ref(tris, n, &o, 0, w, h, NULL);
            if (iter % 4 == 0) bad += !batch_equals_ref(tris, n, &o, 1, w, h, &clip);
            /* gray8 goes the inline path: uncut when a triangle's columns
             * are inside the clip, through the clip test when not */
            if (iter % 4 == 1) bad += !batch_equals_ref(tris, n, &o, 0, w, h, &clip);
            runs++;
        }
    }
    CHECK(runs == 4000 * RAST_TRI_COUNT_);
    CHECK(bad == 0);
}

/* ---- the edge setup's fast paths against the formulas in 64 bits ------------
 * rast__edge_setup takes rows by shifts and the first crossing by a 32-bit
 * division when it fits; each field must be what the plain 64-bit formulas
 * of internal.h give, for short edges near the origin and edges across the
 * whole range seen through windows anywhere. */
static int edge_equals_formula(rast_point a, rast_point b, const rast__grid *g, int32_t lo, int32_t hi)
{
    rast__edge ed;
    int64_t ya = 2 * (int64_t)a.y, yb = 2 * (int64_t)b.y, first, end, x, n, q;
    int got = rast__edge_setup(&ed, a, b, g, lo, hi);
    if (ya > yb) {
        rast_point t = a;
        a = b;
        b = t;
        ya = 2 * (int64_t)a.y;
        yb = 2 * (int64_t)b.y;
    }
    first = rast__ceildiv(ya - g->off, g->unit);
    end = rast__ceildiv(yb - g->off, g->unit);
    if (first < lo) first = lo;
    if (end > hi) end = hi;
    if (ya == yb || first >= end) return got == 0;
    if (!got || ed.row != first || ed.end != end) return 0;
    /* the crossing of row `first`, as rast__cross_col computes it */
    q = yb - ya;
    n = 2 * (int64_t)a.x * q + (first * g->unit + g->off - ya) * (2 * (int64_t)b.x - 2 * (int64_t)a.x);
    x = rast__cross_col(n, q, g);
    if (ed.x != x || ed.q != q * g->unit) return 0;
    /* e = x*q' - n' (q' = q*unit, n' the numerator the walk uses), checked
     * without forming x*q' (it may not fit): 0 <= e < q' and q' | e + n' */
    n -= (int64_t)g->off * q;
    if (g->textbook) n += (int64_t)(g->unit / 2) * q - ed.q + 1;
    if (ed.e < 0 || ed.e >= ed.q || (ed.e + n) % ed.q != 0) return 0;
    return ed.step == rast__floordiv(2 * (int64_t)b.x - 2 * (int64_t)a.x, q) && ed.dr >= 0 && ed.dr < ed.q;
}

static void test_edge_setup(void)
{
    int iter, bad = 0;
    for (iter = 0; iter < 200000; iter++) {
        int s = (int)(rng() % 17), big = (int)(rng() % 3);
        rast__grid g;
        rast_point a, b;
        int32_t lo, hi, m = big ? RAST_COORD_MAX : (int32_t)(64 << s);
        rast__grid_init(&g, s, (rast_sample)(rng() & 1), (rast_rounding)(rng() & 1), RAST_BOUNDARY_EXACT);
        a.x = (int32_t)(rng() % (2u * (uint32_t)m + 1)) - m;
        a.y = (int32_t)(rng() % (2u * (uint32_t)m + 1)) - m;
        b.x = (int32_t)(rng() % (2u * (uint32_t)m + 1)) - m;
        b.y = (int32_t)(rng() % (2u * (uint32_t)m + 1)) - m;
        if (big == 2) a.x = (rng() & 1) ? RAST_COORD_MAX : -RAST_COORD_MAX;
        /* a window of rows: everything, or 40 rows somewhere along the edge */
        lo = -RAST_MAX_DIM;
        hi = RAST_MAX_DIM;
        if (rng() & 1) {
            lo = (int32_t)rast__floordiv(2 * (int64_t)(a.y + (b.y - a.y) / 2), g.unit) - 20;
            hi = lo + 40;
        }
        bad += !edge_equals_formula(a, b, &g, lo, hi);
    }
    CHECK(bad == 0);
}

/* ---- coordinates at the limit ------------------------------------------------ */
static void test_limits(void)
{
    int s, c, tb, a, bad = 0;
    const int32_t M = RAST_COORD_MAX;
    for (s = 0; s <= RAST_MAX_SUBPIXEL_BITS; s++) {
        rast_point tris[3 * 4] = {
            {-M, -M}, {M, M - 1}, {M, M},     /* a thin wedge corner to corner */
            {-M, 0}, {M, -M}, {M, M},         /* vertices on the extremes */
            {-M, M}, {M, -M}, {-M, -M},       /* the other half of the range */
            {M, 3 << (s > 4 ? 4 : s)}, {-M, 2}, {-M, 1 << (s > 4 ? 4 : s)},
        };
        for (c = 0; c < 2; c++)
            for (tb = 0; tb < 2; tb++)
                for (a = 0; a < RAST_TRI_COUNT_; a++) {
                    rast_tri_opts o = topts(a, s, c, tb);
                    bad += !batch_equals_ref(tris, 4, &o, 1, 40, 40, NULL);
                }
    }
    CHECK(bad == 0);
}

/* ---- a square cut into triangles is covered exactly once -------------------- */
static void test_watertight(void)
{
    static uint16_t cnt[64 * 64];
    static rast_point tris[2 * 8 * 8 * 3];
    rast_point grid[9][9];
    int i, j, a, s, n = 0, bad = 0;
    for (s = 0; s < 2; s++) {
        int sb = s ? 4 : 0;
        for (j = 0; j <= 8; j++)
            for (i = 0; i <= 8; i++) {
                int32_t jx = (i > 0 && i < 8) ? (int32_t)(rng() % 5) - 2 : 0;
                int32_t jy = (j > 0 && j < 8) ? (int32_t)(rng() % 5) - 2 : 0;
                grid[j][i].x = ((i * 8) << sb) + (sb ? jx * 5 : jx / 2);
                grid[j][i].y = ((j * 8) << sb) + (sb ? jy * 5 : jy / 2);
            }
        for (n = 0, j = 0; j < 8; j++)
            for (i = 0; i < 8; i++) {
                rast_point p00 = grid[j][i], p10 = grid[j][i + 1], p01 = grid[j + 1][i], p11 = grid[j + 1][i + 1];
                if ((i + j) & 1) {
                    tris[n++] = p00; tris[n++] = p10; tris[n++] = p11;
                    tris[n++] = p00; tris[n++] = p01; tris[n++] = p11; /* the other winding */
                } else {
                    tris[n++] = p00; tris[n++] = p10; tris[n++] = p01;
                    tris[n++] = p10; tris[n++] = p11; tris[n++] = p01;
                }
            }
        for (a = 0; a < RAST_TRI_COUNT_; a++) {
            int c, tb;
            for (c = 0; c < 2; c++)
                for (tb = 0; tb < 2; tb++) {
                    rast_tri_opts o = topts(a, sb, c, tb);
                    rast_target t;
                    memset(cnt, 0, sizeof cnt);
                    CHECK(rast_target_init(&t, cnt, 64, 64, 128, RAST_FORMAT_COUNT16) == RAST_OK);
                    CHECK(rast_fill_triangles(&t, tris, (uint32_t)(n / 3), &o, NULL, scratch, sizeof scratch) == RAST_OK);
                    for (i = 0; i < 64 * 64; i++) bad += cnt[i] != 1;
                }
        }
    }
    CHECK(bad == 0);
}

/* ---- spans: one triangle after the other, rows top down, clipped ---------- */
typedef struct {
    int n, bad;
    int32_t y;
    long area;
} span_log;

static void log_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    span_log *l = (span_log *)user;
    if (x0 >= x1) l->bad++;
    l->n++;
    l->y = y;
    l->area += x1 - x0;
}

static void test_spans(void)
{
    /* two triangles making the square [0,8)^2 (S = 0, centres), then a
     * degenerate one */
    static const rast_point tris[] = {{0, 0}, {8, 0}, {8, 8}, {0, 0}, {8, 8}, {0, 8}, {1, 1}, {2, 2}, {3, 3}};
    rast_rect clip = {-5, -5, 100, 100}, band = {2, 1, 6, 3}, none = {3, 3, 3, 9}, far = {-1073741823, 0, 1073741823, 4};
    rast_rect bad_clip = {0, 0, 1073741824, 4};
    rast_tri_opts o;
    span_log l;
    int a;
    size_t need;
    for (a = 0; a < RAST_TRI_COUNT_; a++) {
        o = topts(a, 0, 1, 0);
        memset(&l, 0, sizeof l);
        CHECK(rast_fill_triangles_spans(tris, 3, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_OK);
        CHECK(l.n == 15 && l.bad == 0 && l.area == 64); /* row 0 of the lower triangle is empty */
        memset(&l, 0, sizeof l);
        CHECK(rast_fill_triangles_spans(tris, 3, &o, &band, log_span, &l, scratch, sizeof scratch) == RAST_OK);
        CHECK(l.bad == 0 && l.area == 8);
        memset(&l, 0, sizeof l);
        CHECK(rast_fill_triangles_spans(tris, 3, &o, &none, log_span, &l, scratch, sizeof scratch) == RAST_OK);
        CHECK(l.n == 0);
        memset(&l, 0, sizeof l);
        CHECK(rast_tri_scratch_size(&o, far.x1 - far.x0, far.y1 - far.y0, &need) == RAST_E_SIZE);
        CHECK(rast_fill_triangles_spans(tris, 3, &o, &far, log_span, &l, scratch, sizeof scratch) == RAST_OK);
        CHECK(l.bad == 0 && l.area == 32);
        CHECK(rast_fill_triangles_spans(tris, 3, &o, &bad_clip, log_span, &l, scratch, sizeof scratch) == RAST_E_SIZE);
        memset(&l, 0, sizeof l);
        CHECK(rast_fill_triangles_spans(NULL, 0, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_OK);
        CHECK(l.n == 0);
    }
}

/* ---- COUNT16: saturation, and the polygon fill paints into it too --------- */
static void test_count16(void)
{
    static const rast_point tri[3] = {{0, 0}, {4, 0}, {0, 4}};
    uint16_t cnt[4 * 4], bg = 0;
    uint32_t three = 3;
    rast_polygon p = {tri, &three, 1};
    rast_fill_opts fo;
    rast_tri_opts o = topts(RAST_TRI_EDGE, 0, 1, 0);
    rast_target t;
    int i, ok = 1;
    unsigned char odd[40];
    for (i = 0; i < 16; i++) cnt[i] = 65534;
    CHECK(rast_target_init(&t, cnt, 4, 4, 8, RAST_FORMAT_COUNT16) == RAST_OK);
    CHECK(rast_fill_triangles(&t, tri, 1, &o, NULL, scratch, sizeof scratch) == RAST_OK);
    CHECK(rast_fill_triangles(&t, tri, 1, &o, NULL, scratch, sizeof scratch) == RAST_OK);
    for (i = 0; i < 16; i++) ok &= cnt[i] == ((i % 4) + (i / 4) < 3 ? 65535 : 65534);
    CHECK(ok);
    memset(&fo, 0, sizeof fo);
    fo.sample = RAST_SAMPLE_CENTER;
    memset(cnt, 0, sizeof cnt);
    CHECK(rast_fill_polygon(&t, &p, &fo, NULL, scratch, sizeof scratch) == RAST_OK);
    CHECK(rast_fill_polygon(&t, &p, &fo, NULL, scratch, sizeof scratch) == RAST_OK);
    for (ok = 1, i = 0; i < 16; i++) ok &= cnt[i] == ((i % 4) + (i / 4) < 3 ? 2 : 0);
    CHECK(ok);
    memset(cnt, 0, sizeof cnt);
    CHECK(rast_fill_polygon_opaque(&t, &p, &fo, &bg, &bg, scratch, sizeof scratch) == RAST_E_FORMAT);
    for (ok = 1, i = 0; i < 16; i++) ok &= cnt[i] == 0;
    CHECK(ok);
    {
        int32_t bpp = 0;
        CHECK(rast_format_bytes(RAST_FORMAT_COUNT16, &bpp) == RAST_OK && bpp == 2);
    }
    /* uint16_t pixels: an odd stride or address is refused */
    CHECK(rast_target_init(&t, odd, 4, 4, 9, RAST_FORMAT_COUNT16) == RAST_E_SIZE);
    CHECK(rast_target_init(&t, odd + ((uintptr_t)odd % 2 ? 0 : 1), 4, 4, 8, RAST_FORMAT_COUNT16) == RAST_E_SIZE);
}

/* ---- errors: a status, and nothing written ------------------------------------ */
static void test_errors(void)
{
    rast_point tris[6] = {{1, 1}, {30, 2}, {10, 30}, {0, 0}, {20, 0}, {0, 20}};
    rast_tri_opts o = topts(RAST_TRI_EDGEFLAG, 0, 1, 0);
    rast_target t;
    rast_rect clip = {0, 0, 32, 32};
    unsigned char img[32 * 32], before[32 * 32], one = 1;
    const char *name = NULL;
    size_t need = 0;
    span_log l;
    int a;

    memset(img, 7, sizeof img);
    memcpy(before, img, sizeof img);
    CHECK(rast_target_init(&t, img, 32, 32, 32, RAST_FORMAT_GRAY8) == RAST_OK);
    for (a = 0; a < RAST_TRI_COUNT_; a++) CHECK(rast_tri_algorithm_info((rast_tri_algorithm)a, &name) == RAST_OK && name);
    CHECK(rast_tri_algorithm_info(RAST_TRI_EDGE, &name) == RAST_OK && strcmp(name, "edge") == 0);
    CHECK(rast_tri_algorithm_info(RAST_TRI_SWEEP, &name) == RAST_OK && strcmp(name, "sweep") == 0);
    CHECK(rast_tri_algorithm_info(RAST_TRI_EDGEFLAG, NULL) == RAST_OK);
    CHECK(rast_tri_algorithm_info(RAST_TRI_COUNT_, &name) == RAST_E_ALGORITHM);
    CHECK(rast_tri_algorithm_info((rast_tri_algorithm)-1, &name) == RAST_E_ALGORITHM);

    CHECK(rast_tri_scratch_size(&o, 32, 32, &need) == RAST_OK && need >= 2 * 32 * sizeof(int32_t));
    CHECK(rast_tri_scratch_size(NULL, 32, 32, &need) == RAST_E_NULL);
    CHECK(rast_tri_scratch_size(&o, 32, 32, NULL) == RAST_E_NULL);
    CHECK(rast_tri_scratch_size(&o, -1, 32, &need) == RAST_E_SIZE);
    CHECK(rast_tri_scratch_size(&o, 32, RAST_MAX_DIM + 1, &need) == RAST_E_SIZE);
    o.algorithm = RAST_TRI_COUNT_;
    CHECK(rast_tri_scratch_size(&o, 32, 32, &need) == RAST_E_ALGORITHM);
    o.algorithm = RAST_TRI_EDGEFLAG;
    o.rounding = (rast_rounding)2;
    CHECK(rast_tri_scratch_size(&o, 32, 32, &need) == RAST_E_ARG);
    o.rounding = RAST_ROUND_EXACT;
    CHECK(rast_tri_scratch_size(&o, 32, 32, &need) == RAST_OK);

    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, need - 1) == RAST_E_SCRATCH);
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, (char *)scratch + 4, need) == RAST_E_ALIGN);
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, NULL, need) == RAST_E_NULL);
    tris[4].x = RAST_COORD_MAX + 1; /* the second triangle: nothing of the first drawn */
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_RANGE);
    tris[4].x = 20;
    tris[5].y = -RAST_COORD_MAX - 1;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_RANGE);
    CHECK(rast_fill_triangles_spans(tris, 2, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_E_RANGE);
    tris[5].y = 20;
    o.subpixel_bits = RAST_MAX_SUBPIXEL_BITS + 1;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_SUBPIXEL);
    o.subpixel_bits = -1;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_SUBPIXEL);
    o.subpixel_bits = 0;
    o.sample = (rast_sample)2;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.sample = RAST_SAMPLE_CENTER;
    o.rounding = (rast_rounding)-1;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.rounding = RAST_ROUND_EXACT;
    o.boundary = (rast_boundary)3;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_ARG);
    o.boundary = RAST_BOUNDARY_EXACT;
    o.algorithm = RAST_TRI_COUNT_;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_ALGORITHM);
    CHECK(rast_fill_triangles_spans(tris, 2, &o, &clip, log_span, &l, scratch, sizeof scratch) == RAST_E_ALGORITHM);
    o.algorithm = RAST_TRI_SWEEP;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, NULL, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles(NULL, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles(&t, NULL, 2, &o, &one, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles(&t, tris, 2, NULL, &one, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles_spans(tris, 2, &o, NULL, log_span, &l, scratch, sizeof scratch) == RAST_E_NULL);
    CHECK(rast_fill_triangles_spans(tris, 2, &o, &clip, NULL, &l, scratch, sizeof scratch) == RAST_E_NULL);
    t.format = (rast_format)9;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_FORMAT);
    t.format = RAST_FORMAT_GRAY8;
    t.stride = 31;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_E_SIZE);
    t.stride = 32;
    CHECK(memcmp(img, before, sizeof img) == 0);

    /* no triangles, or an empty clip: nothing to do, and fine */
    CHECK(rast_fill_triangles(&t, NULL, 0, &o, &one, scratch, sizeof scratch) == RAST_OK);
    t.clip.x1 = 0;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_OK);
    CHECK(memcmp(img, before, sizeof img) == 0);
    t.clip.x1 = 32;
    CHECK(rast_fill_triangles(&t, tris, 2, &o, &one, scratch, sizeof scratch) == RAST_OK);
    CHECK(memcmp(img, before, sizeof img) != 0);
}

int main(void)
{
    test_example_3_1();
    test_edge_setup();
    test_random();
    test_limits();
    test_watertight();
    test_spans();
    test_count16();
    test_errors();
    return check_report("test_tri");
}

/* test_painter.c - the pipeline's one painter interface (internal.h,
 * paint.h): a painter's entries agree with each other.
 *  - The solid painter of every format: a levels run of all 255 (full
 *    coverage) writes what a full run writes, over random pixels.
 *  - Its fast kind (one-byte rows, a memset per run), where it has one:
 *    a triangle batch fed through it gives the pixels the same batch gives
 *    through the painter's full entry, clipped or not, each algorithm.
 *  - The coverage pipeline (rast__cov_paint) feeding the solid painter
 *    (levels runs, and full runs for long stretches covered whole) gives
 *    the pixels of the public route: the coverage spans
 *    (rast_polygon_coverage_spans, whole runs of levels) blended by a
 *    callback through the format's own levels entry. */
#include <string.h>

#include "check.h"
#include "painters/paint.h"

#define W 67
#define H 41

static unsigned char a[H * W * 4], b[H * W * 4];
static uint64_t scratch[1 << 14];

static void fill_random(unsigned char *p, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) p[k] = (unsigned char)rng();
}

/* Random pixels in a, the same in b, and the solid painter of `value` over
 * each (W x H, format f): a into *pa, b into *pb. */
static void two_painters(int f, int32_t stride, const unsigned char *value, rast__solid *sa,
                         rast__painter *pa, rast__solid *sb, rast__painter *pb)
{
    rast_target ta, tb;
    fill_random(a, sizeof a);
    memcpy(b, a, sizeof a);
    CHECK(rast_target_init(&ta, a, W, H, stride, (rast_format)f) == RAST_OK);
    CHECK(rast_target_init(&tb, b, W, H, stride, (rast_format)f) == RAST_OK);
    CHECK(rast__solid_init(sa, &ta, &ta.clip, value, NULL, pa) == RAST_OK);
    CHECK(rast__solid_init(sb, &tb, &tb.clip, value, NULL, pb) == RAST_OK);
}

static void levels_vs_full(void)
{
    static uint8_t full[W];
    int f, rep;
    memset(full, 255, sizeof full);
    for (f = 0; f < RAST_FORMAT_COUNT_; f++) {
        int32_t stride;
        if (rast_format_stride((rast_format)f, W, &stride) != RAST_OK) continue;
        for (rep = 0; rep < 200; rep++) {
            rast__solid sa, sb;
            rast__painter pa, pb;
            unsigned char value[4];
            int32_t xs[2], y = (int32_t)(rng() % H);
            fill_random(value, sizeof value);
            two_painters(f, stride, value, &sa, &pa, &sb, &pb);
            CHECK(pa.full != NULL && pa.levels != NULL);
            xs[0] = (int32_t)(rng() % W);
            xs[1] = xs[0] + 1 + (int32_t)(rng() % (uint32_t)(W - xs[0]));
            pa.full(pa.user, y, xs, 1);
            pb.levels(pb.user, y, xs[0], xs[1], full);
            CHECK(memcmp(a, b, sizeof a) == 0);
            /* the fast kind writes what the full entry writes */
            if (pa.bytes) {
                memcpy(b, a, sizeof a);
                pa.full(pa.user, (y + 1) % H, xs, 1);
                memset(pb.bytes + (ptrdiff_t)((y + 1) % H) * pb.stride + xs[0], pb.value,
                       (size_t)(xs[1] - xs[0]));
                CHECK(memcmp(a, b, sizeof a) == 0);
            }
        }
    }
}

static int32_t coord(int32_t span)
{
    return (int32_t)(rng() % (uint32_t)(span * 256)) - 8 * 256;
}

static void fast_kind_vs_full(void)
{
    static rast_point tris[3 * 40];
    int rep, k;
    for (rep = 0; rep < check_count(300); rep++) {
        rast_target ta, tb;
        rast__solid sa, sb;
        rast__painter pa, pb;
        rast_tri_opts o;
        unsigned char value = (unsigned char)(1 + rng() % 255);
        uint32_t n = 1 + rng() % 40;
        for (k = 0; k < (int)(3 * n); k++) {
            tris[k].x = coord(W + 16);
            tris[k].y = coord(H + 16);
        }
        memset(&o, 0, sizeof o);
        o.subpixel_bits = 8;
        o.algorithm = (rast_tri_algorithm)(rep % RAST_TRI_COUNT_);
        o.sample = (rep / 3) % 2 ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
        o.rounding = (rep / 6) % 2 ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT;
        memset(a, 0, sizeof a);
        memset(b, 0, sizeof b);
        CHECK(rast_target_init(&ta, a, W, H, W, RAST_FORMAT_GRAY8) == RAST_OK);
        tb = ta;
        tb.pixels = b;
        if (rep % 2) { /* a clip inside the target: runs cut by the sink */
            ta.clip.x0 = tb.clip.x0 = (int32_t)(rng() % 20);
            ta.clip.x1 = tb.clip.x1 = W - (int32_t)(rng() % 20);
            ta.clip.y0 = tb.clip.y0 = (int32_t)(rng() % 10);
            ta.clip.y1 = tb.clip.y1 = H - (int32_t)(rng() % 10);
        }
        CHECK(rast__solid_init(&sa, &ta, &ta.clip, &value, NULL, &pa) == RAST_OK);
        CHECK(rast__solid_init(&sb, &tb, &tb.clip, &value, NULL, &pb) == RAST_OK);
        CHECK(pa.bytes != NULL);
        pb.bytes = NULL; /* the same painter without its fast kind */
        CHECK(rast__tri_fill(tris, n, &o, &ta.clip, &pa, NULL, scratch, sizeof scratch) ==
              RAST_OK);
        CHECK(rast__tri_fill(tris, n, &o, &tb.clip, &pb, NULL, scratch, sizeof scratch) ==
              RAST_OK);
        CHECK(memcmp(a, b, sizeof a) == 0);
    }
}

/* The public route: coverage spans, blended by the painter's levels
 * entry from a callback. */
static void blend_span(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *cov)
{
    const rast__painter *p = (const rast__painter *)user;
    p->levels(p->user, y, x0, x1, cov);
}

static void coverage_vs_public(void)
{
    static rast_point pts[24];
    int rep, k, f;
    for (rep = 0; rep < check_count(120); rep++) {
        uint32_t n = 3 + rng() % 22;
        rast_polygon poly;
        rast_coverage_opts o;
        rast_rect clip = {0, 0, W, H};
        unsigned char value[4];
        for (k = 0; k < (int)n; k++) {
            pts[k].x = coord(W + 16);
            pts[k].y = coord(H + 16);
        }
        poly.points = pts;
        poly.ring_sizes = &n;
        poly.nrings = 1;
        memset(&o, 0, sizeof o);
        o.subpixel_bits = 8;
        o.method = (rast_aa_method)(rep % RAST_AA_COUNT_);
        o.rule = (rep / 6) % 2 ? RAST_RULE_NONZERO : RAST_RULE_EVENODD;
        fill_random(value, sizeof value);
        for (f = 0; f < RAST_FORMAT_COUNT_; f++) {
            rast__solid sa, sb;
            rast__painter pa, pb;
            int32_t stride;
            if (rast_format_stride((rast_format)f, W, &stride) != RAST_OK) continue;
            two_painters(f, stride, value, &sa, &pa, &sb, &pb);
            CHECK(rast__cov_paint(&poly, NULL, 0, &o, &clip, &pa, scratch, sizeof scratch) ==
                  RAST_OK);
            CHECK(rast_polygon_coverage_spans(&poly, &o, &clip, blend_span, &pb, scratch,
                                              sizeof scratch) == RAST_OK);
            CHECK(memcmp(a, b, sizeof a) == 0);
        }
    }
}

int main(void)
{
    levels_vs_full();
    fast_kind_vs_full();
    coverage_vs_public();
    return check_report("test_painter");
}

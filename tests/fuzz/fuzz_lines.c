/*
 * fuzz_lines.c - rast_draw_line, rast_draw_polyline,
 * rast_draw_polyline_spans and rast_line_pixels, both algorithms, any S,
 * sample, format and clip.  Oracle: errors exactly for bad input, with
 * nothing written; otherwise nothing outside the clip changes, and with
 * RAST_LINE_BRESENHAM every pixel is the reference line's (ref.h:
 * rast_draw_line's definition), counted per segment; rast_line_pixels
 * lists exactly the reference pixels inside its clip, in order from a,
 * one per major step (DDA: the same major steps, the minor coordinate
 * within one pixel of the exact line for lines under 2^16 pixels), and
 * with too small a capacity writes nothing.
 */
#include "fuzz.h"

#define MAXPTS 8
#define MAXPIX 4096

static fz_target ft;
static fz_spans spans;
static uint16_t want[FZ_MAXDIM * FZ_MAXDIM];
static int32_t xy[2 * MAXPIX + 16];

static int64_t absdiff(int64_t a, int64_t b) { return a > b ? a - b : b - a; }

/* rast_line_pixels against the reference. */
static void check_pixels(rast_point a, rast_point b, const rast_line_opts *o, const rast_rect *clip,
                         size_t capacity)
{
    int s = o->subpixel_bits, center = o->sample == RAST_SAMPLE_CENTER;
    int ymajor = absdiff(b.y, a.y) > absdiff(b.x, a.x);
    size_t count = 12345, k, nref = 0;
    int64_t i, j, q, prev = 0;
    rast_status st;
    for (k = 0; k < sizeof xy / sizeof xy[0]; k++) xy[k] = -7;
    st = rast_line_pixels(a, b, o, clip, xy, capacity, &count);
    for (j = clip->y0; j < clip->y1; j++)
        for (i = clip->x0; i < clip->x1; i++) nref += (size_t)ref_line_has(a, b, s, center, i, j);
    if (o->algorithm == RAST_LINE_BRESENHAM) FZ_ASSERT(count == nref);
    if (count > capacity) {
        FZ_ASSERT(st == RAST_E_SCRATCH);
        for (k = 0; k < sizeof xy / sizeof xy[0]; k++) FZ_ASSERT(xy[k] == -7);
        return;
    }
    FZ_ASSERT(st == RAST_OK);
    for (k = 2 * count; k < sizeof xy / sizeof xy[0]; k++) FZ_ASSERT(xy[k] == -7);
    for (k = 0; k < count; k++) {
        int64_t x = xy[2 * k], y = xy[2 * k + 1], major = ymajor ? y : x, minor = ymajor ? x : y;
        FZ_ASSERT(fz_in_rect(clip, (int32_t)x, (int32_t)y));
        if (k) FZ_ASSERT(absdiff(major, prev) == 1); /* one pixel per major step */
        prev = major;
        if (o->algorithm == RAST_LINE_BRESENHAM) {
            FZ_ASSERT(ref_line_has(a, b, s, center, x, y));
        } else if ((absdiff(b.x, a.x) >> s) < 65536 && (absdiff(b.y, a.y) >> s) < 65536) {
            FZ_ASSERT(ref_line_minor(a, b, s, center, major, &q));
            FZ_ASSERT(absdiff(q, minor) <= 1);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point pts[MAXPTS];
    rast_line_opts o;
    rast_rect clip;
    rast_format f;
    int32_t w, h, x, y, entry, closed;
    uint32_t n, k, segs;
    rast_status st;

    w = 1 + fz_below(&in, FZ_MAXDIM);
    h = 1 + fz_below(&in, FZ_MAXDIM);
    f = fz_format(&in);
    clip = fz_clip(&in, w, h);
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_line_algorithm)fz_below(&in, RAST_LINE_COUNT_);
    o.subpixel_bits = fz_below(&in, RAST_MAX_SUBPIXEL_BITS + 1);
    o.sample = (rast_sample)fz_below(&in, 2);
    entry = fz_below(&in, 4);
    closed = fz_below(&in, 2);
    n = entry == 0 || entry == 3 ? 2 : (uint32_t)fz_below(&in, MAXPTS + 1);
    for (k = 0; k < n; k++) pts[k] = fz_point(&in, o.subpixel_bits, w > h ? w : h);

    if (entry == 3) { /* rast_line_pixels, capacity from none to plenty */
        size_t cap = (size_t)fz_below(&in, 4) == 0 ? (size_t)fz_below(&in, 64) : MAXPIX;
        if (in.out_of_range) {
            size_t count = 0;
            FZ_ASSERT(rast_line_pixels(pts[0], pts[1], &o, &clip, xy, cap, &count) == RAST_E_RANGE);
            return 0;
        }
        if (clip.x1 < clip.x0) clip.x1 = clip.x0;
        if (clip.y1 < clip.y0) clip.y1 = clip.y0;
        check_pixels(pts[0], pts[1], &o, &clip, cap);
        return 0;
    }

    fz_target_init(&ft, w, h, f, &clip);
    fz_spans_init(&spans, &clip, 0);
    if (entry == 0)
        st = rast_draw_line(&ft.t, pts[0], pts[1], &o, fz_value);
    else if (entry == 1)
        st = rast_draw_polyline(&ft.t, pts, n, closed, &o, fz_value);
    else
        st = rast_draw_polyline_spans(pts, n, closed, &o, &clip, fz_span, &spans);
    if (in.out_of_range) {
        FZ_ASSERT(st == RAST_E_RANGE);
        FZ_ASSERT(fz_untouched(&ft));
        for (k = 0; k < FZ_SPAN * FZ_SPAN; k++) FZ_ASSERT(spans.count[k] == 0);
        return 0;
    }
    FZ_ASSERT(st == RAST_OK);
    if (o.algorithm != RAST_LINE_BRESENHAM) { /* DDA: only where it may write */
        if (entry == 2) {
            for (y = -FZ_PAD; y < FZ_MAXDIM + FZ_PAD; y++)
                for (x = -FZ_PAD; x < FZ_MAXDIM + FZ_PAD; x++)
                    FZ_ASSERT(fz_in_rect(&clip, x, y) || fz_spans_at(&spans, x, y) == 0);
        } else {
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++) want[y * w + x] = 0;
            for (y = ft.cut.y0; y < ft.cut.y1; y++) /* tolerate anything inside the clip */
                for (x = ft.cut.x0; x < ft.cut.x1; x++) want[y * w + x] = (uint16_t)fz_count(&ft, x, y);
            fz_check(&ft, want);
        }
        return 0;
    }
    /* Bresenham: each segment's reference pixels, counted */
    segs = n == 0 ? 0 : n - 1 + (closed && entry != 0 ? 1 : 0);
    if (entry == 0) segs = 1;
    for (y = -FZ_PAD; y < FZ_MAXDIM + FZ_PAD; y++)
        for (x = -FZ_PAD; x < FZ_MAXDIM + FZ_PAD; x++) {
            const rast_rect *r = entry == 2 ? &clip : &ft.cut;
            uint16_t c = 0;
            if (fz_in_rect(r, x, y))
                for (k = 0; k < segs; k++)
                    c = (uint16_t)(c + ref_line_has(pts[k], pts[(k + 1) % n], o.subpixel_bits,
                                                    o.sample == RAST_SAMPLE_CENTER, x, y));
            if (entry == 2)
                FZ_ASSERT(fz_spans_at(&spans, x, y) == c);
            else if (x >= 0 && y >= 0 && x < w && y < h)
                want[y * w + x] = c;
        }
    if (entry != 2) fz_check(&ft, want);
    return 0;
}

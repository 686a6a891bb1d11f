/*
 * fuzz_polygon.c - rast_fill_polygon, rast_fill_polygon_opaque and
 * rast_fill_polygon_spans with every algorithm, rule, S, sample, rounding,
 * boundary mode, format and clip.  Oracle: the call fails (and writes
 * nothing) exactly when the input is bad; otherwise every pixel of the clip
 * is the per-sample reference's (fuzz.h), nothing outside the clip or after
 * the scratch changes, and every other algorithm supporting the rule gives
 * the same bytes.  rast_fill_bounds: a rectangle inside the clip holding
 * every filled pixel, and a fill clipped to it (with the scratch its size
 * asks for) gives the same bytes; RAST_E_RANGE with *bounds untouched.
 */
#include "fuzz.h"

static const unsigned char fz_off[4] = {0, 0, 0, 0}; /* MONO1's opaque background */

#define MAXPTS 40

static fz_target ft, ft2;
static fz_scratch scratch;
static fz_spans spans;
static uint16_t want[FZ_MAXDIM * FZ_MAXDIM];

/* Run one entry point on ft (or spans) with opts o; the status. */
static rast_status run(int entry, fz_target *t, const rast_polygon *pg, const rast_fill_opts *o,
                       const rast_rect *clip, size_t bytes)
{
    void *mem = fz_scratch_init(&scratch, bytes);
    rast_status st;
    if (entry == 0)
        st = rast_fill_polygon(&t->t, pg, o, fz_value, mem, bytes);
    else if (entry == 1)
        st = rast_fill_polygon_opaque(&t->t, pg, o, fz_value,
                                      t->t.format == RAST_FORMAT_MONO1 ? fz_off : fz_background, mem,
                                      bytes);
    else
        st = rast_fill_polygon_spans(pg, o, clip, fz_span, &spans, mem, bytes);
    fz_scratch_check(&scratch);
    return st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point pts[MAXPTS];
    uint32_t rings[4], nrings, npts = 0, k, rules = 0;
    rast_polygon pg;
    rast_fill_opts o;
    rast_rect clip;
    rast_format f;
    int32_t w, h, x, y, entry, bad_rule, short_scratch;
    size_t need = 0, bytes;
    rast_status st;
    int a;

    w = 1 + fz_below(&in, FZ_MAXDIM);
    h = 1 + fz_below(&in, FZ_MAXDIM);
    f = fz_format(&in);
    clip = fz_clip(&in, w, h);
    o = fz_fill_opts(&in);
    entry = fz_below(&in, 3);
    short_scratch = fz_u8(&in) == 0;
    nrings = (uint32_t)fz_below(&in, 5);
    for (k = 0; k < nrings; k++) {
        rings[k] = (uint32_t)fz_below(&in, (int32_t)(MAXPTS / 4 + 1));
        npts += rings[k];
    }
    for (k = 0; k < npts; k++) pts[k] = fz_point(&in, o.subpixel_bits, w > h ? w : h);
    pg.points = pts;
    pg.ring_sizes = rings;
    pg.nrings = nrings;

    rast_algorithm_info(o.algorithm, NULL, &rules);
    bad_rule = !(rules & (1u << o.rule));
    if (rast_scratch_size(&o, npts, clip.x1 > clip.x0 ? clip.x1 - clip.x0 : 0,
                          clip.y1 > clip.y0 ? clip.y1 - clip.y0 : 0, &need) != RAST_OK) {
        FZ_ASSERT(bad_rule);
        need = 0;
    }
    /* spans take the clip as it is; targets cut it (a smaller need) */
    fz_target_init(&ft, w, h, f, &clip);
    if (entry != 2)
        FZ_ASSERT(rast_scratch_size(&o, npts, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) ==
                  (bad_rule ? RAST_E_RULE : RAST_OK));
    if (bad_rule) need = 0;
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    bytes = short_scratch && need >= 8 ? need - 8 : need;
    fz_spans_init(&spans, &clip, 1);

    st = run(entry, &ft, &pg, &o, &clip, bytes);
    {
        /* each bad thing alone gives its own status; any gives nothing drawn */
        const int range = in.out_of_range, rule = bad_rule, small = bytes < need,
                  format = entry == 1 && f == RAST_FORMAT_COUNT16;
        if (range + rule + small + format > 0) {
            FZ_ASSERT(st != RAST_OK);
            if (range + rule + small + format == 1)
                FZ_ASSERT(st == (range ? RAST_E_RANGE : rule ? RAST_E_RULE
                                 : small ? RAST_E_SCRATCH : RAST_E_FORMAT));
            FZ_ASSERT(fz_untouched(&ft));
            for (k = 0; k < FZ_SPAN * FZ_SPAN; k++) FZ_ASSERT(spans.count[k] == 0);
            if (range) { /* rast_fill_bounds: the same status, *bounds untouched */
                rast_rect b = {7, 7, 7, 7};
                rast_status bs = rast_fill_bounds(&o, &pg, &clip, &b);
                FZ_ASSERT(bs != RAST_OK);
                if (range + rule + small + format == 1) FZ_ASSERT(bs == RAST_E_RANGE);
                FZ_ASSERT(b.x0 == 7 && b.y0 == 7 && b.x1 == 7 && b.y1 == 7);
            }
            return 0;
        }
    }
    FZ_ASSERT(st == RAST_OK);

    /* the reference, over the clip (cut to the target, or the spans' own) */
    if (entry == 2) {
        for (y = -FZ_PAD; y < FZ_MAXDIM + FZ_PAD; y++)
            for (x = -FZ_PAD; x < FZ_MAXDIM + FZ_PAD; x++) {
                int in_clip = fz_in_rect(&clip, x, y);
                FZ_ASSERT(fz_spans_at(&spans, x, y) == (in_clip && fz_ref_polygon(&pg, &o, x, y)));
            }
        return 0;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            want[y * w + x] = (uint16_t)(fz_in_rect(&ft.cut, x, y) && fz_ref_polygon(&pg, &o, x, y));
    if (entry == 1 && f == RAST_FORMAT_MONO1) { /* opaque: background is "off", as before */
    } else if (entry == 1) { /* opaque: turn the background into "0" and check as the fill */
        for (y = ft.cut.y0; y < ft.cut.y1; y++)
            for (x = ft.cut.x0; x < ft.cut.x1; x++) {
                unsigned char *p = fz_px(&ft, x, y);
                if (memcmp(p, fz_background, (size_t)ft.bpp) == 0) {
                    memset(p, 0, (size_t)ft.bpp);
                } else {
                    FZ_ASSERT(memcmp(p, fz_value, (size_t)ft.bpp) == 0);
                    FZ_ASSERT(want[y * w + x]);
                }
            }
    }
    fz_check(&ft, want);

    /* rast_fill_bounds: a rectangle inside the clip holding every pixel of
     * the fill (empty as x0 == x1 and y0 == y1); a fill clipped to it, with
     * the scratch its size asks for, gives the same bytes */
    if (entry == 0) {
        rast_rect b;
        FZ_ASSERT(rast_fill_bounds(&o, &pg, &ft.cut, &b) == RAST_OK);
        FZ_ASSERT(b.x0 <= b.x1 && b.y0 <= b.y1);
        if (b.x0 == b.x1 || b.y0 == b.y1) FZ_ASSERT(b.x0 == b.x1 && b.y0 == b.y1);
        if (b.x0 < b.x1)
            FZ_ASSERT(b.x0 >= ft.cut.x0 && b.x1 <= ft.cut.x1 && b.y0 >= ft.cut.y0 && b.y1 <= ft.cut.y1);
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if (want[y * w + x]) FZ_ASSERT(fz_in_rect(&b, x, y));
        FZ_ASSERT(rast_scratch_size(&o, npts, b.x1 - b.x0, b.y1 - b.y0, &need) == RAST_OK);
        fz_target_init(&ft2, w, h, f, &b);
        FZ_ASSERT(run(0, &ft2, &pg, &o, &b, need) == RAST_OK);
        FZ_ASSERT(memcmp(ft.mem, ft2.mem, sizeof ft.mem) == 0);
    }

    /* every other algorithm with this rule: the same bytes */
    for (a = 0; a < RAST_ALGO_COUNT_; a++) {
        rast_fill_opts o2 = o;
        o2.algorithm = (rast_algorithm)a;
        rast_algorithm_info(o2.algorithm, NULL, &rules);
        if (a == (int)o.algorithm || !(rules & (1u << o.rule))) continue;
        FZ_ASSERT(rast_scratch_size(&o2, npts, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0,
                                    &need) == RAST_OK);
        fz_target_init(&ft2, w, h, f, &clip);
        FZ_ASSERT(run(0, &ft2, &pg, &o2, &clip, need) == RAST_OK);
        if (entry == 0) FZ_ASSERT(memcmp(ft.mem, ft2.mem, sizeof ft.mem) == 0);
        else fz_check(&ft2, want);
    }
    return 0;
}

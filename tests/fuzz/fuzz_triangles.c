/*
 * fuzz_triangles.c - rast_fill_triangles and rast_fill_triangles_spans
 * with every algorithm, S, sample, rounding, boundary mode, format and
 * clip.  Oracle: errors exactly for bad input, with nothing written;
 * otherwise each pixel holds the number of triangles whose one-ring
 * polygon owns it by the reference (fuzz.h) - COUNT16 shows the count -
 * nothing outside the clip or after the scratch changes, and the other
 * algorithms give the same bytes.
 */
#include "fuzz.h"

#define MAXTRIS 8

static fz_target ft, ft2;
static fz_scratch scratch;
static fz_spans spans;
static uint16_t want[FZ_MAXDIM * FZ_MAXDIM];

static rast_status run(int entry, fz_target *t, const rast_point *tris, uint32_t n,
                       const rast_tri_opts *o, const rast_rect *clip, size_t bytes)
{
    void *mem = fz_scratch_init(&scratch, bytes);
    rast_status st = entry == 0 ? rast_fill_triangles(&t->t, tris, n, o, fz_value, mem, bytes)
                                : rast_fill_triangles_spans(tris, n, o, clip, fz_span, &spans, mem,
                                                            bytes);
    fz_scratch_check(&scratch);
    return st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point tris[3 * MAXTRIS];
    rast_tri_opts o;
    rast_fill_opts fo;
    rast_rect clip;
    rast_format f;
    int32_t w, h, x, y, entry, short_scratch, a;
    uint32_t n, k;
    size_t need = 0, bytes;
    rast_status st;

    w = 1 + fz_below(&in, FZ_MAXDIM);
    h = 1 + fz_below(&in, FZ_MAXDIM);
    f = fz_format(&in);
    clip = fz_clip(&in, w, h);
    fo = fz_fill_opts(&in);
    memset(&o, 0, sizeof o);
    o.algorithm = (rast_tri_algorithm)fz_below(&in, RAST_TRI_COUNT_);
    o.subpixel_bits = fo.subpixel_bits;
    o.sample = fo.sample;
    o.rounding = fo.rounding;
    o.boundary = fo.boundary;
    entry = fz_below(&in, 2);
    short_scratch = fz_u8(&in) == 0;
    n = (uint32_t)fz_below(&in, MAXTRIS + 1);
    for (k = 0; k < 3 * n; k++) tris[k] = fz_point(&in, o.subpixel_bits, w > h ? w : h);

    fz_target_init(&ft, w, h, f, &clip);
    if (entry == 0)
        FZ_ASSERT(rast_tri_scratch_size(&o, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) ==
                  RAST_OK);
    else
        FZ_ASSERT(rast_tri_scratch_size(&o, clip.x1 > clip.x0 ? clip.x1 - clip.x0 : 0,
                                        clip.y1 > clip.y0 ? clip.y1 - clip.y0 : 0, &need) == RAST_OK);
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    bytes = short_scratch && need >= 8 ? need - 8 : need;
    fz_spans_init(&spans, &clip, 0);

    st = run(entry, &ft, tris, n, &o, &clip, bytes);
    if (in.out_of_range || bytes < need) {
        FZ_ASSERT(st == (in.out_of_range ? RAST_E_RANGE : RAST_E_SCRATCH) ||
                  (in.out_of_range && bytes < need && st == RAST_E_SCRATCH));
        FZ_ASSERT(fz_untouched(&ft));
        for (k = 0; k < FZ_SPAN * FZ_SPAN; k++) FZ_ASSERT(spans.count[k] == 0);
        return 0;
    }
    FZ_ASSERT(st == RAST_OK);

    /* the reference: each triangle as a one-ring polygon, counted */
    fo.rule = RAST_RULE_NONZERO;
    for (y = -FZ_PAD; y < FZ_MAXDIM + FZ_PAD; y++)
        for (x = -FZ_PAD; x < FZ_MAXDIM + FZ_PAD; x++) {
            const rast_rect *r = entry == 0 ? &ft.cut : &clip;
            uint16_t c = 0;
            static const uint32_t three = 3;
            if (fz_in_rect(r, x, y))
                for (k = 0; k < n; k++) {
                    rast_polygon pg;
                    pg.points = tris + 3 * k;
                    pg.ring_sizes = &three;
                    pg.nrings = 1;
                    c = (uint16_t)(c + fz_ref_polygon(&pg, &fo, x, y));
                }
            if (entry == 1)
                FZ_ASSERT(fz_spans_at(&spans, x, y) == c);
            else if (x >= 0 && y >= 0 && x < w && y < h)
                want[y * w + x] = c;
        }
    if (entry == 1) return 0;
    fz_check(&ft, want);

    for (a = 0; a < RAST_TRI_COUNT_; a++) {
        rast_tri_opts o2 = o;
        if (a == (int)o.algorithm) continue;
        o2.algorithm = (rast_tri_algorithm)a;
        FZ_ASSERT(rast_tri_scratch_size(&o2, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) ==
                  RAST_OK);
        fz_target_init(&ft2, w, h, f, &clip);
        FZ_ASSERT(run(0, &ft2, tris, n, &o2, &clip, need) == RAST_OK);
        FZ_ASSERT(memcmp(ft.mem, ft2.mem, sizeof ft.mem) == 0);
    }
    return 0;
}

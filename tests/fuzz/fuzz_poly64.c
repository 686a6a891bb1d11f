/*
 * fuzz_poly64.c - the 64-bit vertex path: rast_fill_polygon64, _opaque,
 * _spans, rast_fill_bounds64 and the batch rast_fill_polygons64_spans at
 * every S in 0..32, both rules and sample offsets, the exact and
 * conservative boundaries, with windows anywhere in the 2^28-pixel plane.
 * Oracle: the status is the documented one (RAST_E_RANGE exactly when a
 * coordinate is past RAST_COORD64_MAX(S), RAST_E_WIDE for what the path
 * does not offer) and then nothing is written; otherwise every pixel of the
 * clip is the 128-bit per-sample reference's (ref.h, ref_polygon64),
 * nothing outside the clip or after the scratch changes, the opaque fill
 * writes the background elsewhere in the clip, the spans are the same
 * pixels, the bounds hold them, and the batch gives the same spans.
 */
#include "fuzz.h"

#define MAXPTS 24
#define WIN 40

static unsigned char img[WIN + 2 * FZ_PAD][WIN + 2 * FZ_PAD];
static unsigned char spans_img[WIN][WIN];
static fz_scratch scratch;

/* The plane pixel that the window's (0, 0) stands for. */
static int64_t org_x, org_y;

static void put_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    (void)user;
    FZ_ASSERT(x0 < x1);
    memset(&spans_img[y - org_y][x0 - org_x], 1, (size_t)(x1 - x0));
}

static void put_batch(void *user, uint32_t k, int32_t y, int32_t x0, int32_t x1)
{
    (void)user;
    FZ_ASSERT(k == 0);
    put_span(NULL, y, x0, x1);
}

/* A 64-bit coordinate at S: near the window (plane pixels org..org+WIN,
 * with a subpixel part), at or just past a limit, or anything in range. */
static int64_t coord(fz_in *in, int s, int64_t org)
{
    const int64_t lim = RAST_COORD64_MAX(s), unit = (int64_t)1 << s;
    uint32_t kind = fz_u8(in) % 16;
    int64_t v;
    if (kind < 10) {
        v = (org + fz_below(in, WIN + 16) - 8) * unit;
        if (s > 0) v += (int64_t)(fz_u32(in) & 0x7FFFFFFF) % unit;
    } else if (kind < 12) {
        v = (kind & 1) ? lim : -lim;
    } else if (kind == 12) {
        v = (fz_u8(in) & 1) ? lim + 1 : -lim - 1; /* just past */
    } else if (kind == 13) {
        v = (fz_u8(in) & 1) ? INT64_MAX : INT64_MIN;
    } else {
        v = ((int64_t)fz_u32(in) << 31 | fz_u32(in)) % lim;
    }
    return v;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point64 pts[MAXPTS];
    uint32_t rings[3], nrings, npts = 0, k, failed;
    rast_polygon64 pg;
    rast_fill_opts o;
    rast_rect clip, b = {0, 0, 0, 0};
    rast_target t;
    int32_t w, h, x, y, entry, s;
    int64_t lim;
    size_t need = 0, bytes;
    rast_status st, want_st = RAST_OK;
    static const unsigned char one = 0x5A, bg = 0x11;

    w = 1 + fz_below(&in, WIN);
    h = 1 + fz_below(&in, WIN);
    memset(&o, 0, sizeof o);
    s = fz_below(&in, RAST_MAX_SUBPIXEL_BITS64 + 1);
    o.subpixel_bits = s;
    o.rule = (rast_fill_rule)fz_below(&in, 2);
    o.sample = (rast_sample)fz_below(&in, 2);
    o.boundary = fz_u8(&in) & 1 ? RAST_BOUNDARY_CONSERVATIVE : RAST_BOUNDARY_EXACT;
    if (fz_u8(&in) < 8) { /* something the 64-bit path does not offer */
        int what = fz_below(&in, 3);
        if (what == 0) o.algorithm = (rast_algorithm)(1 + fz_below(&in, RAST_ALGO_COUNT_ - 1));
        if (what == 1) o.rounding = RAST_ROUND_TEXTBOOK;
        if (what == 2) o.boundary = RAST_BOUNDARY_CLOSED;
        o.rule = RAST_RULE_EVENODD; /* every algorithm has it */
        want_st = RAST_E_WIDE;
    }
    lim = RAST_COORD64_MAX(s);
    /* the window: at the origin, or next to a corner of the plane */
    org_x = org_y = 0;
    if (fz_u8(&in) & 1) {
        int64_t far = (lim >> s) - WIN;
        org_x = fz_u8(&in) & 1 ? far : -far - WIN;
        org_y = fz_u8(&in) & 1 ? far : -far - WIN;
    }
    clip.x0 = (int32_t)org_x + fz_below(&in, w + 1);
    clip.y0 = (int32_t)org_y + fz_below(&in, h + 1);
    clip.x1 = (int32_t)org_x + fz_below(&in, w + 1);
    clip.y1 = (int32_t)org_y + fz_below(&in, h + 1);
    if (clip.x1 < clip.x0) clip.x1 = clip.x0;
    if (clip.y1 < clip.y0) clip.y1 = clip.y0;

    nrings = 1 + (uint32_t)fz_below(&in, 3);
    for (k = 0; k < nrings; k++) {
        rings[k] = (uint32_t)fz_below(&in, MAXPTS / 3 + 1);
        for (x = 0; x < (int32_t)rings[k]; x++, npts++) {
            pts[npts].x = coord(&in, s, org_x);
            pts[npts].y = coord(&in, s, org_y);
            if (want_st == RAST_OK &&
                (pts[npts].x > lim || pts[npts].x < -lim || pts[npts].y > lim || pts[npts].y < -lim))
                want_st = RAST_E_RANGE;
        }
    }
    pg.points = pts;
    pg.ring_sizes = rings;
    pg.nrings = nrings;
    entry = fz_below(&in, 4);

    st = rast_scratch_size64(&o, npts, clip.x1 - clip.x0, clip.y1 - clip.y0, &need);
    FZ_ASSERT(st == (want_st == RAST_E_WIDE ? RAST_E_WIDE : RAST_OK));
    bytes = st == RAST_OK ? need : 64;

    /* The window as a target: its pixel (x, y) is plane pixel (org + x, org + y);
     * the polygon is drawn through spans for a window away from the origin. */
    memset(img, FZ_GUARD, sizeof img);
    memset(spans_img, 0, sizeof spans_img);
    for (y = 0; y < h; y++) memset(&img[y + FZ_PAD][FZ_PAD], 0, (size_t)w);
    if (entry < 2 && org_x == 0 && org_y == 0) {
        FZ_ASSERT(rast_target_init(&t, &img[FZ_PAD][FZ_PAD], w, h, (int32_t)sizeof img[0],
                                   RAST_FORMAT_GRAY8) == RAST_OK);
        t.clip = clip;
        st = entry == 0 ? rast_fill_polygon64(&t, &pg, &o, &one, fz_scratch_init(&scratch, bytes), bytes)
                        : rast_fill_polygon64_opaque(&t, &pg, &o, &one, &bg,
                                                     fz_scratch_init(&scratch, bytes), bytes);
        fz_scratch_check(&scratch);
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++) spans_img[y][x] = img[y + FZ_PAD][x + FZ_PAD] == one;
    } else if (entry == 3) {
        st = rast_fill_polygons64_spans(&pg, 1, &o, &clip, put_batch, NULL,
                                        fz_scratch_init(&scratch, FZ_SCRATCH_MAX), FZ_SCRATCH_MAX,
                                        &failed);
        fz_scratch_check(&scratch);
    } else {
        st = rast_fill_polygon64_spans(&pg, &o, &clip, put_span, NULL,
                                       fz_scratch_init(&scratch, bytes), bytes);
        fz_scratch_check(&scratch);
    }
    FZ_ASSERT(st == want_st);
    if (st == RAST_OK) FZ_ASSERT(rast_fill_bounds64(&o, &pg, &clip, &b) == RAST_OK);
    /* guards and the pixels outside the clip */
    for (y = -FZ_PAD; y < WIN + FZ_PAD; y++)
        for (x = -FZ_PAD; x < WIN + FZ_PAD; x++) {
            unsigned char v = img[y + FZ_PAD][x + FZ_PAD];
            int inside = x >= 0 && y >= 0 && x < w && y < h;
            int in_clip = inside && org_x == 0 && org_y == 0 && x >= clip.x0 && x < clip.x1 &&
                          y >= clip.y0 && y < clip.y1;
            if (!inside) FZ_ASSERT(v == FZ_GUARD);
            else if (!in_clip || st != RAST_OK) FZ_ASSERT(v == 0);
            else FZ_ASSERT(v == one || v == (entry == 1 ? bg : 0));
        }
    for (y = 0; y < WIN; y++)
        for (x = 0; x < WIN; x++) {
            int64_t px = org_x + x, py = org_y + y;
            int in_clip = px >= clip.x0 && px < clip.x1 && py >= clip.y0 && py < clip.y1 &&
                          x < w && y < h;
            int want = st == RAST_OK && in_clip && ref_polygon64(&pg, &o, px, py);
            FZ_ASSERT(spans_img[y][x] == want);
            if (want) FZ_ASSERT(px >= b.x0 && px < b.x1 && py >= b.y0 && py < b.y1);
        }
    return 0;
}

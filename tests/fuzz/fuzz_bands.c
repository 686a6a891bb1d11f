/*
 * fuzz_bands.c - rast_render_bands and rast_render_bands_spans on small
 * random scenes (polygons, triangle batches, polylines; every option),
 * band heights 1..70 and scratch from plenty down to less than one row
 * needs.  Oracle: with enough scratch for one row the band render's bytes
 * (target, guards) equal those of drawing each primitive with its own
 * entry point into the whole clip, and so do the spans painted; with less,
 * or with a bad primitive anywhere, an error and not one byte or span
 * written.  Sometimes also the widest clip, -RAST_MAX_DIM..RAST_MAX_DIM
 * across: the scene's spans are its primitives' own (issue 18).  The primitives' own pixels are checked against the references
 * by the other fuzz targets.
 */
#include "fuzz.h"

#define MAXPRIMS 4
#define MAXPTS 24

static fz_target ft, ft2, ft3;
static fz_scratch scratch;
static uint64_t big[FZ_SCRATCH_MAX / 8];

typedef struct {
    fz_target *t;
    const rast_prim *prims;
    uint32_t n;
    rast_rect clip;
} painter;

static void paint(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    painter *p = (painter *)user;
    int32_t x;
    FZ_ASSERT(prim >= p->prims && prim < p->prims + p->n);
    FZ_ASSERT(x0 < x1 && fz_in_rect(&p->clip, x0, y) && x1 <= p->clip.x1);
    for (x = x0; x < x1; x++) {
        unsigned char *px = fz_px(p->t, x, y);
        if (p->t->t.format == RAST_FORMAT_COUNT16) {
            uint16_t v;
            memcpy(&v, px, 2);
            if (v < 65535) v++;
            memcpy(px, &v, 2);
        } else {
            fz_set(p->t, p->t->mem, x, y, (const unsigned char *)prim->pixel);
        }
    }
}

/* Spans as an order-free digest (count and a sum of hashes): the wide
 * clip's spans of the scene against those of the primitives' own span
 * entry points (issue 18: the scene refused clips they accept). */
typedef struct {
    uint64_t count, sum;
    const rast_prim *prims;
    uint32_t index;
} digest;

static void digest_add(digest *d, uint32_t i, int32_t y, int32_t x0, int32_t x1)
{
    uint64_t hsh = 1469598103934665603u;
    hsh = (hsh ^ i) * 1099511628211u;
    hsh = (hsh ^ (uint32_t)y) * 1099511628211u;
    hsh = (hsh ^ (uint32_t)x0) * 1099511628211u;
    hsh = (hsh ^ (uint32_t)x1) * 1099511628211u;
    d->count++;
    d->sum += hsh ^ (hsh >> 29);
}

static void digest_prim(void *user, const rast_prim *prim, int32_t y, int32_t x0, int32_t x1)
{
    digest *d = (digest *)user;
    FZ_ASSERT(x0 < x1);
    digest_add(d, (uint32_t)(prim - d->prims), y, x0, x1);
}

static void digest_one(void *user, int32_t y, int32_t x0, int32_t x1)
{
    digest *d = (digest *)user;
    FZ_ASSERT(x0 < x1);
    digest_add(d, d->index, y, x0, x1);
}

static void wide_clip(const rast_prim *prims, uint32_t n, int32_t y0, int32_t y1)
{
    rast_rect wide;
    digest a, b;
    uint32_t i;
    int all_ok = 1;
    rast_status st;
    wide.x0 = -RAST_MAX_DIM;
    wide.x1 = RAST_MAX_DIM;
    wide.y0 = y0;
    wide.y1 = y1;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.prims = b.prims = prims;
    /* Too slow there: the per-sample algorithms walk every column, and a
     * polyline's pixels are all visible (up to 2^28 of them). */
    for (i = 0; i < n; i++)
        if (prims[i].kind == RAST_PRIM_POLYLINE ||
            (prims[i].kind == RAST_PRIM_POLYGON && (prims[i].fill->algorithm == RAST_ALGO_CROSSING ||
                                                    prims[i].fill->algorithm == RAST_ALGO_WINDING)))
            return;
    for (i = 0; i < n && all_ok; i++) {
        const rast_prim *p = &prims[i];
        a.index = i;
        if (p->kind == RAST_PRIM_POLYGON)
            st = rast_fill_polygon_spans(&p->polygon, p->fill, &wide, digest_one, &a, big, sizeof big);
        else if (p->kind == RAST_PRIM_POLYGON64)
            st = rast_fill_polygon64_spans(&p->polygon64, p->fill, &wide, digest_one, &a, big,
                                           sizeof big);
        else if (p->kind == RAST_PRIM_TRIANGLES)
            st = rast_fill_triangles_spans(p->points, p->count, p->tri, &wide, digest_one, &a, big,
                                           sizeof big);
        else
            st = rast_draw_polyline_spans(p->points, p->count, p->closed, p->line, &wide,
                                          digest_one, &a);
        all_ok = st == RAST_OK;
    }
    st = rast_render_bands_spans(prims, n, &wide, y1 - y0, digest_prim, &b, big,
                                 sizeof big, NULL);
    if (all_ok) FZ_ASSERT(st == RAST_OK && a.count == b.count && a.sum == b.sum);
    FZ_ASSERT(st != RAST_E_SIZE);
}

static rast_status draw_full(fz_target *t, const rast_prim *p, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        rast_status st;
        if (p[i].kind == RAST_PRIM_POLYGON)
            st = rast_fill_polygon(&t->t, &p[i].polygon, p[i].fill, p[i].pixel, big, sizeof big);
        else if (p[i].kind == RAST_PRIM_POLYGON64)
            st = rast_fill_polygon64(&t->t, &p[i].polygon64, p[i].fill, p[i].pixel, big,
                                     sizeof big);
        else if (p[i].kind == RAST_PRIM_TRIANGLES)
            st = rast_fill_triangles(&t->t, p[i].points, p[i].count, p[i].tri, p[i].pixel, big,
                                     sizeof big);
        else
            st = rast_draw_polyline(&t->t, p[i].points, p[i].count, p[i].closed, p[i].line,
                                    p[i].pixel);
        if (st != RAST_OK) return st;
    }
    return RAST_OK;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_prim prims[MAXPRIMS];
    rast_fill_opts fo[MAXPRIMS];
    rast_tri_opts to[MAXPRIMS];
    rast_line_opts lo[MAXPRIMS];
    rast_point pts[MAXPRIMS][MAXPTS];
    rast_point64 pts64[MAXPRIMS][MAXPTS];
    uint32_t rings[MAXPRIMS][3];
    unsigned char pixel[MAXPRIMS][4];
    rast_band_stats stats;
    painter pt;
    rast_rect clip;
    rast_format f;
    int32_t w, h, k_rows, choice;
    uint32_t n, i, k;
    size_t one = 0, full = 0, bytes;
    rast_status st, st_full, st_spans;

    w = 1 + fz_below(&in, FZ_MAXDIM);
    h = 1 + fz_below(&in, FZ_MAXDIM);
    f = fz_format(&in);
    clip = fz_clip(&in, w, h);
    k_rows = 1 + fz_below(&in, 70);
    choice = fz_below(&in, 4);
    n = (uint32_t)fz_below(&in, MAXPRIMS + 1);
    for (i = 0; i < n; i++) {
        rast_prim *p = &prims[i];
        uint32_t m;
        memset(p, 0, sizeof *p);
        p->kind = (rast_prim_kind)fz_below(&in, RAST_PRIM_COUNT_);
        fo[i] = fz_fill_opts(&in);
        memset(&to[i], 0, sizeof to[i]);
        to[i].algorithm = (rast_tri_algorithm)(fo[i].algorithm % RAST_TRI_COUNT_);
        to[i].subpixel_bits = fo[i].subpixel_bits;
        to[i].sample = fo[i].sample;
        to[i].rounding = fo[i].rounding;
        to[i].boundary = fo[i].boundary;
        lo[i].algorithm = (rast_line_algorithm)(fo[i].rule);
        lo[i].subpixel_bits = fo[i].subpixel_bits;
        lo[i].sample = fo[i].sample;
        p->fill = &fo[i];
        p->tri = &to[i];
        p->line = &lo[i];
        for (k = 0; k < 4; k++) pixel[i][k] = (unsigned char)(fz_value[k] + 16 * i + 1);
        p->pixel = pixel[i];
        m = (uint32_t)fz_below(&in, MAXPTS / 3 + 1) * 3;
        for (k = 0; k < m; k++) pts[i][k] = fz_point(&in, fo[i].subpixel_bits, w > h ? w : h);
        p->points = pts[i];
        p->count = p->kind == RAST_PRIM_TRIANGLES ? m / 3 : m;
        p->closed = fz_below(&in, 2);
        rings[i][0] = m / 3;
        rings[i][1] = m / 3;
        rings[i][2] = m - 2 * (m / 3);
        p->polygon.points = pts[i];
        p->polygon.ring_sizes = rings[i];
        p->polygon.nrings = 1 + (uint32_t)fz_below(&in, 3);
        if (p->polygon.nrings == 1) rings[i][0] = m;
        if (p->polygon.nrings == 2) rings[i][1] = m - m / 3;
        /* RAST_PRIM_POLYGON64: the same polygon with 64-bit vertices */
        for (k = 0; k < m; k++) {
            pts64[i][k].x = pts[i][k].x;
            pts64[i][k].y = pts[i][k].y;
        }
        p->polygon64.points = pts64[i];
        p->polygon64.ring_sizes = rings[i];
        p->polygon64.nrings = p->polygon.nrings;
    }

    fz_target_init(&ft, w, h, f, &clip);
    fz_target_init(&ft2, w, h, f, &clip);
    fz_target_init(&ft3, w, h, f, &clip);
    st_full = draw_full(&ft2, prims, n);
    st = rast_scene_scratch_size(prims, n, 1, ft.cut.x1 - ft.cut.x0, &one);
    if (st == RAST_OK) st = rast_scene_scratch_size(prims, n, k_rows, ft.cut.x1 - ft.cut.x0, &full);
    if (st != RAST_OK) {
        one = 0;
        full = 0;
    }
    FZ_ASSERT(full <= FZ_SCRATCH_MAX && one <= full);
    bytes = choice == 0 ? full : choice == 1 ? one + (full - one) / 2 : choice == 2 ? one
            : (one >= 8 ? one - 8 : one);
    bytes -= bytes % 8;

    st = rast_render_bands(&ft.t, prims, n, k_rows, fz_scratch_init(&scratch, bytes), bytes, &stats);
    fz_scratch_check(&scratch);
    pt.t = &ft3;
    pt.prims = prims;
    pt.n = n;
    pt.clip = ft.cut;
    st_spans = rast_render_bands_spans(prims, n, &ft.cut, k_rows, paint, &pt,
                                       fz_scratch_init(&scratch, bytes), bytes, NULL);
    fz_scratch_check(&scratch);

    if (st_full != RAST_OK || bytes < one) {
        FZ_ASSERT(st != RAST_OK && st_spans != RAST_OK);
        if (st_full == RAST_OK) FZ_ASSERT(st == RAST_E_SCRATCH && st_spans == RAST_E_SCRATCH);
        FZ_ASSERT(fz_untouched(&ft));
        FZ_ASSERT(fz_untouched(&ft3));
        return 0;
    }
    FZ_ASSERT(st == RAST_OK && st_spans == RAST_OK);
    if (fz_below(&in, 4) == 0 && ft.cut.y0 < ft.cut.y1) wide_clip(prims, n, ft.cut.y0, ft.cut.y1);
    FZ_ASSERT(stats.peak_scratch <= bytes);
    FZ_ASSERT(memcmp(ft.mem, ft2.mem, sizeof ft.mem) == 0);
    FZ_ASSERT(memcmp(ft3.mem, ft2.mem, sizeof ft.mem) == 0);
    return 0;
}

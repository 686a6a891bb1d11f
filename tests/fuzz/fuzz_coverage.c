/*
 * fuzz_coverage.c - rast_polygon_coverage and rast_triangles_coverage with
 * every method, rule, S, sample, output format and clip.  Oracles:
 *  - bad input (a vertex out of range, or out of range once scaled by k
 *    for ssK; a short scratch) gives its status and writes nothing;
 *  - every clip pixel is written, nothing around it (row padding, guard
 *    bytes after the last row, the scratch's guard);
 *  - ssK: each value is floor(count M / k^2 + 1/2) of the per-sample
 *    reference (tests/c/ref.h) on the k-times finer grid (for a triangle
 *    batch, the union: a fine sample is counted when some triangle owns
 *    it);
 *  - area and accumulate on rectangles on the 2^-S grid (possibly
 *    overlapping, either orientation): the exact area by cells;
 *  - area on any polygon: translating it (and the clip) by whole pixels,
 *    and (even-odd) reversing its rings, gives the same bytes;
 *  - area in uint8 and uint16 (polygons, triangle batches): the level of
 *    the 2^-62 fixed point of the same call, which never takes the
 *    accumulation's rows (one off only at a tie within the bound);
 *  - triangle batches also many times over (copies drawn in toward their
 *    centres), so that hundreds are active on a row, the walk's way with
 *    many (columns covered on every fine row, triangles inside skipped),
 *    or made into a ladder mesh whose inner edges cancel (ssK then walks
 *    its outline as a polygon);
 *  - rast_polygon_coverage_spans and rast_triangles_coverage_spans
 *    (uint8): the same values, in ordered runs of values not 0 inside the
 *    clip;
 *  - rast_fill_polygon_aa / rast_fill_triangles_aa (uint8, a clip inside
 *    the target): a target of any format with fuzzed pixels becomes the
 *    documented blend (tests/c/blend_ref.h) of those values, nothing
 *    around the clip written;
 *  - rast_fill_triangles_shaded_aa with one colour at every vertex (exact
 *    or flat): the same bytes as rast_fill_triangles_aa with that colour
 *    packed (rast_pack_color), for every colour format.
 */
#include "blend_ref.h"
#include "fuzz.h"

#define MAXPTS 24
#define CW 8 /* largest clip side */
#define PADB 8 /* padding bytes after each row */

#define REPS 301 /* copies of a batch of one triangle: more than 256 active */

static fz_scratch scratch;
static rast_point many[MAXPTS * REPS], fine[MAXPTS * REPS];
static unsigned char out[(CW * 8 + PADB) * CW + 64], out2[(CW * 8 + PADB) * CW + 64];

static const int32_t fmt_size[3] = {1, 2, 8};

static uint64_t value_at(const unsigned char *o, rast_coverage_format f, ptrdiff_t stride,
                         int32_t x, int32_t y)
{
    const unsigned char *row = o + y * stride;
    if (f == RAST_COVERAGE_U8) return row[x];
    if (f == RAST_COVERAGE_U16) return ((const uint16_t *)(const void *)row)[x];
    return ((const uint64_t *)(const void *)row)[x];
}

/* The value of coverage num / den in format f. */
static uint64_t want_value(uint64_t num, uint64_t den, rast_coverage_format f)
{
    uint64_t M = f == RAST_COVERAGE_U8 ? 255 : 65535;
    if (f == RAST_COVERAGE_FIX62) return num * (((uint64_t)1 << 62) / den); /* den: 2^n <= 2^8 */
    return (2 * num * M + den) / (2 * den);
}

/* rast_polygon_coverage_spans into an image of the clip (stride CW). */
typedef struct fz_cspans {
    unsigned char img[CW * CW];
    rast_rect clip;
    int32_t y, x1;
} fz_cspans;

static fz_cspans cspans;

static void fz_cspan(void *user, int32_t y, int32_t x0, int32_t x1, const uint8_t *v)
{
    fz_cspans *s = (fz_cspans *)user;
    int32_t x;
    FZ_ASSERT(x0 < x1 && y >= s->clip.y0 && y < s->clip.y1 && x0 >= s->clip.x0 && x1 <= s->clip.x1);
    FZ_ASSERT(y > s->y || (y == s->y && x0 > s->x1)); /* ordered, not touching */
    for (x = x0; x < x1; x++) {
        FZ_ASSERT(v[x - x0] != 0);
        s->img[(y - s->clip.y0) * CW + x - s->clip.x0] = v[x - x0];
    }
    s->y = y;
    s->x1 = x1;
}

static rast_status run(const rast_polygon *pg, const rast_point *tris, uint32_t ntris,
                       const rast_coverage_opts *o, const rast_rect *clip,
                       rast_coverage_format f, unsigned char *buf, ptrdiff_t stride,
                       size_t bytes)
{
    void *mem = fz_scratch_init(&scratch, bytes);
    rast_status st = pg ? rast_polygon_coverage(pg, o, clip, f, buf, stride, mem, bytes)
                        : rast_triangles_coverage(tris, ntris, o, clip, f, buf, stride, mem, bytes);
    fz_scratch_check(&scratch);
    return st;
}

/* The uint8 values in `out` (stride `stride`) painted into a target of a
 * fuzzed format and fuzzed pixels whose clip is `clip`: the target must
 * become blend_ref of them, its guards and the pixels outside the clip
 * untouched (fz_target's frame). */
static fz_target paint_t;
static unsigned char paint_want[sizeof paint_t.mem], paint_before[sizeof paint_t.mem];
static uint8_t shade_colors[4 * MAXPTS * REPS]; /* a batch may be replicated REPS times */

/* The shaded anti-aliased batch with `rgba` at every vertex, over the
 * pixels of paint_before: the blend of that colour packed, as
 * rast_fill_triangles_aa paints it (paint_want for that value). */
static void shade_check(fz_in *in, const rast_point *tris, uint32_t ntris,
                        const rast_coverage_opts *o, const rast_rect *clip, ptrdiff_t stride)
{
    rast_shade_opts sh;
    unsigned char rgba[4], value[4] = {0, 0, 0, 0};
    int32_t x, y;
    size_t k, need;
    void *mem;
    for (k = 0; k < 4; k++) rgba[k] = (unsigned char)fz_u8(in);
    memset(&sh, 0, sizeof sh);
    sh.precision = fz_u8(in) & 1 ? RAST_PRECISION_FLAT : RAST_PRECISION_EXACT;
    for (k = 0; k < 3 * (size_t)ntris; k++) memcpy(shade_colors + 4 * k, rgba, 4);
    if (paint_t.t.format == RAST_FORMAT_COUNT16) return; /* no colour: test_shaded_aa.c */
    FZ_ASSERT(rast_pack_color(paint_t.t.format, rgba, value) == RAST_OK);
    memcpy(paint_t.mem, paint_before, sizeof paint_before);
    memcpy(paint_want, paint_before, sizeof paint_want);
    for (y = clip->y0; y < clip->y1; y++)
        for (x = clip->x0; x < clip->x1; x++)
            blend_ref(paint_t.t.format,
                      paint_want + ((unsigned char *)paint_t.t.pixels - paint_t.mem) + y * paint_t.t.stride,
                      x, out[(y - clip->y0) * stride + (x - clip->x0)], value);
    FZ_ASSERT(rast_shaded_aa_scratch_size(o, ntris, clip->x1 - clip->x0, clip->y1 - clip->y0,
                                          &need) == RAST_OK);
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    mem = fz_scratch_init(&scratch, need);
    FZ_ASSERT(rast_fill_triangles_shaded_aa(&paint_t.t, tris, ntris, shade_colors, o, &sh, mem,
                                            need) == RAST_OK);
    fz_scratch_check(&scratch);
    FZ_ASSERT(memcmp(paint_t.mem, paint_want, sizeof paint_want) == 0);
}

static void paint_check(fz_in *in, const rast_polygon *pg, const rast_point *tris, uint32_t ntris,
                        int triangles, const rast_coverage_opts *o, const rast_rect *clip,
                        ptrdiff_t stride, size_t need)
{
    rast_format pf = (rast_format)fz_below(in, RAST_FORMAT_COUNT_);
    unsigned char value[4];
    int32_t x, y, row = 0;
    size_t k;
    void *mem;
    rast_status st;
    fz_target_init(&paint_t, clip->x1, clip->y1, pf, clip);
    if (pf == RAST_FORMAT_MONO1) rast_format_stride(pf, clip->x1, &row);
    else row = clip->x1 * paint_t.bpp;
    for (y = 0; y < clip->y1; y++)
        for (x = 0; x < row; x++)
            ((unsigned char *)paint_t.t.pixels)[y * paint_t.t.stride + x] = (unsigned char)fz_u8(in);
    for (k = 0; k < 4; k++) value[k] = (unsigned char)fz_u8(in);
    memcpy(paint_want, paint_t.mem, sizeof paint_want);
    memcpy(paint_before, paint_t.mem, sizeof paint_before);
    for (y = clip->y0; y < clip->y1; y++)
        for (x = clip->x0; x < clip->x1; x++)
            blend_ref(pf, paint_want + ((unsigned char *)paint_t.t.pixels - paint_t.mem) + y * paint_t.t.stride,
                      x, out[(y - clip->y0) * stride + (x - clip->x0)], value);
    mem = fz_scratch_init(&scratch, need);
    st = triangles ? rast_fill_triangles_aa(&paint_t.t, tris, ntris, o, value, mem, need)
                   : rast_fill_polygon_aa(&paint_t.t, pg, o, value, mem, need);
    fz_scratch_check(&scratch);
    FZ_ASSERT(st == RAST_OK);
    FZ_ASSERT(memcmp(paint_t.mem, paint_want, sizeof paint_want) == 0);
    if (triangles) shade_check(in, tris, ntris, o, clip, stride);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point pts[MAXPTS], moved[MAXPTS], *tris = pts;
    uint32_t rings[3], nrings = 0, npts = 0, k, ntris = 0;
    int32_t rx0[4], ry0[4], rx1[4], ry1[4], sg[4], nrect = 0;
    rast_polygon pg;
    rast_coverage_opts o;
    rast_coverage_format f;
    rast_rect clip;
    int32_t cw, ch, x, y, kb, scale, shape = fz_below(&in, 3); /* polygon, rectangles, triangles */
    ptrdiff_t stride;
    size_t need = 0, bytes;
    int short_scratch, scaled_out = 0;
    rast_status st;

    memset(&o, 0, sizeof o);
    o.method = (rast_aa_method)fz_below(&in, RAST_AA_COUNT_);
    o.rule = (rast_fill_rule)fz_below(&in, 2);
    o.subpixel_bits = fz_below(&in, 9);
    o.sample = (rast_sample)fz_below(&in, 2);
    f = (rast_coverage_format)fz_below(&in, 3);
    kb = (o.method >= RAST_AA_SS2 && o.method <= RAST_AA_SS16) ? (int32_t)o.method : 0;
    scale = kb > o.subpixel_bits ? kb - o.subpixel_bits : 0;
    clip.x0 = fz_below(&in, 9) - 4;
    clip.y0 = fz_below(&in, 9) - 4;
    cw = fz_below(&in, CW + 1);
    ch = fz_below(&in, CW + 1);
    if (kb == 4) { /* 256 samples a pixel: keep the reference quick */
        cw = cw > 3 ? 3 : cw;
        ch = ch > 3 ? 3 : ch;
    }
    clip.x1 = clip.x0 + cw;
    clip.y1 = clip.y0 + ch;
    short_scratch = fz_u8(&in) == 0;
    if (shape == 1) { /* rectangles, S <= 3: their area by cells is exact */
        if (o.subpixel_bits > 3) o.subpixel_bits = 3;
        scale = kb > o.subpixel_bits ? kb - o.subpixel_bits : 0;
        nrect = 1 + fz_below(&in, 4);
        for (k = 0; k < (uint32_t)nrect; k++) {
            int32_t g = 1 << o.subpixel_bits;
            int32_t a = fz_below(&in, 16 * g) - 4 * g, b = fz_below(&in, 16 * g) - 4 * g;
            int32_t c = fz_below(&in, 16 * g) - 4 * g, d = fz_below(&in, 16 * g) - 4 * g;
            rx0[k] = a < b ? a : b, rx1[k] = a < b ? b : a;
            ry0[k] = c < d ? c : d, ry1[k] = c < d ? d : c;
            sg[k] = fz_u8(&in) & 1 ? 1 : -1;
            pts[4 * k].x = rx0[k], pts[4 * k].y = ry0[k];
            pts[4 * k + 1].x = sg[k] < 0 ? rx1[k] : rx0[k];
            pts[4 * k + 1].y = sg[k] < 0 ? ry0[k] : ry1[k];
            pts[4 * k + 2].x = rx1[k], pts[4 * k + 2].y = ry1[k];
            pts[4 * k + 3].x = sg[k] < 0 ? rx0[k] : rx1[k];
            pts[4 * k + 3].y = sg[k] < 0 ? ry1[k] : ry0[k];
        }
        nrings = (uint32_t)nrect;
        for (k = 0; k < nrings; k++) rings[k % 3] = 4;
        if (nrings > 3) nrings = 3, nrect = 3;
        npts = 4 * nrings;
    } else if (shape == 0) {
        nrings = (uint32_t)fz_below(&in, 4);
        for (k = 0; k < nrings; k++) {
            rings[k] = (uint32_t)fz_below(&in, MAXPTS / 3 + 1);
            npts += rings[k];
        }
        for (k = 0; k < npts; k++) pts[k] = fz_point(&in, o.subpixel_bits, CW);
    } else {
        ntris = (uint32_t)fz_below(&in, MAXPTS / 3 + 1);
        npts = 3 * ntris;
        for (k = 0; k < npts; k++) pts[k] = fz_point(&in, o.subpixel_bits, CW);
        if (ntris && fz_u8(&in) & 1 && !in.out_of_range) {
            /* copy r of each, (r mod 4) / 8 of the way in to its centre */
            uint32_t reps = (REPS - 1) / ntris + 1, r, t, v;
            for (r = 0; r < reps; r++)
                for (t = 0; t < ntris; t++) {
                    const rast_point *a = &pts[3 * t];
                    int64_t cx = ((int64_t)a[0].x + a[1].x + a[2].x) / 3;
                    int64_t cy = ((int64_t)a[0].y + a[1].y + a[2].y) / 3;
                    for (v = 0; v < 3; v++) {
                        rast_point *q = &many[3 * (r * ntris + t) + v];
                        q->x = (int32_t)(a[v].x + (cx - a[v].x) * (int64_t)(r % 4) / 8);
                        q->y = (int32_t)(a[v].y + (cy - a[v].y) * (int64_t)(r % 4) / 8);
                    }
                }
            tris = many;
            ntris *= reps;
        } else if (ntris >= 4 && fz_u8(&in) & 1 && !in.out_of_range) {
            /* a ladder mesh: columns of two vertices (the points by pairs,
             * sorted by x, the upper one above), each two neighbours a quad
             * cut by one of its diagonals: its inner edges come once each
             * way and cancel, the outline is left */
            uint32_t m = ntris / 2, c, col[MAXPTS], t;
            for (c = 0; c <= m; c++)
                for (t = c, col[c] = c; t > 0 && pts[2 * col[t - 1]].x > pts[2 * c].x; t--) {
                    col[t] = col[t - 1];
                    col[t - 1] = c;
                }
            for (c = 0; c < m; c++) {
                rast_point q[4], *v = &many[6 * c];
                for (t = 0; t < 2; t++) {
                    const rast_point a = pts[2 * col[c + t]], b = pts[2 * col[c + t] + 1];
                    q[t].x = q[3 - t].x = a.x; /* q: upper left, upper right, lower right, lower left */
                    q[t].y = a.y < b.y ? a.y : b.y;
                    q[3 - t].y = a.y < b.y ? b.y : a.y;
                }
                t = fz_u8(&in) & 1;
                v[0] = q[0], v[1] = q[1], v[2] = q[t ? 2 : 3];
                v[3] = q[t ? 0 : 1], v[4] = q[2], v[5] = q[3];
            }
            tris = many;
            ntris = 2 * m;
        }
    }
    for (k = 0; k < (shape == 2 ? 3 * ntris : npts) && scale; k++) { /* the points passed */
        const rast_point p = shape == 2 ? tris[k] : pts[k];
        if (fz_in_range(p) && (p.x > RAST_COORD_MAX >> scale || p.x < -(RAST_COORD_MAX >> scale) ||
                               p.y > RAST_COORD_MAX >> scale || p.y < -(RAST_COORD_MAX >> scale)))
            scaled_out = 1;
    }
    pg.points = pts;
    pg.ring_sizes = rings;
    pg.nrings = nrings;

    FZ_ASSERT(rast_coverage_scratch_size(&o, shape == 2 ? 3 * ntris : npts, cw, ch, &need) ==
              RAST_OK);
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    bytes = short_scratch && need >= 8 ? need - 8 : need;
    stride = (ptrdiff_t)cw * fmt_size[f] + PADB;
    memset(out, FZ_GUARD, sizeof out);
    st = run(shape == 2 ? NULL : &pg, tris, ntris, &o, &clip, f, out, stride, bytes);
    if (in.out_of_range || scaled_out || bytes < need) {
        FZ_ASSERT(st != RAST_OK);
        if (in.out_of_range + scaled_out + (bytes < need) == 1)
            FZ_ASSERT(st == (bytes < need ? RAST_E_SCRATCH : RAST_E_RANGE));
        for (k = 0; k < sizeof out; k++) FZ_ASSERT(out[k] == FZ_GUARD);
        return 0;
    }
    FZ_ASSERT(st == RAST_OK);
    /* the padding after each row and everything after the last: untouched */
    for (y = 0; y < ch; y++)
        for (x = cw * fmt_size[f]; x < stride; x++) FZ_ASSERT(out[y * stride + x] == FZ_GUARD);
    for (k = (uint32_t)(ch * stride); k < sizeof out; k++) FZ_ASSERT(out[k] == FZ_GUARD);

    if (f == RAST_COVERAGE_U8) { /* the spans call: the same values */
        void *mem = fz_scratch_init(&scratch, need);
        memset(&cspans, 0, sizeof cspans);
        cspans.clip = clip;
        cspans.y = INT32_MIN;
        FZ_ASSERT((shape == 2 ? rast_triangles_coverage_spans(tris, ntris, &o, &clip, fz_cspan,
                                                              &cspans, mem, need)
                              : rast_polygon_coverage_spans(&pg, &o, &clip, fz_cspan, &cspans,
                                                            mem, need)) == RAST_OK);
        fz_scratch_check(&scratch);
        for (y = 0; y < ch; y++)
            FZ_ASSERT(memcmp(cspans.img + y * CW, out + y * stride, (size_t)cw) == 0);
    }
    if (f == RAST_COVERAGE_U8 && clip.x0 >= 0 && clip.y0 >= 0) paint_check(&in, &pg, tris, ntris, shape == 2, &o, &clip, stride, need);
    if (kb) { /* the per-sample reference, k times finer */
        const int32_t K = 1 << kb, sf = o.subpixel_bits >= kb ? o.subpixel_bits - kb : 0;
        uint32_t base = 0, t;
        const rast_point *src = shape == 2 ? tris : pts;
        for (k = 0; k < (shape == 2 ? 3 * ntris : npts); k++) {
            fine[k].x = src[k].x * (1 << scale);
            fine[k].y = src[k].y * (1 << scale);
        }
        for (y = 0; y < ch; y++)
            for (x = 0; x < cw; x++) {
                uint32_t count = 0;
                int32_t u, v;
                for (v = 0; v < K; v++)
                    for (u = 0; u < K; u++) {
                        int64_t I = (int64_t)(clip.x0 + x) * K + u, J = (int64_t)(clip.y0 + y) * K + v;
                        int cr, in_ = 0;
                        if (shape == 2) {
                            for (t = 0; t < ntris && !in_; t++) {
                                uint32_t three = 3;
                                in_ = ref_winding(&fine[3 * t], &three, 1, sf, o.sample, 0, I, J, &cr) != 0;
                            }
                        } else {
                            int w = ref_winding(fine, rings, nrings, sf, o.sample, 0, I, J, &cr);
                            in_ = o.rule == RAST_RULE_EVENODD ? (cr & 1) : (w != 0);
                        }
                        count += (uint32_t)in_;
                    }
                FZ_ASSERT(value_at(out, f, stride, x, y) == want_value(count, (uint64_t)K * K, f));
            }
        (void)base;
        return 0;
    }
    if (shape == 1 && (o.method == RAST_AA_AREA || nrect == 1)) { /* exact area by cells */
        const int32_t g = 1 << o.subpixel_bits;
        for (y = 0; y < ch; y++)
            for (x = 0; x < cw; x++) {
                uint32_t cells = 0;
                int32_t u, v, r;
                for (v = (clip.y0 + y) * g; v < (clip.y0 + y + 1) * g; v++)
                    for (u = (clip.x0 + x) * g; u < (clip.x0 + x + 1) * g; u++) {
                        int w = 0;
                        for (r = 0; r < nrect; r++)
                            if (u >= rx0[r] && u < rx1[r] && v >= ry0[r] && v < ry1[r]) w += sg[r];
                        cells += o.rule == RAST_RULE_EVENODD ? (uint32_t)(w & 1) : (w != 0);
                    }
                FZ_ASSERT(value_at(out, f, stride, x, y) == want_value(cells, (uint64_t)g * g, f));
            }
    }
    if (o.method == RAST_AA_AREA && f != RAST_COVERAGE_FIX62) {
        /* the levels against the 2^-62 fixed point, which never takes the
         * accumulation's rows (simple rows, fast rows): floor(a M + 1/2)
         * of it, or one off where a M + 1/2 is within the bound of an
         * integer (the fixed point is within (n + m + 1) 2^-58 of a, n the
         * edges, m their crossings: at most n (n - 1) / 2) */
        const ptrdiff_t s62 = (ptrdiff_t)cw * 8 + PADB;
        const uint64_t M = f == RAST_COVERAGE_U8 ? 255 : 65535;
        const uint64_t n = shape == 2 ? 3 * (uint64_t)ntris : npts;
        const uint64_t win = ((n + n * (n - 1) / 2 + 1) * M >> 12) + 2; /* 2^-46 level units */
        memset(out2, FZ_GUARD, sizeof out2);
        FZ_ASSERT(run(shape == 2 ? NULL : &pg, tris, ntris, &o, &clip, RAST_COVERAGE_FIX62, out2, s62,
                      FZ_SCRATCH_MAX) == RAST_OK);
        for (y = 0; y < ch; y++)
            for (x = 0; x < cw; x++) {
                const uint64_t a = value_at(out2, RAST_COVERAGE_FIX62, s62, x, y);
                /* a M + 1/2 in 2^-46 level units (a < 2^63: no overflow) */
                const uint64_t v = (a >> 16) * M + (((a & 0xFFFF) * M) >> 16) + ((uint64_t)1 << 45);
                const uint64_t lev = v >> 46, fr = v & (((uint64_t)1 << 46) - 1);
                const uint64_t got = value_at(out, f, stride, x, y);
                if (got != lev)
                    FZ_ASSERT((got + 1 == lev && fr < win) ||
                              (got == lev + 1 && fr > ((uint64_t)1 << 46) - win));
            }
    }
    if (o.method == RAST_AA_AREA && shape != 2) {
        /* translated by whole pixels: the same values */
        int32_t tx = fz_below(&in, 64) - 32, ty = fz_below(&in, 64) - 32, ok = 1;
        rast_rect c2 = {clip.x0 + tx, clip.y0 + ty, clip.x1 + tx, clip.y1 + ty};
        rast_polygon p2 = pg;
        for (k = 0; k < npts; k++) {
            moved[k].x = pts[k].x + tx * (1 << o.subpixel_bits);
            moved[k].y = pts[k].y + ty * (1 << o.subpixel_bits);
            if (!fz_in_range(moved[k])) ok = 0;
        }
        if (ok) {
            p2.points = moved;
            memset(out2, FZ_GUARD, sizeof out2);
            FZ_ASSERT(run(&p2, NULL, 0, &o, &c2, f, out2, stride, need) == RAST_OK);
            FZ_ASSERT(memcmp(out, out2, sizeof out) == 0);
        }
        if (o.rule == RAST_RULE_EVENODD) { /* rings reversed */
            uint32_t b = 0, r;
            for (r = 0; r < nrings; b += rings[r], r++)
                for (k = 0; k < rings[r]; k++) moved[b + k] = pts[b + rings[r] - 1 - k];
            p2.points = moved;
            memset(out2, FZ_GUARD, sizeof out2);
            FZ_ASSERT(run(&p2, NULL, 0, &o, &clip, f, out2, stride, need) == RAST_OK);
            FZ_ASSERT(memcmp(out, out2, sizeof out) == 0);
        }
    }
    return 0;
}

/*
 * fuzz_shade.c - the shading entry points: rast_fill_triangles_shaded
 * (exact, fixed, flat; with and without depth), rast_fill_rect_gouraud,
 * rast_fill_polygon_gouraud, and rast_pack_color / rast_format_stride, in
 * every format (RGB565 and MONO1 included) and clip.
 *
 * Oracles:
 *  - errors exactly for bad input (the statuses the header lists), with
 *    nothing written: target, zbuf and the bytes after the scratch as
 *    before;
 *  - the pixel set: every vertex in one colour K, the shaded call writes
 *    exactly the bytes the unshaded fill (rast_fill_triangles,
 *    rast_fill_polygon) writes with rast_pack_color(K) - for every
 *    precision (a constant plane is constant, also stepped);
 *  - exact and flat colours (and depth, and the depth test) equal a slow
 *    reference computed here pixel by pixel: the barycentric sum of the
 *    header with 128-bit numerators (__int128: coordinates anywhere in
 *    range, depths any int32_t), floor(v + 1/2), clamped; the bilinear sum
 *    for rectangles; for a polygon of one ring of three vertices the same
 *    barycentric value (the header's triangle == plane identity); for other
 *    polygons the pixel set only;
 *  - fixed point (not exact by contract): only the pixels of the set
 *    change, and with depth zbuf only decreases there.
 */
#include "fuzz.h"

__extension__ typedef __int128 fz_i128;

#define MAXTRIS 6
#define MAXPTS 10

static fz_target ft, ft2, ft3;
static unsigned char expect[sizeof ft.mem];
static fz_scratch scratch;
static int32_t zbuf[FZ_MAXDIM * FZ_MAXDIM], zbuf0[FZ_MAXDIM * FZ_MAXDIM], zwant[FZ_MAXDIM * FZ_MAXDIM];
static unsigned char inset[FZ_MAXDIM * FZ_MAXDIM];
static const uint8_t K[4] = {0xC3, 0x5A, 0x96, 0x3C};

/* Put a packed pixel at (x, y) of a copy of ft's memory. */
static void put(const fz_target *t, unsigned char *mem, int32_t x, int32_t y, const unsigned char *px)
{
    if (t->t.format == RAST_FORMAT_MONO1) {
        unsigned char *b = mem + ((const unsigned char *)t->t.pixels - t->mem) +
                           (ptrdiff_t)y * t->stride + x / 8;
        unsigned char bit = (unsigned char)(0x80u >> (x % 8));
        *b = (unsigned char)(px[0] ? (*b | bit) : (*b & ~bit));
        return;
    }
    memcpy(mem + (fz_px((fz_target *)t, x, y) - t->mem), px, (size_t)t->bpp);
}

/* floor(num / den + 1/2), den != 0 */
static int64_t round_div(fz_i128 num, fz_i128 den)
{
    fz_i128 n2, d2, q;
    if (den < 0) {
        num = -num;
        den = -den;
    }
    n2 = 2 * num + den;
    d2 = 2 * den;
    q = n2 / d2;
    if (n2 % d2 < 0) q--;
    if (q > INT64_MAX / 2) return INT64_MAX / 2;
    if (q < INT64_MIN / 2) return INT64_MIN / 2;
    return (int64_t)q;
}

static int64_t clamp(int64_t v, int64_t lo, int64_t hi) { return v < lo ? lo : v > hi ? hi : v; }

/* The plane through t[0..2] with values c[0..2] at the sample of (i, j):
 * the header's barycentric sum, doubled coordinates; vertex 0's value for
 * a degenerate triangle. */
static int64_t ref_plane(const rast_point *t, const int64_t *c, int s, int center, int64_t i, int64_t j)
{
    int64_t unit = (int64_t)2 << s, off = center ? ((int64_t)1 << s) : 0;
    int64_t px = i * unit + off, py = j * unit + off;
    int64_t x[3], y[3], w[3];
    int m;
    for (m = 0; m < 3; m++) {
        x[m] = 2 * (int64_t)t[m].x;
        y[m] = 2 * (int64_t)t[m].y;
    }
    w[0] = (x[1] - px) * (y[2] - py) - (y[1] - py) * (x[2] - px);
    w[1] = (px - x[0]) * (y[2] - y[0]) - (py - y[0]) * (x[2] - x[0]);
    w[2] = (x[1] - x[0]) * (py - y[0]) - (y[1] - y[0]) * (px - x[0]);
    if (w[0] + w[1] + w[2] == 0) return c[0];
    return round_div((fz_i128)w[0] * c[0] + (fz_i128)w[1] * c[1] + (fz_i128)w[2] * c[2],
                     (fz_i128)w[0] + w[1] + w[2]);
}

static void ref_color(const rast_point *t, const uint8_t *col, int flat, int s, int center, int64_t i,
                      int64_t j, uint8_t *rgba)
{
    int ch;
    for (ch = 0; ch < 4; ch++) {
        int64_t c[3];
        c[0] = col[ch];
        c[1] = col[4 + ch];
        c[2] = col[8 + ch];
        rgba[ch] = (uint8_t)(flat ? c[0] : clamp(ref_plane(t, c, s, center, i, j), 0, 255));
    }
}

/* rast_pack_color from its header comment */
static void ref_pack(rast_format f, const uint8_t *c, unsigned char *px)
{
    uint16_t v;
    switch (f) {
    case RAST_FORMAT_GRAY8: px[0] = c[0]; break;
    case RAST_FORMAT_RGB888: memcpy(px, c, 3); break;
    case RAST_FORMAT_RGBA8888: memcpy(px, c, 4); break;
    case RAST_FORMAT_RGB565:
        v = (uint16_t)((c[0] >> 3) << 11 | (c[1] >> 2) << 5 | c[2] >> 3);
        memcpy(px, &v, 2);
        break;
    default: px[0] = c[0] >= 128; break;
    }
}

static int owns(const rast_point *pts, uint32_t npts, const rast_fill_opts *fo, int64_t i, int64_t j)
{
    rast_polygon pg;
    pg.points = pts;
    pg.ring_sizes = &npts;
    pg.nrings = 1;
    return fz_ref_polygon(&pg, fo, i, j);
}

/* Target as the unshaded fill with K leaves it, vs the shaded one. */
static void same_as_plain(const fz_target *a, const fz_target *b) { FZ_ASSERT(memcmp(a->mem, b->mem, sizeof a->mem) == 0); }

/* Fixed point: bytes change only at pixels of `inset`. */
static void only_inset(void)
{
    int32_t x, y;
    memcpy(expect, ft.before, sizeof expect);
    for (y = ft.cut.y0; y < ft.cut.y1; y++)
        for (x = ft.cut.x0; x < ft.cut.x1; x++)
            if (inset[y * ft.w + x]) {
                unsigned char px[4];
                if (ft.t.format == RAST_FORMAT_MONO1) {
                    const unsigned char *p = (const unsigned char *)ft.t.pixels + (ptrdiff_t)y * ft.stride + x / 8;
                    px[0] = (unsigned char)((*p >> (7 - x % 8)) & 1);
                } else
                    memcpy(px, fz_px(&ft, x, y), (size_t)ft.bpp);
                put(&ft, expect, x, y, px);
            }
    FZ_ASSERT(memcmp(expect, ft.mem, sizeof expect) == 0);
}

static void decode_tri_opts(fz_in *in, rast_tri_opts *o, rast_fill_opts *fo)
{
    *fo = fz_fill_opts(in);
    memset(o, 0, sizeof *o);
    o->algorithm = (rast_tri_algorithm)fz_below(in, RAST_TRI_COUNT_);
    o->subpixel_bits = fo->subpixel_bits;
    o->sample = fo->sample;
    o->rounding = fo->rounding;
    o->boundary = fo->boundary;
    fo->rule = RAST_RULE_NONZERO;
}

static rast_shade_opts decode_shade(fz_in *in, int *bad)
{
    rast_shade_opts sh;
    uint32_t m = fz_u8(in);
    sh.precision = (rast_precision)(m < 8 ? 3 + (int)m : (int)(m % 3)); /* rarely unknown */
    sh.fraction_bits = fz_below(in, 18);                              /* 0 and 17: bad */
    *bad = sh.precision > RAST_PRECISION_FLAT ||
           (sh.precision == RAST_PRECISION_FIXED && (sh.fraction_bits < 1 || sh.fraction_bits > 16));
    return sh;
}

static void fuzz_triangles(fz_in *in, int32_t w, int32_t h, rast_format f, const rast_rect *clip)
{
    rast_point tris[3 * MAXTRIS];
    uint8_t colors[12 * MAXTRIS], kcol[12 * MAXTRIS];
    int32_t z[3 * MAXTRIS];
    rast_tri_opts o;
    rast_fill_opts fo;
    rast_shade_opts sh;
    uint32_t n, k;
    int depth, bad_shade, short_scratch, one_null, s, center, flat, exact;
    size_t need = 0, bytes;
    int32_t x, y;
    unsigned char kpx[4];
    rast_status st;
    void *mem;

    decode_tri_opts(in, &o, &fo);
    sh = decode_shade(in, &bad_shade);
    depth = fz_below(in, 2);
    one_null = depth && fz_u8(in) == 0;
    short_scratch = fz_u8(in) == 0;
    n = (uint32_t)fz_below(in, MAXTRIS + 1);
    for (k = 0; k < 3 * n; k++) tris[k] = fz_point(in, o.subpixel_bits, w > h ? w : h);
    for (k = 0; k < 12 * n; k++) colors[k] = (uint8_t)fz_u8(in);
    for (k = 0; k < 3 * n; k++) z[k] = fz_u8(in) < 200 ? (int32_t)fz_u16(in) - 32768 : (int32_t)fz_u32(in);
    for (k = 0; k < (uint32_t)(w * h); k++)
        zbuf[k] = fz_u8(in) < 128 ? INT32_MAX : (int32_t)fz_u16(in) - 32768;
    memcpy(zbuf0, zbuf, sizeof zbuf);

    fz_target_init(&ft, w, h, f, clip);
    FZ_ASSERT(rast_tri_scratch_size(&o, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) == RAST_OK);
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    bytes = short_scratch && need >= 8 ? need - 8 : need;
    mem = fz_scratch_init(&scratch, bytes);
    st = rast_fill_triangles_shaded(&ft.t, tris, n, colors, depth ? z : NULL,
                                    depth && !one_null ? zbuf : NULL, &o, &sh, mem, bytes);
    fz_scratch_check(&scratch);
    if (in->out_of_range || bytes < need || bad_shade || one_null || f == RAST_FORMAT_COUNT16) {
        FZ_ASSERT(st != RAST_OK);
        FZ_ASSERT((in->out_of_range && st == RAST_E_RANGE) || (bytes < need && st == RAST_E_SCRATCH) ||
                  (bad_shade && st == RAST_E_ARG) || (one_null && st == RAST_E_NULL) ||
                  (f == RAST_FORMAT_COUNT16 && st == RAST_E_FORMAT));
        FZ_ASSERT(fz_untouched(&ft));
        FZ_ASSERT(memcmp(zbuf, zbuf0, sizeof zbuf) == 0);
        return;
    }
    FZ_ASSERT(st == RAST_OK);

    /* the pixel set: one colour K everywhere, no depth, == the plain fill */
    for (k = 0; k < 3 * n; k++) memcpy(kcol + 4 * k, K, 4);
    FZ_ASSERT(rast_pack_color(f, K, kpx) == RAST_OK);
    fz_target_init(&ft2, w, h, f, clip);
    fz_target_init(&ft3, w, h, f, clip);
    FZ_ASSERT(rast_fill_triangles_shaded(&ft2.t, tris, n, kcol, NULL, NULL, &o, &sh, scratch.mem, need) ==
              RAST_OK);
    FZ_ASSERT(rast_fill_triangles(&ft3.t, tris, n, &o, kpx, scratch.mem, need) == RAST_OK);
    same_as_plain(&ft2, &ft3);

    /* the reference, triangle by triangle in order */
    s = o.subpixel_bits;
    center = o.sample == RAST_SAMPLE_CENTER;
    flat = sh.precision == RAST_PRECISION_FLAT;
    exact = sh.precision != RAST_PRECISION_FIXED;
    memcpy(expect, ft.before, sizeof expect);
    memcpy(zwant, zbuf0, sizeof zwant);
    memset(inset, 0, sizeof inset);
    for (y = ft.cut.y0; y < ft.cut.y1; y++)
        for (x = ft.cut.x0; x < ft.cut.x1; x++)
            for (k = 0; k < n; k++) {
                uint8_t rgba[4];
                unsigned char px[4];
                if (!owns(tris + 3 * k, 3, &fo, x, y)) continue;
                inset[y * w + x] = 1;
                if (depth) {
                    int64_t zc[3];
                    int64_t zv;
                    zc[0] = z[3 * k];
                    zc[1] = z[3 * k + 1];
                    zc[2] = z[3 * k + 2];
                    zv = clamp(ref_plane(tris + 3 * k, zc, s, center, x, y), INT32_MIN, INT32_MAX);
                    if (!(zv < zwant[y * w + x])) continue;
                    zwant[y * w + x] = (int32_t)zv;
                }
                ref_color(tris + 3 * k, colors + 12 * k, flat, s, center, x, y, rgba);
                ref_pack(f, rgba, px);
                put(&ft, expect, x, y, px);
            }
    if (exact) {
        FZ_ASSERT(memcmp(expect, ft.mem, sizeof expect) == 0);
        FZ_ASSERT(memcmp(zwant, zbuf, sizeof zbuf) == 0);
        return;
    }
    only_inset();
    for (k = 0; k < (uint32_t)(w * h); k++)
        FZ_ASSERT(depth ? (zbuf[k] == zbuf0[k] || (inset[k] && zbuf[k] < zbuf0[k])) : zbuf[k] == zbuf0[k]);
}

static void fuzz_rect(fz_in *in, int32_t w, int32_t h, rast_format f, const rast_rect *clip)
{
    rast_tri_opts o;
    rast_fill_opts fo;
    rast_shade_opts sh;
    rast_point p[2], ring[4];
    uint8_t colors[16], rgba[4];
    unsigned char px[4];
    int bad_shade, bad, s, center, ch;
    int32_t x, y;
    int64_t X0, Y0, X1, Y1, unit, off;
    rast_status st;
    uint32_t k;

    decode_tri_opts(in, &o, &fo);
    if (fz_u8(in) < 192) o.boundary = fo.boundary = RAST_BOUNDARY_EXACT;
    sh = decode_shade(in, &bad_shade);
    p[0] = fz_point(in, o.subpixel_bits, w > h ? w : h);
    p[1] = fz_point(in, o.subpixel_bits, w > h ? w : h);
    for (k = 0; k < 16; k++) colors[k] = (uint8_t)fz_u8(in);
    bad = !in->out_of_range &&
          ((int64_t)p[1].x - p[0].x > RAST_GOURAUD_RECT_MAX_SIZE ||
           (int64_t)p[0].x - p[1].x > RAST_GOURAUD_RECT_MAX_SIZE ||
           (int64_t)p[1].y - p[0].y > RAST_GOURAUD_RECT_MAX_SIZE ||
           (int64_t)p[0].y - p[1].y > RAST_GOURAUD_RECT_MAX_SIZE);

    fz_target_init(&ft, w, h, f, clip);
    st = rast_fill_rect_gouraud(&ft.t, p[0], p[1], colors, &o, &sh);
    if (in->out_of_range || bad || bad_shade || o.boundary != RAST_BOUNDARY_EXACT ||
        f == RAST_FORMAT_COUNT16) {
        FZ_ASSERT(st != RAST_OK);
        FZ_ASSERT(((in->out_of_range || bad) && st == RAST_E_RANGE) ||
                  ((bad_shade || o.boundary != RAST_BOUNDARY_EXACT) && st == RAST_E_ARG) ||
                  (f == RAST_FORMAT_COUNT16 && st == RAST_E_FORMAT));
        FZ_ASSERT(fz_untouched(&ft));
        return;
    }
    FZ_ASSERT(st == RAST_OK);

    ring[0] = p[0];
    ring[1].x = p[1].x;
    ring[1].y = p[0].y;
    ring[2] = p[1];
    ring[3].x = p[0].x;
    ring[3].y = p[1].y;
    s = o.subpixel_bits;
    center = o.sample == RAST_SAMPLE_CENTER;
    unit = (int64_t)2 << s;
    off = center ? ((int64_t)1 << s) : 0;
    X0 = 2 * (int64_t)p[0].x, Y0 = 2 * (int64_t)p[0].y, X1 = 2 * (int64_t)p[1].x, Y1 = 2 * (int64_t)p[1].y;
    memcpy(expect, ft.before, sizeof expect);
    memset(inset, 0, sizeof inset);
    for (y = ft.cut.y0; y < ft.cut.y1; y++)
        for (x = ft.cut.x0; x < ft.cut.x1; x++) {
            int64_t xs = x * unit + off, ys = y * unit + off;
            if (!owns(ring, 4, &fo, x, y)) continue;
            inset[y * w + x] = 1;
            for (ch = 0; ch < 4; ch++) {
                fz_i128 num = (fz_i128)(X1 - xs) * (Y1 - ys) * colors[ch] +
                              (fz_i128)(xs - X0) * (Y1 - ys) * colors[4 + ch] +
                              (fz_i128)(xs - X0) * (ys - Y0) * colors[8 + ch] +
                              (fz_i128)(X1 - xs) * (ys - Y0) * colors[12 + ch];
                rgba[ch] = (uint8_t)(sh.precision == RAST_PRECISION_FLAT
                                         ? colors[ch]
                                         : clamp(round_div(num, (fz_i128)(X1 - X0) * (Y1 - Y0)), 0, 255));
            }
            ref_pack(f, rgba, px);
            put(&ft, expect, x, y, px);
        }
    if (sh.precision != RAST_PRECISION_FIXED) {
        FZ_ASSERT(memcmp(expect, ft.mem, sizeof expect) == 0);
    } else
        only_inset();
    /* one colour: exactly the set, any precision */
    FZ_ASSERT(rast_pack_color(f, K, px) == RAST_OK);
    memcpy(colors, K, 4), memcpy(colors + 4, K, 4), memcpy(colors + 8, K, 4), memcpy(colors + 12, K, 4);
    fz_target_init(&ft2, w, h, f, clip);
    FZ_ASSERT(rast_fill_rect_gouraud(&ft2.t, p[0], p[1], colors, &o, &sh) == RAST_OK);
    memcpy(expect, ft2.before, sizeof expect);
    for (y = ft.cut.y0; y < ft.cut.y1; y++)
        for (x = ft.cut.x0; x < ft.cut.x1; x++)
            if (inset[y * w + x]) put(&ft2, expect, x, y, px);
    FZ_ASSERT(memcmp(expect, ft2.mem, sizeof expect) == 0);
}

static void fuzz_polygon(fz_in *in, int32_t w, int32_t h, rast_format f, const rast_rect *clip)
{
    rast_point pts[MAXPTS];
    uint32_t sizes[3], nrings, npts = 0, k;
    uint8_t colors[4 * MAXPTS], kcol[4 * MAXPTS];
    rast_fill_opts o;
    rast_shade_opts sh;
    rast_polygon pg;
    int bad_shade, short_scratch, s, center;
    size_t need = 0, bytes;
    int32_t x, y;
    unsigned char kpx[4];
    rast_status st;
    void *mem;

    o = fz_fill_opts(in);
    if (fz_u8(in) < 200) o.algorithm = RAST_ALGO_AET;
    if (fz_u8(in) < 200) o.boundary = RAST_BOUNDARY_EXACT;
    sh = decode_shade(in, &bad_shade);
    if (sh.precision == RAST_PRECISION_FIXED && fz_u8(in) < 200) sh.precision = RAST_PRECISION_EXACT;
    bad_shade = sh.precision > RAST_PRECISION_FLAT || sh.precision == RAST_PRECISION_FIXED;
    short_scratch = fz_u8(in) == 0;
    nrings = (uint32_t)fz_below(in, 4);
    if (nrings == 0 && fz_u8(in) < 250) nrings = 1;
    if (nrings == 3) nrings = 1; /* mostly one ring */
    for (k = 0; k < nrings; k++) {
        sizes[k] = (uint32_t)fz_below(in, MAXPTS / 2 + 1);
        if (fz_u8(in) < 128) sizes[k] = 3;
        npts += sizes[k];
    }
    for (k = 0; k < npts; k++) pts[k] = fz_point(in, o.subpixel_bits, w > h ? w : h);
    for (k = 0; k < 4 * npts; k++) colors[k] = (uint8_t)fz_u8(in);
    pg.points = pts;
    pg.ring_sizes = sizes;
    pg.nrings = nrings;

    fz_target_init(&ft, w, h, f, clip);
    FZ_ASSERT(rast_polygon_gouraud_scratch_size(npts, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &need) ==
              RAST_OK);
    FZ_ASSERT(need <= FZ_SCRATCH_MAX);
    bytes = short_scratch && need >= 8 ? need - 8 : need;
    mem = fz_scratch_init(&scratch, bytes);
    st = rast_fill_polygon_gouraud(&ft.t, &pg, colors, &o, &sh, mem, bytes);

    fz_scratch_check(&scratch);
    if (in->out_of_range || bytes < need || bad_shade || o.algorithm != RAST_ALGO_AET ||
        o.boundary != RAST_BOUNDARY_EXACT || f == RAST_FORMAT_COUNT16) {
        FZ_ASSERT(st != RAST_OK);
        FZ_ASSERT((in->out_of_range && st == RAST_E_RANGE) || (bytes < need && st == RAST_E_SCRATCH) ||
                  ((bad_shade || o.boundary != RAST_BOUNDARY_EXACT) && st == RAST_E_ARG) ||
                  (o.algorithm != RAST_ALGO_AET && st == RAST_E_ALGORITHM) ||
                  (f == RAST_FORMAT_COUNT16 && st == RAST_E_FORMAT));
        FZ_ASSERT(fz_untouched(&ft));
        return;
    }
    FZ_ASSERT(st == RAST_OK);

    /* the pixel set: one colour K, == rast_fill_polygon with K packed */
    for (k = 0; k < npts; k++) memcpy(kcol + 4 * k, K, 4);
    FZ_ASSERT(rast_pack_color(f, K, kpx) == RAST_OK);
    fz_target_init(&ft2, w, h, f, clip);
    fz_target_init(&ft3, w, h, f, clip);
    FZ_ASSERT(rast_fill_polygon_gouraud(&ft2.t, &pg, kcol, &o, &sh, scratch.mem, need) == RAST_OK);
    {
        size_t pneed = 0;
        FZ_ASSERT(rast_scratch_size(&o, npts, ft.cut.x1 - ft.cut.x0, ft.cut.y1 - ft.cut.y0, &pneed) == RAST_OK);
        FZ_ASSERT(pneed <= FZ_SCRATCH_MAX);
        FZ_ASSERT(rast_fill_polygon(&ft3.t, &pg, &o, kpx, scratch.mem, pneed) == RAST_OK);
    }
    same_as_plain(&ft2, &ft3);

    /* the colours: flat everywhere; exact for a triangle (the plane) */
    if (!(sh.precision == RAST_PRECISION_FLAT || (nrings == 1 && npts == 3))) return;
    s = o.subpixel_bits;
    center = o.sample == RAST_SAMPLE_CENTER;
    memcpy(expect, ft.before, sizeof expect);
    for (y = ft.cut.y0; y < ft.cut.y1; y++)
        for (x = ft.cut.x0; x < ft.cut.x1; x++) {
            uint8_t rgba[4];
            unsigned char px[4];
            if (!fz_ref_polygon(&pg, &o, x, y)) continue;
            if (sh.precision == RAST_PRECISION_FLAT)
                memcpy(rgba, colors, 4);
            else
                ref_color(pts, colors, 0, s, center, x, y, rgba);
            ref_pack(f, rgba, px);
            put(&ft, expect, x, y, px);
        }
    FZ_ASSERT(memcmp(expect, ft.mem, sizeof expect) == 0);
}

static void fuzz_pack(fz_in *in)
{
    int32_t v = fz_u8(in) < 240 ? fz_below(in, RAST_FORMAT_COUNT_ + 1) : (int32_t)fz_u32(in);
    int32_t width = fz_u8(in) < 200 ? fz_below(in, 100) : (int32_t)fz_u32(in), bytes = -7, bpp = 0;
    uint8_t c[4];
    unsigned char got[8], want[4];
    int k, known = (unsigned)v < RAST_FORMAT_COUNT_;
    rast_status st;
    for (k = 0; k < 4; k++) c[k] = (uint8_t)fz_u8(in);
    memset(got, 0xEE, sizeof got);
    st = rast_pack_color((rast_format)v, c, got);
    if (!known || v == RAST_FORMAT_COUNT16) {
        FZ_ASSERT(st == RAST_E_FORMAT);
        for (k = 0; k < 8; k++) FZ_ASSERT(got[k] == 0xEE);
    } else {
        FZ_ASSERT(st == RAST_OK);
        FZ_ASSERT(rast_format_bytes((rast_format)v, &bpp) == RAST_OK);
        ref_pack((rast_format)v, c, want);
        if (v == RAST_FORMAT_MONO1)
            FZ_ASSERT((got[0] != 0) == (want[0] != 0));
        else
            FZ_ASSERT(memcmp(got, want, (size_t)bpp) == 0);
        for (k = bpp; k < 8; k++) FZ_ASSERT(got[k] == 0xEE);
    }
    FZ_ASSERT(rast_pack_color((rast_format)v, NULL, got) == (known ? RAST_E_NULL : RAST_E_FORMAT) ||
              rast_pack_color((rast_format)v, NULL, got) == RAST_E_NULL ||
              rast_pack_color((rast_format)v, NULL, got) == RAST_E_FORMAT);
    st = rast_format_stride((rast_format)v, width, &bytes);
    if (!known) {
        FZ_ASSERT(st == RAST_E_FORMAT && bytes == -7);
    } else if (width < 0 || width > RAST_MAX_DIM) {
        FZ_ASSERT(st == RAST_E_SIZE && bytes == -7);
    } else {
        int64_t want_b;
        FZ_ASSERT(rast_format_bytes((rast_format)v, &bpp) == RAST_OK);
        want_b = v == RAST_FORMAT_MONO1 ? ((int64_t)width + 7) / 8 : (int64_t)width * bpp;
        if (want_b > INT32_MAX)
            FZ_ASSERT(st == RAST_E_SIZE && bytes == -7);
        else
            FZ_ASSERT(st == RAST_OK && bytes == want_b);
    }
    FZ_ASSERT(rast_format_stride((rast_format)v, width, NULL) == RAST_E_NULL ||
              (!known && rast_format_stride((rast_format)v, width, NULL) == RAST_E_FORMAT));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    int32_t entry = fz_below(&in, 4), w, h;
    rast_format f;
    rast_rect clip;
    if (entry == 3) {
        fuzz_pack(&in);
        return 0;
    }
    w = 1 + fz_below(&in, FZ_MAXDIM);
    h = 1 + fz_below(&in, FZ_MAXDIM);
    f = (rast_format)fz_below(&in, RAST_FORMAT_COUNT_);
    clip = fz_clip(&in, w, h);
    if (entry == 0)
        fuzz_triangles(&in, w, h, f, &clip);
    else if (entry == 1)
        fuzz_rect(&in, w, h, f, &clip);
    else
        fuzz_polygon(&in, w, h, f, &clip);
    return 0;
}

/*
 * fuzz_coverage64.c - rast_polygon_coverage64 (exact-area coverage on
 * 64-bit vertices), both rules, S = 0..32, windows anywhere in the
 * 2^28-pixel plane.  Oracles, each independent of coverage64.c:
 *  - exact area in 128 bits: for one ring that is simple (no two edges
 *    meet but neighbours at their shared vertex, decided by exact integer
 *    orientations), the cells' sum over a window holding it is |shoelace|/2,
 *    computed exactly, within the cells' count times the bound of rastrum.h,
 *    (n + m + 1) 2^-50 per cell;
 *  - the 32-bit exact-area path (coverage_area.c, written separately): at
 *    S0 <= 16 with small coordinates rast_polygon_coverage and
 *    rast_polygon_coverage64 agree within the sum of their bounds;
 *  - scale: the vertices times 2^k at S0 + k (the same polygon) give the
 *    same areas within twice the bound;
 *  - translation: the polygon and the window moved by whole pixels (up to
 *    near +-2^28) give the same values bit for bit;
 *  - every value in [0, 2^62]; uint8 and uint16 are floor(a' M + 1/2) of
 *    the FIX62 value a'; nothing outside the clip or after the scratch is
 *    written; a vertex past RAST_COORD64_MAX(S) is RAST_E_RANGE and writes
 *    nothing.
 */
#include "fuzz.h"

#define MAXPTS 16
#define WIN 12

static fz_scratch scratch;
static uint64_t a32[WIN][WIN], b64[WIN][WIN], c64[WIN][WIN], d64[WIN + 2][WIN + 2];
static uint8_t u8[WIN][WIN];
static uint16_t u16[WIN][WIN];

/* 128-bit signed helpers, here written out again (independent of wide.h) */
typedef struct {
    int64_t hi;
    uint64_t lo;
} i128;

static i128 mul(int64_t a, int64_t b)
{
    __extension__ typedef __int128 s128;
    s128 p = (s128)a * b;
    i128 r;
    r.lo = (uint64_t)p;
    r.hi = (int64_t)(p >> 64);
    return r;
}

static __int128 as(i128 v)
{
    return (__int128)(((unsigned __int128)(uint64_t)v.hi << 64) | v.lo);
}

/* sign of the orientation (b - a) x (c - a) */
static int orient(rast_point64 a, rast_point64 b, rast_point64 c)
{
    __int128 v = as(mul(b.x - a.x, c.y - a.y)) - as(mul(b.y - a.y, c.x - a.x));
    return (v > 0) - (v < 0);
}

static int on_segment(rast_point64 a, rast_point64 b, rast_point64 p)
{
    return (p.x >= (a.x < b.x ? a.x : b.x)) && (p.x <= (a.x > b.x ? a.x : b.x)) &&
           (p.y >= (a.y < b.y ? a.y : b.y)) && (p.y <= (a.y > b.y ? a.y : b.y));
}

static int segs_meet(rast_point64 a, rast_point64 b, rast_point64 c, rast_point64 d)
{
    int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) {
        if (o1 && o2 && o3 && o4) return 1;
    }
    if (!o1 && on_segment(a, b, c)) return 1;
    if (!o2 && on_segment(a, b, d)) return 1;
    if (!o3 && on_segment(c, d, a)) return 1;
    if (!o4 && on_segment(c, d, b)) return 1;
    return o1 * o2 < 0 && o3 * o4 < 0;
}

/* A ring of n >= 3 vertices is simple: no repeated vertex, no two edges
 * meet except neighbours at their shared vertex (and those only there). */
static int simple_ring(const rast_point64 *p, uint32_t n)
{
    uint32_t i, j;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (p[i].x == p[j].x && p[i].y == p[j].y) return 0;
    for (i = 0; i < n; i++) {
        rast_point64 a = p[i], b = p[(i + 1) % n];
        for (j = i + 1; j < n; j++) {
            rast_point64 c = p[j], d = p[(j + 1) % n];
            if (j == i + 1 || (i == 0 && j == n - 1)) {
                /* neighbours: meeting anywhere but the shared vertex means
                 * they overlap (collinear, folding back) */
                rast_point64 shared = j == i + 1 ? b : a, other1 = j == i + 1 ? a : b,
                             other2 = j == i + 1 ? d : c;
                if (orient(shared, other1, other2) == 0 &&
                    (on_segment(shared, other1, other2) || on_segment(shared, other2, other1)))
                    return 0;
                continue;
            }
            if (segs_meet(a, b, c, d)) return 0;
        }
    }
    return 1;
}

static rast_status cov64(const rast_point64 *pts, const uint32_t *sizes, uint32_t nrings, int s,
                         rast_fill_rule rule, rast_rect clip, rast_coverage_format f, void *out,
                         ptrdiff_t stride)
{
    rast_polygon64 poly;
    rast_coverage_opts o;
    size_t need;
    void *sc;
    rast_status st;
    memset(&o, 0, sizeof o);
    o.method = RAST_AA_AREA;
    o.rule = rule;
    o.subpixel_bits = s;
    poly.points = pts;
    poly.ring_sizes = sizes;
    poly.nrings = nrings;
    FZ_ASSERT(rast_coverage64_scratch_size(&o, 40, clip.x1 - clip.x0, clip.y1 - clip.y0, &need) ==
              RAST_OK);
    sc = fz_scratch_init(&scratch, need);
    st = rast_polygon_coverage64(&poly, &o, &clip, f, out, stride, sc, need);
    fz_scratch_check(&scratch);
    return st;
}

static uint64_t absdiff(uint64_t a, uint64_t b)
{
    return a > b ? a - b : b - a;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_point64 p0[MAXPTS], pk[MAXPTS], pm[MAXPTS];
    rast_point pts32[MAXPTS];
    uint32_t sizes[3], nrings, npts = 0, i, j, k;
    int s0 = (int)(fz_u8(&in) % 17), kk, s1;
    rast_fill_rule rule = (fz_u8(&in) & 1) ? RAST_RULE_NONZERO : RAST_RULE_EVENODD;
    int32_t w = 1 + fz_below(&in, WIN), h = 1 + fz_below(&in, WIN);
    rast_rect clip = {0, 0, 0, 0};
    int64_t n_edges, bound, mx, my, unit0 = (int64_t)1 << s0;
    rast_coverage_opts o;
    rast_polygon poly32;
    size_t need;
    void *sc;

    clip.x1 = w;
    clip.y1 = h;
    nrings = 1 + fz_u8(&in) % 3;
    for (k = 0; k < nrings; k++) {
        uint32_t n = 3 + fz_u8(&in) % 4;
        if (npts + n > MAXPTS) n = MAXPTS - npts;
        if (n < 3) {
            nrings = k;
            break;
        }
        sizes[k] = n;
        for (i = 0; i < n; i++) {
            /* inside the window's pixels -1 .. w + 1 at S0 */
            p0[npts].x = (int64_t)fz_below(&in, (w + 2) * (int32_t)unit0 + 1) - unit0;
            p0[npts].y = (int64_t)fz_below(&in, (h + 2) * (int32_t)unit0 + 1) - unit0;
            if (fz_u8(&in) & 1) { /* on a pixel corner */
                p0[npts].x -= ((p0[npts].x % unit0) + unit0) % unit0;
                p0[npts].y -= ((p0[npts].y % unit0) + unit0) % unit0;
            }
            npts++;
        }
    }
    if (nrings == 0) return 0;
    n_edges = (int64_t)npts;
    /* (n + m + 1) 2^-50 in 2^-62 units, m <= n(n-1)/2, and the 2^-62 rounding */
    bound = ((n_edges + n_edges * (n_edges - 1) / 2 + 1) << 12) + 2;

    /* the 32-bit path at S0 */
    for (i = 0; i < npts; i++) {
        pts32[i].x = (int32_t)p0[i].x;
        pts32[i].y = (int32_t)p0[i].y;
    }
    memset(&o, 0, sizeof o);
    o.method = RAST_AA_AREA;
    o.rule = rule;
    o.subpixel_bits = s0;
    poly32.points = pts32;
    poly32.ring_sizes = sizes;
    poly32.nrings = nrings;
    FZ_ASSERT(rast_coverage_scratch_size(&o, npts, w, h, &need) == RAST_OK);
    sc = fz_scratch_init(&scratch, need);
    FZ_ASSERT(rast_polygon_coverage(&poly32, &o, &clip, RAST_COVERAGE_FIX62, a32, sizeof a32[0],
                                    sc, need) == RAST_OK);

    FZ_ASSERT(cov64(p0, sizes, nrings, s0, rule, clip, RAST_COVERAGE_FIX62, b64, sizeof b64[0]) ==
              RAST_OK);
    for (j = 0; j < (uint32_t)h; j++)
        for (i = 0; i < (uint32_t)w; i++) {
            FZ_ASSERT(b64[j][i] <= ((uint64_t)1 << 62));
            FZ_ASSERT(absdiff(a32[j][i], b64[j][i]) <= (uint64_t)bound);
        }

    /* the same polygon at S1 = S0 + k */
    kk = (int)(fz_u8(&in) % (33 - s0));
    s1 = s0 + kk;
    for (i = 0; i < npts; i++) {
        pk[i].x = p0[i].x * ((int64_t)1 << kk);
        pk[i].y = p0[i].y * ((int64_t)1 << kk);
    }
    FZ_ASSERT(cov64(pk, sizes, nrings, s1, rule, clip, RAST_COVERAGE_FIX62, c64, sizeof c64[0]) ==
              RAST_OK);
    for (j = 0; j < (uint32_t)h; j++)
        for (i = 0; i < (uint32_t)w; i++) FZ_ASSERT(absdiff(c64[j][i], b64[j][i]) <= 2 * (uint64_t)bound);

    /* levels from the FIX62 values */
    FZ_ASSERT(cov64(pk, sizes, nrings, s1, rule, clip, RAST_COVERAGE_U8, u8, sizeof u8[0]) == RAST_OK);
    FZ_ASSERT(cov64(pk, sizes, nrings, s1, rule, clip, RAST_COVERAGE_U16, u16, sizeof u16[0]) ==
              RAST_OK);
    for (j = 0; j < (uint32_t)h; j++)
        for (i = 0; i < (uint32_t)w; i++) {
            unsigned __int128 v = c64[j][i];
            FZ_ASSERT(u8[j][i] == (uint8_t)((v * 255 + ((uint64_t)1 << 61)) >> 62));
            FZ_ASSERT(u16[j][i] == (uint16_t)((v * 65535 + ((uint64_t)1 << 61)) >> 62));
        }

    /* moved by whole pixels, up to near +-2^28: bit for bit, nothing
     * outside the clip written */
    {
        const int64_t lim_px = ((int64_t)1 << 28) - WIN - 4;
        int64_t sx = (int64_t)(fz_u32(&in) % (uint32_t)(2 * lim_px + 1)) - lim_px;
        int64_t sy = (int64_t)(fz_u32(&in) % (uint32_t)(2 * lim_px + 1)) - lim_px;
        rast_rect c2;
        if (fz_u8(&in) & 1) {
            sx = (sx < 0) ? -lim_px : lim_px;
        }
        for (i = 0; i < npts; i++) {
            pm[i].x = pk[i].x + sx * ((int64_t)1 << s1);
            pm[i].y = pk[i].y + sy * ((int64_t)1 << s1);
        }
        c2.x0 = (int32_t)sx;
        c2.y0 = (int32_t)sy;
        c2.x1 = (int32_t)sx + w;
        c2.y1 = (int32_t)sy + h;
        memset(d64, 0xA5, sizeof d64);
        FZ_ASSERT(cov64(pm, sizes, nrings, s1, rule, c2, RAST_COVERAGE_FIX62, &d64[1][1],
                        sizeof d64[0]) == RAST_OK);
        for (j = 0; j < (uint32_t)WIN + 2; j++)
            for (i = 0; i < (uint32_t)WIN + 2; i++) {
                if (j >= 1 && j <= (uint32_t)h && i >= 1 && i <= (uint32_t)w)
                    FZ_ASSERT(d64[j][i] == c64[j - 1][i - 1]);
                else
                    FZ_ASSERT(d64[j][i] == 0xA5A5A5A5A5A5A5A5u);
            }
        /* a vertex past the range: RAST_E_RANGE, nothing written */
        pm[npts - 1].x = (fz_u8(&in) & 1) ? RAST_COORD64_MAX(s1) + 1 : -RAST_COORD64_MAX(s1) - 1;
        memset(d64, 0xA5, sizeof d64);
        FZ_ASSERT(cov64(pm, sizes, nrings, s1, rule, c2, RAST_COVERAGE_FIX62, &d64[1][1],
                        sizeof d64[0]) == RAST_E_RANGE);
        for (j = 0; j < (uint32_t)WIN + 2; j++)
            for (i = 0; i < (uint32_t)WIN + 2; i++) FZ_ASSERT(d64[j][i] == 0xA5A5A5A5A5A5A5A5u);
    }

    /* exact area: one simple ring, the window holding it (vertices within
     * pixels -1 .. w + 1: a window from -1 of w + 2 columns) */
    if (nrings == 1 && simple_ring(pk, npts)) {
        rast_rect cw;
        __int128 twice = 0, sum = 0, want, diff, tol;
        cw.x0 = -1;
        cw.y0 = -1;
        cw.x1 = w + 1;
        cw.y1 = h + 1;
        FZ_ASSERT(cov64(pk, sizes, 1, s1, rule, cw, RAST_COVERAGE_FIX62, d64, sizeof d64[0]) ==
                  RAST_OK);
        for (j = 0; j < (uint32_t)h + 2; j++)
            for (i = 0; i < (uint32_t)w + 2; i++) sum += d64[j][i];
        for (i = 0; i < npts; i++) {
            rast_point64 a = pk[i], b = pk[(i + 1) % npts];
            twice += as(mul(a.x, b.y)) - as(mul(b.x, a.y));
        }
        if (twice < 0) twice = -twice;
        /* area = twice / 2 / 2^(2 S1) pixels; in 2^-62 units: twice 2^(61 - 2 S1) */
        mx = 61 - 2 * s1;
        if (mx >= 0) {
            want = twice << mx;
            diff = sum - want;
            if (diff < 0) diff = -diff;
        } else {
            /* compare sum 2^-mx with twice */
            diff = (sum << -mx) - twice;
            if (diff < 0) diff = -diff;
            diff >>= -mx; /* back to 2^-62 units, rounded down */
        }
        tol = (__int128)bound * (w + 2) * (h + 2);
        FZ_ASSERT(diff <= tol);
    }
    (void)my;
    return 0;
}

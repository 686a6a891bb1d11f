/*
 * fuzz_burn.c - the binding's line walk and burn writers
 * (python/glue/gdalline.c, batch.c's rastpy_burn_gdal_lines and its span
 * writers for every dtype and merge): lines of any slope, inside and far
 * outside the raster, pixel by pixel or geometry by geometry, into a
 * strided array between guard bytes.  Oracle, written apart: GDAL's walk
 * stepped naively (every step of the major axis, minor offset
 * floor((2 k dminor + dmajor) / (2 dmajor))), the pixels kept when inside,
 * each geometry's set burnt once; the merges in plain C per dtype
 * (replace, add modulo 2^bits, add saturating, IEEE add), byte for byte.
 * Far lines (+-2^28) are walked by the glue only: guards and nothing
 * outside the raster.
 */
#include "glue.h"
#include "fuzz.h"

#include <string.h>

#define BZ_MAXD 12
#define BZ_MAXP 16
#define BZ_GUARD 32

static const size_t isz[11] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};

/* cell op= value for dtype dt, merge mg (the reference). */
static void ref_put(int dt, int mg, unsigned char *cell, const unsigned char *val)
{
    if (mg == RASTPY_MERGE_REPLACE) {
        memcpy(cell, val, isz[dt]);
        return;
    }
    if (dt == RASTPY_DT_F32) {
        float a, b;
        memcpy(&a, cell, 4);
        memcpy(&b, val, 4);
        a = a + b;
        memcpy(cell, &a, 4);
        return;
    }
    if (dt == RASTPY_DT_F64) {
        double a, b;
        memcpy(&a, cell, 8);
        memcpy(&b, val, 8);
        a = a + b;
        memcpy(cell, &a, 8);
        return;
    }
    {
        int sgn = dt == RASTPY_DT_I8 || dt == RASTPY_DT_I16 || dt == RASTPY_DT_I32 || dt == RASTPY_DT_I64;
        unsigned bits = (unsigned)isz[dt] * 8;
        uint64_t a = 0, b = 0, mask = bits == 64 ? ~(uint64_t)0 : (((uint64_t)1 << bits) - 1), r;
        memcpy(&a, cell, isz[dt]); /* little-endian: the low bytes */
        memcpy(&b, val, isz[dt]);
        r = (a + b) & mask;
        if (mg == RASTPY_MERGE_ADD_SAT) {
            uint64_t top = (uint64_t)1 << (bits - 1);
            if (!sgn) {
                if (r < a) r = mask; /* carried out */
            } else if (!((a ^ b) & top) && ((r ^ a) & top)) {
                r = (a & top) ? top : top - 1; /* same signs in, other sign out */
            }
        }
        memcpy(cell, &r, isz[dt]);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    int32_t h = fz_below(&in, BZ_MAXD + 1), w = fz_below(&in, BZ_MAXD + 1);
    int dt = 1 + fz_below(&in, 10), mg = fz_below(&in, 3), far = fz_u8(&in) < 32, bygeom = fz_u8(&in) & 1;
    size_t n = (size_t)fz_below(&in, BZ_MAXP + 1), k, e, s, i;
    int64_t ij[2 * BZ_MAXP];
    int8_t last[BZ_MAXP];
    uint32_t part[BZ_MAXP], geom[BZ_MAXP];
    unsigned char values[BZ_MAXP * 8], vbuf[8];
    int64_t stride = ((int64_t)w + fz_below(&in, 3)) * (int64_t)isz[dt];
    static unsigned char mem[BZ_GUARD * 2 + BZ_MAXD * (BZ_MAXD + 2) * 8], want[sizeof mem];
    unsigned char *out = mem + BZ_GUARD;
    long st;
    for (i = 0; i < sizeof mem; i++) mem[i] = (unsigned char)(0xA5 ^ (i * 7));
    /* a few small values in the cells, so that adds saturate now and then */
    for (i = 0; i < (size_t)h * (size_t)stride; i++)
        if (fz_u8(&in) < 16) out[i] = (unsigned char)fz_u8(&in);
    for (k = 0; k < n; k++) {
        if (far && fz_u8(&in) < 128) {
            ij[2 * k] = (int64_t)(fz_u32(&in) % (1u << 29)) - (1 << 28);
            ij[2 * k + 1] = (int64_t)(fz_u32(&in) % (1u << 29)) - (1 << 28);
        } else {
            ij[2 * k] = fz_below(&in, 3 * BZ_MAXD) - BZ_MAXD;
            ij[2 * k + 1] = fz_below(&in, 3 * BZ_MAXD) - BZ_MAXD;
        }
        last[k] = (int8_t)(fz_below(&in, 3) - 1);
        geom[k] = (k && fz_u8(&in) < 192) ? geom[k - 1] : (uint32_t)k; /* consecutive runs */
        part[k] = bygeom ? geom[k] : (uint32_t)fz_below(&in, BZ_MAXP);
    }
    for (k = 0; k < BZ_MAXP; k++) { /* a dtype array: value k at k * itemsize */
        unsigned char *v = vbuf;
        uint32_t pick = fz_u8(&in);
        memset(v, 0, 8);
        if (dt == RASTPY_DT_F32) {
            float f = (float)((int)(pick % 64) - 32);
            memcpy(v, &f, 4);
        } else if (dt == RASTPY_DT_F64) {
            double d = (double)((int)(pick % 64) - 32);
            memcpy(v, &d, 8);
        } else if (pick < 32) {
            memset(v, 0xFF, isz[dt]); /* -1, or the unsigned max */
            if (pick < 16) v[isz[dt] - 1] = 0x7F; /* the signed max */
        } else if (pick < 48) {
            v[isz[dt] - 1] = 0x80; /* the signed min */
        } else {
            v[0] = (unsigned char)pick;
        }
        memcpy(values + k * isz[dt], v, isz[dt]);
    }
    memcpy(want, mem, sizeof mem);
    if (!n) return 0;
    st = rastpy_burn_gdal_lines(out, h, w, stride, dt, mg, values, ij, last, part, bygeom ? geom : NULL, n);
    FZ_ASSERT(st == 0);
    /* guards, and the padding between rows, untouched */
    for (i = 0; i < BZ_GUARD; i++) FZ_ASSERT(mem[i] == want[i]);
    for (i = BZ_GUARD + (size_t)h * (size_t)stride; i < sizeof mem; i++) FZ_ASSERT(mem[i] == want[i]);
    for (i = 0; i < (size_t)h * (size_t)stride; i++)
        if ((int64_t)(i % (size_t)(stride ? stride : 1)) >= (int64_t)w * (int64_t)isz[dt])
            FZ_ASSERT(mem[BZ_GUARD + i] == want[BZ_GUARD + i]);
    if (far) return 0;
    /* the reference, geometry by geometry (or one pixel at a time) */
    for (s = 0; s < n; s = e) {
        unsigned char seen[BZ_MAXD * BZ_MAXD];
        for (e = s + 1; bygeom && e < n && geom[e] == geom[s];) e++;
        if (!bygeom) e = n;
        memset(seen, 0, sizeof seen);
        for (k = s; k + 1 < e; k++) {
            int64_t x0 = ij[2 * k], y0 = ij[2 * k + 1], x1 = ij[2 * k + 2], y1 = ij[2 * k + 3];
            int64_t dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y1 - y0 : y0 - y1;
            int xm = dx >= dy;
            int64_t dmaj = xm ? dx : dy, dmin = xm ? dy : dx, step;
            int64_t smaj = xm ? (x1 < x0 ? -1 : 1) : (y1 < y0 ? -1 : 1);
            int64_t smin = xm ? (y1 < y0 ? -1 : 1) : (x1 < x0 ? -1 : 1);
            if (last[k] < 0) continue;
            for (step = 0; step < dmaj + last[k]; step++) {
                int64_t off = dmaj ? (2 * step * dmin + dmaj) / (2 * dmaj) : 0;
                int64_t mj = (xm ? x0 : y0) + smaj * step, mn = (xm ? y0 : x0) + smin * off;
                int64_t col = xm ? mj : mn, row = xm ? mn : mj;
                if (col < 0 || col >= w || row < 0 || row >= h) continue;
                if (bygeom) {
                    if (seen[row * BZ_MAXD + col]) continue;
                    seen[row * BZ_MAXD + col] = 1;
                }
                ref_put(dt, mg, want + BZ_GUARD + row * stride + col * (int64_t)isz[dt],
                        values + isz[dt] * (bygeom ? part[s] : part[k]));
            }
        }
    }
    FZ_ASSERT(memcmp(mem, want, sizeof mem) == 0);
    return 0;
}

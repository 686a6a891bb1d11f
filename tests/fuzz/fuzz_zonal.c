/*
 * fuzz_zonal.c - rastpy_window_fractions64 (python/glue/zonal.c), the one C
 * call behind rastrum.zonal_stats' fast path (python/rastrum/_zonal.py):
 * a table of windows, each the 64-bit "area" coverage of its own rings and
 * points, its nonzero cells written as (feature, cell, fraction) triples.
 *
 * Input: the options (mostly method area; sometimes any method or rule),
 * raster_width (mostly small, sometimes any int64), a capacity (mostly
 * room for everything, sometimes 0..63), sometimes one NULL pointer, 1..8
 * ring sizes (0..8, sometimes any uint32), 0..63 points (float64 in
 * window-local pixels: near the window, anywhere in range, out of it, NaN
 * or infinite) and 1..6 windows (rarely none).  Each window's fields are
 * made valid (h, w 1..32; S 0..32; its rings inside the sizes given, its
 * points inside the points given when they fit), then sometimes one or two
 * of them are replaced by anything (negative, 0, past the ends, 2^31,
 * 2^32 + k, INT64_MIN/MAX, any 64-bit value).  xy and ring_sizes are
 * malloc'd at exactly the counts the call is told, so a read past them is
 * an ASan report.
 *
 * Oracle, independently of zonal.c's loop: window by window, the table
 * checked against its definition (zonal.c's comment: h, w 1..RAST_MAX_DIM,
 * S >= 0, at least one ring, rings and points inside the counts given),
 * then rastpy_polygon_coverage64 on the same points into a window buffer
 * (S above 32 as 33: RAST_E_SUBPIXEL), rastpy_fix62_to_double, the nonzero
 * cells in row-major order, cell = corner + row * raster_width + column
 * in two's complement (mod 2^64).  The glue's return equals the oracle's
 * (the count, or the status and failed[] of the first failing window: a
 * bad table or a full capacity RAST_E_ARG with failed = {k, 0}, a bad
 * point j RAST_E_ARG with failed = {k, j + 1}, another status as it is
 * with failed = {k, 0}); the triples written equal the oracle's, the
 * entries after them keep their guard values (so nothing is written past
 * the count nor past capacity), the input arrays are never written, and
 * a NULL pointer gives RAST_E_NULL with nothing written.  The glue is
 * compiled in (#include), as Python builds it.
 */
#include "glue.h"
#include "../../python/glue/zonal.c"
#include "fuzz.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ZZ_MAXWIN 6
#define ZZ_MAXRINGS 8
#define ZZ_MAXPTS 64
#define ZZ_OUT 8192 /* > 6 windows of 32 x 32, and 1 x 1024 */
#define ZZ_GUARD 16
#define ZZ_GUARD_I64 ((int64_t)0x5A5A5A5A5A5A5A5A)

static int64_t zz_f[ZZ_OUT + ZZ_GUARD], zz_c[ZZ_OUT + ZZ_GUARD];
static double zz_v[ZZ_OUT + ZZ_GUARD];
static int64_t zz_wf[ZZ_OUT], zz_wc[ZZ_OUT];
static double zz_wv[ZZ_OUT];

/* Anything for an int64 field: the edges a check can get wrong. */
static int64_t zz_odd(fz_in *in, int64_t nrings, int64_t npoints)
{
    uint32_t m = fz_u8(in) % 16;
    switch (m) {
    case 0: return -1;
    case 1: return 0;
    case 2: return INT64_MIN;
    case 3: return INT64_MAX;
    case 4: return (int64_t)1 << 31;
    case 5: return ((int64_t)1 << 32) + (int64_t)(fz_u8(in) % 40); /* int truncates it to 0..39 */
    case 6: return (int64_t)UINT32_MAX;
    case 7: return nrings;
    case 8: return npoints;
    case 9: return (int64_t)1 << 62;
    case 10: return -((int64_t)1 << 62);
    case 11: return RAST_MAX_DIM + 1;
    case 12: return RAST_MAX_SUBPIXEL_BITS64 + 1;
    case 13: return -(int64_t)(fz_u8(in) % 40);
    default: {
        uint64_t u = (uint64_t)fz_u32(in) << 32 | fz_u32(in);
        return (int64_t)u;
    }
    }
}

/* A coordinate in window-local pixels. */
static double zz_coord(fz_in *in)
{
    static const double odd[8] = {0.0, 0.0, 0.0, 1e300, -3e9, 3e9, 268435455.5, -0.0};
    uint32_t m = fz_u8(in);
    if (m >= 248) {
        if (m == 248) return NAN;
        if (m == 249) return INFINITY;
        if (m == 250) return -INFINITY;
        return odd[m - 248];
    }
    if (m >= 232) /* anywhere in range (+-2^28 pixels), or past it */
        return (double)(int32_t)fz_u32(in) / ((m & 1) ? 4.0 : 16.0);
    return (double)((int32_t)(m % 48) - 8) + (double)fz_u8(in) / 256.0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    rast_coverage_opts opts, opts0;
    int64_t raster_width, win[8 * ZZ_MAXWIN], win0[8 * ZZ_MAXWIN], failed[2], wfailed[2] = {0, 0};
    uint32_t nwin, nrings, npoints, sizes0[ZZ_MAXRINGS], k, j, nullarg, m;
    double xy0[2 * ZZ_MAXPTS];
    double *xy, *buf = NULL;
    uint32_t *sizes;
    size_t capacity, written = 0, i;
    long got, want = 0;

    /* the options, raster_width, capacity, a NULL */
    memset(&opts, 0, sizeof opts);
    m = fz_u8(&in);
    opts.method = m < 224 ? RAST_AA_AREA : (rast_aa_method)(m % (RAST_AA_COUNT_ + 1));
    m = fz_u8(&in);
    opts.rule = (rast_fill_rule)(m < 240 ? m % 2 : m % 3);
    m = fz_u8(&in);
    raster_width = m < 240 ? 32 + (int64_t)m : zz_odd(&in, 0, 0);
    m = fz_u8(&in);
    capacity = m < 192 ? ZZ_OUT : m - 192;
    m = fz_u8(&in);
    nullarg = m >= 248 ? m - 248 + 1 : 0;

    /* ring sizes and points */
    nrings = 1 + fz_u8(&in) % ZZ_MAXRINGS;
    for (j = 0; j < nrings; j++) {
        m = fz_u8(&in);
        sizes0[j] = m < 240 ? m % 9 : fz_u32(&in);
    }
    npoints = fz_u8(&in) % ZZ_MAXPTS;
    for (j = 0; j < 2 * npoints; j++) xy0[j] = zz_coord(&in);

    /* the windows: valid, then sometimes one or two fields anything */
    m = fz_u8(&in);
    nwin = m == 255 ? 0 : 1 + m % ZZ_MAXWIN;
    for (k = 0; k < nwin; k++) {
        int64_t *v = win + 8 * k, h, w;
        uint64_t npts = 0;
        uint32_t fr, nr, mm = fz_u8(&in);
        v[0] = (int64_t)fz_u16(&in) - 1000;
        v[1] = 1 + fz_u8(&in) % 32;
        v[2] = 1 + fz_u8(&in) % 32;
        v[3] = fz_u8(&in) % (RAST_MAX_SUBPIXEL_BITS64 + 1);
        fr = fz_u8(&in) % nrings;
        nr = 1 + fz_u8(&in) % (nrings - fr);
        for (j = 0; j < nr; j++) npts += sizes0[fr + j];
        v[5] = fr;
        v[6] = nr;
        v[4] = npts <= npoints ? (int64_t)(fz_u8(&in) % (npoints - npts + 1)) : (int64_t)fz_u8(&in);
        v[7] = (int64_t)fz_u16(&in) - 64;
        if (mm >= 128) v[mm % 8] = zz_odd(&in, nrings, npoints);
        if (mm >= 224) v[(mm >> 3) % 8] = zz_odd(&in, nrings, npoints);
        /* no window the glue would malloc gigabytes for: h * w <= 2^12 */
        h = v[1];
        w = v[2];
        if (h > 0 && w > 0 && h <= RAST_MAX_DIM && w <= RAST_MAX_DIM && h * w > 4096) {
            v[1] = 1 + h % 4;
            v[2] = 1 + w % 1024;
        }
    }

    /* exactly the counts the call is told: a read past them is an ASan report */
    xy = (double *)malloc(npoints ? 2 * npoints * sizeof(double) : 1);
    sizes = (uint32_t *)malloc(nrings * sizeof(uint32_t));
    FZ_ASSERT(xy && sizes);
    memcpy(xy, xy0, 2 * npoints * sizeof(double));
    memcpy(sizes, sizes0, nrings * sizeof(uint32_t));
    memcpy(win0, win, sizeof win);
    opts0 = opts;
    for (i = 0; i < ZZ_OUT + ZZ_GUARD; i++) {
        zz_f[i] = zz_c[i] = ZZ_GUARD_I64;
        zz_v[i] = -7.0;
    }
    failed[0] = failed[1] = ZZ_GUARD_I64;

    /* the glue */
    got = rastpy_window_fractions64(nwin, nullarg == 1 ? NULL : win, nullarg == 2 ? NULL : xy, npoints,
                                    nullarg == 3 ? NULL : sizes, nrings, nullarg == 4 ? NULL : &opts,
                                    raster_width, nullarg == 5 ? NULL : zz_f, nullarg == 6 ? NULL : zz_c,
                                    nullarg == 7 ? NULL : zz_v, capacity, nullarg == 8 ? NULL : failed);

    /* the oracle */
    if (nullarg) {
        want = RAST_E_NULL;
    } else {
        for (k = 0; k < nwin && want == 0; k++) {
            const int64_t *v = win0 + 8 * k;
            int64_t h = v[1], w = v[2], r, c;
            uint64_t npts = 0;
            size_t cells, n;
            rast_coverage_opts o = opts0;
            long st;
            wfailed[0] = k;
            wfailed[1] = 0;
            if (!(h >= 1 && h <= RAST_MAX_DIM && w >= 1 && w <= RAST_MAX_DIM && v[3] >= 0 && v[5] >= 0 &&
                  v[5] <= (int64_t)nrings && v[6] >= 1 && v[6] <= (int64_t)nrings - v[5] && v[4] >= 0 &&
                  v[4] <= (int64_t)npoints)) {
                want = RAST_E_ARG;
                break;
            }
            for (j = 0; j < (uint32_t)v[6]; j++) npts += sizes0[v[5] + j];
            if (npts > (uint64_t)npoints - (uint64_t)v[4]) {
                want = RAST_E_ARG;
                break;
            }
            cells = (size_t)(h * w);
            buf = (double *)malloc(cells * sizeof(double));
            FZ_ASSERT(buf);
            o.subpixel_bits = v[3] > RAST_MAX_SUBPIXEL_BITS64 ? RAST_MAX_SUBPIXEL_BITS64 + 1 : (int)v[3];
            st = rastpy_polygon_coverage64(buf, (int32_t)h, (int32_t)w, 2, xy0 + 2 * v[4], (uint32_t)npts,
                                           sizes0 + v[5], (uint32_t)v[6], &o);
            if (st > 0) {
                want = RAST_E_ARG;
                wfailed[1] = st;
            } else if (st < 0) {
                want = st;
            } else {
                rastpy_fix62_to_double(buf, cells);
                for (r = 0, n = 0; r < h && want == 0; r++)
                    for (c = 0; c < w; c++, n++) {
                        if (buf[n] == 0.0) continue;
                        if (written == capacity) {
                            want = RAST_E_ARG;
                            break;
                        }
                        zz_wf[written] = v[0];
                        zz_wc[written] = (int64_t)((uint64_t)v[7] + (uint64_t)r * (uint64_t)raster_width +
                                                   (uint64_t)c);
                        zz_wv[written] = buf[n];
                        written++;
                    }
            }
            free(buf);
            buf = NULL;
        }
        if (want == 0) want = (long)written;
    }

    if (got != want) {
        fprintf(stderr, "status: glue %ld, oracle %ld (window %ld, %u windows, %u points, %u rings)\n", got,
                want, (long)wfailed[0], nwin, npoints, nrings);
        FZ_ASSERT(got == want);
    }
    if (want < 0 && want != RAST_E_NULL) {
        if (failed[0] != wfailed[0] || failed[1] != wfailed[1])
            fprintf(stderr, "failed: glue {%ld, %ld}, oracle {%ld, %ld}\n", (long)failed[0], (long)failed[1],
                    (long)wfailed[0], (long)wfailed[1]);
        FZ_ASSERT(failed[0] == wfailed[0] && failed[1] == wfailed[1]);
    }
    if (want == RAST_E_NULL) {
        written = 0;
        FZ_ASSERT(failed[0] == ZZ_GUARD_I64 && failed[1] == ZZ_GUARD_I64);
    }
    /* the oracle's triples, then the guard values untouched */
    for (i = 0; i < written; i++) {
        if (zz_f[i] != zz_wf[i] || zz_c[i] != zz_wc[i] || memcmp(&zz_v[i], &zz_wv[i], sizeof(double)) != 0)
            fprintf(stderr, "triple %lu: glue (%ld, %ld, %a), oracle (%ld, %ld, %a)\n", (unsigned long)i,
                    (long)zz_f[i], (long)zz_c[i], zz_v[i], (long)zz_wf[i], (long)zz_wc[i], zz_wv[i]);
        FZ_ASSERT(zz_f[i] == zz_wf[i] && zz_c[i] == zz_wc[i]);
        FZ_ASSERT(memcmp(&zz_v[i], &zz_wv[i], sizeof(double)) == 0);
    }
    for (i = written; i < ZZ_OUT + ZZ_GUARD; i++)
        FZ_ASSERT(zz_f[i] == ZZ_GUARD_I64 && zz_c[i] == ZZ_GUARD_I64 && zz_v[i] == -7.0);
    /* the inputs as they were */
    FZ_ASSERT(memcmp(win, win0, sizeof win) == 0);
    FZ_ASSERT(npoints == 0 || memcmp(xy, xy0, 2 * npoints * sizeof(double)) == 0);
    FZ_ASSERT(memcmp(sizes, sizes0, nrings * sizeof(uint32_t)) == 0);
    FZ_ASSERT(memcmp(&opts, &opts0, sizeof opts) == 0);
    free(xy);
    free(sizes);
    return 0;
}

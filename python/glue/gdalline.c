/* gdalline.c - glue: the pixels GDAL's GDALdllImageLine burns for lines,
 * for rastrum.rasterize (python/rastrum/_burn.py).
 *
 * ij holds npoints pixel positions (x, y), the floors of the line's
 * vertices; segment k runs from position k to k + 1 where last[k] >= 0
 * (last[k] = 1: a line's last segment, whose end pixel is burnt; 0: an
 * inner segment, whose end pixel the next one burns; -1: position k ends
 * a line).  Along the major axis (x when |dx| >= |dy|) a segment burns one
 * pixel per step k = 0 .. dmajor - 1 (+ 1 for a last segment), the minor
 * coordinate moving by floor((2k dminor + dmajor) / (2 dmajor)): k dminor /
 * dmajor rounded, a half towards the end (GDAL 3.10).  Only the steps whose
 * major coordinate lies in the raster are walked, so a segment costs at
 * most the raster's side.  Coordinates must lie within +-2^29 (the caller
 * keeps them within +-2^28), where no product overflows int64_t. */
#include "gdalline.h"

typedef struct rastpy_seg {
    int64_t m0, n0, dmaj, dmin, k0, k1;
    int smaj, smin, xmaj;
} rastpy_seg;

/* Segment k's walk, cut to the steps inside the raster's major side. */
static rastpy_seg rastpy_seg_setup(const int64_t *ij, size_t k, int last, int32_t height,
                                   int32_t width)
{
    rastpy_seg s;
    const int64_t x0 = ij[2 * k], y0 = ij[2 * k + 1], x1 = ij[2 * k + 2], y1 = ij[2 * k + 3];
    const int64_t dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y1 - y0 : y0 - y1;
    int64_t count, dim;
    s.xmaj = dx >= dy;
    s.dmaj = s.xmaj ? dx : dy;
    s.dmin = s.xmaj ? dy : dx;
    s.m0 = s.xmaj ? x0 : y0;
    s.n0 = s.xmaj ? y0 : x0;
    s.smaj = s.xmaj ? (x0 > x1 ? -1 : 1) : (y0 > y1 ? -1 : 1);
    s.smin = s.xmaj ? (y0 > y1 ? -1 : 1) : (x0 > x1 ? -1 : 1);
    count = s.dmaj + last;
    dim = s.xmaj ? width : height;
    if (s.smaj > 0) {
        s.k0 = -s.m0 > 0 ? -s.m0 : 0;
        s.k1 = dim - s.m0 < count ? dim - s.m0 : count;
    } else {
        s.k0 = s.m0 - dim + 1 > 0 ? s.m0 - dim + 1 : 0;
        s.k1 = s.m0 + 1 < count ? s.m0 + 1 : count;
    }
    if (s.k1 < s.k0) s.k1 = s.k0;
    return s;
}

/* An upper bound of the pixels the walk hands to fn. */
size_t rastpy_gdal_line_count(const int64_t *ij, const int8_t *last, size_t npoints,
                              int32_t height, int32_t width)
{
    size_t k, n = 0;
    for (k = 0; k + 1 < npoints; k++)
        if (last[k] >= 0) {
            rastpy_seg s = rastpy_seg_setup(ij, k, last[k], height, width);
            n += (size_t)(s.k1 - s.k0);
        }
    return n;
}

size_t rastpy_gdal_line_walk(const int64_t *ij, const int8_t *last, size_t npoints, int32_t height,
                             int32_t width, rastpy_pixel_fn fn, void *user)
{
    size_t k, n = 0;
    for (k = 0; k + 1 < npoints; k++) {
        rastpy_seg s;
        int64_t step, off, rem, twice;
        if (last[k] < 0) continue;
        s = rastpy_seg_setup(ij, k, last[k], height, width);
        if (s.k0 >= s.k1) continue;
        /* off = floor((2 k dmin + dmaj) / (2 dmaj)), stepped: rem is the
         * remainder, below 2 dmaj; dmin <= dmaj moves off by 0 or 1. */
        twice = 2 * (s.dmaj > 0 ? s.dmaj : 1);
        off = (2 * s.k0 * s.dmin + s.dmaj) / twice;
        rem = (2 * s.k0 * s.dmin + s.dmaj) % twice;
        for (step = s.k0; step < s.k1; step++) {
            const int64_t major = s.m0 + s.smaj * step, minor = s.n0 + s.smin * off;
            const int64_t col = s.xmaj ? major : minor, row = s.xmaj ? minor : major;
            if (col >= 0 && col < width && row >= 0 && row < height) {
                fn(user, k, row, col);
                n++;
            }
            rem += 2 * s.dmin;
            if (rem >= twice) {
                rem -= twice;
                off++;
            }
        }
    }
    return n;
}

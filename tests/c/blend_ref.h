/* blend_ref.h - the documented anti-aliased paint of one pixel (rastrum.h,
 * "anti-aliased fills"), written from the documentation for the tests and
 * fuzz targets, independently of formats.c: pixel x of `row` (a target
 * row's first byte) painted with `value` at coverage level c, in place.
 *  - GRAY8, RGB888, RGBA8888: each byte d -> (s c + d (255 - c) + 127) / 255;
 *  - RGB565: the same on the 5/6/5-bit fields of the native uint16_t;
 *  - COUNT16: + 1 (saturating) iff c > 0;
 *  - MONO1: bit 7 - x % 8 of byte x / 8 set to (value != 0) iff c >= 128. */
#ifndef RAST_TEST_BLEND_REF_H
#define RAST_TEST_BLEND_REF_H

#include <stdint.h>
#include <string.h>

#include "rastrum.h"

static unsigned blend_ref_mix(unsigned s, unsigned d, unsigned c)
{
    return (s * c + d * (255 - c) + 127) / 255;
}

static void blend_ref(rast_format f, unsigned char *row, int32_t x, unsigned c,
                      const unsigned char *value)
{
    int k, n = f == RAST_FORMAT_GRAY8 ? 1 : f == RAST_FORMAT_RGB888 ? 3 : 4;
    uint16_t d, s;
    switch (f) {
    case RAST_FORMAT_GRAY8:
    case RAST_FORMAT_RGB888:
    case RAST_FORMAT_RGBA8888:
        for (k = 0; k < n; k++) row[x * n + k] = (unsigned char)blend_ref_mix(value[k], row[x * n + k], c);
        break;
    case RAST_FORMAT_RGB565:
        memcpy(&d, row + 2 * x, 2);
        memcpy(&s, value, 2);
        d = (uint16_t)(blend_ref_mix(s >> 11, d >> 11, c) << 11 |
                       blend_ref_mix((s >> 5) & 63, (d >> 5) & 63, c) << 5 | blend_ref_mix(s & 31, d & 31, c));
        memcpy(row + 2 * x, &d, 2);
        break;
    case RAST_FORMAT_COUNT16:
        memcpy(&d, row + 2 * x, 2);
        if (c > 0 && d < 65535) d++;
        memcpy(row + 2 * x, &d, 2);
        break;
    default: { /* MONO1 */
        unsigned m = 0x80u >> (x % 8);
        if (c >= 128) row[x / 8] = (unsigned char)(value[0] ? row[x / 8] | m : row[x / 8] & ~m);
        break;
    }
    }
}

#endif

/*
 * firmware_band.h - the frame loop the firmware examples share: a
 * FIRMWARE_W x FIRMWARE_H RGB565 picture drawn as bands of FIRMWARE_BAND
 * rows into one static buffer (what a display's DMA would send), each band
 * cleared to black, drawn by the example's draw_band(target, first row)
 * and hashed (FNV-1a) as a display driver would push it.  main() returns
 * 0 when every call succeeded; the hash is left in `firmware_hash` (and
 * printed when FIRMWARE_PRINT is defined: the host build, compared with
 * the full library's by make test-config).
 */
#ifndef FIRMWARE_BAND_H
#define FIRMWARE_BAND_H

#include <stdint.h>
#include <string.h>

#include "rastrum.h"

#define FIRMWARE_W 320
#define FIRMWARE_H 64
#define FIRMWARE_BAND 16

static uint16_t band[FIRMWARE_BAND][FIRMWARE_W];
volatile uint32_t firmware_hash;

/* Draw rows [y0, y0 + FIRMWARE_BAND) of the picture into t (the band:
 * its row 0 is the picture's row y0); 0 when every call succeeded. */
static int draw_band(const rast_target *t, int32_t y0);

#ifdef FIRMWARE_PRINT
#include <stdio.h>
#endif

int main(void)
{
    uint32_t h = 2166136261u;
    int32_t y0, x, y;
    int bad = 0;
    rast_target t;
    if (rast_target_init(&t, band, FIRMWARE_W, FIRMWARE_BAND, FIRMWARE_W * 2,
                         RAST_FORMAT_RGB565) != RAST_OK)
        return 1;
    for (y0 = 0; y0 < FIRMWARE_H; y0 += FIRMWARE_BAND) {
        memset(band, 0, sizeof band); /* black */
        bad |= draw_band(&t, y0);
        for (y = 0; y < FIRMWARE_BAND; y++)
            for (x = 0; x < FIRMWARE_W; x++) {
                h = (h ^ (band[y][x] & 0xFFu)) * 16777619u;
                h = (h ^ (uint32_t)(band[y][x] >> 8)) * 16777619u;
            }
    }
    firmware_hash = h;
#ifdef FIRMWARE_PRINT
    printf("%s, picture hash %08lx\n", bad ? "FAILED" : "ok", (unsigned long)h);
#endif
    return bad;
}

#endif /* FIRMWARE_BAND_H */

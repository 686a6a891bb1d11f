/*
 * grid.c - the options every entry point shares, checked once.
 */
#include "internal.h"

rast_status rast__grid_init(rast__grid *g, int32_t subpixel_bits, rast_sample sample,
                            rast_rounding rounding, rast_boundary boundary)
{
    if (subpixel_bits < 0 || subpixel_bits > RAST_MAX_SUBPIXEL_BITS)
        return RAST_E_SUBPIXEL;
    if (sample != RAST_SAMPLE_CORNER && sample != RAST_SAMPLE_CENTER) return RAST_E_ARG;
    if (rounding != RAST_ROUND_EXACT && rounding != RAST_ROUND_TEXTBOOK) return RAST_E_ARG;
    if ((unsigned)boundary > RAST_BOUNDARY_CONSERVATIVE || !RAST__BOUNDARY_KEPT(boundary))
        return RAST_E_ARG;
    g->unit = (int32_t)2 << subpixel_bits;
    g->shift = subpixel_bits + 1;
    g->off = sample == RAST_SAMPLE_CENTER ? (int32_t)1 << subpixel_bits : 0;
    g->textbook = rounding == RAST_ROUND_TEXTBOOK;
    return RAST_OK;
}

/* display_rgb565_conf.h - display_rgb565.c's build configuration of
 * rastrum: the polygon algorithms, triangle algorithm and line it draws
 * with, and "area" coverage for its anti-aliased gauge, nothing else (see
 * "Pay for what you call" in docs/c.md). */
#define RAST_CONFIG_ALGORITHMS \
    ((1u << RAST_ALGO_AET) | (1u << RAST_ALGO_EDGEFLAG) | (1u << RAST_ALGO_XSCAN))
#define RAST_CONFIG_TRI_ALGORITHMS (1u << RAST_TRI_EDGE)
#define RAST_CONFIG_LINE_ALGORITHMS (1u << RAST_LINE_BRESENHAM)
#define RAST_CONFIG_FORMATS (1u << RAST_FORMAT_RGB565)
#define RAST_CONFIG_BOUNDARIES 0u
#define RAST_CONFIG_AA_METHODS (1u << RAST_AA_AREA)
#define RAST_CONFIG_SHADING 0
#define RAST_CONFIG_POLYGON64 0

/* config_cut.h - a cut configuration (see csrc/src/base/config.h) for
 * test_config.c: every table and dispatch point keeps some of its values
 * and loses others. */
#define RAST_CONFIG_ALGORITHMS ((1u << RAST_ALGO_AET) | (1u << RAST_ALGO_EDGEFLAG))
#define RAST_CONFIG_TRI_ALGORITHMS (1u << RAST_TRI_EDGE)
#define RAST_CONFIG_LINE_ALGORITHMS (1u << RAST_LINE_BRESENHAM)
#define RAST_CONFIG_FORMATS ((1u << RAST_FORMAT_GRAY8) | (1u << RAST_FORMAT_RGB565))
#define RAST_CONFIG_BOUNDARIES (1u << RAST_BOUNDARY_CLOSED)
#define RAST_CONFIG_AA_METHODS (1u << RAST_AA_AREA)
#define RAST_CONFIG_SHADING 0
#define RAST_CONFIG_POLYGON64 0

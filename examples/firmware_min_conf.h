/* firmware_min_conf.h - firmware_min.c's build configuration of rastrum
 * (the features it calls; see "Pay for what you call" in docs/c.md):
 * compile the library with -DRAST_CONFIG_HEADER='"firmware_min_conf.h"'. */
#define RAST_CONFIG_ALGORITHMS (1u << RAST_ALGO_AET)
#define RAST_CONFIG_TRI_ALGORITHMS 0u
#define RAST_CONFIG_LINE_ALGORITHMS 0u
#define RAST_CONFIG_FORMATS (1u << RAST_FORMAT_RGB565)
#define RAST_CONFIG_BOUNDARIES 0u
#define RAST_CONFIG_AA_METHODS 0u
#define RAST_CONFIG_SHADING 0
#define RAST_CONFIG_POLYGON64 0

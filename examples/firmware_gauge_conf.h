/* firmware_gauge_conf.h - firmware_gauge.c's build configuration of
 * rastrum: area coverage into RGB565, nothing else (see "Pay for what
 * you call" in docs/c.md). */
#define RAST_CONFIG_ALGORITHMS 0u
#define RAST_CONFIG_TRI_ALGORITHMS 0u
#define RAST_CONFIG_LINE_ALGORITHMS 0u
#define RAST_CONFIG_FORMATS (1u << RAST_FORMAT_RGB565)
#define RAST_CONFIG_BOUNDARIES 0u
#define RAST_CONFIG_AA_METHODS (1u << RAST_AA_AREA)
#define RAST_CONFIG_SHADING 0
#define RAST_CONFIG_POLYGON64 0

/*
 * status.c - status messages and the runtime version.
 */
#include "rastrum.h"

int rast_version_number(void)
{
    return RAST_VERSION_NUMBER;
}

const char *rast_status_str(rast_status status)
{
    switch (status) {
#define RAST__STATUS_CASE(name, value, text) \
    case name:                               \
        return text;
        RAST_STATUS_LIST(RAST__STATUS_CASE)
#undef RAST__STATUS_CASE
    default:
        return "unknown status";
    }
}

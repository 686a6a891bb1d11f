/*
 * registry.c - the polygon algorithms by number: name, fill rules, scratch
 * size, filler.  Adding an algorithm adds one row here (and its file).
 */
#include "poly.h"
#include "registry.h"

#define RAST__BOTH_RULES ((1u << RAST_RULE_EVENODD) | (1u << RAST_RULE_NONZERO))
#define RAST__EVENODD (1u << RAST_RULE_EVENODD)

/* A row of algorithm a, or an empty one (no filler: "unknown") when the
 * build's configuration leaves a out (base/config.h). */
#define RAST__ROW(a, name, rules, scratch, fill)                              \
    {name, rules, RAST__HAS(RAST_CONFIG_ALGORITHMS, a) ? scratch : NULL,      \
     RAST__HAS(RAST_CONFIG_ALGORITHMS, a) ? fill : NULL}

static const rast__algo rast__algos[RAST_ALGO_COUNT_] = {
    RAST__ROW(RAST_ALGO_AET, "aet", RAST__BOTH_RULES, rast__aet_scratch, rast__aet_fill),
    RAST__ROW(RAST_ALGO_XSCAN, "xscan", RAST__BOTH_RULES, rast__xscan_scratch, rast__xscan_fill),
    RAST__ROW(RAST_ALGO_EDGEFILL, "edgefill", RAST__EVENODD, rast__complement_scratch,
              rast__edgefill_fill),
    RAST__ROW(RAST_ALGO_FENCE, "fence", RAST__EVENODD, rast__complement_scratch, rast__fence_fill),
    RAST__ROW(RAST_ALGO_EDGEFLAG, "edgeflag", RAST__BOTH_RULES, rast__edgeflag_scratch,
              rast__edgeflag_fill),
    RAST__ROW(RAST_ALGO_CROSSING, "crossing", RAST__EVENODD, rast__pointwise_scratch,
              rast__crossing_fill),
    RAST__ROW(RAST_ALGO_WINDING, "winding", RAST__BOTH_RULES, rast__pointwise_scratch,
              rast__winding_fill),
};

const rast__algo *rast__algo_get(rast_algorithm a)
{
    if ((unsigned)a >= RAST_ALGO_COUNT_ || !rast__algos[a].fill) return NULL;
    return &rast__algos[a];
}

rast_status rast_algorithm_info(rast_algorithm algorithm, const char **name,
                                uint32_t *rules)
{
    const rast__algo *al = rast__algo_get(algorithm);
    if (!al) return RAST_E_ALGORITHM;
    if (name) *name = al->name;
    if (rules) *rules = al->rules;
    return RAST_OK;
}

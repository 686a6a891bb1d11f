/*
 * registry.h - the table of polygon algorithms.
 */
#ifndef RAST_REGISTRY_H
#define RAST_REGISTRY_H

#include "../base/internal.h"

typedef struct rast__algo {
    /* in the row, not a pointer: a pointer would keep every string
     * literal of the build (they share one section) in a firmware image
     * that never asks for a name */
    char name[10];
    uint32_t rules; /* bit r set: rast_fill_rule r supported */
    rast__scratch_fn scratch;
    rast__polygon_fill_fn fill;
} rast__algo;

/* The algorithm's row, or NULL if `a` names none. */
const rast__algo *rast__algo_get(rast_algorithm a);

#endif /* RAST_REGISTRY_H */

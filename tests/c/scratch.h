/* scratch.h - the C tests' scratch buffers: exactly the bytes a call asks
 * for, aligned, with guard bytes after them that the call must not touch.
 * The including file defines `scratch_mem` (a static uint64_t array) and
 * GUARD (the guard byte value). */
#ifndef RAST_TEST_SCRATCH_H
#define RAST_TEST_SCRATCH_H

#include <stddef.h>
#include <string.h>

#include "rastrum.h"

#define SCRATCH_GUARD 64

/* Scratch of exactly `need` bytes (aligned), followed by guard bytes, at
 * the end of scratch_mem.  NULL if scratch_mem is too small. */
static unsigned char *scratch_for(size_t need)
{
    size_t cap = sizeof scratch_mem, start;
    if (need > cap - SCRATCH_GUARD) return NULL;
    start = (cap - SCRATCH_GUARD - need) & ~(size_t)(RAST_SCRATCH_ALIGN - 1);
    memset((unsigned char *)scratch_mem + start + need, GUARD, SCRATCH_GUARD);
    return (unsigned char *)scratch_mem + start;
}

static int scratch_guard_ok(const unsigned char *s, size_t need)
{
    size_t k;
    for (k = 0; k < SCRATCH_GUARD && s + need + k < (unsigned char *)scratch_mem + sizeof scratch_mem; k++)
        if (s[need + k] != GUARD) return 0;
    return 1;
}

#endif

/* check.h - the smallest test harness: CHECK(cond), then check_report();
 * and rng(), the tests' deterministic generator (an LCG), seeded by
 * CHECK_RNG_SEED, which a test file may define before including this. */
#ifndef RAST_CHECK_H
#define RAST_CHECK_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef CHECK_RNG_SEED
#define CHECK_RNG_SEED 1u
#endif

static uint32_t rng_state = CHECK_RNG_SEED;

/* 24 random bits. */
static inline uint32_t rng(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return rng_state >> 8;
}

static int check_passed, check_failed;

#define CHECK(cond)                                                        \
    do {                                                                   \
        if (cond) {                                                        \
            check_passed++;                                                \
        } else {                                                           \
            check_failed++;                                                \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                  \
    } while (0)

/* How many random cases to run: n, or a fifth of it when the environment
 * sets RAST_TEST_QUICK (the slow runs: valgrind, qemu).  The cases are
 * the first ones of the full run; no check changes. */
static inline int check_count(int n)
{
    const char *q = getenv("RAST_TEST_QUICK");
    return q && *q ? (n + 4) / 5 : n;
}

/* Prints the closing line CI reads and returns the exit status. */
static int check_report(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, check_passed, check_failed);
    return check_failed ? 1 : 0;
}

#endif

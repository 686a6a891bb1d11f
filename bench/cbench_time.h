/* cbench_time.h - what the C benchmarks (cbench.c, cbench_coverage.c,
 * bench_precision.c) share: a monotonic clock in seconds and the qsort
 * comparison of doubles for their medians.  Each includes it after
 * defining _POSIX_C_SOURCE and including <time.h>. */
#ifndef RAST_CBENCH_TIME_H
#define RAST_CBENCH_TIME_H

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#endif /* RAST_CBENCH_TIME_H */

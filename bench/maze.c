/* maze.c - the seed fill's fixed-memory fallback on its worst input, a
 * perfect maze of one-pixel corridors (issue 18): time (and, with
 * rast_seed_fill_limited, the work units) of rast_flood_fill on an N x N
 * maze for stacks from rast_seed_stack_size() down to none.
 *
 *   cc -O2 -Icsrc/include bench/maze.c build/librastrum.a -o build/maze
 *   build/maze N STACK_BYTES [MAX_WORK]
 *
 * The maze: cells at odd coordinates, walls (255) between them, a random
 * spanning tree (iterative depth-first search, a fixed LCG) knocked
 * through; the corridors (0) are one region, filled from (1, 1) with 1.
 * Prints one line: N, stack bytes, status, seconds, pixels filled, work
 * (with MAX_WORK, else "-").  Uses rast_seed_fill_limited when MAX_WORK is
 * given (or RAST_BENCH_LIMITED is set), else rast_flood_fill, so that the
 * same file times the code before issue 18. */
#define _POSIX_C_SOURCE 199309L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rastrum.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static uint32_t lcg = 2024u;
static uint32_t rnd(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return lcg >> 8;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 1024, cells, top = 0;
    size_t stack_bytes = argc > 2 ? (size_t)strtoull(argv[2], NULL, 10) : 0, need = 0, filled = 0, i;
    unsigned char *img, value = 1;
    uint32_t *todo;
    void *stack;
    rast_target t;
    rast_status st;
    double t0, t1;
    if (n < 3) return 2;
    cells = (n - 1) / 2;
    img = malloc((size_t)n * (size_t)n);
    todo = malloc(sizeof *todo * (size_t)cells * (size_t)cells);
    if (!img || !todo) return 2;
    memset(img, 255, (size_t)n * (size_t)n);
    /* Depth-first spanning tree over the cells. */
    img[(size_t)1 * (size_t)n + 1] = 0;
    todo[top++] = 0;
    while (top) {
        uint32_t c = todo[top - 1], cx = c % (uint32_t)cells, cy = c / (uint32_t)cells, k, opts[4], m = 0;
        static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
        for (k = 0; k < 4; k++) {
            long nx = (long)cx + dx[k], ny = (long)cy + dy[k];
            if (nx < 0 || ny < 0 || nx >= cells || ny >= cells) continue;
            if (img[(size_t)(2 * ny + 1) * (size_t)n + (size_t)(2 * nx + 1)] == 0) continue;
            opts[m++] = k;
        }
        if (!m) {
            top--;
            continue;
        }
        k = opts[rnd() % m];
        img[(size_t)(2 * cy + 1 + (uint32_t)dy[k]) * (size_t)n + (2 * cx + 1 + (uint32_t)dx[k])] = 0;
        img[(size_t)(2 * (cy + (uint32_t)dy[k]) + 1) * (size_t)n + (2 * (cx + (uint32_t)dx[k]) + 1)] = 0;
        todo[top++] = (cy + (uint32_t)dy[k]) * (uint32_t)cells + cx + (uint32_t)dx[k];
    }
    rast_seed_stack_size(n, n, &need);
    if (stack_bytes == (size_t)-1) stack_bytes = need;
    stack = stack_bytes ? aligned_alloc(16, (stack_bytes + 15) / 16 * 16) : NULL;
    rast_target_init(&t, img, n, n, n, RAST_FORMAT_GRAY8);
    t0 = now();
#ifdef RAST_BENCH_LIMITED
    {
        uint64_t work = 0, max_work = argc > 3 ? strtoull(argv[3], NULL, 10) : UINT64_MAX;
        st = rast_seed_fill_limited(&t, 1, 1, &value, NULL, 4, stack, stack_bytes, max_work, &work);
        t1 = now();
        for (i = 0; i < (size_t)n * (size_t)n; i++) filled += img[i] == 1;
        printf("maze %d stack %zu (full %zu): status %d, %.3f s, %zu pixels filled, work %llu\n", n,
               stack_bytes, need, (int)st, t1 - t0, filled, (unsigned long long)work);
    }
#else
    st = rast_flood_fill(&t, 1, 1, &value, 4, stack, stack_bytes);
    t1 = now();
    for (i = 0; i < (size_t)n * (size_t)n; i++) filled += img[i] == 1;
    printf("maze %d stack %zu (full %zu): status %d, %.3f s, %zu pixels filled, work -\n", n,
           stack_bytes, need, (int)st, t1 - t0, filled);
#endif
    free(stack);
    free(img);
    free(todo);
    return st == RAST_OK ? 0 : 1;
}

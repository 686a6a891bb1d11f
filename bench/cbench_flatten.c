/* cbench_flatten.c - the path flattener alone (issue 34): a path read from
 * a file (bench/dump_path.py writes one: the paragraph of bench_paths.py
 * by default), counted and flattened as python/glue/pathfill.c does it,
 * under callgrind:
 *   build/cbench_flatten FILE size|flatten|both [REPS]
 * "size" calls rast_path_flatten_size REPS times, "flatten"
 * rast_path_flatten, "both" the pair (the fill's order); each call is a
 * function of its own (count_pass, flatten_pass), so
 * `callgrind_annotate` names them.  Prints the sizes and an FNV-1a hash
 * of the flattened vertices and ring sizes, to compare two builds. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rastrum.h"

__attribute__((noinline)) static rast_status count_pass(const rast_path *p, int32_t tol, uint32_t *np, uint32_t *nr)
{
    return rast_path_flatten_size(p, tol, np, nr);
}

__attribute__((noinline)) static rast_status flatten_pass(const rast_path *p, int32_t tol, rast_point *pts, uint32_t np,
                                uint32_t *sizes, uint32_t nr, rast_polygon *poly)
{
    return rast_path_flatten(p, tol, pts, np, sizes, nr, poly);
}

static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *c = (const unsigned char *)data;
    size_t k;
    for (k = 0; k < n; k++) h = (h ^ c[k]) * 1099511628211ULL;
    return h;
}

int main(int argc, char **argv)
{
    FILE *f;
    unsigned nv, npt, k;
    int tol, reps = 1, r, x, y, v, do_size, do_flat;
    uint8_t *verbs;
    rast_point *pts, *out = NULL;
    uint32_t *sizes = NULL, np = 0, nr = 0;
    rast_path path;
    rast_polygon poly;
    rast_status st = RAST_OK;
    uint64_t h = 14695981039346656037ULL;
    if (argc < 3 || !(f = fopen(argv[1], "r"))) {
        fprintf(stderr, "usage: %s FILE size|flatten|both [REPS]\n", argv[0]);
        return 2;
    }
    do_size = strcmp(argv[2], "flatten") != 0;
    do_flat = strcmp(argv[2], "size") != 0;
    if (argc > 3) reps = atoi(argv[3]);
    if (fscanf(f, "%u %u %d", &nv, &npt, &tol) != 3) return 2;
    verbs = (uint8_t *)malloc(nv + 1);
    pts = (rast_point *)malloc((npt + 1) * sizeof *pts);
    for (k = 0; k < nv; k++) {
        if (fscanf(f, "%d", &v) != 1) return 2;
        verbs[k] = (uint8_t)v;
    }
    for (k = 0; k < npt; k++) {
        if (fscanf(f, "%d %d", &x, &y) != 2) return 2;
        pts[k].x = x;
        pts[k].y = y;
    }
    fclose(f);
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = pts;
    path.npoints = npt;
    st = rast_path_flatten_size(&path, tol, &np, &nr);
    if (st != RAST_OK) return 1;
    out = (rast_point *)malloc((np + 1) * sizeof *out);
    sizes = (uint32_t *)malloc((nr + 1) * sizeof *sizes);
    for (r = 0; r < reps; r++) {
        if (do_size) st = count_pass(&path, tol, &np, &nr);
        if (st == RAST_OK && do_flat) st = flatten_pass(&path, tol, out, np, sizes, nr, &poly);
        if (st != RAST_OK) return 1;
    }
    if (do_flat) {
        h = fnv(h, out, np * sizeof *out);
        h = fnv(h, sizes, nr * sizeof *sizes);
    }
    printf("%u verbs, %u points, tolerance %d: %u vertices in %u rings, hash %016llx\n", nv, npt, tol, np,
           nr, (unsigned long long)h);
    free(verbs);
    free(pts);
    free(out);
    free(sizes);
    return 0;
}

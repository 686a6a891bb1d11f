/* comb.c - the AET's worst case for edge insertion: a comb of `teeth` teeth
 * hanging from one row, so 2 x teeth edges join the active edge table on
 * the same row.  Fills it once with the "aet" algorithm into a gray8 target
 * and prints the pixel count; run it under `valgrind --tool=callgrind` to
 * count instructions (repeatable, unlike a timer):
 *
 *   cc -O2 -std=c99 -Icsrc/include bench/comb.c csrc/src/*/*.c -o build/comb
 *   valgrind --tool=callgrind --callgrind-out-file=/dev/null build/comb 10000
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrum.h"

int main(int argc, char **argv)
{
    uint32_t teeth = argc > 1 ? (uint32_t)strtoul(argv[1], NULL, 10) : 10000u, n, k;
    const int32_t w = 4096, h = 64;
    rast_point *pts;
    unsigned char *img, one = 1;
    void *scratch;
    size_t need, count = 0, i;
    rast_target t;
    rast_polygon p;
    rast_fill_opts o;
    rast_status st;

    if (teeth < 1 || teeth > 1000000) return 2;
    n = 2 * teeth + 3;
    pts = malloc(n * sizeof *pts);
    img = calloc((size_t)w * h, 1);
    if (!pts || !img) return 2;
    /* S = 8; tooth k spans x in [k, k+1) * 4096/teeth px, from row 1 down to 60 */
    for (k = 0; k < teeth; k++) {
        int32_t x0 = (int32_t)(((int64_t)k * w << 8) / teeth);
        int32_t x1 = (int32_t)(((int64_t)(k + 1) * w << 8) / teeth);
        pts[2 * k].x = x0;
        pts[2 * k].y = 1 << 8;
        pts[2 * k + 1].x = (x0 + x1) / 2;
        pts[2 * k + 1].y = 60 << 8;
    }
    pts[2 * teeth].x = w << 8;
    pts[2 * teeth].y = 1 << 8;
    pts[2 * teeth + 1].x = w << 8;
    pts[2 * teeth + 1].y = 0;
    pts[2 * teeth + 2].x = 0; /* back along y = 0; the ring closes to (0, 1) */
    pts[2 * teeth + 2].y = 0;
    p.points = pts;
    p.ring_sizes = &n;
    p.nrings = 1;
    memset(&o, 0, sizeof o);
    o.algorithm = RAST_ALGO_AET;
    o.rule = RAST_RULE_EVENODD;
    o.subpixel_bits = 8;
    o.sample = RAST_SAMPLE_CENTER;
    if (rast_target_init(&t, img, w, h, w, RAST_FORMAT_GRAY8) != RAST_OK) return 2;
    if (rast_scratch_size(&o, n, w, h, &need) != RAST_OK) return 2;
    scratch = malloc(need + 8);
    if (!scratch) return 2;
    st = rast_fill_polygon(&t, &p, &o, &one, scratch, need);
    if (st != RAST_OK) {
        printf("%s\n", rast_status_str(st));
        return 1;
    }
    for (i = 0; i < (size_t)w * h; i++) count += img[i];
    printf("comb of %u teeth (%u edges starting on row 1): %lu pixels\n", teeth, 2 * teeth,
           (unsigned long)count);
    free(scratch);
    free(pts);
    free(img);
    return 0;
}

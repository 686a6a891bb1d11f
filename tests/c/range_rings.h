/*
 * range_rings.h - the polygons of the range tests (test_range.c, the
 * binary fills; test_coverage_range.c, the coverage calls): a small
 * zigzag of n points inside a 16 x 12 canvas at S = s, and the polygon
 * made of them, one ring or three (1, n - 2 and 1 points: a point past
 * the range then stands first, inside and last in a ring).  Include after
 * check.h (rng()).
 */
#ifndef RAST_TEST_RANGE_RINGS_H
#define RAST_TEST_RANGE_RINGS_H

/* n points of a zigzag, each jittered within its pixel at S = s. */
static void range_zigzag(rast_point *p, uint32_t n, int32_t s)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        p[i].x = (int32_t)(((1 + (i * 5) % 13) << s) + (int32_t)(rng() % (1u << s)));
        p[i].y = (int32_t)(((1 + (i * 7) % 9) << s) + (int32_t)(rng() % (1u << s)));
    }
}

/* *poly: p's n points as one ring (rings == 1) or three (sizes: room for
 * three). */
static void range_polygon(rast_polygon *poly, const rast_point *p, uint32_t n, int rings, uint32_t *sizes)
{
    poly->points = p;
    if (rings == 1) {
        sizes[0] = n;
        poly->nrings = 1;
    } else { /* three rings: 1, n - 2 and 1 points */
        sizes[0] = 1;
        sizes[1] = n - 2;
        sizes[2] = 1;
        poly->nrings = 3;
    }
    poly->ring_sizes = sizes;
}

#endif

/*
 * path.h - what the path flattener and its users share (internal).
 */
#ifndef RAST_PATH_H
#define RAST_PATH_H

#include "../base/internal.h"

/* ceil(sqrt(v)) for any v < 2^62, exactly (integer square root), and
 * floor(sqrt(v)) for any v. */
uint32_t rast__isqrt_ceil(uint64_t v);
uint32_t rast__isqrt_floor(uint64_t v);

/* The flattened path, as rast_path_flatten writes it, or only counted:
 * with points == NULL nothing is stored and the counts are the sizes. */
typedef struct rast__flat {
    rast_point *points;   /* NULL: count only */
    uint32_t *ring_sizes; /* one per subpath */
    uint8_t *closed;      /* NULL, or one per subpath: 1 iff it ended in CLOSE */
    uint32_t npoints, nrings;
    /* with points: the room of points[] and ring_sizes[] (and closed[]),
     * or 0 for both: sized by a counting call (no check) */
    uint32_t max_points, max_rings;
} rast__flat;

/* Check `path` and `tolerance` as rast_path_flatten does (RAST_E_NULL,
 * RAST_E_ARG, RAST_E_RANGE, RAST_E_TOO_MANY), then flatten it into *f
 * (counts from 0; f->points NULL: count only).  The caller sized f's
 * arrays by a counting call, or gave their room in f->max_points and
 * f->max_rings (both > 0): a vertex or a subpath past it is not stored
 * and the call returns RAST_E_SCRATCH, some of the room written (a
 * counting call then gives the sizes, or the error that comes first:
 * RAST_E_TOO_MANY). */
/* A curve of degree d (2 or 3) from p[0] with controls p[1 .. d]: its edge
 * count at tolerance tol, and its point i of n, rounded (as flattened). */
uint32_t rast__curve_edges(const rast_point *p, int d, int32_t tol);
rast_point rast__curve_point(const rast_point *p, int d, uint32_t i, uint32_t n);

rast_status rast__path_flatten(const rast_path *path, int32_t tolerance, rast__flat *f);

/* rast_path_stroke's outline in one pass, without the counting pass first
 * (path/stroke.c): into points[0 .. max_points) and ring_sizes[0 ..
 * max_rings), laid out as rast_path_stroke lays it out, *npoints and
 * *nrings set.  The room may be any size: too little gives RAST_E_SCRATCH
 * (rast_path_stroke_size then says how much, or which other error comes
 * first), with some of the room written.  Errors otherwise as
 * rast_path_stroke_size's, and RAST_E_NULL. */
rast_status rast__path_stroke_into(const rast_path *path, const rast_stroke_style *style, rast_point *points,
                                   uint32_t max_points, uint32_t *ring_sizes, uint32_t max_rings,
                                   uint32_t *npoints, uint32_t *nrings);

/* The same outline but for the flags: RAST__STROKE_MEET takes, at a join
 * whose two segments' parallelograms cover the inner corner, the inner
 * edges' meeting point (rounded) in place of the inner side's three
 * points through the vertex (path/stroke.c, "Inner joins"): no loop there,
 * the region within sqrt(2)/2 u of the pieces' union instead of equal to
 * it; a build for size ignores it.  points NULL: counted only (the sizes
 * in *npoints, *nrings, as rast_path_stroke_size); else stored as
 * rast__path_stroke_into stores; each flag alone or both. */
#define RAST__STROKE_MEET 1u
/* RAST__STROKE_ARCS: round joins' and caps' points on a circle a little
 * wider, radius h (1 + 1/(4 m^2)), so that the polygon straddles the true
 * circle (vertices out, chords' middles in): the same bound with about
 * 1/sqrt(2) as many points (path/stroke.c, "Round parts"). */
#define RAST__STROKE_ARCS 2u
rast_status rast__path_stroke_run(const rast_path *path, const rast_stroke_style *style, unsigned flags,
                                  rast_point *points, uint32_t max_points, uint32_t *ring_sizes,
                                  uint32_t max_rings, uint32_t *npoints, uint32_t *nrings);

#endif

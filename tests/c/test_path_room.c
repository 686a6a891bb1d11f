/*
 * test_path_room.c - rast__path_flatten into a room given (path/path.h:
 * max_points, max_rings; the one pass of python/glue/pathfill.c, with no
 * count first): for random paths (moves, lines, quadratics, cubics,
 * closes, a drawing verb after a close) and every room from one vertex
 * and one subpath to two past the sizes rast_path_flatten_size gives,
 * RAST_OK exactly when the room holds them, then the same vertices, ring
 * sizes and closed flags as rast_path_flatten's counted way; else
 * RAST_E_SCRATCH; either way nothing written past the room (guard values
 * after each array).  Errors of the path come first, as from the count.
 */
#include <string.h>

#include "check.h"
#include "rastrum.h"
#include "path/path.h"

#define MAXV 48
#define MAXPT 4096
#define GUARD 8
#define GP 0x5A5A5A5A

static rast_point ref_pts[MAXPT], pts[MAXPT + GUARD];
static uint32_t ref_rings[MAXV], rings[MAXV + GUARD];
static uint8_t closed[MAXV + GUARD], ref_closed[MAXV];

static int32_t coord(void) { return (int32_t)(rng() % 801u) - 400; }

/* A random path: nv verbs, its points; returns the point count. */
static uint32_t random_path(uint8_t *verbs, uint32_t nv, rast_point *p)
{
    static const uint8_t take[5] = {1, 1, 2, 3, 0};
    uint32_t k, n = 0;
    int j;
    for (k = 0; k < nv; k++) {
        uint32_t r = rng() % 10u;
        uint8_t v = k == 0 || r == 0 ? RAST_PATH_MOVE
                    : r <= 3         ? RAST_PATH_LINE
                    : r <= 5         ? RAST_PATH_QUAD
                    : r <= 7         ? RAST_PATH_CUBIC
                                     : RAST_PATH_CLOSE;
        verbs[k] = v;
        for (j = 0; j < take[v]; j++) {
            p[n].x = coord();
            p[n].y = coord();
            n++;
        }
    }
    return n;
}

static void one_path(void)
{
    uint8_t verbs[MAXV];
    rast_point p[3 * MAXV];
    rast_path path;
    rast_polygon poly;
    uint32_t nv = 1 + rng() % 12u, np, nr, room, rroom, i;
    int32_t tol = 1 + (int32_t)(rng() % 6u);
    path.verbs = verbs;
    path.nverbs = nv;
    path.points = p;
    path.npoints = random_path(verbs, nv, p);
    CHECK(rast_path_flatten_size(&path, tol, &np, &nr) == RAST_OK);
    if (np > MAXPT - 2 || nr > MAXV - 2) return;
    {   /* the counted way, with the closed flags */
        rast__flat f;
        memset(&f, 0, sizeof f);
        f.points = ref_pts;
        f.ring_sizes = ref_rings;
        f.closed = ref_closed;
        CHECK(rast__path_flatten(&path, tol, &f) == RAST_OK && f.npoints == np && f.nrings == nr);
        CHECK(rast_path_flatten(&path, tol, pts, MAXPT, rings, MAXV, &poly) == RAST_OK);
        CHECK(memcmp(pts, ref_pts, np * sizeof *pts) == 0 && memcmp(rings, ref_rings, nr * sizeof *rings) == 0);
    }
    for (room = 1; room <= np + 2; room++)
        for (rroom = 1; rroom <= nr + 2; rroom++) {
            rast__flat f;
            rast_status st;
            int fits = room >= np && rroom >= nr, intact = 1;
            for (i = 0; i < MAXPT + GUARD; i++) pts[i].x = pts[i].y = GP;
            for (i = 0; i < MAXV + GUARD; i++) {
                rings[i] = GP;
                closed[i] = 0xA5;
            }
            memset(&f, 0, sizeof f);
            f.points = pts;
            f.ring_sizes = rings;
            f.closed = closed;
            f.max_points = room;
            f.max_rings = rroom;
            st = rast__path_flatten(&path, tol, &f);
            CHECK(st == (fits ? RAST_OK : RAST_E_SCRATCH));
            for (i = room; i < room + GUARD; i++) intact &= pts[i].x == GP && pts[i].y == GP;
            for (i = rroom; i < rroom + GUARD; i++) intact &= rings[i] == GP && closed[i] == 0xA5;
            CHECK(intact);
            if (st == RAST_OK) {
                CHECK(f.npoints == np && f.nrings == nr);
                CHECK(memcmp(pts, ref_pts, np * sizeof *pts) == 0);
                CHECK(memcmp(rings, ref_rings, nr * sizeof *rings) == 0);
                CHECK(memcmp(closed, ref_closed, nr) == 0);
            }
        }
}

/* Bad paths: the same error as the count's, whatever the room. */
static void bad_paths(void)
{
    uint8_t verbs[3] = {RAST_PATH_MOVE, RAST_PATH_LINE, RAST_PATH_LINE};
    rast_point p[3] = {{0, 0}, {RAST_COORD_MAX + 1, 0}, {5, 5}};
    rast_path path;
    rast__flat f;
    uint32_t np, nr;
    path.verbs = verbs;
    path.nverbs = 3;
    path.points = p;
    path.npoints = 3;
    memset(&f, 0, sizeof f);
    f.points = pts;
    f.ring_sizes = rings;
    f.max_points = 1;
    f.max_rings = 1;
    CHECK(rast_path_flatten_size(&path, 1, &np, &nr) == RAST_E_RANGE);
    CHECK(rast__path_flatten(&path, 1, &f) == RAST_E_RANGE);
    p[1].x = 7;
    memset(&f, 0, sizeof f);
    f.points = pts;
    f.ring_sizes = rings;
    f.max_points = 1;
    f.max_rings = 1;
    CHECK(rast__path_flatten(&path, 0, &f) == RAST_E_ARG);
    CHECK(rast__path_flatten(&path, 1, &f) == RAST_E_SCRATCH);
}

int main(void)
{
    int k;
    bad_paths();
    for (k = 0; k < check_count(400); k++) one_path();
    return check_report("test_path_room");
}

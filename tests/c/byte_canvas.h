/*
 * byte_canvas.h - a gray8 target W x H (rows of STRIDE bytes) filled
 * through the AET by a chosen way (RAST__AET_BY_*) into the solid or
 * opaque painter, and the check of its bytes against the brute-force
 * reference (ref.h), for the C tests that write one-byte pixels
 * (test_delta_bytes.c, test_aet_bytes.c, test_delta_*.c); and the
 * delta tests' random scenes, their clips drawn too (bytes_scenes).  The includer defines
 * W, H, STRIDE and the bytes VALUE and BACKGROUND first.
 */
#ifndef RAST_TEST_BYTE_CANVAS_H
#define RAST_TEST_BYTE_CANVAS_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ref.h"
#include "base/internal.h"
#include "painters/paint.h"
#include "rastrum.h"

/* Fill by `how` into px (set to `pre` first): opaque (background
 * BACKGROUND outside the polygon, inside the clip), or the solid fill;
 * the status. */
static rast_status bytes_fill(unsigned char *px, const unsigned char *pre, const rast_polygon *poly,
                              uint32_t npoints, const rast__grid *g, rast_fill_rule rule,
                              const rast_rect *clip, void *scratch, size_t bytes, int opaque, int how)
{
    rast_target t;
    rast__solid solid;
    rast__painter p;
    rast__sink sink;
    rast__arena arena = rast__arena_of(scratch, bytes);
    rast_status st;
    (void)how; /* a build for size has the sweep only (base/internal.h) */
    memcpy(px, pre, (size_t)STRIDE * H);
    CHECK(rast_target_init(&t, px, W, H, STRIDE, RAST_FORMAT_GRAY8) == RAST_OK);
    CHECK(rast__solid_init(&solid, &t, clip, &VALUE, opaque ? &BACKGROUND : NULL, &p) == RAST_OK);
    rast__sink_init(&sink, &p, clip);
    st = rast__aet_fill_by(poly, npoints, g, rule, clip, &sink, &arena, how);
    if (st == RAST_OK && opaque) rast__opaque_finish(&solid);
    return st;
}

/* Every byte of px (filled from pre) against the reference: inside the
 * clip VALUE where the sample is inside by the rule, else BACKGROUND
 * (opaque) or the byte it was; outside the clip the byte it was.  The
 * first byte that differs is printed (iter names the case) and 0
 * returned; 1 when all agree. */
static int bytes_match_ref(const unsigned char *px, const unsigned char *pre, const rast_point *pts,
                           const uint32_t *sizes, uint32_t nrings, int s, int center, int textbook,
                           rast_fill_rule rule, const rast_rect *clip, int opaque, int iter)
{
    int32_t i, j;
    for (j = 0; j < H; j++) {
        for (i = 0; i < STRIDE; i++) {
            const unsigned char got = px[j * STRIDE + i], was = pre[j * STRIDE + i];
            unsigned char want = was;
            if (i >= clip->x0 && i < clip->x1 && j >= clip->y0 && j < clip->y1) {
                int cr, w = ref_winding(pts, sizes, nrings, s, center, textbook, i, j, &cr);
                int in = rule == RAST_RULE_EVENODD ? (cr & 1) : w != 0;
                want = in ? VALUE : opaque ? BACKGROUND : was;
            }
            if (got != want) {
                fprintf(stderr, "iter %d (%s): byte (%d, %d) is %d, the reference %d\n", iter,
                        opaque ? "opaque" : "solid", (int)i, (int)j, got, want);
                return 0;
            }
        }
    }
    return 1;
}

/* One scene filled both ways (the sweep and the winding rule), from
 * garbage bytes: the two equal byte for byte and equal to the
 * reference (ref.h) inside the clip, `pre` kept outside it. */
static inline void bytes_check_scene(int iter, const rast_point *pts, const uint32_t *sizes, uint32_t nrings,
                                     uint32_t np, int s, int center, int textbook, rast_fill_rule rule,
                                     const rast_rect *clip, int opaque)
{
    static unsigned char pre[STRIDE * H], a[STRIDE * H], b[STRIDE * H];
    static unsigned char scratch[1 << 20];
    const size_t need = rast__aet_scratch(np, W, H);
    const rast_polygon poly = {pts, sizes, nrings};
    const rast_sample at = center ? RAST_SAMPLE_CENTER : RAST_SAMPLE_CORNER;
    rast__grid g;
    int32_t k;
    CHECK(need <= sizeof scratch);
    CHECK(rast__grid_init(&g, s, at, textbook ? RAST_ROUND_TEXTBOOK : RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT) ==
          RAST_OK);
    for (k = 0; k < STRIDE * H; k++) pre[k] = (unsigned char)rng(); /* garbage: the clip's part written */
    CHECK(bytes_fill(a, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_SWEEP) == RAST_OK);
    CHECK(bytes_fill(b, pre, &poly, np, &g, rule, clip, scratch, need, opaque, RAST__AET_BY_RULE) == RAST_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK(bytes_match_ref(b, pre, pts, sizes, nrings, s, center, textbook, rule, clip, opaque, iter));
}

/* A clip for a scene of np vertices on the canvas: 1 to np / 8 rows
 * (at least 8 vertices a row: the rule's count), anywhere down; when
 * opaque, 3 times in 4 the whole width (the counters in the mask itself),
 * else up to 19 columns off each side.  1 when the rule's counts
 * (fillers/aet.c, as test_aet_rule.c: 8 vertices a clip row, the
 * counters' rows in the edge records' room, at most 8 words of them a
 * vertex) take the scene. */
static inline int bytes_pick_clip(uint32_t np, int opaque, rast_rect *clip)
{
    int32_t rows = (int32_t)(np / 8) < H ? (int32_t)(np / 8) : H;
    rows = 1 + (int32_t)(rng() % (uint32_t)rows);
    clip->y0 = (int32_t)(rng() % (uint32_t)(H - rows + 1));
    clip->y1 = clip->y0 + rows;
    if (opaque && (rng() & 3)) {
        clip->x0 = 0;
        clip->x1 = W;
    } else {
        clip->x0 = (int32_t)(rng() % 20);
        clip->x1 = W - (int32_t)(rng() % 20);
    }
    return np >= 8 * (uint32_t)rows && rows * ((clip->x1 - clip->x0 + 8) & ~7) <= (int32_t)np * 48 &&
           rows * ((clip->x1 - clip->x0 + 8) / 8) <= 8 * (int32_t)np;
}

/* A scene's rings for bytes_scenes: into pts and sizes, S s, the sample
 * at the pixel's centre or not, scene `iter`; the rings' count, the
 * points' into *np. */
typedef uint32_t (*bytes_rings_fn)(int iter, int s, int center, rast_point *pts, uint32_t *sizes, uint32_t *np);

/* One ring of n vertices round the pixel (cx, cy), S s, the sample at
 * the pixel's centre or not; its count back. */
typedef uint32_t (*bytes_ring_fn)(rast_point *pts, uint32_t n, int32_t cx, int32_t cy, int s, int center);

/* A scene of ring() rings (for a bytes_rings_fn): 16 to 315 vertices in
 * all, one scene in 8 600 to 1,299 (past 511: non-zero's pieces
 * counted), 4 to 26 a ring, each round a point near the canvas, one ring
 * in 6 near a side or past it. */
static inline uint32_t bytes_rings_near(int iter, int s, int center, bytes_ring_fn ring, rast_point *pts,
                                        uint32_t *sizes, uint32_t *np)
{
    const uint32_t want = iter % 8 == 5 ? 600 + rng() % 700 : 16 + rng() % 300;
    uint32_t nrings = 0;
    while (*np + 4 <= want) {
        uint32_t m = 4 + 2 * (rng() % 12);
        const int32_t cx = rng() % 6 ? (int32_t)(rng() % W) : (rng() & 1) ? -2 : W + 1;
        const int32_t cy = (int32_t)(rng() % (H + 4)) - 2;
        if (*np + m > want) m = (want - *np) & ~1u;
        sizes[nrings++] = ring(pts + *np, m, cx, cy, s, center);
        *np += m;
    }
    return nrings;
}

/* The delta tests' scenes (check_count(1500) of them): for each, S 0 to
 * 16, the sample, textbook rounding one time in `tb`, opaque or not and
 * the rule drawn (rng(), in that order), then its rings (rings()), a
 * scene of fewer than `least` points passed over, then its clip
 * (bytes_pick_clip) and its check (bytes_check_scene); more than half of
 * them must be taken by the rule's counts. */
static inline void bytes_scenes(uint32_t tb, uint32_t least, bytes_rings_fn rings, rast_point *pts, uint32_t *sizes)
{
    int iter, n = check_count(1500), taken = 0;
    for (iter = 0; iter < n; iter++) {
        const int s = (int)(rng() % 17), center = (int)(rng() & 1);
        const int textbook = (int)(rng() % tb == 0), opaque = (int)(rng() & 1);
        const rast_fill_rule rule = (rng() & 1) ? RAST_RULE_EVENODD : RAST_RULE_NONZERO;
        uint32_t np = 0;
        const uint32_t nrings = rings(iter, s, center, pts, sizes, &np);
        rast_rect clip;
        if (np < least) continue;
        taken += bytes_pick_clip(np, opaque, &clip);
        bytes_check_scene(iter, pts, sizes, nrings, np, s, center, textbook, rule, &clip, opaque);
    }
    CHECK(taken > n / 2);
}

#endif

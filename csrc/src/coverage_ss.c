/*
 * coverage_ss.c - k x k supersampling ("ss2" .. "ss16"): the binary rule
 * (DESIGN section 1) on a grid k times finer, counted per pixel.
 *
 * The fine grid's pixel (I, J) is pixel (I / k, J / k) of the output and
 * its sample sits at ((I + o) / k, (J + o) / k): exactly sub-sample
 * (I mod k, J mod k) of section 1a.  The polygon arrives on that grid
 * already (coverage.c scales its vertices by k exactly); the exact AET
 * walk (aet.h) hands its runs straight to rast__ss_span, row by row, and
 * a row of counters (one output row) adds them up.
 *
 * The counters are kept as differences (count[i] = d[0] + ... + d[i]), so
 * a run costs at most four additions whatever its length, and a bit per
 * column marks the differences not 0.  Flushing an output row walks only
 * the marked columns: between two of them the count is constant, and its
 * value is written as one run (a memset for uint8_t).  A row costs its
 * runs plus a pass over its pixels at memset speed.
 */
#include "coverage.h"
#include "aet.h"
#include "poly.h"

typedef struct rast__ss {
    const rast__cov_out *o;
    int32_t *d;      /* the output row's counts as differences, clip
                        columns, two more at the end (a run ending at the
                        clip's right edge touches d[w + 1], with 0) */
    uint64_t *mark;  /* bit i: d[i] may not be 0 */
    uint64_t *level; /* the value of each count 0..k^2 */
    int32_t kbits;
    int32_t fx0, fx1, fy0; /* the fine clip's columns and first row */
    int32_t row;           /* the output row (clip-relative); -1 before the first */
    int32_t next;          /* the first output row (clip-relative) not written yet */
    int32_t py, px0, px1;  /* the pending run: fine row py, clip-relative
                              fine columns [px0, px1); px0 == px1 none */
} rast__ss;

/* Pixels [k0, k1) of a clip row get value v. */
static void rast__ss_run(rast_coverage_format f, unsigned char *row, int32_t k0, int32_t k1,
                         uint64_t v)
{
    int32_t k;
    if (k0 >= k1) return;
    if (f == RAST_COVERAGE_U8) {
        memset(row + k0, (int)v, (size_t)(k1 - k0));
    } else if (f == RAST_COVERAGE_U16) {
        uint16_t *p = (uint16_t *)(void *)row;
        for (k = k0; k < k1; k++) p[k] = (uint16_t)v;
    } else {
        uint64_t *p = (uint64_t *)(void *)row;
        for (k = k0; k < k1; k++) p[k] = v;
    }
}

static void rast__ss_flush(rast__ss *ss)
{
    const rast__cov_out *o = ss->o;
    const int32_t y = o->clip.y0 + ss->row;
    unsigned char *row = rast__cov_row(o, y);
    int32_t w = o->clip.x1 - o->clip.x0, words = (w + 1) / 64 + 1, k, at = 0, count = 0;
    for (k = 0; k < words; k++) {
        uint64_t m = ss->mark[k];
        ss->mark[k] = 0;
        while (m) {
            int32_t i = k * 64 + (int32_t)rast__ctz64(m);
            m &= m - 1;
            rast__ss_run(o->format, row, at, i < w ? i : w, ss->level[count]);
            count += ss->d[i];
            ss->d[i] = 0;
            at = i;
        }
    }
    rast__ss_run(o->format, row, at, w, ss->level[0]);
    ss->next = ss->row + 1;
    rast__cov_row_done(o, y);
}

/* A run's end at clip-relative fine column x, sign sg (+1 where a run
 * starts, -1 where it ends): the count of pixel i = x / k changes by
 * sg (k - x mod k) and that of every pixel after it by sg k, i.e. d[i]
 * by the first and d[i + 1] by the rest. */
static inline void rast__ss_end(rast__ss *ss, int32_t x, int32_t sg)
{
    const int32_t kb = ss->kbits;
    int32_t i = x >> kb, f = x & (((int32_t)1 << kb) - 1);
    ss->d[i] += sg * (((int32_t)1 << kb) - f);
    ss->d[i + 1] += sg * f;
    ss->mark[i >> 6] |= (uint64_t)1 << (i & 63);
    ss->mark[(i + 1) >> 6] |= (uint64_t)1 << ((i + 1) & 63);
}

/* Fine row y's clip-relative run [x0, x1) (not empty) into the counts. */
static void rast__ss_put(rast__ss *ss, int32_t y, int32_t x0, int32_t x1)
{
    int32_t row = y >> ss->kbits;
    if (row != ss->row) {
        if (ss->row >= 0) rast__ss_flush(ss);
        rast__cov_zero_rows(ss->o, ss->o->clip.y0 + ss->next, ss->o->clip.y0 + row);
        ss->row = row;
    }
    rast__ss_end(ss, x0, 1);
    rast__ss_end(ss, x1, -1);
}

/* The run [l->x, r->x) of fine row y.  Runs that touch (a mesh's
 * triangles side by side under non-zero) are joined first: one run costs
 * the same whatever its length. */
static inline void rast__ss_span(void *user, int32_t y, const rast__edge *l, const rast__edge *r)
{
    rast__ss *ss = (rast__ss *)user;
    int32_t x0 = l->x, x1 = r->x;
    if (x0 < ss->fx0) x0 = ss->fx0;
    if (x1 > ss->fx1) x1 = ss->fx1;
    if (x0 >= x1) return;
    /* clip-relative from here: non-negative, so shifts divide */
    x0 -= ss->fx0;
    x1 -= ss->fx0;
    y -= ss->fy0;
    if (y == ss->py && x0 <= ss->px1) {
        if (x1 > ss->px1) ss->px1 = x1;
        return;
    }
    if (ss->px0 < ss->px1) rast__ss_put(ss, ss->py, ss->px0, ss->px1);
    ss->py = y;
    ss->px0 = x0;
    ss->px1 = x1;
}

size_t rast__cov_ss_scratch(uint32_t npoints, int32_t kbits, int32_t width, int32_t height)
{
    if ((int64_t)width << kbits > RAST_MAX_DIM || (int64_t)height << kbits > RAST_MAX_DIM)
        return (size_t)-1;
    return rast__size_add(
        rast__aet_scratch(npoints, width << kbits, height << kbits),
        rast__size_add(rast__align(rast__size_mul((size_t)width + 2, sizeof(int32_t))),
                       rast__size_add(rast__align(((size_t)(width + 1) / 64 + 1) * 8),
                                      ((size_t)1 << (2 * kbits)) * 8 + 8)));
}

rast_status rast__cov_ss(const rast_polygon *poly, uint32_t npoints, int32_t s,
                         int32_t kbits, rast_fill_rule rule, rast_sample sample,
                         const rast__cov_out *o, rast__arena *arena)
{
    rast__ss ss;
    rast__grid g;
    rast_rect fine;
    rast_status st;
    int32_t k, w = o->clip.x1 - o->clip.x0;
    st = rast__grid_init(&g, s, sample, RAST_ROUND_EXACT, RAST_BOUNDARY_EXACT);
    if (st != RAST_OK) return st;
    ss.o = o;
    ss.kbits = kbits;
    ss.row = -1;
    ss.next = 0;
    ss.py = ss.px0 = ss.px1 = 0;
    ss.d = (int32_t *)rast__take(arena, ((size_t)w + 2) * sizeof(int32_t));
    ss.mark = (uint64_t *)rast__take(arena, ((size_t)(w + 1) / 64 + 1) * 8);
    ss.level = (uint64_t *)rast__take(arena, (((size_t)1 << (2 * kbits)) + 1) * sizeof(uint64_t));
    if (!ss.d || !ss.mark || !ss.level) return RAST_E_SCRATCH;
    memset(ss.d, 0, ((size_t)w + 2) * sizeof(int32_t));
    memset(ss.mark, 0, ((size_t)(w + 1) / 64 + 1) * 8);
    /* count / k^2 is exactly count 2^(62 - 2 kbits) / 2^62 */
    for (k = 0; k <= (int32_t)1 << (2 * kbits); k++)
        ss.level[k] = rast__cov_level(o->format, (uint64_t)k << (62 - 2 * kbits));
    fine.x0 = ss.fx0 = o->clip.x0 * ((int32_t)1 << kbits);
    fine.y0 = ss.fy0 = o->clip.y0 * ((int32_t)1 << kbits);
    fine.x1 = ss.fx1 = o->clip.x1 * ((int32_t)1 << kbits);
    fine.y1 = o->clip.y1 * ((int32_t)1 << kbits);
    st = rast__aet_walk(poly, npoints, &g, rule, &fine, arena, rast__ss_span, NULL, &ss, NULL);
    if (st != RAST_OK) return st;
    if (ss.px0 < ss.px1) rast__ss_put(&ss, ss.py, ss.px0, ss.px1);
    if (ss.row >= 0) rast__ss_flush(&ss);
    rast__cov_zero_rows(o, o->clip.y0 + ss.next, o->clip.y1);
    return RAST_OK;
}

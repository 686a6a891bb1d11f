/*
 * coverage_ss.c - k x k supersampling ("ss2" .. "ss16"): the binary rule
 * (DESIGN section 1) on a grid k times finer, counted per pixel.
 *
 * The fine grid's pixel (I, J) is pixel (I / k, J / k) of the output and
 * its sample sits at ((I + o) / k, (J + o) / k): exactly sub-sample
 * (I mod k, J mod k) of section 1a.  The polygon arrives on that grid
 * already (coverage.c scales its vertices by k exactly); the exact AET
 * filler hands its spans row by row, and a row of counters (one output
 * row) adds them up.
 */
#include "coverage.h"

typedef struct rast__ss {
    const rast__cov_out *o;
    int32_t *d;       /* the output row's counts as differences: count[i] =
                         d[0] + ... + d[i], clip columns, one more at the end */
    uint64_t *level;  /* the value of each count 0..k^2 */
    int32_t kbits;
    int32_t row;  /* that row; INT32_MIN before the first */
    int32_t next; /* the first output row not written yet */
} rast__ss;

static void rast__ss_flush(rast__ss *ss)
{
    const rast__cov_out *o = ss->o;
    unsigned char *row = rast__cov_row(o, ss->row);
    int32_t k, w = o->clip.x1 - o->clip.x0, count = 0;
    for (k = 0; k < w; k++) {
        count += ss->d[k];
        ss->d[k] = 0;
        rast__cov_store(o->format, row, k, ss->level[count]);
    }
    ss->d[w] = 0;
    ss->next = ss->row + 1;
    rast__cov_row_done(o, ss->row);
}

/* Add n to the counts of clip columns [i0, i1). */
static void rast__ss_add(int32_t *d, int32_t i0, int32_t i1, int32_t n)
{
    d[i0] += n;
    d[i1] -= n;
}

static void rast__ss_span(void *user, int32_t y, int32_t x0, int32_t x1)
{
    rast__ss *ss = (rast__ss *)user;
    const int32_t K = (int32_t)1 << ss->kbits, cx0 = ss->o->clip.x0;
    int32_t r = (int32_t)rast__floordiv(y, K);
    int32_t i0 = (int32_t)rast__floordiv(x0, K), i1 = (int32_t)rast__floordiv(x1 - 1, K);
    if (r != ss->row) {
        if (ss->row != INT32_MIN) rast__ss_flush(ss);
        rast__cov_zero_rows(ss->o, ss->next, r);
        ss->row = r;
    }
    if (i0 == i1) {
        rast__ss_add(ss->d, i0 - cx0, i0 - cx0 + 1, x1 - x0);
        return;
    }
    rast__ss_add(ss->d, i0 - cx0, i0 - cx0 + 1, (i0 + 1) * K - x0);
    if (i0 + 1 < i1) rast__ss_add(ss->d, i0 + 1 - cx0, i1 - cx0, K);
    rast__ss_add(ss->d, i1 - cx0, i1 - cx0 + 1, x1 - i1 * K);
}

static void rast__ss_fopts(rast_fill_opts *fo, int32_t s, rast_fill_rule rule, rast_sample sample)
{
    memset(fo, 0, sizeof *fo);
    fo->algorithm = RAST_ALGO_AET;
    fo->rule = rule;
    fo->subpixel_bits = s;
    fo->sample = sample;
}

size_t rast__cov_ss_scratch(uint32_t npoints, int32_t kbits, int32_t width, int32_t height)
{
    rast_fill_opts fo;
    size_t aet = 0;
    rast__ss_fopts(&fo, 0, RAST_RULE_EVENODD, RAST_SAMPLE_CENTER);
    if ((int64_t)width << kbits > RAST_MAX_DIM || (int64_t)height << kbits > RAST_MAX_DIM)
        return (size_t)-1;
    rast_scratch_size(&fo, npoints, width << kbits, height << kbits, &aet);
    return rast__size_add(aet, rast__size_add(
                                   rast__align(rast__size_mul((size_t)width + 1, sizeof(int32_t))),
                                   ((size_t)1 << (2 * kbits)) * 8 + 8));
}

rast_status rast__cov_ss(const rast_polygon *poly, uint32_t npoints, int32_t s,
                         int32_t kbits, rast_fill_rule rule, rast_sample sample,
                         const rast__cov_out *o, rast__arena *arena)
{
    rast__ss ss;
    rast_fill_opts fo;
    rast_rect fine;
    rast_status st;
    int32_t k, w = o->clip.x1 - o->clip.x0;
    (void)npoints;
    ss.o = o;
    ss.kbits = kbits;
    ss.row = INT32_MIN;
    ss.next = o->clip.y0;
    ss.d = (int32_t *)rast__take(arena, ((size_t)w + 1) * sizeof(int32_t));
    ss.level = (uint64_t *)rast__take(arena, (((size_t)1 << (2 * kbits)) + 1) * sizeof(uint64_t));
    if (!ss.d || !ss.level) return RAST_E_SCRATCH;
    for (k = 0; k <= w; k++) ss.d[k] = 0;
    /* count / k^2 is exactly count 2^(62 - 2 kbits) / 2^62 */
    for (k = 0; k <= (int32_t)1 << (2 * kbits); k++)
        ss.level[k] = rast__cov_level(o->format, (uint64_t)k << (62 - 2 * kbits));
    fine.x0 = o->clip.x0 * ((int32_t)1 << kbits);
    fine.y0 = o->clip.y0 * ((int32_t)1 << kbits);
    fine.x1 = o->clip.x1 * ((int32_t)1 << kbits);
    fine.y1 = o->clip.y1 * ((int32_t)1 << kbits);
    rast__ss_fopts(&fo, s, rule, sample);
    st = rast_fill_polygon_spans(poly, &fo, &fine, rast__ss_span, &ss, arena->p, arena->left);
    if (st != RAST_OK) return st;
    if (ss.row != INT32_MIN) rast__ss_flush(&ss);
    rast__cov_zero_rows(o, ss.next, o->clip.y1);
    return RAST_OK;
}

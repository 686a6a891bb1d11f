/*
 * rows.c - the row machinery of the coverage engines (rows.h): each
 * edge built from a ring or a triangle, its steps from row to row and
 * from column to column, the rows the edges reach, the order of edges by
 * a key, and a finished row handed on to a painter (or a band of rows
 * cleared).  Moved here from entry/coverage.c, coverage_area.c and
 * coverage_acc.c unchanged (issue 33: the engines called each other in a
 * circle, and entry/ defined what they share).
 */
#include "rows.h"
#include "../base/bits.h"
/* Speed builds on x86 scan a finished row 16 bytes a step with SSE2
 * integer vectors (docs/c.md: SSE2, RAST_NO_SIMD), the rest byte by byte;
 * size builds and other machines byte by byte: the same runs. */
#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
#define RAST__ROWS_SSE2 1
#endif

void rast__cov_row_done(const rast__cov_out *o, int32_t y)
{
    const unsigned char *row = o->base;
    const rast__painter *p = o->paint;
    int32_t k = 0, w, x0;
    unsigned lim;
    if (!p) return;
    w = o->clip.x1 - o->clip.x0;
    x0 = o->clip.x0;
    /* Each run of levels not 0 to the levels entry; when the painter takes
     * full runs too, its long stretches of 255 go to the full entry.  One
     * pass, one test a pixel: levels 1..lim go on (lim 254 when a 255 must
     * stop the scan, else 255); `start` is the first column not handed on
     * yet. */
    lim = p->full ? 254u : 255u;
    while (k < w) {
        int32_t start;
#if defined(RAST__ROWS_SSE2)
        /* (the 0s 16 a step, to the first level not 0: a sparse row, a
         * line of text's, is mostly 0s) */
        for (; k + 16 <= w; k += 16) {
            const unsigned z = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(
                _mm_loadu_si128((const __m128i *)(const void *)(row + k)), _mm_setzero_si128()));
            if (z != 0xFFFFu) {
                k += rast__ctz64((uint64_t)(~z & 0xFFFFu));
                break;
            }
        }
#endif
        while (k < w && !row[k]) k++;
        start = k;
        for (;;) {
            int32_t f;
#if defined(RAST__ROWS_SSE2)
            { /* (16 a step to the first 0, or 255 when it stops the run) */
                const __m128i stop = _mm_set1_epi8((char)(lim == 254u ? 255 : 0));
                for (; k + 16 <= w; k += 16) {
                    const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(row + k));
                    const unsigned z = (unsigned)_mm_movemask_epi8(
                        _mm_or_si128(_mm_cmpeq_epi8(v, _mm_setzero_si128()), _mm_cmpeq_epi8(v, stop)));
                    if (z) {
                        k += rast__ctz64((uint64_t)z);
                        break;
                    }
                }
            }
#endif
            while (k < w && (unsigned)row[k] - 1u < lim) k++;
            if (k == w || row[k] != 255) break; /* a 255 stops it only for a full entry */
            f = k;
#if defined(RAST__ROWS_SSE2)
            for (; k + 16 <= w; k += 16) { /* (the 255s 16 a step) */
                const unsigned z = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(
                    _mm_loadu_si128((const __m128i *)(const void *)(row + k)), _mm_set1_epi8((char)-1)));
                if (z != 0xFFFFu) {
                    k += rast__ctz64((uint64_t)(~z & 0xFFFFu));
                    break;
                }
            }
#endif
            while (k < w && row[k] == 255) k++;
            if (k - f >= RAST__COV_FULL_MIN) {
                int32_t xs[2];
                if (f > start) p->levels(p->user, y, x0 + start, x0 + f, row + start);
                xs[0] = x0 + f;
                xs[1] = x0 + k;
                p->full(p->user, y, xs, 1);
                start = k;
            }
        }
        if (k > start) p->levels(p->user, y, x0 + start, x0 + k, row + start);
    }
}

void rast__cov_zero_rows(const rast__cov_out *o, int32_t y0, int32_t y1)
{
    static const int32_t size[3] = {1, 2, 8};
    size_t row;
    int32_t y;
    if (o->paint || y0 >= y1) return; /* nothing to hand on */
    row = (size_t)(o->clip.x1 - o->clip.x0) * (size_t)size[o->format];
    /* rows back to back (stride = the row: a whole array's, as the
     * binding's): one memset, not one a row (a small shape's coverage
     * into a 512 x 512 array cleared 500 rows each apart, issue 33) */
    if (o->stride == (ptrdiff_t)row) {
        memset(rast__cov_row(o, y0), 0, row * (size_t)(y1 - y0));
        return;
    }
    for (y = y0; y < y1; y++) memset(rast__cov_row(o, y), 0, row);
}

uint32_t rast__cov_edges_polygon(const rast_polygon *poly, rast__cedge *e)
{
    uint32_t k, i, base, n = 0;
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        const uint32_t size = poly->ring_sizes[k];
        const rast_point *pt = poly->points + base;
        rast_point a, b;
        int32_t yp; /* the ordinate of the vertex before a */
        if (!size) continue;
        /* a vertex and the next in registers from one edge to the next:
         * one vertex read an edge (a third of the reads, and of the index
         * wraps, of reading each edge's four) */
        yp = pt[size - 1].y;
        a = pt[0];
        b = pt[size > 1 ? 1 : 0];
        for (i = 0; i < size; i++) {
            uint32_t i2 = i + 2; /* (i + 2) mod size, without a division per edge */
            if (i2 >= size) i2 -= size;
            if (i2 >= size) i2 -= size;
            const rast_point c = pt[i2];
            if (a.y != b.y) {
                rast__cedge *ed = &e[n];
                /* the ring's edges before a and after b horizontal (or empty)? */
                const int32_t ha = yp == a.y, hb = c.y == b.y;
                ed->dir = rast__cov_edge_of(a, b, &ed->xt, &ed->yt, &ed->dx, &ed->dy);
                ed->hz = (ha ? RAST__HZ_TOP : 0) | (hb ? RAST__HZ_BOTTOM : 0);
                if (hb) { /* the horizontal run after b: its abscissae */
                    uint32_t q = i2;
                    ed->hz |= RAST__HZ_RUN;
                    ed->hx0 = ed->hx1 = b.x;
                    for (;;) {
                        int32_t x = pt[q].x;
                        if (x < ed->hx0) ed->hx0 = x;
                        if (x > ed->hx1) ed->hx1 = x;
                        q = q + 1 < size ? q + 1 : 0;
                        if (pt[q].y != b.y) break;
                    }
                }
                if (ed->dir < 0)
                    ed->hz = (ed->hz & RAST__HZ_RUN) | (hb ? RAST__HZ_TOP : 0) | (ha ? RAST__HZ_BOTTOM : 0);
                n++;
            }
            yp = a.y;
            a = b;
            b = c;
        }
    }
    return n;
}

/* Triangle k with its vertices in the order that makes its signed area
 * positive; 0 when it is degenerate (its edges would cancel). */
int rast__cov_tri(const rast_point *t, rast_point *v)
{
    int64_t cross = (int64_t)(t[1].x - t[0].x) * (t[2].y - t[0].y) -
                    (int64_t)(t[1].y - t[0].y) * (t[2].x - t[0].x);
    if (cross == 0) return 0;
    v[0] = t[0];
    v[1] = cross > 0 ? t[1] : t[2];
    v[2] = cross > 0 ? t[2] : t[1];
    return 1;
}

uint32_t rast__cov_edges_triangles(const rast_point *tris, uint32_t ntris, rast__cedge *e)
{
    uint32_t k, n = 0;
    uint32_t three = 3;
    for (k = 0; k < ntris; k++) {
        rast_point v[3];
        rast_polygon p;
        if (!rast__cov_tri(&tris[3 * k], v)) continue;
        p.points = v;
        p.ring_sizes = &three;
        p.nrings = 1;
        n += rast__cov_edges_polygon(&p, e + n);
    }
    return n;
}

/* The per-row and per-column steps of e (see rast__cedge). */
/* floor(n 2^60 / d) into *q, the remainder into *rem, for 0 <= n, 0 < d,
 * both < 2^28: two 64-bit divisions (n 2^30 < 2^58, and the first
 * remainder times 2^30 < 2^58); *q30, *rem30: floor(n 2^30 / d) and its
 * remainder on the way. */
static void rast__cov_step60(uint64_t n, uint64_t d, rast__i128 *q, uint64_t *rem, uint64_t *q30,
                             uint64_t *rem30)
{
    const uint64_t a = n << 30, r = (a % d) << 30;
    *q30 = a / d;
    *rem30 = a % d;
    *q = rast__i128_add(rast__i128_shl(rast__i128_u64(*q30), 30), rast__i128_u64(r / d));
    *rem = r % d;
}

/* e's steps for the exact way (2^-60 pixel): per row, xs + xsr/dy; per
 * column, ts + tsr/|dx|; its caches unset.  The column step of the quick
 * way (2^-30 pixel) comes with it: dy 2^30 / |dx| into *q30, *r30 (0 for
 * a vertical edge). */
static void rast__cov_steps_exact(rast__cedge *e, uint64_t *q30, uint64_t *r30)
{
    uint64_t adx = (uint64_t)(e->dx < 0 ? -(int64_t)e->dx : e->dx), rem;
    rast__i128 q;
    rast__cov_step60(adx, (uint64_t)e->dy, &q, &rem, q30, r30);
    if (e->dx >= 0) {
        e->xs = q;
        e->xsr = (int64_t)rem;
    } else if (rem) {
        e->xs = rast__i128_neg(rast__i128_add(q, rast__i128_u64(1)));
        e->xsr = e->dy - (int64_t)rem;
    } else {
        e->xs = rast__i128_neg(q);
        e->xsr = 0;
    }
    e->ts = rast__i128_u64(0);
    e->tsr = 0;
    *q30 = *r30 = 0;
    if (adx) { /* the column steps: dy 2^60 / |dx|, and dy 2^30 / |dx| */
        rast__cov_step60((uint64_t)e->dy, adx, &e->ts, &rem, q30, r30);
        e->tsr = (uint32_t)rem;
    }
    e->rowx = INT32_MIN;
    e->cX = INT64_MIN;
    e->crow = INT32_MIN;
    e->cn = -1;
}

/* e's steps for the quick way (2^-30 pixel), the column step q30, r30
 * given: per row, dx 2^30 / dy (|dx| <= 2^28); its steppers unset. */
static void rast__cov_steps_quick(rast__cedge *e, uint64_t q30, uint64_t r30)
{
    e->qts = (int64_t)q30;
    e->qtsr = (uint32_t)r30;
    rast__cov_qxstep(e->dx, e->dy, &e->qxs, &e->qxsr);
    e->qrow = INT32_MIN;
    e->qX = INT64_MIN;
}

static void rast__cov_steps(rast__cedge *e)
{
    uint64_t q30, r30;
    rast__cov_steps_exact(e, &q30, &r30);
    rast__cov_steps_quick(e, q30, r30);
}

void rast__cov_exact_steps_of(rast__cedge *e, const int32_t *ix, int32_t n, unsigned char *done)
{
    uint64_t q30, r30;
    int32_t k;
    for (k = 0; k < n; k++)
        if (!done[ix[k]]) {
            rast__cov_steps_exact(&e[ix[k]], &q30, &r30);
            done[ix[k]] = 1;
        }
}

void rast__cov_exact_steps(rast__cedge *e, uint32_t n)
{
    uint64_t q30, r30;
    uint32_t i;
    for (i = 0; i < n; i++) rast__cov_steps_exact(&e[i], &q30, &r30);
}

void rast__cov_qtop_set(rast__cedge *e, int32_t j, int32_t p, int32_t hq)
{
    rast__cov_qx_at(e->xt, e->yt, e->dx, e->dy, j, p, hq, &e->qx, &e->qxr);
    e->qrow = j;
}

void rast__cov_rows(rast__cedge *e, uint32_t n, int32_t p, int32_t *order, const rast__cov_out *o,
                    int32_t *ja, int32_t *jb, int quick)
{
    int64_t ymin = e[0].yt, ymax = (int64_t)e[0].yt + e[0].dy;
    uint32_t i;
    for (i = 0; i < n; i++) {
        order[i] = (int32_t)i;
        if (quick) { /* the column step by one division, not with the exact ones */
            rast__cov_qsteps(e[i].dx, e[i].dy, &e[i].qts, &e[i].qtsr, &e[i].qxs, &e[i].qxsr);
            e[i].qrow = INT32_MIN;
            e[i].qX = INT64_MIN;
        } else {
            rast__cov_steps(&e[i]);
        }
        if (e[i].yt < ymin) ymin = e[i].yt;
        if ((int64_t)e[i].yt + e[i].dy > ymax) ymax = (int64_t)e[i].yt + e[i].dy;
    }
    rast__cov_rows_reached(ymin, ymax, p, o, ja, jb);
}

void rast__cov_rows_reached(int64_t ymin, int64_t ymax, int32_t p, const rast__cov_out *o, int32_t *ja,
                            int32_t *jb)
{
    /* Rows whose strip the edges reach: floor(ymin / P) .. ceil(ymax / P). */
    ymin = rast__floordiv(ymin, p);
    ymax = rast__ceildiv(ymax, p);
    *ja = ymin > o->clip.y0 ? (int32_t)(ymin < o->clip.y1 ? ymin : o->clip.y1) : o->clip.y0;
    *jb = ymax < o->clip.y1 ? (int32_t)(ymax > *ja ? ymax : *ja) : o->clip.y1;
}

/* Below this many, an insertion sort (stable, the same order): a radix
 * pass clears and sums 256 counts, which a polygon of a few edges (one
 * small shape a call) does not repay. */
#define RAST__COV_SORT_FEW 24

void rast__cov_radix_sort(int32_t *ix, int32_t *tmp, const int32_t *key, uint32_t n)
{
    uint32_t cnt[256], i, d, sh, top = 0;
    if (n < RAST__COV_SORT_FEW) {
        for (i = 1; i < n; i++) {
            const int32_t x = ix[i];
            const uint32_t kx = (uint32_t)key[x];
            uint32_t q = i;
            for (; q > 0 && (uint32_t)key[ix[q - 1]] > kx; q--) ix[q] = ix[q - 1];
            ix[q] = x;
        }
        return;
    }
    int32_t *src = ix, *dst = tmp, *t;
    for (i = 0; i < n; i++) top |= (uint32_t)key[ix[i]];
    for (sh = 0; sh < 32 && (top >> sh); sh += 8) {
        uint32_t sum = 0;
        for (d = 0; d < 256; d++) cnt[d] = 0;
        for (i = 0; i < n; i++) cnt[((uint32_t)key[src[i]] >> sh) & 0xFF]++;
        for (d = 0; d < 256; d++) {
            uint32_t c = cnt[d];
            cnt[d] = sum;
            sum += c;
        }
        for (i = 0; i < n; i++) dst[cnt[((uint32_t)key[src[i]] >> sh) & 0xFF]++] = src[i];
        t = src; /* (each pass reads the other's result: no copy back) */
        src = dst;
        dst = t;
    }
    if (src != ix)
        for (i = 0; i < n; i++) ix[i] = src[i];
}

void rast__cov_count_sort(int32_t *ix, uint32_t *cnt, const int32_t *key, uint32_t n, uint32_t nkeys)
{
    uint32_t i;
    rast__cov_count_starts(cnt, key, n, nkeys);
    for (i = 0; i < n; i++) ix[cnt[key[i]]++] = (int32_t)i;
}

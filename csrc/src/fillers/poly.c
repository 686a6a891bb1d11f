/*
 * poly.c - code the polygon fillers of poly.h share: the visible box, the
 * per-row edge records, and one-bit-per-pixel mask rows.
 */
#include <string.h>

#include "poly.h"

/* The record sizes are part of the scratch contract in rastrum.h
 * (RAST_XSCAN_SCRATCH_BOUND, RAST_POINTWISE_SCRATCH_BOUND). */
typedef char rast__line_size_check[sizeof(rast__line) == 32 ? 1 : -1];

int rast__poly_box(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                   const rast_rect *clip, rast__box *box)
{
    int32_t b[4];

    if (npoints == 0) return 0;
    rast__pts_extent(poly->points, npoints, b);
    return rast__box_of(b[0], b[1], b[2], b[3], g, clip, box);
}

int rast__box_of(int32_t minx, int32_t maxx, int32_t miny, int32_t maxy, const rast__grid *g,
                 const rast_rect *clip, rast__box *box)
{
    int64_t r;
    /* Rows: those whose sample some edge crosses, ymin <= yc < ymax. */
    r = rast__row_at_or_after(2 * (int64_t)miny, g);
    box->row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)maxy, g);
    box->row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    /* Columns: see rast__box.  |2 x| < 2^28 with den 1: far inside the
     * bounds rast__cross_col states. */
    r = rast__cross_col(2 * (int64_t)minx, 1, g);
    box->col0 = r > clip->x0 ? (int32_t)r : clip->x0;
    r = rast__cross_col(2 * (int64_t)maxx, 1, g);
    box->col1 = r < clip->x1 ? (int32_t)r : clip->x1;
    return box->row0 < box->row1 && box->col0 < box->col1;
}

int32_t rast__poly_lines(const rast_polygon *poly, const rast__grid *g,
                         const rast__box *box, rast__line *lines)
{
    const rast_point *pts = poly->points;
    uint32_t k, i, base;
    int32_t n = 0;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t size = poly->ring_sizes[k];
        for (i = 0; i < size; i++) {
            rast_point a = pts[base + i], b = pts[base + (i + 1 == size ? 0 : i + 1)];
            rast__line *l = &lines[n];
            int64_t first, end;
            if (a.y == b.y) continue; /* horizontal edges never cross */
            l->dir = 1;
            if (a.y > b.y) {
                rast_point t = a;
                a = b;
                b = t;
                l->dir = -1;
            }
            first = rast__row_at_or_after(2 * (int64_t)a.y, g);
            end = rast__row_at_or_after(2 * (int64_t)b.y, g);
            if (first < box->row0) first = box->row0;
            if (end > box->row1) end = box->row1;
            if (first >= end) continue;
            /* Doubled coordinates below 2^28 and differences below 2^29 in
             * magnitude: all fit int32_t (see poly.h). */
            l->x0 = 2 * a.x;
            l->y0 = 2 * a.y;
            l->dx = 2 * (b.x - a.x);
            l->dy = 2 * (b.y - a.y);
            l->row = (int32_t)first;
            l->end = (int32_t)end;
            l->pad = 0;
            n++;
        }
    }
    return n;
}

/* ---- bit rows ---------------------------------------------------------------- */

void rast__bits_flip(uint64_t *row, int32_t a, int32_t b)
{
    int32_t ka, kb, k;
    uint64_t ma, mb;
    if (a >= b) return;
    ka = a / RAST__WORD_BITS;
    kb = (b - 1) / RAST__WORD_BITS;
    ma = ~(uint64_t)0 << (a % RAST__WORD_BITS);
    mb = ~(uint64_t)0 >> (RAST__WORD_BITS - 1 - (b - 1) % RAST__WORD_BITS);
    if (ka == kb) {
        row[ka] ^= ma & mb;
        return;
    }
    row[ka] ^= ma;
    for (k = ka + 1; k < kb; k++) row[k] = ~row[k];
    row[kb] ^= mb;
}

void rast__bits_spans(const uint64_t *row, int32_t nbits, int32_t col0, int32_t y,
                      rast__sink *sink)
{
    int32_t k, nw = (int32_t)rast__words(nbits), start = -1;
    for (k = 0; k < nw; k++) {
        uint64_t w = row[k];
        int32_t b = 0;
        /* Runs that go on through the whole word cost one comparison. */
        if (start < 0 ? w == 0 : w == ~(uint64_t)0) continue;
        for (;;) {
            uint64_t m = (start < 0 ? w : ~w) >> b;
            if (!m) break;
            b += rast__ctz64(m);
            if (start < 0) {
                start = k * RAST__WORD_BITS + b;
            } else {
                rast__sink_span(sink, y, col0 + start, col0 + k * RAST__WORD_BITS + b);
                start = -1;
            }
        }
    }
    if (start >= 0) rast__sink_span(sink, y, col0 + start, col0 + nbits);
}

/* ---- bit masks ------------------------------------------------------------------ */

size_t rast__mask_scratch(int32_t width, int32_t height)
{
    /* A whole number of words, so already a multiple of RAST_SCRATCH_ALIGN. */
    return rast__size_mul(rast__size_mul((size_t)height, rast__words(width)), sizeof(uint64_t));
}

rast_status rast__mask_begin(rast__mask *m, const rast_polygon *poly, uint32_t npoints,
                             const rast__grid *g, const rast_rect *clip, rast__arena *arena)
{
    size_t n;
    m->bits = 0;
    if (!rast__poly_box(poly, npoints, g, clip, &m->box)) return RAST_OK;
    m->bits = m->box.col1 - m->box.col0;
    m->words = rast__words(m->bits);
    n = (size_t)(m->box.row1 - m->box.row0) * m->words;
    m->w = (uint64_t *)rast__take(arena, n * sizeof(uint64_t));
    if (!m->w) return RAST_E_SCRATCH;
    memset(m->w, 0, n * sizeof(uint64_t));
    return RAST_OK;
}

void rast__mask_spans(const rast__mask *m, rast__sink *sink)
{
    int32_t j;
    for (j = m->box.row0; j < m->box.row1; j++)
        rast__bits_spans(rast__mask_row(m, j), m->bits, m->box.col0, j, sink);
    rast__sink_flush(sink);
}

size_t rast__pointwise_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)width;
    (void)height;
    return 2 * rast__align((size_t)npoints * sizeof(rast__line));
}

rast_status rast__pointwise_begin(const rast_polygon *poly, uint32_t npoints,
                                  const rast__grid *g, const rast_rect *clip,
                                  rast__arena *arena, rast__box *box, rast__line **lines,
                                  rast__line **row, int32_t *nlines)
{
    *nlines = -1;
    if (!rast__poly_box(poly, npoints, g, clip, box)) return RAST_OK;
    *lines = (rast__line *)rast__take(arena, (size_t)npoints * sizeof(rast__line));
    *row = (rast__line *)rast__take(arena, (size_t)npoints * sizeof(rast__line));
    if (!*lines || !*row) return RAST_E_SCRATCH;
    *nlines = rast__poly_lines(poly, g, box, *lines);
    return RAST_OK;
}

size_t rast__complement_scratch(uint32_t npoints, int32_t width, int32_t height)
{
    (void)npoints;
    return rast__mask_scratch(width, height);
}

rast_status rast__complement_fill(const rast_polygon *poly, uint32_t npoints,
                                  const rast__grid *g, const rast_rect *clip,
                                  rast__sink *sink, rast__arena *arena,
                                  rast__fence_fn fence)
{
    const rast_point *pts = poly->points;
    rast__mask m;
    uint32_t k, i, base;
    int32_t f;
    rast_status st;

    st = rast__mask_begin(&m, poly, npoints, g, clip, arena);
    if (st != RAST_OK || m.bits == 0) return st;
    f = fence ? fence(poly, npoints, g, &m) : m.bits;

    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            rast__edge ed;
            int32_t j;
            if (!rast__edge_setup(&ed, pts[base + i], pts[base + (i + 1 == n ? 0 : i + 1)], g,
                                  m.box.row0, m.box.row1))
                continue;
            for (j = ed.row; j < ed.end; j++, rast__edge_step(&ed)) {
                /* The crossing's column, clamped to the box [0, bits]
                 * (which changes no sample's count), then the run between
                 * it and the fence. */
                int32_t c = ed.x - m.box.col0;
                if (c < 0) c = 0;
                if (c > m.bits) c = m.bits;
                if (c < f)
                    rast__bits_flip(rast__mask_row(&m, j), c, f);
                else if (c > f)
                    rast__bits_flip(rast__mask_row(&m, j), f, c);
            }
        }
    }
    rast__mask_spans(&m, sink);
    return RAST_OK;
}

/*
 * poly.h - what the polygon fillers other than the AET share (issue 4):
 * the visible box of a polygon, a compact edge record for the fillers that
 * compute crossings from scratch (no DDA), one-bit-per-pixel mask rows, and
 * each filler's entry points for the registry (poly.c has the shared code).
 * Not installed.
 *
 * Ranges (DESIGN section 3).  Vertices satisfy |x|, |y| <= RAST_COORD_MAX =
 * 2^27 - 1 (fixed point), so the doubled internal coordinates satisfy
 * |X|, |Y| < 2^28 and every edge difference |dx|, |dy| < 2^29: all fit
 * int32_t, and every product of two of them (or of one of them and a sample
 * coordinate of the polygon's bounding box, itself below 2^28 + 2^17 in
 * magnitude) is below 2^58 + 2^47 < 2^59 in int64_t.
 */
#ifndef RAST_POLY_H
#define RAST_POLY_H

#include "../base/internal.h"
#include "../base/bits.h"

/* The part of the clip a polygon can own: rows [row0, row1) and columns
 * [col0, col1).  A sample left of every crossing of its row, or right of
 * every one, is outside under both rules (a closed ring crosses each row an
 * even number of times with directions summing to 0), and the first column
 * counting a crossing grows with its abscissa under both roundings; so the
 * columns are [first column counting min x, first column counting max x).
 * Returns 0 when the box is empty (then nothing is inside). */
typedef struct rast__box {
    int32_t row0, row1, col0, col1;
} rast__box;

int rast__poly_box(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                   const rast_rect *clip, rast__box *box);
/* The same box from the vertices' extent (min and max of x and y). */
int rast__box_of(int32_t minx, int32_t maxx, int32_t miny, int32_t maxy, const rast__grid *g,
                 const rast_rect *clip, rast__box *box);

/* A non-horizontal edge as the per-row (no DDA) fillers keep it, in
 * internal (doubled) units: (x0, y0) is the upper end (smaller y), dy > 0,
 * dir the direction of the original edge (+1 down, -1 up), rows
 * [row, end) the visible rows it crosses.  32 bytes. */
typedef struct rast__line {
    int32_t x0, y0, dx, dy;
    int32_t row, end, dir, pad;
} rast__line;

/* The edges of `poly` that cross at least one of rows [box->row0,
 * box->row1), into lines[] (room for npoints); returns how many. */
int32_t rast__poly_lines(const rast_polygon *poly, const rast__grid *g,
                         const rast__box *box, rast__line *lines);

/* ---- one bit per pixel ------------------------------------------------------
 * Mask rows of 64-bit words, bit b of word k standing for column
 * col0 + 64k + b.  Words rather than bytes: the complement of a run is a
 * handful of word XORs, and finding the next change of state is one
 * count-trailing-zeros per change. */
#define RAST__WORD_BITS 64

static inline size_t rast__words(int32_t bits)
{
    return ((size_t)bits + RAST__WORD_BITS - 1) / RAST__WORD_BITS;
}

/* (rast__ctz64: base/bits.h) */

/* Complement bits [a, b) of a row (0 <= a <= b <= the row's bits). */
void rast__bits_flip(uint64_t *row, int32_t a, int32_t b);

/* Hand the runs of set bits of a row of `nbits` bits (bits past nbits
 * clear) to the sink as spans of row y, shifted by col0. */
void rast__bits_spans(const uint64_t *row, int32_t nbits, int32_t col0, int32_t y,
                      rast__sink *sink);

/* A cleared bit mask over a box: rows box.row0.. of `words` words each.
 * Scratch: rast__mask_scratch(width, height) bytes for any box inside a
 * clip width x height.  The complement fillers (edgefill.c, fence.c) use
 * it: take the mask, complement runs of it, then hand its rows to the sink
 * with rast__mask_spans. */
typedef struct rast__mask {
    rast__box box;
    int32_t bits;  /* columns of the box: col1 - col0 */
    size_t words;  /* words per row */
    uint64_t *w;
} rast__mask;

size_t rast__mask_scratch(int32_t width, int32_t height);
/* RAST_OK with an empty box (m->bits == 0: nothing to fill), RAST_OK with
 * the cleared mask, or RAST_E_SCRATCH. */
rast_status rast__mask_begin(rast__mask *m, const rast_polygon *poly, uint32_t npoints,
                             const rast__grid *g, const rast_rect *clip, rast__arena *arena);
static inline uint64_t *rast__mask_row(const rast__mask *m, int32_t j)
{
    return m->w + (size_t)(j - m->box.row0) * m->words;
}
void rast__mask_spans(const rast__mask *m, rast__sink *sink);

/* ---- the fillers (one file each) -------------------------------------------- */
#define RAST__DECLARE_FILLER(name)                                                  \
    rast_status rast__##name##_fill(const rast_polygon *poly, uint32_t npoints,       \
                                    const rast__grid *g, rast_fill_rule rule,       \
                                    const rast_rect *clip, rast__sink *sink,        \
                                    rast__arena *arena);                            \
    size_t rast__##name##_scratch(uint32_t npoints, int32_t width, int32_t height)

RAST__DECLARE_FILLER(xscan);    /* xscan.c */
/* edgefill.c and fence.c: both the complement walk of poly.c, on the same
 * one-bit mask; they differ only in where a crossing's run ends: at the
 * box's right side (edge fill) or at the fence (fence.c's column). */
typedef int32_t (*rast__fence_fn)(const rast_polygon *poly, uint32_t npoints,
                                  const rast__grid *g, const rast__mask *m);
rast_status rast__complement_fill(const rast_polygon *poly, uint32_t npoints,
                                  const rast__grid *g, const rast_rect *clip,
                                  rast__sink *sink, rast__arena *arena,
                                  rast__fence_fn fence);
size_t rast__complement_scratch(uint32_t npoints, int32_t width, int32_t height);
rast_status rast__edgefill_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink, rast__arena *arena);
rast_status rast__fence_fill(const rast_polygon *poly, uint32_t npoints,
                             const rast__grid *g, rast_fill_rule rule,
                             const rast_rect *clip, rast__sink *sink, rast__arena *arena);
RAST__DECLARE_FILLER(edgeflag); /* edgeflag.c */
/* crossing.c and winding.c: point by point, with the same work memory (one
 * rast__line per vertex, twice: all edges, and those crossing the row) and
 * the same start, from poly.c. */
rast_status rast__crossing_fill(const rast_polygon *poly, uint32_t npoints,
                                const rast__grid *g, rast_fill_rule rule,
                                const rast_rect *clip, rast__sink *sink, rast__arena *arena);
rast_status rast__winding_fill(const rast_polygon *poly, uint32_t npoints,
                               const rast__grid *g, rast_fill_rule rule,
                               const rast_rect *clip, rast__sink *sink, rast__arena *arena);
size_t rast__pointwise_scratch(uint32_t npoints, int32_t width, int32_t height);
/* The bounding box, the edge lines and room for a row's lines.  *nlines is
 * -1 when the box is empty (nothing to do) and the status RAST_OK. */
rast_status rast__pointwise_begin(const rast_polygon *poly, uint32_t npoints,
                                  const rast__grid *g, const rast_rect *clip,
                                  rast__arena *arena, rast__box *box, rast__line **lines,
                                  rast__line **row, int32_t *nlines);

#endif /* RAST_POLY_H */

/*
 * coverage.h - anti-aliased coverage (DESIGN section 1a): what the
 * coverage entry points (coverage.c), the exact-area and accumulation
 * sweeps (coverage_area.c, coverage_acc.c), the test of a plain polygon
 * (coverage_plain.c) and supersampling (coverage_ss.c) share.
 * The row machinery they share is rows.h's; the exact cells cells.h's.
 * Not installed.
 */
#ifndef RAST_COVERAGE_H
#define RAST_COVERAGE_H

#include "rows.h"

/* ---- the methods -------------------------------------------------------- */

/* Exact area (accumulate = 0) or signed-area accumulation (accumulate =
 * 1) of the n edges e[] under `rule`, S = s, into o (a non-empty clip).
 * Work memory from `arena`: rast__cov_area_scratch(n, clip width). */
size_t rast__cov_area_scratch(uint32_t n, int32_t width);
/* 1 when the polygon's rings are simple, apart, and every face's winding
 * number is in {0, 1} (or every one in {0, -1}): then the accumulation of
 * its edges gives the exact coverage (coverage_plain.c).  Scratch from a
 * copy of the arena: about npoints * 36 + nrings * 20 bytes. */
int rast__cov_plain(const rast_polygon *poly, uint32_t npoints, rast__arena arena);
/* The same test part by part (coverage_plain.c: rings whose pixel boxes
 * share no pixel are apart), S = sb, on a polygon of two rings or more
 * whose nedges edges rast__cov_edges_polygon put in e[]: 1 when every
 * part is plain (the accumulation gives the exact coverage); else 0, and
 * the edges of the plain parts marked RAST__HZ_PLAIN (rast__cedge.hz: a
 * row of marked edges only may go by the accumulation).  Scratch from a
 * copy of the arena: about nrings * 64 bytes and 36 a point of the
 * largest part tested.  Not in size-optimised builds. */
#define RAST__HZ_PLAIN 0x40000000
int rast__cov_plain_parts(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb,
                          rast__cedge *e, uint32_t nedges);
/* The same, but -1 (not 0) when some parts are plain, and then the edges
 * of the other parts are marked RAST__HZ_BAD, not the plain ones
 * RAST__HZ_PLAIN (most often the fewer: text with a glyph or two whose
 * rings touch; the records are large, and marking every plain one cost a
 * pass over them all), for rast__cov_area_marked; and at the start of
 * arena's room (its first RAST__COV_RING_ROWS(nrings) bytes) a table of
 * three int32 a ring: its edges' first and last row (S = sb) and how many
 * edges it has in e[], as ~ that count when it is not plain, which
 * rast__cov_area_marked reads there (the same arena, nothing taken from
 * it between): its bands by the rings, not by reading every edge's
 * record; then two int32 a ring, its first and last column where its
 * winding number may not be 0 (rast__cov_parts_boxes). */
#define RAST__HZ_BAD 0x20000000
#define RAST__COV_RING_ROWS(nrings) ((size_t)(nrings) * 5 * sizeof(int32_t))
int rast__cov_parts_marked(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb,
                           rast__cedge *e, uint32_t nedges);
/* rast__cov_parts_marked in two steps: the test, from the points alone
 * (1, 0, or -1 and the table written, as above), and the marks, from the
 * table, of the edges rast__cov_edges_polygon made since (-1 marked; 0
 * when they are not the table's, nothing marked): so that a polygon whose
 * parts are all plain needs no edge records (rast__cov_acc_points). */
int rast__cov_parts_test(const rast_polygon *poly, uint32_t npoints, rast__arena arena, int32_t sb);
/* From rast__cov_parts_test's table (-1; its rings' pixel boxes: rows and
 * columns where each ring's winding number may not be 0), pixel boxes
 * bx[4 k ..] (first column, first row, last column, last row), at most
 * `most`, apart (no two share a pixel), that hold every ring that is not
 * plain and no pixel of a ring outside them: each ring's place in in[0 ..
 * nr): 0 outside every box, k + 1 in box k, RAST__PARTS_NONE a ring not
 * plain whose winding number is 0 off its edges (nothing to draw).
 * Returns how many boxes, or -1 (too many, the rings in them more than
 * half the edges, or no table).  So the coverage of the rings outside
 * the boxes is their accumulation (every pixel of theirs sees plain
 * parts only: docs/coverage.md), and in box k that of its rings alone. */
#define RAST__PARTS_NONE 255
#define RAST__PARTS_ROUNDS 8
int rast__cov_parts_boxes(rast__arena arena, uint32_t nr, unsigned char *in, int32_t *bx, int32_t most);
int rast__cov_parts_mark(rast__arena arena, uint32_t nr, rast__cedge *e, uint32_t nedges, int32_t mark);
/* The polygon with every two equal and opposite edges dropped (a map's
 * shared borders: the same winding number off the edges), its remaining
 * edges joined into rings, into *out (its arrays taken from *arena): 1
 * when that polygon is plain (rast__cov_plain), so that its accumulation
 * is the coverage of the original; 0 when not, or when fewer than a
 * quarter of the edges cancel, or fewer than 64 points (*arena then
 * partly taken: pass a copy).  Its room: about npoints * 7 bytes kept
 * from *arena, 29 more while it runs; the accumulation after it fits in
 * what "area" counts (rast__cov_area_scratch).  Not in size-optimised
 * builds. */
int rast__cov_borders(const rast_polygon *poly, uint32_t npoints, rast__arena *arena, rast_polygon *out);

rast_status rast__cov_area(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                           int accumulate, const rast__cov_out *o, rast__arena *arena);
/* "area" (accumulate = 0) of edges some of which rast__cov_parts_marked
 * marked RAST__HZ_BAD (the others of plain parts; its table of the
 * polygon's nrings rings at the start of arena's room): the rows that no
 * marked edge reaches in bands by rast__cov_acc (when rast__cov_acc_may),
 * the others by rast__cov_area (their unmarked edges marked
 * RAST__HZ_PLAIN for it); the same levels.  e[] is reordered.  Not in
 * size-optimised builds. */
rast_status rast__cov_area_marked(rast__cedge *e, uint32_t n, uint32_t nrings, int32_t s, rast_fill_rule rule,
                                  const rast__cov_out *o, rast__arena *arena);

/* Accumulation into uint8 or uint16 levels (coverage_acc.c), when
 * rast__cov_acc_may: as rast__cov_area(..., accumulate = 1, ...), in the
 * same scratch.  It sets each edge's steps by rast__cov_rows and sends a
 * row whose levels its 64-bit cells cannot decide to
 * rast__cov_acc_exact_row: the edges row[0..nrow) of row j, whole, the
 * exact way, into row j of o (handed on), with cleared cells cover[],
 * area[] (clip width each) and bits[] (a bit a column), left cleared.
 * It walks each edge over a band of RAST__ACC_BAND rows at a time, whose
 * cells rast__cov_area_scratch counts. */
#define RAST__ACC_BAND 4
int rast__cov_acc_may(const rast__cov_out *o, int32_t s);
rast_status rast__cov_acc(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                          const rast__cov_out *o, rast__arena *arena);
/* rast__cov_acc with coincident edges of opposite directions dropped
 * first (the same levels; a hash table's cost an edge): for a triangle
 * batch, or a polygon of many small rings (a mesh's inner edges). */
rast_status rast__cov_acc_shared(rast__cedge *e, uint32_t n, int32_t s, rast_fill_rule rule,
                                 const rast__cov_out *o, rast__arena *arena);
/* "accumulate" of a polygon (tris NULL; its rings skip[0 .. nskip) left
 * out, in increasing order) or of the ntris triangles tris[]
 * (as rast__cov_edges_triangles takes them), its edges' shared sides
 * dropped first when `shared` (rast__cov_acc_shared's; a polygon's, when
 * `shared` is RAST__ACC_LOOK, if a sample of its edges finds many of
 * them shared: a map's borders): rast__cov_acc of
 * the edges rast__cov_edges_polygon or rast__cov_edges_triangles would
 * make, read straight from the vertices (no rast__cedge written: the
 * walk's own records), in room, the edges' room (a rast__cedge a vertex),
 * the same levels.  Not in size-optimised builds (coverage_acc.c). */
#define RAST__ACC_LOOK 2
rast_status rast__cov_acc_points(const rast_polygon *poly, const uint32_t *skip, uint32_t nskip,
                                 const rast_point *tris, uint32_t ntris, int shared, int32_t s, rast_fill_rule rule,
                                 const rast__cov_out *o, rast__cedge *room, rast__arena *arena);
/* Row j of "area" by the accumulation, when the row is simple (see
 * coverage_acc.c) and its levels are certain: 1, written and handed on;
 * else 0, nothing handed on (the row may be written), the cells clean.
 * The edges row[0..nrow) of the row; runs[0..nrun) the edges (with
 * RAST__HZ_RUN, cancelled or not) whose runs lie strictly inside its strip;
 * acc[] (clip width + 1 words), bits[] and z[] (clip width words, left
 * cleared) the cleared cells of rast__cov_acc; own[] (clip width words)
 * the columns' marks, stamp a
 * number no other row of the call has (none is 0). */
int rast__cov_acc_area_row(rast__cedge *e, const int32_t *row, int32_t nrow, const int32_t *runs,
                           int32_t nrun, int32_t j, int32_t s, rast_fill_rule rule,
                           const rast__cov_out *o, uint64_t *acc, uint64_t *bits, uint32_t *z,
                           uint64_t *own, uint32_t stamp);
/* The second half of rast__cov_acc_area_row: row j's parts row[0..nrow),
 * their ends already in qa, qta, qb, qtb (rast__q_part's quick units),
 * added with their directions and the levels emitted, when the caller
 * knows the winding number on every pixel of the row takes two
 * consecutive values at most (rast__cov_row_groups: each group fast) and
 * that no column is touched by more than `most` parts (the window).
 * The same answers and cells. */
int rast__cov_acc_area_parts(rast__cedge *e, const int32_t *row, int32_t nrow, int32_t most, int32_t j, int32_t s,
                             rast_fill_rule rule, const rast__cov_out *o, uint64_t *acc, uint64_t *bits,
                             uint32_t *z);

/* "area" and "accumulate" of one small convex ring through a painter
 * (coverage_small.c), without the engines' setup.  rast__cov_small_fits:
 * 1 when poly is one ring of 3..RAST__CS_EDGES vertices whose pixel box
 * (into *box) is at most RAST__CS_DIM pixels a side, S = s <= 16.
 * rast__cov_small, for such a ring that is convex (o->paint set; turn
 * the way it turns, entry/coverage.c's rast__cov_convex's +1 or -1): 1 when
 * its rows inside o's clip are handed on, the levels the engines give;
 * 0 when a level lies too near a tie to be sure of it in 64 bits
 * (nothing handed on: the engines' turn).  Not in size-optimised builds. */
#define RAST__CS_DIM 24
#define RAST__CS_EDGES 16
int rast__cov_small_fits(const rast_polygon *poly, int32_t s, rast_rect *box);
int rast__cov_small(const rast_polygon *poly, int32_t s, int32_t turn, const rast__cov_out *o,
                    const rast_rect *box);
/* "ss2" and "ss4" (kb = 1, 2) of such a ring, S = s > kb, its samples
 * where `sample` puts them: handed on, the levels rast__cov_ss gives. */
void rast__cov_small_ss(const rast_polygon *poly, int32_t s, int32_t kb, rast_sample sample,
                        const rast__cov_out *o, const rast_rect *box);

/* Supersampling k x k (k = 2^kbits) of `poly` (a polygon in range, already
 * scaled or not: see coverage_ss.c) into o. */
size_t rast__cov_ss_scratch(uint32_t npoints, int32_t kbits, int32_t width, int32_t height);
rast_status rast__cov_ss(const rast_polygon *poly, uint32_t npoints, int32_t s,
                         int32_t kbits, rast_fill_rule rule, rast_sample sample,
                         const rast__cov_out *o, rast__arena *arena);

/* The same for the union of ntris triangles tris[3k..3k+2] on the fine
 * grid (turned one way, none degenerate): the edges left once those given
 * both ways cancel through the AET when they are few (a mesh's outline),
 * else each triangle walked on its own.  Scratch as
 * rast__cov_ss_scratch(3 ntris, ...). */
rast_status rast__cov_ss_tris(const rast_point *tris, uint32_t ntris, int32_t s, int32_t kbits,
                              rast_sample sample, const rast__cov_out *o, rast__arena *arena);

#endif /* RAST_COVERAGE_H */

/*
 * aet.h - the active edge table walk (seed 001, section 3.4), shared by
 * the AET filler (fillers/aet.c), the colour-interpolating polygon fill
 * (painters/shade_poly.c), supersampling (coverage/coverage_ss.c) and
 * the 64-bit polygon fill (entry/poly64.c): in base/, below all of them.  Static inline so that each user's span function is
 * inlined into its own copy of the loop: the plain fill pays no call per
 * span.  Not installed.
 *
 * A bucket edge table holds each edge under the first visible row it
 * crosses; the active edge table holds the edges crossing the current row,
 * sorted by their crossing column.  Each row: move the row's bucket into the
 * AET, pair the crossings into spans (even-odd) or sum their directions
 * (non-zero), then drop the edges that end and step the others one row down
 * with the exact DDA.  Insertion sort keeps the AET ordered: from one row to
 * the next the order changes only where edges cross, so it is nearly sorted.
 *
 * Edges that start on the same row join the AET together: the edge table
 * is grouped by first row (a counting sort, so a row's new edges are one
 * run of the table), the run is sorted by column in place (a heapsort when
 * it is long) and merged into the AET from the back.  That is
 * O(k log k + n) for k new edges and n active ones, where inserting them
 * one by one cost O(k n): 20,000 teeth of a comb hanging from one row took
 * ~10^9 record moves.  The AET's room stages the edges while the table is
 * grouped, so the scratch is what it was (RAST_AET_SCRATCH_BOUND).
 */
#ifndef RAST_AET_H
#define RAST_AET_H

#include "internal.h"

/* One inside run of row `row`: columns [l->x, r->x) (possibly empty),
 * bounded on the left by the crossing of edge l and on the right by that
 * of edge r.  Even-odd: the crossings 2k and 2k+1 of the row; non-zero:
 * the crossing where the winding number leaves 0 and the one where it
 * comes back.  An edge's `next` is its index in the walk's edge table
 * (see `src`); `order` may be NULL, `span` too (see the order hook).  Runs come row by row, in increasing x. */
typedef void (*rast__aet_span_fn)(void *user, int32_t row, const rast__edge *l,
                                  const rast__edge *r);

/* Called for each row with its active edges sorted by column, before the
 * row's runs are formed; it may reorder edges of EQUAL column (which
 * changes no pixel, only which edges bound the runs).  With `span` NULL
 * it does the row's work itself instead: it forms the row's runs, steps
 * every active edge to the next row (rast__edge_step) and leaves them
 * sorted by column again (rast__aet_sort, needed only where two changed
 * places), in one pass over them where it can; the walk then drops the
 * edges that end. */
typedef void (*rast__aet_order_fn)(void *user, int32_t row, rast__edge *aet, int32_t n);

/* The walk: every run of `poly` inside `clip` to `span`.  Scratch as
 * rast__aet_scratch.  With `src` (room for 2 * npoints) not NULL, the edge
 * of index k is the ring edge from vertex src[2k] to vertex src[2k+1]
 * (indices into poly->points). */
/* Insertion sort of the AET by crossing column.  The edges are held by
 * value: comparisons read consecutive records and stepping walks the array
 * in order; a record moves only when its edge crosses another. */
static inline void rast__aet_sort(rast__edge *aet, int32_t n)
{
    int32_t i, k;
    for (i = 1; i < n; i++) {
        if (aet[i - 1].x > aet[i].x) {
            rast__edge v = aet[i];
            for (k = i; k > 0 && aet[k - 1].x > v.x; k--) aet[k] = aet[k - 1];
            aet[k] = v;
        }
    }
}

/* Heapsort of e[0..n) by crossing column: in place, O(n log n) at worst. */
static inline void rast__aet_sift(rast__edge *e, int32_t root, int32_t n)
{
    rast__edge v = e[root];
    for (;;) {
        int32_t c = 2 * root + 1;
        if (c >= n) break;
        if (c + 1 < n && e[c + 1].x > e[c].x) c++;
        if (e[c].x <= v.x) break;
        e[root] = e[c];
        root = c;
    }
    e[root] = v;
}

static inline void rast__aet_heapsort(rast__edge *e, int32_t n)
{
    int32_t i;
    for (i = n / 2; i-- > 0;) rast__aet_sift(e, i, n);
    for (i = n - 1; i > 0; i--) {
        rast__edge t = e[0];
        e[0] = e[i];
        e[i] = t;
        rast__aet_sift(e, 0, i);
    }
}

/* Insertion sort of e[0..n) by column that gives up once it has moved
 * `budget` records and heapsorts instead (returning 0).  A row's new edges
 * come in the table's order (ring by ring), nearly sorted where rings
 * follow each other across the canvas (a paragraph's glyphs, a mesh's
 * cells), and there the heapsort's record moves were a sixth of the
 * fill; after 4 moves an edge on average the rest would be wasted (a
 * map's countries in no order across a row), and the heapsort bounds the
 * worst case, O(k log k) with the budget's O(k) moves. */
static inline int rast__aet_sort_within(rast__edge *e, int32_t n, int32_t budget)
{
    int32_t i, k;
    for (i = 1; i < n; i++) {
        if (e[i - 1].x > e[i].x) {
            rast__edge v = e[i];
            for (k = i; k > 0 && e[k - 1].x > v.x; k--) e[k] = e[k - 1];
            e[k] = v;
            budget -= i - k;
            if (budget < 0) {
                rast__aet_heapsort(e, n);
                return 0;
            }
        }
    }
    return 1;
}

/* Sort the k edges add[] by column (insertion; for many, insertion with
 * a budget and a heapsort past it, which bounds the worst case) and merge
 * them into the n sorted ones of aet[] (room for n + k), from the back;
 * an edge goes after active ones of equal column.  Returns n + k. */
static inline int32_t rast__aet_join(rast__edge *aet, int32_t n, rast__edge *add, int32_t k)
{
    const int32_t total = n + k;
    int32_t m = total;
#if defined(__OPTIMIZE_SIZE__)
    /* a build for size (firmware): no more code than the plain heapsort */
    if (k > 16)
        rast__aet_heapsort(add, k);
    else
        rast__aet_sort(add, k);
#else
    if (k <= 16)
        rast__aet_sort(add, k); /* few: insertion is quicker */
    else
        (void)rast__aet_sort_within(add, k, 4 * k); /* nearly sorted? */
#endif
    for (n--, k--; k >= 0;) {
        if (n >= 0 && aet[n].x > add[k].x)
            aet[--m] = aet[n--];
        else
            aet[--m] = add[k--];
    }
    return total;
}

#if !defined(__OPTIMIZE_SIZE__)
/* rast__aet_join for a run function's own row pass (span NULL, the
 * order hook's: supersampling), 16 < k <= RAST__AET_KEYS edges (fewer:
 * the records' insertion sort is quicker): what is sorted
 * is a key an edge, its column over its index (so that the order is the
 * stable one), not the 48-byte records, which each move once, into the
 * AET.  Sorting the records (insertion, or a heapsort past its budget)
 * was a sixteenth of a stroke outline's supersampled fill (a score of
 * short edges joining on most fine rows).  The heapsort may order edges
 * of equal column otherwise: the order hook's counts do not depend on
 * that order (rast__aet_order_fn); the run functions' users keep
 * rast__aet_join. */
#define RAST__AET_KEYS 64
/* The merge: the k edges add[(uint32_t)key[i]] (key[] in order of their
 * columns) into the n sorted ones of aet[] (room for n + k), from the
 * back, each after active ones of equal column.  Returns n + k. */
static inline int32_t rast__aet_merge_keys(rast__edge *aet, int32_t n, const rast__edge *add,
                                           const uint64_t *key, int32_t k)
{
    const int32_t total = n + k;
    int32_t m = total;
    for (n--, k--; k >= 0;) {
        const rast__edge *e = &add[(uint32_t)key[k]];
        if (n >= 0 && aet[n].x > e->x)
            aet[--m] = aet[n--];
        else {
            aet[--m] = *e;
            k--;
        }
    }
    return total;
}

static inline int32_t rast__aet_join_keys(rast__edge *aet, int32_t n, const rast__edge *add,
                                          int32_t k)
{
    uint64_t key[RAST__AET_KEYS];
    int32_t i;
    for (i = 0; i < k; i++) {
        const uint64_t v = ((uint64_t)((uint32_t)add[i].x ^ 0x80000000u) << 32) | (uint32_t)i;
        int32_t at = i;
        for (; at > 0 && key[at - 1] > v; at--) key[at] = key[at - 1];
        key[at] = v;
    }
    return rast__aet_merge_keys(aet, n, add, key, k);
}
#endif

/* The edge table grouped by first row: the nedges records aet[k] (each
 * with `row` its first row in [row0, row1), bucket[r - row0 + 1] holding
 * how many start on row r, bucket[0] = 0) placed into edges[] by row;
 * bucket[r - row0] is then where row r's run ends. */
static inline void rast__aet_group(rast__edge *edges, const rast__edge *aet, int32_t *bucket,
                                   int32_t nedges, int32_t row0, int32_t row1)
{
    int32_t j, k, run = 0;
    /* (the running sum in a register: through memory, each row waited
     * for the store of the one before) */
    for (j = 0; j <= row1 - row0; j++) {
        run += bucket[j];
        bucket[j] = run;
    }
    /* Placing an edge moves its row's start on: bucket[r] ends up where
     * row r's run ends. */
    for (k = 0; k < nedges; k++) edges[bucket[aet[k].row - row0]++] = aet[k];
}

/* The walk once the edge table is set up: nedges edge records in aet[]
 * (each with `row` its first row in [row0, row1)), bucket[r - row0 + 1]
 * holding how many start on row r (bucket[0] = 0).  Groups the table by
 * first row into edges[], then walks rows [row0, row1).  Shared by the
 * 32-bit walk below and the 64-bit one (poly64.c): after the setup the
 * walk is the same integers. */
static inline void rast__aet_sweep(rast__edge *edges, rast__edge *aet, int32_t *bucket,
                                   int32_t nedges, int32_t row0, int32_t row1,
                                   rast_fill_rule rule, rast__aet_span_fn span,
                                   rast__aet_order_fn order, void *user)
{
    int32_t j, first, nactive = 0, k;
    /* the first row after the current one that an active edge does not
     * cross: only then is the AET compacted (an edge ends on few rows, and
     * checking every edge on every row for it cost an eighth of a walk) */
    int32_t soonest = row1;
    rast__aet_group(edges, aet, bucket, nedges, row0, row1);
    for (j = row0, first = 0; j < row1; j++) {
        int32_t m, n, last = bucket[j - row0];

        /* Edges starting on this row join the AET: sort them, then merge
         * from the back (an edge goes after active ones of equal column). */
        if (last != first) {
            for (k = first; k < last; k++)
                if (edges[k].end < soonest) soonest = edges[k].end;
#if !defined(__OPTIMIZE_SIZE__)
            if (!span && last - first > 16 && last - first <= RAST__AET_KEYS)
                nactive = rast__aet_join_keys(aet, nactive, &edges[first], last - first);
            else
#endif
                nactive = rast__aet_join(aet, nactive, &edges[first], last - first);
            first = last;
        }
        if (nactive == 0) continue;
        if (order) order(user, j, aet, nactive);

        if (span) {
            /* Spans: sample i is inside iff the crossings with x <= i make
             * it so. */
            if (rule == RAST_RULE_EVENODD) {
                for (n = 0; n + 1 < nactive; n += 2) span(user, j, &aet[n], &aet[n + 1]);
            } else {
                int32_t w = 0, start = 0;
                for (n = 0; n < nactive; n++) {
                    if (w == 0) start = n;
                    w += aet[n].dir;
                    if (w == 0) span(user, j, &aet[start], &aet[n]);
                }
            }
            /* Step every edge to the next row. */
            for (n = 0; n < nactive; n++) rast__edge_step(&aet[n]);
        }

        /* Drop the edges that end here (few rows have any, so the
         * compaction is a separate, rare pass, and finds the next such
         * row). */
        if (soonest == j + 1) {
            /* the edges before the first that ends stay where they are
             * (copying each onto itself cost a percent of a map's
             * supersampled walk), but in a build for size (flash) */
#if defined(__OPTIMIZE_SIZE__)
            for (soonest = row1, m = n = 0; n < nactive; n++) {
#else
            for (soonest = row1, n = 0; n < nactive && aet[n].end != j + 1; n++)
                if (aet[n].end < soonest) soonest = aet[n].end;
            for (m = n; n < nactive; n++) {
#endif
                if (aet[n].end == j + 1) continue;
                if (aet[n].end < soonest) soonest = aet[n].end;
                aet[m++] = aet[n];
            }
            nactive = m;
        }
        if (span) rast__aet_sort(aet, nactive);
    }
}

/* The walk's tables out of the arena: the edge table and the AET (an edge
 * record per vertex each) and the buckets of rows [row0, row1], cleared.
 * 0 when the arena is too small. */
static inline int rast__aet_tables(rast__arena *arena, uint32_t npoints, int32_t row0,
                                   int32_t row1, rast__edge **edges, rast__edge **aet,
                                   int32_t **bucket)
{
    *edges = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    *aet = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    *bucket = (int32_t *)rast__take(arena, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));
    if (!*edges || !*aet || !*bucket) return 0;
    memset(*bucket, 0, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));
    return 1;
}

/* The walk's edge setup, rast__edge_setup: inline (the call and its
 * by-value points were a fifth of the setup's instructions on a paragraph
 * of text), its ends ordered without a branch (which way an edge goes is
 * a coin toss: the inlined branch mispredicted on 7,000 of the
 * paragraph's 34,000 edges), except in a build for size, where the
 * out-of-line copy saves code (as rast__edge_setup_tri, internal.h).
 * The rows of its ends come known (ra, rb: rast__row_at_or_after of each
 * end's y), which the walk finds once a vertex, not twice (a vertex ends
 * two edges; finding them was a twelfth of a paragraph's fill).  Equal
 * rows: the edge crosses none (a horizontal edge, and the many short ones
 * of text that stay between two row centres), told before anything else
 * is done. */
#if !defined(__OPTIMIZE_SIZE__)
static inline int rast__aet_edge_rows(rast__edge *ed, const rast_point *pa, const rast_point *pb,
                                      int32_t ra, int32_t rb, const rast__grid *g, int32_t row0,
                                      int32_t row1)
{
    /* (rows grow with y: different rows, the same order as the ends' y) */
    const int32_t down = ra < rb;
    /* (pointer arithmetic, which compilers do not turn into a branch) */
    const ptrdiff_t swap = (pb - pa) & -(ptrdiff_t)(1 - down);
    const rast_point *top = pa + swap, *bottom = pb - swap;
    int32_t first = down ? ra : rb, end = down ? rb : ra;
    if (ra == rb) return 0;
    if (first < row0) first = row0;
    if (end > row1) end = row1;
    if (first >= end) return 0;
    rast__edge_start_inline(ed, *top, *bottom, down ? 1 : -1, first, end, g);
    return 1;
}
#endif

/* The walk's tables (rast__aet_prepare): the edge records, set up in
 * aet[0..nedges) (`row` each one's first row in [row0, row1)), the room
 * for the edge table (edges[], npoints records, free until the sweep) and
 * the buckets (bucket[r - row0 + 1]: how many edges start on row r); and,
 * except in a build for size, the vertices' least and greatest x (minx, maxx),
 * which the fill by winding deltas (fillers/aet.c) wants. */
typedef struct rast__aet_tab {
    rast__edge *edges, *aet;
    int32_t *bucket;
    int32_t nedges, row0, row1;
    int32_t minx, maxx;
} rast__aet_tab;

#if defined(__OPTIMIZE_SIZE__)
/* The walk's setup: the visible rows and the edge records of `poly`
 * (src as rast__aet_walk's).  RAST_OK with t->row0 >= t->row1 when no
 * visible row is crossed (nothing to walk), RAST_E_SCRATCH when the arena
 * is too small. */
static inline rast_status rast__aet_prepare(const rast_polygon *poly, uint32_t npoints,
                                            const rast__grid *g, const rast_rect *clip,
                                            rast__arena *arena, int32_t *src, rast__aet_tab *t)
{
    const rast_point *pts = poly->points;
    rast__edge *edges, *aet;
    int32_t *bucket;
    int32_t row0, row1, nedges = 0;
    uint32_t i, k, base;
    int32_t miny, maxy;
    int64_t r;

    t->row0 = t->row1 = 0;
    if (npoints == 0) return RAST_OK;

    /* Visible rows: the clip's rows that the polygon's y extent reaches. */
    miny = maxy = pts[0].y;
    for (i = 1; i < npoints; i++) {
        if (pts[i].y < miny) miny = pts[i].y;
        if (pts[i].y > maxy) maxy = pts[i].y;
    }
    r = rast__row_at_or_after(2 * (int64_t)miny, g);
    row0 = r > clip->y0 ? (int32_t)r : clip->y0;
    r = rast__row_at_or_after(2 * (int64_t)maxy, g);
    row1 = r < clip->y1 ? (int32_t)r : clip->y1;
    if (row0 >= row1) return RAST_OK;

    if (!rast__aet_tables(arena, npoints, row0, row1, &edges, &aet, &bucket))
        return RAST_E_SCRATCH;

    /* The edge table, grouped by first visible row: set the edges up in
     * the AET's room (`next` holding each edge's index, see `src`), count
     * them per row, and place each row's run at bucket[row] (the counts'
     * running sum). */
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        uint32_t n = poly->ring_sizes[k];
        for (i = 0; i < n; i++) {
            rast__edge *ed = &aet[nedges];
            rast_point a = pts[base + i];
            rast_point b = pts[base + (i + 1 == n ? 0 : i + 1)];
            if (rast__edge_setup(ed, a, b, g, row0, row1)) {
                if (src) {
                    src[2 * nedges] = (int32_t)(base + i);
                    src[2 * nedges + 1] = (int32_t)(base + (i + 1 == n ? 0 : i + 1));
                }
                ed->next = nedges++;
                bucket[ed->row - row0 + 1]++;
            }
        }
    }
    t->edges = edges;
    t->aet = aet;
    t->bucket = bucket;
    t->nedges = nedges;
    t->row0 = row0;
    t->row1 = row1;
    return RAST_OK;
}
#else
/* The walk's setup in two steps.  First the rows: the room for the edge
 * table and the AET (an edge record per vertex each: t->edges, t->aet),
 * each vertex's row (rast__row_at_or_after of its y) in the edge table's
 * room (t->edges as int32_t[npoints]: the rows the edges' setup reads),
 * the visible rows t->row0, t->row1 and the vertices' least and greatest
 * x.  RAST_OK with t->row0 >= t->row1 when no visible row is crossed
 * (nothing to walk), RAST_E_SCRATCH when the arena is too small. */
static inline rast_status rast__aet_prepare_rows(const rast_polygon *poly, uint32_t npoints,
                                                 const rast__grid *g, const rast_rect *clip,
                                                 rast__arena *arena, rast__aet_tab *t)
{
    const rast_point *pts = poly->points;
    /* The grid in a local: the int32 stores of the rows might alias the
     * caller's, which made the loop reload it for every vertex. */
    const rast__grid gl = *g;
    int32_t *vrow, lo, hi, minx, maxx;
    uint32_t i;

    t->row0 = t->row1 = 0;
    t->edges = t->aet = NULL; /* (set on every path: gcc -O1 could not tell) */
    t->bucket = NULL;
    t->minx = t->maxx = 0;
    if (npoints == 0) return RAST_OK;
    t->edges = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    t->aet = (rast__edge *)rast__take(arena, (size_t)npoints * sizeof(rast__edge));
    if (!t->edges || !t->aet) return RAST_E_SCRATCH;
    vrow = (int32_t *)(void *)t->edges;

    /* Visible rows: the clip's rows that the polygon's y extent reaches
     * (rows grow with y: the lowest vertex row is the top one's). */
    lo = hi = vrow[0] = (int32_t)rast__row_at_or_after(2 * (int64_t)pts[0].y, &gl);
    minx = maxx = pts[0].x;
    for (i = 1; i < npoints; i++) {
        int32_t v = (int32_t)rast__row_at_or_after(2 * (int64_t)pts[i].y, &gl);
        vrow[i] = v;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
        if (pts[i].x < minx) minx = pts[i].x;
        if (pts[i].x > maxx) maxx = pts[i].x;
    }
    t->minx = minx;
    t->maxx = maxx;
    t->row0 = lo > clip->y0 ? lo : clip->y0;
    t->row1 = hi < clip->y1 ? hi : clip->y1;
    return RAST_OK;
}

/* Then the edge records (rows as rast__aet_prepare_rows left them, t->row0
 * < t->row1): set up in t->aet[0 .. t->nedges) (`next` each one's index,
 * see `src`), and the buckets, bucket[r - row0 + 1] how many start on row
 * r.  RAST_E_SCRATCH when the arena is too small for the buckets. */
static inline rast_status rast__aet_prepare_edges(const rast_polygon *poly, const rast__grid *g,
                                                  rast__arena *arena, int32_t *src,
                                                  rast__aet_tab *t)
{
    const rast_point *pts = poly->points;
    const rast__grid gl = *g; /* (as above: not reloaded every edge) */
    const int32_t *vrow = (const int32_t *)(const void *)t->edges;
    rast__edge *const aet = t->aet;
    const int32_t row0 = t->row0, row1 = t->row1;
    int32_t *bucket, nedges = 0;
    uint32_t k, base;

    bucket = (int32_t *)rast__take(arena, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));
    if (!bucket) return RAST_E_SCRATCH;
    memset(bucket, 0, ((size_t)(row1 - row0) + 1) * sizeof(int32_t));

    /* The edge table, grouped by first visible row: set the edges up in
     * the AET's room (`next` holding each edge's index, see `src`), count
     * them per row, and place each row's run at bucket[row] (the counts'
     * running sum). */
    for (k = 0, base = 0; k < poly->nrings; base += poly->ring_sizes[k], k++) {
        /* edge ia -> ib: the next vertex, or the ring's first after its
         * last; an edge between two vertices of one row crosses none (most
         * of a paragraph's), told from the rows alone */
        uint32_t ia, ib;
        const uint32_t stop = base + poly->ring_sizes[k];
        for (ia = base, ib = base + 1; ia < stop; ia++, ib++) {
            rast__edge *ed = &aet[nedges];
            if (ib == stop) ib = base;
            if (vrow[ia] == vrow[ib]) continue;
            if (rast__aet_edge_rows(ed, &pts[ia], &pts[ib], vrow[ia], vrow[ib], &gl, row0, row1)) {
                if (src) {
                    src[2 * nedges] = (int32_t)ia;
                    src[2 * nedges + 1] = (int32_t)ib;
                }
                ed->next = nedges++;
                bucket[ed->row - row0 + 1]++;
            }
        }
    }
    t->bucket = bucket;
    t->nedges = nedges;
    return RAST_OK;
}

/* The walk's setup: the visible rows and the edge records of `poly`
 * (src as rast__aet_walk's): the two steps above.  RAST_OK with t->row0
 * >= t->row1 when no visible row is crossed (nothing to walk),
 * RAST_E_SCRATCH when the arena is too small. */
static inline rast_status rast__aet_prepare(const rast_polygon *poly, uint32_t npoints,
                                            const rast__grid *g, const rast_rect *clip,
                                            rast__arena *arena, int32_t *src, rast__aet_tab *t)
{
    rast_status st = rast__aet_prepare_rows(poly, npoints, g, clip, arena, t);
    if (st != RAST_OK || t->row0 >= t->row1) return st;
    return rast__aet_prepare_edges(poly, g, arena, src, t);
}
#endif

/* ---- shared edges cancel (base/edge.c) ----------------------------------------
 * The winding number of a sample is the sum of the edges' parts, and an
 * edge a->b and an edge b->a (two cells of a mesh on either side of their
 * common edge) cross the same rows at the same columns (the DDA of each
 * runs from the same upper end to the same lower one) in opposite
 * directions: their parts cancel at every sample, and neither need be
 * walked.  A segment from its upper end to its lower one (by y, then x),
 * n the times it is in the polygon that way less the other way. */
typedef struct rast__seg {
    rast_point a, b;
    int32_t n;
} rast__seg;

/* The edges of the rings `pts` (npoints vertices in rings of
 * ring_sizes[], or, ring_sizes NULL, triangles) as segments, equal ones
 * summed, out of the arena: returns m, the segments left in
 * (*seg)[0 .. m), crossing edges only (a horizontal one crosses no row),
 * n of each not 0 (even-odd, `evenodd`: n mod 2 with its sign, +-1) and
 * *copies the sum of their |n| (the edges to walk), when at most half of
 * the edges are left so; else -1, the arena as it was (also when it is
 * too small, or when a quarter of the way fewer than one edge in 64 has
 * met another).  Memory: npoints segments (20 bytes) and a table of
 * indices of at most 16 bytes a vertex.  Used by the binary fill (builds
 * for speed) and supersampling. */
int32_t rast__segs_cancel(const rast_point *pts, const uint32_t *ring_sizes, uint32_t npoints,
                          int evenodd, rast__arena *arena, rast__seg **seg, uint32_t *copies);

/* seg[0 .. m) (rast__segs_cancel's) set up as a walk's edge table between
 * rows row0 and row1: |n| edges of each, turned as n says, into aet[]
 * (room for *copies) and counted into bucket[] (rast__aet_tables');
 * returns how many cross a row there. */
int32_t rast__segs_edges(const rast__seg *seg, int32_t m, const rast__grid *g, int32_t row0,
                         int32_t row1, rast__edge *aet, int32_t *bucket);

static inline rast_status rast__aet_walk(const rast_polygon *poly, uint32_t npoints,
                                         const rast__grid *g, rast_fill_rule rule,
                                         const rast_rect *clip, rast__arena *arena,
                                         rast__aet_span_fn span, rast__aet_order_fn order,
                                         void *user, int32_t *src)
{
    rast__aet_tab t;
    rast_status st = rast__aet_prepare(poly, npoints, g, clip, arena, src, &t);
    if (st != RAST_OK || t.row0 >= t.row1) return st;
    rast__aet_sweep(t.edges, t.aet, t.bucket, t.nedges, t.row0, t.row1, rule, span, order, user);
    return RAST_OK;
}

#if !defined(__OPTIMIZE_SIZE__)
/* ---- winding deltas in byte counters ----------------------------------------
 * Edge *d's direction `dir` (1 under even-odd) added at each of its
 * crossings of the band of rows [j0, j1), counters from buf (stride bytes
 * a row, columns relative to col0); `rows`: its rows cut to the band (else
 * they are inside it); `cut`: its columns cut to [0, bits] (a crossing left
 * of them counts for every column of the row, one right of them for none;
 * else they are inside them).  Its DDA is left on row j1 when it goes on
 * past it (not stepped past its last row: nothing reads it).  The binary
 * fill's deltas (fillers/aet.c, rows of pixels) and supersampling's
 * (coverage/coverage_ss.c, rows of samples, the record a copy in locals
 * there) both walk their edges here.  (Not in a build for size: neither
 * takes the deltas there.) */
static inline void rast__delta_walk(rast__edge *d, unsigned char *buf, int32_t j0, int32_t j1,
                                    int32_t stride, int32_t col0, int32_t bits, unsigned char dir,
                                    int rows, int cut)
{
    const int32_t a = rows && d->row < j0 ? j0 : d->row, b = rows && d->end > j1 ? j1 : d->end;
    unsigned char *p = buf + (ptrdiff_t)(a - j0) * stride;
    int32_t j;
    if (a >= b) return;
    d->x -= col0; /* (the counters' columns while it walks) */
    for (j = a;;) {
        int32_t c = d->x;
        if (cut) {
            c = c < 0 ? 0 : c;
            c = c > bits ? bits : c;
        }
        p[c] = (unsigned char)(p[c] + dir);
        if (++j == b) break;
        p += stride;
        rast__edge_step(d);
    }
    if (b < d->end) rast__edge_step(d);
    d->x += col0;
}
#endif

#if defined(__SSE2__) && !defined(RAST_NO_SIMD) && !defined(__OPTIMIZE_SIZE__)
#include <emmintrin.h> /* (integer vectors only: every x86-64 has them) */
/* 16 byte counters of winding deltas v as their running sums along the
 * row (lane i: v[0] + ... + v[i], modulo 2^8, by four shifted adds); and
 * those at c, cleared, so summed: the binary fill's rows (fillers/aet.c)
 * and supersampling's fine rows (coverage/coverage_ss.c) both start here. */
static inline __m128i rast__delta_sum16(__m128i v)
{
    v = _mm_add_epi8(v, _mm_slli_si128(v, 1));
    v = _mm_add_epi8(v, _mm_slli_si128(v, 2));
    v = _mm_add_epi8(v, _mm_slli_si128(v, 4));
    return _mm_add_epi8(v, _mm_slli_si128(v, 8));
}

static inline __m128i rast__delta_take16(unsigned char *c)
{
    const __m128i v = _mm_loadu_si128((const __m128i *)(void *)c);
    _mm_storeu_si128((__m128i *)(void *)c, _mm_setzero_si128());
    return rast__delta_sum16(v);
}
#endif

#endif /* RAST_AET_H */

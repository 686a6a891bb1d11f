/*
 * small.c - a filler for the many small polygons of a batch (masks and
 * instance labels: 10,000 polygons of 6..40 vertices, a few dozen rows
 * each).
 *
 * The AET pays per row for keeping its table: joining new edges, stepping
 * every active edge through the table, re-sorting, compacting.  For a
 * polygon of few edges it is cheaper to walk edge by edge: each edge steps
 * its exact DDA (the AET's, rast__edge) down its rows, dropping its
 * crossing into its row's slots; then each row sorts its few crossings (two
 * for most rows of a simple polygon) and forms its runs under the rule.
 * The crossings are the AET's to the bit, so are the runs.
 *
 * A crossing is kept as one key: its first counting column, clamped to the
 * clip's columns [c0, c1], less c0, times 2, plus 1 for a downward edge.
 * Clamping changes no visible sample: sample i in [c0, c1) counts a
 * crossing at column x (x <= i) iff it counts the clamped one.  Keys of
 * equal column sort their directions -1 first, which changes no sample's
 * winding number either (the sum at each column is taken over all of
 * them).
 *
 * Scratch: the edge records (one per vertex), then bands of rows, each row
 * a count and one slot per edge; the rows are taken in bands as tall as
 * the scratch allows (the AET's own scratch gives bands of at least eight
 * rows), the edges' DDAs carried from one band to the next.
 */
#include "small.h"

int rast__small_fill(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                     rast_fill_rule rule, const rast_rect *clip, rast_batch_span_fn span,
                     void *user, uint32_t index, void *scratch, size_t bytes)
{
    return rast__small_walk(poly, npoints, g, rule, clip, span, user, index, scratch, bytes);
}

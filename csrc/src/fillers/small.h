/*
 * small.h - the batch's filler for polygons of few vertices (small.c).
 * Not installed; used only by the polygon batch (entry/batch.c).
 */
#ifndef RAST_SMALL_H
#define RAST_SMALL_H

#include "../base/internal.h"

/* Polygons of at most this many vertices take the small filler. */
#define RAST__SMALL_POINTS 256

/* Fill `poly` (npoints vertices, checked) in `clip` (non-empty, at most
 * RAST_MAX_DIM columns wide: the span clip, or the polygon's box within
 * it; the rows drawn are those its edges cross within the clip's, so the
 * box need not be measured first) under `rule` with the exact boundary, as polygon
 * `index` of a batch: each run to span(user, index, y, x0, x1), the runs
 * the AET filler gives through a sink (maximal runs, rows top to bottom,
 * in increasing x).  `scratch` (aligned, `bytes` long)
 * as the AET filler's for the polygon's box is always enough.  Returns 0, having
 * done nothing, when npoints is past RAST__SMALL_POINTS or the scratch is
 * too small; 1 when filled. */
int rast__small_fill(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                     rast_fill_rule rule, const rast_rect *clip, rast_batch_span_fn span,
                     void *user, uint32_t index, void *scratch, size_t bytes);

#endif /* RAST_SMALL_H */

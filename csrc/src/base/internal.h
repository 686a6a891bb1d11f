/*
 * internal.h - what the fillers, painters and the dispatcher share.
 * Not installed; nothing here is part of the API.
 *
 * Internal units.  A vertex (x, y) given in 1/2^S pixel is doubled on entry,
 * so one pixel is UNIT = 2^(S+1) internal units and a sample offset of 1/2
 * pixel is the integer 2^S.  Sample (i, j) then sits at
 * (i*UNIT + OFF, j*UNIT + OFF) with OFF = 2^S (centres) or 0 (corners), and
 * every comparison of DESIGN section 1 is between integers.
 */
#ifndef RAST_INTERNAL_H
#define RAST_INTERNAL_H

#include <string.h>

#define RAST_STATIC_LINKING_ONLY /* the library's own files see the whole header */
#include "rastrum.h"
#include "config.h"

/* A coordinate in internal units: a rast_fixed doubled, 2^(S+1) to the
 * pixel (|value| < 2^28 for a vertex, differences < 2^29), as FreeType's
 * ftgrays.c names its TPos.  rast__dpos64 is the 64-bit vertices' (a
 * rast_fixed64 doubled, |value| < 2^62). */
typedef int32_t rast__dpos;
typedef int64_t rast__dpos64;

/* For a filler's row loop and its setup: inlined whatever the compiler's
 * weighing of code size says, where it can be told (GCC, clang), so that
 * the walk's state stays in registers (a call taking it by pointer puts
 * it in memory, and a small triangle pays ~5% for it).  Not in a build
 * for size (-Os, firmware). */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE_SIZE__)
#define RAST__HOT static inline __attribute__((always_inline))
#else
#define RAST__HOT static inline
#endif

/* Kept out of line (GCC, clang): a loop whose state should stay in
 * registers, apart from its caller's; or a rare path that would crowd
 * one. */
#if defined(__GNUC__) || defined(__clang__)
#define RAST__APART static __attribute__((noinline))
#else
#define RAST__APART static
#endif

typedef struct rast__grid {
    int32_t unit;     /* 2^(S+1): one pixel in internal units */
    int32_t off;      /* sample offset in internal units: 2^S or 0 */
    int32_t textbook; /* 1: RAST_ROUND_TEXTBOOK, 0: exact */
    int32_t shift;    /* S + 1, unit == 1 << shift: divisions by the unit
                         in a small primitive's setup become shifts */
} rast__grid;

/* Check S, the sample, rounding and boundary options and set up the grid.
 * RAST_E_SUBPIXEL or RAST_E_ARG; shared by every entry point (grid.c). */
rast_status rast__grid_init(rast__grid *g, int32_t subpixel_bits, rast_sample sample,
                            rast_rounding rounding, rast_boundary boundary);

/* The least and greatest x and y of pts[0 .. n), n >= 1: b[0] = min x,
 * b[1] = max x, b[2] = min y, b[3] = max y. */
static inline void rast__pts_extent(const rast_point *pts, uint32_t n, int32_t b[4])
{
    uint32_t i;
    b[0] = b[1] = pts[0].x;
    b[2] = b[3] = pts[0].y;
    for (i = 1; i < n; i++) {
        if (pts[i].x < b[0]) b[0] = pts[i].x;
        if (pts[i].x > b[1]) b[1] = pts[i].x;
        if (pts[i].y < b[2]) b[2] = pts[i].y;
        if (pts[i].y > b[3]) b[3] = pts[i].y;
    }
}

/* The bounds calls' last step (entry/fill.c rast_fill_bounds, poly64.c
 * rast__fill64_measure): the pixels [x0, x1) x [y0, y1) cut to clip c,
 * into *out when that leaves any (else *out as it was: empty). */
static inline void rast__rect_cut64(rast_rect *out, const rast_rect *c, int64_t x0, int64_t x1, int64_t y0,
                                    int64_t y1)
{
    if (x0 < c->x0) x0 = c->x0;
    if (x1 > c->x1) x1 = c->x1;
    if (y0 < c->y0) y0 = c->y0;
    if (y1 > c->y1) y1 = c->y1;
    if (x0 < x1 && y0 < y1) {
        out->x0 = (int32_t)x0;
        out->x1 = (int32_t)x1;
        out->y0 = (int32_t)y0;
        out->y1 = (int32_t)y1;
    }
}

/* (b - a) x (c - a): twice the signed area of abc, exact for vertices
 * (|coordinates| < 2^28: |.| < 2^58).  Positive when a, b, c turn
 * clockwise on screen (y down), counter-clockwise with y up. */
static inline int64_t rast__cross3(rast_point a, rast_point b, rast_point c)
{
    return ((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

/* Floor of a / b for b > 0, with a non-negative remainder. */
static inline int64_t rast__floordiv(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b < 0) ? q - 1 : q;
}

/* Ceiling of a / b for b > 0. */
static inline int64_t rast__ceildiv(int64_t a, int64_t b)
{
    return -rast__floordiv(-a, b);
}

/* n = f*q + r with f = floor(n / q) and 0 <= r < q, for q > 0: a 32-bit
 * division when both fit, several times faster than a 64-bit one on
 * common CPUs. */
static inline void rast__floordivmod(int64_t n, int64_t q, int64_t *f, int64_t *r)
{
    int64_t t, m;
    if (q <= INT32_MAX && n >= -INT32_MAX && n <= INT32_MAX) {
        t = (int32_t)n / (int32_t)q;
        m = (int32_t)n % (int32_t)q;
    } else {
        t = n / q;
        m = n % q;
    }
    *f = t - (m < 0);
    *r = m + (q & -(int64_t)(m < 0));
}

/* floor(a / unit) and ceil(a / unit) for |a| < 2^61: shifts of the value
 * made non-negative by a bias (the unit is a power of two), instead of a
 * 64-bit division. */
static inline int64_t rast__floor_unit(int64_t a, const rast__grid *g)
{
    const int64_t bias = (int64_t)1 << 61;
    return (int64_t)((uint64_t)(a + bias) >> g->shift) - (bias >> g->shift);
}

static inline int64_t rast__ceil_unit(int64_t a, const rast__grid *g)
{
    return -rast__floor_unit(-a, g);
}

/* The first column that counts a crossing at internal abscissa X = num/den
 * (den > 0): exact, the least i with X <= i*unit + off, ceil((X-off)/unit);
 * textbook, floor((X - off + unit/2)/unit) (see RAST_ROUND_TEXTBOOK).
 * |num| < 2^60 and den < 2^47 keep every product inside int64_t. */
static inline int64_t rast__cross_col(int64_t num, int64_t den, const rast__grid *g)
{
    int64_t q = den * g->unit;
    if (g->textbook) /* floor(n/q) == ceil((n - q + 1)/q) for integers */
        return rast__ceildiv(num + (int64_t)(g->unit / 2 - g->off) * den - q + 1, q);
    return rast__ceildiv(num - (int64_t)g->off * den, q);
}

/* The first row whose sample is at or below internal ordinate y:
 * the least j with j*unit + off >= y, for |y| < 2^40.  A shift of the
 * value made non-negative by a bias, instead of a division. */
static inline int64_t rast__row_at_or_after(int64_t y, const rast__grid *g)
{
    const int64_t bias = (int64_t)1 << 41;
    return (int64_t)((uint64_t)(y - g->off + g->unit - 1 + bias) >> g->shift) -
           (bias >> g->shift);
}

/*
 * One non-horizontal edge, walked row by row with an exact integer DDA.
 * At row j the edge's crossing is the rational X(j); `x` is the first column
 * whose sample is at or right of it, x = ceil((X(j) - off) / unit), so that a
 * sample i counts the crossing iff i >= x.  With the crossing written as
 * (X(j) - off) / unit = n / q  (q = dy * unit > 0), the invariant is
 *     x*q - n = e,  0 <= e < q.
 * From one row to the next n grows by dx*unit = step*q + dr (0 <= dr < q).
 */
typedef struct rast__edge {
    int64_t e;    /* x*q - n, in [0, q) */
    int64_t dr;   /* remainder of the per-row growth, in [0, q) */
    int64_t q;    /* dy * unit */
    int32_t x;    /* first column at or right of the crossing */
    int32_t step; /* whole columns per row: floor(dx / dy) */
    int32_t row;  /* first row crossed (after clipping) */
    int32_t end;  /* first row not crossed (after clipping) */
    int32_t dir;  /* +1 if the edge goes down (y grows), -1 if up */
    int32_t next; /* free for the filler's lists */
} rast__edge;

/* Set up edge a->b (fixed-point input units) restricted to rows
 * [row_lo, row_hi).  Returns 1 and fills *ed when the edge crosses at least
 * one of those rows, 0 otherwise.  Coordinates must be in range. */
int rast__edge_setup(rast__edge *ed, rast_point a, rast_point b,
                     const rast__grid *g, int32_t row_lo, int32_t row_hi);

/* The same for a caller that has the rows already (a triangle shares each
 * vertex's row between two edges): `top` above `bottom` (top.y < bottom.y,
 * in range), the edge walking rows [first, end) (first < end, all crossed
 * by the edge), direction `dir`. */
void rast__edge_start(rast__edge *ed, rast_point top, rast_point bottom,
                      int32_t dir, int32_t first, int32_t end, const rast__grid *g);

/* Advance an edge to the next row.  Branch-free: whether the remainder
 * wraps is a coin toss for most slopes, which a branch would mispredict. */
static inline void rast__edge_step(rast__edge *ed)
{
    int64_t e = ed->e - ed->dr;
    int64_t carry = e < 0;
    ed->x += ed->step + (int32_t)carry;
    ed->e = e + (ed->q & -carry);
}

/* The bodies of rast__edge_start and rast__edge_setup (edge.c), for the
 * triangle fillers, which set up three edges per triangle: inlined, the
 * edge stays in registers and the call is gone.  Setup is most of the
 * cost of a small primitive (a triangle of a mesh has three edges and a
 * handful of rows), and its cost is divisions.  Those by the unit (a
 * power of two) are shifts; the whole columns per row always fit 32 bits;
 * the first crossing is split into a whole column at the upper vertex
 * plus a remainder that fits 32 bits unless the edge is very long or
 * starts far above the first row, and a 32-bit division is several times
 * faster than a 64-bit one on common CPUs. */
/* floor(a / 2^shift) for |a| < 2^30, by a shift of a + 2^30 >= 0. */
static inline int32_t rast__floorshift32(int32_t a, int32_t shift)
{
    const uint32_t bias = (uint32_t)1 << 30;
    return (int32_t)(((uint32_t)a + bias) >> shift) - (int32_t)(bias >> shift);
}

/* The first column of edge top -> bottom (top.y < bottom.y) at row
 * `first`, x = ceil(n / q) with q = dy * unit (below), and its remainder
 * e = x q - n, 0 <= e < q, into *e: the start of rast__edge_start_inline,
 * and all that an edge crossing one row needs (fillers/aet.c). */
static inline int32_t rast__edge_first_col(rast_point top, rast_point bottom, int32_t first,
                                           const rast__grid *g, int64_t *e)
{
    /* Internal units: |coordinate| < 2^28, differences < 2^29. */
    rast__dpos xa = 2 * top.x, ya = 2 * top.y;
    rast__dpos dx = 2 * bottom.x - xa, dy = 2 * bottom.y - ya;
    int32_t base, xr;
    int64_t q = (int64_t)dy * g->unit; /* < 2^46 */
    int64_t n, t, r;

    /* The first column x = ceil(n / q), n = (xa - off)*dy + (yc - ya)*dx
     * with yc = first*unit + off.  With xa - off = base*unit + xr
     * (0 <= xr < unit), n / q is base plus n' / q, n' = xr*dy + (yc - ya)*dx,
     * small unless the edge is long or starts far above row `first`;
     * |n'| < 2^59 in any case. */
    base = rast__floorshift32(xa - g->off, g->shift);
    xr = xa - g->off - base * g->unit;
    n = (int64_t)xr * dy + ((int64_t)first * g->unit + g->off - ya) * dx;
    /* Textbook rounding: the first column is floor((n + h*dy) / q) with
     * h = unit/2, which is ceil((n + h*dy - q + 1) / q); from then on the
     * walk is the same (rast__cross_col says this once for other users). */
    if (g->textbook) n += (int64_t)(g->unit / 2) * dy - q + 1;

    /* x = ceil(n / q) and e = x*q - n, without forming x*q (it may not fit),
     * from one floor division n = t*q + r (0 <= r < q): the ceiling is
     * t + 1 when r > 0, else t. */
    rast__floordivmod(n, q, &t, &r);
    *e = r > 0 ? q - r : 0;
    return (int32_t)(base + t + (r > 0));
}

static inline void rast__edge_start_inline(rast__edge *ed, rast_point top, rast_point bottom,
                                           int32_t dir, int32_t first, int32_t end,
                                           const rast__grid *g)
{
    rast__dpos dx = 2 * bottom.x - 2 * top.x, dy = 2 * bottom.y - 2 * top.y;
    int32_t step;
    int64_t e;

    ed->x = rast__edge_first_col(top, bottom, first, g, &e);
    ed->e = e;
    ed->q = (int64_t)dy * g->unit;

    /* Whole columns per row, floor(dx / dy), and the remainder's growth. */
    step = dx / dy;
    step -= dx % dy < 0;
    ed->step = step;
    ed->dr = (int64_t)(dx - step * dy) * g->unit;
    ed->row = first;
    ed->end = end;
    ed->dir = dir;
    ed->next = -1;
}

static inline int rast__edge_setup_inline(rast__edge *ed, rast_point a, rast_point b,
                                          const rast__grid *g, int32_t row_lo, int32_t row_hi)
{
    int64_t first, end;
    int32_t dir = 1;

    if (a.y == b.y) return 0; /* horizontal edges never cross */
    if (a.y > b.y) {
        rast_point s = a;
        a = b;
        b = s;
        dir = -1;
    }
    /* Rows j with ya <= j*unit + off < yb, cut to [row_lo, row_hi). */
    first = rast__row_at_or_after(2 * (int64_t)a.y, g);
    end = rast__row_at_or_after(2 * (int64_t)b.y, g);
    if (first < row_lo) first = row_lo;
    if (end > row_hi) end = row_hi;
    if (first >= end) return 0;
    rast__edge_start_inline(ed, a, b, dir, (int32_t)first, (int32_t)end, g);
    return 1;
}

/* What the triangle fillers call: the inline bodies, except in a build
 * for size (-Os, firmware), where the out-of-line copies save about 400
 * bytes of code per filler that uses them. */
#if defined(__OPTIMIZE_SIZE__)
#define rast__edge_start_tri rast__edge_start
#define rast__edge_setup_tri rast__edge_setup
#else
#define rast__edge_start_tri rast__edge_start_inline
#define rast__edge_setup_tri rast__edge_setup_inline
#endif

/* ---- the pipeline: fillers -> sink -> painter ------------------------------
 * A filler decides WHICH pixels a primitive covers and how much; a painter
 * decides WHAT they get.  Between them runs (y, x0, x1) carry a coverage:
 *  - a full run: every pixel of [x0, x1) covered whole (what a binary
 *    filler gives), handed on a row at a time as spans;
 *  - a levels run: pixel x0 + k covered cov[k] / 255 (uint8 levels,
 *    floor(a 255 + 1/2), none of them 0), what a coverage method gives.
 * A painter is one struct with an entry for each (rast__painter); the
 * binary fillers feed its full entry through a sink (below), the coverage
 * methods its levels entry, and its full entry with long stretches
 * covered whole, through rast__cov_row_done (coverage/coverage.h). */

/* A painter's full entry: the spans of row y, xs[2k] <= i < xs[2k+1] for
 * k < n, in increasing x, each non-empty, none touching the next. */
typedef void (*rast__row_fn)(void *user, int32_t y, const int32_t *xs, int32_t n);

/* A painter's levels entry: columns [x0, x1) of row y (x0 < x1), pixel
 * x0 + k with coverage level cov[k] (1..255). */
typedef void (*rast__levels_fn)(void *user, int32_t y, int32_t x0, int32_t x1,
                                const uint8_t *cov);

/* A painter.  `full` and `levels` take `user`; an entry a painter has no
 * use for is NULL (the opaque painter and a rast_span_fn take full runs
 * only, a rast_coverage_span_fn levels runs only: no public call feeds
 * them the other kind).
 *
 * `bytes`, when not NULL, is the painter's fast kind, which a sink may
 * take instead of calling `full` (rast__rows_put): its full runs set
 * one-byte pixels to `value`, rows of `stride` bytes from `bytes` (a row
 * run is one memset at bytes + y stride + x0).  The solid painter of a
 * one-byte format says so (paint.c); a filler only sees "one-byte rows",
 * never a format.  The same pixels as `full`, without the indirect call,
 * the painter's loop and its reloads for a run of a few pixels.  The
 * library memset is also the fastest way to write a few bytes of unknown
 * count on common CPUs: overlapping 1..8-byte stores inline were slower,
 * their size tests mispredicting. */
typedef struct rast__painter {
    rast__row_fn full;
    rast__levels_fn levels;
    void *user;
    unsigned char *bytes;
    ptrdiff_t stride;
    unsigned char value;
} rast__painter;

/* Spans a sink gathers before handing them on; a longer row goes in parts. */
#define RAST__SINK_SPANS 64

/* Where a binary filler's runs go.  A filler calls rast__sink_span for
 * each inside run of a row, rows in increasing order and runs in
 * increasing x; the sink clips to the clip columns, merges runs that
 * touch, and hands each row's spans to the painter's full entry in one
 * call.  A triangle filler hands one run per row through rast__rows_put /
 * rast__rows_emit instead, which take the painter's fast kind when it has
 * one. */
typedef struct rast__sink {
    rast__row_fn fn;  /* the painter's full entry and its user */
    void *user;
    int32_t cx0, cx1; /* clip columns */
    int32_t y;        /* row of the gathered spans */
    int32_t n;        /* spans gathered */
    int32_t xs[2 * RAST__SINK_SPANS];
    /* the painter's fast kind (rast__painter::bytes), NULL when none */
    unsigned char *direct;
    ptrdiff_t stride;
    int value;
} rast__sink;

static inline void rast__sink_flush(rast__sink *s)
{
    if (s->n) {
        s->fn(s->user, s->y, s->xs, s->n);
        s->n = 0;
    }
}

static inline void rast__sink_span(rast__sink *s, int32_t y, int32_t x0, int32_t x1)
{
    if (x0 < s->cx0) x0 = s->cx0;
    if (x1 > s->cx1) x1 = s->cx1;
    if (x0 >= x1) return;
    if (s->n) {
        if (y == s->y) {
            int32_t *last = &s->xs[2 * s->n - 1];
            if (x0 <= *last) { /* touches the previous span: extend it */
                if (x1 > *last) *last = x1;
                return;
            }
            if (s->n == RAST__SINK_SPANS) rast__sink_flush(s);
        } else {
            rast__sink_flush(s);
        }
    }
    s->y = y;
    s->xs[2 * s->n] = x0;
    s->xs[2 * s->n + 1] = x1;
    s->n++;
}

/* A filler's copy of what it needs from a sink to hand on one run per row
 * (a triangle): kept in the filler's locals, so that the pixel stores of
 * the inline path (which may alias anything) do not force the compiler to
 * reload the sink after each one.  Rows must come in increasing order and
 * the sink must be empty (flushed); the runs bypass its gathering. */
typedef struct rast__rows {
    rast__sink *sink;
    unsigned char *direct; /* the painter's fast kind (rast__painter::bytes) */
    ptrdiff_t stride;
    int value;
    int32_t cx0, cx1;
} rast__rows;

static inline rast__rows rast__rows_of(rast__sink *s)
{
    rast__rows o;
    o.sink = s;
    o.direct = s->direct;
    o.stride = s->stride;
    o.value = s->value;
    o.cx0 = s->cx0;
    o.cx1 = s->cx1;
    return o;
}

/* Hand on the run [x0, x1) of row y, clipped (it may be empty). */
static inline void rast__rows_put(const rast__rows *o, int32_t y, int32_t x0, int32_t x1)
{
    int32_t xs[2];
    xs[0] = x0 < o->cx0 ? o->cx0 : x0;
    xs[1] = x1 > o->cx1 ? o->cx1 : x1;
    if (xs[0] >= xs[1]) return;
    if (o->direct)
        memset(o->direct + (ptrdiff_t)y * o->stride + xs[0], o->value, (size_t)(xs[1] - xs[0]));
    else
        o->sink->fn(o->sink->user, y, xs, 1);
}

/* Does the inline path take every run of a primitive whose crossings lie
 * in [xmin, xmax] (internal units), uncut?  Each run's ends are first
 * columns counting a crossing X in that range, which lie between
 * ceil((X - s)/unit) and floor((X - s)/unit) + 1, s the sample offset
 * (moved half a pixel right for textbook rounding); when all those
 * columns are inside the clip, a filler may write its runs without
 * cutting them (1), else it hands them to rast__rows_put (0). */
static inline int rast__rows_direct_uncut(const rast__rows *o, int64_t xmin, int64_t xmax,
                                          const rast__grid *g)
{
    int64_t s = g->off + (g->textbook ? g->unit / 2 : 0);
    return o->direct && rast__ceil_unit(xmin - s, g) >= o->cx0 &&
           rast__floor_unit(xmax - s, g) + 1 <= o->cx1;
}

/* Row y's run [x0, x1) (maybe empty) from a triangle filler's loop over
 * consecutive rows.  `uncut` (a constant in the caller, so that it makes
 * two loops) says rast__rows_direct_uncut held: the run is one memset at
 * *row, the row pointer, which then moves down a row (an empty run as a
 * memset of nothing: cheaper than a branch that sometimes mispredicts).
 * Else it goes to rast__rows_put. */
static inline void rast__rows_emit(const rast__rows *o, unsigned char **row, int32_t y,
                                   int32_t x0, int32_t x1, int uncut)
{
    if (uncut) {
        int32_t n = x1 - x0;
        memset(*row + x0, o->value, (size_t)(n & ~(n >> 31)));
        *row += o->stride;
    } else {
        rast__rows_put(o, y, x0, x1);
    }
}

/* The row pointer rast__rows_emit starts from at row y (NULL unless
 * uncut). */
static inline unsigned char *rast__rows_at(const rast__rows *o, int32_t y, int uncut)
{
    return uncut ? o->direct + (ptrdiff_t)y * o->stride : NULL;
}

/* Saturating size arithmetic for the scratch functions: a clip of
 * 2^30 x 2^30 pixels must give SIZE_MAX ("too much"), never a small
 * wrapped number, where size_t has 32 bits. */
static inline size_t rast__size_mul(size_t a, size_t b)
{
    if (a != 0 && b > (size_t)-1 / a) return (size_t)-1;
    return a * b;
}

static inline size_t rast__size_add(size_t a, size_t b)
{
    return a > (size_t)-1 - b ? (size_t)-1 : a + b;
}

/* A sink handing the runs inside `clip`'s columns to painter p (its full
 * entry, or its fast kind). */
static inline void rast__sink_init(rast__sink *s, const rast__painter *p, const rast_rect *clip)
{
    s->fn = p->full;
    s->user = p->user;
    s->cx0 = clip->x0;
    s->cx1 = clip->x1;
    s->y = clip->y0;
    s->n = 0;
    s->direct = p->bytes;
    s->stride = p->stride;
    s->value = p->value;
}

/* A caller's scratch, checked before anything is written: at least `need`
 * bytes, not NULL unless empty, aligned to RAST_SCRATCH_ALIGN. */
static inline rast_status rast__scratch_check(const void *scratch, size_t bytes, size_t need)
{
    if (bytes < need) return RAST_E_SCRATCH;
    if (bytes > 0 && !scratch) return RAST_E_NULL;
    if ((uintptr_t)scratch % RAST_SCRATCH_ALIGN) return RAST_E_ALIGN;
    return RAST_OK;
}

/* Bump allocation out of the caller's scratch buffer. */
typedef struct rast__arena {
    unsigned char *p;
    size_t left;
} rast__arena;

/* Round n up to a multiple of RAST_SCRATCH_ALIGN; SIZE_MAX stays SIZE_MAX
 * (a saturated size must not wrap to a small one). */
static inline size_t rast__align(size_t n)
{
    if (n > (size_t)-1 - (RAST_SCRATCH_ALIGN - 1)) return (size_t)-1;
    return (n + (RAST_SCRATCH_ALIGN - 1)) & ~(size_t)(RAST_SCRATCH_ALIGN - 1);
}

/* An arena over the caller's whole scratch. */
static inline rast__arena rast__arena_of(void *scratch, size_t bytes)
{
    rast__arena a;
    a.p = (unsigned char *)scratch;
    a.left = bytes;
    return a;
}

static inline void *rast__take(rast__arena *a, size_t n)
{
    void *p;
    n = rast__align(n);
    if (n > a->left) return NULL;
    p = a->p;
    a->p += n;
    a->left -= n;
    return p;
}

/* A polygon filler: coverage of `poly` inside `clip` (non-empty, already cut
 * to the target) handed to `sink`, with work memory from `arena`.  Called
 * only after the dispatcher has checked every argument and the scratch size,
 * so it may assume valid input. */
typedef rast_status (*rast__polygon_fill_fn)(const rast_polygon *poly,
                                             uint32_t npoints,
                                             const rast__grid *g,
                                             rast_fill_rule rule,
                                             const rast_rect *clip,
                                             rast__sink *sink,
                                             rast__arena *arena);

/* Scratch bytes a filler needs for npoints vertices and a clip of the given
 * size (both already checked against the limits). */
typedef size_t (*rast__scratch_fn)(uint32_t npoints, int32_t width, int32_t height);

/* ---- the library's line, by formula (linerun.c) --------------------------
 * The pixels rast_draw_line defines for a -> b (fixed-point input units),
 * row by row: the rows [*r0, *r1) that hold pixels of the line, and in row
 * j of those the columns [*x0, *x1) (never empty).  Exact divisions, no
 * stepping: the boundary modes use it, and the tests hold the incremental
 * Bresenham of line.c against it. */
void rast__line_rows(rast_point a, rast_point b, const rast__grid *g,
                     int64_t *r0, int64_t *r1);
void rast__line_run(rast_point a, rast_point b, const rast__grid *g,
                    int64_t row, int64_t *x0, int64_t *x1);

/* ---- boundary modes (boundary.c) ------------------------------------------
 * RAST_BOUNDARY_CLOSED and _CONSERVATIVE add, row by row, the pixels of a
 * polygon's edges to its fill.  The filler writes into `in` (set up by
 * rast__bound_begin), which merges each of its rows with the edges' pixels
 * of that row and passes the union on to `out` in row order;
 * rast__bound_end adds the rows after the filler's last and flushes `out`. */
typedef struct rast__bound_edge {
    rast_point a, b;  /* a above b (a.y <= b.y), fixed-point input units */
    int32_t row, end; /* rows [row, end) it adds pixels to, cut to the clip */
    int32_t next;
} rast__bound_edge;

typedef struct rast__bound {
    rast__sink *out;
    rast__sink in;
    const rast__grid *g;
    rast_boundary mode;
    rast__bound_edge *edges;
    const struct rast__grid64 *g64; /* the 64-bit path (conservative only), else NULL */
    struct rast__bound_edge64 *edges64; /* its edges */
    int32_t *bucket;   /* first edge of each clip row, -1 when none */
    int32_t *active;   /* edges adding pixels to the current row */
    int32_t *xs;       /* the current row's edge runs, merged (pairs) */
    int32_t nactive, nxs, k; /* k: runs already passed on */
    int32_t row;       /* row whose runs are in xs */
    int32_t y0, y1;    /* clip rows */
} rast__bound;

/* The 64-bit path's grid (poly64.c): S up to 32, so the unit 2^(S+1)
 * needs 64 bits. */
typedef struct rast__grid64 {
    int64_t unit;  /* 2^(S+1) */
    int64_t off;   /* 2^S (centres) or 0 */
    int32_t shift; /* S + 1 */
} rast__grid64;

/* An edge of a 64-bit polygon for RAST_BOUNDARY_CONSERVATIVE: internal
 * (doubled) coordinates, a above b. */
typedef struct rast__bound_edge64 {
    rast__dpos64 ax, ay, bx, by;
    int32_t row, end, next, pad;
} rast__bound_edge64;

size_t rast__bound_scratch(uint32_t npoints, int32_t height);
size_t rast__bound_scratch64(uint32_t npoints, int32_t height);
rast_status rast__bound_begin64(rast__bound *b, const rast_polygon64 *poly,
                                uint32_t npoints, const rast__grid64 *g,
                                const rast_rect *clip, rast__sink *out,
                                rast__arena *arena);
rast_status rast__bound_begin(rast__bound *b, const rast_polygon *poly,
                              uint32_t npoints, const rast__grid *g,
                              rast_boundary mode, const rast_rect *clip,
                              rast__sink *out, rast__arena *arena);
void rast__bound_end(rast__bound *b);

/* ---- triangle fillers -------------------------------------------------------
 * Coverage of one triangle t[0..2] (in range, any orientation, possibly
 * degenerate) inside `clip` (non-empty, cut to the target), handed to
 * `sink` row by row from the top; work memory from `arena`, at most
 * what the algorithm's scratch function asked for the clip.  The sink is
 * empty on entry and must be left empty (flushed) on return. */
typedef rast_status (*rast__tri_fill_fn)(const rast_point *t, const rast__grid *g,
                                         const rast_rect *clip, rast__sink *sink,
                                         rast__arena *arena);
typedef size_t (*rast__tri_scratch_fn)(int32_t width, int32_t height);

/* The three triangle fillers (tri_edge.c, tri_sweep.c, tri_edgeflag.c). */
rast_status rast__tri_edge_fill(const rast_point *t, const rast__grid *g,
                                const rast_rect *clip, rast__sink *sink,
                                rast__arena *arena);
size_t rast__tri_edge_scratch(int32_t width, int32_t height);
rast_status rast__tri_sweep_fill(const rast_point *t, const rast__grid *g,
                                 const rast_rect *clip, rast__sink *sink,
                                 rast__arena *arena);
size_t rast__tri_sweep_scratch(int32_t width, int32_t height);
rast_status rast__tri_edgeflag_fill(const rast_point *t, const rast__grid *g,
                                    const rast_rect *clip, rast__sink *sink,
                                    rast__arena *arena);
size_t rast__tri_edgeflag_scratch(int32_t width, int32_t height);

/* The edge-flag arrays of seed 001 (section 3.3, algorithm 9) for triangle
 * t: for each row j of [row_lo, row_hi) that the triangle covers,
 * span_left[j - row_lo] and span_right[j - row_lo] get the first column
 * that counts the crossing of its left and of its right edge (see
 * rast__cross_col), so that the row's pixels are
 * span_left <= i < span_right.  The covered rows are [*r0, *r1); returns 0
 * (and leaves the arrays alone) when there are none in the range, or the
 * triangle is degenerate.  The arrays hold row_hi - row_lo entries. */
int rast__tri_span_flags(const rast_point *t, const rast__grid *g,
                         int32_t row_lo, int32_t row_hi, int32_t *span_left,
                         int32_t *span_right, int32_t *r0, int32_t *r1);

/* The rectangle filler (rect.c): the pixels of the rectangle
 * [x0, x0 + w) x [y0, y0 + h) (internal units, w, h > 0, every corner
 * within the input range), those of its polygon fill, cut to `clip`
 * (maybe empty), row by row from the top, a full run per row to painter p. */
void rast__rect_fill(int64_t x0, int64_t y0, int64_t w, int64_t h, const rast__grid *g,
                     const rast_rect *clip, const rast__painter *p);

/* The AET filler (aet.c). */
rast_status rast__aet_fill(const rast_polygon *poly, uint32_t npoints,
                           const rast__grid *g, rast_fill_rule rule,
                           const rast_rect *clip, rast__sink *sink,
                           rast__arena *arena);
size_t rast__aet_scratch(uint32_t npoints, int32_t width, int32_t height);
/* The same with the way chosen: RAST__AET_BY_RULE (rast__aet_fill: the
 * rule in aet.c), the AET's sweep (RAST__AET_BY_SWEEP), or the winding
 * deltas wherever they can be used (RAST__AET_BY_DELTA, else the sweep):
 * the same runs (tests/c/test_delta.c).  A build for size has the sweep
 * only, and this is rast__aet_fill there. */
enum { RAST__AET_BY_RULE = 0, RAST__AET_BY_SWEEP = 1, RAST__AET_BY_DELTA = 2 };
#if defined(__OPTIMIZE_SIZE__)
#define rast__aet_fill_by(poly, npoints, g, rule, clip, sink, arena, how) \
    rast__aet_fill(poly, npoints, g, rule, clip, sink, arena)
#else
rast_status rast__aet_fill_by(const rast_polygon *poly, uint32_t npoints, const rast__grid *g,
                              rast_fill_rule rule, const rast_rect *clip, rast__sink *sink,
                              rast__arena *arena, int how);
#endif

#endif /* RAST_INTERNAL_H */

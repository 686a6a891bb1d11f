/*
 * seedfill.c - region (seed) fill, seed 001 section 3.6: flood fill of an
 * interior-defined region and boundary fill of a boundary-defined one, 4-
 * or 8-connected.
 *
 * The fill is the span (scanline) seed fill: fill the seed's whole run,
 * then keep a stack of row ranges still to scan ("row y + dy, columns
 * xl - e .. xr + e", e = 1 for 8-connectivity), each scan filling the
 * runs it finds whole and pushing their own ranges.  The stack lives in
 * the caller's memory.
 *
 * Which pixels are "inside" (still to fill) is decided by the pixel value
 * alone, and a filled pixel is never inside again: flood fill takes pixels
 * equal to the seed's value (the fill value differs, else the call does
 * nothing), boundary fill pixels that are neither the boundary value nor
 * the fill value.  So the image itself records what is done, and the
 * pixels reachable from a pending range are always pixels of the region.
 *
 * When the stack is full, a range that cannot be pushed is not dropped:
 * each inside pixel in it has its whole component (of the pixels inside
 * NOW, which lie in the region) filled at once by a fixed-memory fill,
 * rast__component.  That fill keeps the unfilled rest of the component
 * connected, so it never needs to remember anything but its position:
 * it fills a pixel only when the pixel's inside neighbours stay connected
 * without it (checked in the 3 x 3 neighbourhood, and when that is not
 * enough by walking the crack contour around the pixel), and otherwise
 * walks away from where it came from until it finds such a pixel.  It is
 * exact for every format, also for one with two values (after filling, a
 * pixel that had the fill value before looks like a filled one; the
 * method never needs to tell them apart).  Cost: O(1) memory; time per
 * pixel O(1) where the region is at least 2 pixels thick.  Where it is a
 * thin curve (a maze's corridors) a pixel that would cut it needs contour
 * walks; the walks stop at the first contour pixel that may be filled at
 * once (a dead end, a corner) and the fill goes there (issue 18: a 1024^2
 * maze with no stack went from minutes to half a second, 8192^2 from
 * hours to ~25 s; bench/maze.c).  The proven bound stays large (see "work
 * and a changing target" below), so rast_seed_fill_limited takes a
 * caller's limit.  Give enough stack (see rast_seed_stack_size) and the
 * fallback never runs.
 */
#include <string.h>

#include "../painters/paint.h"

/* ---- pixels ----------------------------------------------------------------
 * A pixel is read as an integer of up to 32 bits; two pixels are equal iff
 * their integers are.  Whole-byte formats are read as their bytes
 * (rast__formats gives the size) and written by the format's own fill;
 * mono1 is read as its bit, its value as on (not 0) or off.  A format
 * needs a case here only if it is packed otherwise. */

typedef struct rast__seed {
    unsigned char *base;
    ptrdiff_t stride;
    int32_t bpp;
    int32_t cx0, cy0, cx1, cy1; /* the clip */
    uint32_t m1, m2;            /* the values compared with (see inside) */
    uint32_t inv, all;          /* flood: 0, 1; boundary: 1, 0 */
    int32_t e;                  /* 1 for 8-connectivity, else 0 */
    int32_t fast8;              /* gray8 with one value deciding: word scans */
    int32_t ex, ey;             /* a pixel the contour walk treats as outside */
    unsigned char value[4];     /* the fill value's bytes */
    const rast__format *fmt;    /* its writer (fill), for all but COUNT16 */
    /* Bounds on the work (see "work and a changing target" below). */
    uint64_t area;              /* the clip's pixels */
    uint64_t written;           /* pixels written so far */
    uint64_t work, max_work;    /* work units so far; the caller's limit */
    uint64_t idle;              /* fixed-memory steps since the last write */
    rast_status stop;           /* RAST_OK, or why the fill stopped */
} rast__seed;

static uint32_t rast__seed_read(const unsigned char *p, int32_t bpp)
{
    uint16_t h;
    uint32_t w;
    switch (bpp) {
    case 1: return p[0];
    case 2: memcpy(&h, p, 2); return h;
    case 3: return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16;
    default: memcpy(&w, p, 4); return w;
    }
}

/* Flood fill: inside iff v == m1 (the seed's value).  Boundary fill:
 * inside iff v != m1 (the boundary) and v != m2 (the fill value).
 * Branch-free, so that the run scans stay tight loops. */
static inline int rast__seed_is_in(const rast__seed *s, uint32_t v)
{
    return (int)((((uint32_t)(v == s->m1)) ^ s->inv) & ((uint32_t)(v != s->m2) | s->all));
}

static inline unsigned char *rast__seed_at(const rast__seed *s, int32_t x, int32_t y)
{
    return s->base + (ptrdiff_t)y * s->stride + (ptrdiff_t)x * s->bpp;
}

/* Inside and in the clip (anything outside the clip is outside). */
/* Pixel (x, y) of any format as an integer. */
static uint32_t rast__seed_px(const rast__seed *s, int32_t x, int32_t y)
{
    if (s->bpp == 0) /* mono1: bit 7 - x % 8 of byte x / 8 */
        return (uint32_t)(s->base[(ptrdiff_t)y * s->stride + (x >> 3)] >> (7 - (x & 7))) & 1u;
    return rast__seed_read(rast__seed_at(s, x, y), s->bpp);
}

static int rast__seed_in(const rast__seed *s, int32_t x, int32_t y)
{
    if (x < s->cx0 || x >= s->cx1 || y < s->cy0 || y >= s->cy1) return 0;
    return rast__seed_is_in(s, rast__seed_px(s, x, y));
}

/* The same, but the pixel (ex, ey) counts as outside too. */
static int rast__seed_in_ex(const rast__seed *s, int32_t x, int32_t y)
{
    return (x != s->ex || y != s->ey) && rast__seed_in(s, x, y);
}

/* ---- work and a changing target ---------------------------------------------
 * Each pixel is written only after it was read as inside, and every run
 * written is [l, r] with cx0 <= l <= x <= r < cx1 for a column x already
 * read as inside: whatever the pixels read, a write stays in the clip and
 * its length is at least 1.  On an unchanging target a written pixel is
 * never inside again, so a fill writes at most `area` pixels; the
 * fixed-memory fill makes at most `area` moves between two writes and
 * a contour walk at most 4 (area + 1) steps.  A count past one of these
 * can only come from another writer changing the target during the call:
 * the fill stops there (RAST_E_WORK).  Every write, move and contour step
 * is a unit of work; past the caller's max_work the fill stops too. */
static int rast__seed_spend(rast__seed *s, uint64_t units)
{
    if (s->stop != RAST_OK) return 1;
    if (units > s->max_work - s->work) {
        s->stop = RAST_E_WORK;
        return 1;
    }
    s->work += units;
    return 0;
}

/* Write the fill value over columns [x0, x1) of row y (x0 < x1), unless
 * the work limit or the pixel budget is reached. */
static void rast__seed_write(rast__seed *s, int32_t y, int32_t x0, int32_t x1)
{
    unsigned char *row = s->base + (ptrdiff_t)y * s->stride;
    uint64_t n = (uint64_t)(x1 - x0);
    if (s->stop != RAST_OK) return;
    if (n > s->area - s->written) { /* more than the clip: the target changed */
        s->stop = RAST_E_WORK;
        return;
    }
    if (rast__seed_spend(s, n)) return;
    s->written += n;
    s->idle = 0;
    if (s->bpp == 1) { /* gray8: the common case, a bare memset */
        memset(row + x0, s->value[0], (size_t)(x1 - x0));
    } else if (s->fmt) {
        s->fmt->fill(row, x0, x1, s->value);
    } else { /* COUNT16 counts in its fill; a seed fill writes the value */
        for (; x0 < x1; x0++) memcpy(row + 2 * (ptrdiff_t)x0, s->value, 2);
    }
}

/* Gray8 scans eight pixels per step where one value decides (flood fill,
 * or boundary fill with boundary == value): a word of pixels XOR the value
 * repeated has a zero byte where a pixel equals the value. */
#define RAST__ONES ((uint64_t)0x0101010101010101u)
#define RAST__HIGHS ((uint64_t)0x8080808080808080u)

/* First column >= x (and < end) of row y with (pixel == c) == eq (gray8). */
static int32_t rast__seed_find8(const unsigned char *row, int32_t x, int32_t end, unsigned char c, int eq)
{
    const uint64_t pat = RAST__ONES * c;
    while (end - x >= 8) {
        uint64_t w;
        memcpy(&w, row + x, 8);
        w ^= pat;
        if (eq ? ((w - RAST__ONES) & ~w & RAST__HIGHS) != 0 : w != 0) break;
        x += 8;
    }
    for (; x < end && (row[x] == c) != eq; x++) continue;
    return x;
}

/* First column >= x (and < end) of row y that is inside (want 1) or
 * outside (want 0); end if none. */
static int32_t rast__seed_scan(const rast__seed *s, int32_t y, int32_t x, int32_t end, int want)
{
    const unsigned char *p;
    int32_t bpp = s->bpp;
    if (x >= end) return end;
    if (s->fast8) /* flood: in iff == m1; boundary == value: in iff != m1 */
        return rast__seed_find8(rast__seed_at(s, 0, y), x, end, (unsigned char)s->m1,
                                want ^ (int)s->inv);
    if (bpp == 0) {
        for (; x < end && rast__seed_is_in(s, rast__seed_px(s, x, y)) != want; x++) continue;
        return x;
    }
    p = rast__seed_at(s, x, y);
    if (bpp == 1) {
        for (; x < end && rast__seed_is_in(s, *p) != want; x++) p++;
    } else {
        for (; x < end && rast__seed_is_in(s, rast__seed_read(p, bpp)) != want; x++) p += bpp;
    }
    return x;
}

static int32_t rast__seed_next_in(const rast__seed *s, int32_t y, int32_t x, int32_t end)
{
    return rast__seed_scan(s, y, x, end, 1);
}

static int32_t rast__seed_next_out(const rast__seed *s, int32_t y, int32_t x, int32_t end)
{
    return rast__seed_scan(s, y, x, end, 0);
}

/* Last column <= x (and >= lo) of row y going left while inside, i.e. the
 * left end of the inside run through x + 1; x + 1 if x is outside. */
static int32_t rast__seed_run_left(const rast__seed *s, int32_t y, int32_t x, int32_t lo)
{
    const unsigned char *p;
    int32_t bpp = s->bpp;
    if (x < lo) return x + 1; /* no pointer before the row */
    if (bpp == 0) {
        for (; x >= lo && rast__seed_is_in(s, rast__seed_px(s, x, y)); x--) continue;
        return x + 1;
    }
    p = rast__seed_at(s, x, y);
    if (bpp == 1) {
        for (; x >= lo && rast__seed_is_in(s, *p); x--) p--;
    } else {
        for (; x >= lo && rast__seed_is_in(s, rast__seed_read(p, bpp)); x--) p -= bpp;
    }
    return x + 1;
}

/* ---- the fixed-memory fill ------------------------------------------------
 * The 8 neighbours of a pixel in circular order; even indices are the 4
 * orthogonal ones, index i lies in direction i / 2 (0 right, 1 down,
 * 2 left, 3 up). */
static const int8_t rast__rx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int8_t rast__ry[8] = {0, 1, 1, 1, 0, -1, -1, -1};
static const int8_t rast__dx[4] = {1, 0, -1, 0};
static const int8_t rast__dy[4] = {0, 1, 0, -1};

/* The inside neighbours of (x, y), grouped by how they connect among
 * themselves within the 3 x 3 neighbourhood: gid[i] is the group of
 * neighbour i (-1: outside, or a diagonal that is no 4-neighbour and joins
 * none); returns the number of groups. */
static int32_t rast__seed_groups(const rast__seed *s, int32_t x, int32_t y, int32_t gid[8])
{
    int32_t in[8], root[8], i, k = 0;
    for (i = 0; i < 8; i++) {
        in[i] = rast__seed_in(s, x + rast__rx[i], y + rast__ry[i]);
        root[i] = i;
    }
    /* Union-find on 8 elements, parents always smaller indices. */
#define RAST__FIND(a) do { while (root[a] != (a)) (a) = root[a]; } while (0)
    for (i = 0; i < 8; i++) {
        int32_t a = i, b = (i + 1) & 7, c = (i + 2) & 7;
        if (in[a] && in[b]) { /* neighbours in the ring touch by a side */
            int32_t ra = a, rb = b;
            RAST__FIND(ra);
            RAST__FIND(rb);
            if (ra != rb) root[ra > rb ? ra : rb] = ra < rb ? ra : rb;
        }
        if (s->e && !(i & 1) && in[a] && in[c]) { /* two sides touch by a corner */
            int32_t ra = a, rc = c;
            RAST__FIND(ra);
            RAST__FIND(rc);
            if (ra != rc) root[ra > rc ? ra : rc] = ra < rc ? ra : rc;
        }
    }
    for (i = 0; i < 8; i++) gid[i] = -1;
    for (i = 0; i < 8; i++) { /* a group counts if it holds a neighbour */
        int32_t r = i;
        if (!in[i] || (!s->e && (i & 1))) continue;
        RAST__FIND(r);
        if (gid[r] < 0) gid[r] = k++;
    }
    for (i = 0; i < 8; i++) {
        int32_t r = i;
        if (!in[i]) continue;
        RAST__FIND(r);
        gid[i] = gid[r];
    }
#undef RAST__FIND
    return k;
}

/* A walk along the crack contour: the side `d` of inside pixel (x, y)
 * faces an outside pixel; groups seen so far, and where it started. */
typedef struct rast__crack {
    int32_t x, y, d, sx, sy, sd;
    uint32_t seen;
} rast__crack;

/* Start on a side of group g of (x, y) that faces (x, y) itself, or for a
 * group touching (x, y) only by a corner (8-connectivity), its side that
 * faces the outside side neighbour next to that corner. */
static void rast__crack_start(rast__crack *c, int32_t x, int32_t y, const int32_t gid[8], int32_t g)
{
    int32_t i, d;
    for (i = 0; gid[i] != g; i++) continue;
    if (!(i & 1)) {
        d = ((i >> 1) + 2) & 3;
    } else { /* neighbour i - 1 is outside, or it would share the group */
        int32_t ddx = rast__rx[i - 1] - rast__rx[i], ddy = rast__ry[i - 1] - rast__ry[i];
        for (d = 0; rast__dx[d] != ddx || rast__dy[d] != ddy; d++) continue;
    }
    c->x = c->sx = x + rast__rx[i];
    c->y = c->sy = y + rast__ry[i];
    c->d = c->sd = d;
    c->seen = 0;
}

/* One step along the contour (inside pixels on the walk's right), noting
 * the group of each neighbour of (x, y) passed; 1 when back at the start. */
static int rast__crack_step(const rast__seed *s, rast__crack *c, int32_t x, int32_t y,
                            const int32_t gid[8])
{
    int32_t t = (c->d + 1) & 3, ax, ay, bx, by, rx = c->x - x, ry = c->y - y, i;
    if (rx >= -1 && rx <= 1 && ry >= -1 && ry <= 1) {
        for (i = 0; rast__rx[i] != rx || rast__ry[i] != ry; i++) continue;
        if (gid[i] >= 0) c->seen |= 1u << gid[i];
    }
    ax = c->x + rast__dx[t];
    ay = c->y + rast__dy[t];
    bx = ax + rast__dx[c->d];
    by = ay + rast__dy[c->d];
    if (rast__seed_in_ex(s, bx, by) && (s->e || rast__seed_in_ex(s, ax, ay))) {
        c->x = bx; /* the contour turns round the outside pixel */
        c->y = by;
        c->d = (t + 2) & 3;
    } else if (rast__seed_in_ex(s, ax, ay)) {
        c->x = ax; /* straight on */
        c->y = ay;
    } else {
        c->d = t; /* round the corner of this pixel */
    }
    return c->x == c->sx && c->y == c->sy && c->d == c->sd;
}

/* Does filling (x, y), whose inside neighbours form k >= 2 groups in its
 * 3 x 3 neighbourhood, leave them connected?  With (x, y) taken as
 * outside, walk the crack contour from each group at once, one step each
 * in turn.  A walk runs once round the border between its group's
 * component and the outside component that (x, y) joins, and every group
 * of that component touches that outside component next to (x, y), so a
 * finished walk has seen exactly its component's groups.  All k: 1.
 * Otherwise 0, and *go is a neighbour in the first component found closed
 * that does not hold neighbour `from` (-1: any): the smallest such part,
 * and the walks cost about twice its contour. */
/* Does filling (px, py) keep its inside neighbours connected within its
 * 3 x 3 neighbourhood (at most one group)?  Then it is a pixel the
 * fixed-memory fill may fill at once, wherever it is in the component. */
static int rast__seed_simple(const rast__seed *s, int32_t px, int32_t py)
{
    int32_t gid[8];
    return rast__seed_groups(s, px, py, gid) <= 1;
}

static int rast__seed_joined(rast__seed *s, int32_t x, int32_t y, const int32_t gid[8],
                             int32_t k, int32_t from, int32_t *go, int32_t *jx, int32_t *jy)
{
    rast__crack c[4];
    /* gid[from] < 0 only if the target changed (the pixel left behind is
     * inside): then any part will do. */
    uint32_t want = (1u << k) - 1u, open = want;
    uint32_t back = from >= 0 && gid[from] >= 0 ? 1u << gid[from] : 0;
    int32_t g, i;
    uint64_t steps = 0;
    for (g = 0; g < k; g++) rast__crack_start(&c[g], x, y, gid, g);
    s->ex = x;
    s->ey = y;
    for (;;) {
        /* A contour of the clip has at most 4 (area + 1) sides; a walk
         * longer than that is one over a target that changed. */
        if (++steps > 4 * (s->area + 1)) s->stop = RAST_E_WORK;
        if (rast__seed_spend(s, (uint64_t)k)) {
            s->ex = s->cx0 - 1;
            return 0;
        }
        for (g = 0; g < k; g++) {
            int closed;
            if (!(open & (1u << g))) continue;
            closed = rast__crack_step(s, &c[g], x, y, gid);
            /* A pixel of the contour that may be filled at once (a dead
             * end of a corridor, a corner): go there instead of walking
             * on.  This keeps a maze of one-pixel corridors from costing
             * a contour per pixel: its dead ends are found as the walks
             * pass them. */
            if ((c[g].x != x || c[g].y != y) && rast__seed_simple(s, c[g].x, c[g].y)) {
                *jx = c[g].x;
                *jy = c[g].y;
                s->ex = s->cx0 - 1;
                return 2;
            }
            if (!closed) continue;
            if (c[g].seen == want) {
                s->ex = s->cx0 - 1;
                return 1;
            }
            if (!(c[g].seen & back)) {
                for (i = 0; gid[i] < 0 || !(c[g].seen & (1u << gid[i])) || (!s->e && (i & 1)); i++)
                    continue;
                *go = i;
                s->ex = s->cx0 - 1;
                return 0;
            }
            open &= ~c[g].seen;
        }
    }
}

/* Fill the component of inside pixels holding (x, y), in fixed memory.
 * The unfilled part of the component stays connected throughout: a pixel
 * is filled only when its inside neighbours stay connected without it.
 * A pixel that would cut them apart is left, and the walk moves to a
 * neighbour not on the side it came from; each such move enters a strictly
 * smaller part cut off by the pixel left behind, so the walk reaches a
 * pixel it may fill. */
static void rast__component(rast__seed *s, int32_t x, int32_t y)
{
    int32_t gid[8], from = -1;
    for (;;) {
        int32_t k = rast__seed_groups(s, x, y, gid), i = 0, j, jx = 0, jy = 0;
        /* At most `area` moves between two writes (each enters a strictly
         * smaller part); more, or the limit: stop. */
        if (++s->idle > s->area) s->stop = RAST_E_WORK;
        if (rast__seed_spend(s, 1)) return;
        if (k == 0) {
            rast__seed_write(s, y, x, x + 1);
            return;
        }
        j = k == 1 ? 1 : rast__seed_joined(s, x, y, gid, k, from, &i, &jx, &jy);
        if (j == 2) { /* a pixel that may be filled, found on a contour */
            if (s->stop != RAST_OK) return;
            x = jx;
            y = jy;
            from = -1;
            continue;
        }
        if (j) {
            rast__seed_write(s, y, x, x + 1);
            if (s->stop != RAST_OK) return;
            for (i = 0; gid[i] < 0 || (!s->e && (i & 1)); i++) continue;
            from = -1;
        } else {
            if (s->stop != RAST_OK) return;
            from = (i + 4) & 7; /* where we come from, seen from the next pixel */
        }
        x += rast__rx[i];
        y += rast__ry[i];
    }
}

/* ---- the span fill ----------------------------------------------------------- */

typedef struct rast__span_entry {
    int32_t y, xl, xr, dy; /* row y's run [xl, xr] is filled; scan row y + dy */
} rast__span_entry;

typedef struct rast__span_stack {
    rast__span_entry *e;
    size_t n, cap;
} rast__span_stack;

/* Queue the scan of row y + dy over [xl - e, xr + e]; with no room, do it
 * now with the fixed-memory fill, component by component. */
static void rast__span_push(rast__seed *s, rast__span_stack *st, int32_t y, int32_t xl,
                            int32_t xr, int32_t dy)
{
    int32_t ny = y + dy, x, end;
    if (ny < s->cy0 || ny >= s->cy1) return;
    if (st->n < st->cap) {
        rast__span_entry *p = &st->e[st->n++];
        p->y = y;
        p->xl = xl;
        p->xr = xr;
        p->dy = dy;
        return;
    }
    x = xl - s->e < s->cx0 ? s->cx0 : xl - s->e;
    end = xr + s->e + 1 > s->cx1 ? s->cx1 : xr + s->e + 1;
    for (x = rast__seed_next_in(s, ny, x, end); x < end && s->stop == RAST_OK;
         x = rast__seed_next_in(s, ny, x + 1, end))
        rast__component(s, x, ny);
}

/* The seed (x, y) was read as inside once, by the setup: it is not read
 * again, so the first run [l, r] holds x whatever the pixel is now. */
static void rast__span_fill(rast__seed *s, int32_t x, int32_t y, rast__span_stack *st)
{
    int32_t l = rast__seed_run_left(s, y, x - 1, s->cx0);
    int32_t r = rast__seed_next_out(s, y, x + 1, s->cx1) - 1;
    rast__seed_write(s, y, l, r + 1);
    rast__span_push(s, st, y, l, r, 1);
    rast__span_push(s, st, y, l, r, -1);
    while (st->n && s->stop == RAST_OK) {
        rast__span_entry en = st->e[--st->n];
        int32_t ny = en.y + en.dy;
        int32_t lo = en.xl - s->e < s->cx0 ? s->cx0 : en.xl - s->e;
        int32_t end = en.xr + s->e + 1 > s->cx1 ? s->cx1 : en.xr + s->e + 1;
        x = rast__seed_next_in(s, ny, lo, end);
        while (x < end && s->stop == RAST_OK) {
            /* x was read as inside: the run [l, r] holds it. */
            l = x == lo ? rast__seed_run_left(s, ny, x - 1, s->cx0) : x;
            r = rast__seed_next_out(s, ny, x + 1, s->cx1) - 1;
            rast__seed_write(s, ny, l, r + 1);
            /* Onwards over the whole run; back towards the parent row only
             * where the run reaches past the parent run: that run was
             * maximal, so its own neighbours xl - 1 and xr + 1 there are
             * not inside, whatever the connectivity. */
            if (l < en.xl || r > en.xr) rast__span_push(s, st, ny, l, r, -en.dy);
            rast__span_push(s, st, ny, l, r, en.dy);
            x = r + 2 > end ? end : rast__seed_next_in(s, ny, r + 2, end);
        }
    }
}

/* ---- entry points ------------------------------------------------------------ */

rast_status rast_seed_stack_size(int32_t width, int32_t height, size_t *bytes)
{
    size_t runs;
    if (!bytes) return RAST_E_NULL;
    if (width < 0 || height < 0 || width > RAST_MAX_DIM || height > RAST_MAX_DIM)
        return RAST_E_SIZE;
    /* Each run filled pushes at most 2 ranges; a row holds at most
     * ceil(width / 2) runs (runs are separated by an outside pixel). */
    runs = rast__size_mul((size_t)height, ((size_t)width + 1) / 2);
    *bytes = rast__size_mul(rast__size_add(rast__size_mul(runs, 2), 2), sizeof(rast__span_entry));
    return RAST_OK;
}

/* Check everything, set up *s; *noop when the fill has nothing to do. */
static rast_status rast__seed_setup(rast__seed *s, const rast_target *target, int32_t x,
                                    int32_t y, const void *value, const void *boundary,
                                    int connectivity, const void *stack, size_t stack_bytes,
                                    int *noop)
{
    rast_rect clip;
    rast_status st = rast__target_check(target, &clip);
    uint32_t v;
    if (st != RAST_OK) return st;
    if (!value) return RAST_E_NULL;
    if (connectivity != 4 && connectivity != 8) return RAST_E_ARG;
    st = rast__scratch_check(stack, stack_bytes, 0);
    if (st != RAST_OK) return st;
    if (x < 0 || y < 0 || x >= target->width || y >= target->height) return RAST_E_ARG;
    memset(s, 0, sizeof *s);
    s->base = (unsigned char *)target->pixels;
    s->stride = target->stride;
    s->bpp = rast__formats[target->format].bits / 8; /* 0: mono1 */
    s->fmt = target->format == RAST_FORMAT_COUNT16 ? NULL : &rast__formats[target->format];
    s->cx0 = clip.x0;
    s->cy0 = clip.y0;
    s->cx1 = clip.x1;
    s->cy1 = clip.y1;
    s->e = connectivity == 8;
    s->ex = s->cx0 - 1;
    if (s->bpp) {
        memcpy(s->value, value, (size_t)s->bpp);
        v = rast__seed_read(s->value, s->bpp);
        if (boundary) s->m1 = rast__seed_read((const unsigned char *)boundary, s->bpp);
    } else { /* mono1: a value byte is on iff not 0 */
        s->value[0] = *(const unsigned char *)value ? 1 : 0;
        v = s->value[0];
        if (boundary) s->m1 = *(const unsigned char *)boundary ? 1u : 0u;
    }
    if (boundary) {
        s->m2 = v;
        s->inv = 1;
        s->all = 0;
    } else {
        *noop = x < s->cx0 || x >= s->cx1 || y < s->cy0 || y >= s->cy1;
        if (*noop) return RAST_OK;
        s->m1 = rast__seed_px(s, x, y);
        s->m2 = 0;
        s->inv = 0;
        s->all = 1;
    }
    /* Outside the clip, on the boundary, or nothing to change. */
    *noop = !rast__seed_in(s, x, y) || (!boundary && s->m1 == v);
    s->fast8 = s->bpp == 1 && (!boundary || s->m1 == s->m2);
    return RAST_OK;
}

static rast_status rast__seed_run(const rast_target *target, int32_t x, int32_t y,
                                  const void *value, const void *boundary, int connectivity,
                                  void *stack, size_t stack_bytes, uint64_t max_work,
                                  uint64_t *work)
{
    rast__seed s;
    rast__span_stack st;
    int noop = 0;
    rast_status status = rast__seed_setup(&s, target, x, y, value, boundary, connectivity,
                                          stack, stack_bytes, &noop);
    if (status != RAST_OK) return status;
    if (work) *work = 0;
    if (noop) return RAST_OK;
    s.area = (uint64_t)(s.cx1 - s.cx0) * (uint64_t)(s.cy1 - s.cy0);
    s.max_work = max_work;
    s.stop = RAST_OK;
    st.e = (rast__span_entry *)stack;
    st.n = 0;
    st.cap = stack_bytes / sizeof(rast__span_entry);
    rast__span_fill(&s, x, y, &st);
    if (work) *work = s.work;
    return s.stop;
}

rast_status rast_flood_fill(const rast_target *target, int32_t x, int32_t y, const void *value,
                            int connectivity, void *stack, size_t stack_bytes)
{
    return rast__seed_run(target, x, y, value, NULL, connectivity, stack, stack_bytes,
                          UINT64_MAX, NULL);
}

rast_status rast_boundary_fill(const rast_target *target, int32_t x, int32_t y,
                               const void *value, const void *boundary, int connectivity,
                               void *stack, size_t stack_bytes)
{
    if (!boundary) return RAST_E_NULL;
    return rast__seed_run(target, x, y, value, boundary, connectivity, stack, stack_bytes,
                          UINT64_MAX, NULL);
}

rast_status rast_seed_fill_limited(const rast_target *target, int32_t x, int32_t y,
                                   const void *value, const void *boundary, int connectivity,
                                   void *stack, size_t stack_bytes, uint64_t max_work,
                                   uint64_t *work)
{
    return rast__seed_run(target, x, y, value, boundary, connectivity, stack, stack_bytes,
                          max_work, work);
}
